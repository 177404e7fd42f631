// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/InterfaceSpecReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/RoughnessSpectrum.hpp"
#include "roughContact/thermal/Gas.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace roughContact {

namespace {

using Kind = SurfaceSpec::Kind;

std::string joined(const std::vector<std::string>& names)
{
    std::string out;
    for (const std::string& n : names) {
        out += (out.empty() ? "" : ", ") + n;
    }
    return out;
}

bool among(const std::vector<std::string>& names, const std::string& key)
{
    return std::find(names.begin(), names.end(), key) != names.end();
}

/// f(), its ParameterError renamed to the source's name of `key` (a core function names the
/// entry by its plain name: "units", "direction").
template <class F>
auto named(const SpecSource& source, const std::string& key, F f) -> decltype(f())
{
    try {
        return f();
    } catch (const ParameterError& e) {
        throw ParameterError(source.name(key), e.message());
    }
}

/// Every entry of `source` is one of `known`; `what` says what they are the entries of.
/// `elsewhere(key)`: where an unknown entry does belong, if anywhere ("" if nowhere).
template <class Elsewhere>
void requireKnown(const SpecSource& source, const std::vector<std::string>& known, const std::string& what,
                  Elsewhere elsewhere)
{
    for (const std::string& key : source.keys()) {
        if (!among(known, key)) {
            const std::string other = elsewhere(key);
            throw ParameterError(source.name(key), "is not an entry of " + what + " (its entries: " + joined(known) +
                                                       ")" + (other.empty() ? "" : "; it is for " + other));
        }
    }
}

void requireKnown(const SpecSource& source, const std::vector<std::string>& known, const std::string& what)
{
    requireKnown(source, known, what, [](const std::string&) { return std::string(); });
}

/// A list of exactly two numbers (a1 a2): `meaning` says what they are.
std::pair<double, double> pairOf(const SpecSource& source, const std::string& key, const std::string& meaning)
{
    const std::vector<double> v = source.numbers(key);
    if (v.size() != 2) {
        throw ParameterError(source.name(key), "expects two values (" + meaning + "), got " +
                                                   std::to_string(v.size()));
    }
    return {v[0], v[1]};
}

double scanLength(const SpecSource& source)
{
    const double L = source.number("length");
    if (!(std::isfinite(L) && L > 0.0)) {
        throw ParameterError(source.name("length"), "must be a finite scan length > 0 [m], got " + formatNumber(L, 6));
    }
    return L;
}

std::string required(const SpecSource& source, const std::string& key, const std::string& why)
{
    if (!source.has(key)) {
        throw ParameterError(source.name(key), "is missing: " + why);
    }
    return key;
}

} // namespace

const std::vector<std::string>& surfaceTypeNames()
{
    static const std::vector<std::string> names{"profile", "spectrum", "powerLaw", "fractal", "areal", "roughness"};
    return names;
}

SurfaceSpec::Kind parseSurfaceKind(const std::string& text, const std::string& what)
{
    static const Kind kinds[] = {Kind::profile, Kind::spectrum, Kind::powerLaw, Kind::fractal, Kind::areal,
                                 Kind::roughness};
    const std::vector<std::string>& names = surfaceTypeNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (text == names[i]) {
            return kinds[i];
        }
    }
    throw ParameterError(what, "unknown surface type '" + text + "' (" + joined(names) + ")");
}

const std::vector<std::string>& surfaceEntries(SurfaceSpec::Kind kind)
{
    static const std::vector<std::string> profile{"type", "file", "alongLay", "units", "spacing", "stride"};
    static const std::vector<std::string> spectrum{"type", "file", "length"};
    static const std::vector<std::string> powerLaw{"type", "bm", "m", "fmin", "fmax", "length"};
    static const std::vector<std::string> fractal{"type", "D", "G", "fmin", "fmax", "length"};
    static const std::vector<std::string> areal{"type", "file", "units", "dx", "dy", "fillInvalid", "direction"};
    static const std::vector<std::string> roughness{"type", "Rq", "Ra", "slope", "cutoff", "shortCutoff"};
    switch (kind) {
    case Kind::roughness:
        return roughness;
    case Kind::profile:
        return profile;
    case Kind::spectrum:
        return spectrum;
    case Kind::powerLaw:
        return powerLaw;
    case Kind::fractal:
        return fractal;
    case Kind::areal:
        break;
    }
    return areal;
}

const std::vector<std::string>& materialEntries()
{
    static const std::vector<std::string> names{"E", "nu", "Sy"};
    return names;
}

const std::vector<std::string>& gapEntries()
{
    static const std::vector<std::string> names{"gas", "pressure", "accommodation", "emissivity"};
    return names;
}

const std::vector<std::string>& gasEntries()
{
    static const std::vector<std::string> names{"conductivity",      "conductivityExponent", "referenceTemperature",
                                                "heatCapacityRatio", "prandtl",              "meanFreePath",
                                                "referencePressure", "accommodation"};
    return names;
}

const std::vector<std::string>& interfaceEntries()
{
    static const std::vector<std::string> names{"model",
                                                "surface",
                                                "surfaces",
                                                "side1",
                                                "side2",
                                                "conductance",
                                                "microhardness",
                                                "vickers",
                                                "minPressure",
                                                "maxPressure",
                                                "pointsPerDecade",
                                                "synthesize",
                                                "seed",
                                                "periodic",
                                                "mirror",
                                                "detrend",
                                                "hardness",
                                                "hardnessFromYield",
                                                "gap",
                                                "check",
                                                "checkPeriods",
                                                "checkPressures",
                                                "checkUnloadFrom",
                                                "threads",
                                                "tableRanks",
                                                "loadHistory"};
    return names;
}

SurfaceSpec readSurfaceSpec(const SpecSource& source)
{
    required(source, "type", "the surface's type: " + joined(surfaceTypeNames()));
    SurfaceSpec s;
    s.kind = named(source, "type", [&] { return parseSurfaceKind(source.word("type")); });
    const std::string type = source.word("type");
    requireKnown(source, surfaceEntries(s.kind), "a surface of type " + type, [](const std::string& key) {
        std::string types;
        for (const std::string& name : surfaceTypeNames()) {
            if (among(surfaceEntries(parseSurfaceKind(name)), key)) {
                types += (types.empty() ? "type " : " or ") + name;
            }
        }
        if (key == "units" && !types.empty()) {
            types += " (a spectrum file, a powerLaw and a fractal are in metres)";
        }
        if (key == "length" && !types.empty()) {
            types += " (a profile's length is N dx, an areal map's nx dx and ny dy)";
        }
        return types;
    });
    switch (s.kind) {
    case Kind::profile:
        s.file = source.path(required(source, "file", "the profile's file"));
        if (source.has("alongLay")) {
            s.alongLay = source.path("alongLay"); // the same units, spacing and stride as file's
        }
        if (source.has("units")) {
            s.profileOptions.units = named(source, "units", [&] { return parseLengthUnit(source.word("units")); });
        }
        if (source.has("spacing")) {
            s.profileOptions.spacing = source.number("spacing");
        }
        if (source.has("stride")) {
            s.stride = static_cast<std::size_t>(source.whole("stride"));
        }
        break;
    case Kind::spectrum:
        s.file = source.path(required(source, "file", "the spectrum's file"));
        break;
    case Kind::areal:
        s.file = source.path(required(source, "file", "the height map's file (X3P or a text matrix)"));
        if (source.has("units")) {
            s.arealOptions.units = named(source, "units", [&] { return parseLengthUnit(source.word("units")); });
        }
        if (source.has("dx")) {
            s.arealOptions.dx = source.number("dx");
        }
        if (source.has("dy")) {
            s.arealOptions.dy = source.number("dy");
        }
        if (source.has("fillInvalid")) {
            s.arealOptions.fillInvalid = source.flag("fillInvalid");
        }
        if (source.has("direction")) {
            s.direction = named(source, "direction", [&] { return parseScanDirection(source.word("direction")); });
        }
        break;
    case Kind::roughness: {
        // Rq, or Ra of Gaussian heights; the rms slope; the band (RoughnessSpectrum.hpp).
        if (source.has("Rq") == source.has("Ra")) {
            throw ParameterError(source.name(source.has("Rq") ? "Ra" : "Rq"),
                                 "give one of Rq (the rms height [m]) and Ra (the mean absolute height [m], "
                                 "of Gaussian heights: Rq = sqrt(pi/2) Ra)");
        }
        const double Rq = source.has("Rq") ? source.number("Rq")
                                           : named(source, "Ra", [&] { return rqFromRa(source.number("Ra")); });
        const double slope = source.number(required(source, "slope", "the rms slope Rdq of the profile"));
        s.parameters = {Rq, slope, source.has("cutoff") ? source.number("cutoff") : defaultLongCutoff,
                        source.has("shortCutoff") ? source.number("shortCutoff") : defaultShortCutoff};
        break;
    }
    case Kind::powerLaw:
    case Kind::fractal: {
        const bool power = s.kind == Kind::powerLaw;
        for (const char* key : {power ? "bm" : "D", power ? "m" : "G", "fmin", "fmax"}) {
            s.parameters.push_back(
                source.number(required(source, key, power ? "a power law takes bm, m, fmin and fmax"
                                                          : "a fractal takes D, G, fmin and fmax")));
        }
        break;
    }
    }
    if (source.has("length")) {
        s.length = scanLength(source);
    }
    // The values' rules are the struct's (SurfaceSpec::check), named as this source names them.
    try {
        s.check();
    } catch (const ParameterError& e) {
        throw ParameterError(source.has(e.parameter()) ? source.name(e.parameter()) : e.parameter(), e.message());
    }
    return s;
}

void readYieldStrength(const SpecSource& source, Material& m)
{
    if (source.isWord("Sy")) {
        const std::string word = source.word("Sy");
        if (word != "none") {
            throw ParameterError(source.name("Sy"), "must be a yield strength [Pa] or none (the solid does not "
                                                    "yield), got '" + word + "'");
        }
        m.elastic = true;
    } else {
        m.Sy = source.number("Sy");
    }
}

Material readMaterial(const SpecSource& source)
{
    requireKnown(source, materialEntries(), source.context());
    Material m;
    m.E = source.number(required(source, "E", "Young's modulus [Pa]"));
    m.nu = source.number(required(source, "nu", "Poisson's ratio"));
    if (source.has("Sy")) {
        readYieldStrength(source, m);
    }
    // checkMaterial (the one place of the ranges) names the property; the error adds where the
    // source has the entry, if it can say (a dictionary's line). The properties are checked one
    // at a time to know which it was.
    const auto check = [&](const Material& partial, const char* key) {
        try {
            checkMaterial(partial, source.context());
        } catch (const ParameterError& e) {
            const std::string where = source.locate(key);
            if (where.empty()) {
                throw;
            }
            throw ParameterError(e.parameter() + " (" + where + ")", e.message());
        }
    };
    check(Material{m.E, 0.0, std::nullopt, false}, "E");
    check(Material{m.E, m.nu, std::nullopt, false}, "nu");
    check(m, "Sy");
    return m;
}

GapSpec readGapSpec(const SpecSource& source)
{
    requireKnown(source, gapEntries(), source.context());
    GapSpec g;
    if (source.has("gas")) {
        GasGapSpec gas;
        if (source.isSub("gas")) {
            const std::unique_ptr<SpecSource> p = source.sub("gas");
            requireKnown(*p, gasEntries(), p->context());
            GasProperties& q = gas.gas;
            q.name = "user";
            const std::string why = "a gas given by its properties takes " + joined(gasEntries()) +
                                    " (referencePressure optional)";
            q.conductivity = p->number(required(*p, "conductivity", why));
            // k_g = k_0 (T/T_0)^n: no n is right for every gas (0 is refused by checkGas).
            q.conductivityExponent = p->number(required(*p, "conductivityExponent", why));
            q.referenceTemperature = p->number(required(*p, "referenceTemperature", why));
            q.heatCapacityRatio = p->number(required(*p, "heatCapacityRatio", why));
            q.prandtl = p->number(required(*p, "prandtl", why));
            q.meanFreePath = p->number(required(*p, "meanFreePath", why));
            q.referencePressure = p->has("referencePressure") ? p->number("referencePressure") : standardAtmosphere;
            q.accommodation = p->number(required(*p, "accommodation", why));
        } else {
            gas.gas = named(source, "gas", [&] { return gasByName(source.word("gas")); });
        }
        if (source.has("pressure")) {
            gas.pressure = source.number("pressure");
        }
        if (source.has("accommodation")) {
            std::tie(gas.accommodation1, gas.accommodation2) =
                pairOf(source, "accommodation", "a1 a2, the thermal accommodation coefficients of the two surfaces");
        }
        g.gas = gas;
    }
    if (source.has("emissivity")) {
        std::tie(g.emissivity1, g.emissivity2) = pairOf(source, "emissivity", "e1 e2, the emissivities of the two surfaces");
    }
    checkGapSpec(g);
    if (!g.gas) {
        for (const char* key : {"pressure", "accommodation"}) {
            if (source.has(key)) {
                throw ParameterError(source.name(key), "is for a gas; this gap has none (add gas, or remove it)");
            }
        }
    }
    return g;
}

InterfaceSpec readInterfaceSpec(const SpecSource& source)
{
    requireKnown(source, interfaceEntries(), "a contact specification");
    InterfaceSpec spec;
    required(source, "model", "the asperity model (jacksonGreen, ..., or boundaryElement)");
    const char* surfacesWhy = "give surface { ... } (one equivalent surface) or surfaces ( { ... } { ... } ) (one "
                              "per side: side1's first)";
    if (source.has("surface") && source.has("surfaces")) {
        throw ParameterError(source.name("surfaces"), std::string("is given beside surface: ") + surfacesWhy);
    }
    if (source.has("surfaces")) {
        for (const std::unique_ptr<SpecSource>& s : source.subs("surfaces")) {
            spec.surfaces.push_back(readSurfaceSpec(*s));
        }
        if (spec.surfaces.empty() || spec.surfaces.size() > 2) {
            throw ParameterError(source.name("surfaces"), "holds " + std::to_string(spec.surfaces.size()) +
                                                              " surfaces: " + surfacesWhy);
        }
    } else {
        spec.surfaces.push_back(readSurfaceSpec(*source.sub(required(source, "surface", surfacesWhy))));
    }
    spec.side1 = readMaterial(*source.sub(required(source, "side1", "the solid on side 1: { E ...; nu ...; Sy ...; }")));
    spec.side2 = readMaterial(*source.sub(required(source, "side2", "the solid on side 2: { E ...; nu ...; Sy ...; }")));
    if (source.has("gap")) {
        spec.gap = readGapSpec(*source.sub("gap"));
    }
    readInterfaceSettings(source, spec);
    return spec;
}

void readInterfaceSettings(const SpecSource& source, InterfaceSpec& spec)
{
    if (source.has("model")) {
        spec.model = source.word("model");
    }
    if (source.has("conductance")) {
        spec.conductanceLaw = source.word("conductance");
    }
    if (source.has("microhardness")) {
        spec.microhardness = source.number("microhardness");
    }
    if (source.has("vickers")) {
        const auto [c1, c2] = pairOf(source, "vickers", "c1 [Pa] and c2 of H_v = c1 (d_v/1 um)^c2");
        spec.vickers = VickersCoefficients{c1, c2};
    }
    if (source.has("minPressure")) {
        spec.minPressure = source.number("minPressure");
    }
    if (source.has("maxPressure")) {
        spec.maxPressure = source.number("maxPressure");
    }
    if (source.has("pointsPerDecade")) {
        // One entry, the table of the model named: the boundary-element loads or the
        // multi-scale table's points (their ranges: Limits.hpp, checked where they are used).
        (spec.model == "boundaryElement" ? spec.bemPointsPerDecade : spec.pointsPerDecade) =
            static_cast<std::size_t>(source.whole("pointsPerDecade"));
    }
    if (source.has("synthesize")) {
        spec.synthesize = static_cast<std::size_t>(source.whole("synthesize"));
    }
    if (source.has("seed")) {
        if (!source.has("synthesize")) {
            throw ParameterError(source.name("seed"), "is the phases' seed of synthesize N; there is no synthesize");
        }
        spec.seed = source.whole("seed");
    }
    if (source.has("periodic")) {
        spec.periodic = source.flag("periodic");
    }
    if (source.has("mirror")) {
        spec.mirror = source.flag("mirror");
    }
    if (source.has("detrend")) {
        spec.detrend = named(source, "detrend", [&] { return parseDetrend(source.word("detrend"), "detrend"); });
    }
    if (source.has("hardness")) {
        spec.hardness = source.number("hardness");
    }
    if (source.has("hardnessFromYield")) {
        spec.hardnessFromYield = source.flag("hardnessFromYield");
    }
    if (source.has("loadHistory")) {
        spec.loadHistory = source.flag("loadHistory");
    }
    if (source.has("check")) {
        spec.check = source.flag("check");
    }
    if (source.has("checkPeriods")) {
        if (!spec.check) {
            throw ParameterError(source.name("checkPeriods"), "is the period of the check's light loads; it needs "
                                                              "check yes");
        }
        spec.checkPeriods =
            checkedLightLoadPeriods(source.whole("checkPeriods"), spec.surfaces, source.name("checkPeriods"));
    }
    if (source.has("checkPressures")) {
        const std::string name = source.name("checkPressures");
        if (!spec.check) {
            throw ParameterError(name, "are the pressures of the check; it needs check yes");
        }
        spec.checkPressures = source.numbers("checkPressures");
        if (spec.checkPressures.empty() || spec.checkPressures.size() > maximumCheckedPressures) {
            throw ParameterError(name, "give 1 to " + std::to_string(maximumCheckedPressures) +
                                           " pressures [Pa] (the check solves each), not " +
                                           std::to_string(spec.checkPressures.size()));
        }
        for (double P : spec.checkPressures) {
            if (!(P > 0.0) || !std::isfinite(P)) {
                throw ParameterError(name, "a pressure is " + limits::valueText(P, "Pa") +
                                               ": give nominal pressures above 0 in Pa");
            }
        }
    }
    if (source.has("checkUnloadFrom")) {
        const std::string name = source.name("checkUnloadFrom");
        if (!spec.check) {
            throw ParameterError(name, "is the peak the check unloads from; it needs check yes");
        }
        const double peak = source.number("checkUnloadFrom");
        if (!(peak > 0.0) || !std::isfinite(peak)) {
            throw ParameterError(name, "is " + limits::valueText(peak, "Pa") +
                                           ": give the joint's peak nominal pressure above 0 in Pa");
        }
        spec.checkUnloadFrom = peak; // below the cap: the check says so, naming the entry
    }
    if (source.has("threads")) {
        const std::uint64_t t = source.whole("threads");
        if (t < 1 || t > std::uint64_t(limits::maximumThreads)) {
            throw ParameterError(source.name("threads"), "must be 1 to " + std::to_string(limits::maximumThreads) +
                                                             " (the threads of the boundary-element solves), got " +
                                                             std::to_string(t));
        }
        spec.threads = static_cast<int>(t);
    }
    if (source.has("tableRanks")) {
        if (spec.model != "boundaryElement") {
            throw ParameterError(source.name("tableRanks"), "is for model boundaryElement (the ranks that build its "
                                                            "table), not model " + spec.model);
        }
        const std::uint64_t r = source.whole("tableRanks");
        if (r < 1) {
            throw ParameterError(source.name("tableRanks"),
                                 "must be 1 or more (the ranks of a decomposed run that share the "
                                 "boundary-element table's build), got 0");
        }
        spec.tableRanks = static_cast<std::size_t>(r);
    }
    // The model's rules with the entries of another (InterfaceSpec::checkEntries, once), each
    // error naming the entry as this source writes it.
    try {
        spec.checkEntries();
    } catch (const ParameterError& e) {
        throw ParameterError(source.has(e.parameter()) ? source.name(e.parameter()) : e.parameter(), e.message());
    }
}

} // namespace roughContact
