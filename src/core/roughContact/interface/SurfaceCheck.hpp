// SPDX-License-Identifier: GPL-3.0-or-later
// The check of a user's own surface: the exact (boundary-element) model
// solved on the user's surface at a few pressures across the interface's range, and every
// conductance law's h_c/k_s held to it there, so a user sees how far the law they chose is from
// the exact answer on their own surface, and which law is closest.
//
// What is solved. A measured areal map (surfaces of kind areal): the map itself (the composite
// of two), as the boundaryElement model solves it (non-periodic unless `periodic`). A 1-D
// description (profile, spectrum, power law, fractal; the equivalent of two): `seeds` periodic
// N x N Gaussian surfaces synthesized from its spectrum (synthesizeIsotropic) cut at N/8
// levels, the shortest wavelength 8 cells; a profile across a lay with one along it, from the
// across spectrum so cut, stretched along y by the lay ratio (synthesizeStretched,
// LaySpectra::stretch), the laws on the two directions' averaged cut spectrum (the convention of the fidelity study,
// docs/validation/fidelity.md, at which the exact conductance is converged to a few per cent
// from p/E' of about 1e-3 on). The laws are built on the same cut spectrum, so law and exact
// see one surface; what the cut leaves out is said (levels kept of levels given).
//
// At light loads a larger period. A profile's or spectrum's pressures up to p/(E' h') =
// smallCellLoadPerGradient (MeasuredAccuracy.hpp) are solved on periods of lightLoadPeriods scan
// lengths (default 4) on the same grid: the spectrum on that period (Spectrum::onPeriod) cut at
// its gridSize/8 levels, so the same cost with wavelengths down to 8 cells of the longer period,
// and the laws on that cut spectrum there. A cell of one scan length holds few contact spots at
// those loads and may conduct far more than a large joint (docs/checking.md gives what two and
// four scan lengths gained against periods of 8 on the report's spectra: four gave the default
// law's verdict as a period of 8 does at 78 of 84 points, two at 69, one at 45).
//
// How the periods join. From smallCellLoadPerGradient to checkBlendEnd both surfaces are solved
// and every value (the exact h_c/k_s and A_r/A_n, each law's h_c/k_s) is the geometric mean of
// the two with the longer period's weight falling log-linearly in p/(E' h') from 1 to 0
// (longPeriodWeight, joinPeriods), so the reference is continuous in the load; from checkBlendEnd
// on, one scan length alone. The check refuses a grid and period that keep fewer than
// minimumCheckedLevels of the surface's levels (naming the options).
//
// Elastic or capped as the materials say: the cap p <= H where the spec gives a hardness (or
// hardnessFromYield) or the yielding material has S_y (H = 2.84 S_y), elastic otherwise.
//
// The pressures. `pressureCount` log spaced over the spec's table range [minPressure,
// maxPressure] (its defaults, ContactInterface.hpp) clipped to p/(E' h') within [1e-4, 1e-1]
// (h' the areal rms gradient of the checked surface: lighter loads leave a 512^2 grid with too
// few spots, heavier ones are near complete contact) and, capped, to p <= 0.9 H.
//
// The ratio of a law is its h_c/k_s over the exact one's geometric mean over the seeds; the
// seeds' spread is reported beside it. A law holds at a pressure when its ratio is within
// [1 - checkTolerance, 1 + checkTolerance] (0.75 to 1.25, the band of the fidelity study).
// Where the exact answer is not to be trusted (a map solved padded near complete contact:
// patchCorrectionWarning) the pressure is reported apart and counts for no law: not as a miss,
// not for the closest law. The verdict names a law to use only when it holds at every counted
// pressure; else it says that none does.
//
// The answer. What was solved is the checked surface (a 1-D description's band-limited
// synthesized surfaces; a map itself), not the user's whole surface: its exact h_c/k_s is not
// the number for the joint, the law's ratio to it is what carries over. So the check gives as
// its answer the chosen law on the whole surface as given (the h_c/k_s the condition uses) and,
// beside it, where the exact answer for the whole surface lies if the law misses it as it
// missed the checked one: the answer over the law's ratio, over the seeds' spread.
#pragma once

#include "roughContact/interface/ContactInterface.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace roughContact {

/// A law off the exact conductance by more than this fraction is said to miss it.
inline constexpr double checkTolerance = 0.25;
/// The most pressures one check solves.
inline constexpr std::size_t maximumCheckedPressures = 5;
/// p/(E' h') from which the check solves one scan length alone (How the periods join).
inline constexpr double checkBlendEnd = 1e-2;
/// The fewest of the surface's levels a checked surface may hold (or all of them, when the
/// surface has fewer): below it the check is not of this surface.
inline constexpr std::size_t minimumCheckedLevels = 4;

/// The longer period's weight at p/(E' h') = x: 1 up to smallCellLoadPerGradient, 0 from
/// checkBlendEnd, log(checkBlendEnd/x)/log(checkBlendEnd/smallCellLoadPerGradient) between.
double longPeriodWeight(double loadPerGradient);
/// onePeriod^(1 - w) longPeriod^w (the value on one scan length and on the longer period); a
/// weight of 0 or 1 gives the one value as it is, and a value not positive and finite joins
/// linearly.
double joinPeriods(double onePeriod, double longPeriod, double weight);

struct SurfaceCheckOptions {
    /// Grid of the synthesized surfaces (N x N, even, 8 to 4096).
    std::size_t gridSize = 512;
    /// Seeds of the synthesized surfaces, each once (a measured map is solved once).
    std::vector<std::uint64_t> seeds{1, 2, 3};
    /// Pressures checked across the range, 1 to maximumCheckedPressures.
    std::size_t pressureCount = 4;
    /// Pressures [Pa] to check instead of the spec's range, at most maximumCheckedPressures and
    /// finite (each within the clipped range is kept; none left is a ParameterError).
    std::vector<double> pressures;
    /// With pressures: one outside the checked range is checked at the range's nearer end instead
    /// (and said: SurfaceCheck::moved), not dropped. The condition's default, the pressures its
    /// faces carry, which may lie beyond what the check can solve.
    bool movePressuresIntoRange = false;
    /// A profile's or spectrum's pressures up to p/(E' h') = smallCellLoadPerGradient are solved
    /// on periods of this many scan lengths, and joined with one scan length's up to
    /// checkBlendEnd (1 to 64; 1: one scan length at every pressure).
    std::size_t lightLoadPeriods = 4;
    /// The joint has carried this nominal pressure [Pa] (with a cap, below it): each solved
    /// surface is also unloaded from it (BoundaryElementModel::loadPath, docs/theory.md §7.3) at the
    /// checked pressures, and the check gives the exact unloading h_c/k_s beside the loading one
    /// and the chosen law's h on unloading (its unloading branch, or its loading value for a law
    /// without one) over it.
    std::optional<double> unloadFrom;
    /// A line for a log, at the start and after each solve.
    std::function<void(const std::string&)> log;
    /// How the front-end names these options in errors (the CLI's --synthesize, the contact
    /// entry's checkPeriods, Python's light_load_periods, ...).
    struct Names {
        std::string gridSize = "check grid";
        std::string seeds = "check seeds";
        std::string pressures = "check pressures";
        std::string lightLoadPeriods = "check light-load periods";
        std::string unloadFrom = "check unload-from";
    } names;
};

struct CheckedLaw {
    std::string name;
    /// Empty when the law can be built; else why not (and hPerK, ratio are empty).
    std::string unavailable;
    std::vector<double> hPerK; ///< h_c/k_s [1/m] per checked pressure
    std::vector<double> ratio; ///< hPerK / exact
    /// The largest of max(ratio, 1/ratio) over the counted pressures (exactTrusted): 1 is exact.
    double worstFactor = 0.0;
};

struct SurfaceCheck {
    /// What was solved: "3 seeds of 512 x 512 synthesized from ..." or "the map ... (nx x ny, ...)";
    /// the levels kept are levelsKept/levelsGiven.
    std::string surface;
    /// "elastic" or "capped at H = ... Pa".
    std::string regime;
    std::optional<double> hardness;
    double reducedModulus = 0.0;
    double gradient = 0.0;     ///< h': areal rms gradient of the checked surface
    /// The lay ratio of a finish given by profiles across and along its lay (LaySpectra::stretch):
    /// its surfaces are stretched so along y; 1 for an isotropic surface and a map.
    double layStretch = 1.0;
    std::size_t levelsKept = 0;  ///< levels of the spectrum in the check (the across spectrum's with a lay)
    std::size_t levelsGiven = 0; ///< levels of the spectrum given
    /// The period [scan lengths] of the pressures up to p/(E' h') = smallCellLoadPerGradient (1:
    /// none solved on a longer one), and the levels of the spectrum on it that the check holds.
    std::size_t lightLoadPeriods = 1;
    std::size_t lightLevelsKept = 0;
    /// The given spectrum's levels that the longer period's cut surface holds (0: none solved).
    std::size_t lightLevelsOfGiven = 0;
    /// Each pressure's weight of the longer period (longPeriodWeight; 0 for a map).
    std::vector<double> longPeriodWeights;
    /// How many of the pressures were solved on one scan length (levelsKept's surface): all of a
    /// map's, none where every one is light and solved on the longer period.
    std::size_t onePeriodPressures = 0;
    std::vector<double> pressures;       ///< [Pa]
    /// Pressures asked for (SurfaceCheckOptions::pressures) outside the checked range [Pa].
    std::vector<double> dropped;
    /// Of those, the ones checked at the range's nearer end instead (movePressuresIntoRange).
    std::vector<double> moved;
    double lowestCheckable = 0.0;        ///< the checked range [Pa] (SurfaceCheck.hpp)
    double highestCheckable = 0.0;
    /// The exact answer of the checked surface (not the whole surface: The answer, above).
    std::vector<double> exactHPerK;      ///< geometric mean over the seeds [1/m]
    std::vector<double> exactHPerKLow;   ///< the seeds' smallest
    std::vector<double> exactHPerKHigh;  ///< the seeds' largest
    std::vector<double> exactArea;       ///< A_r/A_n, the mean over the seeds
    /// Per pressure: false where the exact answer is not to be trusted (exactWarning); such a
    /// pressure counts for no law.
    std::vector<bool> exactTrusted;
    /// With SurfaceCheckOptions::unloadFrom: that peak [Pa], and per pressure the checked
    /// surface's exact h_c/k_s unloaded from it (geometric mean over the seeds, the periods joined
    /// as the loading one) and the chosen law's over it (empty without a peak).
    std::optional<double> unloadFrom;
    std::vector<double> exactUnloadingHPerK;
    std::vector<double> chosenUnloadingRatio;
    bool chosenUnloads = false; ///< the chosen law has an unloading branch (else its loading h)
    std::vector<CheckedLaw> laws;        ///< every law, in conductanceLawNames() order
    std::string chosenLaw;               ///< the spec's (or the default)
    /// The smallest worstFactor over the counted pressures; empty when none is counted.
    std::string closestLaw;
    /// The answer (SurfaceCheck.hpp): the chosen law's h_c/k_s [1/m] on the whole surface as
    /// given, per pressure; and the exact answer it implies, answer / the law's ratio, at the
    /// seeds' extremes [1/m] (NaN where the exact answer is not trusted).
    std::vector<double> answerHPerK;
    std::vector<double> answerExactLow;
    std::vector<double> answerExactHigh;
    /// A map solved padded near complete contact: that its exact h_c is not to be trusted at
    /// some pressures (patchCorrectionWarning) and the ratios there neither; empty otherwise.
    std::string exactWarning;
    /// A profile or spectrum checked where the longer period takes part (p/(E' h') below
    /// checkBlendEnd): that its exact answer there is a periodic cell's (lightLoadPeriods scan
    /// lengths), which may still be too high for a large joint; empty otherwise (and for a map).
    std::string smallCellNote;
    double seconds = 0.0;                ///< the time the check took

    /// The chosen law's entry (ParameterError when it is not among laws).
    const CheckedLaw& chosen() const;
    /// The pressures at which the chosen law misses the exact conductance by more than
    /// checkTolerance (counted pressures only).
    std::vector<double> chosenMisses() const;
    /// With a peak (unloadFrom): the counted pressures at which the chosen law's h on unloading
    /// misses the exact unloading conductance by more than checkTolerance; empty without one.
    std::vector<double> chosenUnloadingMisses() const;
    /// What a front-end warns of after the check, one message each (none when the chosen law
    /// holds): the chosen law off the exact conductance at counted pressures, with the closest
    /// law if that one holds; with a peak, off the exact unloading conductance (`peakName`: how
    /// the front-end names the peak, as "checkUnloadFrom").
    std::vector<std::string> missWarnings(const std::string& peakName) const;
    /// The pressures whose exact answer is not trusted (exactTrusted false).
    std::vector<double> untrusted() const;
    /// Whether the closest law holds (within checkTolerance) at every counted pressure: then it is
    /// the law to use; else no law does.
    bool closestHolds() const;
    /// A table for a log or a terminal: the exact h_c/k_s per pressure with the seeds' spread,
    /// each law's ratio, the closest law and the chosen law's verdict (and exactWarning); with a
    /// peak, its verdict on unloading too.
    std::string report() const;
    /// The numbers as CSV: nominal_pressure [Pa], nominal_pressure_per_Eprime (F/(A_n E')),
    /// h_per_k_answer and the exact answer it implies (h_per_k_answer_exact_low, _high), the
    /// checked surface's exact area and h_c/k_s (area_checked_surface, h_per_k_checked_surface,
    /// its seeds' _min and _max), exact_trusted (1 or 0), one ratio_NAME column per law that
    /// could be built; with a peak, h_per_k_checked_surface_unloading and
    /// ratio_chosen_unloading last.
    std::string csv() const;
};

/// A light-load period asked for by a front-end (the CLI's --check-periods, the contact entry's
/// checkPeriods, Python's light_load_periods; `name` is how it names it): 1 to
/// Spectrum::maximumPeriodMultiple scan lengths, and only for surfaces the check synthesizes (a
/// profile, spectrum, power law or fractal; an areal map is solved as itself). Returns it;
/// ParameterError(name) otherwise.
std::size_t checkedLightLoadPeriods(std::uint64_t periods, const std::vector<SurfaceSpec>& surfaces,
                                    const std::string& name);

/// What a check needs: the surfaces, the materials, the area model and the law, and the
/// range it is asked over (SurfaceCheck.hpp; an InterfaceSpec gives these, the CLI its options).
struct SurfaceCheckInputs {
    std::vector<SurfaceSpec> surfaces; ///< one equivalent surface or one per side
    std::optional<ContactMaterials> materials;     ///< required
    /// The multi-scale area model of the laws; boundaryElement (or empty): jacksonGreen where
    /// capped, hertz where elastic.
    std::string model;
    std::string conductanceLaw;                  ///< the chosen law; empty: the default
    std::optional<double> microhardness;         ///< cooperMikicYovanovich; unset: the cap H
    std::optional<VickersCoefficients> vickers;
    std::optional<double> hardness;              ///< the cap; unset: 2.84 S_y where given
    std::optional<bool> periodic;                ///< a map's solve (InterfaceSpec::periodic)
    std::optional<bool> mirror;                  ///< a map's solve (InterfaceSpec::mirror)
    std::optional<Detrend> detrend;
    double minPressure = 0.0;                    ///< [Pa]; the range the pressures are taken from
    double maxPressure = 0.0;
};

/// The check of an interface's surface: its surfaces, materials, model, law, hardness (or
/// hardnessFromYield) and table range (ContactInterface.hpp's defaults where unset).
SurfaceCheckInputs checkInputsOf(const InterfaceSpec& spec);

/// The check (SurfaceCheck.hpp). ParameterError/InputError on bad inputs or when no pressure is
/// left.
SurfaceCheck checkSurface(const SurfaceCheckInputs& inputs, const SurfaceCheckOptions& options = {});
/// checkSurface(checkInputsOf(spec), options).
SurfaceCheck checkSurface(const InterfaceSpec& spec, const SurfaceCheckOptions& options = {});

} // namespace roughContact
