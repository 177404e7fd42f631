// SPDX-License-Identifier: GPL-3.0-or-later
// A joint that has carried a peak load (BoundaryElementModel::deformedSurface, loadPath;
// docs/theory.md §7.3): the cap's overlap at the peak is the permanent set, below the peak the
// deformed surface is elastic. Held to the closed form of a fully plastic sphere, to the loading
// curve at the peak and without a cap, and to the direction of the hysteresis.
#include "roughContact/Error.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace roughContact;

namespace {
const double Ep = 1.1e11;
const double pi = std::acos(-1.0);

// A periodic self-affine surface (Hurst 0.8, 8 levels on L = 100 um, 64^2): rms gradient about
// 0.1, as the engineering range's.
ArealSurface roughSurface()
{
    const double L = 1e-4;
    const Spectrum s = Spectrum::powerLaw(8e-7 * std::pow(1.0 / L, 1.3), 1.3, 1.0 / L, 8.0 / L, L);
    return synthesizeIsotropic(s, 64, 4, "rough");
}
} // namespace

TEST(LoadPath, AFullyPlasticSphereIsLeftWithTheClosedFormSet)
{
    // A paraboloid h = -r^2/(2R) pressed far past the cap (Hertz would give p0 = 36 H): p = H on
    // the disc r < a = sqrt(F/(pi H)), and the permanent set is delta(r) = h(r) - h(a) - (u(r) -
    // u(a)) with u(r) = (4 H a/(pi E')) E(r/a) (docs/theory.md §7.3). The geometric part is exact
    // on the cells; the elastic part's shape, u(r) - u(0) = h(r) - h(0) - (delta(r) - delta(0)),
    // is held to the closed form within 1 % of u(0) - u(0.8 a) (measured 0.09 %: the cells' pressure
    // is piecewise constant, 40 cells a radius). Its level, u(0) - u(a), is set where the set
    // ends, at the cells' rim: within h's change over one cell there, a dx/R.
    const std::size_t n = 160;
    const double L = 1e-4;
    const double dx = L / double(n);
    const double R = 1e-4;
    const double H = 1e8;
    std::vector<double> h(n * n);
    const auto radius = [&](std::size_t ix, std::size_t iy) {
        return std::hypot((double(ix) + 0.5 - 0.5 * double(n)) * dx, (double(iy) + 0.5 - 0.5 * double(n)) * dx);
    };
    for (std::size_t iy = 0; iy < n; ++iy) {
        for (std::size_t ix = 0; ix < n; ++ix) {
            h[iy * n + ix] = -radius(ix, iy) * radius(ix, iy) / (2 * R);
        }
    }
    BoundaryElementOptions o;
    o.hardness = H;
    o.detrend = Detrend::none;
    const BoundaryElementModel model(ArealSurface(h, n, n, dx, dx, "sphere"), Ep, o);
    const double a = 0.25 * L;
    const double F = pi * H * a * a;
    const double load = F / (L * L * Ep);
    const BoundaryElementPoint loaded = model.solve(load);
    EXPECT_GT(loaded.plasticFraction, 0.9 * loaded.areaFraction);
    const ArealSurface deformed = model.deformedSurface(load);
    const double scale = 4.0 * H * a / (pi * Ep); // u(r) = scale E(r/a)
    const std::size_t c = n / 2;                  // the cell next to the centre (r = dx/sqrt(2))
    const double r0 = radius(c, c);
    const double elastic0 = deformed.at(c, c); // h - delta at r0: u(r0) less a constant
    double worst = 0.0;
    double offset = 0.0;
    for (std::size_t iy = 0; iy < n; ++iy) {
        for (std::size_t ix = 0; ix < n; ++ix) {
            const double r = radius(ix, iy);
            if (r > 0.8 * a) {
                continue;
            }
            const double delta = h[iy * n + ix] - deformed.at(ix, iy);
            // u(r) - u(r0) from the set, and from the closed form
            const double fromSet = (h[iy * n + ix] - delta) - elastic0;
            const double closed = scale * (std::comp_ellint_2(r / a) - std::comp_ellint_2(r0 / a));
            worst = std::max(worst, std::abs(fromSet - closed) /
                                        (scale * (std::comp_ellint_2(0.0) - std::comp_ellint_2(0.8))));
            if (ix == c && iy == c) {
                // u(r0) - u(a) = h(r0) - h(a) - delta(r0), against the closed form
                offset = (h[iy * n + ix] + a * a / (2 * R) - delta) - scale * (std::comp_ellint_2(r / a) - 1.0);
            }
        }
    }
    std::printf("fully plastic sphere: the elastic part's shape off the closed form by %.4f; its level by %.3g m "
                "(a cell at the rim: %.3g m)\n",
                worst, offset, a * dx / R);
    EXPECT_LT(worst, 0.01);
    EXPECT_LT(std::abs(offset), a * dx / R);
}

TEST(LoadPath, AtThePeakItIsTheLoadingPointAndWithoutACapTheLoadingCurve)
{
    const ArealSurface surface = roughSurface();
    BoundaryElementOptions o;
    o.periodic = true;
    const BoundaryElementModel elastic(surface, Ep, o);
    const std::vector<double> loads{1e-4, 3e-4, 1e-3};
    const std::vector<BoundaryElementPoint> virgin = elastic.curve(loads);
    const std::vector<BoundaryElementPoint> path = elastic.loadPath(3e-4, loads);
    for (std::size_t k = 0; k < loads.size(); ++k) {
        EXPECT_EQ(path[k].areaFraction, virgin[k].areaFraction);
        EXPECT_EQ(path[k].conductancePerConductivity, virgin[k].conductancePerConductivity);
    }
    // Capped: at the peak the deformed surface's elastic solution is the capped one (the same
    // contact set to a cell: 1/4096; h to 1e-4, the contact solves' tolerance of 1e-8 in the
    // separations moving the contact set's rim by at most a cell).
    o.hardness = 0.02 * Ep * 0.1; // H/(E' h') = 0.02: soft, the peak far into the plastic range
    const BoundaryElementModel capped(surface, Ep, o);
    const double peak = 1e-3;
    const BoundaryElementPoint loading = capped.solve(peak);
    ASSERT_GT(loading.plasticFraction, 0.3 * loading.areaFraction);
    const BoundaryElementPoint atPeak = capped.loadPath(peak, {peak})[0];
    EXPECT_NEAR(atPeak.areaFraction, loading.areaFraction, 1.0 / 4096.0);
    EXPECT_NEAR(atPeak.conductancePerConductivity, loading.conductancePerConductivity,
                1e-4 * loading.conductancePerConductivity);
    // A peak at or above H leaves nothing to unload.
    try {
        capped.deformedSurface(1.01 * *o.hardness / Ep);
        ADD_FAILURE() << "a peak above H taken";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "peak load");
    }
}

TEST(LoadPath, UnloadingConductsMoreThanLoadingAndReloadingAboveThePeakLoadsOn)
{
    // Flattened summits stay flat: unloaded from the peak the joint keeps more contact and conducts
    // more than it did at the same load on the way up, the more the deeper the unloading (the
    // issue's table: 1.53 at half the peak, 1.6 at a tenth, on another surface). Beyond the peak,
    // loading goes on from the deformed surface as the virgin curve would (the same capped problem
    // once the plastic set only grows: 1 % for the rim cells that change sides).
    const ArealSurface surface = roughSurface();
    BoundaryElementOptions o;
    o.periodic = true;
    o.hardness = 0.02 * Ep * 0.1;
    const BoundaryElementModel model(surface, Ep, o);
    const double peak = 1e-3;
    const std::vector<double> loads{peak / 30, peak / 10, peak / 2, 1.5 * peak};
    const std::vector<BoundaryElementPoint> loading = model.curve(loads);
    const std::vector<BoundaryElementPoint> path = model.loadPath(peak, loads);
    double previous = 0.0;
    for (std::size_t k = 0; k + 1 < loads.size(); ++k) {
        const double ratio = path[k].conductancePerConductivity / loading[k].conductancePerConductivity;
        std::printf("P/P_max = %.3f: unloading/loading A_r %.3f, h %.3f\n", loads[k] / peak,
                    path[k].areaFraction / loading[k].areaFraction, ratio);
        EXPECT_GT(path[k].areaFraction, loading[k].areaFraction);
        EXPECT_GT(ratio, 1.1); // measured 1.8-4.6: more than the solves' 1e-4 by far
        if (k > 0) {
            EXPECT_LT(ratio, previous) << "the hysteresis falls towards the peak";
        }
        previous = ratio;
        EXPECT_EQ(path[k].plasticFraction, 0.0) << "unloading is elastic";
    }
    EXPECT_NEAR(path[3].areaFraction, loading[3].areaFraction, 0.01 * loading[3].areaFraction);
    EXPECT_NEAR(path[3].conductancePerConductivity, loading[3].conductancePerConductivity,
                0.01 * loading[3].conductancePerConductivity);
}
