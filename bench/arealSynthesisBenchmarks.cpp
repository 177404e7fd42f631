// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic synthesis of an areal surface (ArealSynthesis.hpp) from the stand-in profile's
// spectrum: the 2-D spectrum on the grid, the random phases and FFTW's c2r transform.
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <benchmark/benchmark.h>

#include <string>

using namespace roughContact;

namespace {

void BM_SynthesizeIsotropic(benchmark::State& state)
{
    const Spectrum s =
        Spectrum::fromProfile(readProfile(std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv"));
    const auto n = static_cast<std::size_t>(state.range(0));
    std::uint64_t seed = 1;
    for (auto _ : state) {
        const ArealSurface a = synthesizeIsotropic(s, n, seed++);
        benchmark::DoNotOptimize(a.heights().data());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
}
BENCHMARK(BM_SynthesizeIsotropic)->Arg(256)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);

} // namespace
