// SPDX-License-Identifier: GPL-3.0-or-later
// The regime said out loud (InterfaceRegime.hpp) and the measured accuracy bands it quotes
// (MeasuredAccuracy.hpp): h', P/H and the plasticity index from their definitions, the band the
// report's row for the law, model, reference and decade, and the interface's log saying both.
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"
#include "roughContact/thermal/MeasuredAccuracyTable.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unistd.h>

#include <cmath>
#include <string>

using namespace roughContact;

TEST(MeasuredAccuracy, IsTheReportsRowForTheLawModelReferenceAndDecade)
{
    // Every row is found by its own key at the middle of its decade, and at its lower edge.
    for (const measured::AccuracyRow& r : measured::accuracyRows) {
        SCOPED_TRACE(std::string(r.law) + " on " + r.areaModel);
        for (double x : {std::sqrt(r.from * r.to), r.from}) {
            const auto band = measuredAccuracy(r.law, r.areaModel, r.capped, x);
            ASSERT_TRUE(band.has_value());
            EXPECT_EQ(band->low, r.low);
            EXPECT_EQ(band->high, r.high);
            EXPECT_EQ(band->from, r.from);
            EXPECT_EQ(band->surfaces, r.surfaces);
            EXPECT_LE(band->low, band->high);
        }
    }
    // jacksonBhavnaniFerguson on the condition's default model, capped, at p/(E' h') =
    // 1e-3..1e-2: the engineering-range study's 0.197-1.31 over its 5 surfaces.
    const auto d = measuredAccuracy("jacksonBhavnaniFerguson", "jacksonGreen", true, 3e-3);
    ASSERT_TRUE(d.has_value());
    EXPECT_EQ(d->low, 0.197);
    EXPECT_EQ(d->high, 1.31);
    EXPECT_EQ(d->surfaces, 5);
    EXPECT_EQ(d->report, "engineering-range study");
    // The area models that report does not run come from the fidelity study.
    const auto t = measuredAccuracy("jacksonBhavnaniFerguson", "truncation", true, 3e-3);
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(t->report, "fidelity study");
    // The laws that take no area ignore the model; the ones that do, do not.
    EXPECT_TRUE(measuredAccuracy("persson", "hertz", false, 3e-3).has_value());
    EXPECT_EQ(measuredAccuracy("persson", "hertz", false, 3e-3)->high,
              measuredAccuracy("persson", "jacksonGreen", false, 3e-3)->high);
    EXPECT_FALSE(measuredAccuracy("jacksonBhavnaniFerguson", "jgh", false, 3e-3).has_value());
    // Nothing measured below the reports' lightest load or beyond the largest, nor for
    // cooperMikicYovanovich against the elastic one.
    EXPECT_FALSE(measuredAccuracy("jacksonBhavnaniFerguson", "jacksonGreen", true, 1e-7).has_value());
    EXPECT_FALSE(measuredAccuracy("jacksonBhavnaniFerguson", "jacksonGreen", true, 2.0).has_value());
    EXPECT_FALSE(measuredAccuracy("cooperMikicYovanovich", "", false, 3e-3).has_value());
    EXPECT_EQ(describeAccuracy(std::nullopt, 1e-7), "not measured at p/(E' h') = 1e-07");
    EXPECT_EQ(describeAccuracy(d, 3e-3),
              "0.197-1.31 of exact (5 surfaces of the engineering-range study, p/(E' h') 0.001 to 0.01)");
    // Below p/(E' h') = 1e-3 the references are periodic cells (of 8L), which may conduct more than
    // a large joint (engineeringRange.md, "Light loads: how large a period"): the band says so.
    const auto light = measuredAccuracy("fittedElastoPlastic", "", true, 3e-4);
    ASSERT_TRUE(light.has_value());
    EXPECT_EQ(light->to, 1e-3);
    const std::string said = describeAccuracy(light, 3e-4);
    EXPECT_NE(said.find("p/(E' h') 0.0001 to 0.001); measured against periodic cells, which may conduct more "
                        "than a large joint at these loads (docs/checking.md)"),
              std::string::npos)
        << said;
    // The report's top decade holds one load, x = 0.1: the band says so, and claims nothing
    // beyond it (the default law is 0.67 of exact at x = 0.64 on the Dektak surface, 0.67-1.61 over
    // the heavy-load study's surfaces, where the decade's x = 0.1 alone says 0.854-1.05).
    const auto top = measuredAccuracy("fittedElastoPlastic", "", false, 0.1);
    ASSERT_TRUE(top.has_value());
    EXPECT_EQ(describeAccuracy(top, 0.1), "0.854-1.05 of exact (5 surfaces of the engineering-range study, "
                                          "p/(E' h') = 0.1 only, the largest measured)");
    // Beyond it, elastically, the heavy-load study's band (docs/validation/heavyLoads.md), up to its
    // heaviest load (x = 0.64) and no further; capped, nothing.
    const auto heavy = measuredAccuracy("fittedElastoPlastic", "", false, 0.2);
    ASSERT_TRUE(heavy.has_value());
    EXPECT_EQ(describeAccuracy(heavy, 0.2), "0.672-1.61 of exact (12 surfaces of the heavy-load study, p/(E' h') 0.1 to 0.64)");
    EXPECT_EQ(measuredAccuracy("fittedElastoPlastic", "", false, 0.64)->report, std::string("heavy-load study"));
    EXPECT_EQ(measuredAccuracy("fittedElastoPlastic", "", false, 0.1001)->report, std::string("heavy-load study"));
    EXPECT_EQ(measuredAccuracy("fittedElastoPlastic", "", false, 0.1)->report, std::string("engineering-range study"));
    EXPECT_FALSE(measuredAccuracy("fittedElastoPlastic", "", false, 0.7).has_value());
    EXPECT_FALSE(measuredAccuracy("fittedElastoPlastic", "", true, 0.2).has_value());
    EXPECT_FALSE(measuredAccuracy("fittedElastoPlastic", "", true, 0.64).has_value());
    EXPECT_FALSE(measuredAccuracy("mikic", "", false, 0.2).has_value()); // the default law's alone
    EXPECT_TRUE(measuredAccuracy("fittedElastoPlastic", "", true, 0.09).has_value()); // the decade below: whole
}

TEST(InterfaceRegime, FromTheDefinitions)
{
    // A power law of 200 levels: h' = sqrt(2 m2), P/(E' h'), P/H, psi = (E'/H) sqrt(sigma_s/R).
    const Spectrum s = Spectrum::powerLaw(1e-7 * std::pow(1e3, 1.3), 1.3, 1e3, 2e5, 1e-3);
    const double m2 = spectralMoments(s).m2;
    const double Ep = 1e11;
    const double H = 1.2e9;
    const InterfaceRegime r = interfaceRegime(s, Ep, H, "jacksonBhavnaniFerguson", "jacksonGreen", true, 1e5, 1e8);
    EXPECT_DOUBLE_EQ(r.gradient, std::sqrt(2.0 * m2));
    EXPECT_DOUBLE_EQ(r.low.load, 1e5 / Ep);
    EXPECT_DOUBLE_EQ(r.low.loadPerGradient, 1e5 / Ep / r.gradient);
    EXPECT_DOUBLE_EQ(*r.high.perHardness, 1e8 / H);
    const SummitParameters p = mcCoolParameters(s);
    ASSERT_TRUE(r.plasticityIndex.has_value());
    EXPECT_DOUBLE_EQ(*r.plasticityIndex, Ep / H * std::sqrt(p.sigmaS / p.R));
    // The bands are the table's at each end.
    const auto expectBand = [&](const RegimeAt& at) {
        const auto band = measuredAccuracy("jacksonBhavnaniFerguson", "jacksonGreen", true, at.loadPerGradient);
        ASSERT_EQ(at.band.has_value(), band.has_value());
        if (band) {
            EXPECT_EQ(at.band->low, band->low);
            EXPECT_EQ(at.band->high, band->high);
        }
    };
    expectBand(r.low);
    expectBand(r.high);
    const std::string text = r.describe();
    EXPECT_NE(text.find("plasticity index"), std::string::npos) << text;
    EXPECT_NE(text.find("(capped reference)"), std::string::npos) << text;
    EXPECT_NE(text.find("P/H = 0.0833"), std::string::npos) << text;
    // Elastic: no hardness, no P/H, no index; the elastic reference's band.
    const InterfaceRegime e = interfaceRegime(s, Ep, std::nullopt, "persson", "hertz", false, 1e5, 1e8);
    EXPECT_FALSE(e.plasticityIndex.has_value());
    EXPECT_FALSE(e.low.perHardness.has_value());
    EXPECT_NE(e.describe().find("elastic (no hardness)"), std::string::npos) << e.describe();
    // Two ends: two lines; one pressure (a CLI run at one load): one line, not the same twice.
    const auto lines = [](const std::string& t) { return std::count(t.begin(), t.end(), '\n'); };
    EXPECT_EQ(lines(e.describe()), 2) << e.describe();
    const InterfaceRegime one = interfaceRegime(s, Ep, std::nullopt, "persson", "hertz", false, 1e6, 1e6);
    EXPECT_EQ(lines(one.describe()), 1) << one.describe();
    // The spectrum's first level's share s1 is said for the default law, with its light-load
    // factor at p/(E' h') = 1e-4 (FittedElastoPlastic.hpp); not for a law that does not take it.
    ASSERT_TRUE(r.firstLevelShare.has_value());
    EXPECT_DOUBLE_EQ(*r.firstLevelShare, firstLevelShare(s));
    EXPECT_EQ(text.find("first level's share"), std::string::npos) << text;
    const InterfaceRegime fitted = interfaceRegime(s, Ep, H, "fittedElastoPlastic", "jacksonGreen", true, 1e5, 1e8);
    std::ostringstream said;
    said << std::setprecision(3) << "first level's share s1 " << firstLevelShare(s)
         << " (the law's light-load factor below p/(E' h') = 0.01 takes it: "
         << fittedLightLoadFactor(firstLevelShare(s), 1e-4) << " at 1e-4;";
    EXPECT_NE(fitted.describe().find(said.str()), std::string::npos) << fitted.describe() << "\n" << said.str();
    // Beyond the training spectra's s1 the law holds it, and the line says so: two levels of
    // powers 1 and 19 (s1 = 0.05).
    const Spectrum flat({1e3, 2e3}, {1e-7, std::sqrt(19.0) * 1e-7}, 1e-3);
    const InterfaceRegime held = interfaceRegime(flat, Ep, std::nullopt, "fittedElastoPlastic", "hertz", false, 1e5, 1e8);
    EXPECT_NE(held.describe().find("s1 0.05 (held at 0.11, the training spectra's range; the law's light-load factor"), std::string::npos)
        << held.describe();
    // The finest octave's Hurst exponent (0.8 for this power law, beta ~ f^-1.3) is said for the
    // default law with a cap, whose unloading branch takes it; not without a cap (no branch) nor
    // for another law; above 1 (the training spectra's range) the line says the law holds it.
    ASSERT_TRUE(fitted.fineHurst.has_value());
    EXPECT_NEAR(*fitted.fineHurst, 0.8, 1e-12);
    EXPECT_NE(fitted.describe().find("finest octave's Hurst exponent H_f 0.8 (the law's unloading branch"),
              std::string::npos)
        << fitted.describe();
    EXPECT_EQ(text.find("H_f"), std::string::npos) << text;
    const InterfaceRegime elastic = interfaceRegime(s, Ep, std::nullopt, "fittedElastoPlastic", "hertz", false, 1e5, 1e8);
    EXPECT_EQ(elastic.describe().find("H_f"), std::string::npos) << elastic.describe();
    const Spectrum steep = Spectrum::powerLaw(1e-7 * std::pow(1e3, 2.0), 2.0, 1e3, 2e5, 1e-3);
    const InterfaceRegime steepest = interfaceRegime(steep, Ep, H, "fittedElastoPlastic", "jacksonGreen", true, 1e5, 1e8);
    EXPECT_NE(steepest.describe().find("H_f 1.5 (held at 1, the training spectra's range;"), std::string::npos)
        << steepest.describe();
}

TEST(InterfaceRegime, TheInterfaceSaysItsRegimeAtTheTablesEnds)
{
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::powerLaw;
    s.parameters = {1e-7 * std::pow(1e3, 1.3), 1.3, 1e3, 2e5};
    s.length = 1e-3;
    spec.surfaces = {s};
    spec.side1 = Material{200e9, 0.3, 0.5e9};
    spec.side2 = Material{200e9, 0.3, 0.4e9};
    spec.model = "jacksonGreen";
    spec.minPressure = 1e4;
    spec.maxPressure = 1e8;
    const ContactInterface ci(spec);
    const InterfaceRegime& r = ci.regime();
    EXPECT_EQ(r.low.pressure, ci.table().pressures().front());
    EXPECT_EQ(r.high.pressure, ci.table().pressures().back());
    EXPECT_TRUE(r.capped);
    ASSERT_TRUE(r.hardness.has_value());
    EXPECT_DOUBLE_EQ(*r.hardness, 2.84 * 0.4e9); // the softer side yields
    EXPECT_EQ(r.law, defaultConductanceLaw());
    EXPECT_NE(ci.summary().find(r.describe()), std::string::npos) << ci.summary();
    // hertz with the default law: still capped, the law has a plastic branch and the hardness.
    spec.model = "hertz";
    EXPECT_TRUE(ContactInterface(spec).regime().capped);
    // hertz with jacksonBhavnaniFerguson: held to the elastic reference, though the materials
    // have a hardness (P/H said).
    spec.conductanceLaw = "jacksonBhavnaniFerguson";
    const ContactInterface elastic(spec);
    EXPECT_FALSE(elastic.regime().capped);
    EXPECT_TRUE(elastic.regime().low.perHardness.has_value());
    // A surface given by its spectrum has Gaussian heights: no skewness said.
    EXPECT_FALSE(elastic.regime().skewness.has_value());
    EXPECT_EQ(elastic.regime().describe().find("skewness"), std::string::npos);
}

namespace {
// An interface on one measured map (read along both directions) between two materials, over
// 0.1-10 MPa.
InterfaceSpec oneMap(SurfaceSpec map, const Material& side1, const Material& side2)
{
    map.kind = SurfaceSpec::Kind::areal;
    map.direction = ScanDirection::both;
    InterfaceSpec spec;
    spec.surfaces = {map};
    spec.side1 = side1;
    spec.side2 = side2;
    spec.minPressure = 1e5;
    spec.maxPressure = 1e7;
    return spec;
}
} // namespace

// A measured map's heights are not Gaussian, and the regime says by how much: the map's own
// skewness (arealSkewness, -0.38 for data/x3p-2.x3p), on the line that names h'. Two surfaces:
// that of their sum (combinedSkewness), a spectrum counting as 0.
TEST(InterfaceRegime, SaysTheSkewnessOfMeasuredHeights)
{
    SurfaceSpec x3p;
    x3p.file = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p";
    InterfaceSpec spec = oneMap(x3p, Material{68.9e9, 0.33, 276e6}, Material{200e9, 0.3, 0.5e9});
    const SurfaceSpec map = spec.surfaces.front();
    const InterfaceRegime r = ContactInterface(spec).regime();
    ASSERT_TRUE(r.skewness.has_value());
    EXPECT_NEAR(r.skewness->skewness, -0.3787, 5e-4); // docs/validation/mapSurrogates.md: -0.38
    EXPECT_EQ(r.skewness->skewness, map.skewness()->skewness);
    EXPECT_EQ(r.skewness->spread, map.skewness()->spread);
    const std::string text = r.describe();
    EXPECT_NE(text.substr(0, text.find('\n')).find("heights' skewness -0.379 (Gaussian heights of this spectrum and "
                                                     "size give +-0.125 by chance; the law takes -0.338, "
                                                     "chance's share out"),
              std::string::npos)
        << text;
    // The default law takes the shrunk skewness: its h is the law's with that skewness.
    EXPECT_EQ(r.law, "fittedElastoPlastic");
    SurfaceSpec gaussian;
    gaussian.kind = SurfaceSpec::Kind::powerLaw;
    gaussian.parameters = {1e-7 * std::pow(1e3, 1.3), 1.3, 1e3, 2e5};
    gaussian.length = 1e-3;
    spec.surfaces = {map, gaussian};
    const HeightSkewness s2 = ContactInterface(spec).regime().skewness.value();
    const HeightSkewness expected =
        combinedSkewness(map.roughness().sigma, *map.skewness(), gaussian.roughness().sigma, HeightSkewness{0.0, 0.0});
    EXPECT_EQ(s2.skewness, expected.skewness);
    EXPECT_EQ(s2.spread, expected.spread);
    EXPECT_GT(s2.skewness, map.skewness()->skewness); // diluted towards 0 by the Gaussian side
    EXPECT_LT(s2.skewness, 0.0);
}

// A plateau-honed surface is skewed far beyond the skewness the default law's factor was fitted
// on (|s| = 0.6): the interface is built (no error), and the line says the factor is held there.
TEST(InterfaceRegime, SaysWhereTheSkewnessFactorIsHeld)
{
    const std::size_t n = 64;
    const double pi = std::acos(-1.0);
    const std::string file = testing::TempDir() + "/plateauMap-" + std::to_string(::getpid()) + ".txt";
    {
        std::ofstream out(file);
        out.precision(17);
        for (std::size_t iy = 0; iy < n; ++iy) {
            for (std::size_t ix = 0; ix < n; ++ix) {
                // Deep narrow pits in a flat plateau: -exp of a smooth field.
                const double g = std::cos(2.0 * pi * 3.0 * double(ix) / double(n) + 0.3) +
                                 std::cos(2.0 * pi * 5.0 * double(iy) / double(n) + 1.1) +
                                 0.5 * std::cos(2.0 * pi * (7.0 * double(ix) + 4.0 * double(iy)) / double(n));
                out << (ix ? " " : "") << -1e-6 * std::exp(1.5 * g);
            }
            out << '\n';
        }
    }
    SurfaceSpec plateau;
    plateau.file = file;
    plateau.arealOptions.dx = 1e-4 / double(n);
    const InterfaceSpec spec = oneMap(plateau, Material{200e9, 0.3, 400e6}, Material{200e9, 0.3, 400e6});
    const HeightSkewness s = spec.surfaces.front().skewness().value();
    EXPECT_LT(shrunkSkewness(s), -0.6) << s.skewness << " +- " << s.spread; // the case this test is about
    const InterfaceRegime r = ContactInterface(spec).regime();
    const std::string line = r.describe().substr(0, r.describe().find('\n'));
    EXPECT_NE(line.find("held at -0.6 (the largest skewness its factor was fitted on)"), std::string::npos) << line;
    std::remove(file.c_str());
}
