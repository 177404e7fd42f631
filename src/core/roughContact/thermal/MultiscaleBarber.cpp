#include "roughContact/thermal/MultiscaleBarber.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughContact {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr double relativeStep = 1e-3; // of the load, for dU/d load
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
