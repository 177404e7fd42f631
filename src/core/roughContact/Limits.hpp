// SPDX-License-Identifier: GPL-3.0-or-later
// The ranges the core accepts: one place for each. Outside them a computation would leave the
// range of a double (an overflow, or an underflow to 0 that a later division turns into an
// infinity) or the input has no physical meaning; either way the core refuses it with a
// ParameterError or InputError that names the input and the range, before any large
// allocation. Inside them every model runs with floating-point traps on (as OpenFOAM runs):
// tests/core/acceptance/testExtremeInputs.cpp holds each model to that at the corners of these ranges.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

namespace roughContact {
namespace limits {

/// Lengths [m]: sample spacings, scan lengths L (A_n = L^2) and wavelengths 1/f. From a
/// picometre (below any interatomic distance) to a kilometre.
constexpr double minimumLength = 1e-12;
constexpr double maximumLength = 1e3;
/// Heights and spectral amplitudes [m], in magnitude (a profile's heights before its mean and
/// tilt are removed included).
constexpr double maximumHeight = 1e3;
/// An rms slope Rdq (RoughnessSpectrum.hpp): measured surfaces have 0.001 to a few; the bounds
/// keep (Rdq/Rq)^2 finite for every accepted Rq (at most (1e3/1e-15)^2 = 1e36).
constexpr double minimumSlope = 1e-9;
constexpr double maximumSlope = 1e3;
/// Threads of the boundary-element solves (setThreads, parallel/Threads.hpp; a contact entry's
/// `threads`, the CLI's --threads): 1 to this.
constexpr int maximumThreads = 4096;
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

/// Hardness [Pa]: the plastic cap H of boundaryElement and the microhardness H_c of the
/// correlations (cooperMikicYovanovich, the gap's separation). Soft polymers have 1e7, metals
/// 1e8-1e10, diamond about 1e11; from the softest gels (the least modulus) to ten times diamond.
/// Outside it the number is a unit mistake (a hardness of 1e30 Pa would make every surface
/// elastic, one of 1e100 overflowed the capped solve's sums).
constexpr double minimumHardness = minimumModulus;
constexpr double maximumHardness = 1e12;

/// Points per decade of pressure of a contact table (the multi-scale table's pointsPerDecade
/// and the boundary-element table's): at least 2 (a table must bracket each decade it
/// interpolates over), at most 1000 (a table of 1000 points a decade over the widest default
/// range, 9 decades, is 9000 solves: minutes for the multi-scale model, hours for the exact one;
/// a finer table changes nothing a log-log interpolation can show).
constexpr std::size_t minimumPointsPerDecade = 2;
constexpr std::size_t maximumPointsPerDecade = 1000;

/// The grid size N of a synthesized N x N surface: even, from 8 (fewer points hold no contact
/// spots) to 4096 (maximumGridPoints). The seed of its random phases: any 64-bit unsigned
/// integer, 0 to 2^64 - 1 (a front-end refuses a larger or non-integer number, it does not wrap).
constexpr std::size_t minimumSynthesisSize = 8;
constexpr std::size_t maximumSynthesisSize = 4096;
/// ParameterError naming `what` unless n is such a grid size ("the grid size must be even and
/// within [8, 4096], got n"): the synthesis, the resampling and the check of a surface.
void requireSynthesisSize(const std::string& what, std::size_t n);

/// Thermal conductivities [W/(m K)] of the solids (k1, k2; k_s = 2 k1 k2/(k1 + k2)): aerogels
/// have 0.01, diamond 2200; from 1e-4 to 1e5.
constexpr double minimumConductivity = 1e-4;
constexpr double maximumConductivity = 1e5;

/// A gas's numbers (beyond the physical ones, they keep every product of GasGap finite).
/// Conductivity [W/(m K)]: gases have 0.005-0.2; liquids and liquid metals, which a "user" gas
/// may stand for, reach 100.
constexpr double minimumGasConductivity = 1e-6;
constexpr double maximumGasConductivity = 1e3;
/// The exponent of k_g(T): real gases have 0.5-1 (kinetic theory 0.5 for hard spheres); 2 keeps
/// (T/T0)^n finite over the accepted temperatures. From 0 (a constant k_g).
constexpr double maximumConductivityExponent = 2.0;
/// gamma must exceed 1 (c_p > c_v); the monatomic ideal gas has the largest, 5/3.
constexpr double maximumHeatCapacityRatio = 10.0;
/// Pr: gases 0.6-1.
constexpr double minimumPrandtl = 1e-3;
constexpr double maximumPrandtl = 1e3;
/// Accommodation coefficients lie in (0, 1]; below 1e-6 (no measured surface comes near: the
/// temperature jump would pass a million mean free paths) they are refused.
constexpr double minimumAccommodation = 1e-6;

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
/// value as a message quotes it: "1.5e-06 m" (unit after a space, none for ""), or "inf (not a
/// finite number)" and "nan (not a number)" without a unit.
std::string valueText(double value, const char* unit);
/// A length [m] within [minimumLength, maximumLength].
double requireLength(const std::string& what, double value);
/// Throws ParameterError(what, ...) naming the count, the cap and the memory it would need,
/// when levels > maximumLevels; `hint` ends the message (how to get fewer levels).
void requireLevelCount(const std::string& what, double levels, const std::string& hint = "");

} // namespace limits
} // namespace roughContact
