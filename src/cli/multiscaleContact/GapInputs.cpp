// SPDX-License-Identifier: GPL-3.0-or-later
#include "GapInputs.hpp"
#include "Inputs.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SpecSource.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

namespace {

// How an entry of the gap is written on the command line (the reader names it so).
std::string gapOption(const std::string& key)
{
    return key == "pressure" ? "--gas-pressure" : "--" + key;
}

} // namespace

std::optional<GapInputs> gapOf(const Options& o)
{
    const bool given =
        !o.gas.empty() || o.gasPressure.has_value() || !o.accommodation.empty() || !o.emissivity.empty();
    if (!given) {
        for (const auto& [set, what] : {std::pair<bool, const char*>{!o.temperature.empty(), "--temperature"},
                                        {o.gapWidth.has_value(), "--gap-width"}}) {
            if (set) {
                throw ParameterError(what, "is for the gap beside the contact: add --gas NAME and/or --emissivity "
                                           "E1,E2");
            }
        }
        return std::nullopt;
    }
    // The options as the condition's gap sub-dictionary, through the core's reader.
    SpecValues v("gap", gapOption);
    if (!o.gas.empty()) {
        v.set("gas", o.gas);
    }
    if (o.gasPressure) {
        v.set("pressure", *o.gasPressure);
    }
    if (!o.accommodation.empty()) {
        v.set("accommodation", splitNumbers(o.accommodation, ',', "--accommodation"));
    }
    if (!o.emissivity.empty()) {
        v.set("emissivity", splitNumbers(o.emissivity, ',', "--emissivity"));
    }
    GapInputs g;
    g.spec = readGapSpec(v);
    if (o.temperature.empty()) {
        throw ParameterError("--temperature", std::string("the gap's conductance (") +
                                                  (g.spec.gas ? "--gas" : "--emissivity") +
                                                  ") is taken at the interface temperature: give --temperature T [K]");
    }
    const std::vector<double> T = splitNumbers(o.temperature, ',', "--temperature");
    if (T.size() > 2) {
        throw ParameterError("--temperature", "expects T or T1,T2 [K], the two faces' temperatures");
    }
    for (double t : T) {
        limits::requireInRange("--temperature", t, limits::minimumTemperature, limits::maximumTemperature, "K");
    }
    g.T1 = T.front();
    g.T2 = T.back();
    if (o.gapWidth) {
        g.width = limits::requireInRange("--gap-width", *o.gapWidth, 0.0, limits::maximumLength, "m");
    }
    return g;
}

InterfaceGap interfaceGapOf(const Options& o, const GapInputs& g, const ContactMaterials& materials,
                            std::function<double(double)> separation, double firstTouchPressure)
{
    double sigma = 0.0;
    double Hc = 0.0;
    if (!separation) {
        // The correlation's inputs, as ContactInterface::buildGap takes them: the surfaces'
        // combined rms height and the microhardness (--hardness, else 2.84 S_y).
        sigma = roughnessOf(o).sigma;
        const std::optional<double> H = hardnessOf(o, materials, "--hardness-from-yield");
        if (H) {
            Hc = *H;
        } else {
            try {
                Hc = materials.hardness("the gap's separation");
            } catch (const ParameterError&) {
                throw ParameterError(g.spec.gas ? "--gas" : "--emissivity",
                                     "the gap's separation Y (the plastic Gaussian correlation of sigma and P/H_c; "
                                     "this model and law define no mean separation) needs the microhardness H_c: "
                                     "give --Sy (H_c = 2.84 S_y), --hardness H_C or --hardness-from-yield");
            }
        }
    }
    return InterfaceGap(g.spec, std::move(separation), sigma, Hc, firstTouchPressure);
}

GapRow gapRowOf(const InterfaceGap& gap, const GapInputs& g, double P, bool complete)
{
    GapRow row;
    if (complete) {
        return row; // no gap: Y 0, h_g = h_r = 0 (h infinite)
    }
    double Y = 0.0;
    if (P > 0.0) {
        Y = gap.separation(P);
        row.separation = Y;
    } else if (g.width) {
        Y = *g.width;
        row.separation = Y;
    } else if (gap.hasGas()) {
        throw ParameterError("--gap-width", "at load 0 the surfaces do not touch, and the gas conductance "
                                            "k_g/(Y + M) needs their separation Y: give --gap-width W [m]");
    } else {
        row.separation = std::numeric_limits<double>::quiet_NaN(); // radiation alone needs none
    }
    row.h = gap.conductances(Y, g.T1, g.T2);
    return row;
}

void writeGapCells(std::ostream& out, const InterfaceGap& gap, const GapInputs& g, double P, bool complete,
                   const std::optional<double>& ks, double hPerK)
{
    const GapRow row = gapRowOf(gap, g, P, complete);
    out << ',';
    if (!std::isnan(row.separation)) {
        out << row.separation;
    }
    writeConductanceCells(out, row, ks, hPerK);
}

void writeConductanceCells(std::ostream& out, const GapRow& row, const std::optional<double>& ks, double hPerK)
{
    out << ',' << row.h.gas << ',' << row.h.radiative;
    if (ks) {
        out << ',';
        if (!std::isnan(hPerK)) {
            out << *ks * hPerK + row.h.gas + row.h.radiative; // inf at complete contact
        }
    }
}

} // namespace multiscaleContact
