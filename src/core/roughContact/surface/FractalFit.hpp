// SPDX-License-Identifier: GPL-3.0-or-later
// Fractal dimension D and roughness G of a Weierstrass-Mandelbrot surface fitted to a spectrum
// (Majumdar & Tien 1990 as used by the seed §3.2; docs/theory.md §4.3).
#pragma once

#include <limits>

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

} // namespace roughContact
