// SPDX-License-Identifier: GPL-3.0-or-later
// The contact entry of the boundary-element table tests (testBoundaryElementTable,
// testTableRanks): a power law synthesized on a 32 x 32 periodic grid, steel on steel, 17 loads
// from 0.1 MPa to 1 GPa (4 a decade): a table in well under a second.
#pragma once

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"

#include <fstream>
#include <string>

namespace roughContactTest {

inline roughContact::InterfaceSpec smallBoundaryElementSpec()
{
    using namespace roughContact;
    const Material steel{200e9, 0.3, 0.4e9};
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::powerLaw;
    s.parameters = {2.56e-4, 0.8, 1e3, 16e3};
    s.length = 1e-3;
    spec.surfaces = {s};
    spec.side1 = steel;
    spec.side2 = steel;
    spec.model = "boundaryElement";
    spec.synthesize = 32;
    spec.seed = 1;
    spec.minPressure = 1e5;
    spec.maxPressure = 1e9;
    spec.bemPointsPerDecade = 4;
    return spec;
}

/// The spec above on a 32 x 32 map (its spectrum synthesized with seed 5, written to `file` as a
/// text matrix) solved padded up to 1e10 Pa (p/E' 0.09, elastic: near complete contact), where
/// the padded answer is not to be trusted (BoundaryElement.hpp, patchCorrectionWarning).
inline roughContact::InterfaceSpec smallPaddedMapSpec(const std::string& file)
{
    using namespace roughContact;
    InterfaceSpec spec = smallBoundaryElementSpec();
    const ArealSurface map = synthesizeIsotropic(spec.surfaces[0].spectrum(), 32, 5);
    std::ofstream out(file);
    out.precision(17);
    for (std::size_t iy = 0; iy < 32; ++iy) {
        for (std::size_t ix = 0; ix < 32; ++ix) {
            out << (ix ? " " : "") << map.at(ix, iy);
        }
        out << '\n';
    }
    spec.synthesize.reset();
    SurfaceSpec a;
    a.kind = SurfaceSpec::Kind::areal;
    a.file = file;
    a.arealOptions.dx = map.dx();
    spec.surfaces = {a};
    spec.maxPressure = 1e10;
    return spec;
}

} // namespace roughContactTest
