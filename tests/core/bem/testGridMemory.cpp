// SPDX-License-Identifier: GPL-3.0-or-later
// The memory of the boundary-element grids (bem/GridMemory.hpp): aligned as the transforms need
// (64 bytes) and, from 2 MiB on, to whole huge pages advised to the kernel; a GridField holds
// its values as any vector does. The advice is checked where the kernel takes it (the
// mapping's VmFlags); whether the kernel then gives huge pages is its own choice (printed, not
// asserted: a fragmented machine may have none to give).
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

// The lines of the mapping that holds p in /proc/self/smaps (empty where there is none).
std::string mappingOf(const void* p)
{
    std::ifstream smaps("/proc/self/smaps");
    std::string line, out;
    bool inside = false;
    while (std::getline(smaps, line)) {
        unsigned long lo = 0, hi = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &lo, &hi) == 2) { // a mapping's first line
            inside = address(p) >= lo && address(p) < hi;
        }
        if (inside) {
            out += line + "\n";
        }
    }
    return out;
}

// Advised for huge pages: the mapping's VmFlags carry "hg" (MADV_HUGEPAGE).
bool advised(const void* p)
{
    const std::string m = mappingOf(p);
    const std::size_t flags = m.find("VmFlags:");
    return flags != std::string::npos && m.find(" hg", flags) != std::string::npos;
}

// The kernel has transparent huge pages (it takes the advice).
bool kernelHasHugePages()
{
    return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
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
        if (kernelHasHugePages()) {
            // Its whole huge pages advised, and no more: the part past them (a grid's last
            // rows) is not, so that nothing is rounded up to a whole huge page.
            EXPECT_TRUE(advised(p)) << bytes << "\n" << mappingOf(p);
            if (bytes % huge != 0) {
                EXPECT_FALSE(advised(static_cast<char*>(p) + bytes / huge * huge)) << bytes;
            }
        }
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
    // Whether the kernel gave huge pages is its choice (a fragmented machine may have none):
    // printed, not asserted.
    const std::string m = mappingOf(copy.data());
    const std::size_t at = m.find("AnonHugePages:");
    std::printf("the copy's mapping: %s", at == std::string::npos ? "unknown\n" : m.substr(at, m.find('\n', at) - at + 1).c_str());
}
