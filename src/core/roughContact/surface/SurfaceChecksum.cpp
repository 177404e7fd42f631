// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/SurfaceChecksum.hpp"

#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cstring>

namespace roughContact {

namespace {

constexpr std::uint64_t fnvOffsetBasis = 0xcbf29ce484222325ULL;
constexpr std::uint64_t fnvPrime = 0x100000001b3ULL;

std::uint64_t addDouble(std::uint64_t hash, double value)
{
    if (value == 0.0) {
        value = 0.0; // -0.0 and +0.0 are the same surface
    }
    static_assert(sizeof(double) == sizeof(std::uint64_t), "IEEE-754 binary64 expected");
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int byte = 0; byte < 8; ++byte) {
        hash ^= (bits >> (8 * byte)) & 0xffU;
        hash *= fnvPrime;
    }
    return hash;
}

} // namespace

std::uint64_t surfaceChecksum(const Spectrum& surface)
{
    std::uint64_t hash = fnvOffsetBasis;
    const std::vector<double>& f = surface.frequencies();
    const std::vector<double>& beta = surface.amplitudes();
    for (std::size_t i = 0; i < f.size(); ++i) {
        hash = addDouble(hash, f[i]);
        hash = addDouble(hash, beta[i]);
    }
    return addDouble(hash, surface.length());
}

std::uint64_t surfaceChecksum(const Spectrum& lineScan, const ArealSurface& solved, bool periodic, bool mirrored)
{
    std::uint64_t hash = surfaceChecksum(lineScan);
    hash = addDouble(hash, double(solved.nx()));
    hash = addDouble(hash, double(solved.ny()));
    hash = addDouble(hash, solved.dx());
    hash = addDouble(hash, solved.dy());
    for (double z : solved.heights()) {
        hash = addDouble(hash, z);
    }
    return addDouble(hash, mirrored ? 2.0 : periodic ? 1.0 : 0.0);
}

std::string checksumHex(std::uint64_t value)
{
    static const char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 15; i >= 0; --i) {
        s[static_cast<std::size_t>(i)] = digits[value & 0xfU];
        value >>= 4;
    }
    return s;
}

std::string surfaceChecksumHex(const Spectrum& surface)
{
    return checksumHex(surfaceChecksum(surface));
}

} // namespace roughContact
