// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers as text, one way for the whole core: parsed and formatted independently of the
// process's locale (a program that called setlocale(LC_ALL, "de_DE.UTF-8"), as Python's
// locale.setlocale does, would otherwise read "8.2477e-08" as 8 and write "1,5"), and without
// raising a floating-point flag on the way (OpenFOAM runs with overflow traps on: FloatingPoint.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace roughContact {

/// True when the whole of text, surrounding whitespace ignored, is a decimal number in the C
/// locale's syntax (as std::strtod in the "C" locale: an optional sign, digits with an optional
/// '.', an optional exponent; "inf", "nan" too), which then gives value. Hexadecimal ("0x1p3")
/// is not a number here, nor is an empty text or one holding a NUL byte. A magnitude beyond the
/// range of a double gives +-inf (callers that need a finite value check), one below the
/// smallest gives 0 or a subnormal (which is what the text means). Raises no floating-point
/// flag (a trapped overflow would be a SIGFPE) and never throws.
bool parseNumber(std::string_view text, double& value);

/// A whole number 0 .. 2^64 - 1 written in decimal digits only (no sign, fraction, exponent or
/// whitespace): the one reading of a count, a grid size or a seed written as text, for every
/// front-end. ParameterError naming `name`, saying `what` it is ("the seed SEED") and quoting
/// the text, for anything else, and for a number beyond 2^64 - 1.
std::uint64_t parseWholeNumber(std::string_view text, const std::string& name, const std::string& what);

/// v with the given significant digits (1 to 17), as printf's "%.*g" writes it in the "C"
/// locale ("0.10000000000000001", "1e+21", "inf", "nan"). 17 digits read back exactly.
std::string formatNumber(double v, int significantDigits = 17);

} // namespace roughContact
