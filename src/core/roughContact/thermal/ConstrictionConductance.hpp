// SPDX-License-Identifier: GPL-3.0-or-later
// Thermal contact conductance of a multi-scale contact: the constriction resistances of the
// frequency levels in series (docs/theory.md §5.2; the level-by-level form is derived there, the
// exact choice of Jackson, Bhavnani & Ferguson, J. Heat Transfer 130 (2008) 081301, is
// unverified).
#pragma once

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/models/MultiscaleModel.hpp"

#include <vector>

namespace roughContact {

/// Cooper-Mikic-Yovanovich constriction alleviation factor psi(eps) = (1 - eps)^1.5 of a
/// circular spot of radius a in a flux tube of radius b, eps = a/b in [0, 1].
double constrictionFactor(double eps);

/// h_c / k_s [1/m] of the contact whose per-level state is `trace` (MultiscaleModel::trace),
/// over the nominal area An [m^2]:
///   at level i, N_i spots of radius a_i = sqrt(A_i / (pi N_i)) in flux tubes of radius
///   b_i = 1/sqrt(pi eta_i), so eps_i = a_i / b_i = sqrt(A_i / A_{i-1});
///   R_i = psi(eps_i) / (2 k_s a_i N_i); R = sum_i R_i; h_c = 1 / (R A_n),
/// with k_s = 2 k1 k2 / (k1 + k2) (harmonicMeanConductivity). A level in complete contact
/// (eps_i = 1) adds nothing; one spot in an infinite body is Holm's R = (1/(4a))(1/k1 + 1/k2).
/// Returns 0 with no contact (empty trace or zero area) and +infinity when every level is in
/// complete contact (A_r = A_n: the solids are joined, no constriction is left).
double constrictionConductancePerConductivity(const std::vector<LevelState>& trace, double An);

/// h_c / k_s [1/m] of a multi-scale model at the load F/(A_n E').
double constrictionConductancePerConductivity(const MultiscaleModel& model, double load);

/// k_s = 2 k1 k2 / (k1 + k2) [W/(m K)]; both conductivities within limits::minimumConductivity..
/// maximumConductivity (ParameterError naming "conductivity k1"/"k2" otherwise), where 2 k1 k2
/// cannot overflow. Inline: called per face and per
/// evaluation (the checks cost two comparisons each and build no string unless they fail).
inline double harmonicMeanConductivity(double k1, double k2)
{
    limits::requireInRange("conductivity k1", k1, limits::minimumConductivity, limits::maximumConductivity,
                           "W/(m K)");
    limits::requireInRange("conductivity k2", k2, limits::minimumConductivity, limits::maximumConductivity,
                           "W/(m K)");
    return 2.0 * k1 * k2 / (k1 + k2);
}

} // namespace roughContact
