// SPDX-License-Identifier: GPL-3.0-or-later
// syntheticProfile: writes a seeded Gaussian power-law profile as CSV "x,z" in metres
// (the documented generator of the stand-in for the seed's measured profile).
#include "roughContact/surface/SyntheticProfile.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

using namespace roughContact;

int main(int argc, char** argv)
{
    CLI::App app{"syntheticProfile: a Gaussian random profile with one-sided PSD ~ f^-(5-2D) from 1/L to\n"
                 "Nyquist, scaled to the given rms; deterministic for a seed. Writes CSV 'x,z' [m] on stdout.\n"
                 "The defaults make the stand-in for the seed's Fig. 4a profile (2454 points at 0.204 um,\n"
                 "rms 0.115 um, D = 1.597 of its Table 1).",
                 "syntheticProfile"};
    SyntheticProfileSpec spec;
    app.add_option("--points", spec.points, "number of samples")->capture_default_str();
    app.add_option("--dx", spec.spacing, "sample spacing [m]")->capture_default_str();
    app.add_option("--rms", spec.rms, "rms height [m]")->capture_default_str();
    app.add_option("--D", spec.D, "fractal dimension setting the PSD slope 5-2D")->capture_default_str();
    app.add_option("--seed", spec.seed, "random seed (std::mt19937_64)")->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 1; // CLI11's own codes (104-114) are errors: 1
    }
    try {
        const Profile p = generateSyntheticProfile(spec); // every check before the first line out
        std::cout << "# syntheticProfile --points " << spec.points << " --dx " << spec.spacing << " --rms "
                  << spec.rms << " --D " << spec.D << " --seed " << spec.seed << "\nx,z\n";
        std::cout.precision(17);
        for (std::size_t i = 0; i < p.size(); ++i) {
            std::cout << static_cast<double>(i) * p.spacing() << ',' << p.heights()[i] << '\n';
        }
    } catch (const std::exception& e) {
        std::cerr << "syntheticProfile: error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
