// SPDX-License-Identifier: GPL-3.0-or-later
// A picture of one's own interface, as numbers: every conductance law's h_c/k_s on the whole
// surface as given (the spectrum, the surfaces' roughness and skewness: as the condition builds
// its law) over a range of pressures, and where the exact answer lies by the chosen law's
// measured band there (MeasuredAccuracy.hpp: the law over the band's high and low ends). What the
// CLI's --plot and Python's plot() draw (io/CurvesPlot.hpp; docs/checking.md, "A picture of your
// interface"); the check's answer (SurfaceCheck.hpp) is the chosen law's curve at its pressures.
#pragma once

#include "roughContact/interface/SurfaceCheck.hpp"

#include <memory>
#include <string>
#include <vector>

namespace roughContact {

class ConductanceLaw;
class MultiscaleModel;

struct LawCurve {
    std::string name;
    std::vector<double> hPerK;  ///< h_c/k_s [1/m] at InterfaceCurves::pressures
    std::string unavailable;    ///< why the law cannot be built here (then hPerK is empty)
};

struct InterfaceCurves {
    std::vector<double> pressures; ///< [Pa], increasing
    std::vector<LawCurve> laws;    ///< every law, in conductanceLawNames() order
    std::string chosenLaw;
    std::string areaModel;         ///< the multi-scale area model of the laws that take one
    bool capped = false;           ///< the chosen law held to the capped reference
    double gradient = 0.0;         ///< h' of the whole surface
    double reducedModulus = 0.0;   ///< E' [Pa]
    /// Where the exact h_c/k_s lies [1/m] if the chosen law misses it as the studies measured
    /// there: its h_c/k_s over the band's high and low ends; NaN where nothing was measured.
    std::vector<double> exactLow;
    std::vector<double> exactHigh;

    /// The chosen law's curve (ParameterError when it is not among laws).
    const LawCurve& chosen() const;
};

/// The hardness a check or a picture caps at: `in.hardness`, else 2.84 S_y of the yielding
/// material, else none (elastic).
std::optional<double> capOf(const SurfaceCheckInputs& in);

/// The law `name` on the whole surface as given, as the condition builds it: on the spectrum
/// `given` (equivalentSurface of in.surfaces) with the area model `multiscale` built on it, the
/// surfaces' roughness and skewness, the microhardness (or the cap) and Vickers coefficients.
/// ParameterError where the law cannot be built from these.
std::unique_ptr<ConductanceLaw> wholeSurfaceLaw(const std::string& name, const SurfaceCheckInputs& in,
                                                const Spectrum& given, const MultiscaleModel& multiscale);

/// Every law at `pressures` [Pa] (each > 0 and finite, at most limits' count), with the chosen
/// law's measured band. ParameterError on bad inputs.
InterfaceCurves interfaceCurves(const SurfaceCheckInputs& in, const std::vector<double>& pressures);

/// n pressures [Pa] spaced evenly in log from `low` to `high` (0 < low <= high; n >= 2), the
/// grid a picture draws its curves on.
std::vector<double> logSpacedPressures(double low, double high, std::size_t n);

/// The points of a picture's curves, unless asked otherwise: smooth on a log axis.
inline constexpr std::size_t defaultPlotPoints = 60;

/// The pressures a picture draws its curves on: n log-spaced from `low` to `high` [Pa], a decade
/// each way of a single pressure, and with `marked` points at the ends (a check's) a factor of 1.5
/// beyond them so that the points are not cut by the frame.
std::vector<double> plotPressures(double low, double high, bool marked, std::size_t n = defaultPlotPoints);

} // namespace roughContact
