// SPDX-License-Identifier: GPL-3.0-or-later
// The one reader of a contact specification (InterfaceSpecReader.hpp): each rule once, through
// an in-memory source (SpecValues) as the CLI and Python fill one. The OpenFOAM dictionary's
// source is the same reader's (tests/cases/errors runs its variants through it).
#include "ExpectParameterError.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SpecSource.hpp"
#include "roughContact/thermal/Gas.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

// Errors named as the CLI names them ("--key"), so a test sees which source's name is used.
std::string dashed(const std::string& key)
{
    return "--" + key;
}

std::shared_ptr<const SpecValues> sub(SpecValues v)
{
    return std::make_shared<const SpecValues>(std::move(v));
}

SpecValues profile()
{
    SpecValues s("surface", dashed);
    s.set("type", std::string("profile")).set("file", std::string("p.csv"));
    return s;
}

SpecValues solid(double E, double nu, double Sy, const std::string& context)
{
    SpecValues s(context, dashed);
    s.set("E", E).set("nu", nu).set("Sy", Sy);
    return s;
}

SpecValues contact()
{
    SpecValues c("slabs", dashed);
    c.set("model", std::string("jacksonGreen"))
        .set("surface", sub(profile()))
        .set("side1", sub(solid(200e9, 0.3, 0.4e9, "side1")))
        .set("side2", sub(solid(70e9, 0.33, 0.1e9, "side2")));
    return c;
}

// The message of the ParameterError f throws, which must name `entry`.
template <class F>
std::string messageOf(F f, const std::string& entry)
{
    try {
        f();
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), entry) << e.what();
        return e.message();
    }
    ADD_FAILURE() << "no ParameterError naming " << entry;
    return "";
}

} // namespace

TEST(InterfaceSpecReader, ReadsAWholeSpecificationWithItsDefaults)
{
    const InterfaceSpec spec = readInterfaceSpec(contact());
    EXPECT_EQ(spec.model, "jacksonGreen");
    ASSERT_EQ(spec.surfaces.size(), 1u);
    EXPECT_EQ(spec.surfaces[0].kind, SurfaceSpec::Kind::profile);
    EXPECT_EQ(spec.surfaces[0].file, "p.csv");
    EXPECT_EQ(spec.surfaces[0].stride, 1u);
    EXPECT_FALSE(spec.surfaces[0].length);
    EXPECT_EQ(spec.side1.E, 200e9);
    EXPECT_EQ(*spec.side2.Sy, 0.1e9);
    EXPECT_TRUE(spec.conductanceLaw.empty());
    EXPECT_EQ(spec.pointsPerDecade, 40u);
    EXPECT_EQ(spec.bemPointsPerDecade, 6u);
    EXPECT_FALSE(spec.gap);
    EXPECT_FALSE(spec.check);
}

TEST(InterfaceSpecReader, UnknownEntryIsNamedWithTheEntriesThatExist)
{
    SpecValues c = contact();
    c.set("maxPresure", 1e9);
    const std::string m = messageOf([&] { readInterfaceSpec(c); }, "--maxPresure");
    EXPECT_NE(m.find("not an entry of a contact specification"), std::string::npos) << m;
    EXPECT_NE(m.find("maxPressure"), std::string::npos) << m;
}

TEST(InterfaceSpecReader, RequiredEntriesAreNamedWhenMissing)
{
    for (const char* key : {"model", "side1", "side2"}) {
        SpecValues c("slabs", dashed);
        for (const std::string& k : contact().keys()) {
            if (k != key) {
                const SpecValues whole = contact();
                // copy the entry over by reading it back as what it is
                if (k == "model") {
                    c.set(k, whole.word(k));
                } else if (k == "surface") {
                    c.set(k, sub(profile()));
                } else {
                    c.set(k, sub(solid(200e9, 0.3, 0.4e9, k)));
                }
            }
        }
        EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, dashed(key)).find("is missing"), std::string::npos);
    }
}

TEST(InterfaceSpecReader, SurfaceOrSurfacesExactlyOne)
{
    SpecValues both = contact();
    both.set("surfaces", std::vector<std::shared_ptr<const SpecValues>>{sub(profile())});
    messageOf([&] { readInterfaceSpec(both); }, "--surfaces");
    SpecValues three = contact();
    SpecValues none("slabs", dashed);
    none.set("model", std::string("jacksonGreen"))
        .set("surfaces", std::vector<std::shared_ptr<const SpecValues>>{sub(profile()), sub(profile()), sub(profile())})
        .set("side1", sub(solid(200e9, 0.3, 0.4e9, "side1")))
        .set("side2", sub(solid(70e9, 0.33, 0.1e9, "side2")));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(none); }, "--surfaces").find("holds 3 surfaces"), std::string::npos);
    SpecValues two = none;
    two.set("surfaces", std::vector<std::shared_ptr<const SpecValues>>{sub(profile()), sub(profile())});
    EXPECT_EQ(readInterfaceSpec(two).surfaces.size(), 2u);
}

TEST(InterfaceSpecReader, SurfaceTypeMustBeKnown)
{
    SpecValues s = profile();
    s.set("type", std::string("wavy"));
    const std::string m = messageOf([&] { readSurfaceSpec(s); }, "--type");
    EXPECT_NE(m.find("profile, spectrum, powerLaw, fractal, areal"), std::string::npos) << m;
}

TEST(InterfaceSpecReader, AnEntryOfAnotherSurfaceTypeSaysWhichTypeItIsFor)
{
    SpecValues areal("surface", dashed);
    areal.set("type", std::string("areal")).set("file", std::string("m.x3p")).set("stride", std::uint64_t(2));
    EXPECT_NE(messageOf([&] { readSurfaceSpec(areal); }, "--stride").find("it is for type profile"),
              std::string::npos);
    SpecValues withLength = profile();
    withLength.set("length", 1e-3);
    const std::string m = messageOf([&] { readSurfaceSpec(withLength); }, "--length");
    EXPECT_NE(m.find("type spectrum or powerLaw or fractal"), std::string::npos) << m;
    SpecValues spectrumUnits("surface", dashed);
    spectrumUnits.set("type", std::string("spectrum")).set("file", std::string("s.csv")).set("units", std::string("um"));
    messageOf([&] { readSurfaceSpec(spectrumUnits); }, "--units");
}

TEST(InterfaceSpecReader, StrideIsAWholeNumberAtLeastOne)
{
    SpecValues s = profile();
    s.set("stride", std::uint64_t(0));
    messageOf([&] { readSurfaceSpec(s); }, "--stride");
    s.set("stride", 2.5);
    messageOf([&] { readSurfaceSpec(s); }, "--stride");
    s.set("stride", std::string("3"));
    EXPECT_EQ(readSurfaceSpec(s).stride, 3u);
}

TEST(InterfaceSpecReader, ScanLengthIsFiniteAndPositive)
{
    SpecValues s("surface", dashed);
    s.set("type", std::string("powerLaw")).set("bm", 6e-4).set("m", 1.3).set("fmin", 2e3).set("fmax", 2e6);
    for (double L : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
        s.set("length", L);
        messageOf([&] { readSurfaceSpec(s); }, "--length");
    }
    s.set("length", 5e-4);
    const SurfaceSpec spec = readSurfaceSpec(s);
    EXPECT_EQ(*spec.length, 5e-4);
    EXPECT_EQ(spec.parameters, (std::vector<double>{6e-4, 1.3, 2e3, 2e6}));
}

TEST(InterfaceSpecReader, RoughnessTakesRqOrRaAndTheSlope)
{
    SpecValues s("surface", dashed);
    s.set("type", std::string("roughness")).set("Ra", 0.4e-6).set("slope", 0.1);
    SurfaceSpec spec = readSurfaceSpec(s);
    ASSERT_EQ(spec.parameters.size(), 4u);
    EXPECT_DOUBLE_EQ(spec.parameters[0], std::sqrt(M_PI / 2.0) * 0.4e-6);
    EXPECT_EQ(spec.parameters[2], 0.8e-3);  // the cut-offs' defaults
    EXPECT_EQ(spec.parameters[3], 2.5e-6);
    s.set("Rq", 0.5e-6);
    messageOf([&] { readSurfaceSpec(s); }, "--Ra");
    SpecValues noSlope("surface", dashed);
    noSlope.set("type", std::string("roughness")).set("Rq", 0.5e-6).set("cutoff", 2.5e-3);
    messageOf([&] { readSurfaceSpec(noSlope); }, "--slope");
    noSlope.set("slope", 0.05);
    EXPECT_EQ(readSurfaceSpec(noSlope).parameters[2], 2.5e-3);
}

TEST(InterfaceSpecReader, PowerLawAndFractalNameTheirMissingParameter)
{
    SpecValues s("surface", dashed);
    s.set("type", std::string("fractal")).set("D", 1.5).set("fmin", 2e3).set("fmax", 2e6);
    EXPECT_NE(messageOf([&] { readSurfaceSpec(s); }, "--G").find("D, G, fmin and fmax"), std::string::npos);
}

TEST(InterfaceSpecReader, WordsAreTheCoresNamesAndNamedByTheSource)
{
    SpecValues units = profile();
    units.set("units", std::string("furlong"));
    messageOf([&] { readSurfaceSpec(units); }, "--units");
    SpecValues areal("surface", dashed);
    areal.set("type", std::string("areal")).set("file", std::string("m.x3p")).set("direction", std::string("z"));
    EXPECT_NE(messageOf([&] { readSurfaceSpec(areal); }, "--direction").find("x (rows), y (columns) or both"),
              std::string::npos);
    // Without a direction a map is read along both (the engineering range measures the laws so).
    SpecValues plain("surface", dashed);
    plain.set("type", std::string("areal")).set("file", std::string("m.x3p"));
    EXPECT_EQ(readSurfaceSpec(plain).direction, ScanDirection::both);
    areal.set("direction", std::string("x")).set("fillInvalid", true).set("units", std::string("um"));
    const SurfaceSpec s = readSurfaceSpec(areal);
    EXPECT_EQ(s.direction, ScanDirection::x);
    EXPECT_TRUE(s.arealOptions.fillInvalid);
    SpecValues c = contact();
    c.set("detrend", std::string("tilt"));
    messageOf([&] { readInterfaceSpec(c); }, "--detrend");
}

TEST(InterfaceSpecReader, YieldStrengthIsANumberOrNone)
{
    SpecValues s("side2", dashed);
    s.set("E", 200e9).set("nu", 0.3).set("Sy", std::string("none"));
    const Material m = readMaterial(s);
    EXPECT_TRUE(m.elastic);
    EXPECT_FALSE(m.Sy);
    s.set("Sy", std::string("soft"));
    EXPECT_NE(messageOf([&] { readMaterial(s); }, "--Sy").find("or none"), std::string::npos);
    s.set("Sy", std::string("4e8")); // a number as text (the CLI's) is a number
    EXPECT_EQ(*readMaterial(s).Sy, 4e8);
}

TEST(InterfaceSpecReader, MaterialValuesAreCheckedNamingTheSide)
{
    SpecValues s = solid(200e9, 0.6, 0.4e9, "side1");
    messageOf([&] { readMaterial(s); }, "side1 Poisson's ratio nu");
    SpecValues e = solid(-1, 0.3, 0.4e9, "side2");
    messageOf([&] { readMaterial(e); }, "side2 Young's modulus E");
    SpecValues y = solid(200e9, 0.3, -0.4e9, "side2");
    messageOf([&] { readMaterial(y); }, "side2 yield strength S_y");
    SpecValues extra = solid(200e9, 0.3, 0.4e9, "side1");
    extra.set("k", 50.0);
    messageOf([&] { readMaterial(extra); }, "--k");
}

TEST(InterfaceSpecReader, YieldStrengthOnOneSideOnlyIsAnErrorOfThePair)
{
    // The reader takes each side as written; the pair's rule (ContactMaterials::pair) names the
    // side without one when the spec is built into an interface.
    SpecValues c = contact();
    SpecValues side2("side2", dashed);
    side2.set("E", 70e9).set("nu", 0.33);
    c.set("side2", sub(side2));
    const InterfaceSpec spec = readInterfaceSpec(c);
    try {
        ContactMaterials::pair(spec.side1, spec.side2, "side1", "side2");
        ADD_FAILURE() << "one-sided S_y accepted";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("side2"), std::string::npos) << e.what();
    }
}

TEST(InterfaceSpecReader, PointsPerDecadeGoesToTheTableOfTheModelNamed)
{
    SpecValues c = contact();
    c.set("pointsPerDecade", std::uint64_t(20));
    EXPECT_EQ(readInterfaceSpec(c).pointsPerDecade, 20u);
    EXPECT_EQ(readInterfaceSpec(c).bemPointsPerDecade, 6u);
    c.set("model", std::string("boundaryElement"));
    EXPECT_EQ(readInterfaceSpec(c).pointsPerDecade, 40u);
    EXPECT_EQ(readInterfaceSpec(c).bemPointsPerDecade, 20u);
    c.set("pointsPerDecade", -3.0);
    messageOf([&] { readInterfaceSpec(c); }, "--pointsPerDecade");
}

TEST(InterfaceSpecReader, ThreadsAreAWholeNumberFrom1)
{
    SpecValues c = contact();
    EXPECT_FALSE(readInterfaceSpec(c).threads.has_value());
    c.set("threads", std::uint64_t(2));
    EXPECT_EQ(*readInterfaceSpec(c).threads, 2);
    c.set("threads", std::uint64_t(0));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--threads").find("1 to 4096"), std::string::npos);
    c.set("threads", 1.5);
    messageOf([&] { readInterfaceSpec(c); }, "--threads");
}

TEST(InterfaceSpecReader, TableRanksAreAWholeNumberFrom1ForTheBoundaryElementModel)
{
    SpecValues c = contact();
    c.set("model", std::string("boundaryElement")).set("synthesize", std::uint64_t(64));
    EXPECT_FALSE(readInterfaceSpec(c).tableRanks.has_value());
    c.set("tableRanks", std::uint64_t(3));
    EXPECT_EQ(*readInterfaceSpec(c).tableRanks, 3u);
    c.set("tableRanks", std::uint64_t(0));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--tableRanks").find("1 or more"), std::string::npos);
    c.set("tableRanks", 1.5);
    messageOf([&] { readInterfaceSpec(c); }, "--tableRanks");
    // Another model has no table to share: said, not ignored.
    SpecValues j = contact();
    j.set("tableRanks", std::uint64_t(2));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(j); }, "--tableRanks").find("is for model boundaryElement"),
              std::string::npos);
}

TEST(InterfaceSpecReader, MirrorIsAFlag)
{
    // mirror (a map mirrored about its edges): a flag, unset by default, not a number.
    SpecValues c = contact();
    SpecValues areal("surface", dashed);
    areal.set("type", std::string("areal")).set("file", std::string("m.x3p"));
    c.set("model", std::string("boundaryElement")).set("surface", sub(areal));
    EXPECT_FALSE(readInterfaceSpec(c).mirror.has_value());
    c.set("mirror", true);
    EXPECT_TRUE(*readInterfaceSpec(c).mirror);
    c.set("mirror", false);
    EXPECT_FALSE(*readInterfaceSpec(c).mirror);
    c.set("mirror", 1.5);
    messageOf([&] { readInterfaceSpec(c); }, "--mirror");
}

TEST(InterfaceSpecReader, LoadHistoryIsAFlagOnByDefaultForEveryModel)
{
    // loadHistory (the condition's memory of each face's peak): yes unless said, for any model
    // (a law without unloading curves keeps the peaks and follows the pressure of the moment).
    SpecValues c = contact();
    EXPECT_TRUE(readInterfaceSpec(c).loadHistory);
    c.set("loadHistory", false);
    EXPECT_FALSE(readInterfaceSpec(c).loadHistory);
    c.set("loadHistory", true);
    EXPECT_TRUE(readInterfaceSpec(c).loadHistory);
    c.set("loadHistory", 2.0);
    messageOf([&] { readInterfaceSpec(c); }, "--loadHistory");
}

TEST(InterfaceSpecReader, SeedBelongsToSynthesize)
{
    SpecValues c = contact();
    c.set("model", std::string("boundaryElement")).set("seed", std::uint64_t(7));
    messageOf([&] { readInterfaceSpec(c); }, "--seed");
    c.set("synthesize", std::uint64_t(64)).set("seed", std::string("18446744073709551615"));
    const InterfaceSpec spec = readInterfaceSpec(c);
    EXPECT_EQ(*spec.synthesize, 64u);
    EXPECT_EQ(spec.seed, 18446744073709551615ull); // 2^64 - 1 exactly: not through a double
    c.set("seed", std::string("18446744073709551616"));
    messageOf([&] { readInterfaceSpec(c); }, "--seed");
}

TEST(InterfaceSpecReader, ListsOfTwoSayWhatTheTwoAre)
{
    SpecValues c = contact();
    c.set("vickers", std::vector<double>{3e9});
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--vickers").find("c1 [Pa] and c2"), std::string::npos);
    c.set("vickers", std::vector<double>{3e9, -0.1});
    EXPECT_EQ(readInterfaceSpec(c).vickers->c2, -0.1);
}

TEST(InterfaceSpecReader, GapByNameWithDefaultsAndChecked)
{
    SpecValues gap("gap", dashed);
    gap.set("gas", std::string("helium"));
    GapSpec g = readGapSpec(gap);
    ASSERT_TRUE(g.gas);
    EXPECT_EQ(g.gas->gas.name, "helium");
    EXPECT_EQ(g.gas->pressure, standardAtmosphere);
    EXPECT_FALSE(g.gas->accommodation1);
    EXPECT_FALSE(g.emissivity1);

    gap.set("gas", std::string("xenon"));
    EXPECT_NE(messageOf([&] { readGapSpec(gap); }, "--gas").find("xenon"), std::string::npos);
    gap.set("gas", std::string("air")).set("emissivity", std::vector<double>{1.5, 0.3});
    messageOf([&] { readGapSpec(gap); }, "gap emissivity e1");
    gap.set("emissivity", std::vector<double>{0.5});
    messageOf([&] { readGapSpec(gap); }, "--emissivity");
    gap.set("emissivity", std::vector<double>{0.5, 0.3}).set("accommodation", std::vector<double>{0.0, 0.9});
    messageOf([&] { readGapSpec(gap); }, "accommodation coefficient a1");

    SpecValues empty("gap", dashed);
    empty.set("pressure", 1e5);
    EXPECT_NE(messageOf([&] { readGapSpec(empty); }, "gap").find("neither a gas nor emissivities"),
              std::string::npos);
    SpecValues vacuum("gap", dashed);
    vacuum.set("emissivity", std::vector<double>{0.3, 0.3}).set("pressure", 1e5);
    messageOf([&] { readGapSpec(vacuum); }, "--pressure");
}

TEST(InterfaceSpecReader, GapGasByItsProperties)
{
    SpecValues gas("gap gas", dashed);
    gas.set("conductivity", 0.026)
        .set("conductivityExponent", 0.8)
        .set("referenceTemperature", 300.0)
        .set("heatCapacityRatio", 1.4)
        .set("prandtl", 0.7)
        .set("meanFreePath", 6.8e-8)
        .set("accommodation", 0.9);
    SpecValues gap("gap", dashed);
    gap.set("gas", sub(gas)).set("pressure", 2e5);
    const GapSpec g = readGapSpec(gap);
    EXPECT_EQ(g.gas->gas.name, "user");
    EXPECT_EQ(g.gas->gas.conductivityExponent, 0.8);
    EXPECT_EQ(g.gas->gas.referencePressure, standardAtmosphere);
    EXPECT_EQ(g.gas->pressure, 2e5);
    SpecValues noPrandtl("gap gas", dashed);
    for (const std::string& k : gas.keys()) {
        if (k != "prandtl") {
            noPrandtl.set(k, gas.number(k));
        }
    }
    gap.set("gas", sub(noPrandtl));
    messageOf([&] { readGapSpec(gap); }, "--prandtl");
}

TEST(InterfaceSpecReader, ValuesOfTheWrongKindAreNamed)
{
    SpecValues c = contact();
    c.set("minPressure", std::string("low"));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--minPressure").find("expects a number"), std::string::npos);
    SpecValues f = contact();
    f.set("check", std::string("maybe"));
    messageOf([&] { readInterfaceSpec(f); }, "--check");
    f.set("check", std::string("yes"));
    EXPECT_TRUE(readInterfaceSpec(f).check);
}

TEST(InterfaceSpecReader, CheckPeriodsIsTheChecksLightLoadPeriodOfAProfileOrSpectrum)
{
    // checkPeriods K: unset by default (the check's own default then), K with check yes on a
    // 1-D surface; without check, outside 1 to 64, or on an areal map (solved as itself) an error
    // naming the entry.
    SpecValues c = contact();
    c.set("check", true);
    EXPECT_FALSE(readInterfaceSpec(c).checkPeriods);
    c.set("checkPeriods", std::uint64_t(8));
    EXPECT_EQ(readInterfaceSpec(c).checkPeriods, std::optional<std::size_t>(8));
    c.set("checkPeriods", std::uint64_t(0));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkPeriods").find("must be 1 to 64"), std::string::npos);
    c.set("checkPeriods", std::uint64_t(65));
    messageOf([&] { readInterfaceSpec(c); }, "--checkPeriods");
    c.set("checkPeriods", std::uint64_t(2)).set("check", false);
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkPeriods").find("needs check yes"), std::string::npos);
    SpecValues areal("surface", dashed);
    areal.set("type", std::string("areal")).set("file", std::string("m.x3p"));
    c.set("check", true).set("surface", sub(areal));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkPeriods").find("an areal map is solved as itself"),
              std::string::npos);
}

TEST(InterfaceSpecReader, CheckPressuresAreTheChecksPressures)
{
    // checkPressures (P ...): empty by default (the front-end's pressures then), 1 to 5 pressures
    // above 0 with check yes; otherwise an error naming the entry.
    SpecValues c = contact();
    c.set("check", true);
    EXPECT_TRUE(readInterfaceSpec(c).checkPressures.empty());
    c.set("checkPressures", std::vector<double>{5e6, 2e7});
    EXPECT_EQ(readInterfaceSpec(c).checkPressures, (std::vector<double>{5e6, 2e7}));
    c.set("checkPressures", std::vector<double>{1e6, 2e6, 3e6, 4e6, 5e6, 6e6});
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkPressures").find("give 1 to 5 pressures"),
              std::string::npos);
    c.set("checkPressures", std::vector<double>{1e6, 0.0});
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkPressures").find("above 0"), std::string::npos);
    c.set("checkPressures", std::vector<double>{1e6}).set("check", false);
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkPressures").find("needs check yes"), std::string::npos);
}

TEST(InterfaceSpecReader, CheckUnloadFromIsThePeakTheCheckUnloadsFrom)
{
    // checkUnloadFrom P: unset by default (the check loads only); a pressure above 0 with check
    // yes; otherwise an error naming the entry.
    SpecValues c = contact();
    c.set("check", true);
    EXPECT_FALSE(readInterfaceSpec(c).checkUnloadFrom.has_value());
    c.set("checkUnloadFrom", 5e7);
    EXPECT_EQ(readInterfaceSpec(c).checkUnloadFrom, std::optional<double>(5e7));
    c.set("checkUnloadFrom", 0.0);
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkUnloadFrom").find("above 0"),
              std::string::npos);
    c.set("checkUnloadFrom", std::numeric_limits<double>::infinity());
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkUnloadFrom").find("above 0"),
              std::string::npos);
    c.set("checkUnloadFrom", 5e7).set("check", false);
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--checkUnloadFrom").find("needs check yes"),
              std::string::npos);
}

// A source that can say where an entry is written (as a dictionary gives its line).
class LocatingValues final : public SpecSource {
public:
    explicit LocatingValues(SpecValues v) : v_(std::move(v)) {}
    std::vector<std::string> keys() const override { return v_.keys(); }
    bool has(const std::string& k) const override { return v_.has(k); }
    bool isSub(const std::string& k) const override { return v_.isSub(k); }
    bool isWord(const std::string& k) const override { return v_.isWord(k); }
    std::string word(const std::string& k) const override { return v_.word(k); }
    std::string path(const std::string& k) const override { return v_.path(k); }
    double number(const std::string& k) const override { return v_.number(k); }
    std::vector<double> numbers(const std::string& k) const override { return v_.numbers(k); }
    std::uint64_t whole(const std::string& k) const override { return v_.whole(k); }
    bool flag(const std::string& k) const override { return v_.flag(k); }
    std::unique_ptr<SpecSource> sub(const std::string& k) const override { return v_.sub(k); }
    std::vector<std::unique_ptr<SpecSource>> subs(const std::string& k) const override { return v_.subs(k); }
    std::string name(const std::string& k) const override { return v_.name(k); }
    std::string context() const override { return v_.context(); }
    std::string locate(const std::string& k) const override { return "entry '" + k + "' (line 20)"; }

private:
    SpecValues v_;
};

TEST(InterfaceSpecReader, MaterialValueErrorsSayWhereTheEntryIsWhereTheSourceCan)
{
    messageOf([&] { readMaterial(LocatingValues(solid(200e9, 0.3, -0.4e9, "side2"))); },
              "side2 yield strength S_y (entry 'Sy' (line 20))");
    messageOf([&] { readMaterial(LocatingValues(solid(200e9, 0.7, 0.4e9, "side2"))); },
              "side2 Poisson's ratio nu (entry 'nu' (line 20))");
}

TEST(SpecValues, DefaultNamesSayTheContext)
{
    SpecValues s("side1");
    EXPECT_EQ(s.name("E"), "'E' of side1");
    s.set("nu", 0.3, "--nu (solid 1)");
    EXPECT_EQ(s.name("nu"), "--nu (solid 1)");
}

TEST(InterfaceSpecReader, EndsWithTheModelsRulesNamedAsWritten)
{
    // The reader ends with InterfaceSpec::checkEntries, its errors naming the entry as the source
    // writes it (here "--" + key): the one place of each rule, for every front-end.
    SpecValues c = contact(); // jacksonGreen on a profile
    c.set("synthesize", std::uint64_t(64));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--synthesize").find("is for model boundaryElement"),
              std::string::npos);
    c = contact();
    c.set("conductance", std::string("mikic")).set("vickers", std::vector<double>{5e9, -0.2});
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--vickers").find("cooperMikicYovanovich, not mikic"),
              std::string::npos);
    c.set("check", true); // the check computes cooperMikicYovanovich's column beside mikic
    EXPECT_TRUE(readInterfaceSpec(c).vickers.has_value());
    c = contact();
    c.set("model", std::string("boundaryElement")).set("synthesize", std::uint64_t(64)).set("mirror", true);
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--mirror").find("is for areal maps"), std::string::npos);
    c = contact();
    c.set("model", std::string("boundaryElement")).set("synthesize", std::uint64_t(64)).set("microhardness", 1e9);
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--microhardness").find("takes 'hardness'"), std::string::npos);
    c.set("check", true); // the check's laws take it
    EXPECT_EQ(*readInterfaceSpec(c).microhardness, 1e9);
    c = contact();
    c.set("model", std::string("boundaryElement")).set("synthesize", std::uint64_t(64)).set("conductance",
                                                                                           std::string("mikic"));
    EXPECT_NE(messageOf([&] { readInterfaceSpec(c); }, "--conductance").find("no place beside it"), std::string::npos);
}

TEST(InterfaceSpecReader, AlongLayIsAProfilesSecondDirection)
{
    // alongLay: a profile of the surface along its lay (file across it), a path as file is.
    SpecValues p("surface", dashed);
    p.set("type", std::string("profile")).set("file", std::string("across.csv")).set("alongLay",
                                                                                    std::string("along.csv"));
    EXPECT_EQ(readSurfaceSpec(p).alongLay, "along.csv");
    SpecValues areal("surface", dashed);
    areal.set("type", std::string("areal")).set("file", std::string("m.x3p")).set("alongLay", std::string("b.csv"));
    EXPECT_NE(messageOf([&] { readSurfaceSpec(areal); }, "--alongLay").find("it is for type profile"),
              std::string::npos);
}
