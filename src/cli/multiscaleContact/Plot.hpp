// SPDX-License-Identifier: GPL-3.0-or-later
// --plot FILE.png: the picture of the interface (io/CurvesPlot.hpp) from the run's options.
#pragma once

#include "Inputs.hpp"
#include "GapInputs.hpp"
#include "Options.hpp"

#include "roughContact/interface/InterfaceGap.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"

#include <optional>
#include <vector>

namespace multiscaleContact {

// The picture across the run's pressures [Pa] (a decade each way of a single one), with k_s and
// the gap's parts where given and the check's answer when given; says on stderr where it is.
// ParameterError("--plot", ...) where it cannot be drawn.
void writePlot(const Options& o, const std::vector<double>& pressures, const std::optional<double>& ks,
               const roughContact::InterfaceGap* gap, const GapInputs* gapInputs,
               const roughContact::SurfaceCheck* check);

} // namespace multiscaleContact
