// SPDX-License-Identifier: GPL-3.0-or-later
// Length units of input files: metres, micrometres, nanometres.
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

} // namespace roughContact
