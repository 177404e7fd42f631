// SPDX-License-Identifier: GPL-3.0-or-later
// A surface from its roughness numbers: the rms height Rq (or Ra) and the rms slope Rdq of a
// profile, as a stylus instrument reports them after its filters, stand for the self-affine
// power-law spectrum that has exactly those two numbers over the band the filters pass
// (docs/theory.md §1.4). The band is the measurement standard's: the long-wavelength cut-off
// lambda_c (ISO 4288: 0.8 mm for 0.1 um < Ra <= 2 um) is the scan length L, the levels are
// f_i = i/L up to the short-wavelength cut-off lambda_s (ISO 3274: 2.5 um with lambda_c 0.8 mm),
// and the amplitudes beta_i = b_m f_i^-m, m = H + 1/2 (a profile of Hurst exponent H). Of b_m
// and H, Rq fixes b_m (Rq^2 = sum beta_i^2/2) and Rdq/Rq fixes H (Rdq^2 = sum (2 pi f_i
// beta_i)^2/2): the ratio falls from H -> 0 to H = 1, so one H in (0, 1] gives it, found by
// bisection. A ratio outside that range is no self-affine surface over that band: an error
// that says the range.
#pragma once

#include "roughContact/surface/Spectrum.hpp"

namespace roughContact {

/// The defaults of the band: ISO 4288's sampling length and ISO 3274's lambda_s for it [m].
inline constexpr double defaultLongCutoff = 0.8e-3;
inline constexpr double defaultShortCutoff = 2.5e-6;

/// Rq of Gaussian heights from their Ra: Rq = sqrt(pi/2) Ra (Ra = <|z|> = sqrt(2/pi) Rq).
double rqFromRa(double Ra);

struct RoughnessSpectrum {
    Spectrum spectrum;
    double hurst;   ///< H, found from Rdq/Rq
    double bm;      ///< b_m [m^(1-m)]
};

/// The spectrum of rms height Rq [m] and rms slope Rdq over [1/longCutoff, 1/shortCutoff]
/// (both cut-offs in m, longCutoff > shortCutoff). ParameterError naming "Rq", "slope",
/// "cutoff" or "shortCutoff" for a value out of range, and "slope" when Rdq/Rq lies outside what
/// a Hurst exponent in (0, 1] gives over the band (the message gives that range).
RoughnessSpectrum roughnessSpectrum(double Rq, double rmsSlope, double longCutoff = defaultLongCutoff,
                                    double shortCutoff = defaultShortCutoff);

} // namespace roughContact
