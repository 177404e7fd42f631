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
    void* p = nullptr;
    if (posix_memalign(&p, huge ? hugePage : simdAlignment, bytes > 0 ? bytes : 1) != 0 || p == nullptr) {
        throw std::bad_alloc();
    }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge) {
        // The whole huge pages inside the array only: its last part (a grid's rows of mx/2 + 1
        // values end just past a page) stays in small pages, so no memory is added. Advice
        // only: a kernel without transparent huge pages refuses it (EINVAL), one with them
        // turned off ignores it, and the memory stays in small pages.
        (void)madvise(p, bytes / hugePage * hugePage, MADV_HUGEPAGE);
    }
#endif
    return p;
}

void freeGridMemory(void* p) noexcept
{
    std::free(p);
}

} // namespace roughContact
