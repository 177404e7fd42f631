// SPDX-License-Identifier: GPL-3.0-or-later
// The measured accuracy bands of the conductance laws (MeasuredAccuracy.hpp reads them): one row
// a law, its area model ("" where it takes none), capped (the reference with the cap p <= H =
// 2.84 S_y) or elastic, a decade [from, to) of p/(E' h'), the smallest and largest law / exact
// over the surfaces measured there, how many surfaces, and which study measured them. The rows
// are MeasuredAccuracyTable.inc, written by `python3 -m validation run accuracyTable`
// (docs/validation.md) from the studies' data.
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

} // namespace roughContact::measured
