// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module roughcontact: a thin pybind11 binding of the core. Every number is computed
// by the core; these files only convert (numpy arrays in and out, SI units: pressures in Pa,
// lengths in m, dimensionless loads F/(A_n E') where a name says "load") and translate the
// core's errors into Python exceptions with the same message (InputError, ParameterError, both
// subclasses of ValueError). docs/python.md documents it.
//
// This file: the module, its docstring, the exception types and their translation, and one bind
// function per topic (bindings.hpp), called in the order the module has always bound them:
// surfaces.cpp, models.cpp (materials, then models), boundaryElement.cpp, thermal.cpp (laws,
// gases, the gap, GapSpec), interface.cpp. convert.hpp holds the shared conversions,
// numberCasters.hpp the caster of double that every file of the module includes first.
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/parallel/Threads.hpp"

#include <exception>

namespace py = pybind11;
using namespace roughContact;

namespace {

// The exception types, created once at import (never destroyed: they live as long as the module).
PyObject* inputErrorType = nullptr;
PyObject* parameterErrorType = nullptr;

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

    // ---- threads of the boundary-element solves (parallel/Threads.hpp)
    m.def("set_threads", &setThreads, py::arg("n"),
          "Threads of the boundary-element solves (FFTW's and the solvers' loops), for the whole "
          "process: BoundaryElement, check() and ContactInterface's boundaryElement tables made after "
          "it. Default: the processors the process may run on, and never more of them than that (more cannot "
          "help). The answers are the same for any number, bit for bit.");
    m.def("threads", &threads, "The threads the boundary-element solves use (set_threads).");
    m.def("set_fft_wisdom", &setFftWisdom, py::arg("path"),
          "Plan the boundary-element FFTs by timing them (FFTW_MEASURE) and keep the plans in the file "
          "`path` (created when missing; a file there must be FFTW wisdom): runs sharing it with the same "
          "threads use the same plans and give the same answer bit for bit. '' (the default): the blocked transforms, planned without timing runs, the same answer on "
          "every run and for any number of threads.");

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
    roughcontact_py::bindSurfaces(m);

    // ---- materials
    roughcontact_py::bindMaterials(m);

    // ---- models
    roughcontact_py::bindModels(m);
    roughcontact_py::bindBoundaryElement(m);

    // ---- conductance laws; the gap beside the contact (gas and radiation; docs/theory.md, "Gap conductance")
    roughcontact_py::bindThermal(m);
    roughcontact_py::bindFittedLaw(m);

    // ---- the interface
    roughcontact_py::bindInterface(m);
    roughcontact_py::bindInterfaceRegime(m);
    roughcontact_py::bindCheck(m);
    roughcontact_py::bindPlot(m);
}
