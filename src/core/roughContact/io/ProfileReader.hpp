// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a measured line profile z(x) from a text file (columns, or a Bruker Dektak export).
#pragma once

#include "roughContact/io/Units.hpp"
#include "roughContact/surface/Profile.hpp"

#include <iosfwd>
#include <optional>
#include <string>

namespace roughContact {

/// How to interpret a profile file.
struct ProfileReadOptions {
    /// Unit of both the positions and the heights in the file. Unset: metres, except for a
    /// Dektak export, whose data header ("Lateral um,Raw Micrometer,") names the unit of each
    /// column (um, nm, Angstrom, mm or m; heights may differ from positions); a Dektak export
    /// whose header names no unit is an error.
    std::optional<LengthUnit> units;
    /// Sample spacing for one-column (heights only) files, in `units` (metres when unset).
    /// Must be finite and > 0; giving it for a two-column file is an error.
    std::optional<double> spacing;
};

/// Reads a profile from path: two columns x z, or one column z with options.spacing.
/// Fields are separated by commas, semicolons, tabs or spaces; `#` starts a comment; blank lines
/// and one header line are skipped; empty trailing fields are ignored. A Bruker Dektak CSV
/// export is read from the line after "Scan Data" on (its data header is the one header line).
/// Positions must increase strictly on a uniform grid (to within their printed rounding, be it
/// fixed decimals or significant digits as `%g` prints); the spacing is
/// dx = (x_last - x_first) / (N - 1). Heights are returned as read, in metres, not
/// detrended; the profile's source is path.
/// Throws InputError(path, line, ...) for bad content (line 0 for an unreadable file or fewer
/// than Profile::minimumSize points) and ParameterError("spacing", ...) for a bad spacing value.
Profile readProfile(const std::string& path, const ProfileReadOptions& options = {});

/// The same from a stream (read once, front to back); path is the file name that errors and the
/// profile's source give. Memory: about 30 bytes a point beyond the profile's own 8.
Profile readProfile(std::istream& in, const std::string& path, const ProfileReadOptions& options = {});

} // namespace roughContact
