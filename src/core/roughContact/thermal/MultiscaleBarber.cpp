// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/MultiscaleBarber.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughContact {

namespace {
constexpr double relativeStep = 1e-3; // of the load, for dU/d load
// (B5)'s panels: a hundredth of a decade of load each, by adaptive Gauss-Kronrod to 1e-10
// relative (at most 2^6 pieces: a jump of U is not smooth at any depth, and its error, the jump
// times the last piece's width, is then below 1e-4 of the panel's); the part of a panel above a
// load by 10-point Gauss-Legendre (the traces cost ~1 us each, so one u ~ 10 us).
constexpr double panelWidth = 0.02302585092994046; // ln(10)/100
constexpr double quadratureTolerance = 1e-10;
constexpr unsigned quadratureDepth = 6;
} // namespace

MultiscaleBarber::MultiscaleBarber(const MultiscaleModel& model, const Spectrum& lineScan, double gamma)
    : model_(model), gamma_(gamma)
{
    if (!(gamma >= 0.0 && gamma <= 1.0)) {
        throw ParameterError("gamma", "must lie in [0, 1]");
    }
    const IsotropicSpectrum iso(lineScan);
    const std::vector<double>& f = lineScan.frequencies();
    binEnergy_.assign(f.size(), 0.0);
    for (std::size_t i = 0; i < f.size(); ++i) {
        // The bin: from the midpoint with the level below to the one with the level above (the
        // first and last bins as wide as their neighbour's half-gap on the other side).
        const double below = i > 0 ? 0.5 * (f[i - 1] + f[i]) : f[i] - 0.5 * (f.size() > 1 ? f[1] - f[0] : f[0]);
        const double above = i + 1 < f.size() ? 0.5 * (f[i] + f[i + 1]) : f[i] + 0.5 * (f.size() > 1 ? f[i] - f[i - 1] : f[0]);
        const double variance = iso.powerOutside(std::max(0.0, below)) - iso.powerOutside(above);
        binEnergy_[i] = 2.0 * pi * f[i] * std::max(0.0, variance) / 4.0;
    }
}

double MultiscaleBarber::energy(double load) const
{
    double U = 0.0;
    for (const LevelState& s : model_.trace(checkLoad(load))) {
        const double a = std::min(1.0, s.area / model_.nominalArea());
        U += binEnergy_[s.index] * a * (gamma_ + (1.0 - gamma_) * a * a);
    }
    return U;
}

double MultiscaleBarber::conductancePerConductivity(double load) const
{
    if (checkLoad(load) == 0.0) {
        return 0.0;
    }
    // Central, but inside the accepted loads: one-sided at their ends.
    const double lo = std::max(load * (1.0 - relativeStep), limits::minimumLoad);
    const double hi = std::min(load * (1.0 + relativeStep), limits::maximumLoad);
    const double dU = (energy(hi) - energy(lo)) / (hi - lo);
    return dU > 0.0 ? load / dU : std::numeric_limits<double>::infinity();
}

} // namespace roughContact

namespace roughContact {

double MultiscaleBarber::completeContactLoad() const
{
    std::lock_guard<std::mutex> guard(separation_->lock);
    startSeparation();
    return separation_->loadC;
}

void MultiscaleBarber::startSeparation() const
{
    Separation& s = *separation_;
    if (s.started) {
        return;
    }
    // As ContactTable's completeContactLoad: bisection in log load on the monotone path.
    double hi = limits::maximumLoad;
    if (model_.areaFraction(hi) < 1.0) {
        s.loadC = std::numeric_limits<double>::infinity();
    } else {
        double lo = limits::minimumLoad;
        if (!(model_.areaFraction(lo) < 1.0)) {
            hi = lo;
        }
        while (hi / lo > 1.0 + 1e-10) {
            const double mid = std::sqrt(lo * hi);
            (model_.areaFraction(mid) < 1.0 ? lo : hi) = mid;
        }
        s.loadC = hi;
        s.energyC = energy(hi);
    }
    s.started = true;
}

double MultiscaleBarber::meanSeparation(double load) const
{
    if (checkLoad(load) == 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    Separation& s = *separation_;
    std::lock_guard<std::mutex> guard(s.lock);
    startSeparation();
    if (!std::isfinite(s.loadC)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    if (load >= s.loadC) {
        return 0.0;
    }
    using Quadrature = boost::math::quadrature::gauss_kronrod<double, 15>;
    // int U(l) dl / l^2 = int U(e^t) e^-t dt.
    const auto integrand = [&](double t) { return energy(std::exp(t)) * std::exp(-t); };
    const double tc = std::log(s.loadC);
    const double t = std::max(std::log(load), std::log(limits::minimumLoad));
    // Panel j spans [tc - (j + 1) w, tc - j w]; the panels above load's are summed once.
    const auto j = static_cast<std::size_t>((tc - t) / panelWidth);
    while (s.below.size() <= j) {
        const std::size_t k = s.below.size();
        const double top = tc - double(k) * panelWidth;
        const double bottom = std::max(top - panelWidth, std::log(limits::minimumLoad));
        const double part = bottom < top ? Quadrature::integrate(integrand, bottom, top, quadratureDepth,
                                                                 quadratureTolerance)
                                         : 0.0;
        s.below.push_back((k > 0 ? s.below[k - 1] : 0.0) + part);
    }
    const double top = tc - double(j) * panelWidth;
    const double above = j > 0 ? s.below[j - 1] : 0.0;
    const double piece = t < top ? boost::math::quadrature::gauss<double, 10>::integrate(integrand, t, top) : 0.0;
    // (B5); a rounding below 0 (at load_c) is 0.
    return std::max(0.0, s.energyC / s.loadC - energy(load) / load + above + piece);
}

} // namespace roughContact
