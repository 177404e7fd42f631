// SPDX-License-Identifier: GPL-3.0-or-later
// Fit of the Weierstrass-Mandelbrot D and G to a spectrum's PSD (docs/theory.md §4.3, Majumdar & Tien
// 1990).
#include "roughContact/Error.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace roughContact;

namespace {
// W-M one-sided PSD S(f) = G^(2(D-1)) / (2 ln(1.5) f^(5-2D)) (docs/theory.md §4.3), written here
// independently of Spectrum::fractal.
double wmPsd(double D, double G, double f)
{
    return std::pow(G, 2.0 * (D - 1.0)) / (2.0 * std::log(1.5) * std::pow(f, 5.0 - 2.0 * D));
}

// A spectrum built level by level from the PSD: beta^2 = 2 S df, df = 1/L.
Spectrum wmSpectrum(double D, double G, double L, int i0, int i1)
{
    std::vector<double> f;
    std::vector<double> beta;
    for (int i = i0; i <= i1; ++i) {
        f.push_back(i / L);
        beta.push_back(std::sqrt(2.0 * wmPsd(D, G, i / L) / L));
    }
    return Spectrum(f, beta, L, "W-M test spectrum");
}
} // namespace

TEST(FractalFit, recoversDAndGOfAnExactFractalSpectrum)
{
    // The seed's Table 1 values and a spread of D. The data lie exactly on the fitted line, so
    // only round-off separates fit and truth: ln S ~ -50 carries ~1e-14 absolute error per
    // level, the least-squares slope over ln f spanning ~7 then has ~1e-14 error, i.e. D to
    // ~1e-14. G = exp(intercept / (2 (D - 1))) magnifies the intercept's error (~1e-13, the
    // extrapolation to ln f = 0 from ln f ~ 10) by 1/(2(D-1)) <= 5 for D >= 1.1: 1e-11 leaves
    // ample margin while a wrong gamma (1.5) in the intercept would shift G by >= 10 %.
    for (double D : {1.1, 1.3, 1.5, 1.597, 1.9}) {
        for (double G : {2.86e-10, 1e-8}) {
            const double L = 500e-6;
            const FractalParameters p = fitFractal(wmSpectrum(D, G, L, 1, 2000));
            EXPECT_NEAR(p.D, D, 1e-12) << "D=" << D << " G=" << G;
            EXPECT_NEAR(p.G / G, 1.0, 1e-11) << "D=" << D << " G=" << G;
            // Spectrum::fractal is the project's generator of the same PSD.
            const FractalParameters q = fitFractal(Spectrum::fractal(D, G, 1.0 / L, 4e6, L));
            EXPECT_NEAR(q.D, D, 1e-12) << "D=" << D << " G=" << G;
            EXPECT_NEAR(q.G / G, 1.0, 1e-11) << "D=" << D << " G=" << G;
        }
    }
}

TEST(FractalFit, fitsOnlyTheRequestedBand)
{
    // Below 1e5 1/m one fractal, above it another, different in both D and G: fitting each
    // band recovers its own parameters; fitting all of it recovers neither. Tolerances as in
    // recoversDAndGOfAnExactFractalSpectrum.
    const double L = 1e-3;
    const double D1 = 1.4, G1 = 1e-9, D2 = 1.7;
    // G2 makes the PSD continuous at 1e5 1/m, so the fit over everything stays a plausible
    // fractal (D in (1, 2)) that is neither band's.
    const double G2 = std::pow(wmPsd(D1, G1, 1e5) * 2.0 * std::log(1.5) * std::pow(1e5, 5.0 - 2.0 * D2),
                               1.0 / (2.0 * (D2 - 1.0)));
    std::vector<double> f;
    std::vector<double> beta;
    for (int i = 1; i <= 1000; ++i) {
        const double fi = i / L;
        const double S = fi < 1e5 ? wmPsd(D1, G1, fi) : wmPsd(D2, G2, fi);
        f.push_back(fi);
        beta.push_back(std::sqrt(2.0 * S / L));
    }
    const Spectrum s(f, beta, L);
    const FractalParameters low = fitFractal(s, 0.0, 0.99e5);
    EXPECT_NEAR(low.D, D1, 1e-12);
    EXPECT_NEAR(low.G / G1, 1.0, 1e-11);
    const FractalParameters high = fitFractal(s, 1e5, 1e6);
    EXPECT_NEAR(high.D, D2, 1e-12);
    EXPECT_NEAR(high.G / G2, 1.0, 1e-11);
    const FractalParameters all = fitFractal(s);
    EXPECT_GT(std::abs(all.D - D1), 1e-3);
    EXPECT_GT(std::abs(all.D - D2), 1e-3);
}

TEST(FractalFit, skipsZeroLevels)
{
    // A zero amplitude has ln S = -inf; it must be left out, not poison the fit.
    const double L = 1e-3;
    Spectrum s = wmSpectrum(1.6, 1e-10, L, 1, 100);
    std::vector<double> beta = s.amplitudes();
    beta[10] = 0.0;
    beta[50] = 0.0;
    const FractalParameters p = fitFractal(Spectrum(s.frequencies(), beta, L));
    EXPECT_NEAR(p.D, 1.6, 1e-12);      // as in recoversDAndGOfAnExactFractalSpectrum
    EXPECT_NEAR(p.G / 1e-10, 1.0, 1e-11);
}

TEST(FractalFit, errorsOnTooFewLevelsAndBadRanges)
{
    const double L = 1e-3;
    const Spectrum s = wmSpectrum(1.5, 1e-10, L, 1, 100); // f = 1e3 ... 1e5 1/m
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Two levels in range (a line through two points says nothing about the fit).
    EXPECT_THROW(fitFractal(s, 1e3, 2e3), ParameterError);
    EXPECT_NO_THROW(fitFractal(s, 1e3, 3e3));
    // No level in range.
    EXPECT_THROW(fitFractal(s, 2e5, 3e5), ParameterError);
    // Only two levels exist.
    EXPECT_THROW(fitFractal(wmSpectrum(1.5, 1e-10, L, 1, 2)), ParameterError);
    // All-zero amplitudes except two.
    std::vector<double> beta(s.size(), 0.0);
    beta[3] = 1e-9;
    beta[7] = 1e-10;
    EXPECT_THROW(fitFractal(Spectrum(s.frequencies(), beta, L)), ParameterError);
    // Bad ranges.
    EXPECT_THROW(fitFractal(s, 5e4, 1e4), ParameterError);
    EXPECT_THROW(fitFractal(s, 1e4, 1e4), ParameterError);
    EXPECT_THROW(fitFractal(s, -1.0, 1e4), ParameterError);
    EXPECT_THROW(fitFractal(s, nan, 1e4), ParameterError);
    EXPECT_THROW(fitFractal(s, 0.0, nan), ParameterError);
    EXPECT_THROW(fitFractal(s, inf, inf), ParameterError);
    // The message names the parameter.
    try {
        fitFractal(s, 1e3, 2e3);
        FAIL() << "no error";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("found 2"), std::string::npos) << e.what();
    }
}

TEST(FractalFit, errorsWhenTheSlopeIsNotFractal)
{
    // White noise (flat PSD, slope 0) gives D = 2.5; beta ~ f^-3 (PSD slope -6) gives D = -0.5.
    const double L = 1e-3;
    std::vector<double> f;
    std::vector<double> flat;
    std::vector<double> steep;
    for (int i = 1; i <= 50; ++i) {
        f.push_back(i / L);
        flat.push_back(1e-9);
        steep.push_back(1e-9 * std::pow(i, -3.0));
    }
    EXPECT_THROW(fitFractal(Spectrum(f, flat, L)), ParameterError);
    EXPECT_THROW(fitFractal(Spectrum(f, steep, L)), ParameterError);
}

TEST(FractalFit, theFinestOctavesHurstExponentIsTheSpectrumsSlope)
{
    // beta = b f^-(H + 1/2) (PSD ~ f^-(1 + 2H)): H_f = H to round-off, whatever the spectrum does
    // below its finest octave (a roll-off); on a period four times as long within 0.03 (onPeriod
    // interpolates the density linearly between the levels and ends the band half a bin beyond
    // the last: its finest octave is not quite a power law); a spectrum steeper than any
    // self-affine one gives its H_f all the same (1.5); too few levels: none.
    const double L = 1e-3;
    for (double H : {0.3, 0.8, 1.0}) {
        SCOPED_TRACE(H);
        const Spectrum plain = Spectrum::powerLaw(1e-9, H + 0.5, 1.0 / L, 64.0 / L);
        ASSERT_TRUE(fineHurstExponent(plain).has_value());
        EXPECT_NEAR(*fineHurstExponent(plain), H, 1e-12);
        std::vector<double> f;
        std::vector<double> beta;
        for (int i = 1; i <= 64; ++i) {
            f.push_back(i / L);
            beta.push_back(1e-9 * std::pow(std::max(i, 8) / L, -(H + 0.5))); // flat below the 8th level
        }
        const Spectrum rolled(f, beta, L);
        EXPECT_NEAR(*fineHurstExponent(rolled), H, 1e-12);
        EXPECT_NEAR(*fineHurstExponent(rolled.onPeriod(4)), H, 0.03);
    }
    EXPECT_NEAR(*fineHurstExponent(Spectrum::powerLaw(1e-9, 2.0, 1.0 / L, 64.0 / L)), 1.5, 1e-12);
    EXPECT_FALSE(fineHurstExponent(Spectrum({1e3, 2e3, 3e3}, {1e-6, 1e-7, 1e-8}, L)).has_value()); // 2 in [1.5e3, 3e3]
    EXPECT_TRUE(fineHurstExponent(Spectrum({1e3, 2e3, 3e3, 4e3}, {1e-6, 1e-7, 1e-8, 1e-9}, L)).has_value());
}
