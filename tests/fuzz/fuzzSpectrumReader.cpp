// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the spectrum reader on arbitrary input (tests/fuzz/ReaderChecks.hpp says what
// the first bytes choose and what is checked); any bug aborts. Run it with tests/fuzz/run.
#include "ReaderChecks.hpp"

ROUGHCONTACT_FUZZ_TARGET("fuzzSpectrumReader", roughContactFuzz::checkSpectrumInput)
