// SPDX-License-Identifier: GPL-3.0-or-later
#include "Inputs.hpp"
#include "Run.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

int runTable(const Options& o)
{
    if (o.model != "boundaryElement") {
        throw ParameterError("--table", "is the boundary-element table's cache: give --model boundaryElement, not " +
                                            o.model);
    }
    if (o.E.size() != 2 || o.nu.size() != 2) {
        throw ParameterError("--table", "needs the interface's two solids, as the condition's side1 and side2: "
                                        "--E E1,E2 and --nu nu1,nu2 (not --Eprime)");
    }
    for (const auto& [given, what] : {std::pair<bool, const char*>{o.check, "--check"},
                                      {o.levels, "--levels"},
                                      {!o.loads.empty(), "--loads"},
                                      {!o.loadRange.empty(), "--load-range"},
                                      {!o.resample.empty(), "--resample"},
                                      {!o.pressureMap.empty(), "--pressure-map"},
                                      {o.conductance || !o.conductanceLaw.empty(), "--conductance"},
                                      {o.k1 || o.k2, "--k1/--k2"}}) {
        if (given) {
            throw ParameterError(what, "is not an input of the boundary-element table (--table): the table's "
                                       "loads are its own, its columns fixed");
        }
    }
    InterfaceSpec spec = interfaceSpecOf(o); // the surfaces and the exact model's entries
    const std::vector<Material> sides = solidsOf(o);
    spec.side1 = sides[0];
    spec.side2 = sides[1];
    if (!o.pressures.empty()) {
        std::vector<double> range;
        for (const std::string& item : o.pressures) {
            for (double v : splitNumbers(item, ',', "--pressures")) {
                range.push_back(v);
            }
        }
        if (range.empty() || range.size() > 2) {
            throw ParameterError("--pressures", "with --table is the table's range MIN[,MAX] [Pa] (the "
                                                "condition's minPressure and maxPressure)");
        }
        spec.minPressure = range[0];
        if (range.size() == 2) {
            spec.maxPressure = range[1];
        }
    }
    const BoundaryElementTable table(spec);
    const BoundaryElementTablePoints points = table.loadOrBuild(
        o.table,
        [&](std::size_t done, std::size_t total, double P, const BoundaryElementPoint& p, double seconds) {
            std::cerr << "multiscaleContact: boundary-element table: load " << done << " of " << total << ", P = " << P
                      << " Pa, A_r/A_n = " << p.areaFraction << ", " << seconds << " s\n";
        },
        [](const std::string& line, bool warning) {
            std::cerr << "multiscaleContact: " << (warning ? "warning: " : "") << line << '\n';
        });
    std::ostringstream out;
    out << "pressure,area,h_per_k,separation\n";
    for (std::size_t i = 0; i < points.pressures.size(); ++i) {
        out << formatNumber(points.pressures[i], 10) << ',' << formatNumber(points.areaFractions[i], 10) << ','
            << formatNumber(points.conductancesPerConductivity[i], 10) << ','
            << (i < points.separations.size() ? formatNumber(points.separations[i], 10) : std::string()) << '\n';
    }
    std::cout << out.str();
    return 0;
}

} // namespace multiscaleContact
