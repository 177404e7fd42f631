// SPDX-License-Identifier: GPL-3.0-or-later
// The regime at the faces' pressures (FaceRegimeLog.hpp): said at the first evaluation in
// contact and again only when the min, mean or max pressure moved by more than a factor of two;
// its lines are InterfaceRegime's at those pressures, and h's parts are the means of the faces'
// values, the gap's said "not validated".
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"
#include "roughContact/interface/FaceRegimeLog.hpp"
#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/thermal/Gas.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

InterfaceSpec steelOnSteel()
{
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::powerLaw;
    s.parameters = {1e-7 * std::pow(1e3, 1.3), 1.3, 1e3, 2e5};
    s.length = 1e-3;
    spec.surfaces = {s};
    spec.side1 = Material{200e9, 0.3, 0.5e9};
    spec.side2 = Material{200e9, 0.3, 0.5e9};
    spec.model = "jacksonGreen";
    spec.minPressure = 1e4;
    spec.maxPressure = 1e9;
    return spec;
}

const ContactInterface& dry()
{
    static const ContactInterface ci(steelOnSteel());
    return ci;
}

const ContactInterface& inAir()
{
    static const ContactInterface ci([] {
        InterfaceSpec spec = steelOnSteel();
        GapSpec gap;
        gap.gas = GasGapSpec{gasByName("air"), 101325.0, std::nullopt, std::nullopt};
        gap.emissivity1 = 0.5;
        gap.emissivity2 = 0.5;
        spec.gap = gap;
        return spec;
    }());
    return ci;
}

// Faces with the given pressures [Pa] (0: apart) and parts of h [W/(m^2 K)] (h_c inf: complete).
CouplingOutputs faces(const std::vector<double>& P, const std::vector<double>& hc, const std::vector<double>& hg,
                      const std::vector<double>& hr)
{
    CouplingOutputs out;
    out.resize(P.size());
    for (std::size_t i = 0; i < P.size(); ++i) {
        out.pressure[i] = P[i];
        out.state[i] = P[i] <= 0.0 ? FaceState::apart
                                   : std::isfinite(hc[i]) ? FaceState::partial : FaceState::complete;
        out.contactConductance[i] = hc[i];
        out.gapConductance[i] = hg[i];
        out.radiativeConductance[i] = hr[i];
    }
    return out;
}

FaceSums sums(const std::vector<double>& P)
{
    FaceSums s;
    s.add(faces(P, std::vector<double>(P.size(), 1e4), std::vector<double>(P.size(), 0.0),
                std::vector<double>(P.size(), 0.0)));
    return s;
}

std::string line(const ContactInterface& ci, double P, const std::string& label)
{
    return ci.regime().describeAt({{label, P}});
}

} // namespace

TEST(FaceRegimeLog, SaysTheRegimeAtFirstContactAndWhenThePressuresMoveByMoreThanTwice)
{
    FaceRegimeLog log;
    EXPECT_EQ(log.update(dry(), sums({0.0, 0.0})), "") << "no face in contact: nothing yet";
    EXPECT_NE(log.update(dry(), sums({1e6, 2e6, 3e6})), "") << "the first evaluation in contact";
    EXPECT_EQ(log.update(dry(), sums({1e6, 2e6, 3e6})), "") << "the same pressures";
    // Min 1e6 -> 1.2e6, mean 2e6 -> 3e6, max 3e6 -> 5.9e6: each within a factor 2.
    EXPECT_EQ(log.update(dry(), sums({1.9e6, 1.2e6, 5.9e6})), "");
    // The max more than doubles (3e6 -> 6.1e6): said again, at the new pressures.
    const std::string again = log.update(dry(), sums({1e6, 2e6, 6.1e6}));
    EXPECT_NE(again.find(line(dry(), 6.1e6, "max")), std::string::npos) << again;
    // Compared with what was last said (max 6.1e6), not the first: 3.1e6 is within 2 of it.
    EXPECT_EQ(log.update(dry(), sums({1e6, 2e6, 3.1e6})), "");
    // A fall by more than 2 is said too (min 1e6 -> 0.4e6).
    EXPECT_NE(log.update(dry(), sums({0.4e6, 2e6, 3.1e6})), "");
    // A new log (a restarted run) says it at once.
    FaceRegimeLog restarted;
    EXPECT_NE(restarted.update(dry(), sums({0.4e6, 2e6, 3.1e6})), "");
    EXPECT_THROW(FaceRegimeLog(1.0), std::invalid_argument);
}

TEST(FaceRegimeLog, ItsLinesAreTheRegimeAtTheMinMeanAndMax)
{
    const FaceSums s = sums({0.0, 1e6, 2e6, 6e6});
    const std::string text = FaceRegimeLog::describe(dry(), s);
    EXPECT_NE(text.find("3 of 4 faces in contact"), std::string::npos) << text;
    EXPECT_NE(text.find(line(dry(), 1e6, "min")), std::string::npos) << text;
    EXPECT_NE(text.find(line(dry(), 3e6, "mean")), std::string::npos) << text; // of the faces in contact
    EXPECT_NE(text.find(line(dry(), 6e6, "max")), std::string::npos) << text;
    // Each line's numbers: p/(E' h') from its definition and the band the table has there.
    const InterfaceRegime& r = dry().regime();
    const RegimeAt at = r.at(3e6);
    EXPECT_DOUBLE_EQ(at.load, 3e6 / r.reducedModulus);
    EXPECT_DOUBLE_EQ(at.loadPerGradient, 3e6 / r.reducedModulus / r.gradient);
    EXPECT_DOUBLE_EQ(*at.perHardness, 3e6 / *r.hardness);
    const auto band = measuredAccuracy(r.law, r.areaModel, r.capped, at.loadPerGradient);
    ASSERT_TRUE(band.has_value());
    EXPECT_NE(text.find(describeAccuracy(band, at.loadPerGradient)), std::string::npos) << text;
    // Faces that carry the same pressure: one line.
    const std::string uniform = FaceRegimeLog::describe(dry(), sums({5e6, 5e6, 5e6}));
    EXPECT_NE(uniform.find(line(dry(), 5e6, "every face")), std::string::npos) << uniform;
    EXPECT_EQ(uniform.find("(min)"), std::string::npos) << uniform;
    // No line for a pressure <= 0.
    EXPECT_EQ(r.describeAt({{"x", 0.0}, {"y", -1.0}}), "");
}

TEST(FaceRegimeLog, HsPartsAreTheFacesMeansAndTheGapsAreSaidNotValidated)
{
    // Three faces: apart (gap only), partial, complete (h_c infinite: out of the means).
    const double inf = std::numeric_limits<double>::infinity();
    FaceSums s;
    s.add(faces({0.0, 2e6, 9e9}, {0.0, 3e4, inf}, {100.0, 80.0, 0.0}, {6.0, 6.0, 0.0}));
    EXPECT_EQ(s.faces, 3u);
    EXPECT_EQ(s.inContact, 2u);
    EXPECT_EQ(s.complete, 1u);
    const std::string text = FaceRegimeLog::describe(inAir(), s);
    std::ostringstream parts;
    parts << std::setprecision(4) << "means over the 2 faces not in complete contact: " << (3e4 + 180.0 + 12.0) / 2
          << " = " << 3e4 / 2 << " (contact: the band above) + " << 180.0 / 2 << " (gas: not validated) + "
          << 12.0 / 2 << " (radiation: not validated) W/m^2/K";
    EXPECT_NE(text.find(parts.str()), std::string::npos) << text << "\n" << parts.str();
    // Without a gap it says there is none.
    const std::string dryText = FaceRegimeLog::describe(dry(), sums({1e6}));
    EXPECT_NE(dryText.find("(no gap: no gas or radiation)"), std::string::npos) << dryText;
    EXPECT_NE(dryText.find(line(dry(), 1e6, "the face")), std::string::npos) << dryText;
}

TEST(FaceRegimeLog, TheSumsOfTwoProcessorsAreTheSumsOfAllFaces)
{
    // What a parallel run reduces (min, max, sums) gives what one processor with every face does.
    const std::vector<double> P{0.0, 1e6, 4e6, 2e6, 8e6};
    const std::vector<double> hc{0.0, 1e4, 3e4, 2e4, 5e4}, hg{50.0, 40.0, 30.0, 35.0, 20.0}, hr{5.0, 5.0, 5.0, 5.0, 5.0};
    FaceSums whole;
    whole.add(faces(P, hc, hg, hr));
    FaceSums a, b;
    a.add(faces({P[0], P[1]}, {hc[0], hc[1]}, {hg[0], hg[1]}, {hr[0], hr[1]}));
    b.add(faces({P[2], P[3], P[4]}, {hc[2], hc[3], hc[4]}, {hg[2], hg[3], hg[4]}, {hr[2], hr[3], hr[4]}));
    FaceSums reduced;
    reduced.pressureMin = std::min(a.pressureMin, b.pressureMin);
    reduced.pressureMax = std::max(a.pressureMax, b.pressureMax);
    reduced.pressureSum = a.pressureSum + b.pressureSum;
    reduced.inContact = a.inContact + b.inContact;
    reduced.complete = a.complete + b.complete;
    reduced.faces = a.faces + b.faces;
    reduced.contactSum = a.contactSum + b.contactSum;
    reduced.gasSum = a.gasSum + b.gasSum;
    reduced.radiationSum = a.radiationSum + b.radiationSum;
    EXPECT_EQ(FaceRegimeLog::describe(inAir(), reduced), FaceRegimeLog::describe(inAir(), whole));
    EXPECT_EQ(whole.pressureMin, 1e6);
    EXPECT_EQ(whole.pressureMax, 8e6);
    EXPECT_DOUBLE_EQ(whole.meanPressure(), 15e6 / 4);
}

TEST(FaceRegimeLog, PressuresNearTheLargestDoubleAreSaidWithoutOverflow)
{
    // (The tests run with overflow trapped, as OpenFOAM does: a sum of such pressures would trap.)
    const FaceSums s = sums({1e308, 1.7e308, 1.5e308});
    EXPECT_DOUBLE_EQ(s.meanPressure(), (1e308 / 3 + 1.7e308 / 3 + 1.5e308 / 3));
    const std::string text = FaceRegimeLog::describe(dry(), s);
    EXPECT_NE(text.find("(max)"), std::string::npos) << text;
    EXPECT_NE(text.find("not measured"), std::string::npos) << text;
    FaceRegimeLog log;
    EXPECT_NE(log.update(dry(), s), "");
}

TEST(FaceRegimeLog, PressuresDecideAndHsPartsAreAddedOnlyWhenDue)
{
    // The condition adds the faces' pressures at every evaluation and h's parts only when the log
    // is due (FaceSums::addPressures, addConductances): together they are add(), and due() reads
    // the pressures alone, so a log fed that way says what update() says of the whole sums.
    const CouplingOutputs out = faces({0.0, 1e6, 3e6, 5e6}, {0.0, 2e4, INFINITY, 5e4}, {10.0, 20.0, 30.0, 40.0},
                                      {1.0, 2.0, 3.0, 4.0});
    FaceSums whole;
    whole.add(out);
    FaceSums parts;
    parts.addPressures(out);
    EXPECT_EQ(parts.faces, 4U);
    EXPECT_EQ(parts.inContact, 3U);
    EXPECT_EQ(parts.pressureMax, 5e6);
    EXPECT_EQ(parts.contactSum, 0.0) << "h's parts are not read for the decision";
    FaceRegimeLog byParts;
    FaceRegimeLog byWhole;
    ASSERT_TRUE(byParts.due(parts));
    parts.addConductances(out);
    EXPECT_EQ(parts.complete, whole.complete);
    EXPECT_EQ(parts.contactSum, whole.contactSum);
    EXPECT_EQ(parts.gasSum, whole.gasSum);
    EXPECT_EQ(parts.radiationSum, whole.radiationSum);
    EXPECT_EQ(FaceRegimeLog::describe(dry(), parts), byWhole.update(dry(), whole));
    EXPECT_FALSE(byParts.due(parts)) << "the same pressures: not due again";
}
