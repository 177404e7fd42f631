// SPDX-License-Identifier: GPL-3.0-or-later
// The default law with constants of one's choosing (thermal/FittedElastoPlastic.hpp): its
// constants as an object and its formula on given numbers, for the study that fits it
// (validation/studies/fittedElastoPlastic.py), so that the fit evaluates the law the core runs.
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

namespace {
// The constants' names, values and descriptions in the order of FittedElastoPlasticConstants.inc.
struct ConstantInfo {
    const char* name;
    double FittedElastoPlasticConstants::*member;
    const char* what;
};
const std::vector<ConstantInfo>& constantInfo()
{
    static const std::vector<ConstantInfo> info = {
#define ROUGHCONTACT_FITTED_CONSTANT(name, value, what) {#name, &FittedElastoPlasticConstants::name, what},
#include "roughContact/thermal/FittedElastoPlasticConstants.inc"
#undef ROUGHCONTACT_FITTED_CONSTANT
    };
    return info;
}

// An array of P's shape holding at(i, a) at each point i, where a(k) is the i-th value of the
// k-th of `arrays` (each as many values as P: ParameterError naming `function` otherwise);
// computed without the GIL.
template <std::size_t N, class At>
Array vectorized(const char* function, const Array& p, const Array (&arrays)[N], At at)
{
    const auto n = static_cast<std::size_t>(p.size());
    for (const Array& a : arrays) {
        if (static_cast<std::size_t>(a.size()) != n) {
            throw ParameterError(function, "every argument needs as many values as P (" + std::to_string(n) + ")");
        }
    }
    Array out(p.request().shape);
    double* o = out.mutable_data();
    {
        py::gil_scoped_release release;
        for (std::size_t i = 0; i < n; ++i) {
            o[i] = at(p.data()[i], [&](std::size_t k) { return arrays[k].data()[i]; });
        }
    }
    return out;
}

// NaN: none.
std::optional<double> given(double v)
{
    return std::isnan(v) ? std::nullopt : std::optional<double>(v);
}
} // namespace

void bindFittedLaw(py::module_& m)
{
    py::class_<FittedElastoPlasticConstants> c(
        m, "FittedElastoPlasticConstants",
        "The constants of the default law fittedElastoPlastic (FittedElastoPlasticConstants.inc), each an "
        "attribute of the C++ name; FittedElastoPlasticConstants() holds the built-in values.");
    c.def(py::init<>());
    for (const ConstantInfo& k : constantInfo()) {
        c.def_readwrite(k.name, k.member, k.what);
    }
    c.def_static(
        "names",
        [] {
            std::vector<std::string> out;
            for (const ConstantInfo& k : constantInfo()) {
                out.emplace_back(k.name);
            }
            return out;
        },
        "The constants' names, in the order of FittedElastoPlasticConstants.inc.");
    c.def_static(
        "descriptions",
        [] {
            std::vector<std::string> out;
            for (const ConstantInfo& k : constantInfo()) {
                out.emplace_back(k.what);
            }
            return out;
        },
        "What each constant is, in the order of names().");

    m.def(
        "fitted_elasto_plastic",
        [](const py::handle& P, const py::handle& sigma, const py::handle& m, const py::handle& bandwidth,
           const py::handle& Eprime, const py::handle& hardness, const py::handle& skewness,
           const py::handle& firstLevelShare, const FittedElastoPlasticConstants& constants) {
            const Array p = numbers(P, "P");
            const Array arrays[] = {numbers(sigma, "sigma"),         numbers(m, "m"),
                                    numbers(bandwidth, "bandwidth"), numbers(Eprime, "Eprime"),
                                    numbers(hardness, "hardness"),   numbers(skewness, "skewness"),
                                    numbers(firstLevelShare, "first_level_share")};
            return vectorized("fitted_elasto_plastic", p, arrays, [&](double Pi, const auto& a) {
                return fittedElastoPlasticConductancePerConductivity(Pi, SurfaceRoughness{a(0), a(1)}, a(2), a(3),
                                                                     given(a(4)), a(5), given(a(6)), constants);
            });
        },
        py::arg("P"), py::arg("sigma"), py::arg("m"), py::arg("bandwidth"), py::arg("Eprime"), py::arg("hardness"),
        py::arg("skewness"), py::arg("first_level_share"), py::arg("constants") = FittedElastoPlasticConstants{},
        "h_c/k_s [1/m] of fittedElastoPlastic (the core's fittedElastoPlasticConductancePerConductivity) at "
        "each point: nominal pressure P [Pa], rms height sigma [m], mean absolute slope m, bandwidth ratio W, "
        "E' [Pa], the cap H [Pa] (NaN: elastic), the heights' shrunk skewness and the first level's share s1 "
        "(NaN: no light-load factor), with `constants`. Equally long arrays (or numbers) in, an array out.");
    m.def(
        "fitted_unloading_factor",
        [](const py::handle& P, const py::handle& peak, const py::handle& m, const py::handle& bandwidth,
           const py::handle& Eprime, const py::handle& hardness, const py::handle& fineHurst,
           const FittedElastoPlasticConstants& constants) {
            const Array p = numbers(P, "P");
            const Array arrays[] = {numbers(peak, "peak"), numbers(m, "m"), numbers(bandwidth, "bandwidth"),
                                    numbers(Eprime, "Eprime"), numbers(hardness, "hardness"),
                                    numbers(fineHurst, "fine_hurst")};
            return vectorized("fitted_unloading_factor", p, arrays, [&](double Pi, const auto& a) {
                return fittedUnloadingFactor(Pi, a(0), a(1), a(2), a(3), given(a(4)), given(a(5)), constants);
            });
        },
        py::arg("P"), py::arg("peak"), py::arg("m"), py::arg("bandwidth"), py::arg("Eprime"), py::arg("hardness"),
        py::arg("fine_hurst"), py::arg("constants") = FittedElastoPlasticConstants{},
        "R of fittedElastoPlastic's unloading branch (the core's fittedUnloadingFactor): the factor on the "
        "law's loading h_c/k_s at the nominal pressure P [Pa] of a joint that has carried peak [Pa], for the "
        "mean absolute slope m, the bandwidth ratio W, E' [Pa], the cap H [Pa] (NaN: elastic, R = 1) and the Hurst exponent of the "
        "spectrum's finest octave H_f (fine_hurst_exponent; NaN: none), with `constants`. Equally long arrays "
        "(or numbers) in, an array out.");
    m.def(
        "fitted_elasto_plastic_unloading",
        [](const py::handle& P, const py::handle& peak, const py::handle& sigma, const py::handle& m,
           const py::handle& bandwidth, const py::handle& Eprime, const py::handle& hardness,
           const py::handle& skewness, const py::handle& firstLevelShare, const py::handle& fineHurst,
           const FittedElastoPlasticConstants& constants) {
            const Array p = numbers(P, "P");
            const Array arrays[] = {numbers(peak, "peak"),           numbers(sigma, "sigma"),
                                    numbers(m, "m"),                 numbers(bandwidth, "bandwidth"),
                                    numbers(Eprime, "Eprime"),       numbers(hardness, "hardness"),
                                    numbers(skewness, "skewness"),   numbers(firstLevelShare, "first_level_share"),
                                    numbers(fineHurst, "fine_hurst")};
            return vectorized("fitted_elasto_plastic_unloading", p, arrays, [&](double Pi, const auto& a) {
                return fittedElastoPlasticUnloadingConductancePerConductivity(Pi, a(0), SurfaceRoughness{a(1), a(2)},
                                                                              a(3), a(4), given(a(5)), a(6),
                                                                              given(a(7)), given(a(8)), constants);
            });
        },
        py::arg("P"), py::arg("peak"), py::arg("sigma"), py::arg("m"), py::arg("bandwidth"), py::arg("Eprime"),
        py::arg("hardness"), py::arg("skewness"), py::arg("first_level_share"), py::arg("fine_hurst"),
        py::arg("constants") = FittedElastoPlasticConstants{},
        "h_c/k_s [1/m] of fittedElastoPlastic's unloading branch (the core's "
        "fittedElastoPlasticUnloadingConductancePerConductivity) at each point: P [Pa] of a joint that has "
        "carried peak [Pa], the other arguments as fitted_elasto_plastic's and fitted_unloading_factor's. "
        "Equally long arrays (or numbers) in, an array out.");
    m.def("gaussian_plastic_spot_conductance", &gaussianPlasticSpotConductance, py::arg("a"),
          "g(a): sigma h_c/(k_s m) of Gaussian plastic spots covering the area fraction a (FittedElastoPlastic.hpp).");
}

} // namespace roughcontact_py
