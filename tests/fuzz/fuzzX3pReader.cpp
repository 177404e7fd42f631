// libFuzzer target: the X3P reader on arbitrary input (tests/fuzz/ReaderChecks.hpp says what
// the first bytes choose and what is checked); any bug aborts. Run it with tests/fuzz/run.
#include "ReaderChecks.hpp"

#include <cfenv>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

// Floating-point traps on, as OpenFOAM runs the readers (a solver traps overflow, invalid
// operations and division by zero): an overflow in a reader is a crash here too.
extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::string bug = roughContactFuzz::checkX3pInput(input);
    if (!bug.empty()) {
        std::fprintf(stderr, "fuzzX3pReader: %s\n", bug.c_str());
        std::abort();
    }
    return 0;
}
