// SPDX-License-Identifier: GPL-3.0-or-later
// The threads of the boundary-element solves (the transforms' rows and columns, FFTW's threads
// with measured 2-D plans, and the solvers' own loops), and
// the loops they run: each loop's answer is the same for any number of threads, bit for bit.
#pragma once

#include <algorithm>
#include <cstddef>
#include <mutex>
#include <vector>

namespace roughContact {

/// The threads the core uses for its boundary-element work (HalfSpaceOperator's FFTs and the
/// solvers' loops; operators made after a change use it). Default: the processors this process
/// may run on (usableThreads). 1 = serial. setThreads takes 1 to limits::maximumThreads and
/// uses at most usableThreads() of them: more cannot make a solve faster (the answer is the same
/// for any number) and cost a thread's memory each. A build without OpenMP has 1 only
/// (threadsAvailable() false): setThreads accepts any n >= 1 and uses one.
void setThreads(int n);
int threads() noexcept;
/// setThreads without the cap at usableThreads(): for the tests of the loops, whose answer must
/// not depend on the number of threads, more of them than a small machine has cores.
void setThreadsUncapped(int n);
/// The machine's hardware threads (at least 1).
int hardwareThreads() noexcept;
/// The processors this process may run on (its CPU affinity; hardwareThreads() where it cannot
/// be read), at least 1.
int usableThreads() noexcept;
/// True when the core was built with OpenMP (more than one thread can run).
bool threadsAvailable() noexcept;

/// FFTW's planner (making and destroying plans, its wisdom and thread settings) is not
/// thread-safe: every use of it in the core holds this lock, so that the core's objects (grids,
/// synthesized surfaces, solves) may be made on several threads at once.
std::mutex& fftwPlanner();
/// f() with fftwPlanner() held; its result.
template <class F>
auto underFftwPlanner(F&& f)
{
    const std::lock_guard<std::mutex> lock(fftwPlanner());
    return f();
}

namespace parallel {

/// Loops shorter than this run serially (a thread team costs more than they do).
inline constexpr std::size_t minimumParallelSize = 16384;
/// The block of a reduction: partial results per block, combined in block order, so that a
/// sum is the same for any number of threads (and for one).
inline constexpr std::size_t reductionBlock = 4096;

/// (Loop bodies are arithmetic and must not throw: an exception leaving an OpenMP region ends
/// the process.)
///
/// body(begin, end, context) over [0, n) in pieces, on threads() threads when n items of
/// `weight` elements each are at least minimumParallelSize elements (the pieces of one call
/// are disjoint: body may write its own items).
void forRange(std::size_t n, std::size_t weight, void (*body)(std::size_t, std::size_t, void*), void* context);

template <class Body>
void forEach(std::size_t n, Body&& body)
{
    forRange(
        n, 1,
        [](std::size_t begin, std::size_t end, void* c) {
            Body& b = *static_cast<Body*>(c);
            for (std::size_t i = begin; i < end; ++i) {
                b(i);
            }
        },
        &body);
}

/// The reduction of body(i, acc) over [0, n): each block of reductionBlock elements from a copy
/// of `init`, the blocks then combined in order by combine(acc, blockAcc). The same answer for
/// any number of threads.
template <class Acc, class Body, class Combine>
Acc reduce(std::size_t n, const Acc& init, Body&& body, Combine&& combine)
{
    const std::size_t blocks = (n + reductionBlock - 1) / reductionBlock;
    std::vector<Acc> part(blocks, init);
    struct Context {
        Body& body;
        std::vector<Acc>& part;
        std::size_t n;
    } context{body, part, n};
    forRange(
        blocks, reductionBlock,
        [](std::size_t begin, std::size_t end, void* c) {
            Context& x = *static_cast<Context*>(c);
            for (std::size_t b = begin; b < end; ++b) {
                const std::size_t last = std::min((b + 1) * reductionBlock, x.n);
                // A local accumulator (in registers: the arrays body writes cannot alias it)
                Acc acc = x.part[b];
                for (std::size_t i = b * reductionBlock; i < last; ++i) {
                    x.body(i, acc);
                }
                x.part[b] = acc;
            }
        },
        &context);
    Acc out = init;
    for (const Acc& a : part) {
        combine(out, a);
    }
    return out;
}

} // namespace parallel
} // namespace roughContact
