// SPDX-License-Identifier: GPL-3.0-or-later
// Mathematical constants of the core, one place for each (C++17 has no std::numbers).
#pragma once

namespace roughContact {

/// pi to the double's precision.
inline constexpr double pi = 3.14159265358979323846;

} // namespace roughContact
