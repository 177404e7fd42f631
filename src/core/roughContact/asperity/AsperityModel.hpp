// SPDX-License-Identifier: GPL-3.0-or-later
// The contact law of one frequency level of the multi-scale framework (seed §2.2).
#pragma once

#include <limits>
#include <string>

namespace roughContact {

/// One frequency level as the asperity models see it (seed Eqs. 4-5).
struct Level {
    double frequency = 0.0; ///< f_i [1/m]
    double amplitude = 0.0; ///< beta_i [m]
    double density = 0.0;   ///< eta_i = 2 f_i^2 [1/m^2]
    double radius = 0.0;    ///< R_i = 1/(4 pi^2 beta_i f_i^2) [m]

    static Level of(double frequency, double amplitude);
};

/// An asperity contact law used inside the multi-scale framework.
class AsperityModel {
public:
    virtual ~AsperityModel() = default;

    /// The name users select it by (`hertz`, `jgh`, `jacksonGreen`, `truncation`, ...).
    virtual std::string name() const = 0;

    /// A_i / A_{i-1} of one level before assumption 5 caps it at 1, when the load F is spread
    /// over the level's nominal area A_{i-1} at mean pressure pbar = F / A_{i-1} [Pa].
    /// For asperity models N_i = eta_i A_{i-1}, so this is eta_i * Abar_i(F / N_i).
    /// Values >= 1 mean the level is in complete contact; the result may be +inf.
    virtual double areaRatio(double pbar, const Level& level) const = 0;

    /// A mean pressure from which on areaRatio(pbar, level) >= 1, i.e. the level is in
    /// complete contact (assumption 5 then keeps A_i = A_{i-1}). An upper bound of the least
    /// such pressure is allowed; +inf (the default) means unknown. MultiscaleModel uses it
    /// only to skip areaRatio where its answer is known, so it never changes a result.
    virtual double completeContactPressure(const Level&) const
    {
        return std::numeric_limits<double>::infinity();
    }
    /// True when its asperities can yield (a plastic law past some force); false for an elastic
    /// law, whose contact unloads along its loading curve (MultiscaleModel::unloadingAreaFraction).
    virtual bool yields() const { return true; }
};

} // namespace roughContact
