// SPDX-License-Identifier: GPL-3.0-or-later
// The module's conductance laws (ConductanceLaw by name) and the gap beside the contact: the
// gases, gas conduction across the gap (GasGap), radiation, the gap's separation correlations
// (docs/theory.md, "Gap conductance") and what a ContactInterface has in its gap (GapSpec).
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SpecSource.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/GapConductance.hpp"
#include "roughContact/thermal/Gas.hpp"

#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

using namespace roughContact;

namespace roughcontact_py {

namespace {

/// A conductance law, holding what it was built from alive.
struct Law {
    std::shared_ptr<const Spectrum> spectrum;
    std::shared_ptr<const ContactModel> model;
    std::unique_ptr<ConductanceLaw> law;
};

} // namespace

void bindThermal(py::module_& m)
{
    m.def("conductance_law_names", &conductanceLawNames,
          "The conductance laws by name: jacksonBhavnaniFerguson, multiscaleBarber, persson, mikic, "
          "cooperMikicYovanovich, fittedElastoPlastic.");
    m.def("default_conductance_law", &defaultConductanceLaw, "The law used unless another is named.");

    py::class_<Law>(m, "ConductanceLaw", "A contact conductance law by name: h_c/k_s [1/m] at a nominal pressure [Pa].")
        .def(py::init([](const std::string& name, const Model* model, const Spectrum* spectrum,
                         std::optional<double> Eprime, std::optional<SurfaceRoughness> roughness,
                         std::optional<double> microhardness, std::optional<std::pair<double, double>> vickers,
                         std::optional<double> hardness, std::optional<HeightSkewness> skewness) {
                 Law x;
                 ConductanceLawInputs in;
                 if (model != nullptr) {
                     x.model = model->model;
                     x.spectrum = model->spectrum;
                     in.multiscale = model->multiscale();
                     in.Eprime = model->Eprime;
                 }
                 if (spectrum != nullptr) {
                     x.spectrum = std::make_shared<const Spectrum>(*spectrum);
                 }
                 in.spectrum = x.spectrum.get();
                 if (Eprime) {
                     in.Eprime = *Eprime;
                 }
                 in.roughness = roughness;
                 in.microhardness = microhardness;
                 in.hardness = hardness;
                 in.skewness = skewness;
                 if (vickers) {
                     in.vickers = VickersCoefficients{vickers->first, vickers->second};
                 }
                 x.law = makeConductanceLaw(name, in);
                 return x;
             }),
             py::arg("name"), py::arg("model") = nullptr, py::arg("spectrum") = nullptr, py::arg("Eprime") = py::none(),
             py::arg("roughness") = py::none(), py::arg("microhardness") = py::none(), py::arg("vickers") = py::none(),
             py::arg("hardness") = py::none(), py::arg("skewness") = py::none(),
             "ConductanceLaw(name, model=None, spectrum=None, Eprime=None, roughness=None, microhardness=None, "
             "vickers=None, hardness=None, skewness=None): name from conductance_law_names(). What each law needs: "
             "jacksonBhavnaniFerguson and multiscaleBarber a multi-scale Model; persson a spectrum (the "
             "model's by default) and E' [Pa] (the model's by default); mikic a SurfaceRoughness and E'; "
             "cooperMikicYovanovich a SurfaceRoughness and the microhardness H_c [Pa] or the Vickers "
             "coefficients (c1 [Pa], c2); fittedElastoPlastic a SurfaceRoughness, E' and, for its plastic "
             "branch, the cap `hardness` H [Pa] (None: elastic) and a spectrum (the model's by default: its "
             "bandwidth ratio W, which also sets the elastic growth beyond p/(E' h') = 0.1, and its first "
             "level's share s1; without a spectrum W = 0.55 stands in and s1 plays no part), and a measured surface's HeightSkewness (SurfaceSpec.skewness(); None: Gaussian "
             "heights), taken with chance's share out (shrunk_skewness). ParameterError names what is missing.")
        .def_property_readonly("name", [](const Law& x) { return x.law->name(); }, "The law's name.")
        .def(
            "conductance_per_conductivity",
            [](const Law& x, const py::object& P, std::optional<double> unloadFrom) {
                const ConductanceLaw& law = *x.law;
                if (!unloadFrom) {
                    return vectorize(P, "pressures", [&](double p) { return law.perConductivity(p); });
                }
                if (!law.unloads()) {
                    throw ParameterError("unload_from", "the law " + law.name() + " has no unloading branch "
                                                        "(fittedElastoPlastic with a hardness has one)");
                }
                const double peak = requirePositive("unload_from", *unloadFrom);
                return vectorize(P, "pressures",
                                 [&](double p) { return law.perConductivity(p) * law.unloadingFactor(p, peak); });
            },
            py::arg("pressures"), py::kw_only(), py::arg("unload_from") = py::none(),
            "h_c/k_s [1/m] at the nominal pressures [Pa] (inf at complete contact). unload_from [Pa]: the "
            "heaviest pressure the joint has carried; below it the law's unloading branch (docs/theory.md "
            "§5.7c), at and above it the loading value. ParameterError for a law without one (unloads).")
        .def_property_readonly("unloads", [](const Law& x) { return x.law->unloads(); },
                               "True when the law has an unloading branch (fittedElastoPlastic with a hardness).")
        .def(
            "mean_separation",
            [](const Law& x, const py::object& P) {
                const ConductanceLaw& law = *x.law;
                return vectorize(P, "pressures", [&](double p) { return law.meanSeparation(p); });
            },
            py::arg("pressures"),
            "The mean-plane separation [m] at the pressures [Pa] where the law defines one (persson, "
            "multiscaleBarber), NaN otherwise.");

    // ---- the gap beside the contact (gas and radiation; docs/theory.md, "Gap conductance")
    m.def("gas_names", &gasNames, "The gases known by name: air, helium, argon, nitrogen.");
    py::class_<GasProperties>(m, "Gas",
                              "A gas's properties: by name with roughcontact.gas('air'), or as numbers "
                              "(Gas(conductivity=..., ...); name 'user').")
        .def(py::init([](double conductivity, double conductivityExponent, double referenceTemperature,
                         double heatCapacityRatio, double prandtl, double meanFreePath, double referencePressure,
                         double accommodation) {
                 GasProperties g;
                 g.name = "user";
                 g.conductivity = conductivity;
                 g.conductivityExponent = conductivityExponent;
                 g.referenceTemperature = referenceTemperature;
                 g.heatCapacityRatio = heatCapacityRatio;
                 g.prandtl = prandtl;
                 g.meanFreePath = meanFreePath;
                 g.referencePressure = referencePressure;
                 g.accommodation = accommodation;
                 checkGas(g);
                 return g;
             }),
             py::kw_only(), py::arg("conductivity"), py::arg("conductivity_exponent"),
             py::arg("reference_temperature"), py::arg("heat_capacity_ratio"), py::arg("prandtl"),
             py::arg("mean_free_path"), py::arg("reference_pressure") = standardAtmosphere, py::arg("accommodation"),
             "k_g [W/(m K)] at T0 [K], k_g(T) = k_g (T/T0)^conductivity_exponent, gamma, Pr, the mean free "
             "path [m] at T0 and reference_pressure [Pa], the default accommodation coefficient. "
             "ParameterError names a number out of range.")
        .def_readonly("name", &GasProperties::name, "'air', ..., or 'user'.")
        .def_readonly("conductivity", &GasProperties::conductivity, "k_g [W/(m K)] at the reference temperature.")
        .def_readonly("conductivity_exponent", &GasProperties::conductivityExponent, "n in k_g (T/T0)^n.")
        .def_readonly("reference_temperature", &GasProperties::referenceTemperature, "T0 [K].")
        .def_readonly("heat_capacity_ratio", &GasProperties::heatCapacityRatio, "gamma.")
        .def_readonly("prandtl", &GasProperties::prandtl, "Pr.")
        .def_readonly("mean_free_path", &GasProperties::meanFreePath, "Lambda0 [m] at T0 and P0.")
        .def_readonly("reference_pressure", &GasProperties::referencePressure, "P0 [Pa].")
        .def_readonly("accommodation", &GasProperties::accommodation, "The default accommodation coefficient.")
        .def("__repr__", [](const GasProperties& g) {
            std::ostringstream os;
            os << "<roughcontact.Gas " << g.name << ": k_g " << g.conductivity << " W/(m K) at "
               << g.referenceTemperature << " K>";
            return os.str();
        });
    m.def("gas", &gasByName, py::arg("name"),
          "The tabulated properties of a gas by name (gas_names()); ParameterError for any other name.");

    py::class_<GasGap>(m, "GasGap",
                       "Gas conduction across the gap: h_g = k_g(T)/(Y + M), M the rarefaction parameter "
                       "from the accommodation coefficients, gamma, Pr and the mean free path at the gas "
                       "pressure.")
        .def(py::init([](const GasProperties& gas, std::optional<double> pressure,
                         std::optional<std::pair<double, double>> accommodation) {
                 GasGapSpec spec;
                 spec.gas = gas;
                 spec.pressure = pressure.value_or(spec.pressure); // None: the core's, one atmosphere
                 if (accommodation) {
                     spec.accommodation1 = accommodation->first;
                     spec.accommodation2 = accommodation->second;
                 }
                 return GasGap(spec);
             }),
             py::arg("gas"), py::arg("pressure") = py::none(), py::arg("accommodation") = py::none(),
             "gas a Gas; pressure P_g [Pa] (None: one standard atmosphere); accommodation (a1, a2), each in (0, 1], or None for the gas's "
             "default.")
        .def_property_readonly("accommodation",
                               [](const GasGap& g) {
                                   return std::make_pair(*g.spec().accommodation1, *g.spec().accommodation2);
                               },
                               "The accommodation coefficients (a1, a2) as used (the defaults resolved).")
        .def(
            "conductivity", [](const GasGap& g, const py::object& T) { return vectorize(T, "T", [&](double t) { return g.conductivity(t); }); },
            py::arg("T"), "k_g [W/(m K)] at the temperatures T [K].")
        .def(
            "mean_free_path", [](const GasGap& g, const py::object& T) { return vectorize(T, "T", [&](double t) { return g.meanFreePath(t); }); },
            py::arg("T"), "Lambda [m] at T [K] and the gas pressure.")
        .def(
            "rarefaction", [](const GasGap& g, const py::object& T) { return vectorize(T, "T", [&](double t) { return g.rarefaction(t); }); },
            py::arg("T"), "M [m] at T [K].")
        .def(
            "conductance",
            [](const GasGap& g, const py::object& Y, double T) { return vectorize(Y, "separation", [&](double y) { return g.conductance(y, T); }); },
            py::arg("separation"), py::arg("T"), "h_g [W/(m^2 K)] at the separations Y [m] and gas temperature T [K].");

    // numpy's broadcasting over all four (pybind11's vectorize).
    m.def(
        "radiative_conductance",
        [](const py::object& T1, const py::object& T2, const py::object& e1, const py::object& e2) {
            using Broadcast = py::array_t<double, py::array::forcecast>;
            static auto f = py::vectorize([](double t1, double t2, double a1, double a2) {
                return radiativeConductance(t1, t2, a1, a2);
            });
            return f(Broadcast(numbers(T1, "T1")), Broadcast(numbers(T2, "T2")), Broadcast(numbers(e1, "e1")),
                     Broadcast(numbers(e2, "e2")));
        },
          py::arg("T1"), py::arg("T2"), py::arg("e1"), py::arg("e2"),
          "h_r [W/(m^2 K)] of grey parallel plates at T1, T2 [K] with emissivities e1, e2 in (0, 1] (numbers or "
          "arrays, broadcast): sigma_SB (T1^2 + T2^2)(T1 + T2)/(1/e1 + 1/e2 - 1).");
    m.def(
        "gap_separation",
        [](const py::object& P, double sigma, double Hc) {
            return vectorize(P, "pressures", [&](double p) { return gapSeparationCorrelation(p, sigma, Hc); });
        },
        py::arg("pressures"), py::arg("sigma"), py::arg("Hc"),
        "The mean-plane separation Y [m] of a plastic Gaussian contact at P [Pa] > 0, sigma [m], microhardness "
        "Hc [Pa]: the published fit 1.184 sigma (-ln(3.132 P/Hc))^0.547 within 1e-6..0.1 of P/Hc, the exact "
        "Gaussian form outside.");
    m.def(
        "gap_separation_gaussian",
        [](const py::object& P, double sigma, double Hc) {
            return vectorize(P, "pressures", [&](double p) { return gapSeparationGaussian(p, sigma, Hc); });
        },
        py::arg("pressures"), py::arg("sigma"), py::arg("Hc"),
        "The exact Gaussian form: Y = sqrt(2) sigma erfc^-1(2 P/Hc) [m] (0 from P/Hc = 1/2 on).");

    py::class_<GapSpec>(m, "GapSpec",
                        "What is in the gap of a ContactInterface: a gas and/or radiation (the OpenFOAM "
                        "dictionary's gap entry).")
        .def(py::init([](const py::object& gas, std::optional<double> pressure,
                         std::optional<std::pair<double, double>> accommodation,
                         std::optional<std::pair<double, double>> emissivity) {
                 // Through the core's reader of a gap (InterfaceSpecReader.hpp): the dictionary's
                 // rules. A Gas object goes in as its properties and keeps its name.
                 SpecValues v("GapSpec", [](const std::string& key) { return key; });
                 std::optional<GasProperties> object;
                 if (py::isinstance<py::str>(gas)) {
                     v.set("gas", gas.cast<std::string>());
                 } else if (!gas.is_none()) {
                     object = gas.cast<GasProperties>();
                     SpecValues p("GapSpec gas", [](const std::string& key) { return "gas." + key; });
                     p.set("conductivity", object->conductivity)
                         .set("conductivityExponent", object->conductivityExponent)
                         .set("referenceTemperature", object->referenceTemperature)
                         .set("heatCapacityRatio", object->heatCapacityRatio)
                         .set("prandtl", object->prandtl)
                         .set("meanFreePath", object->meanFreePath)
                         .set("referencePressure", object->referencePressure)
                         .set("accommodation", object->accommodation);
                     v.set("gas", std::make_shared<const SpecValues>(p));
                 }
                 if (pressure) {
                     v.set("pressure", *pressure); // None: the reader's default (one atmosphere)
                 }
                 if (accommodation) {
                     v.set("accommodation", std::vector<double>{accommodation->first, accommodation->second});
                 }
                 if (emissivity) {
                     v.set("emissivity", std::vector<double>{emissivity->first, emissivity->second});
                 }
                 GapSpec g = readGapSpec(v);
                 if (object) {
                     g.gas->gas.name = object->name;
                 }
                 return g;
             }),
             py::kw_only(), py::arg("gas") = py::none(), py::arg("pressure") = py::none(),
             py::arg("accommodation") = py::none(), py::arg("emissivity") = py::none(),
             "gas a name ('air'), a Gas or None (vacuum); pressure P_g [Pa] (None: one standard atmosphere); accommodation (a1, a2), each in "
             "(0, 1], or None for the gas's default; emissivity (e1, e2) for radiation, or None. "
             "ContactInterface checks it.");
}

} // namespace roughcontact_py
