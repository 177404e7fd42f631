// SPDX-License-Identifier: GPL-3.0-or-later
// The contact spots of a contact set (bem/ContactSpots): shapes counted by hand, the period's
// edges, a flood fill cell by cell on random sets, and the spots of solved contacts (a
// sinusoidal ridge's one strip, a bisinusoid's two spots and their conductance beside Holm's).
#include "roughContact/Error.hpp"
#include "roughContact/bem/ContactSpots.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace roughContact;

namespace {
constexpr double pi = 3.14159265358979323846;

// A grid drawn as text: '#' a cell in contact, rows from y = 0 down.
struct Drawn {
    std::vector<bool> cells;
    std::size_t nx = 0;
    std::size_t ny = 0;
};
Drawn drawn(const std::vector<std::string>& rows)
{
    Drawn d;
    d.ny = rows.size();
    d.nx = rows.front().size();
    for (const std::string& r : rows) {
        for (char c : r) {
            d.cells.push_back(c == '#');
        }
    }
    return d;
}

std::size_t count(const std::vector<std::string>& rows, bool periodic)
{
    const Drawn d = drawn(rows);
    return contactSpots(d.cells, d.nx, d.ny, 1.0, 1.0, periodic).count;
}

// The spots' areas in cells by a flood fill cell by cell (another method than the runs').
std::vector<std::size_t> floodFill(const std::vector<bool>& contact, std::size_t nx, std::size_t ny,
                                   bool periodic)
{
    std::vector<int> seen(contact.size(), 0);
    std::vector<std::size_t> areas;
    for (std::size_t start = 0; start < contact.size(); ++start) {
        if (!contact[start] || seen[start]) {
            continue;
        }
        std::size_t area = 0;
        std::vector<std::size_t> stack{start};
        seen[start] = 1;
        while (!stack.empty()) {
            const std::size_t c = stack.back();
            stack.pop_back();
            ++area;
            const long x = long(c % nx);
            const long y = long(c / nx);
            const long steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            for (const auto& s : steps) {
                long u = x + s[0];
                long v = y + s[1];
                if (periodic) {
                    u = (u + long(nx)) % long(nx);
                    v = (v + long(ny)) % long(ny);
                } else if (u < 0 || v < 0 || u >= long(nx) || v >= long(ny)) {
                    continue;
                }
                const std::size_t n = std::size_t(v) * nx + std::size_t(u);
                if (contact[n] && !seen[n]) {
                    seen[n] = 1;
                    stack.push_back(n);
                }
            }
        }
        areas.push_back(area);
    }
    return areas;
}
} // namespace

TEST(ContactSpots, ShapesCountedByHand)
{
    EXPECT_EQ(count({"....", "....", "...."}, true), 0u);
    EXPECT_EQ(count({"....", ".#..", "...."}, false), 1u);
    // Cells that share a corner only are two spots.
    EXPECT_EQ(count({"#...", ".#..", "...."}, false), 2u);
    // A U: its arms are two runs in the rows above and meet below.
    EXPECT_EQ(count({"#..#", "#..#", "####"}, false), 1u);
    // An upside-down U, and a run that meets two runs of the row above it.
    EXPECT_EQ(count({"####", "#..#", "#..#"}, false), 1u);
    EXPECT_EQ(count({"#.#.#", "#####", "....."}, false), 1u);
    // A comb whose teeth meet only in its last row, and a spiral.
    EXPECT_EQ(count({"#.#.#.#", "#.#.#.#", "#######"}, false), 1u);
    EXPECT_EQ(count({"#######", "#.....#", "#.###.#", "#.#.#.#", "#.#...#", "#.#####"}, false), 1u);
    // Rings inside each other are two.
    EXPECT_EQ(count({"#####", "#...#", "#.#.#", "#...#", "#####"}, false), 2u);
}

TEST(ContactSpots, AcrossThePeriodsEdges)
{
    // A spot cut by the edge along x, by the edge along y, and by both (the corner's four
    // pieces): one spot of a periodic surface, two or four of a patch.
    EXPECT_EQ(count({"....", "#..#", "...."}, true), 1u);
    EXPECT_EQ(count({"....", "#..#", "...."}, false), 2u);
    EXPECT_EQ(count({".#..", "....", ".#.."}, true), 1u);
    EXPECT_EQ(count({".#..", "....", ".#.."}, false), 2u);
    EXPECT_EQ(count({"#..#", "....", "#..#"}, true), 1u);
    EXPECT_EQ(count({"#..#", "....", "#..#"}, false), 4u);
    // Opposite corners meet at a corner only, across the period: two spots.
    EXPECT_EQ(count({"#...", "....", "...#"}, true), 2u);
    // A full row wraps onto itself along x: one spot, and a full grid is one spot.
    EXPECT_EQ(count({"....", "####", "...."}, true), 1u);
    EXPECT_EQ(count({"###", "###"}, true), 1u);
}

TEST(ContactSpots, AreasAndRadiiAreTheCellsOfEachSpot)
{
    // A 3 x 2 block and a single cell on cells of 2 x 0.5: areas 6 and 1 cells of 1 m^2.
    const Drawn d = drawn({"###....", "###..#.", "......."});
    const ContactSpots s = contactSpots(d.cells, d.nx, d.ny, 2.0, 0.5, false);
    ASSERT_EQ(s.count, 2u);
    EXPECT_DOUBLE_EQ(s.largestArea, 6.0);
    EXPECT_DOUBLE_EQ(s.radiusSum, std::sqrt(6.0 / pi) + std::sqrt(1.0 / pi));
    EXPECT_DOUBLE_EQ(s.meanRadius(), s.radiusSum / 2.0);
    // Holm: 2 sum a_i over the nominal area 14 x 1.5.
    EXPECT_DOUBLE_EQ(s.holmConductancePerConductivity(21.0), 2.0 * s.radiusSum / 21.0);
    EXPECT_EQ(ContactSpots{}.meanRadius(), 0.0);
}

TEST(ContactSpots, TheRunsAgreeWithAFloodFillCellByCell)
{
    // Random sets from sparse to nearly full, periodic and not, on grids of odd and even sizes:
    // the same number of spots and the same sum of radii (the areas sorted alike).
    std::mt19937 rng(7);
    for (const double density : {0.05, 0.3, 0.5, 0.593, 0.7, 0.95}) {
        for (const bool periodic : {false, true}) {
            for (const auto& [nx, ny] :
                 {std::pair<std::size_t, std::size_t>{37, 23}, {64, 64}, {1, 9}, {9, 1}}) {
                std::bernoulli_distribution in(density);
                std::vector<bool> contact(nx * ny);
                for (std::size_t i = 0; i < contact.size(); ++i) {
                    contact[i] = in(rng);
                }
                const std::vector<std::size_t> areas = floodFill(contact, nx, ny, periodic);
                double radiusSum = 0.0;
                std::size_t largest = 0;
                for (std::size_t a : areas) {
                    radiusSum += std::sqrt(double(a) / pi);
                    largest = std::max(largest, a);
                }
                const ContactSpots s = contactSpots(contact, nx, ny, 1.0, 1.0, periodic);
                EXPECT_EQ(s.count, areas.size()) << density << " " << periodic << " " << nx << "x" << ny;
                EXPECT_NEAR(s.radiusSum, radiusSum, 1e-9 * radiusSum) << density << " " << periodic;
                EXPECT_EQ(s.largestArea, double(largest)) << density << " " << periodic;
            }
        }
    }
}

TEST(ContactSpots, ABadGridIsRefused)
{
    const std::vector<bool> contact(12, false);
    EXPECT_THROW(contactSpots(contact, 5, 2, 1.0, 1.0, true), ParameterError);
    EXPECT_THROW(contactSpots(contact, 4, 3, 0.0, 1.0, true), ParameterError);
    EXPECT_THROW(contactSpots(contact, 4, 3, 1.0, std::nan(""), true), ParameterError);
    EXPECT_EQ(contactSpots(contact, 4, 3, 1.0, 1.0, true).count, 0u);
}

TEST(ContactSpots, ASolvedRidgeTouchesOnOneStripAndABisinusoidOnTwoSpots)
{
    const std::size_t n = 128;
    const double L = 1e-4;
    const double dx = L / double(n);
    const double Ep = 100e9;
    const double D = 1e-7;
    BoundaryElementOptions o;
    o.periodic = true;
    // z = D cos(2 pi x/L): the contact is one strip along y about x = 0, cut by the edge x = 0.
    std::vector<double> ridge(n * n);
    // z = D cos(2 pi x/L) cos(2 pi y/L): summits at (0, 0), cut by both edges, and (L/2, L/2).
    std::vector<double> bisinusoid(n * n);
    for (std::size_t iy = 0; iy < n; ++iy) {
        for (std::size_t ix = 0; ix < n; ++ix) {
            ridge[iy * n + ix] = D * std::cos(2 * pi * double(ix) / double(n));
            bisinusoid[iy * n + ix] =
                D * std::cos(2 * pi * double(ix) / double(n)) * std::cos(2 * pi * double(iy) / double(n));
        }
    }
    const BoundaryElementModel strip(ArealSurface(ridge, n, n, dx, dx, "ridge"), Ep, o);
    const BoundaryElementPoint r = strip.solve(1e-4);
    ASSERT_GT(r.areaFraction, 0.05);
    EXPECT_EQ(r.spots.count, 1u);
    EXPECT_DOUBLE_EQ(r.spots.largestArea, r.areaFraction * L * L);
    const BoundaryElementModel summits(ArealSurface(bisinusoid, n, n, dx, dx, "bisinusoid"), Ep, o);
    const BoundaryElementPoint b = summits.solve(2e-5);
    ASSERT_GT(b.areaFraction, 0.01);
    EXPECT_EQ(b.spots.count, 2u);
    // The two summits are alike (the surface is symmetric under a shift by (L/2, L/2)): each
    // half of the area, to the cells of their edges (a ring of 2 pi a/dx cells).
    const double half = 0.5 * b.areaFraction * L * L;
    const double a = std::sqrt(half / pi);
    EXPECT_NEAR(b.spots.largestArea / half, 1.0, 2 * pi * a / dx / (half / (dx * dx)));
    // The two radii sum to 2a whatever the split of the area between them to first order:
    // areas half (1 +- e) give 2a (1 - e^2/8), so 1 % allows a split of up to 28 %.
    EXPECT_NEAR(b.spots.radiusSum, 2 * a, 0.01 * a);
    // Holm's independent spots beside the exact conductance: in a periodic array each spot
    // draws its heat from its own share of the area, a flux tube, and constricts less than
    // alone in a half-space, by the Cooper-Mikic-Yovanovich factor psi(eps) = (1 - eps)^1.5,
    // eps = a/b = sqrt(A_r/A_n) (b the radius of a tube of the spot's share): Holm's sum lies
    // below the exact h by about psi. Within 5 %: psi is a circular tube's, and the spots' share
    // is a square cell of the lattice.
    const double holm = b.spots.holmConductancePerConductivity(L * L);
    const double psi = constrictionFactor(std::sqrt(b.areaFraction));
    std::printf("bisinusoid: a = %.3g L, Holm / exact h = %.4f, psi = %.4f\n", a / L,
                holm / b.conductancePerConductivity, psi);
    EXPECT_LT(holm, b.conductancePerConductivity);
    EXPECT_NEAR(holm / b.conductancePerConductivity, psi, 0.05);
    // Complete contact (the cap below the load): one spot, the whole period.
    o.hardness = 1e-6 * Ep;
    const BoundaryElementPoint full =
        BoundaryElementModel(ArealSurface(ridge, n, n, dx, dx, "ridge"), Ep, o).solve(2e-6);
    EXPECT_EQ(full.spots.count, 1u);
    EXPECT_DOUBLE_EQ(full.spots.largestArea, L * L);
}
