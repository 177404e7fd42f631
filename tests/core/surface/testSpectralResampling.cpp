// SPDX-License-Identifier: GPL-3.0-or-later
// The same periodic surface on another grid (SpectralResampling.hpp): a trigonometric polynomial
// resampled is that polynomial at the new points; levels beyond the kept ones are gone; a
// synthesized surface refined is the same surface (its coarse points unchanged).
#include "roughContact/Error.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double L = 1e-3;

// z(x, y) sampled on n x n points of L x L.
ArealSurface sampled(std::size_t n, const std::function<double(double, double)>& z)
{
    std::vector<double> h(n * n);
    const double dx = L / double(n);
    for (std::size_t iy = 0; iy < n; ++iy) {
        for (std::size_t ix = 0; ix < n; ++ix) {
            h[iy * n + ix] = z(double(ix) * dx, double(iy) * dx);
        }
    }
    return ArealSurface(std::move(h), n, n, dx, dx, "test surface");
}

// The largest difference between a surface and z at its points, relative to amplitude a.
double worst(const ArealSurface& s, const std::function<double(double, double)>& z, double a)
{
    double w = 0.0;
    for (std::size_t iy = 0; iy < s.ny(); ++iy) {
        for (std::size_t ix = 0; ix < s.nx(); ++ix) {
            w = std::max(w, std::abs(s.at(ix, iy) - z(double(ix) * s.dx(), double(iy) * s.dy())) / a);
        }
    }
    return w;
}

// Three waves, one oblique, plus a mean: a trigonometric polynomial of degree 5.
double waves(double x, double y)
{
    const double k = 2.0 * pi / L;
    return 1e-6 * (0.3 + std::cos(k * 3.0 * x + 0.4) + 0.5 * std::sin(k * (2.0 * x - 5.0 * y)) +
                   0.25 * std::cos(k * 4.0 * y - 1.0));
}
} // namespace

// Exact in exact arithmetic; 1e-12 of the amplitude is FFT round-off on these grids.
TEST(SpectralResampling, APolynomialOnAFinerOrCoarserGridIsThatPolynomialThere)
{
    const ArealSurface coarse = sampled(16, waves);
    for (std::size_t n : {16, 32, 48, 64, 12}) {
        SCOPED_TRACE(n);
        const ArealSurface s = resampledPeriodic(coarse, n);
        EXPECT_EQ(s.nx(), n);
        EXPECT_EQ(s.ny(), n);
        EXPECT_DOUBLE_EQ(s.dx(), L / double(n));
        EXPECT_LT(worst(s, waves, 1e-6), 1e-12);
    }
}

// A cosine at the coarse grid's Nyquist frequency, sampled at its crests, is that cosine on a
// finer grid (each of +n/2 and -n/2 gets half the coefficient), not twice it, along x, y and both.
// An oblique wave at the Nyquist frequency along x, cos(8 k x + 3 k y) on 16 points, has the same
// samples as cos(8 k x) cos(3 k y) (sin(8 k x) is 0 at every point): the splitting gives the
// latter, the one interpolant symmetric in +-k_x. What the grid cannot tell apart stays so.
TEST(SpectralResampling, ANyquistCosineStaysThatCosine)
{
    const double k = 2.0 * pi / L;
    using F = std::function<double(double, double)>;
    const std::vector<std::pair<F, F>> cases{
        {[k](double x, double) { return 1e-6 * std::cos(k * 8.0 * x); }, nullptr},
        {[k](double, double y) { return 1e-6 * std::cos(k * 8.0 * y); }, nullptr},
        {[k](double x, double y) { return 1e-6 * std::cos(k * 8.0 * x) * std::cos(k * 8.0 * y); }, nullptr},
        {[k](double x, double y) { return 1e-6 * std::cos(k * (8.0 * x + 3.0 * y)); },
         [k](double x, double y) { return 1e-6 * std::cos(k * 8.0 * x) * std::cos(k * 3.0 * y); }},
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE(i);
        const ArealSurface fine = resampledPeriodic(sampled(16, cases[i].first), 64);
        EXPECT_LT(worst(fine, cases[i].second ? cases[i].second : cases[i].first, 1e-6), 1e-12);
    }
}

// Levels kept: the waves at |k| <= K stay as they were, the others are gone; down to a grid that
// cannot hold a wave, that wave is dropped, not folded onto a longer one.
TEST(SpectralResampling, LevelsBeyondTheKeptOnesAndBeyondTheGridAreDropped)
{
    const double k = 2.0 * pi / L;
    const auto longWave = [k](double x, double y) { return 1e-6 * std::cos(k * (2.0 * x + 1.0 * y) + 0.3); };
    const auto shortWave = [k](double x, double y) { return 0.4e-6 * std::sin(k * (6.0 * x - 6.0 * y)); };
    const ArealSurface both = sampled(32, [&](double x, double y) { return longWave(x, y) + shortWave(x, y); });
    EXPECT_LT(worst(resampledPeriodic(both, 32, 5.0), longWave, 1e-6), 1e-12);  // |k| = 8.5 > 5
    EXPECT_LT(worst(resampledPeriodic(both, 32, 9.0), [&](double x, double y) { return longWave(x, y) + shortWave(x, y); }, 1e-6), 1e-12);
    EXPECT_LT(worst(resampledPeriodic(both, 64, 3.0), longWave, 1e-6), 1e-12); // finer and cut at once
    EXPECT_LT(worst(resampledPeriodic(both, 8), longWave, 1e-6), 1e-12);        // 8 points hold |k_x| < 4 only
}

// What the fidelity study relies on: a synthesized surface refined to 4x the points is the same
// surface (every fourth point is an old one) with the same variance.
TEST(SpectralResampling, ASynthesizedSurfaceRefinedKeepsItsPointsAndItsVariance)
{
    const Spectrum s = Spectrum::powerLaw(1e-9 * std::pow(1.0 / L, 1.3), 1.3, 1.0 / L, 16.0 / L, L);
    const ArealSurface a = synthesizeIsotropic(s, 64, 5);
    const ArealSurface f = resampledPeriodic(a, 256);
    double worstPoint = 0.0;
    for (std::size_t iy = 0; iy < 64; ++iy) {
        for (std::size_t ix = 0; ix < 64; ++ix) {
            worstPoint = std::max(worstPoint, std::abs(f.at(4 * ix, 4 * iy) - a.at(ix, iy)));
        }
    }
    EXPECT_LT(worstPoint, 1e-12 * a.rms());
    // The variance of a trigonometric polynomial is the sum of its |c_k|^2 on any grid that holds it.
    EXPECT_NEAR(f.rms() / a.rms(), 1.0, 1e-12);
    EXPECT_NE(f.source().find("resampled to 256 x 256"), std::string::npos) << f.source();
}

TEST(SpectralResampling, RefusesWhatItCannotDoByName)
{
    const ArealSurface a = sampled(16, waves);
    const auto names = [](const std::function<void()>& f, const std::string& what) {
        try {
            f();
            ADD_FAILURE() << "no error for " << what;
        } catch (const ParameterError& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    names([&] { resampledPeriodic(a, 15); }, "n");
    names([&] { resampledPeriodic(a, 6); }, "n");
    names([&] { resampledPeriodic(a, 8192); }, "n");
    names([&] { resampledPeriodic(a, 32, 0.5); }, "levels");
    std::vector<double> h(16 * 24, 0.0);
    names([&] { resampledPeriodic(ArealSurface(h, 16, 24, 1e-6, 1e-6, "oblong.csv"), 32); }, "oblong.csv");
}
