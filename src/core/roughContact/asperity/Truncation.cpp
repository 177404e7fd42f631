// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/asperity/Truncation.hpp"

#include "roughContact/Constants.hpp"

#include <algorithm>
#include <cmath>

namespace roughContact {

Truncation::Truncation(double Eprime, double nu, double Sy)
    : hertz_(Eprime), onset_(Eprime, nu, Sy), H_(hardnessCoefficient * Sy)
{
}

double Truncation::area(double w, double R) const
{
    return w < onset_.interference(R) ? hertz_.area(w, R) : 2.0 * pi * R * w;
}

double Truncation::force(double w, double R) const
{
    return w < onset_.interference(R) ? hertz_.force(w, R) : H_ * 2.0 * pi * R * w;
}

double Truncation::areaAtForce(double F, double R) const
{
    if (F < onset_.force(R)) {
        return hertz_.areaAtForce(F, R);
    }
    // Plastic branch: w = F / (2 pi R H), held at w_c inside the force jump.
    const double w = std::max(onset_.interference(R), F / (2.0 * pi * R * H_));
    return 2.0 * pi * R * w;
}

double Truncation::forceBeyondArea(double A, double R) const
{
    const double Ac = hertz_.area(onset_.interference(R), R); // the Hertz area at w_c
    if (A < Ac) {
        return hertz_.forceBeyondArea(A, R); // F < F_c, or just above it with area >= 2 A_c
    }
    if (A <= 2.0 * Ac) {
        return (1.0 + 1e-12) * onset_.force(R); // across the jump: from F_c the area is >= 2 A_c
    }
    return (1.0 + 1e-12) * A * H_; // plastic branch: A = F / H
}

} // namespace roughContact
