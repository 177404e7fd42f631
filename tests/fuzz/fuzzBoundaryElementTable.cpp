// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the boundary-element cache reader (BoundaryElementTable::parse) on arbitrary
// text (tests/fuzz/ReaderChecks.hpp says how the key and digest are stood in for and what is
// checked); any bug aborts. Run it with tests/fuzz/run.
#include "ReaderChecks.hpp"

ROUGHCONTACT_FUZZ_TARGET("fuzzBoundaryElementTable", roughContactFuzz::checkBoundaryElementTableInput)
