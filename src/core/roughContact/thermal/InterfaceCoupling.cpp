// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/InterfaceCoupling.hpp"

#include "roughContact/Error.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

namespace detail {

void badCoupling(double h, double kDelta, double kDeltaNbr)
{
    std::ostringstream os;
    if (std::isnan(h) || h < 0.0) {
        os << "must be >= 0 (+inf for complete contact), got " << h;
        throw ParameterError("interface conductance h", os.str());
    }
    requirePositive("kappa*deltaCoeff", kDelta);
    requirePositive("neighbour kappa*deltaCoeff", kDeltaNbr);
    throw ParameterError("interface coupling", "bad input"); // not reached
}

} // namespace detail

} // namespace roughContact
