// Load-curve benchmarks on the 2454-point stand-in profile (issue target: a 100-point jacksonGreen
// curve well under 50 ms on one core). The model is built once outside the timed loop, as the
// CLI does; construction is timed separately. Registered for every model name the factory knows.
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ContactTable.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

const std::string standinPath = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";

// The CLI's materials for the seed's steel: E = 179.52 GPa, nu = 0.32, S_y = 0.2 GPa.
const ContactMaterials& steel()
{
    static const ContactMaterials m = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    return m;
}

const Spectrum& standinSpectrum()
{
    static const Spectrum s = Spectrum::fromProfile(readProfile(standinPath));
    return s;
}

// 100 loads F/(A_n E') log-spaced from 1e-6 to 1e-2, as --load-range 1e-6:1e-2:100.
std::vector<double> curveLoads(std::size_t n = 100, double lo = 1e-6, double hi = 1e-2)
{
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        out[i] = lo * std::pow(hi / lo, double(i) / double(n - 1));
    }
    return out;
}

void loadCurve(benchmark::State& state, const std::string& name)
{
    const auto model = makeContactModel(name, standinSpectrum(), steel());
    const std::vector<double> loads = curveLoads();
    for (auto _ : state) {
        for (double load : loads) {
            double a = model->areaFraction(load);
            benchmark::DoNotOptimize(a);
        }
    }
    state.counters["loads"] = double(loads.size());
    state.counters["levels"] = double(standinSpectrum().size());
}

void construction(benchmark::State& state, const std::string& name)
{
    const Spectrum& s = standinSpectrum();
    for (auto _ : state) {
        auto model = makeContactModel(name, s, steel());
        benchmark::DoNotOptimize(model.get());
    }
}

// What one CLI run does apart from parsing and printing: read, FFT, build, 100 loads.
void BM_PipelineJacksonGreen(benchmark::State& state)
{
    const std::vector<double> loads = curveLoads();
    for (auto _ : state) {
        const Spectrum s = Spectrum::fromProfile(readProfile(standinPath));
        const auto model = makeContactModel("jacksonGreen", s, steel());
        for (double load : loads) {
            double a = model->areaFraction(load);
            benchmark::DoNotOptimize(a);
        }
    }
}
BENCHMARK(BM_PipelineJacksonGreen)->Unit(benchmark::kMillisecond);

// The boundary condition's pressure table (40 points a decade from 1e-9 E' to complete contact).
void BM_ContactTable(benchmark::State& state)
{
    const double Ep = steel().reducedModulus();
    const MultiscaleModel m(standinSpectrum(), Ep, makeAsperityModel("jacksonGreen", steel()));
    std::size_t points = 0;
    for (auto _ : state) {
        const ContactTable t(m, 1e-9 * Ep, Ep);
        points = t.pressures().size();
    }
    state.counters["points"] = double(points);
}
BENCHMARK(BM_ContactTable)->Unit(benchmark::kMillisecond);

const bool registered = [] {
    for (const std::string& name : modelNames()) {
        benchmark::RegisterBenchmark(("BM_LoadCurve100/" + name).c_str(), loadCurve, name)
            ->Unit(benchmark::kMillisecond);
    }
    for (const std::string& name : modelNames()) {
        benchmark::RegisterBenchmark(("BM_Construct/" + name).c_str(), construction, name)
            ->Unit(benchmark::kMillisecond);
    }
    return true;
}();

} // namespace
