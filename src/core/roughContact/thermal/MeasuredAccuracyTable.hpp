// SPDX-License-Identifier: GPL-3.0-or-later
// The measured accuracy bands of the conductance laws (MeasuredAccuracy.hpp reads them): one row
// a law, its area model ("" where it takes none), capped (the reference with the cap p <= H =
// 2.84 S_y) or elastic, a decade [from, to) of p/(E' h'), the smallest and largest law / exact
// over the surfaces measured there, how many surfaces, and which study measured them. The rows
// are MeasuredAccuracyTable.inc, written by `python3 -m validation run accuracyTable`
// (docs/validation.md) from the studies' data. The default law's unloading branch has its own
// rows, MeasuredUnloadingAccuracy.inc (from the unloading study): one a decade of the peak's
// p/(E' h').
#pragma once

namespace roughContact::measured {

struct AccuracyRow {
    const char* law;
    const char* areaModel;
    bool capped;
    double from;
    double to;
    double low;
    double high;
    int surfaces;
    const char* report;
};

inline constexpr AccuracyRow accuracyRows[] = {
#include "roughContact/thermal/MeasuredAccuracyTable.inc"
};

/// The branch's R over the exact unloading-to-loading ratio at the unloading study's counted
/// points with a peak in [from, to) (docs/validation/unloading.md).
struct UnloadingAccuracyRow {
    double from; ///< the peak's p/(E' h')
    double to;
    double leastFraction; ///< the deepest unloading measured, P/P_max
    double low;           ///< the smallest R / exact R
    double high;          ///< the largest
    int points;
    int outside; ///< points beyond 25 % of 1
};

inline constexpr UnloadingAccuracyRow unloadingAccuracyRows[] = {
#include "roughContact/thermal/MeasuredUnloadingAccuracy.inc"
};

} // namespace roughContact::measured
