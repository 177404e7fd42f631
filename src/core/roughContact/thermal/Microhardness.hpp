// SPDX-License-Identifier: GPL-3.0-or-later
// The microhardness H_c of a rough surface's plastically deformed asperities, from the
// Vickers microhardness correlation of its material: the correlation of Song & Yovanovich,
// "Relative contact pressure: dependence on surface roughness and Vickers microhardness",
// J. Thermophys. Heat Transfer 2 (1988) 43-47 (docs/correlations.md).
//
// A Vickers test gives H_v = c1 (d_v/d_0)^c2, d_v the indentation diagonal, d_0 = 1 um; c1 [Pa]
// and c2 [-] are fitted per material. Song & Yovanovich equate the asperity contacts to an
// indentation and obtain the relative contact pressure explicitly:
//
//   P/H_c = [ P / (c1 (1.62 sigma'/m)^c2) ]^(1/(1 + 0.071 c2)),   sigma' = sigma / sigma_0,
//   sigma_0 = 1 um,
//
// with sigma and m the combined rms height and mean absolute slope. Hence H_c = P/(P/H_c)
// = H_0^(1/(1+0.071 c2)) P^(0.071 c2/(1+0.071 c2)), H_0 = c1 (1.62 sigma'/m)^c2: H_c = H_0 where
// P = H_0, and it varies weakly (as a small negative power for c2 < 0) with P.
// The constants 1.62 and 0.071 are as the project's sources state them; a second source for
// them could not be reached (docs/correlations.md).
#pragma once

#include "roughContact/surface/Roughness.hpp"

namespace roughContact {

/// Vickers microhardness coefficients: H_v = c1 (d_v / 1 um)^c2.
struct VickersCoefficients {
    double c1; ///< [Pa], finite and > 0
    double c2; ///< [-], in [minimumC2, maximumC2]
};

/// Accepted c2. The published metal fits we know of have c2 < 0, of order -0.1 to -0.4 (the
/// hardness falls as the indentation grows; recalled from Song & Yovanovich's tables, not
/// re-checked here); [-1, 0] keeps 1 + 0.071 c2 >= 0.929 and refuses a positive c2.
constexpr double minimumC2 = -1.0;
constexpr double maximumC2 = 0.0;

/// ParameterError naming "Vickers coefficient c1" or "Vickers coefficient c2" when out of range.
void checkVickersCoefficients(const VickersCoefficients& v);

/// H_0 = c1 (1.62 sigma'/m)^c2 [Pa], sigma' = sigma/1 um: the microhardness at which P = H_c.
double referenceMicrohardness(const SurfaceRoughness& r, const VickersCoefficients& v);

/// P/H_c of Song & Yovanovich at the apparent pressure P [Pa] (finite, >= 0; 0 gives 0).
/// ParameterError naming the entry otherwise.
double relativeContactPressure(double P, const SurfaceRoughness& r, const VickersCoefficients& v);

/// H_c [Pa] at the pressure P [Pa], finite and > 0 (at P = 0 the correlation gives no H_c:
/// it grows without bound as P -> 0 for c2 < 0). ParameterError naming the entry otherwise.
double microhardness(double P, const SurfaceRoughness& r, const VickersCoefficients& v);

} // namespace roughContact
