// SPDX-License-Identifier: GPL-3.0-or-later
// The threads of the boundary-element solves (parallel/Threads.hpp): every loop, and so every
// solve, gives the same answer bit for bit for any number of threads.
#include "roughContact/Error.hpp"
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/bem/PolonskyKeer.hpp"
#include "roughContact/parallel/Threads.hpp"

#include "RunCommand.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <random>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

// Sets the core's threads for one scope, and puts back what was there.
class ThreadsFor {
public:
    explicit ThreadsFor(int n) : before_(threads()) { setThreadsUncapped(n); }
    ~ThreadsFor() { setThreadsUncapped(before_); }
    ThreadsFor(const ThreadsFor&) = delete;
    ThreadsFor& operator=(const ThreadsFor&) = delete;

private:
    int before_;
};

// A rough periodic surface of nx x ny cells: 40 waves of random direction and phase, amplitude
// falling with the wavenumber (heights of rms about `rms`).
std::vector<double> waves(std::size_t nx, std::size_t ny, unsigned seed, double rms)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> k(-12, 12);
    std::uniform_real_distribution<double> phase(0.0, 2 * pi);
    std::vector<double> h(nx * ny, 0.0);
    for (int w = 0; w < 40; ++w) {
        const int kx = k(rng);
        const int ky = k(rng);
        const double q = std::hypot(kx, ky);
        if (q < 1.0) {
            continue;
        }
        const double a = rms * std::pow(q, -1.8);
        const double ph = phase(rng);
        for (std::size_t iy = 0; iy < ny; ++iy) {
            for (std::size_t ix = 0; ix < nx; ++ix) {
                h[iy * nx + ix] += a * std::cos(2 * pi * (kx * double(ix) / double(nx) + ky * double(iy) / double(ny)) + ph);
            }
        }
    }
    return h;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
} // namespace

TEST(Threads, AtLeastOneAndChecked)
{
    EXPECT_GE(hardwareThreads(), 1);
    EXPECT_GE(threads(), 1);
    EXPECT_THROW(setThreads(0), ParameterError);
    EXPECT_THROW(setThreads(-2), ParameterError);
    const ThreadsFor two(2);
    EXPECT_EQ(threads(), threadsAvailable() ? 2 : 1);
}

TEST(Threads, NoMoreThanTheProcessorsThatHelp)
{
    // Issue 49, item 15: --threads 4096 started 4096 OpenMP threads (93 s on 2 cores; under a
    // 4 GB memory limit libgomp aborted). setThreads uses at most the processors this process
    // may run on; the answer is the same for any number, so nothing else changes.
    const int before = threads();
    EXPECT_GE(usableThreads(), 1);
    EXPECT_LE(usableThreads(), hardwareThreads());
    setThreads(4096);
    EXPECT_EQ(threads(), threadsAvailable() ? usableThreads() : 1);
    setThreads(1);
    EXPECT_EQ(threads(), 1);
    EXPECT_THROW(setThreads(4097), ParameterError);
    setThreadsUncapped(before);
}

TEST(Threads, ForEachVisitsEveryElementOnce)
{
    for (int t : {1, 2, 3}) {
        const ThreadsFor scope(t);
        for (std::size_t n : {std::size_t(0), std::size_t(5), parallel::minimumParallelSize - 1,
                              std::size_t(100003)}) {
            std::vector<int> visits(n, 0);
            parallel::forEach(n, [&](std::size_t i) { ++visits[i]; });
            std::size_t wrong = 0;
            for (int v : visits) {
                wrong += v != 1;
            }
            EXPECT_EQ(wrong, 0u) << "threads " << t << ", n " << n;
        }
    }
}

TEST(Threads, SumsAreTheSameForAnyNumberOfThreads)
{
    // 100003 values (not a multiple of the block) over eight decades, so that the order of the
    // additions shows in the last bits: the sum by blocks is the same double for 1, 2 and 3
    // threads, and within 1e-13 of the long double sum (values of one sign: the blocked sum's
    // error is at most n eps of the sum).
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> x(100003);
    long double exact = 0.0L;
    for (double& v : x) {
        v = u(rng) * std::pow(10.0, 8.0 * u(rng));
        exact += v;
    }
    std::vector<double> sums;
    for (int t : {1, 2, 3}) {
        const ThreadsFor scope(t);
        sums.push_back(parallel::reduce(
            x.size(), 0.0, [&](std::size_t i, double& a) { a += x[i]; }, [](double& a, double b) { a += b; }));
    }
    EXPECT_EQ(std::memcmp(&sums[0], &sums[1], sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&sums[0], &sums[2], sizeof(double)), 0);
    EXPECT_NEAR(sums[0] / double(exact), 1.0, 1e-13);
}

TEST(Threads, SolvesAreTheSameForAnyNumberOfThreads)
{
    // A periodic elastic solve (160 x 150: the loops and FFTs above minimumParallelSize), a
    // non-periodic one (96 x 90, padded to 192 x 180), a mirrored one (260 x 250: the cosine
    // transforms' rows and 33 column blocks, the last of 4 columns, above minimumParallelSize on
    // 2 and 3 threads) and a capped one, with their spot
    // conductances: the pressures, separations, iterations and h_c/k_s of 2 and 3 threads are
    // those of 1, bit for bit (the blocked transforms give each row and column its own 1-D
    // transform, the same whichever thread does it: 76 and 97 columns, a block of 8 and a
    // remainder; the sums are by blocks in order).
    struct Case {
        std::size_t nx, ny;
        HalfSpaceOperator::Edges edges;
        bool capped;
    };
    using Edges = HalfSpaceOperator::Edges;
    const double Ep = 1e11;
    for (const Case c : {Case{160, 150, Edges::periodic, false}, Case{96, 90, Edges::padded, false},
                         Case{260, 250, Edges::mirrored, false}, Case{160, 150, Edges::periodic, true}}) {
        const std::vector<double> h = waves(c.nx, c.ny, 3, 1e-7);
        std::vector<ContactSolution> solutions;
        std::vector<double> conductances;
        for (int t : {1, 2, 3}) {
            const ThreadsFor scope(t);
            const HalfSpaceOperator K(c.nx, c.ny, 1e-6, 1e-6, Ep, c.edges);
            PolonskyKeerOptions options;
            if (c.capped) {
                options.hardness = 3e8;
            }
            const PolonskyKeer solver(K, h, options);
            const ContactSolution s = solver.solve(1e-3 * Ep);
            ASSERT_TRUE(s.converged) << c.nx << " threads " << t;
            std::vector<bool> contact(s.pressure.size());
            for (std::size_t i = 0; i < contact.size(); ++i) {
                contact[i] = s.pressure[i] > 0.0;
            }
            conductances.push_back(spotConductance(K, contact).perConductivity);
            solutions.push_back(s);
        }
        const ContactSolution& one = solutions[0];
        EXPECT_GT(one.areaFraction, 0.01);
        EXPECT_LT(one.areaFraction, 0.9);
        if (c.capped) {
            EXPECT_GT(one.plasticFraction, 0.0);
        }
        for (std::size_t k = 1; k < solutions.size(); ++k) {
            EXPECT_TRUE(sameBits(solutions[k].pressure, one.pressure)) << c.nx << " edges " << int(c.edges);
            EXPECT_TRUE(sameBits(solutions[k].gap, one.gap)) << c.nx << " edges " << int(c.edges);
            EXPECT_EQ(solutions[k].iterations, one.iterations);
            EXPECT_EQ(std::memcmp(&conductances[k], &conductances[0], sizeof(double)), 0);
        }
    }
}

TEST(FftWisdom, MeasuredPlansAreKeptAndGiveTheSameAnswerEveryRun)
{
    // setFftWisdom (HalfSpaceOperator.hpp): FFTW_MEASURE plans kept in a file. The file is
    // written when the first operator is planned; two solves planned from it are the same bit
    // for bit, and agree with the FFTW_ESTIMATE solve to what its tolerance leaves (1e-8 of the
    // rms height on the contact set: pressures to 1e-6 relative, the area's cells exactly or
    // within a few). An unwritable file is an error naming it.
    const roughContactTest::TempDir dir;
    const std::string file = (dir.path() / "wisdom").string();
    const std::vector<double> h = waves(128, 128, 5, 1e-7);
    const auto solve = [&h]() {
        const HalfSpaceOperator K(128, 128, 1e-6, 1e-6, 1e11, true);
        return PolonskyKeer(K, h).solve(1e8);
    };
    const ThreadsFor one(1);
    const ContactSolution estimated = solve();
    setFftWisdom(file);
    const ContactSolution first = solve();
    EXPECT_TRUE(std::filesystem::exists(file));
    const ContactSolution second = solve();
    setFftWisdom("");
    EXPECT_TRUE(sameBits(first.pressure, second.pressure));
    EXPECT_TRUE(sameBits(first.gap, second.gap));
    EXPECT_NEAR(first.areaFraction, estimated.areaFraction, 4.0 / (128.0 * 128.0));
    EXPECT_NEAR(first.meanSeparation / estimated.meanSeparation, 1.0, 1e-6);
    // A file in a folder that is missing is refused when it is set; one whose folder went
    // missing since, when the plans are made.
    try {
        setFftWisdom((dir.path() / "no" / "such" / "folder" / "wisdom").string());
        ADD_FAILURE() << "a wisdom file in a missing folder was accepted";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("no/such/folder/wisdom"), std::string::npos) << e.what();
    }
    std::filesystem::create_directory(dir.path() / "gone");
    setFftWisdom((dir.path() / "gone" / "wisdom").string());
    std::filesystem::remove(dir.path() / "gone");
    try {
        solve();
        ADD_FAILURE() << "a wisdom file whose folder is gone was accepted";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("gone/wisdom"), std::string::npos) << e.what();
    }
    setFftWisdom("");
}
