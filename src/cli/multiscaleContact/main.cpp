// SPDX-License-Identifier: GPL-3.0-or-later
// multiscaleContact: real contact area of rough surfaces against load, from the command line.
// The interface is fixed: scripts rely on --profile/--spectrum, --model, the
// material options, --loads/--load-range, --levels and the CSV columns, named for what they are:
// nominal_pressure_per_Eprime (F/(A_n E')), area_fraction (A_r/A_n),
// contact_pressure_per_Eprime (F/(A_r E')). --pressures (nominal pressures in Pa, each the load
// P/E') adds a first column nominal_pressure [Pa]; the gap options (--gas, --emissivity) the
// columns gap_separation, h_gas, h_radiation and h_total.
//
// The program in files: Options (the command line), Inputs, SurfaceInputs, GapInputs (options to
// the core's objects, through its readers), Run, Check, BoundaryElementRun, Table (what it
// computes); this file only parses and reports errors.
#include "Options.hpp"
#include "Run.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/parallel/Threads.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

using namespace multiscaleContact;

int main(int argc, char** argv)
{
    CLI::App app{
        "multiscaleContact: real contact area A_r/A_n of a rough surface against a flat, or of two rough\n"
        "surfaces, as a function of the load F/(A_n E'), by the multi-scale model of Jackson & Streator\n"
        "(2006) and the models it is compared with. Prints CSV on stdout: the columns\n"
        "nominal_pressure_per_Eprime = F/(A_n E'), area_fraction = A_r/A_n and\n"
        "contact_pressure_per_Eprime = F/(A_r E') (with --pressures, a first column nominal_pressure =\n"
        "F/A_n [Pa]); with --conductance separation [m], h_per_k [1/m] (and h [W/(m^2 K)] with --k1/--k2);\n"
        "with a gap (--gas, --emissivity) gap_separation [m], h_gas, h_radiation (and h_total = h + h_gas +\n"
        "h_radiation) [W/(m^2 K)]. Errors go to stderr, exit 1.",
        "multiscaleContact"};
    Options o;

    addOptions(app, o);

    try {
        app.parse(argc, argv);
        if (o.loads.empty() && o.loadRange.empty() && o.pressures.empty() && app.count("--table") == 0) {
            throw CLI::RequiredError("--loads, --load-range or --pressures");
        }
    } catch (const CLI::ParseError& e) {
        // CLI11 prints the message (or the help); its own codes (104-114) become 1 (docs/cli.md).
        return app.exit(e) == 0 ? 0 : 1;
    }
    try {
        refuseEmptyValues(app, argc, argv);
        if (o.threads > 0) {
            roughContact::setThreads(o.threads);
        }
        try {
            roughContact::setFftWisdom(o.fftWisdom);
        } catch (const roughContact::ParameterError& e) {
            throw roughContact::ParameterError("--fft-wisdom", e.message());
        }
        return run(o);
    } catch (const std::exception& e) {
        std::cerr << "multiscaleContact: error: " << e.what() << '\n';
        return 1;
    }
}
