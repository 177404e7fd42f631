// SPDX-License-Identifier: GPL-3.0-or-later
// Barber's relation on the elastic energy of the multi-scale levels (MultiscaleBarber.hpp):
// the bins hold the whole 2-D variance, one level gives the closed form, the law is +inf at
// complete contact and rises with the load.
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/MultiscaleBarber.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
const ContactMaterials steel = ContactMaterials::againstRigidFlat(Material{200e9, 0.3, 0.5e9});
} // namespace

TEST(MultiscaleBarber, TheBinsHoldTheWhole2DVariance)
{
    // Sum over the levels of 4 E_i/q_i = V_i, the bins' 2-D variances, is the variance of the
    // isotropic spectrum (the bins tile its band), to round-off.
    const Spectrum s = Spectrum::powerLaw(1e-9, 1.3, 1e3, 64e3);
    const MultiscaleModel m(s, steel.reducedModulus(), makeAsperityModel("hertz", steel));
    const MultiscaleBarber law(m, s);
    double total = 0.0;
    for (std::size_t i = 0; i < s.frequencies().size(); ++i) {
        total += 4.0 * law.binEnergies()[i] / (2.0 * pi * s.frequencies()[i]);
    }
    EXPECT_NEAR(total / IsotropicSpectrum(s).powerOutside(0.0), 1.0, 1e-12);
}

TEST(MultiscaleBarber, OneLevelIsTheClosedForm)
{
    // One Hertz level: a = A_1/A_n grows as load^(2/3) (Hertz), so with W(a) = a (gamma +
    // (1 - gamma) a^2), dU/d load = E_1 (gamma + 3 (1 - gamma) a^2) (2/3) a/load and
    // h_c/k_s = 1.5 load^2 / (E_1 a (gamma + 3 (1 - gamma) a^2)). The law's central difference
    // (step 1e-3) is exact to O(1e-6).
    const double L = 1e-3;
    const Spectrum s({4.0 / L}, {2e-7}, L);
    const MultiscaleModel m(s, steel.reducedModulus(), makeAsperityModel("hertz", steel));
    const MultiscaleBarber law(m, s);
    const double E1 = law.binEnergies()[0];
    const double gamma = 0.42;
    for (double load : {1e-8, 1e-7, 1e-6}) {
        const double a = m.areaFraction(load);
        ASSERT_GT(a, 0.0);
        ASSERT_LT(a, 1.0);
        const double expected = 1.5 * load * load / (E1 * a * (gamma + 3.0 * (1.0 - gamma) * a * a));
        EXPECT_NEAR(law.conductancePerConductivity(load) / expected, 1.0, 1e-5) << load;
    }
}

TEST(MultiscaleBarber, CompleteContactZeroAndLightLoad)
{
    // A self-affine line scan (Hurst 0.8) of rms slope 0.07.
    const Spectrum s = Spectrum::powerLaw(0.0376, 1.3, 1e3, 64e3);
    const MultiscaleModel m(s, steel.reducedModulus(), makeAsperityModel("hertz", steel));
    const MultiscaleBarber law(m, s);
    EXPECT_EQ(law.conductancePerConductivity(0.0), 0.0);
    EXPECT_THROW(law.conductancePerConductivity(-1.0), ParameterError);
    // The ends of the accepted loads (the difference stays inside them).
    EXPECT_GT(law.conductancePerConductivity(limits::minimumLoad), 0.0);
    EXPECT_TRUE(std::isinf(law.conductancePerConductivity(limits::maximumLoad)));
    // Every level in complete contact: the energy no longer changes, nothing constricts.
    EXPECT_TRUE(std::isinf(law.conductancePerConductivity(10.0)));
    // h_c rises with the load. Not in proportion to it, although the multi-scale area does at
    // light load: the coarser levels close one after another, and the energy that still changes
    // moves to finer levels with less of it (measured: h_c ~ load^1.3 from 1e-9 to 1e-5).
    double previous = 0.0;
    for (double load : {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4}) {
        const double h = law.conductancePerConductivity(load);
        EXPECT_GT(h, previous) << load;
        previous = h;
    }
}

TEST(MultiscaleBarber, OneLevelSeparationIsTheClosedForm)
{
    // (B4) on one Hertz level: a = c load^(2/3), U = E_1 a (gamma + (1 - gamma) a^2), so
    // dU/dl / l = (2/3) E_1 (gamma c l^(-4/3) + 3 (1 - gamma) c^3) and between two loads below
    // complete contact
    //     u(l1) - u(l2) = (2/3) E_1 [3 gamma c (l1^(-1/3) - l2^(-1/3)) + 3 (1 - gamma) c^3 (l2 - l1)].
    // The quadrature of (B5) (Gauss-Kronrod to 1e-10 per panel) meets it to ~5e-15 (measured).
    const double L = 1e-3;
    const Spectrum s({4.0 / L}, {2e-7}, L);
    const MultiscaleModel m(s, steel.reducedModulus(), makeAsperityModel("hertz", steel));
    const MultiscaleBarber law(m, s);
    const double E1 = law.binEnergies()[0];
    const double gamma = 0.42;
    const double c = m.areaFraction(1e-7) / std::pow(1e-7, 2.0 / 3.0);
    ASSERT_NEAR(m.areaFraction(1e-8) / std::pow(1e-8, 2.0 / 3.0) / c, 1.0, 1e-9); // Hertz: a power law
    const auto difference = [&](double l1, double l2) {
        return 2.0 / 3.0 * E1 *
               (3.0 * gamma * c * (std::pow(l1, -1.0 / 3.0) - std::pow(l2, -1.0 / 3.0)) +
                3.0 * (1.0 - gamma) * c * c * c * (l2 - l1));
    };
    for (const auto& [l1, l2] : {std::pair<double, double>{1e-8, 1e-7}, {1e-8, 1e-6}, {3e-7, 1e-6}}) {
        ASSERT_LT(m.areaFraction(l2), 1.0);
        const double expected = difference(l1, l2);
        EXPECT_NEAR((law.meanSeparation(l1) - law.meanSeparation(l2)) / expected, 1.0, 1e-10) << l1 << " " << l2;
    }
    // Complete contact: u = 0 there and beyond, positive just below; +inf at load 0.
    const double lc = law.completeContactLoad();
    ASSERT_TRUE(std::isfinite(lc));
    EXPECT_EQ(m.areaFraction(lc), 1.0);
    EXPECT_LT(m.areaFraction(lc * (1.0 - 1e-9)), 1.0);
    EXPECT_EQ(law.meanSeparation(lc), 0.0);
    EXPECT_EQ(law.meanSeparation(10.0 * lc), 0.0);
    EXPECT_GT(law.meanSeparation(0.5 * lc), 0.0);
    EXPECT_TRUE(std::isinf(law.meanSeparation(0.0)));
    EXPECT_THROW(law.meanSeparation(-1.0), ParameterError);
}
