// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/ContactInterface.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/RoughnessSpectrum.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/SurfaceChecksum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace roughContact {

void SurfaceSpec::check() const
{
    // Which entries go with which kind is surfaceEntries' (InterfaceSpecReader.hpp), once.
    const std::vector<std::string>& entries = surfaceEntries(kind);
    const auto takes = [&](const char* key) { return std::find(entries.begin(), entries.end(), key) != entries.end(); };
    if (stride != 1 && !takes("stride")) {
        throw ParameterError("stride", "subsamples a profile; this surface is used whole");
    }
    if (stride < 1) {
        throw ParameterError("stride", "must be at least 1 (every stride-th sample), got 0");
    }
    if (length && !takes("length")) {
        throw ParameterError("length", "has no meaning here: a profile's scan length is N dx, an areal map's nx dx "
                                       "and ny dy, a roughness surface's its cutoff; it is for a spectrum, power "
                                       "law or fractal");
    }
    if (!alongLay.empty() && !takes("alongLay")) {
        throw ParameterError("alongLay", "is a second profile, along the lay of the surface a profile measures "
                                         "across it; this surface is not a profile (an areal map has both "
                                         "directions: its 'direction both')");
    }
    const bool parametric = kind == Kind::powerLaw || kind == Kind::fractal || kind == Kind::roughness;
    if (parametric && parameters.size() != 4) {
        throw ParameterError("parameters", "a " + surfaceTypeNames()[static_cast<std::size_t>(kind)] +
                                               " surface needs 4 parameters, got " + std::to_string(parameters.size()));
    }
}

Spectrum SurfaceSpec::spectrum() const
{
    check();
    switch (kind) {
    case Kind::profile: {
        if (const std::optional<LaySpectra> lay = laySpectra()) {
            return Spectrum::averaged(lay->across, lay->along, file + " across and " + alongLay + " along the lay");
        }
        return Spectrum::fromProfile(readProfile(file, profileOptions).subsampled(stride));
    }
    case Kind::areal:
        return lineScanSpectrum(readAreal(file, arealOptions).detrended(), direction);
    case Kind::spectrum:
        return readSpectrum(file, length);
    case Kind::powerLaw:
        return Spectrum::powerLaw(parameters[0], parameters[1], parameters[2], parameters[3],
                                  length.value_or(0.0));
    case Kind::fractal:
        return Spectrum::fractal(parameters[0], parameters[1], parameters[2], parameters[3],
                                 length.value_or(0.0));
    case Kind::roughness:
        return roughnessSpectrum(parameters[0], parameters[1], parameters[2], parameters[3]).spectrum;
    }
    throw ParameterError("surface", "unknown kind");
}

std::optional<LaySpectra> SurfaceSpec::laySpectra() const
{
    check();
    if (kind != Kind::profile || alongLay.empty()) {
        return std::nullopt;
    }
    return LaySpectra{Spectrum::fromProfile(readProfile(file, profileOptions).subsampled(stride)),
                      Spectrum::fromProfile(readProfile(alongLay, profileOptions).subsampled(stride))};
}

double LaySpectra::stretch() const
{
    const double across2 = spectralMoments(across).m2;
    const double along2 = spectralMoments(along).m2;
    // A ratio outside the range, a flat profile's infinite one or 0/0 of two included, is
    // refused before it is divided out.
    const double m = maximumLayStretch * maximumLayStretch;
    if (!(across2 > 0.0 && along2 > 0.0 && across2 <= m * along2 && along2 <= m * across2)) {
        std::ostringstream os;
        os << "the rms slope across the lay (" << across.source() << ", " << std::sqrt(across2) << ") over the one "
           << "along it (" << along.source() << ", " << std::sqrt(along2) << ")"
           << " is outside a lay ratio from 1/" << maximumLayStretch << " to " << maximumLayStretch
           << ", which is taken; give a profile that crosses the lay's features, or an areal map";
        throw ParameterError("alongLay", os.str());
    }
    return std::sqrt(across2 / along2);
}

SurfaceRoughness SurfaceSpec::roughness() const
{
    check();
    switch (kind) {
    case Kind::profile: {
        const SurfaceRoughness across = profileRoughness(readProfile(file, profileOptions).subsampled(stride));
        return alongLay.empty()
                   ? across
                   : twoDirectionRoughness(across, profileRoughness(readProfile(alongLay, profileOptions).subsampled(stride)));
    }
    case Kind::areal:
        return arealRoughness(readAreal(file, arealOptions), direction);
    default:
        return spectrumRoughness(spectrum());
    }
}

std::optional<HeightSkewness> SurfaceSpec::skewness() const
{
    check();
    switch (kind) {
    case Kind::profile: {
        const HeightSkewness across = profileSkewness(readProfile(file, profileOptions).subsampled(stride));
        return alongLay.empty()
                   ? across
                   : twoDirectionSkewness(across, profileSkewness(readProfile(alongLay, profileOptions).subsampled(stride)));
    }
    case Kind::areal:
        return arealSkewness(readAreal(file, arealOptions));
    default:
        return std::nullopt;
    }
}

namespace {
void requireOneOrTwo(const std::vector<SurfaceSpec>& surfaces)
{
    if (surfaces.empty() || surfaces.size() > 2) {
        throw ParameterError("surfaces", "give one equivalent surface or one per side");
    }
}
} // namespace

namespace {
bool allAreal(const std::vector<SurfaceSpec>& surfaces)
{
    return std::all_of(surfaces.begin(), surfaces.end(),
                       [](const SurfaceSpec& s) { return s.kind == SurfaceSpec::Kind::areal; });
}
} // namespace

std::string singleProfileNote(const std::vector<SurfaceSpec>& surfaces, const std::string& alongName)
{
    const bool single = std::any_of(surfaces.begin(), surfaces.end(), [](const SurfaceSpec& s) {
        return s.kind == SurfaceSpec::Kind::profile && s.alongLay.empty();
    });
    if (!single) {
        return "";
    }
    std::ostringstream os;
    os << "one profile is taken as a line scan of an isotropic surface; a finish with a lay (ground, turned, "
          "milled), measured across it as ISO 4288 does, is then rougher than it is, and its h can come out up to "
       << formatNumber(singleProfileOverstatement, 2)
       << " times too high from the lay alone (docs/validation/anisotropy.md). Give a profile along the lay too ("
       << alongName
       << ") or an areal map; for a finish without a lay this note does not apply";
    return os.str();
}

void requireMirrorOfMaps(const std::vector<SurfaceSpec>& surfaces, bool mirror)
{
    if (mirror && !allAreal(surfaces)) {
        throw ParameterError("mirror", "is for areal maps; a surface synthesized from a 1-D description is periodic "
                                       "already");
    }
}

void InterfaceSpec::checkEntries() const
{
    const bool exact = model == "boundaryElement";
    if (exact && !conductanceLaw.empty()) {
        throw ParameterError("conductance", "model boundaryElement gives the exact conductance of its contact spots; a "
                                            "conductance law ('" + conductanceLaw + "') has no place beside it: remove it");
    }
    // microhardness and vickers are the laws' (vickers cooperMikicYovanovich's): the chosen law's,
    // or the check's, which computes every law beside the chosen one or the exact model.
    if (exact && microhardness && !check) {
        throw ParameterError("microhardness", "is for the conductance laws and the gap's separation; model "
                                              "boundaryElement takes 'hardness' (its plastic cap) instead");
    }
    const bool otherLaw = !conductanceLaw.empty() && conductanceLaw != "cooperMikicYovanovich";
    if (vickers && !check && (exact || otherLaw)) {
        throw ParameterError("vickers", "is for the conductance law cooperMikicYovanovich" +
                                            (exact ? std::string("; model boundaryElement takes 'hardness' (its "
                                                                 "plastic cap) instead")
                                                   : ", not " + conductanceLaw));
    }
    if (exact || check) {
        requireMirrorOfMaps(surfaces, mirror.value_or(false)); // the solve's, or the check's
    }
    if (exact) {
        return;
    }
    // periodic and mirror also say how the check (SurfaceCheck.hpp) solves a map, and detrend how
    // it detrends what it solves, so they are taken with it: periodic and mirror for areal maps
    // only (the check synthesizes periodic surfaces from a 1-D description), and not both.
    const bool ofCheckedMaps = check && !surfaces.empty() && allAreal(surfaces);
    if (ofCheckedMaps) {
        (void)edgesOf(periodic.value_or(false), mirror.value_or(false));
    }
    for (const auto& [given, what] : {std::pair<bool, const char*>{synthesize.has_value(), "synthesize"},
                                      {periodic.has_value() && !ofCheckedMaps, "periodic"},
                                      {mirror.has_value() && !ofCheckedMaps, "mirror"},
                                      {detrend.has_value() && !check, "detrend"},
                                      {hardness.has_value(), "hardness"},
                                      {hardnessFromYield, "hardnessFromYield"}}) {
        if (given) {
            const bool ofTheCheck = std::string(what) == "periodic" || std::string(what) == "mirror" ||
                                    std::string(what) == "detrend";
            throw ParameterError(what, std::string("is for model boundaryElement") +
                                           (ofTheCheck ? " (or the check of an areal map)" : "") + ", not " +
                                           model);
        }
    }
}

std::optional<HeightSkewness> equivalentSkewness(const std::vector<SurfaceSpec>& surfaces)
{
    requireOneOrTwo(surfaces);
    std::vector<std::optional<HeightSkewness>> s;
    for (const SurfaceSpec& one : surfaces) {
        s.push_back(one.skewness());
    }
    if (std::none_of(s.begin(), s.end(),
                     [](const std::optional<HeightSkewness>& v) { return v.has_value(); })) {
        return std::nullopt;
    }
    if (surfaces.size() == 1) {
        return s.front();
    }
    const HeightSkewness gaussian{0.0, 0.0};
    return combinedSkewness(surfaces[0].roughness().sigma, s[0].value_or(gaussian),
                            surfaces[1].roughness().sigma, s[1].value_or(gaussian));
}

SurfaceRoughness equivalentRoughness(const std::vector<SurfaceSpec>& surfaces)
{
    requireOneOrTwo(surfaces);
    std::optional<SurfaceRoughness> total;
    for (const SurfaceSpec& s : surfaces) {
        const SurfaceRoughness one = s.roughness();
        total = total ? combined(*total, one) : one;
    }
    return *total;
}

Spectrum equivalentSurface(const std::vector<SurfaceSpec>& surfaces)
{
    requireOneOrTwo(surfaces);
    std::optional<Spectrum> total;
    for (const SurfaceSpec& s : surfaces) {
        const Spectrum one = s.spectrum();
        total = total ? Spectrum::combine(*total, one) : one;
    }
    return *total;
}

std::optional<LaySpectra> equivalentLay(const std::vector<SurfaceSpec>& surfaces)
{
    requireOneOrTwo(surfaces);
    std::vector<LaySpectra> sides;
    bool lay = false;
    for (const SurfaceSpec& s : surfaces) {
        std::optional<LaySpectra> one = s.laySpectra();
        lay = lay || one.has_value();
        if (!one) {
            const Spectrum isotropic = s.spectrum();
            one = LaySpectra{isotropic, isotropic};
        }
        sides.push_back(*one);
    }
    if (!lay) {
        return std::nullopt;
    }
    if (sides.size() == 1) {
        return sides.front();
    }
    return LaySpectra{Spectrum::combine(sides[0].across, sides[1].across),
                      Spectrum::combine(sides[0].along, sides[1].along)};
}

ArealSurface synthesizeEquivalent(const std::vector<SurfaceSpec>& surfaces, std::size_t n, std::uint64_t seed)
{
    if (const std::optional<LaySpectra> lay = equivalentLay(surfaces)) {
        const double stretch = lay->stretch();
        std::ostringstream os;
        os << "synthesized from " << lay->across.source() << ", stretched " << stretch << " times along the lay";
        return synthesizeStretched(lay->across, stretch, n, seed, os.str());
    }
    const Spectrum total = equivalentSurface(surfaces);
    return synthesizeIsotropic(total, n, seed, "synthesized from " + total.source());
}

ContactInterface::ContactInterface(const InterfaceSpec& spec, const BoundaryElementTablePoints* boundaryElementTable)
    : surface_(equivalentSurface(spec.surfaces)), materials_(ContactMaterials::pair(spec.side1, spec.side2, "side1", "side2")),
      modelName_(spec.model)
{
    spec.checkEntries();
    loadHistory_ = spec.loadHistory;
    if (spec.model == "boundaryElement") {
        conductanceLaw_ = "boundaryElement (exact)";
        const BoundaryElementTable bem(spec);
        const BoundaryElementTablePoints points = boundaryElementTable ? *boundaryElementTable : bem.build();
        table_ = std::make_unique<ContactTable>(points.table(bem.reducedModulus()));
        unloading_ = points.unloadingTable(*table_, bem.hardness());
        cappedTable_ = bem.hardness().has_value();
        tableWarning_ = points.patchWarning;
        std::ostringstream os;
        os << bem.surface().nx() << " x " << bem.surface().ny() << " "
           << (bem.mirrored() ? "mirrored" : bem.periodic() ? "periodic" : "non-periodic") << " "
           << bem.surface().source();
        bemSurface_ = os.str();
        surfaceChecksum_ =
            checksumHex(roughContact::surfaceChecksum(surface_, bem.surface().detrended(bem.detrend()), bem.periodic(),
                                                        bem.mirrored()));
        // The regime of what is solved: a synthesized surface holds the levels up to its grid's
        // Nyquist frequency (ArealSynthesis.hpp), a map its own.
        const Spectrum solvedSpectrum =
            spec.synthesize ? surface_.truncated(double(*spec.synthesize / 2) / surface_.length() * (1.0 + 1e-12))
                            : surface_;
        regime_ = interfaceRegime(solvedSpectrum, materials_.reducedModulus(), bem.hardness(), conductanceLaw_,
                                  "boundaryElement", bem.hardness().has_value(), table_->pressures().front(),
                                  table_->pressures().back());
        buildGap(spec);
        return;
    }
    if (boundaryElementTable != nullptr) {
        throw ParameterError("boundary-element table", "is for model boundaryElement, not " + spec.model);
    }
    if (!isMultiscaleModel(spec.model)) {
        std::string names;
        for (const std::string& n : multiscaleModelNames()) {
            names += (names.empty() ? "" : ", ") + n;
        }
        throw ParameterError("model", "unknown multi-scale model '" + spec.model + "' (one of " + names +
                                          ", or boundaryElement)");
    }
    surfaceChecksum_ = surfaceChecksumHex(surface_);
    const double Ep = materials_.reducedModulus();
    model_ = std::make_unique<MultiscaleModel>(surface_, Ep, makeAsperityModel(spec.model, materials_));
    conductanceLaw_ = spec.conductanceLaw.empty() ? defaultConductanceLaw() : spec.conductanceLaw;
    ConductanceLawInputs in;
    in.multiscale = model_.get();
    in.spectrum = &surface_;
    in.Eprime = Ep;
    in.microhardness = spec.microhardness;
    in.vickers = spec.vickers;
    in.hardness = conductanceLawHardness(spec.microhardness, materials_);
    if (conductanceLawNeedsRoughness(conductanceLaw_)) {
        in.roughness = equivalentRoughness(spec.surfaces);
    }
    // A measured profile's or map's (the regime says it too); none for a spectrum.
    const std::optional<HeightSkewness> skewness = equivalentSkewness(spec.surfaces);
    in.skewness = skewness;
    law_ = makeConductanceLaw(conductanceLaw_, in);
    table_ = std::make_unique<ContactTable>(*model_, spec.minPressure.value_or(1e-9 * Ep),
                                            spec.maxPressure.value_or(Ep), spec.pointsPerDecade, law_.get());
    // Held to the capped reference when the area model caps the pressure, or when the law has a
    // plastic branch and a cap to use; P/H with the law's cap (conductanceLawHardness).
    const std::optional<double> H = conductanceLawHardness(spec.microhardness, materials_);
    const bool capped = heldToCappedReference(spec.model, conductanceLaw_, H.has_value());
    regime_ = interfaceRegime(surface_, Ep, H, conductanceLaw_, spec.model, capped, table_->pressures().front(),
                              table_->pressures().back());
    regime_.skewness = skewness;
    buildGap(spec);
}

void ContactInterface::buildGap(const InterfaceSpec& spec)
{
    if (!spec.gap) {
        return;
    }
    std::function<double(double)> separation;
    double sigma = 0.0;
    double Hc = 0.0;
    if (table_->hasSeparation()) {
        // The model's own mean separation (boundaryElement, persson, multiscaleBarber).
        const ContactTable* table = table_.get(); // owned by this, which is not copied
        separation = [table](double P) { return table->meanSeparation(P); };
    } else {
        // The correlation's inputs: the surfaces' combined rms height and the microhardness.
        sigma = equivalentRoughness(spec.surfaces).sigma;
        Hc = spec.microhardness ? *spec.microhardness
             : spec.hardness    ? *spec.hardness
                                : materials_.hardness("the gap's separation (the correlation of sigma and P/H_c)");
    }
    gap_.emplace(*spec.gap, std::move(separation), sigma, Hc, table_->pressures().front());
}

const InterfaceGap& ContactInterface::gap() const
{
    if (!gap_) {
        throw ParameterError("gap", "the interface has none");
    }
    return *gap_;
}

FaceContact ContactInterface::face(double P, double k1, double k2, double peak) const
{
    requireFinite("pressure", P);
    const double ks = harmonicMeanConductivity(k1, k2);
    const ContactTable::Values v = table_->values(P);
    const UnloadingFactors f = unloadingFactors(P, peak);
    return {std::min(1.0, v.areaFraction * f.areaFraction), ks * v.conductancePerConductivity * f.conductancePerConductivity};
}

UnloadingFactors ContactInterface::unloadingFactors(double P, double peak) const
{
    if (!unloading_.empty() || !lawUnloads()) {
        return unloading_.factors(P, peak);
    }
    UnloadingFactors f;
    // As the curves': 1 for faces apart (h_c 0 anyway), at or above the peak and for a pressure
    // or peak that is not a number (the callers refuse those first).
    if (std::isfinite(P) && std::isfinite(peak) && P > 0.0 && P < peak) {
        f.conductancePerConductivity = law_->unloadingFactor(P, peak);
    }
    return f;
}

std::string ContactInterface::loadHistoryNote() const
{
    if (!loadHistory_) {
        return std::string();
    }
    std::ostringstream os;
    os.precision(3);
    if (lawUnloads()) {
        os << "load history: each face keeps the largest pressure it carried; below it h_c follows "
           << conductanceLaw_ << "'s unloading branch (docs/theory.md §5.7c), A_r/A_n"
           << (gap_ ? " and the gap's separation" : "") << " the pressure of the moment";
        return os.str();
    }
    if (unloading_.empty()) {
        os << "load history: each face keeps the largest pressure it carried, but " << conductanceLaw_
           << (modelName_ != "boundaryElement" ? " has no unloading branch"
               : cappedTable_ ? " has a table too short for an unloading curve (a curve needs a load below its "
                                "peak: widen minPressure to maxPressure)"
                              : " without a cap (elastic: unloading retraces loading)")
           << ", so h follows the pressure of the moment (docs/limitations.md)";
        return os.str();
    }
    os << "load history: each face keeps the largest pressure it carried; below it h_c and A_r/A_n follow the "
          "exact unloading curves from ";
    const auto& c = unloading_.curves();
    for (std::size_t k = 0; k < c.size(); ++k) {
        os << (k == 0 ? "" : k + 1 == c.size() ? " and " : ", ") << c[k].peak;
    }
    os << " Pa, interpolated between them (docs/theory.md §7.6)";
    return os.str();
}

const MultiscaleModel& ContactInterface::model() const
{
    if (!model_) {
        throw ParameterError("model", "boundaryElement is not a multi-scale model");
    }
    return *model_;
}

std::string ContactInterface::summary() const
{
    std::ostringstream os;
    const auto& p = table_->pressures();
    if (!model_) {
        os << "surface " << bemSurface_ << "; E' = " << reducedModulus()
           << " Pa; area and conductance from boundaryElement (exact)";
    } else {
        os << "surface " << surface_.source() << ": " << surface_.size() << " levels, L = " << surface_.length()
           << " m; E' = " << reducedModulus() << " Pa; area from the model " << model_->name()
           << ", conductance from the law " << conductanceLaw_;
    }
    os << "; table " << p.size()
       << " points from " << p.front() << " to " << p.back() << " Pa (h_c/k_s "
       << table_->conductancesPerConductivity().front() << " to "
       << table_->conductancesPerConductivity().back() << " 1/m); ";
    if (!model_ && std::isinf(table_->completeContactPressure())) {
        os << "no complete contact up to the table's end";
    } else {
        os << "complete contact at " << table_->completeContactPressure() << " Pa";
    }
    if (gap_) {
        os << "; " << gap_->summary();
    }
    os << "\n    " << regime_.describe();
    return os.str();
}

} // namespace roughContact
