// SPDX-License-Identifier: GPL-3.0-or-later
// The module's interface: one rough surface as ContactInterface reads it (SurfaceSpec) and
// ContactInterface, the pressure table a boundary condition interpolates, with its gap.
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"
#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SpecSource.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/thermal/ContactTable.hpp"
#include "roughContact/parallel/Threads.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

namespace {

/// Python's name of an entry: its keyword argument (snake_case; a surface's file is `path`).
std::string argumentOf(const std::string& key)
{
    if (key == "file") {
        return "path";
    }
    // camelCase to snake_case after a lower-case letter; a name in capitals (Rq, Ra, D, G) stays.
    std::string out;
    for (std::size_t i = 0; i < key.size(); ++i) {
        const char c = key[i];
        if (c >= 'A' && c <= 'Z' && i > 0 && key[i - 1] >= 'a' && key[i - 1] <= 'z') {
            out += '_';
            out += static_cast<char>(c - 'A' + 'a');
        } else {
            out += c;
        }
    }
    return out;
}

/// The keyword arguments given (not None) as a specification's entries, for the core's reader.
SpecValues arguments(const std::string& context)
{
    return SpecValues(context, argumentOf);
}

template <class T>
void setIf(SpecValues& v, const std::string& key, const std::optional<T>& value)
{
    if (value) {
        v.set(key, *value);
    }
}

/// A surface through the core's reader of a surface (InterfaceSpecReader.hpp): the same rules as
/// the dictionary's surface entry and the CLI's surface options.
SurfaceSpec surfaceOf(const SpecValues& v)
{
    return readSurfaceSpec(v);
}

SpecValues parametric(const char* type, const char* const (&keys)[4], const double (&values)[4],
                      std::optional<double> length)
{
    SpecValues v = arguments(std::string("SurfaceSpec.") + type);
    v.set("type", std::string(type));
    for (std::size_t i = 0; i < 4; ++i) {
        v.set(keys[i], values[i]);
    }
    setIf(v, "length", length);
    return v;
}

} // namespace

InterfaceSpec interfaceSpec(const std::vector<SurfaceSpec>& surfaces, const Material& side1, const Material& side2,
                            const std::optional<std::string>& model, const std::optional<std::string>& conductance,
                            std::optional<double> microhardness, std::optional<std::pair<double, double>> vickers,
                            std::optional<double> minPressure, std::optional<double> maxPressure,
                            std::optional<std::size_t> pointsPerDecade, std::optional<std::size_t> synthesize,
                            std::optional<std::uint64_t> seed, std::optional<bool> periodic,
                            std::optional<double> hardness, bool hardnessFromYield,
                            std::optional<std::size_t> bemPointsPerDecade, std::optional<GapSpec> gap,
                            std::optional<std::string> detrend, std::optional<bool> mirror, bool check)
{
    // The parts are objects already read (SurfaceSpec and GapSpec through the core's reader,
    // Material checked by the pair); the settings through the core's reader of them.
    InterfaceSpec s;
    s.surfaces = surfaces;
    s.side1 = side1;
    s.side2 = side2;
    s.gap = gap;
    SpecValues v = arguments("ContactInterface");
    setIf(v, "model", model);
    setIf(v, "conductance", conductance);
    setIf(v, "microhardness", microhardness);
    if (vickers) {
        v.set("vickers", std::vector<double>{vickers->first, vickers->second});
    }
    setIf(v, "minPressure", minPressure);
    setIf(v, "maxPressure", maxPressure);
    if (synthesize) {
        v.set("synthesize", std::uint64_t(*synthesize));
    }
    setIf(v, "seed", seed); // the reader: a seed is of synthesize N
    setIf(v, "periodic", periodic);
    setIf(v, "mirror", mirror);
    setIf(v, "hardness", hardness);
    if (hardnessFromYield) {
        v.set("hardnessFromYield", true);
    }
    setIf(v, "detrend", detrend);
    if (check) {
        v.set("check", true);
    }
    // Python has an argument for each table's points (the dictionary one entry, for the model
    // named); unset: InterfaceSpec's.
    s.pointsPerDecade = pointsPerDecade.value_or(s.pointsPerDecade);
    s.bemPointsPerDecade = bemPointsPerDecade.value_or(s.bemPointsPerDecade);
    readInterfaceSettings(v, s);
    if (const std::string note = singleProfileNote(s.surfaces, "SurfaceSpec.profile(..., along_lay=)"); !note.empty()) {
        py::module_::import("warnings").attr("warn")(note, py::module_::import("builtins").attr("UserWarning"), 1);
    }
    return s;
}

namespace {

// The peak keyword: none (0: loading), else a peak pressure (isPeakPressure).
double checkedPeak(std::optional<double> peak)
{
    if (peak && !roughContact::isPeakPressure(*peak)) {
        throw roughContact::ParameterError("peak", "must be a finite pressure >= 0, got " + std::to_string(*peak));
    }
    return peak.value_or(0.0);
}

} // namespace

void bindInterface(py::module_& m)
{
    py::class_<SurfaceSpec>(m, "SurfaceSpec",
                            "One rough surface as ContactInterface reads it (the OpenFOAM dictionary's "
                            "surface entry): build it with the static methods.")
        .def_static(
            "profile",
            [](const std::string& path, std::optional<std::string> units, std::optional<double> spacing,
               std::optional<std::uint64_t> stride, std::optional<std::string> alongLay) {
                SpecValues v = arguments("SurfaceSpec.profile");
                v.set("type", std::string("profile")).set("file", path);
                setIf(v, "alongLay", alongLay);
                setIf(v, "units", units);
                setIf(v, "spacing", spacing);
                setIf(v, "stride", stride); // None: the reader's (every sample)
                return surfaceOf(v);
            },
            py::arg("path"), py::arg("units") = py::none(), py::arg("spacing") = py::none(), py::arg("stride") = py::none(),
            py::arg("along_lay") = py::none(),
            "A profile file (read_profile's units and spacing), every stride-th sample; along_lay: a second "
            "profile of the surface along its lay (path across it), for the isotropic equivalent of the two "
            "directions.")
        .def_static(
            "spectrum",
            [](const std::string& path, std::optional<double> length) {
                SpecValues v = arguments("SurfaceSpec.spectrum");
                v.set("type", std::string("spectrum")).set("file", path);
                setIf(v, "length", length);
                return surfaceOf(v);
            },
            py::arg("path"), py::arg("length") = py::none(), "A spectrum table file; length [m].")
        .def_static(
            "power_law",
            [](double bm, double mm, double fmin, double fmax, std::optional<double> length) {
                return surfaceOf(parametric("powerLaw", {"bm", "m", "fmin", "fmax"}, {bm, mm, fmin, fmax}, length));
            },
            py::arg("bm"), py::arg("m"), py::arg("fmin"), py::arg("fmax"), py::arg("length") = py::none(),
            "A power-law spectrum bm f^-m [m], fmin, fmax [1/m], length [m].")
        .def_static(
            "fractal",
            [](double D, double G, double fmin, double fmax, std::optional<double> length) {
                return surfaceOf(parametric("fractal", {"D", "G", "fmin", "fmax"}, {D, G, fmin, fmax}, length));
            },
            py::arg("D"), py::arg("G"), py::arg("fmin"), py::arg("fmax"), py::arg("length") = py::none(),
            "A Weierstrass-Mandelbrot spectrum: D, G [m], fmin, fmax [1/m], length [m].")
        .def_static(
            "areal",
            [](const std::string& path, std::optional<std::string> units, std::optional<double> dx,
               std::optional<double> dy, bool fillInvalid, std::optional<std::string> direction) {
                SpecValues v = arguments("SurfaceSpec.areal");
                v.set("type", std::string("areal")).set("file", path);
                setIf(v, "units", units);
                setIf(v, "dx", dx);
                setIf(v, "dy", dy);
                v.set("fillInvalid", fillInvalid);
                setIf(v, "direction", direction); // none: the core's default (defaultScanDirection)
                return surfaceOf(v);
            },
            py::arg("path"), py::arg("units") = py::none(), py::arg("dx") = py::none(), py::arg("dy") = py::none(),
            py::arg("fill_invalid") = false, py::arg("direction") = py::none(),
            "An areal file (read_areal's options) and the line scans that make its spectrum.")
        .def_static(
            "from_roughness",
            [](std::optional<double> Rq, double slope, std::optional<double> Ra, std::optional<double> cutoff,
               std::optional<double> shortCutoff) {
                SpecValues v = arguments("SurfaceSpec.from_roughness");
                v.set("type", std::string("roughness"));
                setIf(v, "Rq", Rq);
                setIf(v, "Ra", Ra);
                v.set("slope", slope);
                setIf(v, "cutoff", cutoff);
                setIf(v, "shortCutoff", shortCutoff);
                return surfaceOf(v);
            },
            py::kw_only(), py::arg("Rq") = py::none(), py::arg("slope"), py::arg("Ra") = py::none(),
            py::arg("cutoff") = py::none(), py::arg("short_cutoff") = py::none(),
            "The self-affine surface of rms height Rq [m] (or Ra [m] of Gaussian heights) and rms slope "
            "`slope` over wavelengths short_cutoff to cutoff [m] (default 2.5e-6 to 0.8e-3, ISO 3274/4288); "
            "its Hurst exponent is found from slope/Rq (docs/theory.md §1.4).")
        .def("read_spectrum", &SurfaceSpec::spectrum, "The surface's spectrum (reads the file; a Spectrum).")
        .def("roughness", &SurfaceSpec::roughness, "Its sigma [m] and mean absolute slope.")
        .def("skewness", &SurfaceSpec::skewness,
             "Its heights' skewness and its spread by chance (HeightSkewness: skewness, spread; a profile's or an "
             "areal map's, detrended), or None for a spectrum: fittedElastoPlastic takes it with chance's share out "
             "(shrunk_skewness), the other laws assume 0 (Gaussian heights).");

    // The defaults it names are the core's (InterfaceSpec, defaultConductanceLaw): one place for them.
    const InterfaceSpec defaults;
    static const std::string interfaceDoc =
        "ContactInterface(*, surfaces, side1, side2, model=None, conductance=None, ...): "
        "surfaces a list of one or two SurfaceSpec; side1, side2 the Materials of the two solids; model a "
        "multi-scale model or 'boundaryElement' (None: " + defaults.model + "); conductance a law name (None: " +
        defaultConductanceLaw() + "); microhardness "
        "[Pa] or vickers (c1 [Pa], c2) for cooperMikicYovanovich; min_pressure, max_pressure [Pa] the "
        "table's range (default 1e-9 E' to E'); points_per_decade (None: " + std::to_string(defaults.pointsPerDecade) +
        "); boundaryElement only: synthesize N "
        "(an N x N surface from the 1-D surfaces), seed (None: " + std::to_string(defaults.seed) + "), periodic, "
        "mirror (a map mirrored about its edges into "
        "one period of a periodic surface), detrend ('none', 'mean' or 'plane'; None: "
        "'mean' when periodic, 'plane' otherwise), hardness [Pa], hardness_from_yield, "
        "bem_points_per_decade (None: " + std::to_string(defaults.bemPointsPerDecade) + "), table_file (the "
        "boundary-element table's cache file, as the condition's "
        "constant/boundaryElementTable.NAME.csv: read when it holds this table, else built and written); "
        "load_history (None: " + std::string(defaults.loadHistory ? "True" : "False") + "): with a hardness, the "
        "boundary-element table holds unloading curves and the default law uses its unloading branch (the peak "
        "keyword of area_fraction, conductance_per_conductivity and conductance); "
        "gap a GapSpec (gas and/or radiation beside the contact) or None; threads the process's threads of the "
        "boundary-element solves (set_threads; None: as they are). Building the table takes a fraction of a second "
        "for the multi-scale models, far longer for boundaryElement.";
    py::class_<ContactInterface>(m, "ContactInterface",
                                 "Surfaces + materials + model + conductance law -> the pressure table "
                                 "a boundary condition interpolates: A_r/A_n and h_c/k_s at a nominal pressure [Pa].")
        .def(py::init([](const std::vector<SurfaceSpec>& surfaces, const Material& side1, const Material& side2,
                         const std::optional<std::string>& model, const std::optional<std::string>& conductance,
                         std::optional<double> microhardness, std::optional<std::pair<double, double>> vickers,
                         std::optional<double> minPressure, std::optional<double> maxPressure,
                         std::optional<std::size_t> pointsPerDecade, std::optional<std::size_t> synthesize,
                         std::optional<std::uint64_t> seed, std::optional<bool> periodic,
                         std::optional<double> hardness, bool hardnessFromYield,
                         std::optional<std::size_t> bemPointsPerDecade, std::optional<GapSpec> gap,
                         std::optional<std::string> detrend,
                         std::optional<std::string> tableFile, const py::object& threads, std::optional<bool> mirror,
                         std::optional<bool> loadHistory) {
                 InterfaceSpec s =
                     interfaceSpec(surfaces, side1, side2, model, conductance, microhardness, vickers, minPressure,
                                   maxPressure, pointsPerDecade, synthesize, seed, periodic, hardness,
                                   hardnessFromYield, bemPointsPerDecade, gap, detrend, mirror);
                 if (loadHistory) {
                     s.loadHistory = *loadHistory;
                 }
                 if (tableFile && tableFile->empty()) {
                     throw ParameterError("table_file", "is empty: give the table's file name (None: no file)");
                 }
                 if (tableFile && s.model != "boundaryElement") {
                     throw ParameterError("table_file", "is the cache of model 'boundaryElement', not of '" +
                                                            s.model + "'");
                 }
                 if (!threads.is_none()) {
                     setThreads(threads.cast<int>());
                 }
                 // What the build warns of (a cache file replaced; a padded map's h_c not to be
                 // trusted near complete contact): RuntimeWarnings, once the GIL is held again.
                 std::vector<std::string> warned;
                 std::unique_ptr<ContactInterface> made;
                 {
                     py::gil_scoped_release release;
                     if (tableFile) {
                         // The case's cache, shared with the condition: read when it holds this
                         // table (its key and digest), else built and written (BoundaryElementTable.hpp).
                         const BoundaryElementTablePoints points = BoundaryElementTable(s).loadOrBuild(
                             *tableFile, {}, [&](const std::string& line, bool warning) {
                                 if (warning) {
                                     warned.push_back(line);
                                 }
                             });
                         made = std::make_unique<ContactInterface>(s, &points);
                     } else {
                         made = std::make_unique<ContactInterface>(s);
                         if (!made->tableWarning().empty()) {
                             warned.push_back("boundary-element table: " + made->tableWarning());
                         }
                     }
                 }
                 for (const std::string& w : warned) {
                     py::module_::import("warnings").attr("warn")(w, py::module_::import("builtins").attr("RuntimeWarning"), 1);
                 }
                 return made;
             }),
             py::kw_only(), py::arg("surfaces"), py::arg("side1"), py::arg("side2"), py::arg("model") = py::none(),
             py::arg("conductance") = py::none(), py::arg("microhardness") = py::none(), py::arg("vickers") = py::none(),
             py::arg("min_pressure") = py::none(), py::arg("max_pressure") = py::none(),
             py::arg("points_per_decade") = py::none(), py::arg("synthesize") = py::none(), py::arg("seed") = py::none(),
             py::arg("periodic") = py::none(), py::arg("hardness") = py::none(),
             py::arg("hardness_from_yield") = false, py::arg("bem_points_per_decade") = py::none(),
             py::arg("gap") = py::none(), py::arg("detrend") = py::none(), py::arg("table_file") = py::none(),
             py::arg("threads") = py::none(), py::arg("mirror") = py::none(), py::arg("load_history") = py::none(),
             interfaceDoc.c_str())
        .def(
            "area_fraction",
            [](const ContactInterface& ci, const py::object& P, std::optional<double> peak) {
                const double pk = checkedPeak(peak);
                return vectorize(P, "pressures", [&](double p) {
                    return peak ? ci.face(p, 1.0, 1.0, pk).areaFraction : ci.areaFraction(p);
                });
            },
            py::arg("pressures"), py::kw_only(), py::arg("peak") = py::none(),
            "A_r/A_n at the nominal pressures [Pa] (0 for P <= 0, 1 beyond complete contact); peak [Pa]: the "
            "heaviest load the joint carried (below it, the unloading curves or the law's unloading branch where "
            "the interface has them: remembers_load; the branch leaves A_r/A_n at its loading value).")
        .def(
            "conductance_per_conductivity",
            [](const ContactInterface& ci, const py::object& P, std::optional<double> peak) {
                const double pk = checkedPeak(peak);
                return vectorize(P, "pressures", [&](double p) {
                    return peak ? ci.face(p, 1.0, 1.0, pk).conductance : ci.conductancePerConductivity(p);
                });
            },
            py::arg("pressures"), py::kw_only(), py::arg("peak") = py::none(),
            "h_c/k_s [1/m] at the nominal pressures [Pa] (inf beyond complete contact); peak as area_fraction's.")
        .def(
            "conductance",
            [](const ContactInterface& ci, const py::object& P, double k1, double k2, std::optional<double> peak) {
                const double pk = checkedPeak(peak);
                return vectorize(P, "pressures", [&](double p) { return ci.face(p, k1, k2, pk).conductance; });
            },
            py::arg("pressures"), py::arg("k1"), py::arg("k2"), py::kw_only(), py::arg("peak") = py::none(),
            "h_c [W/(m^2 K)] at the pressures [Pa] between solids of conductivities k1, k2 [W/(m K)] "
            "(k_s = 2 k1 k2/(k1 + k2)); peak as area_fraction's.")
        .def_property_readonly("remembers_load", &ContactInterface::remembersLoad,
                               "True with load_history when the interface unloads: boundaryElement with a hardness "
                               "(its unloading curves, unloading_peaks) or a law with an unloading branch (the "
                               "default law with a hardness): below its peak a joint conducts as they say.")
        .def_property_readonly(
            "unloading_peaks",
            [](const ContactInterface& ci) {
                std::vector<double> peaks;
                for (const UnloadingCurve& c : ci.unloading().curves()) {
                    peaks.push_back(c.peak);
                }
                return toArray(peaks);
            },
            "The peaks [Pa] of the solved unloading curves (between them interpolated; docs/theory.md §7.6).")
        .def_property_readonly("load_history_note", &ContactInterface::loadHistoryNote,
                               "What the load history does with this model, as the condition's log says it.")
        .def(
            "mean_separation",
            [](const ContactInterface& ci, const py::object& P) {
                return vectorize(P, "pressures", [&](double p) { return ci.meanSeparation(p); });
            },
            py::arg("pressures"), "The mean-plane separation [m] where the table has one (has_separation), else NaN.")
        .def_property_readonly("has_separation", &ContactInterface::hasSeparation,
                               "True when the table carries the mean separation.")
        .def_property_readonly("table_pressures", [](const ContactInterface& ci) { return toArray(ci.table().pressures()); },
                               "The table's pressures [Pa].")
        .def_property_readonly("table_area_fractions",
                               [](const ContactInterface& ci) { return toArray(ci.table().areaFractions()); },
                               "A_r/A_n at the table's pressures.")
        .def_property_readonly(
            "table_conductances_per_conductivity",
            [](const ContactInterface& ci) { return toArray(ci.table().conductancesPerConductivity()); },
            "h_c/k_s [1/m] at the table's pressures.")
        .def_property_readonly("table_separations",
                               [](const ContactInterface& ci) { return toArray(ci.table().separations()); },
                               "The mean separation [m] at the table's pressures (empty without the column).")
        .def_property_readonly("table_end", &ContactInterface::tableEnd, "The table's last pressure [Pa].")
        .def_property_readonly("complete_contact_pressure", &ContactInterface::completeContactPressure,
                               "The lowest pressure [Pa] of complete contact (inf: none).")
        .def_property_readonly("reduced_modulus", &ContactInterface::reducedModulus, "E' [Pa].")
        .def_property_readonly("model_name", &ContactInterface::modelName, "The model's name.")
        .def_property_readonly("table_warning", &ContactInterface::tableWarning,
                               "model boundaryElement on a map solved padded: where its table's h_c is not to be "
                               "trusted (near complete contact; solve it mirror=True); empty otherwise, and for a table "
                               "read back from table_file.")
        .def_property_readonly("conductance_law", &ContactInterface::conductanceLaw, "The law of the h column.")
        .def_property_readonly("surface", &ContactInterface::surface, "The equivalent surface's spectrum.")
        .def_property_readonly("has_gap", &ContactInterface::hasGap, "True with a gap (gas or radiation).")
        .def(
            "gap_separation",
            [](const ContactInterface& ci, const py::object& P) {
                const InterfaceGap& gap = ci.gap();
                return vectorize(P, "pressures", [&](double p) { return gap.separation(p); });
            },
            py::arg("pressures"),
            "Y [m] the gap uses at P [Pa] > 0: the model's mean separation where the table has one, else the "
            "correlation of sigma and P/H_c. ParameterError without a gap.")
        .def_property_readonly(
            "gap_first_touch_separation", [](const ContactInterface& ci) { return ci.gap().firstTouchSeparation(); },
            "Y [m] of faces apart with no gap width given: the separation at the table's first pressure.")
        .def(
            "gap_conductances",
            [](const ContactInterface& ci, const py::object& Y, double T1, double T2) {
                const InterfaceGap& gap = ci.gap();
                py::object hg = vectorize(Y, "separation", [&](double y) { return gap.conductances(y, T1, T2).gas; });
                return py::make_tuple(hg, gap.radiativeConductance(T1, T2));
            },
            py::arg("separation"), py::arg("T1"), py::arg("T2"),
            "(h_g, h_r) [W/(m^2 K)] at the separations Y [m] and the two face temperatures T1, T2 [K] (the gas "
            "at their mean), as the boundary condition adds them to h_c. ParameterError without a gap.")
        .def("summary", &ContactInterface::summary, "A few lines for a log.");
}

} // namespace roughcontact_py
