// SPDX-License-Identifier: GPL-3.0-or-later
#include "Options.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/Gas.hpp"

#include <algorithm>
#include <string>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

namespace {

// An option that takes a number with a unit suffix (roughContact::parseQuantity: 1MPa, 200GPa,
// 0.8um): CLI11 reads the SI number it stands for. Comma-separated items are converted one by
// one (a plain number, an empty item stay as written, for the option's own checks; `none` stays
// where a solid may not yield). A bad unit is CLI11's error naming the option.
CLI::Option* withUnits(CLI::Option* option, roughContact::Quantity quantity, bool allowNone = false)
{
    const std::string name = option->get_name();
    return option->transform([name, quantity, allowNone](std::string text) {
        std::string out;
        std::size_t start = 0;
        while (true) {
            const std::size_t comma = text.find(',', start);
            const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            double plain = 0.0;
            if (!item.empty() && !(allowNone && item == "none") && !roughContact::parseNumber(item, plain)) {
                try {
                    out += roughContact::formatNumber(roughContact::parseQuantity(item, quantity, name), 17);
                } catch (const roughContact::ParameterError& e) {
                    throw CLI::ValidationError(e.message()); // CLI11 names the option
                }
            } else {
                out += item;
            }
            if (comma == std::string::npos) {
                return out;
            }
            out += ',';
            start = comma + 1;
        }
    });
}

} // namespace

void addOptions(CLI::App& app, Options& o)
{
    auto* surface = app.add_option_group("surface", "exactly one surface description");
    surface
        ->add_option("--profile", o.profiles,
                     "measured profile: columns 'x z', or 'z' with --dx; comma or whitespace separated, "
                     "# comments and one header line allowed, Dektak CSV exports read as is; mean and tilt "
                     "are removed. Give it twice for two rough surfaces")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);
    surface
        ->add_option(
            "--areal", o.areals,
            "measured areal surface (height map): an X3P file (.x3p, ISO 25178-72), or a text matrix "
            "of heights (rows along y, columns along x) with --dx (and --dy, --units); plane removed, "
            "its line scans (--direction) averaged into one spectrum. Twice for two rough surfaces")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);
    surface
        ->add_option("--spectrum", o.spectra,
                     "spectrum table: columns 'frequency [1/m]  amplitude [m]'; twice for two surfaces")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);
    surface
        ->add_option("--power-law", o.powerLaw,
                     "BM,M,FMIN,FMAX: amplitude BM f^-M [m] at f = i/L in [FMIN, FMAX]")
        ->delimiter(',')
        ->expected(4);
    surface
        ->add_option("--fractal", o.fractal,
                     "D,G,FMIN,FMAX: Majumdar-Bhushan (Weierstrass-Mandelbrot) spectrum, G in m")
        ->delimiter(',')
        ->expected(4);
    surface
        ->add_option("--roughness", o.roughness,
                     "RQ,SLOPE[,CUTOFF[,SHORTCUTOFF]]: the self-affine surface of rms height RQ [m] and rms "
                     "slope SLOPE (a number) over wavelengths SHORTCUTOFF to CUTOFF [m] (default 2.5e-6 to "
                     "0.8e-3: ISO 3274/4288), its Hurst exponent found from SLOPE/RQ; the lengths may carry a "
                     "unit (0.8um,0.1,0.8mm)")
        ->delimiter(',')
        ->expected(2, 4);
    surface->require_option(1);
    app.add_option("--profile-along", o.profilesAlong,
                   "a profile of the same surface along its lay, the --profile being across it (ISO 4288): "
                   "the surface is then the isotropic equivalent of the two directions; with two --profile, "
                   "the first --profile-along goes with the first")
        ->expected(1, 2)
        ->check(CLI::ExistingFile);

    app.add_option("--units", o.units,
                   "units of profile and --areal matrix files: m (default), um or nm; a Dektak export's "
                   "own header (um) is used when this is not given");
    app.add_option("--dx", o.dx,
                   "sample spacing of one-column profiles and of --areal matrices (along x), in --units");
    app.add_option("--dy", o.dy, "spacing along y of an --areal matrix, in --units (default --dx)");
    app.add_option("--direction", o.direction,
                   "line scans of an --areal surface: x (rows), y (columns) or both (default, as the laws' "
                   "accuracy bands are measured)");
    app.add_flag("--fill-invalid", o.fillInvalid,
                 "fill the invalid points of an --areal X3P file with the mean of their valid neighbours "
                 "(default: they are an error)");
    withUnits(app.add_option("--length", o.length,
                             "scan length L [m] (or with a unit: 0.5mm) for --spectrum/--power-law/--fractal "
                             "(default 1/lowest frequency); A_n = L^2"),
              roughContact::Quantity::length);
    app.add_option("--stride", o.stride,
                   "use every K-th profile sample (sampling interval K dx; seed Fig. 8)")
        ->check(CLI::Range(std::size_t(1), std::size_t(1000000000)));

    std::vector<std::string> allModels = modelNames();
    allModels.push_back("boundaryElement");
    app.add_option("--model", o.model,
                   "hertz | jgh | jghConsistent | jacksonGreen | truncation (multi-scale, seed §2) | "
                   "greenwoodWilliamson | greenwoodWilliamsonJG | majumdarBhushan | persson (Persson's theory, "
                   "Yang-Persson mean separation, gamma 0.42, on the isotropic 2-D form of the spectrum) | "
                   "boundaryElement (the exact reference: boundary elements on an --areal or --synthesize'd "
                   "surface)")
        ->required()
        ->check(CLI::IsMember(allModels));
    app.add_option("--synthesize", o.synthesize,
                   "N[,SEED]: boundaryElement on an N x N isotropic Gaussian surface synthesized from the "
                   "--profile/--spectrum/--power-law/--fractal (periodic; SEED default 1)");
    app.add_option("--resample", o.resample,
                   "N[,K]: boundaryElement on the --synthesize'd surface put on an N x N grid (its Fourier series "
                   "there: the same surface, finer or coarser), without its wavelengths shorter than L/K if K is "
                   "given (the same surface with fewer levels)");
    app.add_flag("--periodic", o.periodic,
                 "boundaryElement: solve an --areal map as one period of a periodic surface (default: "
                 "non-periodic, zero-padded)");
    app.add_flag("--mirror", o.mirror,
                 "boundaryElement: solve an --areal map mirrored about its edges into one period of a periodic "
                 "surface twice as long each way (an interface with the map's heights: no edges, no patch "
                 "constriction to remove; at the cost of a periodic solve of the map's size)");
    app.add_option("--detrend", o.detrend,
                   "boundaryElement: what is removed from the heights before the solve: none, mean or plane "
                   "(default: mean for a periodic solve, which has no trend to remove; plane for a "
                   "non-periodic map, whose fixture tilts it)");
    withUnits(app.add_option("--hardness", o.hardness, "boundaryElement: perfectly plastic cap p <= H [Pa]"),
              roughContact::Quantity::pressure);
    withUnits(app.add_option("--unload-from", o.unloadFrom,
                             "the peak nominal pressure PMAX [Pa] (or with a unit: 50MPa) the joint has carried. "
                             "boundaryElement with a cap: the output gains the columns unloading_area_fraction, "
                             "unloading_separation, unloading_h_per_k (and unloading_h; with the gap "
                             "unloading_h_gas, unloading_h_radiation, unloading_h_total), unloading_iterations and "
                             "unloading_residual, the joint unloaded from PMAX (loaded on from it above PMAX); a "
                             "multi-scale model: unloading_area_fraction, and with a conductance the law's "
                             "unloading branch unloading_h_per_k (and unloading_h, unloading_h_total with the gap; "
                             "fittedElastoPlastic with a cap)"),
              roughContact::Quantity::pressure);
    app.add_option("--pressure-map", o.pressureMap,
                   "boundaryElement: write the contact pressure [Pa] at the highest load to this file, as a "
                   "text matrix (rows along x, one per line)");
    app.add_flag("--hardness-from-yield", o.hardnessFromYield,
                 "boundaryElement: the cap H = 2.84 S_y (--Sy of the yielding material)");

    auto* E = withUnits(app.add_option("--E", o.E, "Young's modulus [Pa] (or with a unit: 200GPa); E1,E2 for two "
                                                   "solids"),
                        roughContact::Quantity::pressure)
                  ->delimiter(',')
                  ->expected(1, 2);
    app.add_option("--nu", o.nu, "Poisson's ratio; nu1,nu2 with two moduli")->delimiter(',')->expected(1, 2);
    auto* Ep = withUnits(app.add_option("--Eprime", o.Eprime, "reduced modulus E' [Pa] instead of --E/--nu"),
                         roughContact::Quantity::pressure);
    E->excludes(Ep);
    withUnits(app.add_option("--Sy", o.Sy,
                             "yield strength [Pa] (or with a unit: 400MPa; jacksonGreen, truncation, "
                             "greenwoodWilliamsonJG, majumdarBhushan); Sy1,Sy2 with two moduli, none for a solid "
                             "that does not yield (Sy1,none)"),
              roughContact::Quantity::pressure, true)
        ->delimiter(',')
        ->expected(1, 2);

    auto* loads = app.add_option("--loads", o.loads, "loads F/(A_n E'), comma separated: 0, or 1e-30 to 1e4");
    auto* range = app.add_option("--load-range", o.loadRange, "MIN:MAX:N, N loads log spaced");
    loads->excludes(range);
    auto* pressures = withUnits(app.add_option("--pressures", o.pressures,
                                               "nominal pressures F/A_n [Pa] (or with a unit: 1MPa), comma "
                                               "separated, instead of --loads: each is the load P/E' (E' from "
                                               "--E/--nu or --Eprime); the output gains a first column "
                                               "nominal_pressure [Pa]"),
                                roughContact::Quantity::pressure);
    pressures->excludes(loads);
    pressures->excludes(range);

    app.add_option("--D", o.D, "Majumdar-Bhushan fractal dimension (default: fitted to the spectrum)");
    app.add_option("--G", o.G, "Majumdar-Bhushan fractal roughness [m] (default: fitted)");
    app.add_option("--fit-range", o.fitRange, "FMIN:FMAX [1/m]: frequencies the D,G fit uses (default all)");
    app.add_flag("--levels", o.levels, "print the per-level trace (seed Fig. 5) instead of the load curve");
    app.add_flag(
        "--conductance", o.conductance,
        "add the columns separation and h_per_k: contact conductance over k_s = 2 k1 k2/(k1 + k2), in 1/m, "
        "from the --conductance-law (default: the multi-scale constriction resistances in series, inf at "
        "complete contact, for the multi-scale models; for persson its mean separation [m] and Barber's "
        "h_c/k_s = -(1/E') dp/du); separation [m] is the model's (persson) or the law's (persson, "
        "multiscaleBarber: Barber-consistent with their h_per_k), empty where neither defines one");
    std::string lawNames;
    for (const std::string& n : conductanceLawNames()) {
        lawNames += (lawNames.empty() ? "" : ", ") + n;
    }
    app.add_option("--conductance-law", o.conductanceLaw,
                   "the law of the h_per_k column (implies --conductance): " + lawNames + " (default " +
                       defaultConductanceLaw() + "); 'all': the default's column and one h_per_k_NAME "
                       "column per law that can be built. cooperMikicYovanovich needs the microhardness: "
                       "--hardness H_C, --hardness-from-yield (2.84 S_y) or --vickers C1,C2");
    app.add_option("--vickers", o.vickers,
                   "cooperMikicYovanovich: Vickers coefficients C1 [Pa], C2 of H_v = c1 (d_v/1 um)^c2, the "
                   "microhardness from Song & Yovanovich's correlation");
    app.add_flag("--info", o.info, "print the surface's parameters (McCool, fractal fit) to stderr");
    app.add_option("--threads", o.threads,
                   "threads of the boundary-element solves (--model boundaryElement, --check, --table): "
                   "FFTW's and the solver's loops; the answer is the same for any number (default: what "
                   "the machine has)")
        ->check(CLI::Range(1, roughContact::limits::maximumThreads));
    app.add_option("--fft-wisdom", o.fftWisdom,
                   "boundary-element solves: FFTW's 2-D plans chosen by timing them (FFTW_MEASURE: a few "
                   "seconds to plan a new size) and kept in FILE (created when missing; a file there must be FFTW "
                   "wisdom), so that runs sharing FILE with the same --threads use the same plans and give "
                   "the same answer bit for bit (default: the blocked "
                   "transforms, planned without timing runs: the same answer on every run and for any "
                   "number of threads; docs/benchmarks.md compares the two)");
    app.add_option("--k1", o.k1, "conductivity [W/(m K)] of solid 1: with --k2, add the column h = k_s h_per_k "
                                 "[W/(m^2 K)], k_s = 2 k1 k2/(k1 + k2)");
    app.add_option("--k2", o.k2, "conductivity [W/(m K)] of solid 2 (with --k1)");
    std::string gases;
    for (const std::string& n : gasNames()) {
        gases += (gases.empty() ? "" : ", ") + n;
    }
    app.add_option("--gas", o.gas,
                   "the gas in the gap beside the contact, by name: " + gases + " (the boundary condition's gap "
                   "entry gas; a gas given by its properties is for the dictionary or Python's GapSpec). Adds the "
                   "columns gap_separation, h_gas, h_radiation (and h_total with --k1/--k2); needs --temperature");
    withUnits(app.add_option("--gas-pressure", o.gasPressure,
                             "the gas pressure P_g [Pa] (or with a unit: 10kPa) of --gas (default 101325, 1 atm)"),
              roughContact::Quantity::pressure);
    app.add_option("--accommodation", o.accommodation,
                   "A1,A2: the thermal accommodation coefficients of the two surfaces for --gas, each in (0, 1] "
                   "(default: the gas's)");
    app.add_option("--emissivity", o.emissivity,
                   "E1,E2: the emissivities of the two surfaces, each in (0, 1]: radiation across the gap (grey "
                   "parallel plates), the column h_radiation; with or without --gas");
    app.add_option("--temperature", o.temperature,
                   "T[,T2]: the interface temperature [K] the gap conductance is taken at (T2: the second face's, "
                   "the gas at their mean; default T); required with --gas or --emissivity");
    withUnits(app.add_option("--gap-width", o.gapWidth,
                             "the gap's width [m] (or with a unit: 20um) at load 0, where the surfaces do not touch "
                             "(the condition's gap/gapField); required there with --gas"),
              roughContact::Quantity::length);
    app.add_option("--table", o.table,
                   "with --model boundaryElement and two solids (--E E1,E2 --nu nu1,nu2, the condition's side1 "
                   "and side2): the boundary-element table the boundary condition builds for these inputs "
                   "(loads 1e-6 E' to min(0.1 E', 0.95 H), 6 a decade; --pressures MIN[,MAX] [Pa] sets the "
                   "range), read from FILE when it holds this table (its key and digest), else solved and "
                   "written to FILE, the condition's constant/boundaryElementTable.NAME.csv; prints "
                   "pressure,area,h_per_k,separation");
    app.add_flag("--check", o.check,
                 "check the laws on this surface: the exact model (boundaryElement) on the --areal map, or on "
                 "3 surfaces of 512 x 512 (--synthesize N) synthesized from the profile or spectrum (up to "
                 "p/(E' h') = 1e-3 on periods of " +
                     std::to_string(roughContact::SurfaceCheckOptions{}.lightLoadPeriods) +
                     " scan lengths, joined with one scan length's by 1e-2), at the given --pressures or --loads (up to 5) or N across the range of "
                     "--load-range MIN:MAX:N (N up to 5), within p/(E' h') 1e-4 to 1e-1; capped at "
                 "H where --Sy, --hardness or --hardness-from-yield say, elastic otherwise. Prints every law's "
                 "ratio to the exact h_c/k_s, the closest, and whether the chosen law (--conductance-law, "
                 "default " + defaultConductanceLaw() + ") is within 25 %");
    app.add_option("--check-periods", o.checkPeriods,
                   "with --check on a profile or spectrum: solve its pressures up to p/(E' h') = 1e-3 on "
                   "periods of K scan lengths, 1 to " + std::to_string(roughContact::Spectrum::maximumPeriodMultiple) +
                       " (default " + std::to_string(roughContact::SurfaceCheckOptions{}.lightLoadPeriods) +
                       "; 1: every pressure on one scan length; docs/checking.md says what each gains)");
    app.add_option("--plot", o.plot,
                   "draw the interface as a PNG (gnuplot): every law's h_c/k_s (h with --k1, --k2) against the "
                   "pressure across the run's pressures, the chosen law's measured band, the gap's h_gas and h_rad, "
                   "and with --check the exact answer it implies (docs/checking.md)");

}

void refuseEmptyValues(const CLI::App& app, int argc, const char* const* argv)
{
    for (const CLI::Option* option : app.get_options()) {
        if (option->count() == 0 || option->get_expected_min() == 0) {
            continue; // not given, or a flag
        }
        const std::string name = option->get_name();
        const std::vector<std::string>& results = option->results();
        if (results.empty() || std::find(results.begin(), results.end(), std::string()) != results.end()) {
            throw ParameterError(name, "is given an empty value (''): give one, or leave the option out");
        }
        if (option->get_delimiter() == '\0') {
            continue;
        }
        // CLI11 drops an empty item of a list ("200GPa," is read as "200GPa"): the lists as typed.
        const char delimiter = option->get_delimiter();
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            std::string value;
            if (arg == name && i + 1 < argc) {
                value = argv[i + 1];
            } else if (arg.rfind(name + "=", 0) == 0) {
                value = arg.substr(name.size() + 1);
            } else {
                continue;
            }
            const std::string doubled(2, delimiter);
            if (value.empty() || value.front() == delimiter || value.back() == delimiter ||
                value.find(doubled) != std::string::npos) {
                throw ParameterError(name, "'" + value + "' has an empty item (a '" + std::string(1, delimiter) +
                                               "' too many?); give the items separated by '" +
                                               std::string(1, delimiter) + "'");
            }
        }
    }
}

} // namespace multiscaleContact
