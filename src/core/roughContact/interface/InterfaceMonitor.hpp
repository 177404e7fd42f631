// SPDX-License-Identifier: GPL-3.0-or-later
// What a run writes about an interface besides its fields: a time series, one CSV row per
// write time (interface.csv), the pressure table the run used, once (table.csv), and what both
// are (about.txt). The function object thermalContactMonitor (on the master processor, from one
// of the interface's two sides) writes them under postProcessing/thermalContactResistance/; the
// formatting is here so that it is tested. The CSV files are plain CSV, a header line and rows,
// which numpy (genfromtxt with names=True) and pandas (read_csv) read without options.
//
// The time series' columns (interfaceSeriesHeader):
//   time                   the run's time [s]
//   Q_from_<side1>_W       heat [W] leaving side 1 through the interface, from side 1's faces
//                          (sum of kappa dT/dn |S_f|)
//   Q_into_<side2>_W       heat [W] entering side 2, from side 2's faces: the same number where
//                          the interface conserves heat (it does at every iteration)
//   h_mean_touching        area-weighted mean h [W/(m^2 K)] over faces in contact (partial or
//                          complete; complete faces as contactConductance shows them)
//   h_mean_all             the same over all faces (faces apart count with their gap's h)
//   h_gap_mean_all         area-weighted mean of h_g + h_r over all faces
//   P_mean_Pa              area-weighted mean nominal pressure [Pa] over all faces
//   Ar_An_mean_touching    area-weighted mean A_r/A_n over faces in contact
//   faces_apart, faces_partial, faces_complete   counts (partial includes beyond-the-table faces)
//   P_peak_mean_Pa         area-weighted mean of each face's heaviest pressure so far [Pa] (its
//                          pressure without a load history)
//   faces_unloading        faces in contact below their peak (unloading or reloading)
// A mean over no faces is written as an empty field, never as NaN.
#pragma once

#include "roughContact/interface/FaceCoupling.hpp"

#include <ostream>
#include <string>

namespace roughContact {

class ContactInterface;

/// The column names of the time series (a line).
std::string interfaceSeriesHeader(const std::string& side1, const std::string& side2);
/// One row (ending in a newline): the time, both sides' heat [W] and the summary (summed over
/// every processor) of the faces of side 1.
std::string interfaceSeriesRow(double time, double heatFromSide1, double heatIntoSide2, const CouplingSummary& s);

/// The interface's table as CSV: P_Pa, Ar_An, hc_per_ks_per_m at every table point (h_c = k_s
/// times the last).
void writeInterfaceTable(std::ostream& os, const ContactInterface& iface);

/// about.txt: what the interface is (`description`), what each file holds, the interface's
/// summary (model, law, range, the regime) and a line of Python that plots the table.
std::string interfaceAbout(const std::string& description, const ContactInterface& iface);

} // namespace roughContact
