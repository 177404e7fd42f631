// SPDX-License-Identifier: GPL-3.0-or-later
// The module's pieces: one bind function per topic, called in this order by module.cpp (the
// order matters: a signature names a class as roughcontact.X only once X is bound), and the one
// type two of them share (Model: bound in models.cpp, taken by ConductanceLaw in thermal.cpp).
#ifndef ROUGHCONTACT_PY_BINDINGS_HPP
#define ROUGHCONTACT_PY_BINDINGS_HPP

#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include "roughContact/Error.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace roughcontact_py {

/// Profile, read_profile, Spectrum, ArealSurface, read_areal, synthesize_isotropic,
/// SurfaceRoughness and the roughness functions (surfaces.cpp).
void bindSurfaces(pybind11::module_& m);
/// Material, ContactMaterials (models.cpp).
void bindMaterials(pybind11::module_& m);
/// model_names, multiscale_model_names, Model (models.cpp).
void bindModels(pybind11::module_& m);
/// BoundaryElement (boundaryElement.cpp).
void bindBoundaryElement(pybind11::module_& m);
/// The conductance laws, the gases, GasGap, radiation, the gap correlations, GapSpec (thermal.cpp).
void bindThermal(pybind11::module_& m);
/// FittedElastoPlasticConstants, fitted_elasto_plastic (fittedLaw.cpp).
void bindFittedLaw(pybind11::module_& m);
/// SurfaceSpec, ContactInterface (interface.cpp).
void bindInterface(pybind11::module_& m);
/// ContactInterface's regime, regime_at and accuracy_band (interfaceRegime.cpp).
void bindInterfaceRegime(pybind11::module_& m);
/// check, SurfaceCheck (check.cpp).
void bindCheck(pybind11::module_& m);
/// plot (plot.cpp).
void bindPlot(pybind11::module_& m);

/// The InterfaceSpec of ContactInterface's keyword arguments (interface.cpp), which check()
/// and plot() take too. An argument left None is not given: the core's default stands. check:
/// the spec of a check or of a picture of every law (InterfaceSpec::check: the laws' entries
/// are taken beside any law or model).
roughContact::InterfaceSpec interfaceSpec(
    const std::vector<roughContact::SurfaceSpec>& surfaces, const roughContact::Material& side1,
    const roughContact::Material& side2, const std::optional<std::string>& model,
    const std::optional<std::string>& conductance, std::optional<double> microhardness,
    std::optional<std::pair<double, double>> vickers, std::optional<double> minPressure,
    std::optional<double> maxPressure, std::optional<std::size_t> pointsPerDecade,
    std::optional<std::size_t> synthesize, std::optional<std::uint64_t> seed, std::optional<bool> periodic,
    std::optional<double> hardness, bool hardnessFromYield, std::optional<std::size_t> bemPointsPerDecade,
    std::optional<roughContact::GapSpec> gap, std::optional<std::string> detrend,
    std::optional<bool> mirror = std::nullopt, bool check = false);

/// A contact model built by name, with the spectrum and E' it was built from.
struct Model {
    std::shared_ptr<const roughContact::Spectrum> spectrum;
    std::shared_ptr<const roughContact::ContactModel> model;
    double Eprime = 0.0;

    const roughContact::PerssonModel& persson(const char* what) const
    {
        const auto* p = dynamic_cast<const roughContact::PerssonModel*>(model.get());
        if (p == nullptr) {
            throw roughContact::ParameterError(what, "exists for the model persson only, not " + model->name());
        }
        return *p;
    }
    const roughContact::MultiscaleModel* multiscale() const
    {
        return dynamic_cast<const roughContact::MultiscaleModel*>(model.get());
    }
};

} // namespace roughcontact_py

#endif
