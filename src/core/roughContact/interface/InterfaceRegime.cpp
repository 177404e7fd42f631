// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/InterfaceRegime.hpp"

#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace roughContact {

namespace {

RegimeAt regimeAt(double P, double Eprime, double gradient, std::optional<double> H, const std::string& law,
                  const std::string& areaModel, bool capped)
{
    RegimeAt r;
    r.pressure = P;
    r.load = P / Eprime;
    // (A pressure near the largest double over a small gradient: infinite, not an overflow.)
    const bool finite = gradient >= 1.0 || r.load < std::numeric_limits<double>::max() * gradient;
    r.loadPerGradient = gradient <= 0.0 ? 0.0 : finite ? r.load / gradient : std::numeric_limits<double>::infinity();
    if (H) {
        r.perHardness = P / *H;
    }
    if (areaModel != "boundaryElement") {
        r.band = measuredAccuracy(law, areaModel, capped, r.loadPerGradient);
    }
    return r;
}

} // namespace

bool heldToCappedReference(const std::string& areaModel, const std::string& law, bool hasCap)
{
    return areaModel == "jacksonGreen" || areaModel == "truncation" ||
           ((law == "fittedElastoPlastic" || law == "cooperMikicYovanovich") && hasCap);
}

InterfaceRegime interfaceRegime(const Spectrum& surface, double Eprime, std::optional<double> hardness,
                                const std::string& law, const std::string& areaModel, bool capped, double Plow,
                                double Phigh)
{
    InterfaceRegime out;
    const SpectralMoments m = spectralMoments(surface);
    out.reducedModulus = Eprime;
    out.gradient = arealRmsGradient(m);
    out.hardness = hardness;
    out.law = law;
    out.areaModel = areaModel;
    out.capped = capped;
    try {
        out.firstLevelShare = roughContact::firstLevelShare(surface);
    } catch (const std::exception&) {
        // An all-zero spectrum: nothing to say (the law refuses it anyway).
    }
    out.fineHurst = fineHurstExponent(surface);
    if (hardness) {
        try {
            const SummitParameters s = mcCoolParameters(m);
            const double psi = Eprime / *hardness * std::sqrt(s.sigmaS / s.R);
            if (std::isfinite(psi)) {
                out.plasticityIndex = psi;
            }
        } catch (const std::exception&) {
            // Too few levels for McCool's parameters: no index.
        }
    }
    out.low = regimeAt(Plow, Eprime, out.gradient, hardness, law, areaModel, capped);
    out.high = regimeAt(Phigh, Eprime, out.gradient, hardness, law, areaModel, capped);
    return out;
}

std::string InterfaceRegime::describe() const
{
    std::string out = describeSurface();
    out += describeLine(low, "");
    if (high.pressure != low.pressure) { // one pressure (a run at one load): said once
        out += describeLine(high, "");
    }
    return out;
}

std::string InterfaceRegime::describeSurface() const
{
    std::ostringstream os;
    os << std::setprecision(3);
    os << "regime: h' = " << gradient;
    if (hardness) {
        os << ", H = " << *hardness << " Pa";
        if (gradient > 0.0) {
            os << ", H/(E' h') = " << *hardness / (reducedModulus * gradient);
        }
        if (plasticityIndex) {
            os << ", plasticity index " << *plasticityIndex
               << (*plasticityIndex < 0.6 ? " (elastic summits)" : *plasticityIndex > 1.0 ? " (plastic summits)" : "");
        }
    } else {
        os << ", elastic (no hardness)";
    }
    if (skewness) {
        os << ", heights' skewness " << skewness->skewness
           << " (Gaussian heights of this spectrum and size give +-" << skewness->spread << " by chance; ";
        if (law == "fittedElastoPlastic") {
            const double s = shrunkSkewness(*skewness);
            os << "the law takes " << s << ", chance's share out";
            if (std::abs(s) > FittedElastoPlasticConstants{}.skewnessLargest) {
                os << ", held at " << (s < 0 ? "-" : "+") << FittedElastoPlasticConstants{}.skewnessLargest
                   << " (the largest skewness its factor was fitted on)";
            }
        } else {
            os << "the law assumes 0 (fittedElastoPlastic takes " << shrunkSkewness(*skewness) << ")";
        }
        os << "; how far it matters: docs/validation/skewness.md)";
    }
    if (firstLevelShare && law == "fittedElastoPlastic") {
        const FittedElastoPlasticConstants c;
        const double s1 = *firstLevelShare;
        os << ", first level's share s1 " << s1 << " (";
        const double held = fittedLightLoadShare(s1, c);
        if (held != s1) {
            os << "held at " << held << ", the training spectra's range; ";
        }
        os << "the law's light-load factor below p/(E' h') = " << c.lightLoadEnd << " takes it: "
           << fittedLightLoadFactor(s1, 1e-4, c)
           << " at 1e-4; from one profile a noisy number: docs/validation/fittedElastoPlastic.md)";
    }
    if (fineHurst && hardness && law == "fittedElastoPlastic") {
        os << ", finest octave's Hurst exponent H_f " << *fineHurst << " (";
        const double held = fittedUnloadingHurst(*fineHurst);
        if (held != *fineHurst) {
            os << "held at " << held << ", the training spectra's range; ";
        }
        os << "the law's unloading branch below a face's peak takes it: docs/theory.md §5.7c)";
    }
    return os.str();
}

RegimeAt InterfaceRegime::at(double P) const
{
    return regimeAt(P, reducedModulus, gradient, hardness, law, areaModel, capped);
}

std::string InterfaceRegime::describeLine(const RegimeAt& r, const std::string& label) const
{
    std::ostringstream os;
    os << std::setprecision(3);
    os << "\n    at " << r.pressure << " Pa";
    if (!label.empty()) {
        os << " (" << label << ")";
    }
    os << ": p/E' = " << r.load << ", p/(E' h') = " << r.loadPerGradient;
    if (r.perHardness) {
        os << ", P/H = " << *r.perHardness;
    }
    os << "; " << law;
    if (areaModel == "boundaryElement") {
        os << ": the exact model";
    } else {
        os << " on " << areaModel << (capped ? " (capped reference)" : " (elastic reference)") << ": "
           << describeAccuracy(r.band, r.loadPerGradient);
    }
    return os.str();
}

std::optional<UnloadingAccuracyBand> InterfaceRegime::unloadingBand(double peakMin, double peakMax) const
{
    const double scale = reducedModulus * gradient; // p/(E' h') of a pressure
    return measuredUnloadingAccuracy(peakMin / scale, peakMax / scale);
}

std::string InterfaceRegime::describeUnloading(double peakMin, double peakMax) const
{
    const double scale = reducedModulus * gradient;
    return describeUnloadingAccuracy(unloadingBand(peakMin, peakMax), peakMin / scale, peakMax / scale);
}

std::string InterfaceRegime::describeAt(const std::vector<std::pair<std::string, double>>& labelledPressures) const
{
    std::string out;
    for (const auto& [label, P] : labelledPressures) {
        if (P > 0.0 && std::isfinite(P)) {
            out += describeLine(at(P), label);
        }
    }
    return out;
}

} // namespace roughContact
