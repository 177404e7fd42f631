// SPDX-License-Identifier: GPL-3.0-or-later
// The surfaces of multiscaleContact's options (Inputs.hpp): SurfaceSpecs through the core's
// reader of a surface, and what the load curve takes of them (spectrum, roughness, skewness).
#include "Inputs.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SpecSource.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/SpectralMoments.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

Spectrum surfaceOf(const Options& o)
{
    return equivalentSurface(surfaceSpecsOf(o));
}

// sigma and the mean absolute slope of the surfaces, for the correlations (the same surfaces
// surfaceOf reads; two combined): a profile's and a map's from their heights, a spectrum's from
// its moments (Roughness.hpp).
SurfaceRoughness roughnessOf(const Options& o)
{
    return equivalentRoughness(surfaceSpecsOf(o));
}

// The heights' skewness of the same surfaces (equivalentSkewness): none for a spectrum.
std::optional<HeightSkewness> skewnessOf(const Options& o)
{
    return equivalentSkewness(surfaceSpecsOf(o));
}

void printInfo(const Spectrum& s, std::ostream& os)
{
    os << "# surface: " << s.source() << "\n# levels: " << s.size() << ", f = " << s.frequencies().front()
       << " .. " << s.frequencies().back() << " 1/m, L = " << s.length() << " m, A_n = " << s.nominalArea()
       << " m^2\n# rms height (Parseval): " << std::sqrt(s.profileVariance()) << " m\n";
    try {
        const SummitParameters p = mcCoolParameters(s);
        os << "# McCool: eta = " << p.eta << " 1/m^2, R = " << p.R << " m, sigma_s = " << p.sigmaS
           << " m, alpha = " << p.alpha << "\n";
    } catch (const std::exception& e) {
        os << "# McCool: " << e.what() << "\n";
    }
    try {
        const FractalParameters f = fitFractal(s);
        os << "# fractal fit: D = " << f.D << ", G = " << f.G << " m\n";
    } catch (const std::exception& e) {
        os << "# fractal fit: " << e.what() << "\n";
    }
}

// The surfaces as SurfaceSpecs, read by the core's reader of a surface (InterfaceSpecReader.hpp)
// from the options as a dictionary's entries, each named by its option. An option goes to the
// surfaces whose type takes it (--units to a profile and an areal map, not to a spectrum beside
// them); one that no surface takes is the core's error for the first surface.
std::vector<SurfaceSpec> surfaceSpecsOf(const Options& o)
{
    struct Given {
        std::string key;       ///< the entry's name in a dictionary
        std::string arealKey;  ///< ... for an areal surface (--dx: a profile's spacing, a map's dx)
        SpecValues::Value value;
        std::string option;
    };
    std::vector<Given> given;
    if (o.units) {
        given.push_back({"units", "units", *o.units, "--units"});
    }
    if (o.dx) {
        given.push_back({"spacing", "dx", *o.dx, "--dx"});
    }
    if (o.dy) {
        given.push_back({"dy", "dy", *o.dy, "--dy"});
    }
    if (o.fillInvalid) {
        given.push_back({"fillInvalid", "fillInvalid", true, "--fill-invalid"});
    }
    if (o.direction) {
        given.push_back({"direction", "direction", *o.direction, "--direction"});
    }
    if (o.stride != 1) {
        given.push_back({"stride", "stride", std::uint64_t(o.stride), "--stride"});
    }
    if (o.length) {
        given.push_back({"length", "length", *o.length, "--length"});
    }

    std::vector<SpecValues> surfaces;
    const auto add = [&](const char* type, const std::string& option, const std::string& file) {
        SpecValues v(option + " " + file);
        v.set("type", std::string(type), option);
        if (!file.empty()) {
            v.set("file", file, option);
        }
        surfaces.push_back(v);
        return &surfaces.back();
    };
    if (o.profilesAlong.size() > o.profiles.size()) {
        throw ParameterError("--profile-along", "is a profile along the lay of a --profile's surface; give one "
                                                "--profile (across the lay) for each");
    }
    for (std::size_t i = 0; i < o.profiles.size(); ++i) {
        SpecValues* v = add("profile", "--profile", o.profiles[i]);
        if (i < o.profilesAlong.size()) {
            v->set("alongLay", o.profilesAlong[i], "--profile-along");
        }
    }
    for (const std::string& f : o.areals) {
        add("areal", "--areal", f);
    }
    for (const std::string& f : o.spectra) {
        add("spectrum", "--spectrum", f);
    }
    if (!o.powerLaw.empty()) {
        SpecValues* v = add("powerLaw", "--power-law", "");
        const char* keys[] = {"bm", "m", "fmin", "fmax"};
        for (std::size_t i = 0; i < o.powerLaw.size() && i < 4; ++i) {
            v->set(keys[i], o.powerLaw[i], "--power-law");
        }
    }
    if (!o.roughness.empty()) {
        SpecValues* v = add("roughness", "--roughness", "");
        const char* keys[] = {"Rq", "slope", "cutoff", "shortCutoff"};
        for (std::size_t i = 0; i < o.roughness.size() && i < 4; ++i) {
            // RQ, CUTOFF and SHORTCUTOFF are lengths (SI, or with a unit: 0.8um); SLOPE a number
            const std::string& item = o.roughness[i];
            double value = 0.0;
            if (i == 1) {
                if (!parseNumber(item, value)) {
                    throw ParameterError("--roughness", "SLOPE (the rms slope, a number) is '" + item + "'");
                }
            } else {
                value = parseQuantity(item, Quantity::length, "--roughness");
            }
            v->set(keys[i], value, "--roughness");
        }
        // A length without a unit beside lengths with one is most likely a slip (0.8um,0.1,0.8
        // meant 0.8 mm, not 0.8 m): said, and read as written (SI).
        const char* names[] = {"RQ", "SLOPE", "CUTOFF", "SHORTCUTOFF"};
        double plain = 0.0;
        bool anyUnit = false;
        for (std::size_t i = 0; i < o.roughness.size() && i < 4; ++i) {
            anyUnit = anyUnit || (i != 1 && !parseNumber(o.roughness[i], plain));
        }
        for (std::size_t i = 0; anyUnit && i < o.roughness.size() && i < 4; ++i) {
            if (i != 1 && parseNumber(o.roughness[i], plain)) {
                std::cerr << "multiscaleContact: warning: --roughness: " << names[i] << " '" << o.roughness[i]
                          << "' has no unit and is read as " << o.roughness[i]
                          << " m, while another length there has one; give it a unit (0.8mm, 2.5um) if another "
                             "was meant\n";
            }
        }
    }
    if (!o.fractal.empty()) {
        SpecValues* v = add("fractal", "--fractal", "");
        const char* keys[] = {"D", "G", "fmin", "fmax"};
        for (std::size_t i = 0; i < o.fractal.size() && i < 4; ++i) {
            v->set(keys[i], o.fractal[i], "--fractal");
        }
    }
    for (const Given& g : given) {
        bool taken = false;
        for (SpecValues& v : surfaces) {
            const SurfaceSpec::Kind kind = parseSurfaceKind(v.word("type"));
            const std::string& key = kind == SurfaceSpec::Kind::areal ? g.arealKey : g.key;
            const std::vector<std::string>& entries = surfaceEntries(kind);
            if (std::find(entries.begin(), entries.end(), key) != entries.end()) {
                v.set(key, g.value, g.option);
                taken = true;
            }
        }
        if (!taken && !surfaces.empty()) {
            SpecValues first = surfaces.front();
            first.set(g.key, g.value, g.option);
            readSurfaceSpec(first); // throws: no surface of this run takes the option
        }
    }
    std::vector<SurfaceSpec> out;
    for (const SpecValues& v : surfaces) {
        out.push_back(readSurfaceSpec(v));
    }
    return out;
}

} // namespace multiscaleContact
