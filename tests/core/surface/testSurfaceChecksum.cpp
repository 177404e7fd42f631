// SPDX-License-Identifier: GPL-3.0-or-later
// The surface checksum a run records (SurfaceChecksum.hpp): FNV-1a over the IEEE bytes of the
// levels and the length.
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/surface/SurfaceChecksum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace roughContact;

namespace {
Spectrum threeLevels()
{
    return Spectrum({1e3, 2e3, 3e3}, {1e-6, 0.5e-6, 0.25e-6}, 1e-3, "a");
}
} // namespace

TEST(SurfaceChecksum, knownValueOfOneLevelComputedByHand)
{
    // FNV-1a 64 over the 24 bytes (least significant first) of f = 1000 (0x408f400000000000),
    // beta = 1e-6 (0x3eb0c6f7a0b5ed8d), L = 1e-3 (0x3f50624dd2f1a9fc), computed independently
    // (Python: struct.pack('<ddd', 1000.0, 1e-6, 1e-3), h ^= byte, h *= 0x100000001b3 mod 2^64).
    const Spectrum s({1000.0}, {1e-6}, 1e-3);
    EXPECT_EQ(surfaceChecksum(s), 0xf906c117b4359c24ULL);
    EXPECT_EQ(surfaceChecksumHex(s), "f906c117b4359c24");
}

TEST(SurfaceChecksum, hexHasSixteenDigitsWithLeadingZeros)
{
    EXPECT_EQ(checksumHex(0), "0000000000000000");
    EXPECT_EQ(checksumHex(0xabcULL), "0000000000000abc");
    EXPECT_EQ(checksumHex(0xffffffffffffffffULL), "ffffffffffffffff");
    // FNV-1a's published test vector of "a" would be af63dc4c8601ec8c; the hex form of it:
    EXPECT_EQ(checksumHex(0xaf63dc4c8601ec8cULL), "af63dc4c8601ec8c");
}

TEST(SurfaceChecksum, equalSpectraHaveEqualChecksums)
{
    // The source name is not part of the surface.
    const Spectrum a = threeLevels();
    const Spectrum b({1e3, 2e3, 3e3}, {1e-6, 0.5e-6, 0.25e-6}, 1e-3, "another name");
    EXPECT_EQ(surfaceChecksum(a), surfaceChecksum(b));
    EXPECT_EQ(surfaceChecksum(Spectrum::powerLaw(1e-8, 1.5, 1e3, 1e5)),
              surfaceChecksum(Spectrum::powerLaw(1e-8, 1.5, 1e3, 1e5)));
}

TEST(SurfaceChecksum, anyChangedAmplitudeFrequencyOrLengthChangesIt)
{
    const Spectrum base = threeLevels();
    const std::uint64_t c0 = surfaceChecksum(base);
    std::set<std::uint64_t> seen{c0};
    for (std::size_t i = 0; i < base.size(); ++i) {
        std::vector<double> beta = base.amplitudes();
        beta[i] = std::nextafter(beta[i], 1.0); // the smallest change there is
        const std::uint64_t c = surfaceChecksum(Spectrum(base.frequencies(), beta, base.length()));
        EXPECT_TRUE(seen.insert(c).second) << "amplitude " << i;

        std::vector<double> f = base.frequencies();
        f[i] = std::nextafter(f[i], 0.0);
        const std::uint64_t cf = surfaceChecksum(Spectrum(f, base.amplitudes(), base.length()));
        EXPECT_TRUE(seen.insert(cf).second) << "frequency " << i;
    }
    const double L = std::nextafter(base.length(), 1.0);
    EXPECT_TRUE(seen.insert(surfaceChecksum(Spectrum(base.frequencies(), base.amplitudes(), L))).second);
    // One level fewer, and an amplitude set to zero.
    EXPECT_TRUE(seen.insert(surfaceChecksum(base.truncated(2.5e3))).second);
    EXPECT_TRUE(
        seen.insert(surfaceChecksum(Spectrum(base.frequencies(), {1e-6, 0.0, 0.25e-6}, 1e-3))).second);
    // Swapping two amplitudes (same multiset of bytes) changes it too: the order counts.
    EXPECT_TRUE(
        seen.insert(surfaceChecksum(Spectrum(base.frequencies(), {0.5e-6, 1e-6, 0.25e-6}, 1e-3))).second);
}

TEST(SurfaceChecksum, negativeZeroIsZero)
{
    EXPECT_EQ(surfaceChecksum(Spectrum({1e3, 2e3}, {1e-6, 0.0}, 1e-3)),
              surfaceChecksum(Spectrum({1e3, 2e3}, {1e-6, -0.0}, 1e-3)));
}
