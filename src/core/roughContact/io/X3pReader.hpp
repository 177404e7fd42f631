// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface from an ISO 25178-72 X3P file (the ISO 5436-2 XML container).
#pragma once

#include "roughContact/surface/ArealSurface.hpp"

#include <string>

namespace roughContact {

/// How to treat an X3P file.
struct X3pReadOptions {
    /// Invalid points (NaN in D or F binary data, an empty or NaN Datum of inline data, or a 0
    /// bit in the valid-points mask) are an error naming how many, unless this is set: each is
    /// then given the mean of its valid neighbours (the 8 around it), layer by layer from the
    /// valid points inwards, so that a hole fills from its rim (a point filled in one layer
    /// counts as valid for the next).
    bool fillInvalid = false;
};

/// Reads the height map of an X3P file: a zip archive holding main.xml (ISO 5436-2) and the
/// point data it links to (Record3/DataLink/PointDataLink, binary little-endian, x fastest:
/// z(ix, iy) is point iy * SizeX + ix), or the data inline in Record3/DataList (one Datum per
/// point). Record1/Axes: CX and CY must be incremental (AxisType I) with their Increment, the
/// spacing [m]; CZ's DataType (D double, F float, I int16, L int32) types the binary data,
/// and the heights are Offset + Increment * value [m] (Increment 1 and Offset 0 when absent).
/// Record3/MatrixDimension gives SizeX, SizeY (SizeZ must be 1). The MD5 checksum of the point
/// data (Record3/DataLink/MD5ChecksumPointData) is checked, as is that of the valid-points mask
/// (ValidPointsLink: one bit a point, least significant bit first, 1 valid) when one is given.
/// Heights are returned as read (not detrended); the surface's source is path.
/// Throws InputError(path, 0, ...) naming what is wrong: not a zip, a corrupt or truncated
/// archive, a missing file or XML element (by its path, e.g. Record1/Axes/CX/Increment), a
/// checksum mismatch, sizes that disagree with the data, invalid points.
ArealSurface readX3p(const std::string& path, const X3pReadOptions& options = {});

/// The same from the bytes of an X3P file held in memory; name is the file name that errors and
/// the surface's source give.
ArealSurface readX3pBytes(const std::string& bytes, const std::string& name,
                          const X3pReadOptions& options = {});

} // namespace roughContact
