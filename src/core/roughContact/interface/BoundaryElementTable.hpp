// SPDX-License-Identifier: GPL-3.0-or-later
// The pressure table of `model boundaryElement`: A_r/A_n and the exact h_c/k_s of the
// boundary-element solution (models/BoundaryElement) at log-spaced loads, built once (minutes
// for large maps) and so kept in a small self-describing text file keyed by a hash of every
// input that changes it, which a later run reads instead of solving again.
//
// With a cap and loadHistory (InterfaceSpec), the table also holds unloading curves: from two
// peaks a decade (down from the table's last load), the joint's load path
// (BoundaryElementModel::loadPath) at three loads a decade over the two decades below it
// (UnloadingTable.hpp interpolates between them; docs/theory.md §7.6).
//
// The file (v4; v1 had no separation column, v2 no digest, v3 no unloading curves; all are read
// as foreign, i.e. rebuilt):
//     # roughContact boundary-element table v4
//     # key <64 hex digits: SHA-256 of the inputs, see key()>
//     # inputs: <one human-readable line: surface, grid, periodic, E', hardness, loads, tolerance>
//     # end <maxPressure|completeContact|conductanceCeiling> <complete-contact pressure [Pa] or inf>
//     pressure,area,h_per_k,separation
//     <P [Pa]>,<A_r/A_n>,<h_c/k_s [1/m]>,<Y [m]>   one line per point, 17 significant digits
//     # unloading from <P_max [Pa]>                 for each peak (none without a cap or history)
//     <P [Pa]>,<A_r/A_n>,<h_c/k_s [1/m]>,<Y [m]>   its load path below P_max, increasing
//     # sha256 <64 hex digits: SHA-256 of every byte above this line>
// A file is reused only when it is this version's, its key is the inputs' and its contents
// match their digest: a table edited by hand (or damaged) is rebuilt, not trusted.
#pragma once

#include "roughContact/bem/PolonskyKeer.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/thermal/ContactTable.hpp"
#include "roughContact/thermal/UnloadingTable.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace roughContact {

struct InterfaceSpec;
struct SurfaceSpec;
struct BoundaryElementPoint;
struct BoundaryElementOptions;

/// The points of a boundary-element table: what ContactTable::fromPoints takes, and what a
/// cache file holds.
struct BoundaryElementTablePoints {
    std::vector<double> pressures;                   ///< [Pa], increasing
    std::vector<double> areaFractions;               ///< A_r/A_n
    std::vector<double> conductancesPerConductivity; ///< h_c/k_s [1/m]
    /// The mean separation Y [m] (BoundaryElementPoint::meanSeparation): the gap per cell
    /// (0 in contact) averaged over the grid, the heights detrended (their least-squares plane
    /// removed, so Y is measured from the mean plane of the solved map). Periodic (and mirrored:
    /// the map mirrored about its edges is the period): relative to the mean displacement, the
    /// mean-plane separation of an interface of which the grid is one period. Non-periodic (a measured map): the local gaps of the patch loaded on an unbounded
    /// half-space, so the patch's own bowl-shaped deflection (less at its edges) is averaged in,
    /// as its constriction is in the spots' conductance (BoundaryElement.hpp); no correction is
    /// applied to Y. Measured on a 128 x 128 synthesized power law solved both ways: the same Y
    /// to 0.1 % at p/E' = 1e-4 and 0.5 % at 1e-3, 14 % above the periodic Y at 1e-2. Empty:
    /// none (ContactTable::fromPoints then makes no separation column).
    std::vector<double> separations;
    /// The first load of the list at which the solve reports complete contact (A_r/A_n = 1 or
    /// h_c/k_s infinite): from there on the table gives complete contact; +inf: not reached.
    double completeContactPressure = std::numeric_limits<double>::infinity();
    ContactTable::End end = ContactTable::End::maxPressure;
    /// A map solved padded: patchCorrectionWarning of the loads solved (where its h_c is not to
    /// be trusted), or empty. Set by a build (build(), loadOrBuild() when it solves); not kept in
    /// the file, so a table read back has none.
    std::string patchWarning;
    /// The unloading curves (peaks increasing; empty: none, without a cap or loadHistory).
    std::vector<UnloadingCurve> unloading;

    /// The table these points make (ContactTable::fromPoints).
    ContactTable table(double Eprime) const;
    /// The unloading curves over that table, of solves capped at `hardness` (empty without
    /// curves).
    UnloadingTable unloadingTable(const ContactTable& loading, std::optional<double> hardness) const;
};

/// What reading a cache file found.
struct BoundaryElementTableRead {
    /// notATable: a file that is no table of this project (its first line is not a table's
    /// header, or it is not a regular file of a table's size): never replaced.
    enum class Status { ok, missing, corrupt, foreign, notATable };
    Status status = Status::missing;
    std::string reason;                              ///< why not ok (empty when ok)
    std::optional<BoundaryElementTablePoints> points; ///< set when ok
};

/// The ranks (processes) of a job that build one table together (loadOrBuild), as a
/// front-end gives them: this rank's number and their count, and the two collective operations
/// the build needs. The core has no MPI; the condition gives OpenFOAM's Pstream (every rank of a
/// decomposed run calls loadOrBuild with the same table and in the same order). The default is
/// one rank alone (no exchange).
struct TableRanks {
    std::size_t rank = 0;  ///< 0 .. count - 1; rank 0 reads and writes the file and logs
    std::size_t count = 1;
    /// Rank 0's values to every rank: the others' vectors become rank 0's (any size).
    std::function<void(std::vector<double>&)> broadcast;
    /// The element-wise sum over all ranks, to every rank (every rank gives the same size).
    std::function<void(std::vector<double>&)> sum;
};

/// Which of a table's `loads` loads (in increasing order; indices into it) rank `rank` of
/// `ranks` solves when they share the build: dealt from the heaviest load down, one to each rank
/// in turn and back again (ranks 0, 1, ..., R-1, R-1, ..., 0, 0, 1, ...), so that each rank's
/// share has about the same cost when the cost grows with the load (the top decade's loads take
/// 3-10 times the iterations of the lowest); returned in increasing order. Each rank solves its
/// share as one warm-started curve. Empty when rank >= loads. ParameterError when rank >= ranks.
std::vector<std::size_t> shareOfLoads(std::size_t loads, std::size_t rank, std::size_t ranks);

/// The solved surface of one or two areal maps (surfaces of kind areal): their composite
/// (compositeSurface), as read; the solve detrends it. ParameterError for another kind or count.
ArealSurface arealComposite(const std::vector<SurfaceSpec>& surfaces);

class BoundaryElementTable {
public:
    /// The solved surface, the materials and the loads of spec (model boundaryElement; reads
    /// and synthesizes the surface, cheap next to build()). ParameterError/InputError on a bad
    /// spec: no areal surface and no synthesize, both, a periodic false with synthesize, ...
    explicit BoundaryElementTable(const InterfaceSpec& spec);

    /// SHA-256 (64 hex digits) over, as little-endian IEEE-754 binary64 and 64-bit integers:
    /// the format version, nx, ny, dx, dy, the heights solved (after detrending as the spec's
    /// detrend, or defaultDetrend(periodic), says), periodic,
    /// E', the hardness (or none), the loads, the contact and conductance tolerances and the
    /// preconditioning. Any change of them changes it.
    const std::string& key() const noexcept { return key_; }
    /// One line for the file and a log: surface, grid, periodic, E', hardness, loads, tolerance.
    const std::string& inputs() const noexcept { return inputs_; }
    /// The table's pressures [Pa] (loads x E'), increasing.
    const std::vector<double>& pressures() const noexcept { return pressures_; }
    const std::vector<double>& loads() const noexcept { return loads_; }
    double reducedModulus() const noexcept { return Eprime_; }
    /// The surface as given (the composite of the maps, or the synthesized one), before detrend().
    const ArealSurface& surface() const noexcept { return surface_; }
    /// What the solve removes from it (the spec's detrend, or defaultDetrend(periodic())).
    Detrend detrend() const noexcept { return detrend_; }
    bool periodic() const noexcept { return periodic_; }
    /// A map solved mirrored about its edges (InterfaceSpec::mirror; BoundaryElementOptions).
    bool mirrored() const noexcept { return mirrored_; }
    /// The cap p <= H [Pa] of the solve (none: elastic).
    std::optional<double> hardness() const noexcept { return hardness_; }
    /// True when the table holds unloading curves: a cap and the spec's loadHistory.
    bool unloads() const noexcept { return unloads_; }
    /// The indices (into loads()) of the unloading curves' peaks of a table of `rows` loading
    /// points: every unloadingPeakStep()-th load (two a decade) down from the last row, while
    /// unloadingLoads() of it is not empty; increasing. Empty unless unloads().
    std::vector<std::size_t> unloadingPeaks(std::size_t rows) const;
    std::size_t unloadingPeakStep() const noexcept { return std::max<std::size_t>(1, pointsPerDecade_ / 2); }
    /// The indices of the loads a peak's curve is solved at: every (pointsPerDecade/3)-th load
    /// (at least every one; three a decade) down from it over the unloadingDecades below it;
    /// increasing.
    std::vector<std::size_t> unloadingLoads(std::size_t peak) const;
    std::size_t unloadingStride() const noexcept { return std::max<std::size_t>(1, pointsPerDecade_ / 3); }
    /// The decades below its peak an unloading curve spans (below them UnloadingTable holds
    /// the lowest point's ratios).
    static constexpr std::size_t unloadingDecades = 2;

    /// Progress of build(): after each load, the loads done, their number, the point and the
    /// seconds since the start.
    using Progress = std::function<void(std::size_t done, std::size_t total, double pressure,
                                        const BoundaryElementPoint& point, double seconds)>;
    /// Solves the loads as one warm-started curve (BoundaryElementModel::curve); the table ends
    /// before the first load of complete contact (End::completeContact), after the first with
    /// h_c/k_s > 1e9 1/m (End::conductanceCeiling), or at the last load (End::maxPressure).
    /// The values are the solve's (a running maximum keeps the area and h_c non-decreasing, a
    /// running minimum the separation non-increasing, should a solve dip by its tolerance). ParameterError when fewer than 2 points lie below complete contact.
    /// solveProgress (optional): every progressInterval seconds of a long solve (PolonskyKeer.hpp).
    BoundaryElementTablePoints build(const Progress& progress = {}, const SolveProgressCallback& solveProgress = {}) const;

    /// About how long build() takes [s], before it starts: one displacement evaluation on this
    /// grid (an FFT pair) timed here, times the evaluations a table of these loads takes
    /// (BoundaryElementTable.cpp: measured on periodic and non-periodic tables). A guide for a
    /// log line, not a bound: a hard surface or a load near complete contact takes longer.
    double estimatedSeconds() const;

    /// The file's text for points (17 significant digits: reading it back is exact).
    /// ParameterError for points without their separations (every build() has them).
    std::string write(const BoundaryElementTablePoints& points) const;
    /// The points of a file's text, or why not: corrupt (bad header, number, count, order, a
    /// NaN, a pressure not of this table's loads) or foreign (a key not this table's, or a file
    /// of another format version, e.g. v1 without the separation column). Never throws.
    BoundaryElementTableRead parse(const std::string& text) const;
    /// SHA-256 of text as 64 lower-case hex digits: what a file's last line holds for the text
    /// above it (write() puts it there, parse() checks it).
    static std::string digest(const std::string& text);
    /// parse() of a file (io/Files.hpp's rules for a reader); missing when there is none,
    /// notATable when it is not a table of this project.
    BoundaryElementTableRead read(const std::string& path) const;
    /// Writes write(points) to path by io/Files.hpp's rules for a writer (replaceFile): only
    /// over a table of this project, atomically. ParameterError when it cannot.
    void writeFile(const std::string& path, const BoundaryElementTablePoints& points) const;

    /// What loadOrBuild says as it goes: one line for a log, and whether it is a warning (a file
    /// that was there but is not used).
    using LogCallback = std::function<void(const std::string& line, bool warning)>;
    /// The cache: the points of the file at path when read() finds them ok (this version, this
    /// key, contents matching their digest; a read-only folder is fine then); otherwise
    /// build(progress), then writeFile(path). A file at path that is not a table of this project
    /// is refused (ParameterError) and left as it is. Before anything is solved, path must be a
    /// name a file can be written to (in a writable directory): ParameterError naming it
    /// otherwise, so that minutes of solving are not lost at the end. log (optional) receives: reusing, why a file is not used, the
    /// build's start and end.
    ///
    /// ranks (optional): the ranks of a job, every one of which calls loadOrBuild alike. Rank 0
    /// alone checks, reads and writes path and logs; every rank returns the same points. A build
    /// is shared by sharingRanks(ranks.count) of them (shareOfLoads: each solves its share as a
    /// curve, progress reports its own loads), the values summed to all, and every rank makes the
    /// table of them as build() does. The warm starts differ from one curve's, so the table
    /// agrees with build()'s to the solves' tolerance, not bit for bit; the same number of
    /// sharing ranks gives the same table. When rank 0 cannot read or write the file, or a rank's
    /// solve fails, every rank throws (ParameterError; the failing rank its own error), none waits.
    BoundaryElementTablePoints loadOrBuild(const std::string& path, const Progress& progress = {},
                                           const LogCallback& log = {}, const SolveProgressCallback& solveProgress = {},
                                           const TableRanks& ranks = {}) const;

    /// How many of `ranks` ranks share a build: the spec's tableRanks when given (at most
    /// `ranks`), else all, but no more than the loads and than the ranks whose solves
    /// (boundaryElementBytes each) fit together in half of this machine's memory (as if they
    /// all ran on it: a decomposed run's ranks often share a node). At least 1.
    std::size_t sharingRanks(std::size_t ranks) const;
    /// About the peak memory of one rank's solves [bytes] (boundaryElementBytes).
    double bytesPerRank() const;

private:
    /// The solves of the loads of `indices` (increasing), as one warm-started curve; progress
    /// counts these loads.
    std::vector<BoundaryElementPoint> solveLoads(const std::vector<std::size_t>& indices, const Progress& progress,
                                                 const SolveProgressCallback& solveProgress) const;
    /// The table of every load's A_r/A_n, h_c/k_s and mean separation (as solved, load order):
    /// what build() says of it.
    BoundaryElementTablePoints assemble(const std::vector<double>& areas, const std::vector<double>& conductances,
                                        const std::vector<double>& separations) const;
    /// The load path of the peak at index `peak` (unloadingLoads(peak)) as solved.
    std::vector<BoundaryElementPoint> solveUnloading(std::size_t peak) const;
    /// The curve of those points (checked: positive area and h_c, finite separation).
    UnloadingCurve unloadingCurve(std::size_t peak, const std::vector<double>& areas,
                                  const std::vector<double>& conductances,
                                  const std::vector<double>& separations) const;
    /// The options every solve of this table uses.
    BoundaryElementOptions solveOptions() const;

    bool periodic_; // before surface_: both are set from the spec in this order
    bool mirrored_ = false;
    ArealSurface surface_;
    Detrend detrend_ = Detrend::plane;
    double Eprime_ = 0.0;
    std::optional<double> hardness_;
    double tolerance_ = 0.0;
    bool precondition_ = true;
    std::size_t pointsPerDecade_ = 0;
    std::optional<std::size_t> tableRanks_; // the spec's; not in the key (any share gives the table)
    bool unloads_ = false;
    std::vector<double> loads_;
    std::vector<double> pressures_;
    std::string key_;
    std::string inputs_;
};

/// The first line of a table file.
inline constexpr const char* boundaryElementTableHeader = "# roughContact boundary-element table v4";
/// True when `start` (a file's first bytes) begins as a table of this project does, of any
/// format version: the files loadOrBuild may replace.
bool isBoundaryElementTableText(const std::string& start);

} // namespace roughContact
