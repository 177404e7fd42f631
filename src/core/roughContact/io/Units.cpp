// SPDX-License-Identifier: GPL-3.0-or-later
// Length units of input files: parsing their names and converting to metres.
#include "roughContact/io/Units.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Numbers.hpp"

#include <utility>
#include <vector>

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

double parseQuantity(const std::string& text, Quantity quantity, const std::string& what)
{
    static const std::vector<std::pair<std::string, double>> pressures{
        {"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}};
    // "\xC2\xB5m": U+00B5 MICRO SIGN; "\xCE\xBCm": U+03BC GREEK SMALL LETTER MU (both UTF-8).
    static const std::vector<std::pair<std::string, double>> lengths{
        {"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}, {"\xC2\xB5m", 1e-6}, {"\xCE\xBCm", 1e-6}, {"nm", 1e-9}};
    const std::string t = trimmed(text);
    double value = 0.0;
    if (parseNumber(t, value)) {
        return value; // no suffix: SI
    }
    // The suffix: the trailing letters (and the UTF-8 bytes of the micro sign).
    std::size_t end = t.size();
    while (end > 0) {
        const auto c = static_cast<unsigned char>(t[end - 1]);
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c >= 0x80)) {
            break;
        }
        --end;
    }
    const std::string suffix = t.substr(end);
    const std::string number = trimmed(t.substr(0, end));
    const auto& units = quantity == Quantity::pressure ? pressures : lengths;
    const auto& others = quantity == Quantity::pressure ? lengths : pressures;
    const char* kind = quantity == Quantity::pressure ? "a pressure" : "a length";
    std::string names;
    for (const auto& u : units) {
        names += (names.empty() ? "" : ", ") + u.first;
    }
    if (suffix.empty() || number.empty() || !parseNumber(number, value)) {
        throw ParameterError(what, "'" + text + "' is not a number with an optional unit (" + kind + ": " + names + ")");
    }
    for (const auto& u : units) {
        if (u.first == suffix) {
            return value * u.second;
        }
    }
    for (const auto& u : others) {
        if (u.first == suffix) {
            throw ParameterError(what, "'" + text + "' is not " + kind + " (" + suffix + "); give one in " + names +
                                           ", or a number in SI");
        }
    }
    throw ParameterError(what, "'" + text + "': unknown unit '" + suffix + "' for " + kind + " (" + names + ")");
}

} // namespace roughContact
