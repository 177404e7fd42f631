// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/asperity/JacksonGreen.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughContact {

namespace {
const double logElasticLimit = std::log(JacksonGreen::elasticLimit);
// Density of the inversion's bracketing table (denser tables did not cut the evaluations per
// inversion: measured at 1000 a decade).
constexpr double pointsPerDecade = 200.0;
const double logCubicStart = std::log(JacksonGreen::cubicStart);

// H_G / S_y of seed Eq. 19 and its slope in x = a/R.
double eq19(double x)
{
    return 2.84 * (1.0 - std::exp(-0.82 * std::pow(x, -0.7)));
}
double eq19Slope(double x)
{
    return -2.84 * std::exp(-0.82 * std::pow(x, -0.7)) * 0.82 * 0.7 * std::pow(x, -1.7);
}
} // namespace

JacksonGreen::JacksonGreen(double Eprime, double nu, double E, double Sy) : onset_(Eprime, nu, Sy), Sy_(Sy)
{
    requirePositive("Young's modulus E", E);
    B_ = 0.14 * std::exp(23.0 * Sy / E);  // seed Eqs. 17-18
    floorCoefficient_ = 1.5 / onset_.C(); // A_c S_y / F_c
    fourOverC_ = 4.0 / onset_.C();
    logKappa_ = std::log(onset_.interferenceRatio());

    // The cubic of seed §2.2: value and slope of Eq. 19 at x0 = 0.41, value 1 and slope 0 at 1.
    const double x0 = cubicStart;
    Eigen::Matrix4d M;
    M << 1.0, x0, x0 * x0, x0 * x0 * x0,   //
        0.0, 1.0, 2.0 * x0, 3.0 * x0 * x0, //
        1.0, 1.0, 1.0, 1.0,                //
        0.0, 1.0, 2.0, 3.0;
    const Eigen::Vector4d rhs(eq19(x0), eq19Slope(x0), 1.0, 0.0);
    const Eigen::Vector4d c = M.fullPivLu().solve(rhs);
    cubic_ = {c[0], c[1], c[2], c[3]};

    // Complete contact where a/R = 1, i.e. A/A_c = 1 / kappa (A_c = pi R w_c, a^2 = A/pi).
    const double kappa = onset_.interferenceRatio();
    if (elasticLimit * kappa >= 1.0) {
        wStarComplete_ = 1.0 / kappa; // reached while still Hertzian
    } else {
        wStarComplete_ = std::exp((-std::log(kappa) + B_ * std::log(elasticLimit)) / (1.0 + B_));
    }

    // Bracketing table of the loading path above w* = 1.9.
    if (wStarComplete_ > elasticLimit) {
        const double decades = std::log10(wStarComplete_ / elasticLimit);
        const auto n = static_cast<std::size_t>(std::ceil(pointsPerDecade * decades)) + 1;
        tableW_.resize(n + 1);
        tableF_.resize(n + 1);
        tableRaw_.resize(n + 1);
        tableLogW_.resize(n + 1);
        tableLogRaw_.resize(n + 1);
        for (std::size_t j = 0; j <= n; ++j) {
            const double w =
                j == n ? wStarComplete_ : elasticLimit * std::pow(10.0, decades * double(j) / double(n));
            tableW_[j] = w;
            tableF_[j] = forceRatioRaw(w);
            tableRaw_[j] = tableF_[j];
            tableLogW_[j] = std::log(w);
            tableLogRaw_[j] = std::log(tableRaw_[j]);
            if (j > 0) {
                tableF_[j] = std::max(tableF_[j], tableF_[j - 1]);
            }
        }
    }
}

double JacksonGreen::hardnessRatio(double x) const
{
    if (x <= cubicStart) {
        return eq19(x);
    }
    if (x >= 1.0) {
        return 1.0;
    }
    return cubic_[0] + x * (cubic_[1] + x * (cubic_[2] + x * cubic_[3]));
}

double JacksonGreen::areaRatio(double wStar) const
{
    const double w = std::min(wStar, wStarComplete_);
    if (w < elasticLimit) {
        return w;
    }
    return w * std::pow(w / elasticLimit, B_); // seed Eq. 15 over A_c = pi R w_c
}

double JacksonGreen::forceRatioEq16(double w) const
{
    const double aOverR = std::sqrt(onset_.interferenceRatio() * areaRatio(w));
    const double HG = hardnessRatio(aOverR); // H_G / S_y
    return std::exp(-0.25 * std::pow(w, 5.0 / 12.0)) * std::pow(w, 1.5) +
           4.0 * HG / onset_.C() * (1.0 - std::exp(-std::pow(w, 5.0 / 9.0) / 25.0)) * w;
}

double JacksonGreen::forceRatioRaw(double w) const
{
    if (w < elasticLimit) {
        return w * std::sqrt(w);
    }
    // max(Eq. 16, floor F >= A S_y), with every power of w taken from one logarithm: the same
    // numbers as forceRatioEq16 and areaRatio (to round-off, testJacksonGreen checks), at half
    // the cost; this is the inner loop of every jacksonGreen load curve.
    const double lw = std::log(w);
    const double logArea = lw + B_ * (lw - logElasticLimit); // areaRatio (Eq. 15)
    const double area = std::exp(logArea);
    const double logAOverR = 0.5 * (logKappa_ + logArea);
    const double HG = logAOverR <= logCubicStart ? 2.84 * (1.0 - std::exp(-0.82 * std::exp(-0.7 * logAOverR)))
                                                 : hardnessRatio(std::exp(logAOverR));
    const double eq16 = std::exp(-0.25 * std::exp(lw * (5.0 / 12.0))) * w * std::sqrt(w) +
                        fourOverC_ * HG * (1.0 - std::exp(-std::exp(lw * (5.0 / 9.0)) / 25.0)) * w;
    return std::max(eq16, floorCoefficient_ * area);
}

double JacksonGreen::forceRatio(double wStar) const
{
    return forceRatioRaw(std::min(wStar, wStarComplete_));
}

double JacksonGreen::area(double w, double R) const
{
    return onset_.area(R) * areaRatio(w / onset_.interference(R));
}

double JacksonGreen::force(double w, double R) const
{
    return onset_.force(R) * forceRatio(w / onset_.interference(R));
}

double JacksonGreen::interferenceRatioAtForce(double q) const
{
    const double hertzTop = elasticLimit * std::sqrt(elasticLimit);
    if (q <= hertzTop || tableW_.empty()) {
        const double c = std::cbrt(q); // q^(2/3); q * q would underflow for a large asperity
        return std::min(c * c, wStarComplete_);
    }
    if (q <= tableF_.front()) {
        return elasticLimit; // inside the force jump at 1.9 w_c
    }
    if (q > tableF_.back()) {
        return std::numeric_limits<double>::infinity(); // beyond complete contact
    }
    const auto it = std::lower_bound(tableF_.begin(), tableF_.end(), q);
    const std::size_t j = static_cast<std::size_t>(it - tableF_.begin()); // tableF_[j-1] < q <= tableF_[j]
    double lo = tableW_[j - 1];
    double hi = tableW_[j];
    // The running maximum can sit above the raw law where it dips; the loading path then holds.
    if (tableRaw_[j] < q) {
        return hi;
    }
    double flo = tableRaw_[j - 1] - q;
    if (flo >= 0.0) {
        return lo;
    }
    double fhi = tableRaw_[j] - q;
    // Illinois (regula falsi with halving): the table is dense (pointsPerDecade), so the first
    // secant through the bracket is already close and one or two more steps reach a residual
    // of 1e-13 q; the bracket keeps it safe across the law's kinks (the F >= A S_y floor, the
    // cubic's start). toms748 on the same bracket stops on the bracket's width, which costs
    // about twice the evaluations; this is the inner loop of every jacksonGreen load curve.
    // First point: linear interpolation of ln w against ln F between the nodes (the law is
    // nearly a power law, so this is within ~1e-7), then Illinois from the bracket.
    const double t = (std::log(q) - tableLogRaw_[j - 1]) / (tableLogRaw_[j] - tableLogRaw_[j - 1]);
    double c = std::exp(tableLogW_[j - 1] + t * (tableLogW_[j] - tableLogW_[j - 1]));
    int side = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
        if (iteration > 0) {
            c = (lo * fhi - hi * flo) / (fhi - flo);
        }
        const double fc = forceRatioRaw(c) - q;
        if (std::abs(fc) <= 1e-13 * q || hi - lo <= 1e-15 * hi) {
            return c;
        }
        if (fc > 0.0) {
            hi = c;
            fhi = fc;
            if (side == -1) {
                flo *= 0.5;
            }
            side = -1;
        } else {
            lo = c;
            flo = fc;
            if (side == +1) {
                fhi *= 0.5;
            }
            side = +1;
        }
    }
    return 0.5 * (lo + hi);
}

double JacksonGreen::areaAtForce(double F, double R) const
{
    const double w = interferenceRatioAtForce(F / onset_.force(R));
    if (!(w < wStarComplete_)) {
        return std::numeric_limits<double>::infinity();
    }
    return onset_.area(R) * areaRatio(w);
}

double JacksonGreen::forceBeyondArea(double A, double R) const
{
    const double t = A / onset_.area(R); // A / A_c
    double q = 0.0;                      // F / F_c
    if (tableW_.empty()) {
        // Complete contact while Hertzian: area A_c w* up to w*_complete, then +inf.
        const double w = std::min(t, wStarComplete_);
        q = w * std::sqrt(w);
    } else if (t <= elasticLimit) {
        q = t * std::sqrt(t); // Hertz: A/A_c = w* = q^(2/3)
    } else if (t >= areaRatio(wStarComplete_)) {
        q = tableF_.back(); // reached only at complete contact: areaAtForce is +inf beyond
    } else {
        // w* of the area (seed Eq. 15 inverted); interferenceRatioAtForce(q) brackets any
        // q > tableF_[j] in [tableW_[j'], tableW_[j' + 1]] with j' >= j, so w* >= tableW_[j].
        const double w = (1.0 + 1e-12) * std::exp((std::log(t) + B_ * logElasticLimit) / (1.0 + B_));
        const auto j = static_cast<std::size_t>(std::lower_bound(tableW_.begin(), tableW_.end(), w) -
                                                tableW_.begin());
        q = std::max(j < tableF_.size() ? tableF_[j] : tableF_.back(), elasticLimit * std::sqrt(elasticLimit));
    }
    return (1.0 + 1e-12) * onset_.force(R) * q;
}

} // namespace roughContact
