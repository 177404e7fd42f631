// SPDX-License-Identifier: GPL-3.0-or-later
// The contact entry of the boundary-element table tests (testBoundaryElementTable,
// testTableRanks): a power law synthesized on a 32 x 32 periodic grid, steel on steel, 17 loads
// from 0.1 MPa to 1 GPa (4 a decade): a table in well under a second.
#pragma once

#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/material/Materials.hpp"

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

} // namespace roughContactTest
