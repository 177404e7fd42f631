// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/BoundaryElementTable.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/TableReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <openssl/evp.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cctype>
#include <cstring>
#include <memory>
#include <numeric>
#include <sstream>

namespace roughContact {

namespace {

// How a table's user asks for the mirrored solve (patchCorrectionWarning).
const char* const patchWarningMirror =
    "mirror true; in the contact entry, --mirror on the command line, mirror=True in Python";

// Bumped whenever the meaning of a table changes for the same inputs (the solver, the
// conductance, the file's layout): every older file is then foreign and rebuilt.
// The version of what the table holds, in its key: 2 since the conductance of a non-periodic
// patch has the patch's own constriction removed (BoundaryElement.hpp); 3 since the file
// carries the mean separation (header v2). A table of an older version is foreign and rebuilt
// (an older header is reported as foreign too, before its key is read); 4 since the file ends
// in the digest of its contents (header v3); 5 since it carries the unloading curves (header v4).
constexpr std::uint64_t formatVersion = 5;
constexpr const char* headerStem = "# roughContact boundary-element table v";
constexpr const char* columns = "pressure,area,h_per_k,separation";
constexpr const char* digestTag = "# sha256 ";
constexpr const char* unloadingTag = "# unloading from ";
// h_c/k_s beyond this is perfect contact for any mesh (as ContactTable's ceiling).
constexpr double conductanceCeiling = 1e9;

const char* endName(ContactTable::End e)
{
    switch (e) {
    case ContactTable::End::maxPressure:
        return "maxPressure";
    case ContactTable::End::completeContact:
        return "completeContact";
    case ContactTable::End::conductanceCeiling:
        return "conductanceCeiling";
    }
    return "maxPressure";
}

std::string number(double v)
{
    return formatNumber(v, 17);
}

// SHA-256 of n bytes, as 64 lower-case hex digits.
std::string sha256Hex(const void* data, std::size_t n)
{
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int len = 0;
    const std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1 ||
        EVP_DigestUpdate(ctx.get(), data, n) != 1 || EVP_DigestFinal_ex(ctx.get(), md, &len) != 1) {
        throw ParameterError("boundary-element table", "OpenSSL could not compute a SHA-256 hash");
    }
    static const char* digits = "0123456789abcdef";
    std::string out;
    for (unsigned int i = 0; i < len; ++i) {
        out += digits[md[i] >> 4];
        out += digits[md[i] & 0xfu];
    }
    return out;
}

// Bytes for the key: little-endian, independent of the host.
class KeyBytes {
public:
    void u64(std::uint64_t v)
    {
        for (int i = 0; i < 8; ++i) {
            bytes_.push_back(static_cast<unsigned char>((v >> (8 * i)) & 0xffu));
        }
    }
    void f64(double v)
    {
        if (v == 0.0) {
            v = 0.0; // -0.0 as +0.0
        }
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        u64(bits);
    }
    std::string sha256Hex() const { return roughContact::sha256Hex(bytes_.data(), bytes_.size()); }

private:
    std::vector<unsigned char> bytes_;
};

ArealSurface solvedSurface(const InterfaceSpec& spec)
{
    if (spec.surfaces.empty() || spec.surfaces.size() > 2) {
        throw ParameterError("surfaces", "give one equivalent surface or one per side");
    }
    const bool areal = spec.surfaces.front().kind == SurfaceSpec::Kind::areal;
    for (const SurfaceSpec& s : spec.surfaces) {
        if ((s.kind == SurfaceSpec::Kind::areal) != areal) {
            throw ParameterError("surfaces", "model boundaryElement takes two areal surfaces or two 1-D "
                                             "descriptions to synthesize from, not one of each");
        }
    }
    if (areal) {
        if (spec.synthesize) {
            throw ParameterError("synthesize", "makes an areal surface from a profile, spectrum, powerLaw or "
                                               "fractal description; an areal surface is one already");
        }
        return arealComposite(spec.surfaces);
    }
    if (!spec.synthesize) {
        throw ParameterError("model boundaryElement",
                             "needs an areal surface: a surface of type areal (one, or one per side), or "
                             "'synthesize N' with a profile, spectrum, powerLaw or fractal description");
    }
    if (spec.periodic && !*spec.periodic) {
        throw ParameterError("periodic", "a synthesized surface is periodic and is solved so; 'periodic "
                                         "false' is for areal maps");
    }
    return synthesizeEquivalent(spec.surfaces, *spec.synthesize, spec.seed);
}

} // namespace

ArealSurface arealComposite(const std::vector<SurfaceSpec>& surfaces)
{
    if (surfaces.empty() || surfaces.size() > 2) {
        throw ParameterError("surfaces", "give one equivalent surface or one per side");
    }
    std::optional<ArealSurface> total;
    for (const SurfaceSpec& s : surfaces) {
        if (s.kind != SurfaceSpec::Kind::areal) {
            throw ParameterError("surfaces", "the composite of areal maps takes areal surfaces only");
        }
        // As read: the detrending (BoundaryElementModel) is of the composite, and both kinds
        // are linear, so it is the composite of the detrended maps.
        const ArealSurface one = readAreal(s.file, s.arealOptions);
        total = total ? compositeSurface(*total, one) : one;
    }
    return *total;
}

ContactTable BoundaryElementTablePoints::table(double Eprime) const
{
    return ContactTable::fromPoints(pressures, areaFractions, conductancesPerConductivity, completeContactPressure,
                                    end, Eprime, separations);
}

UnloadingTable BoundaryElementTablePoints::unloadingTable(const ContactTable& loading,
                                                          std::optional<double> hardness) const
{
    return UnloadingTable(
        unloading,
        [&](double P) {
            const ContactTable::Values v = loading.values(P);
            return std::array<double, 3>{v.areaFraction, v.conductancePerConductivity, loading.meanSeparation(P)};
        },
        hardness);
}

BoundaryElementTable::BoundaryElementTable(const InterfaceSpec& spec)
    // A synthesized surface is periodic (solvedSurface refuses 'periodic false' with it).
    : periodic_(spec.synthesize ? true : spec.periodic.value_or(false)), surface_(solvedSurface(spec))
{
    mirrored_ = spec.mirror.value_or(false);
    requireMirrorOfMaps(spec.surfaces, mirrored_);
    (void)edgesOf(periodic_, mirrored_); // periodic and mirror: refused before the key is made
    if (spec.model != "boundaryElement") {
        throw ParameterError("model", "a boundary-element table is for model boundaryElement, not '" +
                                          spec.model + "'");
    }
    const ContactMaterials materials = ContactMaterials::pair(spec.side1, spec.side2, "side1", "side2");
    Eprime_ = materials.reducedModulus();
    if (spec.hardness && spec.hardnessFromYield) {
        throw ParameterError("hardness", "give a hardness or hardnessFromYield, not both");
    }
    if (spec.hardness) {
        hardness_ = limits::requireInRange("hardness", *spec.hardness, limits::minimumHardness, limits::maximumHardness, "Pa");
    } else if (spec.hardnessFromYield) {
        hardness_ = materials.hardness("boundaryElement hardnessFromYield");
    }
    const BoundaryElementOptions defaults;
    tolerance_ = defaults.tolerance;
    precondition_ = defaults.precondition;
    pointsPerDecade_ = spec.bemPointsPerDecade;
    tableRanks_ = spec.tableRanks;
    unloads_ = hardness_.has_value() && spec.loadHistory;
    limits::requireInRange("pointsPerDecade", double(pointsPerDecade_), double(limits::minimumPointsPerDecade),
                           double(limits::maximumPointsPerDecade), "");
    const double minP = spec.minPressure.value_or(1e-6 * Eprime_);
    const double maxP = spec.maxPressure.value_or(hardness_ ? std::min(0.1 * Eprime_, 0.95 * *hardness_)
                                                            : 0.1 * Eprime_);
    limits::requireInRange("minimum pressure", minP, limits::minimumLoad * Eprime_, limits::maximumLoad * Eprime_,
                           "Pa");
    limits::requireInRange("maximum pressure", maxP, limits::minimumLoad * Eprime_, limits::maximumLoad * Eprime_,
                           "Pa");
    if (!(maxP > minP)) {
        std::ostringstream os;
        os << "must exceed the minimum pressure (" << maxP << " <= " << minP << " Pa)";
        throw ParameterError("maximum pressure", os.str());
    }
    const double decades = std::log10(maxP / minP);
    const auto n = static_cast<std::size_t>(std::ceil(decades * double(pointsPerDecade_) - 1e-9)) + 1;
    for (std::size_t k = 0; k < n; ++k) {
        const double P = k + 1 == n ? maxP : minP * std::pow(maxP / minP, double(k) / double(n - 1));
        pressures_.push_back(P);
        loads_.push_back(checkLoad(P / Eprime_));
    }

    detrend_ = spec.detrend.value_or(defaultDetrend(periodic_));
    const ArealSurface solved = surface_.detrended(detrend_); // what BoundaryElementModel solves
    KeyBytes k;
    k.u64(formatVersion);
    k.u64(solved.nx());
    k.u64(solved.ny());
    k.f64(solved.dx());
    k.f64(solved.dy());
    for (double z : solved.heights()) {
        k.f64(z);
    }
    k.u64(mirrored_ ? 2 : periodic_ ? 1 : 0);
    k.f64(Eprime_);
    k.u64(hardness_ ? 1 : 0);
    k.f64(hardness_.value_or(0.0));
    k.u64(loads_.size());
    for (double l : loads_) {
        k.f64(l);
    }
    k.f64(tolerance_);
    k.f64(conductanceTolerance);
    k.u64(precondition_ ? 1 : 0);
    // The curves' peaks, loads and span follow pointsPerDecade too, which a short range's load
    // list alone may not tell apart.
    k.u64(unloads_ ? unloadingDecades : 0);
    k.u64(unloads_ ? pointsPerDecade_ : 0);
    key_ = k.sha256Hex();

    std::ostringstream os;
    os.precision(6);
    os << "surface " << surface_.source() << ", " << solved.nx() << " x " << solved.ny() << " points at "
       << solved.dx() << " x " << solved.dy() << " m, " << (mirrored_ ? "mirrored about its edges" : periodic_ ? "periodic" : "non-periodic")
       << ", detrended " << detrendName(detrend_) << ", rms height " << solved.rms() << " m; E' = " << Eprime_ << " Pa; hardness ";
    if (hardness_) {
        os << *hardness_ << " Pa";
    } else {
        os << "none";
    }
    os << "; " << n << " loads from " << minP << " to " << maxP << " Pa (" << pointsPerDecade_
       << " per decade); tolerance " << tolerance_;
    if (unloads_) {
        os << "; unloading curves from two peaks a decade, each " << unloadingDecades << " decades down";
    }
    inputs_ = os.str();
}

double BoundaryElementTable::estimatedSeconds() const
{
    const HalfSpaceOperator op(surface_.nx(), surface_.ny(), surface_.dx(), surface_.dy(), Eprime_,
                               edgesOf(periodic_, mirrored_));
    // An unloading curve: its peak's capped solve and its loads, counted as loads of the table.
    std::size_t solves = pressures_.size();
    for (std::size_t peak : unloadingPeaks(pressures_.size())) {
        solves += 1 + unloadingLoads(peak).size();
    }
    return estimatedCurveSeconds(op, solves);
}

std::vector<std::size_t> shareOfLoads(std::size_t loads, std::size_t rank, std::size_t ranks)
{
    if (ranks == 0 || rank >= ranks) {
        throw ParameterError("boundary-element table", "rank " + std::to_string(rank) + " of " +
                                                           std::to_string(ranks) + " ranks");
    }
    std::vector<std::size_t> mine;
    for (std::size_t j = 0; j < loads; ++j) { // j = 0: the heaviest load
        const std::size_t round = j / ranks;
        const std::size_t place = j % ranks;
        if ((round % 2 == 0 ? place : ranks - 1 - place) == rank) {
            mine.push_back(loads - 1 - j);
        }
    }
    std::reverse(mine.begin(), mine.end());
    return mine;
}

BoundaryElementOptions BoundaryElementTable::solveOptions() const
{
    BoundaryElementOptions bo;
    bo.detrend = detrend_;
    bo.periodic = periodic_;
    bo.mirrored = mirrored_;
    bo.hardness = hardness_;
    bo.tolerance = tolerance_;
    bo.precondition = precondition_;
    return bo;
}

std::vector<std::size_t> BoundaryElementTable::unloadingPeaks(std::size_t rows) const
{
    std::vector<std::size_t> peaks;
    if (!unloads_) {
        return peaks;
    }
    // Down from the last row while a curve's first load (a stride below) lies in the table.
    const std::size_t step = unloadingPeakStep();
    const std::size_t stride = unloadingStride();
    for (std::size_t j = std::min(rows, loads_.size()); j >= stride + 1; j -= step) {
        peaks.push_back(j - 1);
        if (j <= step) {
            break;
        }
    }
    std::reverse(peaks.begin(), peaks.end());
    return peaks;
}

std::vector<std::size_t> BoundaryElementTable::unloadingLoads(std::size_t peak) const
{
    // Every stride-th load down from the peak, over the decades the curve spans.
    std::vector<std::size_t> out;
    const std::size_t span = unloadingDecades * pointsPerDecade_;
    const std::size_t stride = unloadingStride();
    for (std::size_t d = stride; d <= std::min(span, peak); d += stride) {
        out.push_back(peak - d);
    }
    std::reverse(out.begin(), out.end());
    return out;
}

std::vector<BoundaryElementPoint> BoundaryElementTable::solveUnloading(std::size_t peak) const
{
    std::vector<double> loads;
    for (std::size_t k : unloadingLoads(peak)) {
        loads.push_back(loads_.at(k));
    }
    return BoundaryElementModel(surface_, Eprime_, solveOptions()).loadPath(loads_.at(peak), loads);
}

UnloadingCurve BoundaryElementTable::unloadingCurve(std::size_t peak, const std::vector<double>& areas,
                                                    const std::vector<double>& conductances,
                                                    const std::vector<double>& separations) const
{
    UnloadingCurve c;
    c.peak = pressures_.at(peak);
    const std::vector<std::size_t> at = unloadingLoads(peak);
    for (std::size_t i = 0; i < at.size(); ++i) {
        const double P = pressures_[at[i]];
        if (!(std::isfinite(areas[i]) && std::isfinite(conductances[i]) && std::isfinite(separations[i]) &&
              areas[i] > 0.0 && areas[i] <= 1.0 && conductances[i] > 0.0 && separations[i] >= 0.0)) {
            std::ostringstream os;
            os << "unloaded from " << c.peak << " Pa, the solve gives A_r/A_n = " << areas[i] << ", h_c/k_s = "
               << conductances[i] << " 1/m and a separation of " << separations[i] << " m at " << P
               << " Pa; the table needs A_r/A_n in (0, 1], a finite h_c/k_s > 0 and a finite separation >= 0";
            throw ParameterError("boundary-element table", os.str());
        }
        c.pressures.push_back(P);
        c.areaFractions.push_back(areas[i]);
        c.conductancesPerConductivity.push_back(conductances[i]);
        c.separations.push_back(separations[i]);
    }
    return c;
}

std::vector<BoundaryElementPoint> BoundaryElementTable::solveLoads(const std::vector<std::size_t>& indices,
                                                                   const Progress& progress,
                                                                   const SolveProgressCallback& solveProgress) const
{
    BoundaryElementOptions bo = solveOptions();
    bo.progress = solveProgress;
    const BoundaryElementModel model(surface_, Eprime_, bo);
    const auto start = std::chrono::steady_clock::now();
    std::vector<double> loads;
    for (std::size_t k : indices) {
        loads.push_back(loads_.at(k));
    }
    // Increasing, so curve() solves them in this order, each warm-started from the one below.
    return model.curve(loads, [&](std::size_t done, std::size_t total, const BoundaryElementPoint& p) {
        if (progress) {
            progress(done, total, pressures_[indices[done - 1]], p,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
    });
}

BoundaryElementTablePoints BoundaryElementTable::build(const Progress& progress,
                                                       const SolveProgressCallback& solveProgress) const
{
    std::vector<std::size_t> all(loads_.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    const std::vector<BoundaryElementPoint> curve = solveLoads(all, progress, solveProgress);
    std::vector<double> areas, conductances, separations;
    for (const BoundaryElementPoint& p : curve) {
        areas.push_back(p.areaFraction);
        conductances.push_back(p.conductancePerConductivity);
        separations.push_back(p.meanSeparation);
    }
    BoundaryElementTablePoints points = assemble(areas, conductances, separations);
    points.patchWarning = patchCorrectionWarning(curve, Eprime_, patchWarningMirror);
    for (std::size_t peak : unloadingPeaks(points.pressures.size())) {
        std::vector<double> a, h, y;
        for (const BoundaryElementPoint& p : solveUnloading(peak)) {
            a.push_back(p.areaFraction);
            h.push_back(p.conductancePerConductivity);
            y.push_back(p.meanSeparation);
        }
        points.unloading.push_back(unloadingCurve(peak, a, h, y));
    }
    return points;
}

BoundaryElementTablePoints BoundaryElementTable::assemble(const std::vector<double>& areas,
                                                          const std::vector<double>& conductances,
                                                          const std::vector<double>& separations) const
{
    BoundaryElementTablePoints out;
    double area = 0.0;
    double h = 0.0;
    double separation = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < areas.size(); ++k) {
        struct {
            double areaFraction, conductancePerConductivity, meanSeparation;
        } const p{areas[k], conductances[k], separations[k]};
        if (!(p.areaFraction < 1.0) || !std::isfinite(p.conductancePerConductivity)) {
            out.end = ContactTable::End::completeContact;
            out.completeContactPressure = pressures_[k];
            break;
        }
        if (!(p.areaFraction > 0.0 && p.conductancePerConductivity > 0.0)) {
            std::ostringstream os;
            os << "the solve gives A_r/A_n = " << p.areaFraction << " and h_c/k_s = " << p.conductancePerConductivity
               << " 1/m at " << pressures_[k] << " Pa; the table needs positive values";
            throw ParameterError("boundary-element table", os.str());
        }
        if (!(p.meanSeparation >= 0.0 && std::isfinite(p.meanSeparation))) {
            std::ostringstream os;
            os << "the solve gives a mean separation of " << p.meanSeparation << " m at " << pressures_[k]
               << " Pa; the table needs finite values >= 0";
            throw ParameterError("boundary-element table", os.str());
        }
        area = std::max(area, p.areaFraction);
        h = std::max(h, p.conductancePerConductivity);
        separation = std::min(separation, p.meanSeparation);
        out.pressures.push_back(pressures_[k]);
        out.areaFractions.push_back(area);
        out.conductancesPerConductivity.push_back(h);
        out.separations.push_back(separation);
        if (h > conductanceCeiling) {
            out.end = ContactTable::End::conductanceCeiling;
            break;
        }
    }
    if (out.pressures.size() < 2) {
        std::ostringstream os;
        if (out.end == ContactTable::End::conductanceCeiling) {
            // A surface so smooth for its grid (or a range starting so high) that it conducts as
            // a bonded joint from the first load on.
            os << "h_c/k_s = " << out.conductancesPerConductivity.back() << " 1/m at the table's first load, "
               << out.pressures.front() << " Pa, is above the " << conductanceCeiling
               << " 1/m at which the table ends (the joint conducts as if bonded: no contact resistance to "
                  "tabulate); lower minPressure, or check the units of the surface's heights and spacing";
        } else {
            os << "complete contact at " << out.completeContactPressure
               << " Pa leaves fewer than 2 points of the table below it; lower minPressure";
        }
        throw ParameterError("boundary-element table", os.str());
    }
    return out;
}

std::string BoundaryElementTable::write(const BoundaryElementTablePoints& points) const
{
    std::string s;
    s += boundaryElementTableHeader;
    s += "\n# key " + key_ + "\n# inputs: " + inputs_ + "\n# end " + endName(points.end) + " " +
         number(points.completeContactPressure) + "\n" + columns + "\n";
    if (points.separations.size() != points.pressures.size()) {
        throw ParameterError("boundary-element table", "the points have no mean separation column to write");
    }
    for (std::size_t k = 0; k < points.pressures.size(); ++k) {
        s += number(points.pressures[k]) + "," + number(points.areaFractions[k]) + "," +
             number(points.conductancesPerConductivity[k]) + "," + number(points.separations[k]) + "\n";
    }
    for (const UnloadingCurve& c : points.unloading) {
        if (c.separations.size() != c.pressures.size()) {
            throw ParameterError("boundary-element table", "an unloading curve has no separation column to write");
        }
        s += unloadingTag + number(c.peak) + "\n";
        for (std::size_t k = 0; k < c.pressures.size(); ++k) {
            s += number(c.pressures[k]) + "," + number(c.areaFractions[k]) + "," +
                 number(c.conductancesPerConductivity[k]) + "," + number(c.separations[k]) + "\n";
        }
    }
    s += digestTag + digest(s) + "\n";
    return s;
}

BoundaryElementTableRead BoundaryElementTable::parse(const std::string& text) const
{
    BoundaryElementTableRead r;
    const auto corrupt = [&](const std::string& why) {
        r.status = BoundaryElementTableRead::Status::corrupt;
        r.reason = why;
        r.points.reset();
        return r;
    };
    try {
        if (text.empty() || text.back() != '\n') {
            return corrupt(text.empty() ? "the file is empty" : "the file does not end with a newline (cut short?)");
        }
        std::vector<std::string> lines;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) {
            lines.push_back(line);
        }
        if (!lines.empty() && lines[0] != boundaryElementTableHeader && lines[0].rfind(headerStem, 0) == 0) {
            r.status = BoundaryElementTableRead::Status::foreign;
            r.reason = "it is a table of format " + detail::printable(lines[0].substr(std::string(headerStem).size() - 1), 20) +
                       ", not this version's (" + boundaryElementTableHeader +
                       "; v2 added the mean separation, v3 the digest, v4 the unloading curves)";
            return r;
        }
        if (lines.empty() || lines[0] != boundaryElementTableHeader) {
            return corrupt(std::string("the first line is not '") + boundaryElementTableHeader + "'");
        }
        const std::string keyTag = "# key ";
        if (lines.size() < 2 || lines[1].rfind(keyTag, 0) != 0) {
            return corrupt("line 2 is not '# key <hash>'");
        }
        const std::string key = lines[1].substr(keyTag.size());
        if (key != key_) {
            r.status = BoundaryElementTableRead::Status::foreign;
            r.reason = "its key " + detail::printable(key, 80) + " is not this table's " + key_ +
                       " (made for another surface, material, hardness, load list or solver)";
            return r;
        }
        if (lines.size() < 5 || lines[2].rfind("# inputs: ", 0) != 0 || lines[3].rfind("# end ", 0) != 0 ||
            lines[4] != columns) {
            return corrupt(std::string("lines 3 to 5 are not '# inputs: ...', '# end ...' and '") + columns + "'");
        }
        BoundaryElementTablePoints p;
        {
            std::istringstream e(lines[3].substr(6));
            std::string name;
            std::string value;
            std::string extra;
            e >> name >> value;
            if (e >> extra) {
                return corrupt("line 4 has more than '# end NAME PRESSURE'");
            }
            if (name == "maxPressure") {
                p.end = ContactTable::End::maxPressure;
            } else if (name == "completeContact") {
                p.end = ContactTable::End::completeContact;
            } else if (name == "conductanceCeiling") {
                p.end = ContactTable::End::conductanceCeiling;
            } else {
                return corrupt("line 4: unknown end '" + detail::printable(name, 40) + "'");
            }
            if (!parseNumber(value, p.completeContactPressure) || std::isnan(p.completeContactPressure)) {
                return corrupt("line 4: '" + detail::printable(value, 40) + "' is not a pressure");
            }
        }
        // The last line is the digest of everything above it.
        if (lines.back().rfind(digestTag, 0) != 0) {
            return corrupt(std::string("the last line is not '") + digestTag + "<hash>' (cut short?)");
        }
        // Four comma-separated finite numbers, or why not.
        const auto row = [&](std::size_t i, double (&v)[4]) {
            const std::string& line = lines[i];
            bool good = true;
            std::size_t from = 0;
            for (std::size_t f = 0; f < 4 && good; ++f) {
                const std::size_t comma = line.find(',', from);
                const bool last = f == 3;
                if (last != (comma == std::string::npos)) {
                    good = false;
                    break;
                }
                good = parseNumber(line.substr(from, last ? std::string::npos : comma - from), v[f]) &&
                       std::isfinite(v[f]);
                from = comma + 1;
            }
            return good ? std::string()
                        : "line " + std::to_string(i + 1) + " '" + detail::printable(line, 80) +
                              "' is not four finite numbers P,area,h_per_k,separation";
        };
        std::size_t i = 5;
        for (; i + 1 < lines.size() && lines[i].rfind(unloadingTag, 0) != 0; ++i) {
            double v[4];
            if (const std::string bad = row(i, v); !bad.empty()) {
                return corrupt(bad);
            }
            const std::size_t k = i - 5;
            if (k >= pressures_.size() || v[0] != pressures_[k]) {
                return corrupt("line " + std::to_string(i + 1) + ": the pressure " + number(v[0]) +
                               " Pa is not the table's load " + std::to_string(k + 1) +
                               (k < pressures_.size() ? " (" + number(pressures_[k]) + " Pa)" : std::string()));
            }
            p.pressures.push_back(v[0]);
            p.areaFractions.push_back(v[1]);
            p.conductancesPerConductivity.push_back(v[2]);
            p.separations.push_back(v[3]);
        }
        // Complete: every load, or up to the load of complete contact, or the ceiling.
        const std::size_t n = p.pressures.size();
        bool complete = false;
        switch (p.end) {
        case ContactTable::End::maxPressure:
            complete = n == pressures_.size() && std::isinf(p.completeContactPressure);
            break;
        case ContactTable::End::completeContact:
            complete = n < pressures_.size() && p.completeContactPressure == pressures_[n];
            break;
        case ContactTable::End::conductanceCeiling:
            complete = n > 0 && std::isinf(p.completeContactPressure) &&
                       p.conductancesPerConductivity.back() > conductanceCeiling &&
                       (n < 2 || !(p.conductancesPerConductivity[n - 2] > conductanceCeiling));
            break;
        }
        if (!complete) {
            return corrupt(std::to_string(n) + " points of " + std::to_string(pressures_.size()) +
                           " loads do not make a whole table ending at " + endName(p.end) + " (cut short?)");
        }
        // The unloading curves: one block per peak of unloadingPeaks(n), each at its loads.
        for (std::size_t peak : unloadingPeaks(n)) {
            if (!(i + 1 < lines.size()) || lines[i] != unloadingTag + number(pressures_[peak])) {
                return corrupt("line " + std::to_string(i + 1) + " is not '" + unloadingTag +
                               number(pressures_[peak]) + "' (the unloading curve from the table's load " +
                               std::to_string(peak + 1) + ")");
            }
            ++i;
            UnloadingCurve c;
            c.peak = pressures_[peak];
            for (std::size_t k : unloadingLoads(peak)) {
                double v[4];
                if (!(i + 1 < lines.size())) {
                    return corrupt("the unloading curve from " + number(c.peak) + " Pa is cut short");
                }
                if (const std::string bad = row(i, v); !bad.empty()) {
                    return corrupt(bad);
                }
                if (v[0] != pressures_[k]) {
                    return corrupt("line " + std::to_string(i + 1) + ": the pressure " + number(v[0]) +
                                   " Pa is not the unloading curve's load " + number(pressures_[k]) + " Pa");
                }
                c.pressures.push_back(v[0]);
                c.areaFractions.push_back(v[1]);
                c.conductancesPerConductivity.push_back(v[2]);
                c.separations.push_back(v[3]);
                ++i;
            }
            p.unloading.push_back(std::move(c));
        }
        if (i + 1 != lines.size()) {
            return corrupt("line " + std::to_string(i + 1) + " '" + detail::printable(lines[i], 80) +
                           "' follows the table's last curve");
        }
        // The checks of a table (increasing, in range, non-decreasing) and of its unloading curves.
        (void)p.unloadingTable(p.table(Eprime_), hardness_);
        // Last, the contents against their digest: a file whose numbers were changed (by hand, or
        // damaged) cannot be told from a valid one by the checks above.
        const std::size_t digestLine = text.rfind(digestTag);
        if (lines.back().substr(std::string(digestTag).size()) != digest(text.substr(0, digestLine))) {
            return corrupt("its contents do not match their digest (the last line): the file was changed "
                           "after it was written");
        }
        r.status = BoundaryElementTableRead::Status::ok;
        r.reason.clear();
        r.points = std::move(p);
        return r;
    } catch (const std::exception& e) {
        return corrupt(e.what());
    } catch (...) {
        return corrupt("unreadable");
    }
}

std::string BoundaryElementTable::digest(const std::string& text)
{
    return sha256Hex(text.data(), text.size());
}

BoundaryElementTableRead BoundaryElementTable::read(const std::string& path) const
{
    BoundaryElementTableRead r;
    if (existingFile(path).kind == ExistingFile::Kind::none) {
        r.reason = "there is no file " + path;
        return r;
    }
    std::string text;
    try {
        text = readWholeFile(path, fileLimits::maximumTableBytes, "boundary-element table");
    } catch (const InputError& e) {
        r.status = BoundaryElementTableRead::Status::notATable;
        r.reason = e.message();
        return r;
    }
    if (!isBoundaryElementTableText(text)) {
        r.status = BoundaryElementTableRead::Status::notATable;
        r.reason = text.empty() ? std::string("is empty")
                                : "begins '" + detail::printable(text.substr(0, 60), 60) + "', not '" + headerStem + "...'";
        return r;
    }
    return parse(text);
}

void BoundaryElementTable::writeFile(const std::string& path, const BoundaryElementTablePoints& points) const
{
    replaceFile(path, write(points), "boundary-element table", "boundary-element table of this project",
                isBoundaryElementTableText);
}

bool isBoundaryElementTableText(const std::string& start)
{
    return start.rfind(headerStem, 0) == 0;
}

namespace {

// A table's points as doubles, for a broadcast: their count, the four columns, the
// complete-contact pressure (-1: none, so that no infinity need travel), the end, and the
// unloading curves' count, then each curve's peak, count and four columns. Exact.
std::vector<double> flatten(const BoundaryElementTablePoints& p)
{
    std::vector<double> v{double(p.pressures.size())};
    for (const std::vector<double>* c :
         {&p.pressures, &p.areaFractions, &p.conductancesPerConductivity, &p.separations}) {
        v.insert(v.end(), c->begin(), c->end());
    }
    v.push_back(std::isinf(p.completeContactPressure) ? -1.0 : p.completeContactPressure);
    v.push_back(double(int(p.end)));
    v.push_back(double(p.unloading.size()));
    for (const UnloadingCurve& u : p.unloading) {
        if (u.separations.size() != u.pressures.size()) {
            throw ParameterError("boundary-element table", "an unloading curve has no separation column to send");
        }
        v.push_back(u.peak);
        v.push_back(double(u.pressures.size()));
        for (const std::vector<double>* c :
             {&u.pressures, &u.areaFractions, &u.conductancesPerConductivity, &u.separations}) {
            v.insert(v.end(), c->begin(), c->end());
        }
    }
    return v;
}

BoundaryElementTablePoints unflatten(const std::vector<double>& v, std::size_t at)
{
    const auto incomplete = [] {
        return ParameterError("boundary-element table", "the points received from rank 0 are incomplete");
    };
    // n values from v[i] on into c, or incomplete.
    const auto take = [&](std::size_t& i, std::size_t n, std::vector<double>& c) {
        if (v.size() < i + n) {
            throw incomplete();
        }
        c.assign(v.begin() + std::ptrdiff_t(i), v.begin() + std::ptrdiff_t(i + n));
        i += n;
    };
    BoundaryElementTablePoints p;
    const auto n = static_cast<std::size_t>(v.at(at));
    std::size_t i = at + 1;
    for (std::vector<double>* c : {&p.pressures, &p.areaFractions, &p.conductancesPerConductivity, &p.separations}) {
        take(i, n, *c);
    }
    if (v.size() < i + 3) {
        throw incomplete();
    }
    p.completeContactPressure = v[i] < 0.0 ? std::numeric_limits<double>::infinity() : v[i];
    p.end = ContactTable::End(int(v[i + 1]));
    const auto curves = static_cast<std::size_t>(v[i + 2]);
    i += 3;
    for (std::size_t c = 0; c < curves; ++c) {
        if (v.size() < i + 2) {
            throw incomplete();
        }
        UnloadingCurve u;
        u.peak = v[i];
        const auto m = static_cast<std::size_t>(v[i + 1]);
        i += 2;
        for (std::vector<double>* col :
             {&u.pressures, &u.areaFractions, &u.conductancesPerConductivity, &u.separations}) {
            take(i, m, *col);
        }
        p.unloading.push_back(std::move(u));
    }
    if (i != v.size()) {
        throw incomplete();
    }
    return p;
}

// Where the table will be written: checked before minutes of solving (replaceFile's rules).
void requireWritable(const std::string& path)
{
    const ExistingFile existing = existingFile(path);
    if (existing.kind == ExistingFile::Kind::other) {
        throw ParameterError("boundary-element table",
                             "'" + path + "' is " + existing.what +
                                 "; the table is read from and written to this name: remove it or choose another");
    }
    const std::string directory = folderOf(path);
    if (::access(directory.c_str(), W_OK | X_OK) != 0) {
        throw ParameterError("boundary-element table", "cannot write into the directory '" + directory +
                                                           "' of '" + path + "' (missing, or not writable)");
    }
}

// What rank 0 decides before a build, broadcast as the first value.
constexpr double failed = 0.0;
constexpr double reuse = 1.0;
constexpr double rebuild = 2.0;

} // namespace

double BoundaryElementTable::bytesPerRank() const
{
    return boundaryElementBytes(surface_.nx(), surface_.ny(), periodic_ || mirrored_, hardness_.has_value());
}

std::size_t BoundaryElementTable::sharingRanks(std::size_t ranks) const
{
    std::size_t n = std::max<std::size_t>(1, ranks);
    if (tableRanks_) {
        return std::min(n, *tableRanks_);
    }
    n = std::min(n, loads_.size());
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && pageSize > 0) {
        const double fit = std::floor(0.5 * double(pages) * double(pageSize) / bytesPerRank());
        n = std::min(n, static_cast<std::size_t>(std::max(1.0, std::min(fit, double(n)))));
    }
    return n;
}

BoundaryElementTablePoints BoundaryElementTable::loadOrBuild(const std::string& path, const Progress& progress,
                                                             const LogCallback& log,
                                                             const SolveProgressCallback& solveProgress,
                                                             const TableRanks& ranks) const
{
    const bool shared = ranks.count > 1;
    if (ranks.count == 0 || ranks.rank >= ranks.count || (shared && (!ranks.broadcast || !ranks.sum))) {
        throw ParameterError("boundary-element table", "rank " + std::to_string(ranks.rank) + " of " +
                                                           std::to_string(ranks.count) +
                                                           (shared ? " ranks without their broadcast and sum" : ""));
    }
    const bool first = ranks.rank == 0;
    const auto say = [&](const std::string& line, bool warning) {
        if (log && first) {
            log(line, warning);
        }
    };
    const auto exchange = [&](std::vector<double>& v, bool sum) {
        if (shared) {
            (sum ? ranks.sum : ranks.broadcast)(v);
        }
    };

    // Rank 0 checks where the table goes and reads it: [decision, sharing ranks, points...].
    std::vector<double> decision{failed, 1.0};
    std::exception_ptr failure;
    if (first) {
        try {
            if (path.empty()) {
                throw ParameterError("boundary-element table", "the file name is empty: give the table's file");
            }
            const BoundaryElementTableRead r = read(path);
            if (r.status == BoundaryElementTableRead::Status::notATable) {
                throw ParameterError("boundary-element table",
                                     "'" + path + "' " + r.reason +
                                         ": it is not a table of this project, so it is left as it is; give another "
                                         "name, or remove it");
            }
            if (r.status == BoundaryElementTableRead::Status::ok) {
                say("reusing " + path + " (key " + key_ + "): " + std::to_string(r.points->pressures.size()) +
                        " points",
                    false);
                decision = {reuse, 1.0};
                const std::vector<double> points = flatten(*r.points);
                decision.insert(decision.end(), points.begin(), points.end());
            } else {
                requireWritable(path); // a matching table is read from a read-only folder too
                if (r.status != BoundaryElementTableRead::Status::missing) {
                    say("the boundary-element table " + path + " is " +
                            (r.status == BoundaryElementTableRead::Status::foreign ? "foreign" : "corrupt") + ": " +
                            r.reason + "; it is rebuilt and replaced",
                        true);
                }
                decision = {rebuild, double(sharingRanks(ranks.count))};
                // Said here, where a failure (the estimate's transform, the log) still stops
                // every rank at the broadcast below rather than leaving them at the sum.
                const auto sharing = static_cast<std::size_t>(decision[1]);
                std::ostringstream os;
                os.precision(2);
                os << "building the boundary-element table: " << loads_.size() << " loads";
                if (unloads_) {
                    os << " and " << unloadingPeaks(loads_.size()).size() << " unloading curves";
                }
                os << ", about "
                   << estimatedSeconds() / double(sharing) << " s";
                if (sharing > 1) {
                    os << " (shared by " << sharing << " ranks, this one solving "
                       << shareOfLoads(loads_.size(), 0, sharing).size() << " loads and holding about "
                       << bytesPerRank() / 1048576.0 << " MiB)";
                }
                os << "; " << inputs_;
                say(os.str(), false);
            }
        } catch (...) {
            failure = std::current_exception();
            decision = {failed, 1.0};
        }
    }
    exchange(decision, false);
    if (decision.at(0) == failed) {
        if (failure) {
            std::rethrow_exception(failure);
        }
        throw ParameterError("boundary-element table", "not read or built: rank 0 stopped (its error says why)");
    }
    if (decision[0] == reuse) {
        return unflatten(decision, 2);
    }

    const auto sharing = static_cast<std::size_t>(decision.at(1));
    const std::size_t n = loads_.size();
    const std::vector<std::size_t> mine =
        ranks.rank < sharing ? shareOfLoads(n, ranks.rank, sharing) : std::vector<std::size_t>{};
    const auto start = std::chrono::steady_clock::now();
    // Every load's A_r/A_n, h_c/k_s, separation and patch-correction gain, from the rank that
    // solved it (0 elsewhere: x + 0 = x, so the sum is exact), and the number of ranks whose
    // solves failed.
    constexpr std::size_t columns = 4;
    std::vector<double> values(columns * n + 1, 0.0);
    try {
        if (!mine.empty()) {
            const std::vector<BoundaryElementPoint> curve = solveLoads(mine, progress, solveProgress);
            for (std::size_t i = 0; i < mine.size(); ++i) {
                values[mine[i]] = curve[i].areaFraction;
                values[n + mine[i]] = curve[i].conductancePerConductivity;
                values[2 * n + mine[i]] = curve[i].meanSeparation;
                values[3 * n + mine[i]] = curve[i].patchCorrectionGain;
            }
        }
    } catch (...) {
        if (!shared) {
            throw;
        }
        failure = std::current_exception();
        values.assign(columns * n + 1, 0.0);
        values[columns * n] = 1.0;
    }
    exchange(values, true);
    if (values[columns * n] > 0.0) {
        if (failure) {
            std::rethrow_exception(failure);
        }
        throw ParameterError("boundary-element table", "not built: the solves failed on " +
                                                           std::to_string(std::lround(values[columns * n])) +
                                                           " rank(s) (their errors say why)");
    }
    const auto column = [&](std::size_t c) {
        return std::vector<double>(values.begin() + std::ptrdiff_t(c * n), values.begin() + std::ptrdiff_t((c + 1) * n));
    };
    // The same values on every rank, so the same table (or the same error).
    BoundaryElementTablePoints points = assemble(column(0), column(1), column(2));
    {
        // A padded map near complete contact: its h_c is a difference of two nearly equal
        // resistances (BoundaryElement.hpp, patchCorrectionGainLimit).
        std::vector<BoundaryElementPoint> solved(n);
        for (std::size_t k = 0; k < n; ++k) {
            solved[k].load = loads_[k];
            solved[k].areaFraction = values[k];
            solved[k].patchCorrectionGain = values[3 * n + k];
        }
        points.patchWarning = patchCorrectionWarning(solved, Eprime_, patchWarningMirror);
    }
    {
        // The unloading curves, dealt to the sharing ranks from the heaviest peak down (the
        // solves of a peak are one load path); each curve's three columns summed to all as above.
        const std::vector<std::size_t> peaks = unloadingPeaks(points.pressures.size());
        std::vector<std::size_t> offset{0};
        for (std::size_t peak : peaks) {
            offset.push_back(offset.back() + 3 * unloadingLoads(peak).size());
        }
        std::vector<double> curves(offset.back() + 1, 0.0);
        try {
            for (std::size_t c = 0; c < peaks.size(); ++c) {
                if ((peaks.size() - 1 - c) % sharing != ranks.rank) {
                    continue;
                }
                const auto t0 = std::chrono::steady_clock::now();
                const std::vector<BoundaryElementPoint> solved = solveUnloading(peaks[c]);
                const std::size_t m = solved.size();
                for (std::size_t k = 0; k < m; ++k) {
                    curves[offset[c] + k] = solved[k].areaFraction;
                    curves[offset[c] + m + k] = solved[k].conductancePerConductivity;
                    curves[offset[c] + 2 * m + k] = solved[k].meanSeparation;
                }
                std::ostringstream os;
                os.precision(3);
                os << "unloading curve from " << pressures_[peaks[c]] << " Pa (" << c + 1 << " of " << peaks.size()
                   << "): " << m << " loads in "
                   << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s";
                say(os.str(), false);
            }
        } catch (...) {
            if (!shared) {
                throw;
            }
            failure = std::current_exception();
            curves.assign(offset.back() + 1, 0.0);
            curves.back() = 1.0;
        }
        exchange(curves, true);
        if (curves.back() > 0.0) {
            if (failure) {
                std::rethrow_exception(failure);
            }
            throw ParameterError("boundary-element table", "not built: an unloading curve's solves failed on " +
                                                               std::to_string(std::lround(curves.back())) +
                                                               " rank(s) (their errors say why)");
        }
        for (std::size_t c = 0; c < peaks.size(); ++c) {
            const std::size_t m = (offset[c + 1] - offset[c]) / 3;
            const auto part = [&](std::size_t col) {
                const auto from = curves.begin() + std::ptrdiff_t(offset[c] + col * m);
                return std::vector<double>(from, from + std::ptrdiff_t(m));
            };
            points.unloading.push_back(unloadingCurve(peaks[c], part(0), part(1), part(2)));
        }
    }
    std::vector<double> written{1.0};
    if (first) {
        try {
            writeFile(path, points);
        } catch (...) {
            failure = std::current_exception();
            written[0] = 0.0;
        }
    }
    exchange(written, false);
    if (written.at(0) == 0.0) {
        if (failure) {
            std::rethrow_exception(failure);
        }
        throw ParameterError("boundary-element table", "rank 0 could not write " + path + " (its error says why)");
    }
    std::ostringstream os;
    os.precision(3);
    os << "built the boundary-element table in "
       << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s: "
       << points.pressures.size() << " points; wrote " << path << " (key " << key_ << ")";
    say(os.str(), false);
    if (!points.patchWarning.empty()) {
        say("boundary-element table: " + points.patchWarning, true);
    }
    return points;
}

} // namespace roughContact
