// SPDX-License-Identifier: GPL-3.0-or-later
// A picture of one's own interface (InterfaceCurves.hpp) as a PNG: every law's h_c/k_s (or h_c,
// given k_s) against the pressure on log axes, the chosen law bold, the band where the exact
// answer lies by its measured accuracy shaded, the gap's h_gas and h_rad where given, and the
// exact answer the check implies at its pressures with the seeds' spread. Drawn by gnuplot
// (Debian: gnuplot-nox), run on a script file; the PNG replaces only a PNG (Files.hpp's rules).
#pragma once

#include "roughContact/interface/InterfaceCurves.hpp"

#include <optional>
#include <string>
#include <vector>

namespace roughContact {

struct PlotExtras {
    /// k_s [W/(m K)]: draw h_c = k_s h_c/k_s [W/(m^2 K)] (and the gap's parts); none: h_c/k_s.
    std::optional<double> conductivity;
    /// h_gas and h_rad [W/(m^2 K)] at the curves' pressures (drawn with a conductivity); empty: none.
    std::vector<double> gas;
    std::vector<double> radiation;
    /// The check's exact answer for the whole surface at its pressures (SurfaceCheck::answerExactLow,
    /// answerExactHigh; NaN where not trusted, not drawn) and the law's answer there.
    struct Check {
        std::vector<double> pressures, answer, exactLow, exactHigh;
    } check;
    std::string title; ///< what the surface and materials are
};

/// Whether a file starting with `start` is a PNG (its 8-byte signature): the kind --plot replaces.
bool isPngStart(const std::string& start);

/// ParameterError(parameter, ...) when gnuplot is not on the PATH: what a front-end asks before
/// a long computation whose picture it could not draw.
void requireGnuplot(const std::string& parameter);

/// The gnuplot script that writes the picture to `pngPath` (its data inline).
std::string curvesPlotScript(const InterfaceCurves& curves, const PlotExtras& extras, const std::string& pngPath);

/// The picture written to `path` (a .png): gnuplot draws it into a temporary folder and it
/// replaces `path` only where that is a PNG or nothing. ParameterError(parameter, ...) when
/// gnuplot is missing or fails, or `path` is another kind of file.
void writeCurvesPlot(const InterfaceCurves& curves, const PlotExtras& extras, const std::string& path,
                     const std::string& parameter);

} // namespace roughContact
