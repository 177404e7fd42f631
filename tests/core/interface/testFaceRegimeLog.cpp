// SPDX-License-Identifier: GPL-3.0-or-later
// The regime at the faces' pressures (FaceRegimeLog.hpp): said at the first evaluation in
// contact and again only when the min, mean or max pressure moved by more than a factor of two;
// its lines are InterfaceRegime's at those pressures, and h's parts are the means of the faces'
// values, the gap's said "not validated"; faces below their peak are said with the unloading
// branch's measured band there (MeasuredAccuracy.hpp).
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"
#include "roughContact/interface/FaceRegimeLog.hpp"
#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/thermal/Gas.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"
#include "roughContact/thermal/MeasuredAccuracyTable.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

namespace {

// Faces at pressures P [Pa] that carried the peaks `peak` [Pa] (P == peak: loading).
FaceSums history(const std::vector<double>& P, const std::vector<double>& peak)
{
    CouplingOutputs out = faces(P, std::vector<double>(P.size(), 1e4), std::vector<double>(P.size(), 0.0),
                                std::vector<double>(P.size(), 0.0));
    out.peakPressure = peak;
    FaceSums s;
    s.add(out);
    return s;
}

const ContactInterface& mikic()
{
    static const ContactInterface ci([] {
        InterfaceSpec spec = steelOnSteel();
        spec.conductanceLaw = "mikic";
        return spec;
    }());
    return ci;
}

} // namespace

TEST(FaceRegimeLog, FacesBelowTheirPeakAreCountedWithTheirPeaksAndDeepestUnloading)
{
    // Apart (0 below a peak), loading (P == peak), and two below their peaks.
    const FaceSums s = history({0.0, 3e6, 1e6, 4e6}, {2e7, 3e6, 1e7, 4e7});
    EXPECT_EQ(s.inContact, 3u);
    EXPECT_EQ(s.unloading, 2u);
    EXPECT_EQ(s.unloadingPeakMin, 1e7);
    EXPECT_EQ(s.unloadingPeakMax, 4e7);
    EXPECT_DOUBLE_EQ(s.unloadingFractionMin, 0.1);
    // Without peaks (no load history: peakPressure is P) no face is below its peak.
    EXPECT_EQ(sums({1e6, 2e6}).unloading, 0u);
    // Nor is a load held at its peak that comes back an ulp below it (a table in time).
    EXPECT_EQ(history({std::nextafter(5e7, 0.0)}, {5e7}).unloading, 0u);
    EXPECT_EQ(history({5e7 * (1.0 - 1e-8)}, {5e7}).unloading, 1u);
}

TEST(FaceRegimeLog, FacesBelowTheirPeakAreSaidWithTheBranchsMeasuredBand)
{
    ASSERT_TRUE(dry().remembersLoad()) << "the default law with a cap has an unloading branch";
    const InterfaceRegime& r = dry().regime();
    const double scale = r.reducedModulus * r.gradient;
    // Peaks at p/(E' h') 0.0033 and 0.013: in the study's range, across two of its decades.
    const std::string text = FaceRegimeLog::describe(dry(), history({3e6, 1e5, 4e5}, {3e6, 1e6, 4e6}));
    EXPECT_NE(
        text.find(
            "2 faces are below the largest pressure carried (peaks 1e+06 to 4e+06 Pa, P/P_max down to 0.1)"),
        std::string::npos)
        << text;
    const auto band = measuredUnloadingAccuracy(1e6 / scale, 4e6 / scale);
    ASSERT_TRUE(band.has_value()) << "peaks at p/(E' h') " << 1e6 / scale << " to " << 4e6 / scale;
    EXPECT_NE(text.find("times the unloading branch's R"), std::string::npos) << text;
    EXPECT_NE(text.find(describeUnloadingAccuracy(band, 1e6 / scale, 4e6 / scale)), std::string::npos)
        << text;
    EXPECT_EQ(text.find("deeper than measured"), std::string::npos) << text;
    // Unloaded deeper than the study measured (1/100 of the peak): said.
    const std::string deep = FaceRegimeLog::describe(dry(), history({1e4}, {1e6}));
    EXPECT_NE(deep.find("1 face is below"), std::string::npos) << deep;
    EXPECT_NE(deep.find("(unloaded deeper than measured)"), std::string::npos) << deep;
    // Just below the peak: rounded down, never "1".
    const std::string shallow = FaceRegimeLog::describe(dry(), history({0.99999e6}, {1e6}));
    EXPECT_NE(shallow.find("P/P_max down to 0.999)"), std::string::npos) << shallow;
    // Signed with the band where the study's points there all lie within 25 %; else wider, said so.
    for (const measured::UnloadingAccuracyRow& row : measured::unloadingAccuracyRows) {
        const double peak = row.from * scale * (row.to > 1.01 * row.from ? 2.0 : 1.0);
        const std::string at = FaceRegimeLog::describe(dry(), history({0.5 * peak}, {peak}));
        SCOPED_TRACE(at);
        EXPECT_EQ(at.find("sign h there") != std::string::npos, row.outside == 0);
        EXPECT_EQ(at.find("wider than 25 % there") != std::string::npos, row.outside > 0);
    }
    // No face below its peak: no such line.
    EXPECT_EQ(FaceRegimeLog::describe(dry(), history({3e6}, {3e6})).find("below the largest"),
              std::string::npos);
    // A law without an unloading branch: h follows the pressure of the moment, and says so.
    const std::string plain = FaceRegimeLog::describe(mikic(), history({1e6}, {1e7}));
    EXPECT_NE(plain.find("mikic has no unloading branch: h_c follows the pressure of the moment"),
              std::string::npos)
        << plain;
}

TEST(FaceRegimeLog, IsSaidAgainWhenTheFirstFaceFallsBelowItsPeakAndWhenTheLastLeavesIt)
{
    FaceRegimeLog log;
    EXPECT_NE(log.update(dry(), history({2e7, 2e7}, {2e7, 2e7})), "") << "first contact";
    // Relaxed by less than the factor 2: the pressures alone would not be said again.
    EXPECT_NE(log.update(dry(), history({1.5e7, 1.5e7}, {2e7, 2e7})), "")
        << "the first faces below their peak";
    EXPECT_EQ(log.update(dry(), history({1.4e7, 1.5e7}, {2e7, 2e7})), "")
        << "still below, pressures within 2";
    EXPECT_NE(log.update(dry(), history({2.1e7, 2.1e7}, {2.1e7, 2.1e7})), "")
        << "retightened beyond the peak";
    EXPECT_EQ(log.update(dry(), history({2.2e7, 2.2e7}, {2.2e7, 2.2e7})), "");
}

TEST(MeasuredUnloadingAccuracy, ABandSpansTheDecadesOfThePeaksAndNothingOutsideTheStudy)
{
    const auto& rows = measured::unloadingAccuracyRows;
    const std::size_t n = sizeof rows / sizeof rows[0];
    ASSERT_GE(n, 2u);
    // Peaks within one row: that row.
    const double inside = std::sqrt(rows[0].from * rows[0].to);
    const auto one = measuredUnloadingAccuracy(inside, inside);
    ASSERT_TRUE(one.has_value());
    EXPECT_EQ(one->low, rows[0].low);
    EXPECT_EQ(one->high, rows[0].high);
    EXPECT_EQ(one->points, rows[0].points);
    EXPECT_EQ(one->outside, rows[0].outside);
    // Peaks across two rows: their extremes and sums.
    const auto two = measuredUnloadingAccuracy(inside, rows[1].from);
    ASSERT_TRUE(two.has_value());
    EXPECT_EQ(two->from, rows[0].from);
    EXPECT_EQ(two->to, rows[1].to);
    EXPECT_EQ(two->low, std::min(rows[0].low, rows[1].low));
    EXPECT_EQ(two->high, std::max(rows[0].high, rows[1].high));
    EXPECT_EQ(two->points, rows[0].points + rows[1].points);
    EXPECT_EQ(two->outside, rows[0].outside + rows[1].outside);
    // Peaks heavier than any measured (4e7 Pa on the test's surface: p/(E' h') = 0.13): said so.
    const std::string heavy = FaceRegimeLog::describe(dry(), history({1e6}, {4e7}));
    EXPECT_NE(heavy.find("the unloading branch was not measured for peaks at"), std::string::npos) << heavy;
    EXPECT_EQ(heavy.find("sign h"), std::string::npos) << heavy;
    // Peaks lighter or heavier than any measured, or reaching beyond them: none, and said so.
    EXPECT_FALSE(measuredUnloadingAccuracy(0.5 * rows[0].from, inside).has_value());
    EXPECT_FALSE(measuredUnloadingAccuracy(inside, 2.0 * rows[n - 1].to).has_value());
    const std::string none = describeUnloadingAccuracy(std::nullopt, 1.0, 2.0);
    EXPECT_NE(none.find("not measured for peaks at p/(E' h') = 1 to 2"), std::string::npos) << none;
    std::ostringstream measuredPeaks; // which peaks it did measure, from the rows
    measuredPeaks << std::setprecision(2) << "(the unloading study's peaks: " << rows[0].from << " to "
                  << rows[n - 1].from << ")";
    EXPECT_NE(none.find(measuredPeaks.str()), std::string::npos) << none;
    // The rows cover the study's peaks without a gap, and every band is a real one.
    for (std::size_t k = 0; k < n; ++k) {
        EXPECT_LT(rows[k].from, rows[k].to);
        EXPECT_LE(rows[k].low, rows[k].high);
        EXPECT_GT(rows[k].points, 0);
        EXPECT_LE(rows[k].outside, rows[k].points);
        if (k > 0) {
            EXPECT_EQ(rows[k].from, rows[k - 1].to);
        }
    }
}
