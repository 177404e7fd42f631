// SPDX-License-Identifier: GPL-3.0-or-later
// The gap beside the contact on multiscaleContact's command line (--gas, --gas-pressure,
// --accommodation, --emissivity, --temperature, --gap-width): read by the core's reader of a gap,
// and the load curve's gap columns (gap_separation, h_gas, h_radiation, h_total).
#pragma once

#include "Options.hpp"

#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/material/Materials.hpp"

#include <functional>
#include <optional>
#include <ostream>

namespace multiscaleContact {

using roughContact::ContactMaterials;

// The gap beside the contact: --gas, --gas-pressure, --accommodation, --emissivity read by the
// core's reader of a gap (readGapSpec, the condition's gap entries and rules, each error naming
// the option), the face temperatures of --temperature T[,T2] [K] and the --gap-width [m].
struct GapInputs {
    roughContact::GapSpec spec;
    double T1 = 0.0; ///< face temperatures [K] (the gas at their mean)
    double T2 = 0.0;
    std::optional<double> width; ///< the separation at load 0 (the surfaces apart)
};
// None without a gap option; ParameterError naming the option: --temperature missing with a gap,
// --temperature or --gap-width without one, any rule of the reader.
std::optional<GapInputs> gapOf(const Options& o);

// The run's gap (InterfaceGap, as ContactInterface builds it): Y(P) from `separation`, the
// contact model's or the law's mean separation (the separation column), where the run has one;
// else the gap's correlation of sigma (the surfaces combined, roughnessOf) and H_c (--hardness,
// --hardness-from-yield, else 2.84 S_y). firstTouchPressure [Pa] > 0: a pressure `separation`
// can be asked at (InterfaceGap's first touch; the CLI asks for --gap-width at load 0 instead).
roughContact::InterfaceGap interfaceGapOf(const Options& o, const GapInputs& g, const ContactMaterials& materials,
                                          std::function<double(double)> separation, double firstTouchPressure);

// One row's gap columns at the nominal pressure P [Pa]: the separation Y [m] the gas term is
// taken at (NaN where none is: radiation alone, surfaces apart) and h_g, h_r [W/(m^2 K)]
// (InterfaceGap::conductances). complete: complete contact, no gap (Y 0, both 0). P = 0: Y is
// --gap-width (required with a gas).
struct GapRow {
    double separation = 0.0;
    roughContact::GapConductances h;
};
GapRow gapRowOf(const roughContact::InterfaceGap& gap, const GapInputs& g, double P, bool complete);

// The gap's cells of a row at P [Pa], each after a comma: gap_separation (empty where none is
// used), h_gas, h_radiation, and with ks (k_s [W/(m K)]) h_total = k_s hPerK + h_g + h_r (empty
// where hPerK, the row's h_per_k, is NaN: no law).
void writeGapCells(std::ostream& out, const roughContact::InterfaceGap& gap, const GapInputs& g, double P,
                   bool complete, const std::optional<double>& ks, double hPerK);

// A row's conductance cells, each after a comma: h_gas, h_radiation, and with ks h_total =
// k_s hPerK + h_g + h_r (inf at complete contact; empty where hPerK is NaN). writeGapCells's
// last cells, and the unloaded joint's (its separation in a column of its own).
void writeConductanceCells(std::ostream& out, const GapRow& row, const std::optional<double>& ks, double hPerK);

} // namespace multiscaleContact
