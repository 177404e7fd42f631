// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface (height map) from a plain text matrix of heights.
#pragma once

#include "roughContact/io/Units.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <iosfwd>
#include <optional>
#include <string>

namespace roughContact {

/// How to interpret a matrix file.
struct MatrixReadOptions {
    /// Unit of the spacings and of the heights in the file.
    LengthUnit units = LengthUnit::m;
    /// Spacing along x (between the columns), in `units`; required, finite and > 0.
    std::optional<double> dx;
    /// Spacing along y (between the rows), in `units`; unset: dx.
    std::optional<double> dy;
};

/// Reads a height map from path: one line per row along y (the first line is y index 0), one
/// field per column along x, so that the field in column ix of data row iy is z(ix, iy).
/// Fields are separated by whitespace, commas or semicolons; `#` starts a comment; blank lines
/// are skipped. Every field must be a finite number and every row as long as the first; at
/// least ArealSurface::minimumSize x minimumSize points. Heights are returned as read (in
/// metres, not detrended); the surface's source is path.
/// Throws InputError(path, line, ...) for bad content (line 0 for an unreadable file or too few
/// points) and ParameterError("dx"/"dy", ...) for a missing or bad spacing.
ArealSurface readMatrix(const std::string& path, const MatrixReadOptions& options);

/// The same from a stream; path is the file name that errors and the surface's source give.
ArealSurface readMatrix(std::istream& in, const std::string& path, const MatrixReadOptions& options);

} // namespace roughContact
