// SPDX-License-Identifier: GPL-3.0-or-later
// Everything a boundary condition needs from the core, built once from a plain description of
// the interface (surfaces, materials, asperity model) and then asked, per face, for the real
// contact area and h_c/k_s at the local nominal pressure. No OpenFOAM type appears here: the
// OpenFOAM glue fills an InterfaceSpec from its dictionary and calls this.
#pragma once

#include "roughContact/Error.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ContactTable.hpp"
#include "roughContact/thermal/Microhardness.hpp"
#include "roughContact/thermal/UnloadingTable.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace roughContact {

/// A finish with a lay, from a profile across it and one along it (or the equivalent of two
/// surfaces, one of which has a lay): the two line-scan spectra (docs/theory.md §1.6).
struct LaySpectra {
    Spectrum across;
    Spectrum along;
    /// The lay ratio: the rms slope across over the rms slope along (sqrt of their second
    /// moments). The across spectrum's isotropic surface with its y spacing stretched by it
    /// (synthesizeStretched) has both directions' rms slopes: the surface the check and the
    /// boundaryElement model synthesize for a finish with a lay. ParameterError naming alongLay
    /// outside [1/maximumLayStretch, maximumLayStretch] (a flat profile along the lay included).
    double stretch() const;
};
/// The largest lay ratio taken (LaySpectra::stretch).
inline constexpr double maximumLayStretch = 64.0;

/// One rough surface as a user describes it.
struct SurfaceSpec {
    enum class Kind { profile, spectrum, powerLaw, fractal, areal, roughness };
    Kind kind = Kind::profile;
    std::string file;                  ///< profile, spectrum or areal (X3P or matrix) file
    /// profile: a second profile of the same surface along its lay (`file` then is the one
    /// across it, as ISO 4288 measures). Given, the surface is the isotropic equivalent of the
    /// two directions (Spectrum::averaged, twoDirectionRoughness; docs/theory.md §1.6); empty:
    /// the one profile taken as a line scan of an isotropic surface.
    std::string alongLay;
    ProfileReadOptions profileOptions; ///< units, spacing of one-column profiles
    ArealReadOptions arealOptions;     ///< areal: units, dx, dy of a matrix; fillInvalid of an X3P
    /// areal: the line scans whose averaged spectrum stands for the surface (lineScanSpectrum
    /// of the detrended height map): rows (x), columns (y) or both (defaultScanDirection).
    ScanDirection direction = defaultScanDirection;
    std::size_t stride = 1;            ///< use every stride-th profile sample
    std::optional<double> length;      ///< scan length [m] of a spectrum or power law
    /// powerLaw: b_m [m], m, fmin, fmax [1/m]; fractal: D, G [m], fmin, fmax [1/m]; roughness:
    /// Rq [m], the rms slope Rdq, the cut-offs lambda_c, lambda_s [m] (RoughnessSpectrum.hpp).
    std::vector<double> parameters;

    /// The rules of the description's values, one place for the C++ API and the reader
    /// (InterfaceSpecReader.hpp): stride >= 1 and only on a profile, length only where the kind
    /// takes one (surfaceEntries), four parameters for powerLaw, fractal and roughness.
    /// ParameterError naming the entry ("stride", "length", "parameters").
    void check() const;
    /// The surface's spectrum (check(), then reads the file; InputError/ParameterError on bad
    /// input). A profile with alongLay: the two directions' averaged spectrum.
    Spectrum spectrum() const;
    /// A profile with alongLay: its two directions' spectra; none otherwise.
    std::optional<LaySpectra> laySpectra() const;
    /// Its rms height and mean absolute slope (Roughness.hpp): a profile's and an areal map's
    /// (along `direction`) from their heights, a spectrum's from its moments.
    SurfaceRoughness roughness() const;
    /// Its heights' skewness and its spread by chance (profileSkewness, arealSkewness): a
    /// profile's and an areal map's; none for a surface given by its spectrum or parameters, whose
    /// heights are Gaussian.
    std::optional<HeightSkewness> skewness() const;
};

/// The interface between two solids.
struct InterfaceSpec {
    /// One equivalent surface, or one per side (combined into the equivalent one, seed §2.1).
    std::vector<SurfaceSpec> surfaces;
    /// The solids on either side (E, nu, S_y); E' = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2) and the
    /// softer S_y deforms (ContactMaterials::pair).
    Material side1;
    Material side2;
    /// A multi-scale asperity model: hertz, jgh, jghConsistent, jacksonGreen or truncation; or
    /// boundaryElement: the exact boundary-element solution of an areal surface
    /// (BoundaryElementTable.hpp), whose table holds the exact area and conductance.
    std::string model = "jacksonGreen";
    /// The conductance law (ConductanceLaw.hpp); empty: defaultConductanceLaw().
    std::string conductanceLaw;
    /// cooperMikicYovanovich: the microhardness H_c [Pa], or the Vickers coefficients.
    std::optional<double> microhardness;
    std::optional<VickersCoefficients> vickers;
    /// Table range [Pa]; unset: 1e-9 E' to E' (complete contact ends it earlier).
    std::optional<double> minPressure;
    std::optional<double> maxPressure;
    std::size_t pointsPerDecade = 40;

    // boundaryElement only (ParameterError with any other model):
    /// Synthesize an N x N periodic areal surface (synthesizeEquivalent: isotropic, or stretched
    /// along a profile's lay) from the 1-D surface description(s) (profile, spectrum, powerLaw,
    /// fractal); unset: the
    /// surfaces are one or two areal maps (their composite), solved non-periodic by default.
    std::optional<std::size_t> synthesize;
    std::uint64_t seed = 1;   ///< synthesize: the phases' seed
    /// Solve an areal map as one period of a periodic surface; unset: false for a map, true
    /// for a synthesized surface (which cannot be solved non-periodic).
    std::optional<bool> periodic;
    /// Solve an areal map mirrored about its edges into one period of a periodic surface
    /// (BoundaryElementOptions::mirrored: an interface with neither edges nor the patch's own
    /// constriction, which near complete contact is ill-conditioned); unset: false.
    /// periodic, mirror and detrend are for model boundaryElement, and with check also say how
    /// the check solves a map (with any model).
    std::optional<bool> mirror;
    /// What is removed from the solved heights; unset: defaultDetrend(periodic) (the mean of a
    /// periodic surface, the plane of a measured map: ArealSurface.hpp).
    std::optional<Detrend> detrend;
    /// The perfectly plastic cap p <= H [Pa] of the solve, or H = 2.84 S_y of the softer side.
    std::optional<double> hardness;
    bool hardnessFromYield = false;
    /// Loads of the boundary-element table per decade of pressure (log spaced from minPressure,
    /// default 1e-6 E', to maxPressure, default min(0.1 E', 0.95 H)).
    std::size_t bemPointsPerDecade = 6;

    /// Every face remembers the largest pressure it has carried, and a joint unloaded from it
    /// conducts as the model's unloading curves say (docs/theory.md §7.6): boundaryElement with a
    /// cap builds them into its table (BoundaryElementTable.hpp); a multi-scale model's h_c takes
    /// its law's unloading branch where the law has one (fittedElastoPlastic with a cap,
    /// §5.7c; A_r/A_n then follows the pressure of the moment); otherwise h follows the pressure
    /// of the moment (the front-ends keep the peaks and say so). false: no memory, no unloading
    /// curves (today's behaviour, a table without them).
    bool loadHistory = true;

    /// The gap beside the contact (gas, radiation: InterfaceGap.hpp); none: nothing crosses
    /// where the surfaces do not touch.
    std::optional<GapSpec> gap;

    /// Front-ends: check the laws on this surface at start-up (checkSurface, SurfaceCheck.hpp)
    /// and warn when the chosen one misses the exact model. ContactInterface does not use it.
    bool check = false;
    /// Front-ends, with check on a profile or spectrum: its pressures below p/(E' h') = 1e-3
    /// are solved on periods of this many scan lengths (SurfaceCheckOptions::lightLoadPeriods);
    /// unset: that option's default. ContactInterface does not use it.
    std::optional<std::size_t> checkPeriods;
    /// Front-ends, with check: the pressures [Pa] it checks (1 to maximumCheckedPressures, each
    /// > 0); empty: the front-end's (the condition: the pressures the patch carries at its first
    /// evaluation). ContactInterface does not use it.
    std::vector<double> checkPressures;
    /// Front-ends, with check: the peak [Pa] the joint carried; the check also unloads each
    /// surface from it and judges the chosen law on unloading (SurfaceCheckOptions::unloadFrom).
    /// Unset: loading only. ContactInterface does not use it.
    std::optional<double> checkUnloadFrom;
    /// Front-ends: the threads of the boundary-element solves of this entry's table and check
    /// (setThreads, parallel/Threads.hpp); unset: the front-end's default (the condition: 1 in a
    /// parallel run, where every core has a rank, else what the machine has). ContactInterface
    /// does not use it.
    std::optional<int> threads;
    /// Front-ends with ranks (the condition in a decomposed run): how many ranks share the build
    /// of this entry's boundary-element table (BoundaryElementTable::sharingRanks); unset: all,
    /// as many as the loads and the memory allow. ContactInterface does not use it.
    std::optional<std::size_t> tableRanks;

    /// The rules of the model with the entries that belong to another, one place for every
    /// front-end (the reader ends with it; ContactInterface runs it for a spec built in C++):
    /// boundaryElement takes no conductance law, and no microhardness or vickers but for the
    /// check, which computes every law (its cap is 'hardness'); vickers is for the law
    /// cooperMikicYovanovich (refused beside another law named, but for the check's column of
    /// it); mirror is for areal maps
    /// (requireMirrorOfMaps); any other model takes no synthesize, hardness or
    /// hardnessFromYield, and periodic, mirror and detrend only with check (periodic and mirror
    /// of an areal map's check, not both). ParameterError naming the entry as written here
    /// ("synthesize"); a reader renames it to the source's name.
    void checkEntries() const;
};

/// How much higher profiles across a lay make h than the areal map of the same surface, from the
/// lay alone: the largest of docs/validation/anisotropy.md's "mean of the profiles across" over the
/// map's h (lay ratios up to 8, the engineering range's pairs; generated/anisotropy/inputs.csv,
/// which a test holds this to). One profile's chance comes on top (the same page).
inline constexpr double singleProfileOverstatement = 2.3;

/// What one profile cannot tell, for a front-end to say once: empty unless a surface is a single
/// profile (no alongLay), then that a finish with a lay measured across it can be given an h up
/// to singleProfileOverstatement times too high, and how to avoid it: a profile along the lay
/// (`alongName`: the front-end's name of alongLay) or an areal map.
std::string singleProfileNote(const std::vector<SurfaceSpec>& surfaces, const std::string& alongName);

/// mirror (solve an areal map mirrored about its edges) is for areal maps: a surface synthesized
/// from a 1-D description is periodic already. ParameterError "mirror" when `mirror` is set and
/// a surface is not an areal map.
void requireMirrorOfMaps(const std::vector<SurfaceSpec>& surfaces, bool mirror);

/// The equivalent surface of one or two surfaces: the spectrum of one, the combination of two
/// (Spectrum::combine, seed §2.1). ParameterError for none or more than two.
Spectrum equivalentSurface(const std::vector<SurfaceSpec>& surfaces);
/// The equivalent surface's two directions when a surface is a profile with alongLay (a surface
/// without a lay, isotropic, adds its spectrum to both directions; two sides' lays are taken
/// parallel); none when no surface has a lay. ParameterError for none or more than two.
std::optional<LaySpectra> equivalentLay(const std::vector<SurfaceSpec>& surfaces);
/// The areal surface the exact model solves for 1-D descriptions (the check, boundaryElement's
/// synthesize): synthesizeIsotropic of equivalentSurface, or with a lay synthesizeStretched of
/// its across spectrum by its stretch; `n` x `n`, the phases' `seed`.
ArealSurface synthesizeEquivalent(const std::vector<SurfaceSpec>& surfaces, std::size_t n, std::uint64_t seed);
/// The equivalent roughness of the same surfaces (SurfaceSpec::roughness(); two combined:
/// Roughness.hpp combined). ParameterError for none or more than two.
SurfaceRoughness equivalentRoughness(const std::vector<SurfaceSpec>& surfaces);

/// The heights' skewness of the equivalent surface of one or two surfaces (combinedSkewness; a
/// surface given by its spectrum counts as Gaussian, {0, 0}); none when no surface has heights.
std::optional<HeightSkewness> equivalentSkewness(const std::vector<SurfaceSpec>& surfaces);

/// What a boundary condition needs at one face.
struct FaceContact {
    double areaFraction = 0.0; ///< A_r/A_n
    double conductance = 0.0;  ///< h_c [W/(m^2 K)]: 0 without contact, +inf at complete contact
};

class ContactInterface {
public:
    /// boundaryElementTable (model boundaryElement only): the table's points, built before
    /// (BoundaryElementTable::build) or read from a cache; none: built here.
    explicit ContactInterface(const InterfaceSpec& spec, const BoundaryElementTablePoints* boundaryElementTable = nullptr);
    // Its law may point into its own members (the model, the surface): built in place, never
    // copied or moved.
    ContactInterface(const ContactInterface&) = delete;
    ContactInterface& operator=(const ContactInterface&) = delete;

    /// A_r/A_n at the nominal pressure P [Pa] (0 for P <= 0, 1 beyond complete contact).
    double areaFraction(double P) const { return table_->areaFraction(P); }
    /// h_c/k_s [1/m] at P [Pa] (0 for P <= 0, +infinity beyond complete contact).
    double conductancePerConductivity(double P) const { return table_->conductancePerConductivity(P); }
    /// True when the table carries the mean separation (ContactTable.hpp: the laws persson and
    /// multiscaleBarber, and boundaryElement).
    bool hasSeparation() const noexcept { return table_->hasSeparation(); }
    /// The mean-plane separation Y [m] at P [Pa] (ContactTable::meanSeparation): NaN without
    /// the column and for P <= 0 (faces apart: the caller's case), 0 beyond complete contact.
    double meanSeparation(double P) const { return table_->meanSeparation(P); }

    /// A_r/A_n and h_c = k_s (h_c/k_s)(P) at the nominal pressure P [Pa] (finite; P <= 0: no
    /// contact) between solids of conductivities k1, k2 [W/(m K)] (finite, > 0), with
    /// k_s = 2 k1 k2/(k1 + k2) (docs/theory.md §5.1), of a joint whose heaviest load so far was
    /// `peak` [Pa] (at or below P: loading; remembersLoad() false: ignored). ParameterError on a
    /// NaN or infinite pressure or a bad k.
    FaceContact face(double P, double k1, double k2, double peak = 0.0) const;

    /// True with loadHistory when the interface unloads: boundaryElement with a cap (its unloading
    /// curves) or a law with an unloading branch (ConductanceLaw::unloads): a joint below the
    /// heaviest load it carried then conducts as they say.
    bool remembersLoad() const noexcept { return !unloading_.empty() || lawUnloads(); }
    /// True with loadHistory when below a peak h_c follows the law's unloading branch (the
    /// default law with a cap: the branch whose measured band InterfaceRegime::unloadingBand gives).
    bool lawUnloads() const noexcept { return loadHistory_ && law_ && law_->unloads(); }
    /// The spec's loadHistory: a front-end keeps each face's peak pressure (and gives it to
    /// couple(), CouplingInputs::peakPressure) when it is on.
    bool loadHistory() const noexcept { return loadHistory_; }
    /// The unloading curves (empty: none).
    const UnloadingTable& unloading() const noexcept { return unloading_; }
    /// The factors on the loading values at P [Pa] of a joint that has carried peak [Pa]: the
    /// unloading curves' (UnloadingTable::factors), or h_c's by the law's unloading branch (A_r/A_n
    /// and the separation 1); all 1 at P >= peak and where the interface does not unload.
    UnloadingFactors unloadingFactors(double P, double peak) const;
    /// What the load history does here, for a front-end to say once: with loadHistory on, the
    /// unloading curves' peaks, or that the model has none and h follows the pressure of the
    /// moment (the peaks are still kept); empty with it off.
    std::string loadHistoryNote() const;
    /// The last pressure [Pa] the table resolves: above it and below complete contact the
    /// table returns its last values (a floor), so a boundary condition should say so.
    double tableEnd() const noexcept { return table_->pressures().back(); }
    /// True when P lies beyond a table that the maximum pressure cut short (below complete
    /// contact): its values are then held at the table's end, and raising maxPressure helps.
    /// False where the table reaches complete contact or perfect conductance (ContactTable::end).
    bool heldAtTableEnd(double P) const noexcept
    {
        return table_->end() == ContactTable::End::maxPressure && P > tableEnd() && P < completeContactPressure();
    }
    double completeContactPressure() const noexcept { return table_->completeContactPressure(); }

    /// True when the interface has a gap conductance (gas or radiation) beside the contact.
    bool hasGap() const noexcept { return gap_.has_value(); }
    /// The gap (ParameterError without one).
    const InterfaceGap& gap() const;

    const ContactTable& table() const noexcept { return *table_; }
    /// The conductance law of the table's h column.
    const std::string& conductanceLaw() const noexcept { return conductanceLaw_; }
    /// The multi-scale model (ParameterError with boundaryElement, which has none).
    const MultiscaleModel& model() const;
    /// The model's name: a multi-scale model's or boundaryElement.
    const std::string& modelName() const noexcept { return modelName_; }
    /// model boundaryElement on a map solved padded: where its table's h_c is not to be trusted
    /// (BoundaryElementTablePoints::patchWarning of the points it was made of), or empty.
    const std::string& tableWarning() const noexcept { return tableWarning_; }
    const Spectrum& surface() const noexcept { return surface_; }
    /// What identifies the surface this interface was built on, so that a restart can tell a
    /// changed surface (16 hex digits, SurfaceChecksum.hpp): the spectrum's checksum; for
    /// boundaryElement, continued over the solved areal surface (grid, heights, periodic), which
    /// a synthesized surface's seed and grid size change too.
    const std::string& surfaceChecksum() const noexcept { return surfaceChecksum_; }
    double reducedModulus() const noexcept { return materials_.reducedModulus(); }
    /// The regime at the table's two ends and the chosen law's measured accuracy band there
    /// (InterfaceRegime.hpp): the hardness is the boundaryElement cap, or 2.84 S_y where the
    /// materials have one; the law is held to the capped reference when the area model caps the
    /// pressure (jacksonGreen, truncation).
    const InterfaceRegime& regime() const noexcept { return regime_; }
    /// A few lines for a log: surface, levels, E', model, table range, complete contact, and the
    /// regime (regime().describe()).
    std::string summary() const;

private:
    Spectrum surface_;
    ContactMaterials materials_;
    std::unique_ptr<MultiscaleModel> model_;
    std::unique_ptr<ContactTable> table_;
    std::string conductanceLaw_;
    std::string modelName_;
    std::string bemSurface_; ///< boundaryElement: what was solved (for summary())
    std::string tableWarning_;
    std::string surfaceChecksum_;
    std::optional<InterfaceGap> gap_;
    InterfaceRegime regime_;
    UnloadingTable unloading_;
    bool loadHistory_ = true;
    bool cappedTable_ = false; ///< boundaryElement with a cap (for loadHistoryNote)
    /// A multi-scale model's conductance law (its unloading branch); none for boundaryElement.
    std::unique_ptr<ConductanceLaw> law_;

    /// Builds gap_ from spec.gap (after the table).
    void buildGap(const InterfaceSpec& spec);
};

} // namespace roughContact
