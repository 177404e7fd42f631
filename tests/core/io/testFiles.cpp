// SPDX-License-Identifier: GPL-3.0-or-later
// The rules every reader and writer of the core follows (io/Files.hpp), each held to the defect
// of issue 49 it answers: a reader refuses what is not a regular file of a sane size before it
// reads a byte (a FIFO or /dev/zero hung or grew without bound), a writer replaces only a file of
// its own kind, through a temporary file no planted link can redirect.
#include "TempDirTest.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/io/MatrixReader.hpp"
#include "roughContact/io/NpyReader.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/X3pReader.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

using namespace roughContact;

namespace {

class Files : public roughContactTest::TempDirTest {};

// The InputError a reader gives for path (ADD_FAILURE when it gives none), and how long it took.
InputError refusal(const std::function<void()>& read, double& seconds)
{
    const auto start = std::chrono::steady_clock::now();
    try {
        read();
    } catch (const InputError& e) {
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return e;
    }
    ADD_FAILURE() << "read without an error";
    return InputError("", 0, "");
}

// Every reader of the core on one path.
std::vector<std::pair<std::string, std::function<void(const std::string&)>>> readers()
{
    MatrixReadOptions matrix;
    matrix.dx = 1e-6;
    return {
        {"profile", [](const std::string& p) { (void)readProfile(p); }},
        {"spectrum", [](const std::string& p) { (void)readSpectrum(p); }},
        {"height map", [matrix](const std::string& p) { (void)readMatrix(p, matrix); }},
        {"X3P", [](const std::string& p) { (void)readX3p(p); }},
        {".npy", [matrix](const std::string& p) { (void)readNpy(p, matrix); }},
    };
}

} // namespace

TEST_F(Files, AStreamIsRefusedBeforeAByteIsRead)
{
    // Issue 49, items 1 and 3: /dev/zero grew a reader to 7.9 GB in 30 s (the text readers
    // stopped near 4.2 GB) and a FIFO without a writer waited for ever. Each reader refuses
    // either at once (well within a second) and says what it is.
    const std::string fifo = (dir_ / "fifo").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const auto& [kind, read] : readers()) {
        SCOPED_TRACE(kind);
        double seconds = 0.0;
        const InputError zero = refusal([&] { read("/dev/zero"); }, seconds);
        EXPECT_LT(seconds, 1.0);
        EXPECT_EQ(zero.file(), "/dev/zero");
        EXPECT_NE(zero.message().find("is a character device, not a"), std::string::npos) << zero.what();
        EXPECT_NE(zero.message().find("the tools read regular files only"), std::string::npos) << zero.what();
        const InputError pipe = refusal([&] { read(fifo); }, seconds);
        EXPECT_LT(seconds, 1.0);
        EXPECT_NE(pipe.message().find("is a FIFO (a pipe)"), std::string::npos) << pipe.what();
        const InputError folder = refusal([&] { read(dir_.string()); }, seconds);
        EXPECT_NE(folder.message().find("is a directory"), std::string::npos) << folder.what();
    }
}

TEST_F(Files, AFileLargerThanAnyInputIsRefusedWithItsSize)
{
    // Issue 49, item 3: a 3 GB sparse .x3p ended in std::bad_alloc. A file larger than its kind's
    // bound (fileLimits) is refused before it is read, the message giving its size; a sparse file
    // of 3 GB takes no disk.
    const std::string big = (dir_ / "big.x3p").string();
    {
        std::ofstream(big) << "x";
    }
    std::filesystem::resize_file(big, 3'000'000'000ull);
    for (const auto& [kind, read] : readers()) {
        SCOPED_TRACE(kind);
        double seconds = 0.0;
        const InputError e = refusal([&] { read(big); }, seconds);
        EXPECT_LT(seconds, 1.0);
        EXPECT_NE(e.message().find("is 3 GB (3000000000 bytes), more than any"), std::string::npos) << e.what();
        EXPECT_NE(e.message().find("(at most "), std::string::npos) << e.what();
    }
    // Within its bound a file is read to its end: the size the reader saw, and every byte.
    const std::string small = write("small.txt", std::string(200000, 'a'));
    EXPECT_EQ(readWholeFile(small, 200000, "test").size(), 200000U);
    EXPECT_THROW(readWholeFile(small, 199999, "test"), InputError);
    InputFile in(small, 200000, "test");
    EXPECT_EQ(in.size(), 200000U);
}

TEST_F(Files, AWriterLeavesAnotherKindOfFileAsItIs)
{
    // Issue 49, items 2 and 8: the FFT wisdom file and the boundary-element table replaced the
    // user's file given by a slip of the shell. replaceFile replaces only a file its writer owns
    // (isOwn of its first bytes), and leaves any other as it was, byte for byte.
    const auto isOwn = [](const std::string& start) { return start.rfind("# mine", 0) == 0; };
    const std::string theirs = write("data.csv", "x,y\n1,2\n");
    try {
        replaceFile(theirs, "# mine\n", "out", "file of mine", isOwn);
        ADD_FAILURE() << "another's file was replaced";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "out");
        EXPECT_NE(e.message().find("exists and is not a file of mine (it begins 'x,y\\x0A1,2\\x0A'): it is left as "
                                   "it is"),
                  std::string::npos)
            << e.what();
    }
    std::ifstream in(theirs);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "x,y\n1,2\n");
    // Its own kind is replaced whole; a name that is missing is written; a directory refused.
    const std::string mine = write("mine.txt", "# mine, old\n");
    replaceFile(mine, "# mine, new\n", "out", "file of mine", isOwn);
    EXPECT_EQ(readWholeFile(mine, 100, "test"), "# mine, new\n");
    const std::string fresh = (dir_ / "fresh.txt").string();
    replaceFile(fresh, "# mine\n", "out", "file of mine", isOwn);
    EXPECT_EQ(readWholeFile(fresh, 100, "test"), "# mine\n");
    EXPECT_THROW(replaceFile(dir_.string(), "# mine\n", "out", "file of mine", isOwn), ParameterError);
    EXPECT_THROW(replaceFile("", "# mine\n", "out", "file of mine", isOwn), ParameterError);
    // Nothing else was left in the folder: no temporary file.
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
        files += entry.is_regular_file() ? 1 : 0;
    }
    EXPECT_EQ(files, 3U);
}

TEST_F(Files, APlantedLinkDoesNotRedirectAWrite)
{
    // Issue 49, item 4: the table's temporary name was TABLE.tmp.PID and the wisdom's
    // WISDOM.partial, so a link planted there redirected the write onto another file. The
    // temporary file is created exclusively under a random name: links planted at every name the
    // old scheme used leave their targets untouched, and the file is written.
    const auto isOwn = [](const std::string& start) { return start.rfind("# mine", 0) == 0; };
    const std::string victim = write("victim.txt", "precious\n");
    const std::string target = (dir_ / "table.csv").string();
    for (const std::string& planted :
         {target + ".tmp." + std::to_string(::getpid()), target + ".partial", target + ".tmp"}) {
        std::filesystem::create_symlink(victim, planted);
    }
    replaceFile(target, "# mine\n", "out", "file of mine", isOwn);
    EXPECT_EQ(readWholeFile(victim, 100, "test"), "precious\n");
    EXPECT_EQ(readWholeFile(target, 100, "test"), "# mine\n");
    struct stat st {};
    ASSERT_EQ(::lstat(target.c_str(), &st), 0);
    EXPECT_TRUE(S_ISREG(st.st_mode));
    // The file is as readable as any new file (umask 022: 0644), not private as mkstemp's.
    const mode_t mask = ::umask(022);
    replaceFile(target, "# mine 2\n", "out", "file of mine", isOwn);
    ::umask(mask);
    ASSERT_EQ(::stat(target.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0644U);
}
