// SPDX-License-Identifier: GPL-3.0-or-later
// Persson's theory (models/Persson.hpp) held to its closed forms: the separation kernel against
// the exponential integral and a brute-force quadrature, the spectrum conversion (P1) against the
// IsotropicSpectrum's variance and slope, the light-load area sqrt(8/pi) p/(E' h'), complete
// contact, the exponential law of the separation, Barber's relation by an independent finite
// difference, the scaling with the heights, and the boundary-element reference on a surface
// synthesized from the same line-scan spectrum.
#include "roughContact/Error.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include "ClosedForms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
const double Ep = 1e11; // E' [Pa]

// A line scan of length 1 mm with a power law beta = b f^-1.3 (Hurst exponent 0.8: the 1-D PSD
// falls as f^-(1 + 2H)) at f = i/L for i in [first, last], scaled to the rms areal gradient
// `gradient` (measured by the model itself, so the loads below mean the same contact).
Spectrum powerLawSpectrum(double first, double last, double gradient)
{
    const double L = 1e-3;
    const Spectrum unit = Spectrum::powerLaw(1.0, 1.3, first / L, last / L, L);
    const double g = PerssonModel(unit, Ep).rmsGradient();
    return Spectrum::powerLaw(gradient / g, 1.3, first / L, last / L, L);
}

// J(s) of Persson.hpp (P6) by brute force: composite Simpson in y = ln x from s to s + 9
// (exp(-x^2) is below 1e-35 of its value at s there), 200000 intervals.
double bruteKernel(double s, double gamma)
{
    const int n = 200000;
    const double a = std::log(s);
    const double b = std::log(s + 9.0);
    const double h = (b - a) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double x = std::exp(a + h * i);
        const double e = std::erf(x);
        const double f = (gamma + 3.0 * (1.0 - gamma) * e * e) * std::exp(-(x * x - s * s)); // x dx/x = dy
        sum += f * (i == 0 || i == n ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    return sum * h / 3.0; // exp(s^2) J(s)
}
} // namespace

TEST(PerssonKernel, MatchesTheExponentialIntegral)
{
    // gamma = 1: J(s) = E1(s^2)/2 exactly; std::expint(-z) = -E1(z). Relative 1e-13: the series
    // and the continued fraction both stop at 1e-16 to 1e-18 per term.
    for (double s : {1e-12, 1e-6, 1e-3, 0.3, 0.999, 1.0, 1.001, 2.0, 5.9, 6.1}) {
        const double z = s * s;
        const double exact = -0.5 * std::exp(z) * std::expint(-z);
        EXPECT_NEAR(persson::scaledSeparationKernel(s, 1.0), exact, 1e-13 * exact) << s;
        EXPECT_NEAR(persson::scaledExponentialIntegral(z), 2.0 * exact, 2e-13 * exact) << s;
    }
    // Large z (libstdc++'s expint is not accurate there): the asymptotic series
    // sum (-1)^k k!/z^(k+1), 10 terms, truncation 10!/z^11 < 1e-19 relative at z = 400.
    for (double z : {400.0, 1e4, 1e12}) {
        double sum = 0.0;
        double term = 1.0 / z;
        for (int k = 0; k < 10; ++k) {
            sum += term;
            term *= -double(k + 1) / z;
        }
        EXPECT_NEAR(persson::scaledExponentialIntegral(z), sum, 1e-14 * sum) << z;
    }
}

TEST(PerssonKernel, MatchesBruteForceForEveryGamma)
{
    // Relative 1e-9: Simpson's error with 200000 intervals over at most 30 units of ln x is
    // below 1e-12; the kernel's own rules are good to about 1e-14.
    for (double gamma : {0.42, 0.1, 0.9}) {
        for (double s : {1e-4, 0.1, 0.5, 0.9999, 1.0, 1.5, 3.0, 5.5, 6.5}) {
            const double ref = bruteKernel(s, gamma);
            EXPECT_NEAR(persson::scaledSeparationKernel(s, gamma), ref, 1e-9 * ref) << gamma << " " << s;
        }
    }
    EXPECT_THROW(persson::scaledSeparationKernel(0.0, 0.42), ParameterError);
}

TEST(PerssonModel, SpectrumConversionKeepsHeightAndGradient)
{
    // 1000 levels. (P1) makes 2 pi int q C dq the variance of the isotropic surface and
    // 2 pi int q^3 C dq its mean square gradient.
    const Spectrum s = powerLawSpectrum(1, 1000, 0.1);
    const IsotropicSpectrum iso(s);
    const PerssonModel m(s, Ep);
    const double variance = iso.powerOutside(0.0);
    // The model's Gauss-Legendre quadrature of C2 against the closed form (3) of
    // ArealSynthesis.hpp: relative 1e-9 (12 points per bin on the smooth mapped integrand;
    // measured 1e-15).
    EXPECT_NEAR(m.rmsHeight() * m.rmsHeight(), variance, 1e-9 * variance);
    // Not the line scan's own variance: the IsotropicSpectrum's C2 is its Abel inversion on the
    // band only (the inversion of a C1 that is 0 below the band would be negative there), and
    // the band's C2 alone holds more power than the line scans: 32 % more for this spectrum
    // (levels from 1/L, band from 0.5/L). The synthesized surfaces carry the same C2.
    std::printf("variance: 2-D band %.10g, line scan %.10g\n", variance, s.variance());
    // The gradient independently of C2: int over the band of (2 pi f)^2 C2 d^2f
    // = 4 pi^2 int f^2 (-dT/df) df = 4 pi^2 (f_low^2 T(f_low) + int 2 f T(f) df), T = powerOutside
    // in closed form, by Simpson per bin in v with f = b - (b - a) v^2 (T has (b - f)^(3/2)
    // kinks at the nodes and a square root at the top, both smooth in v), 64 intervals.
    std::vector<double> nodes{iso.lowestFrequency()};
    for (double f : s.frequencies()) {
        if (f > nodes.back() && f < iso.highestFrequency()) {
            nodes.push_back(f);
        }
    }
    nodes.push_back(iso.highestFrequency());
    double moment = nodes.front() * nodes.front() * iso.powerOutside(nodes.front());
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
        const double a = nodes[i];
        const double b = nodes[i + 1];
        const int k = 64;
        for (int j = 0; j <= k; ++j) {
            const double v = double(j) / k;
            const double f = b - (b - a) * v * v;
            const double g = 2.0 * f * iso.powerOutside(f) * 2.0 * (b - a) * v; // df = -2 (b-a) v dv
            moment += g * (1.0 / (3.0 * k)) * (j == 0 || j == k ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0));
        }
    }
    const double gradient2 = 4 * pi * pi * moment;
    // Relative 1e-8: Simpson's h^4 with 64 intervals per bin; the model's rule is exact to 1e-12.
    EXPECT_NEAR(m.rmsGradient() * m.rmsGradient(), gradient2, 1e-8 * gradient2);
    // Against the discrete levels, 2 sum (beta^2/2) (2 pi f)^2 (an isotropic gradient has two
    // components, each with the line scans' slope variance): the band's extra power (above) and
    // C1's linear interpolation between the levels; measured 0.78 % here, so 2 %.
    double discrete = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        discrete += 2.0 * 0.5 * s.amplitude(i) * s.amplitude(i) * 4 * pi * pi * s.frequency(i) * s.frequency(i);
    }
    std::printf("gradient^2: model %.10g, interpolated C1 %.10g, levels %.10g\n", m.rmsGradient() * m.rmsGradient(),
                gradient2, discrete);
    EXPECT_NEAR(m.rmsGradient() * m.rmsGradient(), discrete, 2e-2 * discrete);
    // Twice the points per bin changes nothing beyond the quadrature tolerance (1e-6; measured
    // 2.2e-7 in h_c at load 1e-7, where J's logarithm near q0 is hardest, 1e-9 and below else).
    const PerssonModel fine(s, Ep, PerssonOptions{0.42, 24, 1e9});
    EXPECT_NEAR(fine.rmsHeight(), m.rmsHeight(), 1e-12 * m.rmsHeight());
    for (double load : {1e-7, 1e-3, 0.1}) {
        EXPECT_NEAR(fine.meanSeparation(load), m.meanSeparation(load), 1e-6 * m.meanSeparation(load));
        EXPECT_NEAR(fine.conductancePerConductivity(load), m.conductancePerConductivity(load),
                    1e-6 * m.conductancePerConductivity(load));
    }
}

TEST(PerssonModel, LightLoadAreaAndCompleteContact)
{
    const Spectrum s = powerLawSpectrum(2, 200, 0.2);
    const PerssonModel m(s, Ep);
    const double h = m.rmsGradient();
    // (P3): A/A_n -> sqrt(8/pi) p/(E' h'); erf(x) = 2x/sqrt(pi) (1 - x^2/3 + ...), so at
    // load 1e-6 h' the relative error is below 1e-12: 1e-10.
    for (double load : {1e-9, 1e-7}) {
        const double expected = roughContactTest::closedForm::perssonLightLoadAreaFraction(load, h);
        EXPECT_NEAR(m.areaFraction(load), expected, 1e-10 * expected);
    }
    // Monotonic, below 1, and 1 to double precision at load 5 h' (1 - erf(sqrt(2) 5) ~ 1e-23).
    double previous = 0.0;
    for (double load = 1e-6; load < 3.0; load *= 1.5) { // to 15 h': u within double range
        const PerssonPoint p = m.evaluate(load);
        EXPECT_GE(p.areaFraction, previous);
        EXPECT_LE(p.areaFraction, 1.0);
        EXPECT_GT(p.meanSeparation, 0.0);
        EXPECT_GT(p.conductancePerConductivity, 0.0);
        previous = p.areaFraction;
    }
    EXPECT_EQ(m.areaFraction(5.0 * h), 1.0);
    EXPECT_EQ(m.areaFraction(0.0), 0.0);
    const PerssonPoint zero = m.evaluate(0.0);
    EXPECT_TRUE(std::isinf(zero.meanSeparation));
    EXPECT_EQ(zero.conductancePerConductivity, 0.0);
    // Near complete contact u falls like exp(-(sqrt(2) load/h')^2) and h_c/k_s rises like its
    // inverse; finite within double range (to load ~ 19 h'), +inf beyond and u = 0, no trap.
    // There h_c/k_s is still Barber's relation -load/(du/d ln p) (as in the test below), by a
    // central difference with step 1e-6 in ln p: d ln u/d ln p ~ -4 (load/h')^2 = -400, so the
    // truncation is (1e-6 x 400)^2/6 ~ 3e-8; 1e-6 relative. (Was: only "finite".)
    const PerssonPoint near = m.evaluate(10.0 * h);
    EXPECT_GT(near.meanSeparation, 0.0);
    {
        const double load = 10.0 * h;
        const double d = 1e-6;
        const double dudlnp =
            (m.meanSeparation(load * std::exp(d)) - m.meanSeparation(load * std::exp(-d))) / (2.0 * d);
        EXPECT_NEAR(near.conductancePerConductivity, -load / dudlnp, -1e-6 * load / dudlnp);
    }
    const PerssonPoint far = m.evaluate(1e4);
    EXPECT_EQ(far.areaFraction, 1.0);
    EXPECT_EQ(far.meanSeparation, 0.0);
    EXPECT_TRUE(std::isinf(far.conductancePerConductivity));
}

TEST(PerssonModel, SeparationFollowsTheExponentialLawAtLightLoad)
{
    // u = -u0 ln p + const (P7): the slope du/d ln p by central differences (step 0.01 in ln p;
    // u is linear in ln p up to O(s^2) there, so the difference is exact to ~1e-10) tends to
    // -u0. Relative 1e-4 at loads 1e-9, 1e-7 (the corrections are O((w p/E')^2) and the
    // quadrature's 1e-6 or so).
    const Spectrum s = powerLawSpectrum(2, 200, 0.2);
    const PerssonModel m(s, Ep);
    const double u0 = m.lightLoadDecayLength();
    for (double load : {1e-9, 1e-7}) {
        const double d = 0.01;
        const double slope =
            (m.meanSeparation(load * std::exp(d)) - m.meanSeparation(load * std::exp(-d))) / (2.0 * d);
        EXPECT_NEAR(slope, -u0, 1e-4 * u0) << load;
    }
    // Beyond light load the slope's magnitude falls below u0 (here 0.1 u0 at load 0.1 = h'): the
    // separation approaches 0 only asymptotically.
    const double load = 0.1;
    const double slope = (m.meanSeparation(load * 1.01) - m.meanSeparation(load / 1.01)) / (2.0 * std::log(1.01));
    std::printf("u0 = %.6g m, du/dlnp at load 0.1 = %.6g m, rms height %.6g m\n", u0, slope, m.rmsHeight());
    EXPECT_LT(slope, 0.0);
    EXPECT_LT(-slope, u0);
}

TEST(PerssonModel, ConductanceIsBarbersRelationOfTheSeparation)
{
    // h_c/k_s = -(1/E') dp/du = -load / (du/d ln p), with du/d ln p here by an independent central
    // difference of meanSeparation (step 1e-5 in ln p: truncation (1e-5 d ln|u'|/d ln p)^2/6,
    // below 1e-8 even at 3 h' where u falls like exp(-2 (load/h')^2); rounding
    // ~1e-16 u/(1e-5 |du/d ln p|) < 1e-9). Relative 1e-6.
    const Spectrum s = powerLawSpectrum(2, 200, 0.2);
    const PerssonModel m(s, Ep);
    const double h = m.rmsGradient();
    for (double load : {1e-8 * h, 1e-4 * h, 1e-2 * h, 0.1 * h, h, 3.0 * h}) {
        const double d = 1e-5;
        const double dudlnp =
            (m.meanSeparation(load * std::exp(d)) - m.meanSeparation(load * std::exp(-d))) / (2.0 * d);
        const double barber = -load / dudlnp;
        EXPECT_NEAR(m.conductancePerConductivity(load), barber, 1e-6 * barber) << load;
    }
}

TEST(PerssonModel, ScalesWithTheHeights)
{
    // Heights times lambda: C times lambda^2, w over lambda, so A(lambda p) = A(p),
    // u(lambda p) = lambda u(p) and h_c(lambda p) = h_c(p) (-(1/E') dp/du: p and u both scale),
    // exactly but for rounding (1e-12).
    const Spectrum a = powerLawSpectrum(1, 300, 0.05);
    const double lambda = 10.0;
    std::vector<double> beta = a.amplitudes();
    for (double& b : beta) {
        b *= lambda;
    }
    const Spectrum scaled(a.frequencies(), beta, a.length());
    const PerssonModel ma(a, Ep);
    const PerssonModel mb(scaled, Ep);
    EXPECT_NEAR(mb.rmsGradient(), lambda * ma.rmsGradient(), 1e-12 * mb.rmsGradient());
    for (double load : {1e-6, 1e-4, 1e-3, 1e-2}) {
        const PerssonPoint pa = ma.evaluate(load);
        const PerssonPoint pb = mb.evaluate(lambda * load);
        EXPECT_NEAR(pb.areaFraction, pa.areaFraction, 1e-12 * pa.areaFraction);
        EXPECT_NEAR(pb.meanSeparation, lambda * pa.meanSeparation, 1e-12 * pb.meanSeparation);
        EXPECT_NEAR(pb.conductancePerConductivity, pa.conductancePerConductivity,
                    1e-12 * pb.conductancePerConductivity);
    }
}

TEST(PerssonModel, RefusesBadInput)
{
    const Spectrum s = powerLawSpectrum(1, 50, 0.1);
    EXPECT_THROW(PerssonModel(s, Ep, PerssonOptions{0.0, 6}), ParameterError);
    EXPECT_THROW(PerssonModel(s, Ep, PerssonOptions{1.5, 6}), ParameterError);
    EXPECT_THROW(PerssonModel(s, Ep, PerssonOptions{0.42, 1}), ParameterError);
    EXPECT_THROW(PerssonModel(s, -1.0), ParameterError);
    const PerssonModel m(s, Ep);
    EXPECT_THROW(m.evaluate(-1.0), ParameterError);
    EXPECT_THROW(m.areaFraction(std::nan("")), ParameterError);
    const Spectrum flat({1e3, 2e3}, {0.0, 0.0}, 1e-3);
    EXPECT_THROW(PerssonModel(flat, Ep), ParameterError);
}

TEST(PerssonModel, AThousandLevelsKeepTheClosedForms)
{
    // 1000 levels through the factory (its speed is the benchmark's business, not a test's:
    // was a wall-clock assertion, < 5 s, and sum of separations > 0). The rms gradient is the
    // 0.1 the spectrum was scaled to (linear in the amplitudes: rounding, 1e-12); the light-load
    // area is (P3) sqrt(8/pi) p/(E' h') to 1e-10 (as in LightLoadAreaAndCompleteContact), and
    // the separation's slope in ln p is -u0 (P7) to 1e-4 (as in
    // SeparationFollowsTheExponentialLawAtLightLoad).
    const Spectrum s = powerLawSpectrum(1, 1000, 0.1);
    const auto model = makeContactModel("persson", s, ContactMaterials::fromReducedModulus(Ep, std::nullopt, std::nullopt));
    const auto* m = dynamic_cast<const PerssonModel*>(model.get());
    ASSERT_NE(m, nullptr);
    EXPECT_NEAR(m->rmsGradient(), 0.1, 1e-12);
    for (double load : {1e-9, 1e-7}) {
        const double expected =
            roughContactTest::closedForm::perssonLightLoadAreaFraction(load, m->rmsGradient());
        EXPECT_NEAR(m->areaFraction(load), expected, 1e-10 * expected) << load;
        const double d = 0.01;
        const double slope =
            (m->meanSeparation(load * std::exp(d)) - m->meanSeparation(load * std::exp(-d))) / (2.0 * d);
        EXPECT_NEAR(slope, -m->lightLoadDecayLength(), 1e-4 * m->lightLoadDecayLength()) << load;
    }
}

TEST(PerssonModel, AgainstTheBoundaryElementReference)
{
    // A power law (H = 0.8) at f = i/L, i = 2..16 (the long wavelengths below 2/L cut off, so that
    // one realization is not one wave), rms gradient 0.1, synthesized on 256 x 256 points: the
    // shortest wavelength L/16.5 spans 15.5 grid points. Persson gets the same line-scan spectrum
    // (both use the IsotropicSpectrum's C2 on the same band). BEM: periodic, the mean of 4 seeds.
    // Measured ratios Persson/BEM (gcc 13, x86-64) at loads 1e-4, 1e-3, 1e-2:
    //     area 0.593, 0.709, 0.764;  u 1.084, 1.033, 1.062;  h_c 0.646, 0.980, 0.938.
    // Persson's area (kappa = sqrt(8/pi) = 1.60) is below the BEM's by 24-41 %, more than the
    // 10-30 % usually quoted: this band is narrow (magnification 8; the exact kappa grows as the
    // band narrows) and at 1e-4 the BEM's contact is 176 cells in few spots (its area converges
    // from above on refinement: 128^2 gave 0.52 for the area ratio there). The separation agrees to
    // 3-8 %, the conductance to 2-6 % from 1e-3 on. Asserted: each ratio within 0.05 of the
    // measured one (a regression band: the solves are deterministic to ~1e-6; not a validation),
    // and the area below the BEM's at every load.
    const Spectrum s = powerLawSpectrum(2, 16, 0.1);
    const PerssonModel persson(s, Ep);
    const std::vector<double> loads{1e-4, 1e-3, 1e-2};
    std::vector<double> area(3, 0.0), gap(3, 0.0), hc(3, 0.0);
    const int seeds = 4;
    BoundaryElementOptions bo;
    bo.periodic = true;
    for (int seed = 1; seed <= seeds; ++seed) {
        const BoundaryElementModel bem(synthesizeIsotropic(s, 256, std::uint64_t(seed)), Ep, bo);
        const std::vector<BoundaryElementPoint> pts = bem.curve(loads);
        for (std::size_t i = 0; i < loads.size(); ++i) {
            area[i] += pts[i].areaFraction / seeds;
            gap[i] += pts[i].meanSeparation / seeds;
            hc[i] += pts[i].conductancePerConductivity / seeds;
        }
    }
    std::vector<double> ra, ru, rh;
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const PerssonPoint p = persson.evaluate(loads[i]);
        ra.push_back(p.areaFraction / area[i]);
        ru.push_back(p.meanSeparation / gap[i]);
        rh.push_back(p.conductancePerConductivity / hc[i]);
        std::printf("load %g: area persson %.4g bem %.4g (ratio %.3f); u persson %.4g bem %.4g m (ratio %.3f); "
                    "h/k persson %.4g bem %.4g 1/m (ratio %.3f)\n",
                    loads[i], p.areaFraction, area[i], ra.back(), p.meanSeparation, gap[i], ru.back(),
                    p.conductancePerConductivity, hc[i], rh.back());
    }
    const double measuredArea[] = {0.593, 0.709, 0.764};
    const double measuredGap[] = {1.084, 1.033, 1.062};
    const double measuredConductance[] = {0.646, 0.980, 0.938};
    for (std::size_t i = 0; i < loads.size(); ++i) {
        EXPECT_NEAR(ra[i], measuredArea[i], 0.05) << loads[i];
        EXPECT_NEAR(ru[i], measuredGap[i], 0.05) << loads[i];
        EXPECT_NEAR(rh[i], measuredConductance[i], 0.05) << loads[i];
        EXPECT_LT(ra[i], 1.0);
    }
}

TEST(PerssonModel, GroupedBinsOfALongSpectrum)
{
    // 3000 levels: with a work budget of 1e7 the 3000 bins are grouped into 277 log-spaced panels;
    // against every bin resolved (budget 1e9). Measured relative differences: printed; asserted
    // within 1e-4 (the unresolved kinks of C2 inside a panel).
    const Spectrum s = powerLawSpectrum(1, 3000, 0.1);
    const PerssonModel grouped(s, Ep, PerssonOptions{0.42, 12, 1e7});
    const PerssonModel full(s, Ep, PerssonOptions{0.42, 12, 1e9});
    double worst = std::abs(grouped.rmsGradient() / full.rmsGradient() - 1.0);
    worst = std::max(worst, std::abs(grouped.rmsHeight() / full.rmsHeight() - 1.0));
    for (double load : {1e-8, 1e-4, 1e-2, 0.1}) {
        const PerssonPoint g = grouped.evaluate(load);
        const PerssonPoint f = full.evaluate(load);
        worst = std::max(worst, std::abs(g.meanSeparation / f.meanSeparation - 1.0));
        worst = std::max(worst, std::abs(g.conductancePerConductivity / f.conductancePerConductivity - 1.0));
        worst = std::max(worst, std::abs(g.areaFraction / f.areaFraction - 1.0));
    }
    std::printf("grouped panels against all bins: worst relative difference %.3g\n", worst);
    EXPECT_LT(worst, 1e-4);
    EXPECT_THROW(PerssonModel(s, Ep, PerssonOptions{0.42, 12, 1.0}), ParameterError);
}
