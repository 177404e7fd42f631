// SPDX-License-Identifier: GPL-3.0-or-later
// ContactInterface's regime and the law's measured accuracy band at pressures: methods added to
// the class interface.cpp binds (bindings.hpp: bound after it).
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"

#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

void bindInterfaceRegime(py::module_& m)
{
    auto cls = py::reinterpret_borrow<py::class_<ContactInterface>>(m.attr("ContactInterface"));
    cls.def_property_readonly(
           "regime", [](const ContactInterface& ci) { return ci.regime().describe(); },
           "The regime at the table's ends (p/E', p/(E' h'), P/H, the plasticity index) and the law's "
           "measured "
           "accuracy band there (the log's lines).")
        .def(
            "regime_at",
            [](const ContactInterface& ci, const py::object& P) {
                const Array a = numbers(P, "pressures");
                std::vector<std::pair<std::string, double>> at;
                for (py::ssize_t i = 0; i < a.size(); ++i) {
                    at.emplace_back("", a.data()[i]);
                }
                return ci.regime().describeAt(at);
            },
            py::arg("pressures"),
            "The regime at the nominal pressures [Pa] (p/E', p/(E' h'), P/H) and the law's measured band of "
            "h/exact there, a line each (none for P <= 0), as the condition's log says it at its faces' "
            "pressures.")
        .def(
            "accuracy_band",
            [](const ContactInterface& ci, const py::object& P) {
                const auto band = [&](double p, bool high) {
                    if (!(p > 0.0) || ci.regime().areaModel == "boundaryElement") {
                        return std::numeric_limits<double>::quiet_NaN();
                    }
                    const RegimeAt r = ci.regime().at(p);
                    return r.band ? (high ? r.band->high : r.band->low) : std::numeric_limits<double>::quiet_NaN();
                };
                return py::make_tuple(vectorize(P, "pressures", [&](double p) { return band(p, false); }),
                                      vectorize(P, "pressures", [&](double p) { return band(p, true); }));
            },
            py::arg("pressures"),
            "(low, high): the smallest and largest h/exact the studies measured for this interface's law "
            "at the nominal pressures [Pa] (docs/checking.md); NaN where nothing was measured, for P <= 0 "
            "and for the exact model.")
        .def(
            "unloading_accuracy_band",
            [](const ContactInterface& ci, const py::object& peaks) {
                const auto band = [&](double peak, bool high) {
                    const auto b =
                        ci.lawUnloads() && peak > 0.0 ? ci.regime().unloadingBand(peak, peak) : std::nullopt;
                    return b ? (high ? b->high : b->low) : std::numeric_limits<double>::quiet_NaN();
                };
                return py::make_tuple(vectorize(peaks, "peaks", [&](double p) { return band(p, false); }),
                                      vectorize(peaks, "peaks", [&](double p) { return band(p, true); }));
            },
            py::arg("peaks"),
            "(low, high): the smallest and largest R / exact R the unloading studies measured for the "
            "default law's unloading branch at joints loaded to the peak pressures [Pa] (docs/checking.md): "
            "h below the peak carries it on top of accuracy_band at the pressure of the moment; NaN where it "
            "was not measured, for peak <= 0, and where the interface has no unloading branch (another law, "
            "no cap, loadHistory off, or the exact model's own unloading curves).");
}

} // namespace roughcontact_py
