// The fuzz corpus (tests/fuzz/corpus/<target>/: seeds and every input that ever made a fuzz
// target fail) replayed through the fuzz targets' own checks (tests/fuzz/ReaderChecks.hpp), so
// the regressions run in the ordinary build too, without clang.
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

std::string content(const fs::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Every file of the target's corpus passes check; the corpus has at least minimumFiles files
/// (so that a missing or emptied corpus fails instead of passing on nothing).
template <class Check> void replay(const std::string& target, Check check, std::size_t minimumFiles)
{
    const std::vector<fs::path> files = corpus(target);
    ASSERT_GE(files.size(), minimumFiles) << "tests/fuzz/corpus/" << target;
    for (const fs::path& file : files) {
        EXPECT_EQ(check(content(file)), "") << file.filename().string();
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
