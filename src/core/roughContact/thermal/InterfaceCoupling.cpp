#include "roughContact/thermal/InterfaceCoupling.hpp"

#include "roughContact/Error.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

namespace {

void requireConductance(double h)
{
    if (!(h >= 0.0)) { // also NaN
        std::ostringstream os;
        os << "must be >= 0 (+inf for complete contact), got " << h;
        throw ParameterError("interface conductance h", os.str());
    }
}

} // namespace

double effectiveConductance(double h, double kDeltaNbr)
{
    requireConductance(h);
    requirePositive("neighbour kappa*deltaCoeff", kDeltaNbr);
    if (std::isinf(h)) {
        return kDeltaNbr;
    }
    return h * kDeltaNbr / (h + kDeltaNbr);
}

double coupledValueFraction(double h, double kDelta, double kDeltaNbr)
{
    requirePositive("kappa*deltaCoeff", kDelta);
    const double hEff = effectiveConductance(h, kDeltaNbr);
    return hEff / (hEff + kDelta);
}

} // namespace roughContact
