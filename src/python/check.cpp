// SPDX-License-Identifier: GPL-3.0-or-later
// The module's check of a user's own surface (SurfaceCheck.hpp): check() takes ContactInterface's
// keyword arguments and the check's own, and returns a SurfaceCheck.
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/parallel/Threads.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

namespace {

// [1, 2, 3]: a list of seeds as Python writes it, for a docstring.
std::string seedList(const std::vector<std::uint64_t>& seeds)
{
    std::string out;
    for (std::uint64_t s : seeds) {
        out += (out.empty() ? "[" : ", ") + std::to_string(s);
    }
    return out + "]";
}

} // namespace

void bindCheck(py::module_& m)
{
    py::class_<SurfaceCheck>(
        m, "SurfaceCheck",
        "What check() found: the answer for the user's whole surface (the chosen law, and the exact "
        "answer it implies), the exact h_c/k_s of the checked surface at the checked pressures "
        "and every law's ratio to it.")
        .def_readonly("surface", &SurfaceCheck::surface,
                      "What was solved (the map, or the seeds synthesized).")
        .def_readonly("regime", &SurfaceCheck::regime, "'elastic' or 'capped at H = ... Pa'.")
        .def_readonly("hardness", &SurfaceCheck::hardness, "The cap H [Pa], or None (elastic).")
        .def_readonly("reduced_modulus", &SurfaceCheck::reducedModulus, "E' [Pa].")
        .def_readonly("gradient", &SurfaceCheck::gradient,
                      "h': the areal rms gradient of the checked surface.")
        .def_readonly("lay_stretch", &SurfaceCheck::layStretch,
                      "The lay ratio of profiles given across and along a lay (their rms slopes' ratio): the "
                      "checked surfaces are stretched so along y. 1 for an isotropic surface or a map.")
        .def_readonly("levels_kept", &SurfaceCheck::levelsKept, "Levels of the spectrum in the check.")
        .def_readonly("levels_given", &SurfaceCheck::levelsGiven, "Levels of the spectrum given.")
        .def_readonly("unload_from", &SurfaceCheck::unloadFrom,
                      "The peak [Pa] the check unloaded from (None: none).")
        .def_property_readonly(
            "exact_unloading_h_per_k", [](const SurfaceCheck& c) { return toArray(c.exactUnloadingHPerK); },
            "With unload_from: the checked surface's exact h_c/k_s unloaded from it [1/m].")
        .def_property_readonly(
            "chosen_unloading_ratio", [](const SurfaceCheck& c) { return toArray(c.chosenUnloadingRatio); },
            "With unload_from: the chosen law's h on unloading (its unloading branch, or its "
            "loading value for a law without one) over the exact unloading h.")
        .def_readonly("chosen_unloads", &SurfaceCheck::chosenUnloads,
                      "True when the chosen law has an unloading branch (chosen_unloading_ratio holds it).")
        .def_readonly(
            "light_load_periods", &SurfaceCheck::lightLoadPeriods,
            "The period [scan lengths] of the pressures up to p/(E' h') = 1e-3 (1: none on a longer one).")
        .def_readonly("light_levels_kept", &SurfaceCheck::lightLevelsKept,
                      "Levels of the spectrum on that period in the check (0: none).")
        .def_readonly("light_levels_of_given", &SurfaceCheck::lightLevelsOfGiven,
                      "Levels of the spectrum given that the longer period's surfaces hold (0: none solved).")
        .def_property_readonly(
            "long_period_weights", [](const SurfaceCheck& c) { return toArray(c.longPeriodWeights); },
            "Each pressure's weight of the longer period: 1 up to p/(E' h') = 1e-3, 0 from 1e-2, falling "
            "log-linearly between (the two joined there).")
        .def_property_readonly(
            "pressures", [](const SurfaceCheck& c) { return toArray(c.pressures); },
            "The checked pressures [Pa].")
        .def_property_readonly(
            "dropped", [](const SurfaceCheck& c) { return toArray(c.dropped); },
            "Pressures asked for [Pa] outside the checked range.")
        .def_property_readonly(
            "answer", [](const SurfaceCheck& c) { return toArray(c.answerHPerK); },
            "The answer: the chosen law's h_c/k_s [1/m] on the whole surface as given, at the "
            "checked pressures (what the condition uses).")
        .def_property_readonly(
            "answer_exact_low", [](const SurfaceCheck& c) { return toArray(c.answerExactLow); },
            "The exact h_c/k_s [1/m] the answer implies (the answer over the law's ratio), at "
            "the seeds' smallest; NaN where the exact answer is not trusted.")
        .def_property_readonly(
            "answer_exact_high", [](const SurfaceCheck& c) { return toArray(c.answerExactHigh); },
            "The same at the seeds' largest.")
        .def_property_readonly(
            "checked_exact", [](const SurfaceCheck& c) { return toArray(c.exactHPerK); },
            "The exact h_c/k_s [1/m] of the checked surface (geometric mean over the seeds): a "
            "1-D description's band-limited synthesized surfaces, not the whole surface.")
        .def_property_readonly(
            "checked_exact_low", [](const SurfaceCheck& c) { return toArray(c.exactHPerKLow); },
            "The seeds' smallest exact h_c/k_s [1/m] of the checked surface.")
        .def_property_readonly(
            "checked_exact_high", [](const SurfaceCheck& c) { return toArray(c.exactHPerKHigh); },
            "The seeds' largest exact h_c/k_s [1/m] of the checked surface.")
        .def_property_readonly(
            "checked_area", [](const SurfaceCheck& c) { return toArray(c.exactArea); },
            "The exact A_r/A_n of the checked surface (mean over the seeds).")
        .def_property_readonly(
            "exact_trusted",
            [](const SurfaceCheck& c) {
                py::array_t<bool> a(static_cast<py::ssize_t>(c.exactTrusted.size()));
                for (std::size_t i = 0; i < c.exactTrusted.size(); ++i) {
                    a.mutable_at(i) = c.exactTrusted[i];
                }
                return a;
            },
            "Per pressure: False where the exact answer is not to be trusted (exact_warning); such a "
            "pressure counts "
            "for no law.")
        .def_property_readonly(
            "ratios",
            [](const SurfaceCheck& c) {
                py::dict d;
                for (const CheckedLaw& l : c.laws) {
                    if (l.unavailable.empty()) {
                        d[py::str(l.name)] = toArray(l.ratio);
                    }
                }
                return d;
            },
            "{law: array of h_c/k_s law / exact at the pressures}, for every law that could be built.")
        .def_property_readonly(
            "unavailable",
            [](const SurfaceCheck& c) {
                py::dict d;
                for (const CheckedLaw& l : c.laws) {
                    if (!l.unavailable.empty()) {
                        d[py::str(l.name)] = l.unavailable;
                    }
                }
                return d;
            },
            "{law: why it was not checked}.")
        .def_readonly("chosen_law", &SurfaceCheck::chosenLaw,
                      "The law judged (the conductance given, or the default).")
        .def_readonly(
            "closest_law", &SurfaceCheck::closestLaw,
            "The law with the smallest worst factor over the counted pressures ('' when none is counted).")
        .def_property_readonly(
            "closest_holds", &SurfaceCheck::closestHolds,
            "Whether the closest law is within 25 % at every counted pressure (then it is the law "
            "to use; else none is).")
        .def_property_readonly(
            "chosen_misses", [](const SurfaceCheck& c) { return toArray(c.chosenMisses()); },
            "The counted pressures [Pa] at which the chosen law is off by more than 25 %.")
        .def_property_readonly(
            "chosen_unloading_misses",
            [](const SurfaceCheck& c) { return toArray(c.chosenUnloadingMisses()); },
            "With unload_from: the counted pressures [Pa] at which the chosen law's h on unloading is off "
            "the exact "
            "unloading conductance by more than 25 % (empty without a peak).")
        .def_property_readonly(
            "untrusted", [](const SurfaceCheck& c) { return toArray(c.untrusted()); },
            "The pressures [Pa] where the exact answer is not to be trusted (not counted).")
        .def_readonly(
            "exact_warning", &SurfaceCheck::exactWarning,
            "A map solved padded near complete contact: that its exact h_c (and the ratios) are not "
            "to be trusted at some pressures, and to solve it mirrored; empty otherwise.")
        .def_readonly("small_cell_note", &SurfaceCheck::smallCellNote,
                      "A profile or spectrum checked where the longer period takes part (below p/(E' h') = "
                      "1e-2): that its exact answer there is a "
                      "small periodic cell's, which may be too high for a large joint; empty otherwise (and "
                      "for a map).")
        .def_readonly("seconds", &SurfaceCheck::seconds, "How long the check took [s].")
        .def("report", &SurfaceCheck::report, "The table a terminal or a log shows.")
        .def("csv", &SurfaceCheck::csv, "The numbers as CSV (the CLI's --check).")
        .def("__repr__", &SurfaceCheck::report);

    m.def(
        "measured_accuracy",
        [](const std::string& law, const std::string& model, bool capped, double loadPerGradient) -> py::object {
            const std::optional<AccuracyBand> b = measuredAccuracy(law, model, capped, loadPerGradient);
            if (!b) {
                return py::none();
            }
            py::dict d;
            d["low"] = b->low;
            d["high"] = b->high;
            d["from"] = b->from;
            d["to"] = b->to;
            d["surfaces"] = b->surfaces;
            d["report"] = b->report;
            return d;
        },
        py::arg("law"), py::arg("model"), py::arg("capped"), py::arg("load_per_gradient"),
        "The band of law / exact the engineering-range study (or, for the area models it does not run, the "
        "fidelity study) measured for `law` on the area `model` against the capped (p <= H) or elastic "
        "reference, in the decade of p/(E' h') holding load_per_gradient: a dict (low, high, from, to, surfaces, "
        "report), or None where nothing was measured.");

    // The signature's default light-load period is the core's (one place for it).
    static const std::string checkDoc =
        "check(*, surfaces, side1, side2, model=None, conductance=None, ..., pressures=[], grid=None, "
        "seeds=None, count=None, progress=None, threads=None, mirror=None, light_load_periods=None, unload_from=None): the exact model "
        "(boundaryElement) on the user's "
        "own surface (an areal map as it is, or mirror=True: mirrored about its edges into a periodic surface; a 1-D description as `seeds` surfaces of grid x grid synthesized from its "
        "spectrum, cut at grid/8 levels, up to p/(E' h') = 1e-3 on periods of light_load_periods scan lengths, 1 to 64, None: " +
        std::to_string(SurfaceCheckOptions{}.lightLoadPeriods) + "; refused for a map; joined with one scan length's up to 1e-2; "
        "each surface holding at least 4 of the spectrum's levels) at `pressures` [Pa] (at most 5) or `count` pressures across "
        "[min_pressure, max_pressure], within p/(E' h') 1e-4 to 1e-1; capped at H where hardness, "
        "hardness_from_yield or S_y say, elastic otherwise; every law's ratio to it. The interface's keyword "
        "arguments are ContactInterface's. None: grid " + std::to_string(SurfaceCheckOptions{}.gridSize) +
        ", seeds " + seedList(SurfaceCheckOptions{}.seeds) + ", count " + std::to_string(SurfaceCheckOptions{}.pressureCount) + ". progress: a callable given a line after each solve. threads: the "
        "process's threads of the solves (set_threads; None: as they are). unload_from [Pa], with a cap: the joint "
        "has carried it; the check also unloads each surface from it (exact_unloading_h_per_k, "
        "chosen_unloading_ratio). About 0.5 s a pressure and seed at 512^2.";
    m.def(
        "check",
        [](const std::vector<SurfaceSpec>& surfaces, const Material& side1, const Material& side2,
           const std::optional<std::string>& model, const std::optional<std::string>& conductance,
           std::optional<double> microhardness,
           std::optional<std::pair<double, double>> vickers, std::optional<double> minPressure,
           std::optional<double> maxPressure, std::optional<bool> periodic, std::optional<double> hardness,
           bool hardnessFromYield, std::optional<std::string> detrend, const std::vector<double>& pressures,
           std::optional<std::size_t> grid, const std::optional<std::vector<std::uint64_t>>& seeds,
           std::optional<std::size_t> count, const py::object& progress,
           const py::object& threads, std::optional<bool> mirror, std::optional<std::uint64_t> lightLoadPeriods,
           std::optional<double> unloadFrom) {
            const InterfaceSpec spec = interfaceSpec(surfaces, side1, side2, model, conductance, microhardness, vickers,
                                                     minPressure, maxPressure, std::nullopt, std::nullopt, std::nullopt,
                                                     periodic, hardness, hardnessFromYield, std::nullopt,
                                                     std::nullopt, detrend, mirror, true);
            SurfaceCheckOptions o; // what is left None: the core's
            o.names = {"grid", "seeds", "pressures", "light_load_periods", "unload_from"};
            o.unloadFrom = unloadFrom;
            o.gridSize = grid.value_or(o.gridSize);
            o.seeds = seeds.value_or(o.seeds);
            o.pressureCount = count.value_or(o.pressureCount);
            o.pressures = pressures;
            if (lightLoadPeriods) {
                o.lightLoadPeriods = checkedLightLoadPeriods(*lightLoadPeriods, surfaces, "light_load_periods");
            }
            if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
                throw py::type_error("progress: expected a callable or None");
            }
            PyObject* target = progress.ptr();
            if (!progress.is_none()) {
                // progress(line) after each solve, with the GIL held.
                o.log = [target](const std::string& line) {
                    py::gil_scoped_acquire acquire;
                    const py::object ignored = py::handle(target)(line);
                };
            }
            if (!threads.is_none()) {
                setThreads(threads.cast<int>());
            }
            py::gil_scoped_release release;
            return checkSurface(spec, o);
        },
        py::kw_only(), py::arg("surfaces"), py::arg("side1"), py::arg("side2"), py::arg("model") = py::none(),
        py::arg("conductance") = py::none(), py::arg("microhardness") = py::none(), py::arg("vickers") = py::none(),
        py::arg("min_pressure") = py::none(), py::arg("max_pressure") = py::none(), py::arg("periodic") = py::none(),
        py::arg("hardness") = py::none(), py::arg("hardness_from_yield") = false, py::arg("detrend") = py::none(),
        py::arg("pressures") = std::vector<double>{}, py::arg("grid") = py::none(),
        py::arg("seeds") = py::none(), py::arg("count") = py::none(), py::arg("progress") = py::none(),
        py::arg("threads") = py::none(), py::arg("mirror") = py::none(), py::arg("light_load_periods") = py::none(),
        py::arg("unload_from") = py::none(), checkDoc.c_str());
}

} // namespace roughcontact_py
