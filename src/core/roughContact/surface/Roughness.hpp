// SPDX-License-Identifier: GPL-3.0-or-later
// The two roughness parameters of the thermal contact correlations (Mikic.hpp,
// CooperMikicYovanovich.hpp, Microhardness.hpp): the rms height sigma and the mean absolute
// slope m, from a profile, an areal surface or a spectrum, and of two surfaces in contact
// (docs/correlations.md).
#pragma once

#include "roughContact/surface/ArealSurface.hpp"

namespace roughContact {

class Profile;
class Spectrum;

struct SurfaceRoughness {
    double sigma;             ///< rms height about the mean plane [m]
    double meanAbsoluteSlope; ///< m = <|dz/dx|> [-]
};

/// ParameterError naming the entry ("rms roughness sigma", "mean absolute slope m") unless both
/// are finite and > 0 and sigma >= limits::minimumRoughness (1e-15 m). Every correlation calls
/// it on its input.
void checkRoughness(const SurfaceRoughness& r);

/// A surface a contact model can work with: rms height at least limits::minimumRoughness and at
/// least one level steeper than limits::flatSlope. ParameterError naming the surface otherwise.
void requireRoughness(const Spectrum& surface);

/// sigma and m of a line profile, after removing its mean and linear tilt (Profile::detrended,
/// least squares): sigma = rms of the detrended heights; m = (1/(N-1)) sum_i |z_{i+1} - z_i| / dx,
/// the forward difference of neighbouring samples (first order in dx; on a sinusoid of
/// wavelength lambda it underestimates the slope by at most about (pi dx/lambda)^2/2, relative).
/// The slope depends on the sampling interval dx: a finer stylus sees shorter wavelengths and a
/// larger m, so m is only defined together with the instrument's resolution.
SurfaceRoughness profileRoughness(const Profile& profile);

/// sigma and m of an areal surface after removing its least-squares plane
/// (ArealSurface::detrended): sigma = rms of the detrended heights; m = the mean of |forward
/// difference|/spacing along x (over every row), along y (over every column), or, for `both`,
/// the arithmetic mean of the two (most authors quote m of a profile: choose the direction the
/// stylus would have run). Same difference scheme and resolution dependence as profileRoughness.
SurfaceRoughness arealRoughness(const ArealSurface& surface, ScanDirection direction);

/// sigma and m of a spectrum: sigma^2 = m0 = sum_i beta_i^2/2 and the rms slope
/// sqrt(m2), m2 = sum_i (2 pi f_i beta_i)^2/2 (spectralMoments), and m = sqrt(2/pi) sqrt(m2).
/// The factor sqrt(2/pi) = <|s|>/sqrt(<s^2>) holds for a Gaussian slope s only: this ASSUMES
/// Gaussian (normally distributed) slopes; for a single sinusoid it is 2 sqrt(2)/pi instead
/// (0.90 rather than 0.80 of the rms slope). ParameterError when sigma or m is zero.
SurfaceRoughness spectrumRoughness(const Spectrum& spectrum);

/// A surface's heights' skewness and how much of it chance alone would give (docs/theory.md §5.15).
struct HeightSkewness {
    double skewness; ///< mu3/sigma^3 of the detrended heights, mu3 = <z^3> the third central moment
    /// The standard deviation of the skewness that Gaussian heights with the same autocorrelation
    /// rho give on a sample of the same N points: sqrt((6/N) sum_k rho(k)^3), the sum over every
    /// lag k of the sample (rho from the zero-padded autocorrelation, so over the overlap), the
    /// large-N variance of the sample third moment of a Gaussian process (6/N for independent
    /// heights). A profile or map that holds few of its longest wavelengths is skewed by chance:
    /// the seed's stand-in profile 0.243 against a spread of 0.322, the X3P map -0.379 against 0.125.
    /// A map of more than spreadSide points a side gives it from every k-th point each way
    /// (k = ceil(side/spreadSide)): the padded grid of a 4096^2 map would take 1 GB. That keeps
    /// the long-range correlation that makes a spread large, and overstates the spread of heights
    /// uncorrelated from point to point (by up to k: on the side of "could be chance").
    double spread;
};

/// The most points a side from which a map's skewness spread is computed (HeightSkewness).
constexpr std::size_t spreadSide = 1024;

/// The skewness of a profile's heights after removing its mean and linear tilt (as
/// profileRoughness), with its spread. Every law and multi-scale model here assumes Gaussian
/// heights, skewness 0; a measured surface's says how far it is from that (the X3P map: -0.38;
/// elastically the exact conductance moves by tens of per cent with it,
/// docs/validation/skewness.md). ParameterError when the heights are flat (sigma below
/// limits::minimumRoughness, 1e-15 m, after detrending).
HeightSkewness profileSkewness(const Profile& profile);

/// The same of an areal surface's heights after removing its least-squares plane (as
/// arealRoughness).
HeightSkewness arealSkewness(const ArealSurface& surface);

/// The skewness of the equivalent surface z1 + z2 of two independent rough surfaces of rms
/// heights sigma1, sigma2: (s1 sigma1^3 + s2 sigma2^3) / (sigma1^2 + sigma2^2)^(3/2) (third
/// central moments add for independent sums); the spreads add likewise, in quadrature. A
/// surface given by its spectrum is {0, 0}.
HeightSkewness combinedSkewness(double sigma1, const HeightSkewness& a, double sigma2,
                                const HeightSkewness& b);

/// The skewness of one surface from profiles in two directions (across and along its lay): the
/// mean of the two, its spread that of a mean of two independent estimates,
/// sqrt(e_a^2 + e_b^2)/2.
HeightSkewness twoDirectionSkewness(const HeightSkewness& across, const HeightSkewness& along);

/// The surface's skewness with the share chance explains taken out: s (1 - e^2/s^2) where
/// |s| > e (the spread), else 0. A sample skewness s is the surface's theta plus chance of
/// variance e^2; with theta and chance Gaussian, theta drawn from a zero-mean spread tau^2, the
/// posterior mean of theta is s tau^2/(tau^2 + e^2) (the empirical-Bayes shrinkage of Efron &
/// Morris, J. Am. Stat. Assoc. 68 (1973) 117-130), and s^2 estimates tau^2 + e^2: a plug-in from
/// one observation, the positive-part form of Stein's rule without its guarantee (which needs
/// three or more estimates; docs/theory.md §5.7b). The skewness
/// the law fittedElastoPlastic takes: the X3P map's -0.379 +- 0.125 gives -0.338; the seed's
/// stand-in profile's 0.243 +- 0.322 gives 0. Non-finite input: ParameterError.
double shrunkSkewness(const HeightSkewness& s);

/// The equivalent surface of two rough surfaces in contact: sigma = sqrt(s1^2 + s2^2),
/// m = sqrt(m1^2 + m2^2) (Yovanovich, J. Thermophys. Heat Transfer 19 (2005) 379-386, the
/// "effective" roughness and slope of a joint; see docs/correlations.md). Both checked.
SurfaceRoughness combined(const SurfaceRoughness& a, const SurfaceRoughness& b);

/// One surface from profiles in two directions (across and along its lay), as an areal map's
/// `both` directions (arealRoughness): sigma = sqrt((s_a^2 + s_b^2)/2), the mean of the two
/// variances; m = (m_a + m_b)/2, the mean of the two mean absolute slopes. Both checked.
SurfaceRoughness twoDirectionRoughness(const SurfaceRoughness& across, const SurfaceRoughness& along);

} // namespace roughContact
