// SPDX-License-Identifier: GPL-3.0-or-later
// Heat transfer across the gas-filled and radiating gap of a joint of nominally flat rough
// surfaces, beside the solid spots (Mikic.hpp, CooperMikicYovanovich.hpp): the joint conductance
// is h_j = h_c + h_g + h_r.
//
// Gas gap (the model of Yovanovich's group: Bahrami, Yovanovich & Culham, "Thermal joint
// resistances of conforming rough surfaces with gas-filled gaps" and "... of nonconforming rough
// surfaces with gas-filled gaps", J. Thermophys. Heat Transfer 18(3) (2004); Yovanovich, "Four
// decades of research on thermal contact, gap, and joint resistance in microelectronics", IEEE
// Trans. Comp. Packag. Technol. 28(2) (2005) 182-206):
//
//   h_g = k_g(T) / (Y + M)                                   parallel plates Y apart with a
//                                                            temperature jump at each face
//   M   = [ (2 - a1)/a1 + (2 - a2)/a2 ] [ 2 gamma/(gamma + 1) ] Lambda / Pr    gas parameter
//   Lambda = Lambda_0 (T/T_0) (P_0/P_g)                      mean free path
//
// a1, a2 the thermal accommodation coefficients of the two faces, gamma, Pr, k_g(T), Lambda_0 the
// gas's (Gas.hpp), P_g the gas pressure. h_g -> k_g/Y when Y >> M (continuum) and -> k_g/M when
// Y << M (free-molecular; then h_g is proportional to P_g, as M ~ 1/P_g). What was checked: the
// form of M against two independent implementations found by code search (chaos-polymtl/lethe,
// DEM heat transfer: gas parameter 2 (2-a)/a 2gamma/(1+gamma) Lambda/Pr for a1 = a2 = a; and a
// CFD code's temperature-slip wall, ((2-a)/a) 2gamma/(gamma+1) Lambda/Pr per face). The papers
// themselves could not be read here (only their first pages: titles, abstracts, nomenclature
// with "gas parameter M", "mean surface plane separation Y", "thermal accommodation coefficient",
// "ratio of gas specific heats", "mean free path", Pr): no equation numbers are given, and
// h_g = k_g/(Y + M) as the gap law, one relation from the continuum to the free-molecular regime
// as the abstracts describe, is NOT VERIFIED against their text.
//
// Mean-plane separation Y of a plastically deformed Gaussian rough contact (the model of Cooper,
// Mikic & Yovanovich 1969: the real contact fraction is A_r/A_a = P/H_c = (1/2) erfc(Y/(sqrt(2)
// sigma)), H_c the microhardness):
//
//   Y/sigma = sqrt(2) erfc^-1(2 P/H_c)                        exact for Gaussian heights
//   Y/sigma = 1.184 [ -ln(3.132 P/H_c) ]^0.547                the published fit of it (attributed
//                                                             to Antonetti, Whittle & Simons 1991
//                                                             and quoted by Yovanovich 2005; NOT
//                                                             VERIFIED: paper, equation number and
//                                                             its stated range of P/H_c could not
//                                                             be read)
//
// sigma the joint's combined rms roughness. The fit was measured here against the exact form: within
// 0.9% for 1e-6 <= P/H_c <= 0.1 (largest +0.90% near P/H_c = 0.05, -0.25% near 6e-5); beyond
// 0.1 it falls away (-7% at 0.2) and at P/H_c = 1/3.132 = 0.319 the logarithm's argument reaches 1
// (Y = 0; beyond, a NaN). gapSeparationCorrelation therefore uses the fit only within
// [correlationMinimumRelativePressure, correlationMaximumRelativePressure] = [1e-6, 0.1] and the
// exact Gaussian form outside (a step of at most 0.3% where it switches); no NaN for any P > 0.
// The exact form: Y falls to 0 at P/H_c = 1/2 (half the area in contact; the Gaussian model
// means nothing beyond) and is 0 from there on (the gap closed: h_g = k_g/M); as P -> 0 it
// grows without bound but slowly (Y/sigma = 4.75 at 1e-6, 11.5 at 1e-30): P/H_c below
// minimumRelativePressure (1e-300, Y/sigma = 37.0) is taken as 1e-300. P <= 0 (no contact, the
// faces apart) is a ParameterError: the caller handles an open gap itself.
//
// Radiation across the gap, grey diffuse parallel plates (the standard two-surface enclosure
// result, e.g. Incropera's textbook; the formula is checked by its two limits in the tests):
//
//   h_r = sigma_SB (T1^2 + T2^2)(T1 + T2) / (1/e1 + 1/e2 - 1)
//
// evaluated with 1/(1/e1 + 1/e2 - 1) = e_min/(e_min/e_max + 1 - e_min), finite and accurate for
// any e in (0, 1]. sigma_SB is defined here, the core's one place for it (src/core/roughContact has no
// constants header): the CODATA 2018 value, exact in the 2019 SI, checked against two physical
// constant libraries (Rust physical_constants, Dart quantify) through the docs search.
#pragma once

#include "roughContact/thermal/Gas.hpp"

#include <cmath>
#include <optional>

namespace roughContact {

/// Stefan-Boltzmann constant [W/(m^2 K^4)] (CODATA 2018, exact in the 2019 SI).
constexpr double stefanBoltzmann = 5.670374419e-8;

struct GasGapSpec {
    GasProperties gas;
    double pressure = standardAtmosphere;          ///< gas pressure P_g [Pa]
    /// The thermal accommodation coefficients of the two surfaces, in (0, 1]; unset: the gas's
    /// default (GasProperties::accommodation). There is no number meaning "default": 0 is an
    /// error, as any value outside the range (1e-300 too, which OpenFOAM reads as 0).
    std::optional<double> accommodation1, accommodation2;
};

class GasGap {
public:
    /// Validates: checkGas(spec.gas), "gas pressure P_g" within limits::minimumGasPressure..
    /// maximumGasPressure, "accommodation coefficient a1"/"a2" unset (the gas's default) or within
    /// [limits::minimumAccommodation, 1]. ParameterError naming the entry otherwise.
    explicit GasGap(const GasGapSpec& spec);

    /// k_g(T) [W/(m K)]; T [K] within limits::minimumTemperature..maximumTemperature
    /// (ParameterError naming "gas temperature T").
    double conductivity(double T) const;
    /// Lambda = Lambda0 (T/T0)(P0/P_g) [m].
    double meanFreePath(double T) const;
    /// M = [(2-a1)/a1 + (2-a2)/a2] [2 gamma/(gamma+1)] Lambda/Pr [m].
    double rarefaction(double T) const;
    /// h_g = k_g(T)/(Y + M) [W/(m^2 K)]; Y [m] finite, within [0, limits::maximumLength]
    /// (ParameterError naming "gap separation Y").
    double conductance(double Y, double T) const;
    /// conductance(Y, T) for a Y and T the caller has checked as conductance() would (Y within
    /// [0, limits::maximumLength], T within limits::minimumTemperature..maximumTemperature): the
    /// same arithmetic, the same bits, without the checks. Inline: the per-face path
    /// (InterfaceGap::conductances) calls it once per face and evaluation.
    double conductanceOfChecked(double Y, double T) const
    {
        return conductivityOfChecked(T) / (Y + alphaBeta_ * meanFreePathOfChecked(T));
    }
    /// The spec as validated, with the accommodation coefficients resolved (both set: an unset
    /// one is the gas's default).
    const GasGapSpec& spec() const { return spec_; }

private:
    // The formulas themselves (k_g(T), Lambda(T)), for a T already checked.
    double conductivityOfChecked(double T) const
    {
        return spec_.gas.conductivity * std::pow(T / spec_.gas.referenceTemperature, spec_.gas.conductivityExponent);
    }
    double meanFreePathOfChecked(double T) const
    {
        return spec_.gas.meanFreePath * (T / spec_.gas.referenceTemperature) * (spec_.gas.referencePressure / spec_.pressure);
    }

    GasGapSpec spec_;
    double alphaBeta_; ///< [(2-a1)/a1 + (2-a2)/a2] 2 gamma/((gamma+1) Pr)
};

/// Grey diffuse parallel plates: h_r = sigma_SB (T1^2 + T2^2)(T1 + T2) / (1/e1 + 1/e2 - 1)
/// [W/(m^2 K)]; T within limits::minimumTemperature..maximumTemperature [K] ("temperature T1",
/// "temperature T2"), e in (0, 1] ("emissivity e1", "emissivity e2").
double radiativeConductance(double T1, double T2, double e1, double e2);

/// The grey factor 1/(1/e1 + 1/e2 - 1) of two emissivities in (0, 1] (checked by the caller),
/// written e_min/(e_min/e_max + 1 - e_min): no 1/e and no product e1 e2 that could underflow, so
/// finite and accurate for every e in (0, 1] (the denominator lies in (0, 2]).
double greyFactor(double e1, double e2);

/// h_r = factor (T1^2 + T2^2)(T1 + T2), factor = sigma_SB greyFactor(e1, e2) [W/(m^2 K^4)], for
/// temperatures the caller has checked: radiativeConductance()'s arithmetic without the checks.
/// Inline: per face (InterfaceGap::conductances).
inline double radiativeConductanceOfChecked(double T1, double T2, double factor)
{
    return factor * ((T1 * T1 + T2 * T2) * (T1 + T2));
}

/// P/H_c range over which gapSeparationCorrelation uses the published fit (header comment).
constexpr double correlationMinimumRelativePressure = 1e-6;
constexpr double correlationMaximumRelativePressure = 0.1;
/// P/H_c below this is taken as this by both forms (Y/sigma = 37.0 there).
constexpr double minimumRelativePressure = 1e-300;

/// Mean-plane separation Y [m] of a plastically deformed Gaussian rough contact from the published
/// fit Y = 1.184 sigma (-ln(3.132 P/H_c))^0.547 within [1e-6, 0.1] of P/H_c, the exact Gaussian
/// form outside (header comment). P [Pa] ("contact pressure P") and H_c [Pa] ("microhardness
/// H_c") finite and > 0, sigma [m] ("rms roughness sigma") within limits::minimumRoughness..
/// maximumHeight; ParameterError otherwise.
double gapSeparationCorrelation(double P, double sigma, double Hc);
/// The exact form for Gaussian heights: Y = sqrt(2) sigma erfc^-1(2 P/H_c) for P/H_c < 1/2, 0 from
/// there on. Same inputs and errors.
double gapSeparationGaussian(double P, double sigma, double Hc);

} // namespace roughContact
