// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/Roughness.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/parallel/Threads.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <new>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {
// Sum of |z[start + (i+1) stride] - z[start + i stride]| over n - 1 differences.
double absoluteDifferences(const std::vector<double>& z, std::size_t start, std::size_t stride, std::size_t n)
{
    double s = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        s += std::abs(z[start + (i + 1) * stride] - z[start + i * stride]);
    }
    return s;
}
} // namespace

void checkRoughness(const SurfaceRoughness& r)
{
    requirePositive("rms roughness sigma", r.sigma);
    if (r.sigma < limits::minimumRoughness) {
        std::ostringstream os;
        os << "is " << r.sigma << " m, below " << limits::minimumRoughness
           << " m: a perfectly smooth surface (or a unit mistake)";
        throw ParameterError("rms roughness sigma", os.str());
    }
    limits::requireInRange("rms roughness sigma", r.sigma, limits::minimumRoughness, limits::maximumHeight, "m");
    // Measured slopes are 1e-3 to a few; the bounds keep m/sigma, E' m and P/(E' m) finite.
    limits::requireInRange("mean absolute slope m", r.meanAbsoluteSlope, limits::minimumSlope, limits::maximumSlope, "");
}

SurfaceRoughness profileRoughness(const Profile& profile)
{
    const Profile d = profile.detrended();
    const std::size_t n = d.size();
    const double m = absoluteDifferences(d.heights(), 0, 1, n) / (static_cast<double>(n - 1) * d.spacing());
    SurfaceRoughness r{d.rms(), m};
    checkRoughness(r);
    return r;
}

SurfaceRoughness arealRoughness(const ArealSurface& surface, ScanDirection direction)
{
    const ArealSurface d = surface.detrended();
    const std::size_t nx = d.nx();
    const std::size_t ny = d.ny();
    const std::vector<double>& z = d.heights();
    double mx = 0.0;
    double my = 0.0;
    if (direction != ScanDirection::y) {
        double s = 0.0;
        for (std::size_t iy = 0; iy < ny; ++iy) {
            s += absoluteDifferences(z, iy * nx, 1, nx);
        }
        mx = s / (static_cast<double>(ny) * static_cast<double>(nx - 1) * d.dx());
    }
    if (direction != ScanDirection::x) {
        double s = 0.0;
        for (std::size_t ix = 0; ix < nx; ++ix) {
            s += absoluteDifferences(z, ix, nx, ny);
        }
        my = s / (static_cast<double>(nx) * static_cast<double>(ny - 1) * d.dy());
    }
    const double m = direction == ScanDirection::x ? mx : direction == ScanDirection::y ? my : 0.5 * (mx + my);
    SurfaceRoughness r{d.rms(), m};
    checkRoughness(r);
    return r;
}

namespace {

// sqrt((6/N) sum_k rho(k)^3) of the N = nx ny heights d (mean removed; ny = 1: a profile), rho
// their autocorrelation over the overlap at each lag: the transform of |D|^2 on a grid padded to
// twice the size each way (no wrap-around).
double gaussianSkewnessSpread(const std::vector<double>& d, std::size_t nx, std::size_t ny)
{
    const std::size_t px = 2 * nx;
    const std::size_t py = ny == 1 ? 1 : 2 * ny;
    const std::size_t pc = px / 2 + 1;
    std::vector<double> in(px * py, 0.0);
    for (std::size_t iy = 0; iy < ny; ++iy) {
        for (std::size_t ix = 0; ix < nx; ++ix) {
            in[iy * px + ix] = d[iy * nx + ix];
        }
    }
    std::unique_ptr<fftw_complex, decltype(&fftw_free)> spec(
        static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * pc * py)), &fftw_free);
    if (!spec) {
        throw std::bad_alloc();
    }
    const int dims[2] = {static_cast<int>(py), static_cast<int>(px)};
    fftw_plan forward =
        underFftwPlanner([&] { return fftw_plan_dft_r2c(2, dims, in.data(), spec.get(), FFTW_ESTIMATE); });
    fftw_execute(forward);
    underFftwPlanner([&] { fftw_destroy_plan(forward); });
    for (std::size_t i = 0; i < pc * py; ++i) {
        spec.get()[i][0] = spec.get()[i][0] * spec.get()[i][0] + spec.get()[i][1] * spec.get()[i][1];
        spec.get()[i][1] = 0.0;
    }
    fftw_plan backward =
        underFftwPlanner([&] { return fftw_plan_dft_c2r(2, dims, spec.get(), in.data(), FFTW_ESTIMATE); });
    fftw_execute(backward);
    underFftwPlanner([&] { fftw_destroy_plan(backward); });
    // The zero-lag sum; 0 only when every sample lies on the mean (a map whose every k-th point
    // does): nothing is known of their correlation, so the independent heights' sqrt(6/N).
    const double r0 = in[0];
    if (!(r0 > 0.0)) {
        return std::sqrt(6.0 / static_cast<double>(nx * ny));
    }
    double sum = 0.0;
    for (double r : in) {
        const double rho = r / r0;
        sum += rho * rho * rho;
    }
    return std::sqrt(std::max(0.0, 6.0 * sum / static_cast<double>(nx * ny)));
}

HeightSkewness skewnessOf(const std::vector<double>& z, std::size_t nx, std::size_t ny, const char* what)
{
    // z is detrended: z.size() == nx ny.
    double mean = 0.0;
    for (double v : z) {
        mean += v;
    }
    mean /= static_cast<double>(z.size());
    double m2 = 0.0;
    double m3 = 0.0;
    for (double v : z) {
        const double d = v - mean;
        m2 += d * d;
        m3 += d * d * d;
    }
    m2 /= static_cast<double>(z.size());
    m3 /= static_cast<double>(z.size());
    // As checkRoughness: round-off of the detrending leaves some 1e-21 m of a flat surface.
    if (!(std::sqrt(m2) >= limits::minimumRoughness)) {
        throw ParameterError(what, "its heights are flat (rms below 1e-15 m after detrending): no skewness");
    }
    // A map of more than spreadSide points a side: the spread from every k-th point each way
    // (Roughness.hpp), so that its padded grid stays within (2 spreadSide)^2.
    const std::size_t k = ny == 1 ? 1 : (std::max(nx, ny) + spreadSide - 1) / spreadSide;
    const std::size_t sx = (nx + k - 1) / k;
    const std::size_t sy = (ny + k - 1) / k;
    std::vector<double> d(sx * sy);
    for (std::size_t iy = 0; iy < sy; ++iy) {
        for (std::size_t ix = 0; ix < sx; ++ix) {
            d[iy * sx + ix] = z[iy * k * nx + ix * k] - mean;
        }
    }
    return HeightSkewness{m3 / (m2 * std::sqrt(m2)), gaussianSkewnessSpread(d, sx, sy)};
}

} // namespace

HeightSkewness profileSkewness(const Profile& profile)
{
    const Profile d = profile.detrended();
    return skewnessOf(d.heights(), d.size(), 1, "profile");
}

HeightSkewness arealSkewness(const ArealSurface& surface)
{
    const ArealSurface d = surface.detrended();
    return skewnessOf(d.heights(), d.nx(), d.ny(), "areal surface");
}

HeightSkewness combinedSkewness(double sigma1, const HeightSkewness& a, double sigma2,
                                const HeightSkewness& b)
{
    const double v = sigma1 * sigma1 + sigma2 * sigma2;
    if (!(v > 0.0) || !std::isfinite(v) || !std::isfinite(a.skewness) || !std::isfinite(b.skewness) ||
        !std::isfinite(a.spread) || !std::isfinite(b.spread)) {
        throw ParameterError("skewness", "needs finite skewnesses and rms heights, not both zero");
    }
    const double c1 = sigma1 * sigma1 * sigma1;
    const double c2 = sigma2 * sigma2 * sigma2;
    const double v3 = v * std::sqrt(v);
    return HeightSkewness{(a.skewness * c1 + b.skewness * c2) / v3,
                          std::hypot(a.spread * c1, b.spread * c2) / v3};
}

double shrunkSkewness(const HeightSkewness& s)
{
    if (!std::isfinite(s.skewness) || !std::isfinite(s.spread) || s.spread < 0.0) {
        throw ParameterError("skewness", "needs a finite skewness and a finite spread >= 0");
    }
    const double s2 = s.skewness * s.skewness;
    const double e2 = s.spread * s.spread;
    return s2 > e2 ? s.skewness * (1.0 - e2 / s2) : 0.0;
}

SurfaceRoughness spectrumRoughness(const Spectrum& spectrum)
{
    const SpectralMoments mo = spectralMoments(spectrum);
    SurfaceRoughness r{std::sqrt(mo.m0), std::sqrt(2.0 / pi) * std::sqrt(mo.m2)};
    checkRoughness(r);
    return r;
}

SurfaceRoughness combined(const SurfaceRoughness& a, const SurfaceRoughness& b)
{
    checkRoughness(a);
    checkRoughness(b);
    return SurfaceRoughness{std::hypot(a.sigma, b.sigma), std::hypot(a.meanAbsoluteSlope, b.meanAbsoluteSlope)};
}

SurfaceRoughness twoDirectionRoughness(const SurfaceRoughness& across, const SurfaceRoughness& along)
{
    checkRoughness(across);
    checkRoughness(along);
    return SurfaceRoughness{std::sqrt(0.5 * (across.sigma * across.sigma + along.sigma * along.sigma)),
                            0.5 * (across.meanAbsoluteSlope + along.meanAbsoluteSlope)};
}

HeightSkewness twoDirectionSkewness(const HeightSkewness& across, const HeightSkewness& along)
{
    if (!std::isfinite(across.skewness) || !std::isfinite(along.skewness) || !std::isfinite(across.spread) ||
        !std::isfinite(along.spread)) {
        throw ParameterError("skewness", "needs finite skewnesses and spreads");
    }
    return HeightSkewness{0.5 * (across.skewness + along.skewness), 0.5 * std::hypot(across.spread, along.spread)};
}

void requireRoughness(const Spectrum& surface)
{
    const std::string what =
        "surface " + (surface.source().empty() ? std::string("(spectrum)") : surface.source());
    const double rms = std::sqrt(surface.profileVariance());
    if (rms == 0.0) {
        throw ParameterError(what, "has zero roughness (every amplitude is 0): perfectly smooth surfaces "
                                   "conform and are in complete contact at any load; there is no contact "
                                   "resistance to model");
    }
    if (rms < limits::minimumRoughness) {
        std::ostringstream os;
        os << "rms height " << rms << " m is below " << limits::minimumRoughness
           << " m (a femtometre): not a physical roughness; check the units";
        throw ParameterError(what, os.str());
    }
    for (std::size_t i = 0; i < surface.size(); ++i) {
        if (surface.amplitude(i) * surface.frequency(i) > limits::flatSlope) {
            return;
        }
    }
    std::ostringstream os;
    os << "every level is flat (slope beta f <= " << limits::flatSlope
       << "): the surfaces are in complete contact at any load the models accept";
    throw ParameterError(what, os.str());
}

} // namespace roughContact
