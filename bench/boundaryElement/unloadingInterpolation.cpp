// SPDX-License-Identifier: GPL-3.0-or-later
// How close the boundary-element table's unloading is between its solved peaks
// (docs/theory.md §7.6): a power law synthesized on N x N (default 256) periodic cells, steel
// (E' = 110 GPa) with the cap H (default 1.14 GPa, 2.84 x 0.4 GPa), the table 1e-6 E' to
// 0.95 H at 6 loads a decade. At every table load that is not a solved peak, the exact unloading
// curve from it (BoundaryElementModel::loadPath) against the table's interpolation
// (ContactInterface::face with that peak), at the curve's loads down to P/P_max = 0.03; and the
// grid's own scatter: the largest difference at the same fraction between the exact curves of
// two neighbouring loads. Prints one row per peak.
//   unloadingInterpolation [N] [H]
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

using namespace roughContact;

int main(int argc, char** argv)
{
    const std::size_t n = argc > 1 ? std::size_t(std::atoi(argv[1])) : 256;
    const double H = argc > 2 ? std::atof(argv[2]) : 1.136e9;
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::powerLaw;
    s.parameters = {2.56e-4, 0.8, 1e3, 64e3};
    s.length = 1e-3;
    spec.surfaces = {s};
    spec.side1 = spec.side2 = Material{200e9, 0.3, 0.4e9};
    spec.model = "boundaryElement";
    spec.synthesize = n;
    spec.hardness = H;
    const BoundaryElementTable table(spec);
    const BoundaryElementTablePoints points = table.build();
    const ContactInterface iface(spec, &points);
    BoundaryElementOptions bo;
    bo.periodic = true;
    bo.hardness = H;
    const BoundaryElementModel model(table.surface(), table.reducedModulus(), bo);

    const std::vector<std::size_t> peaks = table.unloadingPeaks(points.pressures.size());
    // The exact curve from load j at every load down to 2 decades (by index: same fractions).
    const std::size_t span = 2 * spec.bemPointsPerDecade;
    std::map<std::size_t, std::vector<double>> rho; // ln(h_unloading/h_loading) at j-1, j-2, ...
    const auto curve = [&](std::size_t j) -> const std::vector<double>& {
        auto found = rho.find(j);
        if (found != rho.end()) {
            return found->second;
        }
        std::vector<double> loads;
        for (std::size_t d = 1; d <= std::min(span, j); ++d) {
            loads.push_back(table.loads()[j - d]);
        }
        const std::vector<BoundaryElementPoint> path = model.loadPath(table.loads()[j], loads);
        std::vector<double> r;
        for (std::size_t d = 1; d <= path.size(); ++d) {
            r.push_back(std::log(path[d - 1].conductancePerConductivity / points.conductancesPerConductivity[j - d]));
        }
        return rho[j] = r;
    };
    std::printf("# %zu x %zu cells, H/E' = %.4g; %zu solved peaks; fractions P/P_max >= 0.03\n", n, n,
                H / table.reducedModulus(), peaks.size());
    std::printf("P_max/H,unloading_over_loading_max,interpolated_over_exact_worst,neighbours_scatter\n");
    for (std::size_t j = 2; j + 1 < points.pressures.size(); ++j) {
        if (std::find(peaks.begin(), peaks.end(), j) != peaks.end()) {
            continue;
        }
        const std::vector<double>& exact = curve(j);
        const std::vector<double>& next = curve(j + 1);
        double effect = 0.0, worst = 0.0, scatter = 0.0;
        for (std::size_t d = 1; d <= exact.size(); ++d) {
            const double P = points.pressures[j - d];
            if (P / points.pressures[j] < 0.03) {
                break;
            }
            const double hExact = std::exp(exact[d - 1]) * points.conductancesPerConductivity[j - d];
            const double h = iface.face(P, 1.0, 1.0, points.pressures[j]).conductance;
            effect = std::max(effect, std::abs(exact[d - 1]));
            worst = std::max(worst, std::abs(std::log(h / hExact)));
            if (d <= next.size()) {
                scatter = std::max(scatter, std::abs(exact[d - 1] - next[d - 1]));
            }
        }
        std::printf("%.3g,%.3f,%.3f,%.3f\n", points.pressures[j] / H, std::exp(effect), std::exp(worst),
                    std::exp(scatter));
    }
}
