// SPDX-License-Identifier: GPL-3.0-or-later
// Reads one profile file and prints its size and spacing: run it under /usr/bin/time -v to see
// the reader's peak memory (maximum resident set size) on a large file.
#include "roughContact/io/ProfileReader.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: readProfilePeak PROFILE\n");
        return 2;
    }
    try {
        const roughContact::Profile p = roughContact::readProfile(argv[1]);
        std::printf("%zu points, dx = %.17g m\n", p.size(), p.spacing());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
