// SPDX-License-Identifier: GPL-3.0-or-later
// Onset of yield in a hemispherical asperity (seed Eqs. 11-14, Jackson & Green 2005).
#pragma once

namespace roughContact {

/// The critical values scale with R; the coefficients here are per material.
class YieldOnset {
public:
    /// Eprime [Pa], nu of the material that yields first, Sy [Pa].
    YieldOnset(double Eprime, double nu, double Sy);

    /// C = 1.295 exp(0.736 nu) (seed Eq. 12).
    double C() const noexcept { return C_; }
    /// w_c / R = (pi C S_y / (2 E'))^2 (seed Eq. 11).
    double interferenceRatio() const noexcept { return kappa_; }
    /// w_c = (pi C S_y / (2 E'))^2 R (seed Eq. 11).
    double interference(double R) const noexcept { return kappa_ * R; }
    /// F_c = (4/3) (R/E')^2 (pi C S_y / 2)^3 (seed Eq. 13, read as docs/theory.md §3.3 explains).
    double force(double R) const noexcept;
    /// A_c = pi^3 (C S_y R / (2 E'))^2 = pi R w_c (seed Eq. 14).
    double area(double R) const noexcept;

private:
    double Eprime_;
    double Sy_;
    double C_;
    double kappa_;
};

} // namespace roughContact
