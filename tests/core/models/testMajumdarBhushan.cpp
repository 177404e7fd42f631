// SPDX-License-Identifier: GPL-3.0-or-later
// Majumdar-Bhushan fractal contact (Majumdar & Bhushan, ASME J. Tribol. 113 (1991) 1-11;
// docs/theory.md §4.4): closed forms against numerical integration of the spot distribution.
#include "roughContact/Error.hpp"
#include "roughContact/models/MajumdarBhushan.hpp"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double Ep = 200e9; // seed Table 1
constexpr double Sy = 0.2e9;
constexpr double G0 = 2.86e-10;
constexpr double An = 1e-6;
constexpr double H = 2.84 * Sy; // seed §3.1

// MB's geometry of a spot of (truncated) area a: interference delta = G^(D-1) a^((2-D)/2),
// tip radius R = a^(D/2) / (pi^2 G^(D-1)) (MB 1991). Hertz from the contact area a = pi r^2:
// F = (4/3) E' r^3 / R. Together: (4 sqrt(pi)/3) E' G^(D-1) a^((3-D)/2), the form docs/theory.md
// §4.4 quotes; here it is assembled from the geometry so that the coefficient is checked too.
double tipRadius(double D, double G, double a)
{
    return std::pow(a, D / 2.0) / (pi * pi * std::pow(G, D - 1.0));
}
double interference(double D, double G, double a)
{
    return std::pow(G, D - 1.0) * std::pow(a, (2.0 - D) / 2.0);
}
double elasticSpotForce(double D, double G, double a)
{
    const double r = std::sqrt(a / pi);
    return 4.0 / 3.0 * Ep * r * r * r / tipRadius(D, G, a);
}
// Spot distribution n(a) = (D/2) a_L^(D/2) a^(-(D/2+1)).
double spots(double D, double aL, double a)
{
    return D / 2.0 * std::pow(aL, D / 2.0) * std::pow(a, -(D / 2.0 + 1.0));
}

double integrate(const std::function<double(double)>& f, double a, double b)
{
    boost::math::quadrature::tanh_sinh<double> ts;
    return ts.integrate(f, a, b, 1e-13);
}

// int_0^amax a n(a) da over u = ln(amax / a) in [0, inf) (da = a du) by exp-sinh: the
// a^(-D/2) singularity at a = 0 becomes the slowly decaying exp(-(1 - D/2) u). n(a) a^2 is
// evaluated in logarithms, exp(ln n(a) + 2 ln a), since a = amax e^-u underflows long before
// the integrand is negligible for D near 2.
double firstMomentFromZero(double D, double aL, double amax)
{
    boost::math::quadrature::exp_sinh<double> es;
    return es.integrate(
        [&](double u) {
            const double lnA = std::log(amax) - u;
            const double lnN = std::log(D / 2.0) + D / 2.0 * std::log(aL) - (D / 2.0 + 1.0) * lnA;
            return std::exp(lnN + 2.0 * lnA);
        },
        1e-13);
}

// A_r = int_0^aL a n(a) da.
double realAreaByQuadrature(double D, double aL)
{
    return firstMomentFromZero(D, aL, aL);
}

// F = int_0^min(aL, ac) H a n(a) da + int_ac^aL f_e(a) n(a) da. The elastic part is
// integrated over ln a (a range of many decades) by tanh-sinh, one decade at a time.
double loadByQuadrature(double D, double G, double ac, double aL)
{
    double F = H * firstMomentFromZero(D, aL, std::min(aL, ac));
    if (aL > ac) {
        const double u0 = std::log(ac);
        const double u1 = std::log(aL);
        const int n = std::max(1, static_cast<int>(std::ceil((u1 - u0) / std::log(10.0))));
        for (int j = 0; j < n; ++j) {
            F += integrate(
                [&](double u) {
                    const double a = std::exp(u);
                    return elasticSpotForce(D, G, a) * spots(D, aL, a) * a;
                },
                u0 + (u1 - u0) * j / n, u0 + (u1 - u0) * (j + 1) / n);
        }
    }
    return F;
}

// The plastic limit delta_c = (pi K phi / 2)^2 R (MB 1991; K = H/S_y, phi = S_y/E'): a_c is
// where delta(a) = delta_c(a), found here by bisection in ln a on the geometry above.
double criticalAreaByBisection(double D, double G)
{
    const double K = H / Sy;
    const double phiY = Sy / Ep;
    const auto g = [&](double u) {
        const double a = std::exp(u);
        return std::log(interference(D, G, a)) -
               std::log(std::pow(pi * K * phiY / 2.0, 2) * tipRadius(D, G, a));
    };
    double lo = -300.0, hi = 300.0; // g decreases: delta/R ~ a^(1-D)
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) > 0 ? lo : hi) = mid;
    }
    return std::exp(0.5 * (lo + hi));
}

MajumdarBhushan model(double D, double G = G0)
{
    return MajumdarBhushan({D, G}, An, Ep, Sy);
}

const std::vector<double> dimensions{1.1, 1.3, 1.45, 1.5, 1.5 + 1e-9, 1.597, 1.75, 1.9};
} // namespace

TEST(MajumdarBhushan, criticalAreaIsWhereSpotsTurnPlastic)
{
    for (double D : dimensions) {
        const double ac = criticalAreaByBisection(D, G0);
        // 200 bisections of a 600-wide interval in ln a reach double precision; ln a_c ~ -30
        // to +100, so the error is ~1e-14 x |ln a_c| x (ln a_c's condition, 1/(D-1) <= 10).
        EXPECT_NEAR(model(D).criticalArea() / ac, 1.0, 1e-11) << "D=" << D;
    }
}

TEST(MajumdarBhushan, realAreaMatchesQuadratureOfTheSpotDistribution)
{
    for (double D : dimensions) {
        const MajumdarBhushan mb = model(D);
        for (double aL : {1e-14, 1e-12, 3e-10}) {
            // exp-sinh at 1e-13 on exp(-(1 - D/2) u), decaying slowly for D near 2: ~1e-12;
            // 1e-10 leaves room for its error estimate being optimistic.
            EXPECT_NEAR(mb.realArea(aL) / realAreaByQuadrature(D, aL), 1.0, 1e-10)
                << "D=" << D << " aL=" << aL;
        }
        EXPECT_EQ(mb.realArea(0.0), 0.0);
    }
}

TEST(MajumdarBhushan, loadMatchesQuadratureBelowAndAboveCriticalArea)
{
    for (double D : dimensions) {
        for (double G : {G0, 1e-11}) {
            const MajumdarBhushan mb = model(D, G);
            const double ac = criticalAreaByBisection(D, G);
            for (double ratio : {1e-3, 0.5, 0.999, 1.001, 2.0, 1e2, 1e6}) {
                const double aL = ratio * ac;
                // Quadrature as in realAreaMatchesQuadratureOfTheSpotDistribution; a_c from
                // the bisection (1e-11) enters the load through a_c^((2-D)/2) and the elastic
                // range: the same order.
                EXPECT_NEAR(mb.load(aL) / loadByQuadrature(D, G, ac, aL), 1.0, 1e-10)
                    << "D=" << D << " G=" << G << " aL/ac=" << ratio;
            }
        }
    }
}

TEST(MajumdarBhushan, loadIsContinuousAcrossDOneAndAHalf)
{
    // D = 1.5 takes the logarithmic closed form, D = 1.5 +- 1e-7 the power form. Moving D by
    // 1e-7 moves ln a_c by 1e-7 x 2 |ln(K phi/2)|/(D-1)^2 ~ 6e-6 and the load by about as
    // much, times ln(a_L/a_c) <= 20 here: 1e-3 separates that from a wrong branch (the
    // closed forms' coefficients differ by O(1)).
    const double ac = model(1.5).criticalArea();
    for (double ratio : {2.0, 1e3, 1e8}) {
        const double aL = ratio * ac;
        const double mid = model(1.5).load(aL);
        EXPECT_NEAR(model(1.5 - 1e-7).load(aL) / mid, 1.0, 1e-3) << ratio;
        EXPECT_NEAR(model(1.5 + 1e-7).load(aL) / mid, 1.0, 1e-3) << ratio;
    }
}

TEST(MajumdarBhushan, largestSpotInvertsLoad)
{
    for (double D : dimensions) {
        const MajumdarBhushan mb = model(D);
        for (double ratio : {1e-2, 0.9, 1.0, 1.5, 1e3, 1e7}) {
            const double aL = ratio * mb.criticalArea();
            // toms748 to 2^-52 in ln a_L; the load's slope d ln F / d ln a_L lies in [D/2, 1].
            EXPECT_NEAR(mb.largestSpot(mb.load(aL)) / aL, 1.0, 1e-12) << "D=" << D << " r=" << ratio;
        }
    }
}

TEST(MajumdarBhushan, areaFractionSolvesTheLoadIndependently)
{
    // Bisection in ln a_L on the quadrature load; then A_r/A_n from the quadrature area.
    for (double D : {1.3, 1.5, 1.597, 1.8}) {
        const MajumdarBhushan mb = model(D);
        const double ac = criticalAreaByBisection(D, G0);
        for (double loadRatio : {1e-9, 1e-7, 1e-5, 1e-4}) {
            const double F = loadRatio * An * Ep;
            double lo = std::log(ac) - 60.0, hi = std::log(ac) + 60.0;
            for (int i = 0; i < 80; ++i) {
                const double mid = 0.5 * (lo + hi);
                (loadByQuadrature(D, G0, ac, std::exp(mid)) < F ? lo : hi) = mid;
            }
            const double aL = std::exp(0.5 * (lo + hi));
            const double expected = std::min(1.0, realAreaByQuadrature(D, aL) / An);
            // 80 bisections of 120 leave 1e-22 in ln a_L; the quadratures' 1e-10.
            EXPECT_NEAR(mb.areaFraction(loadRatio) / expected, 1.0, 1e-9)
                << "D=" << D << " load=" << loadRatio;
        }
    }
}

TEST(MajumdarBhushan, plasticRegimeIsHardnessTimesArea)
{
    // a_L <= a_c: every spot plastic, F = H A_r, so A_r/A_n = (F/(A_n E')) E'/H.
    const MajumdarBhushan mb = model(1.597);
    const double Fc = H * mb.realArea(mb.criticalArea());
    const double load = 0.5 * Fc / (An * Ep);
    EXPECT_NEAR(mb.areaFraction(load) / (load * Ep / H), 1.0, 1e-14); // round-off only
    EXPECT_NEAR(mb.hardness() / H, 1.0, 1e-15);
}

TEST(MajumdarBhushan, areaFractionIsMonotoneAndBounded)
{
    for (double D : dimensions) {
        const MajumdarBhushan mb = model(D);
        EXPECT_EQ(mb.areaFraction(0.0), 0.0);
        double previous = 0.0;
        for (double e = -16.0; e <= 1.0; e += 0.25) {
            const double a = mb.areaFraction(std::pow(10.0, e));
            EXPECT_GE(a, previous) << "D=" << D << " load=1e" << e;
            EXPECT_GT(a, 0.0);
            EXPECT_LE(a, 1.0);
            previous = a;
        }
        EXPECT_EQ(previous, 1.0) << "D=" << D;
    }
}

TEST(MajumdarBhushan, rejectsBadInput)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double D : {1.0, 2.0, 0.5, nan}) {
        EXPECT_THROW(MajumdarBhushan({D, G0}, An, Ep, Sy), ParameterError) << D;
    }
    EXPECT_THROW(MajumdarBhushan({1.5, 0.0}, An, Ep, Sy), ParameterError);
    EXPECT_THROW(MajumdarBhushan({1.5, G0}, 0.0, Ep, Sy), ParameterError);
    EXPECT_THROW(MajumdarBhushan({1.5, G0}, An, -Ep, Sy), ParameterError);
    EXPECT_THROW(MajumdarBhushan({1.5, G0}, An, Ep, 0.0), ParameterError);
    const MajumdarBhushan mb = model(1.5);
    for (double bad : {-1e-6, nan, inf}) {
        EXPECT_THROW(mb.areaFraction(bad), ParameterError) << bad;
    }
    EXPECT_THROW(mb.largestSpot(0.0), ParameterError);
    EXPECT_THROW(mb.realArea(-1.0), ParameterError);
}
