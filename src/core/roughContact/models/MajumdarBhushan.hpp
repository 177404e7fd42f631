// SPDX-License-Identifier: GPL-3.0-or-later
// Majumdar-Bhushan fractal contact (Majumdar & Bhushan, ASME J. Tribol. 113 (1991) 1-11;
// seed §3.1; docs/theory.md §4.4).
#pragma once

#include "roughContact/material/Materials.hpp"

#include "roughContact/models/ContactModel.hpp"
#include "roughContact/surface/FractalFit.hpp"

namespace roughContact {

/// Contact spots of area a (the truncated, real spot area) distributed as
/// n(a) = (D/2) a_L^(D/2) a^(-(D/2+1)) up to the largest spot a_L, so A_r = D a_L/(2-D).
/// A spot is plastic (load H a) below the critical area a_c = G^2/(K phi/2)^(2/(D-1)) and
/// elastic (load (4 sqrt(pi)/3) E G^(D-1) a^((3-D)/2)) above it; phi = S_y/E, H = 2.84 S_y,
/// K = H/S_y (docs/theory.md §4.4). E is MB's composite modulus, i.e. E' here.
class MajumdarBhushan final : public ContactModel {
public:
    /// fractal D in (1, 2), G [m] > 0; nominalArea A_n [m^2]; Eprime [Pa]; Sy [Pa].
    MajumdarBhushan(const FractalParameters& fractal, double nominalArea, double Eprime, double Sy);

    std::string name() const override { return "majumdarBhushan"; }
    /// A_r/A_n at the load F/(A_n E'), capped at 1 (the MB spot sum does not know A_n and
    /// exceeds it at heavy loads; the cap reports complete contact). load 0 gives 0.
    double areaFraction(double load) const override;

    /// Largest spot area a_L [m^2] carrying the total force F [N] (> 0).
    double largestSpot(double F) const;
    /// A_r = D a_L / (2 - D) [m^2] (docs/theory.md §4.4).
    double realArea(double aL) const;
    /// Total force F [N] when the largest spot is a_L [m^2] (docs/theory.md §4.4, closed forms).
    double load(double aL) const;
    /// a_c = G^2 / (K phi/2)^(2/(D-1)) [m^2] (docs/theory.md §4.4).
    double criticalArea() const noexcept { return ac_; }
    /// H = 2.84 S_y [Pa] (seed §3.1).
    double hardness() const noexcept { return H_; }

    const FractalParameters& fractal() const noexcept { return fractal_; }
    double nominalArea() const noexcept { return An_; }
    double reducedModulus() const noexcept { return Eprime_; }
    double yieldStrength() const noexcept { return Sy_; }

    static constexpr double hardnessCoefficient = hardnessPerYieldStrength; ///< H = 2.84 S_y (seed §3.1)

private:
    FractalParameters fractal_;
    double An_;
    double Eprime_;
    double Sy_;
    double H_;
    double logAc_;
    double ac_;
};

} // namespace roughContact
