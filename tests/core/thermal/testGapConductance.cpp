// SPDX-License-Identifier: GPL-3.0-or-later
// The gas-gap and radiation conductances (thermal/GapConductance.hpp) and the gas table
// (thermal/Gas.hpp). Every expected number is written out from the formula and the tabulated
// source numbers, computed independently (python3, double precision), never by the code under
// test.
#include "ExpectParameterError.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/thermal/GapConductance.hpp"
#include "roughContact/thermal/Gas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace roughContact;

namespace {

constexpr double roundOff = 1e-12;
const double notANumber = std::numeric_limits<double>::quiet_NaN();
const double infinity = std::numeric_limits<double>::infinity();

GasGap airGap(double pressure = 101325.0)
{
    GasGapSpec spec;
    spec.gas = gasByName("air");
    spec.pressure = pressure;
    return GasGap(spec);
}

} // namespace

TEST(GapGas, AirTableEntryFromItsSources)
{
    const GasProperties air = gasByName("air");
    EXPECT_EQ(air.name, "air");
    // CRC table: 26.2 mW/(m K) at 300 K, 33.3 at 400 K; n = ln(33.3/26.2)/ln(4/3).
    EXPECT_DOUBLE_EQ(air.conductivity, 0.0262);
    EXPECT_NEAR(air.conductivityExponent, 0.8335520673070103, roundOff);
    EXPECT_DOUBLE_EQ(air.referenceTemperature, 300.0);
    EXPECT_DOUBLE_EQ(air.referencePressure, 101325.0);
    EXPECT_DOUBLE_EQ(air.heatCapacityRatio, 1.4);
    // Karniadakis et al. Table 1.1: Pr = 1.85e-5 * 1004.5 / 0.0261; Lambda = 61.11 nm * 300/298.
    EXPECT_NEAR(air.prandtl, 0.7120019157088122, roundOff);
    EXPECT_NEAR(air.meanFreePath, 6.152013422818792e-08, roundOff * 6.152e-8);
    EXPECT_DOUBLE_EQ(air.accommodation, 0.9);
}

TEST(GapGas, PowerLawReproducesTheTablesSecondPoint)
{
    // The exponent is the power law through the table's 300 K and 400 K values, so k_g(400 K)
    // is the table's 400 K value: air 0.0333, helium 0.1906, argon 0.0226, nitrogen 0.0323.
    const char* names[] = {"air", "helium", "argon", "nitrogen"};
    const double k400[] = {0.0333, 0.1906, 0.0226, 0.0323};
    for (int i = 0; i < 4; ++i) {
        GasGapSpec spec;
        spec.gas = gasByName(names[i]);
        const GasGap gap(spec);
        EXPECT_NEAR(gap.conductivity(400.0), k400[i], roundOff * k400[i]) << names[i];
        EXPECT_NEAR(gap.conductivity(300.0), spec.gas.conductivity, roundOff) << names[i];
    }
}

TEST(GapGas, EveryTabulatedGasPassesItsOwnCheck)
{
    ASSERT_EQ(gasNames().size(), 4u);
    for (const std::string& name : gasNames()) {
        const GasProperties g = gasByName(name);
        EXPECT_EQ(g.name, name);
        EXPECT_NO_THROW(checkGas(g)) << name;
    }
}

TEST(GapGas, UnknownGasListsTheFourNames)
{
    try {
        gasByName("xenon");
        ADD_FAILURE() << "no ParameterError for an unknown gas";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "gas");
        const std::string what = e.what();
        for (const char* name : {"xenon", "air", "helium", "argon", "nitrogen"}) {
            EXPECT_NE(what.find(name), std::string::npos) << name << " missing from: " << what;
        }
    }
    expectParameterError([] { gasByName("Air"); }, "gas"); // exact, lower case
    expectParameterError([] { gasByName(""); }, "gas");
}

TEST(GapGas, EveryBadFieldIsNamed)
{
    const GasProperties air = gasByName("air");
    auto bad = [&](auto edit, const std::string& entry) {
        GasProperties g = air;
        edit(g);
        expectParameterError([&] { checkGas(g); }, entry);
        GasGapSpec spec;
        spec.gas = g;
        expectParameterError([&] { GasGap{spec}; }, entry);
    };
    for (double v : {0.0, -1.0, notANumber, infinity}) {
        bad([v](GasProperties& g) { g.conductivity = v; }, "gas conductivity k_g");
        bad([v](GasProperties& g) { g.conductivityExponent = v; }, "gas conductivity exponent");
        bad([v](GasProperties& g) { g.referenceTemperature = v; }, "gas reference temperature T0");
        bad([v](GasProperties& g) { g.heatCapacityRatio = v; }, "gas heat capacity ratio gamma");
        bad([v](GasProperties& g) { g.prandtl = v; }, "gas Prandtl number Pr");
        bad([v](GasProperties& g) { g.meanFreePath = v; }, "gas mean free path Lambda0");
        bad([v](GasProperties& g) { g.referencePressure = v; }, "gas reference pressure P0");
        bad([v](GasProperties& g) { g.accommodation = v; }, "gas accommodation coefficient");
    }
    bad([](GasProperties& g) { g.heatCapacityRatio = 1.0; }, "gas heat capacity ratio gamma"); // gamma > 1
    bad([](GasProperties& g) { g.heatCapacityRatio = 0.9; }, "gas heat capacity ratio gamma");
    bad([](GasProperties& g) { g.accommodation = 1.01; }, "gas accommodation coefficient");
    bad([](GasProperties& g) { g.conductivityExponent = 3.0; }, "gas conductivity exponent");
    // The boundaries that are accepted.
    GasProperties edge = air;
    edge.accommodation = 1.0;
    EXPECT_NO_THROW(checkGas(edge));
}

TEST(GapConductance, RarefactionOfAirAtOneAtmosphere)
{
    // a1 = a2 = 0.9: alpha = 2 (2 - 0.9)/0.9 = 2.444444; beta = (2 * 1.4/2.4)/Pr
    // = 1.1666667/0.7120019 = 1.6385724; Lambda(300 K) = 61.11 nm * 300/298 = 61.520134 nm;
    // M = 2.444444 * 1.6385724 * 61.520134 nm = 0.24641269 um.
    const GasGap gap = airGap();
    EXPECT_NEAR(gap.meanFreePath(300.0), 6.152013422818792e-08, roundOff * 6.152e-8);
    EXPECT_NEAR(gap.rarefaction(300.0), 2.464126919520601e-07, roundOff * 2.464e-7);
    // At 288 K: Lambda = 59.059329 nm, M = 0.23655618 um (M ~ T at fixed P_g).
    EXPECT_NEAR(gap.rarefaction(288.0), 2.3655618427397773e-07, roundOff * 2.366e-7);
    // The accommodation coefficients given replace the default: a1 = a2 = 1 gives alpha = 2.
    GasGapSpec spec = gap.spec();
    spec.accommodation1 = 1.0;
    spec.accommodation2 = 1.0;
    EXPECT_NEAR(GasGap(spec).rarefaction(300.0), 2.0 * 1.6385723702796875 * 6.152013422818792e-08,
                roundOff * 2.02e-7);
    EXPECT_DOUBLE_EQ(*gap.spec().accommodation1, 0.9); // the default filled in
    EXPECT_DOUBLE_EQ(*gap.spec().accommodation2, 0.9);
}

TEST(GapConductance, HeliumRarefactionIsTenTimesAirs)
{
    // a = 0.4: alpha = 2 * 1.6/0.4 = 8; beta = (2 (5/3)/(8/3))/Pr = 1.25/0.694311 = 1.8003745;
    // Lambda = 176.51 nm * 300/298 = 177.69463 nm; M = 2.5592945 um.
    GasGapSpec spec;
    spec.gas = gasByName("helium");
    EXPECT_NEAR(GasGap(spec).rarefaction(300.0), 2.559294478590765e-06, roundOff * 2.56e-6);
}

TEST(GapConductance, ContinuumLimit)
{
    // Y = 1 mm >> M = 0.2464 um: h_g = 0.0262/(1e-3 + 2.4641269e-7) = 26.193546 W/(m^2 K),
    // k_g/Y = 26.2 to within M/Y = 2.5e-4.
    const GasGap gap = airGap();
    const double h = gap.conductance(1e-3, 300.0);
    EXPECT_NEAR(h, 26.19354557792238, roundOff * 26.2);
    EXPECT_NEAR(h / (0.0262 / 1e-3), 1.0, 2.5e-4);
}

TEST(GapConductance, FreeMolecularLimit)
{
    // Y = 0: h_g = k_g/M = 0.0262/2.4641269e-7 = 106325.69 W/(m^2 K).
    const GasGap gap = airGap();
    EXPECT_NEAR(gap.conductance(0.0, 300.0), 106325.69204307561, roundOff * 1.06e5);
    // Y = 1 nm << M: within Y/M = 0.4% of k_g/M.
    EXPECT_NEAR(gap.conductance(1e-9, 300.0) / 106325.69204307561, 1.0, 1e-9 / 2.464e-7);
    // In the free-molecular limit h_g is proportional to the gas pressure.
    const GasGap thin = airGap(101325.0 / 100.0);
    EXPECT_NEAR(thin.conductance(0.0, 300.0), 1063.2569204307561, roundOff * 1.06e3);
}

TEST(GapConductance, MeanFreePathDoublesWhenPressureHalves)
{
    const GasGap full = airGap(101325.0);
    const GasGap half = airGap(101325.0 / 2.0);
    EXPECT_NEAR(half.meanFreePath(300.0), 2.0 * 6.152013422818792e-08, roundOff * 1.23e-7);
    EXPECT_NEAR(half.rarefaction(350.0) / full.rarefaction(350.0), 2.0, roundOff);
    // and grows as T at fixed pressure.
    EXPECT_NEAR(full.meanFreePath(600.0) / full.meanFreePath(300.0), 2.0, roundOff);
}

TEST(GapConductance, BadGapInputsAreNamed)
{
    GasGapSpec spec;
    spec.gas = gasByName("air");
    for (double v : {0.0, -1.0, notANumber, infinity, 1e-11, 1e10}) {
        GasGapSpec s = spec;
        s.pressure = v;
        expectParameterError([&] { GasGap{s}; }, "gas pressure P_g");
    }
    // 0 is an error like any other value outside (0, 1]: "the gas's default" is an unset
    // coefficient (issue 18, item 15: 0 and 1e-300 were taken as the default).
    for (double v : {-0.5, 1.5, notANumber, infinity, 1e-9, 0.0, 1e-300}) {
        GasGapSpec s = spec;
        s.accommodation1 = v;
        expectParameterError([&] { GasGap{s}; }, "accommodation coefficient a1");
        s = spec;
        s.accommodation2 = v;
        expectParameterError([&] { GasGap{s}; }, "accommodation coefficient a2");
    }
    const GasGap gap(spec);
    for (double T : {0.0, -300.0, notANumber, infinity, 1e6}) {
        expectParameterError([&] { gap.conductivity(T); }, "gas temperature T");
        expectParameterError([&] { gap.meanFreePath(T); }, "gas temperature T");
        expectParameterError([&] { gap.rarefaction(T); }, "gas temperature T");
        expectParameterError([&] { gap.conductance(1e-6, T); }, "gas temperature T");
    }
    for (double Y : {-1e-9, notANumber, infinity, 1e4}) {
        expectParameterError([&] { gap.conductance(Y, 300.0); }, "gap separation Y");
    }
}

TEST(GapRadiation, BlackBodiesAtOneTemperature)
{
    // h_r = sigma (2 T^2)(2 T) = 4 sigma T^3 = 4 * 5.670374419e-8 * 300^3 = 6.12400437252.
    EXPECT_NEAR(radiativeConductance(300.0, 300.0, 1.0, 1.0), 6.12400437252, roundOff * 6.124);
    // e1 = e2 = 0.5: 1/(2 + 2 - 1) = 1/3 of black.
    EXPECT_NEAR(radiativeConductance(300.0, 300.0, 0.5, 0.5), 6.12400437252 / 3.0, roundOff * 2.04);
}

TEST(GapRadiation, UnequalTemperaturesAndEmissivities)
{
    // sigma (300^2 + 400^2)(300 + 400) = 5.670374419e-8 * 250000 * 700 = 9.92315523325;
    // e = 0.8 and 0.5: / (1.25 + 2 - 1) = 4.41029121478.
    EXPECT_NEAR(radiativeConductance(300.0, 400.0, 1.0, 1.0), 9.92315523325, roundOff * 9.92);
    EXPECT_NEAR(radiativeConductance(400.0, 300.0, 0.8, 0.5), 4.410291214777778, roundOff * 4.41);
    // Tiny emissivities stay finite and accurate (no 1/e, no underflowing e1 e2):
    // e1 = e2 = 1e-300 gives 1/(2e300 - 1) = 0.5e-300 of black; e1 = 1, e2 = 1e-310 gives 1e-310.
    EXPECT_NEAR(radiativeConductance(300.0, 300.0, 1e-300, 1e-300) / (6.12400437252 * 0.5e-300), 1.0,
                roundOff);
    EXPECT_GT(radiativeConductance(300.0, 300.0, 1.0, 1e-310), 0.0);
}

TEST(GapRadiation, BadInputsAreNamed)
{
    for (double T : {0.0, -1.0, notANumber, infinity, 1e6}) {
        expectParameterError([&] { radiativeConductance(T, 300.0, 0.5, 0.5); }, "temperature T1");
        expectParameterError([&] { radiativeConductance(300.0, T, 0.5, 0.5); }, "temperature T2");
    }
    for (double e : {0.0, -0.1, 1.01, notANumber, infinity}) {
        expectParameterError([&] { radiativeConductance(300.0, 300.0, e, 0.5); }, "emissivity e1");
        expectParameterError([&] { radiativeConductance(300.0, 300.0, 0.5, e); }, "emissivity e2");
    }
}

TEST(GapSeparation, GaussianFormIsTheNormalQuantile)
{
    // Y/sigma = sqrt(2) erfc^-1(2 P/H_c) is the standard normal quantile of 1 - P/H_c:
    // 1.6448536269514729 at P/H_c = 0.05, 1.2815515655446006 at 0.1, 3.0902323061678136 at 1e-3.
    const double sigma = 2e-6, Hc = 3e9;
    EXPECT_NEAR(gapSeparationGaussian(0.05 * Hc, sigma, Hc), 1.6448536269514729 * sigma, 1e-10 * sigma);
    EXPECT_NEAR(gapSeparationGaussian(0.1 * Hc, sigma, Hc), 1.2815515655446006 * sigma, 1e-10 * sigma);
    EXPECT_NEAR(gapSeparationGaussian(1e-3 * Hc, sigma, Hc), 3.0902323061678136 * sigma, 1e-10 * sigma);
    // Half the area in contact: the mean planes meet; beyond, the gap stays closed.
    EXPECT_EQ(gapSeparationGaussian(0.5 * Hc, sigma, Hc), 0.0);
    EXPECT_EQ(gapSeparationGaussian(2.0 * Hc, sigma, Hc), 0.0);
    EXPECT_EQ(gapSeparationGaussian(1e300, sigma, limits::minimumHardness), 0.0); // P far above H_c
    // Vanishing pressure: P/H_c is taken as 1e-300 at least, Y/sigma = 37.047096.
    EXPECT_NEAR(gapSeparationGaussian(1e-320, sigma, 1e10), 37.04709629936121 * sigma, 1e-8 * sigma);
}

TEST(GapSeparation, CorrelationAgainstGaussianForm)
{
    const double sigma = 1e-6, Hc = 2e9;
    // Hand values of the fit: 1.184 (-ln(3.132e-3))^0.547 = 3.087120414135807 at P/H_c = 1e-3,
    // 1.184 (-ln(0.3132))^0.547 = 1.2846865838844015 at 0.1 (the upper end of its use).
    EXPECT_NEAR(gapSeparationCorrelation(1e-3 * Hc, sigma, Hc), 3.087120414135807 * sigma, 1e-10 * sigma);
    EXPECT_NEAR(gapSeparationCorrelation(0.1 * Hc, sigma, Hc), 1.2846865838844015 * sigma, 1e-10 * sigma);
    // Within 1% of the exact form over the range it is used on, 1e-6 <= P/H_c <= 0.1 (measured
    // largest deviation +0.90% near 0.05).
    for (double lg = -6.0; lg <= -1.0 + 1e-12; lg += 0.05) {
        const double P = std::pow(10.0, lg) * Hc;
        const double ratio = gapSeparationCorrelation(P, sigma, Hc) / gapSeparationGaussian(P, sigma, Hc);
        EXPECT_NEAR(ratio, 1.0, 0.01) << "P/H_c = " << P / Hc;
    }
    // Outside it, the exact form: at 0.2 the fit would be 7% low (0.7814 vs 0.8416), at 0.3 half
    // the exact value, past 1/3.132 a NaN; below 1e-6 the exact form too.
    for (double x : {0.2, 0.3, 0.319, 0.32, 0.4, 0.5, 0.9, 1.0, 5.0, 1e-7, 1e-20, 1e-310}) {
        EXPECT_EQ(gapSeparationCorrelation(x * Hc, sigma, Hc), gapSeparationGaussian(x * Hc, sigma, Hc))
            << "P/H_c = " << x;
    }
    EXPECT_NEAR(gapSeparationCorrelation(0.2 * Hc, sigma, Hc), 0.8416212335729141 * sigma, 1e-10 * sigma);
}

TEST(GapSeparation, BadInputsAreNamed)
{
    for (auto f : {&gapSeparationCorrelation, &gapSeparationGaussian}) {
        for (double v : {0.0, -1.0, notANumber, infinity}) {
            expectParameterError([&] { f(v, 1e-6, 3e9); }, "contact pressure P");
            expectParameterError([&] { f(1e6, v, 3e9); }, "rms roughness sigma");
            expectParameterError([&] { f(1e6, 1e-6, v); }, "microhardness H_c");
        }
    }
}

TEST(GapConductance, StefanBoltzmannConstant)
{
    // CODATA 2018 (exact in the 2019 SI): 2 pi^5 k_B^4/(15 h^3 c^2) with k_B = 1.380649e-23,
    // h = 6.62607015e-34, c = 299792458 gives 5.670374419...e-8.
    const double pi = std::acos(-1.0);
    const double kB = 1.380649e-23, h = 6.62607015e-34, c = 299792458.0;
    EXPECT_NEAR(stefanBoltzmann, 2.0 * std::pow(pi, 5) * std::pow(kB, 4) / (15.0 * h * h * h * c * c),
                1e-9 * stefanBoltzmann);
}

TEST(GapConductance, FiniteAtTheCornersOfTheAcceptedRanges)
{
    // Every accepted extreme at once, with the traps on (overflow, invalid, division by zero): each
    // result finite and > 0 (an underflow towards 0 is allowed, as OpenFOAM does not trap it).
    for (double k : {limits::minimumGasConductivity, limits::maximumGasConductivity}) {
        for (double n : {1e-300, limits::maximumConductivityExponent}) {
            for (double Pr : {limits::minimumPrandtl, limits::maximumPrandtl}) {
                for (double a : {limits::minimumAccommodation, 1.0}) {
                    for (double Pg : {1e-10, 1e9}) {
                        GasGapSpec spec;
                        spec.gas = {"user", k, n, 1e-2, 10.0, Pr, 1e3, 1e-10, a};
                        spec.pressure = Pg;
                        const GasGap gap(spec);
                        for (double T : {1e-2, 1e5}) {
                            for (double Y : {0.0, 1e3}) {
                                const double h = gap.conductance(Y, T);
                                EXPECT_TRUE(std::isfinite(h) && h >= 0.0) << h;
                            }
                            EXPECT_TRUE(std::isfinite(gap.rarefaction(T)));
                        }
                    }
                }
            }
        }
    }
    for (double T1 : {1e-2, 1e5}) {
        for (double e : {1e-320, 1.0}) {
            const double h = radiativeConductance(T1, 1e5, e, 1.0);
            EXPECT_TRUE(std::isfinite(h) && h >= 0.0) << h;
        }
    }
    for (double sigma : {1e-15, 1e3}) {
        for (double P : {1e-320, 1.0, 1e308}) {
            for (double Hc : {limits::minimumHardness, 1e9, limits::maximumHardness}) {
                EXPECT_TRUE(std::isfinite(gapSeparationCorrelation(P, sigma, Hc)));
                EXPECT_TRUE(std::isfinite(gapSeparationGaussian(P, sigma, Hc)));
            }
        }
    }
}
