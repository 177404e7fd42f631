// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/Microhardness.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

namespace {
// Song & Yovanovich (1988): the equivalent Vickers diagonal 1.62 sigma/m, the exponent
// 1/(1 + 0.071 c2), and sigma_0 = 1 um.
constexpr double diagonalFactor = 1.62;
constexpr double exponentFactor = 0.071;
constexpr double sigma0 = 1e-6;

void checkPressure(double P)
{
    if (std::isnan(P) || !std::isfinite(P) || P < 0.0) {
        throw ParameterError("contact pressure P", "must be finite and >= 0 Pa");
    }
}
} // namespace

void checkVickersCoefficients(const VickersCoefficients& v)
{
    limits::requireInRange("Vickers coefficient c1", v.c1, limits::minimumHardness, limits::maximumHardness, "Pa");
    if (std::isnan(v.c2) || v.c2 < minimumC2 || v.c2 > maximumC2) {
        std::ostringstream os;
        os << "is " << v.c2 << "; must lie in [" << minimumC2 << ", " << maximumC2
           << "] (published metal fits have c2 < 0)";
        throw ParameterError("Vickers coefficient c2", os.str());
    }
}

double referenceMicrohardness(const SurfaceRoughness& r, const VickersCoefficients& v)
{
    checkRoughness(r);
    checkVickersCoefficients(v);
    const double H0 = v.c1 * std::pow(diagonalFactor * (r.sigma / sigma0) / r.meanAbsoluteSlope, v.c2);
    return requirePositive("microhardness c1 (1.62 sigma'/m)^c2", H0);
}

double relativeContactPressure(double P, const SurfaceRoughness& r, const VickersCoefficients& v)
{
    checkPressure(P);
    const double H0 = referenceMicrohardness(r, v);
    if (P == 0.0) {
        return 0.0;
    }
    return std::pow(P / H0, 1.0 / (1.0 + exponentFactor * v.c2));
}

double microhardness(double P, const SurfaceRoughness& r, const VickersCoefficients& v)
{
    requirePositive("contact pressure P", P);
    const double ratio = relativeContactPressure(P, r, v);
    return requirePositive("microhardness H_c", P / requirePositive("relative contact pressure P/H_c", ratio));
}

} // namespace roughContact
