// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/bem/HalfSpaceOperator.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/bem/GridMemory.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/io/TableReader.hpp"
#include "roughContact/parallel/Threads.hpp"

#include <fftw3.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>

#include <algorithm>
#include <cmath>
#include <string>
#include <complex>
#include <stdexcept>

namespace roughContact {

namespace {
// x asinh(y/|x|), 0 at x = 0 (its limit).
double term(double x, double y)
{
    return x == 0.0 ? 0.0 : x * std::asinh(y / std::abs(x));
}

double F(double x, double y)
{
    return term(x, y) + term(y, x);
}

// The periodic half-space's multipliers at the wavenumber q [1/m] (HalfSpaceOperator.hpp): the
// compliance u(q)/p(q) = 2/(E' q), 0 for the mean (q = 0); the stiffness E' q/2, at least that
// of the longest wavelength of a grid of lengths Lx, Ly, E' pi/max(Lx, Ly).
double compliance(double q, double Eprime)
{
    return q > 0.0 ? 2.0 / (Eprime * q) : 0.0;
}

double longestWaveStiffness(double Lx, double Ly, double Eprime)
{
    return 0.5 * Eprime * 2.0 * pi / std::max(Lx, Ly);
}

double stiffness(double q, double Eprime, double smallest)
{
    return std::max(0.5 * Eprime * q, smallest);
}

template <class T> struct GridFree {
    void operator()(T* p) const { freeGridMemory(p); }
};

// n Ts in grid memory (GridMemory.hpp: std::bad_alloc when there is none), freed with it.
template <class T> std::unique_ptr<T, GridFree<T>> gridArray(std::size_t n)
{
    return std::unique_ptr<T, GridFree<T>>(static_cast<T*>(allocateGridMemory(sizeof(T) * n)));
}

std::string& wisdomPath()
{
    static std::string path;
    return path;
}

// FFTW's threads, set up once before any other FFTW call that concerns plans (FFTW's manual,
// "Usage of Multi-threaded FFTW": fftw_init_threads first, before wisdom is imported too).
bool threadsReady()
{
#if defined(ROUGHCONTACT_OPENMP)
    static const bool ready = fftw_init_threads() != 0;
    return ready;
#else
    return false;
#endif
}

// FFTW plans its next transforms for `n` threads (its OpenMP threads; a serial build has one).
// FFTW's planner is not thread-safe: operators are made on one thread.
void planFor(int n)
{
#if defined(ROUGHCONTACT_OPENMP)
    fftw_plan_with_nthreads(threadsReady() ? n : 1);
#else
    (void)n;
#endif
}

constexpr const char* wisdomParameter = "FFT wisdom file";

// A file FFTW wrote as wisdom begins "(fftw-3.3.10 fftw_wisdom ...".
bool isWisdomText(const std::string& start)
{
    return start.rfind("(fftw-3", 0) == 0 && start.find(" fftw_wisdom", 0) != std::string::npos &&
           start.find(" fftw_wisdom") < 40;
}

// The wisdom file's text, read by the readers' rules (io/Files.hpp): empty when there is none.
// ParameterError when it is there but not FFTW wisdom.
std::string wisdomText(const std::string& path)
{
    const ExistingFile existing = existingFile(path);
    if (existing.kind == ExistingFile::Kind::none) {
        return std::string();
    }
    std::string text;
    try {
        text = readWholeFile(path, fileLimits::maximumWisdomBytes, "FFTW wisdom");
    } catch (const InputError& e) {
        throw ParameterError(wisdomParameter, "'" + path + "' " + e.message());
    }
    if (!isWisdomText(text)) {
        throw ParameterError(wisdomParameter, "'" + path + "' exists and is not FFTW wisdom (it begins '" +
                                                  detail::printable(text.substr(0, 40), 40) +
                                                  "'): it is left as it is; give another name");
    }
    return text;
}

// The planning of one grid's plans with the wisdom file, held by one process at a time (an
// exclusive lock on the file's folder: flock, released by the destructor or the process's
// end): the file read in, the plans made (FFTW_MEASURE finds the plans the file holds instead
// of timing again), the file rewritten when FFTW learnt something. So every run that shares the
// file plans a grid of a size and thread count the same way: the first times it, the others
// read its plans.
class WisdomSession {
public:
    explicit WisdomSession(const std::string& path) : path_(path)
    {
        const std::string folder = folderOf(path);
        fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (fd_ < 0) {
            throw ParameterError(wisdomParameter, "the folder '" + folder + "' of '" + path + "' cannot be opened");
        }
        while (::flock(fd_, LOCK_EX) != 0) {
            if (errno != EINTR) {
                ::close(fd_);
                throw ParameterError(wisdomParameter, "cannot lock the folder '" + folder + "' of '" + path + "'");
            }
        }
        try {
            threadsReady();
            before_ = wisdomText(path);
            if (!before_.empty() && fftw_import_wisdom_from_string(before_.c_str()) == 0) {
                throw ParameterError(wisdomParameter, "'" + path + "' is not wisdom this FFTW can read (damaged, or "
                                                      "written by another FFTW version): give another name");
            }
        } catch (...) {
            ::close(fd_);
            throw;
        }
    }
    ~WisdomSession()
    {
        ::close(fd_); // and the lock with it
    }
    WisdomSession(const WisdomSession&) = delete;
    WisdomSession& operator=(const WisdomSession&) = delete;
    // After planning: what FFTW knows now back to the file, when it is more than the file held.
    void save() const
    {
        char* text = fftw_export_wisdom_to_string();
        if (text == nullptr) {
            throw ParameterError(wisdomParameter, "FFTW could not export its wisdom");
        }
        const std::string after(text);
        fftw_free(text);
        if (after != before_) {
            replaceFile(path_, after, wisdomParameter, "FFTW wisdom file", isWisdomText);
        }
    }

private:
    std::string path_;
    std::string before_;
    int fd_ = -1;
};
} // namespace

// The columns one pass of the column transforms takes at a time (blocked transforms, below):
// 8 columns of 2048 complex values are 256 KiB, within a core's level-2 cache. Chosen from
// single timed runs of a pair on the benchmarks' machine (2026-11-27): 4, 8 and 16 could not be
// told apart reliably at 1024^2-2048^2, 16 was slower at 512^2 and 32 slower everywhere.
constexpr std::size_t columnBlock = 8;

// FFT plans of one grid, made once. Two kinds:
//  - blocked (the default, FFTW_ESTIMATE): the 2-D transform done as its two passes by the
//    core itself, 1-D real transforms of the rows, then the columns taken columnBlock at a time
//    into a contiguous buffer, transformed, multiplied by the operator's multiplier, transformed
//    back and put back, then the rows back. Every 1-D transform is planned without timing runs
//    and done the same way whichever thread does it: the answer is the same bit for bit on every
//    run and for any number of threads. FFTW's own estimated 2-D plan strides through memory
//    column by column: a cold solve was 1.5 times slower with it at 2048^2 (docs/benchmarks.md).
//    A padded (non-periodic) grid's rows beyond the surface are zero and are not transformed
//    forward, nor transformed back (the answer is read on the surface's rows only).
//  - with a wisdom file (setFftWisdom): FFTW's 2-D plans, FFTW_MEASURE, for the threads() of the
//    time they are made (FFTW's threads). FFTW_MEASURE overwrites the buffers while it plans:
//    they are filled after.
struct HalfSpaceOperator::Fft {
    std::size_t mx;
    std::size_t my;
    std::size_t hx; // mx / 2 + 1 complex values a row
    bool blocked;
    std::unique_ptr<double, GridFree<double>> real; // 2-D plans only
    std::unique_ptr<fftw_complex, GridFree<fftw_complex>> spectral;
    fftw_plan forward = nullptr;  // 2-D, or a row's r2c
    fftw_plan backward = nullptr; // 2-D, or a row's c2r
    // Blocked: the columns' c2c transforms, in place on a buffer of columnBlock columns of my
    // values each, forward and backward; and the same for the last block's remaining columns.
    fftw_plan columnsForward = nullptr;
    fftw_plan columnsBackward = nullptr;
    fftw_plan restForward = nullptr;
    fftw_plan restBackward = nullptr;
    int realAlignment = 0; // fftw_alignment_of the buffers the row plans were made on
    // Blocked: a row and a block of columns for each thread, made at the first transform and
    // kept (an operator is used by one solve at a time: HalfSpaceOperator::pairs_).
    mutable std::vector<std::unique_ptr<double, GridFree<double>>> rowBuffers;
    mutable std::vector<std::unique_ptr<fftw_complex, GridFree<fftw_complex>>> columnBuffers;

    Fft(std::size_t mx_, std::size_t my_) : mx(mx_), my(my_), hx(mx_ / 2 + 1)
    {
        spectral = gridArray<fftw_complex>(my * hx);
        const std::lock_guard<std::mutex> lock(fftwPlanner());
        const std::string wisdom = wisdomPath();
        blocked = wisdom.empty();
        if (blocked) {
            planFor(1);
            const auto row = gridArray<double>(mx);
            const auto columns = gridArray<fftw_complex>(columnBlock * my);
            realAlignment = fftw_alignment_of(row.get());
            const int n = static_cast<int>(mx);
            forward = fftw_plan_dft_r2c_1d(n, row.get(), spectral.get(), FFTW_ESTIMATE);
            backward = fftw_plan_dft_c2r_1d(n, spectral.get(), row.get(), FFTW_ESTIMATE);
            const int length[1] = {static_cast<int>(my)};
            const auto plan = [&](std::size_t count, int sign) {
                return fftw_plan_many_dft(1, length, static_cast<int>(count), columns.get(), nullptr, 1,
                                          length[0], columns.get(), nullptr, 1, length[0], sign, FFTW_ESTIMATE);
            };
            const std::size_t rest = hx % columnBlock;
            columnsForward = plan(columnBlock, FFTW_FORWARD);
            columnsBackward = plan(columnBlock, FFTW_BACKWARD);
            if (rest > 0) {
                restForward = plan(rest, FFTW_FORWARD);
                restBackward = plan(rest, FFTW_BACKWARD);
            }
            if (!forward || !backward || !columnsForward || !columnsBackward || (rest > 0 && !restBackward) ||
                (rest > 0 && !restForward)) {
                destroy();
                throw ParameterError("FFT", "FFTW could not plan a " + std::to_string(mx) + " x " +
                                                std::to_string(my) + " transform");
            }
            return;
        }
        real = gridArray<double>(mx * my);
        const WisdomSession session(wisdom);
        // FFTW's 2-D real transforms: n0 = my rows of n1 = mx (row-major, x fastest).
        planFor(threads());
        forward = fftw_plan_dft_r2c_2d(static_cast<int>(my), static_cast<int>(mx), real.get(), spectral.get(),
                                       FFTW_MEASURE);
        backward = fftw_plan_dft_c2r_2d(static_cast<int>(my), static_cast<int>(mx), spectral.get(),
                                        real.get(), FFTW_MEASURE);
        if (!forward || !backward) {
            destroy();
            throw ParameterError("FFT", "FFTW could not plan a " + std::to_string(mx) + " x " + std::to_string(my) +
                                            " transform");
        }
        session.save();
    }
    ~Fft()
    {
        const std::lock_guard<std::mutex> lock(fftwPlanner());
        destroy();
    }
    // (With the planner's lock held.)
    void destroy()
    {
        for (fftw_plan* p : {&forward, &backward, &columnsForward, &columnsBackward, &restForward, &restBackward}) {
            if (*p != nullptr) {
                fftw_destroy_plan(*p);
                *p = nullptr;
            }
        }
    }

    // Blocked: the spectrum of `rows` rows of `length` values each (`stride` apart in `in`), the
    // grid's other values zero: the rows' transforms into `spectral`, the rows beyond `rows`
    // zero; then the columns, each multiplied by `multiplier` (my x hx, as `spectral`) and
    // transformed back when it is given, or left as the 2-D spectrum when it is null.
    void rowsForward(const double* in, std::size_t rows, std::size_t length, std::size_t stride) const;
    void columns(const double* multiplier) const;
    // The rows back: the first `rows` rows of the inverse transform, `length` values of each
    // into `out`, `stride` apart. (The row transforms overwrite `spectral`: scratch.)
    void rowsBackward(double* out, std::size_t rows, std::size_t length, std::size_t stride) const;
};

namespace {
// body(first, last, buffer) over [0, n) in one piece per thread (forRange's pieces of items of
// `weight` values), each with its own buffer of `bufferSize` Ts from `buffers` (made there when
// there are fewer than pieces, before the threads start: a loop's body must not throw). Which
// thread does a piece changes nothing in it.
template <class T, class Body>
void inPieces(std::size_t n, std::size_t weight, std::vector<std::unique_ptr<T, GridFree<T>>>& buffers,
              std::size_t bufferSize, Body&& body)
{
    const std::size_t pieces = std::max<std::size_t>(1, std::min<std::size_t>(n, std::size_t(threads())));
    while (buffers.size() < pieces) {
        buffers.push_back(gridArray<T>(bufferSize));
    }
    struct Context {
        Body& body;
        std::vector<std::unique_ptr<T, GridFree<T>>>& buffers;
        std::size_t n;
        std::size_t pieces;
    } context{body, buffers, n, pieces};
    parallel::forRange(
        pieces, weight * ((n + pieces - 1) / pieces),
        [](std::size_t begin, std::size_t end, void* c) {
            Context& x = *static_cast<Context*>(c);
            for (std::size_t k = begin; k < end; ++k) {
                x.body(x.n * k / x.pieces, x.n * (k + 1) / x.pieces, x.buffers[k].get());
            }
        },
        &context);
}
} // namespace

void HalfSpaceOperator::Fft::rowsForward(const double* in, std::size_t rows, std::size_t length,
                                         std::size_t stride) const
{
    inPieces<double>(rows, mx, rowBuffers, mx, [&](std::size_t first, std::size_t last, double* row) {
        for (std::size_t y = first; y < last; ++y) {
            const double* source = in + y * stride;
            fftw_complex* target = spectral.get() + y * hx;
            if (length == mx && fftw_alignment_of(const_cast<double*>(source)) == realAlignment) {
                fftw_execute_dft_r2c(forward, const_cast<double*>(source), target);
                continue;
            }
            std::copy(source, source + length, row);
            std::fill(row + length, row + mx, 0.0);
            fftw_execute_dft_r2c(forward, row, target);
        }
    });
    std::fill(spectral.get()[0] + 2 * rows * hx, spectral.get()[0] + 2 * my * hx, 0.0);
}

void HalfSpaceOperator::Fft::columns(const double* multiplier) const
{
    const std::size_t blocks = (hx + columnBlock - 1) / columnBlock;
    inPieces<fftw_complex>(blocks, columnBlock * my, columnBuffers, columnBlock * my,
                           [&](std::size_t first, std::size_t last, fftw_complex* buffer) {
        fftw_complex* c = spectral.get();
        for (std::size_t b = first; b < last; ++b) {
            const std::size_t x0 = b * columnBlock;
            const std::size_t count = std::min(columnBlock, hx - x0);
            const bool whole = count == columnBlock;
            for (std::size_t y = 0; y < my; ++y) {
                for (std::size_t j = 0; j < count; ++j) {
                    buffer[j * my + y][0] = c[y * hx + x0 + j][0];
                    buffer[j * my + y][1] = c[y * hx + x0 + j][1];
                }
            }
            fftw_execute_dft(whole ? columnsForward : restForward, buffer, buffer);
            if (multiplier != nullptr) {
                for (std::size_t y = 0; y < my; ++y) {
                    for (std::size_t j = 0; j < count; ++j) {
                        const double m = multiplier[y * hx + x0 + j];
                        buffer[j * my + y][0] *= m;
                        buffer[j * my + y][1] *= m;
                    }
                }
                fftw_execute_dft(whole ? columnsBackward : restBackward, buffer, buffer);
            }
            for (std::size_t y = 0; y < my; ++y) {
                for (std::size_t j = 0; j < count; ++j) {
                    c[y * hx + x0 + j][0] = buffer[j * my + y][0];
                    c[y * hx + x0 + j][1] = buffer[j * my + y][1];
                }
            }
        }
    });
}

void HalfSpaceOperator::Fft::rowsBackward(double* out, std::size_t rows, std::size_t length,
                                          std::size_t stride) const
{
    inPieces<double>(rows, mx, rowBuffers, mx, [&](std::size_t first, std::size_t last, double* row) {
        for (std::size_t y = first; y < last; ++y) {
            double* target = out + y * stride;
            fftw_complex* source = spectral.get() + y * hx;
            if (length == mx && fftw_alignment_of(target) == realAlignment) {
                fftw_execute_dft_c2r(backward, source, target);
                continue;
            }
            fftw_execute_dft_c2r(backward, source, row);
            std::copy(row, row + length, target);
        }
    });
}

void setFftWisdom(const std::string& path)
{
    if (!path.empty()) {
        if (path.find('\0') != std::string::npos) {
            throw ParameterError(wisdomParameter, "the file name holds a NUL byte");
        }
        const ExistingFile existing = existingFile(path);
        if (existing.kind == ExistingFile::Kind::other) {
            throw ParameterError(wisdomParameter, "'" + path + "' is " + existing.what +
                                                      ", not a file FFTW's wisdom can be kept in: give a file name");
        }
        (void)wisdomText(path); // there and not wisdom: refused now, before anything is solved
        const std::string folder = folderOf(path);
        if (::access(folder.c_str(), X_OK) != 0) {
            throw ParameterError(wisdomParameter, "the folder '" + folder + "' of '" + path + "' is missing");
        }
    }
    const std::lock_guard<std::mutex> lock(fftwPlanner());
    wisdomPath() = path;
}

const std::string& fftWisdom() noexcept
{
    return wisdomPath();
}

double HalfSpaceOperator::loveRectangle(double x, double y, double a, double b, double p, double Eprime)
{
    return p / (pi * Eprime) * (F(x + a, y + b) - F(x + a, y - b) - F(x - a, y + b) + F(x - a, y - b));
}

double HalfSpaceOperator::bytesFor(std::size_t nx, std::size_t ny, bool periodic)
{
    const double m = (periodic ? 1.0 : 4.0) * double(nx) * double(ny);
    // A real grid, the half-complex buffer, K and S. (The blocked transforms hold no real grid,
    // only a few rows and columns a thread, but a padded operator makes one while it is built,
    // and the measured peaks of periodic solves, docs/benchmarks.md, are matched with it
    // counted: FFTW's 2-D plans never touched theirs there either.)
    return m * (8.0 + 16.0 * 0.5 + 2.0 * 8.0 * 0.5);
}

// The mirrored grid's transforms: FFTW's DCT-II (REDFT10) and DCT-III (REDFT01), blocked as the
// periodic transforms are (Fft): the rows in place in one grid buffer, then the columns
// columnBlock at a time through a small buffer, multiplied there, transformed back, put back,
// then the rows back. FFTW's own 2-D cosine transform strides down the columns and took 1.7
// times a padded transform pair at 1024^2 (about twice the blocked one; single runs). Every 1-D plan is
// FFTW_ESTIMATE (the rows' FFTW_UNALIGNED: a row of an odd length starts anywhere), so the
// answer is the same on every run and for any number of threads.
struct HalfSpaceOperator::Dct {
    std::size_t nx;
    std::size_t ny;
    std::unique_ptr<double, GridFree<double>> grid;
    fftw_plan rowForward = nullptr;
    fftw_plan rowBackward = nullptr;
    fftw_plan columnsForward = nullptr; // columnBlock columns of ny values, contiguous
    fftw_plan columnsBackward = nullptr;
    fftw_plan restForward = nullptr; // the last block's nx % columnBlock columns
    fftw_plan restBackward = nullptr;
    mutable std::vector<std::unique_ptr<double, GridFree<double>>> columnBuffers;

    Dct(std::size_t nx_, std::size_t ny_);
    ~Dct()
    {
        const std::lock_guard<std::mutex> lock(fftwPlanner());
        destroy();
    }
    Dct(const Dct&) = delete;
    Dct& operator=(const Dct&) = delete;
    // out = DCT-III(multiplier DCT-II(in)) (unnormalised: the multiplier carries 1/(4 nx ny)).
    void convolve(const double* multiplier, const double* in, double* out) const;
    // Every row of `from` transformed by `plan` in the grid buffer and put in `to` (either may
    // be the grid), in pieces of rows on threads() threads (weighted by their length, as the
    // periodic rows are).
    void rows(fftw_plan plan, const double* from, double* to) const;

private:
    // (With the planner's lock held.)
    void destroy()
    {
        for (fftw_plan* p : {&rowForward, &rowBackward, &columnsForward, &columnsBackward, &restForward, &restBackward}) {
            if (*p != nullptr) {
                fftw_destroy_plan(*p);
                *p = nullptr;
            }
        }
    }
};

HalfSpaceOperator::Dct::Dct(std::size_t nx_, std::size_t ny_)
    : nx(nx_), ny(ny_), grid(gridArray<double>(nx_ * ny_))
{
    const auto block = gridArray<double>(columnBlock * ny);
    const std::lock_guard<std::mutex> lock(fftwPlanner());
    planFor(1);
    const int m[1] = {int(ny)};
    const fftw_r2r_kind two[1] = {FFTW_REDFT10};
    const fftw_r2r_kind three[1] = {FFTW_REDFT01};
    double* row = grid.get();
    rowForward = fftw_plan_r2r_1d(int(nx), row, row, FFTW_REDFT10, FFTW_ESTIMATE | FFTW_UNALIGNED);
    rowBackward = fftw_plan_r2r_1d(int(nx), row, row, FFTW_REDFT01, FFTW_ESTIMATE | FFTW_UNALIGNED);
    const auto columnsOf = [&](std::size_t count, const fftw_r2r_kind* kind) {
        return fftw_plan_many_r2r(1, m, int(count), block.get(), nullptr, 1, int(ny), block.get(), nullptr, 1,
                                  int(ny), kind, FFTW_ESTIMATE);
    };
    columnsForward = columnsOf(columnBlock, two);
    columnsBackward = columnsOf(columnBlock, three);
    const std::size_t rest = nx % columnBlock;
    if (rest > 0) {
        restForward = columnsOf(rest, two);
        restBackward = columnsOf(rest, three);
    }
    if (rowForward == nullptr || rowBackward == nullptr || columnsForward == nullptr || columnsBackward == nullptr ||
        (rest > 0 && (restForward == nullptr || restBackward == nullptr))) {
        destroy();
        throw ParameterError("FFT", "FFTW could not plan the cosine transforms of a mirrored " + std::to_string(nx) +
                                        " x " + std::to_string(ny) + " grid");
    }
}

void HalfSpaceOperator::Dct::rows(fftw_plan plan, const double* from, double* to) const
{
    struct Context {
        const Dct& dct;
        fftw_plan plan;
        const double* from;
        double* to;
    } context{*this, plan, from, to};
    parallel::forRange(
        ny, nx,
        [](std::size_t begin, std::size_t end, void* c) {
            const Context& x = *static_cast<const Context*>(c);
            const std::size_t n = x.dct.nx;
            double* g = x.dct.grid.get();
            for (std::size_t y = begin; y < end; ++y) {
                if (x.from != g) {
                    std::copy(x.from + y * n, x.from + (y + 1) * n, g + y * n);
                }
                fftw_execute_r2r(x.plan, g + y * n, g + y * n);
                if (x.to != g) {
                    std::copy(g + y * n, g + (y + 1) * n, x.to + y * n);
                }
            }
        },
        &context);
}

void HalfSpaceOperator::Dct::convolve(const double* multiplier, const double* in, double* out) const
{
    double* g = grid.get();
    rows(rowForward, in, g);
    const std::size_t blocks = (nx + columnBlock - 1) / columnBlock;
    inPieces<double>(blocks, columnBlock * ny, columnBuffers, columnBlock * ny,
                     [&](std::size_t first, std::size_t last, double* buffer) {
        for (std::size_t b = first; b < last; ++b) {
            const std::size_t x0 = b * columnBlock;
            const std::size_t count = std::min(columnBlock, nx - x0);
            const bool whole = count == columnBlock;
            for (std::size_t y = 0; y < ny; ++y) {
                for (std::size_t j = 0; j < count; ++j) {
                    buffer[j * ny + y] = g[y * nx + x0 + j];
                }
            }
            fftw_execute_r2r(whole ? columnsForward : restForward, buffer, buffer);
            for (std::size_t y = 0; y < ny; ++y) {
                for (std::size_t j = 0; j < count; ++j) {
                    buffer[j * ny + y] *= multiplier[y * nx + x0 + j];
                }
            }
            fftw_execute_r2r(whole ? columnsBackward : restBackward, buffer, buffer);
            for (std::size_t y = 0; y < ny; ++y) {
                for (std::size_t j = 0; j < count; ++j) {
                    g[y * nx + x0 + j] = buffer[j * ny + y];
                }
            }
        }
    });
    rows(rowBackward, g, out);
}

HalfSpaceOperator::HalfSpaceOperator(std::size_t nx, std::size_t ny, double dx, double dy, double Eprime,
                                     bool periodic)
    : HalfSpaceOperator(nx, ny, dx, dy, Eprime, periodic ? Edges::periodic : Edges::padded)
{
}

HalfSpaceOperator::HalfSpaceOperator(std::size_t nx, std::size_t ny, double dx, double dy, double Eprime,
                                     Edges edges)
    : nx_(nx), ny_(ny), dx_(requirePositive("grid spacing dx", dx)),
      dy_(requirePositive("grid spacing dy", dy)), Eprime_(requirePositive("reduced modulus E'", Eprime)),
      edges_(edges), mx_(edges == Edges::padded ? 2 * nx : nx), my_(edges == Edges::padded ? 2 * ny : ny)
{
    if (nx_ < 2 || ny_ < 2) {
        throw ParameterError("boundary-element grid", "needs at least 2 x 2 points");
    }
    if (edges_ == Edges::mirrored) {
        makeMirrored();
        return;
    }
    fft_ = std::make_unique<Fft>(mx_, my_);
    const std::size_t hx = mx_ / 2 + 1;
    kernel_.assign(my_ * hx, 0.0);
    if (edges_ == Edges::periodic) {
        const double Lx = dx_ * double(nx_);
        const double Ly = dy_ * double(ny_);
        for (std::size_t ky = 0; ky < my_; ++ky) {
            const double fy = double(ky <= my_ / 2 ? ky : my_ - ky) / Ly; // wrapped wavenumbers
            for (std::size_t kx = 0; kx < hx; ++kx) {
                const double fx = double(kx) / Lx;
                const double q = 2.0 * pi * std::sqrt(fx * fx + fy * fy);
                // u(q) = 2 p(q) / (E' q); q = 0: mean displacement 0. The 1/(mx my) of FFTW's
                // unnormalised inverse is folded in here.
                kernel_[ky * hx + kx] = compliance(q, Eprime_) / double(mx_ * my_);
                largest_ = std::max(largest_, kernel_[ky * hx + kx] * double(mx_ * my_));
            }
        }
        makeStiffness();
        return;
    }
    // Non-periodic: Love's influence of one cell at every offset (i dx, j dy), |i| < nx,
    // |j| < ny, placed in wrap-around order on the padded grid; the rest (offset nx, ny) 0.
    // (Blocked transforms hold no real grid: a temporary one, freed at the end of construction.)
    const auto temporary = fft_->blocked ? gridArray<double>(mx_ * my_) : nullptr;
    double* k = fft_->blocked ? temporary.get() : fft_->real.get();
    for (std::size_t jy = 0; jy < my_; ++jy) {
        for (std::size_t jx = 0; jx < mx_; ++jx) {
            const long ix = jx < nx_ ? long(jx) : (jx > nx_ ? long(jx) - long(mx_) : 0);
            const long iy = jy < ny_ ? long(jy) : (jy > ny_ ? long(jy) - long(my_) : 0);
            const bool unused = jx == nx_ || jy == ny_;
            k[jy * mx_ + jx] = unused ? 0.0
                                      : loveRectangle(double(ix) * dx_, double(iy) * dy_, 0.5 * dx_,
                                                      0.5 * dy_, 1.0, Eprime_);
        }
    }
    if (fft_->blocked) {
        fft_->rowsForward(k, my_, mx_, mx_);
        fft_->columns(nullptr);
    } else {
        fftw_execute(fft_->forward);
    }
    // The kernel is even in x and y, so its transform is real (to round-off).
    for (std::size_t i = 0; i < kernel_.size(); ++i) {
        kernel_[i] = fft_->spectral.get()[i][0] / double(mx_ * my_);
        largest_ = std::max(largest_, std::abs(fft_->spectral.get()[i][0]));
    }
    makeStiffness();
}

void HalfSpaceOperator::makeStiffness()
{
    // E'|q|/2 on the FFT grid (periodic: the exact inverse of K on the modes q != 0; padded: the
    // stiffness of the periodic half-space of twice the size, an approximate inverse). The mean
    // mode, which K sets to 0, gets the stiffness of the longest wavelength of the grid.
    const std::size_t hx = mx_ / 2 + 1;
    const double Lx = dx_ * double(mx_);
    const double Ly = dy_ * double(my_);
    stiffness_.assign(my_ * hx, 0.0);
    smallestStiffness_ = longestWaveStiffness(Lx, Ly, Eprime_);
    for (std::size_t ky = 0; ky < my_; ++ky) {
        const double fy = double(ky <= my_ / 2 ? ky : my_ - ky) / Ly;
        for (std::size_t kx = 0; kx < hx; ++kx) {
            const double fx = double(kx) / Lx;
            const double q = 2.0 * pi * std::sqrt(fx * fx + fy * fy);
            stiffness_[ky * hx + kx] = stiffness(q, Eprime_, smallestStiffness_) / double(mx_ * my_);
        }
    }
}

void HalfSpaceOperator::makeMirrored()
{
    // The periodic multipliers of the 2nx x 2ny grid at the cosine modes kx < nx, ky < ny (the
    // mode nx of a field even about the edges is 0), with the 1/(4 nx ny) of REDFT01(REDFT10)
    // folded in; S's mean mode gets the stiffness of the longest wavelength, 2 max(Lx, Ly).
    dct_ = std::make_unique<Dct>(nx_, ny_);
    const double Lx = 2.0 * dx_ * double(nx_);
    const double Ly = 2.0 * dy_ * double(ny_);
    const double scale = 4.0 * double(nx_) * double(ny_);
    smallestStiffness_ = longestWaveStiffness(Lx, Ly, Eprime_);
    kernel_.assign(nx_ * ny_, 0.0);
    stiffness_.assign(nx_ * ny_, 0.0);
    for (std::size_t ky = 0; ky < ny_; ++ky) {
        const double fy = double(ky) / Ly;
        for (std::size_t kx = 0; kx < nx_; ++kx) {
            const double fx = double(kx) / Lx;
            const double q = 2.0 * pi * std::sqrt(fx * fx + fy * fy);
            const double k = compliance(q, Eprime_);
            kernel_[ky * nx_ + kx] = k / scale;
            largest_ = std::max(largest_, k);
            stiffness_[ky * nx_ + kx] = stiffness(q, Eprime_, smallestStiffness_) / scale;
        }
    }
}

HalfSpaceOperator::~HalfSpaceOperator() = default;

void HalfSpaceOperator::convolve(const GridField& multiplier, const double* in, double* out) const
{
    ++pairs_;
    if (dct_) {
        dct_->convolve(multiplier.data(), in, out);
        return;
    }
    fftw_complex* c = fft_->spectral.get();
    if (fft_->blocked) {
        // Periodic: the grid's rows; padded: the surface's ny rows of nx, the rest zero, and
        // only the surface's rows back.
        fft_->rowsForward(in, ny_, nx_, nx_);
        fft_->columns(multiplier.data());
        fft_->rowsBackward(out, ny_, nx_, nx_);
        return;
    }
    double* r = fft_->real.get();
    // Periodic: transform the caller's arrays directly when their alignment matches the
    // planned buffers' (FFTW's new-array execute), sparing two copies of the grid.
    const int aligned = fftw_alignment_of(r);
    const bool periodic = edges_ == Edges::periodic;
    if (periodic && fftw_alignment_of(const_cast<double*>(in)) == aligned) {
        fftw_execute_dft_r2c(fft_->forward, const_cast<double*>(in), c);
    } else if (periodic) {
        std::copy(in, in + size(), r);
        fftw_execute(fft_->forward);
    } else {
        std::fill(r, r + mx_ * my_, 0.0);
        for (std::size_t iy = 0; iy < ny_; ++iy) {
            std::copy(in + iy * nx_, in + (iy + 1) * nx_, r + iy * mx_);
        }
        fftw_execute(fft_->forward);
    }
    const double* m = multiplier.data();
    parallel::forEach(multiplier.size(), [c, m](std::size_t i) {
        c[i][0] *= m[i];
        c[i][1] *= m[i];
    });
    if (periodic && fftw_alignment_of(out) == aligned) {
        fftw_execute_dft_c2r(fft_->backward, c, out); // c2r overwrites c: scratch
    } else if (periodic) {
        fftw_execute(fft_->backward);
        std::copy(r, r + size(), out);
    } else {
        fftw_execute(fft_->backward);
        for (std::size_t iy = 0; iy < ny_; ++iy) {
            std::copy(r + iy * mx_, r + iy * mx_ + nx_, out + iy * nx_);
        }
    }
}

void HalfSpaceOperator::apply(const double* p, double* u) const
{
    convolve(kernel_, p, u);
}

void HalfSpaceOperator::applyStiffness(const double* u, double* p) const
{
    convolve(stiffness_, u, p);
}

std::vector<double> HalfSpaceOperator::apply(const std::vector<double>& p) const
{
    if (p.size() != size()) {
        throw ParameterError("pressure field", "has " + std::to_string(p.size()) + " values for " +
                                                   std::to_string(size()) + " grid points");
    }
    std::vector<double> u(size());
    apply(p.data(), u.data());
    return u;
}

} // namespace roughContact
