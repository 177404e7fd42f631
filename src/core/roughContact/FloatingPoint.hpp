// SPDX-License-Identifier: GPL-3.0-or-later
// Floating-point traps. OpenFOAM runs a solver with overflow, invalid-operation and
// division-by-zero traps on (FOAM_SIGFPE), so a core function called from the boundary
// condition must not raise those flags on any input: a NaN or an overflow there is a SIGFPE,
// not a result. The core's tests run with the same traps (tests/support/trappingMain.cpp).
#pragma once

#include <cfenv>

namespace roughContact {

/// Holds the floating-point traps while it lives: for a library call whose result is checked
/// afterwards but which raises a flag on its way (std::strtod raises overflow for "1e999" before
/// returning inf, which the caller rejects). The caller's environment, traps and flags, is
/// restored on destruction; the flags raised meanwhile are dropped.
class QuietFloatingPoint {
public:
    QuietFloatingPoint() noexcept { std::feholdexcept(&saved_); }
    ~QuietFloatingPoint() { std::fesetenv(&saved_); }
    QuietFloatingPoint(const QuietFloatingPoint&) = delete;
    QuietFloatingPoint& operator=(const QuietFloatingPoint&) = delete;

private:
    std::fenv_t saved_;
};

} // namespace roughContact
