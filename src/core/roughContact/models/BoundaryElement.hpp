// SPDX-License-Identifier: GPL-3.0-or-later
// The exact reference: the boundary-element contact of an areal surface (bem/PolonskyKeer) as
// a contact model, with the exact contact conductance of its contact set.
#pragma once

#include "roughContact/bem/ContactSpots.hpp"
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/bem/PolonskyKeer.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace roughContact {

/// The conductance solve's tolerance (relative residual of K x = 1 on the contact set). The
/// conductance is the mean of x, whose error after conjugate gradients is the error's energy
/// norm squared: it falls as the square of the residual, so 1e-7 leaves it exact to about
/// 1e-10 (testBoundaryElement measures it against 1e-12).
inline constexpr double conductanceTolerance = 1e-7;

struct BoundaryElementOptions {
    /// Solve the surface as one period of a periodic surface (synthesized surfaces are);
    /// otherwise (measured maps) without wrap-around: zero-padded, the surface a patch of an
    /// unbounded half-space loaded only on the patch.
    bool periodic = false;
    /// Solve a measured map mirrored about its edges into one period (2nx x 2ny) of a periodic
    /// surface (HalfSpaceOperator::Edges::mirrored): an interface with the map's heights,
    /// neither edges nor a patch of its own, so no patch constriction to remove (which near
    /// complete contact is a difference of two nearly equal resistances:
    /// docs/validation/boundaryElement.md). Not with periodic. Detrended like a map (plane).
    bool mirrored = false;
    /// Perfectly plastic cap p <= H [Pa]; none when unset.
    std::optional<double> hardness;
    /// What is removed from the heights before the solve; unset: defaultDetrend(periodic), the
    /// mean of a periodic surface, the plane of a measured map (ArealSurface.hpp says why).
    std::optional<Detrend> detrend;
    double tolerance = 1e-8;
    std::size_t maxIterations = 20000;
    /// Precondition the contact and conductance solves (PolonskyKeerOptions::precondition).
    bool precondition = true;
    /// The most memory [bytes] the solver may take (checked before allocating).
    double memoryLimit = 8e9;
    /// Called every progressInterval seconds while a contact or conductance solve runs
    /// (PolonskyKeer.hpp), the bonded patch's included (optional); every progressEvery seconds.
    SolveProgressCallback progress;
    double progressEvery = progressInterval;
};

/// The peak pressure [Pa] a front-end's option `name` gives a joint to unload from
/// (BoundaryElementModel::loadPath): it needs the cap `hardness` (`capName`: how the front-end
/// names it; elastic, unloading is loading) and lies above 0 and below H (at H the whole surface
/// flows). Returns it; ParameterError naming `name` otherwise.
double requireUnloadingPeak(double peakPressure, const std::optional<double>& hardness, const std::string& name,
                            const std::string& capName);

/// The operator's edges of a solve: mirrored, periodic or padded (a patch). ParameterError
/// naming "mirror" for both periodic and mirrored (a mirrored map is its own periodic surface).
HalfSpaceOperator::Edges edgesOf(bool periodic, bool mirrored);

/// One load point of a boundary-element curve.
struct BoundaryElementPoint {
    double load = 0.0;                       ///< F/(A_n E')
    double areaFraction = 0.0;               ///< A_r/A_n
    double plasticFraction = 0.0;            ///< fraction of A_n at p = H
    double meanSeparation = 0.0;             ///< [m] (PolonskyKeer.hpp: ContactSolution)
    /// h_c/k_s [1/m]: +inf at complete contact. Non-periodic: of the interface, the conductance
    /// of the spots with the patch's own constriction removed (BoundaryElementModel).
    double conductancePerConductivity = 0.0;
    /// Non-periodic: the spots' conductance as solved, the patch's constriction included
    /// (1/h = 1/conductancePerConductivity + 1/patchConductancePerConductivity); periodic: the
    /// same as conductancePerConductivity.
    double spotsConductancePerConductivity = 0.0;
    /// Non-periodic: how many times 1/h_c = 1/h_spots - 1/h_patch multiplies a relative error of
    /// h_spots into h_c, 1/(1 - h_spots/h_patch) = 1 + h_c/h_patch (+inf when the spots conduct
    /// as the bonded patch does); periodic and mirrored: 1 (nothing is removed); 1 at P >= H too
    /// (every point flows: complete contact, exact without a correction). Above
    /// patchCorrectionGainLimit the padded answer is not to be trusted (patchCorrectionWarning).
    double patchCorrectionGain = 1.0;
    /// The contact set's spots (ContactSpots.hpp): across the period's edges when periodic; a
    /// mirrored map's on the map itself; one spot, the whole grid, at complete contact (P >= H).
    ContactSpots spots;
    std::size_t iterations = 0;              ///< contact solve
    double residual = 0.0;                   ///< contact solve
    std::size_t conductanceIterations = 0;
    double conductanceResidual = 0.0;
};

/// The largest patchCorrectionGain at which a padded map's h_c is trusted. Near complete contact
/// the spots of a patch conduct nearly as the bonded patch does, and the difference of the two
/// resistances amplifies any error of the series picture: at a gain of 50 a 0.5 % error of h_spots
/// is 25 % of h_c. On the X3P map against the same map solved mirrored (the engineering range's
/// 48 points, docs/validation/boundaryElement.md): 0.87-1.16 at gains up to 39, and 1.22, 1.06,
/// 1.90 and 1.96 at gains 51, 70, 172 and 205 (39-64 % contact).
inline constexpr double patchCorrectionGainLimit = 50.0;

/// A warning for the points of a padded map's curve whose patchCorrectionGain exceeds
/// patchCorrectionGainLimit: how many, from which pressure on (P = load x Eprime [Pa] and the
/// load), the largest gain, and that the map solved mirrored (the front-end's option `mirror`)
/// gives the interface's h_c there. Empty when none does (always for periodic and mirrored solves).
std::string patchCorrectionWarning(const std::vector<BoundaryElementPoint>& points, double Eprime,
                                   const std::string& mirror);

/// The conductance of a measured (non-periodic) map. The map is a patch of an unbounded
/// half-space; the heat through its spots then also has to spread from the patch into the
/// half-space around it, a constriction of the patch as a whole that an interface (nominally in
/// contact everywhere) does not have. It is in series with the spots' own constriction
/// (Holm, Electric Contacts, 1967, §4; Greenwood, Brit. J. Appl. Phys. 17 (1966) 1621: a
/// cluster's resistance is its spots' plus the cluster's), so the interface's conductance is
///     1/h_c = 1/h_spots - 1/h_patch,
/// h_patch the conductance of the whole patch bonded (every cell in contact). Measured on the
/// X3P map against its periodic solve: within 1 % at p/E' = 1e-3, 6 % at 1e-4, 10 % at 1e-2
/// (docs/validation/boundaryElement.md); testBoundaryElement checks it on a periodic surface.
/// Without it h_c of the map would stay below h_patch (9200 1/m for the X3P map) at any load.
class BoundaryElementModel final : public ContactModel {
public:
    /// surface: the composite surface (compositeSurface() of two rough ones), detrended here as
    /// options.detrend says; Eprime: E' of the pair.
    BoundaryElementModel(const ArealSurface& surface, double Eprime, BoundaryElementOptions options = {});

    std::string name() const override { return "boundaryElement"; }
    /// Non-periodic: h/k_s [1/m] of the whole patch bonded to the half-space (every cell in
    /// contact), the constriction of the patch itself; periodic: +inf.
    double patchConductancePerConductivity() const noexcept { return patchConductance_; }
    /// A_r/A_n at F/(A_n E'); ParameterError when the solve does not converge.
    double areaFraction(double load) const override;
    /// Everything at one load; warmStart: a previous solution's pressure field.
    /// pressure/flux (optional) receive the pressure field and the conductance solve's field,
    /// warmStart/warmFlux (optional) are first guesses of them (a neighbouring load's).
    BoundaryElementPoint solve(double load, std::vector<double>* pressure = nullptr,
                               const std::vector<double>* warmStart = nullptr,
                               std::vector<double>* flux = nullptr,
                               const std::vector<double>* warmFlux = nullptr) const;
    /// A curve: loads solved in increasing order, each warm-started from the one below;
    /// returned in the order given. progress (optional) is called after each point.
    std::vector<BoundaryElementPoint>
    curve(const std::vector<double>& loads,
          const std::function<void(std::size_t done, std::size_t total, const BoundaryElementPoint&)>&
              progress = {}) const;

    /// The surface a joint loaded to peakLoad = F/(A_n E') with the cap is left with: the
    /// heights solved less the cap's interpenetration at the points at p = H (the negative
    /// ContactSolution::gap there), kept as permanent set (docs/theory.md §7.3). Without a cap, the heights solved.
    /// ParameterError when peakLoad E' >= H (the whole surface flows) or the solve does not converge.
    ArealSurface deformedSurface(double peakLoad) const;
    /// The points at `loads` (F/(A_n E'), in the order given) of a joint that has carried
    /// peakLoad: at and below it the deformed surface unloaded or reloaded elastically, above it
    /// loaded on with the cap from the deformed surface (docs/theory.md §7.3). At peakLoad it is
    /// the loading curve's point; without a cap, the loading curve.
    std::vector<BoundaryElementPoint>
    loadPath(double peakLoad, const std::vector<double>& loads,
             const std::function<void(std::size_t done, std::size_t total, const BoundaryElementPoint&)>&
                 progress = {}) const;

    const ArealSurface& surface() const noexcept { return surface_; }
    double reducedModulus() const noexcept { return Eprime_; }
    const BoundaryElementOptions& options() const noexcept { return options_; }

private:
    ArealSurface surface_;
    double Eprime_;
    BoundaryElementOptions options_;
    std::unique_ptr<HalfSpaceOperator> op_;
    std::unique_ptr<PolonskyKeer> solver_;
    double patchConductance_ = 0.0;
};

/// About the peak memory [bytes] of the solves on an nx x ny map (periodic, or padded to twice
/// each way), elastic or capped: what the size check before a solve compares with
/// BoundaryElementOptions::memoryLimit (within 4 % of the peaks measured at 512^2 to 4096^2).
double boundaryElementBytes(std::size_t nx, std::size_t ny, bool periodic, bool capped);

/// About how long a curve of `loads` loads takes [s] on op's grid, before it starts (with the
/// bonded patch of a non-periodic map): one displacement evaluation (an FFT pair) timed here,
/// times the evaluations such a curve takes (BoundaryElement.cpp: measured). A guide for a log
/// line, not a bound: a hard surface or a load near complete contact takes longer.
double estimatedCurveSeconds(const HalfSpaceOperator& op, std::size_t loads);

/// The composite of two rough surfaces on the same grid, each given as its heights towards the
/// other: the gap between them is that of their sum against a flat (Johnson 1985 §13.1), so
/// h = h1 + h2. InputError when the grids differ.
ArealSurface compositeSurface(const ArealSurface& a, const ArealSurface& b);

} // namespace roughContact
