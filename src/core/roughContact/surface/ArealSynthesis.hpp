// SPDX-License-Identifier: GPL-3.0-or-later
// Synthesis of an isotropic Gaussian areal surface from a line-scan spectrum:
// a user with only a stylus profile (or a 1-D spectrum) gets an areal surface whose line scans
// have that spectrum, for the exact (boundary-element) models.
//
// The conversion. Let the heights h(x, y) be a stationary isotropic random field and write the
// power spectra in spatial frequency (cycles per metre), each normalised so that it integrates
// to the variance over all its (positive and negative) frequencies:
//     <h^2> = integral over R of C1(f) df = integral over R^2 of C2(|q|) d^2q.
// A line scan along x sees every wavevector (f, q_y), so its two-sided 1-D PSD is
//     C1(f) = integral over R of C2(sqrt(f^2 + q_y^2)) dq_y
//           = 2 integral_f^inf C2(q) q dq / sqrt(q^2 - f^2),                      (1)
// the Abel transform of C2, and the inverse Abel transform gives
//     C2(q) = -(1/pi) integral_q^inf C1'(k) dk / sqrt(k^2 - q^2).                  (2)
// Sources. (1) is the projection-slice theorem for an isotropic field (the autocorrelation of a
// line scan is the areal one on the line, so its Fourier transform is the areal spectrum
// integrated across); (2) is the Abel inversion of (1). Normalisation checked against Jacobs,
// Junge, Pastewka, "Quantitative characterization of surface topography using spectral
// analysis", Surf. Topogr.: Metrol. Prop. 5 (2017) 013001, Eqs. (1) and (4), as quoted in the
// docstring of self_affine_prefactor in PyCo's/SurfaceTopography's Topography/Generation.py
// (the paper itself was not at hand): h_rms^2 = (1/(2 pi)) integral_0^inf q C^iso(q) dq and
// h_rms^2 = (1/pi) integral_0^inf C^1D(q) dq with q = 2 pi f in rad/m. Their C^1D(q) and
// C^iso(q) are then numerically our C1(f) and C2(f), and (1) in their variables reads
// C^1D(q_x) = (1/(2 pi)) integral C^iso(sqrt(q_x^2 + q_y^2)) dq_y; integrated over q_x it turns
// one of their two normalisations into the other, so (1) and theirs agree.
// tests/core/surface/testArealSynthesis.cpp checks (2) against (1) numerically and against the
// closed form of a power law. (1) and (2) hold for a C2
// that is zero beyond some q only if C1 is continued by its jump: a C1 that ends at f_c with value C1(f_c)
// contributes C1(f_c) / (pi sqrt(f_c^2 - q^2)) to (2), an integrable pile-up of 2-D power just inside f_c.
// Also used: the power outside a radius r, swapping the integrals of (2),
//     T(r) = integral over |q| > r of C2 d^2q = -2 integral_r^inf C1'(k) sqrt(k^2 - r^2) dk.  (3)
//
// The project's Spectrum is single-sided amplitudes beta_i at f_i (a line scan
// z = sum beta_i cos(2 pi f_i x + phi_i)). Level i carries the variance beta_i^2/2 spread over
// its frequency bin of width df_i (1/L for f_i = i/L) at +f_i and -f_i, so
//     C1(f_i) = beta_i^2 / (4 df_i)           (the Nyquist level of an even-length profile,
//                                              a cosine sampled at its crests: beta^2 / df).
// C1 between the levels is interpolated linearly in f (the levels are one bin apart, so this is
// the plainest continuous spectrum through them, and (2) and (3) have closed forms for it),
// continued flat by half a bin below the first level and above the last, and zero outside.
// A non-increasing C1 makes every term of (2) >= 0, so C2 >= 0 (sufficient, not necessary: a
// ring of 2-D power gives a C1 that rises towards it). A measured spectrum (a periodogram: each
// level scatters by 100 %) would make (2) negative just below each level that stands above its
// neighbours, so the levels are first made non-increasing by pooling adjacent violators (PAVA:
// each pooled run of levels takes its mean density), which keeps the variance of every pooled
// run and so the total variance exactly, but moves power within a run (the stand-in's lowest
// three octaves change by +267 %, +185 % and -43 %, its slope^2 by -1.4 %). A power law is
// non-increasing already and passes unchanged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace roughContact {

class ArealSurface;
class Spectrum;

/// The isotropic 2-D spectrum of a line-scan spectrum, Eqs. (1)-(3) of this header.
class IsotropicSpectrum {
public:
    /// From the levels of `lineScan` up to `cutoff` [1/m] (<= 0: all levels); C1 ends at
    /// min(last level + half a bin, cutoff).
    explicit IsotropicSpectrum(const Spectrum& lineScan, double cutoff = 0.0);

    /// Scan length L of the line scan [m].
    double length() const noexcept { return L_; }
    /// The band [lowest, highest] [1/m] on which C1 (and C2) are non-zero.
    double lowestFrequency() const noexcept { return k_.front() / L_; }
    double highestFrequency() const noexcept { return k_.back() / L_; }

    /// The two-sided 1-D PSD C1(f) [m^3] that is inverted: the (pooled) levels, linear between
    /// them; 0 outside the band.
    double c1(double f) const;
    /// The 2-D PSD C2(|q|) [m^4] of Eq. (2), exact for the piecewise linear C1; 0 outside the
    /// band, +inf never (|q| = highestFrequency() gives 0 by convention: a set of measure 0).
    double c2(double q) const;
    /// Eq. (3): the variance in |q| > r [m^2]; powerOutside(0) is the variance of the surface.
    double powerOutside(double r) const;

private:
    std::vector<double> k_; // nodes in units of 1/L
    std::vector<double> c_; // C1 at the nodes in units of m^2 (per unit of k)
    std::vector<double> s_; // slopes dC1/dk of the segments
    double L_;
};

/// The variance of every cell of the n x n FFT grid of an L x L periodic surface (L the spectrum's
/// length) [m^2], in FFTW's half-complex layout: n rows of wavenumber k_y = 0..n-1 (k_y > n/2
/// meaning k_y - n) by n/2 + 1 columns k_x = 0..n/2, index k_y (n/2 + 1) + k_x. A cell at
/// |k| = rho (in units of 1/L) gets C2 averaged over the annulus rho - 1/2 < |k| < rho + 1/2
/// (T(rho - 1/2) - T(rho + 1/2)) / (2 pi rho), which spreads the pile-up at the cutoff over the
/// cells it falls in. The cutoff is min(spectrum's highest level + half a bin, n/(2L)) so the
/// whole disc lies inside the grid; a cell on a Nyquist line (k_x or k_y = n/2) is also its own
/// mirror image at -n/2 and holds twice that (so a level at n/2 that is not the spectrum's own
/// Nyquist level comes out as one: a grid of n points holds only its cosine, half its power).
std::vector<double> isotropicGridPower(const Spectrum& lineScan, std::size_t n);

/// An n x n periodic surface on L x L (spacing L/n, L the spectrum's length) whose Fourier
/// coefficients have the moduli sqrt(isotropicGridPower) and phases uniform in [0, 2 pi) from
/// std::mt19937_64(seed) (53-bit uniforms, so the surface is the same on every platform up to
/// libm rounding), Hermitian so that FFTW's c2r transform (FFTW_ESTIMATE) is real; the
/// self-conjugate coefficients (k_x, k_y in {0, n/2}) are real with a random sign. Zero at
/// |k| < 1/2 (the mean) and beyond the cutoff. The moduli are fixed, so the variance of the
/// surface and the mean power of its line scans are the same for every seed; the heights are
/// Gaussian in the limit of many coefficients (central limit theorem).
/// n even, within [8, 4096] (ParameterError naming "n" otherwise, before anything is allocated).
ArealSurface synthesizeIsotropic(const Spectrum& lineScan, std::size_t n, std::uint64_t seed,
                                 std::string source = "");

/// A finish with a lay along y: synthesizeIsotropic(across, n, seed) with its y spacing `stretch`
/// times its x spacing (an n x n period of L x stretch L), so that its features are `stretch`
/// times longer along y than across. Its rows have the line-scan spectrum `across`, its columns
/// across.stretched(stretch), and its rms slope along y is the rows' over `stretch`
/// (docs/theory.md §1.6). stretch > 0 and finite (ParameterError "stretch" otherwise); 1 is
/// synthesizeIsotropic.
ArealSurface synthesizeStretched(const Spectrum& across, double stretch, std::size_t n, std::uint64_t seed,
                                 std::string source = "");

} // namespace roughContact
