// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/Error.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

namespace {
std::string locate(const std::string& file, long line, const std::string& message)
{
    std::ostringstream os;
    os << file;
    if (line > 0) {
        os << ':' << line;
    }
    os << ": " << message;
    return os.str();
}
} // namespace

InputError::InputError(const std::string& file, long line, const std::string& message)
    : std::runtime_error(locate(file, line, message)), file_(file), line_(line), message_(message)
{
}

ParameterError::ParameterError(const std::string& parameter, const std::string& message)
    : std::invalid_argument(parameter + ": " + message), parameter_(parameter), message_(message)
{
}

double requireFinite(const std::string& parameter, double value)
{
    if (!std::isfinite(value)) {
        std::ostringstream os;
        os << "must be a finite number, got " << value;
        throw ParameterError(parameter, os.str());
    }
    return value;
}

double requirePositive(const std::string& parameter, double value)
{
    requireFinite(parameter, value);
    if (!(value > 0.0)) {
        std::ostringstream os;
        os << "must be positive, got " << value;
        throw ParameterError(parameter, os.str());
    }
    return value;
}

double requireNonNegative(const std::string& parameter, double value)
{
    requireFinite(parameter, value);
    if (!(value >= 0.0)) {
        std::ostringstream os;
        os << "must be >= 0, got " << value;
        throw ParameterError(parameter, os.str());
    }
    return value;
}

} // namespace roughContact
