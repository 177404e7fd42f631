// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/bem/PolonskyKeer.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/bem/GridMemory.hpp"
#include "roughContact/parallel/Threads.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace roughContact {

namespace {
// The separation is u - h, u = K p computed by FFTs with an absolute error of a few hundred
// machine epsilons of max |u| (measured: an 8 x 300 non-periodic map at F/(A_n E') = 1e4, where
// max |u| is 2.8e5 rms heights, stagnates at 1.2e-8 = 205 eps max|u|/rms h; at 1e3, 1e2 the
// solves converge to 350 and 3100 of them). When the load makes that floor exceed the
// tolerance (displacements a million times the roughness: complete contact), the elastic solve
// is converged at 1000 eps max|u| / rms h instead, the best its arithmetic can tell.
constexpr double displacementRoundOff = 1000.0 * std::numeric_limits<double>::epsilon();

// The loops over the grid run on threads() threads (parallel/Threads.hpp): elementwise ones by
// forEach, sums by these, in blocks combined in order, so every result is the same for any
// number of threads.
using parallel::forEach;

// The sum over i of body(i) (which may also write element i of its arrays).
template <class Body> double sumOf(std::size_t n, Body&& body)
{
    return parallel::reduce(
        n, 0.0, [&body](std::size_t i, double& a) { a += body(i); }, [](double& a, double b) { a += b; });
}

// Several sums and flags at once: body(i, acc) adds element i into acc.
template <class Acc, class Body> Acc sumsOf(std::size_t n, Body&& body)
{
    return parallel::reduce(n, Acc{}, body, [](Acc& a, const Acc& b) { a += b; });
}

// Reports a solve's progress every progressInterval seconds (reads the clock once an iteration:
// nothing next to the iteration's FFTs).
class ProgressClock {
public:
    ProgressClock(const SolveProgressCallback& callback, const char* stage, double tolerance, double every)
        : callback_(callback), stage_(stage), tolerance_(tolerance), every_(every),
          start_(std::chrono::steady_clock::now()), next_(every)
    {
    }
    void tick(std::size_t iteration, double residual)
    {
        if (!callback_) {
            return;
        }
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (t >= next_) {
            next_ = t + every_;
            callback_(SolveProgress{stage_, iteration, residual, tolerance_, t});
        }
    }

private:
    const SolveProgressCallback& callback_;
    const char* stage_;
    double tolerance_;
    double every_;
    std::chrono::steady_clock::time_point start_;
    double next_;
};
} // namespace

PolonskyKeer::PolonskyKeer(const HalfSpaceOperator& op, std::vector<double> heights,
                           PolonskyKeerOptions options)
    : op_(op), h_(std::move(heights)), options_(options)
{
    if (h_.size() != op_.size()) {
        throw ParameterError("heights", "has " + std::to_string(h_.size()) + " values for the operator's " +
                                            std::to_string(op_.size()) + " grid points");
    }
    double s = 0.0;
    double m = 0.0;
    for (double v : h_) {
        requireFinite("height", v);
        m += v;
    }
    m /= double(h_.size());
    for (double v : h_) {
        s += (v - m) * (v - m);
    }
    hScale_ = std::sqrt(s / double(h_.size()));
    if (!(hScale_ > 0.0)) {
        throw ParameterError("heights", "the surface is flat (zero rms height): nothing to solve");
    }
    requirePositive("tolerance", options_.tolerance);
    if (options_.hardness) {
        limits::requireInRange("hardness H", *options_.hardness, limits::minimumHardness, limits::maximumHardness, "Pa");
    }
}

ContactSolution PolonskyKeer::solve(double P, const std::vector<double>* warmStart) const
{
    requirePositive("mean pressure", P);
    if (options_.hardness && P > *options_.hardness) {
        std::ostringstream os;
        os << "the mean pressure " << P << " Pa exceeds the hardness " << *options_.hardness
           << " Pa: every point would flow";
        throw ParameterError("mean pressure", os.str());
    }
    if (options_.hardness && options_.cappedMethod == CappedMethod::projectedGradient) {
        return solveCapped(P, warmStart, options_.maxIterations);
    }
    // Polonsky & Keer's constrained conjugate gradients, preconditioned (Vollebregt 2014), with
    // the bounds 0 <= p <= H (Vollebregt's bound-constrained CG, J. Optim. Theory Appl. 162
    // (2014) 931, for the upper bound): the conjugate directions live on the active points
    // 0 < p < H, where the separation must vanish; a point at 0 that the surface penetrates
    // gets pressure (the overlap correction), a point at H where the surfaces part gives some
    // back (its mirror), and the load W is kept by scaling the active points. Without a cap
    // (H = inf) this is the elastic solve, operation for operation.
    const bool capped = options_.hardness.has_value();
    const double H = capped ? *options_.hardness : std::numeric_limits<double>::infinity();
    const std::size_t n = h_.size();
    const double W = P * double(n); // the sum of the cells' pressures
    const auto active = [H](double v) { return v > 0.0 && v < H; };
    // The load W with 0 <= p <= H: the active points scaled onto W less the capped points' share
    // (those the scaling lifts to H join them); when that would take more than half the active
    // points' load, every point is scaled down instead; when the points below the cap carry
    // nothing, the rest goes to the unloaded points in the order of `rank` (the separation:
    // the most penetrating first), H each, as a rigid-plastic contact would take it. Says
    // whether a point changed its set (reached H, left it, or was added), and otherwise the
    // factor k the active points were scaled by and how many points are at the cap.
    struct Balanced {
        bool changed = false;
        double k = 1.0;
        std::size_t atCap = 0;
    };
    const auto balance = [&](std::vector<double>& q, const auto& rank) {
        Balanced b;
        bool& changed = b.changed;
        for (int pass = 0; pass < 100; ++pass) {
            struct Loads {
                double sumActive = 0.0;
                std::size_t atCap = 0;
                Loads& operator+=(const Loads& o)
                {
                    sumActive += o.sumActive;
                    atCap += o.atCap;
                    return *this;
                }
            };
            const Loads loads = sumsOf<Loads>(n, [&](std::size_t i, Loads& a) {
                if (q[i] >= H) {
                    ++a.atCap;
                } else {
                    a.sumActive += q[i];
                }
            });
            const double sumActive = loads.sumActive;
            const std::size_t atCap = loads.atCap;
            const double target = W - double(atCap) * H;
            // (Round-off of W - atCap H counts as 0: a load exactly carried by the cap.)
            const double slack = 1e-12 * W;
            b.atCap = atCap;
            if (!(sumActive > 0.0) && std::abs(target) <= slack) {
                b.k = 1.0;
                return b;
            }
            if (atCap > 0 && target <= slack) {
                // The active points would lose more than half their load (a new contact point
                // beside a contact that is all at the cap): every loaded point gives its share,
                // those at H leave it.
                const double k = W / (sumActive + double(atCap) * H);
                forEach(n, [&](std::size_t i) { q[i] *= k; });
                changed = true;
                continue;
            }
            if (!(sumActive > 0.0)) {
                // Nothing below the cap carries load: new contact points, H each, the most
                // penetrating first.
                std::vector<std::size_t> order;
                for (std::size_t i = 0; i < n; ++i) {
                    if (q[i] <= 0.0) {
                        order.push_back(i);
                    }
                }
                const auto need = std::min(order.size(), static_cast<std::size_t>(std::ceil(target / H)) + 1);
                std::partial_sort(order.begin(), order.begin() + need, order.end(),
                                  [&](std::size_t i, std::size_t j) { return rank[i] < rank[j]; });
                double left = target;
                for (std::size_t k = 0; k < need && left > 0.0; ++k) {
                    q[order[k]] = std::min(H, left);
                    left -= q[order[k]];
                }
                b.changed = true;
                return b;
            }
            const double k = target / sumActive;
            b.k = k;
            struct Lifted {
                bool any = false;
                Lifted& operator+=(const Lifted& o)
                {
                    any = any || o.any;
                    return *this;
                }
            };
            const bool lifted = sumsOf<Lifted>(n, [&](std::size_t i, Lifted& a) {
                                    double& v = q[i];
                                    if (v < H) {
                                        v *= k;
                                        if (v >= H) {
                                            v = H;
                                            a.any = true;
                                        }
                                    }
                                }).any;
            if (!lifted) {
                break;
            }
            changed = true;
        }
        return b;
    };
    std::vector<double> p(n, P);
    if (warmStart != nullptr && warmStart->size() == n) {
        double sum = 0.0;
        for (double v : *warmStart) {
            sum += v;
        }
        if (sum > 0.0) {
            for (std::size_t i = 0; i < n; ++i) {
                p[i] = std::max(0.0, (*warmStart)[i]) * W / sum;
            }
            if (capped) {
                for (double& v : p) {
                    v = std::min(v, H);
                }
                std::vector<double> minusHeight(n);
                for (std::size_t i = 0; i < n; ++i) {
                    minusHeight[i] = -h_[i];
                }
                (void)balance(p, minusHeight);
            }
        }
    }
    // (In grid memory: huge pages where the kernel gives them, GridMemory.hpp.)
    GridField u(n); // K p
    GridField g(n); // separation: u - h less its mean on the active set
    GridField t(n, 0.0);
    GridField r(n);
    GridField z(options_.precondition ? n : 0);    // the preconditioned gap
    GridField zOut(options_.precondition ? n : 0); // S of the penetration outside
    GridField zRel(options_.precondition && capped ? n : 0); // S of the opening at H
    GridField uH(capped ? n : 0); // K of the points at H alone
    bool uHCurrent = false;
    double delta = 0.0;
    double Gold = 1.0;
    ContactSolution out;
    bool uCurrent = false; // u = K p already (updated by linearity in the last iteration)
    std::size_t sinceExact = 0;
    ProgressClock clock(options_.progress, "contact", options_.tolerance, options_.progressEvery);
    // With the cap, the active set can cycle (a contact nearly all at H, a point or two active:
    // their mean gap is a poor estimate of the approach, and the points it finds penetrating
    // push the rest off the cap and back): when the residual has not halved in stallLimit
    // iterations, the projected gradients (which always converge) finish from the best iterate.
    constexpr std::size_t stallLimit = 50;
    double bestResidual = std::numeric_limits<double>::infinity();
    std::size_t bestAt = 0;
    for (std::size_t it = 1; it <= options_.maxIterations; ++it) {
        // The displacement: by an FFT, or (when the last step neither clamped nor added a
        // point) by linearity, K(k (p - tau t)) = k (u - tau r); an exact one every 20
        // iterations keeps round-off from accumulating.
        if (!uCurrent || sinceExact >= 20) {
            op_.apply(p.data(), u.data());
            sinceExact = 0;
        }
        struct GapSums {
            double gbar = 0.0;
            double uMax = 0.0;
            std::size_t na = 0;
            GapSums& operator+=(const GapSums& o)
            {
                gbar += o.gbar;
                uMax = std::max(uMax, o.uMax);
                na += o.na;
                return *this;
            }
        };
        const GapSums gs = sumsOf<GapSums>(n, [&](std::size_t i, GapSums& a) {
            a.uMax = std::max(a.uMax, std::abs(u[i]));
            g[i] = u[i] - h_[i];
            if (active(p[i])) {
                a.gbar += g[i];
                ++a.na;
            }
        });
        const std::size_t na = gs.na;
        double gbar = gs.gbar;
        const double uMax = gs.uMax;
        if (na == 0) {
            if (!capped) {
                throw ParameterError("mean pressure", "no point carries load: the solve lost its contact set");
            }
            // Every loaded point at the cap: the approach that leaves none of them apart.
            gbar = -std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < n; ++i) {
                if (p[i] >= H) {
                    gbar = std::max(gbar, g[i]);
                }
            }
        } else {
            gbar /= double(na);
        }
        double G = sumOf(n, [&](std::size_t i) {
            g[i] -= gbar;
            return active(p[i]) ? g[i] * g[i] : 0.0;
        });
        const double gapResidual = na == 0 ? 0.0 : std::sqrt(G / double(na)) / hScale_;
        if (capped && na > 1 && gapResidual < 0.5 * bestResidual) {
            bestResidual = gapResidual;
            bestAt = it;
        } else if (capped && it > bestAt + stallLimit) {
            // The projected gradients start from p alone: the conjugate gradients' arrays go
            // first, so that the two solvers' arrays are never held at once (at 4096^2 that
            // was 2.70 GB at the peak instead of 2.06: docs/benchmarks.md).
            for (GridField* v : {&u, &g, &t, &r, &z, &zOut, &zRel, &uH}) {
                GridField().swap(*v);
            }
            ContactSolution rest = solveCapped(P, &p, options_.maxIterations - it);
            rest.iterations += it;
            rest.fallback = true;
            return rest;
        }
        const double tolerance = std::max(options_.tolerance, displacementRoundOff * uMax / hScale_);
        if (options_.precondition && na > 0) {
            // The preconditioned gap z = P S P g, P the projection onto the fields on the
            // active set with zero sum (the load stays W), S the stiffness (HalfSpaceOperator).
            forEach(n, [&](std::size_t i) { z[i] = active(p[i]) ? g[i] : 0.0; });
            op_.applyStiffness(z.data(), z.data());
            double zbar = sumOf(n, [&](std::size_t i) { return active(p[i]) ? z[i] : 0.0; });
            zbar /= double(na);
            G = sumOf(n, [&](std::size_t i) {
                z[i] = active(p[i]) ? z[i] - zbar : 0.0;
                return z[i] * g[i];
            });
        } else if (options_.precondition) {
            std::fill(z.begin(), z.end(), 0.0);
        }
        // The overlap correction turns a penetration outside the contact set into a pressure
        // there: with the plain gap as the direction, tau is a stiffness [Pa/m] and the
        // pressure -tau g (Polonsky & Keer); preconditioned, tau is a number and the pressure
        // -tau (S g_out), g_out the penetration alone, so that a patch of penetrating points
        // gets the patch's stiffness, not each point's (which would overshoot the load
        // many times over), and at least the stiffness of the longest wavelength. Its mirror at
        // the cap: where the surfaces part at a point carrying H, tau (S g_open) is taken off.
        if (options_.precondition) {
            struct Flags {
                bool penetrating = false;
                bool opening = false;
                Flags& operator+=(const Flags& o)
                {
                    penetrating = penetrating || o.penetrating;
                    opening = opening || o.opening;
                    return *this;
                }
            };
            const Flags f = sumsOf<Flags>(n, [&](std::size_t i, Flags& a) {
                zOut[i] = p[i] <= 0.0 && g[i] < 0.0 ? g[i] : 0.0;
                a.penetrating = a.penetrating || zOut[i] < 0.0;
                if (capped) {
                    zRel[i] = p[i] >= H && g[i] > 0.0 ? g[i] : 0.0;
                    a.opening = a.opening || zRel[i] > 0.0;
                }
            });
            const bool penetrating = f.penetrating;
            const bool opening = f.opening;
            if (penetrating) {
                op_.applyStiffness(zOut.data(), zOut.data());
            }
            if (opening) {
                op_.applyStiffness(zRel.data(), zRel.data());
            }
        }
        const GridField& direction = options_.precondition ? z : g;
        // Gold is 0 after an iteration whose gap vanished exactly on the contact set (one
        // point in contact): restart the conjugate direction then instead of dividing by it.
        const double beta = delta > 0.0 && Gold > 0.0 ? delta * G / Gold : 0.0;
        forEach(n, [&](std::size_t i) { t[i] = active(p[i]) ? direction[i] + beta * t[i] : 0.0; });
        Gold = G;
        op_.apply(t.data(), r.data());
        double rbar = sumOf(n, [&](std::size_t i) { return active(p[i]) ? r[i] : 0.0; });
        rbar /= double(std::max<std::size_t>(na, 1));
        struct Step {
            double num = 0.0;
            double den = 0.0;
            Step& operator+=(const Step& o)
            {
                num += o.num;
                den += o.den;
                return *this;
            }
        };
        const Step st = sumsOf<Step>(n, [&](std::size_t i, Step& a) {
            if (active(p[i])) {
                a.num += g[i] * t[i];
                a.den += (r[i] - rbar) * t[i];
            }
        });
        const double num = st.num;
        const double den = st.den;
        const double tau = den > 0.0 ? num / den : 0.0;
        // The overlap correction's factor: tau, or, when the step is empty (one point in
        // contact: the gap vanishes on the contact set, so t = 0 and tau = 0; a warm start
        // from a neighbouring load starts so at light loads), the stiffness itself, so that a
        // penetration is never left standing (that "converged" to one point at any load).
        const double tauOverlap = tau > 0.0 ? tau : (options_.precondition ? 1.0 : op_.smallestStiffness());
        // The step, the clamps 0 <= p <= H and, where the surface penetrates a point without
        // pressure, some pressure there (Polonsky & Keer's overlap correction); where it parts
        // from a point at H, less.
        struct Update {
            bool clamped = false;
            bool overlap = false;
            double sum = 0.0;
            Update& operator+=(const Update& o)
            {
                clamped = clamped || o.clamped;
                overlap = overlap || o.overlap;
                sum += o.sum;
                return *this;
            }
        };
        const bool precondition = options_.precondition;
        const double smallest = op_.smallestStiffness();
        const Update up = sumsOf<Update>(n, [&](std::size_t i, Update& a) {
            const double old = p[i];
            if (active(old)) {
                const double v = old - tau * t[i];
                a.clamped = a.clamped || v < 0.0 || v > H;
                p[i] = std::min(H, std::max(0.0, v));
            } else if (old <= 0.0 && g[i] < 0.0) {
                p[i] = precondition ? tauOverlap * std::max(-zOut[i], -g[i] * smallest) : -tauOverlap * g[i];
                p[i] = std::min(H, p[i]);
                a.overlap = true;
            } else if (old >= H && g[i] > 0.0) { // (capped only: nothing reaches H = inf)
                const double give =
                    precondition ? tauOverlap * std::max(zRel[i], g[i] * smallest) : tauOverlap * g[i];
                p[i] = std::max(0.0, H - give);
                a.overlap = true;
            }
            a.sum += p[i];
        });
        bool clamped = up.clamped;
        const bool overlap = up.overlap;
        const double sum = up.sum;
        delta = overlap ? 0.0 : 1.0;
        // The load: scale to the sum W (with the cap: the active points, balance()).
        if (capped) {
            // Without a change of sets u follows by linearity as in the elastic solve: the
            // active points were scaled by k, those at H kept it, so with u_H = K p_H (the
            // points at H alone; made once for each set of them),
            // K p = k (u - tau r) + (1 - k) u_H.
            const Balanced b = balance(p, g);
            clamped = b.changed || clamped;
            uCurrent = !clamped && !overlap;
            if (clamped || overlap) {
                uHCurrent = false;
            }
            if (uCurrent && b.atCap > 0 && !uHCurrent) {
                forEach(n, [&](std::size_t i) { uH[i] = p[i] >= H ? H : 0.0; });
                op_.apply(uH.data(), uH.data());
                uHCurrent = true;
            }
            if (uCurrent) {
                forEach(n, [&](std::size_t i) {
                    u[i] = b.k * (u[i] - tau * r[i]) + (b.atCap > 0 ? (1.0 - b.k) * uH[i] : 0.0);
                });
            }
        } else {
            const double k = sum > 0.0 ? W / sum : 1.0;
            uCurrent = !clamped && !overlap;
            const bool linear = uCurrent;
            forEach(n, [&](std::size_t i) {
                p[i] *= k;
                if (linear) {
                    u[i] = k * (u[i] - tau * r[i]);
                }
            });
        }
        ++sinceExact;
        // Converged: the separation vanishes on the active set (to the tolerance), no point
        // was clamped, none penetrated and none at the cap parts: the complementarity
        // conditions hold.
        out.iterations = it;
        out.residual = gapResidual;
        out.tolerance = tolerance;
        if (gapResidual <= tolerance && !overlap && !clamped) {
            out.converged = true;
            break;
        }
        clock.tick(it, gapResidual);
    }
    return finish(std::move(p), P, out);
}

ContactSolution PolonskyKeer::finish(std::vector<double> p, double P, ContactSolution out) const
{
    // The reported state: the final pressure's displacement and separations.
    const std::size_t n = h_.size();
    const double H = options_.hardness ? *options_.hardness : std::numeric_limits<double>::infinity();
    GridField u(n);
    op_.apply(p.data(), u.data());
    std::size_t nc = 0;
    std::size_t nh = 0;
    double D = 0.0; // rigid approach: the separation is 0 on the elastic contact set
    std::size_t nd = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (p[i] > 0.0) {
            ++nc;
        }
        if (p[i] >= H) {
            ++nh;
        } else if (p[i] > 0.0) {
            D += h_[i] - u[i];
            ++nd;
        }
    }
    if (nd == 0) {
        // All contact points at the cap: the approach is any that leaves the free points apart
        // (u - h + D >= 0) and the capped ones pressed (<= 0); the least, at which the nearest
        // free point just touches: D = max over the free points of h - u. (It was the min, which
        // left every free point's separation at 0: found by the capped solver's test, where
        // W = 2048 H exactly on a 64^2 grid.)
        D = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i) {
            if (p[i] == 0.0) {
                D = std::max(D, h_[i] - u[i]);
            }
        }
        if (!std::isfinite(D)) {
            D = 0.0;
        }
    } else {
        D /= double(nd);
    }
    out.gap.resize(n);
    double sep = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double sv = p[i] >= H ? std::min(0.0, u[i] - h_[i] + D)
                          : p[i] > 0.0 ? 0.0
                                       : std::max(0.0, u[i] - h_[i] + D);
        out.gap[i] = sv;
        sep += std::max(0.0, sv);
    }
    out.pressure = std::move(p);
    out.meanPressure = P;
    out.areaFraction = double(nc) / double(n);
    out.plasticFraction = double(nh) / double(n);
    out.meanSeparation = sep / double(n);
    return out;
}

namespace {
// The exact projection onto {0 <= p <= H, sum p = W}: p = clamp(z - mu, 0, H) with mu found by
// bisection (the sum falls monotonically with mu, from n H at mu = min z - H to 0 at max z).
// When H >= W no point can reach the cap (all are >= 0 and sum to W), and mu = max z - W
// already gives a sum >= W: the bracket is then that of the pressures, whatever H is (a bracket
// from min z - H would leave the bisection no digits for pressures far below a high cap).
void projectCapped(const std::vector<double>& z, double H, double W, std::vector<double>& p)
{
    const double zMax = *std::max_element(z.begin(), z.end());
    double lo = H >= W ? zMax - W : *std::min_element(z.begin(), z.end()) - H;
    double hi = zMax;
    const auto sumAt = [&](double mu) {
        double sum = 0.0;
        for (double v : z) {
            sum += std::clamp(v - mu, 0.0, H);
        }
        return sum;
    };
    for (int k = 0; k < 200 && hi - lo > 1e-15 * (std::abs(lo) + std::abs(hi)); ++k) {
        const double mid = 0.5 * (lo + hi);
        (sumAt(mid) > W ? lo : hi) = mid;
    }
    const double mu = 0.5 * (lo + hi);
    p.resize(z.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        p[i] = std::clamp(z[i] - mu, 0.0, H);
        sum += p[i];
    }
    // The bisection leaves the sum within round-off of W; scale the free points onto it.
    double free = 0.0;
    for (double v : p) {
        if (v < H) {
            free += v;
        }
    }
    if (free > 0.0) {
        const double k = 1.0 + (W - sum) / free;
        for (double& v : p) {
            if (v < H) {
                v = std::min(H, v * k);
            }
        }
    } else if (sum == 0.0 && H >= W) {
        // A load below the resolution of z (z ~ E' h' is 1e20 times a load of 1e-14 Pa): the
        // exact projection puts it all on the highest point, which z - mu cannot resolve.
        p[std::size_t(std::max_element(z.begin(), z.end()) - z.begin())] = W;
    }
}
} // namespace

ContactSolution PolonskyKeer::solveCapped(double P, const std::vector<double>* warmStart,
                                          std::size_t maxIterations) const
{
    const double H = *options_.hardness;
    if (P > H) {
        std::ostringstream os;
        os << "the mean pressure " << P << " Pa exceeds the hardness " << H << " Pa: every point would flow";
        throw ParameterError("mean pressure", os.str());
    }
    const std::size_t n = h_.size();
    const double W = P * double(n);
    std::vector<double> x(n, P);
    if (warmStart != nullptr && warmStart->size() == n) {
        projectCapped(*warmStart, H, W, x);
    }
    const double step = 1.0 / op_.largestEigenvalue();
    std::vector<double> y = x;
    std::vector<double> xNew(n);
    std::vector<double> z(n);
    std::vector<double> grad(n);
    double t = 1.0;
    ContactSolution out;
    out.tolerance = options_.tolerance;
    ProgressClock clock(options_.progress, "contact", options_.tolerance, options_.progressEvery);
    for (std::size_t it = 1; it <= maxIterations; ++it) {
        op_.apply(y.data(), grad.data()); // the gradient of 1/2 p.Kp - p.h at y: K y - h
        for (std::size_t i = 0; i < n; ++i) {
            grad[i] -= h_[i];
            z[i] = y[i] - step * grad[i];
        }
        projectCapped(z, H, W, xNew);
        double change = 0.0;
        double restart = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            change += std::abs(xNew[i] - x[i]);
            restart += grad[i] * (xNew[i] - x[i]);
        }
        const double tNew = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * t * t));
        if (restart > 0.0) { // the momentum points uphill: restart it
            t = 1.0;
            y = xNew;
        } else {
            for (std::size_t i = 0; i < n; ++i) {
                y[i] = xNew[i] + (t - 1.0) / tNew * (xNew[i] - x[i]);
            }
            t = tNew;
        }
        x.swap(xNew);
        out.iterations = it;
        out.residual = change / W;
        if (out.residual <= options_.tolerance) {
            out.converged = true;
            break;
        }
        clock.tick(it, out.residual);
    }
    return finish(std::move(x), P, out);
}

SpotConductance spotConductance(const HalfSpaceOperator& op, const std::vector<bool>& contact,
                                double tolerance, std::size_t maxIterations,
                                const std::vector<double>* initial, std::vector<double>* solution,
                                bool precondition_, const SolveProgressCallback& progress, double progressEvery)
{
    const std::size_t n = op.size();
    if (contact.size() != n) {
        throw ParameterError("contact set", "does not match the grid");
    }
    SpotConductance out;
    const std::size_t nc = static_cast<std::size_t>(std::count(contact.begin(), contact.end(), true));
    if (nc == 0) {
        out.converged = true;
        return out;
    }
    if (nc == n && op.periodic()) {
        // A periodic interface in contact everywhere: the solids are joined, nothing constricts.
        // (A non-periodic patch in contact everywhere still constricts the flow into the
        // half-space around it: solved below, the bonded patch's conductance.)
        out.perConductivity = std::numeric_limits<double>::infinity();
        out.converged = true;
        return out;
    }
    // Conjugate gradients for K_cc x = 1 (K restricted to the contact set: symmetric positive
    // definite), x = 0 off the set, preconditioned with the stiffness restricted to the set
    // (HalfSpaceOperator::applyStiffness; symmetric positive definite too).
    std::vector<double> x(n, 0.0); // the solution, handed out (moved) at the end
    GridField res(n, 0.0);
    GridField z(n, 0.0);
    GridField d(n, 0.0);
    GridField Kd(n);
    const bool warm = initial != nullptr && initial->size() == n;
    if (warm) {
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = contact[i] ? (*initial)[i] : 0.0;
        }
        op.apply(x.data(), Kd.data());
    }
    double rr = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        res[i] = contact[i] ? 1.0 - (warm ? Kd[i] : 0.0) : 0.0;
        rr += res[i] * res[i];
    }
    const auto precondition = [&]() {
        if (!precondition_) {
            z = res;
            return;
        }
        op.applyStiffness(res.data(), z.data());
        forEach(n, [&](std::size_t i) {
            if (!contact[i]) {
                z[i] = 0.0;
            }
        });
    };
    precondition();
    double rz = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        rz += res[i] * z[i];
    }
    d = z;
    const double norm = std::sqrt(double(nc));
    out.residual = std::sqrt(rr) / norm;
    out.converged = out.residual <= tolerance;
    ProgressClock clock(progress, "conductance", tolerance, progressEvery);
    for (std::size_t it = 1; it <= maxIterations && !out.converged; ++it) {
        op.apply(d.data(), Kd.data());
        const double dKd = sumOf(n, [&](std::size_t i) { return contact[i] ? d[i] * Kd[i] : 0.0; });
        const double alpha = rz / dKd;
        const double rrNew = sumOf(n, [&](std::size_t i) {
            if (!contact[i]) {
                return 0.0;
            }
            x[i] += alpha * d[i];
            res[i] -= alpha * Kd[i];
            return res[i] * res[i];
        });
        out.iterations = it;
        out.residual = std::sqrt(rrNew) / norm;
        if (out.residual <= tolerance) {
            out.converged = true;
            break;
        }
        clock.tick(it, out.residual);
        precondition();
        const double rzNew = sumOf(n, [&](std::size_t i) { return res[i] * z[i]; });
        const double beta = rzNew / rz;
        rz = rzNew;
        forEach(n, [&](std::size_t i) { d[i] = contact[i] ? z[i] + beta * d[i] : 0.0; });
    }
    double mean = 0.0;
    for (double v : x) {
        mean += v;
    }
    mean /= double(n);
    out.perConductivity = mean / op.reducedModulus();
    if (solution != nullptr) {
        *solution = std::move(x);
    }
    return out;
}

} // namespace roughContact
