// SPDX-License-Identifier: GPL-3.0-or-later
// Fractal dimension D and roughness G of a Weierstrass-Mandelbrot surface fitted to a spectrum
// (Majumdar & Tien 1990 as used by the seed §3.2; docs/theory.md §4.3).
#pragma once

#include <limits>
#include <optional>

namespace roughContact {

class Spectrum;

/// W-M parameters: fractal dimension D (1 < D < 2) and fractal roughness G [m].
struct FractalParameters {
    double D;
    double G;
};

/// Least-squares fit (Eigen) of ln S = c + s ln f over the levels with fmin <= f <= fmax and
/// beta > 0, S_k = beta_k^2 L / 2 the one-sided PSD (df = 1/L). Against the W-M PSD
/// S(f) = G^(2(D-1)) / (2 ln(gamma) f^(5-2D)), gamma = 1.5 (docs/theory.md §4.3):
/// D = (5 + s) / 2 and 2 (D-1) ln G = c + ln(2 ln gamma).
/// Spectrum::fractal(D, G, ...) has exactly this PSD, so fitting it returns D and G.
/// ParameterError with fewer than 3 levels in range or a fitted D outside (1, 2).
FractalParameters fitFractal(const Spectrum& spectrum, double fmin = 0.0,
                             double fmax = std::numeric_limits<double>::infinity());

/// The Hurst exponent H_f of the spectrum's finest octave: ln S = c + s ln f by least squares over
/// the levels with f_max/2 <= f <= f_max and beta > 0 (S as fitFractal's), H_f = -(1 + s)/2 (a
/// self-affine profile's PSD falls as f^-(1 + 2H)); 0.8 for a self-affine spectrum of Hurst
/// exponent 0.8 whatever its roll-off and its period. Any finite value (no range check: 1.2 for
/// a spectrum that falls faster than any self-affine one). None when the octave holds fewer than
/// 3 such levels. The conductance law fittedElastoPlastic's unloading branch takes it
/// (FittedElastoPlastic.hpp; docs/theory.md §5.7c).
std::optional<double> fineHurstExponent(const Spectrum& spectrum);

} // namespace roughContact
