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
    return load;
}

} // namespace roughContact
