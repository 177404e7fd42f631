// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/Roughness.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cmath>
#include <cstddef>
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
    requirePositive("mean absolute slope m", r.meanAbsoluteSlope);
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

double skewnessOf(const std::vector<double>& z, const char* what)
{
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
    return m3 / (m2 * std::sqrt(m2));
}

} // namespace

double profileSkewness(const Profile& profile)
{
    return skewnessOf(profile.detrended().heights(), "profile");
}

double arealSkewness(const ArealSurface& surface)
{
    return skewnessOf(surface.detrended().heights(), "areal surface");
}

double combinedSkewness(double sigma1, double s1, double sigma2, double s2)
{
    const double v = sigma1 * sigma1 + sigma2 * sigma2;
    if (!(v > 0.0) || !std::isfinite(v) || !std::isfinite(s1) || !std::isfinite(s2)) {
        throw ParameterError("skewness", "needs finite skewnesses and rms heights, not both zero");
    }
    return (s1 * sigma1 * sigma1 * sigma1 + s2 * sigma2 * sigma2 * sigma2) / (v * std::sqrt(v));
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

} // namespace roughContact
