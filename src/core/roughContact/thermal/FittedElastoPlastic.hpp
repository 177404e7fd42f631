// SPDX-License-Identifier: GPL-3.0-or-later
// fittedElastoPlastic, the default conductance law: Mikic's elastic form and the Cooper-Mikic-
// Yovanovich plastic form with their constants fitted to the exact (boundary-element)
// conductance, blended by a smooth maximum (docs/theory.md §5.7a; skewed heights §5.7b; how it
// is fitted and how close it comes: docs/validation/fittedElastoPlastic.md):
//
//   h_el = C_E (m/sigma) (sqrt(2) P/(E' m))^A exp(G(x)) l(s1, x) f(s, x)
//   G(x) = beta min(x, x_g) + beta_2(W) max(0, x - x_g),   beta_2(W) = B_0 + B_W (W - W_0)
//   h_pl = C_P W (m/sigma) g(P/H) (1 - P/H)^-K
//   h_c/k_s = (h_el^N + h_pl^N)^(1/N) with a cap H (f then enters as f^w, w = h_el^N/(h_el^N +
//   h_pl^N)), h_el without one
//
// and, below the heaviest pressure P_max a joint has carried, its unloading branch (§5.7c):
// min(h_c/k_s(P) R(P/P_max), h_c/k_s(P_max)) with
//   ln R = (l_0 Phi(gamma) max(0, W - W_c) + l_1 c (1 + u (H_f - H_0)))(1 - s^q) + e ln(1/s),
//   e = Phi(gamma) max(t max(0, H_f - H_0), min(e_1, v max(0, ln(A_c H/P_max)))),
// s = P/P_max, c = -ln(1 - P_max/H), Phi(gamma) = 1/(1 + (gamma/gamma_M)^2), gamma = H/(E' m
// sqrt(pi/2)) Mikic's plasticity index, H_f the Hurst exponent of the spectrum's finest octave
// (fineHurstExponent) and e_1 = 1/6 an isolated plastic summit's (R = 1 without a cap: an
// elastic joint retraces its loading curve)
//
// with x = P/(sqrt(pi) E' m) (= P/(E' h') for Gaussian slopes), sigma and m the rms height and
// mean absolute slope, W the bandwidth ratio and s1 the first level's share of the line-scan
// spectrum, s the heights' shrunk skewness, E' the reduced modulus, H the cap (2.84 S_y of the
// yielding material by default), g the geometry of Gaussian plastic spots, l the light-load
// factor below x_r and f the skewness factor. The constants and the ranges they hold their
// inputs to: FittedElastoPlasticConstants.inc, written by `python3 -m validation run
// fittedElastoPlastic`.
#pragma once

#include "roughContact/surface/Roughness.hpp"

#include <optional>

namespace roughContact {

/// The law's constants (FittedElastoPlasticConstants.inc: each with what it is).
struct FittedElastoPlasticConstants {
#define ROUGHCONTACT_FITTED_CONSTANT(name, value, what) double name = value;
#include "roughContact/thermal/FittedElastoPlasticConstants.inc"
#undef ROUGHCONTACT_FITTED_CONSTANT
};

/// s1 as l(s1, x) takes it: held within [lightLoadShareLeast, lightLoadShareMost], the training
/// spectra's range (no check; the law and fittedLightLoadFactor check s1 first).
double fittedLightLoadShare(double firstLevelShare, const FittedElastoPlasticConstants& c = {});

/// l(s1, x) of the header: the elastic branch's factor at light loads for a spectrum whose first
/// level carries the share s1 of the heights' variance (0 <= s1 <= 1; held within [0.11, 0.86])
/// at x = P/(E' h') (finite, > 0). 1 at and above x = 0.01 and at s1 = 0.3.
double fittedLightLoadFactor(double firstLevelShare, double x, const FittedElastoPlasticConstants& c = {});

/// f(s, x) of the header: the elastic branch's factor for heights of skewness s (finite; the
/// shrunk skewness; held within [-0.6, 0.6], the skewness the fit saw) at x = P/(E' h')
/// (finite, > 0; held within [1e-3, 0.1]). 1 at s = 0; above 1 for s < 0 (the heights
/// reach up in broad plateaus and down in narrow pits: more of the surface is near its top).
double fittedSkewnessFactor(double skewness, double x, const FittedElastoPlasticConstants& c = {});

/// beta_2(W) of the header: the elastic growth's rate beyond x_g for the bandwidth ratio W
/// (0 < W <= 1; held within [0.45, 0.80]).
double fittedHeavyLoadGrowth(double bandwidth, const FittedElastoPlasticConstants& c = {});

/// g(a) of the header: sigma h_c/(k_s m) of Gaussian plastic spots covering the area fraction a
/// (0 <= a < 1; 0 gives 0). ParameterError outside [0, 1).
double gaussianPlasticSpotConductance(double a);

/// Phi(gamma) of the header: the share of the unloading branch's light-peak ratio a pair of
/// plasticity index gamma = H/(E' m sqrt(pi/2)) (finite, >= 0) keeps; 1 at 0, 1/2 at gamma_M.
double fittedUnloadingPlasticShare(double plasticityIndex, const FittedElastoPlasticConstants& c = {});

/// H_f as the unloading branch takes it: held within [unloadingHurstLeast, unloadingHurstMost]
/// (0.3 and 1, the training spectra's; no check).
double fittedUnloadingHurst(double fineHurst, const FittedElastoPlasticConstants& c = {});

/// W as the unloading branch takes it: held at unloadingBandwidthMost (0.72, the training
/// spectra's largest) above it (no check).
double fittedUnloadingBandwidth(double bandwidth, const FittedElastoPlasticConstants& c = {});

/// R of the header: the unloading branch's factor on the law's loading h_c/k_s at the nominal
/// pressure P [Pa] (finite, >= 0) of a joint that has carried the pressure peak [Pa] (finite,
/// >= 0), for the combined surfaces' mean absolute slope m (within the project's slope range, as
/// the law's roughness), the spectrum's bandwidth ratio W (0 < W <= 1, as the law's; held at
/// 0.72 above it), the reduced modulus E' [Pa], the cap H [Pa] and the Hurst exponent H_f of
/// the combined spectrum's finest octave (finite; fineHurstExponent; none: H_0, where neither of
/// its terms acts). 1 at P >= peak (loading) and without a cap; P_max/H held at
/// unloadingPeakHeaviest (0.77) above it in c (not in the light-peak term), H_f within
/// [unloadingHurstLeast, unloadingHurstMost] (0.3 and 1, the training spectra's) and s at
/// unloadingDeepest (1/30) in the deep-unloading term. ParameterError naming the entry on bad
/// input.
double fittedUnloadingFactor(double P, double peak, double meanAbsoluteSlope, double bandwidth, double Eprime,
                             std::optional<double> H, std::optional<double> fineHurst = std::nullopt,
                             const FittedElastoPlasticConstants& c = {});

/// The law's h_c/k_s [1/m] at the nominal pressure P [Pa], loading and on the unloading branch
/// of the header of a joint that has carried the pressure peak [Pa]: the loading value times R,
/// at most the law's at the peak (an unloaded joint conducts no more than it did there); the
/// loading value at P >= peak and without a cap. Inputs as the law's and fittedUnloadingFactor's.
struct FittedUnloading {
    double loading;
    double unloading;
};
FittedUnloading fittedElastoPlasticUnloading(double P, double peak, const SurfaceRoughness& r, double bandwidth,
                                             double Eprime, std::optional<double> H, double skewness = 0.0,
                                             std::optional<double> firstLevelShare = std::nullopt,
                                             std::optional<double> fineHurst = std::nullopt,
                                             const FittedElastoPlasticConstants& c = {});

/// fittedElastoPlasticUnloading(...).unloading.
double fittedElastoPlasticUnloadingConductancePerConductivity(double P, double peak, const SurfaceRoughness& r,
                                                              double bandwidth, double Eprime, std::optional<double> H,
                                                              double skewness = 0.0,
                                                              std::optional<double> firstLevelShare = std::nullopt,
                                                              std::optional<double> fineHurst = std::nullopt,
                                                              const FittedElastoPlasticConstants& c = {});

/// h_c/k_s [1/m] of the law at the nominal pressure P [Pa] (finite, >= 0), for the combined
/// roughness r (sigma [m], m), the bandwidth ratio W of the combined line-scan spectrum (0 < W <= 1,
/// spectralBandwidthRatio), the reduced modulus E' [Pa] and the cap H [Pa] (none: elastic; W then
/// only sets beta_2 beyond x_g), the heights' shrunk skewness s (finite; 0: Gaussian heights; held at +-0.6),
/// and the first level's share s1 of the combined line-scan spectrum (0 <= s1 <= 1,
/// firstLevelShare; none: no light-load factor, l = 1);
/// W also sets the elastic growth's rate beyond x_g = 0.1 (beta_2(W); below x_g W is the plastic
/// branch's alone).
/// +inf at and beyond P = H, and where the elastic branch raised to N passes e^700 (x of about
/// 540/beta_2).
/// ParameterError naming the entry on bad input.
double fittedElastoPlasticConductancePerConductivity(double P, const SurfaceRoughness& r, double bandwidth,
                                                     double Eprime, std::optional<double> H, double skewness = 0.0,
                                                     std::optional<double> firstLevelShare = std::nullopt,
                                                     const FittedElastoPlasticConstants& c = {});

} // namespace roughContact
