// SPDX-License-Identifier: GPL-3.0-or-later
// The consumer of an installed roughContact: two steel blocks with a power-law surface, the
// jacksonGreen multi-scale model and the default conductance law, at one nominal pressure.
// Prints the load F/(A_n E') it asks for, A_r/A_n and h_c/k_s from the interface's table,
// A_r/A_n from the model itself, and h_c; tests/install/run checks them against the installed
// multiscaleContact at the same input.
#include "roughContact/interface/ContactInterface.hpp"

#include <cmath>
#include <cstdio>
#include <exception>

int main()
{
    using namespace roughContact;
    try {
        InterfaceSpec spec;
        SurfaceSpec surface;
        surface.kind = SurfaceSpec::Kind::powerLaw;
        // b_m f^-m [m] at f = i/L for f in [2e3, 2e6] 1/m, L = 0.5 mm (1000 levels)
        surface.parameters = {1e-7 * std::pow(2e3, 1.2), 1.2, 2e3, 2e6};
        surface.length = 5e-4;
        spec.surfaces.push_back(surface);
        spec.side1 = Material{200e9, 0.3, 0.5e9};
        spec.side2 = Material{200e9, 0.3, 0.5e9};
        spec.model = "jacksonGreen";
        const ContactInterface contact(spec);

        const double P = 1e6;       // nominal pressure [Pa]
        const double k = 45.0;      // both sides' conductivity [W/(m K)]
        const FaceContact face = contact.face(P, k, k);
        std::printf("load %.17g\n", P / contact.reducedModulus());
        std::printf("area %.17g\n", face.areaFraction);
        std::printf("modelArea %.17g\n", contact.model().areaFraction(P / contact.reducedModulus()));
        std::printf("h_per_k %.17g\n", contact.conductancePerConductivity(P));
        std::printf("h %.17g\n", face.conductance);
        std::printf("law %s\n", contact.conductanceLaw().c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
}
