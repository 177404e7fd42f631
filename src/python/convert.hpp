// SPDX-License-Identifier: GPL-3.0-or-later
// The module's conversions, shared by its binding files: numbers in (a number or an array of
// numbers, refused with a TypeError that names the argument when it is not), arrays out, the
// materials of a model, a number as text, length units by name.
#ifndef ROUGHCONTACT_PY_CONVERT_HPP
#define ROUGHCONTACT_PY_CONVERT_HPP

#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "roughContact/io/Units.hpp"
#include "roughContact/material/Materials.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace roughcontact_py {

namespace py = pybind11;

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// x, "a number or an array of numbers" (a float, an int, a numpy array or scalar, a list), as a
/// C-ordered float64 array. numpy's forcecast alone turns '1e6', b'1e6' and True into numbers
/// (and None into NaN); they are refused here with a TypeError that names the argument: str,
/// bytes, bool and None, arrays of dtype bool, str, bytes, complex or datetime, and object arrays
/// holding anything but real numbers. (A list mixing bools and floats becomes a float64 array in
/// numpy before anything here sees it, and is taken as numbers.)
Array numbers(const py::handle& x, const char* name);

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

/// x as a 1-D array of numbers (the argument `what`), copied.
std::vector<double> toVector(const py::handle& x, const char* what);

/// v as a 1-D float64 array (a copy).
Array toArray(const std::vector<double>& v);

/// The materials of a model: a ContactMaterials as it is, a Material against a rigid flat, a pair
/// (a, b) of Materials as ContactMaterials::pair (the core's errors, not a conversion failure).
roughContact::ContactMaterials materialsOf(const py::handle& x);

/// x as an ostream writes it (the __repr__s).
std::string number(double x);

/// A length unit by name ('m', 'um', 'nm'), or none.
std::optional<roughContact::LengthUnit> unitsOf(const std::optional<std::string>& units);

} // namespace roughcontact_py

#endif
