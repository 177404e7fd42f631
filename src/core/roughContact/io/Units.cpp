// SPDX-License-Identifier: GPL-3.0-or-later
// Length units of input files: parsing their names and converting to metres.
#include "roughContact/io/Units.hpp"

#include "roughContact/Error.hpp"

namespace roughContact {

namespace {
std::string trimmed(const std::string& s)
{
    const char* space = " \t\r\n\f\v";
    const auto first = s.find_first_not_of(space);
    if (first == std::string::npos) {
        return std::string();
    }
    const auto last = s.find_last_not_of(space);
    return s.substr(first, last - first + 1);
}
} // namespace

LengthUnit parseLengthUnit(const std::string& text)
{
    const std::string t = trimmed(text);
    if (t == "m") {
        return LengthUnit::m;
    }
    // "\xC2\xB5m": U+00B5 MICRO SIGN; "\xCE\xBCm": U+03BC GREEK SMALL LETTER MU (both UTF-8).
    if (t == "um" || t == "\xC2\xB5m" || t == "\xCE\xBCm" || t == "micron") {
        return LengthUnit::um;
    }
    if (t == "nm") {
        return LengthUnit::nm;
    }
    throw ParameterError("units", "unknown unit '" + text + "'; use m, um or nm");
}

double metresPer(LengthUnit unit)
{
    switch (unit) {
    case LengthUnit::m:
        return 1.0;
    case LengthUnit::um:
        return 1e-6;
    case LengthUnit::nm:
        return 1e-9;
    }
    throw ParameterError("units", "invalid LengthUnit value");
}

std::string toString(LengthUnit unit)
{
    switch (unit) {
    case LengthUnit::m:
        return "m";
    case LengthUnit::um:
        return "um";
    case LengthUnit::nm:
        return "nm";
    }
    throw ParameterError("units", "invalid LengthUnit value");
}

} // namespace roughContact
