// SPDX-License-Identifier: GPL-3.0-or-later
// Areal surfaces (height maps): layout, detrending, line scans and their averaged spectrum.
#include "roughContact/Error.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

// z = a cos(2 pi kx x / Lx) on an nx x ny grid: every row is the same sinusoid.
ArealSurface ridges(std::size_t nx, std::size_t ny, double dx, double dy, double a, int kx)
{
    std::vector<double> z(nx * ny);
    for (std::size_t iy = 0; iy < ny; ++iy) {
        for (std::size_t ix = 0; ix < nx; ++ix) {
            z[iy * nx + ix] = a * std::cos(2 * pi * kx * double(ix) / double(nx));
        }
    }
    return ArealSurface(z, nx, ny, dx, dy, "ridges");
}
} // namespace

TEST(ArealSurface, LayoutAndLengths)
{
    std::vector<double> z(10 * 12);
    for (std::size_t i = 0; i < z.size(); ++i) {
        z[i] = 1e-9 * double(i);
    }
    const ArealSurface s(z, 10, 12, 1e-6, 2e-6, "map");
    EXPECT_EQ(s.at(3, 2), 1e-9 * (2 * 10 + 3)); // rows along x, one after the other along y
    EXPECT_DOUBLE_EQ(s.lengthX(), 10e-6);
    EXPECT_DOUBLE_EQ(s.lengthY(), 24e-6);
    EXPECT_DOUBLE_EQ(s.nominalArea(), 240e-12);
    EXPECT_EQ(s.row(2).heights()[3], s.at(3, 2));
    EXPECT_EQ(s.column(3).heights()[2], s.at(3, 2));
    EXPECT_EQ(s.column(3).spacing(), 2e-6);
    // A plane is removed exactly by detrending.
    const ArealSurface d = s.detrended();
    for (double v : d.heights()) {
        EXPECT_NEAR(v, 0.0, 1e-20);
    }
}

TEST(ArealSurface, RefusesBadInput)
{
    const std::vector<double> z(64, 0.0);
    EXPECT_THROW(ArealSurface(std::vector<double>(49, 0.0), 7, 7, 1e-6, 1e-6), InputError);
    EXPECT_THROW(ArealSurface(z, 8, 9, 1e-6, 1e-6), InputError); // 64 heights for 72 points
    EXPECT_THROW(ArealSurface(z, 8, 8, 0.0, 1e-6), ParameterError);
    EXPECT_THROW(ArealSurface(z, 8, 8, 1e-6, 1e300), ParameterError);
    std::vector<double> bad = z;
    bad[9] = std::nan("");
    try {
        ArealSurface(bad, 8, 8, 1e-6, 1e-6, "m.txt");
        ADD_FAILURE() << "NaN accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("x index 1, y index 1"), std::string::npos) << e.what();
    }
    EXPECT_THROW(ArealSurface(std::vector<double>(4097 * 4097, 0.0), 4097, 4097, 1e-9, 1e-9), InputError);
    EXPECT_THROW(parseScanDirection("z"), ParameterError);
    // Issue 18, item 16: an infinite height was "is not finite m" (X3P), "is inf m" (here).
    bad = z;
    bad[10] = std::numeric_limits<double>::infinity();
    try {
        ArealSurface(bad, 8, 8, 1e-6, 1e-6, "m.txt");
        ADD_FAILURE() << "inf accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("x index 2, y index 1 is inf (not a finite number); heights must"),
                  std::string::npos)
            << e.what();
    }
}

TEST(ArealSurface, LineScanSpectrumOfRidgesIsTheirSinusoid)
{
    // Rows carry a cosine of amplitude a at level kx; columns are flat.
    const double a = 3e-8;
    const ArealSurface s = ridges(64, 32, 1e-6, 2e-6, a, 5);
    const Spectrum x = lineScanSpectrum(s, ScanDirection::x);
    ASSERT_EQ(x.size(), 32u);
    EXPECT_DOUBLE_EQ(x.length(), 64e-6);
    // Every row is the same: the average is that row's spectrum (detrended: the cosine's small
    // least-squares tilt is removed, so level 5 holds 0.9986 a, not a).
    const Spectrum one = Spectrum::fromProfile(s.row(0));
    for (std::size_t i = 0; i < x.size(); ++i) {
        EXPECT_NEAR(x.amplitude(i), one.amplitude(i), 1e-12 * a) << i;
    }
    EXPECT_NEAR(x.amplitude(4), a, 2e-3 * a); // level 5 (f = 5/L)
    const Spectrum y = lineScanSpectrum(s, ScanDirection::y);
    EXPECT_NEAR(std::sqrt(y.variance()), 0.0, 1e-20);
    // Both: the mean of the two directions' powers (re-binned onto one grid: the variances, the
    // Nyquist levels' included, are kept).
    const Spectrum both = lineScanSpectrum(s, ScanDirection::both);
    EXPECT_NEAR(both.variance(), 0.5 * (x.profileVariance() + y.profileVariance()), 1e-12 * x.variance());
}

TEST(ArealSurface, AveragedSpectrumIsTheMeanPowerOfTheRows)
{
    std::mt19937 rng(3);
    std::normal_distribution<double> g(0.0, 1e-7);
    const std::size_t nx = 40;
    const std::size_t ny = 9;
    std::vector<double> z(nx * ny);
    for (double& v : z) {
        v = g(rng);
    }
    const ArealSurface s(z, nx, ny, 1e-6, 1e-6, "noise");
    const Spectrum avg = lineScanSpectrum(s, ScanDirection::x);
    double meanVariance = 0.0;
    for (std::size_t iy = 0; iy < ny; ++iy) {
        meanVariance += Spectrum::fromProfile(s.row(iy)).profileVariance() / double(ny);
    }
    // Parseval per row, then the mean: the averaged spectrum holds the mean variance exactly
    // (Nyquist level included).
    EXPECT_TRUE(avg.hasNyquistLevel());
    EXPECT_NEAR(avg.profileVariance(), meanVariance, 1e-12 * meanVariance);
}
