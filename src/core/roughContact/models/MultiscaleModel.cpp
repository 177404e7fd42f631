// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/MultiscaleModel.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/Roughness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughContact {

MultiscaleModel::MultiscaleModel(const Spectrum& spectrum, double Eprime,
                                 std::shared_ptr<const AsperityModel> asperity)
    : An_(spectrum.nominalArea()), Eprime_(requirePositive("reduced modulus E'", Eprime)),
      asperity_(std::move(asperity))
{
    if (!asperity_) {
        throw ParameterError("asperity model", "none given");
    }
    requireRoughness(spectrum);
    for (std::size_t i = 0; i < spectrum.size(); ++i) {
        // Zero amplitude carries nothing; a flat level (Limits.hpp) is in complete contact at
        // every load the model accepts: both are skipped, with the same result.
        if (spectrum.amplitude(i) * spectrum.frequency(i) > limits::flatSlope) {
            levels_.push_back(Level::of(spectrum.frequency(i), spectrum.amplitude(i)));
            index_.push_back(i);
        }
    }
    constexpr double unknown = std::numeric_limits<double>::infinity();
    completeAt_.reserve(levels_.size());
    for (const Level& level : levels_) {
        double p = asperity_->completeContactPressure(level);
        // The law's own answer at that pressure must be complete contact; if rounding says
        // otherwise, evaluate this level always.
        if (!(p > 0.0 && p < unknown && asperity_->areaRatio(p, level) >= 1.0)) {
            p = unknown;
        }
        completeAt_.push_back(p);
    }
}

double MultiscaleModel::areaFraction(double load) const
{
    if (checkLoad(load) == 0.0) {
        return 0.0;
    }
    const double F = load * An_ * Eprime_;
    double A = An_;
    const std::size_t n = levels_.size();
    for (std::size_t k = 0; k < n; ++k) {
        const double pbar = F / A;
        if (pbar >= completeAt_[k]) {
            continue; // complete contact, A_i = A_{i-1} (assumption 5)
        }
        const double r = asperity_->areaRatio(pbar, levels_[k]);
        if (r < 1.0) { // assumption 5
            A *= r;
        }
    }
    return A / An_;
}

double MultiscaleModel::unloadingAreaFraction(double load, double peakLoad) const
{
    checkLoad(peakLoad);
    if (checkLoad(load) == 0.0) {
        return 0.0;
    }
    if (!(load < peakLoad) || !asperity_->yields()) {
        return areaFraction(load); // at or above the peak, or elastic: the loading curve
    }
    const double F = load * An_ * Eprime_;
    const double Fmax = peakLoad * An_ * Eprime_;
    double A = An_;    // the unloading state's A_{i-1}
    double Amax = An_; // the peak's
    for (std::size_t k = 0; k < levels_.size(); ++k) {
        const double pbarMax = Fmax / Amax;
        const double pbar = F / A;
        // The level's area at the peak as its law gives it, beyond complete contact too (the
        // Hertzian radius of an elastic level that reached it is its own).
        const Level& level = levels_[k];
        const double rMax = asperity_->areaRatio(pbarMax, level);
        // Fbar/Fbar_max = (F/N_i)/(Fmax/N_i,max) = pbar/pbarMax (eta_i cancels).
        // The loading law at pbar: what the level has when loaded there (beyond its peak's force,
        // loading on); below it the Hertzian unloading, never less (the flattened summits keep at
        // least the contact the virgin ones would have).
        const double loading = pbar >= completeAt_[k] ? 1.0 : asperity_->areaRatio(pbar, level);
        const double r = pbar < pbarMax ? std::max(rMax * std::pow(pbar / pbarMax, 2.0 / 3.0), loading) : loading;
        if (rMax < 1.0) { // assumption 5, at the peak and now
            Amax *= rMax;
        }
        if (r < 1.0) {
            A *= r;
        }
    }
    return A / An_;
}

std::vector<LevelState> MultiscaleModel::trace(double load) const
{
    checkLoad(load);
    std::vector<LevelState> out;
    out.reserve(levels_.size());
    const double F = load * An_ * Eprime_;
    double A = An_;
    for (std::size_t k = 0; k < levels_.size(); ++k) {
        const Level& level = levels_[k];
        LevelState s;
        s.index = index_[k];
        s.frequency = level.frequency;
        s.amplitude = level.amplitude;
        s.density = level.density;
        s.radius = level.radius;
        s.asperities = level.density * A;
        s.asperityForce = F > 0.0 ? F / s.asperities : 0.0; // no load: no area, no asperity (not 0/0)
        if (F > 0.0) {
            const double pbar = F / A;
            const double r = pbar >= completeAt_[k] ? 1.0 : asperity_->areaRatio(pbar, level);
            s.complete = !(r < 1.0);
            if (!s.complete) {
                A *= r;
            }
        } else {
            A = 0.0;
        }
        s.area = A;
        out.push_back(s);
    }
    return out;
}

} // namespace roughContact
