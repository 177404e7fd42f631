// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include "roughContact/thermal/MeasuredAccuracyTable.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace roughContact {

std::optional<AccuracyBand> measuredAccuracy(const std::string& law, const std::string& areaModel, bool capped,
                                             double loadPerGradient)
{
    const bool takesArea = law == "jacksonBhavnaniFerguson" || law == "multiscaleBarber";
    for (const measured::AccuracyRow& r : measured::accuracyRows) {
        if (law == r.law && (!takesArea || areaModel == r.areaModel) && capped == r.capped &&
            loadPerGradient >= r.from && loadPerGradient < r.to) {
            return AccuracyBand{r.from, r.to, r.low, r.high, r.surfaces, r.report};
        }
    }
    return std::nullopt;
}

namespace {

/// A band's end as the table holds it (three significant digits, as README.md's table and the
/// pages show it), a whole number below 10 with its ".0" (1.0, not 1).
std::string bandEnd(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    std::string s(text);
    if (s.find_first_of(".e") == std::string::npos && std::fabs(v) < 10.0) {
        s += ".0";
    }
    return s;
}

} // namespace

std::string describeAccuracy(const std::optional<AccuracyBand>& band, double loadPerGradient)
{
    std::ostringstream os;
    os << std::setprecision(2);
    if (!band) {
        os << "not measured at p/(E' h') = " << loadPerGradient;
        return os.str();
    }
    os << bandEnd(band->low) << "-" << bandEnd(band->high) << " of exact (" << band->surfaces
       << (band->surfaces == 1 ? " surface" : " surfaces") << " of the " << band->report << ", p/(E' h') ";
    if (band->to < 1.01 * band->from) {
        os << "= " << band->from << " only, the largest measured"; // the top of the study's range
    } else {
        os << band->from << " to " << band->to;
    }
    os << ")";
    if (band->to <= smallCellLoadPerGradient * (1.0 + 1e-9)) {
        os << "; measured against periodic cells, which may conduct more than a large joint at these loads "
              "(docs/checking.md)";
    }
    return os.str();
}

std::optional<UnloadingAccuracyBand> measuredUnloadingAccuracy(double peakMin, double peakMax)
{
    std::optional<UnloadingAccuracyBand> out;
    for (const measured::UnloadingAccuracyRow& r : measured::unloadingAccuracyRows) {
        if (!(r.from <= peakMax && peakMin < r.to)) {
            continue;
        }
        if (!out) {
            out = UnloadingAccuracyBand{r.from, r.to, r.leastFraction, r.low, r.high, r.points, r.outside};
            continue;
        }
        if (r.from != out->to) { // a gap between the decades: not measured there
            return std::nullopt;
        }
        out->to = r.to;
        out->leastFraction = std::max(out->leastFraction, r.leastFraction);
        out->low = std::min(out->low, r.low);
        out->high = std::max(out->high, r.high);
        out->points += r.points;
        out->outside += r.outside;
    }
    if (!out || peakMin < out->from || !(peakMax < out->to)) {
        return std::nullopt;
    }
    return out;
}

std::string describeUnloadingAccuracy(const std::optional<UnloadingAccuracyBand>& band, double peakMin,
                                      double peakMax)
{
    std::ostringstream os;
    os << std::setprecision(2);
    if (!band) {
        os << "the unloading branch was not measured for peaks at p/(E' h') = " << peakMin;
        if (peakMax > peakMin) {
            os << " to " << peakMax;
        }
        const auto& rows = measured::unloadingAccuracyRows;
        os << " (the unloading study's peaks: " << rows[0].from << " to "
           << rows[sizeof rows / sizeof rows[0] - 1].from << ")";
        return os.str();
    }
    os << "R / exact R " << bandEnd(band->low) << "-" << bandEnd(band->high) << " at " << band->points
       << " points of the unloading studies (peaks p/(E' h') ";
    if (band->to < 1.01 * band->from) {
        os << "= " << band->from << " only";
    } else {
        os << band->from << " to " << band->to;
    }
    os << ", unloaded down to P/P_max = " << band->leastFraction << "; " << band->outside << " outside 25 %)";
    return os.str();
}

} // namespace roughContact
