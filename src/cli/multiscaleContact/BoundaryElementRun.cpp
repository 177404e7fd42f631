// SPDX-License-Identifier: GPL-3.0-or-later
#include "Run.hpp"
#include "Inputs.hpp"
#include "GapInputs.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/interface/InterfaceRegime.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace multiscaleContact {

namespace {
// "spots,mean_spot_radius," of a point (ContactSpots.hpp): the radius empty without a spot.
void writeSpotCells(std::ostream& out, const ContactSpots& spots)
{
    out << spots.count << ',';
    if (spots.count > 0) {
        out << spots.meanRadius();
    }
    out << ',';
}
} // namespace

// --model boundaryElement: the curve, one progress line on stderr per load once the run takes
// longer than 2 s, then the whole CSV.
int runBoundaryElement(const Options& o)
{
    if (o.levels) {
        throw ParameterError("--levels", "the per-level trace exists for the multi-scale models only");
    }
    const std::optional<GapInputs> gapInputs = gapOf(o); // its errors before minutes of solving
    const InterfaceSpec spec = interfaceSpecOf(o);         // the model's rules, the core's
    const auto [surface, periodic] = arealSurfaceOf(o);
    const ContactMaterials materials = materialsOf(o);
    BoundaryElementOptions bo;
    bo.periodic = periodic;
    bo.mirrored = spec.mirror.value_or(false);
    bo.detrend = spec.detrend;
    bo.hardness = hardnessOf(o, materials, "boundaryElement --hardness-from-yield");
    std::vector<double> pressures; // --pressures [Pa]: the first column
    const std::vector<double> loads = loadsOf(o, materials.reducedModulus(), &pressures);
    // --unload-from: the joint's peak, below the cap (at H the whole surface flows).
    std::optional<double> peak;
    if (o.unloadFrom) {
        requireUnloadingPeak(*o.unloadFrom, bo.hardness, "--unload-from", "--hardness or --hardness-from-yield");
        peak = *o.unloadFrom / materials.reducedModulus();
    }
    if (!o.pressureMap.empty()) {
        checkOutputFile(o, o.pressureMap, "--pressure-map"); // before minutes of solving
    }
    const auto start = std::chrono::steady_clock::now();
    const auto seconds = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    // A solve that runs longer than a few seconds says where it is (PolonskyKeer.hpp), and which
    // load it is of (in the order solved, increasing).
    std::size_t current = 1;
    bo.progress = [&](const SolveProgress& s) {
        std::cerr << "multiscaleContact: boundaryElement " << surface.nx() << " x " << surface.ny() << ": ";
        if (std::string(s.stage) != "bonded-patch conductance") {
            std::cerr << "load " << current << " of " << loads.size() << ", ";
        }
        std::cerr << s.stage << " solve: iteration " << s.iteration << ", residual " << s.residual << " (tolerance " << s.tolerance
                  << "), " << s.seconds << " s in this solve; " << seconds() << " s in all" << std::endl;
    };
    const BoundaryElementModel model(surface, materials.reducedModulus(), bo);
    {
        // Before a long run, what to expect (a timed FFT pair times the solves' evaluations).
        const HalfSpaceOperator op(surface.nx(), surface.ny(), surface.dx(), surface.dy(), materials.reducedModulus(),
                                   edgesOf(periodic, o.mirror));
        const double expected = estimatedCurveSeconds(op, loads.size() + (o.pressureMap.empty() ? 0 : 1));
        if (expected > 3.0) {
            std::cerr << "multiscaleContact: boundaryElement " << surface.nx() << " x " << surface.ny() << ": "
                      << loads.size() << " load" << (loads.size() == 1 ? "" : "s") << ", about "
                      << std::setprecision(2) << expected << std::setprecision(6) << " s" << std::endl;
        }
    }
    const std::vector<BoundaryElementPoint> points =
        model.curve(loads, [&](std::size_t done, std::size_t total, const BoundaryElementPoint& p) {
            current = done + 1;
            if (seconds() > 2.0) {
                std::cerr << "multiscaleContact: boundaryElement " << surface.nx() << " x " << surface.ny()
                          << (o.mirror ? " (mirrored)" : periodic ? " (periodic)" : " (non-periodic)") << ": load " << done << " of " << total
                          << ", F/(A_n E') = " << p.load << ": A_r/A_n = " << p.areaFraction << ", "
                          << p.iterations << " iterations, residual " << p.residual << "; " << seconds()
                          << " s\n";
            }
        });
    // The same loads on the joint that has carried the peak (BoundaryElementModel::loadPath).
    std::vector<BoundaryElementPoint> unloading;
    if (peak) {
        current = 1;
        unloading = model.loadPath(*peak, loads, [&](std::size_t done, std::size_t total, const BoundaryElementPoint& p) {
            current = done + 1;
            if (seconds() > 2.0) {
                std::cerr << "multiscaleContact: boundaryElement unloading from F/(A_n E') = " << *peak << ": load "
                          << done << " of " << total << ", F/(A_n E') = " << p.load
                          << ": A_r/A_n = " << p.areaFraction << "; " << seconds() << " s\n";
            }
        });
    }
    if (const std::string warning = patchCorrectionWarning(points, materials.reducedModulus(), "--mirror"); !warning.empty()) {
        std::cerr << "multiscaleContact: warning: " << warning << std::endl;
    }
    std::ostringstream out;
    out.precision(10);
    const std::optional<double> ks = harmonicConductivityOf(o, true);
    const double Ep = materials.reducedModulus();
    std::optional<InterfaceGap> gap;
    std::optional<InterfaceGap> unloadingGap; // the unloaded joint's: Y its own mean separation
    if (gapInputs) {
        // The gap's Y is the model's mean separation (the separation column), as the condition's
        // boundary-element table gives it: the solved point's at each load (another solve only
        // for a pressure not solved, the first touch of a run without a positive load).
        double firstTouch = 0.0;
        for (double l : loads) {
            if (l > 0.0 && (firstTouch == 0.0 || l * Ep < firstTouch)) {
                firstTouch = l * Ep;
            }
        }
        if (firstTouch == 0.0) {
            firstTouch = 1e-9 * Ep;
        }
        const auto separation = [&](double P) {
            for (std::size_t i = 0; i < loads.size(); ++i) {
                if (loads[i] * Ep == P) {
                    return points[i].meanSeparation;
                }
            }
            return model.solve(P / Ep).meanSeparation;
        };
        gap.emplace(interfaceGapOf(o, *gapInputs, materials, separation, firstTouch));
        if (peak) {
            // Every positive load was solved on the unloaded joint: its Y at the row's P.
            const auto unloadedSeparation = [&](double P) {
                for (std::size_t i = 0; i < loads.size(); ++i) {
                    if (loads[i] * Ep == P) {
                        return unloading[i].meanSeparation;
                    }
                }
                return model.loadPath(*peak, {P / Ep}).front().meanSeparation;
            };
            unloadingGap.emplace(interfaceGapOf(o, *gapInputs, materials, unloadedSeparation, firstTouch));
        }
    }
    out << (pressures.empty() ? "" : "nominal_pressure,")
        << "nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime,separation,h_per_k,"
        << (ks ? "h," : "") << (gap ? "gap_separation,h_gas,h_radiation," : "")
        << (gap && ks ? "h_total," : "") << "spots,mean_spot_radius,"
        << (peak ? "unloading_area_fraction,unloading_separation,unloading_h_per_k," : "")
        << (peak && ks ? "unloading_h," : "") << (peak && gap ? "unloading_h_gas,unloading_h_radiation," : "")
        << (peak && gap && ks ? "unloading_h_total," : "")
        << (peak ? "unloading_spots,unloading_mean_spot_radius," : "") << "iterations,residual"
        << (peak ? ",unloading_iterations,unloading_residual" : "") << "\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        const BoundaryElementPoint& p = points[i];
        if (!pressures.empty()) {
            out << pressures[i] << ',';
        }
        out << p.load << ',' << p.areaFraction << ',';
        if (p.areaFraction > 0.0) {
            out << p.load / p.areaFraction;
        }
        out << ',' << p.meanSeparation << ',' << p.conductancePerConductivity << ',';
        if (ks) {
            out << *ks * p.conductancePerConductivity << ',';
        }
        if (gap) {
            std::ostringstream cells; // ",Y,h_g,h_r[,h_total]"
            cells.precision(out.precision());
            writeGapCells(cells, *gap, *gapInputs, loads[i] * Ep, p.areaFraction >= 1.0, ks,
                          p.conductancePerConductivity);
            out << cells.str().substr(1) << ',';
        }
        writeSpotCells(out, p.spots);
        if (peak) {
            out << unloading[i].areaFraction << ',' << unloading[i].meanSeparation << ','
                << unloading[i].conductancePerConductivity << ',';
            if (ks) {
                out << *ks * unloading[i].conductancePerConductivity << ',';
            }
            if (gap) {
                // The unloaded joint's gap at its own separation (the column unloading_separation).
                std::ostringstream cells; // ",h_g,h_r[,h_total]"
                cells.precision(out.precision());
                writeConductanceCells(cells,
                                      gapRowOf(*unloadingGap, *gapInputs, loads[i] * Ep,
                                               unloading[i].areaFraction >= 1.0),
                                      ks, unloading[i].conductancePerConductivity);
                out << cells.str().substr(1) << ',';
            }
            writeSpotCells(out, unloading[i].spots);
        }
        out << p.iterations << ',' << p.residual;
        if (peak) {
            out << ',' << unloading[i].iterations << ',' << unloading[i].residual;
        }
        out << '\n';
    }
    if (!o.pressureMap.empty()) {
        // The highest load's field again (one more solve, warm-started from nothing): written as
        // a text matrix the areal reader reads back (rows along x, one per line, along y), by the
        // core's rules for a writer (io/Files.hpp): only over a pressure map this tool wrote, through
        // a temporary file renamed over it once complete.
        const double top = *std::max_element(loads.begin(), loads.end());
        current = loads.size();
        std::vector<double> pressure;
        model.solve(top, &pressure);
        std::ostringstream map;
        map << pressureMapHeader << " at F/(A_n E') = " << top << "; " << surface.nx() << " x " << surface.ny()
            << " points at dx = " << surface.dx() << " m, dy = " << surface.dy()
            << " m; rows along x, one per line, following each other along y\n";
        map.precision(8);
        for (std::size_t iy = 0; iy < surface.ny(); ++iy) {
            for (std::size_t ix = 0; ix < surface.nx(); ++ix) {
                map << (ix > 0 ? " " : "") << (pressure.empty() ? 0.0 : pressure[iy * surface.nx() + ix]);
            }
            map << '\n';
        }
        replaceFile(o.pressureMap, map.str(), "--pressure-map", "pressure map of multiscaleContact", isPressureMap);
    }
    std::cout << out.str();
    return 0;
}

} // namespace multiscaleContact
