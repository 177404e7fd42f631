// SPDX-License-Identifier: GPL-3.0-or-later
// Surface benchmarks (issue target: Spectrum::fromProfile of a 10^6-point profile under 0.5 s),
// and reading a 10^6-point profile file written as syntheticProfile writes it.
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/surface/SyntheticProfile.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

using namespace roughContact;

namespace {

Profile syntheticProfile(std::size_t points)
{
    SyntheticProfileSpec spec;
    spec.points = points;
    return generateSyntheticProfile(spec);
}

void BM_SpectrumFromProfile(benchmark::State& state)
{
    const Profile p = syntheticProfile(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        const Spectrum s = Spectrum::fromProfile(p);
        benchmark::DoNotOptimize(s.amplitudes().data());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_SpectrumFromProfile)->Arg(2454)->Arg(1 << 20)->Arg(1000000)->Unit(benchmark::kMillisecond);

// Two profiles of n points on different grids (spacings 1 and 1.3 times the synthetic one's):
// Spectrum::combine re-bins both onto the longer scan's levels. It sweeps each once (O(n));
// before, each output level summed over every input level (O(n^2): 3.3x the time for 2x n).
void BM_CombineDifferentGrids(benchmark::State& state)
{
    const Profile p = syntheticProfile(static_cast<std::size_t>(state.range(0)));
    const Profile q(p.heights(), 1.3 * p.spacing(), "stretched");
    const Spectrum a = Spectrum::fromProfile(p);
    const Spectrum b = Spectrum::fromProfile(q);
    for (auto _ : state) {
        const Spectrum c = Spectrum::combine(a, b);
        benchmark::DoNotOptimize(c.amplitudes().data());
    }
    state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_CombineDifferentGrids)
    ->Arg(20000)
    ->Arg(40000)
    ->Arg(80000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

// A temporary x,z CSV of the synthetic profile (17 significant digits, as syntheticProfile
// prints), removed when the benchmark ends.
class ProfileFile {
public:
    explicit ProfileFile(std::size_t points)
        : path_((std::filesystem::temp_directory_path() /
                 ("roughContact-bench-" + std::to_string(::getpid()) + "-" + std::to_string(points) + ".csv"))
                    .string())
    {
        const Profile p = syntheticProfile(points);
        std::ofstream out(path_);
        out << "x,z\n";
        out.precision(17);
        for (std::size_t i = 0; i < p.size(); ++i) {
            out << static_cast<double>(i) * p.spacing() << ',' << p.heights()[i] << '\n';
        }
        if (!out) {
            throw std::runtime_error("cannot write " + path_);
        }
    }
    ~ProfileFile() { std::remove(path_.c_str()); }
    ProfileFile(const ProfileFile&) = delete;
    ProfileFile& operator=(const ProfileFile&) = delete;
    const std::string& path() const noexcept { return path_; }

private:
    std::string path_;
};

void BM_ReadProfile(benchmark::State& state)
{
    const ProfileFile file(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        const Profile p = readProfile(file.path());
        benchmark::DoNotOptimize(p.heights().data());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    state.SetBytesProcessed(state.iterations() *
                            static_cast<std::int64_t>(std::filesystem::file_size(file.path())));
}
BENCHMARK(BM_ReadProfile)->Arg(2454)->Arg(1000000)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
