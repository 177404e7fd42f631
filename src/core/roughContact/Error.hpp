// SPDX-License-Identifier: GPL-3.0-or-later
// Errors of the core. Every failure on bad input names where it came from:
// InputError a file and line, ParameterError the parameter. Nothing returns NaN.
// Checks test std::isfinite/std::isnan before any ordered comparison: `x > 0` raises the
// invalid-operation flag for a NaN x, which is a SIGFPE under OpenFOAM (FloatingPoint.hpp).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

namespace roughContact {

/// Bad content of an input file; what() reads "FILE:LINE: message" (LINE omitted when 0).
class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, long line, const std::string& message);

    const std::string& file() const noexcept { return file_; }
    long line() const noexcept { return line_; }
    const std::string& message() const noexcept { return message_; }

private:
    std::string file_;
    long line_;
    std::string message_;
};

/// A parameter out of its range or missing; what() reads "NAME: message".
class ParameterError : public std::invalid_argument {
public:
    ParameterError(const std::string& parameter, const std::string& message);

    const std::string& parameter() const noexcept { return parameter_; }
    /// The message without the name.
    const std::string& message() const noexcept { return message_; }

private:
    std::string parameter_;
    std::string message_;
};

/// Throws ParameterError unless value is finite and > 0.
double requirePositive(const std::string& parameter, double value);
/// Throws ParameterError unless value is finite.
double requireFinite(const std::string& parameter, double value);
/// Throws ParameterError unless value is finite and >= 0.
double requireNonNegative(const std::string& parameter, double value);

/// The same for a literal name: the name becomes a string only when the check fails, so the
/// checks cost nothing on per-face paths.
inline double requirePositive(const char* parameter, double value)
{
    return std::isfinite(value) && value > 0.0 ? value : requirePositive(std::string(parameter), value);
}
inline double requireFinite(const char* parameter, double value)
{
    return std::isfinite(value) ? value : requireFinite(std::string(parameter), value);
}
inline double requireNonNegative(const char* parameter, double value)
{
    return std::isfinite(value) && value >= 0.0 ? value : requireNonNegative(std::string(parameter), value);
}

} // namespace roughContact
