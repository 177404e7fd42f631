// SPDX-License-Identifier: GPL-3.0-or-later
// Length units of input files (metres, micrometres, nanometres), and numbers with a unit suffix
// (1MPa, 0.8um) where a front-end takes them (parseQuantity).
#pragma once

#include <string>

namespace roughContact {

/// Unit of the lengths (positions and heights) written in a data file.
enum class LengthUnit { m, um, nm };

/// The unit named by text: "m"; "um", "µm" (UTF-8 micro sign or Greek mu) or "micron"; "nm".
/// Surrounding whitespace is ignored; the match is case-sensitive ("M" is not metres).
/// Anything else throws ParameterError("units", ...).
LengthUnit parseLengthUnit(const std::string& text);

/// Metres in one unit: 1, 1e-6 or 1e-9.
double metresPer(LengthUnit unit);

/// The canonical name of the unit: "m", "um" or "nm".
std::string toString(LengthUnit unit);

/// What a number with a unit suffix measures (parseQuantity).
enum class Quantity { pressure, length };

/// A number with an optional unit suffix, in SI: "1e6" (SI as it stands), "1MPa", "1 MPa",
/// "200GPa", "400kPa", "0.4e9Pa" for a pressure (Pa, kPa, MPa, GPa); "0.8um", "2.5 µm", "1mm",
/// "5e-4m", "20nm" for a length (m, mm, um, µm or μm, nm). Case-sensitive (mPa is not MPa).
/// ParameterError naming `what` for no number, a unit of another quantity or an unknown one.
double parseQuantity(const std::string& text, Quantity quantity, const std::string& what);

} // namespace roughContact
