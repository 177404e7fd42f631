// Google Benchmark targets for the performance figures (reported in the README, never
// asserted in a timed test):
//  - a 100-point load curve on the 2454-point stand-in profile with each model (built once);
//  - building a model and the boundary condition's pressure table;
//  - the FFT spectrum of a 10^6-point profile.
// Run: build/bin/coreBenchmarks --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/surface/SyntheticProfile.hpp"
#include "roughContact/thermal/ContactTable.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

const ContactMaterials& steel()
{
    static const ContactMaterials m = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    return m;
}

const Spectrum& standin()
{
    static const Spectrum s =
        Spectrum::fromProfile(readProfile(std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv"));
    return s;
}

std::vector<double> loadCurve()
{
    std::vector<double> loads(100);
    for (int k = 0; k < 100; ++k) {
        loads[k] = 1e-6 * std::pow(1e4, k / 99.0); // 1e-6 .. 1e-2, log spaced
    }
    return loads;
}

void BM_LoadCurve100(benchmark::State& state, const std::string& name)
{
    const auto model = makeContactModel(name, standin(), steel());
    const std::vector<double> loads = loadCurve();
    for (auto _ : state) {
        for (double l : loads) {
            benchmark::DoNotOptimize(model->areaFraction(l));
        }
    }
    state.SetLabel("2454-point profile, " + std::to_string(standin().size()) + " levels");
}

void BM_BuildModel(benchmark::State& state, const std::string& name)
{
    for (auto _ : state) {
        benchmark::DoNotOptimize(makeContactModel(name, standin(), steel()));
    }
}

void BM_ContactTable(benchmark::State& state)
{
    const double Ep = steel().reducedModulus();
    const MultiscaleModel m(standin(), Ep, makeAsperityModel("jacksonGreen", steel()));
    std::size_t points = 0;
    for (auto _ : state) {
        const ContactTable t(m, 1e-9 * Ep, Ep);
        points = t.pressures().size();
    }
    state.SetLabel(std::to_string(points) + " table points, 1e-9 E' .. complete contact");
}

void BM_FftSpectrum(benchmark::State& state)
{
    SyntheticProfileSpec spec;
    spec.points = static_cast<std::size_t>(state.range(0));
    const Profile p = generateSyntheticProfile(spec);
    for (auto _ : state) {
        benchmark::DoNotOptimize(Spectrum::fromProfile(p));
    }
}

} // namespace

BENCHMARK_CAPTURE(BM_LoadCurve100, jacksonGreen, std::string("jacksonGreen"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadCurve100, hertz, std::string("hertz"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadCurve100, jgh, std::string("jgh"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadCurve100, truncation, std::string("truncation"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadCurve100, greenwoodWilliamson, std::string("greenwoodWilliamson"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadCurve100, greenwoodWilliamsonJG, std::string("greenwoodWilliamsonJG"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadCurve100, majumdarBhushan, std::string("majumdarBhushan"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BuildModel, jacksonGreen, std::string("jacksonGreen"))->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactTable)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FftSpectrum)->Arg(1 << 20)->Arg(1000000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
