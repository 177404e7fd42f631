// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/parallel/Threads.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <string>
#include <thread>

#if defined(ROUGHCONTACT_OPENMP)
#include <omp.h>
#endif

namespace roughContact {

namespace {
std::atomic<int>& chosen()
{
    static std::atomic<int> n{usableThreads()};
    return n;
}

void requireThreads(int n)
{
    if (n < 1 || n > limits::maximumThreads) {
        throw ParameterError("threads", "must be 1 to " + std::to_string(limits::maximumThreads) + ", got " +
                                            std::to_string(n));
    }
}
} // namespace

std::mutex& fftwPlanner()
{
    static std::mutex m;
    return m;
}

int hardwareThreads() noexcept
{
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(n);
}

int usableThreads() noexcept
{
#if defined(__linux__)
    cpu_set_t set;
    CPU_ZERO(&set);
    if (::sched_getaffinity(0, sizeof set, &set) == 0) {
        const int n = CPU_COUNT(&set);
        if (n > 0) {
            return n;
        }
    }
#endif
    return hardwareThreads();
}

bool threadsAvailable() noexcept
{
#if defined(ROUGHCONTACT_OPENMP)
    return true;
#else
    return false;
#endif
}

void setThreads(int n)
{
    requireThreads(n);
    chosen() = std::min(n, usableThreads());
}

void setThreadsUncapped(int n)
{
    requireThreads(n);
    chosen() = n;
}

int threads() noexcept
{
#if defined(ROUGHCONTACT_OPENMP)
    return chosen();
#else
    return 1;
#endif
}

namespace parallel {

void forRange(std::size_t n, std::size_t weight, void (*body)(std::size_t, std::size_t, void*), void* context)
{
#if defined(ROUGHCONTACT_OPENMP)
    const int t = threads();
    if (t > 1 && n > 1 && n * weight >= minimumParallelSize) {
        const auto items = static_cast<long long>(n);
        // Static pieces, one per thread: which thread does a piece changes nothing in it.
#pragma omp parallel num_threads(t)
        {
            const long long k = omp_get_num_threads();
            const long long me = omp_get_thread_num();
            const long long begin = items * me / k;
            const long long end = items * (me + 1) / k;
            if (begin < end) {
                body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end), context);
            }
        }
        return;
    }
#else
    (void)weight;
#endif
    body(0, n, context);
}

} // namespace parallel
} // namespace roughContact
