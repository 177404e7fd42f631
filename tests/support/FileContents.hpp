// SPDX-License-Identifier: GPL-3.0-or-later
// The contents of a file, byte for byte (for the reader, corpus and CLI tests).
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace roughContactTest {

/// Every byte of the file at p ("" when it cannot be opened).
inline std::string slurp(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace roughContactTest
