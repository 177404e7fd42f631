// SPDX-License-Identifier: GPL-3.0-or-later
// The pair of solids (material/Materials.hpp): E', which one yields first, and the rule that a
// yield strength on one side only must be meant (issue 21: a S_y left off one side by mistake was
// taken silently, and the other side's then governed).
#include "roughContact/Error.hpp"
#include "roughContact/material/Materials.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace roughContact;

namespace {
// The message of the ParameterError f throws (empty when it throws none).
template <class F> std::string errorOf(F f)
{
    try {
        f();
    } catch (const ParameterError& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(Materials, ReducedModulusAndTheSofterYieldsFirst)
{
    const Material steel{200e9, 0.3, 0.5e9};
    const Material aluminium{68.9e9, 0.33, 276e6};
    const ContactMaterials c = ContactMaterials::pair(steel, aluminium, "side1", "side2");
    // 1/E' = (1 - 0.09)/200e9 + (1 - 0.1089)/68.9e9: the sum of the two compliances.
    EXPECT_NEAR(c.reducedModulus(), 1.0 / (0.91 / 200e9 + 0.8911 / 68.9e9), 1e-6);
    EXPECT_EQ(c.yieldStrength("test"), 276e6);
    EXPECT_EQ(c.poissonRatio("test"), 0.33);
    EXPECT_EQ(c.youngModulus("test"), 68.9e9);
}

TEST(Materials, AYieldStrengthOnOneSideOnlyIsAnErrorNamingTheOtherSide)
{
    const Material yielding{200e9, 0.3, 0.4e9};
    const Material forgotten{200e9, 0.3, std::nullopt};
    for (const bool yieldingFirst : {true, false}) {
        SCOPED_TRACE(yieldingFirst);
        const std::string what = errorOf([&] {
            yieldingFirst ? ContactMaterials::pair(yielding, forgotten, "side1", "side2")
                          : ContactMaterials::pair(forgotten, yielding, "side1", "side2");
        });
        const std::string missing = yieldingFirst ? "side2" : "side1";
        const std::string other = yieldingFirst ? "side1" : "side2";
        EXPECT_EQ(what.rfind(missing + " yield strength S_y", 0), 0U) << what;
        EXPECT_NE(what.find("while " + other + " has one (S_y = 4e+08 Pa)"), std::string::npos) << what;
        EXPECT_NE(what.find("Sy none;"), std::string::npos) << what; // how to say it does not yield
    }
    // Neither side yields: an elastic pair, no error (the elastic models need no S_y).
    EXPECT_FALSE(ContactMaterials::pair(forgotten, forgotten).hasYieldStrength());
}

TEST(Materials, ASideSaidNotToYieldLeavesTheOtherAsTheYieldingOne)
{
    const Material yielding{200e9, 0.3, 0.4e9};
    Material ceramic{300e9, 0.25, std::nullopt};
    ceramic.elastic = true;
    for (const bool yieldingFirst : {true, false}) {
        const ContactMaterials c = yieldingFirst ? ContactMaterials::pair(yielding, ceramic, "side1", "side2")
                                                 : ContactMaterials::pair(ceramic, yielding, "side1", "side2");
        EXPECT_EQ(c.yieldStrength("test"), 0.4e9);
        EXPECT_EQ(c.youngModulus("test"), 200e9);
    }
    // Said not to yield and given a yield strength: one or the other.
    Material both = ceramic;
    both.Sy = 1e9;
    const std::string what = errorOf([&] { ContactMaterials::pair(yielding, both, "side1", "side2"); });
    EXPECT_EQ(what.rfind("side2 yield strength S_y", 0), 0U) << what;
    EXPECT_NE(what.find("also said not to yield"), std::string::npos) << what;
    // Against a rigid flat there is no other side: elastic or not, no rule applies.
    EXPECT_FALSE(ContactMaterials::againstRigidFlat(ceramic).hasYieldStrength());
}
