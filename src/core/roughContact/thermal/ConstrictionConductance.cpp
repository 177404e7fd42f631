// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughContact {

double constrictionFactor(double eps)
{
    if (std::isnan(eps) || eps < 0.0 || eps > 1.0) {
        throw ParameterError("constriction ratio a/b", "must lie in [0, 1]");
    }
    const double g = 1.0 - eps;
    return g * std::sqrt(g);
}

double constrictionConductancePerConductivity(const std::vector<LevelState>& trace, double An)
{
    requirePositive("nominal area A_n", An);
    if (trace.empty() || !(trace.back().area > 0.0)) {
        return 0.0;
    }
    double resistance = 0.0; // R k_s [1/m]
    double previousArea = An;
    for (const LevelState& s : trace) {
        // A level may only keep or shrink the area (assumption 5 caps it at A_{i-1}).
        const double eps = std::sqrt(std::min(1.0, s.area / previousArea));
        if (eps < 1.0) {
            const double a = std::sqrt(s.area / (pi * s.asperities));
            resistance += constrictionFactor(eps) / (2.0 * a * s.asperities);
        }
        previousArea = s.area;
    }
    if (resistance == 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    return 1.0 / (resistance * An);
}

double constrictionConductancePerConductivity(const MultiscaleModel& model, double load)
{
    return constrictionConductancePerConductivity(model.trace(checkLoad(load)), model.nominalArea());
}

} // namespace roughContact
