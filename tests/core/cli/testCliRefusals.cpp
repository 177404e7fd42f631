// SPDX-License-Identifier: GPL-3.0-or-later
// multiscaleContact against the defects a hostile user found (issue 49), one test each, named
// after it: files it must never overwrite or hang on, a wisdom file runs share, a table in a
// read-only folder, and the small refusals of item 15. Each failed before its fix.
#include "RunCommand.hpp"

#include "roughContact/io/Files.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

using roughContactTest::cli;
using roughContactTest::CommandResult;
using roughContactTest::runCommand;
using roughContactTest::standin;
using roughContactTest::TempDir;

namespace {

constexpr auto& run = roughContactTest::runCli;
// A small boundary-element solve: the stand-in synthesized on 96^2 (FFTW plans a size with
// several factors), steel on steel.
const std::string bem =
    "--profile '" + standin + "' --model boundaryElement --synthesize 96 --E 200e9 --nu 0.3 --loads 1e-4,1e-3,1e-2";

std::string contents(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void expectRefused(const CommandResult& r, const std::vector<std::string>& needles)
{
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.out, "");
    for (const std::string& n : needles) {
        EXPECT_NE(r.err.find(n), std::string::npos) << "stderr lacks '" << n << "':\n" << r.err;
    }
}

// A boundary-element table of two solids (as the condition's), small enough to build in a second.
std::string tableArgs(const std::string& file)
{
    return "--power-law 2.56e-4,0.8,1e3,32e3 --length 1e-3 --model boundaryElement --synthesize 32,3 "
           "--E 200e9,200e9 --nu 0.3,0.3 --table '" + file + "'";
}

} // namespace

TEST(CliRefusals, FftWisdomFromAStreamIsRefusedNotHung)
{
    // Item 1: --fft-wisdom /dev/zero (or /dev/full, a FIFO) hung for ever in FFTW's import. Each
    // is refused at once, naming the option and what the path is.
    TempDir dir;
    const std::string fifo = (dir.path() / "fifo").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const std::string& path : {std::string("/dev/zero"), std::string("/dev/full"), fifo}) {
        SCOPED_TRACE(path);
        const auto start = std::chrono::steady_clock::now();
        const CommandResult r = runCommand("timeout 20 '" + cli + "' " + bem + " --fft-wisdom '" + path + "'");
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
        expectRefused(r, {"--fft-wisdom", path == fifo ? "is a FIFO" : "is a character device"});
    }
}

TEST(CliRefusals, FftWisdomDoesNotOverwriteAnotherFile)
{
    // Item 2: --fft-wisdom FILE overwrote any file that was not wisdom (the user's profile, by a
    // slip of the shell). It is refused before anything is solved and left byte for byte.
    TempDir dir;
    const std::string profile = (dir.path() / "profile.csv").string();
    std::filesystem::copy_file(standin, profile);
    const std::string before = contents(profile);
    expectRefused(run(bem + " --fft-wisdom '" + profile + "'"),
                  {"--fft-wisdom", "exists and is not FFTW wisdom", "it is left as it is"});
    EXPECT_EQ(contents(profile), before);
    // A wisdom file the tool wrote is read and kept.
    const std::string wisdom = (dir.path() / "wisdom").string();
    ASSERT_EQ(run(bem + " --fft-wisdom '" + wisdom + "'").status, 0);
    EXPECT_EQ(contents(wisdom).rfind("(fftw-3", 0), 0U);
    ASSERT_EQ(run(bem + " --fft-wisdom '" + wisdom + "'").status, 0);
}

TEST(CliRefusals, RunsSharingAWisdomFileGiveOneAnswerAndNeverFail)
{
    // Items 5 and 6: six runs sharing one new wisdom file failed at random ("cannot be written":
    // all wrote the same .partial) and gave four different answers (each timed its own plans). The
    // planning of a grid is one run's at a time (a lock on the folder): the first times it, the
    // others read its plans, so all six give the same output, bit for bit.
    TempDir dir;
    const std::string wisdom = (dir.path() / "shared.wisdom").string();
    std::string script;
    for (int i = 0; i < 6; ++i) {
        script += "'" + cli + "' " + bem + " --threads 2 --fft-wisdom '" + wisdom + "' > '" +
                  (dir.path() / ("out" + std::to_string(i))).string() + "' 2> '" +
                  (dir.path() / ("err" + std::to_string(i))).string() + "' & ";
    }
    script += "wait";
    ASSERT_EQ(std::system(("bash -c \"" + script + "\"").c_str()), 0);
    std::set<std::string> outputs;
    for (int i = 0; i < 6; ++i) {
        const std::string out = contents((dir.path() / ("out" + std::to_string(i))).string());
        const std::string err = contents((dir.path() / ("err" + std::to_string(i))).string());
        EXPECT_EQ(err.find("error"), std::string::npos) << "run " << i << ":\n" << err;
        EXPECT_NE(out.find("0.01,"), std::string::npos) << "run " << i << ":\n" << out;
        outputs.insert(out);
    }
    EXPECT_EQ(outputs.size(), 1U);
    // Nothing but the wisdom file was left in the folder (no temporary file).
    std::size_t others = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        const std::string name = entry.path().filename().string();
        others += name != "shared.wisdom" && name.rfind("out", 0) != 0 && name.rfind("err", 0) != 0 ? 1 : 0;
    }
    EXPECT_EQ(others, 0U);
}

TEST(CliRefusals, TableDoesNotReplaceAFileThatWasNeverATable)
{
    // Item 8: --table mydata.csv replaced a file that was never a table, after a warning. It is
    // refused before anything is solved and left as it is; a table of this project that is
    // foreign (another surface's) is still rebuilt and replaced.
    TempDir dir;
    const std::string mine = (dir.path() / "mydata.csv").string();
    std::ofstream(mine) << "pressure,area\n1,2\n";
    expectRefused(run(tableArgs(mine)), {"not a table of this project, so it is left as it is"});
    EXPECT_EQ(contents(mine), "pressure,area\n1,2\n");
    const std::string table = (dir.path() / "table.csv").string();
    ASSERT_EQ(run(tableArgs(table)).status, 0);
    const std::string seed3 = contents(table);
    const std::string other = tableArgs(table);
    const CommandResult rebuilt = run(other.substr(0, other.find("--synthesize 32,3")) + "--synthesize 32,4" +
                                      other.substr(other.find("--synthesize 32,3") + 17));
    ASSERT_EQ(rebuilt.status, 0) << rebuilt.err;
    EXPECT_NE(rebuilt.err.find("foreign"), std::string::npos) << rebuilt.err;
    EXPECT_NE(contents(table), seed3);
    // Item 15: an empty name is refused, not built and then lost ("cannot rename ... to ''").
    expectRefused(run(tableArgs("")), {"--table", "empty value"});
}

TEST(CliRefusals, TableIsReadFromAReadOnlyFolder)
{
    // Item 9: a valid, matching table in a folder the user cannot write was refused ("cannot write
    // into the directory") instead of being read. Run as an unprivileged user (root may write
    // anywhere): the table is read; a table that must be built there is refused before solving.
    TempDir dir;
    const std::filesystem::path folder = dir.path() / "readOnly";
    std::filesystem::create_directory(folder);
    const std::string table = (folder / "table.csv").string();
    const CommandResult built = run(tableArgs(table));
    ASSERT_EQ(built.status, 0) << built.err;
    std::filesystem::permissions(folder, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                                             std::filesystem::perms::group_read | std::filesystem::perms::group_exec |
                                             std::filesystem::perms::others_read |
                                             std::filesystem::perms::others_exec);
    std::filesystem::permissions(dir.path(), std::filesystem::perms::others_read | std::filesystem::perms::others_exec,
                                 std::filesystem::perm_options::add);
    const std::string as = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
    const CommandResult read = runCommand(as + "'" + cli + "' " + tableArgs(table));
    EXPECT_EQ(read.status, 0) << read.err;
    EXPECT_EQ(read.out, built.out);
    EXPECT_NE(read.err.find("reusing"), std::string::npos) << read.err;
    const std::string other = (folder / "other.csv").string();
    const CommandResult refused = runCommand(as + "'" + cli + "' " + tableArgs(other));
    expectRefused(refused, {"cannot write into the directory"});
    EXPECT_EQ(refused.err.find("load 1 of"), std::string::npos) << "solved before refusing:\n" << refused.err;
    std::filesystem::permissions(folder, std::filesystem::perms::owner_all);
}

TEST(CliRefusals, PressureMapDoesNotOverwriteAnotherFile)
{
    // The same rule for the CLI's own output file: --pressure-map replaces a pressure map it wrote,
    // never another file.
    TempDir dir;
    const std::string mine = (dir.path() / "notes.txt").string();
    std::ofstream(mine) << "my notes\n";
    expectRefused(run(bem + " --pressure-map '" + mine + "'"), {"--pressure-map", "it is left as it is"});
    EXPECT_EQ(contents(mine), "my notes\n");
    const std::string map = (dir.path() / "map.txt").string();
    ASSERT_EQ(run(bem + " --pressure-map '" + map + "'").status, 0);
    ASSERT_EQ(run(bem + " --pressure-map '" + map + "'").status, 0);
}

TEST(CliRefusals, ReadersRefuseStreamsAndHugeFiles)
{
    // Item 3 through the CLI: --areal /dev/zero grew to 7.9 GB in 30 s; a 3 GB sparse .x3p ended
    // in std::bad_alloc. Both refused at once, with what they are.
    TempDir dir;
    const std::string big = (dir.path() / "big.x3p").string();
    std::ofstream(big) << "x";
    std::filesystem::resize_file(big, 3'000'000'000ull);
    const std::string hertz = " --model hertz --E 200e9 --nu 0.3 --loads 1e-4";
    expectRefused(runCommand("timeout 20 '" + cli + "' --areal /dev/zero --dx 1e-6" + hertz),
                  {"/dev/zero", "is a character device"});
    expectRefused(run("--areal '" + big + "'" + hertz), {"is 3 GB (3000000000 bytes), more than any X3P"});
    expectRefused(runCommand("timeout 20 '" + cli + "' --profile /dev/zero" + hertz),
                  {"/dev/zero", "is a character device"});
}

TEST(CliRefusals, EmptyValuesAndEmptyListItemsAreRefused)
{
    // Item 15: --check-periods "" and trailing commas (--E 200GPa,) were accepted: CLI11 reads an
    // empty value as unset and drops an empty item of a list.
    const std::string p = "--profile '" + standin + "' --model hertz --nu 0.3 --loads 1e-4";
    expectRefused(run(p + " --E 200GPa,"), {"--E", "'200GPa,' has an empty item"});
    expectRefused(run(p + " --E=200GPa,,200GPa"), {"--E", "empty item"});
    expectRefused(run("--profile '" + standin + "' --model hertz --E 2e11 --nu 0.3, --loads 1e-4"), {"--nu", "empty item"});
    expectRefused(run(p + " --E 2e11 --check --check-periods ''"), {"--check-periods", "empty value"});
    expectRefused(run(p + " --E 2e11 --fft-wisdom ''"), {"--fft-wisdom", "empty value"});
    // --check keeps no table: --table with it is refused, not ignored.
    expectRefused(run(p + " --E 2e11 --check --table t.csv"), {"--table", "--check"});
}

TEST(CliRefusals, PressuresBelowTheRangeAndNegativeZero)
{
    // Item 15: -0 was printed as -0; 5e-324 Pa (a load that underflows to 0) was accepted as 0
    // while 1e-300 Pa was refused.
    const std::string p = "--profile '" + standin + "' --model hertz --E 200e9 --nu 0.3";
    const CommandResult zero = run(p + " --pressures -0");
    ASSERT_EQ(zero.status, 0) << zero.err;
    EXPECT_EQ(zero.out.find("-0"), std::string::npos) << zero.out;
    EXPECT_NE(zero.out.find("\n0,0,0,"), std::string::npos) << zero.out;
    const CommandResult loads = run(p + " --loads -0");
    ASSERT_EQ(loads.status, 0) << loads.err;
    EXPECT_EQ(loads.out.find("-0"), std::string::npos) << loads.out;
    for (const std::string& tiny : {"5e-324", "1e-300"}) {
        expectRefused(run(p + " --pressures " + tiny), {"--pressures", "loads must be 0 or within [1e-30"});
    }
}

TEST(CliRefusals, ALengthWithoutAUnitBesideOnesWithOneIsSaid)
{
    // Item 15: --roughness 0.8um,0.1,0.8 took the cut-off as 0.8 m without a word (14 times the
    // area); it is read as written, and said.
    const std::string p = " --model hertz --E 200e9 --nu 0.3 --loads 1e-4";
    const CommandResult slip = run("--roughness 0.8um,0.1,0.8" + p);
    ASSERT_EQ(slip.status, 0) << slip.err;
    EXPECT_NE(slip.err.find("warning: --roughness: CUTOFF '0.8' has no unit and is read as 0.8 m"), std::string::npos)
        << slip.err;
    const CommandResult plain = run("--roughness 0.8e-6,0.1,0.8e-3" + p);
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(plain.err, "");
    const CommandResult units = run("--roughness 0.8um,0.1,0.8mm" + p);
    ASSERT_EQ(units.status, 0) << units.err;
    EXPECT_EQ(units.err, "");
    EXPECT_EQ(units.out, plain.out);
}

TEST(CliRefusals, AMapTooSmoothForItsTableSaysSo)
{
    // Item 15: a picometre map's table failed with "complete contact at inf Pa": it conducts as
    // if bonded from the table's first load, which is what the message now says.
    TempDir dir;
    std::string rows;
    std::uint64_t state = 1;
    for (int iy = 0; iy < 32; ++iy) {
        for (int ix = 0; ix < 32; ++ix) {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            rows += (ix ? " " : "") + std::to_string(1e-2 * (double(state >> 11) / double(1ULL << 53) - 0.5));
        }
        rows += "\n";
    }
    const auto map = dir.write("pm.txt", rows);
    const CommandResult r = run("--areal '" + map.string() + "' --dx 0.001 --units nm --model boundaryElement "
                                "--E 200e9,200e9 --nu 0.3,0.3 --pressures 1e8 --table '" +
                                (dir.path() / "t.csv").string() + "'");
    expectRefused(r, {"at the table's first load", "conducts as if bonded", "check the units"});
    EXPECT_EQ(r.err.find("inf Pa"), std::string::npos) << r.err;
}

TEST(CliRefusals, ANearlyFlatMapIsCheckedAgainstTheRoughnessFloor)
{
    // Item 15: a near-constant map with --check was refused with a range message about
    // h' = 7e-33; the roughness floor's message applies.
    TempDir dir;
    std::string rows;
    for (int iy = 0; iy < 16; ++iy) {
        for (int ix = 0; ix < 16; ++ix) {
            rows += (ix ? " " : "") + std::string((ix + iy) % 2 ? "1.000000000000000001" : "1");
        }
        rows += "\n";
    }
    const auto map = dir.write("flat.txt", rows);
    const CommandResult r = run("--areal '" + map.string() + "' --dx 1e-6 --model jacksonGreen --E 200e9 --nu 0.3 "
                                "--Sy 0.4e9 --check --loads 1e-4");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err.find("h' ="), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("zero roughness"), std::string::npos) << r.err;
}

TEST(CliRefusals, ThreadsBeyondTheCoresAreNotStarted)
{
    // Item 15: --threads 4096 started 4096 threads (93 s here; under a 4 GB memory limit libgomp
    // aborted). More than the cores cannot help: they are not started, and the answer is the same.
    const CommandResult many = runCommand("bash -c \"ulimit -v 4000000; '" + cli + "' " + bem + " --threads 4096\"");
    ASSERT_EQ(many.status, 0) << many.err;
    const CommandResult one = run(bem + " --threads 1");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(many.out, one.out);
}

TEST(CliRefusals, PlotReplacesOnlyAPictureAndOnlyWhereItCanDraw)
{
    // --plot FILE draws the laws on the whole surface: a PNG it replaces; any other file is
    // refused before anything is computed and left byte for byte; with --levels, --table or the
    // boundary-element model's load curve (no law to draw) it is refused; without gnuplot it says
    // so before it computes anything and writes nothing.
    TempDir dir;
    const std::string standinRun = "--profile '" + standin + "' --model jacksonGreen --E 200e9 --nu 0.3 --Sy 0.4e9";
    const std::string png = (dir.path() / "h.png").string();
    const CommandResult drawn = run(standinRun + " --pressures 1e5,1e8 --plot '" + png + "'");
    ASSERT_EQ(drawn.status, 0) << drawn.err;
    EXPECT_EQ(contents(png).rfind(std::string("\x89PNG\r\n\x1a\n", 8), 0), 0U);
    EXPECT_NE(drawn.err.find("the picture of the interface is in " + png), std::string::npos) << drawn.err;
    // The CSV is the run's conductance (--plot implies --conductance): an h_per_k column.
    EXPECT_NE(drawn.out.substr(0, drawn.out.find('\n')).find(",h_per_k"), std::string::npos) << drawn.out;
    ASSERT_EQ(run(standinRun + " --pressures 1e6 --plot '" + png + "'").status, 0); // a PNG is replaced

    const std::string profile = (dir.path() / "profile.csv").string();
    std::filesystem::copy_file(standin, profile);
    const std::string before = contents(profile);
    expectRefused(run(standinRun + " --pressures 1e6 --plot '" + profile + "'"), {"--plot", "is left as it is"});
    EXPECT_EQ(contents(profile), before);

    const std::string other = (dir.path() / "other.png").string();
    expectRefused(run(standinRun + " --loads 1e-4 --levels --plot '" + other + "'"), {"--plot", "--levels"});
    expectRefused(run(tableArgs((dir.path() / "t.table").string()) + " --plot '" + other + "'"), {"--plot", "--table"});
    expectRefused(run(bem + " --plot '" + other + "'"), {"--plot", "--check"});
    const CommandResult noGnuplot =
        runCommand("PATH=/nonexistent '" + cli + "' " + standinRun + " --pressures 1e6 --plot '" + other + "'");
    expectRefused(noGnuplot, {"--plot", "needs gnuplot, which is not installed"}); // before any solve
    EXPECT_FALSE(std::filesystem::exists(other));
}
