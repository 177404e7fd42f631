// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/InterfaceMonitor.hpp"

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/io/Numbers.hpp"

#include <limits>
#include <sstream>

namespace roughContact {

namespace {

/// Every number to ten digits, whatever the stream's state or the process's locale.
std::string number(double x)
{
    return formatNumber(x, 10);
}

/// sum/area, or empty where no face counts (area 0).
std::string mean(double sum, double area)
{
    return area > 0.0 ? number(sum / area) : std::string();
}

} // namespace

std::string interfaceSeriesHeader(const std::string& side1, const std::string& side2)
{
    return "time,Q_from_" + side1 + "_W,Q_into_" + side2 +
           "_W,h_mean_touching,h_mean_all,h_gap_mean_all,P_mean_Pa,Ar_An_mean_touching,faces_apart,faces_partial,"
           "faces_complete,P_peak_mean_Pa,faces_unloading\n";
}

std::string interfaceSeriesRow(double time, double heatFromSide1, double heatIntoSide2, const CouplingSummary& s)
{
    std::ostringstream os;
    os << number(time) << ',' << number(heatFromSide1) << ',' << number(heatIntoSide2) << ','
       << mean(s.hTouchingArea, s.touchingArea) << ',' << mean(s.hAllArea, s.area) << ','
       << mean(s.gapAllArea, s.area) << ',' << mean(s.pressureArea, s.area) << ','
       << mean(s.areaFractionArea, s.touchingArea) << ',' << s.apart << ',' << s.partial + s.beyondTable << ','
       << s.complete << ',' << mean(s.peakPressureArea, s.area) << ',' << s.unloading << '\n';
    return os.str();
}

void writeInterfaceTable(std::ostream& os, const ContactInterface& iface)
{
    const ContactTable& t = iface.table();
    os << "P_Pa,Ar_An,hc_per_ks_per_m\n";
    const auto& P = t.pressures();
    for (std::size_t i = 0; i < P.size(); ++i) {
        os << number(P[i]) << ',' << number(t.areaFractions()[i]) << ','
           << number(t.conductancesPerConductivity()[i]) << '\n';
    }
}

std::string interfaceAbout(const std::string& description, const ContactInterface& iface)
{
    const ContactTable& t = iface.table();
    std::ostringstream os;
    os << "thermalContactResistance: " << description << "\n\n"
       << "interface.csv: one row per write time; means are area-weighted; h in W/(m^2 K); an empty field: no "
          "face to average (the columns: docs/boundary-condition.md)\n"
       << "table.csv: the pressure table the run interpolates, P_Pa, Ar_An, hc_per_ks_per_m; h_c = k_s * "
          "hc_per_ks_per_m, k_s = 2 k1 k2/(k1 + k2); below the first pressure the first interval's power law, "
          "above the last its values";
    if (t.completeContactPressure() < std::numeric_limits<double>::infinity()) {
        os << ", complete contact (h infinite) from " << number(t.completeContactPressure()) << " Pa";
    }
    os << "\n\n" << iface.summary() << "\n\n"
       << "To plot the table (numpy.genfromtxt(..., delimiter=',', names=True) and pandas.read_csv read both "
          "files as they are):\n"
       << "  python3 -c \"import numpy, matplotlib.pyplot as plt; t = numpy.genfromtxt('table.csv', delimiter=',', "
          "names=True); plt.loglog(t['P_Pa'], t['hc_per_ks_per_m']); plt.xlabel('P [Pa]'); "
          "plt.ylabel('h_c/k_s [1/m]'); plt.savefig('table.png')\"\n";
    return os.str();
}

} // namespace roughContact
