// SPDX-License-Identifier: GPL-3.0-or-later
// The module's conversions (convert.hpp).
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "convert.hpp"

#include <algorithm>
#include <sstream>

using namespace roughContact;

namespace roughcontact_py {

namespace {

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

} // namespace

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

} // namespace roughcontact_py
