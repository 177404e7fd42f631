// SPDX-License-Identifier: GPL-3.0-or-later
// How far each conductance law was measured from the exact answer: the band
// of law / exact the engineering-range study (docs/validation/engineeringRange.md; the fidelity
// study, docs/validation/fidelity.md, for the area models it does not run) found for a law on
// its area model, against the elastic or the capped (p <= H) reference, in a decade of
// p/(E' h'). The numbers are the studies', in one place: MeasuredAccuracyTable.hpp, whose rows
// `python3 -m validation run accuracyTable` writes from the studies' tables (a CTest test keeps
// them equal).
#pragma once

#include <optional>
#include <string>

namespace roughContact {

/// Below this p/(E' h') a periodic cell may conduct more than a large joint of the same finish: the
/// exact answer at 1e-4 on periods of 8L was well below one period L's where the longest wave
/// holds most of the heights (down to a quarter), about the same where the spectrum rolls off well
/// below it, and not yet converged (8L within 10 % of 4L) on the spectra without a roll-off
/// (docs/validation/engineeringRange.md, "Light loads: how large a period"). The bands
/// measured below it say so (describeAccuracy; a band is [from, to), so the one that starts at
/// 1e-3 does not), and so does the check of a profile or a spectrum (SurfaceCheck::smallCellNote).
inline constexpr double smallCellLoadPerGradient = 1e-3;

struct AccuracyBand {
    /// The decade of p/(E' h') [from, to) the band was measured in; `to` is below the decade's end
    /// where the study measured less of it (its top decade: x = 0.1 only; the heavy-load study:
    /// from just above 0.1 to its heaviest load).
    double from = 0.0;
    double to = 0.0;
    double low = 0.0;  ///< the smallest law / exact over the study's surfaces there
    double high = 0.0; ///< the largest
    int surfaces = 0;  ///< how many of the study's surfaces had a point there
    std::string report; ///< which study measured it ("engineering-range study", "fidelity study", "heavy-load study")
};

/// The band of `law` on `areaModel` (a multi-scale model's name; ignored for the laws that take
/// no area: persson, mikic, cooperMikicYovanovich) against the capped or the elastic reference,
/// in the decade of p/(E' h') that holds loadPerGradient; none where no study has a number
/// (a law or model it does not measure, a load outside 1e-5 to 1).
std::optional<AccuracyBand> measuredAccuracy(const std::string& law, const std::string& areaModel, bool capped,
                                             double loadPerGradient);

/// One line: "0.30-0.86 of exact (4 surfaces of the engineering-range study, p/(E' h') 0.0001 to
/// 0.001)" or "not measured at
/// p/(E' h') = ...". A band below smallCellLoadPerGradient adds that it was measured against
/// periodic cells, which may conduct more than a large joint there.
std::string describeAccuracy(const std::optional<AccuracyBand>& band, double loadPerGradient);

/// How far the default law's unloading branch (fittedElastoPlastic with a cap, docs/theory.md
/// §5.7c) was measured from the exact model: its R over the exact unloading-to-loading ratio, at
/// the unloading study's points whose peaks lie in [from, to) of p/(E' h'), unloaded to
/// leastFraction of the peak at the deepest. The error of h on unloading is this times the
/// loading band's at the pressure of the moment.
struct UnloadingAccuracyBand {
    double from = 0.0; ///< the peaks' p/(E' h'), over the decades the peaks asked for span
    double to = 0.0;
    double leastFraction = 0.0; ///< P/P_max: deeper unloading was not measured
    double low = 0.0;           ///< the smallest R / exact R
    double high = 0.0;          ///< the largest
    int points = 0;
    int outside = 0; ///< points beyond 25 % of 1
};

/// The branch's band over every decade that holds a peak from peakMin to peakMax (p/(E' h'), >
/// 0, peakMin <= peakMax); none where a peak lies outside what the study measured.
std::optional<UnloadingAccuracyBand> measuredUnloadingAccuracy(double peakMin, double peakMax);

/// One line: "R / exact R 0.733-1.3 at 256 points of the unloading studies (peaks p/(E' h') 0.001
/// to 0.01, unloaded down to P/P_max = 0.033; 5 outside 25 %)", or that the peaks from peakMin
/// to peakMax were not measured (and which the studies measured).
std::string describeUnloadingAccuracy(const std::optional<UnloadingAccuracyBand>& band, double peakMin,
                                      double peakMax);

} // namespace roughContact
