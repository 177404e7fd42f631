// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/asperity/JohnsonGreenwoodHigginson.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>

namespace roughContact {

JohnsonGreenwoodHigginson::JohnsonGreenwoodHigginson(double Eprime, Form form)
    : Eprime_(requirePositive("reduced modulus E'", Eprime)), form_(form)
{
    if (form_ == Form::consistent) {
        // Eq. 9 - Eq. 10 changes sign once in [0.7, 0.8] (it is -0.015 at 0.7, +4e-4 at 0.8).
        std::uintmax_t iterations = 100;
        const auto gap = [this](double x) { return eq9(x) - eq10(x); };
        const auto r = boost::math::tools::toms748_solve(
            gap, 0.7, blendLimit, boost::math::tools::eps_tolerance<double>(52), iterations);
        switch_ = 0.5 * (r.first + r.second);
    }
}

std::string JohnsonGreenwoodHigginson::name() const
{
    return form_ == Form::seed ? "jgh" : "jghConsistent";
}

double JohnsonGreenwoodHigginson::completeContactPressure(const Level& level) const
{
    const double c = form_ == Form::seed ? 2.0 * pi : std::sqrt(2.0) * pi;
    return c * Eprime_ * level.amplitude * level.frequency;
}

// Areas in units of the asperity cell 1/eta = 1/(2 f^2), so eta * Abar is dimensionless.
double JohnsonGreenwoodHigginson::eq10(double x) const
{
    return 1.0 - 3.0 / (2.0 * pi) * (1.0 - x); // Eq. 8 (= Eq. 10)
}

double JohnsonGreenwoodHigginson::eq9(double x) const
{
    const double perCell = form_ == Form::seed ? 1.0 : 0.5;
    const double a1 = perCell * 2.0 * pi * std::cbrt(std::pow(3.0 * x / (8.0 * pi), 2.0)); // Eq. 7
    return a1 * (1.0 - std::pow(x, 1.51)) + eq10(x) * std::pow(x, 1.04);                // Eq. 9
}

double JohnsonGreenwoodHigginson::areaRatioAt(double x) const
{
    return x < switch_ ? eq9(x) : eq10(x);
}

double JohnsonGreenwoodHigginson::areaRatio(double pbar, const Level& level) const
{
    const double pstar = completeContactPressure(level);
    if (!(pbar < pstar)) {
        return 1.0; // complete contact (seed §2.2)
    }
    return areaRatioAt(pbar / pstar);
}

} // namespace roughContact
