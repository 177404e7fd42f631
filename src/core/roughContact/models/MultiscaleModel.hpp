// SPDX-License-Identifier: GPL-3.0-or-later
// The multi-scale framework of seed §2.1 (Eqs. 1-2, assumptions 1-5).
#pragma once

#include "roughContact/asperity/AsperityModel.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cstddef>
#include <memory>
#include <vector>

namespace roughContact {

/// The state of one frequency level at one load (the seed's Fig. 5).
struct LevelState {
    std::size_t index = 0;      ///< position in the spectrum (0-based)
    double frequency = 0.0;     ///< f_i [1/m]
    double amplitude = 0.0;     ///< beta_i [m]
    double density = 0.0;       ///< eta_i [1/m^2]
    double radius = 0.0;        ///< R_i [m]
    double asperities = 0.0;    ///< N_i = eta_i A_{i-1}
    double asperityForce = 0.0; ///< Fbar_i = F / N_i [N]
    double area = 0.0;          ///< A_i [m^2]
    bool complete = false;      ///< assumption 5 held the area: A_i = A_{i-1}
};

/// Built once from a surface, the materials (inside the asperity model) and an asperity law;
/// then asked for A_r/A_n at many loads, each a single pass over the levels:
///   A_0 = A_n; N_i = eta_i A_{i-1}; Fbar_i = F / N_i; A_i = min(A_{i-1}, N_i Abar_i);
///   A_r = A_imax. Levels with zero amplitude carry nothing and are skipped.
class MultiscaleModel final : public ContactModel {
public:
    MultiscaleModel(const Spectrum& spectrum, double Eprime, std::shared_ptr<const AsperityModel> asperity);

    std::string name() const override { return asperity_->name(); }
    double areaFraction(double load) const override;
    /// A_r/A_n at `load` of a contact that has carried peakLoad (both F/(A_n E'); at and above
    /// the peak: areaFraction(load)). Level by level, each level's asperities unload elastically
    /// from the state the peak left them in, as a Hertzian contact of the radius that gives their
    /// peak area at their peak force (the continuous-radius unloading of a flattened sphere;
    /// docs/theory.md §3.6):
    ///   Abar_i = max(Abar_i(Fbar_i,max) (Fbar_i/Fbar_i,max)^(2/3), Abar_i(Fbar_i))   for Fbar_i < Fbar_i,max,
    /// their loading law above it; Fbar_i = F/N_i with N_i = eta_i A_{i-1} of the unloading
    /// state, Fbar_i,max of the peak's; assumption 5 as on loading. An elastic asperity law
    /// (AsperityModel::yields false: hertz, jgh, jghConsistent) unloads along its loading curve.
    double unloadingAreaFraction(double load, double peakLoad) const;
    /// Every level's state at the load (levels with zero amplitude omitted).
    std::vector<LevelState> trace(double load) const;

    const AsperityModel& asperityModel() const noexcept { return *asperity_; }
    double nominalArea() const noexcept { return An_; }
    double reducedModulus() const noexcept { return Eprime_; }
    const std::vector<Level>& levels() const noexcept { return levels_; }

private:
    std::vector<Level> levels_;
    std::vector<std::size_t> index_;
    /// Per level, a mean pressure F/A_{i-1} from which on the level is known to be in complete
    /// contact (areaRatio >= 1, checked once here), so its areaRatio need not be evaluated;
    /// +inf when the asperity law gives none. The result is the same either way: most levels
    /// of a measured surface are in complete contact (~99 % on the stand-in profile), and this
    /// skips their Jackson-Green inversions.
    std::vector<double> completeAt_;
    double An_;
    double Eprime_;
    std::shared_ptr<const AsperityModel> asperity_;
};

} // namespace roughContact
