// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface (height map) from a file of either format: an X3P file or a text
// matrix or a NumPy .npy array (io/X3pReader, io/MatrixReader, io/NpyReader).
#pragma once

#include "roughContact/io/Units.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <optional>
#include <string>

namespace roughContact {

/// How to read an areal file; which options apply depends on the format.
struct ArealReadOptions {
    /// Matrix files: unit of the spacings and heights (unset: metres). X3P files are in metres
    /// by the standard, so giving units for one is an error.
    std::optional<LengthUnit> units;
    /// Matrix files: spacing along x (required) and along y (unset: dx), in units. An error for
    /// an X3P file, which carries its own (Record1/Axes/CX, CY Increment).
    std::optional<double> dx;
    std::optional<double> dy;
    /// X3P files: fill invalid points (X3pReadOptions::fillInvalid). An error for a matrix
    /// file, where a NaN is a bad field.
    bool fillInvalid = false;
};

/// True when path names an X3P file (it ends in ".x3p", any case).
bool isX3pPath(const std::string& path);

/// readX3p for an X3P file (isX3pPath), readNpy for a NumPy .npy array (isNpyPath), readMatrix
/// otherwise (a text matrix; dx, dy and units apply to .npy as to it). Throws ParameterError naming the
/// option ("dx", "dy", "units", "fillInvalid") given for the wrong format.
ArealSurface readAreal(const std::string& path, const ArealReadOptions& options);

} // namespace roughContact
