// SPDX-License-Identifier: GPL-3.0-or-later
// Hertz + fully plastic truncation asperity (seed §3.1).
#include "roughContact/asperity/Hertz.hpp"
#include "roughContact/asperity/Truncation.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double Ep = 200e9;
constexpr double nu = 0.32;
constexpr double Sy = 0.2e9;
} // namespace

TEST(Truncation, hertzBelowCriticalInterference)
{
    const Truncation t(Ep, nu, Sy);
    const Hertz h(Ep);
    const double R = 4e-6;
    const double wc = t.onset().interference(R);
    for (double ws : {0.01, 0.5, 0.999}) {
        EXPECT_DOUBLE_EQ(t.area(ws * wc, R), h.area(ws * wc, R));
        EXPECT_DOUBLE_EQ(t.force(ws * wc, R), h.force(ws * wc, R));
        EXPECT_DOUBLE_EQ(t.areaAtForce(h.force(ws * wc, R), R), h.areaAtForce(h.force(ws * wc, R), R));
    }
}

TEST(Truncation, plasticBranchCarriesHardnessTimesTruncatedArea)
{
    const Truncation t(Ep, nu, Sy);
    const double R = 4e-6;
    const double w = 10.0 * t.onset().interference(R);
    EXPECT_DOUBLE_EQ(t.area(w, R), 2.0 * pi * R * w);
    EXPECT_DOUBLE_EQ(t.force(w, R), 2.84 * Sy * 2.0 * pi * R * w);
    EXPECT_NEAR(t.areaAtForce(t.force(w, R), R) / t.area(w, R), 1.0, 1e-15);
}

TEST(Truncation, areaDoublesAndForceJumpsAtCriticalInterference)
{
    const Truncation t(Ep, nu, Sy);
    const double R = 4e-6;
    const double wc = t.onset().interference(R);
    const double below = std::nextafter(wc, 0.0);
    // Area: pi R w_c elastic, 2 pi R w_c truncated (seed §3.1: "a discontinuity").
    EXPECT_NEAR(t.area(wc, R) / t.area(below, R), 2.0, 1e-14);
    // Force: H 2 pi R w_c over F_c = 8.52 / C (docs/theory.md §3.5).
    const double C = t.onset().C();
    EXPECT_NEAR(t.force(wc, R) / t.force(below, R), 3.0 * 2.84 / C, 1e-12);
    // On the loading path the area jumps at F_c and then holds until F = H 2 pi R w_c.
    const double Fc = t.onset().force(R);
    EXPECT_NEAR(t.areaAtForce(Fc * (1.0 - 1e-12), R) / (pi * R * wc), 1.0, 1e-11);
    EXPECT_NEAR(t.areaAtForce(Fc * (1.0 + 1e-12), R) / (2.0 * pi * R * wc), 1.0, 1e-15);
    EXPECT_NEAR(t.areaAtForce(0.5 * (Fc + t.force(wc, R)), R) / (2.0 * pi * R * wc), 1.0, 1e-15);
}

TEST(Truncation, areaNeverDecreasesWithForce)
{
    const Truncation t(Ep, nu, Sy);
    const double R = 1e-5;
    const double Fc = t.onset().force(R);
    double previous = 0.0;
    for (double q = 1e-4; q < 1e6; q *= 1.01) {
        const double A = t.areaAtForce(q * Fc, R);
        ASSERT_GE(A, previous) << q;
        previous = A;
    }
}
