// SPDX-License-Identifier: GPL-3.0-or-later
// A GoogleTest fixture with a fresh directory per test under the system temp directory,
// removed afterwards, and a helper to write files into it (for the input-layer tests).
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace roughContactTest {

class TempDirTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("roughContact-io-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" +
                std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override
    {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    /// Writes content byte for byte to a file of the test directory; returns its path.
    std::string write(const std::string& name, const std::string& content) const
    {
        const std::filesystem::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << content;
        return p.string();
    }
    std::filesystem::path dir_;
};

} // namespace roughContactTest
