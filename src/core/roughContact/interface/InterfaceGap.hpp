// SPDX-License-Identifier: GPL-3.0-or-later
// The gap beside the contact: where the surfaces do not touch, heat still crosses by the gas in
// the gap and by radiation. Per face (interface/FaceCoupling.hpp):
//     h = h_c + h_g + h_r,
//     h_g = k_g(T_g)/(Y + M)   (thermal/GapConductance.hpp: M the gas rarefaction parameter,
//                               T_g = (T_f1 + T_f2)/2 the mean of the two face temperatures)
//     h_r = sigma_SB (T_f1^2 + T_f2^2)(T_f1 + T_f2)/(1/e1 + 1/e2 - 1)   (grey parallel plates)
// Both are taken over the whole nominal area, as the correlations of Yovanovich's group add them
// (h_j = h_c + h_g + h_r); at complete contact there is no gap and both are 0 (h infinite).
//
// Y, the mean-plane separation of the two rough surfaces:
//   touching faces (P > 0): the contact model's own separation where its table carries one
//     (ContactTable::meanSeparation: boundaryElement, persson, multiscaleBarber); otherwise the
//     plastic Gaussian correlation of sigma and P/H_c (gapSeparationCorrelation), sigma the
//     surfaces' combined rms height and H_c the microhardness (the `microhardness` entry, the
//     boundaryElement `hardness`, or H = 2.84 S_y of the softer side);
//   faces apart (P <= 0): the width the boundary condition gives (`gap`, `gapField`), else the
//     separation at first touch: Y at the table's lowest pressure (the surfaces resting on each
//     other with no load), said in the log.
#pragma once

#include "roughContact/thermal/GapConductance.hpp"

#include <functional>
#include <optional>

namespace roughContact {

/// h_g and h_r of one face [W/(m^2 K)].
struct GapConductances {
    double gas = 0.0;
    double radiative = 0.0;
};

/// What is in the gap, as a user describes it.
struct GapSpec {
    std::optional<GasGapSpec> gas;         ///< none: vacuum (no gas conduction)
    std::optional<double> emissivity1;     ///< radiation: both emissivities, in (0, 1], or neither
    std::optional<double> emissivity2;
};

/// The rules of a gap description, for a reader before anything is built (InterfaceGap checks
/// the same): both emissivities in (0, 1] or neither; a gas or radiation; the gas's properties,
/// pressure and accommodation coefficients (GasGap). ParameterError naming the entry.
void checkGapSpec(const GapSpec& spec);

class InterfaceGap {
public:
    /// separation: the contact model's Y(P) [m] for P > 0, or an empty function (then the
    /// correlation of sigma [m] and Hc [Pa] is used). firstTouchPressure [Pa] > 0: the pressure
    /// whose Y stands for faces apart without a given width. ParameterError naming the entry on
    /// a bad spec (neither gas nor radiation; one emissivity without the other; ...).
    InterfaceGap(const GapSpec& spec, std::function<double(double)> separation, double sigma, double Hc,
                 double firstTouchPressure);

    bool hasGas() const noexcept { return gas_.has_value(); }
    bool hasRadiation() const noexcept { return spec_.emissivity1.has_value(); }
    /// Y [m] at P > 0 (the model's or the correlation's).
    double separation(double P) const;
    /// Y [m] of faces apart with no width given.
    double firstTouchSeparation() const noexcept { return firstTouch_; }
    /// True when Y comes from the contact model (false: the correlation).
    bool separationFromModel() const noexcept { return static_cast<bool>(separation_); }
    /// h_g [W/(m^2 K)] at separation Y [m] and face temperatures T1, T2 [K]; 0 without gas.
    double gasConductance(double Y, double T1, double T2) const;
    /// h_r [W/(m^2 K)] at face temperatures T1, T2 [K]; 0 without radiation.
    double radiativeConductance(double T1, double T2) const;
    /// Both, as gasConductance and radiativeConductance give them (the same bits), with one
    /// test of the inputs: the per-face path of couple(). ParameterError naming "face
    /// temperature", "neighbour face temperature" (each within limits::minimumTemperature..
    /// maximumTemperature) or "gap separation Y".
    GapConductances conductances(double Y, double T1, double T2) const;
    const GapSpec& spec() const noexcept { return spec_; }
    /// One line for a log: gas, its pressure and M at 300 K, emissivities, where Y comes from.
    std::string summary() const;

private:
    GapSpec spec_;
    std::optional<GasGap> gas_;
    std::function<double(double)> separation_;
    double sigma_;
    double Hc_;
    double firstTouch_;
    double radiationFactor_; ///< sigma_SB greyFactor(e1, e2) [W/(m^2 K^4)], 0 without radiation
};

} // namespace roughContact
