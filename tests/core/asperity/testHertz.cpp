// SPDX-License-Identifier: GPL-3.0-or-later
// Hertz asperity (seed Eq. 20).
#include "roughContact/asperity/Hertz.hpp"

#include "ClosedForms.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
// Round-off tolerance: a handful of pow/cbrt calls, each within a few ulp.
constexpr double roundOff = 1e-14;
} // namespace

TEST(Hertz, areaAtForceInvertsForceOfInterference)
{
    const Hertz h(200e9);
    for (double R : {1e-7, 9.3e-6, 1e-3}) {
        for (double w : {1e-12, 1e-9, 3e-7}) {
            const double F = h.force(w, R);
            EXPECT_NEAR(h.areaAtForce(F, R) / h.area(w, R), 1.0, roundOff) << "R=" << R << " w=" << w;
            EXPECT_NEAR(h.interference(F, R) / w, 1.0, roundOff);
        }
    }
}

TEST(Hertz, matchesSeedEquation20)
{
    const double E = 200e9;
    const double R = 9.299e-6;
    const double F = 1e-3;
    const Hertz h(E);
    const double a = roughContactTest::closedForm::hertzContactRadius(F, R, E); // contact radius
    EXPECT_NEAR(h.areaAtForce(F, R) / (pi * a * a), 1.0, roundOff);
}

TEST(Hertz, rejectsNonPositiveModulus)
{
    EXPECT_THROW(Hertz(0.0), std::invalid_argument);
    EXPECT_THROW(Hertz(-1.0), std::invalid_argument);
    EXPECT_THROW(Hertz(std::nan("")), std::invalid_argument);
}
