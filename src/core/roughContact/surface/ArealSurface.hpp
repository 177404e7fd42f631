// SPDX-License-Identifier: GPL-3.0-or-later
// A measured or synthesized areal surface: heights z(x, y) on a uniform rectangular grid
// (ISO 25178 calls it a height map).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace roughContact {

class Profile;
class Spectrum;

/// What is removed from an areal surface's heights before it is solved (BoundaryElementModel):
/// nothing, the mean height, or the least-squares plane (mean and both tilts: form removal).
/// A periodic surface has no trend: a plane fitted to one period of it is a property of the
/// sample, and removing it breaks the periodicity (a step at the period's edges) and moves the
/// summits, so a periodic solve removes the mean only (defaultDetrend). A measured map is not
/// periodic and carries its fixture's tilt: the plane is removed.
enum class Detrend { none, mean, plane };
/// mean for a periodic solve, plane for a non-periodic one (the reasons above).
Detrend defaultDetrend(bool periodic);
/// "none", "mean" or "plane"; ParameterError naming `what` (an option, an entry) otherwise.
Detrend parseDetrend(const std::string& text, const std::string& what);
const char* detrendName(Detrend d);

class ArealSurface {
public:
    /// Heights [m] of nx points along x by ny along y, stored row by row: rows run along x and
    /// follow each other along y, so z(ix, iy) = heights[iy * nx + ix]. Spacings dx, dy [m].
    /// At least minimumSize points each way; finite heights; spacings, lengths and heights within
    /// the accepted ranges (Limits.hpp); at most limits::maximumGridPoints points in all.
    /// source names where the data came from (a file path) for error messages.
    ArealSurface(std::vector<double> heights, std::size_t nx, std::size_t ny, double dx, double dy,
                 std::string source = "");

    std::size_t nx() const noexcept { return nx_; }
    std::size_t ny() const noexcept { return ny_; }
    double dx() const noexcept { return dx_; }
    double dy() const noexcept { return dy_; }
    /// Scan lengths L_x = nx dx and L_y = ny dy [m].
    double lengthX() const noexcept { return dx_ * static_cast<double>(nx_); }
    double lengthY() const noexcept { return dy_ * static_cast<double>(ny_); }
    /// A_n = L_x L_y [m^2].
    double nominalArea() const noexcept { return lengthX() * lengthY(); }
    const std::vector<double>& heights() const noexcept { return z_; }
    double at(std::size_t ix, std::size_t iy) const { return z_[iy * nx_ + ix]; }
    const std::string& source() const noexcept { return source_; }

    /// The surface less its least-squares plane (mean and both tilts removed).
    ArealSurface detrended() const;
    /// The surface less what `how` says (Detrend): itself, less its mean, or detrended().
    ArealSurface detrended(Detrend how) const;
    /// Root-mean-square height about zero [m].
    double rms() const;
    /// Row iy (along x) and column ix (along y) as line profiles.
    Profile row(std::size_t iy) const;
    Profile column(std::size_t ix) const;

    static constexpr std::size_t minimumSize = 8;

private:
    std::vector<double> z_;
    std::size_t nx_;
    std::size_t ny_;
    double dx_;
    double dy_;
    std::string source_;
};

/// Which line scans of an areal surface make its spectrum for the line-scan (1-D) models.
enum class ScanDirection { x, y, both };

/// The line scans a map is read along unless told otherwise (a contact entry's `direction`, the
/// CLI's --direction, Python's direction=): both, as the engineering range measures the laws (an
/// anisotropic map read along x alone gives another h', m and spectrum; docs/checking.md).
constexpr ScanDirection defaultScanDirection = ScanDirection::both;

/// The averaged line-scan spectrum of an areal surface: each row (x), column (y) or both is
/// detrended and transformed as Spectrum::fromProfile does, and the power beta^2 of each level
/// averaged over the scans; with `both` and different grids along x and y, the two averages
/// are combined as Spectrum::combine combines two surfaces' powers, then halved. The result is
/// what a stylus would see on average, for the multi-scale models and Greenwood-Williamson.
Spectrum lineScanSpectrum(const ArealSurface& surface, ScanDirection direction);

/// "x", "y" or "both" (ParameterError naming `what` otherwise).
ScanDirection parseScanDirection(const std::string& text, const std::string& what = "direction");

} // namespace roughContact
