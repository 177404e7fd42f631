// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/Mikic.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>

namespace roughContact {

namespace {
// Mikic (1974), elastic correlation as quoted by Yovanovich (2005): coefficient and exponent.
constexpr double mikicCoefficient = 1.54;
constexpr double mikicExponent = 0.94;
} // namespace

double mikicConductancePerConductivity(double P, const SurfaceRoughness& r, double Eprime)
{
    if (std::isnan(P) || !std::isfinite(P) || P < 0.0) {
        throw ParameterError("contact pressure P", "must be finite and >= 0 Pa");
    }
    checkRoughness(r);
    limits::requireInRange("reduced modulus E'", Eprime, limits::minimumReducedModulus,
                           limits::maximumReducedModulus, "Pa");
    if (P == 0.0) {
        return 0.0;
    }
    const double m = r.meanAbsoluteSlope;
    return mikicCoefficient * (m / r.sigma) * std::pow(std::sqrt(2.0) * P / (Eprime * m), mikicExponent);
}

} // namespace roughContact
