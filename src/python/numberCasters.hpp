// SPDX-License-Identifier: GPL-3.0-or-later
// The module's casters of double and of the whole numbers (int, std::size_t, std::uint64_t):
// every .cpp of the module includes this header FIRST, right after
// <pybind11/pybind11.h> and before <pybind11/stl.h>, <pybind11/numpy.h> or anything else that
// could cast a double. An explicit specialization must be declared before its first use in every
// translation unit that uses it, and all of them must see the same one: a .cpp that cast a double
// with pybind11's own caster, or saw a different specialization, would break the one-definition
// rule (undefined behaviour, the linker keeping either). Hence one header, and helpers with
// external linkage (inline, in a named namespace) rather than a file's anonymous namespace.
#ifndef ROUGHCONTACT_PY_NUMBERCASTERS_HPP
#define ROUGHCONTACT_PY_NUMBERCASTERS_HPP

#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace roughcontact_py {

/// A bool or numpy.bool_ (numpy 1: "numpy.bool_", numpy 2: "numpy.bool"): numbers to float(), but
/// never a pressure, modulus or length (True is 1.0).
inline bool isBool(PyObject* o)
{
    const char* type = Py_TYPE(o)->tp_name;
    return PyBool_Check(o) || std::strcmp(type, "numpy.bool_") == 0 || std::strcmp(type, "numpy.bool") == 0;
}

/// Text: float('1e6') and numpy's casts read it as a number; this module does not.
inline bool isText(PyObject* o)
{
    return PyUnicode_Check(o) || PyBytes_Check(o) || PyByteArray_Check(o);
}

} // namespace roughcontact_py

// Every scalar float argument of the module (a pressure, a modulus, a length, a conductivity,
// in a std::optional or a std::pair too): pybind11's own caster takes whatever float() takes in
// its converting pass, True (1.0) among them. This one takes a float, an int, a numpy real
// scalar or 0-d real array and anything else with __float__ or __index__ as float() reads it,
// but refuses bool, numpy.bool_, str, bytes and numpy values of any other kind (bool, complex,
// text): pybind11 then raises its TypeError "incompatible function arguments", which lists the
// signature with every argument's name and the values given. (The arguments that take "a
// number or an array of numbers" go through numbers() in convert.cpp, whose TypeError names the
// argument.) The module's translation units all include this header (see above), and pybind11's
// casters are internal to the module (hidden visibility), so no other module sees this
// specialization.
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
        if (!convert || roughcontact_py::isBool(o) || roughcontact_py::isText(o)) {
            return false;
        }
        if (hasattr(src, "dtype")) { // numpy scalars and 0-d arrays: real kinds only
            const std::string kind = pybind11::str(src.attr("dtype").attr("kind"));
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

// Every whole-number argument of the module (a grid size, a seed, a count, threads; in a
// std::optional or a list too): pybind11's own caster takes True as 1. This one takes an int,
// a numpy integer scalar and anything else with __index__ in range, and refuses bool,
// numpy.bool_, float and text, so that pybind11 raises its TypeError "incompatible function
// arguments" as for the doubles above.
template <class Whole>
class wholeNumberCaster {
public:
    bool load(handle src, bool convert)
    {
        PyObject* o = src.ptr();
        if (o == nullptr || roughcontact_py::isBool(o) || roughcontact_py::isText(o) || PyFloat_Check(o)) {
            return false;
        }
        if (!PyLong_Check(o) && !(convert && PyIndex_Check(o))) {
            return false;
        }
        const object index = reinterpret_steal<object>(PyNumber_Index(o));
        if (!index) {
            PyErr_Clear();
            return false;
        }
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
        if (std::is_signed<Whole>::value) {
            if (overflow != 0 || (v == -1 && PyErr_Occurred()) || v < static_cast<long long>(std::numeric_limits<Whole>::min()) ||
                v > static_cast<long long>(std::numeric_limits<Whole>::max())) {
                PyErr_Clear();
                return false;
            }
            value = static_cast<Whole>(v);
            return true;
        }
        if (overflow < 0 || (overflow == 0 && v < 0)) {
            PyErr_Clear();
            return false;
        }
        const unsigned long long u = PyLong_AsUnsignedLongLong(index.ptr());
        if (u == static_cast<unsigned long long>(-1) && PyErr_Occurred()) {
            PyErr_Clear();
            return false;
        }
        if (u > static_cast<unsigned long long>(std::numeric_limits<Whole>::max())) {
            return false;
        }
        value = static_cast<Whole>(u);
        return true;
    }
    static handle cast(Whole src, return_value_policy /*policy*/, handle /*parent*/)
    {
        return std::is_signed<Whole>::value ? PyLong_FromLongLong(static_cast<long long>(src))
                                            : PyLong_FromUnsignedLongLong(static_cast<unsigned long long>(src));
    }
    PYBIND11_TYPE_CASTER(Whole, const_name("int"));
};
template <>
class type_caster<int> : public wholeNumberCaster<int> {};
template <>
class type_caster<unsigned long> : public wholeNumberCaster<unsigned long> {};
static_assert(std::is_same<std::size_t, unsigned long>::value && std::is_same<std::uint64_t, unsigned long>::value,
              "the whole-number casters cover std::size_t and std::uint64_t as unsigned long");
} // namespace pybind11::detail

#endif
