// SPDX-License-Identifier: GPL-3.0-or-later
// The memory of the boundary-element grids (bem/GridMemory.hpp): aligned as the transforms need
// (64 bytes) and, from 2 MiB on, to whole huge pages advised to the kernel; a GridField holds
// its values as any vector does. Whether the kernel then gives huge pages is its own choice
// (printed where it can be seen, not asserted: a fragmented machine may have none to give).
#include "roughContact/bem/GridMemory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

using namespace roughContact;

namespace {
std::uintptr_t address(const void* p)
{
    return reinterpret_cast<std::uintptr_t>(p);
}

// The kB of huge pages in the mapping that holds p (/proc/self/smaps), or -1 where unknown.
long hugeKilobytesAt(const void* p)
{
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        unsigned long lo = 0, hi = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &lo, &hi) == 2) { // a mapping's first line
            inside = address(p) >= lo && address(p) < hi;
            continue;
        }
        long kb = 0;
        if (inside && std::sscanf(line.c_str(), "AnonHugePages: %ld kB", &kb) == 1) {
            return kb;
        }
    }
    return -1;
}
} // namespace

TEST(GridMemory, SmallArraysAreAlignedForTheTransformsAndLargeOnesToHugePages)
{
    const std::size_t huge = std::size_t(2) << 20;
    for (std::size_t bytes : {std::size_t(1), std::size_t(100), std::size_t(64 * 1024), huge - 8}) {
        void* p = allocateGridMemory(bytes);
        EXPECT_EQ(address(p) % 64, 0u) << bytes;
        freeGridMemory(p);
    }
    for (std::size_t bytes : {huge, huge + 8, 3 * huge + 1}) {
        void* p = allocateGridMemory(bytes);
        EXPECT_EQ(address(p) % huge, 0u) << bytes;
        static_cast<char*>(p)[bytes - 1] = 1; // the last byte is there
        freeGridMemory(p);
    }
    EXPECT_THROW(GridAllocator<double>().allocate(std::size_t(-1) / 4), std::bad_alloc);
}

TEST(GridMemory, AGridFieldIsAVectorOfItsValues)
{
    const std::size_t n = 1024 * 1024; // 8 MiB: 4 huge pages
    GridField f(n, 1.5);
    EXPECT_EQ(address(f.data()) % (std::size_t(2) << 20), 0u);
    for (std::size_t i = 0; i < n; i += 4099) {
        ASSERT_EQ(f[i], 1.5) << i;
    }
    f[n - 1] = 2.0;
    const GridField copy = f;
    EXPECT_EQ(copy, f);
    GridField().swap(f);
    EXPECT_TRUE(f.empty());
    const long kb = hugeKilobytesAt(copy.data());
    std::printf("the copy's mapping holds %ld kB of huge pages (transparent_hugepage: %s)\n", kb,
                [] {
                    std::ifstream s("/sys/kernel/mm/transparent_hugepage/enabled");
                    std::string v;
                    std::getline(s, v);
                    return v;
                }()
                    .c_str());
}
