// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/Limits.hpp"

#include "roughContact/Error.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {
namespace limits {

double requireInRange(const std::string& what, double value, double lo, double hi, const char* unit)
{
    if (!std::isfinite(value) || value < lo || value > hi) {
        const std::string u = *unit != '\0' ? std::string(" ") + unit : std::string();
        std::ostringstream os;
        os << "must lie within [" << lo << u << ", " << hi << u << "], got " << valueText(value, unit);
        throw ParameterError(what, os.str());
    }
    return value;
}

std::string valueText(double value, const char* unit)
{
    std::ostringstream os;
    os << value;
    if (std::isnan(value)) {
        os << " (not a number)";
    } else if (std::isinf(value)) {
        os << " (not a finite number)";
    } else if (*unit != '\0') {
        os << ' ' << unit;
    }
    return os.str();
}

double requireLength(const std::string& what, double value)
{
    return requireInRange(what, value, minimumLength, maximumLength, "m");
}

void requireSynthesisSize(const std::string& what, std::size_t n)
{
    if (n < minimumSynthesisSize || n > maximumSynthesisSize || n % 2 != 0) {
        std::ostringstream os;
        os << "the grid size must be even and within [" << minimumSynthesisSize << ", " << maximumSynthesisSize
           << "], got " << n;
        throw ParameterError(what, os.str());
    }
}

void requireLevelCount(const std::string& what, double levels, const std::string& hint)
{
    if (levels > static_cast<double>(maximumLevels)) {
        std::ostringstream os;
        os.precision(3);
        os << "would have " << levels << " frequency levels, more than the cap of " << maximumLevels
           << " (about " << levels * bytesPerLevel / 1e6 << " MB and a pressure table of minutes; the cap "
           << "allows " << maximumLevels * bytesPerLevel / 1e6 << " MB)";
        if (!hint.empty()) {
            os << "; " << hint;
        }
        throw ParameterError(what, os.str());
    }
}

} // namespace limits
} // namespace roughContact
