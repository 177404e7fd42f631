// SPDX-License-Identifier: GPL-3.0-or-later
// An elasto-plastic conductance law fitted to the exact (boundary-element) conductance in
// dimensionless form (issue 20, item 2; docs/theory.md, "The fitted elasto-plastic law";
// docs/validation/fittedElastoPlastic.md for the data and the fit). Made dimensionless as
// h sigma/(k_s m), the exact conductance of isotropic Gaussian surfaces is, within about
// +-20 %, one function of x = P/(E' h') and c = H/(E' h') on every synthesized surface measured
// (Hurst 0.3 to 0.8, with and without a roll-off, 40 to 64 levels) wherever the period holds a
// few contact spots; this law is that function:
//
//   h_el = C_E (m/sigma) (sqrt(2) P/(E' m))^A / (1 - B x)       Mikic's elastic form (Mikic.hpp)
//                                                                with its constants refitted and
//                                                                a pole for complete contact;
//   h_pl = C_P (m/sigma) g(a) (1 - a)^-K,   a = P/H,            the Cooper-Mikic-Yovanovich
//   g(a) = exp(-lambda^2/2) / (2 sqrt(2 pi) (1 - sqrt a)^1.5),   geometry of Gaussian plastic
//   erfc(lambda/sqrt 2)/2 = a                                    spots at their area a = P/H
//                                                                (CMY 1969; 1.25 a^0.95 is
//                                                                Yovanovich's fit of g);
//   h_c/k_s = (h_el^N + h_pl^N)^(1/N)                            a smooth maximum (a cap only
//                                                                adds area); no cap: h_el.
//
// m is the mean absolute profile slope (h'/sqrt(pi) for an isotropic surface with Gaussian
// slopes, h' the areal rms gradient), sigma the rms height, both of the band of wavelengths
// the conductance is meant to resolve; E' the reduced modulus, H the plastic cap (the
// hardness, 2.84 S_y of the yielding material by default). Constants: fittedElastoPlastic below,
// a minimax fit of |ln(law/exact)| on 118 points (four synthesized surfaces, elastic and capped at
// c = 0.03, 0.1, 0.3, x = 1e-4 to 1e-1, A_r/A_n <= 0.9, at least 3 contact spots in the solved
// period), never on the X3P map (the hold-out). Measured: 0.75-1.32 of exact on the training
// points, 0.61-0.97 (elastic) and 0.88-1.82 (capped) on the X3P map, 0.75-1.17 on a second
// hold-out surface (Hurst 0.6, roll-off at L/2, h' = 0.2). Not for x above 0.1: the pole is at
// x = 1/B = 0.159 (the law gives +inf there, complete contact).
#pragma once

#include "roughContact/surface/Roughness.hpp"

#include <optional>

namespace roughContact {

/// The fitted constants (docs/validation/fittedElastoPlastic.md).
struct FittedElastoPlasticConstants {
    double elasticPrefactor = 0.5199; ///< C_E
    double elasticExponent = 0.7920;  ///< A
    double plasticPrefactor = 0.5153; ///< C_P
    double plasticExponent = 0.1997;  ///< K
    double blend = 1.2605;            ///< N
    double pole = 6.2835;             ///< B
};

/// g(a) of the header: sigma h_c/(k_s m) of Gaussian plastic spots covering the area fraction a
/// (0 <= a < 1; 0 gives 0). ParameterError outside [0, 1).
double gaussianPlasticSpotConductance(double a);

/// h_c/k_s [1/m] of the law at the nominal pressure P [Pa] (finite, >= 0), for the combined
/// roughness r (sigma [m], m), the reduced modulus E' [Pa] and the cap H [Pa] (none: elastic);
/// +inf at and beyond x = 1/B or P = H. ParameterError naming the entry on bad input.
double fittedElastoPlasticConductancePerConductivity(double P, const SurfaceRoughness& r, double Eprime,
                                                     std::optional<double> H,
                                                     const FittedElastoPlasticConstants& c = {});

} // namespace roughContact
