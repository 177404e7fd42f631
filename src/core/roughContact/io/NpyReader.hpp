// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface (height map) from a NumPy .npy file: the binary form a large map takes
// without a text round trip (numpy.save of a 2-D array of heights).
#pragma once

#include "roughContact/io/MatrixReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <string>

namespace roughContact {

/// True when path names a .npy file (it ends in ".npy", any case).
bool isNpyPath(const std::string& path);

/// Reads a 2-D array of heights from a .npy file (format versions 1.0, 2.0 and 3.0; little- or
/// big-endian float64 or float32, '<f8', '>f8', '<f4', '>f4'; C or Fortran order), laid out as
/// readMatrix's text matrix: array[iy, ix] = z(ix, iy), so numpy's first axis runs along y.
/// Heights and the spacings dx (required) and dy (unset: dx) are in options.units. One read of
/// the data block: the time is proportional to the size. InputError(path, 0, ...) for a file
/// that is not such an array (magic, header, dtype, shape, a truncated data block, a non-finite
/// height: named with its [iy, ix]); ParameterError("dx"/"dy") for a missing or bad spacing.
ArealSurface readNpy(const std::string& path, const MatrixReadOptions& options);

} // namespace roughContact
