// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/asperity/YieldOnset.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <cmath>

namespace roughContact {

YieldOnset::YieldOnset(double Eprime, double nu, double Sy)
    : Eprime_(requirePositive("reduced modulus E'", Eprime)),
      Sy_(requirePositive("yield strength S_y", Sy)), C_(1.295 * std::exp(0.736 * nu))
{
    const double s = pi * C_ * Sy_ / (2.0 * Eprime_);
    kappa_ = s * s;
}

double YieldOnset::force(double R) const noexcept
{
    const double q = R / Eprime_;
    const double s = pi * C_ * Sy_ / 2.0;
    return (4.0 / 3.0) * q * q * s * s * s;
}

double YieldOnset::area(double R) const noexcept
{
    const double s = C_ * Sy_ * R / (2.0 * Eprime_);
    return pi * pi * pi * s * s;
}

} // namespace roughContact
