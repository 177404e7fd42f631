// SPDX-License-Identifier: GPL-3.0-or-later
// Hertz: an elastic sphere against a rigid flat (seed Eq. 20).
#pragma once

#include "roughContact/asperity/SphericalAsperity.hpp"

namespace roughContact {

/// A = pi R w, F = (4/3) E' R^(1/2) w^(3/2); from the force, A = pi (3 F R / (4 E'))^(2/3).
class Hertz final : public SphericalAsperity {
public:
    explicit Hertz(double Eprime);

    std::string name() const override { return "hertz"; }
    bool yields() const override { return false; }
    double area(double w, double R) const override;
    double force(double w, double R) const override;
    double areaAtForce(double F, double R) const override;
    /// (4 E' / (3 R)) (A / pi)^(3/2), the inverse of areaAtForce (seed Eq. 20), raised by 1e-12
    /// for rounding.
    double forceBeyondArea(double A, double R) const override;
    /// Interference at force F: w = (3 F / (4 E' R^(1/2)))^(2/3).
    double interference(double F, double R) const;

private:
    double Eprime_;
};

} // namespace roughContact
