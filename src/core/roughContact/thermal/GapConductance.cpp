// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/GapConductance.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace roughContact {

namespace {

// The published fit of the Gaussian mean-plane separation (GapConductance.hpp).
constexpr double fitCoefficient = 1.184;
constexpr double fitLogFactor = 3.132;
constexpr double fitExponent = 0.547;

double requireTemperature(const char* what, double T)
{
    return limits::requireInRange(what, T, limits::minimumTemperature, limits::maximumTemperature, "K");
}

// Unset: the gas's default; otherwise within [limits::minimumAccommodation, 1].
double resolveAccommodation(const char* what, std::optional<double> given, double gasDefault)
{
    if (!given) {
        return gasDefault;
    }
    if (!std::isfinite(*given) || *given < limits::minimumAccommodation || *given > 1.0) {
        std::ostringstream os;
        os << "must lie in (0, 1] (at least " << limits::minimumAccommodation << "; leave it out for the gas's default "
           << gasDefault << "), got " << limits::valueText(*given, "");
        throw ParameterError(what, os.str());
    }
    return *given;
}

double jump(double a) { return (2.0 - a) / a; }

struct SeparationInputs {
    double relativePressure; // P/H_c, clamped to [minimumRelativePressure, ...); >= 1/2 means closed
    bool closed;             // P/H_c >= 1/2
    double sigma;
};

SeparationInputs separationInputs(double P, double sigma, double Hc)
{
    requirePositive("contact pressure P", P);
    limits::requireInRange("rms roughness sigma", sigma, limits::minimumRoughness, limits::maximumHeight, "m");
    limits::requireInRange("microhardness H_c", Hc, limits::minimumHardness, limits::maximumHardness, "Pa");
    // Compare before dividing: P/H_c itself could overflow.
    if (P >= 0.5 * Hc) {
        return {0.5, true, sigma};
    }
    return {std::max(P / Hc, minimumRelativePressure), false, sigma};
}

double gaussianSeparation(const SeparationInputs& in)
{
    if (in.closed) {
        return 0.0;
    }
    return std::sqrt(2.0) * in.sigma * boost::math::erfc_inv(2.0 * in.relativePressure);
}

} // namespace

GasGap::GasGap(const GasGapSpec& spec) : spec_(spec), alphaBeta_(0.0)
{
    checkGas(spec_.gas);
    limits::requireInRange("gas pressure P_g", spec_.pressure, limits::minimumGasPressure,
                           limits::maximumGasPressure, "Pa");
    spec_.accommodation1 = resolveAccommodation("accommodation coefficient a1", spec_.accommodation1,
                                                spec_.gas.accommodation);
    spec_.accommodation2 = resolveAccommodation("accommodation coefficient a2", spec_.accommodation2,
                                                spec_.gas.accommodation);
    const double gamma = spec_.gas.heatCapacityRatio;
    alphaBeta_ = (jump(*spec_.accommodation1) + jump(*spec_.accommodation2)) * (2.0 * gamma / (gamma + 1.0)) /
                 spec_.gas.prandtl;
}

double GasGap::conductivity(double T) const
{
    return conductivityOfChecked(requireTemperature("gas temperature T", T));
}

double GasGap::meanFreePath(double T) const
{
    return meanFreePathOfChecked(requireTemperature("gas temperature T", T));
}

double GasGap::rarefaction(double T) const { return alphaBeta_ * meanFreePath(T); }

double GasGap::conductance(double Y, double T) const
{
    limits::requireInRange("gap separation Y", Y, 0.0, limits::maximumLength, "m");
    return conductanceOfChecked(Y, requireTemperature("gas temperature T", T));
}

double greyFactor(double e1, double e2)
{
    const double eMin = std::min(e1, e2), eMax = std::max(e1, e2);
    return eMin / (eMin / eMax + (1.0 - eMin));
}

double radiativeConductance(double T1, double T2, double e1, double e2)
{
    requireTemperature("temperature T1", T1);
    requireTemperature("temperature T2", T2);
    limits::requireInRange("emissivity e1", e1, 0.0, 1.0, "");
    limits::requireInRange("emissivity e2", e2, 0.0, 1.0, "");
    if (e1 == 0.0) {
        throw ParameterError("emissivity e1", "must lie in (0, 1], got 0");
    }
    if (e2 == 0.0) {
        throw ParameterError("emissivity e2", "must lie in (0, 1], got 0");
    }
    return radiativeConductanceOfChecked(T1, T2, stefanBoltzmann * greyFactor(e1, e2));
}

double gapSeparationGaussian(double P, double sigma, double Hc)
{
    return gaussianSeparation(separationInputs(P, sigma, Hc));
}

double gapSeparationCorrelation(double P, double sigma, double Hc)
{
    const SeparationInputs in = separationInputs(P, sigma, Hc);
    if (in.closed || in.relativePressure < correlationMinimumRelativePressure ||
        in.relativePressure > correlationMaximumRelativePressure) {
        return gaussianSeparation(in);
    }
    return fitCoefficient * sigma * std::pow(-std::log(fitLogFactor * in.relativePressure), fitExponent);
}

} // namespace roughContact
