// SPDX-License-Identifier: GPL-3.0-or-later
// The mean-plane separation Y carried through the pressure table (ContactTable.hpp): the laws
// that define it (ConductanceLaw::meanSeparation: persson, multiscaleBarber), the table's column
// (the law's at its points, linear in log P between, the stated rules outside), fromPoints'
// checks, and ContactInterface's forwarding. The boundary-element column is tested in
// testBoundaryElementTable.
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ContactTable.hpp"
#include "roughContact/thermal/MultiscaleBarber.hpp"

#include "ExpectParameterError.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

const ContactMaterials steel = ContactMaterials::againstRigidFlat(Material{200e9, 0.3, 0.5e9});

// A self-affine line scan (Hurst 0.8) of rms slope 0.07 (as testMultiscaleBarber's).
Spectrum surface()
{
    return Spectrum::powerLaw(0.0376, 1.3, 1e3, 64e3);
}

struct Laws {
    Spectrum s = surface();
    MultiscaleModel model;
    ConductanceLawInputs in;
    explicit Laws(const std::string& area)
        : model(s, steel.reducedModulus(), makeAsperityModel(area, steel))
    {
        in.multiscale = &model;
        in.spectrum = &s;
        in.Eprime = steel.reducedModulus();
        in.roughness = spectrumRoughness(s);
    }
    std::unique_ptr<ConductanceLaw> law(const std::string& name) const { return makeConductanceLaw(name, in); }
};

double nan()
{
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

TEST(Separation, MultiscaleBarberSatisfiesBarbersRelationWithItsOwnConductance)
{
    // h_c/k_s = -(1/E') dP/dY, dY by a central difference of the law's own Y at P (1 -+ 1e-3):
    // the law's h is the central difference of the same energy with the same step, so the two
    // differ by the difference's O(step^2) term only: with dU/dl / l ~ l^-alpha it is
    // alpha (alpha + 1) step^2 / 6 ~ 5e-7 for alpha ~ 1.3 (measured: at most 4.4e-7 here); 2e-6
    // leaves a factor 4. A Y off by a constant factor k would miss by 1 - 1/k.
    for (const char* area : {"hertz", "jacksonGreen"}) {
        const Laws l(area);
        const auto law = l.law("multiscaleBarber");
        const double Ep = steel.reducedModulus();
        const double Pc = MultiscaleBarber(l.model, l.s).completeContactLoad() * Ep;
        for (double load : {1e-9, 1e-7, 1e-5, 1e-3, 3e-3}) {
            const double P = load * Ep;
            ASSERT_LT(P * 1.001, Pc) << area;
            const double lo = P * (1.0 - 1e-3);
            const double hi = P * (1.0 + 1e-3);
            const double fromY = (hi - lo) / Ep / (law->meanSeparation(lo) - law->meanSeparation(hi));
            EXPECT_NEAR(fromY / law->perConductivity(P), 1.0, 2e-6) << area << " load " << load;
        }
    }
}

TEST(Separation, MultiscaleBarberAtTheEndsOfTheAcceptedLoads)
{
    // With floating-point traps on (every test's main): finite and positive at the least load
    // (panels down 34 decades), 0 at the greatest; a load between 0 and the least is refused.
    for (const char* area : {"hertz", "jacksonGreen", "truncation"}) {
        const Laws l(area);
        const MultiscaleBarber b(l.model, l.s);
        const double least = b.meanSeparation(limits::minimumLoad);
        EXPECT_TRUE(std::isfinite(least) && least > b.meanSeparation(1e-9)) << area << " " << least;
        EXPECT_EQ(b.meanSeparation(limits::maximumLoad), 0.0) << area;
        EXPECT_THROW(b.meanSeparation(limits::minimumLoad / 10.0), ParameterError) << area;
    }
}

TEST(Separation, MultiscaleBarberIsZeroAtCompleteContactAndNonIncreasing)
{
    const Laws l("jacksonGreen");
    const MultiscaleBarber b(l.model, l.s);
    const double lc = b.completeContactLoad();
    ASSERT_TRUE(std::isfinite(lc));
    EXPECT_EQ(l.model.areaFraction(lc), 1.0);
    EXPECT_EQ(b.meanSeparation(lc), 0.0);
    EXPECT_EQ(b.meanSeparation(3.0 * lc), 0.0);
    // Just below load_c only the last sliver of (B4) is left: a small fraction of the light-load Y.
    EXPECT_GT(b.meanSeparation(lc * (1.0 - 1e-3)), 0.0);
    EXPECT_LT(b.meanSeparation(lc * (1.0 - 1e-3)), 1e-3 * b.meanSeparation(1e-9));
    double previous = std::numeric_limits<double>::infinity();
    for (double load = 1e-12; load < lc; load *= 1.2) {
        const double u = b.meanSeparation(load);
        EXPECT_LE(u, previous) << load;
        previous = u;
    }
    // The laws without a separation say so.
    for (const char* name : {"jacksonBhavnaniFerguson", "mikic"}) {
        EXPECT_TRUE(std::isnan(l.law(name)->meanSeparation(1e6))) << name;
    }
    EXPECT_THROW(l.law("mikic")->meanSeparation(-1.0), ParameterError);
    // persson's is PerssonModel's.
    const PerssonModel persson(l.s, steel.reducedModulus());
    EXPECT_EQ(l.law("persson")->meanSeparation(2e6), persson.meanSeparation(2e6 / steel.reducedModulus()));
}

TEST(Separation, PerssonColumnIsTheModelsAtThePointsAndLinearInLogPBetween)
{
    const Laws l("jacksonGreen");
    const double Ep = steel.reducedModulus();
    const auto law = l.law("persson");
    const ContactTable t(l.model, 1e-9 * Ep, Ep, 40, law.get());
    ASSERT_TRUE(t.hasSeparation());
    const PerssonModel persson(l.s, Ep);
    const std::vector<double>& P = t.pressures();
    const std::vector<double>& Y = t.separations();
    ASSERT_EQ(Y.size(), P.size());
    // At the points: the model's own u, bit for bit (the running minimum never acts on it).
    for (std::size_t k = 0; k < P.size(); ++k) {
        EXPECT_EQ(Y[k], persson.meanSeparation(P[k] / Ep)) << k;
        EXPECT_EQ(t.meanSeparation(P[k]), Y[k]) << k;
    }
    // Between: linear in log P, and within 1e-4 of the model (measured 2.1e-5 at 30 % of each
    // interval: u is near linear in log P, and 0 at complete contact rules log-log out).
    double worst = 0.0;
    for (std::size_t k = 0; k + 1 < P.size(); ++k) {
        const double tt = 0.3;
        const double Pm = std::exp((1 - tt) * std::log(P[k]) + tt * std::log(P[k + 1]));
        const double linear = Y[k] + tt * (Y[k + 1] - Y[k]);
        EXPECT_NEAR(t.meanSeparation(Pm), linear, 1e-12 * Y[k]) << k;
        worst = std::max(worst, std::abs(t.meanSeparation(Pm) / persson.meanSeparation(Pm / Ep) - 1.0));
    }
    EXPECT_LT(worst, 1e-4);
    // Below the table: the first interval's slope in log P, which Persson's light-load law
    // u = -u0 ln p + const makes near exact (measured 1.5e-8 two decades down; 1e-6 asked).
    const double below = P.front() / 100.0;
    const double slope = (Y[1] - Y[0]) / std::log(P[1] / P[0]);
    EXPECT_NEAR(t.meanSeparation(below), Y[0] + slope * std::log(below / P[0]), 1e-12 * Y[0]);
    EXPECT_NEAR(t.meanSeparation(below) / persson.meanSeparation(below / Ep), 1.0, 1e-6);
    // Complete contact (the area model's): 0; no pressure: NaN (the caller's case); NaN: refused.
    EXPECT_EQ(t.meanSeparation(t.completeContactPressure()), 0.0);
    EXPECT_EQ(t.meanSeparation(2.0 * t.completeContactPressure()), 0.0);
    EXPECT_TRUE(std::isnan(t.meanSeparation(0.0)));
    EXPECT_TRUE(std::isnan(t.meanSeparation(-1.0)));
    EXPECT_THROW(t.meanSeparation(nan()), ParameterError);
    // A table cut by maxPressure holds its last value up to complete contact, as the others.
    const ContactTable cut(l.model, 1e-9 * Ep, 1e-4 * Ep, 40, law.get());
    EXPECT_EQ(cut.end(), ContactTable::End::maxPressure);
    EXPECT_EQ(cut.meanSeparation(1e-3 * Ep), cut.separations().back());
    EXPECT_EQ(cut.separations().back(), persson.meanSeparation(cut.pressures().back() / Ep));
}

TEST(Separation, MultiscaleBarberColumnFallsToZeroAtCompleteContact)
{
    const Laws l("hertz");
    const double Ep = steel.reducedModulus();
    const auto law = l.law("multiscaleBarber");
    const ContactTable t(l.model, 1e-9 * Ep, Ep, 40, law.get());
    ASSERT_TRUE(t.hasSeparation());
    EXPECT_EQ(t.end(), ContactTable::End::completeContact);
    const std::vector<double>& Y = t.separations();
    for (std::size_t k = 0; k < Y.size(); ++k) {
        EXPECT_EQ(Y[k], law->meanSeparation(t.pressures()[k])) << k; // the running minimum never acts
        if (k > 0) {
            EXPECT_LE(Y[k], Y[k - 1]) << k;
        }
    }
    // The table ends within 1e-6 of complete contact, where Y is all but 0 (the light-load Y is
    // 160 um, the last ~3e-12 m).
    EXPECT_LT(Y.back(), 1e-6 * Y.front());
    EXPECT_EQ(t.meanSeparation(t.completeContactPressure()), 0.0);
}

namespace {
// A law of h_c/k_s = P/1e3 whose Y falls as -ln P but bumps up by `bump` on (1e7, 1.3e7) Pa, or
// is `fixed` everywhere.
class BumpyLaw final : public ConductanceLaw {
public:
    BumpyLaw(double bump, double fixed = 1.0) : bump_(bump), fixed_(fixed) {}
    std::string name() const override { return "bumpy"; }
    double perConductivity(double P) const override { return P / 1e3; }
    double meanSeparation(double P) const override
    {
        if (fixed_ != 1.0) {
            return fixed_;
        }
        return 1e-5 * (1.0 - 0.04 * std::log(P / 1e3)) + (P > 1e7 && P < 1.3e7 ? bump_ : 0.0);
    }

private:
    double bump_;
    double fixed_;
};
} // namespace

TEST(Separation, TheTableKeepsALawsSeparationNonIncreasing)
{
    const Laws l("jacksonGreen");
    const double Ep = steel.reducedModulus();
    // The running minimum cuts the bump to the value before it (a loading path never opens
    // the gap) and leaves the rest as the law gives it.
    const BumpyLaw bumpy(1e-7);
    const ContactTable t(l.model, 1e-9 * Ep, 1e-3 * Ep, 40, &bumpy);
    ASSERT_TRUE(t.hasSeparation());
    std::size_t cut = 0;
    for (std::size_t k = 0; k < t.pressures().size(); ++k) {
        const double P = t.pressures()[k];
        if (k > 0) {
            EXPECT_LE(t.separations()[k], t.separations()[k - 1]) << k;
        }
        if (P > 1e7 && P < 1.3e7) {
            ++cut;
            EXPECT_LT(t.separations()[k], bumpy.meanSeparation(P)) << k;
        } else {
            EXPECT_EQ(t.separations()[k], bumpy.meanSeparation(P)) << k;
        }
    }
    EXPECT_GT(cut, 0u);
    // A law whose Y is NaN has no column; one whose Y is negative or infinite is refused.
    const BumpyLaw none(0.0, nan());
    EXPECT_FALSE(ContactTable(l.model, 1e-9 * Ep, 1e-3 * Ep, 40, &none).hasSeparation());
    for (double bad : {-1e-9, std::numeric_limits<double>::infinity()}) {
        const BumpyLaw wrong(0.0, bad);
        try {
            ContactTable(l.model, 1e-9 * Ep, 1e-3 * Ep, 40, &wrong);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const ParameterError& e) {
            EXPECT_NE(std::string(e.what()).find("the law bumpy gives a mean separation of"), std::string::npos)
                << e.what();
        }
    }
}

TEST(Separation, TablesWithoutASeparationSayNone)
{
    const Laws l("jacksonGreen");
    const double Ep = steel.reducedModulus();
    const ContactTable sum(l.model, 1e-9 * Ep, Ep); // the multi-scale constriction sum
    const auto mikic = l.law("mikic");
    const ContactTable correlation(l.model, 1e-9 * Ep, Ep, 40, mikic.get());
    for (const ContactTable* t : {&sum, &correlation}) {
        EXPECT_FALSE(t->hasSeparation());
        EXPECT_TRUE(t->separations().empty());
        EXPECT_TRUE(std::isnan(t->meanSeparation(1e6)));
    }
}

TEST(Separation, FromPointsInterpolatesAndRefusesABadColumnNamingIt)
{
    const std::vector<double> P{1e6, 1e7, 1e8};
    const std::vector<double> A{0.01, 0.1, 0.5};
    const std::vector<double> H{1e3, 1e4, 1e5};
    const double Ep = 1e11;
    const ContactTable t = ContactTable::fromPoints(P, A, H, 2e8, ContactTable::End::completeContact, Ep,
                                                    {3e-6, 2e-6, 0.5e-6});
    ASSERT_TRUE(t.hasSeparation());
    EXPECT_NEAR(t.meanSeparation(std::sqrt(1e6 * 1e7)), 2.5e-6, 1e-20);   // halfway in log P
    EXPECT_NEAR(t.meanSeparation(std::sqrt(1e7 * 1e8)), 1.25e-6, 1e-20);
    EXPECT_NEAR(t.meanSeparation(1e5), 4e-6, 1e-20);                     // the first slope, a decade down
    EXPECT_NEAR(t.meanSeparation(1e3), 6e-6, 1e-20);
    EXPECT_EQ(t.meanSeparation(1.5e8), 0.5e-6);                           // held to complete contact
    EXPECT_EQ(t.meanSeparation(2e8), 0.0);
    // Without the column: none.
    const ContactTable none = ContactTable::fromPoints(P, A, H, 2e8, ContactTable::End::completeContact, Ep);
    EXPECT_FALSE(none.hasSeparation());
    EXPECT_TRUE(std::isnan(none.meanSeparation(1e7)));
    // Bad columns: the error names the point and what is wrong.
    const auto refused = [&](std::vector<double> Y, const std::string& why) {
        try {
            ContactTable::fromPoints(P, A, H, 2e8, ContactTable::End::completeContact, Ep, Y);
            ADD_FAILURE() << "accepted: " << why;
        } catch (const ParameterError& e) {
            EXPECT_EQ(e.parameter(), "contact table");
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    };
    refused({3e-6, -1e-9, 0.0}, "point 2: the mean separation -1.0000000000000001e-09 m is negative");
    refused({3e-6, nan(), 0.0}, "point 2: the mean separation nan m is NaN");
    refused({3e-6, 2e-6, std::numeric_limits<double>::infinity()}, "point 3: the mean separation inf m is not finite");
    refused({3e-6, 3.5e-6, 1e-6}, "point 2: the mean separation 3.4999999999999999e-06 m exceeds the one before");
    refused({3e-6, 2e-6}, "the pressures and mean separations differ in number");
    // Equal neighbours are non-increasing: accepted.
    EXPECT_NO_THROW(ContactTable::fromPoints(P, A, H, 2e8, ContactTable::End::completeContact, Ep, {1e-6, 1e-6, 0.0}));
}

TEST(Separation, ContactInterfaceForwardsTheTablesColumn)
{
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::powerLaw;
    s.parameters = {0.0376, 1.3, 1e3, 64e3};
    spec.surfaces = {s};
    spec.side1 = Material{200e9, 0.3, 0.5e9};
    spec.side2 = Material{200e9, 0.3, 0.5e9};
    spec.conductanceLaw = "persson";
    const ContactInterface withY(spec);
    ASSERT_TRUE(withY.hasSeparation());
    const PerssonModel persson(withY.surface(), withY.reducedModulus());
    const double P = withY.table().pressures()[7];
    EXPECT_EQ(withY.meanSeparation(P), persson.meanSeparation(P / withY.reducedModulus()));
    EXPECT_EQ(withY.meanSeparation(3e7), withY.table().meanSeparation(3e7));
    EXPECT_TRUE(std::isnan(withY.meanSeparation(0.0)));
    spec.conductanceLaw.clear(); // the default law: no separation
    const ContactInterface without(spec);
    EXPECT_FALSE(without.hasSeparation());
    EXPECT_TRUE(std::isnan(without.meanSeparation(3e7)));
}
