// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary-element benchmarks (issue 9 targets, medians on one core: a 512 x 512 periodic
// elastic load point from a cold start to relative residual 1e-8 in at most 0.5 s, 1024 x 1024
// in at most 3 s; a 20-load curve at 512 x 512 with warm starts in at most 5 s), and how the
// time grows with N. The surface: a periodic Gaussian self-affine surface (Hurst exponent 0.8,
// roll-off at 1/16 of the size, cut-off at 1/4 of the grid's Nyquist wavenumber... of its
// frequencies up to N/4), rms gradient 0.1, at p/E' = 1e-3 (a few per cent in contact).
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

ArealSurface selfAffine(std::size_t n, double L)
{
    const std::size_t hx = n / 2 + 1;
    std::vector<std::complex<double>> c(n * hx, 0.0);
    std::mt19937_64 rng(42);
    std::normal_distribution<double> g(0.0, 1.0);
    const double kr = double(n) / 16.0 / double(n) * double(n); // roll-off index n/16
    for (std::size_t ky = 0; ky < n; ++ky) {
        const double fy = double(ky <= n / 2 ? ky : n - ky);
        for (std::size_t kx = 0; kx < hx; ++kx) {
            const double k = std::hypot(double(kx), fy);
            if (k == 0.0 || k > double(n) / 4.0) {
                continue;
            }
            const double a = std::pow(std::max(k, kr / 16.0), -(1.0 + 0.8));
            c[ky * hx + kx] = a * std::complex<double>(g(rng), g(rng));
        }
    }
    std::vector<double> z(n * n);
    fftw_plan plan = fftw_plan_dft_c2r_2d(int(n), int(n), reinterpret_cast<fftw_complex*>(c.data()), z.data(),
                                          FFTW_ESTIMATE);
    fftw_execute(plan);
    fftw_destroy_plan(plan);
    // Scale to an rms gradient of 0.1 (central differences, periodic).
    const double dx = L / double(n);
    double s = 0.0;
    for (std::size_t iy = 0; iy < n; ++iy) {
        for (std::size_t ix = 0; ix < n; ++ix) {
            const double gx = (z[iy * n + (ix + 1) % n] - z[iy * n + (ix + n - 1) % n]) / (2 * dx);
            const double gy = (z[((iy + 1) % n) * n + ix] - z[((iy + n - 1) % n) * n + ix]) / (2 * dx);
            s += gx * gx + gy * gy;
        }
    }
    const double scale = 0.1 / std::sqrt(s / double(n * n));
    for (double& v : z) {
        v *= scale;
    }
    return ArealSurface(std::move(z), n, n, dx, dx, "self-affine");
}

void BM_BoundaryElementColdPeriodic(benchmark::State& state)
{
    const auto n = static_cast<std::size_t>(state.range(0));
    BoundaryElementOptions o;
    o.periodic = true;
    const BoundaryElementModel model(selfAffine(n, 1e-3), 1e11, o);
    BoundaryElementPoint p;
    for (auto _ : state) {
        std::vector<double> pressure;
        p = model.solve(1e-3, &pressure);
        benchmark::DoNotOptimize(pressure.data());
    }
    state.counters["iterations"] = double(p.iterations);
    state.counters["area"] = p.areaFraction;
    state.counters["cg_iterations"] = double(p.conductanceIterations);
    state.SetComplexityN(state.range(0) * state.range(0));
}
BENCHMARK(BM_BoundaryElementColdPeriodic)
    ->Arg(128)
    ->Arg(256)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

// The contact solve alone (what the 0.5 s / 3 s targets time), without the
// conductance's linear solve.
void BM_PolonskyKeerColdPeriodic(benchmark::State& state)
{
    const auto n = static_cast<std::size_t>(state.range(0));
    const ArealSurface s = selfAffine(n, 1e-3).detrended();
    const HalfSpaceOperator op(n, n, s.dx(), s.dy(), 1e11, true);
    const PolonskyKeer solver(op, s.heights());
    ContactSolution c;
    for (auto _ : state) {
        c = solver.solve(1e-3 * 1e11);
        benchmark::DoNotOptimize(c.pressure.data());
    }
    state.counters["iterations"] = double(c.iterations);
    state.counters["residual"] = c.residual;
    state.SetComplexityN(state.range(0) * state.range(0));
}
BENCHMARK(BM_PolonskyKeerColdPeriodic)
    ->Arg(128)
    ->Arg(256)
    ->Arg(512)
    ->Arg(1024)
    ->Arg(2048)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

void BM_BoundaryElementCurve20(benchmark::State& state)
{
    const auto n = static_cast<std::size_t>(state.range(0));
    BoundaryElementOptions o;
    o.periodic = true;
    const BoundaryElementModel model(selfAffine(n, 1e-3), 1e11, o);
    std::vector<double> loads;
    for (int k = 0; k < 20; ++k) {
        loads.push_back(1e-4 * std::pow(100.0, double(k) / 19.0)); // 1e-4 .. 1e-2
    }
    for (auto _ : state) {
        const auto curve = model.curve(loads);
        benchmark::DoNotOptimize(curve.data());
    }
}
BENCHMARK(BM_BoundaryElementCurve20)->Arg(512)->Unit(benchmark::kMillisecond);

} // namespace
