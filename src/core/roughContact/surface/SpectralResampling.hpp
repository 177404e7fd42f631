// SPDX-License-Identifier: GPL-3.0-or-later
// The same periodic surface on another grid: its Fourier series
// evaluated at N x N points, optionally without its wavelengths shorter than L/K.
//
// A periodic surface of n x n points on L x L is the trigonometric polynomial
//     z(x, y) = sum over k of c_k exp(2 pi i (k_x x + k_y y) / L),   |k_x|, |k_y| <= n/2,
// with c_k its discrete Fourier coefficients divided by n^2. Evaluating that polynomial on a finer
// grid (N > n) gives the same surface with more points per wavelength: a boundary-element solve
// on both grids then differs only by the discretization, which is how the fidelity study shows
// that its references are converged (the synthesis draws its phases on the grid it is given, so
// --synthesize on two grids gives two different realizations, not one surface twice). A
// coefficient on a Nyquist line (k_x or k_y = n/2) stands for both +n/2 and -n/2 on the coarse
// grid; on a finer grid they are two wavevectors and each gets half, so a cosine sampled at its
// crests stays that cosine. On a coarser grid (N < n) the wavevectors the new grid cannot hold
// (|k_x| or |k_y| >= N/2) are dropped: resampling down is a low-pass filter, never an alias.
// With `levels` = K, every wavevector with |k| > K (in units of 1/L: wavelengths shorter than
// L/K) is dropped as well: the same surface without its finest roughness, so that a study of how
// the exact answer moves with the number of levels changes nothing but those levels.
#pragma once

#include <cstddef>
#include <optional>

namespace roughContact {

class ArealSurface;

/// `periodic` (square: nx = ny, dx = dy; one period of a periodic surface, as synthesizeIsotropic
/// makes) as the n x n samples of its Fourier series, without the wavevectors |k| > levels (in
/// units of 1/L) when levels is given; the mean is kept. n even, within
/// [limits::minimumSynthesisSize, limits::maximumSynthesisSize]; levels >= 1. ParameterError
/// naming "n", "levels" or the surface's source otherwise, before anything is allocated.
ArealSurface resampledPeriodic(const ArealSurface& periodic, std::size_t n,
                               std::optional<double> levels = std::nullopt);

} // namespace roughContact
