// SPDX-License-Identifier: GPL-3.0-or-later
// FFT spectrum of a profile and spectrum algebra (seed §2.1, docs/theory.md §1.2).
#include "roughContact/Error.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

std::vector<double> randomHeights(std::size_t n, unsigned seed)
{
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(-1e-6, 1e-6);
    std::vector<double> z(n);
    for (double& v : z) {
        v = u(gen);
    }
    return z;
}

double variance(const Profile& p)
{
    double s = 0.0;
    for (double v : p.heights()) {
        s += v * v;
    }
    return s / static_cast<double>(p.size());
}
} // namespace

TEST(Spectrum, parsevalHoldsForEvenAndOddLengths)
{
    for (std::size_t n : {2454u, 2455u, 8u, 9u}) {
        const Profile p(randomHeights(n, 7), 0.204e-6);
        const Spectrum s = Spectrum::fromProfile(p);
        const double v = variance(p.detrended());
        // sigma^2 = sum beta^2/2 plus the Nyquist cosine's extra beta^2/2 (even N). The sums
        // run over ~N terms of similar size: round-off ~ N eps ~ 1e-12.
        EXPECT_NEAR(s.profileVariance() / v, 1.0, 1e-12) << "N = " << n;
        EXPECT_EQ(s.hasNyquistLevel(), n % 2 == 0);
        EXPECT_EQ(s.size(), n / 2);
    }
}

TEST(Spectrum, recoversAmplitudesOfGridSinusoids)
{
    // Cosines even about the profile's centre are orthogonal to the detrending line, so the
    // FFT must return their amplitudes to round-off.
    const std::size_t n = 1024;
    const double dx = 0.5e-6;
    const double L = dx * n;
    const double xm = 0.5 * (n - 1);
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = (static_cast<double>(i) - xm) / n;
        z[i] = 3e-7 * std::cos(2 * pi * 5 * t) + 1e-8 * std::cos(2 * pi * 100 * t);
    }
    const Spectrum s = Spectrum::fromProfile(Profile(z, dx));
    EXPECT_NEAR(s.length(), L, 1e-20);
    EXPECT_NEAR(s.nominalArea(), L * L, 1e-30);
    EXPECT_NEAR(s.frequency(4) * L, 5.0, 1e-12);
    EXPECT_NEAR(s.amplitude(4) / 3e-7, 1.0, 1e-12);
    EXPECT_NEAR(s.amplitude(99) / 1e-8, 1.0, 1e-10);
    EXPECT_LT(s.amplitude(49), 1e-12 * 3e-7);
}

TEST(Spectrum, fftMatchesDirectFourierSum)
{
    const std::size_t n = 301;
    const Profile p(randomHeights(n, 11), 0.3e-6);
    const Spectrum s = Spectrum::fromProfile(p);
    const Profile d = p.detrended();
    const auto& z = d.heights();
    for (std::size_t k = 1; k <= n / 2; k += 7) {
        double re = 0.0;
        double im = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            re += z[i] * std::cos(2 * pi * double(k * i) / n);
            im -= z[i] * std::sin(2 * pi * double(k * i) / n);
        }
        // A direct sum of 301 terms: round-off ~1e-14 relative to the largest amplitude.
        EXPECT_NEAR(s.amplitude(k - 1), 2.0 * std::hypot(re, im) / n, 1e-13 * 1e-6) << k;
    }
}

TEST(Spectrum, meanAndTiltDoNotChangeTheSpectrum)
{
    const std::size_t n = 500;
    const std::vector<double> z = randomHeights(n, 3);
    std::vector<double> tilted(z);
    for (std::size_t i = 0; i < n; ++i) {
        tilted[i] += 5e-6 + 2e-8 * static_cast<double>(i); // tilt far above the roughness
    }
    const Spectrum a = Spectrum::fromProfile(Profile(z, 1e-6));
    const Spectrum b = Spectrum::fromProfile(Profile(tilted, 1e-6));
    for (std::size_t k = 0; k < a.size(); ++k) {
        // The tilt is 10x the roughness: cancellation leaves ~1e-15 x 1e-5 m absolute.
        EXPECT_NEAR(a.amplitude(k), b.amplitude(k), 1e-18) << k;
    }
}

TEST(Spectrum, straightLineHasNoRoughness)
{
    std::vector<double> z(64);
    for (std::size_t i = 0; i < z.size(); ++i) {
        z[i] = 1e-6 + 3e-9 * static_cast<double>(i);
    }
    const Spectrum s = Spectrum::fromProfile(Profile(z, 1e-6));
    for (double b : s.amplitudes()) {
        EXPECT_LT(b, 1e-20);
    }
}

TEST(Spectrum, asperityParametersOfSeedEquations4And5)
{
    EXPECT_DOUBLE_EQ(asperityDensity(1e4), 2e8);
    EXPECT_DOUBLE_EQ(asperityRadius(1e4, 1e-8), 1.0 / (4 * pi * pi * 1e-8 * 1e8));
    EXPECT_TRUE(std::isinf(asperityRadius(1e4, 0.0)));
}

TEST(Spectrum, powerLawLevels)
{
    const Spectrum s = Spectrum::powerLaw(2e-10, 1.0, 1e3, 1e5, 1e-3);
    ASSERT_EQ(s.size(), 100u); // i = 1..100 with L = 1 mm
    EXPECT_DOUBLE_EQ(s.frequency(0), 1e3);
    EXPECT_DOUBLE_EQ(s.frequency(99), 1e5);
    EXPECT_DOUBLE_EQ(s.amplitude(9), 2e-10 / 1e4);
    EXPECT_DOUBLE_EQ(Spectrum::powerLaw(1, 1, 1e3, 1e5).length(), 1e-3); // L = 1/fmin
    EXPECT_THROW(Spectrum::powerLaw(1, 1, 1e5, 1e3), ParameterError);
    EXPECT_THROW(Spectrum::powerLaw(-1, 1, 1e3, 1e5), ParameterError);
}

TEST(Spectrum, fractalSpectrumHasMajumdarBhushanPsd)
{
    const double D = 1.597;
    const double G = 2.86e-10;
    const double L = 500e-6;
    const Spectrum s = Spectrum::fractal(D, G, 1.0 / L, 1e6, L);
    for (std::size_t k = 0; k < s.size(); k += 97) {
        const double f = s.frequency(k);
        const double S = std::pow(G, 2 * (D - 1)) / (2 * std::log(1.5) * std::pow(f, 5 - 2 * D));
        EXPECT_NEAR(s.amplitude(k) * s.amplitude(k) * L / 2.0 / S, 1.0, 1e-13);
    }
    EXPECT_THROW(Spectrum::fractal(2.0, G, 1, 2), ParameterError);
}

TEST(Spectrum, combineOnSameGridAddsPowers)
{
    const Spectrum a = Spectrum::fromProfile(Profile(randomHeights(256, 1), 1e-6));
    const Spectrum b = Spectrum::fromProfile(Profile(randomHeights(256, 2), 1e-6));
    const Spectrum c = Spectrum::combine(a, b);
    ASSERT_EQ(c.size(), a.size());
    for (std::size_t k = 0; k < c.size(); ++k) {
        EXPECT_DOUBLE_EQ(c.amplitude(k), std::hypot(a.amplitude(k), b.amplitude(k)));
    }
    EXPECT_NEAR(c.profileVariance() / (a.profileVariance() + b.profileVariance()), 1.0, 1e-14);
}

TEST(Spectrum, combineOnDifferentGridsConservesVariance)
{
    const Spectrum a = Spectrum::fromProfile(Profile(randomHeights(300, 1), 1e-6));   // L = 300 um
    const Spectrum b = Spectrum::fromProfile(Profile(randomHeights(1000, 2), 0.2e-6)); // L = 200 um
    const Spectrum c = Spectrum::combine(a, b);
    EXPECT_DOUBLE_EQ(c.length(), 300e-6);
    // Re-binning moves power between neighbouring levels but conserves the sum (~1e-13 from
    // summing ~2500 terms).
    EXPECT_NEAR(c.variance() / (a.profileVariance() + b.profileVariance()), 1.0, 1e-12);
    // The first combined bin [0, 1.5/L] holds all of a's first level and the half of b's
    // first bin [2500, 7500] 1/m that lies below 5000 1/m.
    const double expected = a.amplitude(0) * a.amplitude(0) + 0.5 * b.amplitude(0) * b.amplitude(0);
    EXPECT_NEAR(c.amplitude(0) * c.amplitude(0) / expected, 1.0, 1e-13);
}

TEST(Spectrum, onPeriodIsTheReportsLongerPeriod)
{
    // The engineering range's spectra on periods of 2L, 4L and 8L were written by an independent
    // implementation (in Python; tests/data/spectra/README.md), to 10 digits: the same levels,
    // and amplitudes to 1e-9 relative (the printed digits' 5e-10, and
    // the input's). The Dektak spectrum's levels, printed to 10 digits, are uniform only to about
    // 1e-10 relative: the bins taken from the neighbours here (uniform ones there) and the band's
    // ends from them move its amplitudes by up to 3.3e-8 (8L), so 1e-7 there.
    for (const char* name : {"selfAffine08", "selfAffine05", "dektak"}) {
        const std::string base = std::string(ROUGHCONTACT_SOURCE_DIR) + "/tests/data/spectra/" + name;
        const Spectrum given = readSpectrum(base + ".spectrum");
        for (std::size_t k : {2U, 4U, 8U}) {
            const Spectrum expected = readSpectrum(base + "-" + std::to_string(k) + "L.spectrum");
            const Spectrum longer = given.onPeriod(k);
            EXPECT_NEAR(longer.length(), static_cast<double>(k) * given.length(), 1e-12 * longer.length()) << name;
            ASSERT_EQ(longer.size(), expected.size()) << name << " " << k << "L";
            double worst = 0.0;
            for (std::size_t i = 0; i < longer.size(); ++i) {
                EXPECT_NEAR(longer.frequency(i), expected.frequency(i), 1e-9 * expected.frequency(i)) << name << i;
                worst = std::max(worst, std::abs(longer.amplitude(i) / expected.amplitude(i) - 1.0));
            }
            EXPECT_LT(worst, std::string(name) == "dektak" ? 1e-7 : 1e-9) << name << " " << k << "L";
        }
    }
}

TEST(Spectrum, onPeriodKeepsTheLevelsDensityAndVariance)
{
    // A flat density C1 on levels i/L: on a period of kL the levels are j/(kL) over the same band
    // [1/(2L), (n + 1/2)/L], and the variance is kept exactly (no interpolation error); a
    // power law's within 1 % (the linear interpolation of a convex C1 between the levels).
    const double L = 2e-3;
    std::vector<double> f;
    std::vector<double> flat;
    for (int i = 1; i <= 32; ++i) {
        f.push_back(i / L);
        flat.push_back(1e-7);
    }
    const Spectrum s(f, flat, L);
    EXPECT_EQ(s.onPeriod(1).size(), s.size());
    for (std::size_t k : {2U, 3U, 8U}) {
        const Spectrum longer = s.onPeriod(k);
        EXPECT_DOUBLE_EQ(longer.length(), static_cast<double>(k) * L);
        EXPECT_NEAR(longer.variance(), s.variance(), 1e-12 * s.variance()) << k;
        EXPECT_NEAR(longer.frequencies().front(), std::ceil(0.5 * k) / (k * L), 1e-9 / L) << k;
        // The last level whose bin reaches into the band: j < 32.5 k + 1/2.
        EXPECT_NEAR(longer.frequencies().back(), (std::ceil(32.5 * k + 0.5) - 1.0) / (k * L), 1e-9 / L) << k;
        // Inside the band every level holds C1 dk: beta^2 = 4 C1/(kL) = flat^2/k.
        EXPECT_NEAR(longer.amplitude(longer.size() / 2), 1e-7 / std::sqrt(static_cast<double>(k)), 1e-18) << k;
    }
    const Spectrum power = Spectrum::powerLaw(1e-12, 1.8, 1.0 / L, 64.0 / L, L);
    EXPECT_NEAR(power.onPeriod(4).variance() / power.variance(), 1.0, 0.01);
    EXPECT_THROW(s.onPeriod(0), ParameterError);
    EXPECT_THROW(s.onPeriod(65), ParameterError);
}

TEST(Spectrum, onPeriodEndsAtANyquistLevel)
{
    // A profile's spectrum ends at its Nyquist level, whose density is beta^2/w and whose bin
    // ends at it (IsotropicSpectrum): on a period of 2L the last level is that frequency, and the
    // variance the synthesis sees (variance(): the Nyquist level's beta^2/w over half a bin) is
    // kept to 1 % (measured 1.0016 here: the linear interpolation's end terms).
    const Profile p(randomHeights(64, 7), 1e-6);
    const Spectrum s = Spectrum::fromProfile(p);
    ASSERT_TRUE(s.hasNyquistLevel());
    const Spectrum longer = s.onPeriod(2);
    EXPECT_FALSE(longer.hasNyquistLevel());
    EXPECT_NEAR(longer.frequencies().back(), s.frequencies().back(), 1e-9 * s.frequencies().back());
    EXPECT_NEAR(longer.frequencies().front(), 0.5 * s.frequencies().front(), 1e-9 * s.frequencies().front());
    EXPECT_NEAR(longer.variance() / s.variance(), 1.0, 0.01) << longer.variance() / s.variance();
}

TEST(Spectrum, rejectsBadLevels)
{
    EXPECT_THROW(Spectrum({2.0, 1.0}, {1.0, 1.0}, 1.0), InputError);
    EXPECT_THROW(Spectrum({1.0, 2.0}, {1.0, -1.0}, 1.0), InputError);
    EXPECT_THROW(Spectrum({1.0, 2.0}, {1.0, std::nan("")}, 1.0), InputError);
    EXPECT_THROW(Spectrum({}, {}, 1.0), InputError);
    EXPECT_THROW(Spectrum({1.0}, {1.0}, 0.0), ParameterError);
}

TEST(Profile, detrendRemovesLeastSquaresLine)
{
    std::vector<double> z{1, 3, 2, 5, 4, 6, 8, 7};
    const Profile d = Profile(z, 1.0).detrended();
    double sum = 0.0;
    double moment = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        sum += d.heights()[i];
        moment += static_cast<double>(i) * d.heights()[i];
    }
    EXPECT_NEAR(sum, 0.0, 1e-13);    // residual orthogonal to 1
    EXPECT_NEAR(moment, 0.0, 1e-12); // and to x
}

TEST(Profile, subsampledKeepsEveryStrideSample)
{
    const Profile p(randomHeights(100, 5), 0.2e-6);
    const Profile q = p.subsampled(10);
    EXPECT_EQ(q.size(), 10u);
    EXPECT_DOUBLE_EQ(q.spacing(), 2e-6);
    EXPECT_EQ(q.heights()[3], p.heights()[30]);
    EXPECT_THROW(p.subsampled(0), ParameterError);
    EXPECT_THROW(p.subsampled(20), InputError); // 5 points: fewer than 8
}

TEST(Profile, rejectsTooFewOrNonFinitePoints)
{
    EXPECT_THROW(Profile(std::vector<double>(7, 0.0), 1.0, "short.csv"), InputError);
    std::vector<double> z(8, 0.0);
    z[3] = std::numeric_limits<double>::infinity();
    try {
        Profile(z, 1.0, "inf.csv");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("inf.csv"), std::string::npos);
    }
    EXPECT_THROW(Profile(std::vector<double>(8, 0.0), 0.0), ParameterError);
}
