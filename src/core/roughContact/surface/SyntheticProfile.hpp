// SPDX-License-Identifier: GPL-3.0-or-later
// Seeded random rough profiles with a power-law spectrum: the stand-in for the seed's
// measured profile (Fig. 4a), which is not public.
#pragma once

#include "roughContact/surface/Profile.hpp"

#include <cstdint>

namespace roughContact {

/// A Gaussian random profile whose one-sided PSD follows the Majumdar-Bhushan power law
/// S(f) ~ f^-(5-2D) from 1/L to the Nyquist frequency, scaled to the given rms.
struct SyntheticProfileSpec {
    std::size_t points = 2454;  ///< seed §3.2: 2454 points
    double spacing = 0.204e-6;  ///< seed §3.2: 0.204 um
    double rms = 0.115e-6;      ///< seed Table 1: sigma = 0.115 um
    double D = 1.597;           ///< seed Table 1 fractal dimension (sets the PSD slope)
    std::uint64_t seed = 2006;  ///< std::mt19937_64 seed
};

/// Method: for k = 1..N/2 draw a complex Gaussian coefficient (Box-Muller on
/// std::mt19937_64, whose output the C++ standard fixes, so the profile is the same on every
/// platform up to libm rounding) with variance proportional to f_k^-(5-2D) (the Nyquist
/// coefficient real), inverse-FFT with FFTW, remove mean and linear tilt (least squares), and scale to the
/// rms, so the detrended profile has exactly spec.rms.
Profile generateSyntheticProfile(const SyntheticProfileSpec& spec);

} // namespace roughContact
