// SPDX-License-Identifier: GPL-3.0-or-later
// The interface's time series and table as the boundary condition writes them
// (interface/InterfaceMonitor): the columns, the area-weighted means from a summary worked by
// hand, an empty field (never NaN) where no face counts, and the table's rows.
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/FaceCoupling.hpp"
#include "roughContact/interface/InterfaceMonitor.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace {
std::vector<std::string> fields(const std::string& line)
{
    std::vector<std::string> out;
    std::string f;
    std::istringstream is(line);
    while (std::getline(is, f, ',')) {
        out.push_back(f);
    }
    if (!line.empty() && line.back() == ',') {
        out.emplace_back();
    }
    return out;
}
} // namespace

TEST(InterfaceMonitor, HeaderNamesTheSidesAndTheColumns)
{
    // One line, the header of a plain CSV file (no comment lines: numpy and pandas read it as is).
    EXPECT_EQ(interfaceSeriesHeader("bottom", "top"),
              "time,Q_from_bottom_W,Q_into_top_W,h_mean_touching,h_mean_all,h_gap_mean_all,P_mean_Pa,"
              "Ar_An_mean_touching,faces_apart,faces_partial,faces_complete,P_peak_mean_Pa,faces_unloading\n");
}

// Four faces of areas 1, 2, 3, 4 (the summary of testFaceCoupling's
// SummaryCountsAndWeighsTheFaces): means by hand.
TEST(InterfaceMonitor, RowHoldsTheAreaWeightedMeans)
{
    CouplingSummary s;
    s.apart = 1;
    s.partial = 1;
    s.beyondTable = 1;
    s.complete = 1;
    s.area = 10.0;
    s.touchingArea = 9.0;
    s.pressureArea = 2e6 + 9e6 + 2e9;     // P 0, 1e6, 3e6, 5e8
    s.areaFractionArea = 0.02 + 0.06 + 4; // A_r/A_n 0, 0.01, 0.02, 1
    s.hTouchingArea = 2e4 + 9e4 + 8e5;    // h 0, 1e4, 3e4, 2e5
    s.hAllArea = 2e4 + 9e4 + 8e5 + 5.0;   // the face apart: h_gap 5
    s.gapAllArea = 5.0 + 10.0;
    s.peakPressureArea = 4e6 + 9e6 + 2e9; // peaks 0, 2e6, 3e6, 5e8
    s.unloading = 1;
    const std::vector<std::string> f = fields(interfaceSeriesRow(1500.0, 12.5, 12.25, s));
    ASSERT_EQ(f.size(), 13U);
    EXPECT_EQ(f[0], "1500");
    EXPECT_EQ(f[1], "12.5");
    EXPECT_EQ(f[2], "12.25");
    EXPECT_EQ(f[3], "101111.1111");  // 910000/9
    EXPECT_EQ(f[4], "91000.5");      // 910005/10
    EXPECT_EQ(f[5], "1.5");          // 15/10
    EXPECT_EQ(f[6], "201100000");    // 2.011e9/10
    EXPECT_EQ(f[7], "0.4533333333"); // 4.08/9
    EXPECT_EQ(f[8], "1");
    EXPECT_EQ(f[9], "2");            // partial and beyond the table
    EXPECT_EQ(f[10], "1");
    EXPECT_EQ(f[11], "201300000");   // 2.013e9/10
    EXPECT_EQ(f[12], "1\n");         // the last field carries the line's end
}

TEST(InterfaceMonitor, AMeanOverNoFacesIsEmptyNotNaN)
{
    CouplingSummary s; // no face at all (a processor's empty patch, summed: nothing)
    const std::string row = interfaceSeriesRow(0.0, 0.0, 0.0, s);
    EXPECT_EQ(row, "0,0,0,,,,,,0,0,0,,0\n");
    EXPECT_EQ(row.find("nan"), std::string::npos);
}

TEST(InterfaceMonitor, TableHasEveryPointOfTheInterfacesTable)
{
    InterfaceSpec spec;
    SurfaceSpec surface;
    surface.kind = SurfaceSpec::Kind::profile;
    surface.file = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";
    spec.surfaces = {surface};
    spec.side1 = Material{200e9, 0.3, 0.4e9};
    spec.side2 = spec.side1;
    const ContactInterface ci(spec);
    std::ostringstream os;
    writeInterfaceTable(os, ci);
    std::istringstream is(os.str());
    std::string line;
    std::vector<std::string> rows;
    while (std::getline(is, line)) {
        rows.push_back(line);
    }
    // A header line and a row a point: plain CSV. What it is goes to about.txt: the description,
    // the formula, the summary with its regime, and how to plot it.
    const std::string about = interfaceAbout("the test's interface", ci);
    EXPECT_EQ(about.rfind("thermalContactResistance: the test's interface\n", 0), 0U) << about;
    EXPECT_NE(about.find("h_c = k_s * hc_per_ks_per_m"), std::string::npos) << about;
    EXPECT_NE(about.find(ci.summary()), std::string::npos) << about;
    EXPECT_NE(about.find("numpy.genfromtxt('table.csv', delimiter=',', names=True)"), std::string::npos) << about;
    ASSERT_EQ(rows.size(), ci.table().pressures().size() + 1);
    EXPECT_EQ(rows[0], "P_Pa,Ar_An,hc_per_ks_per_m");
    // The first and last points, to the 10 digits written.
    const std::vector<std::string> first = fields(rows[1]);
    ASSERT_EQ(first.size(), 3U);
    EXPECT_NEAR(std::stod(first[0]), ci.table().pressures().front(), 1e-9 * ci.table().pressures().front());
    EXPECT_NEAR(std::stod(first[2]), ci.table().conductancesPerConductivity().front(),
                1e-9 * ci.table().conductancesPerConductivity().front());
    const std::vector<std::string> last = fields(rows.back());
    EXPECT_NEAR(std::stod(last[1]), ci.table().areaFractions().back(), 1e-9);
    EXPECT_NE(about.find("complete contact (h infinite) from"), std::string::npos);
}
