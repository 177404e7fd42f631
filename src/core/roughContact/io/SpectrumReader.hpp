// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a surface spectrum (frequency levels and their amplitudes) from a text file.
#pragma once

#include "roughContact/surface/Spectrum.hpp"

#include <iosfwd>
#include <optional>
#include <string>

namespace roughContact {

/// Reads a spectrum from path: two columns, frequency f_i [1/m] and amplitude beta_i [m].
/// Separators, comments, blank lines and the one header line follow readProfile's rules.
/// Frequencies must be positive and increase strictly, amplitudes must be >= 0; at least one
/// row. The scan length L is 1 / (lowest frequency) unless length is given (finite, > 0).
/// The spectrum's source is path.
/// Throws InputError(path, line, ...) for bad content (line 0 for an unreadable or empty file)
/// and ParameterError("length", ...) for a bad length.
Spectrum readSpectrum(const std::string& path, std::optional<double> length = std::nullopt);

/// The same from a stream; path is the file name that errors and the spectrum's source give.
Spectrum readSpectrum(std::istream& in, const std::string& path,
                      std::optional<double> length = std::nullopt);

} // namespace roughContact
