// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/io/Numbers.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/FloatingPoint.hpp"

#include <locale.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace roughContact {

namespace {

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// The "C" locale, made once (newlocale is thread-safe; the handle lives as long as the process).
locale_t cLocale()
{
    static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
    return c;
}

} // namespace

bool parseNumber(std::string_view text, double& value)
{
    while (!text.empty() && isSpace(text.front())) {
        text.remove_prefix(1);
    }
    while (!text.empty() && isSpace(text.back())) {
        text.remove_suffix(1);
    }
    if (text.empty() || text.find_first_of(std::string_view("xX\0", 3)) != std::string_view::npos) {
        return false; // (a NUL would end strtod's reading early)
    }
    const locale_t c = cLocale();
    if (c == static_cast<locale_t>(nullptr)) {
        return false; // cannot happen with glibc: the "C" locale is built in
    }
    const std::string copy(text); // strtod needs the terminating NUL
    char* end = nullptr;
    double v = 0.0;
    {
        const QuietFloatingPoint quiet; // "1e999" raises overflow on its way to inf
        v = strtod_l(copy.c_str(), &end, c);
    }
    if (end != copy.c_str() + copy.size()) {
        return false;
    }
    value = v;
    return true;
}

std::string formatNumber(double v, int significantDigits)
{
    significantDigits = std::clamp(significantDigits, 1, 17);
    char buffer[64];
    const std::to_chars_result r =
        std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, significantDigits);
    return std::string(buffer, r.ptr);
}

std::uint64_t parseWholeNumber(std::string_view text, const std::string& name, const std::string& what)
{
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const std::from_chars_result r = std::from_chars(text.data(), end, v);
    if (text.empty() || r.ptr != end || r.ec == std::errc::invalid_argument) {
        throw ParameterError(name, what + " must be a whole number of decimal digits, got '" + std::string(text) + "'");
    }
    if (r.ec == std::errc::result_out_of_range) {
        throw ParameterError(name, what + " " + std::string(text) +
                                       " is beyond the largest, 2^64 - 1 = 18446744073709551615");
    }
    return v;
}

} // namespace roughContact
