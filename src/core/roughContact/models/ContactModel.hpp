// SPDX-License-Identifier: GPL-3.0-or-later
// What every rough-surface contact model answers: real contact area at a load.
#pragma once

#include <string>
#include <vector>

namespace roughContact {

class ContactModel {
public:
    virtual ~ContactModel() = default;

    /// The name users select it by (`hertz`, ..., `greenwoodWilliamson`, `majumdarBhushan`).
    virtual std::string name() const = 0;

    /// Real contact area fraction A_r / A_n (in [0, 1]) at the dimensionless load
    /// F / (A_n E') (>= 0, finite; ParameterError otherwise).
    virtual double areaFraction(double load) const = 0;

    /// areaFraction at each load.
    std::vector<double> areaFractions(const std::vector<double>& loads) const;
};

/// Throws ParameterError unless load is finite and >= 0.
double checkLoad(double load);
/// The load F/(A_n E') = P/E' of a nominal pressure P [Pa] within checkLoad's range (-0 read as
/// 0); a pressure above 0 whose load falls below the range, an underflow to 0 included, is
/// refused as such. ParameterError("pressure", ...) naming P, E' and the load otherwise.
double loadOfPressure(double pressure, double Eprime);

} // namespace roughContact
