// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/ContactModel.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

std::vector<double> ContactModel::areaFractions(const std::vector<double>& loads) const
{
    std::vector<double> out;
    out.reserve(loads.size());
    for (double load : loads) {
        out.push_back(areaFraction(load));
    }
    return out;
}

double checkLoad(double load)
{
    if (!std::isfinite(load) || load < 0.0 || (load > 0.0 && load < limits::minimumLoad) ||
        load > limits::maximumLoad) {
        std::ostringstream os;
        os << "the load F/(A_n E') must be 0 or within [" << limits::minimumLoad << ", " << limits::maximumLoad
           << "], got " << load;
        throw ParameterError("load", os.str());
    }
    return load == 0.0 ? 0.0 : load; // -0 is 0
}

double loadOfPressure(double pressure, double Eprime)
{
    const double load = pressure / Eprime;
    // A pressure above 0 whose load underflows to 0 is as far below the range as one whose load
    // is a subnormal: both refused, not the first taken as 0.
    if (!std::isfinite(pressure) || pressure < 0.0 || (pressure > 0.0 && !(load >= limits::minimumLoad)) ||
        load > limits::maximumLoad) {
        std::ostringstream os;
        os << limits::valueText(pressure, "Pa") << " is the load F/(A_n E') = " << load << " with E' = " << Eprime
           << " Pa; loads must be 0 or within [" << limits::minimumLoad << ", " << limits::maximumLoad << "]";
        throw ParameterError("pressure", os.str());
    }
    return load == 0.0 ? 0.0 : load;
}

} // namespace roughContact
