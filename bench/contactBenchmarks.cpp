// SPDX-License-Identifier: GPL-3.0-or-later
// Load-curve benchmarks on the 2454-point stand-in profile (issue target: a 100-point jacksonGreen
// curve well under 50 ms on one core). The model is built once outside the timed loop, as the
// CLI does; construction is timed separately. Registered for every model name the factory knows.
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ContactTable.hpp"
#include "roughContact/thermal/InterfaceCoupling.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
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

// What the boundary condition does per face and per evaluation, on 102 400 faces (the
// OpenFOAM benchmark's interface): the core's one call, couple() (interface/FaceCoupling), with
// the pressures log-spread over 0.1..10 MPa and new at every evaluation (no cached lookup: the
// most expensive case), k_s, the state and the mixed condition's coefficients. Arg 1: with a
// gap beside the contact (air at 1 atm and radiation: h_g, h_r and the separation per face).
// Reported per face.
void BM_InterfaceFaces(benchmark::State& state)
{
    InterfaceSpec spec;
    SurfaceSpec surface;
    surface.kind = SurfaceSpec::Kind::profile;
    surface.file = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";
    spec.surfaces = {surface};
    spec.side1 = Material{200e9, 0.3, 0.4e9};
    spec.side2 = spec.side1;
    spec.model = "jacksonGreen";
    if (state.range(0) == 1) {
        GapSpec gap;
        gap.gas = GasGapSpec{gasByName("air"), 101325.0, 0.0, 0.0};
        gap.emissivity1 = 0.3;
        gap.emissivity2 = 0.3;
        spec.gap = gap;
    }
    const ContactInterface iface(spec);
    const std::size_t n = 102400;
    std::vector<double> P(n), P2(n), k1(n, 50.0), k2(n, 45.0), d1(n, 1e4), d2(n, 1e4), T1(n, 350.0), T2(n, 320.0),
        Tc(n, 310.0);
    std::mt19937_64 gen(1);
    std::uniform_real_distribution<double> u(5.0, 7.0);
    for (double& p : P) {
        p = std::pow(10.0, u(gen));
    }
    CouplingInputs in;
    in.n = n;
    in.pressure = P.data();
    in.pressureNbr = P.data();
    in.faceTemperature = T1.data();
    in.faceTemperatureNbr = T2.data();
    in.cellTemperatureNbr = Tc.data();
    in.kappa = k1.data();
    in.kappaNbr = k2.data();
    in.deltaCoeffs = d1.data();
    in.deltaCoeffsNbr = d2.data();
    CouplingOutputs out;
    for (auto _ : state) {
        CouplingCache cache; // empty: every face is looked up
        couple(iface, in, cache, out);
        benchmark::DoNotOptimize(out.valueFraction.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
    state.counters["ns_per_face"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                      benchmark::Counter::kInvert);
}
BENCHMARK(BM_InterfaceFaces)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

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
