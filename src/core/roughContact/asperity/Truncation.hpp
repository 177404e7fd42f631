// SPDX-License-Identifier: GPL-3.0-or-later
// Hertz up to the critical interference, then the fully plastic truncation model
// (seed §3.1; Abbott & Firestone; docs/theory.md §3.5).
#pragma once

#include "roughContact/material/Materials.hpp"

#include "roughContact/asperity/Hertz.hpp"
#include "roughContact/asperity/YieldOnset.hpp"

namespace roughContact {

/// w < w_c: Hertz. w >= w_c: A = 2 pi R w, F = H A with H = 2.84 S_y.
/// At w_c the area doubles and the force jumps (by 8.52/C, about 5x for nu = 0.32); on the
/// loading path the interference stays at w_c while the load crosses the jump, so the area
/// jumps from pi R w_c to 2 pi R w_c at F = F_c and then grows as F/H.
class Truncation final : public SphericalAsperity {
public:
    Truncation(double Eprime, double nu, double Sy);

    std::string name() const override { return "truncation"; }
    double area(double w, double R) const override;
    double force(double w, double R) const override;
    double areaAtForce(double F, double R) const override;
    /// Hertz below A_c, F_c up to 2 A_c (the jump), A H beyond (H = 2.84 S_y, seed §3.1);
    /// raised by 1e-12 for rounding.
    double forceBeyondArea(double A, double R) const override;

    const YieldOnset& onset() const noexcept { return onset_; }
    double hardness() const noexcept { return H_; }

    static constexpr double hardnessCoefficient = hardnessPerYieldStrength; ///< H = 2.84 S_y (seed §3.1)

private:
    Hertz hertz_;
    YieldOnset onset_;
    double H_;
};

} // namespace roughContact
