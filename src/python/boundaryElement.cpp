// SPDX-License-Identifier: GPL-3.0-or-later
// The module's boundary-element reference: BoundaryElement, the exact solution of an areal surface
// against a flat (its progress reports, area_fraction and the curve).
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "roughContact/parallel/Threads.hpp"
#include "convert.hpp"

#include "roughContact/Limits.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

namespace {

/// A boundary-element model (the exact reference) on an areal surface.
struct BoundaryElement {
    /// The progress callable (or None); the model's callback calls it with the GIL held. Kept
    /// here, as long as the model, so that the callback can hold a plain pointer to it (a
    /// py::object copied without the GIL would change its reference count unguarded).
    py::object progress;
    std::unique_ptr<BoundaryElementModel> model;
};

} // namespace

void bindBoundaryElement(py::module_& m)
{
    py::class_<BoundaryElement>(m, "BoundaryElement",
                                "The exact reference: the boundary-element solution of an areal surface against "
                                "a flat (multiscaleContact --model boundaryElement). Slow: an FFT contact solve "
                                "per pressure; keep grids small (64 x 64 takes well under a second a pressure, "
                                "the 650 x 650 X3P map tens of seconds).")
        .def(py::init([](const ArealSurface& surface, const py::object& materials, bool periodic,
                         std::optional<double> hardness, double tolerance, std::size_t maxIterations,
                         std::optional<std::string> detrend, const py::object& progress, bool verbose,
                         double progressEvery, const py::object& threads, bool mirror) {
                 BoundaryElementOptions o;
                 o.periodic = periodic;
                 o.mirrored = mirror;
                 if (detrend) {
                     o.detrend = parseDetrend(*detrend, "detrend");
                 }
                 o.hardness = hardness;
                 o.tolerance = tolerance;
                 o.maxIterations = maxIterations;
                 o.progressEvery = limits::requireInRange("progress_every", progressEvery, 0.0, 1e6, "s");
                 BoundaryElement x;
                 if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
                     throw py::type_error("progress: expected a callable or None");
                 }
                 if (!progress.is_none() || verbose) {
                     // progress(dict(stage, iteration, residual, tolerance, seconds)) every 3 s
                     // of a long solve; verbose: the CLI's line on sys.stderr instead.
                     x.progress = progress.is_none() ? py::module_::import("sys").attr("stderr") : progress;
                     PyObject* target = x.progress.ptr();
                     const bool toStream = progress.is_none();
                     o.progress = [target, toStream](const SolveProgress& s) {
                         py::gil_scoped_acquire acquire;
                         if (toStream) {
                             std::ostringstream os;
                             os << "roughcontact: boundaryElement " << s.stage << " solve: iteration " << s.iteration
                                << ", residual " << s.residual << " (tolerance " << s.tolerance << "), " << s.seconds
                                << " s\n";
                             py::handle(target).attr("write")(os.str());
                             py::handle(target).attr("flush")();
                         } else {
                             py::dict d;
                             d["stage"] = s.stage;
                             d["iteration"] = s.iteration;
                             d["residual"] = s.residual;
                             d["tolerance"] = s.tolerance;
                             d["seconds"] = s.seconds;
                             // (Assigned: the statement `py::handle(target)(d);` alone is the
                             // declaration `py::handle target(d);`, C++'s most vexing parse,
                             // and calls nothing.)
                             const py::object ignored = py::handle(target)(d);
                         }
                     };
                 }
                 if (!threads.is_none()) {
                     setThreads(threads.cast<int>());
                 }
                 const double Ep = materialsOf(materials).reducedModulus();
                 py::gil_scoped_release release;
                 x.model = std::make_unique<BoundaryElementModel>(surface, Ep, o);
                 return x;
             }),
             py::arg("surface"), py::arg("materials"), py::arg("periodic") = false, py::arg("hardness") = py::none(),
             py::arg("tolerance") = 1e-8, py::arg("max_iterations") = 20000, py::arg("detrend") = py::none(),
             py::arg("progress") = py::none(), py::arg("verbose") = false, py::arg("progress_every") = 3.0,
             py::arg("threads") = py::none(), py::arg("mirror") = false,
             "BoundaryElement(surface, materials, periodic=False, hardness=None, tolerance=1e-8, "
             "max_iterations=20000, detrend=None, progress=None, verbose=False, progress_every=3.0, "
             "threads=None, mirror=False): mirror solves a measured map mirrored about its edges into one "
             "period of a periodic surface (an interface: no edges, no patch constriction to remove; not "
             "with periodic); threads sets the process's threads of the solves (set_threads; None: as they "
             "are, by default what the machine has); progress "
             "a callable called every progress_every seconds of a long solve with a dict (stage, iteration, "
             "residual, tolerance, seconds), or "
             "verbose=True for a line on sys.stderr; surface an ArealSurface, detrended here as detrend says "
             "('none', 'mean' or 'plane'; None: 'mean' when periodic, 'plane' otherwise); materials a ContactMaterials, "
             "a Material or a pair of Materials; periodic: solve it as one period (synthesized surfaces), else zero-padded (measured "
             "maps); hardness [Pa]: a perfectly plastic cap p <= H.")
        .def_property_readonly("reduced_modulus", [](const BoundaryElement& x) { return x.model->reducedModulus(); },
                               "E' [Pa].")
        .def_property_readonly("patch_conductance_per_conductivity",
                               [](const BoundaryElement& x) { return x.model->patchConductancePerConductivity(); },
                               "Non-periodic: h/k_s [1/m] of the whole patch bonded; periodic or mirrored: inf.")
        .def(
            "area_fraction",
            [](const BoundaryElement& x, const py::object& P) {
                const BoundaryElementModel& bm = *x.model;
                const double Ep = bm.reducedModulus();
                return vectorize(P, "pressures", [&](double p) { return bm.areaFraction(p / Ep); });
            },
            py::arg("pressures"), "A_r/A_n at the nominal pressures [Pa], each solved from scratch.")
        .def(
            "curve",
            [](const BoundaryElement& x, const py::object& P, std::optional<double> unloadFrom) {
                const Array given = numbers(P, "pressures");
                const std::vector<double> pressures(given.data(), given.data() + given.size());
                const double Ep = x.model->reducedModulus();
                std::vector<double> loads;
                for (double p : pressures) {
                    loads.push_back(p / Ep);
                }
                if (unloadFrom) {
                    requireUnloadingPeak(*unloadFrom, x.model->options().hardness, "unload_from", "hardness");
                }
                std::vector<BoundaryElementPoint> points;
                {
                    py::gil_scoped_release release;
                    points = unloadFrom ? x.model->loadPath(*unloadFrom / Ep, loads) : x.model->curve(loads);
                }
                const auto column = [&](auto get) {
                    std::vector<double> v;
                    for (const BoundaryElementPoint& q : points) {
                        v.push_back(static_cast<double>(get(q)));
                    }
                    return toArray(v);
                };
                py::dict d;
                d["pressure"] = toArray(pressures);
                d["load"] = column([](const BoundaryElementPoint& q) { return q.load; });
                d["area_fraction"] = column([](const BoundaryElementPoint& q) { return q.areaFraction; });
                d["plastic_fraction"] = column([](const BoundaryElementPoint& q) { return q.plasticFraction; });
                d["mean_separation"] = column([](const BoundaryElementPoint& q) { return q.meanSeparation; });
                d["conductance_per_conductivity"] =
                    column([](const BoundaryElementPoint& q) { return q.conductancePerConductivity; });
                d["iterations"] = column([](const BoundaryElementPoint& q) { return q.iterations; });
                d["residual"] = column([](const BoundaryElementPoint& q) { return q.residual; });
                d["patch_correction_gain"] = column([](const BoundaryElementPoint& q) { return q.patchCorrectionGain; });
                d["spots"] = column([](const BoundaryElementPoint& q) { return q.spots.count; });
                d["mean_spot_radius"] = column([](const BoundaryElementPoint& q) { return q.spots.meanRadius(); });
                if (const std::string warning = patchCorrectionWarning(points, x.model->reducedModulus(), "mirror=True"); !warning.empty()) {
                    py::module_::import("warnings").attr("warn")(warning, py::module_::import("builtins").attr("RuntimeWarning"), 1);
                }
                return d;
            },
            py::arg("pressures"), py::arg("unload_from") = py::none(),
            "The curve at the nominal pressures [Pa] (solved in increasing order, each warm-started from the one "
            "below; returned in the order given); unload_from [Pa], with a hardness: of a joint that has carried "
            "that peak (the deformed surface unloaded elastically, loaded on with the cap above the peak; "
            "multiscaleContact --unload-from), as a dict of 1-D arrays: pressure [Pa], load (P/E'), "
            "area_fraction, plastic_fraction, mean_separation [m], conductance_per_conductivity [1/m], "
            "iterations, residual, spots, mean_spot_radius [m] (0 without a spot) (the columns of multiscaleContact "
            "--model boundaryElement), and "
            "patch_correction_gain (a map solved padded: how many times 1/h_c = 1/h_spots - 1/h_patch multiplies "
            "an error of the spots' h; 1 periodic or mirrored). A RuntimeWarning when it exceeds 50 at some "
            "pressure: the map's h_c is not to be trusted there; solve it mirror=True.");
}

} // namespace roughcontact_py
