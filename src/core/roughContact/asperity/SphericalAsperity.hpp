// SPDX-License-Identifier: GPL-3.0-or-later
// A hemispherical asperity of radius R against a rigid flat, followed along its loading path.
#pragma once

#include "roughContact/asperity/AsperityModel.hpp"

namespace roughContact {

/// Base of the asperity models that are laws of interference w (Hertz, Jackson-Green,
/// truncation). The same object serves the multi-scale framework (load given) and the
/// Greenwood-Williamson integrals (interference given).
class SphericalAsperity : public AsperityModel {
public:
    /// Contact area [m^2] at interference w [m] (w >= 0).
    virtual double area(double w, double R) const = 0;
    /// Contact force [N] at interference w [m] (w >= 0).
    virtual double force(double w, double R) const = 0;
    /// Contact area at force F [N] on the loading path: A(w) at w = inf{w : force(w) >= F},
    /// so a jump of force(w) holds w (and the area) while the load crosses it.
    /// +inf when the asperity is in complete contact at that force.
    virtual double areaAtForce(double F, double R) const = 0;
    /// A force [N] from which on the loading path has reached the area A [m^2]:
    /// areaAtForce(F', R) >= A for every F' >= this force (when the law reaches A only at
    /// complete contact of the asperity, the force beyond which areaAtForce is +inf). An upper
    /// bound of the least such force is allowed; +inf (the default) means unknown. It only lets
    /// callers skip areaAtForce where its answer is known to be >= A (the multi-scale
    /// framework's complete-contact test, assumption 5), so it never changes a result.
    virtual double forceBeyondArea(double A, double R) const;

    /// eta_i * Abar_i with the asperity force Fbar_i = F / N_i = pbar / eta_i (seed Eq. 2).
    double areaRatio(double pbar, const Level& level) const final;
    /// A mean pressure from which on areaRatio(pbar, level) >= 1 (the level is in complete
    /// contact): eta_i * forceBeyondArea(1/eta_i, R_i); +inf when unknown.
    double completeContactPressure(const Level& level) const override;
};

} // namespace roughContact
