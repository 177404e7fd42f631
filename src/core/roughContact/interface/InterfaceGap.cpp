// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/InterfaceGap.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <sstream>

namespace roughContact {

namespace {

double emissivity(const char* name, double e)
{
    if (!(e > 0.0 && e <= 1.0)) {
        std::ostringstream os;
        os << "must be in (0, 1], got " << e;
        throw ParameterError(name, os.str());
    }
    return e;
}

void checkEmissivities(const GapSpec& spec)
{
    if (spec.emissivity1.has_value() != spec.emissivity2.has_value()) {
        throw ParameterError("gap emissivity", "give both sides' emissivities (radiation) or neither");
    }
    if (spec.emissivity1) {
        emissivity("gap emissivity e1", *spec.emissivity1);
        emissivity("gap emissivity e2", *spec.emissivity2);
    }
    if (!spec.gas && !spec.emissivity1) {
        throw ParameterError("gap", "has neither a gas nor emissivities: nothing crosses it (leave the gap out)");
    }
}

} // namespace

void checkGapSpec(const GapSpec& spec)
{
    checkEmissivities(spec);
    if (spec.gas) {
        GasGap check(*spec.gas);
    }
}

InterfaceGap::InterfaceGap(const GapSpec& spec, std::function<double(double)> separation, double sigma, double Hc,
                           double firstTouchPressure)
    : spec_(spec), separation_(std::move(separation)), sigma_(sigma), Hc_(Hc), firstTouch_(0.0),
      radiationFactor_(0.0)
{
    checkEmissivities(spec);
    if (spec.emissivity1) {
        radiationFactor_ = stefanBoltzmann * greyFactor(*spec.emissivity1, *spec.emissivity2);
    }
    if (spec.gas) {
        gas_.emplace(*spec.gas);
    }
    if (!separation_) {
        requirePositive("rms roughness sigma (gap separation)", sigma);
        limits::requireInRange("microhardness H_c (gap separation)", Hc, limits::minimumHardness, limits::maximumHardness, "Pa");
    }
    firstTouch_ = this->separation(requirePositive("first-touch pressure", firstTouchPressure));
}

double InterfaceGap::separation(double P) const
{
    if (separation_) {
        const double Y = separation_(P);
        if (!(Y >= 0.0 && Y < std::numeric_limits<double>::infinity())) {
            std::ostringstream os;
            os << "the contact model's mean separation at P = " << P << " Pa is " << Y;
            throw ParameterError("gap separation Y", os.str());
        }
        return Y;
    }
    return gapSeparationCorrelation(P, sigma_, Hc_);
}

double InterfaceGap::gasConductance(double Y, double T1, double T2) const
{
    return gas_ ? gas_->conductance(Y, 0.5 * T1 + 0.5 * T2) : 0.0;
}

double InterfaceGap::radiativeConductance(double T1, double T2) const
{
    return spec_.emissivity1 ? roughContact::radiativeConductance(T1, T2, *spec_.emissivity1, *spec_.emissivity2)
                             : 0.0;
}

GapConductances InterfaceGap::conductances(double Y, double T1, double T2) const
{
    // limits::requireInRange with a literal name is inline and builds its message only on failure.
    limits::requireInRange("face temperature", T1, limits::minimumTemperature, limits::maximumTemperature, "K");
    limits::requireInRange("neighbour face temperature", T2, limits::minimumTemperature, limits::maximumTemperature,
                           "K");
    limits::requireInRange("gap separation Y", Y, 0.0, limits::maximumLength, "m");
    // The mean of two temperatures in range is in range: the checks of gasConductance and
    // radiativeConductance hold, and these are their formulas.
    GapConductances h;
    if (gas_) {
        h.gas = gas_->conductanceOfChecked(Y, 0.5 * T1 + 0.5 * T2);
    }
    if (spec_.emissivity1) {
        h.radiative = radiativeConductanceOfChecked(T1, T2, radiationFactor_);
    }
    return h;
}

std::string InterfaceGap::summary() const
{
    std::ostringstream os;
    if (gas_) {
        const GasGapSpec& g = gas_->spec();
        os << "gap: " << g.gas.name << " at " << g.pressure << " Pa (accommodation " << *g.accommodation1 << ", "
           << *g.accommodation2 << "; M = " << gas_->rarefaction(300.0) << " m at 300 K)";
    } else {
        os << "gap: vacuum";
    }
    if (spec_.emissivity1) {
        os << ", radiation (emissivities " << *spec_.emissivity1 << ", " << *spec_.emissivity2 << ")";
    }
    os << "; separation of touching faces from "
       << (separation_ ? "the contact model" : "the Gaussian plastic correlation of sigma and P/H_c")
       << ", of faces apart with no gap width given " << firstTouch_ << " m (first touch)";
    return os.str();
}

} // namespace roughContact
