// SPDX-License-Identifier: GPL-3.0-or-later
// The multi-scale framework (seed §2.1) against the closed forms of seed §2.3.
#include "roughContact/asperity/Hertz.hpp"
#include "roughContact/asperity/JacksonGreen.hpp"
#include "roughContact/asperity/JohnsonGreenwoodHigginson.hpp"
#include "roughContact/asperity/Truncation.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/surface/SyntheticProfile.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double Ep = 200e9; // seed Table 1
constexpr double nu = 0.32;
constexpr double Sy = 0.2e9;
const double E = Ep * (1.0 - nu * nu);

Spectrum standIn()
{
    return Spectrum::fromProfile(generateSyntheticProfile({}));
}

std::vector<std::shared_ptr<const AsperityModel>> allAsperityModels()
{
    using Form = JohnsonGreenwoodHigginson::Form;
    return {std::make_shared<Hertz>(Ep), std::make_shared<JohnsonGreenwoodHigginson>(Ep),
            std::make_shared<JohnsonGreenwoodHigginson>(Ep, Form::consistent),
            std::make_shared<JacksonGreen>(Ep, nu, E, Sy), std::make_shared<Truncation>(Ep, nu, Sy)};
}
} // namespace

TEST(MultiscaleModel, hertzFollowsRecursionOfSeedEquation26)
{
    const Spectrum s = standIn();
    const MultiscaleModel m(s, Ep, std::make_shared<Hertz>(Ep));
    for (double load : {1e-6, 7.94e-5, 1e-3}) {
        const auto trace = m.trace(load);
        const double An = s.nominalArea();
        double previous = 1.0; // A_{i-1}/A_n
        double worst = 0.0;
        for (const LevelState& st : trace) {
            double eq26 = 0.25 * std::cbrt(9.0 / (2.0 * pi)) * std::cbrt(load * load) *
                          std::cbrt(std::pow(1.0 / (st.frequency * st.amplitude), 2.0)) *
                          std::cbrt(previous);
            eq26 = std::min(eq26, previous); // assumption 5
            worst = std::max(worst, std::abs(st.area / An / eq26 - 1.0));
            previous = st.area / An;
        }
        // Each level adds a few ulp (pow, cbrt, products) and errors carry forward with
        // exponent 1/3, so they do not accumulate beyond ~10 eps.
        EXPECT_LT(worst, 1e-13) << "load " << load;
        EXPECT_DOUBLE_EQ(m.areaFraction(load), trace.back().area / An);
    }
}

TEST(MultiscaleModel, hertzReachesClosedFormOfSeedEquations29And30)
{
    // beta_i = b / f_i at every level (i* = 0, A_{i*} = A_n): A_k/A_n = C^(3/2 (1 - 3^-k)),
    // C = (1/4)(9/(2 pi))^(1/3) (F/(E' A_n b))^(2/3) (Eqs. 28-29), -> C^(3/2) (Eq. 30).
    const double L = 1e-3;
    const double b = 3e-4;
    for (std::size_t levels : {1u, 2u, 5u, 40u}) {
        std::vector<double> f;
        std::vector<double> beta;
        for (std::size_t i = 1; i <= levels; ++i) {
            f.push_back(double(i) / L);
            beta.push_back(b / f.back());
        }
        const MultiscaleModel m(Spectrum(f, beta, L), Ep, std::make_shared<Hertz>(Ep));
        for (double load : {1e-7, 1e-5, 1e-4}) {
            const double C = 0.25 * std::cbrt(9.0 / (2.0 * pi)) * std::cbrt(std::pow(load / b, 2.0));
            const double eq29 = std::pow(C, 1.5 * (1.0 - std::pow(3.0, -double(levels))));
            // Round-off: ~10 ulp per level, damped by the 1/3 power (see the test above).
            EXPECT_NEAR(m.areaFraction(load) / eq29, 1.0, 1e-13) << levels << " levels, load " << load;
            if (levels == 40) {
                const double eq30 = 3.0 * load / (8.0 * std::sqrt(2.0 * pi) * b); // A_r/A_n
                EXPECT_NEAR(m.areaFraction(load) / eq30, 1.0, 1e-13);
            }
        }
    }
}

TEST(MultiscaleModel, areaBetweenZeroAndNominalAndNeverDecreasingWithLoad)
{
    const Spectrum s = standIn();
    for (const auto& asperity : allAsperityModels()) {
        const MultiscaleModel m(s, Ep, asperity);
        double previous = 0.0;
        std::size_t drops = 0;
        double worstDrop = 0.0;
        for (double load = 1e-9; load < 10.0; load *= 1.02) {
            const double a = m.areaFraction(load);
            ASSERT_TRUE(std::isfinite(a)) << asperity->name() << " load " << load;
            ASSERT_GE(a, 0.0);
            ASSERT_LE(a, 1.0);
            if (a < previous) {
                ++drops;
                worstDrop = std::max(worstDrop, 1.0 - a / previous);
            }
            previous = std::max(previous, a);
        }
        if (asperity->name() == "jgh") {
            // The seed's JGH form drops where a level crosses pbar/p* = 0.8: Eq. 9 > 1 is capped
            // at complete contact, then Eq. 10 gives 1 - 3 (0.2)/(2 pi) = 0.9045, a 9.55 % step
            // of that level's area (pinned exactly by the one-level test below). In the final
            // area the step is damped by the partial levels finer than the switching one: each
            // takes about the cube root of the area it is given (A_k ~ F^(2/3) A_{k-1}^(1/3),
            // seed Eq. 26), so after m of them the drop is about 1 - 0.9045^(3^-m): 3.3 %,
            // 1.1 %, 0.37 % for m = 1, 2, 3. How many there are depends on the surface, so the
            // bound is empirical: measured 0.42 % here and <= 0.4 % on the surfaces of
            // testContactModels, which uses the same 1 %. It fails if the switch moves to 0.85
            // (5.5 % here). (Was: 9.55 %, the undamped one-level step, 23 times the measured
            // drop, while testContactModels allowed 1 % for the same quantity.)
            std::printf("jgh (seed form): %zu drops, worst %.3g %%\n", drops, 100 * worstDrop);
            EXPECT_GE(drops, 1u) << "the seed form's drop is what this documents";
            EXPECT_LT(worstDrop, 0.01);
        } else {
            EXPECT_EQ(drops, 0u) << asperity->name() << " worst drop " << worstDrop;
        }
        EXPECT_EQ(m.areaFraction(0.0), 0.0);
    }
}

TEST(MultiscaleModel, seedJghDropOfOneLevelIsEquation10AtPoint8)
{
    // One level: A_r/A_n is that level's ratio at pbar = load E' (seed Eq. 2 with i = 1). With
    // p* = 2 pi E' b f (seed Eq. 6), just below pbar = 0.8 p* Eq. 9 exceeds 1 (1.208 x Eq. 10)
    // and the area is complete contact, 1; at and above 0.8 p* it is Eq. 10,
    // 1 - 3 (1 - x)/(2 pi): at x = 0.8 (1 + 1e-9) 1 - 0.6/(2 pi) + 3 (0.8e-9)/(2 pi), i.e. a
    // drop of 0.6/(2 pi) = 9.549 % to 4e-10; 1e-9 covers it and the rounding of x.
    const double L = 1e-3;
    const double f = 1.0 / L;
    const double b = 1e-7;
    const MultiscaleModel m(Spectrum({f}, {b}, L), Ep, std::make_shared<JohnsonGreenwoodHigginson>(Ep));
    const double switchLoad = 0.8 * 2.0 * pi * b * f; // 0.8 p*/E'
    const double before = m.areaFraction(switchLoad * (1.0 - 1e-9));
    const double after = m.areaFraction(switchLoad * (1.0 + 1e-9));
    EXPECT_EQ(before, 1.0);
    EXPECT_NEAR(1.0 - after / before, 0.6 / (2.0 * pi), 1e-9);
}

TEST(MultiscaleModel, completeContactAtVeryHighLoad)
{
    const Spectrum s = standIn();
    // At F/(A_n E') far above every level's p*/E' the JGH levels are all in complete contact.
    const MultiscaleModel m(s, Ep, std::make_shared<JohnsonGreenwoodHigginson>(Ep));
    EXPECT_EQ(m.areaFraction(1.0), 1.0);
    const MultiscaleModel jg(s, Ep, std::make_shared<JacksonGreen>(Ep, nu, E, Sy));
    EXPECT_EQ(jg.areaFraction(1e3), 1.0);
}

TEST(MultiscaleModel, skipsLevelsWithZeroAmplitude)
{
    const MultiscaleModel a(Spectrum({1e3, 2e3, 3e3}, {1e-7, 0.0, 2e-8}, 1e-3), Ep, std::make_shared<Hertz>(Ep));
    const MultiscaleModel b(Spectrum({1e3, 3e3}, {1e-7, 2e-8}, 1e-3), Ep, std::make_shared<Hertz>(Ep));
    EXPECT_EQ(a.levels().size(), 2u);
    EXPECT_DOUBLE_EQ(a.areaFraction(1e-4), b.areaFraction(1e-4));
    EXPECT_EQ(a.trace(1e-4).back().index, 2u);
}

TEST(MultiscaleModel, rejectsBadLoads)
{
    const MultiscaleModel m(standIn(), Ep, std::make_shared<Hertz>(Ep));
    EXPECT_THROW(m.areaFraction(-1e-5), std::invalid_argument);
    EXPECT_THROW(m.areaFraction(std::nan("")), std::invalid_argument);
    EXPECT_THROW(m.areaFraction(INFINITY), std::invalid_argument);
}

TEST(MultiscaleModel, traceIsConsistentWithAssumptions2And3)
{
    const Spectrum s = standIn();
    const double load = 7.94e-5; // seed Fig. 5
    const MultiscaleModel m(s, Ep, std::make_shared<Hertz>(Ep));
    const double F = load * s.nominalArea() * Ep;
    double previous = s.nominalArea();
    for (const LevelState& st : m.trace(load)) {
        EXPECT_NEAR(st.asperities / (st.density * previous), 1.0, 1e-15); // N_i = eta_i A_{i-1}
        EXPECT_NEAR(st.asperityForce * st.asperities / F, 1.0, 1e-15);   // every level carries F
        EXPECT_LE(st.area, previous);                                     // assumption 5
        EXPECT_EQ(st.complete, st.area == previous);
        previous = st.area;
    }
}

// MultiscaleModel skips the asperity law at levels it knows (from each law's
// forceBeyondArea / p*) to be in complete contact. The skip must not change a single bit: this
// recomputes the recursion of seed Eqs. 1-2 with every level evaluated and compares exactly,
// for all five laws, on two surfaces (stand-in: most levels complete; a coarse power law with
// few, elastic levels), over loads from far below to beyond complete contact.
TEST(MultiscaleModel, completeContactShortcutGivesBitIdenticalAreas)
{
    // The power law: rms 0.09 nm, above the 1 fm floor of limits::minimumRoughness.
    const Spectrum surfaces[] = {standIn(), Spectrum::powerLaw(1e-10, 1.0, 1e3, 1e5, 0.0)};
    for (const Spectrum& s : surfaces) {
        for (const auto& asperity : allAsperityModels()) {
            const MultiscaleModel m(s, Ep, asperity);
            std::size_t compared = 0;
            for (double load = 1e-10; load < 20.0; load *= 1.15) {
                const double F = load * m.nominalArea() * Ep;
                double A = m.nominalArea();
                for (const Level& level : m.levels()) {
                    const double r = asperity->areaRatio(F / A, level);
                    if (r < 1.0) {
                        A *= r;
                    }
                }
                const double reference = A / m.nominalArea();
                ASSERT_EQ(m.areaFraction(load), reference) << asperity->name() << " load " << load;
                ++compared;
            }
            EXPECT_GT(compared, 150u);
        }
    }
}

TEST(MultiscaleModel, anElasticContactUnloadsAlongItsLoadingCurve)
{
    // Hertzian asperities: Abar ~ Fbar^(2/3) on loading, so the Hertzian unloading of each level
    // from its peak is its loading curve, whatever the peak; to round-off (pow and products
    // over the levels, as hertzFollowsRecursionOfSeedEquation26).
    const Spectrum s = standIn();
    const MultiscaleModel m(s, Ep, std::make_shared<Hertz>(Ep));
    for (double peak : {1e-5, 1e-3, 1e-1}) {
        for (double f : {1.0, 0.5, 0.1, 1e-3}) {
            EXPECT_NEAR(m.unloadingAreaFraction(f * peak, peak), m.areaFraction(f * peak),
                        1e-12 * m.areaFraction(f * peak))
                << "peak " << peak << ", fraction " << f;
        }
    }
}

TEST(MultiscaleModel, aContactThatYieldedKeepsMoreAreaOnUnloading)
{
    // The stand-in's levels are plastic (A = F/H) at light loads, where the hertzian rule keeps
    // almost nothing more than loading (docs/theory.md §3.6: each finer level recovers part of
    // what the coarser one shed); from a peak at complete contact (3e-3) the levels that were
    // complete separate Hertzian, and the area stays above the loading curve.
    const Spectrum s = standIn();
    for (const auto& asperity : {std::shared_ptr<const AsperityModel>(std::make_shared<JacksonGreen>(Ep, nu, E, Sy)),
                                 std::shared_ptr<const AsperityModel>(std::make_shared<Truncation>(Ep, nu, Sy))}) {
        SCOPED_TRACE(asperity->name());
        const MultiscaleModel m(s, Ep, asperity);
        const double peak = 3e-3;
        // At and above the peak: the loading curve, bit for bit.
        EXPECT_EQ(m.unloadingAreaFraction(peak, peak), m.areaFraction(peak));
        EXPECT_EQ(m.unloadingAreaFraction(2 * peak, peak), m.areaFraction(2 * peak));
        double previous = m.areaFraction(peak);
        for (double f = 0.95; f > 1e-3; f *= 0.9) {
            const double unloaded = m.unloadingAreaFraction(f * peak, peak);
            ASSERT_TRUE(std::isfinite(unloaded));
            EXPECT_LE(unloaded, previous * (1 + 1e-12)) << f; // it falls as the load does
            EXPECT_GE(unloaded, m.areaFraction(f * peak) * (1 - 1e-12)) << f; // never below loading
            previous = unloaded;
        }
        for (double f : {0.5, 0.1}) {
            EXPECT_GT(m.unloadingAreaFraction(f * peak, peak), 1.02 * m.areaFraction(f * peak)) << f;
        }
        EXPECT_EQ(m.unloadingAreaFraction(0.0, peak), 0.0);
    }
}

TEST(MultiscaleModel, oneLevelUnloadsAsAHertzianContactOfItsPeak)
{
    // One level: A/A_n = r(pbar) on loading; unloaded from pbar_max, r(pbar_max) (pbar/pbar_max)^(2/3).
    Spectrum one({1e4}, {1e-6}, 1e-3, "one level");
    const auto jg = std::make_shared<JacksonGreen>(Ep, nu, E, Sy);
    const MultiscaleModel m(one, Ep, jg);
    const double peak = 3e-4; // A_r/A_n 0.10, the summits well past yield
    const double rMax = m.areaFraction(peak);
    ASSERT_LT(rMax, 1.0);
    for (double f : {0.5, 0.1, 0.01}) {
        EXPECT_NEAR(m.unloadingAreaFraction(f * peak, peak), rMax * std::pow(f, 2.0 / 3.0), 1e-14) << f;
    }
    // The level yielded at that peak: unloading keeps more than loading.
    EXPECT_GT(m.unloadingAreaFraction(0.1 * peak, peak), 1.5 * m.areaFraction(0.1 * peak)); // 1.96
}

TEST(MultiscaleModel, NoModelUnloadsBelowItsLoadingCurveAndElasticOnesRetraceIt)
{
    // Every asperity law, peaks from light to complete contact: the unloading area never falls
    // below the loading one at the same load (the flattened summits keep at least the virgin
    // contact), and an elastic law's (hertz, jgh, jghConsistent) is its loading curve, bit for bit.
    // (jgh caps a level at complete contact and grows faster than p^(2/3) near it: the Hertzian
    // rule alone would drop such levels, 0.1 instead of 1.0 at a tenth of the peak 0.1.)
    const Spectrum s = standIn();
    for (const auto& asperity : allAsperityModels()) {
        SCOPED_TRACE(asperity->name());
        const MultiscaleModel m(s, Ep, asperity);
        for (double peak : {1e-4, 1e-3, 1e-2, 1e-1}) {
            for (double f : {0.9, 0.5, 0.1, 0.01}) {
                const double unloaded = m.unloadingAreaFraction(f * peak, peak);
                const double loaded = m.areaFraction(f * peak);
                if (asperity->yields()) {
                    EXPECT_GE(unloaded, loaded) << "peak " << peak << ", fraction " << f;
                } else {
                    EXPECT_EQ(unloaded, loaded) << "peak " << peak << ", fraction " << f;
                }
            }
        }
    }
}
