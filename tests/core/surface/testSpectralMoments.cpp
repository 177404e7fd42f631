// SPDX-License-Identifier: GPL-3.0-or-later
// McCool's spectral moments and summit parameters (McCool, Wear 107 (1986) 37-60; docs/theory.md §4.1).
// Every expected value is computed here from the sinusoids' amplitudes and frequencies, never by
// the code under test.
#include "roughContact/Error.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

// Sums of a few squared terms and one sqrt/pow each: a few ulp of relative error.
constexpr double roundOff = 1e-14;

struct Wave {
    double f;    // [1/m]
    double beta; // [m]
};

// <z^2>, <z'^2>, <z''^2> of z = sum beta cos(2 pi f x + phase) for distinct f: cross terms
// average out over whole periods, each term leaves beta^2/2 times (2 pi f)^(2j) (the j-th
// derivative multiplies the amplitude by 2 pi f). Angular wavenumber, as docs/theory.md §4.1 states.
SpectralMoments momentsByHand(const std::vector<Wave>& waves)
{
    SpectralMoments m{0, 0, 0};
    for (const Wave& w : waves) {
        const double k = 2.0 * pi * w.f;
        m.m0 += w.beta * w.beta / 2.0;
        m.m2 += w.beta * w.beta * k * k / 2.0;
        m.m4 += w.beta * w.beta * k * k * k * k / 2.0;
    }
    return m;
}

Spectrum spectrumOf(const std::vector<Wave>& waves, double L)
{
    std::vector<double> f;
    std::vector<double> beta;
    for (const Wave& w : waves) {
        f.push_back(w.f);
        beta.push_back(w.beta);
    }
    return Spectrum(f, beta, L, "test waves");
}

const std::vector<Wave> threeWaves{{1e4, 0.3e-6}, {5e4, 0.05e-6}, {2.3e5, 4e-9}};
} // namespace

TEST(SpectralMoments, momentsOfAFewSinusoidsInAngularWavenumber)
{
    const SpectralMoments expected = momentsByHand(threeWaves);
    const SpectralMoments m = spectralMoments(spectrumOf(threeWaves, 1e-3));
    EXPECT_NEAR(m.m0 / expected.m0, 1.0, roundOff);
    EXPECT_NEAR(m.m2 / expected.m2, 1.0, roundOff);
    EXPECT_NEAR(m.m4 / expected.m4, 1.0, roundOff);
}

TEST(SpectralMoments, zeroAmplitudeLevelsCarryNothing)
{
    std::vector<Wave> withZeros = threeWaves;
    withZeros.insert(withZeros.begin() + 1, Wave{2e4, 0.0});
    withZeros.push_back(Wave{1e6, 0.0});
    const SpectralMoments a = spectralMoments(spectrumOf(withZeros, 1e-3));
    const SpectralMoments b = momentsByHand(threeWaves);
    EXPECT_NEAR(a.m4 / b.m4, 1.0, roundOff);
    EXPECT_NEAR(a.m2 / b.m2, 1.0, roundOff);
}

TEST(SpectralMoments, mcCoolParametersOfAFewSinusoids)
{
    const SpectralMoments m = momentsByHand(threeWaves);
    // McCool (1986), as docs/theory.md §4.1 gives them.
    const double eta = m.m4 / (6.0 * pi * std::sqrt(3.0) * m.m2);
    const double R = 0.375 * std::sqrt(pi / m.m4);
    const double alpha = m.m0 * m.m4 / (m.m2 * m.m2);
    const double sigmaS = std::sqrt((1.0 - 0.8968 / alpha) * m.m0);

    const SummitParameters p = mcCoolParameters(spectrumOf(threeWaves, 1e-3));
    EXPECT_NEAR(p.eta / eta, 1.0, roundOff);
    EXPECT_NEAR(p.R / R, 1.0, roundOff);
    EXPECT_NEAR(p.alpha / alpha, 1.0, roundOff);
    EXPECT_NEAR(p.sigmaS / sigmaS, 1.0, roundOff);
    // The same from moments given directly.
    const SummitParameters q = mcCoolParameters(m);
    EXPECT_NEAR(q.eta / eta, 1.0, roundOff);
    EXPECT_NEAR(q.sigmaS / sigmaS, 1.0, roundOff);
}

TEST(SpectralMoments, singleSinusoidHasBandwidthOne)
{
    // One level: m0 m4 = m2^2 exactly, alpha = 1, sigma_s^2 = 0.1032 m0; and with
    // k = 2 pi f: eta = k^2 / (6 pi sqrt 3), R = 0.375 sqrt(pi) / (k^2 beta / sqrt 2).
    const double f = 3e4;
    const double beta = 0.2e-6;
    const double k = 2.0 * pi * f;
    const SummitParameters p = mcCoolParameters(spectrumOf({{f, beta}}, 1e-3));
    EXPECT_NEAR(p.alpha, 1.0, roundOff);
    EXPECT_NEAR(p.sigmaS / std::sqrt(0.1032 * beta * beta / 2.0), 1.0, roundOff);
    EXPECT_NEAR(p.eta / (k * k / (6.0 * pi * std::sqrt(3.0))), 1.0, roundOff);
    EXPECT_NEAR(p.R / (0.375 * std::sqrt(pi) * std::sqrt(2.0) / (k * k * beta)), 1.0, roundOff);
}

TEST(SpectralMoments, bandwidthRatioIsTheMeanWavenumberOverTheRmsOne)
{
    // W = m1/sqrt(m0 m2), m1 = sum k beta^2/2, by hand from the waves.
    double m0 = 0.0;
    double m1 = 0.0;
    double m2 = 0.0;
    for (const Wave& w : threeWaves) {
        const double k = 2.0 * pi * w.f;
        m0 += w.beta * w.beta / 2.0;
        m1 += k * w.beta * w.beta / 2.0;
        m2 += k * k * w.beta * w.beta / 2.0;
    }
    const double W = spectralBandwidthRatio(spectrumOf(threeWaves, 1e-3));
    EXPECT_NEAR(W / (m1 / std::sqrt(m0 * m2)), 1.0, roundOff);
    EXPECT_GT(W, 0.0);
    EXPECT_LT(W, 1.0);
    // One level: 1 to round-off and never above (the law refuses W > 1); scaling the heights or
    // the wavelengths leaves it alone (a ratio of wavenumbers, dimensionless).
    for (const Wave& one : {Wave{3e4, 0.2e-6}, Wave{7.7e3, 3e-9}, Wave{1.3e5, 7e-7}}) {
        const double single = spectralBandwidthRatio(spectrumOf({one}, 1e-3));
        EXPECT_NEAR(single, 1.0, roundOff);
        EXPECT_LE(single, 1.0);
    }
    std::vector<Wave> scaled;
    for (const Wave& w : threeWaves) {
        scaled.push_back({4.0 * w.f, 7.0 * w.beta});
    }
    EXPECT_NEAR(spectralBandwidthRatio(spectrumOf(scaled, 0.25e-3)) / W, 1.0, roundOff);
    // Self-affine line scans of 64 levels, C1 ~ f^-(1 + 2 H) above a roll-off level, flat below
    // (beta_i^2 ~ C1): without a roll-off the heights live at the longest waves and W is small;
    // a roll-off at the 16th level narrows the band. The values docs/validation quotes (by hand in
    // Python from the same sums: 0.4645, 0.7882; 5e-5, half the last printed digit).
    const auto selfAffine = [](double hurst, int rolloff) {
        std::vector<Wave> waves;
        for (int i = 1; i <= 64; ++i) {
            const double c1 = i < rolloff ? 1.0 : std::pow(double(i) / rolloff, -(1.0 + 2.0 * hurst));
            waves.push_back({i * 1e3, 1e-6 * std::sqrt(c1)});
        }
        return spectralBandwidthRatio(spectrumOf(waves, 1e-3));
    };
    EXPECT_NEAR(selfAffine(0.5, 1), 0.4645, 5e-5);
    EXPECT_NEAR(selfAffine(0.8, 16), 0.7882, 5e-5);
    EXPECT_THROW(spectralBandwidthRatio(spectrumOf({{1e4, 0.0}}, 1e-3)), ParameterError);
}

TEST(SpectralMoments, momentsOfASampledProfileViaTheFft)
{
    // Sinusoids on the FFT grid f = j/L, each an even function about the scan's centre
    // x_c = (N-1) dx / 2, so that the least-squares line fromProfile removes is exactly zero
    // (an even function is orthogonal to x - x_c) and the sampled sinusoids have zero mean.
    // Then the moments are the analytic <z^2>, <z'^2>, <z''^2> of the continuous sinusoids,
    // with no finite differences anywhere.
    const std::size_t N = 1024;
    const double dx = 0.2e-6;
    const double L = N * dx;
    const std::vector<std::pair<int, double>> bins{{3, 0.4e-6}, {17, 0.07e-6}, {150, 3e-9}};
    std::vector<double> z(N, 0.0);
    std::vector<Wave> waves;
    const double xc = 0.5 * (N - 1) * dx;
    for (const auto& [j, beta] : bins) {
        const double f = j / L;
        waves.push_back({f, beta});
        for (std::size_t n = 0; n < N; ++n) {
            z[n] += beta * std::cos(2.0 * pi * f * (n * dx - xc));
        }
    }
    const SpectralMoments expected = momentsByHand(waves);
    const SpectralMoments m = spectralMoments(Spectrum::fromProfile(Profile(z, dx)));
    // FFT round-off: each beta_k comes out with an absolute error of ~1e-16 x the largest
    // amplitude (a few ulp times log2 N); squared, this leaves the empty bins ~1e-32 beta^2
    // of power, weighted up to (2 pi f_Nyquist / 2 pi f_min)^4 = (512/3)^4 ~ 1e9 for m4 against
    // the smallest contributor's beta^2 k^4, still < 1e-20 relative. Matching amplitudes to
    // ~1e-14 relative gives the tolerance.
    EXPECT_NEAR(m.m0 / expected.m0, 1.0, 1e-12);
    EXPECT_NEAR(m.m2 / expected.m2, 1.0, 1e-12);
    EXPECT_NEAR(m.m4 / expected.m4, 1.0, 1e-12);
}

TEST(SpectralMoments, cyclesInsteadOfRadiansWouldBeCaught)
{
    // Guards the unit: m2 of one level must be (2 pi f)^2 beta^2/2, not f^2 beta^2/2.
    const SpectralMoments m = spectralMoments(spectrumOf({{1e4, 1e-6}}, 1e-3));
    EXPECT_NEAR(m.m2 / (1e-12 / 2.0 * 1e8), 4.0 * pi * pi, 4.0 * pi * pi * roundOff);
}

TEST(SpectralMoments, mcCoolRejectsBadMoments)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(mcCoolParameters(SpectralMoments{0.0, 1.0, 1.0}), ParameterError);
    EXPECT_THROW(mcCoolParameters(SpectralMoments{1.0, -1.0, 1.0}), ParameterError);
    EXPECT_THROW(mcCoolParameters(SpectralMoments{1.0, 1.0, nan}), ParameterError);
    // alpha = m0 m4 / m2^2 = 0.8 < 0.8968: sigma_s^2 < 0 (only possible for moments given
    // directly: any spectrum has alpha >= 1).
    EXPECT_THROW(mcCoolParameters(SpectralMoments{0.8, 1.0, 1.0}), ParameterError);
    // alpha = 0.9 is accepted: sigma_s^2 = (1 - 0.8968/0.9) m0 > 0.
    EXPECT_NO_THROW(mcCoolParameters(SpectralMoments{0.9, 1.0, 1.0}));
}
