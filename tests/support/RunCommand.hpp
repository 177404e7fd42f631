// SPDX-License-Identifier: GPL-3.0-or-later
// Run a shell command and capture its stdout, stderr and exit status (for the CLI tests).
#pragma once

#include "FileContents.hpp" // slurp

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace roughContactTest {

struct CommandResult {
    int status = -1; ///< exit status (-1 when the command did not exit normally)
    std::string out;
    std::string err;
};

/// A fresh directory under the system's temp directory, removed by the destructor.
class TempDir {
public:
    TempDir()
    {
        std::random_device rd;
        path_ = std::filesystem::temp_directory_path() /
                ("roughContactTest-" + std::to_string(rd()) + std::to_string(rd()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir()
    {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const noexcept { return path_; }
    /// Write text to a file in this directory; returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const
    {
        const auto p = path_ / name;
        std::ofstream(p) << text;
        return p;
    }

private:
    std::filesystem::path path_;
};

inline CommandResult runCommand(const std::string& command)
{
    TempDir dir;
    const auto out = dir.path() / "stdout";
    const auto err = dir.path() / "stderr";
    const std::string full = command + " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int raw = std::system(full.c_str());
    CommandResult r;
    r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

#if defined(ROUGHCONTACT_CLI) && defined(ROUGHCONTACT_SOURCE_DIR)
/// The command-line tool of this build, and the stand-in profile (the CLI tests' surface).
inline const std::string cli = ROUGHCONTACT_CLI;
inline const std::string standin = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";

/// multiscaleContact with `args` (a shell command line's arguments).
inline CommandResult runCli(const std::string& args)
{
    return runCommand("'" + cli + "' " + args);
}
#endif

} // namespace roughContactTest
