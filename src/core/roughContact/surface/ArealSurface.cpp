// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/ArealSurface.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

namespace {
std::string where(const std::string& source)
{
    return source.empty() ? std::string("areal surface") : source;
}
} // namespace

ArealSurface::ArealSurface(std::vector<double> heights, std::size_t nx, std::size_t ny, double dx, double dy,
                           std::string source)
    : z_(std::move(heights)), nx_(nx), ny_(ny), dx_(dx), dy_(dy), source_(std::move(source))
{
    const std::string w = where(source_);
    if (nx_ < minimumSize || ny_ < minimumSize) {
        std::ostringstream os;
        os << "an areal surface needs at least " << minimumSize << " x " << minimumSize << " points, got "
           << nx_ << " x " << ny_;
        throw InputError(w, 0, os.str());
    }
    if (nx_ > limits::maximumGridPoints / ny_) {
        std::ostringstream os;
        os << nx_ << " x " << ny_ << " points exceed the cap of " << limits::maximumGridPoints
           << " (4096 x 4096); resample the map coarser or cut a part of it";
        throw InputError(w, 0, os.str());
    }
    if (z_.size() != nx_ * ny_) {
        std::ostringstream os;
        os << "has " << z_.size() << " heights for " << nx_ << " x " << ny_ << " points";
        throw InputError(w, 0, os.str());
    }
    limits::requireLength(w + ": spacing dx", dx_);
    limits::requireLength(w + ": spacing dy", dy_);
    limits::requireLength(w + ": scan length nx dx", lengthX());
    limits::requireLength(w + ": scan length ny dy", lengthY());
    for (std::size_t i = 0; i < z_.size(); ++i) {
        if (!std::isfinite(z_[i]) || std::abs(z_[i]) > limits::maximumHeight) {
            std::ostringstream os;
            os << "height at x index " << i % nx_ << ", y index " << i / nx_ << " is "
               << limits::valueText(z_[i], "m") << "; heights must be finite and within +-" << limits::maximumHeight << " m";
            throw InputError(w, 0, os.str());
        }
    }
}

ArealSurface ArealSurface::detrended() const
{
    // Least-squares plane z = a + b x + c y on centred indices: the normal equations are
    // diagonal on a full rectangular grid.
    const double xm = 0.5 * static_cast<double>(nx_ - 1);
    const double ym = 0.5 * static_cast<double>(ny_ - 1);
    double sz = 0.0;
    double sxz = 0.0;
    double syz = 0.0;
    double sxx = 0.0;
    double syy = 0.0;
    for (std::size_t iy = 0; iy < ny_; ++iy) {
        const double y = static_cast<double>(iy) - ym;
        for (std::size_t ix = 0; ix < nx_; ++ix) {
            const double x = static_cast<double>(ix) - xm;
            const double z = z_[iy * nx_ + ix];
            sz += z;
            sxz += x * z;
            syz += y * z;
            sxx += x * x;
            syy += y * y;
        }
    }
    const double n = static_cast<double>(z_.size());
    const double a = sz / n;
    const double b = sxz / sxx;
    const double c = syz / syy;
    std::vector<double> out(z_.size());
    for (std::size_t iy = 0; iy < ny_; ++iy) {
        const double y = static_cast<double>(iy) - ym;
        for (std::size_t ix = 0; ix < nx_; ++ix) {
            const double x = static_cast<double>(ix) - xm;
            out[iy * nx_ + ix] = z_[iy * nx_ + ix] - a - b * x - c * y;
        }
    }
    return ArealSurface(std::move(out), nx_, ny_, dx_, dy_, source_);
}

ArealSurface ArealSurface::detrended(Detrend how) const
{
    switch (how) {
    case Detrend::none:
        return *this;
    case Detrend::mean: {
        double mean = 0.0;
        for (double v : z_) {
            mean += v;
        }
        mean /= static_cast<double>(z_.size());
        std::vector<double> out(z_.size());
        for (std::size_t i = 0; i < z_.size(); ++i) {
            out[i] = z_[i] - mean;
        }
        return ArealSurface(std::move(out), nx_, ny_, dx_, dy_, source_);
    }
    case Detrend::plane:
        break;
    }
    return detrended();
}

Detrend defaultDetrend(bool periodic)
{
    return periodic ? Detrend::mean : Detrend::plane;
}

Detrend parseDetrend(const std::string& text, const std::string& what)
{
    if (text == "none") {
        return Detrend::none;
    }
    if (text == "mean") {
        return Detrend::mean;
    }
    if (text == "plane") {
        return Detrend::plane;
    }
    throw ParameterError(what, "'" + text + "' is not a detrending: none, mean (the mean height) or plane (the "
                                            "least-squares plane)");
}

const char* detrendName(Detrend d)
{
    switch (d) {
    case Detrend::none:
        return "none";
    case Detrend::mean:
        return "mean";
    case Detrend::plane:
        return "plane";
    }
    return "plane";
}

double ArealSurface::rms() const
{
    double s = 0.0;
    for (double v : z_) {
        s += v * v;
    }
    return std::sqrt(s / static_cast<double>(z_.size()));
}

Profile ArealSurface::row(std::size_t iy) const
{
    if (iy >= ny_) {
        throw ParameterError("row",
                             "index " + std::to_string(iy) + " beyond the " + std::to_string(ny_) + " rows");
    }
    return Profile(std::vector<double>(z_.begin() + static_cast<std::ptrdiff_t>(iy * nx_),
                                       z_.begin() + static_cast<std::ptrdiff_t>((iy + 1) * nx_)),
                   dx_, source_ + " row " + std::to_string(iy + 1));
}

Profile ArealSurface::column(std::size_t ix) const
{
    if (ix >= nx_) {
        throw ParameterError("column", "index " + std::to_string(ix) + " beyond the " + std::to_string(nx_) +
                                           " columns");
    }
    std::vector<double> z(ny_);
    for (std::size_t iy = 0; iy < ny_; ++iy) {
        z[iy] = z_[iy * nx_ + ix];
    }
    return Profile(std::move(z), dy_, source_ + " column " + std::to_string(ix + 1));
}

namespace {
// The level-by-level mean power of the spectra of `count` line scans (all on one grid).
template <class ScanOf> Spectrum averagedScans(std::size_t count, ScanOf scanOf, const std::string& source)
{
    std::vector<double> power;
    std::vector<double> f;
    double length = 0.0;
    bool nyquist = false;
    for (std::size_t k = 0; k < count; ++k) {
        const Spectrum s = Spectrum::fromProfile(scanOf(k));
        if (power.empty()) {
            power.assign(s.size(), 0.0);
            f = s.frequencies();
            length = s.length();
            nyquist = s.hasNyquistLevel();
        }
        for (std::size_t i = 0; i < s.size(); ++i) {
            power[i] += s.amplitude(i) * s.amplitude(i);
        }
    }
    std::vector<double> beta(power.size());
    for (std::size_t i = 0; i < power.size(); ++i) {
        beta[i] = std::sqrt(power[i] / static_cast<double>(count));
    }
    return Spectrum::withNyquistLevel(std::move(f), std::move(beta), length, source, nyquist);
}
} // namespace

Spectrum lineScanSpectrum(const ArealSurface& surface, ScanDirection direction)
{
    const std::string name = surface.source().empty() ? std::string("areal surface") : surface.source();
    const auto rows = [&] {
        return averagedScans(
            surface.ny(), [&](std::size_t k) { return surface.row(k); }, name + " (rows)");
    };
    const auto columns = [&] {
        return averagedScans(
            surface.nx(), [&](std::size_t k) { return surface.column(k); }, name + " (columns)");
    };
    switch (direction) {
    case ScanDirection::x:
        return rows();
    case ScanDirection::y:
        return columns();
    case ScanDirection::both: {
        return Spectrum::averaged(rows(), columns(), name + " (rows and columns)");
    }
    }
    throw ParameterError("direction", "unknown scan direction");
}

ScanDirection parseScanDirection(const std::string& text, const std::string& what)
{
    if (text == "x") {
        return ScanDirection::x;
    }
    if (text == "y") {
        return ScanDirection::y;
    }
    if (text == "both") {
        return ScanDirection::both;
    }
    throw ParameterError(what, "'" + text + "' is not a scan direction: x (rows), y (columns) or both");
}

} // namespace roughContact
