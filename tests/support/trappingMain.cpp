// SPDX-License-Identifier: GPL-3.0-or-later
// The main() of every core test: floating-point traps on, as OpenFOAM runs a solver
// (FOAM_SIGFPE: overflow, invalid operation and division by zero raise SIGFPE). A core function
// that overflows, divides by zero or makes a NaN on any path a test reaches kills that test
// instead of passing a NaN or an infinity on silently. Underflow and inexact results are not
// trapped (OpenFOAM does not trap them either).
#include <gtest/gtest.h>

#include <cfenv>

int main(int argc, char** argv)
{
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
