// SPDX-License-Identifier: GPL-3.0-or-later
// The memory of the boundary-element grids: the transforms' buffers and the solvers' fields.
// A grid of 1024^2 doubles is 8 MiB, 2048 pages of 4 KiB: the transforms' column passes step
// through it a row (a page or more) at a time, each step a miss of the processor's page table
// cache (TLB), and every page is a fault when first written. Arrays of 2 MiB and more are
// therefore aligned to 2 MiB and their whole 2 MiB pages advised to the kernel as transparent
// huge pages (Linux madvise(MADV_HUGEPAGE); with the setting "madvise", Debian's, the kernel
// gives huge pages only to memory so advised; with "always" it gives them anyway, and this
// adds nothing): 4 pages instead of 2048. Measured (docs/benchmarks.md, "Huge pages for the
// grids"): a cold solve 5 % faster on one thread at 1024^2 and 2048^2, 6-13 % on two threads at
// 1024^2. Where the kernel gives no huge pages the memory is the same, in small pages. The
// values are the same either way: only where they live changes.
#pragma once

#include <cstddef>
#include <limits>
#include <new>
#include <vector>

namespace roughContact {

/// `bytes` of memory aligned to 64 bytes (FFTW's SIMD needs 16), and from 2 MiB on aligned to
/// 2 MiB, its whole 2 MiB pages advised for huge pages; std::bad_alloc when there is none. Not
/// initialized. Free it with freeGridMemory.
void* allocateGridMemory(std::size_t bytes);
void freeGridMemory(void* p) noexcept;

/// A std::allocator for grid fields (allocateGridMemory).
template <class T>
struct GridAllocator {
    using value_type = T;
    GridAllocator() noexcept = default;
    template <class U>
    GridAllocator(const GridAllocator<U>&) noexcept
    {
    }
    T* allocate(std::size_t n)
    {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) {
            throw std::bad_alloc();
        }
        return static_cast<T*>(allocateGridMemory(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t) noexcept { freeGridMemory(p); }
};
template <class T, class U>
bool operator==(const GridAllocator<T>&, const GridAllocator<U>&) noexcept
{
    return true;
}
template <class T, class U>
bool operator!=(const GridAllocator<T>&, const GridAllocator<U>&) noexcept
{
    return false;
}

/// A field of a grid: one value per cell, in grid memory.
using GridField = std::vector<double, GridAllocator<double>>;

} // namespace roughContact
