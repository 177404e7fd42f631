// SPDX-License-Identifier: GPL-3.0-or-later
// The module's materials and its contact models by name: Material, ContactMaterials, the model
// names and Model (A_r/A_n at a pressure; persson's separation and conductance).
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <memory>
#include <optional>
#include <string>

using namespace roughContact;

namespace roughcontact_py {

void bindMaterials(py::module_& m)
{
    py::class_<Material>(m, "Material", "One solid: Young's modulus E [Pa], Poisson's ratio nu, yield strength Sy [Pa].")
        .def(py::init([](double E, double nu, std::optional<double> Sy, bool elastic) {
                 return Material{E, nu, Sy, elastic};
             }),
             py::arg("E"), py::arg("nu"), py::arg("Sy") = py::none(), py::arg("elastic") = false,
             "Material(E, nu, Sy=None, elastic=False): E [Pa], nu, Sy [Pa] (needed by jacksonGreen, truncation, "
             "greenwoodWilliamsonJG, majumdarBhushan); elastic=True says the solid does not yield (no Sy), "
             "which a pair with a yield strength on the other side only needs. Checked where it is used.")
        .def_readwrite("E", &Material::E, "Young's modulus [Pa]")
        .def_readwrite("nu", &Material::nu, "Poisson's ratio")
        .def_readwrite("Sy", &Material::Sy, "yield strength [Pa] or None")
        .def_readwrite("elastic", &Material::elastic, "True: said not to yield (no Sy)")
        .def("__repr__", [](const Material& x) {
            return "<roughcontact.Material E = " + number(x.E) + " Pa, nu = " + number(x.nu) +
                   (x.Sy ? ", Sy = " + number(*x.Sy) + " Pa" : std::string()) + (x.elastic ? ", elastic" : "") + ">";
        });

    py::class_<ContactMaterials>(m, "ContactMaterials",
                                 "What the models need of a pair of solids: E' and the yielding material's E, nu, "
                                 "Sy. A Material converts to one against a rigid flat.")
        .def(py::init(&ContactMaterials::againstRigidFlat), py::arg("material"),
             "One solid against a rigid flat: E' = E/(1 - nu^2).")
        .def_static("against_rigid_flat", &ContactMaterials::againstRigidFlat, py::arg("material"),
                    "One solid against a rigid flat: E' = E/(1 - nu^2).")
        .def_static(
            "pair", [](const Material& a, const Material& b) { return ContactMaterials::pair(a, b); }, py::arg("a"),
            py::arg("b"),
            "Two solids: 1/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2; the lower Sy yields first. Sy on one side only "
            "needs the other said elastic=True.")
        .def_static("from_reduced_modulus", &ContactMaterials::fromReducedModulus, py::arg("Eprime"),
                    py::arg("nu") = py::none(), py::arg("Sy") = py::none(),
                    "E' [Pa] given directly (multiscaleContact --Eprime), with nu and Sy [Pa] of the yielding "
                    "material.")
        .def_property_readonly("reduced_modulus", &ContactMaterials::reducedModulus, "E' [Pa].")
        .def_property_readonly(
            "hardness",
            [](const ContactMaterials& c) -> std::optional<double> {
                return c.hasYieldStrength() ? std::optional<double>(c.hardness("hardness")) : std::nullopt;
            },
            "H = 2.84 S_y of the yielding material [Pa] (the cap and microhardness taken from the yield "
            "strength), or None when neither solid yields.");
}

void bindModels(py::module_& m)
{
    m.def("model_names", &modelNames,
          "The area models by name: the multi-scale ones and greenwoodWilliamson, greenwoodWilliamsonJG, "
          "majumdarBhushan, persson (BoundaryElement is separate).");
    m.def("multiscale_model_names", &multiscaleModelNames,
          "The multi-scale models: hertz, jgh, jghConsistent, jacksonGreen, truncation.");

    py::class_<Model>(m, "Model",
                      "A contact model built by name for one surface and a pair of materials, then asked "
                      "for A_r/A_n at many pressures.")
        .def(py::init([](const std::string& name, const Spectrum& spectrum, const py::object& materials,
                         std::optional<double> D, std::optional<double> G) {
                 if (D.has_value() != G.has_value()) {
                     throw ParameterError("D/G", "give both or neither");
                 }
                 ModelOptions o;
                 if (D) {
                     o.fractal = FractalParameters{*D, *G};
                 }
                 Model x;
                 x.spectrum = std::make_shared<const Spectrum>(spectrum);
                 const ContactMaterials cm = materialsOf(materials);
                 x.model = makeContactModel(name, *x.spectrum, cm, o);
                 x.Eprime = cm.reducedModulus();
                 return x;
             }),
             py::arg("name"), py::arg("spectrum"), py::arg("materials"), py::arg("D") = py::none(),
             py::arg("G") = py::none(),
             "Model(name, spectrum, materials, D=None, G=None): name from model_names(); materials a "
             "ContactMaterials, a Material (against a rigid flat) or a pair of Materials; D, G [m]: majumdarBhushan's fractal "
             "parameters (fitted to the spectrum when None).")
        .def_property_readonly("name", [](const Model& x) { return x.model->name(); }, "The model's name.")
        .def_property_readonly("reduced_modulus", [](const Model& x) { return x.Eprime; }, "E' [Pa].")
        .def_property_readonly("spectrum", [](const Model& x) { return *x.spectrum; }, "The surface's spectrum.")
        .def_property_readonly("is_multiscale", [](const Model& x) { return x.multiscale() != nullptr; },
                               "True for the multi-scale models.")
        .def(
            "area_fraction",
            [](const Model& x, const py::object& P, std::optional<double> unloadFrom) {
                const ContactModel& cm = *x.model;
                const double Ep = x.Eprime;
                if (!unloadFrom) {
                    return vectorize(P, "pressures", [&](double p) { return cm.areaFraction(p / Ep); });
                }
                const MultiscaleModel* ms = x.multiscale();
                if (ms == nullptr) {
                    throw ParameterError("unload_from", "is for the multi-scale models (multiscale_model_names()) "
                                                        "and BoundaryElement, not " + cm.name());
                }
                const double peak = checkLoad(requirePositive("unload_from", *unloadFrom) / Ep);
                return vectorize(P, "pressures", [&](double p) { return ms->unloadingAreaFraction(p / Ep, peak); });
            },
            py::arg("pressures"), py::kw_only(), py::arg("unload_from") = py::none(),
            "A_r/A_n at the nominal pressures F/A_n [Pa] (a number or an array): the model at the load P/E'. "
            "unload_from [Pa] (multi-scale models): of a contact that has carried that pressure, each level "
            "unloading as a Hertzian contact from its peak (docs/theory.md §3.6).")
        .def(
            "area_fraction_at_load",
            [](const Model& x, const py::object& loads) {
                const ContactModel& cm = *x.model;
                return vectorize(loads, "loads", [&](double l) { return cm.areaFraction(l); });
            },
            py::arg("loads"),
            "A_r/A_n at the dimensionless loads F/(A_n E') (multiscaleContact --loads).")
        .def(
            "mean_separation",
            [](const Model& x, const py::object& P) {
                const PerssonModel& pm = x.persson("mean_separation");
                const double Ep = x.Eprime;
                return vectorize(P, "pressures", [&](double p) { return pm.meanSeparation(p / Ep); });
            },
            py::arg("pressures"), "persson only: the mean separation u [m] at the pressures [Pa] (inf at 0).")
        .def(
            "conductance_per_conductivity",
            [](const Model& x, const py::object& P) {
                const PerssonModel& pm = x.persson("conductance_per_conductivity");
                const double Ep = x.Eprime;
                return vectorize(P, "pressures", [&](double p) { return pm.conductancePerConductivity(p / Ep); });
            },
            py::arg("pressures"), "persson only: its own h_c/k_s [1/m] at the pressures [Pa].")
        .def("__repr__", [](const Model& x) { return "<roughcontact.Model " + x.model->name() + ">"; });
}

} // namespace roughcontact_py
