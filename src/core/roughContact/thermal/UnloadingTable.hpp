// SPDX-License-Identifier: GPL-3.0-or-later
// The unloading curves of a joint that remembers its heaviest load P_max (docs/theory.md §7.6):
// at a few solved peaks P_k, A_r/A_n, h_c/k_s and the mean separation Y at pressures below P_k
// (the exact model's load path, BoundaryElementModel::loadPath), kept as their ratios to the
// loading curve at the same pressure,
//   rho_k(s) = ln(v_unloading(s P_k; P_k) / v_loading(s P_k)),   s = P/P_max in (0, 1],
// rho_k(1) = 0 (at its peak a joint is on its loading curve). A joint at P that has carried
// P_max >= P takes
//   v(P; P_max) = v_loading(P) exp(rho(s, P_max)),
// rho linear in ln s between a curve's points and, between the two solved peaks around P_max,
// linear in the peak's coordinate c(P_max) = -ln(1 - P_max/H) with a cap H (what yielded grows
// with it: ~P_max/H at light peaks, without bound as P_max nears H, where the effect rises
// steeply), ln P_max without one; held at the first and last peak's beyond them, and at a curve's
// lowest fraction below it. At a solved peak and a solved pressure it is that solve's value.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace roughContact {

/// One solved unloading curve: the points of a joint unloaded from `peak` [Pa].
struct UnloadingCurve {
    double peak = 0.0;                               ///< P_max [Pa]
    std::vector<double> pressures;                   ///< [Pa], strictly increasing, each in (0, peak)
    std::vector<double> areaFractions;               ///< A_r/A_n
    std::vector<double> conductancesPerConductivity; ///< h_c/k_s [1/m]
    std::vector<double> separations;                 ///< Y [m]; empty: none
};

/// What an unloaded joint's values are, as factors on its loading values at the same pressure.
struct UnloadingFactors {
    double areaFraction = 1.0;
    double conductancePerConductivity = 1.0;
    double separation = 1.0;
};

class UnloadingTable {
public:
    /// No curves: every factor 1 (a joint without memory).
    UnloadingTable() = default;
    /// curves: peaks strictly increasing and > 0, each curve's pressures as UnloadingCurve says
    /// (at least one), its values finite and > 0 (separations >= 0: a 0 on either curve gives the
    /// factor 1, complete contact having no separation to scale). loading(P) gives the loading
    /// curve's {A_r/A_n, h_c/k_s, Y} at P (Y NaN or 0: the factor 1). ParameterError naming the
    /// curve and point otherwise.
    /// hardness: the cap H [Pa] of the solves (above every peak), which sets the peaks'
    /// coordinate (header); none: ln P_max.
    template <class Loading>
    UnloadingTable(std::vector<UnloadingCurve> curves, const Loading& loading, std::optional<double> hardness = {});

    bool empty() const noexcept { return curves_.empty(); }
    const std::vector<UnloadingCurve>& curves() const noexcept { return curves_; }

    /// The factors at the nominal pressure P [Pa] of a joint that has carried peak [Pa]: 1 when
    /// there are no curves, P <= 0 or P >= peak (loading).
    UnloadingFactors factors(double P, double peak) const;

private:
    struct LogRatios {
        std::vector<double> logFraction; ///< ln s, increasing, ending at 0 (the peak)
        std::vector<double> area, h, separation;
    };
    void check(const std::vector<double>& loadingArea, const std::vector<double>& loadingH,
               const std::vector<double>& loadingSeparation);
    /// c(P) of the header (+inf at and beyond H).
    double coordinate(double peak) const;
    std::vector<UnloadingCurve> curves_;
    std::optional<double> hardness_;
    std::vector<double> peakCoordinates_;
    std::vector<LogRatios> ratios_;
};

template <class Loading>
UnloadingTable::UnloadingTable(std::vector<UnloadingCurve> curves, const Loading& loading,
                               std::optional<double> hardness)
    : curves_(std::move(curves)), hardness_(hardness)
{
    std::vector<double> area, h, separation;
    for (const UnloadingCurve& c : curves_) {
        for (double P : c.pressures) {
            const auto v = loading(P);
            area.push_back(v[0]);
            h.push_back(v[1]);
            separation.push_back(v[2]);
        }
    }
    check(area, h, separation);
}

} // namespace roughContact
