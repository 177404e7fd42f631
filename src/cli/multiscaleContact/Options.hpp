// SPDX-License-Identifier: GPL-3.0-or-later
// multiscaleContact's command line: what it says (Options) and how CLI11 reads it (addOptions).
// Nothing here computes: Inputs.hpp turns the options into the core's objects, Run.hpp runs them.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace multiscaleContact {

struct Options {
    std::vector<std::string> profiles;
    std::vector<std::string> profilesAlong; ///< --profile-along: the i-th --profile's along its lay
    std::vector<std::string> areals;
    std::vector<std::string> spectra;
    std::vector<double> powerLaw; // b_m, m, fmin, fmax
    std::vector<std::string> roughness; // Rq, rms slope[, cutoff[, short cutoff]], as given (lengths may carry a unit)
    std::vector<double> fractal;  // D, G, fmin, fmax
    std::optional<std::string> units;
    std::optional<double> dx;
    std::optional<double> dy;
    std::optional<std::string> direction;
    bool fillInvalid = false;
    std::string synthesize; // "N[,SEED]"
    std::string resample;   // "N[,K]"
    bool periodic = false;
    bool mirror = false;
    std::optional<std::string> detrend; // boundaryElement: none | mean | plane
    std::optional<double> hardness;
    std::optional<double> unloadFrom; // --unload-from PMAX [Pa]: the curve of a joint that carried PMAX
    bool hardnessFromYield = false;
    std::string pressureMap; // boundaryElement: the pressure field of the highest load, to this file
    std::string plot;        // the interface's picture (every law, the band, the gap, the check), a PNG
    std::optional<double> length;
    std::size_t stride = 1;
    std::string model;
    std::vector<double> E;
    std::vector<double> nu;
    std::optional<double> Eprime;
    std::vector<std::string> Sy; // numbers [Pa], or none: the solid does not yield
    std::vector<std::string> loads; // as given: "1e-5,1e-4" (split here, so "" is an error)
    std::string loadRange;
    std::vector<std::string> pressures; // --pressures: nominal pressures F/A_n [Pa], as given
    std::optional<double> D;
    std::optional<double> G;
    std::string fitRange;
    bool levels = false;
    bool conductance = false;
    std::string conductanceLaw; // --conductance-law NAME (implies --conductance)
    std::string vickers;        // "C1,C2"
    bool info = false;
    int threads = 0; // --threads: the boundary-element solves' threads (0: what the machine has)
    std::string fftWisdom; // --fft-wisdom: measured FFT plans kept in this file (empty: the blocked transforms)
    bool check = false; // --check: the exact model on this surface against every law
    std::string checkPeriods; // --check-periods K, as given: the check's light-load period (scan lengths)
    std::string table;  // --table FILE: the boundary-element table of the interface, cached in FILE
    std::optional<double> k1; // --k1, --k2 [W/(m K)]: add the column h [W/(m^2 K)]
    std::optional<double> k2;
    // The gap beside the contact (the condition's gap sub-dictionary: InterfaceSpecReader's gapEntries)
    std::string gas;                     // --gas NAME: air, helium, argon, nitrogen
    std::optional<double> gasPressure;   // --gas-pressure P [Pa]
    std::string accommodation;           // --accommodation A1,A2
    std::string emissivity;              // --emissivity E1,E2
    std::string temperature;             // --temperature T[,T2] [K]: the two faces' temperatures
    std::optional<double> gapWidth;      // --gap-width W [m]: the separation at load 0
};

/// Every option and flag of multiscaleContact on app, read into o (their help texts are the
/// docs/cli.md's table of the CLI; --help prints them).
void addOptions(CLI::App& app, Options& o);

/// After app.parse(argc, argv): a ParameterError naming the option when one was given an empty
/// value (--table '') or a list with an empty item (--E 200GPa,), which CLI11 takes silently.
void refuseEmptyValues(const CLI::App& app, int argc, const char* const* argv);

} // namespace multiscaleContact
