// SPDX-License-Identifier: GPL-3.0-or-later
// Johnson-Greenwood-Higginson: elastic contact of a two-dimensional sinusoidal surface
// (seed Eqs. 6-10; Johnson, Greenwood & Higginson 1985).
#pragma once

#include "roughContact/asperity/AsperityModel.hpp"

namespace roughContact {

/// The level is a sinusoid of amplitude beta and frequency f; pbar = F / A_{i-1}.
/// Complete contact (A_i = A_{i-1}) for pbar >= p*; otherwise, with x = pbar / p*:
///   A1 = (pi / f^2) [3 x / (8 pi)]^(2/3)             (Eq. 7, light load)
///   A2 = (1 / (2 f^2)) (1 - (3 / (2 pi)) (1 - x))      (Eq. 8, near complete)
///   Abar = A1 (1 - x^1.51) + A2 x^1.04 for x < 0.8     (Eq. 9), Abar = A2 for x >= 0.8 (Eq. 10)
/// and A_i = N_i Abar with N_i = eta_i A_{i-1}, eta_i = 2 f^2.
///
/// Two forms (docs/theory.md §3.2):
/// - Form::seed (`jgh`, the default): p* = 2 pi E' beta f (Eq. 6) and Eq. 7 per asperity, as
///   the seed writes them. Its light-load limit is 2^(2/3) = 1.59 x Hertz, and Eq. 9 at
///   x = 0.8 exceeds Eq. 10 by 21 % (the area drops as the load crosses 0.8 p*).
/// - Form::consistent (`jghConsistent`): the JGH surface z = beta [1 - cos(2 pi f x)
///   cos(2 pi f y)] has p* = sqrt(2) pi E' beta f and two asperities per wavelength cell, so
///   Eq. 7 is the area of a cell and half of it belongs to one asperity. Then the light-load
///   limit equals Hertz with R of Eq. 5 exactly, and Eq. 9 meets Eq. 10 near x = 0.8 to
///   0.05 %. The switch from Eq. 9 to Eq. 10 is moved from 0.8 to where the two cross
///   (x_s = 0.796), so the law is continuous and never decreases with pressure.
class JohnsonGreenwoodHigginson final : public AsperityModel {
public:
    enum class Form { seed, consistent };

    JohnsonGreenwoodHigginson(double Eprime, Form form = Form::seed);

    std::string name() const override;
    bool yields() const override { return false; } // elastic sinusoids
    double areaRatio(double pbar, const Level& level) const override;

    /// p* for the level (Eq. 6, or sqrt(2) pi E' beta f in the consistent form); from p* on
    /// areaRatio is 1 exactly.
    double completeContactPressure(const Level& level) const override;
    /// eta * Abar as a function of x = pbar/p* alone (x < 1).
    double areaRatioAt(double x) const;

    /// Eq. 9 below, Eq. 10 from here: 0.8 (seed), or x_s in the consistent form.
    double blendSwitch() const noexcept { return switch_; }

    static constexpr double blendLimit = 0.8; ///< the seed's switch

private:
    double eq9(double x) const;
    double eq10(double x) const;

    double Eprime_;
    Form form_;
    double switch_ = blendLimit;
};

} // namespace roughContact
