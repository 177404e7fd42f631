// SPDX-License-Identifier: GPL-3.0-or-later
// The interstitial gas of a gas-filled joint: the properties the gap conductance needs
// (GapConductance.hpp) and a small table of common gases.
//
//   k_g(T)      = k_0 (T/T_0)^n                      power law about the reference temperature T_0
//   Lambda(T,P) = Lambda_0 (T/T_0) (P_0/P)           mean free path of a dilute gas (at fixed
//                                                    number density Lambda is constant; at fixed P
//                                                    it grows as T)
//   Pr = mu c_p / k,   gamma = c_p / c_v
//
// The table (gasByName), with the source of every number and how far it was checked. The
// reference state is T_0 = 300 K, P_0 = 101325 Pa (1 atm) for all four gases.
//
// k_0 [W/(m K)] at 300 K and the exponent n: CRC Handbook table of gas thermal conductivities at
//   100 kPa as reproduced by engineersedge.com ("Thermal Conductivity of Gases Chart", mW/(m K)):
//   air 26.2 (300 K) / 33.3 (400 K), helium 156.7 / 190.6, argon 17.9 / 22.6, nitrogen 26.0 / 32.3.
//   k_0 is the 300 K value; n = ln(k_400/k_300)/ln(400/300), the power law through both points:
//   air 0.834, helium 0.681, argon 0.810, nitrogen 0.754. CHECKED against that table (the 100 kPa
//   and 1 atm values differ by far less than its last digit). A second table, Karniadakis, Beskok &
//   Aluru, "Microflows and Nanoflows" (Springer 2005) Table 1.1 at 298 K, gives air 0.0261,
//   N2 0.0260, Ar 0.0177, He 0.150: within 1% of the above for air, N2 and Ar, 4% below for He.
//   The power law is a two-point fit: within 4% of the same table from 200 K to 600 K (air 18.4
//   at 200 K, law 18.7; 45.7 at 600 K, law 46.7; argon is the worst, +3.9% at 200 K); outside
//   that span it is an extrapolation.
// Lambda_0 [m] at 300 K, 1 atm: Karniadakis, Beskok & Aluru Table 1.1 (298 K, 1 atm, hard-sphere
//   mean free path): air 61.11 nm, N2 60.44 nm, He 176.51 nm, Ar 64.41 nm, scaled to 300 K by
//   Lambda ~ T (x 300/298). CHECKED against that table. Other definitions of the mean free path
//   give other numbers: the values the Yovanovich group's gap papers use (about 64 nm for air at
//   288 K, 186 nm for helium) are NOT verified here and are 8-10% above these at the same T. M,
//   hence the gap conductance near the free-molecular limit, scales with Lambda_0.
// Pr [-]: mu c_p / k from the same row of Karniadakis et al. Table 1.1 (air 1.85e-5 x 1004.5 /
//   0.0261 = 0.712, N2 0.719, He 0.694, Ar 0.666). CHECKED (computed from that table).
// gamma [-]: 7/5 for the diatomic gases (air, N2), 5/3 for the monatomic (He, Ar): the ideal-gas
//   values. Checked against the same table: c_p/(c_p - R_specific) from its c_p gives air 1.400,
//   N2 1.400, He 1.66, Ar 1.68.
// accommodation [-], the default thermal accommodation coefficient of both faces: air 0.9,
//   helium 0.4, argon 0.9, nitrogen 0.85. NOT VERIFIED: representative values for engineering
//   metal (steel, aluminium) surfaces within the ranges usually quoted (air and nitrogen 0.8-0.9,
//   argon about 0.9, helium 0.3-0.55); neither Song & Yovanovich's correlation of accommodation
//   coefficients nor a table of Bahrami, Culham & Yovanovich could be reached to check them. The
//   coefficient depends on the surface (material, contamination, temperature) more than on the
//   gas table; give measured values (GasGapSpec::accommodation1/2) when they are known.
#pragma once

#include <string>
#include <vector>

namespace roughContact {

/// One standard atmosphere [Pa]: the gases' reference pressure P_0 and the gap's default gas
/// pressure (the one place of the number: the dictionary and Python take their defaults from here).
inline constexpr double standardAtmosphere = 101325.0;

struct GasProperties {
    std::string name;                  ///< "air", or "user" for numbers given
    double conductivity = 0;           ///< k_g [W/(m K)] at referenceTemperature
    double conductivityExponent = 0;   ///< k_g(T) = conductivity * (T/referenceTemperature)^exponent
    double referenceTemperature = 0;   ///< T0 [K]
    double heatCapacityRatio = 0;      ///< gamma [-]
    double prandtl = 0;                ///< Pr [-]
    double meanFreePath = 0;           ///< Lambda0 [m] at T0 and referencePressure
    double referencePressure = standardAtmosphere; ///< P0 [Pa]
    double accommodation = 0;          ///< a typical thermal accommodation coefficient on engineering
                                       ///< metal surfaces (the default for both sides)
};

/// The names gasByName knows, in table order: air, helium, argon, nitrogen.
const std::vector<std::string>& gasNames();

/// The tabulated properties of a gas (header comment: sources). ParameterError naming "gas"
/// and listing the known names for any other name (the match is exact, lower case).
GasProperties gasByName(const std::string& name);

/// ParameterError naming the first bad field ("gas conductivity k_g", "gas conductivity
/// exponent", "gas reference temperature T0", "gas heat capacity ratio gamma", "gas Prandtl
/// number Pr", "gas mean free path Lambda0", "gas reference pressure P0", "gas accommodation
/// coefficient"): every number finite and > 0 and within the ranges of Limits.hpp (limits::minimumGasConductivity ...), gamma > 1,
/// accommodation in (0, 1], T0 within limits::minimumTemperature..maximumTemperature, P0 within
/// limits::minimumGasPressure..maximumGasPressure, Lambda0 within the accepted lengths
/// (limits::minimumLength..maximumLength).
void checkGas(const GasProperties& gas);

} // namespace roughContact
