// SPDX-License-Identifier: GPL-3.0-or-later
// The picture's numbers (InterfaceCurves.hpp): each law's curve is the law the condition builds
// on the whole surface, evaluated at the curves' pressures; the band is the chosen law over its
// measured band's ends there (NaN where nothing was measured); bad pressures are refused.
#include "roughContact/Error.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceCurves.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

const std::string standin = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";

// Steel on steel (yielding: capped) on the stand-in profile, as a dictionary would give it.
InterfaceSpec standinSpec()
{
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::profile;
    s.file = standin;
    spec.surfaces = {s};
    spec.side1 = Material{200e9, 0.3, 0.4e9};
    spec.side2 = Material{200e9, 0.3, 0.4e9};
    spec.model = "jacksonGreen";
    return spec;
}

} // namespace

TEST(InterfaceCurves, EachLawIsTheLawOnTheWholeSurfaceAtEachPressure)
{
    const InterfaceSpec spec = standinSpec();
    const SurfaceCheckInputs in = checkInputsOf(spec);
    const std::vector<double> pressures = logSpacedPressures(1e5, 1e8, 7);
    const InterfaceCurves curves = interfaceCurves(in, pressures);
    ASSERT_EQ(curves.pressures, pressures);
    ASSERT_EQ(curves.laws.size(), conductanceLawNames().size());
    EXPECT_EQ(curves.chosenLaw, defaultConductanceLaw());
    EXPECT_TRUE(curves.capped);

    // The laws built by hand from the same inputs (the cap 2.84 S_y as every law's hardness),
    // evaluated directly: the same arithmetic, so equal to the last bit.
    const Spectrum given = equivalentSurface(spec.surfaces);
    const ContactMaterials materials = ContactMaterials::pair(spec.side1, spec.side2);
    const MultiscaleModel model(given, materials.reducedModulus(), makeAsperityModel("jacksonGreen", materials));
    ConductanceLawInputs li;
    li.multiscale = &model;
    li.spectrum = &given;
    li.Eprime = materials.reducedModulus();
    li.roughness = equivalentRoughness(spec.surfaces);
    li.skewness = equivalentSkewness(spec.surfaces);
    li.microhardness = 2.84 * 0.4e9;
    li.hardness = li.microhardness;
    for (const LawCurve& curve : curves.laws) {
        SCOPED_TRACE(curve.name);
        ASSERT_EQ(curve.unavailable, "");
        const auto law = makeConductanceLaw(curve.name, li);
        for (std::size_t i = 0; i < pressures.size(); ++i) {
            EXPECT_EQ(curve.hPerK[i], law->perConductivity(pressures[i]));
        }
    }

    // The chosen law is the condition's: ContactInterface's h_c/k_s (its table interpolates in
    // log P at 40 points a decade: 1e-4 covers that interpolation's error on these smooth curves).
    const ContactInterface condition(spec);
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        const double h = condition.conductancePerConductivity(pressures[i]);
        EXPECT_NEAR(curves.chosen().hPerK[i], h, 1e-4 * h) << pressures[i];
    }

    // The band: the chosen law over the measured band's high and low ends at each pressure's
    // p/(E' h'); NaN where the studies measured nothing (1e5 Pa is below their lightest load).
    std::size_t measured = 0;
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        const double x = pressures[i] / (curves.reducedModulus * curves.gradient);
        const auto band = measuredAccuracy(curves.chosenLaw, "jacksonGreen", true, x);
        const double h = curves.chosen().hPerK[i];
        if (band) {
            ++measured;
            EXPECT_DOUBLE_EQ(curves.exactLow[i], h / band->high);
            EXPECT_DOUBLE_EQ(curves.exactHigh[i], h / band->low);
            EXPECT_LE(curves.exactLow[i], curves.exactHigh[i]);
        } else {
            EXPECT_TRUE(std::isnan(curves.exactLow[i]) && std::isnan(curves.exactHigh[i])) << pressures[i];
        }
    }
    EXPECT_TRUE(std::isnan(curves.exactLow.front()));
    EXPECT_GE(measured, 4U);
}

TEST(InterfaceCurves, ALawThatCannotBeBuiltSaysWhyAndTheChosenOneMust)
{
    // Elastic solids (no S_y, no microhardness): cooperMikicYovanovich has no hardness and says so;
    // chosen, it is an error.
    InterfaceSpec spec = standinSpec();
    spec.side1.Sy.reset();
    spec.side2.Sy.reset();
    spec.model = "hertz";
    SurfaceCheckInputs in = checkInputsOf(spec);
    const InterfaceCurves curves = interfaceCurves(in, {1e6, 1e7});
    EXPECT_FALSE(curves.capped);
    bool saidWhy = false;
    for (const LawCurve& l : curves.laws) {
        if (l.name == "cooperMikicYovanovich") {
            saidWhy = !l.unavailable.empty() && l.hPerK.empty();
        }
    }
    EXPECT_TRUE(saidWhy);
    in.conductanceLaw = "cooperMikicYovanovich";
    EXPECT_THROW(interfaceCurves(in, {1e6, 1e7}), ParameterError);
}

TEST(InterfaceCurves, PressuresMustBePositiveFiniteAndIncreasing)
{
    const SurfaceCheckInputs in = checkInputsOf(standinSpec());
    EXPECT_THROW(interfaceCurves(in, {}), ParameterError);
    EXPECT_THROW(interfaceCurves(in, {0.0, 1e6}), ParameterError);
    EXPECT_THROW(interfaceCurves(in, {1e7, 1e6}), ParameterError);
    EXPECT_THROW(interfaceCurves(in, {1e6, std::nan("")}), ParameterError);
    EXPECT_THROW(logSpacedPressures(0.0, 1e6, 5), ParameterError);
    EXPECT_THROW(logSpacedPressures(1e6, 1e5, 5), ParameterError);
    EXPECT_THROW(logSpacedPressures(1e5, 1e6, 1), ParameterError);
    const std::vector<double> p = logSpacedPressures(1e4, 1e8, 5);
    ASSERT_EQ(p.size(), 5U);
    EXPECT_EQ(p.front(), 1e4);
    EXPECT_EQ(p.back(), 1e8);
    for (std::size_t i = 1; i < p.size(); ++i) {
        EXPECT_NEAR(p[i] / p[i - 1], 10.0, 1e-12); // a decade each
    }
    // A picture's: a decade each way of one pressure; a check's points 1.5 inside the frame.
    const std::vector<double> one = plotPressures(1e6, 1e6, true, 3);
    EXPECT_DOUBLE_EQ(one.front(), 1e5);
    EXPECT_DOUBLE_EQ(one.back(), 1e7);
    const std::vector<double> marked = plotPressures(1e6, 1e8, true, 2);
    EXPECT_DOUBLE_EQ(marked.front(), 1e6 / 1.5);
    EXPECT_DOUBLE_EQ(marked.back(), 1.5e8);
    EXPECT_EQ(plotPressures(1e6, 1e8, false, 2), (std::vector<double>{1e6, 1e8}));
}
