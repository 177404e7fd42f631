// SPDX-License-Identifier: GPL-3.0-or-later
// The contact spots of a solved contact set: how many there are and how large (docs/theory.md
// §7.4, "Contact spots"). Holm's conductance of independent circular spots, 2 k_s sum a_i per
// nominal area, set beside the exact one tells how much the spots' shapes and their crowding
// on each other matter.
#pragma once

#include <cstddef>
#include <vector>

namespace roughContact {

/// The spots of a contact set on an nx x ny grid of cells dx x dy.
struct ContactSpots {
    std::size_t count = 0;    ///< connected sets of cells in contact
    double radiusSum = 0.0;   ///< sum over the spots of sqrt(A_i/pi) [m], A_i a spot's area
    double largestArea = 0.0; ///< the largest spot's area [m^2]

    /// sum a_i / count [m]; 0 without a spot.
    double meanRadius() const noexcept { return count > 0 ? radiusSum / static_cast<double>(count) : 0.0; }
    /// Holm's h_c/k_s of independent circular spots of the same areas, 2 sum a_i / A_n [1/m].
    double holmConductancePerConductivity(double nominalArea) const noexcept
    {
        return 2.0 * radiusSum / nominalArea;
    }
};

/// The spots of `contact` (row-major, contact[iy nx + ix] true where the cell is in contact):
/// two cells are in one spot when they share an edge (not a mere corner), and with `periodic`
/// also across the grid's edges (the surface one period of a periodic one). Memory: 32 bytes a
/// run (a row's stretch of cells in contact), about a byte per contact cell for spots 30 cells
/// wide; at most 16 bytes a cell (a set that alternates cell by cell), against the hundred or so
/// bytes a cell of the solve itself (boundaryElementBytes).
/// ParameterError naming "contact" when its size is not nx ny, or when dx or dy is not positive
/// and finite.
ContactSpots contactSpots(const std::vector<bool>& contact, std::size_t nx, std::size_t ny, double dx,
                          double dy, bool periodic);

} // namespace roughContact
