// SPDX-License-Identifier: GPL-3.0-or-later
// How far one exact solve is from the limit its transforms set (issue 23, item 1): one cold load
// on the benchmarks' periodic surface (Rq 0.8 um, rms slope 0.1, synthesized N x N, seed 1,
// steel on steel), the contact solve then the conductance solve as BoundaryElementModel makes
// them, on one thread (threads T: on T). Prints their iterations, the forward/inverse transform pairs each used
// (HalfSpaceOperator::transformPairs), the seconds of one pair (median of 15, timed here on the
// same operator), and the transforms' share of the measured time: pairs x seconds per pair
// against the total. The rest is the solvers' own loops over the grid.
// Usage: transformBound N LOAD [plain] [wisdom FILE] [padded | mirrored] [threads T]
//   plain: without the stiffness preconditioner (PolonskyKeerOptions::precondition false).
//   padded, mirrored: the operator's edges (HalfSpaceOperator::Edges; default periodic), the
//   same surface solved as a zero-padded patch or mirrored about its edges (other problems:
//   for the cost of a pair on the same grid).
//   wisdom FILE: measured FFT plans kept in FILE (setFftWisdom), as --fft-wisdom.
//   threads T: the solves on T threads (setThreads; default 1), as --threads.
#include "roughContact/bem/HalfSpaceOperator.hpp"
#include "roughContact/bem/PolonskyKeer.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/parallel/Threads.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/RoughnessSpectrum.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace roughContact;

namespace {
double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}
} // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: transformBound N LOAD [plain] [wisdom FILE] [padded | mirrored] [threads T]\n");
        return 1;
    }
    const auto n = static_cast<std::size_t>(std::atol(argv[1]));
    const double load = std::atof(argv[2]);
    bool precondition = true;
    HalfSpaceOperator::Edges edges = HalfSpaceOperator::Edges::periodic;
    int threads = 1;
    for (int i = 3; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "plain") {
            precondition = false;
        } else if (a == "padded") {
            edges = HalfSpaceOperator::Edges::padded;
        } else if (a == "mirrored") {
            edges = HalfSpaceOperator::Edges::mirrored;
        } else if (a == "threads" && i + 1 < argc) {
            threads = std::atoi(argv[++i]);
        } else if (a == "wisdom" && i + 1 < argc) {
            setFftWisdom(argv[++i]);
        } else {
            std::fprintf(stderr, "transformBound: unknown argument '%s'\n", argv[i]);
            return 1;
        }
    }
    setThreads(threads);
    const ArealSurface surface =
        synthesizeIsotropic(roughnessSpectrum(0.8e-6, 0.1).spectrum, n, 1).detrended(Detrend::mean);
    const double Eprime = 1.0 / (2.0 * (1.0 - 0.3 * 0.3) / 2e11);
    const HalfSpaceOperator op(n, n, surface.dx(), surface.dy(), Eprime, edges);
    PolonskyKeerOptions options;
    options.precondition = precondition;
    const PolonskyKeer solver(op, surface.heights(), options);

    const auto t0 = std::chrono::steady_clock::now();
    const ContactSolution s = solver.solve(load * Eprime);
    const auto t1 = std::chrono::steady_clock::now();
    const std::size_t contactPairs = op.transformPairs();
    std::vector<bool> contact(s.pressure.size());
    for (std::size_t i = 0; i < contact.size(); ++i) {
        contact[i] = s.pressure[i] > 0.0;
    }
    const SpotConductance c = spotConductance(op, contact, conductanceTolerance, 20000, nullptr, nullptr, precondition);
    const auto t2 = std::chrono::steady_clock::now();
    const std::size_t conductancePairs = op.transformPairs() - contactPairs;

    std::vector<double> p(op.size(), 1.0), u(op.size());
    std::vector<double> pair;
    for (int k = 0; k < 15; ++k) {
        const auto a = std::chrono::steady_clock::now();
        op.apply(p.data(), u.data());
        pair.push_back(seconds(a, std::chrono::steady_clock::now()));
    }
    std::sort(pair.begin(), pair.end());
    const double perPair = pair[pair.size() / 2];

    const double contactSeconds = seconds(t0, t1);
    const double conductanceSeconds = seconds(t1, t2);
    const double total = contactSeconds + conductanceSeconds;
    const std::size_t pairs = contactPairs + conductancePairs;
    const char* edgesName = edges == HalfSpaceOperator::Edges::padded     ? ", padded"
                            : edges == HalfSpaceOperator::Edges::mirrored ? ", mirrored"
                                                                          : "";
    std::printf("%zu^2, p/E' = %g, %s%s%s: A_r/A_n %.6f, h_c/k_s %.6g 1/m\n", n, load,
                precondition ? "preconditioned" : "plain", fftWisdom().empty() ? "" : ", measured plans", edgesName,
                s.areaFraction, c.perConductivity);
    std::printf("  contact:     %4zu iterations, %4zu pairs (%.2f a iteration), %7.3f s\n", s.iterations,
                contactPairs, double(contactPairs) / double(std::max<std::size_t>(s.iterations, 1)), contactSeconds);
    std::printf("  conductance: %4zu iterations, %4zu pairs (%.2f a iteration), %7.3f s\n", c.iterations,
                conductancePairs, double(conductancePairs) / double(std::max<std::size_t>(c.iterations, 1)),
                conductanceSeconds);
    std::printf("  one pair %.4f s (median of 15, %.4f-%.4f); %zu pairs = %.3f s of %.3f s: transforms %.0f %%,"
                " the rest %.3f s\n",
                perPair, pair.front(), pair.back(), pairs, double(pairs) * perPair, total,
                100.0 * double(pairs) * perPair / total, total - double(pairs) * perPair);
    return 0;
}
