// SPDX-License-Identifier: GPL-3.0-or-later
#include "Plot.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/InterfaceCurves.hpp"
#include "roughContact/io/CurvesPlot.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

using namespace roughContact;

namespace multiscaleContact {

void writePlot(const Options& o, const std::vector<double>& pressures, const std::optional<double>& ks,
               const InterfaceGap* gap, const GapInputs* gapInputs, const SurfaceCheck* check)
{
    std::vector<double> positive;
    for (double P : pressures) {
        if (P > 0.0) {
            positive.push_back(P);
        }
    }
    if (positive.empty()) {
        throw ParameterError("--plot", "draws h against pressures above 0; the run has none");
    }
    const auto [lo, hi] = std::minmax_element(positive.begin(), positive.end());
    const SurfaceCheckInputs in = interfaceInputsOf(o, "--plot");
    const InterfaceCurves curves = interfaceCurves(in, plotPressures(*lo, *hi, check != nullptr));
    PlotExtras extras;
    extras.conductivity = ks;
    if (gap && gapInputs) {
        for (double P : curves.pressures) {
            const GapRow row = gapRowOf(*gap, *gapInputs, P, false);
            extras.gas.push_back(row.h.gas);
            extras.radiation.push_back(row.h.radiative);
        }
    }
    if (check) {
        extras.check.pressures = check->pressures;
        extras.check.answer = check->answerHPerK;
        extras.check.exactLow = check->answerExactLow;
        extras.check.exactHigh = check->answerExactHigh;
    }
    std::ostringstream title;
    title.precision(3);
    title << equivalentSurface(in.surfaces).source() << ": E' = " << in.materials->reducedModulus() / 1e9
          << " GPa, " << (curves.capped ? "capped" : "elastic") << ", h' = " << curves.gradient;
    extras.title = title.str();
    writeCurvesPlot(curves, extras, o.plot, "--plot");
    std::cerr << "multiscaleContact: the picture of the interface is in " << o.plot << std::endl;
}

} // namespace multiscaleContact
