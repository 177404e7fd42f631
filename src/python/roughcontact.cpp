// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module roughcontact: a thin pybind11 binding of the core. Every number is computed
// by the core; this file only converts (numpy arrays in and out, SI units: pressures in Pa,
// lengths in m, dimensionless loads F/(A_n E') where a name says "load") and translates the
// core's errors into Python exceptions with the same message (InputError, ParameterError, both
// subclasses of ValueError). docs/python.md documents it.
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/io/ArealReader.hpp"
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
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ContactTable.hpp"
#include "roughContact/thermal/GapConductance.hpp"
#include "roughContact/thermal/Gas.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace roughContact;

namespace {

/// A bool or numpy.bool_ (numpy 1: "numpy.bool_", numpy 2: "numpy.bool"): numbers to float(), but
/// never a pressure, modulus or length (True is 1.0).
bool isBool(PyObject* o)
{
    const char* type = Py_TYPE(o)->tp_name;
    return PyBool_Check(o) || std::strcmp(type, "numpy.bool_") == 0 || std::strcmp(type, "numpy.bool") == 0;
}

/// Text: float('1e6') and numpy's casts read it as a number; this module does not.
bool isText(PyObject* o)
{
    return PyUnicode_Check(o) || PyBytes_Check(o) || PyByteArray_Check(o);
}

} // namespace

// Every scalar float argument of the module (a pressure, a modulus, a length, a conductivity,
// in a std::optional or a std::pair too): pybind11's own caster takes whatever float() takes in
// its converting pass, True (1.0) among them. This one takes a float, an int, a numpy real
// scalar or 0-d real array and anything else with __float__ or __index__ as float() reads it,
// but refuses bool, numpy.bool_, str, bytes and numpy values of any other kind (bool, complex,
// text): pybind11 then raises its TypeError "incompatible function arguments", which lists the
// signature with every argument's name and the values given. (The arguments that take "a
// number or an array of numbers" go through numbers() below, whose TypeError names the
// argument.) This translation unit is the module's only one, and pybind11's casters are
// internal to it, so no other module sees this specialization.
namespace pybind11::detail {
template <>
class type_caster<double> {
public:
    bool load(handle src, bool convert)
    {
        PyObject* o = src.ptr();
        if (o == nullptr) {
            return false;
        }
        if (PyFloat_Check(o)) { // float and numpy.float64
            value = PyFloat_AS_DOUBLE(o);
            return true;
        }
        if (!convert || isBool(o) || isText(o)) {
            return false;
        }
        if (hasattr(src, "dtype")) { // numpy scalars and 0-d arrays: real kinds only
            const std::string kind = py::str(src.attr("dtype").attr("kind"));
            if (kind != "f" && kind != "i" && kind != "u") {
                return false;
            }
        }
        const object f = reinterpret_steal<object>(PyNumber_Float(o));
        if (!f) {
            PyErr_Clear();
            return false;
        }
        value = PyFloat_AS_DOUBLE(f.ptr());
        return true;
    }
    static handle cast(double src, return_value_policy /*policy*/, handle /*parent*/)
    {
        return PyFloat_FromDouble(src);
    }
    PYBIND11_TYPE_CASTER(double, const_name("float"));
};
} // namespace pybind11::detail

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The exception types, created once at import (never destroyed: they live as long as the module).
PyObject* inputErrorType = nullptr;
PyObject* parameterErrorType = nullptr;

/// A SurfaceSpec given by its spectrum's parameters (power law, fractal) and length.
SurfaceSpec parametricSurface(SurfaceSpec::Kind kind, std::vector<double> parameters, std::optional<double> length)
{
    SurfaceSpec s;
    s.kind = kind;
    s.parameters = std::move(parameters);
    s.length = length;
    return s;
}

/// True for an element of an object array that is a real number: a float, an int, a numpy real
/// scalar, a fractions.Fraction (numbers.Real), not a bool, a str or None.
bool isRealNumber(const py::handle& e)
{
    PyObject* o = e.ptr();
    if (isBool(o) || isText(o)) {
        return false;
    }
    if (PyFloat_Check(o) || PyLong_Check(o)) {
        return true;
    }
    static const py::object real = py::module_::import("numbers").attr("Real"); // lives with the module
    return py::isinstance(e, real);
}

/// x, "a number or an array of numbers" (a float, an int, a numpy array or scalar, a list), as a
/// C-ordered float64 array. numpy's forcecast alone turns '1e6', b'1e6' and True into numbers
/// (and None into NaN); they are refused here with a TypeError that names the argument: str,
/// bytes, bool and None, arrays of dtype bool, str, bytes, complex or datetime, and object arrays
/// holding anything but real numbers. (A list mixing bools and floats becomes a float64 array in
/// numpy before anything here sees it, and is taken as numbers.)
Array numbers(const py::handle& x, const char* name)
{
    const auto refuse = [name](const std::string& what) {
        return py::type_error(std::string(name) + ": expected a number or an array of numbers, not " + what);
    };
    if (isText(x.ptr()) || isBool(x.ptr())) {
        throw refuse(std::string(Py_TYPE(x.ptr())->tp_name) + " " + std::string(py::repr(x)));
    }
    const py::array raw = py::array::ensure(x); // numpy's own dtype for x (cleared error on failure)
    if (!raw) {
        throw refuse(Py_TYPE(x.ptr())->tp_name);
    }
    const char kind = raw.dtype().kind();
    if (kind == 'O') {
        for (const py::handle e : raw.attr("flat")) {
            if (!isRealNumber(e)) {
                const std::string type = Py_TYPE(e.ptr())->tp_name;
                throw refuse(raw.ndim() == 0 ? type : "an array holding " + type + " " + std::string(py::repr(e)));
            }
        }
    } else if (kind != 'f' && kind != 'i' && kind != 'u') {
        throw refuse("an array of dtype " + std::string(py::str(raw.dtype())));
    }
    Array a = Array::ensure(raw);
    if (!a) {
        throw refuse(Py_TYPE(x.ptr())->tp_name);
    }
    return a;
}

/// f applied to every element of x (the argument `name`): a float for a number (or a 0-d array),
/// an array of x's shape (float64) otherwise; numbers() refuses what is not numbers. The loop
/// runs without the GIL (the core is plain C++).
template <class F>
py::object vectorize(const py::handle& x, const char* name, F&& f)
{
    const Array a = numbers(x, name);
    if (a.ndim() == 0) {
        const double v = *a.data();
        return py::float_(f(v));
    }
    Array out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
    const double* in = a.data();
    double* o = out.mutable_data();
    const auto n = static_cast<std::size_t>(a.size());
    {
        py::gil_scoped_release release;
        for (std::size_t i = 0; i < n; ++i) {
            o[i] = f(in[i]);
        }
    }
    return std::move(out);
}

std::vector<double> toVector(const py::handle& x, const char* what)
{
    const Array a = numbers(x, what);
    if (a.ndim() != 1) {
        throw py::type_error(std::string(what) + ": expected a 1-D array of numbers");
    }
    return std::vector<double>(a.data(), a.data() + a.size());
}

Array toArray(const std::vector<double>& v)
{
    Array out(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), out.mutable_data());
    return out;
}

/// The materials of a model: a ContactMaterials as it is, a Material against a rigid flat, a pair
/// (a, b) of Materials as ContactMaterials::pair (the core's errors, not a conversion failure).
ContactMaterials materialsOf(const py::handle& x)
{
    if (py::isinstance<ContactMaterials>(x)) {
        return x.cast<ContactMaterials>();
    }
    if (py::isinstance<Material>(x)) {
        return ContactMaterials::againstRigidFlat(x.cast<Material>());
    }
    if (py::isinstance<py::sequence>(x) && !py::isinstance<py::str>(x) && py::len(x) == 2) {
        const auto pair = x.cast<std::vector<Material>>();
        return ContactMaterials::pair(pair[0], pair[1]);
    }
    throw py::type_error("materials: expected a Material, a pair of Materials or a ContactMaterials");
}

std::string number(double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}

std::optional<LengthUnit> unitsOf(const std::optional<std::string>& units)
{
    return units ? std::optional<LengthUnit>(parseLengthUnit(*units)) : std::nullopt;
}

/// A contact model built by name, with the spectrum and E' it was built from.
struct Model {
    std::shared_ptr<const Spectrum> spectrum;
    std::shared_ptr<const ContactModel> model;
    double Eprime = 0.0;

    const PerssonModel& persson(const char* what) const
    {
        const auto* p = dynamic_cast<const PerssonModel*>(model.get());
        if (p == nullptr) {
            throw ParameterError(what, "exists for the model persson only, not " + model->name());
        }
        return *p;
    }
    const MultiscaleModel* multiscale() const { return dynamic_cast<const MultiscaleModel*>(model.get()); }
};

/// A conductance law, holding what it was built from alive.
struct Law {
    std::shared_ptr<const Spectrum> spectrum;
    std::shared_ptr<const ContactModel> model;
    std::unique_ptr<ConductanceLaw> law;
};

/// A boundary-element model (the exact reference) on an areal surface.
struct BoundaryElement {
    /// The progress callable (or None); the model's callback calls it with the GIL held. Kept
    /// here, as long as the model, so that the callback can hold a plain pointer to it (a
    /// py::object copied without the GIL would change its reference count unguarded).
    py::object progress;
    std::unique_ptr<BoundaryElementModel> model;
};

const char* moduleDoc = R"(roughcontact: the roughContact core from Python.

Thermal contact resistance of rough surfaces: the real contact area A_r/A_n and the contact
conductance h_c/k_s of a rough surface against a flat (or of two rough surfaces) at a nominal
pressure. Units are SI throughout: pressures and moduli in Pa, lengths and heights in m,
frequencies in 1/m, h_c/k_s in 1/m. Functions of pressure take a number or a numpy array and
return a float or a float64 array of the same shape. Arguments named `loads` are the
dimensionless loads F/(A_n E') of the command-line tool multiscaleContact.

Errors are exceptions with the C++ core's message: InputError ("FILE:LINE: message") for bad
file content, ParameterError ("NAME: message") for a bad parameter; both derive from ValueError.
)";

} // namespace

PYBIND11_MODULE(roughcontact, m)
{
    m.doc() = moduleDoc;
    m.attr("__version__") = ROUGHCONTACT_VERSION; // the CMake project's version

    // ---- errors
    inputErrorType = PyErr_NewExceptionWithDoc(
        "roughcontact.InputError",
        "Bad content of an input file; str() reads 'FILE:LINE: message' as the C++ InputError's what(). "
        "Attributes: file, line (0: none), message.",
        PyExc_ValueError, nullptr);
    parameterErrorType = PyErr_NewExceptionWithDoc(
        "roughcontact.ParameterError",
        "A parameter out of its range or missing; str() reads 'NAME: message' as the C++ ParameterError's "
        "what(). Attribute: parameter.",
        PyExc_ValueError, nullptr);
    m.add_object("InputError", py::handle(inputErrorType));
    m.add_object("ParameterError", py::handle(parameterErrorType));
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const InputError& e) {
            py::object exc = py::reinterpret_borrow<py::object>(inputErrorType)(e.what());
            exc.attr("file") = e.file();
            exc.attr("line") = e.line();
            exc.attr("message") = e.message();
            PyErr_SetObject(inputErrorType, exc.ptr());
        } catch (const ParameterError& e) {
            py::object exc = py::reinterpret_borrow<py::object>(parameterErrorType)(e.what());
            exc.attr("parameter") = e.parameter();
            PyErr_SetObject(parameterErrorType, exc.ptr());
        }
    });

    // ---- surfaces
    py::class_<Profile>(m, "Profile", "A measured line profile: heights [m] at a uniform spacing [m].")
        .def(py::init([](const py::handle& heights, double spacing, const std::string& source) {
                 return Profile(toVector(heights, "heights"), spacing, source);
             }),
             py::arg("heights"), py::arg("spacing"), py::arg("source") = "",
             "Profile(heights, spacing, source=''): heights [m] (1-D array, at least 8 finite values) at the "
             "sample spacing [m] (> 0); source names the data in error messages.")
        .def_property_readonly("heights", [](const Profile& p) { return toArray(p.heights()); },
                               "The heights [m] as read (not detrended), a 1-D float64 array (a copy).")
        .def_property_readonly("spacing", &Profile::spacing, "The sample spacing dx [m].")
        .def_property_readonly("length", &Profile::length, "The scan length L = N dx [m].")
        .def_property_readonly("source", &Profile::source, "Where the data came from (a file path).")
        .def("__len__", &Profile::size, "The number of samples.")
        .def("detrended", &Profile::detrended, "The profile less its least-squares line (mean and tilt).")
        .def("subsampled", &Profile::subsampled, py::arg("stride"),
             "Every stride-th sample (spacing stride*dx).")
        .def("rms", &Profile::rms, "Root-mean-square height about zero [m] (detrend first for Rq).")
        .def("__repr__", [](const Profile& p) {
            return "<roughcontact.Profile " + std::to_string(p.size()) + " samples, dx = " +
                   number(p.spacing()) + " m>";
        });

    m.def(
        "read_profile",
        [](const std::string& path, std::optional<std::string> units, std::optional<double> spacing) {
            ProfileReadOptions o;
            o.units = unitsOf(units);
            o.spacing = spacing;
            return readProfile(path, o);
        },
        py::arg("path"), py::arg("units") = py::none(), py::arg("spacing") = py::none(),
        "read_profile(path, units=None, spacing=None) -> Profile\n\n"
        "Reads a profile file as multiscaleContact --profile does: columns 'x z', or 'z' alone with "
        "spacing; comma, semicolon, tab or space separated; '#' comments and one header line allowed; a "
        "Dektak CSV export as it is (its header names the units). units: 'm', 'um' or 'nm' for both "
        "columns (default m; a Dektak export's own header otherwise); spacing: the sample spacing of a "
        "one-column file, in units. Heights are returned in metres, not detrended. InputError "
        "('FILE:LINE: message') on bad content or a missing file, ParameterError on a bad option.");

    py::class_<Spectrum>(m, "Spectrum",
                         "A surface as its spectrum: levels f_i [1/m] with single-sided amplitudes beta_i [m] "
                         "for a scan of length L [m] (A_n = L^2).")
        .def(py::init([](const py::handle& f, const py::handle& beta, double length, const std::string& source) {
                 return Spectrum(toVector(f, "frequencies"), toVector(beta, "amplitudes"), length, source);
             }),
             py::arg("frequencies"), py::arg("amplitudes"), py::arg("length"), py::arg("source") = "",
             "Spectrum(frequencies, amplitudes, length, source=''): levels [1/m] (positive, strictly "
             "increasing), amplitudes [m] (>= 0), scan length [m].")
        .def_static("from_profile", &Spectrum::fromProfile, py::arg("profile"),
                    "The FFT of a profile after removing its mean and tilt: f_k = k/L, beta_k = 2|Z_k|/N "
                    "(|Z_{N/2}|/N at Nyquist).")
        .def_static("power_law", &Spectrum::powerLaw, py::arg("bm"), py::arg("m"), py::arg("fmin"),
                    py::arg("fmax"), py::arg("length") = 0.0,
                    "Power law beta = bm f^-m [m] at f_i = i/L within [fmin, fmax] [1/m]; length [m] "
                    "defaults (0) to 1/fmin (multiscaleContact --power-law).")
        .def_static("fractal", &Spectrum::fractal, py::arg("D"), py::arg("G"), py::arg("fmin"), py::arg("fmax"),
                    py::arg("length") = 0.0,
                    "Weierstrass-Mandelbrot (Majumdar-Bhushan) spectrum of fractal dimension D and roughness "
                    "G [m] at f_i = i/L within [fmin, fmax] [1/m]; length [m] defaults (0) to 1/fmin.")
        .def_static(
            "read",
            [](const std::string& path, std::optional<double> length) { return readSpectrum(path, length); },
            py::arg("path"), py::arg("length") = py::none(),
            "Reads a spectrum table (multiscaleContact --spectrum): columns frequency [1/m], amplitude "
            "[m]; length [m] defaults to 1/lowest frequency.")
        .def_static("combine", &Spectrum::combine, py::arg("a"), py::arg("b"),
                    "The equivalent surface of two rough surfaces in contact (powers add level by level).")
        .def_property_readonly("frequencies", [](const Spectrum& s) { return toArray(s.frequencies()); },
                               "The levels f_i [1/m], a 1-D float64 array.")
        .def_property_readonly("amplitudes", [](const Spectrum& s) { return toArray(s.amplitudes()); },
                               "The amplitudes beta_i [m], a 1-D float64 array.")
        .def_property_readonly("length", &Spectrum::length, "The scan length L [m].")
        .def_property_readonly("nominal_area", &Spectrum::nominalArea, "A_n = L^2 [m^2].")
        .def_property_readonly("source", &Spectrum::source, "Where the spectrum came from.")
        .def("__len__", &Spectrum::size, "The number of levels.")
        .def("variance", &Spectrum::variance, "Sum of beta_i^2/2 [m^2]: the variance of the sinusoids.")
        .def("profile_variance", &Spectrum::profileVariance,
             "The variance [m^2] of the profile the spectrum came from (Parseval; the Nyquist level counted "
             "in full).")
        .def("truncated", &Spectrum::truncated, py::arg("fmax"), "The levels with f <= fmax [1/m] only.")
        .def("__repr__", [](const Spectrum& s) {
            return "<roughcontact.Spectrum " + std::to_string(s.size()) + " levels, L = " +
                   number(s.length()) + " m>";
        });

    py::class_<ArealSurface>(m, "ArealSurface",
                             "A height map: heights [m] on nx points along x by ny along y, spacings dx, dy [m].")
        .def(py::init([](const py::handle& heights, double dx, std::optional<double> dy, const std::string& source) {
                 const Array a = numbers(heights, "heights");
                 if (a.ndim() != 2) {
                     throw py::type_error("heights: expected a 2-D array of numbers, shape (ny, nx)");
                 }
                 const auto ny = static_cast<std::size_t>(a.shape(0));
                 const auto nx = static_cast<std::size_t>(a.shape(1));
                 return ArealSurface(std::vector<double>(a.data(), a.data() + a.size()), nx, ny, dx, dy.value_or(dx),
                                     source);
             }),
             py::arg("heights"), py::arg("dx"), py::arg("dy") = py::none(), py::arg("source") = "",
             "ArealSurface(heights, dx, dy=None, source=''): heights [m] as a 2-D array of shape (ny, nx) "
             "(heights[iy, ix]: rows run along x), spacings dx, dy [m] (dy defaults to dx).")
        .def_property_readonly(
            "heights",
            [](const ArealSurface& s) {
                Array out({static_cast<py::ssize_t>(s.ny()), static_cast<py::ssize_t>(s.nx())});
                std::copy(s.heights().begin(), s.heights().end(), out.mutable_data());
                return out;
            },
            "The heights [m], a float64 array of shape (ny, nx) (a copy): heights[iy, ix].")
        .def_property_readonly("nx", &ArealSurface::nx, "Points along x.")
        .def_property_readonly("ny", &ArealSurface::ny, "Points along y.")
        .def_property_readonly("dx", &ArealSurface::dx, "Spacing along x [m].")
        .def_property_readonly("dy", &ArealSurface::dy, "Spacing along y [m].")
        .def_property_readonly("length_x", &ArealSurface::lengthX, "L_x = nx dx [m].")
        .def_property_readonly("length_y", &ArealSurface::lengthY, "L_y = ny dy [m].")
        .def_property_readonly("nominal_area", &ArealSurface::nominalArea, "A_n = L_x L_y [m^2].")
        .def_property_readonly("source", &ArealSurface::source, "Where the data came from.")
        .def(
            "detrended",
            [](const ArealSurface& a, const std::string& how) { return a.detrended(parseDetrend(how, "how")); },
            py::arg("how") = "plane",
            "The surface less its least-squares plane (how='plane'), its mean (how='mean') or nothing "
            "(how='none').")
        .def("rms", &ArealSurface::rms, "Root-mean-square height about zero [m].")
        .def("row", &ArealSurface::row, py::arg("iy"), "Row iy (along x) as a Profile.")
        .def("column", &ArealSurface::column, py::arg("ix"), "Column ix (along y) as a Profile.")
        .def(
            "line_scan_spectrum",
            [](const ArealSurface& s, const std::string& direction) {
                return lineScanSpectrum(s, parseScanDirection(direction));
            },
            py::arg("direction") = "x",
            "The averaged spectrum of the line scans 'x' (rows), 'y' (columns) or 'both', each detrended "
            "(multiscaleContact --areal --direction); detrend the surface first as the CLI does.")
        .def("__repr__", [](const ArealSurface& s) {
            return "<roughcontact.ArealSurface " + std::to_string(s.nx()) + " x " + std::to_string(s.ny()) + ">";
        });

    m.def(
        "read_areal",
        [](const std::string& path, std::optional<std::string> units, std::optional<double> dx,
           std::optional<double> dy, bool fillInvalid) {
            ArealReadOptions o;
            o.units = unitsOf(units);
            o.dx = dx;
            o.dy = dy;
            o.fillInvalid = fillInvalid;
            return readAreal(path, o);
        },
        py::arg("path"), py::arg("units") = py::none(), py::arg("dx") = py::none(), py::arg("dy") = py::none(),
        py::arg("fill_invalid") = false,
        "read_areal(path, units=None, dx=None, dy=None, fill_invalid=False) -> ArealSurface\n\n"
        "An X3P file (.x3p: metres, its own spacings; fill_invalid fills its invalid points) or a text "
        "matrix of heights (one row along x per line; dx required, dy defaults to dx, both in units: "
        "'m' default, 'um', 'nm'), as multiscaleContact --areal reads it. Not detrended.");

    m.def(
        "synthesize_isotropic",
        [](const Spectrum& spectrum, std::size_t n, std::uint64_t seed) { return synthesizeIsotropic(spectrum, n, seed); },
        py::arg("spectrum"), py::arg("n"), py::arg("seed") = 1,
        "synthesize_isotropic(spectrum, n, seed=1) -> ArealSurface\n\n"
        "An n x n periodic isotropic Gaussian surface on L x L (L the spectrum's length, spacing L/n) whose "
        "line scans have the spectrum's power; random phases from seed (multiscaleContact --synthesize "
        "N,SEED). n even, 8 to 4096.");

    py::class_<SurfaceRoughness>(m, "SurfaceRoughness",
                                 "The rms height sigma [m] and mean absolute slope m of a surface (the "
                                 "correlations' inputs).")
        .def(py::init([](double sigma, double slope) { return SurfaceRoughness{sigma, slope}; }), py::arg("sigma"),
             py::arg("mean_absolute_slope"), "SurfaceRoughness(sigma [m], mean_absolute_slope).")
        .def_readwrite("sigma", &SurfaceRoughness::sigma, "rms height about the mean plane [m]")
        .def_readwrite("mean_absolute_slope", &SurfaceRoughness::meanAbsoluteSlope, "m = <|dz/dx|>")
        .def("__repr__", [](const SurfaceRoughness& r) {
            return "<roughcontact.SurfaceRoughness sigma = " + number(r.sigma) +
                   " m, m = " + number(r.meanAbsoluteSlope) + ">";
        });
    m.def("profile_roughness", &profileRoughness, py::arg("profile"),
          "sigma [m] and the mean absolute slope of a profile after removing its mean and tilt.");
    m.def(
        "areal_roughness",
        [](const ArealSurface& s, const std::string& direction) { return arealRoughness(s, parseScanDirection(direction)); },
        py::arg("surface"), py::arg("direction") = "x",
        "sigma [m] and the mean absolute slope of an areal surface along 'x', 'y' or 'both'.");
    m.def("spectrum_roughness", &spectrumRoughness, py::arg("spectrum"),
          "sigma [m] and the mean absolute slope of a spectrum (Gaussian slopes assumed).");
    m.def("combined_roughness", &combined, py::arg("a"), py::arg("b"),
          "The equivalent roughness of two surfaces: sigma and m added in quadrature.");

    // ---- materials
    py::class_<Material>(m, "Material", "One solid: Young's modulus E [Pa], Poisson's ratio nu, yield strength Sy [Pa].")
        .def(py::init([](double E, double nu, std::optional<double> Sy) { return Material{E, nu, Sy}; }),
             py::arg("E"), py::arg("nu"), py::arg("Sy") = py::none(),
             "Material(E, nu, Sy=None): E [Pa], nu, Sy [Pa] (needed by jacksonGreen, truncation, "
             "greenwoodWilliamsonJG, majumdarBhushan). Checked where it is used.")
        .def_readwrite("E", &Material::E, "Young's modulus [Pa]")
        .def_readwrite("nu", &Material::nu, "Poisson's ratio")
        .def_readwrite("Sy", &Material::Sy, "yield strength [Pa] or None")
        .def("__repr__", [](const Material& x) {
            return "<roughcontact.Material E = " + number(x.E) + " Pa, nu = " + number(x.nu) +
                   (x.Sy ? ", Sy = " + number(*x.Sy) + " Pa" : std::string()) + ">";
        });

    py::class_<ContactMaterials>(m, "ContactMaterials",
                                 "What the models need of a pair of solids: E' and the yielding material's E, nu, "
                                 "Sy. A Material converts to one against a rigid flat.")
        .def(py::init(&ContactMaterials::againstRigidFlat), py::arg("material"),
             "One solid against a rigid flat: E' = E/(1 - nu^2).")
        .def_static("against_rigid_flat", &ContactMaterials::againstRigidFlat, py::arg("material"),
                    "One solid against a rigid flat: E' = E/(1 - nu^2).")
        .def_static("pair", &ContactMaterials::pair, py::arg("a"), py::arg("b"),
                    "Two solids: 1/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2; the lower Sy yields first.")
        .def_static("from_reduced_modulus", &ContactMaterials::fromReducedModulus, py::arg("Eprime"),
                    py::arg("nu") = py::none(), py::arg("Sy") = py::none(),
                    "E' [Pa] given directly (multiscaleContact --Eprime), with nu and Sy [Pa] of the yielding "
                    "material.")
        .def_property_readonly("reduced_modulus", &ContactMaterials::reducedModulus, "E' [Pa].");

    // ---- models
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
            [](const Model& x, const py::object& P) {
                const ContactModel& cm = *x.model;
                const double Ep = x.Eprime;
                return vectorize(P, "pressures", [&](double p) { return cm.areaFraction(p / Ep); });
            },
            py::arg("pressures"),
            "A_r/A_n at the nominal pressures F/A_n [Pa] (a number or an array): the model at the load P/E'.")
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

    py::class_<BoundaryElement>(m, "BoundaryElement",
                                "The exact reference: the boundary-element solution of an areal surface against "
                                "a flat (multiscaleContact --model boundaryElement). Slow: an FFT contact solve "
                                "per pressure; keep grids small (64 x 64 takes well under a second a pressure, "
                                "the 650 x 650 X3P map tens of seconds).")
        .def(py::init([](const ArealSurface& surface, const py::object& materials, bool periodic,
                         std::optional<double> hardness, double tolerance, std::size_t maxIterations,
                         std::optional<std::string> detrend, const py::object& progress, bool verbose,
                         double progressEvery) {
                 BoundaryElementOptions o;
                 o.periodic = periodic;
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
                             // (The C API call: handle(target)(d) returned without running the
                             // callable here, measured; not understood, so not used.)
                             PyObject* r = PyObject_CallFunctionObjArgs(target, d.ptr(), nullptr);
                             if (r == nullptr) {
                                 throw py::error_already_set();
                             }
                             Py_DECREF(r);
                         }
                     };
                 }
                 const double Ep = materialsOf(materials).reducedModulus();
                 py::gil_scoped_release release;
                 x.model = std::make_unique<BoundaryElementModel>(surface, Ep, o);
                 return x;
             }),
             py::arg("surface"), py::arg("materials"), py::arg("periodic") = false, py::arg("hardness") = py::none(),
             py::arg("tolerance") = 1e-8, py::arg("max_iterations") = 20000, py::arg("detrend") = py::none(),
             py::arg("progress") = py::none(), py::arg("verbose") = false, py::arg("progress_every") = 3.0,
             "BoundaryElement(surface, materials, periodic=False, hardness=None, tolerance=1e-8, "
             "max_iterations=20000, detrend=None, progress=None, verbose=False, progress_every=3.0): progress "
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
                               "Non-periodic: h/k_s [1/m] of the whole patch bonded; periodic: inf.")
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
            [](const BoundaryElement& x, const py::object& P) {
                const Array given = numbers(P, "pressures");
                const std::vector<double> pressures(given.data(), given.data() + given.size());
                const double Ep = x.model->reducedModulus();
                std::vector<double> loads;
                for (double p : pressures) {
                    loads.push_back(p / Ep);
                }
                std::vector<BoundaryElementPoint> points;
                {
                    py::gil_scoped_release release;
                    points = x.model->curve(loads);
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
                return d;
            },
            py::arg("pressures"),
            "The curve at the nominal pressures [Pa] (solved in increasing order, each warm-started from the one "
            "below; returned in the order given) as a dict of 1-D arrays: pressure [Pa], load (P/E'), "
            "area_fraction, plastic_fraction, mean_separation [m], conductance_per_conductivity [1/m], "
            "iterations, residual (the columns of multiscaleContact --model boundaryElement).");

    // ---- conductance laws
    m.def("conductance_law_names", &conductanceLawNames,
          "The conductance laws by name: jacksonBhavnaniFerguson, multiscaleBarber, persson, mikic, "
          "cooperMikicYovanovich.");
    m.def("default_conductance_law", &defaultConductanceLaw, "The law used unless another is named.");

    py::class_<Law>(m, "ConductanceLaw", "A contact conductance law by name: h_c/k_s [1/m] at a nominal pressure [Pa].")
        .def(py::init([](const std::string& name, const Model* model, const Spectrum* spectrum,
                         std::optional<double> Eprime, std::optional<SurfaceRoughness> roughness,
                         std::optional<double> microhardness, std::optional<std::pair<double, double>> vickers) {
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
                 if (vickers) {
                     in.vickers = VickersCoefficients{vickers->first, vickers->second};
                 }
                 x.law = makeConductanceLaw(name, in);
                 return x;
             }),
             py::arg("name"), py::arg("model") = nullptr, py::arg("spectrum") = nullptr, py::arg("Eprime") = py::none(),
             py::arg("roughness") = py::none(), py::arg("microhardness") = py::none(), py::arg("vickers") = py::none(),
             "ConductanceLaw(name, model=None, spectrum=None, Eprime=None, roughness=None, microhardness=None, "
             "vickers=None): name from conductance_law_names(). What each law needs: "
             "jacksonBhavnaniFerguson and multiscaleBarber a multi-scale Model; persson a spectrum (the "
             "model's by default) and E' [Pa] (the model's by default); mikic a SurfaceRoughness and E'; "
             "cooperMikicYovanovich a SurfaceRoughness and the microhardness H_c [Pa] or the Vickers "
             "coefficients (c1 [Pa], c2). ParameterError names what is missing.")
        .def_property_readonly("name", [](const Law& x) { return x.law->name(); }, "The law's name.")
        .def(
            "conductance_per_conductivity",
            [](const Law& x, const py::object& P) {
                const ConductanceLaw& law = *x.law;
                return vectorize(P, "pressures", [&](double p) { return law.perConductivity(p); });
            },
            py::arg("pressures"), "h_c/k_s [1/m] at the nominal pressures [Pa] (inf at complete contact).")
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
             py::arg("mean_free_path"), py::arg("reference_pressure") = 101325.0, py::arg("accommodation"),
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
        .def(py::init([](const GasProperties& gas, double pressure,
                         std::optional<std::pair<double, double>> accommodation) {
                 GasGapSpec spec{gas, pressure, std::nullopt, std::nullopt};
                 if (accommodation) {
                     spec.accommodation1 = accommodation->first;
                     spec.accommodation2 = accommodation->second;
                 }
                 return GasGap(spec);
             }),
             py::arg("gas"), py::arg("pressure") = 101325.0, py::arg("accommodation") = py::none(),
             "gas a Gas; pressure P_g [Pa]; accommodation (a1, a2), each in (0, 1], or None for the gas's "
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
        .def(py::init([](const py::object& gas, double pressure, std::optional<std::pair<double, double>> accommodation,
                         std::optional<std::pair<double, double>> emissivity) {
                 GapSpec g;
                 if (!gas.is_none()) {
                     const GasProperties props = py::isinstance<py::str>(gas) ? gasByName(gas.cast<std::string>())
                                                                              : gas.cast<GasProperties>();
                     g.gas = GasGapSpec{props, pressure, std::nullopt, std::nullopt};
                     if (accommodation) {
                         g.gas->accommodation1 = accommodation->first;
                         g.gas->accommodation2 = accommodation->second;
                     }
                 } else if (accommodation) {
                     throw ParameterError("accommodation", "is for a gas; this gap has none (gas=None)");
                 }
                 if (emissivity) {
                     g.emissivity1 = emissivity->first;
                     g.emissivity2 = emissivity->second;
                 }
                 return g;
             }),
             py::kw_only(), py::arg("gas") = py::none(), py::arg("pressure") = 101325.0,
             py::arg("accommodation") = py::none(), py::arg("emissivity") = py::none(),
             "gas a name ('air'), a Gas or None (vacuum); pressure P_g [Pa]; accommodation (a1, a2), each in "
             "(0, 1], or None for the gas's default; emissivity (e1, e2) for radiation, or None. "
             "ContactInterface checks it.");

    // ---- the interface
    py::class_<SurfaceSpec>(m, "SurfaceSpec",
                            "One rough surface as ContactInterface reads it (the OpenFOAM dictionary's "
                            "surface entry): build it with the static methods.")
        .def_static(
            "profile",
            [](const std::string& path, std::optional<std::string> units, std::optional<double> spacing,
               std::size_t stride) {
                SurfaceSpec s;
                s.kind = SurfaceSpec::Kind::profile;
                s.file = path;
                s.profileOptions.units = unitsOf(units);
                s.profileOptions.spacing = spacing;
                s.stride = stride;
                return s;
            },
            py::arg("path"), py::arg("units") = py::none(), py::arg("spacing") = py::none(), py::arg("stride") = 1,
            "A profile file (read_profile's units and spacing), every stride-th sample.")
        .def_static(
            "spectrum",
            [](const std::string& path, std::optional<double> length) {
                SurfaceSpec s;
                s.kind = SurfaceSpec::Kind::spectrum;
                s.file = path;
                s.length = length;
                return s;
            },
            py::arg("path"), py::arg("length") = py::none(), "A spectrum table file; length [m].")
        .def_static(
            "power_law",
            [](double bm, double mm, double fmin, double fmax, std::optional<double> length) {
                return parametricSurface(SurfaceSpec::Kind::powerLaw, {bm, mm, fmin, fmax}, length);
            },
            py::arg("bm"), py::arg("m"), py::arg("fmin"), py::arg("fmax"), py::arg("length") = py::none(),
            "A power-law spectrum bm f^-m [m], fmin, fmax [1/m], length [m].")
        .def_static(
            "fractal",
            [](double D, double G, double fmin, double fmax, std::optional<double> length) {
                return parametricSurface(SurfaceSpec::Kind::fractal, {D, G, fmin, fmax}, length);
            },
            py::arg("D"), py::arg("G"), py::arg("fmin"), py::arg("fmax"), py::arg("length") = py::none(),
            "A Weierstrass-Mandelbrot spectrum: D, G [m], fmin, fmax [1/m], length [m].")
        .def_static(
            "areal",
            [](const std::string& path, std::optional<std::string> units, std::optional<double> dx,
               std::optional<double> dy, bool fillInvalid, const std::string& direction) {
                SurfaceSpec s;
                s.kind = SurfaceSpec::Kind::areal;
                s.file = path;
                s.arealOptions.units = unitsOf(units);
                s.arealOptions.dx = dx;
                s.arealOptions.dy = dy;
                s.arealOptions.fillInvalid = fillInvalid;
                s.direction = parseScanDirection(direction);
                return s;
            },
            py::arg("path"), py::arg("units") = py::none(), py::arg("dx") = py::none(), py::arg("dy") = py::none(),
            py::arg("fill_invalid") = false, py::arg("direction") = "x",
            "An areal file (read_areal's options) and the line scans that make its spectrum.")
        .def("read_spectrum", &SurfaceSpec::spectrum, "The surface's spectrum (reads the file; a Spectrum).")
        .def("roughness", &SurfaceSpec::roughness, "Its sigma [m] and mean absolute slope.");

    py::class_<ContactInterface>(m, "ContactInterface",
                                 "Surfaces + materials + model + conductance law -> the pressure table "
                                 "a boundary condition interpolates: A_r/A_n and h_c/k_s at a nominal pressure [Pa].")
        .def(py::init([](const std::vector<SurfaceSpec>& surfaces, const Material& side1, const Material& side2,
                         const std::string& model, const std::string& conductance,
                         std::optional<double> microhardness, std::optional<std::pair<double, double>> vickers,
                         std::optional<double> minPressure, std::optional<double> maxPressure,
                         std::size_t pointsPerDecade, std::optional<std::size_t> synthesize, std::uint64_t seed,
                         std::optional<bool> periodic, std::optional<double> hardness, bool hardnessFromYield,
                         std::size_t bemPointsPerDecade, std::optional<GapSpec> gap, std::optional<std::string> detrend) {
                 InterfaceSpec s;
                 s.surfaces = surfaces;
                 s.side1 = side1;
                 s.side2 = side2;
                 s.model = model;
                 s.conductanceLaw = conductance;
                 s.microhardness = microhardness;
                 if (vickers) {
                     s.vickers = VickersCoefficients{vickers->first, vickers->second};
                 }
                 s.minPressure = minPressure;
                 s.maxPressure = maxPressure;
                 s.pointsPerDecade = pointsPerDecade;
                 s.synthesize = synthesize;
                 s.seed = seed;
                 s.periodic = periodic;
                 s.hardness = hardness;
                 s.hardnessFromYield = hardnessFromYield;
                 s.bemPointsPerDecade = bemPointsPerDecade;
                 s.gap = gap;
                 if (detrend) {
                     s.detrend = parseDetrend(*detrend, "detrend");
                 }
                 py::gil_scoped_release release;
                 return std::make_unique<ContactInterface>(s);
             }),
             py::kw_only(), py::arg("surfaces"), py::arg("side1"), py::arg("side2"), py::arg("model") = "jacksonGreen",
             py::arg("conductance") = "", py::arg("microhardness") = py::none(), py::arg("vickers") = py::none(),
             py::arg("min_pressure") = py::none(), py::arg("max_pressure") = py::none(),
             py::arg("points_per_decade") = 40, py::arg("synthesize") = py::none(), py::arg("seed") = 1,
             py::arg("periodic") = py::none(), py::arg("hardness") = py::none(),
             py::arg("hardness_from_yield") = false, py::arg("bem_points_per_decade") = 6,
             py::arg("gap") = py::none(), py::arg("detrend") = py::none(),
             "ContactInterface(*, surfaces, side1, side2, model='jacksonGreen', conductance='', ...): "
             "surfaces a list of one or two SurfaceSpec; side1, side2 the Materials of the two solids; model a "
             "multi-scale model or 'boundaryElement'; conductance a law name ('' the default); microhardness "
             "[Pa] or vickers (c1 [Pa], c2) for cooperMikicYovanovich; min_pressure, max_pressure [Pa] the "
             "table's range (default 1e-9 E' to E'); points_per_decade; boundaryElement only: synthesize N "
             "(an N x N surface from the 1-D surfaces), seed, periodic, detrend ('none', 'mean' or 'plane'; None: "
             "'mean' when periodic, 'plane' otherwise), hardness [Pa], hardness_from_yield, "
             "bem_points_per_decade; gap a GapSpec (gas and/or radiation beside the contact) or None. Building the table takes a fraction of a second for the multi-scale "
             "models, far longer for boundaryElement.")
        .def(
            "area_fraction",
            [](const ContactInterface& ci, const py::object& P) {
                return vectorize(P, "pressures", [&](double p) { return ci.areaFraction(p); });
            },
            py::arg("pressures"), "A_r/A_n at the nominal pressures [Pa] (0 for P <= 0, 1 beyond complete contact).")
        .def(
            "conductance_per_conductivity",
            [](const ContactInterface& ci, const py::object& P) {
                return vectorize(P, "pressures", [&](double p) { return ci.conductancePerConductivity(p); });
            },
            py::arg("pressures"), "h_c/k_s [1/m] at the nominal pressures [Pa] (inf beyond complete contact).")
        .def(
            "conductance",
            [](const ContactInterface& ci, const py::object& P, double k1, double k2) {
                return vectorize(P, "pressures", [&](double p) { return ci.face(p, k1, k2).conductance; });
            },
            py::arg("pressures"), py::arg("k1"), py::arg("k2"),
            "h_c [W/(m^2 K)] at the pressures [Pa] between solids of conductivities k1, k2 [W/(m K)] "
            "(k_s = 2 k1 k2/(k1 + k2)).")
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
