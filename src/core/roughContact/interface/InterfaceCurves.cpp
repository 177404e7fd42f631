// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/interface/InterfaceCurves.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"

#include <cmath>
#include <limits>

namespace roughContact {

const LawCurve& InterfaceCurves::chosen() const
{
    for (const LawCurve& l : laws) {
        if (l.name == chosenLaw) {
            return l;
        }
    }
    throw ParameterError("conductance", "the chosen law '" + chosenLaw + "' is not among the curves");
}

std::optional<double> capOf(const SurfaceCheckInputs& in)
{
    if (in.hardness) {
        return in.hardness;
    }
    if (in.materials && in.materials->hasYieldStrength()) {
        return in.materials->hardness("check");
    }
    return std::nullopt;
}

std::unique_ptr<ConductanceLaw> wholeSurfaceLaw(const std::string& name, const SurfaceCheckInputs& in,
                                                const Spectrum& given, const MultiscaleModel& multiscale)
{
    ConductanceLawInputs law;
    law.multiscale = &multiscale;
    law.spectrum = &given;
    law.Eprime = in.materials->reducedModulus();
    law.roughness = equivalentRoughness(in.surfaces);
    law.skewness = equivalentSkewness(in.surfaces);
    law.microhardness = in.microhardness ? in.microhardness : capOf(in);
    law.hardness = law.microhardness;
    law.vickers = in.vickers;
    return makeConductanceLaw(name, law);
}

std::vector<double> logSpacedPressures(double low, double high, std::size_t n)
{
    if (!std::isfinite(low) || !std::isfinite(high) || !(low > 0.0) || !(high >= low) || n < 2) {
        throw ParameterError("pressures", "a range of pressures needs 0 < low <= high, finite, and 2 or more points");
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back(i + 1 == n ? high : low * std::pow(high / low, double(i) / double(n - 1)));
    }
    return out;
}

std::vector<double> plotPressures(double low, double high, bool marked, std::size_t n)
{
    const bool one = std::isfinite(low) && std::isfinite(high) && high <= low * 1.0000001;
    const double pad = one ? 10.0 : marked ? 1.5 : 1.0;
    return logSpacedPressures(low / pad, high * pad, n);
}

InterfaceCurves interfaceCurves(const SurfaceCheckInputs& in, const std::vector<double>& pressures)
{
    if (!in.materials) {
        throw ParameterError("materials", "the curves need the materials of the two solids");
    }
    if (pressures.empty()) {
        throw ParameterError("pressures", "give at least one pressure");
    }
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        if (!std::isfinite(pressures[i]) || !(pressures[i] > 0.0) || (i > 0 && !(pressures[i] > pressures[i - 1]))) {
            throw ParameterError("pressures", "the curves' pressures must be finite, above 0 and increasing; one is " +
                                                  limits::valueText(pressures[i], "Pa"));
        }
    }
    InterfaceCurves out;
    out.pressures = pressures;
    const ContactMaterials& materials = *in.materials;
    const double Ep = materials.reducedModulus();
    out.reducedModulus = Ep;
    const std::optional<double> cap = capOf(in);
    out.areaModel = isMultiscaleModel(in.model) ? in.model : (cap ? std::string("jacksonGreen") : std::string("hertz"));
    out.chosenLaw = in.conductanceLaw.empty() ? defaultConductanceLaw() : in.conductanceLaw;
    if (!isConductanceLaw(out.chosenLaw)) {
        throw ParameterError("conductance", "unknown law '" + out.chosenLaw + "'");
    }
    const Spectrum given = equivalentSurface(in.surfaces);
    const MultiscaleModel multiscale(given, Ep, makeAsperityModel(out.areaModel, materials));
    for (const std::string& name : conductanceLawNames()) {
        LawCurve curve;
        curve.name = name;
        try {
            const std::unique_ptr<ConductanceLaw> law = wholeSurfaceLaw(name, in, given, multiscale);
            for (double P : pressures) {
                curve.hPerK.push_back(law->perConductivity(P));
            }
        } catch (const ParameterError& e) {
            if (name == out.chosenLaw) {
                throw;
            }
            curve.unavailable = e.what();
            curve.hPerK.clear();
        }
        out.laws.push_back(curve);
    }
    // The chosen law's band, as the regime line quotes it (InterfaceRegime.hpp).
    const std::optional<double> lawCap = in.microhardness ? in.microhardness : cap;
    out.capped = heldToCappedReference(out.areaModel, out.chosenLaw, lawCap.has_value());
    const InterfaceRegime regime =
        interfaceRegime(given, Ep, lawCap, out.chosenLaw, out.areaModel, out.capped, pressures.front(), pressures.back());
    out.gradient = regime.gradient;
    const LawCurve& chosen = out.chosen();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < pressures.size(); ++i) {
        const RegimeAt r = regime.at(pressures[i]);
        out.exactLow.push_back(r.band ? chosen.hPerK[i] / r.band->high : nan);
        out.exactHigh.push_back(r.band ? chosen.hPerK[i] / r.band->low : nan);
    }
    return out;
}

} // namespace roughContact
