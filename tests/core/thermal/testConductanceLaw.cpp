// SPDX-License-Identifier: GPL-3.0-or-later
// The conductance laws by name (ConductanceLaw.hpp): every name builds, each law is the formula
// it names (the functions tested on their own in testConstrictionConductance, testCorrelations),
// and a missing input or an unknown name is an error that says what is missing or what is known.
#include "roughContact/Error.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"
#include "roughContact/thermal/CooperMikicYovanovich.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"
#include "roughContact/thermal/Mikic.hpp"
#include "roughContact/thermal/MultiscaleBarber.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace roughContact;

namespace {

const ContactMaterials steel = ContactMaterials::againstRigidFlat(Material{200e9, 0.3, 0.5e9});

Spectrum surface()
{
    return Spectrum::powerLaw(1e-9, 1.3, 1e3, 64e3);
}

std::string errorOf(const std::string& name, const ConductanceLawInputs& in)
{
    try {
        makeConductanceLaw(name, in);
    } catch (const ParameterError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ConductanceLaw, EveryNameBuildsAndIsTheFormulaItNames)
{
    const Spectrum s = surface();
    const MultiscaleModel model(s, steel.reducedModulus(), makeAsperityModel("hertz", steel));
    ConductanceLawInputs in;
    in.multiscale = &model;
    in.spectrum = &s;
    in.roughness = spectrumRoughness(s);
    in.Eprime = steel.reducedModulus();
    in.microhardness = 1.42e9;
    in.hardness = 1.2e9;
    ASSERT_FALSE(conductanceLawNames().empty());
    EXPECT_TRUE(isConductanceLaw(defaultConductanceLaw()));
    const PerssonModel persson(s, steel.reducedModulus());
    const MultiscaleBarber barber(model, s);
    for (const std::string& name : conductanceLawNames()) {
        const auto law = makeConductanceLaw(name, in);
        EXPECT_EQ(law->name(), name);
        EXPECT_EQ(law->perConductivity(0.0), 0.0) << name;
        for (double P : {1e4, 1e6, 1e8}) {
            const double h = law->perConductivity(P);
            EXPECT_TRUE(h > 0.0 && !std::isnan(h)) << name << " at " << P;
            double expected = 0.0;
            if (name == "jacksonBhavnaniFerguson") {
                expected = constrictionConductancePerConductivity(model, P / steel.reducedModulus());
            } else if (name == "multiscaleBarber") {
                expected = barber.conductancePerConductivity(P / steel.reducedModulus());
            } else if (name == "persson") {
                expected = persson.conductancePerConductivity(P / steel.reducedModulus());
            } else if (name == "mikic") {
                expected = mikicConductancePerConductivity(P, *in.roughness, in.Eprime);
            } else if (name == "cooperMikicYovanovich") {
                expected = cooperMikicYovanovichConductancePerConductivity(P, *in.roughness, 1.42e9);
            } else if (name == "fittedElastoPlastic") {
                expected = fittedElastoPlasticConductancePerConductivity(P, *in.roughness, spectralBandwidthRatio(s),
                                                                         in.Eprime, 1.2e9, 0.0, firstLevelShare(s));
            } else {
                ADD_FAILURE() << "no expectation for the law " << name;
            }
            EXPECT_EQ(h, expected) << name << " at " << P;
        }
        EXPECT_THROW(law->perConductivity(-1.0), ParameterError) << name;
        EXPECT_THROW(law->perConductivity(std::numeric_limits<double>::quiet_NaN()), ParameterError) << name;
    }
    // Vickers coefficients instead of H_c.
    ConductanceLawInputs vickers = in;
    vickers.microhardness.reset();
    vickers.vickers = VickersCoefficients{5e9, -0.2};
    EXPECT_EQ(makeConductanceLaw("cooperMikicYovanovich", vickers)->perConductivity(1e6),
              cooperMikicYovanovichConductancePerConductivity(1e6, *in.roughness, *vickers.vickers));
}

TEST(ConductanceLaw, MissingInputsAndUnknownNamesSayWhat)
{
    ConductanceLawInputs none;
    EXPECT_NE(errorOf("jacksonBhavnaniFerguson", none).find("multi-scale"), std::string::npos);
    EXPECT_NE(errorOf("mikic", none).find("sigma"), std::string::npos);
    EXPECT_NE(errorOf("persson", none).find("spectrum"), std::string::npos);
    EXPECT_NE(errorOf("multiscaleBarber", none).find("multi-scale"), std::string::npos);
    none.roughness = SurfaceRoughness{1e-6, 0.1};
    EXPECT_NE(errorOf("mikic", none).find("E'"), std::string::npos); // E' = 0
    EXPECT_NE(errorOf("cooperMikicYovanovich", none).find("microhardness"), std::string::npos);
    none.microhardness = 1e9;
    none.vickers = VickersCoefficients{5e9, -0.2};
    EXPECT_NE(errorOf("cooperMikicYovanovich", none).find("not both"), std::string::npos);
    const std::string unknown = errorOf("holm", none);
    EXPECT_NE(unknown.find("unknown law 'holm'"), std::string::npos);
    for (const std::string& name : conductanceLawNames()) {
        EXPECT_NE(unknown.find(name), std::string::npos) << unknown;
    }
}
