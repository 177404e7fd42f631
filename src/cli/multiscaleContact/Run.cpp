// SPDX-License-Identifier: GPL-3.0-or-later
#include "Run.hpp"
#include "Inputs.hpp"
#include "GapInputs.hpp"
#include "Plot.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/CurvesPlot.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

namespace {

/// Up to this many pressures the regime is said at each; beyond, at the lightest and heaviest.
constexpr std::size_t maxRegimeLines = 12;

int runCurve(const Options& o);

} // namespace

int run(const Options& o)
{
    if (o.check || !o.table.empty()) {
        for (const auto& [given, what] : {std::pair<bool, const char*>{!o.gas.empty(), "--gas"},
                                          {o.gasPressure.has_value(), "--gas-pressure"},
                                          {!o.accommodation.empty(), "--accommodation"},
                                          {!o.emissivity.empty(), "--emissivity"},
                                          {!o.temperature.empty(), "--temperature"},
                                          {o.gapWidth.has_value(), "--gap-width"}}) {
            if (given) {
                throw ParameterError(what, std::string("adds the gap's columns to the load curve; ") +
                                               (o.check ? "--check" : "--table") + " has none");
            }
        }
    }
    if (o.unloadFrom && (!o.table.empty() || !o.plot.empty())) {
        throw ParameterError("--unload-from", std::string("adds the unloading columns to the load curve and to "
                                                          "--check; ") +
                                                  (!o.table.empty() ? "--table" : "--plot") +
                                                  " has no unloading branch yet");
    }
    if (!o.checkPeriods.empty() && !o.check) {
        throw ParameterError("--check-periods", "is the period of --check's light loads; give it with --check");
    }
    if (o.check && !o.table.empty()) {
        throw ParameterError("--table", "is the boundary-element table of an interface; --check solves surfaces of "
                                        "its own and keeps no table: give one or the other");
    }
    if (!o.plot.empty() && (o.levels || !o.table.empty() || (o.model == "boundaryElement" && !o.check))) {
        throw ParameterError("--plot", std::string("draws the laws on the whole surface (and with --check the exact "
                                                   "answer it implies); it does not go with ") +
                                           (o.levels ? "--levels" : !o.table.empty() ? "--table" : "--model boundaryElement"));
    }
    if (!o.plot.empty()) {
        requireReplaceable(o.plot, "--plot", "PNG picture", isPngStart); // before anything is computed
        requireGnuplot("--plot");
    }
    // What one profile cannot tell, said once after a run that succeeded.
    const std::string note = singleProfileNote(surfaceSpecsOf(o), "--profile-along");
    const auto noted = [&](int status) {
        if (status == 0 && !note.empty()) {
            std::cerr << "multiscaleContact: note: " << note << std::endl;
        }
        return status;
    };
    if (o.check) {
        return noted(runCheck(o));
    }
    if (!o.table.empty()) {
        return noted(runTable(o));
    }
    if (o.model == "boundaryElement") {
        return noted(runBoundaryElement(o));
    }
    return noted(runCurve(o));
}

namespace {

// The load curve of a multi-scale or comparison model (run's default).
int runCurve(const Options& o)
{
    const std::optional<GapInputs> gapInputs = gapOf(o);
    // The model's rules with the entries of another (--synthesize, --periodic, --mirror,
    // --detrend; --vickers beside another law): the core's, through the specification.
    const InterfaceSpec spec = interfaceSpecOf(o);
    for (const auto& [given, what] : {std::pair<bool, const char*>{!o.resample.empty(), "--resample"},
                                      {!o.pressureMap.empty(), "--pressure-map"}}) {
        if (given) {
            throw ParameterError(what, "is for --model boundaryElement");
        }
    }
    // A gap implies the conductance columns: its separation is the law's where it has one, and
    // h_total adds its terms to h_c.
    const bool conductance = o.conductance || !o.conductanceLaw.empty() || gapInputs.has_value() || !o.plot.empty();
    if ((o.hardness || o.hardnessFromYield) && !conductance) {
        throw ParameterError(o.hardness ? "--hardness" : "--hardness-from-yield",
                             "is the cap of --model boundaryElement, or the microhardness of the conductance laws "
                             "(cooperMikicYovanovich's H_c, the cap of fittedElastoPlastic) and of the gap: add "
                             "--conductance, a --conductance-law or the gap (--gas, --emissivity)");
    }
    const Spectrum spectrum = surfaceOf(o);
    if (o.info) {
        printInfo(spectrum, std::cerr);
    }
    const ContactMaterials materials = materialsOf(o);
    ModelOptions mo;
    if (o.D || o.G) {
        if (!(o.D && o.G)) {
            throw ParameterError("--D/--G", "give both or neither");
        }
        mo.fractal = FractalParameters{*o.D, *o.G};
    } else if (!o.fractal.empty()) {
        mo.fractal = FractalParameters{o.fractal[0], o.fractal[1]};
    } else if (o.model == "majumdarBhushan" && !o.fitRange.empty()) {
        const std::vector<double> r = splitNumbers(o.fitRange, ':', "--fit-range");
        if (r.size() != 2) {
            throw ParameterError("--fit-range", "expects FMIN:FMAX");
        }
        mo.fractal = fitFractal(spectrum, r[0], r[1]);
    }
    std::vector<double> pressures; // --pressures [Pa]: the first column
    const std::vector<double> loads = loadsOf(o, materials.reducedModulus(), &pressures);
    const auto model = makeContactModel(o.model, spectrum, materials, mo);
    const auto* ms = dynamic_cast<const MultiscaleModel*>(model.get());
    // --unload-from on a multi-scale model: its unloading area (docs/theory.md §3.6) and, with a
    // conductance, the law's unloading branch (§5.7c), columns beside the loading ones.
    double peakLoad = 0.0;
    if (o.unloadFrom) {
        if (ms == nullptr) {
            throw ParameterError("--unload-from", "unloads --model boundaryElement (with a cap) and the multi-scale "
                                                  "models; " + o.model + " has no unloading curve");
        }
        if (o.levels) {
            throw ParameterError("--unload-from", "of a multi-scale model gives its unloading area and the law's "
                                                  "unloading conductance: leave out --levels");
        }
        peakLoad = checkLoad(requirePositive("--unload-from", *o.unloadFrom) / materials.reducedModulus());
    }

    // The whole CSV is made before any of it is printed: an error half way leaves stdout empty.
    std::ostringstream out;
    out.precision(10);
    if (o.levels) {
        if (ms == nullptr) {
            throw ParameterError("--levels", "the per-level trace exists for the multi-scale models only");
        }
        if (gapInputs) {
            throw ParameterError("--levels", "prints the per-level trace; the gap's columns are the load curve's "
                                             "(leave out --levels)");
        }
        const double An = spectrum.nominalArea();
        out << (pressures.empty() ? "" : "nominal_pressure,")
            << "nominal_pressure_per_Eprime,level,frequency,amplitude,eta,radius,asperities,asperity_force,area_fraction,"
               "complete\n";
        for (std::size_t i = 0; i < loads.size(); ++i) {
            const double load = loads[i];
            for (const LevelState& s : ms->trace(load)) {
                if (!pressures.empty()) {
                    out << pressures[i] << ',';
                }
                out << load << ',' << s.index + 1 << ',' << s.frequency << ',' << s.amplitude << ','
                          << s.density << ',' << s.radius << ',' << s.asperities << ',' << s.asperityForce
                    << ',' << s.area / An << ',' << (s.complete ? 1 : 0) << '\n';
            }
        }
        std::cout << out.str();
        return 0;
    }
    const auto* persson = dynamic_cast<const PerssonModel*>(model.get());
    const bool allLaws = o.conductanceLaw == "all";
    // persson's own conductance (Barber's relation with its mean separation) unless a law is named.
    const std::string lawName = o.conductanceLaw.empty() || allLaws
                                    ? (persson != nullptr ? "persson" : defaultConductanceLaw())
                                    : o.conductanceLaw;
    ConductanceLawInputs in;
    if (conductance) {
        in.multiscale = ms;
        in.spectrum = &spectrum;
        in.Eprime = materials.reducedModulus();
        if (allLaws || conductanceLawNeedsRoughness(lawName)) {
            in.roughness = roughnessOf(o);
        }
        in.microhardness = hardnessOf(o, materials, "--hardness-from-yield");
        // fittedElastoPlastic's cap: --hardness (or from yield), else 2.84 S_y where --Sy is given.
        in.hardness = conductanceLawHardness(in.microhardness, materials);
        // A measured profile's or map's; none for a spectrum, nor for the Gaussian surfaces
        // --synthesize makes from it (the exact answer beside the laws is on those).
        if ((allLaws || lawName == "fittedElastoPlastic") && o.synthesize.empty()) {
            in.skewness = skewnessOf(o);
        }
        in.vickers = spec.vickers;
    }
    // Why a law cannot be built here, or "" when it can.
    const auto missing = [&](const std::string& name) -> std::string {
        if (name == "cooperMikicYovanovich" && !in.microhardness && !in.vickers) {
            return "needs the microhardness: --hardness H_C [Pa], --hardness-from-yield (2.84 S_y) or "
                   "--vickers C1,C2";
        }
        if ((name == "jacksonBhavnaniFerguson" || name == "multiscaleBarber") && ms == nullptr) {
            return "needs a multi-scale model; choose another --conductance-law (mikic, persson, ...)";
        }
        return "";
    };
    std::unique_ptr<ConductanceLaw> law; // the h_per_k column's (none: persson's own)
    if (conductance && !(persson != nullptr && lawName == "persson")) {
        const std::string why = missing(lawName);
        if (!why.empty() && allLaws) {
            // all: h_per_k stays empty where the default law cannot be built; the other columns say.
        } else if (!why.empty()) {
            throw ParameterError(o.conductanceLaw.empty() ? "--conductance" : "--conductance-law " + lawName,
                                 (o.conductanceLaw.empty() ? "the default law " + lawName + " " : "") + why);
        }
        if (why.empty()) {
            law = makeConductanceLaw(lawName, in);
        }
    }
    if (o.unloadFrom && conductance && !(law && law->unloads())) {
        throw ParameterError("--unload-from", "the conductance law " + lawName + " has no unloading branch" +
                                                  (lawName == "fittedElastoPlastic"
                                                       ? " without a cap (an elastic joint retraces its loading "
                                                         "curve): give --Sy or --hardness"
                                                       : " (fittedElastoPlastic with a cap has one)") +
                                                  "; leave out the conductance options for the unloading area alone");
    }
    // --conductance-law all: every law that can be built here, a column h_per_k_NAME each.
    std::vector<std::pair<std::string, std::unique_ptr<ConductanceLaw>>> every;
    if (allLaws) {
        for (const std::string& name : conductanceLawNames()) {
            const std::string why = missing(name);
            if (why.empty()) {
                every.emplace_back(name, makeConductanceLaw(name, in));
            } else {
                std::cerr << "multiscaleContact: --conductance-law all: no column for " << name << ": " << why
                          << '\n';
            }
        }
    }
    if (conductance) {
        // The regime at the run's pressures and the law's measured accuracy there (InterfaceRegime.hpp),
        // on stderr: at each of up to maxRegimeLines pressures, else at the lightest and the heaviest;
        // the hardness the materials give (2.84 S_y) or --hardness; the law held to the capped
        // reference where the area model caps the pressure.
        std::vector<double> positive;
        for (double l : loads) {
            if (l > 0.0) {
                positive.push_back(l);
            }
        }
        if (!positive.empty()) {
            const double Ep = materials.reducedModulus();
            const std::optional<double> H = in.hardness; // conductanceLawHardness
            const std::string shown = law || persson == nullptr ? lawName : std::string("persson");
            const bool capped = heldToCappedReference(o.model, shown, H.has_value());
            const auto [lo, hi] = std::minmax_element(positive.begin(), positive.end());
            InterfaceRegime r =
                interfaceRegime(spectrum, Ep, H, shown, persson != nullptr ? std::string("persson") : o.model,
                                capped, *lo * Ep, *hi * Ep);
            r.skewness = skewnessOf(o);
            if (positive.size() <= maxRegimeLines) {
                std::vector<std::pair<std::string, double>> at;
                for (double l : positive) {
                    at.emplace_back("", l * Ep);
                }
                std::cerr << "multiscaleContact: " << r.describeSurface() << r.describeAt(at) << std::endl;
            } else {
                std::cerr << "multiscaleContact: " << r.describe() << std::endl;
            }
            if (o.unloadFrom && law && law->unloads()) { // the branch's band at the peak, on top of P's
                std::cerr << "multiscaleContact: unloading_h_per_k is h_per_k times " << lawName
                          << "'s unloading branch R; " << r.describeUnloading(*o.unloadFrom, *o.unloadFrom)
                          << std::endl;
            }
            if (gapInputs) {
                std::cerr << "multiscaleContact: h_gas and h_radiation (their columns, in h_total): "
                          << gapConductanceAccuracy << " (docs/gapConductance.md)" << std::endl;
            }
        }
    }
    const std::optional<double> ks = harmonicConductivityOf(o, conductance);
    const double Ep = materials.reducedModulus();
    // The gap (InterfaceGap, as ContactInterface builds it): Y the separation column's (persson's,
    // or the law's where it defines one), else the gap's correlation.
    std::optional<InterfaceGap> gap;
    if (gapInputs) {
        std::function<double(double)> separation;
        if (persson != nullptr) {
            separation = [persson, Ep](double P) { return persson->evaluate(P / Ep).meanSeparation; };
        }
        double firstTouch = 0.0; // the lightest touching load's P (never used: --gap-width at load 0)
        for (double l : loads) {
            if (l > 0.0 && (firstTouch == 0.0 || l * Ep < firstTouch)) {
                firstTouch = l * Ep;
            }
        }
        if (firstTouch == 0.0) {
            firstTouch = 1e-9 * Ep;
        }
        // (ConductanceLaw::meanSeparation: NaN for a law without one, ContactTable's test.)
        if (persson == nullptr && law && !std::isnan(law->meanSeparation(firstTouch))) {
            const ConductanceLaw* l = law.get();
            separation = [l](double P) { return l->meanSeparation(P); };
        }
        gap.emplace(interfaceGapOf(o, *gapInputs, materials, std::move(separation), firstTouch));
    }
    out << (pressures.empty() ? "" : "nominal_pressure,") << "nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime"
        << (conductance ? ",separation,h_per_k" : "") << (ks ? ",h" : "")
        << (gap ? ",gap_separation,h_gas,h_radiation" : "") << (gap && ks ? ",h_total" : "");
    for (const auto& [name, l] : every) {
        out << ",h_per_k_" << name;
    }
    out << (o.unloadFrom ? ",unloading_area_fraction" : "") << (o.unloadFrom && conductance ? ",unloading_h_per_k" : "")
        << (o.unloadFrom && conductance && ks ? ",unloading_h" : "") << (o.unloadFrom && gap && ks ? ",unloading_h_total" : "")
        << '\n';
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const double load = loads[i];
        if (!pressures.empty()) {
            out << pressures[i] << ',';
        }
        if (persson != nullptr && conductance) {
            // Persson's theory: the mean separation [m] and Barber's h_c/k_s = -(1/E') dp/du
            // (Persson.hpp), or the named law's; u = inf at load 0, h_per_k = inf beyond double range.
            const PerssonPoint p = persson->evaluate(load);
            out << load << ',' << p.areaFraction << ',';
            if (p.areaFraction > 0.0) {
                out << load / p.areaFraction;
            }
            const double hk = law ? law->perConductivity(load * Ep) : p.conductancePerConductivity;
            out << ',' << p.meanSeparation << ',' << hk;
            if (ks) {
                out << ',' << *ks * hk;
            }
            if (gap) {
                writeGapCells(out, *gap, *gapInputs, load * Ep, p.areaFraction >= 1.0, ks, hk);
            }
        } else {
            const double a = model->areaFraction(load);
            out << load << ',' << a << ',';
            if (a > 0.0) {
                out << load / a; // F/(A_r E'), seed Eq. 34
            }
            if (conductance) {
                // No mean separation in these models: the law's where it defines one
                // (ConductanceLaw::meanSeparation: persson, multiscaleBarber), else empty.
                out << ',';
                if (law) {
                    const double Y = law->meanSeparation(load * Ep);
                    if (!std::isnan(Y)) {
                        out << Y;
                    }
                }
                out << ',';
                if (law) {
                    out << law->perConductivity(load * Ep); // inf at complete contact
                }
                if (ks) {
                    out << ',';
                    if (law) {
                        out << *ks * law->perConductivity(load * Ep);
                    }
                }
                if (gap) {
                    writeGapCells(out, *gap, *gapInputs, load * Ep, a >= 1.0, ks,
                                  law ? law->perConductivity(load * Ep) : std::numeric_limits<double>::quiet_NaN());
                }
            }
        }
        for (const auto& [name, l] : every) {
            out << ',' << l->perConductivity(load * Ep);
        }
        if (o.unloadFrom) {
            out << ',' << ms->unloadingAreaFraction(load, peakLoad);
            if (conductance) {
                // The law checked above: it unloads (at and above the peak its loading value).
                const double hk = law->perConductivity(load * Ep) * law->unloadingFactor(load * Ep, peakLoad * Ep);
                out << ',' << hk;
                if (ks) {
                    out << ',' << *ks * hk;
                }
                if (gap && ks) {
                    // The gap as the condition takes it on a law's unloading branch: at the
                    // separation of the moment (the row's h_gas, h_radiation).
                    const GapRow g = gapRowOf(*gap, *gapInputs, load * Ep, model->areaFraction(load) >= 1.0);
                    out << ',' << *ks * hk + g.h.gas + g.h.radiative;
                }
            }
        }
        out << '\n';
    }
    std::cout << out.str();
    if (!o.plot.empty()) {
        std::vector<double> asked;
        for (std::size_t i = 0; i < loads.size(); ++i) {
            asked.push_back(pressures.empty() ? loads[i] * Ep : pressures[i]);
        }
        writePlot(o, asked, ks, gap ? &*gap : nullptr, gapInputs ? &*gapInputs : nullptr, nullptr);
    }
    return 0;
}

} // namespace

} // namespace multiscaleContact
