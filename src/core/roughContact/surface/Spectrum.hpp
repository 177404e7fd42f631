// SPDX-License-Identifier: GPL-3.0-or-later
// The surface as frequency levels f_i with amplitudes beta_i (seed §2.1, docs/theory.md §1.2).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace roughContact {

class Profile;

class Spectrum {
public:
    /// Levels f_i [1/m] (positive, strictly increasing) with single-sided amplitudes
    /// beta_i [m] (finite, >= 0), for a scan of length L [m]; A_n = L^2 (seed §2.1).
    /// source names the origin for error messages.
    Spectrum(std::vector<double> frequencies, std::vector<double> amplitudes, double length,
             std::string source = "");

    /// The constructor's spectrum, marked as ending in the Nyquist level of an even-length
    /// profile when `nyquist` (for spectra derived from profiles: averages of line scans).
    static Spectrum withNyquistLevel(std::vector<double> frequencies, std::vector<double> amplitudes,
                                     double length, std::string source, bool nyquist);

    /// FFT (FFTW) of the profile after removing its mean and linear tilt: f_k = k/L,
    /// beta_k = 2|Z_k|/N for 0 < k < N/2 and |Z_{N/2}|/N at Nyquist (docs/theory.md §1.2).
    static Spectrum fromProfile(const Profile& profile);

    /// Power law beta = b_m f^-m at the levels f_i = i/L with fmin <= f_i <= fmax
    /// (seed §2.3). length defaults to 1/fmin when <= 0.
    static Spectrum powerLaw(double bm, double m, double fmin, double fmax, double length = 0.0);

    /// Weierstrass-Mandelbrot (Majumdar-Bhushan) surface of fractal dimension D and roughness
    /// G [m]: one-sided PSD S(f) = G^(2(D-1)) / (2 ln(gamma) f^(5-2D)), gamma = 1.5
    /// (docs/theory.md §4.3), sampled at f_i = i/L, fmin <= f_i <= fmax: beta_i^2 = 2 S(f_i) / L.
    static Spectrum fractal(double D, double G, double fmin, double fmax, double length = 0.0);

    /// Equivalent surface of two rough surfaces in contact: their powers add level by level
    /// (docs/theory.md §1.5). On different frequency grids each level's power is spread over its
    /// frequency bin and re-binned onto f_k = k/L, L the longer scan, so the total variance is
    /// conserved exactly.
    static Spectrum combine(const Spectrum& a, const Spectrum& b);

    /// The mean of two line-scan spectra of one surface (two scan directions): their powers
    /// added (combine) and halved, level by level. Its every moment is the mean of theirs, so
    /// the isotropic surface it describes has the areal gradient m2_a + m2_b of the surface the
    /// two were measured on (docs/theory.md §1.6). `source` names it.
    static Spectrum averaged(const Spectrum& a, const Spectrum& b, std::string source);

    std::size_t size() const noexcept { return f_.size(); }
    const std::vector<double>& frequencies() const noexcept { return f_; }
    const std::vector<double>& amplitudes() const noexcept { return beta_; }
    double frequency(std::size_t i) const { return f_.at(i); }
    double amplitude(std::size_t i) const { return beta_.at(i); }
    double length() const noexcept { return length_; }
    /// A_n = L^2 (seed §2.1).
    double nominalArea() const noexcept { return length_ * length_; }
    const std::string& source() const noexcept { return source_; }

    /// Sum of beta_i^2/2: the variance of the sinusoids (docs/theory.md §1.2). For a spectrum from
    /// an even-length profile the Nyquist level is a cosine sampled at its crests, whose
    /// variance is beta^2 rather than beta^2/2; profileVariance() accounts for that.
    double variance() const;
    /// Variance of the profile this spectrum came from (Parseval), exact for fromProfile().
    double profileVariance() const;
    /// True when the last level is the Nyquist level of an even-length profile.
    bool hasNyquistLevel() const noexcept { return nyquist_; }

    /// The levels with f <= fmax only.
    Spectrum truncated(double fmax) const;

    /// The same line-scan spectrum on a period of `multiple` times its length (1 to 64): its
    /// two-sided density C1 = beta_i^2/(4 w_i) (w_i a level's bin as IsotropicSpectrum takes it; a
    /// Nyquist level's beta^2/w; not pooled to a non-increasing density, which the synthesis
    /// does after) linear between the levels and flat beyond the first and the last, sampled at
    /// the levels j/(multiple L), each level's power C1 times the part of its bin inside the band
    /// [max(f_1 - w_1/2, f_1/2), f_n + w_n/2] (ending at a Nyquist level): the variance is kept
    /// to the linear interpolation's error. A periodic surface synthesized from it is a
    /// period `multiple` times as long of a surface of the same finish (the check's light loads,
    /// SurfaceCheck.hpp). Levels that would number more than the limit: ParameterError.
    Spectrum onPeriod(std::size_t multiple) const;
    /// The longest period onPeriod takes, in scan lengths.
    static constexpr std::size_t maximumPeriodMultiple = 64;

    /// The line scan of the same heights with every length `factor` times longer (> 0, finite):
    /// the amplitudes at f_i / factor on a scan of factor L. The profile along y of a surface
    /// whose y spacing is stretched by `factor` (synthesizeStretched). ParameterError otherwise.
    Spectrum stretched(double factor) const;

private:
    std::vector<double> f_;
    std::vector<double> beta_;
    double length_;
    std::string source_;
    bool nyquist_ = false;
};

/// Per-level asperity quantities of seed Eqs. 4-5.
/// eta = 2 f^2 [1/m^2]
double asperityDensity(double frequency);
/// R = 1 / (4 pi^2 beta f^2) [m]; +inf for beta = 0.
double asperityRadius(double frequency, double amplitude);

} // namespace roughContact
