// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/FaceCoupling.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"
#include "roughContact/thermal/InterfaceCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace roughContact {

void CouplingOutputs::resize(std::size_t n)
{
    state.resize(n);
    for (std::vector<double>* v : {&pressure, &areaFraction, &contactConductance, &gapConductance,
                                   &radiativeConductance, &conductance, &valueFraction, &refValue, &peakPressure}) {
        v->resize(n);
    }
}

namespace {

void requireArrays(const CouplingInputs& in, bool contact, bool gap)
{
    const bool ok = in.kappa && in.kappaNbr && in.deltaCoeffs && in.deltaCoeffsNbr &&
                    (contact ? in.pressure && in.pressureNbr && in.cellTemperatureNbr : in.faceTemperatureNbr != nullptr) &&
                    (!gap || (in.faceTemperature && in.faceTemperatureNbr)) &&
                    (in.gapWidth == nullptr) == (in.gapWidthNbr == nullptr) &&
                    (in.peakPressure == nullptr) == (in.peakPressureNbr == nullptr);
    if (in.n > 0 && !ok) {
        throw ParameterError("interface coupling", "an input array the coupling needs is missing");
    }
}

} // namespace

namespace {

/// The per-face checks of the conductivities and cell distances, each named: called only when
/// the fast test in couple() fails, to throw the error that names what is wrong.
[[noreturn]] void badFace(const CouplingInputs& in, std::size_t i)
{
    limits::requireInRange("kappa", in.kappa[i], limits::minimumConductivity, limits::maximumConductivity, "W/(m K)");
    limits::requireInRange("neighbour kappa", in.kappaNbr[i], limits::minimumConductivity,
                           limits::maximumConductivity, "W/(m K)");
    requirePositive("deltaCoeffs", in.deltaCoeffs[i]);
    requirePositive("neighbour deltaCoeffs", in.deltaCoeffsNbr[i]);
    requirePositive("kappa*deltaCoeffs", in.kappa[i] * in.deltaCoeffs[i]);
    requirePositive("neighbour kappa*deltaCoeffs", in.kappaNbr[i] * in.deltaCoeffsNbr[i]);
    throw ParameterError("interface coupling", "bad face"); // not reached
}

inline bool positiveFinite(double x) { return x > 0.0 && x < std::numeric_limits<double>::infinity(); }
inline bool conductivity(double k) { return k >= limits::minimumConductivity && k <= limits::maximumConductivity; }

} // namespace

void couple(const ContactInterface& iface, const CouplingInputs& in, CouplingCache& cache, CouplingOutputs& out)
{
    const InterfaceGap* gap = iface.hasGap() ? &iface.gap() : nullptr;
    requireArrays(in, true, gap != nullptr);
    const std::size_t n = in.n;
    out.resize(n);
    out.apart = 0;
    out.beyondTable = 0;
    out.unloading = 0;
    const bool history = in.peakPressure != nullptr;
    if (cache.pressure.size() != n) {
        // NaN never equals a pressure: every face is looked up on the first call.
        cache.pressure.assign(n, std::numeric_limits<double>::quiet_NaN());
        cache.peak.assign(n, 0.0);
        cache.areaFraction.assign(n, 0.0);
        cache.conductancePerConductivity.assign(n, 0.0);
        cache.separation.assign(n, 0.0);
    }
    const ContactTable& table = iface.table();
    const double complete = iface.completeContactPressure();
    // ContactInterface::heldAtTableEnd(P), its constant part hoisted.
    const bool tableCut = table.end() == ContactTable::End::maxPressure;
    const double tableEnd = iface.tableEnd();
    const double tableStart = table.pressures().front();
    out.belowTable = 0;
    out.belowTablePressureSum = 0.0;
    out.pressureMismatch = 0;
    out.largestPressureMismatch = 0.0;
    out.apartAtFirstTouch = 0;
    for (std::size_t i = 0; i < n; ++i) {
        try {
            const double P = requireFinite("nominal pressure", nominalPressure(in.pressure[i], in.pressureNbr[i]));
            double peak = P;
            if (history) {
                const double mine = in.peakPressure[i];
                const double theirs = in.peakPressureNbr[i];
                // One test on the fast path; the named error otherwise.
                if (!(isPeakPressure(mine) && isPeakPressure(theirs))) {
                    const bool bad = !isPeakPressure(mine);
                    throw ParameterError(bad ? "peak pressure" : "neighbour peak pressure",
                                         "must be a finite pressure >= 0, got " + std::to_string(bad ? mine : theirs));
                }
                peak = std::max({P, mine, theirs});
            }
            if (!(P == cache.pressure[i] && peak == cache.peak[i])) {
                const ContactTable::Values v = table.values(P);
                // 1 at the peak and for an interface without unloading curves.
                const UnloadingFactors f = iface.unloadingFactors(P, peak);
                cache.pressure[i] = P;
                cache.peak[i] = peak;
                cache.areaFraction[i] = std::min(1.0, v.areaFraction * f.areaFraction);
                cache.conductancePerConductivity[i] = v.conductancePerConductivity * f.conductancePerConductivity;
                // The gap's separation at this pressure (touching faces short of complete
                // contact; looked up with the table, cached with it).
                cache.separation[i] =
                    gap && P > 0.0 && P < complete ? gap->separation(P) * f.separation : 0.0;
            }
            const double k1 = in.kappa[i];
            const double k2 = in.kappaNbr[i];
            const double kDelta = k1 * in.deltaCoeffs[i];
            const double kDeltaNbr = k2 * in.deltaCoeffsNbr[i];
            // One test on the fast path (finite kDelta > 0 with k in range implies finite
            // deltaCoeffs > 0); the named error otherwise.
            if (!(conductivity(k1) && conductivity(k2) && positiveFinite(kDelta) && positiveFinite(kDeltaNbr))) {
                badFace(in, i);
            }
            const double ks = 2.0 * k1 * k2 / (k1 + k2); // harmonicMeanConductivity, checked above

            FaceState state;
            if (P <= 0.0) {
                state = FaceState::apart;
                ++out.apart;
            } else if (P >= complete) {
                state = FaceState::complete;
            } else if (tableCut && P > tableEnd) {
                state = FaceState::beyondTable;
                ++out.beyondTable;
            } else {
                state = FaceState::partial;
            }
            if (P > 0.0 && P < peak) {
                ++out.unloading;
            }
            // Input that is probably a mistake (counted; the caller warns).
            if (state == FaceState::partial && P < tableStart) {
                ++out.belowTable;
                out.belowTablePressureSum += P;
            }
            {
                const double a = in.pressure[i];
                const double b = in.pressureNbr[i];
                const double larger = std::max(std::abs(a), std::abs(b));
                if (larger > 0.0 && std::abs(a - b) > pressureMismatchTolerance * larger) {
                    ++out.pressureMismatch;
                    out.largestPressureMismatch = std::max(out.largestPressureMismatch, std::abs(a - b) / larger);
                }
            }
            if (state == FaceState::apart && gap && gap->hasGas() && !in.gapWidth) {
                ++out.apartAtFirstTouch;
            }
            const double hc = ks * cache.conductancePerConductivity[i];
            double hg = 0.0;
            double hr = 0.0;
            if (gap && state != FaceState::complete) {
                double Y = cache.separation[i];
                if (state == FaceState::apart) {
                    Y = in.gapWidth ? nominalGapWidth(requireNonNegative("gap width", in.gapWidth[i]),
                                                      requireNonNegative("neighbour gap width", in.gapWidthNbr[i]))
                                    : gap->firstTouchSeparation();
                }
                const GapConductances g = gap->conductances(Y, in.faceTemperature[i], in.faceTemperatureNbr[i]);
                hg = g.gas;
                hr = g.radiative;
            }
            const double h = hc + hg + hr;
            // coupledValueFraction(h, kDelta, kDeltaNbr) (thermal/InterfaceCoupling.hpp), its
            // checks done above: the same operations, so the same bits.
            const double hEff = std::isinf(h) ? kDeltaNbr : h * kDeltaNbr / (h + kDeltaNbr);

            out.state[i] = state;
            out.pressure[i] = P;
            out.areaFraction[i] = cache.areaFraction[i];
            out.contactConductance[i] = hc;
            out.gapConductance[i] = hg;
            out.radiativeConductance[i] = hr;
            out.conductance[i] = h;
            out.valueFraction[i] = hEff / (hEff + kDelta);
            out.refValue[i] = in.cellTemperatureNbr[i];
            out.peakPressure[i] = peak;
        } catch (const ParameterError& e) {
            throw FaceError(i, e);
        }
    }
}

void coupleConstant(double h, const CouplingInputs& in, CouplingOutputs& out)
{
    requirePositive("h", h);
    requireArrays(in, false, false);
    const std::size_t n = in.n;
    out.resize(n);
    out.apart = 0;
    out.beyondTable = 0;
    out.belowTable = 0;
    out.belowTablePressureSum = 0.0;
    out.pressureMismatch = 0;
    out.largestPressureMismatch = 0.0;
    out.apartAtFirstTouch = 0;
    out.unloading = 0;
    for (std::size_t i = 0; i < n; ++i) {
        try {
            const double kDelta =
                requirePositive("kappa", in.kappa[i]) * requirePositive("deltaCoeffs", in.deltaCoeffs[i]);
            out.state[i] = FaceState::partial;
            out.pressure[i] = 0.0;
            out.areaFraction[i] = 1.0;
            out.contactConductance[i] = h;
            out.gapConductance[i] = 0.0;
            out.radiativeConductance[i] = 0.0;
            out.conductance[i] = h;
            // The stock turbulentTemperatureCoupledBaffleMixed with layers, as it writes it.
            out.valueFraction[i] = h / (h + kDelta);
            out.refValue[i] = in.faceTemperatureNbr[i];
            out.peakPressure[i] = 0.0;
        } catch (const ParameterError& e) {
            throw FaceError(i, e);
        }
    }
}

void CouplingDiagnostics::add(const CouplingOutputs& out)
{
    belowTable += out.belowTable;
    belowTablePressureSum += out.belowTablePressureSum;
    pressureMismatch += out.pressureMismatch;
    largestPressureMismatch = std::max(largestPressureMismatch, out.largestPressureMismatch);
    apartAtFirstTouch += out.apartAtFirstTouch;
}

std::string CouplingDiagnostics::belowTableMessage(const ContactInterface& iface) const
{
    if (belowTable == 0) {
        return "";
    }
    const double first = iface.table().pressures().front();
    const double mean = belowTablePressureSum / double(belowTable);
    std::ostringstream os;
    os << belowTable << " face" << (belowTable == 1 ? " has a pressure" : "s have pressures")
       << " below the table's first point ("
       << first << " Pa; their mean " << mean << " Pa): A_r/A_n and h are extrapolated there.";
    if (mean * 1e6 >= first && mean * 1e6 <= iface.tableEnd()) {
        os << " A pressure given in MPa? " << mean << " MPa would be " << mean * 1e6
           << " Pa, inside the table: give pressures in Pa.";
    } else if (mean * 1e3 >= first && mean * 1e3 <= iface.tableEnd()) {
        os << " A pressure given in kPa? Give pressures in Pa.";
    } else {
        os << " Lower minPressure if such pressures are meant.";
    }
    return os.str();
}

std::string CouplingDiagnostics::pressureMismatchMessage() const
{
    if (pressureMismatch == 0) {
        return "";
    }
    std::ostringstream os;
    os.precision(3);
    os << pressureMismatch << " face" << (pressureMismatch == 1 ? "" : "s")
       << ": the two sides' pressures differ by up to " << 100.0 * largestPressureMismatch << " % (more than "
       << 100.0 * pressureMismatchTolerance
       << " % of the larger); their mean is used. Check that both sides give the same pressure (pressure, "
          "pressureField: the same field, units and sign).";
    return os.str();
}

std::string CouplingDiagnostics::apartAtFirstTouchMessage(const ContactInterface& iface) const
{
    if (apartAtFirstTouch == 0) {
        return "";
    }
    std::ostringstream os;
    os << apartAtFirstTouch << " face" << (apartAtFirstTouch == 1 ? " is" : "s are")
       << " apart (pressure <= 0) with a gas in the gap and no gap width given: their separation is taken as "
          "the interface's at first touch ("
       << iface.gap().firstTouchSeparation()
       << " m), so the gas conducts as if the surfaces just touched. Give the width of faces that are apart "
          "(gap or gapField).";
    return os.str();
}

void CouplingSummary::add(const CouplingOutputs& out, const double* magSf, const double* shown)
{
    const std::size_t n = out.state.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double a = magSf[i];
        area += a;
        pressureArea += out.pressure[i] * a;
        peakPressureArea += out.peakPressure[i] * a;
        if (out.pressure[i] > 0.0 && out.pressure[i] < out.peakPressure[i]) {
            ++unloading;
        }
        hAllArea += shown[i] * a;
        gapAllArea += (out.gapConductance[i] + out.radiativeConductance[i]) * a;
        switch (out.state[i]) {
        case FaceState::apart:
            ++apart;
            continue;
        case FaceState::complete:
            ++complete;
            break;
        case FaceState::partial:
        case FaceState::beyondTable: {
            const bool first = partial + beyondTable == 0;
            ++(out.state[i] == FaceState::partial ? partial : beyondTable);
            hPartialMin = first ? shown[i] : std::min(hPartialMin, shown[i]);
            hPartialMax = first ? shown[i] : std::max(hPartialMax, shown[i]);
            partialArea += a;
            hPartialArea += shown[i] * a;
            areaFractionPartialArea += out.areaFraction[i] * a;
            break;
        }
        }
        touchingArea += a;
        areaFractionArea += out.areaFraction[i] * a;
        hTouchingArea += shown[i] * a;
    }
}

} // namespace roughContact
