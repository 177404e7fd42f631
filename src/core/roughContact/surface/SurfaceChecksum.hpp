// SPDX-License-Identifier: GPL-3.0-or-later
// A stable 64-bit checksum of a surface's spectrum, so that a run can record which surface it
// used and a restart can tell when the surface has changed since.
#pragma once

#include <cstdint>
#include <string>

namespace roughContact {

class ArealSurface;
class Spectrum;

/// FNV-1a (64 bit: offset basis 0xcbf29ce484222325, prime 0x100000001b3) over the IEEE-754
/// binary64 bytes, least significant byte first, of f_1, beta_1, f_2, beta_2, ..., f_n, beta_n
/// and then the scan length L. The same on every platform and compiler (no hashing of the
/// host's memory layout); -0.0 is hashed as +0.0. Any change of a frequency, an amplitude, the
/// number of levels or L changes it (up to the 2^-64 chance of a collision).
std::uint64_t surfaceChecksum(const Spectrum& surface);

/// What a boundary-element interface solves: surfaceChecksum(lineScan) continued over the grid
/// (nx, ny, as binary64), the spacings dx, dy, every height of the solved areal surface, row by
/// row, and how it is solved: periodic 1.0, mirrored 2.0, else 0.0. A synthesized surface's seed or grid
/// size changes its heights, so it changes this (the spectrum alone does not).
std::uint64_t surfaceChecksum(const Spectrum& lineScan, const ArealSurface& solved, bool periodic,
                              bool mirrored = false);

/// value as 16 lower-case hexadecimal digits (leading zeros kept).
std::string checksumHex(std::uint64_t value);

/// checksumHex(surfaceChecksum(surface)).
std::string surfaceChecksumHex(const Spectrum& surface);

} // namespace roughContact
