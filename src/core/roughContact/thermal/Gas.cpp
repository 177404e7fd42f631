// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/Gas.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

namespace {

// The reference state of the table: 300 K, 1 atm.
constexpr double tableTemperature = 300.0;
constexpr double tablePressure = standardAtmosphere;

// Karniadakis, Beskok & Aluru, "Microflows and Nanoflows", Table 1.1 (298 K, 1 atm): mean free
// path, viscosity mu, specific heat c_p and conductivity k of one row; Lambda_0 is scaled to 300 K
// (Lambda ~ T at fixed P), Pr = mu c_p / k.
constexpr double tableRowTemperature = 298.0;
double meanFreePathAt300(double lambda298) { return lambda298 * tableTemperature / tableRowTemperature; }

// k at 300 K and 400 K (CRC table via engineersedge.com, W/(m K)): k_0 and the exponent of the
// power law through both points.
double exponentFrom(double k300, double k400) { return std::log(k400 / k300) / std::log(400.0 / 300.0); }

GasProperties tabulated(const std::string& name)
{
    GasProperties g;
    g.name = name;
    g.referenceTemperature = tableTemperature;
    g.referencePressure = tablePressure;
    if (name == "air") {
        g.conductivity = 0.0262;
        g.conductivityExponent = exponentFrom(0.0262, 0.0333);
        g.heatCapacityRatio = 7.0 / 5.0;
        g.prandtl = 1.85e-5 * 1004.5 / 0.0261;
        g.meanFreePath = meanFreePathAt300(61.11e-9);
        g.accommodation = 0.9; // not verified (Gas.hpp)
    } else if (name == "helium") {
        g.conductivity = 0.1567;
        g.conductivityExponent = exponentFrom(0.1567, 0.1906);
        g.heatCapacityRatio = 5.0 / 3.0;
        g.prandtl = 1.99e-5 * 5233.5 / 0.150;
        g.meanFreePath = meanFreePathAt300(176.51e-9);
        g.accommodation = 0.4; // not verified (Gas.hpp)
    } else if (name == "argon") {
        g.conductivity = 0.0179;
        g.conductivityExponent = exponentFrom(0.0179, 0.0226);
        g.heatCapacityRatio = 5.0 / 3.0;
        g.prandtl = 2.29e-5 * 515.0 / 0.0177;
        g.meanFreePath = meanFreePathAt300(64.41e-9);
        g.accommodation = 0.9; // not verified (Gas.hpp)
    } else if (name == "nitrogen") {
        g.conductivity = 0.0260;
        g.conductivityExponent = exponentFrom(0.0260, 0.0323);
        g.heatCapacityRatio = 7.0 / 5.0;
        g.prandtl = 1.80e-5 * 1038.3 / 0.0260;
        g.meanFreePath = meanFreePathAt300(60.44e-9);
        g.accommodation = 0.85; // not verified (Gas.hpp)
    }
    return g;
}

// ParameterError(field) unless lo <= value <= hi (or lo < value when openBelow), finite.
void requireGasRange(const char* field, const GasProperties& gas, double value, double lo, double hi,
                     bool openBelow, const char* unit)
{
    const bool inside = std::isfinite(value) && (openBelow ? value > lo : value >= lo) && value <= hi;
    if (!inside) {
        std::ostringstream os;
        os << "of gas \"" << gas.name << "\" must lie within " << (openBelow ? '(' : '[') << lo << ", " << hi
           << "]" << unit << ", got " << value;
        throw ParameterError(field, os.str());
    }
}
} // namespace

const std::vector<std::string>& gasNames()
{
    static const std::vector<std::string> names{"air", "helium", "argon", "nitrogen"};
    return names;
}

GasProperties gasByName(const std::string& name)
{
    for (const std::string& known : gasNames()) {
        if (name == known) {
            return tabulated(name);
        }
    }
    std::ostringstream os;
    os << "unknown gas \"" << name << "\"; known gases:";
    for (const std::string& known : gasNames()) {
        os << ' ' << known;
    }
    os << " (or give the properties as numbers)";
    throw ParameterError("gas", os.str());
}

void checkGas(const GasProperties& gas)
{
    requireGasRange("gas conductivity k_g", gas, gas.conductivity, limits::minimumGasConductivity, limits::maximumGasConductivity,
                    false, " W/(m K)");
    requireGasRange("gas conductivity exponent", gas, gas.conductivityExponent, 0.0, limits::maximumConductivityExponent,
                    true, "");
    requireGasRange("gas reference temperature T0", gas, gas.referenceTemperature, limits::minimumTemperature,
                    limits::maximumTemperature, false, " K");
    requireGasRange("gas heat capacity ratio gamma", gas, gas.heatCapacityRatio, 1.0, limits::maximumHeatCapacityRatio,
                    true, "");
    requireGasRange("gas Prandtl number Pr", gas, gas.prandtl, limits::minimumPrandtl, limits::maximumPrandtl, false, "");
    requireGasRange("gas mean free path Lambda0", gas, gas.meanFreePath, limits::minimumLength,
                    limits::maximumLength, false, " m");
    requireGasRange("gas reference pressure P0", gas, gas.referencePressure, limits::minimumGasPressure,
                    limits::maximumGasPressure, false, " Pa");
    requireGasRange("gas accommodation coefficient", gas, gas.accommodation, limits::minimumAccommodation, 1.0, false, "");
}

} // namespace roughContact
