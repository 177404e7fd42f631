// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic synthesis of an areal surface from a line-scan spectrum (ArealSynthesis.hpp): the
// Abel pair, its closed form for a power law, and the synthesized surface against its input.
#include "roughContact/Error.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

Spectrum standin()
{
    return Spectrum::fromProfile(
        readProfile(std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv"));
}

// A power law beta = bm f^-(H + 1/2) at f_i = i/L, i = 1..levels: C1 ~ f^-(1 + 2H).
Spectrum powerLaw(double H, std::size_t levels, double L = 1e-3)
{
    return Spectrum::powerLaw(1e-9 * std::pow(1.0 / L, H + 0.5), H + 0.5, 1.0 / L, double(levels) / L, L);
}

// Eq. (1) evaluated numerically: C1(x) = 2 integral_0^tmax C2(sqrt(x^2 + t^2)) dt, t^2 = r^2 - x^2
// (which removes the kernel's 1/sqrt), split at the nodes of C2 (the levels, where C2 has a
// square-root cusp); tanh-sinh on each piece copes with the 1/sqrt pile-up at the cutoff.
double forwardAbel(const IsotropicSpectrum& iso, const std::vector<double>& nodes, double x)
{
    boost::math::quadrature::tanh_sinh<double> integrator;
    const double top = iso.highestFrequency();
    std::vector<double> t{0.0};
    for (double k : nodes) {
        if (k > x && k < top) {
            t.push_back(std::sqrt(k * k - x * x));
        }
    }
    t.push_back(std::sqrt(top * top - x * x));
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
        sum += integrator.integrate([&](double s) { return iso.c2(std::sqrt(x * x + s * s)); }, t[i],
                                    t[i + 1], 1e-11);
    }
    return 2.0 * sum;
}

// The variance and slope variance a line scan with this spectrum has: beta^2/2 per level
// (beta^2 for the Nyquist level of a profile, as Spectrum::profileVariance), times (2 pi f)^2.
double slopeVariance(const Spectrum& s)
{
    double v = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double w = (s.hasNyquistLevel() && i + 1 == s.size()) ? 1.0 : 0.5;
        v += w * std::pow(2.0 * pi * s.frequency(i) * s.amplitude(i), 2);
    }
    return v;
}

// The variance of the levels in [lo, hi) (frequencies in units of 1/L).
double bandVariance(const Spectrum& s, double lo, double hi)
{
    double v = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double k = s.frequency(i) * s.length();
        if (k >= lo * (1 - 1e-9) && k < hi * (1 - 1e-9)) {
            const double w = (s.hasNyquistLevel() && i + 1 == s.size()) ? 1.0 : 0.5;
            v += w * s.amplitude(i) * s.amplitude(i);
        }
    }
    return v;
}
} // namespace

// (a) Eq. (1) applied to the C2 of Eq. (2) gives back the C1 that was inverted. C2 is exact
// for the piecewise linear C1 (closed form), so what is left is the quadrature (tanh-sinh to
// 1e-11 on each piece) and rounding in the differences of acosh: a relative 1e-6 leaves three
// orders of margin and is far below any error of form (a missing 1/pi or 2, or the cutoff's
// jump term, is O(1) in the top levels).
TEST(ArealSynthesis, AbelRoundTrip)
{
    const Spectrum measured = standin();
    for (const Spectrum& s : {powerLaw(0.8, 48), measured.truncated(64.5 / measured.length())}) {
        const IsotropicSpectrum iso(s);
        std::vector<double> nodes;
        for (double f : s.frequencies()) {
            nodes.push_back(f);
        }
        const double L = s.length();
        double worst = 0.0;
        for (double k : {1.0, 1.5, 2.0, 3.0, 7.25, 10.0, 20.0, 33.5, 40.0, 46.0, 47.9, 48.3}) {
            const double f = k / L;
            if (f >= iso.highestFrequency()) {
                continue;
            }
            const double want = iso.c1(f);
            const double got = forwardAbel(iso, nodes, f);
            ASSERT_GT(want, 0.0);
            worst = std::max(worst, std::abs(got / want - 1.0));
            EXPECT_NEAR(got / want, 1.0, 1e-6) << s.source() << " at f L = " << k;
        }
        std::printf("[ measured ] %s: Abel round trip worst relative error %.2e\n", s.source().c_str(),
                    worst);
    }
}

// (b) Closed form. C1 = A f^-(1+2H) gives, with k = q/sqrt(u) in Eq. (2),
//     C2(q) = (A (1 + 2H) / pi) q^-(2+2H) integral_1^inf t^-(2+2H) (t^2 - 1)^-1/2 dt
//           = A (1 + 2H) B(1 + H, 1/2) / (2 pi) q^-(2+2H),
// B the Beta function (for H = 1/2: B(3/2, 1/2) = pi/2, C2 = A/(2 q^3), whose Abel transform
// is A/f^2 by hand). The implementation interpolates C1 linearly between the levels k = fL
// (unit steps) and cuts it off at K' = K + 1/2, which leaves two errors that can be worked out:
//  - the secant slope on [q, q+1] against C1' weighted by the kernel 1/sqrt(k^2 - q^2), which is
//    singular at k = q: C1''/(3 pi sqrt(2q)), relative 2(a+1)/(3 sqrt(2) B) q^-3/2 (a = 1 + 2H;
//    the secant errors of the intervals further out average out against a smooth kernel);
//  - the jump term at K' instead of the tail beyond it: relative 2/(a(a+1)B) (q/K')^(a+1).
// The tolerance is 1.5 times their sum (the next orders in 1/q and q/K'); the two have opposite
// signs, so the bound holds whichever dominates. It is 1.2e-2 to 2e-2 at k = 20 and 5e-4 to
// 6.4e-4 at k = 200 (measured errors: 8e-3 to 1.4e-2 and 1.9e-4 to 5e-4): a
// wrong Beta argument (B(H, 1/2)), factor 2 or pi is far outside.
TEST(ArealSynthesis, PowerLawClosedForm)
{
    EXPECT_NEAR(boost::math::beta(1.5, 0.5), pi / 2, 1e-14);
    for (double H : {0.3, 0.5, 0.8}) {
        const std::size_t K = 4000;
        const Spectrum s = powerLaw(H, K);
        const IsotropicSpectrum iso(s);
        const double L = s.length();
        // beta = bm f^-m, C1 = beta^2 L / 4 = A f^-(1+2H) with A = bm^2 L / 4.
        const double bm = s.amplitude(0) * std::pow(s.frequency(0), H + 0.5);
        const double A = bm * bm * L / 4.0;
        const double a = 1.0 + 2.0 * H;
        const double prefactor = A * a * boost::math::beta(1.0 + H, 0.5) / (2.0 * pi);
        for (double k : {20.0, 50.0, 100.0, 200.0, 1000.0}) {
            const double q = k / L;
            const double want = prefactor * std::pow(q, -(2.0 + 2.0 * H));
            const double got = iso.c2(q);
            const double B = boost::math::beta(1.0 + H, 0.5);
            const double tol = 1.5 * (2.0 * (a + 1.0) / (3.0 * std::sqrt(2.0) * B) * std::pow(k, -1.5) +
                                      2.0 / (a * (a + 1.0) * B) * std::pow(k / (K + 0.5), a + 1.0));
            std::printf("[ measured ] H = %.1f, k = %6.0f: C2 relative error %.2e (tolerance %.2e)\n", H, k,
                        got / want - 1.0, tol);
            EXPECT_NEAR(got / want, 1.0, tol) << "H = " << H << ", k = " << k;
        }
        // The 1-D input itself, between levels (the interpolation).
        EXPECT_NEAR(iso.c1(100.0 / L) / (A * std::pow(100.0 / L, -a)), 1.0, 1e-12);
    }
}

namespace {
struct Case {
    const char* name;
    Spectrum spectrum;
    std::size_t n;
};

// A power law that is not steeper than f^-2 (H = 0.3: C1 ~ f^-1.6): the row detrending that
// lineScanSpectrum does (as Spectrum::fromProfile) removes a tilt from periodic rows, which adds
// a sawtooth whose power falls as f^-2 and would swamp the top levels of a steeper spectrum.
std::vector<Case> cases()
{
    return {{"power law H = 0.3, 200 levels, n = 512", powerLaw(0.3, 200), 512},
            {"stand-in, n = 512 (256 levels)", standin(), 512},
            {"stand-in, n = 2454 (all 1227 levels)", standin(), 2454}};
}

// What a grid of n points can hold of the input: its levels up to n/(2L); a level at exactly
// n/(2L) that is not the input's own Nyquist level is the grid's Nyquist level, of which the grid
// holds the cosine only (density times its one bin: beta^2/4, so amplitude beta/2).
Spectrum gridInput(const Spectrum& s, std::size_t n)
{
    const Spectrum t = s.truncated(0.5 * double(n) / s.length() * (1 + 1e-12));
    const double top = t.frequencies().back() * t.length();
    if (t.hasNyquistLevel() || std::abs(top - 0.5 * double(n)) > 1e-6) {
        return t;
    }
    std::vector<double> beta = t.amplitudes();
    beta.back() *= 0.5;
    return Spectrum::withNyquistLevel(t.frequencies(), beta, t.length(), t.source(), true);
}

// The input as it is synthesized: its levels made non-increasing (IsotropicSpectrum::c1 at the
// levels, the two-sided density c1 over one bin 1/L at +f and -f: beta^2/2 = 2 c1 / L).
Spectrum pooledInput(const Spectrum& spectrum, std::size_t n)
{
    const Spectrum input = gridInput(spectrum, n);
    const IsotropicSpectrum iso(spectrum, 0.5 * double(n) / spectrum.length() * (1 + 1e-12));
    std::vector<double> beta;
    for (std::size_t i = 0; i < input.size(); ++i) {
        const bool nyquist = input.hasNyquistLevel() && i + 1 == input.size();
        beta.push_back(std::sqrt(iso.c1(input.frequency(i)) / input.length() * (nyquist ? 1.0 : 4.0)));
    }
    return Spectrum::withNyquistLevel(input.frequencies(), beta, input.length(), "pooled",
                                      input.hasNyquistLevel());
}

// Mean over the rows (alongX) or columns of: the variance about the scan's mean, and the mean
// square of the periodic forward difference (z[i+1] - z[i])/dx.
std::pair<double, double> scanMoments(const ArealSurface& s, bool alongX)
{
    const std::size_t n = s.nx();
    double var = 0.0;
    double diff = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        double mean = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            mean += alongX ? s.at(i, j) : s.at(j, i);
        }
        mean /= double(n);
        for (std::size_t i = 0; i < n; ++i) {
            const double z = alongX ? s.at(i, j) : s.at(j, i);
            const double next = alongX ? s.at((i + 1) % n, j) : s.at(j, (i + 1) % n);
            var += (z - mean) * (z - mean);
            diff += (next - z) * (next - z) / (s.dx() * s.dx());
        }
    }
    return {var / double(n * n), diff / double(n * n)};
}

// The same mean square difference for a line scan with spectrum s sampled at spacing dx:
// each level's variance times |exp(2 pi i f dx) - 1|^2 / dx^2 = (2 sin(pi f dx) / dx)^2.
double differenceVariance(const Spectrum& s, double dx)
{
    double v = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double w = (s.hasNyquistLevel() && i + 1 == s.size()) ? 1.0 : 0.5;
        v += w * s.amplitude(i) * s.amplitude(i) * std::pow(2.0 * std::sin(pi * s.frequency(i) * dx) / dx, 2);
    }
    return v;
}
} // namespace

// (c) rms height and rms slope of the synthesized surface against the input's (what a grid of n
// points can hold of it, gridInput). The moduli of the Fourier coefficients are fixed, so the
// mean over all rows (or columns) of a scan's variance about its mean, and of its squared
// periodic difference (z[i+1] - z[i])/dx, are the same for every seed (Parseval): what differs
// from the input there is the discretisation of C2 on the grid (annulus averages; measured
// -1.1 % and -0.2 % in variance, +0.07 % and +0.06 % in slope^2), held to 2 %. The slope is
// compared with the pooled input (pooledInput), which is what is synthesized: pooling keeps
// the variance of the stand-in but moves its slope^2 by -3.6 % (n = 512) and -1.4 % (n = 2454).
// The detrended line scans' spectra (lineScanSpectrum, as the line-scan models see them) vary
// with the seed: each row loses a seed-dependent tilt. Over seeds 1..4 their rms slope,
// sqrt(sum (2 pi f beta)^2 / 2), differs from the raw input's by at most 3.6 % (power law: the
// tilt's sawtooth leaks into the top levels) and 0.96 % (stand-in), so 5 % is allowed. The
// surface's own rms is NOT the input's: an isotropic field also varies in the mean of each row
// (wavevectors with |q_x| < 1/L, which a line scan of length L cannot see), so its variance is
// T(0) of Eq. (3), above the line scans' by 19 % (power law) and 6.5 % (stand-in; +3.1 % in
// rms): the surface rms is held to sqrt(T(0)) within 2 % (measured -0.9 % and -0.15 %).
TEST(ArealSynthesis, RmsHeightAndSlope)
{
    for (const Case& c : cases()) {
        const Spectrum input = gridInput(c.spectrum, c.n);
        const Spectrum pooled = pooledInput(c.spectrum, c.n);
        const double h2 = input.profileVariance();
        const double m2 = slopeVariance(input);
        const IsotropicSpectrum iso(c.spectrum, 0.5 * double(c.n) / c.spectrum.length() * (1 + 1e-12));
        const std::vector<double> P = isotropicGridPower(c.spectrum, c.n);
        double total = 0.0;
        for (std::size_t i = 0; i < P.size(); ++i) {
            const std::size_t kx = i % (c.n / 2 + 1);
            total += (kx == 0 || kx == c.n / 2) ? P[i] : 2.0 * P[i]; // the mirrored half
        }
        for (std::uint64_t seed : {1, 2, 3, 4}) {
            const ArealSurface s = synthesizeIsotropic(c.spectrum, c.n, seed);
            SCOPED_TRACE(std::string(c.name) + ", seed " + std::to_string(seed));
            // Parseval: the surface's variance is the grid power (normalisation, Hermitian symmetry).
            EXPECT_NEAR(s.rms() * s.rms() / total, 1.0, 1e-10);
            EXPECT_NEAR(s.rms() / std::sqrt(iso.powerOutside(0.0)), 1.0, 0.02);
            EXPECT_GT(s.rms(), std::sqrt(h2));
            const double dx = s.dx();
            for (bool alongX : {true, false}) {
                const auto [var, diff] = scanMoments(s, alongX);
                EXPECT_NEAR(var / h2, 1.0, 0.02) << (alongX ? "rows" : "columns");
                EXPECT_NEAR(diff / differenceVariance(pooled, dx), 1.0, 0.02)
                    << (alongX ? "rows" : "columns");
                const Spectrum scans = lineScanSpectrum(s, alongX ? ScanDirection::x : ScanDirection::y);
                EXPECT_NEAR(std::sqrt(slopeVariance(scans) / m2), 1.0, 0.05) << (alongX ? "rows" : "columns");
                std::printf("[ measured ] %s seed %d %s: surface rms / input %+.2e, / sqrt(T0) %+.2e; scans "
                            "variance %+.2e, difference slope^2 %+.2e, detrended spectral rms slope %+.2e\n",
                            c.name, int(seed), alongX ? "rows" : "cols", s.rms() / std::sqrt(h2) - 1,
                            s.rms() / std::sqrt(iso.powerOutside(0.0)) - 1, var / h2 - 1,
                            diff / differenceVariance(pooled, dx) - 1,
                            std::sqrt(slopeVariance(scans) / m2) - 1);
            }
        }
    }
}

// (d) Band power per octave [k, 2k) (k = fL) of the averaged line-scan spectrum (rows and
// columns, lineScanSpectrum with `both`) against the input the surface was made from: the input's
// levels made non-increasing (pooled, IsotropicSpectrum::c1 at the levels; a power law is
// unchanged, the stand-in's octaves from k = 8 on change by at most 11 %, its three lowest by
// +267 %, +185 % and -43 %: the pooling that an isotropic surface needs, which keeps the total).
// The octave k = 1 is left out: the detrending of each row removes 30 % to 50 % of the first
// level (a linear fit takes much of one period of a sine). Over seeds 1..6 the octaves [2, 4)
// and [4, 8) (2 and 4 levels) scatter by up to 22 %, the wider ones by up to 10.5 % (the
// seed-dependent tilt of each row leaks into every level, and the power law's top octaves sit
// 4-7 % high from it): allowed 30 % and 15 %.
TEST(ArealSynthesis, OctavePower)
{
    for (const Case& c : cases()) {
        const Spectrum input = gridInput(c.spectrum, c.n);
        const Spectrum pooled = pooledInput(c.spectrum, c.n);
        EXPECT_NEAR(pooled.profileVariance() / input.profileVariance(), 1.0, 0.02) << c.name;
        for (std::uint64_t seed : {1, 2, 3, 4, 5, 6}) {
            const Spectrum both =
                lineScanSpectrum(synthesizeIsotropic(c.spectrum, c.n, seed), ScanDirection::both);
            std::printf("[ measured ] %s seed %d:", c.name, int(seed));
            for (double lo = 2; lo <= double(c.n) / 2; lo *= 2) {
                const double want = bandVariance(pooled, lo, 2 * lo);
                if (want == 0.0) {
                    continue;
                }
                const double got = bandVariance(both, lo, 2 * lo);
                std::printf(" %+.3f", got / want - 1);
                std::size_t levels = 0;
                for (double f : input.frequencies()) {
                    levels +=
                        (f * input.length() >= lo * (1 - 1e-9) && f * input.length() < 2 * lo * (1 - 1e-9));
                }
                EXPECT_NEAR(got / want, 1.0, levels < 8 ? 0.30 : 0.15)
                    << c.name << ", seed " << seed << ", octave " << lo;
            }
            std::printf("\n");
        }
    }
}

// (e) The same seed gives the same surface, another seed another one; bad grid sizes are refused
// before anything is allocated (the largest even size_t would need 2^130 bytes).
TEST(ArealSynthesis, SeedsAndRefusals)
{
    const Spectrum s = powerLaw(0.3, 20);
    const ArealSurface a = synthesizeIsotropic(s, 64, 7);
    const ArealSurface b = synthesizeIsotropic(s, 64, 7);
    const ArealSurface c = synthesizeIsotropic(s, 64, 8);
    EXPECT_EQ(a.heights(), b.heights());
    EXPECT_NE(a.heights(), c.heights());
    EXPECT_EQ(a.nx(), 64u);
    EXPECT_DOUBLE_EQ(a.dx(), s.length() / 64);
    for (std::size_t n : {std::size_t(0), std::size_t(6), std::size_t(7), std::size_t(9), std::size_t(4097),
                          std::size_t(4098), std::numeric_limits<std::size_t>::max() - 1}) {
        try {
            synthesizeIsotropic(s, n, 1);
            ADD_FAILURE() << "n = " << n << " accepted";
        } catch (const ParameterError& e) {
            EXPECT_EQ(e.parameter(), "n");
            EXPECT_NE(std::string(e.what()).find(std::to_string(n)), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(synthesizeIsotropic(s, 8, 1));
    EXPECT_NO_THROW(isotropicGridPower(s, 4096));
}

// The band on the grid: nothing at the mean, nothing below half a bin under the lowest level or
// beyond half a bin over the highest (the cells whose annulus |k| +- 1/2 reaches into the band
// [k_1 - 1/2, K + 1/2] hold power, no other), power at the lowest and highest level.
TEST(ArealSynthesis, GridBand)
{
    const double L = 1e-3;
    const Spectrum s = Spectrum::powerLaw(1e-9 * std::pow(1.0 / L, 0.8), 0.8, 5.0 / L, 20.0 / L, L);
    const std::size_t n = 64;
    const std::vector<double> P = isotropicGridPower(s, n);
    const std::size_t nc = n / 2 + 1;
    for (std::size_t iy = 0; iy < n; ++iy) {
        const double ky = iy <= n / 2 ? double(iy) : double(iy) - double(n);
        for (std::size_t ix = 0; ix < nc; ++ix) {
            const double rho = std::hypot(double(ix), ky);
            const double p = P[iy * nc + ix];
            EXPECT_GE(p, 0.0);
            if (rho + 0.5 <= 4.5 || rho - 0.5 >= 20.5) {
                EXPECT_EQ(p, 0.0) << "k = (" << ix << ", " << ky << ")";
            }
            if (rho == 5.0 || rho == 20.0) {
                EXPECT_GT(p, 0.0) << "k = (" << ix << ", " << ky << ")";
            }
        }
    }
}

// A finish with a lay: the same heights with the y spacing stretched, so that the columns (along
// the lay) are the isotropic surface's columns with every length `stretch` times longer: the
// same amplitudes at the frequencies over `stretch` (Spectrum::stretched), the same variance,
// the rms slope over `stretch`; the rows are the isotropic surface's. Stretch 1 is the isotropic
// surface; a stretch that is not positive and finite is refused.
TEST(ArealSynthesis, ALayStretchesTheFeaturesAlongY)
{
    const Spectrum s = powerLaw(0.3, 20);
    const double g = 3.0;
    const ArealSurface iso = synthesizeIsotropic(s, 64, 5);
    const ArealSurface lay = synthesizeStretched(s, g, 64, 5);
    EXPECT_EQ(lay.heights(), iso.heights());
    EXPECT_EQ(lay.dx(), iso.dx());
    EXPECT_DOUBLE_EQ(lay.dy(), g * iso.dx());
    const Spectrum rows = lineScanSpectrum(lay, ScanDirection::x);
    EXPECT_EQ(rows.amplitudes(), lineScanSpectrum(iso, ScanDirection::x).amplitudes());
    const Spectrum columns = lineScanSpectrum(lay, ScanDirection::y);
    const Spectrum expected = lineScanSpectrum(iso, ScanDirection::y).stretched(g);
    ASSERT_EQ(columns.size(), expected.size());
    EXPECT_DOUBLE_EQ(columns.length(), expected.length());
    for (std::size_t i = 0; i < columns.size(); ++i) {
        EXPECT_NEAR(columns.frequency(i), expected.frequency(i), 1e-12 * expected.frequency(i));
        EXPECT_NEAR(columns.amplitude(i), expected.amplitude(i), 1e-12 * expected.amplitude(0));
    }
    // Spectrum::stretched: the variance kept, the second moment (rms slope squared) over g^2.
    double v = 0.0, vs = 0.0, m2 = 0.0, m2s = 0.0;
    const Spectrum st = s.stretched(g);
    const double pi = std::acos(-1.0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        v += 0.5 * s.amplitude(i) * s.amplitude(i);
        vs += 0.5 * st.amplitude(i) * st.amplitude(i);
        m2 += 0.5 * std::pow(2 * pi * s.frequency(i) * s.amplitude(i), 2);
        m2s += 0.5 * std::pow(2 * pi * st.frequency(i) * st.amplitude(i), 2);
    }
    EXPECT_DOUBLE_EQ(vs, v);
    EXPECT_NEAR(m2s, m2 / (g * g), 1e-12 * m2);
    EXPECT_DOUBLE_EQ(st.length(), g * s.length());
    EXPECT_EQ(synthesizeStretched(s, 1.0, 64, 5).heights(), iso.heights());
    EXPECT_EQ(synthesizeStretched(s, 1.0, 64, 5).dy(), iso.dy());
    for (double bad : {0.0, -2.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
        try {
            synthesizeStretched(s, bad, 64, 5);
            ADD_FAILURE() << "stretch " << bad << " accepted";
        } catch (const ParameterError& e) {
            EXPECT_EQ(e.parameter(), "stretch");
        }
        EXPECT_THROW(s.stretched(bad), ParameterError);
    }
}
