// SPDX-License-Identifier: GPL-3.0-or-later
// McCool's spectral moments and the Greenwood-Williamson summit parameters derived from them
// (McCool, Wear 107 (1986) 37-60; seed §3.2; docs/theory.md §4.1).
#pragma once

namespace roughContact {

class Spectrum;

/// Profile spectral moments in angular wavenumber (docs/theory.md §4.1):
/// m0 = <z^2> [m^2], m2 = <z'^2> [-], m4 = <z''^2> [1/m^2].
struct SpectralMoments {
    double m0;
    double m2;
    double m4;
};

/// m_n = sum_k (2 pi f_k)^n beta_k^2 / 2 (docs/theory.md §4.1), the mean squares of z, z', z'' of the
/// sum of sinusoids beta_k cos(2 pi f_k x + phase_k). Every level is weighted beta^2/2, the
/// Nyquist level of an even-length profile included (docs/theory.md §4.1 weights every
/// level so), so m0 equals Spectrum::variance(), not Spectrum::profileVariance().
/// Levels with beta_k = 0 contribute nothing.
SpectralMoments spectralMoments(const Spectrum& spectrum);

/// The spectrum's bandwidth ratio W = m1/sqrt(m0 m2), m1 = sum_k (2 pi f_k) beta_k^2/2 the first
/// moment (docs/theory.md §4.1): the heights' power-weighted mean wavenumber m1/m0 over the
/// slopes' rms wavenumber sqrt(m2/m0). 0 < W <= 1 (Cauchy-Schwarz), 1 for a single level; a broad
/// spectrum whose heights live at long wavelengths and whose slopes at short ones has a small W
/// (0.46 for a self-affine spectrum of Hurst exponent 0.5 over 64 levels without a roll-off, 0.79
/// for Hurst 0.8 rolled off at the 16th level). Vanmarcke's bandwidth factor is sqrt(1 - W^2).
/// The conductance law fittedElastoPlastic takes it (FittedElastoPlastic.hpp). ParameterError
/// when m0 or m2 is zero.
double spectralBandwidthRatio(const Spectrum& spectrum);

/// The first level's share s1 = beta_1^2 / sum_k beta_k^2 of the heights' variance: how much of
/// the heights the spectrum's longest wave (its first level, 1/L for a scan of length L) carries.
/// 0 <= s1 <= 1 (0 where the first level's amplitude is 0), 1 for a single level; 0.11 for a self-affine spectrum of Hurst exponent 0.5 rolled
/// off at the 4th level, 0.77 for Hurst 0.8 without a roll-off. Like sigma it depends on the
/// longest wavelength the spectrum holds. The conductance law fittedElastoPlastic's light-load
/// exponent follows it (FittedElastoPlastic.hpp). ParameterError when every amplitude is zero.
double firstLevelShare(const Spectrum& spectrum);

/// h' = sqrt(2 m2): the areal rms gradient of an isotropic surface whose line scans have the
/// rms slope sqrt(m2) (each of the two slope components carries m2).
double arealRmsGradient(const SpectralMoments& moments);

/// Gaussian-summit parameters of an isotropic surface from its profile moments (McCool 1986,
/// docs/theory.md §4.1).
struct SummitParameters {
    double eta;    ///< summit density m4 / (6 pi sqrt(3) m2) [1/m^2]
    double R;      ///< mean summit radius 0.375 sqrt(pi / m4) [m]
    double sigmaS; ///< summit-height standard deviation sqrt((1 - 0.8968/alpha) m0) [m]
    double alpha;  ///< bandwidth parameter m0 m4 / m2^2 [-]
};

/// McCool's summit parameters (docs/theory.md §4.1) from the moments.
/// ParameterError (naming the moment) when a moment is not finite and positive, and when
/// sigma_s^2 = (1 - 0.8968/alpha) m0 <= 0, i.e. alpha <= 0.8968. The moments of any spectrum
/// obey m2^2 <= m0 m4 (Cauchy-Schwarz), so alpha >= 1 (= 1 for a single level) and the
/// second error can only come from moments supplied directly.
SummitParameters mcCoolParameters(const SpectralMoments& moments);
/// mcCoolParameters(spectralMoments(spectrum)).
SummitParameters mcCoolParameters(const Spectrum& spectrum);

} // namespace roughContact
