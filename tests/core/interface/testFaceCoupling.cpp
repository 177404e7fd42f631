// SPDX-License-Identifier: GPL-3.0-or-later
// The per-face coupling the boundary condition calls once per evaluation (interface/FaceCoupling):
// the rule for the two sides' pressures, the face states, the same numbers as the interface's
// own face() and the mixed-condition arithmetic (bit for bit, cached or not), conservation
// across the two sides, the constant-h mode's stock arithmetic, the finite conductance shown
// for complete contact, the summary's counts and sums, and bad input named by its face.
#include "roughContact/Error.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"
#include "roughContact/thermal/GapConductance.hpp"
#include "roughContact/thermal/InterfaceCoupling.hpp"

#include "SmallBoundaryElementSpec.hpp" // tests/support

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace roughContact;

namespace {
const std::string standin = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";
constexpr double inf = std::numeric_limits<double>::infinity();

InterfaceSpec steelOnCopper()
{
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::profile;
    s.file = standin;
    spec.surfaces = {s};
    spec.side1 = Material{179.52e9, 0.32, 0.2e9};
    spec.side2 = Material{117e9, 0.34, 0.07e9};
    spec.model = "jacksonGreen";
    return spec;
}

const ContactInterface& interface()
{
    static const ContactInterface ci(steelOnCopper());
    return ci;
}

/// One side's arrays, owned, and the inputs pointing into them.
struct Side {
    std::vector<double> P, Pnbr, Tf, TfNbr, TcNbr, k, kNbr, d, dNbr;
    explicit Side(std::size_t n)
        : P(n), Pnbr(n), Tf(n, 300.0), TfNbr(n, 300.0), TcNbr(n, 300.0), k(n, 50.0), kNbr(n, 50.0), d(n, 1e3),
          dNbr(n, 1e3)
    {
    }
    CouplingInputs inputs() const
    {
        CouplingInputs in;
        in.n = P.size();
        in.pressure = P.data();
        in.pressureNbr = Pnbr.data();
        in.faceTemperature = Tf.data();
        in.faceTemperatureNbr = TfNbr.data();
        in.cellTemperatureNbr = TcNbr.data();
        in.kappa = k.data();
        in.kappaNbr = kNbr.data();
        in.deltaCoeffs = d.data();
        in.deltaCoeffsNbr = dNbr.data();
        return in;
    }
    /// The neighbour's view of the same faces.
    Side mirrored(const std::vector<double>& Tcell) const
    {
        Side o(P.size());
        o.P = Pnbr;
        o.Pnbr = P;
        o.Tf = TfNbr;
        o.TfNbr = Tf;
        o.TcNbr = Tcell;
        o.k = kNbr;
        o.kNbr = k;
        o.d = dNbr;
        o.dNbr = d;
        return o;
    }
};
} // namespace

// The rule: the nominal pressure of a face is the mean of the two sides' (so both sides get
// the same h). A change of the rule (one side's pressure, the larger one) fails here.
TEST(FaceCoupling, ThePressureOfAFaceIsTheMeanOfBothSides)
{
    EXPECT_EQ(nominalPressure(2e6, 0.0), 1e6);
    EXPECT_EQ(nominalPressure(0.0, 2e6), 1e6);
    EXPECT_EQ(nominalPressure(3e6, 1e6), 2e6);
    EXPECT_EQ(nominalPressure(-1e6, 1e6), 0.0);
    // Near the largest double the halves are taken first: no overflow (a trap in the tests).
    const double big = std::numeric_limits<double>::max();
    EXPECT_EQ(nominalPressure(big, big), big);

    Side s(3);
    s.P = {2e6, 0.0, 3e6};
    s.Pnbr = {0.0, 2e6, 1e6};
    CouplingCache cache;
    CouplingOutputs out;
    couple(interface(), s.inputs(), cache, out);
    EXPECT_EQ(out.pressure[0], 1e6);
    EXPECT_EQ(out.pressure[1], 1e6);
    EXPECT_EQ(out.pressure[2], 2e6);
    const double ks = harmonicMeanConductivity(50.0, 50.0);
    EXPECT_EQ(out.contactConductance[0], ks * interface().conductancePerConductivity(1e6));
    EXPECT_EQ(out.contactConductance[1], out.contactConductance[0]); // the two sides agree
    EXPECT_EQ(out.contactConductance[2], ks * interface().conductancePerConductivity(2e6));
    EXPECT_NE(out.contactConductance[2], ks * interface().conductancePerConductivity(3e6));
}

// couple() gives what face() and coupledValueFraction() give, bit for bit, whether a face's
// table lookup is fresh or re-used (pressures kept, changed, moved apart and into complete
// contact between calls; conductivities are never cached).
TEST(FaceCoupling, BatchWithCacheEqualsFaceByFace)
{
    const ContactInterface& ci = interface();
    std::size_t n = 500;
    std::mt19937_64 gen(3);
    std::uniform_real_distribution<double> logP(3.0, 9.5); // 1 kPa .. 3 GPa: beyond complete
    std::uniform_real_distribution<double> kU(10.0, 400.0);
    std::uniform_real_distribution<double> dU(1e2, 1e4);
    std::uniform_real_distribution<double> TU(280.0, 420.0);
    Side s(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.P[i] = std::pow(10.0, logP(gen));
        s.Pnbr[i] = std::pow(10.0, logP(gen));
        s.k[i] = kU(gen);
        s.kNbr[i] = kU(gen);
        s.d[i] = dU(gen);
        s.dNbr[i] = dU(gen);
        s.TcNbr[i] = TU(gen);
    }
    s.P[0] = s.Pnbr[0] = 0.0;
    s.P[1] = s.Pnbr[1] = -3e5;
    CouplingCache cache;
    CouplingOutputs out;
    const auto check = [&](const char* when) {
        couple(ci, s.inputs(), cache, out);
        ASSERT_EQ(out.state.size(), s.P.size());
        for (std::size_t i = 0; i < s.P.size(); ++i) {
            const double P = 0.5 * s.P[i] + 0.5 * s.Pnbr[i];
            const FaceContact c = ci.face(P, s.k[i], s.kNbr[i]);
            ASSERT_EQ(out.areaFraction[i], c.areaFraction) << when << ", face " << i;
            ASSERT_EQ(out.contactConductance[i], c.conductance) << when << ", face " << i;
            ASSERT_EQ(out.conductance[i], c.conductance) << when << ", face " << i; // no gap
            ASSERT_EQ(out.gapConductance[i], 0.0);
            ASSERT_EQ(out.radiativeConductance[i], 0.0);
            ASSERT_EQ(out.valueFraction[i],
                      coupledValueFraction(c.conductance, s.k[i] * s.d[i], s.kNbr[i] * s.dNbr[i]))
                << when << ", face " << i;
            ASSERT_EQ(out.refValue[i], s.TcNbr[i]);
            const FaceState expected = P <= 0                              ? FaceState::apart
                                       : P >= ci.completeContactPressure() ? FaceState::complete
                                                                           : FaceState::partial;
            ASSERT_EQ(out.state[i], expected) << when << ", face " << i << ", P " << P;
        }
    };
    check("first call");
    check("everything cached");
    for (std::size_t i = 0; i < n; i += 3) {
        s.P[i] *= 1.5;     // some pressures change,
        s.k[i + 1] = 7;    // some conductivities (never cached),
        s.dNbr[i + 2] = 9; // and cell distances
    }
    s.P[5] = s.Pnbr[5] = 0.0;  // a face comes apart,
    s.P[6] = s.Pnbr[6] = 1e12; // one is pressed into complete contact
    check("after changes");
    for (std::vector<double>* v : {&s.P, &s.Pnbr, &s.k, &s.kNbr, &s.d, &s.dNbr, &s.TcNbr, &s.Tf, &s.TfNbr}) {
        v->resize(n - 10); // a cache of another size starts over
    }
    n -= 10;
    check("fewer faces");
    // Both states appear: the test covers them.
    EXPECT_EQ(out.state[0], FaceState::apart);
    EXPECT_EQ(out.state[6], FaceState::complete);
    EXPECT_EQ(out.conductance[6], inf);
    EXPECT_EQ(out.valueFraction[0], 0.0); // apart: adiabatic
}

// Faces held at the end of a table that maxPressure cut short are beyondTable (written as 1).
TEST(FaceCoupling, BeyondTheTableIsItsOwnState)
{
    InterfaceSpec spec = steelOnCopper();
    spec.maxPressure = 1e6;
    const ContactInterface cut(spec);
    ASSERT_LT(cut.tableEnd(), cut.completeContactPressure());
    Side s(3);
    s.P = {0.5e6, 4e6, 1e13};
    s.Pnbr = s.P;
    CouplingCache cache;
    CouplingOutputs out;
    couple(cut, s.inputs(), cache, out);
    EXPECT_EQ(out.state[0], FaceState::partial);
    EXPECT_EQ(out.state[1], FaceState::beyondTable);
    EXPECT_EQ(out.state[2], FaceState::complete);
    EXPECT_EQ(contactStateCode(FaceState::apart), 0);
    EXPECT_EQ(contactStateCode(FaceState::partial), 1);
    EXPECT_EQ(contactStateCode(FaceState::beyondTable), 1);
    EXPECT_EQ(contactStateCode(FaceState::complete), 2);
}

// Both sides, each coupled from its own view, carry the same flux through every face: the
// series formula (T_c2 - T_c1)/(1/kd1 + 1/h + 1/kd2). Tolerance as testInterfaceCoupling:
// 1e-12 relative for the formula's roundings plus 8 ulps of 450 K times kDelta.
TEST(FaceCoupling, BothSidesCarryTheSameFlux)
{
    const std::size_t n = 200;
    std::mt19937_64 gen(11);
    std::uniform_real_distribution<double> logP(4.0, 8.0);
    std::uniform_real_distribution<double> TU(280.0, 420.0);
    Side a(n);
    std::vector<double> T1(n), T2(n);
    for (std::size_t i = 0; i < n; ++i) {
        a.P[i] = std::pow(10.0, logP(gen));
        a.Pnbr[i] = std::pow(10.0, logP(gen));
        a.k[i] = 15.0 + i % 7;
        a.kNbr[i] = 380.0 - i % 5;
        a.d[i] = 2e3;
        a.dNbr[i] = 5e2 + i;
        T1[i] = TU(gen);
        T2[i] = TU(gen);
    }
    a.TcNbr = T2;
    const Side b = a.mirrored(T1);
    CouplingCache ca, cb;
    CouplingOutputs oa, ob;
    couple(interface(), a.inputs(), ca, oa);
    couple(interface(), b.inputs(), cb, ob);
    const double ulp = std::numeric_limits<double>::epsilon() * 450.0;
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_EQ(oa.conductance[i], ob.conductance[i]) << "face " << i;
        const double kd1 = a.k[i] * a.d[i];
        const double kd2 = a.kNbr[i] * a.dNbr[i];
        const double h = oa.conductance[i];
        ASSERT_GT(h, 0.0);
        const double fluxA = kd1 * (mixedFaceTemperature(oa.valueFraction[i], T1[i], oa.refValue[i]) - T1[i]);
        const double fluxB = kd2 * (mixedFaceTemperature(ob.valueFraction[i], T2[i], ob.refValue[i]) - T2[i]);
        const double series = (T2[i] - T1[i]) / (1 / kd1 + 1 / h + 1 / kd2);
        ASSERT_NEAR(fluxA, series, 1e-12 * std::abs(series) + 8 * ulp * kd1) << "face " << i;
        ASSERT_NEAR(fluxB, -series, 1e-12 * std::abs(series) + 8 * ulp * kd2) << "face " << i;
    }
}

// The constant-h mode is the stock turbulentTemperatureCoupledBaffleMixed with layers:
// refValue = the neighbour's face temperature, w = h/(h + kappa delta).
TEST(FaceCoupling, ConstantHIsTheStockCoupledBaffle)
{
    Side s(4);
    s.k = {1.0, 15.0, 200.0, 400.0};
    s.d = {10.0, 1e3, 2e4, 5e5};
    s.TfNbr = {301.0, 302.5, 350.0, 299.0};
    s.TcNbr = {1.0, 2.0, 3.0, 4.0}; // not used by the constant mode
    CouplingOutputs out;
    const double h = 2500.0;
    coupleConstant(h, s.inputs(), out);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(out.valueFraction[i], h / (h + s.k[i] * s.d[i]));
        EXPECT_EQ(out.refValue[i], s.TfNbr[i]);
        EXPECT_EQ(out.conductance[i], h);
        EXPECT_EQ(out.state[i], FaceState::partial);
    }
    EXPECT_EQ(out.valueFraction[0], 2500.0 / 2510.0);
    EXPECT_THROW(coupleConstant(0.0, s.inputs(), out), ParameterError);
    EXPECT_THROW(coupleConstant(inf, s.inputs(), out), ParameterError);
}

// Complete contact shows the two half-cells' conductance, finite; any other h as it is.
TEST(FaceCoupling, CompleteContactShowsTheHalfCellsConductance)
{
    EXPECT_EQ(shownConductance(inf, 3e4, 6e4), 2e4); // 1/(1/3e4 + 1/6e4)
    EXPECT_EQ(shownConductance(1234.5, 3e4, 6e4), 1234.5);
    EXPECT_EQ(shownConductance(0.0, 3e4, 6e4), 0.0);
}

// The summary's counts and area-weighted sums, by hand on four faces.
TEST(FaceCoupling, SummaryCountsAndWeighsTheFaces)
{
    CouplingOutputs out;
    out.resize(4);
    out.state = {FaceState::apart, FaceState::partial, FaceState::beyondTable, FaceState::complete};
    out.pressure = {0.0, 1e6, 3e6, 5e8};
    out.areaFraction = {0.0, 0.01, 0.02, 1.0};
    out.gapConductance = {10.0, 20.0, 30.0, 0.0};
    out.radiativeConductance = {1.0, 2.0, 3.0, 0.0};
    const std::vector<double> magSf = {1.0, 2.0, 3.0, 4.0};
    const std::vector<double> shown = {0.0, 1e4, 3e4, 2e5};
    CouplingSummary s;
    s.add(out, magSf.data(), shown.data());
    EXPECT_EQ(s.apart, 1U);
    EXPECT_EQ(s.partial, 1U);
    EXPECT_EQ(s.beyondTable, 1U);
    EXPECT_EQ(s.complete, 1U);
    EXPECT_EQ(s.area, 10.0);
    EXPECT_EQ(s.touchingArea, 9.0);
    EXPECT_EQ(s.partialArea, 5.0);
    EXPECT_EQ(s.pressureArea, 2e6 + 9e6 + 2e9);
    EXPECT_DOUBLE_EQ(s.areaFractionArea, 0.02 + 0.06 + 4.0);
    EXPECT_DOUBLE_EQ(s.areaFractionPartialArea, 0.02 + 0.06);
    EXPECT_EQ(s.hTouchingArea, 2e4 + 9e4 + 8e5);
    EXPECT_EQ(s.hPartialArea, 2e4 + 9e4);
    EXPECT_EQ(s.hAllArea, 2e4 + 9e4 + 8e5);
    EXPECT_EQ(s.gapAllArea, 11.0 + 44.0 + 99.0);
    EXPECT_EQ(s.hPartialMin, 1e4);
    EXPECT_EQ(s.hPartialMax, 3e4);
}

// Bad input comes back as a FaceError naming the face and what is wrong.
TEST(FaceCoupling, BadInputNamesTheFace)
{
    Side s(50);
    std::fill(s.P.begin(), s.P.end(), 1e6);
    s.Pnbr = s.P;
    CouplingCache cache;
    CouplingOutputs out;
    const auto fails = [&](std::size_t face, const std::string& what) {
        try {
            couple(interface(), s.inputs(), cache, out);
            ADD_FAILURE() << "accepted: " << what;
        } catch (const FaceError& e) {
            EXPECT_EQ(e.face(), face);
            EXPECT_NE(std::string(e.what()).find("face " + std::to_string(face) + ": " + what), std::string::npos)
                << e.what();
        }
    };
    s.P[17] = std::nan("");
    fails(17, "nominal pressure");
    s.P[17] = 1e6;
    s.Pnbr[40] = HUGE_VAL;
    fails(40, "nominal pressure");
    s.Pnbr[40] = 1e6;
    s.kNbr[41] = -1.0;
    fails(41, "neighbour kappa");
    s.kNbr[41] = 50.0;
    s.d[3] = 0.0;
    fails(3, "deltaCoeffs");
    s.d[3] = 1e3;
    couple(interface(), s.inputs(), cache, out); // all good again

    CouplingInputs missing = s.inputs();
    missing.cellTemperatureNbr = nullptr;
    EXPECT_THROW(couple(interface(), missing, cache, out), ParameterError);
}

namespace {
InterfaceSpec withAirAndRadiation()
{
    InterfaceSpec spec = steelOnCopper();
    GapSpec gap;
    gap.gas = GasGapSpec{gasByName("air"), 101325.0, std::nullopt, std::nullopt};
    gap.emissivity1 = 0.5;
    gap.emissivity2 = 0.5;
    spec.gap = gap;
    return spec;
}
} // namespace

// With a gap every face not in complete contact adds h_g + h_r. Independent numbers for air at
// 300 K and 1 atm (docs: thermal/Gas.hpp's table): k_g = 0.0262 W/(m K); M = [2 (2 - 0.9)/0.9]
// [2 (1.4)/2.4] 61.52 nm/0.712 = 2.444 x 1.1667 x 86.40 nm = 246.4 nm; a face apart at a gap
// width of 10 um: h_g = 0.0262/10.2464e-6 = 2557.0 W/(m^2 K). Two grey plates at 300 K with
// e = 0.5: h_r = 4 sigma_SB T^3/3 = 2.0413 W/(m^2 K). Tolerance 1e-3 relative: the constants are
// written here to four or five digits.
TEST(FaceCoupling, TheGapAddsGasAndRadiation)
{
    const ContactInterface ci(withAirAndRadiation());
    ASSERT_TRUE(ci.hasGap());
    Side s(4);
    s.P = {0.0, 1e6, 1e13, -5e5};
    s.Pnbr = s.P;
    std::vector<double> width = {10e-6, 0.0, 0.0, 4e-6}, widthNbr = {10e-6, 0.0, 0.0, 6e-6};
    CouplingInputs in = s.inputs();
    in.gapWidth = width.data();
    in.gapWidthNbr = widthNbr.data();
    CouplingCache cache;
    CouplingOutputs out;
    couple(ci, in, cache, out);

    EXPECT_EQ(out.state[0], FaceState::apart);
    EXPECT_NEAR(out.gapConductance[0], 2557.0, 1e-3 * 2557.0);
    EXPECT_NEAR(out.radiativeConductance[0], 2.0413, 1e-3 * 2.0413);
    EXPECT_EQ(out.contactConductance[0], 0.0);
    EXPECT_EQ(out.conductance[0], out.gapConductance[0] + out.radiativeConductance[0]);
    EXPECT_EQ(out.valueFraction[0], coupledValueFraction(out.conductance[0], 5e4, 5e4));
    // The mean of both sides' widths: 5 um.
    EXPECT_NEAR(out.gapConductance[3], 0.0262 / (5e-6 + 246.4e-9), 1e-3 * 0.0262 / (5e-6 + 246.4e-9));

    // A touching face: Y from the correlation of the surfaces' sigma and P/H_c, H_c = 2.84 S_y of
    // copper (the softer side): the same h_c as without a gap, plus the gap's terms.
    EXPECT_EQ(out.state[1], FaceState::partial);
    const double ks = harmonicMeanConductivity(50.0, 50.0);
    EXPECT_EQ(out.contactConductance[1], ks * ci.conductancePerConductivity(1e6));
    // Y is that correlation (testGapConductance pins it against the normal quantile) at the
    // stand-in's sigma = 0.115 um (exact to 1e-12, testStandinTrends) and H_c = 2.84 x 0.07 GPa;
    // Y is proportional to sigma: 1e-10. (Was: Y > 0, and the gap term with this same Y.)
    const double Y = ci.gap().separation(1e6);
    const double expectedY = gapSeparationCorrelation(1e6, 0.115e-6, 2.84 * 0.07e9);
    EXPECT_NEAR(Y, expectedY, 1e-10 * expectedY);
    EXPECT_NEAR(out.gapConductance[1], 0.0262 / (Y + 246.4e-9), 1e-3 * 0.0262 / (Y + 246.4e-9));
    EXPECT_EQ(out.conductance[1], out.contactConductance[1] + out.gapConductance[1] + out.radiativeConductance[1]);

    // Complete contact: no gap left.
    EXPECT_EQ(out.state[2], FaceState::complete);
    EXPECT_EQ(out.gapConductance[2], 0.0);
    EXPECT_EQ(out.radiativeConductance[2], 0.0);
    EXPECT_EQ(out.conductance[2], inf);

    // The gas is at the mean of the two face temperatures: 280 K and 320 K give 300 K's h_g
    // (at 280 K alone k_g would be 5.6 % lower).
    s.Tf[0] = 280.0;
    s.TfNbr[0] = 320.0;
    in.faceTemperature = s.Tf.data();
    in.faceTemperatureNbr = s.TfNbr.data();
    couple(ci, in, cache, out);
    EXPECT_NEAR(out.gapConductance[0], 2557.0, 1e-3 * 2557.0);
    s.Tf[0] = s.TfNbr[0] = 300.0;

    // Faces apart without widths take the separation at first touch (the table's lowest
    // pressure), larger than at 1 MPa.
    in.gapWidth = in.gapWidthNbr = nullptr;
    couple(ci, in, cache, out);
    const double Y0 = ci.gap().firstTouchSeparation();
    EXPECT_EQ(Y0, ci.gap().separation(ci.table().pressures().front()));
    EXPECT_GT(Y0, Y);
    EXPECT_NEAR(out.gapConductance[0], 0.0262 / (Y0 + 246.4e-9), 1e-3 * 0.0262 / (Y0 + 246.4e-9));
    EXPECT_NE(ci.summary().find("gap: air"), std::string::npos) << ci.summary();
}

// Radiation grows as T^3: at 600 K it is 8 times that at 300 K; the gas term uses the mean of
// the two face temperatures. A vacuum gap (radiation only) has h_g = 0.
TEST(FaceCoupling, RadiationFollowsTheFaceTemperatures)
{
    InterfaceSpec spec = withAirAndRadiation();
    spec.gap->gas.reset();
    const ContactInterface vacuum(spec);
    Side s(2);
    s.P = {0.0, 0.0};
    s.Pnbr = s.P;
    s.Tf = {300.0, 600.0};
    s.TfNbr = {300.0, 600.0};
    CouplingCache cache;
    CouplingOutputs out;
    couple(vacuum, s.inputs(), cache, out);
    EXPECT_EQ(out.gapConductance[0], 0.0);
    EXPECT_NEAR(out.radiativeConductance[1] / out.radiativeConductance[0], 8.0, 1e-12);
    EXPECT_NEAR(out.radiativeConductance[0], 4 * 5.670374419e-8 * 2.7e7 / 3, 1e-9);
}

// The per-face path (InterfaceGap::conductances, one test of its inputs) gives the bits of the
// checked functions gasConductance and radiativeConductance, which the tests above and
// testGapConductance pin to closed forms; and names what is out of range.
TEST(FaceCoupling, ThePerFaceGapPathIsTheCheckedFormulas)
{
    const ContactInterface ci(withAirAndRadiation());
    const InterfaceGap& gap = ci.gap();
    for (const double Y : {0.0, 1e-9, 3.7e-6, 1e-3}) {
        for (const double T1 : {0.5, 280.0, 300.0, 1234.5}) {
            const double T2 = 1.1 * T1 + 3.0;
            const GapConductances h = gap.conductances(Y, T1, T2);
            EXPECT_EQ(h.gas, gap.gasConductance(Y, T1, T2)) << Y << " " << T1;
            EXPECT_EQ(h.radiative, gap.radiativeConductance(T1, T2)) << T1;
            EXPECT_EQ(h.radiative, radiativeConductance(T1, T2, 0.5, 0.5)) << T1;
        }
    }
    const auto named = [&](double Y, double T1, double T2, const std::string& what) {
        try {
            gap.conductances(Y, T1, T2);
            ADD_FAILURE() << "accepted Y " << Y << ", T " << T1 << ", " << T2;
        } catch (const ParameterError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(what, 0), 0U) << e.what();
        }
    };
    named(1e-6, 0.0, 300.0, "face temperature");
    named(1e-6, std::nan(""), 300.0, "face temperature");
    named(1e-6, 300.0, 2e5, "neighbour face temperature");
    named(-1e-9, 300.0, 300.0, "gap separation Y");
    named(std::nan(""), 300.0, 300.0, "gap separation Y");
    named(HUGE_VAL, 300.0, 300.0, "gap separation Y");
}

TEST(FaceCoupling, BadGapInputIsNamed)
{
    InterfaceSpec spec = withAirAndRadiation();
    spec.gap->emissivity2.reset();
    EXPECT_THROW(ContactInterface{spec}, ParameterError);
    spec.gap->emissivity1.reset();
    spec.gap->gas.reset();
    EXPECT_THROW(ContactInterface{spec}, ParameterError); // neither gas nor radiation
    spec = withAirAndRadiation();
    spec.gap->emissivity1 = 1.5;
    EXPECT_THROW(ContactInterface{spec}, ParameterError);

    const ContactInterface ci(withAirAndRadiation());
    Side s(3);
    s.Pnbr = s.P;
    std::vector<double> width = {1e-6, -1e-6, 1e-6};
    CouplingInputs in = s.inputs();
    in.gapWidth = width.data();
    in.gapWidthNbr = width.data();
    CouplingCache cache;
    CouplingOutputs out;
    try {
        couple(ci, in, cache, out);
        ADD_FAILURE() << "a negative gap width was accepted";
    } catch (const FaceError& e) {
        EXPECT_EQ(e.face(), 1U);
        EXPECT_NE(std::string(e.what()).find("gap width"), std::string::npos) << e.what();
    }
    in.gapWidth = nullptr;
    in.gapWidthNbr = nullptr;
    s.Tf[2] = 0.0;
    in = s.inputs();
    EXPECT_THROW(couple(ci, in, cache, out), FaceError);
    in.faceTemperature = nullptr;
    EXPECT_THROW(couple(ci, in, cache, out), ParameterError); // the gap needs the face temperatures
}

// Where the contact model carries a mean separation (here persson's), the gap takes it instead
// of the correlation.
TEST(FaceCoupling, TheGapTakesTheModelsSeparation)
{
    InterfaceSpec spec = withAirAndRadiation();
    spec.conductanceLaw = "persson";
    const ContactInterface ci(spec);
    ASSERT_TRUE(ci.table().hasSeparation());
    EXPECT_TRUE(ci.gap().separationFromModel());
    EXPECT_EQ(ci.gap().separation(1e6), ci.table().meanSeparation(1e6));
    const ContactInterface byCorrelation(withAirAndRadiation());
    EXPECT_FALSE(byCorrelation.gap().separationFromModel());
    EXPECT_NE(byCorrelation.gap().separation(1e6), ci.gap().separation(1e6));
}

TEST(FaceCoupling, InputThatIsProbablyAMistakeIsCountedAndSaid)
{
    // Issue 22, item 3: a pressure typed in MPa ran with A_r/A_n = 2.7e-8 below the table's first
    // point without a word; two sides' pressures 50 % apart were averaged silently; faces apart
    // with a gas and no width took the first-touch separation (helium: 53 kW/m^2/K for slabs
    // "apart"). couple() counts each; CouplingDiagnostics says what and why.
    const ContactInterface& ci = interface();
    const double first = ci.table().pressures().front();
    Side s(5);
    s.P = {40.0, 70.0, 1e6, 1e6, 2e6};    // 40 and 70 "MPa"; a matching face; two apart by 50 %
    s.Pnbr = {40.0, 70.0, 1e6, 1.5e6, 1e6};
    ASSERT_LT(70.0, first);
    CouplingCache cache;
    CouplingOutputs out;
    couple(ci, s.inputs(), cache, out);
    EXPECT_EQ(out.belowTable, 2u);
    EXPECT_EQ(out.belowTablePressureSum, 110.0);
    EXPECT_EQ(out.pressureMismatch, 2u);
    EXPECT_DOUBLE_EQ(out.largestPressureMismatch, 0.5);
    EXPECT_EQ(out.apartAtFirstTouch, 0u); // no gap
    CouplingDiagnostics d;
    d.add(out);
    d.add(out); // a second processor's faces
    EXPECT_EQ(d.belowTable, 4u);
    const std::string below = d.belowTableMessage(ci);
    EXPECT_NE(below.find("4 faces have pressures below the table's first point"), std::string::npos) << below;
    EXPECT_NE(below.find("A pressure given in MPa? 55 MPa would be 5.5e+07 Pa"), std::string::npos) << below;
    const std::string mismatch = d.pressureMismatchMessage();
    EXPECT_NE(mismatch.find("4 faces: the two sides' pressures differ by up to 50 % (more than 5 %"), std::string::npos)
        << mismatch;
    EXPECT_EQ(CouplingDiagnostics{}.belowTableMessage(ci), "");
    EXPECT_EQ(CouplingDiagnostics{}.pressureMismatchMessage(), "");
    // Within the tolerance: not counted.
    Side t(2);
    t.P = {1e6, 1e6};
    t.Pnbr = {1.04e6, 0.97e6};
    couple(ci, t.inputs(), cache, out);
    EXPECT_EQ(out.pressureMismatch, 0u);
    EXPECT_EQ(out.belowTable, 0u);

    // Apart with a gas and no width: counted; with widths given, not.
    const ContactInterface gas(withAirAndRadiation());
    Side a(3);
    a.P = {0.0, -1e5, 1e6};
    a.Pnbr = a.P;
    CouplingCache gasCache;
    couple(gas, a.inputs(), gasCache, out);
    EXPECT_EQ(out.apartAtFirstTouch, 2u);
    CouplingDiagnostics g;
    g.add(out);
    const std::string firstTouch = g.apartAtFirstTouchMessage(gas);
    EXPECT_NE(firstTouch.find("2 faces are apart (pressure <= 0) with a gas in the gap and no gap width given"),
              std::string::npos)
        << firstTouch;
    std::vector<double> width = {1e-5, 1e-5, 0.0};
    CouplingInputs in = a.inputs();
    in.gapWidth = width.data();
    in.gapWidthNbr = width.data();
    couple(gas, in, gasCache, out);
    EXPECT_EQ(out.apartAtFirstTouch, 0u);
}

namespace {

// The small capped boundary-element interface (SmallBoundaryElementSpec with a cap: 17 loads
// 0.1 MPa - 1 GPa and unloading curves from four peaks), built once.
const ContactInterface& remembering()
{
    static const ContactInterface ci([] {
        InterfaceSpec s = roughContactTest::smallBoundaryElementSpec();
        s.hardness = 2e9;
        return s;
    }());
    return ci;
}

} // namespace

TEST(FaceCoupling, ALoadThatOnlyGrowsIsTheSameWithAndWithoutHistory)
{
    const ContactInterface& iface = remembering();
    ASSERT_TRUE(iface.remembersLoad());
    Side side(5);
    std::vector<double> peak(5, 0.0);
    CouplingCache withCache, withoutCache;
    CouplingOutputs with, without;
    for (double scale : {1.0, 1.0, 3.0, 10.0, 10.0, 47.0}) {
        for (std::size_t i = 0; i < 5; ++i) {
            side.P[i] = side.Pnbr[i] = scale * 1e6 * double(i); // face 0 apart
        }
        CouplingInputs in = side.inputs();
        couple(iface, in, withoutCache, without);
        in.peakPressure = peak.data();
        in.peakPressureNbr = peak.data();
        couple(iface, in, withCache, with);
        peak = with.peakPressure;
        EXPECT_EQ(with.unloading, 0u);
        EXPECT_EQ(with.contactConductance, without.contactConductance); // bit for bit
        EXPECT_EQ(with.areaFraction, without.areaFraction);
        EXPECT_EQ(with.valueFraction, without.valueFraction);
        EXPECT_EQ(with.peakPressure, with.pressure);
    }
}

TEST(FaceCoupling, AMultiscaleFaceBelowItsPeakUnloadsByTheDefaultLawsBranch)
{
    // The multi-scale interface with the default law and copper's cap: a face below its peak
    // conducts its loading h_c times the law's unloading factor, A_r/A_n unchanged; a face at its
    // peak is the loading face bit for bit.
    const ContactInterface& iface = interface();
    ASSERT_TRUE(iface.remembersLoad());
    Side side(2);
    side.P = {1e6, 1e7};
    side.Pnbr = side.P;
    const std::vector<double> peaks{1e8, 1e7};
    CouplingInputs in = side.inputs();
    in.peakPressure = peaks.data();
    in.peakPressureNbr = peaks.data();
    CouplingCache cache, plainCache;
    CouplingOutputs out, plain;
    couple(iface, in, cache, out);
    couple(iface, side.inputs(), plainCache, plain);
    EXPECT_EQ(out.unloading, 1u);
    const double m = profileRoughness(readProfile(standin)).meanAbsoluteSlope;
    const double R = fittedUnloadingFactor(1e6, 1e8, m, spectralBandwidthRatio(iface.surface()), iface.reducedModulus(),
                                           2.84 * 0.07e9,
                                           fineHurstExponent(iface.surface()));
    EXPECT_GT(R, 1.1);
    EXPECT_NEAR(out.contactConductance[0], R * plain.contactConductance[0], 1e-14 * out.contactConductance[0]);
    EXPECT_EQ(out.areaFraction[0], plain.areaFraction[0]);
    EXPECT_EQ(out.contactConductance[1], plain.contactConductance[1]);
}

TEST(FaceCoupling, AFaceBelowItsPeakUnloadsByTheInterfacesCurves)
{
    const ContactInterface& iface = remembering();
    Side side(4);
    side.P = {2e7, 2e7, 2e7, 3e8};
    side.Pnbr = side.P;
    // Face 0 at its peak's tenth, on this side's memory; face 1 on the neighbour's; face 2 never
    // heavier (loading); face 3 loaded beyond its old peak (loading on).
    const std::vector<double> mine{2e8, 0.0, 0.0, 1e8};
    const std::vector<double> theirs{0.0, 2e8, 1e7, 0.0};
    CouplingInputs in = side.inputs();
    in.peakPressure = mine.data();
    in.peakPressureNbr = theirs.data();
    CouplingCache cache;
    CouplingOutputs out;
    couple(iface, in, cache, out);
    EXPECT_EQ(out.peakPressure, (std::vector<double>{2e8, 2e8, 2e7, 3e8}));
    EXPECT_EQ(out.unloading, 2u);
    for (std::size_t i = 0; i < 4; ++i) {
        const FaceContact f = iface.face(side.P[i], 50.0, 50.0, out.peakPressure[i]);
        EXPECT_EQ(out.contactConductance[i], f.conductance) << i;
        EXPECT_EQ(out.areaFraction[i], f.areaFraction) << i;
    }
    EXPECT_GT(out.contactConductance[0], 1.1 * out.contactConductance[2]); // unloaded: more
    EXPECT_EQ(out.contactConductance[0], out.contactConductance[1]);        // either side's memory
    // The cache follows the peak, not only the pressure.
    const std::vector<double> none(4, 0.0);
    in.peakPressure = none.data();
    in.peakPressureNbr = none.data();
    couple(iface, in, cache, out);
    EXPECT_EQ(out.contactConductance[0], out.contactConductance[2]);
    // A bad memory is named with its face.
    std::vector<double> bad = mine;
    bad[3] = std::nan("");
    in.peakPressure = bad.data();
    try {
        couple(iface, in, cache, out);
        ADD_FAILURE() << "a NaN peak accepted";
    } catch (const FaceError& e) {
        EXPECT_EQ(e.face(), 3u);
        EXPECT_NE(std::string(e.what()).find("peak pressure"), std::string::npos) << e.what();
    }
    bad[3] = -1.0;
    EXPECT_THROW(couple(iface, in, cache, out), FaceError);
    in.peakPressureNbr = nullptr; // one side's memory without the other's
    EXPECT_THROW(couple(iface, in, cache, out), ParameterError);
}
