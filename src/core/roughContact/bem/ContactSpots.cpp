// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/bem/ContactSpots.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace roughContact {

namespace {

// A run of cells in contact along x: row y, cells [begin, end).
struct Run {
    std::size_t begin;
    std::size_t end;
};

struct Forest {
    std::vector<std::size_t> parent;
    std::size_t find(std::size_t a)
    {
        while (parent[a] != a) {
            parent[a] = parent[parent[a]];
            a = parent[a];
        }
        return a;
    }
    void join(std::size_t a, std::size_t b)
    {
        a = find(a);
        b = find(b);
        if (a != b) {
            parent[std::max(a, b)] = std::min(a, b);
        }
    }
};

// Joins the runs of two rows that share an edge: [a0, a1) and [b0, b1) the rows' run indices.
void joinRows(const std::vector<Run>& runs, std::size_t a0, std::size_t a1, std::size_t b0, std::size_t b1,
              Forest& f)
{
    std::size_t i = a0;
    std::size_t j = b0;
    while (i < a1 && j < b1) {
        if (runs[i].begin < runs[j].end && runs[j].begin < runs[i].end) {
            f.join(i, j);
        }
        // The run that ends first can overlap nothing further on.
        if (runs[i].end < runs[j].end) {
            ++i;
        } else {
            ++j;
        }
    }
}

} // namespace

ContactSpots contactSpots(const std::vector<bool>& contact, std::size_t nx, std::size_t ny, double dx,
                          double dy, bool periodic)
{
    if (contact.size() != nx * ny) {
        throw ParameterError("contact", "has " + std::to_string(contact.size()) + " cells, not nx ny = " +
                                            std::to_string(nx) + " x " + std::to_string(ny));
    }
    // isfinite first: a NaN is never compared (the tests trap FE_INVALID, as OpenFOAM does).
    if (!(std::isfinite(dx) && std::isfinite(dy) && dx > 0.0 && dy > 0.0)) {
        throw ParameterError("contact", "needs a positive, finite cell size dx, dy");
    }
    std::vector<Run> runs;
    std::vector<std::size_t> firstRun(ny + 1, 0); // the runs of row y: [firstRun[y], firstRun[y + 1])
    for (std::size_t y = 0; y < ny; ++y) {
        firstRun[y] = runs.size();
        std::size_t x = 0;
        while (x < nx) {
            if (!contact[y * nx + x]) {
                ++x;
                continue;
            }
            const std::size_t begin = x;
            while (x < nx && contact[y * nx + x]) {
                ++x;
            }
            runs.push_back({begin, x});
        }
    }
    firstRun[ny] = runs.size();
    Forest f;
    f.parent.resize(runs.size());
    std::iota(f.parent.begin(), f.parent.end(), std::size_t(0));
    for (std::size_t y = 0; y < ny; ++y) {
        const std::size_t a0 = firstRun[y];
        const std::size_t a1 = firstRun[y + 1];
        if (y > 0) {
            joinRows(runs, firstRun[y - 1], a0, a0, a1, f);
        }
        // Across the period's edge along x: a run ending at nx meets the row's run beginning at 0.
        if (periodic && a1 > a0 && runs[a0].begin == 0 && runs[a1 - 1].end == nx) {
            f.join(a0, a1 - 1);
        }
    }
    // Across the period's edge along y: the last row meets the first.
    if (periodic && ny > 1) {
        joinRows(runs, firstRun[ny - 1], firstRun[ny], firstRun[0], firstRun[1], f);
    }
    std::vector<double> cells(runs.size(), 0.0);
    for (std::size_t r = 0; r < runs.size(); ++r) {
        cells[f.find(r)] += static_cast<double>(runs[r].end - runs[r].begin);
    }
    ContactSpots out;
    const double cellArea = dx * dy;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        if (f.parent[r] == r) { // a spot's root run: the one run of each spot that is its own parent
            const double area = cells[r] * cellArea;
            ++out.count;
            out.radiusSum += std::sqrt(area / pi);
            out.largestArea = std::max(out.largestArea, area);
        }
    }
    return out;
}

} // namespace roughContact
