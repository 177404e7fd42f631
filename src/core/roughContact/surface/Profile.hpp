// SPDX-License-Identifier: GPL-3.0-or-later
// A measured line profile z(x) on a uniform grid (docs/theory.md §1.1).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace roughContact {

class Profile {
public:
    /// Heights [m] at spacing dx [m]. At least 8 finite samples; dx > 0.
    /// source names where the data came from (a file path) for error messages.
    Profile(std::vector<double> heights, double spacing, std::string source = "");

    const std::vector<double>& heights() const noexcept { return z_; }
    double spacing() const noexcept { return dx_; }
    std::size_t size() const noexcept { return z_.size(); }
    /// Scan length L = N dx (docs/theory.md §1.1).
    double length() const noexcept { return dx_ * static_cast<double>(z_.size()); }
    const std::string& source() const noexcept { return source_; }

    /// The profile less its least-squares line (mean and linear tilt removed).
    Profile detrended() const;
    /// Every stride-th sample (spacing stride*dx): the seed's Fig. 8 resolution study.
    Profile subsampled(std::size_t stride) const;
    /// Root-mean-square height about zero [m].
    double rms() const;

    static constexpr std::size_t minimumSize = 8;

private:
    std::vector<double> z_;
    double dx_;
    std::string source_;
};

} // namespace roughContact
