// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/Persson.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace roughContact {

namespace {

constexpr double sqrtPi = 1.77245385090551602730;
constexpr double eulerGamma = 0.57721566490153286061;
constexpr double e1AtOne = 0.21938393439552027368; // E1(1)
// exp(-x) underflows below exp(-745): terms further down than this are exactly 0.
constexpr double negligibleExponent = 745.0;

// Gauss-Legendre rule of n points on [0, 1], nodes increasing (Newton on P_n from the usual
// first guesses).
struct Rule {
    std::vector<double> t;
    std::vector<double> w;
};

Rule gaussLegendre(std::size_t n)
{
    Rule r{std::vector<double>(n), std::vector<double>(n)};
    // P_n(x) and P_n'(x) by the three-term recurrence.
    const auto legendre = [n](double x) {
        double p0 = 1.0;
        double p1 = x;
        for (std::size_t k = 2; k <= n; ++k) {
            const double p2 = ((2.0 * double(k) - 1.0) * x * p1 - (double(k) - 1.0) * p0) / double(k);
            p0 = p1;
            p1 = p2;
        }
        return std::pair<double, double>{p1, double(n) * (x * p1 - p0) / (x * x - 1.0)};
    };
    for (std::size_t i = 0; i < n; ++i) {
        double x = std::cos(pi * (double(i) + 0.75) / (double(n) + 0.5));
        for (int it = 0; it < 100; ++it) {
            const auto [p, dp] = legendre(x);
            const double dx = p / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) {
                break;
            }
        }
        // The derivative at the converged root.
        const double dp = legendre(x).second;
        r.t[n - 1 - i] = 0.5 * (1.0 + x);
        r.w[n - 1 - i] = 1.0 / ((1.0 - x * x) * dp * dp); // 2/((1-x^2) P'^2), halved for [0, 1]
    }
    return r;
}

// S[i][k] = integral from 0 to t_i of the k-th Lagrange polynomial of the rule's nodes: the
// running integral of the interpolating polynomial (exact: degree n-1 with n points).
std::vector<std::vector<double>> runningIntegral(const Rule& r)
{
    const std::size_t n = r.t.size();
    std::vector<std::vector<double>> S(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t m = 0; m < n; ++m) {
            const double tau = r.t[i] * r.t[m];
            for (std::size_t k = 0; k < n; ++k) {
                double l = 1.0;
                for (std::size_t j = 0; j < n; ++j) {
                    if (j != k) {
                        l *= (tau - r.t[j]) / (r.t[k] - r.t[j]);
                    }
                }
                S[i][k] += r.t[i] * r.w[m] * l;
            }
        }
    }
    return S;
}

// E1(z) = -gamma_E - ln z - sum_k (-z)^k / (k k!), for 0 < z <= 1 (logZ = ln z, passed so that
// a tiny z never goes through log of an underflow).
double e1Series(double z, double logZ)
{
    double sum = 0.0;
    double term = 1.0;
    for (int k = 1; k < 60; ++k) {
        term *= -z / double(k);
        const double add = term / double(k);
        sum += add;
        if (std::abs(add) < 1e-18) {
            break;
        }
    }
    return -eulerGamma - logZ - sum;
}

// R(s) = int_0^inf [1 - erf^2(sqrt(s^2 + t))] exp(-t) / (s^2 + t) dt for s >= 1: graded
// Gauss-Legendre panels (12 points) on [0, 24]; the integrand falls like exp(-s^2 - 2t), so the
// rest beyond t = 24 is below exp(-48) of the first panel's.
double erfCorrection(double s)
{
    static const Rule rule = gaussLegendre(12);
    static const std::array<double, 8> edges{0.0, 0.25, 0.75, 1.75, 3.75, 7.75, 15.75, 24.0};
    const double z = s * s;
    double sum = 0.0;
    for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
        const double a = edges[p];
        const double h = edges[p + 1] - a;
        for (std::size_t i = 0; i < rule.t.size(); ++i) {
            const double t = a + h * rule.t[i];
            const double x = std::sqrt(z + t);
            const double oneMinusErf2 = std::erfc(x) * (1.0 + std::erf(x));
            sum += h * rule.w[i] * oneMinusErf2 * std::exp(-t) / (z + t);
        }
    }
    return sum;
}

} // namespace

namespace persson {

double scaledExponentialIntegral(double z)
{
    if (!(z > 0.0) || !std::isfinite(z)) {
        throw ParameterError("z", "exp(z) E1(z) needs a finite z > 0");
    }
    if (z < 1.0) {
        return std::exp(z) * e1Series(z, std::log(z));
    }
    // The continued fraction exp(z) E1(z) = 1/(z + 1 - 1/(z + 3 - 4/(z + 5 - ...))), modified
    // Lentz; it converges quickly for z >= 1.
    constexpr double tiny = 1e-300;
    double b = z + 1.0;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -double(i) * double(i);
        b += 2.0;
        d = 1.0 / (an * d + b);
        c = b + an / c;
        const double del = c * d;
        h *= del;
        if (std::abs(del - 1.0) < 1e-16) {
            break;
        }
    }
    return h;
}

double scaledSeparationKernel(double s, double gamma)
{
    if (!(s > 0.0) || !std::isfinite(s)) {
        throw ParameterError("s", "the separation kernel needs a finite s > 0");
    }
    if (s >= 1.0) {
        // J = ((3 - 2 gamma)/2) E1(s^2) - (3 (1-gamma)/2) exp(-s^2) R(s): erf^2 = 1 - (1 - erf^2)
        // and x^2 = s^2 + t in the erf part; R < 1e-16 exp(s^2) E1(s^2) from s = 6 on.
        const double z = s * s;
        const double main = 0.5 * (3.0 - 2.0 * gamma) * scaledExponentialIntegral(z);
        return s < 6.0 ? main - 1.5 * (1.0 - gamma) * erfCorrection(s) : main;
    }
    // s < 1: J(s) = J(1) + int_s^1: the gamma part in closed form, (E1(s^2) - E1(1))/2, and the
    // erf^2 part by 16-point Gauss-Legendre on [s, 1] (erf^2(x) exp(-x^2)/x is entire: erf is odd).
    static const Rule rule = gaussLegendre(16);
    static const double r1 = erfCorrection(1.0);
    const double jAtOne = 0.5 * (3.0 - 2.0 * gamma) * e1AtOne - 1.5 * (1.0 - gamma) * std::exp(-1.0) * r1;
    const double z = s * s;
    const double gammaPart = 0.5 * (e1Series(z, 2.0 * std::log(s)) - e1AtOne);
    double erfPart = 0.0;
    const double h = 1.0 - s;
    for (std::size_t i = 0; i < rule.t.size(); ++i) {
        const double x = s + h * rule.t[i];
        const double e = std::erf(x);
        erfPart += h * rule.w[i] * e * e * std::exp(-x * x) / x;
    }
    return std::exp(z) * (jAtOne + gamma * gammaPart + 3.0 * (1.0 - gamma) * erfPart);
}

} // namespace persson

PerssonModel::PerssonModel(const Spectrum& lineScan, double Eprime, PerssonOptions options)
    : Eprime_(limits::requireInRange("E'", Eprime, limits::minimumReducedModulus,
                                     limits::maximumReducedModulus, "Pa")),
      options_(options)
{
    if (!(options_.gamma > 0.0 && options_.gamma <= 1.0)) {
        std::ostringstream os;
        os << "Yang & Persson's gamma must be within (0, 1], got " << options_.gamma;
        throw ParameterError("gamma", os.str());
    }
    if (options_.pointsPerBin < 2 || options_.pointsPerBin > 32) {
        std::ostringstream os;
        os << "the Gauss-Legendre points per frequency bin must be within [2, 32], got " << options_.pointsPerBin;
        throw ParameterError("pointsPerBin", os.str());
    }
    if (!(options_.workBudget >= 1e5 && options_.workBudget <= 1e12)) {
        std::ostringstream os;
        os << "the construction's work budget must be within [1e5, 1e12], got " << options_.workBudget;
        throw ParameterError("workBudget", os.str());
    }
    requireRoughness(lineScan);
    const IsotropicSpectrum iso(lineScan);
    const double fLow = iso.lowestFrequency();
    const double fHigh = iso.highestFrequency();
    q0_ = 2.0 * pi * fLow;
    q1_ = 2.0 * pi * fHigh;

    // The bins: the nodes of the IsotropicSpectrum's piecewise linear C1 (its band's ends and
    // the levels between them), where C2 has its kinks.
    std::vector<double> edges{fLow};
    for (double f : lineScan.frequencies()) {
        if (f > edges.back() && f < fHigh) {
            edges.push_back(f);
        }
    }
    edges.push_back(fHigh);
    // IsotropicSpectrum::c2 sums over every bin above its argument, so the construction costs
    // (nodes) x (bins). Beyond options_.workBudget, consecutive bins are grouped into log-spaced panels
    // (edges still at levels): at most max(16, workBudget / (bins x points)) of them.
    const std::size_t bins = edges.size() - 1;
    const double maxPanels =
        std::max(16.0, options_.workBudget / (double(bins) * double(options_.pointsPerBin)));
    if (double(bins) > maxPanels) {
        const auto panels = static_cast<std::size_t>(maxPanels);
        std::vector<double> grouped{fLow};
        std::size_t next = 1;
        for (std::size_t p = 1; p < panels; ++p) {
            const double target = fLow * std::pow(fHigh / fLow, double(p) / double(panels));
            while (next + 1 < edges.size() && edges[next] < target) {
                ++next;
            }
            if (next + 1 < edges.size() && edges[next] > grouped.back()) {
                grouped.push_back(edges[next]);
            }
        }
        grouped.push_back(fHigh);
        edges = std::move(grouped);
    }

    const Rule rule = gaussLegendre(options_.pointsPerBin);
    const auto S = runningIntegral(rule);
    const std::size_t n = rule.t.size();
    // Pieces of a bin in the mapped variable t: the whole bin, or for the lowest bin pieces
    // graded towards q0 (1/4^6 .. 1/4, 1), where J's logarithm of w ~ 1/t sits at light load.
    std::vector<std::pair<double, double>> graded;
    {
        double lo = 0.0;
        for (int e = 6; e >= 1; --e) {
            const double hi = std::pow(0.25, e);
            graded.emplace_back(lo, hi);
            lo = hi;
        }
        graded.emplace_back(lo, 1.0);
    }
    const std::vector<std::pair<double, double>> whole{{0.0, 1.0}};

    double cumulative = 0.0; // int_{q0}^{q} q'^3 C dq'
    double variance = 0.0;   // 2 pi int q C dq
    std::vector<double> nodeQ, nodeDq, nodeC, nodeI;
    std::vector<double> g(n), dq(n), qs(n), cs(n);
    for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
        const double a = edges[b];
        const double width = edges[b + 1] - a;
        for (const auto& [ta, tb] : (b == 0 ? graded : whole)) {
            const double h = tb - ta;
            for (std::size_t i = 0; i < n; ++i) {
                const double t = ta + h * rule.t[i];
                const double f = a + width * t * t * (3.0 - 2.0 * t);
                const double dfdt = width * 6.0 * t * (1.0 - t);
                qs[i] = 2.0 * pi * f;
                cs[i] = iso.c2(f) / (4.0 * pi * pi);      // (P1)
                const double dqdt = 2.0 * pi * dfdt;      // dq/dt
                dq[i] = h * rule.w[i] * dqdt;             // quadrature weight in q
                g[i] = qs[i] * qs[i] * qs[i] * cs[i] * dqdt; // d/dt of int q^3 C dq
            }
            for (std::size_t i = 0; i < n; ++i) {
                double partial = 0.0;
                for (std::size_t k = 0; k < n; ++k) {
                    partial += S[i][k] * g[k];
                }
                nodeQ.push_back(qs[i]);
                nodeDq.push_back(dq[i]);
                nodeC.push_back(cs[i]);
                nodeI.push_back(cumulative + h * partial);
                variance += 2.0 * pi * qs[i] * cs[i] * dq[i];
            }
            for (std::size_t i = 0; i < n; ++i) {
                cumulative += h * rule.w[i] * g[i];
            }
        }
    }
    rmsHeight_ = std::sqrt(variance);
    rmsGradient_ = std::sqrt(2.0 * pi * cumulative);
    if (!(cumulative > 0.0) || !std::isfinite(cumulative)) {
        throw ParameterError(lineScan.source().empty() ? std::string("spectrum") : lineScan.source(),
                             "the spectrum has no slope for Persson's theory (int q^3 C dq = 0)");
    }
    w1_ = 1.0 / std::sqrt(pi * cumulative);
    double massSum = 0.0;
    for (std::size_t i = 0; i < nodeQ.size(); ++i) {
        const double mass = nodeDq[i] * nodeQ[i] * nodeQ[i] * nodeC[i];
        if (!(mass > 0.0) || !(nodeI[i] > 0.0)) {
            continue; // no power here (or none below it): contributes nothing, and w would be inf
        }
        const double w = 1.0 / std::sqrt(pi * nodeI[i]);
        w_.push_back(w);
        mass_.push_back(mass * w);
        massSum += mass * w;
    }
    u0_ = sqrtPi * options_.gamma * massSum; // (P7)
}

double PerssonModel::areaFraction(double load) const
{
    checkLoad(load);
    return std::erf(w1_ * load); // (P2): p/(2 sqrt(G)) = w(q1) p/E'
}

PerssonModel::Sums PerssonModel::sums(double load) const
{
    // Every term carries exp(-s^2); the smallest s (the highest q) is factored out so that
    // the sums stay within double range at any load: u = exp(-s_ref^2) U, h = load exp(s_ref^2)/D.
    double sRef = std::numeric_limits<double>::infinity();
    for (double w : w_) {
        sRef = std::min(sRef, w * load);
    }
    const double gamma = options_.gamma;
    double U = 0.0;
    double D = 0.0;
    for (std::size_t i = 0; i < w_.size(); ++i) {
        const double s = w_[i] * load;
        if (s > sRef + 30.0) {
            continue; // exp(-(s^2 - sRef^2)) < exp(-900)
        }
        const double excess = (s - sRef) * (s + sRef);
        if (excess > negligibleExponent) {
            continue;
        }
        const double damp = std::exp(-excess);
        const double e = std::erf(s);
        U += mass_[i] * persson::scaledSeparationKernel(s, gamma) * damp;
        D += mass_[i] * (gamma + 3.0 * (1.0 - gamma) * e * e) * damp;
    }
    const double sRef2 = sRef * sRef;
    return {std::log(sqrtPi * U) - sRef2, std::log(load) + sRef2 - std::log(sqrtPi * D)};
}

double PerssonModel::meanSeparation(double load) const
{
    return evaluate(load).meanSeparation;
}

double PerssonModel::conductancePerConductivity(double load) const
{
    return evaluate(load).conductancePerConductivity;
}

PerssonPoint PerssonModel::evaluate(double load) const
{
    checkLoad(load);
    PerssonPoint out;
    out.load = load;
    if (load == 0.0) {
        out.meanSeparation = std::numeric_limits<double>::infinity(); // the exponential law
        return out;
    }
    out.areaFraction = areaFraction(load);
    const Sums s = sums(load);
    // exp of a very negative number underflows to 0 (no trap); one beyond the largest double's
    // logarithm would overflow, so it is +inf directly.
    constexpr double logMax = 709.78;
    out.meanSeparation = s.logSeparation > logMax ? std::numeric_limits<double>::infinity() : std::exp(s.logSeparation);
    out.conductancePerConductivity =
        s.logConductance > logMax ? std::numeric_limits<double>::infinity() : std::exp(s.logConductance);
    return out;
}

} // namespace roughContact
