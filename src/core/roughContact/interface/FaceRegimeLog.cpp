// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/FaceRegimeLog.hpp"

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace roughContact {

namespace {

// A face within this of its peak is not said to be below it: a load held in a table in time
// comes back an ulp or two below the pressure it peaked at (interpolated between two equal
// values), which would start and stop the log's unloading line at every such step.
constexpr double saidBelowPeak = 1e-9;

} // namespace

void FaceSums::add(const CouplingOutputs& out)
{
    addPressures(out);
    addConductances(out);
}

void FaceSums::addPressures(const CouplingOutputs& out)
{
    faces += out.state.size();
    for (std::size_t i = 0; i < out.state.size(); ++i) {
        const double P = out.pressure[i];
        if (out.state[i] != FaceState::apart && P > 0.0) {
            ++inContact;
            pressureMin = std::min(pressureMin, P);
            pressureMax = std::max(pressureMax, P);
            pressureSum += P * pressureScale;
            const double peak = i < out.peakPressure.size() ? out.peakPressure[i] : P;
            if (P < peak * (1.0 - saidBelowPeak)) {
                ++unloading;
                unloadingPeakMin = std::min(unloadingPeakMin, peak);
                unloadingPeakMax = std::max(unloadingPeakMax, peak);
                unloadingFractionMin = std::min(unloadingFractionMin, P / peak);
            }
        }
    }
}

void FaceSums::addConductances(const CouplingOutputs& out)
{
    for (std::size_t i = 0; i < out.state.size(); ++i) {
        if (!std::isfinite(out.contactConductance[i])) {
            ++complete;
            continue;
        }
        contactSum += out.contactConductance[i];
        gasSum += out.gapConductance[i];
        radiationSum += out.radiativeConductance[i];
    }
}

double FaceSums::meanPressure() const
{
    if (inContact == 0) {
        return 0.0;
    }
    // Within [min, max] whatever the rounding, and no overflow when scaled back.
    const double scaled = pressureSum / double(inContact);
    const double mean = scaled < std::numeric_limits<double>::max() * pressureScale ? scaled / pressureScale : pressureMax;
    return std::clamp(mean, pressureMin, pressureMax);
}

std::vector<double> FaceSums::pressuresToCheck() const
{
    std::vector<double> out;
    if (inContact == 0) {
        return out;
    }
    for (double P : {pressureMin, meanPressure(), pressureMax}) {
        if (out.empty() || P / 1.01 > out.back()) {
            out.push_back(P);
        }
    }
    return out;
}

FaceRegimeLog::FaceRegimeLog(double factor) : factor_(factor)
{
    if (!(factor > 1.0)) {
        throw std::invalid_argument("FaceRegimeLog: the factor must be > 1");
    }
}

std::string FaceRegimeLog::update(const ContactInterface& iface, const FaceSums& all)
{
    return due(all) ? describe(iface, all) : std::string();
}

bool FaceRegimeLog::due(const FaceSums& all)
{
    if (all.inContact == 0) {
        return false;
    }
    const std::array<double, 3> now{all.pressureMin, all.meanPressure(), all.pressureMax};
    const bool unloading = all.unloading > 0;
    if (said_ && unloading == saidUnloading_) {
        bool moved = false;
        for (std::size_t k = 0; k < 3; ++k) {
            const double ratio = now[k] / (*said_)[k];
            // (A ratio of the factor to round-off, a load that doubled exactly, is no move.)
            moved = moved || ratio > factor_ * (1.0 + 1e-9) || ratio < 1.0 / (factor_ * (1.0 + 1e-9));
        }
        if (!moved) {
            return false;
        }
    }
    said_ = now;
    saidUnloading_ = unloading;
    return true;
}

std::string FaceRegimeLog::describe(const ContactInterface& iface, const FaceSums& all)
{
    std::ostringstream os;
    os << std::setprecision(4);
    const InterfaceRegime& regime = iface.regime();
    if (all.inContact == 0) {
        os << "no face in contact";
    } else {
        const double mean = all.meanPressure();
        os << "the regime at the faces' pressures (" << all.inContact << " of " << all.faces
           << " faces in contact)";
        // One pressure when the faces carry the same within 1 % (a uniform load): said once.
        if (all.pressureMax / 1.01 <= all.pressureMin) {
            os << regime.describeAt({{all.inContact == 1 ? "the face" : "every face", mean}});
        } else {
            os << regime.describeAt({{"min", all.pressureMin}, {"mean", mean}, {"max", all.pressureMax}});
        }
    }
    if (all.unloading > 0) {
        os << "\n    " << all.unloading << (all.unloading == 1 ? " face is" : " faces are")
           << " below the largest pressure carried (peaks " << all.unloadingPeakMin;
        if (all.unloadingPeakMax > all.unloadingPeakMin) {
            os << " to " << all.unloadingPeakMax;
        }
        // Rounded down (0.99999 is "0.999", not "1"): at least as deep as said.
        os << " Pa, P/P_max down to " << std::floor(all.unloadingFractionMin * 1000.0) / 1000.0 << "): ";
        if (!iface.unloading().empty()) {
            os << "h_c from the exact unloading curves, interpolated between their peaks (docs/theory.md "
                  "§7.6)";
        } else if (iface.lawUnloads()) {
            const auto band = regime.unloadingBand(all.unloadingPeakMin, all.unloadingPeakMax);
            os << "h_c is the loading h_c at P times the unloading branch's R (docs/theory.md §5.7c); "
               << regime.describeUnloading(all.unloadingPeakMin, all.unloadingPeakMax);
            if (band) {
                os << (band->outside == 0 ? ": sign h there with the band at P times R's"
                                          : ": wider than 25 % there; check your surface with its peak (the "
                                            "check's --unload-from) or take model boundaryElement");
                // (1e-9: the table's leastFraction is printed to 4 digits; an equal depth is no deeper.)
                if (all.unloadingFractionMin < band->leastFraction * (1.0 - 1e-9)) {
                    os << " (unloaded deeper than measured)";
                }
            }
        } else {
            os << regime.law << " has no unloading branch: h_c follows the pressure of the moment";
        }
    }
    const std::size_t counted = all.faces - all.complete;
    if (counted > 0) {
        const double n = double(counted);
        const double hc = all.contactSum / n;
        const double hg = all.gasSum / n;
        const double hr = all.radiationSum / n;
        os << "\n    h = h_c + h_gas + h_rad, means over the " << counted
           << (all.complete > 0 ? " faces not in complete contact" : " faces") << ": " << hc + hg + hr
           << " = " << hc << " (contact: " << (iface.regime().areaModel == "boundaryElement"
                                                   ? "the exact model's"
                                                   : "the band above")
           << ")";
        if (iface.hasGap()) {
            os << " + " << hg << " (gas: " << gapConductanceAccuracy << ") + " << hr
               << " (radiation: " << gapConductanceAccuracy << ")";
        } else {
            os << " (no gap: no gas or radiation)";
        }
        os << " W/m^2/K";
    }
    return os.str();
}

} // namespace roughContact
