// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/Profile.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

Profile::Profile(std::vector<double> heights, double spacing, std::string source)
    : z_(std::move(heights)), dx_(spacing), source_(std::move(source))
{
    const std::string what = source_.empty() ? std::string("profile") : source_;
    limits::requireLength(what + ": spacing", dx_);
    if (z_.size() < minimumSize) {
        std::ostringstream os;
        os << "a profile needs at least " << minimumSize << " points, got " << z_.size();
        throw InputError(what, 0, os.str());
    }
    limits::requireLength(what + ": scan length N dx", dx_ * static_cast<double>(z_.size()));
    for (std::size_t i = 0; i < z_.size(); ++i) {
        if (!std::isfinite(z_[i]) || std::abs(z_[i]) > limits::maximumHeight) {
            std::ostringstream os;
            os << "height number " << i + 1 << " is " << limits::valueText(z_[i], "m")
               << "; heights must be finite and within +-"
               << limits::maximumHeight << " m";
            throw InputError(what, 0, os.str());
        }
    }
}

Profile Profile::detrended() const
{
    // Least-squares line through (i, z_i); centred abscissa makes the normal equations diagonal.
    const std::size_t n = z_.size();
    const double xm = 0.5 * static_cast<double>(n - 1);
    double zm = 0.0;
    for (double v : z_) {
        zm += v;
    }
    zm /= static_cast<double>(n);
    double sxz = 0.0;
    double sxx = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(i) - xm;
        sxz += x * (z_[i] - zm);
        sxx += x * x;
    }
    const double slope = sxz / sxx;
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        out[i] = z_[i] - zm - slope * (static_cast<double>(i) - xm);
    }
    return Profile(std::move(out), dx_, source_);
}

Profile Profile::subsampled(std::size_t stride) const
{
    if (stride == 0) {
        throw ParameterError("stride", "must be at least 1");
    }
    std::vector<double> out;
    out.reserve(z_.size() / stride + 1);
    for (std::size_t i = 0; i < z_.size(); i += stride) {
        out.push_back(z_[i]);
    }
    return Profile(std::move(out), dx_ * static_cast<double>(stride), source_);
}

double Profile::rms() const
{
    double s = 0.0;
    for (double v : z_) {
        s += v * v;
    }
    return std::sqrt(s / static_cast<double>(z_.size()));
}

} // namespace roughContact
