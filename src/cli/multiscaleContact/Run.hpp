// SPDX-License-Identifier: GPL-3.0-or-later
// What multiscaleContact computes from its options: the load curve of a model (with its
// conductance columns or level trace), the exact model's curve, and the check of the laws.
// Each prints CSV on stdout and returns the exit status; errors are exceptions (main prints them).
#pragma once

#include "Options.hpp"

namespace multiscaleContact {

/// The run the options ask for: --check (runCheck), --model boundaryElement (runBoundaryElement),
/// or a model's load curve.
int run(const Options& o);

/// --check: the exact model on this surface at up to 5 of the run's pressures (or 4 across their
/// range), every law's ratio to it; the report, then its numbers as CSV, on stdout.
int runCheck(const Options& o);

/// --table FILE: the boundary-element table of the interface (BoundaryElementTable::loadOrBuild,
/// the condition's cache), its points as CSV.
int runTable(const Options& o);

/// --model boundaryElement: the curve, one progress line on stderr per load once the run takes
/// longer than 2 s, then the whole CSV.
int runBoundaryElement(const Options& o);

} // namespace multiscaleContact
