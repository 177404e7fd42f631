// SPDX-License-Identifier: GPL-3.0-or-later
// The ranges the core accepts: one place for each. Outside them a computation would leave the
// range of a double (an overflow, or an underflow to 0 that a later division turns into an
// infinity) or the input has no physical meaning; either way the core refuses it with a
// ParameterError or InputError that names the input and the range, before any large
// allocation. Inside them every model runs with floating-point traps on (as OpenFOAM runs):
// tests/core/testExtremeInputs.cpp holds each model to that at the corners of these ranges.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

namespace roughContact {

class Spectrum;

namespace limits {

/// Lengths [m]: sample spacings, scan lengths L (A_n = L^2) and wavelengths 1/f. From a
/// picometre (below any interatomic distance) to a kilometre.
constexpr double minimumLength = 1e-12;
constexpr double maximumLength = 1e3;
/// Heights and spectral amplitudes [m], in magnitude (a profile's heights before its mean and
/// tilt are removed included).
constexpr double maximumHeight = 1e3;
/// rms roughness [m] below which a surface is refused: a femtometre is the size of a nucleus,
/// so a smaller rms is a unit mistake; exactly zero is refused as perfectly smooth (no contact
/// resistance to model).
constexpr double minimumRoughness = 1e-15;

/// Young's and reduced moduli [Pa]: from the softest gels to ten times diamond.
constexpr double minimumModulus = 1e3;
constexpr double maximumModulus = 1e13;
/// The reduced modulus E' = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2) of any such pair: half the least E
/// (two such solids, nu = 0), and far above the greatest (nu towards -1 raises it without bound).
constexpr double minimumReducedModulus = minimumModulus / 2.0;
constexpr double maximumReducedModulus = 1e15;
/// Yield strain S_y/E of the material that yields first: annealed metals reach 1e-4, hard
/// polymers 0.05. Beyond 0.1 the Jackson-Green fits (seed Eqs. 15-19, B = 0.14 exp(23 S_y/E))
/// leave every range they were fitted on and B overflows past S_y/E = 30.9.
constexpr double minimumYieldStrain = 1e-6;
constexpr double maximumYieldStrain = 0.1;

/// Dimensionless loads F/(A_n E'): 0, or within these. 1e-30 E' is 2e-19 Pa on steel (a
/// Greenwood-Williamson separation of 9 sigma_s needs 3e-22); the multi-scale models are in
/// complete contact long before 1e3 (P = 1000 E'), and 1e4 keeps F = load A_n E' far from
/// overflow for every A_n and E' above.
constexpr double minimumLoad = 1e-30;
constexpr double maximumLoad = 1e4;

/// A level whose slope beta f is at most this is flat: every asperity law of the project puts
/// it in complete contact from a mean pressure of 8 E' beta f on (Hertz at 6.7 E' beta f,
/// the seed's JGH at 2 pi E' beta f; testExtremeInputs checks each law), which the smallest
/// load already exceeds, so the multi-scale model skips it like a level of zero amplitude:
/// the result is the same, and its radius (which can overflow) is never computed.
constexpr double flatSlope = minimumLoad / 8.0;

/// The most frequency levels one surface may have: a profile of 2 million samples. The
/// multi-scale model and its pressure table hold about bytesPerLevel a level at their peak
/// (spectrum, levels, one trace); beyond this cap the table takes minutes, so the refusal says
/// how many levels and how much memory the surface would need, and how to thin it (stride).
constexpr std::size_t maximumLevels = 1000000;
constexpr double bytesPerLevel = 200.0;

/// The most points of an areal surface (4096 x 4096): 134 MB of heights. What a model built on
/// it needs beyond that (a boundary-element solve holds several padded copies) is checked by
/// the model.
constexpr std::size_t maximumGridPoints = 4096 * 4096;

/// Temperatures [K] of a gas gap or a radiating surface: from 0.01 K (below any gas in use) to
/// 1e5 K (far above any solid's melting point). Within them T^3 and (T/T0)^n (n <= 2) stay far
/// from overflow.
constexpr double minimumTemperature = 1e-2;
constexpr double maximumTemperature = 1e5;
/// Gas pressures [Pa] of a gas gap: from 1e-10 Pa (ultra-high vacuum; the free-molecular limit
/// long before) to 1e9 Pa (10 kbar, beyond any gas-filled joint). Also a gas's reference pressure.
constexpr double minimumGasPressure = 1e-10;
constexpr double maximumGasPressure = 1e9;

/// Throws ParameterError(what, ...) unless value lies in [lo, hi] (and is finite); `unit`
/// follows the numbers in the message ("m", "Pa", "" for none).
double requireInRange(const std::string& what, double value, double lo, double hi, const char* unit);
/// The same for a literal name: the name becomes a string only when the check fails, so the
/// check costs nothing on per-face paths (the gap's conductance per face and evaluation).
inline double requireInRange(const char* what, double value, double lo, double hi, const char* unit)
{
    // isfinite first: an ordered comparison with a NaN raises FE_INVALID (a trap here).
    return std::isfinite(value) && value >= lo && value <= hi ? value
                                                              : requireInRange(std::string(what), value, lo, hi, unit);
}
/// A length [m] within [minimumLength, maximumLength].
double requireLength(const std::string& what, double value);
/// Throws ParameterError(what, ...) naming the count, the cap and the memory it would need,
/// when levels > maximumLevels; `hint` ends the message (how to get fewer levels).
void requireLevelCount(const std::string& what, double levels, const std::string& hint = "");
/// A surface a contact model can work with: rms height at least minimumRoughness and at least
/// one level that is not flat. ParameterError naming the surface otherwise.
void requireRoughness(const Spectrum& surface);

} // namespace limits
} // namespace roughContact
