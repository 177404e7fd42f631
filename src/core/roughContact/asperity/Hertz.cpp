// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/asperity/Hertz.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <cmath>

namespace roughContact {

Hertz::Hertz(double Eprime) : Eprime_(requirePositive("reduced modulus E'", Eprime)) {}

double Hertz::area(double w, double R) const
{
    return pi * R * w;
}

double Hertz::force(double w, double R) const
{
    return (4.0 / 3.0) * Eprime_ * std::sqrt(R) * w * std::sqrt(w);
}

double Hertz::areaAtForce(double F, double R) const
{
    const double c = std::cbrt(3.0 * F * R / (4.0 * Eprime_)); // squared after the root: no overflow
    return pi * c * c;                                          // seed Eq. 20
}

double Hertz::forceBeyondArea(double A, double R) const
{
    const double s = A / pi;
    return (1.0 + 1e-12) * 4.0 * Eprime_ / (3.0 * R) * s * std::sqrt(s);
}

double Hertz::interference(double F, double R) const
{
    const double c = std::cbrt(3.0 * F / (4.0 * Eprime_ * std::sqrt(R)));
    return c * c;
}

} // namespace roughContact
