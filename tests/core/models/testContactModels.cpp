// SPDX-License-Identifier: GPL-3.0-or-later
// Properties every contact model must have, through the factory users select them by:
// A_r/A_n is 0 at no load, finite, within [0, 1] and never decreases with load, from the
// lightest load to far beyond complete contact, on a measured-like surface and on a power law;
// bad loads and missing material data are refused with the parameter named.
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace roughContact;

namespace {

const ContactMaterials steel = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});

Spectrum standin()
{
    return Spectrum::fromProfile(
        readProfile(std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv"));
}

// Largest relative decrease of the area over a dense log-spaced sweep of loads [lo, hi].
double worstDrop(const ContactModel& m, double lo, double hi, int n)
{
    double previous = 0.0;
    double worst = 0.0;
    for (int k = 0; k < n; ++k) {
        const double load = lo * std::pow(hi / lo, double(k) / (n - 1));
        const double a = m.areaFraction(load);
        EXPECT_TRUE(std::isfinite(a)) << "load " << load;
        EXPECT_GE(a, 0.0) << "load " << load;
        EXPECT_LE(a, 1.0) << "load " << load;
        if (previous > 0.0) {
            worst = std::max(worst, (previous - a) / previous);
        }
        previous = std::max(previous, a);
    }
    return worst;
}

void checkProperties(const Spectrum& s)
{
    for (const std::string& name : modelNames()) {
        SCOPED_TRACE(name);
        const auto m = makeContactModel(name, s, steel);
        EXPECT_EQ(m->name(), name);
        EXPECT_EQ(m->areaFraction(0.0), 0.0);
        const double drop = worstDrop(*m, 1e-9, 10.0, 121);
        if (name == "jgh") {
            // The seed's JGH form (Eq. 9 at pbar/p* = 0.8 is 1.208x Eq. 10) drops the area where
            // a level switches between them (docs/theory.md §3.2): 9.55 % for one level, damped by the
            // finer partial levels (testMultiscaleModel, which pins the one-level step and
            // uses the same empirical 1 % on its surface); measured <= 0.4 % on these surfaces.
            // Its corrected sibling jghConsistent is checked strictly with the others.
            EXPECT_LT(drop, 0.01);
        } else {
            EXPECT_EQ(drop, 0.0);
        }
        // Far beyond any complete contact every model reports complete contact, exactly 1: at
        // F = 1000 A_n E' the mean pressure exceeds every level's p* (2 pi E' b f, with slopes
        // b f far below 1000/(2 pi)) and any hardness (~3 S_y = 3e-3 E'), and GW's summits
        // flattened cover more than A_n. (Was: <= 1, which every model's cap satisfies at any load.)
        EXPECT_EQ(m->areaFraction(1e3), 1.0);
        EXPECT_THROW(m->areaFraction(-1e-5), std::invalid_argument);
        EXPECT_THROW(m->areaFraction(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
        EXPECT_THROW(m->areaFraction(std::numeric_limits<double>::infinity()), std::invalid_argument);
    }
}

} // namespace

TEST(ContactModels, PropertiesOnTheStandin)
{
    checkProperties(standin());
}

TEST(ContactModels, PropertiesOnAPowerLaw)
{
    // b_m f^-1.2 between 1/L and 1000/L (a steep, fractal-like spectrum).
    checkProperties(Spectrum::powerLaw(1e-7 * std::pow(2e3, 1.2), 1.2, 2e3, 2e6, 5e-4));
}

TEST(ContactModels, FactoryRefusesWhatItCannotBuild)
{
    const Spectrum s = standin();
    EXPECT_THROW(makeContactModel("hertzian", s, steel), std::invalid_argument);
    const ContactMaterials elastic =
        ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, std::nullopt});
    for (const char* name : {"jacksonGreen", "truncation", "greenwoodWilliamsonJG", "majumdarBhushan"}) {
        SCOPED_TRACE(name);
        try {
            makeContactModel(name, s, elastic);
            ADD_FAILURE() << "built without S_y";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("S_y"), std::string::npos) << e.what();
        }
    }
    // The purely elastic models need no S_y.
    for (const char* name : {"hertz", "jgh", "jghConsistent", "greenwoodWilliamson", "persson"}) {
        EXPECT_NO_THROW(makeContactModel(name, s, elastic)) << name;
    }
    EXPECT_EQ(modelNames().size(), multiscaleModelNames().size() + 4);
    for (const std::string& n : multiscaleModelNames()) {
        EXPECT_TRUE(isMultiscaleModel(n));
    }
    EXPECT_FALSE(isMultiscaleModel("greenwoodWilliamson"));
}
