// SPDX-License-Identifier: GPL-3.0-or-later
// The module's picture of one's own interface (interface/InterfaceCurves.hpp, io/CurvesPlot.hpp):
// plot() takes ContactInterface's keyword arguments, the pressures to draw across, a check's
// result, k1 and k2, and returns the curves as arrays, writing the PNG the CLI's --plot writes.
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceCurves.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/CurvesPlot.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

void bindPlot(py::module_& m)
{
    static const std::string plotDoc =
        "plot(file=None, *, surfaces, side1, side2, model=None, conductance=None, ..., pressures, points=None, "
        "check=None, k1=None, k2=None, gap=None, temperatures=(300, 300)): every law's h_c/k_s [1/m] on the whole "
        "surface at `points` pressures (None: " + std::to_string(defaultPlotPoints) + ") [Pa] across `pressures` "
        "(a decade each way of one), and where the exact "
        "answer lies by the chosen law's measured band (exact_low, exact_high; NaN where not measured); with gap "
        "h_gas and h_rad [W/(m^2 K)] at the face temperatures [K]. Returns a dict of arrays (pressures, each law, "
        "exact_low, exact_high, h_gas, h_rad); with `file` also draws them as a PNG (gnuplot, as the CLI's --plot), "
        "h with k1 and k2, and a check()'s result as the exact answer it implies at its pressures. The interface's "
        "keyword arguments are ContactInterface's.";
    m.def(
        "plot",
        [](const std::optional<std::string>& file, const std::vector<SurfaceSpec>& surfaces, const Material& side1,
           const Material& side2, const std::optional<std::string>& model, const std::optional<std::string>& conductance,
           std::optional<double> microhardness, std::optional<std::pair<double, double>> vickers,
           std::optional<double> hardness, bool hardnessFromYield, const std::vector<double>& pressures,
           std::optional<std::size_t> points, const SurfaceCheck* check, std::optional<double> k1, std::optional<double> k2,
           std::optional<GapSpec> gap, std::pair<double, double> temperatures) {
            if (pressures.empty()) {
                throw ParameterError("pressures", "give the pressures [Pa] to draw across (one or more)");
            }
            if (k1.has_value() != k2.has_value()) {
                throw ParameterError(k1 ? "k2" : "k1", "give both conductivities k1 and k2, or neither");
            }
            const InterfaceSpec spec = interfaceSpec(surfaces, side1, side2, model, conductance, microhardness, vickers,
                                                     std::nullopt, std::nullopt, std::nullopt, std::nullopt,
                                                     std::nullopt, std::nullopt, hardness, hardnessFromYield,
                                                     std::nullopt, gap, std::nullopt, std::nullopt, true);
            const auto [lo, hi] = std::minmax_element(pressures.begin(), pressures.end());
            if (!(*lo > 0.0)) {
                throw ParameterError("pressures", "draws h against pressures above 0");
            }
            InterfaceCurves curves;
            PlotExtras extras;
            {
                py::gil_scoped_release release;
                curves = interfaceCurves(checkInputsOf(spec), plotPressures(*lo, *hi, check != nullptr, points.value_or(defaultPlotPoints)));
                if (k1) {
                    extras.conductivity = harmonicMeanConductivity(*k1, *k2);
                }
                if (gap) {
                    const ContactInterface ci(spec); // the gap as the condition builds it
                    for (double P : curves.pressures) {
                        const GapConductances h =
                            ci.gap().conductances(ci.gap().separation(P), temperatures.first, temperatures.second);
                        extras.gas.push_back(h.gas);
                        extras.radiation.push_back(h.radiative);
                    }
                }
            }
            if (check) {
                extras.check.pressures = check->pressures;
                extras.check.answer = check->answerHPerK;
                extras.check.exactLow = check->answerExactLow;
                extras.check.exactHigh = check->answerExactHigh;
            }
            extras.title = equivalentSurface(spec.surfaces).source() + ": " + curves.chosenLaw + " and every law";
            if (file) {
                writeCurvesPlot(curves, extras, *file, "file");
            }
            py::dict d;
            d["pressures"] = toArray(curves.pressures);
            for (const LawCurve& l : curves.laws) {
                if (l.unavailable.empty()) {
                    d[py::str(l.name)] = toArray(l.hPerK);
                }
            }
            d["exact_low"] = toArray(curves.exactLow);
            d["exact_high"] = toArray(curves.exactHigh);
            if (!extras.gas.empty()) {
                d["h_gas"] = toArray(extras.gas);
                d["h_rad"] = toArray(extras.radiation);
            }
            return d;
        },
        py::arg("file") = py::none(), py::kw_only(), py::arg("surfaces"), py::arg("side1"), py::arg("side2"),
        py::arg("model") = py::none(), py::arg("conductance") = py::none(), py::arg("microhardness") = py::none(),
        py::arg("vickers") = py::none(), py::arg("hardness") = py::none(), py::arg("hardness_from_yield") = false,
        py::arg("pressures"), py::arg("points") = py::none(), py::arg("check") = py::none(), py::arg("k1") = py::none(),
        py::arg("k2") = py::none(), py::arg("gap") = py::none(),
        py::arg("temperatures") = std::pair<double, double>{300.0, 300.0},
        plotDoc.c_str());
}

} // namespace roughcontact_py
