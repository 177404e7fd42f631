// SPDX-License-Identifier: GPL-3.0-or-later
// The published thermal contact conductance correlations (docs/correlations.md): Mikic's elastic
// law (Mikic.hpp), the Cooper-Mikic-Yovanovich plastic law (CooperMikicYovanovich.hpp) and the
// Song-Yovanovich microhardness (Microhardness.hpp). Every expected number is written out from
// the formula, computed independently (python3, double precision), never by the code under test.
#include "ExpectParameterError.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/thermal/CooperMikicYovanovich.hpp"
#include "roughContact/thermal/Microhardness.hpp"
#include "roughContact/thermal/Mikic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace roughContact;

namespace {

// One pow and a few products: a few ulp; 1e-12 relative leaves room for libm differences.
constexpr double roundOff = 1e-12;

// The reference point: sigma = 1 um, m = 0.1, P = 1 MPa, E' = 100 GPa, H_c = 3 GPa,
// Vickers c1 = 5 GPa, c2 = -0.2.
const SurfaceRoughness rough{1e-6, 0.1};
constexpr double P = 1e6;
constexpr double Eprime = 100e9;
constexpr double Hc = 3e9;
const VickersCoefficients vickers{5e9, -0.2};


} // namespace

TEST(Mikic, HandComputedPoint)
{
    // sqrt(2) P/(E' m) = 1.4142136e6/(1e11 * 0.1) = 1.414213562373095e-4;
    // h_c/k_s = 1.54 * (0.1/1e-6) * (1.414213562373095e-4)^0.94 = 37.06848347651331 1/m.
    EXPECT_NEAR(mikicConductancePerConductivity(P, rough, Eprime), 37.06848347651331,
                roundOff * 37.06848347651331);
}

TEST(Mikic, ScalingLaws)
{
    const double h = mikicConductancePerConductivity(P, rough, Eprime);
    // h ~ P^0.94 exactly: doubling P multiplies h by 2^0.94.
    EXPECT_NEAR(mikicConductancePerConductivity(2.0 * P, rough, Eprime) / h, std::pow(2.0, 0.94), roundOff);
    EXPECT_NEAR(mikicConductancePerConductivity(10.0 * P, rough, Eprime) / h, std::pow(10.0, 0.94), roundOff);
    // h ~ 1/sigma at fixed m.
    EXPECT_NEAR(mikicConductancePerConductivity(P, {2.0 * rough.sigma, rough.meanAbsoluteSlope}, Eprime) / h, 0.5,
                roundOff);
    // h ~ m^(1 - 0.94) at fixed sigma (m/sigma times m^-0.94), and ~ E'^-0.94.
    EXPECT_NEAR(mikicConductancePerConductivity(P, {rough.sigma, 2.0 * rough.meanAbsoluteSlope}, Eprime) / h,
                std::pow(2.0, 0.06), roundOff);
    EXPECT_NEAR(mikicConductancePerConductivity(P, rough, 2.0 * Eprime) / h, std::pow(2.0, -0.94), roundOff);
}

TEST(Mikic, ZeroPressureAndBadInputs)
{
    EXPECT_EQ(mikicConductancePerConductivity(0.0, rough, Eprime), 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    expectParameterError([&] { mikicConductancePerConductivity(-1.0, rough, Eprime); }, "contact pressure P");
    expectParameterError([&] { mikicConductancePerConductivity(nan, rough, Eprime); }, "contact pressure P");
    expectParameterError([&] { mikicConductancePerConductivity(inf, rough, Eprime); }, "contact pressure P");
    expectParameterError([&] { mikicConductancePerConductivity(P, {0.0, 0.1}, Eprime); }, "rms roughness sigma");
    expectParameterError([&] { mikicConductancePerConductivity(P, {nan, 0.1}, Eprime); }, "rms roughness sigma");
    expectParameterError([&] { mikicConductancePerConductivity(P, {1e-6, 0.0}, Eprime); }, "mean absolute slope m");
    expectParameterError([&] { mikicConductancePerConductivity(P, {1e-6, nan}, Eprime); }, "mean absolute slope m");
    expectParameterError([&] { mikicConductancePerConductivity(P, rough, 0.0); }, "reduced modulus E'");
    expectParameterError([&] { mikicConductancePerConductivity(P, rough, nan); }, "reduced modulus E'");
}

TEST(CooperMikicYovanovich, HandComputedPointWithGivenHardness)
{
    // h_c/k_s = 1.25 * (0.1/1e-6) * (1e6/3e9)^0.95 = 62.17915574969894 1/m.
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(P, rough, Hc), 62.17915574969894,
                roundOff * 62.17915574969894);
    EXPECT_NEAR(cooperMikicYovanovichFromRelativePressure(P / Hc, rough), 62.17915574969894,
                roundOff * 62.17915574969894);
}

TEST(CooperMikicYovanovich, ScalingLaws)
{
    const double h = cooperMikicYovanovichConductancePerConductivity(P, rough, Hc);
    // With H_c given: h ~ P^0.95 exactly, ~ H_c^-0.95, ~ m/sigma.
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(2.0 * P, rough, Hc) / h, std::pow(2.0, 0.95),
                roundOff);
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(P, rough, 2.0 * Hc) / h, std::pow(2.0, -0.95),
                roundOff);
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(P, {rough.sigma, 3.0 * rough.meanAbsoluteSlope}, Hc) /
                    h,
                3.0, roundOff);
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(P, {4.0 * rough.sigma, rough.meanAbsoluteSlope}, Hc) /
                    h,
                0.25, roundOff);
}

TEST(CooperMikicYovanovich, HandComputedPointWithVickersHardness)
{
    // H_0 = c1 (1.62 sigma'/m)^c2 = 5e9 * (1.62 * 1 / 0.1)^-0.2 = 5e9 * 16.2^-0.2 = 2864619879.312464 Pa;
    // P/H_c = (1e6 / H_0)^(1/(1 + 0.071 * -0.2)) = (3.490864e-4)^(1/0.9858) = 3.1126875097840177e-4;
    // H_c = P/(P/H_c) = 3212657861.9174905 Pa;
    // h_c/k_s = 1.25 * 1e5 * (3.1126875097840177e-4)^0.95 = 58.26245222987142 1/m.
    EXPECT_NEAR(referenceMicrohardness(rough, vickers), 2864619879.312464, roundOff * 2864619879.312464);
    EXPECT_NEAR(relativeContactPressure(P, rough, vickers), 3.1126875097840177e-4, roundOff * 3.1126875097840177e-4);
    EXPECT_NEAR(microhardness(P, rough, vickers), 3212657861.9174905, roundOff * 3212657861.9174905);
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(P, rough, vickers), 58.26245222987142,
                roundOff * 58.26245222987142);
}

TEST(Microhardness, ConsistentWithTheVickersForm)
{
    // At P = H_0 = c1 (1.62 sigma'/m)^c2 the relative pressure is 1 whatever c2: H_c = H_0.
    const double H0 = referenceMicrohardness(rough, vickers);
    EXPECT_NEAR(relativeContactPressure(H0, rough, vickers), 1.0, roundOff);
    EXPECT_NEAR(microhardness(H0, rough, vickers), H0, roundOff * H0);
    // H_c = H_0^(1/(1+0.071 c2)) P^(0.071 c2/(1+0.071 c2)): a ratio of pressures q gives a ratio
    // of hardnesses q^(0.071 c2/(1 + 0.071 c2)) = q^(-0.0142/0.9858).
    const double e = 0.071 * vickers.c2 / (1.0 + 0.071 * vickers.c2);
    EXPECT_NEAR(microhardness(100.0 * P, rough, vickers) / microhardness(P, rough, vickers), std::pow(100.0, e),
                roundOff);
    // With c2 = 0 the hardness is c1 at every pressure; the CMY law with it equals the given-H_c law.
    const VickersCoefficients flat{4e9, 0.0};
    EXPECT_NEAR(microhardness(P, rough, flat), 4e9, roundOff * 4e9);
    EXPECT_NEAR(cooperMikicYovanovichConductancePerConductivity(P, rough, flat),
                cooperMikicYovanovichConductancePerConductivity(P, rough, 4e9),
                roundOff * cooperMikicYovanovichConductancePerConductivity(P, rough, 4e9));
    // The hardness depends on sigma/m only through (1.62 sigma'/m)^c2 in H_0.
    EXPECT_NEAR(referenceMicrohardness({2e-6, 0.2}, vickers), H0, roundOff * H0);
}

TEST(CooperMikicYovanovich, ZeroPressureAndBadInputs)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(cooperMikicYovanovichConductancePerConductivity(0.0, rough, Hc), 0.0);
    EXPECT_EQ(cooperMikicYovanovichConductancePerConductivity(0.0, rough, vickers), 0.0);
    EXPECT_EQ(relativeContactPressure(0.0, rough, vickers), 0.0);
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(-1.0, rough, Hc); },
                         "contact pressure P");
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(nan, rough, Hc); },
                         "contact pressure P");
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(-1.0, rough, vickers); },
                         "contact pressure P");
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(P, rough, 0.0); },
                         "microhardness H_c");
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(P, rough, nan); },
                         "microhardness H_c");
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(P, {0.0, 0.1}, Hc); },
                         "rms roughness sigma");
    expectParameterError([&] { cooperMikicYovanovichConductancePerConductivity(P, {1e-6, 0.0}, vickers); },
                         "mean absolute slope m");
    expectParameterError([&] { cooperMikicYovanovichFromRelativePressure(-1e-3, rough); },
                         "relative contact pressure P/H_c");
}

TEST(Microhardness, BadInputs)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectParameterError([&] { relativeContactPressure(P, rough, {0.0, -0.2}); }, "Vickers coefficient c1");
    expectParameterError([&] { relativeContactPressure(P, rough, {nan, -0.2}); }, "Vickers coefficient c1");
    expectParameterError([&] { relativeContactPressure(P, rough, {5e9, 0.1}); }, "Vickers coefficient c2");
    expectParameterError([&] { relativeContactPressure(P, rough, {5e9, -1.5}); }, "Vickers coefficient c2");
    expectParameterError([&] { relativeContactPressure(P, rough, {5e9, nan}); }, "Vickers coefficient c2");
    expectParameterError([&] { relativeContactPressure(-1.0, rough, vickers); }, "contact pressure P");
    // H_c at P = 0 is unbounded (c2 < 0): refused rather than infinite.
    expectParameterError([&] { microhardness(0.0, rough, vickers); }, "contact pressure P");
    expectParameterError([&] { referenceMicrohardness({1e-6, 0.0}, vickers); }, "mean absolute slope m");
}
