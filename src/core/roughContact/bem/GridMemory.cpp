// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/bem/GridMemory.hpp"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace roughContact {

namespace {
constexpr std::size_t hugePage = std::size_t(2) << 20; // 2 MiB, the x86-64 and arm64 huge page
constexpr std::size_t simdAlignment = 64;
} // namespace

void* allocateGridMemory(std::size_t bytes)
{
    const bool huge = bytes >= hugePage;
    const std::size_t alignment = huge ? hugePage : simdAlignment;
    // Whole huge pages, so that the last one is not shared with other data.
    const std::size_t size = huge ? (bytes + hugePage - 1) / hugePage * hugePage : (bytes > 0 ? bytes : 1);
    void* p = nullptr;
    if (posix_memalign(&p, alignment, size) != 0 || p == nullptr) {
        throw std::bad_alloc();
    }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge) {
        // Advice only: where the kernel has no huge pages (or they are off) this fails and the
        // memory stays in small pages.
        (void)madvise(p, size, MADV_HUGEPAGE);
    }
#endif
    return p;
}

void freeGridMemory(void* p) noexcept
{
    std::free(p);
}

} // namespace roughContact
