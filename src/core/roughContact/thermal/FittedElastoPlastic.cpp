// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/FittedElastoPlastic.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace roughContact {

double gaussianPlasticSpotConductance(double a)
{
    requireFinite("plastic area fraction P/H", a);
    if (a < 0.0 || a >= 1.0) {
        throw ParameterError("plastic area fraction P/H", "must lie within [0, 1), got " + std::to_string(a));
    }
    if (a == 0.0) {
        return 0.0;
    }
    // erfc(lambda/sqrt 2)/2 = a: the level lambda sigma above which a Gaussian surface covers a.
    const double lambda = std::sqrt(2.0) * boost::math::erfc_inv(2.0 * a);
    return std::exp(-0.5 * lambda * lambda) / (2.0 * std::sqrt(2.0 * pi) * std::pow(1.0 - std::sqrt(a), 1.5));
}

namespace {

void checkBandwidth(double bandwidth)
{
    requireFinite("spectral bandwidth ratio W", bandwidth);
    if (!(bandwidth > 0.0 && bandwidth <= 1.0)) {
        throw ParameterError("spectral bandwidth ratio W", "must lie within (0, 1] (m1/sqrt(m0 m2) of a spectrum), got " +
                                                             std::to_string(bandwidth));
    }
}

/// beta_2(W) of a checked W.
double heavyLoadRate(double bandwidth, const FittedElastoPlasticConstants& c)
{
    const double w = std::min(std::max(bandwidth, c.heavyLoadBandwidthLeast), c.heavyLoadBandwidthMost);
    return c.heavyLoadGrowth + c.heavyLoadGrowthSlope * (w - c.heavyLoadBandwidthPivot);
}

void checkSkewness(double skewness)
{
    // Any finite skewness: a plateau-honed surface has -2 to -3; beyond the fitted range f is held.
    requireFinite("heights' skewness", skewness);
}

// ln f(s, x), unchecked: x may have under- or overflowed to 0 or +inf; s and x are held within
// the ranges the skewed surfaces were solved over.
double logSkewnessFactor(double skewness, double x, const FittedElastoPlasticConstants& c)
{
    const double xc = std::min(std::max(x, c.skewnessLightestLoad), c.skewnessHeaviestLoad);
    const double s = std::min(std::max(skewness, -c.skewnessLargest), c.skewnessLargest);
    return s * (c.skewnessSlope + c.skewnessSlopeLog * std::log(xc)) + c.skewnessCurvature * s * s;
}

void checkFirstLevelShare(double share)
{
    requireFinite("first level's share s1", share);
    // 0 is a spectrum whose first level has no amplitude (a valid spectrum): held at the least.
    if (!(share >= 0.0 && share <= 1.0)) {
        throw ParameterError("first level's share s1", "must lie within [0, 1] (the first level's share of a "
                                                       "spectrum's height variance), got " + std::to_string(share));
    }
}

// ln l(s1, x) from ln x (finite: x itself may underflow to 0 for a denormal P, and 0 times
// ln 0 at s1 = s1_0 would be a NaN).
double logLightLoadFactor(double share, double logX, const FittedElastoPlasticConstants& c)
{
    const double below = logX - std::log(c.lightLoadEnd);
    if (!(below < 0.0)) {
        return 0.0;
    }
    return c.lightLoadShareSlope * (fittedLightLoadShare(share, c) - c.lightLoadSharePivot) * below;
}

} // namespace

double fittedLightLoadShare(double firstLevelShare, const FittedElastoPlasticConstants& c)
{
    return std::min(std::max(firstLevelShare, c.lightLoadShareLeast), c.lightLoadShareMost);
}

double fittedLightLoadFactor(double firstLevelShare, double x, const FittedElastoPlasticConstants& c)
{
    checkFirstLevelShare(firstLevelShare);
    requireFinite("x = P/(E' h')", x);
    if (!(x > 0.0)) {
        throw ParameterError("x = P/(E' h')", "must be > 0, got " + std::to_string(x));
    }
    return std::exp(logLightLoadFactor(firstLevelShare, std::log(x), c));
}

double fittedSkewnessFactor(double skewness, double x, const FittedElastoPlasticConstants& c)
{
    checkSkewness(skewness);
    requireFinite("x = P/(E' h')", x);
    if (!(x > 0.0)) {
        throw ParameterError("x = P/(E' h')", "must be > 0, got " + std::to_string(x));
    }
    return std::exp(logSkewnessFactor(skewness, x, c));
}

double fittedHeavyLoadGrowth(double bandwidth, const FittedElastoPlasticConstants& c)
{
    checkBandwidth(bandwidth);
    return heavyLoadRate(bandwidth, c);
}

double fittedElastoPlasticConductancePerConductivity(double P, const SurfaceRoughness& r, double bandwidth,
                                                     double Eprime, std::optional<double> H, double skewness,
                                                     std::optional<double> firstLevelShare,
                                                     const FittedElastoPlasticConstants& c)
{
    requireFinite("contact pressure P", P);
    if (P < 0.0) {
        throw ParameterError("contact pressure P", "must be >= 0, got " + std::to_string(P));
    }
    checkRoughness(r);
    checkBandwidth(bandwidth);
    limits::requireInRange("reduced modulus E'", Eprime, limits::minimumReducedModulus, limits::maximumReducedModulus,
                           "Pa");
    if (H) {
        limits::requireInRange("hardness H", *H, limits::minimumHardness, limits::maximumHardness, "Pa");
    }
    checkSkewness(skewness);
    if (firstLevelShare) {
        checkFirstLevelShare(*firstLevelShare);
    }
    if (P == 0.0) {
        return 0.0;
    }
    const double inf = std::numeric_limits<double>::infinity();
    const double m = r.meanAbsoluteSlope;
    if (H && P >= *H) {
        return inf;
    }
    // x = P/(E' h'), h' = sqrt(pi) m for Gaussian isotropic slopes. Beyond x = e^690 (a pressure
    // near the largest double) the elastic branch e^G(x) is complete contact: +inf, before x
    // itself could overflow.
    const double logX = std::log(P) - std::log(std::sqrt(pi) * Eprime * m);
    if (logX > 690.0) {
        return inf;
    }
    const double x = P / (std::sqrt(pi) * Eprime * m);
    // In logarithms: far beyond its range (x of hundreds) the elastic branch, or its power N,
    // exceeds a double; it is +inf there (complete contact) without an overflow on the way.
    // ln(sqrt(2) P/(E' m)) as a sum of logarithms: the quotient of a denormal P underflows to 0.
    const double logElastic = std::log(c.elasticPrefactor * (m / r.sigma)) +
                              c.elasticExponent * (0.5 * std::log(2.0) + std::log(P) - std::log(Eprime * m)) +
                              c.elasticGrowth * std::min(x, c.heavyLoadStart) +
                              heavyLoadRate(bandwidth, c) * std::max(0.0, x - c.heavyLoadStart) +
                              (firstLevelShare ? logLightLoadFactor(*firstLevelShare, logX, c) : 0.0);
    // Gaussian heights: no factor (the law is then bit for bit the one without a skewness).
    const double logSkew = skewness == 0.0 ? 0.0 : logSkewnessFactor(skewness, x, c);
    const double logMax = 700.0 / std::max(1.0, c.blend);
    if (logElastic > logMax) {
        return inf;
    }
    if (!H) {
        return logElastic + logSkew > logMax ? inf : std::exp(logElastic + logSkew);
    }
    const double elastic = std::exp(logElastic);
    const double a = P / *H;
    // The plastic spots' spacing follows W m/sigma (= sqrt(2/pi) m1/m0 for a spectrum's own sigma
    // and m): a spectrum whose heights live at long wavelengths clusters its spots on them.
    const double plastic = c.plasticPrefactor * bandwidth * (m / r.sigma) * gaussianPlasticSpotConductance(a) *
                           std::pow(1.0 - a, -c.plasticExponent);
    if (!(plastic < std::exp(logMax))) {
        return inf;
    }
    // Skewed heights scale the elastic branch by f^w, w its share of the Gaussian blend: the caps
    // flatten the tops whose distribution f is about (fitted on nothing; chosen on the capped
    // skewed surfaces of docs/validation/skewness.md over f itself and f^(w^2)).
    const double elasticN = std::pow(elastic, c.blend);
    const double plasticN = std::pow(plastic, c.blend);
    const double sum = elasticN + plasticN; // 0 only where both underflow: h = 0
    const double share = sum > 0.0 ? elasticN / sum : 0.0;
    return std::pow(elasticN * std::exp(c.blend * share * logSkew) + plasticN, 1.0 / c.blend);
}

double fittedUnloadingPlasticShare(double plasticityIndex, const FittedElastoPlasticConstants& c)
{
    requireFinite("plasticity index gamma", plasticityIndex);
    if (plasticityIndex < 0.0) {
        throw ParameterError("plasticity index gamma", "must be >= 0, got " + std::to_string(plasticityIndex));
    }
    const double g = plasticityIndex / c.unloadingPlasticityMidpoint;
    if (g <= 1.0) {
        return 1.0 / (1.0 + g * g);
    }
    const double inverse = 1.0 / g; // no g^2 to overflow for a huge index
    return inverse * inverse / (1.0 + inverse * inverse);
}

double fittedUnloadingHurst(double fineHurst, const FittedElastoPlasticConstants& c)
{
    return std::min(std::max(fineHurst, c.unloadingHurstLeast), c.unloadingHurstMost);
}

double fittedUnloadingBandwidth(double bandwidth, const FittedElastoPlasticConstants& c)
{
    return std::min(bandwidth, c.unloadingBandwidthMost);
}

double fittedUnloadingFactor(double P, double peak, double meanAbsoluteSlope, double bandwidth, double Eprime,
                             std::optional<double> H, std::optional<double> fineHurst,
                             const FittedElastoPlasticConstants& c)
{
    requireFinite("contact pressure P", P);
    requireFinite("peak pressure P_max", peak);
    if (P < 0.0 || peak < 0.0) {
        throw ParameterError(P < 0.0 ? "contact pressure P" : "peak pressure P_max",
                             "must be >= 0, got " + std::to_string(P < 0.0 ? P : peak));
    }
    // The law's range for m (checkRoughness): gamma below it stays far from overflowing.
    limits::requireInRange("mean absolute slope m", meanAbsoluteSlope, limits::minimumSlope, limits::maximumSlope, "");
    checkBandwidth(bandwidth);
    limits::requireInRange("reduced modulus E'", Eprime, limits::minimumReducedModulus, limits::maximumReducedModulus,
                           "Pa");
    if (fineHurst) {
        requireFinite("fine-scale Hurst exponent H_f", *fineHurst);
    }
    if (!H) {
        return 1.0;
    }
    limits::requireInRange("hardness H", *H, limits::minimumHardness, limits::maximumHardness, "Pa");
    if (!(P < peak)) {
        return 1.0;
    }
    // gamma with Mikic's rms profile slope, m sqrt(pi/2) for Gaussian heights.
    const double gamma = *H / (Eprime * meanAbsoluteSlope * std::sqrt(0.5 * pi));
    const double flow = -std::log1p(-std::min(peak / *H, c.unloadingPeakHeaviest));
    // H_f held within the training spectra's; none: H_0, where neither of its terms acts.
    const double above = fineHurst ? fittedUnloadingHurst(*fineHurst, c) - c.unloadingHurstPivot : 0.0;
    const double plastic = fittedUnloadingPlasticShare(gamma, c);
    // A light peak's set grows with W above W_c: spots clustered on the long waves (low W)
    // recover together as one elastic contact, scattered ones (high W) each keep theirs.
    const double scattered = std::max(0.0, fittedUnloadingBandwidth(bandwidth, c) - c.unloadingBandwidthLeast);
    const double plateau = c.unloadingBase * plastic * scattered +
                           c.unloadingFlow * flow * (1.0 + c.unloadingFlowHurst * above);
    const double s = P / peak;
    // The deep unloading's power of 1/s, s held at the deepest fitted: the flattened plateaus'
    // that stay in contact, of the steep fine scales or, at a light peak, of its isolated plastic
    // spots (at most e_1, the Hertzian summit's); a pair that flattens nothing keeps none.
    // (A_c H/P_max overflows to +inf for a denormal peak: e_1.)
    const double crowding = std::max(0.0, std::log(c.unloadingCrowded * *H / peak));
    const double isolated = c.unloadingSpread > 0.0 ? std::min(c.unloadingIsolated, c.unloadingSpread * crowding) : 0.0;
    const double tail = plastic * std::max(c.unloadingTail * std::max(0.0, above), isolated);
    return std::exp(plateau * (1.0 - std::pow(s, c.unloadingRise)) - tail * std::log(std::max(s, c.unloadingDeepest)));
}

FittedUnloading fittedElastoPlasticUnloading(double P, double peak, const SurfaceRoughness& r, double bandwidth,
                                             double Eprime, std::optional<double> H, double skewness,
                                             std::optional<double> firstLevelShare, std::optional<double> fineHurst,
                                             const FittedElastoPlasticConstants& c)
{
    const double R = fittedUnloadingFactor(P, peak, r.meanAbsoluteSlope, bandwidth, Eprime, H, fineHurst, c);
    const double h = fittedElastoPlasticConductancePerConductivity(P, r, bandwidth, Eprime, H, skewness,
                                                                   firstLevelShare, c);
    if (R == 1.0) {
        return {h, h};
    }
    // +inf at a peak at or beyond H: no bound.
    return {h, std::min(h * R, fittedElastoPlasticConductancePerConductivity(peak, r, bandwidth, Eprime, H, skewness,
                                                                             firstLevelShare, c))};
}

double fittedElastoPlasticUnloadingConductancePerConductivity(double P, double peak, const SurfaceRoughness& r,
                                                              double bandwidth, double Eprime, std::optional<double> H,
                                                              double skewness, std::optional<double> firstLevelShare,
                                                              std::optional<double> fineHurst,
                                                              const FittedElastoPlasticConstants& c)
{
    return fittedElastoPlasticUnloading(P, peak, r, bandwidth, Eprime, H, skewness, firstLevelShare, fineHurst, c)
        .unloading;
}

} // namespace roughContact
