// SPDX-License-Identifier: GPL-3.0-or-later
// Jackson-Green elasto-plastic hemisphere against a rigid flat (seed Eqs. 11-19 and §2.2).
#pragma once

#include "roughContact/asperity/SphericalAsperity.hpp"
#include "roughContact/asperity/YieldOnset.hpp"

#include <array>
#include <vector>

namespace roughContact {

/// In w* = w / w_c every quantity is a function of the material only:
/// - w* < 1.9: Hertz, A/A_c = w*, F/F_c = w*^(3/2);
/// - w* >= 1.9: A = pi R w (w / (1.9 w_c))^B (Eq. 15), B = 0.14 exp(23 e_y) (Eq. 17),
///   e_y = S_y / E (Eq. 18),
///   F/F_c = exp(-w*^(5/12)/4) w*^(3/2) + 4 H_G/(C S_y) [1 - exp(-w*^(5/9)/25)] w* (Eq. 16),
///   H_G/S_y = 2.84 [1 - exp(-0.82 (a/R)^-0.7)] (Eq. 19) for a/R <= 0.41 and the cubic of
///   seed §2.2 beyond (value and slope of Eq. 19 at 0.41, value 1 and slope 0 at a/R = 1);
/// - F >= A S_y (seed §2.2, the floor for w > ~5000 w_c);
/// - a/R >= 1: complete contact (seed §2.2).
/// The force jumps by a fraction of a percent at w* = 1.9 while the area is continuous.
class JacksonGreen final : public SphericalAsperity {
public:
    /// Eprime [Pa]; nu, E [Pa] and Sy [Pa] of the material that yields first.
    JacksonGreen(double Eprime, double nu, double E, double Sy);

    std::string name() const override { return "jacksonGreen"; }
    double area(double w, double R) const override;
    double force(double w, double R) const override;
    double areaAtForce(double F, double R) const override;
    /// From the area ratio A/A_c: Hertz below 1.9, else the running-maximum table's force at the
    /// first node at or beyond the interference of that area (so every larger force brackets
    /// at or beyond it), the table's end for complete contact; raised by 1e-12 for rounding.
    double forceBeyondArea(double A, double R) const override;

    const YieldOnset& onset() const noexcept { return onset_; }
    /// B of seed Eq. 17.
    double B() const noexcept { return B_; }
    /// A/A_c at w* (the loading path, capped at complete contact).
    double areaRatio(double wStar) const;
    /// F/F_c at w* including the floor F >= A S_y (capped at complete contact).
    double forceRatio(double wStar) const;
    /// F/F_c of seed Eq. 16 alone (no floor), for w* >= 1.9.
    double forceRatioEq16(double wStar) const;
    /// H_G/S_y at a/R: Eq. 19 up to 0.41, the cubic beyond, 1 from a/R = 1.
    double hardnessRatio(double aOverR) const;
    /// Coefficients c0..c3 of the cubic c0 + c1 x + c2 x^2 + c3 x^3 (x = a/R in [0.41, 1]).
    const std::array<double, 4>& cubic() const noexcept { return cubic_; }
    /// w* at which a/R reaches 1 (complete contact).
    double completeContactInterference() const noexcept { return wStarComplete_; }
    /// Interference ratio w* at the force ratio F/F_c on the loading path.
    double interferenceRatioAtForce(double forceRatio) const;

    static constexpr double elasticLimit = 1.9; ///< w* below which JG is Hertz (seed §2.2)
    static constexpr double cubicStart = 0.41;  ///< a/R beyond which Eq. 19 is replaced

private:
    double forceRatioRaw(double wStar) const;

    YieldOnset onset_;
    double Sy_;
    double B_;
    double floorCoefficient_; ///< A_c S_y / F_c = 3 / (2 C)
    double fourOverC_;        ///< 4 / C of Eq. 16
    double logKappa_;         ///< ln(w_c / R)
    double wStarComplete_;
    std::array<double, 4> cubic_{};
    // Loading-path force ratio at log-spaced w* from 1.9 to complete contact, made
    // non-decreasing (running maximum), to bracket the inversion.
    std::vector<double> tableW_;
    std::vector<double> tableF_;
    std::vector<double> tableRaw_;    ///< forceRatioRaw at tableW_ (before the running maximum)
    std::vector<double> tableLogW_;   ///< ln tableW_
    std::vector<double> tableLogRaw_; ///< ln tableRaw_
};

} // namespace roughContact
