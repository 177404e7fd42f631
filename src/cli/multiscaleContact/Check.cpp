// SPDX-License-Identifier: GPL-3.0-or-later
#include "Run.hpp"
#include "Inputs.hpp"
#include "Plot.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/CurvesPlot.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

// --check: the exact model on this surface at the run's pressures (--pressures, --loads: up to 5)
// or N across the checked part of --load-range MIN:MAX:N (N up to 5), every law's ratio to it; the
// report, then its numbers as CSV, on stdout.
int runCheck(const Options& o)
{
    if (o.levels) {
        throw ParameterError("--check", "checks the conductance; --levels is for the per-level trace");
    }
    if (o.conductance || !o.conductanceLaw.empty()) {
        if (o.conductanceLaw == "all") {
            throw ParameterError("--check", "holds every law to the exact answer already; --conductance-law names "
                                            "the one to judge");
        }
    }
    if (!o.pressureMap.empty()) {
        throw ParameterError("--pressure-map", "is for a boundaryElement curve, not --check");
    }
    if (o.k1 || o.k2) {
        throw ParameterError(o.k1 ? "--k1" : "--k2", "--check compares h_c/k_s, which the conductivities do not change");
    }
    SurfaceCheckInputs in = interfaceInputsOf(o, "--check");
    // The pressures [Pa]: --pressures as given (no round trip through the load), or the loads x E'.
    const double Ep = in.materials->reducedModulus();
    std::vector<double> given;
    const std::vector<double> loads = loadsOf(o, Ep, &given);
    std::vector<double> pressures;
    for (std::size_t i = 0; i < loads.size(); ++i) {
        const double P = given.empty() ? loads[i] * Ep : given[i];
        if (P > 0.0) {
            pressures.push_back(P);
        }
    }
    if (pressures.empty()) {
        throw ParameterError("--check", "needs pressures above 0");
    }
    std::sort(pressures.begin(), pressures.end());
    SurfaceCheckOptions so;
    if (!o.resample.empty()) {
        throw ParameterError("--resample", "is for --model boundaryElement; --check chooses its own grids");
    }
    if (!o.synthesize.empty()) {
        const std::size_t comma = o.synthesize.find(',');
        if (comma != std::string::npos) {
            throw ParameterError("--synthesize", "with --check takes the grid size N only (the check solves seeds 1, 2 and 3)");
        }
        so.gridSize = static_cast<std::size_t>(parseWholeNumber(o.synthesize, "--synthesize", "the grid size N"));
    }
    if (!o.checkPeriods.empty()) {
        so.lightLoadPeriods = checkedLightLoadPeriods(
            parseWholeNumber(o.checkPeriods, "--check-periods", "the light loads' period K in scan lengths"), in.surfaces,
            "--check-periods");
    }
    in.minPressure = pressures.front();
    in.maxPressure = pressures.back();
    so.names.gridSize = "--synthesize";
    so.names.lightLoadPeriods = "--check-periods";
    so.names.unloadFrom = "--unload-from";
    so.unloadFrom = o.unloadFrom; // the joint's peak: the check unloads from it too
    if (!o.loadRange.empty()) {
        // --load-range MIN:MAX:N is a range: N pressures (1 to 5) across its checked part, as
        // Python's min_pressure, max_pressure and count.
        so.pressureCount = loads.size();
        so.names.pressures = "--load-range";
    } else {
        // A list (--pressures, --loads): those pressures, at most 5.
        so.pressures = pressures;
        so.names.pressures = !o.pressures.empty() ? "--pressures" : "--loads";
    }
    so.log = [](const std::string& line) { std::cerr << "multiscaleContact: " << line << std::endl; };
    const SurfaceCheck c = checkSurface(in, so);
    std::istringstream report(c.report());
    std::ostringstream out;
    for (std::string line; std::getline(report, line);) {
        out << "# " << line << '\n';
    }
    out << c.csv();
    std::cout << out.str();
    if (!o.plot.empty()) {
        writePlot(o, c.pressures, std::nullopt, nullptr, nullptr, &c);
    }
    return 0;
}

} // namespace multiscaleContact
