// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface from an ISO 25178-72 X3P file (the ISO 5436-2 XML container).
#pragma once

#include "roughContact/Limits.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace roughContact {

/// What the X3P reader holds in memory at most, so that a small archive that inflates to
/// gigabytes (a zip bomb, or a header that lies about its sizes) is refused, with an InputError
/// naming the file, the entry, its size and the cap, before any large allocation. The reader
/// never holds main.xml whole: it inflates it in pieces, reads Record3/DataList's Datum values
/// as they pass (8 bytes a point), and parses the rest, the metadata, as a document tree.
namespace x3pLimits {
/// The most bytes main.xml may inflate to, checked against its zip header before inflating and
/// against the running count while inflating: inline data of the largest map (4096 x 4096
/// points) at 64 characters a point ("      <Datum>-1.2345678901234567e-06</Datum>" and its
/// line end take 45). It bounds the time spent inflating, not memory (main.xml is not held).
constexpr std::uint64_t maximumXmlBytes = 64ull * limits::maximumGridPoints;
/// The most bytes of main.xml outside the content of Record3/DataList (the metadata: records 1
/// to 4, a few kB in a real file) that are parsed into a document tree. A tree costs pugixml up
/// to 16 times its text (64 bytes for a 4-byte element, <a/>), so a 1 GiB main.xml of markup or
/// whitespace would take gigabytes; 4 MiB of it take at most about 80 MB (measured: 77 MB peak
/// for a main.xml of a million <a/> elements).
constexpr std::size_t maximumMarkupBytes = std::size_t(4) << 20;
/// The most characters of one Datum's text (a number, with any whitespace around it).
constexpr std::size_t maximumDatumCharacters = 1024;
} // namespace x3pLimits

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
/// checksum mismatch, sizes that disagree with the data, invalid points, an entry or main.xml's
/// metadata larger than x3pLimits allow, an entry that inflates to more than its header says.
/// Record3/DataList may hold only Datum elements (ISO 5436-2), comments and whitespace; its
/// Datum values are read as main.xml inflates, so that the text of a large inline map is never
/// held whole.
ArealSurface readX3p(const std::string& path, const X3pReadOptions& options = {});

/// The same from the bytes of an X3P file held in memory; name is the file name that errors and
/// the surface's source give.
ArealSurface readX3pBytes(const std::string& bytes, const std::string& name,
                          const X3pReadOptions& options = {});

} // namespace roughContact
