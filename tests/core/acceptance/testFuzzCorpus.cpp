// SPDX-License-Identifier: GPL-3.0-or-later
// The fuzz corpus (tests/fuzz/corpus/<target>/: seeds and every input that ever made a fuzz
// target fail) replayed through the fuzz targets' own checks (tests/fuzz/ReaderChecks.hpp), so
// the regressions run in the ordinary build too, without clang.
#include "FileContents.hpp"
#include "ReaderChecks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// The files of tests/fuzz/corpus/target, sorted.
std::vector<fs::path> corpus(const std::string& target)
{
    std::vector<fs::path> files;
    for (const auto& entry :
         fs::directory_iterator(fs::path(ROUGHCONTACT_SOURCE_DIR) / "tests/fuzz/corpus" / target)) {
        if (entry.is_regular_file()) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

using roughContactTest::slurp; // a file's bytes: tests/support/FileContents.hpp

/// Every file of the target's corpus passes check; the corpus has at least minimumFiles files
/// (so that a missing or emptied corpus fails instead of passing on nothing).
template <class Check> void replay(const std::string& target, Check check, std::size_t minimumFiles)
{
    const std::vector<fs::path> files = corpus(target);
    ASSERT_GE(files.size(), minimumFiles) << "tests/fuzz/corpus/" << target;
    for (const fs::path& file : files) {
        EXPECT_EQ(check(slurp(file)), "") << file.filename().string();
    }
}
} // namespace

TEST(FuzzCorpus, profileReader)
{
    replay("profileReader", roughContactFuzz::checkProfileInput, 6);
}

TEST(FuzzCorpus, spectrumReader)
{
    replay("spectrumReader", roughContactFuzz::checkSpectrumInput, 2);
}

TEST(FuzzCorpus, tableReader)
{
    replay("tableReader", roughContactFuzz::checkTableInput, 3);
}

TEST(FuzzCorpus, matrixReader)
{
    replay("matrixReader", roughContactFuzz::checkMatrixInput, 4);
}

TEST(FuzzCorpus, x3pReader)
{
    replay("x3pReader", roughContactFuzz::checkX3pInput, 5);
}

TEST(FuzzCorpus, boundaryElementTable)
{
    replay("boundaryElementTable", roughContactFuzz::checkBoundaryElementTableInput, 6);
}

TEST(FuzzCorpus, boundaryElementTableSeedsReachTheNumbers)
{
    // The valid seed reads (so that the fuzzer starts past the key and the digest), and the
    // regressions of issue 18 are refused for their reasons: a field of 1e999 (SIGFPE under
    // traps, item 2), a file whose contents do not match its digest (item 3).
    using Status = roughContact::BoundaryElementTableRead::Status;
    const fs::path dir = fs::path(ROUGHCONTACT_SOURCE_DIR) / "tests/fuzz/corpus/boundaryElementTable";
    const roughContact::BoundaryElementTable& t = roughContactFuzz::boundaryElementTable();
    const auto read = [&](const char* name) {
        return t.parse(roughContactFuzz::boundaryElementTableText(slurp(dir / name)));
    };
    EXPECT_EQ(read("valid.csv").status, Status::ok) << read("valid.csv").reason << " (a seed of another table "
                                                                                    "version: make the seeds anew)";
    EXPECT_NE(read("overflow-1e999.csv").reason.find("is not four finite numbers"), std::string::npos);
    EXPECT_NE(read("edited-digest.csv").reason.find("do not match their digest"), std::string::npos);
    EXPECT_EQ(read("v2-header.csv").status, Status::foreign);
    EXPECT_EQ(read("truncated.csv").status, Status::corrupt);
}

TEST(FuzzCorpus, x3pSeedsReadPastTheChecksums)
{
    // The valid seeds (tests/fuzz/makeX3pSeeds.py) must read, so that the fuzzer starts from
    // files that reach the data; the NaN seed must fail on its one invalid point only.
    const fs::path dir = fs::path(ROUGHCONTACT_SOURCE_DIR) / "tests/fuzz/corpus/x3pReader";
    for (const char* name : {"d-binary.x3p", "i-mask-fill.x3p", "l-binary.x3p", "inline-fill.x3p"}) {
        const std::string input = slurp(dir / name);
        roughContact::X3pReadOptions options;
        options.fillInvalid = input[0] == 'f';
        const roughContact::ArealSurface s = roughContact::readX3pBytes(input.substr(1), "seed", options);
        EXPECT_EQ(s.nx(), 8U) << name;
        EXPECT_EQ(s.dy(), 2e-6) << name;
    }
    try {
        roughContact::readX3pBytes(slurp(dir / "f-nan.x3p").substr(1), "seed");
        ADD_FAILURE() << "f-nan.x3p read";
    } catch (const roughContact::InputError& e) {
        EXPECT_NE(e.message().find("1 of 64 points are invalid"), std::string::npos) << e.what();
    }
}
