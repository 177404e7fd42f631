// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/CooperMikicYovanovich.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>

namespace roughContact {

namespace {
// Yovanovich (1981) fit of the Cooper-Mikic-Yovanovich model: coefficient and exponent.
constexpr double cmyCoefficient = 1.25;
constexpr double cmyExponent = 0.95;

void checkPressure(double P, const char* what)
{
    if (std::isnan(P) || !std::isfinite(P) || P < 0.0) {
        throw ParameterError(what, "must be finite and >= 0");
    }
}
} // namespace

double cooperMikicYovanovichFromRelativePressure(double relativePressure, const SurfaceRoughness& r)
{
    checkPressure(relativePressure, "relative contact pressure P/H_c");
    checkRoughness(r);
    if (relativePressure == 0.0) {
        return 0.0;
    }
    return cmyCoefficient * (r.meanAbsoluteSlope / r.sigma) * std::pow(relativePressure, cmyExponent);
}

double cooperMikicYovanovichConductancePerConductivity(double P, const SurfaceRoughness& r, double Hc)
{
    checkPressure(P, "contact pressure P");
    limits::requireInRange("microhardness H_c", Hc, limits::minimumHardness, limits::maximumHardness, "Pa");
    return cooperMikicYovanovichFromRelativePressure(P / Hc, r);
}

double cooperMikicYovanovichConductancePerConductivity(double P, const SurfaceRoughness& r,
                                                       const VickersCoefficients& vickers)
{
    return cooperMikicYovanovichFromRelativePressure(relativeContactPressure(P, r, vickers), r);
}

} // namespace roughContact
