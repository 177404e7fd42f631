// SPDX-License-Identifier: GPL-3.0-or-later
// A boundary-element table built by the ranks of a job together (BoundaryElementTable::loadOrBuild
// with TableRanks): the loads are dealt out so that every load is solved once, every rank returns
// the same table, the table agrees with one rank's build to the solves' tolerance, rank 0 alone
// reads and writes the file, and a failure on any rank stops every rank. The ranks here are
// threads of this process joined by an in-memory broadcast and sum (what the condition's Pstream
// gives in a decomposed run).
#include "roughContact/Error.hpp"
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"

#include "SmallBoundaryElementSpec.hpp" // tests/support

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <filesystem>
#include <mutex>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

using namespace roughContact;

namespace {

InterfaceSpec smallSpec()
{
    return roughContactTest::smallBoundaryElementSpec();
}

// count ranks as threads: a broadcast from rank 0 and an element-wise sum, each a meeting of all.
class Job {
public:
    explicit Job(std::size_t count) : count_(count) {}

    TableRanks ranks(std::size_t rank)
    {
        TableRanks t;
        t.rank = rank;
        t.count = count_;
        t.broadcast = [this, rank](std::vector<double>& v) {
            if (rank == 0) {
                const std::lock_guard<std::mutex> lock(m_);
                slot_ = v;
            }
            meet();
            if (rank != 0) {
                const std::lock_guard<std::mutex> lock(m_);
                v = slot_;
            }
            meet();
        };
        t.sum = [this, rank](std::vector<double>& v) {
            {
                const std::lock_guard<std::mutex> lock(m_);
                if (sum_.empty()) {
                    sum_.assign(v.size(), 0.0);
                }
                for (std::size_t i = 0; i < v.size(); ++i) {
                    sum_[i] += v[i];
                }
            }
            meet();
            {
                const std::lock_guard<std::mutex> lock(m_);
                v = sum_;
            }
            meet();
            if (rank == 0) {
                const std::lock_guard<std::mutex> lock(m_);
                sum_.clear();
            }
            meet();
        };
        ++calls_;
        return t;
    }

private:
    void meet()
    {
        std::unique_lock<std::mutex> lock(m_);
        const std::size_t generation = generation_;
        if (++arrived_ == count_) {
            arrived_ = 0;
            ++generation_;
            cv_.notify_all();
        } else {
            cv_.wait(lock, [&] { return generation_ != generation; });
        }
    }

    std::size_t count_;
    std::size_t calls_ = 0;
    std::mutex m_;
    std::condition_variable cv_;
    std::size_t arrived_ = 0;
    std::size_t generation_ = 0;
    std::vector<double> slot_;
    std::vector<double> sum_;
};

// What one rank of a job did.
struct RankRun {
    BoundaryElementTablePoints points;
    std::size_t solved = 0;               // progress calls: the loads this rank solved
    std::vector<std::string> log;          // the lines it logged
    std::string error;                     // what it threw (empty: nothing)
};

// loadOrBuild(file) on `count` ranks of one job, each with its own table of spec (as each
// process of a decomposed run makes its own); `fail` (optional): a rank whose progress throws.
std::vector<RankRun> runJob(const InterfaceSpec& spec, std::size_t count, const std::string& file,
                            std::size_t fail = std::size_t(-1))
{
    Job job(count);
    std::vector<TableRanks> ranks;
    for (std::size_t r = 0; r < count; ++r) {
        ranks.push_back(job.ranks(r));
    }
    std::vector<RankRun> runs(count);
    std::vector<std::thread> threads;
    for (std::size_t r = 0; r < count; ++r) {
        threads.emplace_back([&, r] {
            RankRun& run = runs[r];
            try {
                const BoundaryElementTable t(spec);
                run.points = t.loadOrBuild(
                    file,
                    [&](std::size_t, std::size_t, double, const BoundaryElementPoint&, double) {
                        ++run.solved;
                        if (r == fail) {
                            throw ParameterError("test", "rank " + std::to_string(r) + " fails its solve");
                        }
                    },
                    [&](const std::string& line, bool) { run.log.push_back(line); }, {}, ranks[r]);
            } catch (const std::exception& e) {
                run.error = e.what();
            }
        });
    }
    for (std::thread& t : threads) {
        t.join();
    }
    return runs;
}

std::string freshDirectory(const std::string& name)
{
    const std::string dir = testing::TempDir() + "/" + name + "-" + std::to_string(::getpid());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}
} // namespace

TEST(TableRanks, EveryLoadIsDealtToOneRankAndTheSharesCostAlike)
{
    for (std::size_t loads : {1, 2, 5, 17, 31, 40}) {
        for (std::size_t ranks = 1; ranks <= 8; ++ranks) {
            SCOPED_TRACE(std::to_string(loads) + " loads, " + std::to_string(ranks) + " ranks");
            std::vector<int> dealt(loads, 0);
            // A cost that grows with the load, as the solves' iterations do (3-10x over the top
            // decade): each share's cost within the heaviest single load's of each other's.
            std::vector<double> cost(ranks, 0.0);
            std::size_t fewest = loads, most = 0;
            for (std::size_t r = 0; r < ranks; ++r) {
                const std::vector<std::size_t> mine = shareOfLoads(loads, r, ranks);
                EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
                for (std::size_t k : mine) {
                    ASSERT_LT(k, loads);
                    ++dealt[k];
                    cost[r] += std::pow(1.1, double(k));
                }
                fewest = std::min(fewest, mine.size());
                most = std::max(most, mine.size());
            }
            EXPECT_EQ(std::count(dealt.begin(), dealt.end(), 1), std::ptrdiff_t(loads)) << "a load solved twice or never";
            EXPECT_LE(most - fewest, 1u);
            const auto [low, high] = std::minmax_element(cost.begin(), cost.end());
            EXPECT_LE(*high - *low, std::pow(1.1, double(loads - 1)) + 1e-9);
        }
    }
    EXPECT_EQ(shareOfLoads(5, 0, 1), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
    // Two ranks from the top: 4 -> 0, 3 -> 1, then back: 2 -> 1, 1 -> 0, 0 -> 0.
    EXPECT_EQ(shareOfLoads(5, 0, 2), (std::vector<std::size_t>{0, 1, 4}));
    EXPECT_EQ(shareOfLoads(5, 1, 2), (std::vector<std::size_t>{2, 3}));
    EXPECT_THROW(shareOfLoads(5, 2, 2), ParameterError);
    EXPECT_THROW(shareOfLoads(5, 0, 0), ParameterError);
}

TEST(TableRanks, RanksShareTheBuildAndAllHoldTheSameTable)
{
    const InterfaceSpec spec = smallSpec();
    const BoundaryElementTable one(spec);
    const BoundaryElementTablePoints serial = one.build();
    const std::size_t n = one.pressures().size();
    for (std::size_t count : {2, 3}) {
        SCOPED_TRACE(std::to_string(count) + " ranks");
        const std::string dir = freshDirectory("tableRanks" + std::to_string(count));
        const std::string file = dir + "/table.csv";
        const std::vector<RankRun> runs = runJob(spec, count, file);
        std::size_t solved = 0;
        for (std::size_t r = 0; r < count; ++r) {
            SCOPED_TRACE("rank " + std::to_string(r));
            ASSERT_EQ(runs[r].error, "");
            EXPECT_EQ(runs[r].solved, shareOfLoads(n, r, count).size());
            solved += runs[r].solved;
            // Every rank holds rank 0's table, bit for bit.
            EXPECT_EQ(runs[r].points.pressures, runs[0].points.pressures);
            EXPECT_EQ(runs[r].points.areaFractions, runs[0].points.areaFractions);
            EXPECT_EQ(runs[r].points.conductancesPerConductivity, runs[0].points.conductancesPerConductivity);
            EXPECT_EQ(runs[r].points.separations, runs[0].points.separations);
            EXPECT_EQ(runs[r].points.end, runs[0].points.end);
            // Rank 0 alone logs (and so reads and writes the file).
            EXPECT_EQ(runs[r].log.empty(), r != 0);
        }
        EXPECT_EQ(solved, n) << "each load solved once";
        ASSERT_EQ(runs[0].log.size(), 2u);
        EXPECT_NE(runs[0].log[0].find("shared by " + std::to_string(count) + " ranks"), std::string::npos)
            << runs[0].log[0];
        EXPECT_NE(runs[0].log[1].find("wrote " + file), std::string::npos) << runs[0].log[1];
        // The file holds what every rank holds.
        const BoundaryElementTableRead read = one.read(file);
        ASSERT_EQ(read.status, BoundaryElementTableRead::Status::ok) << read.reason;
        EXPECT_EQ(read.points->conductancesPerConductivity, runs[0].points.conductancesPerConductivity);
        // One rank's curve warm-starts each load from the one below, a shared build from the
        // one below in its share: the same solutions to the solves' tolerances (relative residual
        // 1e-8 of the contact solve, 1e-7 of the conductance's), so within 1e-6 (measured: the
        // same contact areas, h_c and Y within 1e-8 at 2 and 3 ranks).
        ASSERT_EQ(runs[0].points.pressures, serial.pressures);
        for (std::size_t k = 0; k < n; ++k) {
            SCOPED_TRACE(k);
            EXPECT_NEAR(runs[0].points.areaFractions[k], serial.areaFractions[k], 1e-6 * serial.areaFractions[k]);
            EXPECT_NEAR(runs[0].points.conductancesPerConductivity[k], serial.conductancesPerConductivity[k],
                        1e-6 * serial.conductancesPerConductivity[k]);
            EXPECT_NEAR(runs[0].points.separations[k], serial.separations[k], 1e-6 * serial.separations[k]);
        }
        // The same number of ranks again (the file removed): the same table, bit for bit.
        std::filesystem::remove(file);
        const std::vector<RankRun> again = runJob(spec, count, file);
        ASSERT_EQ(again[0].error, "");
        EXPECT_EQ(again[0].points.conductancesPerConductivity, runs[0].points.conductancesPerConductivity);
        // With the file there: every rank reuses rank 0's reading, nothing is solved.
        const std::vector<RankRun> reused = runJob(spec, count, file);
        for (std::size_t r = 0; r < count; ++r) {
            ASSERT_EQ(reused[r].error, "");
            EXPECT_EQ(reused[r].solved, 0u);
            EXPECT_EQ(reused[r].points.areaFractions, runs[0].points.areaFractions);
            EXPECT_EQ(reused[r].points.completeContactPressure, runs[0].points.completeContactPressure);
        }
        ASSERT_EQ(reused[0].log.size(), 1u);
        EXPECT_EQ(reused[0].log[0].rfind("reusing " + file, 0), 0u) << reused[0].log[0];
        std::filesystem::remove_all(dir);
    }
}

TEST(TableRanks, RanksShareTheUnloadingCurvesToo)
{
    // With a cap the table holds unloading curves, dealt by peak: every rank holds rank 0's,
    // the file holds them, and they are the serial build's (each curve is one load path solved
    // alike on whichever rank: bit for bit, the peak's capped solve being the same cold start).
    InterfaceSpec spec = smallSpec();
    spec.hardness = 2e9;
    const BoundaryElementTable one(spec);
    const BoundaryElementTablePoints serial = one.build();
    ASSERT_FALSE(serial.unloading.empty());
    const std::string dir = freshDirectory("tableRanksUnloading");
    const std::string file = dir + "/table.csv";
    const std::vector<RankRun> runs = runJob(spec, 3, file);
    for (std::size_t r = 0; r < 3; ++r) {
        SCOPED_TRACE("rank " + std::to_string(r));
        ASSERT_EQ(runs[r].error, "");
        ASSERT_EQ(runs[r].points.unloading.size(), serial.unloading.size());
        for (std::size_t c = 0; c < serial.unloading.size(); ++c) {
            EXPECT_EQ(runs[r].points.unloading[c].peak, serial.unloading[c].peak);
            EXPECT_EQ(runs[r].points.unloading[c].pressures, serial.unloading[c].pressures);
            EXPECT_EQ(runs[r].points.unloading[c].conductancesPerConductivity,
                      serial.unloading[c].conductancesPerConductivity);
            EXPECT_EQ(runs[r].points.unloading[c].separations, serial.unloading[c].separations);
        }
    }
    const BoundaryElementTableRead read = one.read(file);
    ASSERT_EQ(read.status, BoundaryElementTableRead::Status::ok) << read.reason;
    ASSERT_EQ(read.points->unloading.size(), serial.unloading.size());
    EXPECT_EQ(read.points->unloading.back().areaFractions, serial.unloading.back().areaFractions);
    // Read back by every rank: the curves travel with the broadcast.
    const std::vector<RankRun> reused = runJob(spec, 3, file);
    for (std::size_t r = 0; r < 3; ++r) {
        ASSERT_EQ(reused[r].error, "");
        ASSERT_EQ(reused[r].points.unloading.size(), serial.unloading.size());
        EXPECT_EQ(reused[r].points.unloading.front().conductancesPerConductivity,
                  serial.unloading.front().conductancesPerConductivity);
    }
    std::filesystem::remove_all(dir);
}

TEST(TableRanks, APaddedMapsWarningIsTheSerialBuildsOnEveryRank)
{
    // The gains of the patch correction travel with the loads' values (BoundaryElementTable.cpp):
    // a shared build warns of the same loads as a serial one, rank 0 logging it once, every rank
    // holding it. The largest gain may differ: it is where h_spots meets h_patch, and the shared
    // curves' warm starts move h_spots there by the solves' tolerance (measured: 6.95e9 serial,
    // infinite shared), so the texts are compared up to the loads they name.
    const std::string dir = freshDirectory("tableRanksPadded");
    const InterfaceSpec spec = roughContactTest::smallPaddedMapSpec(dir + "/map.txt");
    const std::string serial = BoundaryElementTable(spec).build().patchWarning;
    ASSERT_NE(serial.find("not to be trusted"), std::string::npos) << serial;
    const auto loadsNamed = [](const std::string& w) { return w.substr(0, w.find(") on:")); };
    const std::vector<RankRun> runs = runJob(spec, 2, dir + "/table.csv");
    for (std::size_t r = 0; r < 2; ++r) {
        SCOPED_TRACE("rank " + std::to_string(r));
        ASSERT_EQ(runs[r].error, "");
        EXPECT_EQ(loadsNamed(runs[r].points.patchWarning), loadsNamed(serial));
        EXPECT_EQ(runs[r].points.patchWarning, runs[0].points.patchWarning);
    }
    EXPECT_EQ(std::count(runs[0].log.begin(), runs[0].log.end(), "boundary-element table: " + runs[0].points.patchWarning),
              1);
    EXPECT_TRUE(runs[1].log.empty());
    std::filesystem::remove_all(dir);
}

TEST(TableRanks, TableRanksLimitsTheSharingRanks)
{
    InterfaceSpec spec = smallSpec();
    const BoundaryElementTable all(spec);
    EXPECT_EQ(all.sharingRanks(1), 1u);
    EXPECT_EQ(all.sharingRanks(3), 3u);
    EXPECT_EQ(all.sharingRanks(100), all.loads().size()) << "no more ranks than loads";
    spec.tableRanks = 1;
    EXPECT_EQ(BoundaryElementTable(spec).sharingRanks(3), 1u);
    const std::string dir = freshDirectory("tableRanksOne");
    const std::vector<RankRun> runs = runJob(spec, 3, dir + "/table.csv");
    ASSERT_EQ(runs[0].error, "");
    EXPECT_EQ(runs[0].solved, all.loads().size()) << "rank 0 alone solves";
    EXPECT_EQ(runs[1].solved + runs[2].solved, 0u);
    EXPECT_EQ(runs[2].points.conductancesPerConductivity, runs[0].points.conductancesPerConductivity);
    // One rank solving is build()'s curve: the same table bit for bit.
    EXPECT_EQ(runs[0].points.conductancesPerConductivity, all.build().conductancesPerConductivity);
    std::filesystem::remove_all(dir);
}

TEST(TableRanks, AFailureOnAnyRankStopsEveryRank)
{
    const InterfaceSpec spec = smallSpec();
    const std::string dir = freshDirectory("tableRanksFail");
    // Rank 0 cannot write where the table goes: every rank throws, before anything is solved.
    {
        const std::vector<RankRun> runs = runJob(spec, 3, dir + "/missing/table.csv");
        EXPECT_NE(runs[0].error.find("cannot write into the directory"), std::string::npos) << runs[0].error;
        for (std::size_t r = 1; r < 3; ++r) {
            EXPECT_NE(runs[r].error.find("rank 0 stopped"), std::string::npos) << runs[r].error;
        }
        for (const RankRun& run : runs) {
            EXPECT_EQ(run.solved, 0u);
        }
    }
    // Rank 0 fails while it prepares the build (here its estimate's transform cannot keep its
    // FFT plans in a wisdom file whose folder went missing): every rank throws, none is left
    // waiting at the values' sum (each would wait for ever).
    {
        std::filesystem::create_directory(dir + "/gone");
        setFftWisdom(dir + "/gone/wisdom");
        std::filesystem::remove(dir + "/gone");
        const std::vector<RankRun> runs = runJob(spec, 2, dir + "/table.csv");
        setFftWisdom("");
        EXPECT_NE(runs[0].error.find("cannot be opened"), std::string::npos) << runs[0].error;
        EXPECT_NE(runs[1].error.find("rank 0 stopped"), std::string::npos) << runs[1].error;
        EXPECT_EQ(runs[0].solved + runs[1].solved, 0u);
    }
    // Rank 1's solve fails: it throws its own error, the others say a rank failed; no file.
    {
        const std::string file = dir + "/table.csv";
        const std::vector<RankRun> runs = runJob(spec, 3, file, 1);
        EXPECT_NE(runs[1].error.find("rank 1 fails its solve"), std::string::npos) << runs[1].error;
        for (std::size_t r : {0, 2}) {
            EXPECT_NE(runs[r].error.find("the solves failed on 1 rank(s)"), std::string::npos) << runs[r].error;
        }
        EXPECT_FALSE(std::filesystem::exists(file));
    }
    std::filesystem::remove_all(dir);
}

TEST(TableRanks, RanksWithoutTheirExchangeAreRefused)
{
    const BoundaryElementTable t(smallSpec());
    TableRanks r;
    r.count = 2;
    EXPECT_THROW(t.loadOrBuild(testing::TempDir() + "/unused.csv", {}, {}, {}, r), ParameterError);
    r.count = 1;
    r.rank = 1;
    EXPECT_THROW(t.loadOrBuild(testing::TempDir() + "/unused.csv", {}, {}, {}, r), ParameterError);
}
