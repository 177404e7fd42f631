// SPDX-License-Identifier: GPL-3.0-or-later
// The unloading table's rule (thermal/UnloadingTable.hpp): at a solved peak and pressure the
// solved value, at the peak the loading value, log ratios linear in ln s and in ln P_max
// between solved points, held beyond them; bad curves refused naming the curve and point.
#include "roughContact/Error.hpp"
#include "roughContact/thermal/UnloadingTable.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace roughContact;

namespace {

// A loading curve of power laws: A = 1e-3 (P/1e6)^0.9, h = 1e4 (P/1e6)^0.95, Y = 1e-6 - 1e-7 ln(P/1e6).
std::array<double, 3> loading(double P)
{
    return {1e-3 * std::pow(P / 1e6, 0.9), 1e4 * std::pow(P / 1e6, 0.95), 1e-6 - 1e-7 * std::log(P / 1e6)};
}

// A curve from `peak` at the fractions 0.5, 0.1, 0.01 whose values are the loading ones times
// the given ratios (area, h, Y) at each fraction.
UnloadingCurve curve(double peak, const std::array<std::array<double, 3>, 3>& ratios)
{
    UnloadingCurve c;
    c.peak = peak;
    const double s[3] = {0.01, 0.1, 0.5};
    for (int k = 0; k < 3; ++k) {
        const double P = s[k] * peak;
        const std::array<double, 3> v = loading(P);
        c.pressures.push_back(P);
        c.areaFractions.push_back(v[0] * ratios[k][0]);
        c.conductancesPerConductivity.push_back(v[1] * ratios[k][1]);
        c.separations.push_back(v[2] * ratios[k][2]);
    }
    return c;
}

UnloadingTable twoPeaks()
{
    return UnloadingTable({curve(1e6, {{{3.0, 1.6, 0.5}, {2.0, 1.5, 0.7}, {1.2, 1.1, 0.9}}}),
                           curve(1e7, {{{6.0, 2.5, 0.4}, {4.0, 2.0, 0.6}, {1.5, 1.3, 0.8}}})},
                          loading);
}

} // namespace

TEST(UnloadingTable, WithoutCurvesOrAtThePeakAJointIsOnItsLoadingCurve)
{
    const UnloadingFactors none = UnloadingTable().factors(1e5, 1e7);
    EXPECT_EQ(none.areaFraction, 1.0);
    EXPECT_EQ(none.conductancePerConductivity, 1.0);
    EXPECT_EQ(none.separation, 1.0);
    const UnloadingTable t = twoPeaks();
    for (double P : {1e6, 3e6, 1e7, 2e7}) {
        const UnloadingFactors f = t.factors(P, P); // at the peak
        EXPECT_EQ(f.conductancePerConductivity, 1.0) << P;
        EXPECT_EQ(t.factors(2 * P, P).conductancePerConductivity, 1.0) << P; // above it: loading on
    }
    EXPECT_EQ(t.factors(0.0, 1e7).conductancePerConductivity, 1.0); // apart
    EXPECT_EQ(t.factors(-1.0, 1e7).areaFraction, 1.0);
}

TEST(UnloadingTable, AtASolvedPeakAndPressureTheSolvedValue)
{
    const UnloadingTable t = twoPeaks();
    EXPECT_NEAR(t.factors(1e5, 1e7).conductancePerConductivity, 2.5, 1e-12);
    EXPECT_NEAR(t.factors(1e5, 1e7).areaFraction, 6.0, 1e-12);
    EXPECT_NEAR(t.factors(1e5, 1e7).separation, 0.4, 1e-12);
    EXPECT_NEAR(t.factors(5e5, 1e6).conductancePerConductivity, 1.1, 1e-12);
    EXPECT_NEAR(t.factors(1e5, 1e6).areaFraction, 2.0, 1e-12);
}

TEST(UnloadingTable, LogRatiosAreLinearInLogFractionAndLogPeak)
{
    const UnloadingTable t = twoPeaks();
    // Between 0.1 and 0.5 of the upper peak, at the geometric mean: the geometric mean ratio.
    const double s = std::sqrt(0.1 * 0.5);
    EXPECT_NEAR(t.factors(s * 1e7, 1e7).conductancePerConductivity, std::sqrt(2.0 * 1.3), 1e-12);
    // Between 0.5 and the peak: towards 1.
    EXPECT_NEAR(t.factors(std::sqrt(0.5) * 1e7, 1e7).conductancePerConductivity, std::sqrt(1.3), 1e-12);
    // At the geometric mean of the peaks, at s = 0.1: the geometric mean of the two curves'.
    const double peak = std::sqrt(1e6 * 1e7);
    EXPECT_NEAR(t.factors(0.1 * peak, peak).conductancePerConductivity, std::sqrt(1.5 * 2.0), 1e-12);
    EXPECT_NEAR(t.factors(0.1 * peak, peak).areaFraction, std::sqrt(2.0 * 4.0), 1e-12);
    // A third of the way in ln P_max.
    const double third = std::pow(10.0, 6.0 + 1.0 / 3.0);
    EXPECT_NEAR(t.factors(0.01 * third, third).conductancePerConductivity,
                std::exp(std::log(1.6) + (std::log(2.5) - std::log(1.6)) / 3.0), 1e-12);
}

TEST(UnloadingTable, HeldBeyondThePeaksAndBelowTheLowestFraction)
{
    const UnloadingTable t = twoPeaks();
    EXPECT_NEAR(t.factors(1e3, 1e6).conductancePerConductivity, 1.6, 1e-12);   // s = 1e-3 < 0.01
    EXPECT_NEAR(t.factors(1e4, 1e5).conductancePerConductivity, 1.5, 1e-12);   // P_max below the first peak
    EXPECT_NEAR(t.factors(1e7, 1e8).conductancePerConductivity, 2.0, 1e-12);   // above the last
    EXPECT_NEAR(t.factors(1e5, 1e9).conductancePerConductivity, 2.5, 1e-12);   // both
}

TEST(UnloadingTable, BadCurvesAreRefusedNamingThem)
{
    const auto refused = [](std::vector<UnloadingCurve> curves, const char* what) {
        try {
            UnloadingTable t(std::move(curves), loading);
            ADD_FAILURE() << "accepted: " << what;
        } catch (const ParameterError& e) {
            EXPECT_NE(std::string(e.what()).find("unloading curve"), std::string::npos) << e.what();
        }
    };
    const UnloadingCurve good = curve(1e6, {{{3.0, 1.6, 0.5}, {2.0, 1.5, 0.7}, {1.2, 1.1, 0.9}}});
    refused({good, good}, "peaks not increasing");
    UnloadingCurve c = good;
    c.pressures[2] = 1e6;
    refused({c}, "a pressure at the peak");
    c = good;
    std::swap(c.pressures[0], c.pressures[1]);
    refused({c}, "pressures not increasing");
    c = good;
    c.areaFractions[1] = 1.5;
    refused({c}, "area above 1");
    c = good;
    c.conductancesPerConductivity[0] = std::nan("");
    refused({c}, "NaN h");
    c = good;
    c.separations[0] = -1e-9;
    refused({c}, "negative separation");
    c = good;
    c.separations.pop_back();
    refused({c}, "a short column");
    c = good;
    c.peak = 0.0;
    refused({c}, "peak 0");
    c = good;
    c.pressures.clear();
    c.areaFractions.clear();
    c.conductancesPerConductivity.clear();
    c.separations.clear();
    refused({c}, "no points");
}
