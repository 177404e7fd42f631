// SPDX-License-Identifier: GPL-3.0-or-later
// sigma and the mean absolute slope m of profiles, areal surfaces and spectra, and of two
// surfaces together (Roughness.hpp, docs/correlations.md). Expected values come from the
// closed forms of the test surfaces, with the discretisation error of each stated.
#include "ExpectParameterError.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

constexpr double pi = 3.14159265358979323846;


// z_i = A sin(2 pi x_i/lambda) + a + b x_i at x_i = i dx, i = 0..n-1.
std::vector<double> sampledSine(double A, double lambda, double dx, std::size_t n, double a = 0.0, double b = 0.0)
{
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(i) * dx;
        z[i] = A * std::sin(2.0 * pi * x / lambda) + a + b * x;
    }
    return z;
}

} // namespace

// A sine of amplitude A and wavelength lambda: sigma = A/sqrt(2), m = <|z'|> = 4A/lambda.
// K whole periods of n_lambda points each (n = K n_lambda). The sampled values differ from these
// by (a) the least-squares line, which removes a part 6/(pi^2 K^2) of the sine's variance
// (continuous limit: the line fitted to A sin over K periods has slope -6A/(pi K L)), so sigma is
// low by 3/(pi^2 K^2) relative; its effect on m is second order, (6/(2 pi^2 K^2))^2; (b) the
// forward differences: the sum of |dz| over a period is twice the range of the samples, low by
// at most (pi/n_lambda)^2/2 relative, and the n-1 differences miss one: about 0.6/n relative.
TEST(Roughness, SampledSinusoid)
{
    const double A = 1e-6, lambda = 1e-4;
    const std::size_t K = 100, nLambda = 1000, n = K * nLambda;
    const double dx = lambda / static_cast<double>(nLambda);
    const SurfaceRoughness r = profileRoughness(Profile(sampledSine(A, lambda, dx, n), dx));
    // sigma: 3/(pi^2 K^2) = 3.0e-5 plus O(1/n) = 1e-5: 1e-4 relative.
    EXPECT_NEAR(r.sigma, A / std::sqrt(2.0), 1e-4 * A / std::sqrt(2.0));
    // m: (pi/1000)^2/2 = 4.9e-6 plus 0.6/n = 6e-6: 1e-4 relative.
    EXPECT_NEAR(r.meanAbsoluteSlope, 4.0 * A / lambda, 1e-4 * 4.0 * A / lambda);
}

// Mean and tilt are removed exactly (least squares is linear): the tilted profile has the same
// sigma and m as the untilted one up to round-off.
TEST(Roughness, TiltRemoved)
{
    const double A = 1e-6, lambda = 1e-4;
    const std::size_t n = 20000;
    const double dx = lambda / 200.0;
    const SurfaceRoughness flat = profileRoughness(Profile(sampledSine(A, lambda, dx, n), dx));
    const SurfaceRoughness tilted = profileRoughness(Profile(sampledSine(A, lambda, dx, n, 3e-6, 0.05), dx));
    EXPECT_NEAR(tilted.sigma, flat.sigma, 1e-8 * flat.sigma);
    EXPECT_NEAR(tilted.meanAbsoluteSlope, flat.meanAbsoluteSlope, 1e-8 * flat.meanAbsoluteSlope);
    // The tilt alone (slope 0.05, 40x the sine's mean slope 0.04) would dominate without it.
    EXPECT_NEAR(flat.meanAbsoluteSlope, 4.0 * A / lambda, 2e-3 * 4.0 * A / lambda);
}

// A ridge z = A sin(2 pi x/lambda), constant along y, on a tilted plane: along x sigma = A/sqrt2
// and m = 4A/lambda; along y m = 0 (refused as a perfectly smooth direction); both averaged:
// 2A/lambda. K = 20 periods of 100 points: sigma low by 3/(pi^2 400) = 7.6e-4, m by
// (pi/100)^2/2 + 0.6/2000 = 7.9e-4, relative: tolerance 2e-3.
TEST(Roughness, ArealRidge)
{
    const double A = 2e-6, lambda = 5e-5;
    const std::size_t nx = 2000, ny = 16;
    const double dx = lambda / 100.0, dy = 1e-6;
    std::vector<double> z(nx * ny);
    for (std::size_t iy = 0; iy < ny; ++iy) {
        for (std::size_t ix = 0; ix < nx; ++ix) {
            const double x = static_cast<double>(ix) * dx, y = static_cast<double>(iy) * dy;
            z[iy * nx + ix] = A * std::sin(2.0 * pi * x / lambda) + 1e-5 + 0.01 * x - 0.02 * y;
        }
    }
    const ArealSurface s(z, nx, ny, dx, dy);
    const SurfaceRoughness rx = arealRoughness(s, ScanDirection::x);
    EXPECT_NEAR(rx.sigma, A / std::sqrt(2.0), 2e-3 * A / std::sqrt(2.0));
    EXPECT_NEAR(rx.meanAbsoluteSlope, 4.0 * A / lambda, 2e-3 * 4.0 * A / lambda);
    const SurfaceRoughness rb = arealRoughness(s, ScanDirection::both);
    EXPECT_EQ(rb.sigma, rx.sigma);
    EXPECT_NEAR(rb.meanAbsoluteSlope, 2.0 * A / lambda, 2e-3 * 2.0 * A / lambda);
    // Along y every column of the detrended ridge is constant up to round-off: m is some 1e-10
    // of the x slope at most, refused when exactly 0, and never near the x value.
    try {
        EXPECT_LT(arealRoughness(s, ScanDirection::y).meanAbsoluteSlope, 1e-8 * rx.meanAbsoluteSlope);
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "mean absolute slope m");
    }
}

// A random-phase sum of many sinusoids is close to Gaussian, slopes included. Levels
// f_k = k/L, k = 50..449, amplitudes beta_k = b/k so that every level carries the same slope
// power; the profile is sampled at n = 32768 points (at least 73 points per wavelength).
// From the spectrum: sigma^2 = sum beta_k^2/2 and m = sqrt(2/pi) sqrt(sum (2 pi f_k beta_k)^2/2).
// From the profile: sigma is the same up to the detrending of the longest wave (< 3e-4
// relative, as in SampledSinusoid with K = 50); the rms slope is exact up to the forward
// differences (< (pi 449/32768)^2/6 = 3e-4), but the MEAN |slope| of one realisation scatters
// about sqrt(2/pi) times it: over 30 seeds of an independent simulation (python, 400 equal
// slope components) the relative deviation had mean 2e-4 and standard deviation 0.0066 (extremes
// -0.018, +0.015). Tolerance 0.03: 4.5 standard deviations.
TEST(Roughness, GaussianSpectrumRelation)
{
    const std::size_t n = 32768;
    const double L = 1e-3, dx = L / static_cast<double>(n), b = 1e-7;
    std::vector<double> f, beta, z(n, 0.0);
    std::mt19937_64 rng(20261123);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * pi);
    for (int k = 50; k < 450; ++k) {
        f.push_back(k / L);
        beta.push_back(b / k);
        const double ph = phase(rng);
        for (std::size_t i = 0; i < n; ++i) {
            z[i] += beta.back() * std::cos(2.0 * pi * f.back() * static_cast<double>(i) * dx + ph);
        }
    }
    double m0 = 0.0, m2 = 0.0; // by hand, not by spectralMoments
    for (std::size_t k = 0; k < f.size(); ++k) {
        m0 += beta[k] * beta[k] / 2.0;
        m2 += std::pow(2.0 * pi * f[k] * beta[k], 2) / 2.0;
    }
    const SurfaceRoughness fromSpectrum = spectrumRoughness(Spectrum(f, beta, L));
    EXPECT_NEAR(fromSpectrum.sigma, std::sqrt(m0), 1e-14 * std::sqrt(m0));
    EXPECT_NEAR(fromSpectrum.meanAbsoluteSlope, std::sqrt(2.0 / pi) * std::sqrt(m2),
                1e-14 * std::sqrt(m2));
    const SurfaceRoughness fromProfile = profileRoughness(Profile(z, dx));
    EXPECT_NEAR(fromProfile.sigma, fromSpectrum.sigma, 1e-3 * fromSpectrum.sigma);
    EXPECT_NEAR(fromProfile.meanAbsoluteSlope, fromSpectrum.meanAbsoluteSlope, 0.03 * fromSpectrum.meanAbsoluteSlope);
}

TEST(Roughness, Combined)
{
    // sqrt(3^2 + 4^2) = 5 for both entries.
    const SurfaceRoughness c = combined({3e-6, 0.03}, {4e-6, 0.04});
    EXPECT_NEAR(c.sigma, 5e-6, 1e-15 * 5e-6);
    EXPECT_NEAR(c.meanAbsoluteSlope, 0.05, 1e-15 * 0.05);
    // Symmetric.
    const SurfaceRoughness d = combined({4e-6, 0.04}, {3e-6, 0.03});
    EXPECT_EQ(c.sigma, d.sigma);
    EXPECT_EQ(c.meanAbsoluteSlope, d.meanAbsoluteSlope);
}

// Skewness by hand: z = 0,0,0,3,3,0,0,0 is symmetric about its middle, so the fitted tilt is zero
// and the deviations from the mean 0.75 are -0.75 (six), 2.25 (two): mu2 = 1.6875,
// mu3 = 2.53125, skewness 2.53125/1.6875^1.5 = 2/sqrt 3. Upside down, -2/sqrt 3; scaled and
// tilted, the same.
TEST(Roughness, SkewnessOfAProfileByHand)
{
    const std::vector<double> z{0.0, 0.0, 0.0, 3.0, 3.0, 0.0, 0.0, 0.0};
    EXPECT_NEAR(profileSkewness(Profile(z, 1e-6)).skewness, 2.0 / std::sqrt(3.0), 1e-14);
    std::vector<double> down(z.size());
    std::vector<double> tilted(z.size());
    for (std::size_t i = 0; i < z.size(); ++i) {
        down[i] = -z[i];
        tilted[i] = 1e-7 * z[i] + 5e-7 + 2e-8 * static_cast<double>(i);
    }
    EXPECT_NEAR(profileSkewness(Profile(down, 1e-6)).skewness, -2.0 / std::sqrt(3.0), 1e-14);
    // The least-squares tilt of 5e-7 m offsets and 1e-7 m steps leaves round-off near 1e-16 of the
    // offset, 1e-9 of the steps' skewness at most: 1e-9.
    EXPECT_NEAR(profileSkewness(Profile(tilted, 1e-6)).skewness, 2.0 / std::sqrt(3.0), 1e-9);
}

// An 8 x 8 map with a 4 x 4 plateau of 3 in its middle (symmetric: no plane to remove): a quarter
// of the points, so deviations -0.75 (48) and 2.25 (16), mu2 = 1.6875, mu3 = 2.53125, skewness
// 2.53125/1.6875^1.5 = 2/sqrt 3.
TEST(Roughness, SkewnessOfAMapByHand)
{
    std::vector<double> z(64, 0.0);
    for (std::size_t iy = 2; iy < 6; ++iy) {
        for (std::size_t ix = 2; ix < 6; ++ix) {
            z[iy * 8 + ix] = 3e-6;
        }
    }
    EXPECT_NEAR(arealSkewness(ArealSurface(z, 8, 8, 1e-6, 2e-6)).skewness, 2.0 / std::sqrt(3.0), 1e-12);
}

// Third central moments add for independent sums: equal sigmas, one skewed by s, the other
// Gaussian, give s sigma^3/(2 sigma^2)^1.5 = s/2^1.5; two equal skewnesses give s/sqrt 2; the
// spreads add in quadrature with the same weights.
TEST(Roughness, CombinedSkewness)
{
    const HeightSkewness g{0.0, 0.0};
    EXPECT_NEAR(combinedSkewness(1e-6, {0.4, 0.1}, 1e-6, g).skewness, 0.4 / std::pow(2.0, 1.5), 1e-15);
    EXPECT_NEAR(combinedSkewness(1e-6, {0.4, 0.1}, 1e-6, g).spread, 0.1 / std::pow(2.0, 1.5), 1e-15);
    EXPECT_NEAR(combinedSkewness(1e-6, {0.4, 0.1}, 1e-6, {0.4, 0.1}).skewness, 0.4 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(combinedSkewness(1e-6, {0.4, 0.1}, 1e-6, {0.4, 0.1}).spread, 0.1 / 2.0, 1e-15);
    EXPECT_NEAR(combinedSkewness(2e-6, {-0.3, 0.2}, 0.0, {0.7, 0.5}).skewness, -0.3, 1e-15); // the second flat
    EXPECT_EQ(combinedSkewness(3e-6, {0.2, 0.1}, 4e-6, {-0.1, 0.3}).skewness,
              combinedSkewness(4e-6, {-0.1, 0.3}, 3e-6, {0.2, 0.1}).skewness);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectParameterError([&] { combinedSkewness(0.0, {0.1, 0.1}, 0.0, {0.1, 0.1}); }, "skewness");
    expectParameterError([&] { combinedSkewness(1e-6, {nan, 0.1}, 1e-6, {0.1, 0.1}); }, "skewness");
}

// The spread by chance, sqrt((6/N) sum_k rho(k)^3): for independent heights (rho = 1 at lag 0
// and only noise of order 1/sqrt N elsewhere, whose cubes sum to O(1/sqrt N)) it is the classic
// sqrt(6/N) of the sample skewness of N normal numbers; the tolerance 3 % covers that noise at
// N = 4096. Correlated heights hold fewer independent values: a larger spread. A Monte Carlo over
// 2000 white-noise samples of N = 512 checks that sqrt(6/N) is the sampling spread (its standard
// error about 1.6 %, the large-N formula a few per cent high at this N: 10 %).
TEST(Roughness, ShrunkSkewnessTakesChancesShareOut)
{
    // s (1 - e^2/s^2) where |s| > e, else 0: by hand, odd in s, continuous at |s| = e.
    EXPECT_NEAR(shrunkSkewness(HeightSkewness{-0.379, 0.125}), -0.379 + 0.125 * 0.125 / 0.379, 1e-15);
    EXPECT_NEAR(shrunkSkewness(HeightSkewness{0.5, 0.3}), 0.5 - 0.09 / 0.5, 1e-15);
    EXPECT_EQ(shrunkSkewness(HeightSkewness{-0.5, 0.3}), -shrunkSkewness(HeightSkewness{0.5, 0.3}));
    EXPECT_EQ(shrunkSkewness(HeightSkewness{0.243, 0.322}), 0.0); // the stand-in profile: chance
    EXPECT_EQ(shrunkSkewness(HeightSkewness{0.3, 0.3}), 0.0);
    EXPECT_LT(std::abs(shrunkSkewness(HeightSkewness{0.3 * (1 + 1e-9), 0.3})), 1e-8);
    EXPECT_EQ(shrunkSkewness(HeightSkewness{0.2, 0.0}), 0.2); // no chance: as measured
    EXPECT_THROW(shrunkSkewness(HeightSkewness{std::nan(""), 0.1}), ParameterError);
    EXPECT_THROW(shrunkSkewness(HeightSkewness{0.1, -0.1}), ParameterError);
}

TEST(Roughness, SkewnessSpreadIsWhatChanceGives)
{
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal;
    std::vector<double> white(4096);
    for (double& v : white) {
        v = 1e-6 * normal(rng);
    }
    const double n = static_cast<double>(white.size());
    EXPECT_NEAR(profileSkewness(Profile(white, 1e-6)).spread, std::sqrt(6.0 / n), 0.03 * std::sqrt(6.0 / n));
    std::vector<double> map(64 * 64);
    for (double& v : map) {
        v = 1e-6 * normal(rng);
    }
    EXPECT_NEAR(arealSkewness(ArealSurface(map, 64, 64, 1e-6, 1e-6)).spread, std::sqrt(6.0 / 4096.0),
                0.03 * std::sqrt(6.0 / 4096.0));
    // Correlated heights, an AR(1) series z_i = phi z_{i-1} + e_i: rho(k) = phi^|k|, so
    // sum_k rho^3 = (1 + phi^3)/(1 - phi^3), 6.38 at phi = 0.9. The sample's rho carries noise of
    // a few per cent at the lags that matter (its correlation length 10 of 4096 points): 10 %.
    std::vector<double> ar(4096);
    double previous = 0.0;
    for (double& v : ar) {
        previous = 0.9 * previous + normal(rng);
        v = 1e-6 * previous;
    }
    const double phi3 = 0.9 * 0.9 * 0.9;
    const double expected = std::sqrt(6.0 / n * (1.0 + phi3) / (1.0 - phi3));
    EXPECT_NEAR(profileSkewness(Profile(ar, 1e-6)).spread, expected, 0.10 * expected);
    // A map beyond spreadSide a side: the spread from every second point each way. For heights
    // correlated over many points (a 2-D AR(1), phi = 0.98: rho falls by 1/e in 50 points) it is
    // what the full grid gives. Checked against a quarter of the map at full resolution, its
    // spread scaled by its area to the whole (a spread goes as 1/sqrt N once a map holds many
    // correlation lengths: 1/4): 25 %, as a quarter's rho is another sample of the field's.
    {
        const std::size_t side = 2 * spreadSide;
        std::vector<double> field(side * side);
        std::vector<double> column(side, 0.0);
        for (std::size_t iy = 0; iy < side; ++iy) {
            double row = 0.0;
            for (std::size_t ix = 0; ix < side; ++ix) {
                column[ix] = 0.98 * column[ix] + normal(rng);
                row = 0.98 * row + column[ix];
                field[iy * side + ix] = 1e-9 * row;
            }
        }
        const HeightSkewness whole = arealSkewness(ArealSurface(field, side, side, 1e-6, 1e-6));
        const std::size_t q = side / 4;
        std::vector<double> quarter(q * q);
        for (std::size_t iy = 0; iy < q; ++iy) {
            for (std::size_t ix = 0; ix < q; ++ix) {
                quarter[iy * q + ix] = field[iy * side + ix];
            }
        }
        const double full = arealSkewness(ArealSurface(quarter, q, q, 1e-6, 1e-6)).spread;
        EXPECT_NEAR(whole.spread, full / 4.0, 0.25 * full / 4.0);
    }
    // Monte Carlo: the standard deviation of the skewness of 2000 samples of 512 normal numbers.
    double sum = 0.0;
    double sum2 = 0.0;
    std::vector<double> z(512);
    for (int k = 0; k < 2000; ++k) {
        for (double& v : z) {
            v = 1e-6 * normal(rng);
        }
        const double s = profileSkewness(Profile(z, 1e-6)).skewness;
        sum += s;
        sum2 += s * s;
    }
    const double sd = std::sqrt(sum2 / 2000.0 - (sum / 2000.0) * (sum / 2000.0));
    EXPECT_NEAR(profileSkewness(Profile(z, 1e-6)).spread / sd, 1.0, 0.10);
}

TEST(Roughness, BadInputs)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expectParameterError([&] { combined({0.0, 0.1}, {1e-6, 0.1}); }, "rms roughness sigma");
    expectParameterError([&] { combined({1e-6, 0.1}, {nan, 0.1}); }, "rms roughness sigma");
    expectParameterError([&] { combined({1e-6, 0.0}, {1e-6, 0.1}); }, "mean absolute slope m");
    expectParameterError([&] { combined({1e-6, 0.1}, {1e-6, -0.1}); }, "mean absolute slope m");
    expectParameterError([&] { checkRoughness({1e-6, nan}); }, "mean absolute slope m");
    // A straight tilted line: nothing is left after detrending.
    std::vector<double> line(64);
    for (std::size_t i = 0; i < line.size(); ++i) {
        line[i] = 1e-6 * static_cast<double>(i);
    }
    // (Round-off of the fit may leave some 1e-21 m, below limits::minimumRoughness = 1e-15 m.)
    expectParameterError([&] { profileRoughness(Profile(line, 1e-6)); }, "rms roughness sigma");
    expectParameterError([&] { profileSkewness(Profile(line, 1e-6)); }, "profile");
    expectParameterError([&] { combined({1e-16, 0.1}, {1e-6, 0.1}); }, "rms roughness sigma");
    // A spectrum of zero amplitudes.
    expectParameterError([&] { spectrumRoughness(Spectrum({1e3, 2e3}, {0.0, 0.0}, 1e-3)); }, "rms roughness sigma");
}
