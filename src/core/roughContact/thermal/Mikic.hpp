// SPDX-License-Identifier: GPL-3.0-or-later
// Mikic's correlation for the thermal contact conductance of nominally flat rough surfaces whose
// asperities deform elastically: B. B. Mikic, "Thermal contact conductance; theoretical
// considerations", Int. J. Heat Mass Transfer 17 (1974) 205-214, elastic case, in the form
// Yovanovich's reviews quote it (docs/correlations.md):
//
//   h_c = 1.54 k_s (m/sigma) (sqrt(2) P / (E' m))^0.94,
//
// k_s = 2 k1 k2/(k1 + k2) (harmonicMeanConductivity), sigma and m the joint's combined rms
// height and mean absolute slope (Roughness.hpp: combined()), P the apparent contact pressure
// and E' the reduced modulus 1/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2, the convention of this project
// (Materials.hpp). The 1.54 and 0.94 are a power-law fit of Mikic's Gaussian-surface result
// over a limited range of sqrt(2) P/(E' m) (light loads; docs/correlations.md); outside it the
// law is an extrapolation. What of the form could be checked against a second source is
// in docs/correlations.md.
#pragma once

#include "roughContact/surface/Roughness.hpp"

namespace roughContact {

/// h_c / k_s [1/m] of Mikic's elastic correlation at the apparent pressure P [Pa] (finite,
/// >= 0; P = 0 gives 0), for the combined roughness r and the reduced modulus E' [Pa] (within
/// limits::minimumReducedModulus..maximumReducedModulus). ParameterError naming the entry
/// ("contact pressure P", "rms roughness sigma", "mean absolute slope m", "reduced modulus E'")
/// otherwise.
double mikicConductancePerConductivity(double P, const SurfaceRoughness& r, double Eprime);

} // namespace roughContact
