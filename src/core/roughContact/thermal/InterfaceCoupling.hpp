// SPDX-License-Identifier: GPL-3.0-or-later
// The arithmetic of a coupled temperature condition across an interface of conductance h
// between two solids, face by face, as a mixed (Robin) boundary condition on each side. Plain
// numbers in, plain numbers out: the OpenFOAM boundary condition only gathers them.
//
// Per face, each side sees its own cell (temperature T_c, conductance to the face
// kDelta = kappa * deltaCoeff [W/(m^2 K)]) and, across the interface, the neighbour's cell
// (T_n, kDelta_n). The three resistances 1/kDelta, 1/h, 1/kDelta_n are in series, so with
//   hEff = 1 / (1/h + 1/kDelta_n)            (interface + neighbour half-cell)
// the mixed condition  T_f = w T_n + (1 - w) T_c  with  w = hEff / (hEff + kDelta)
// gives the face flux  q = kDelta (T_f - T_c) = (T_n - T_c) / (1/kDelta + 1/h + 1/kDelta_n),
// the same magnitude on both sides at every iteration (conservative by construction, not only
// at convergence), and face temperatures whose jump T_f - T_f,n equals q / h.
//   h = +inf (complete contact): hEff = kDelta_n, the stock perfect-contact coupling
//            (turbulentTemperatureCoupledBaffleMixed without layers);
//   h = 0    (no contact):       w = 0, an adiabatic face.
#pragma once

#include <cmath>
#include <limits>

namespace roughContact {

namespace detail {
/// Throws the ParameterError that names what is wrong with h, kDelta or kDeltaNbr.
[[noreturn]] void badCoupling(double h, double kDelta, double kDeltaNbr);
inline bool positiveFinite(double x) { return std::isfinite(x) && x > 0.0; }
} // namespace detail

/// hEff = 1/(1/h + 1/kDeltaNbr) [W/(m^2 K)] for h in [0, +inf]; kDeltaNbr finite and > 0.
inline double effectiveConductance(double h, double kDeltaNbr)
{
    if (std::isnan(h) || h < 0.0 || !detail::positiveFinite(kDeltaNbr)) {
        detail::badCoupling(h, 1.0, kDeltaNbr);
    }
    return std::isinf(h) ? kDeltaNbr : h * kDeltaNbr / (h + kDeltaNbr);
}

/// The mixed condition's value fraction w = hEff/(hEff + kDelta) on the side whose cell
/// conductance is kDelta, its reference value being the neighbour's cell temperature.
/// h in [0, +inf]; kDelta and kDeltaNbr finite and > 0 (ParameterError otherwise).
/// Inline: called per face and per evaluation.
inline double coupledValueFraction(double h, double kDelta, double kDeltaNbr)
{
    if (!detail::positiveFinite(kDelta)) {
        detail::badCoupling(h, kDelta, kDeltaNbr);
    }
    const double hEff = effectiveConductance(h, kDeltaNbr);
    return hEff / (hEff + kDelta);
}

/// The face temperature the mixed condition gives: w T_nbrCell + (1 - w) T_cell.
inline double mixedFaceTemperature(double w, double Tcell, double TnbrCell)
{
    return w * TnbrCell + (1.0 - w) * Tcell;
}

} // namespace roughContact
