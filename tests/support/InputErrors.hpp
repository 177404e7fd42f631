// SPDX-License-Identifier: GPL-3.0-or-later
// The roughContact::InputError a reader throws, for the reader tests (io/ and the areal readers):
// the error itself, where it says it is (file and line) and what it says.
#pragma once

#include "roughContact/Error.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>

namespace roughContactTest {

/// The InputError that read() throws; fails the test, naming path, when it throws none.
template <class Read> roughContact::InputError thrownInputError(Read&& read, const std::string& path)
{
    try {
        read();
    } catch (const roughContact::InputError& e) {
        return e;
    }
    ADD_FAILURE() << path << " was read without an error";
    return roughContact::InputError("", 0, "");
}

/// The error names the file and the line as "FILE:LINE: " (just "FILE: " for line 0) and its
/// message contains text.
inline void expectLocated(const roughContact::InputError& e, const std::string& path, long line,
                          const std::string& text)
{
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), line);
    const std::string prefix = line > 0 ? path + ":" + std::to_string(line) + ": " : path + ": ";
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
    EXPECT_NE(what.find(text), std::string::npos) << what;
}

/// Runs f, which must throw an InputError naming file (and line, when one is given); returns
/// its message (without the location).
inline std::string inputErrorMessage(const std::function<void()>& f, const std::string& file,
                                     std::optional<long> line = std::nullopt)
{
    try {
        f();
    } catch (const roughContact::InputError& e) {
        EXPECT_EQ(e.file(), file);
        if (line) {
            EXPECT_EQ(e.line(), *line) << e.what();
        }
        return e.message();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

} // namespace roughContactTest
