// SPDX-License-Identifier: GPL-3.0-or-later
// The Cooper-Mikic-Yovanovich (CMY) correlation for the thermal contact conductance of
// nominally flat rough surfaces whose asperities deform plastically. The model is that of
// Cooper, Mikic & Yovanovich, "Thermal contact conductance", Int. J. Heat Mass Transfer 12
// (1969) 279-300 (Gaussian heights, plastic spots of flow pressure H_c, flux tubes); the
// power-law fit of it used here is Yovanovich's: M. M. Yovanovich, "New contact and gap
// conductance correlations for conforming rough surfaces", AIAA Paper 81-1164 (1981), as
// quoted in Yovanovich, J. Thermophys. Heat Transfer 19 (2005) 379-386 (docs/correlations.md):
//
//   h_c = 1.25 k_s (m/sigma) (P/H_c)^0.95,
//
// k_s = 2 k1 k2/(k1 + k2), sigma and m the combined rms height and mean absolute slope
// (Roughness.hpp: combined()), P the apparent pressure and H_c the microhardness of the softer
// solid, given, or from its Vickers coefficients (Microhardness.hpp, Song & Yovanovich 1988).
// The fit covers a limited range of P/H_c (small values: light loads); docs/correlations.md.
#pragma once

#include "roughContact/surface/Roughness.hpp"
#include "roughContact/thermal/Microhardness.hpp"

namespace roughContact {

/// h_c / k_s [1/m] of the CMY plastic correlation from the relative pressure P/H_c (finite,
/// >= 0; 0 gives 0) and the combined roughness r. ParameterError naming the entry otherwise.
double cooperMikicYovanovichFromRelativePressure(double relativePressure, const SurfaceRoughness& r);

/// h_c / k_s [1/m] at the pressure P [Pa] (finite, >= 0) with the microhardness H_c [Pa]
/// (finite, > 0) given.
double cooperMikicYovanovichConductancePerConductivity(double P, const SurfaceRoughness& r, double Hc);

/// h_c / k_s [1/m] at the pressure P [Pa] with P/H_c from the Vickers coefficients of the
/// softer solid (relativeContactPressure, Song & Yovanovich 1988).
double cooperMikicYovanovichConductancePerConductivity(double P, const SurfaceRoughness& r,
                                                       const VickersCoefficients& vickers);

} // namespace roughContact
