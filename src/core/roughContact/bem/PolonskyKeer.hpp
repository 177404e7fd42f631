// SPDX-License-Identifier: GPL-3.0-or-later
// Normal, frictionless, non-adhesive contact of a rigid rough surface with an elastic half-space
// (two rough elastic bodies reduce to it: their composite surface against a half-space of the
// reduced modulus E'), solved on a grid by the constrained conjugate-gradient method of
// Polonsky & Keer, "A numerical method for solving rough contact problems based on the
// multi-level multi-summation and conjugate gradient techniques", Wear 231 (1999) 206-219,
// its conjugate directions preconditioned with the half-space's stiffness (Vollebregt,
// J. Comput. Phys. 257 (2014) 333),
// and, with a perfectly plastic cap p <= H (points at H may overlap: the surface is flattened
// there; Almqvist et al., Wear 262 (2007) 1164), the same problem as the bound-constrained
// quadratic programme min 1/2 p.Kp - p.h, 0 <= p <= H, mean(p) = P, solved by accelerated
// projected gradients with adaptive restart (Beck & Teboulle, SIAM J. Imaging Sci. 2 (2009)
// 183; O'Donoghue & Candes, Found. Comput. Math. 15 (2015) 715; for rough contact: Bugnicourt
// et al., Tribol. Lett. 66 (2018) 29), the projection onto the capped set being exact.
#pragma once

#include "roughContact/bem/HalfSpaceOperator.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace roughContact {

/// Where a long solve is: reported every progressInterval seconds of it (none for a shorter one).
struct SolveProgress {
    /// "contact" or "conductance" (of a load), or "bonded-patch conductance" (BoundaryElementModel,
    /// before the first load of a non-periodic map)
    const char* stage = "";
    std::size_t iteration = 0;
    double residual = 0.0;    ///< the convergence measure (ContactSolution::residual, SpotConductance::residual)
    double tolerance = 0.0;   ///< the residual it must reach
    double seconds = 0.0;     ///< since this solve began
};
using SolveProgressCallback = std::function<void(const SolveProgress&)>;
/// Seconds between two progress reports of one solve (and before the first).
inline constexpr double progressInterval = 3.0;

/// How a solve with a cap p <= H is done.
enum class CappedMethod {
    /// Bound-constrained conjugate gradients, preconditioned as the elastic solve (the default).
    conjugateGradient,
    /// Accelerated projected gradients with adaptive restart: slower (no preconditioner), kept as
    /// an independent method the tests hold the default to.
    projectedGradient
};

struct PolonskyKeerOptions {
    /// Convergence: the relative residual (below) at most this.
    double tolerance = 1e-8;
    std::size_t maxIterations = 20000;
    /// Perfectly plastic cap p <= H [Pa]; none when unset.
    std::optional<double> hardness;
    CappedMethod cappedMethod = CappedMethod::conjugateGradient;
    /// Elastic solve: precondition the conjugate directions with the half-space's stiffness
    /// (HalfSpaceOperator::applyStiffness, Vollebregt 2014): the same solution in fewer
    /// iterations of one more FFT pair each (docs/benchmarks.md).
    bool precondition = true;
    /// Called every progressEvery seconds while a solve runs (optional).
    SolveProgressCallback progress;
    double progressEvery = progressInterval;
};

/// The solution at one mean pressure.
struct ContactSolution {
    std::vector<double> pressure; ///< p [Pa] per cell (>= 0; <= H with the cap)
    /// Separation s = u - h + D [m] per cell: > 0 apart, 0 in elastic contact, and with the cap
    /// <= 0 at p = H: there -s is the depth the cap flattened the surface, which a joint loaded
    /// to this pressure keeps as permanent set (BoundaryElementModel::deformedSurface).
    std::vector<double> gap;
    double meanPressure = 0.0;    ///< P = mean of p over all cells [Pa]
    double areaFraction = 0.0;    ///< A_r/A_n: the fraction of cells with p > 0
    double plasticFraction = 0.0; ///< the fraction of cells at p = H
    /// Mean separation [m]: the separation averaged over the nominal area, contact counting 0.
    /// Periodic: relative to the mean surface displacement (set 0 there, see HalfSpaceOperator),
    /// so that d(mean separation) is the rigid approach.
    double meanSeparation = 0.0;
    std::size_t iterations = 0;
    /// Elastic solve: the rms separation on the contact set over the rms height, at an
    /// iterate that clamped no point and found no penetration (then the complementarity
    /// conditions hold to it): 0 for the exact solution. With the cap: the relative change of
    /// the pressure over the last step, sum |p - p_previous| / sum p.
    double residual = 0.0;
    /// The residual the solve had to reach: the tolerance, or (elastic) the round-off floor of
    /// the displacements when that is higher (PolonskyKeer.cpp: displacementRoundOff).
    double tolerance = 0.0;
    bool converged = false;
    /// With the cap: the conjugate gradients stalled and the projected gradients finished
    /// (PolonskyKeer.cpp); iterations counts both.
    bool fallback = false;
};

class PolonskyKeer {
public:
    /// heights [m] (nx * ny, the operator's grid; peaks positive, the rigid surface pressed
    /// into the half-space). The heights are used as given (detrend them first).
    PolonskyKeer(const HalfSpaceOperator& op, std::vector<double> heights, PolonskyKeerOptions options = {});

    /// The contact at mean pressure P [Pa] (> 0; at most H with the cap). warmStart: a previous
    /// solution's pressure (e.g. at a neighbouring load), scaled to P as the first iterate.
    ContactSolution solve(double meanPressure, const std::vector<double>* warmStart = nullptr) const;

    const HalfSpaceOperator& op() const noexcept { return op_; }
    const std::vector<double>& heights() const noexcept { return h_; }
    const PolonskyKeerOptions& options() const noexcept { return options_; }

private:
    ContactSolution solveCapped(double meanPressure, const std::vector<double>* warmStart,
                                std::size_t maxIterations) const;
    ContactSolution finish(std::vector<double> p, double meanPressure, ContactSolution out) const;

    const HalfSpaceOperator& op_;
    std::vector<double> h_;
    double hScale_; ///< rms height (for the residual)
    PolonskyKeerOptions options_;
};

/// The conductance of the contact set: the heat flux between two half-spaces of conductivities
/// k1, k2 that touch on the cells of `contact` (true: in contact) at a uniform temperature jump,
/// over that jump and the nominal area, divided by k_s = 2 k1 k2 / (k1 + k2): h_c/k_s [1/m].
/// The temperature rise of a half-space under a surface flux has the same 1/r kernel as the
/// displacement under a pressure (with 1/(2 pi k) for 1/(pi E') per body), so with x solving
/// K x = 1 on the contact set (x = 0 elsewhere; conjugate gradients), h_c/k_s = mean(x) / E':
/// k_s/E' times the contact's stiffness per nominal area. For elastic contact this is Barber's
/// relation h_c = (k_s/E') dP/d(-mean separation) (Barber, Proc. R. Soc. A 459 (2003) 53).
/// Periodic: +inf when every cell is in contact; 0 when none is. Non-periodic (a patch of an
/// unbounded half-space): the heat leaving the patch spreads into the half-space around it, so
/// even the whole patch in contact has a finite conductance, that of a bonded punch of the
/// patch's shape (BoundaryElementModel removes it from the spots' conductance).
struct SpotConductance {
    double perConductivity = 0.0; ///< h_c/k_s [1/m]
    std::size_t iterations = 0;
    double residual = 0.0; ///< ||K x - 1|| / ||1|| on the contact set
    bool converged = false;
};
/// initial: a first guess of x (e.g. the solution at a neighbouring load; its values off the
/// contact set are ignored); solution: when given, receives x; precondition: with the
/// half-space's stiffness restricted to the contact set (as PolonskyKeerOptions).
/// progress (optional): called every progressEvery seconds while it runs (stage "conductance").
SpotConductance spotConductance(const HalfSpaceOperator& op, const std::vector<bool>& contact,
                                double tolerance = 1e-10, std::size_t maxIterations = 20000,
                                const std::vector<double>* initial = nullptr,
                                std::vector<double>* solution = nullptr, bool precondition = true,
                                const SolveProgressCallback& progress = {},
                                double progressEvery = progressInterval);

} // namespace roughContact
