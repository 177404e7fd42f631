// SPDX-License-Identifier: GPL-3.0-or-later
// The coupled mixed condition's arithmetic (thermal/InterfaceCoupling): three resistances in
// series, the same flux on both sides at every iteration, the jump q/h across the interface,
// and the two limits (complete contact = the stock perfect coupling, no contact = adiabatic).
#include "roughContact/Error.hpp"
#include "roughContact/thermal/InterfaceCoupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace roughContact;

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();

struct Face {
    double T;    ///< face temperature
    double flux; ///< kDelta (T_f - T_c): heat entering this side's cell through the face
};

Face side(double h, double kDelta, double kDeltaNbr, double Tcell, double TnbrCell)
{
    const double w = coupledValueFraction(h, kDelta, kDeltaNbr);
    const double Tf = mixedFaceTemperature(w, Tcell, TnbrCell);
    return {Tf, kDelta * (Tf - Tcell)};
}
} // namespace

// For random cells, conductances and h over 12 decades: the flux each side receives is the
// series formula and the two sides' fluxes cancel. The flux is kDelta (T_f - T_c), as OpenFOAM
// computes it: T_f carries a rounding of ~1 ulp of 450 K, which kDelta amplifies when the face
// sits close to its cell (w small). Tolerance: 1e-12 relative for the few roundings of the
// formula itself, plus 8 ulps of 450 K times kDelta for that cancellation.
TEST(InterfaceCoupling, bothSidesCarryTheSeriesFluxAtEveryIterate)
{
    std::mt19937_64 rng(2006);
    std::uniform_real_distribution<double> logU(-3.0, 9.0);
    std::uniform_real_distribution<double> temp(250.0, 450.0);
    for (int k = 0; k < 2000; ++k) {
        const double h = std::pow(10.0, logU(rng));
        const double kd1 = std::pow(10.0, logU(rng) / 2 + 2);
        const double kd2 = std::pow(10.0, logU(rng) / 2 + 2);
        const double T1 = temp(rng);
        const double T2 = temp(rng) + 1.0;
        const Face a = side(h, kd1, kd2, T1, T2);
        const Face b = side(h, kd2, kd1, T2, T1);
        const double series = (T2 - T1) / (1 / kd1 + 1 / h + 1 / kd2);
        const double ulp = std::numeric_limits<double>::epsilon() * 450.0;
        ASSERT_NEAR(a.flux, series, 1e-12 * std::abs(series) + 8 * ulp * kd1) << "h " << h;
        ASSERT_NEAR(b.flux, -series, 1e-12 * std::abs(series) + 8 * ulp * kd2) << "h " << h;
        // The interface law itself: the face temperatures jump by q/h. The jump is a
        // difference of two face temperatures, each rounded to ~1 ulp of 450 K.
        const double jump = a.T - b.T;
        ASSERT_NEAR(jump, -series / h, 1e-12 * std::abs(series / h) + 8 * ulp) << "h " << h;
    }
}

TEST(InterfaceCoupling, completeContactIsTheStockPerfectCoupling)
{
    // turbulentTemperatureCoupledBaffleMixed without layers: refValue = neighbour cell,
    // valueFraction = nbrKDelta/(nbrKDelta + myKDelta), bit for bit.
    for (double kd1 : {1.0, 2e3, 7.5e5}) {
        for (double kd2 : {3.0, 4e4}) {
            EXPECT_EQ(coupledValueFraction(inf, kd1, kd2), kd2 / (kd2 + kd1));
            EXPECT_EQ(effectiveConductance(inf, kd2), kd2);
        }
    }
    // Both faces at one temperature, the harmonic-weighted mean of the two cells.
    const Face a = side(inf, 10.0, 30.0, 400.0, 300.0);
    const Face b = side(inf, 30.0, 10.0, 300.0, 400.0);
    EXPECT_NEAR(a.T, b.T, 1e-12);
    EXPECT_NEAR(a.T, (10.0 * 400.0 + 30.0 * 300.0) / 40.0, 1e-12);
}

TEST(InterfaceCoupling, noContactIsAdiabatic)
{
    EXPECT_EQ(coupledValueFraction(0.0, 5.0, 7.0), 0.0);
    const Face a = side(0.0, 5.0, 7.0, 400.0, 300.0);
    EXPECT_EQ(a.flux, 0.0);
    EXPECT_EQ(a.T, 400.0);
}

TEST(InterfaceCoupling, growingConductanceNeverLowersTheCoupling)
{
    double previous = -1.0;
    for (double h = 1e-6; h < 1e15; h *= 1.7) {
        const double w = coupledValueFraction(h, 2e4, 5e4);
        ASSERT_GE(w, previous);
        ASSERT_LE(w, coupledValueFraction(inf, 2e4, 5e4));
        previous = w;
    }
}

TEST(InterfaceCoupling, refusesWhatWouldBecomeANaN)
{
    EXPECT_THROW(coupledValueFraction(-1.0, 1.0, 1.0), ParameterError);
    EXPECT_THROW(coupledValueFraction(std::nan(""), 1.0, 1.0), ParameterError);
    EXPECT_THROW(coupledValueFraction(1.0, 0.0, 1.0), ParameterError);
    EXPECT_THROW(coupledValueFraction(1.0, 1.0, inf), ParameterError);
    EXPECT_THROW(effectiveConductance(1.0, -2.0), ParameterError);
}
