// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/bem/HalfSpaceOperator.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/parallel/Threads.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <complex>
#include <stdexcept>

namespace roughContact {

namespace {
constexpr double pi = 3.14159265358979323846;

// x asinh(y/|x|), 0 at x = 0 (its limit).
double term(double x, double y)
{
    return x == 0.0 ? 0.0 : x * std::asinh(y / std::abs(x));
}

double F(double x, double y)
{
    return term(x, y) + term(y, x);
}

template <class T> struct FftwFree {
    void operator()(T* p) const { fftw_free(p); }
};

std::string& wisdomPath()
{
    static std::string path;
    return path;
}

// The planner flag, with the wisdom file read in once (FFTW keeps what it read; planning with
// FFTW_MEASURE then finds the stored plans instead of timing again).
unsigned planningFlag()
{
    const std::string& path = wisdomPath();
    if (path.empty()) {
        return FFTW_ESTIMATE;
    }
    static std::string imported;
    if (imported != path) {
        (void)fftw_import_wisdom_from_filename(path.c_str()); // a missing file: nothing known yet
        imported = path;
    }
    return FFTW_MEASURE;
}

// After planning: the wisdom back to its file, through a temporary one renamed over it (a run
// stopped while writing leaves the old file whole).
void saveWisdom()
{
    const std::string& path = wisdomPath();
    if (path.empty()) {
        return;
    }
    const std::string temporary = path + ".partial";
    if (fftw_export_wisdom_to_filename(temporary.c_str()) == 0 ||
        std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw ParameterError("FFT wisdom file", "'" + path + "' cannot be written");
    }
}

// FFTW plans its next transforms for `n` threads (its OpenMP threads, set up once; a serial
// build has one). FFTW's planner is not thread-safe: operators are made on one thread.
void planFor(int n)
{
#if defined(ROUGHCONTACT_OPENMP)
    static const bool ready = fftw_init_threads() != 0;
    fftw_plan_with_nthreads(ready ? n : 1);
#else
    (void)n;
#endif
}
} // namespace

// FFT buffers and plans of one grid, made once for the threads() of the time they are made:
// FFTW_ESTIMATE (deterministic, no timing runs), or with a wisdom file measured plans
// (setFftWisdom). FFTW_MEASURE overwrites the buffers while it plans: they are filled after.
struct HalfSpaceOperator::Fft {
    std::size_t mx;
    std::size_t my;
    std::unique_ptr<double, FftwFree<double>> real;
    std::unique_ptr<fftw_complex, FftwFree<fftw_complex>> spectral;
    fftw_plan forward = nullptr;
    fftw_plan backward = nullptr;

    Fft(std::size_t mx_, std::size_t my_) : mx(mx_), my(my_)
    {
        const std::size_t nc = my * (mx / 2 + 1);
        real.reset(static_cast<double*>(fftw_malloc(sizeof(double) * mx * my)));
        spectral.reset(static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * nc)));
        if (!real || !spectral) {
            throw std::bad_alloc();
        }
        // FFTW's 2-D real transforms: n0 = my rows of n1 = mx (row-major, x fastest).
        const std::lock_guard<std::mutex> lock(fftwPlanner());
        planFor(threads());
        const unsigned flag = planningFlag();
        forward = fftw_plan_dft_r2c_2d(static_cast<int>(my), static_cast<int>(mx), real.get(), spectral.get(),
                                       flag);
        backward = fftw_plan_dft_c2r_2d(static_cast<int>(my), static_cast<int>(mx), spectral.get(),
                                        real.get(), flag);
        if (!forward || !backward) {
            throw ParameterError("FFT", "FFTW could not plan a " + std::to_string(mx) + " x " + std::to_string(my) +
                                            " transform");
        }
        if (flag != FFTW_ESTIMATE) {
            saveWisdom();
        }
    }
    ~Fft()
    {
        const std::lock_guard<std::mutex> lock(fftwPlanner());
        fftw_destroy_plan(forward);
        fftw_destroy_plan(backward);
    }
};

void setFftWisdom(const std::string& path)
{
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
    return m * (8.0 + 16.0 * 0.5 + 2.0 * 8.0 * 0.5); // real buffer, half-complex buffer, K and S
}

HalfSpaceOperator::HalfSpaceOperator(std::size_t nx, std::size_t ny, double dx, double dy, double Eprime,
                                     bool periodic)
    : nx_(nx), ny_(ny), dx_(requirePositive("grid spacing dx", dx)),
      dy_(requirePositive("grid spacing dy", dy)), Eprime_(requirePositive("reduced modulus E'", Eprime)),
      periodic_(periodic), mx_(periodic ? nx : 2 * nx), my_(periodic ? ny : 2 * ny)
{
    if (nx_ < 2 || ny_ < 2) {
        throw ParameterError("boundary-element grid", "needs at least 2 x 2 points");
    }
    fft_ = std::make_unique<Fft>(mx_, my_);
    const std::size_t hx = mx_ / 2 + 1;
    kernel_.assign(my_ * hx, 0.0);
    if (periodic_) {
        const double Lx = dx_ * double(nx_);
        const double Ly = dy_ * double(ny_);
        for (std::size_t ky = 0; ky < my_; ++ky) {
            const double fy = double(ky <= my_ / 2 ? ky : my_ - ky) / Ly; // wrapped wavenumbers
            for (std::size_t kx = 0; kx < hx; ++kx) {
                const double fx = double(kx) / Lx;
                const double q = 2.0 * pi * std::sqrt(fx * fx + fy * fy);
                // u(q) = 2 p(q) / (E' q); q = 0: mean displacement 0. The 1/(mx my) of FFTW's
                // unnormalised inverse is folded in here.
                kernel_[ky * hx + kx] = q > 0.0 ? 2.0 / (Eprime_ * q) / double(mx_ * my_) : 0.0;
                largest_ = std::max(largest_, kernel_[ky * hx + kx] * double(mx_ * my_));
            }
        }
        makeStiffness();
        return;
    }
    // Non-periodic: Love's influence of one cell at every offset (i dx, j dy), |i| < nx,
    // |j| < ny, placed in wrap-around order on the padded grid; the rest (offset nx, ny) 0.
    double* k = fft_->real.get();
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
    fftw_execute(fft_->forward);
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
    smallestStiffness_ = 0.5 * Eprime_ * 2.0 * pi / std::max(Lx, Ly);
    for (std::size_t ky = 0; ky < my_; ++ky) {
        const double fy = double(ky <= my_ / 2 ? ky : my_ - ky) / Ly;
        for (std::size_t kx = 0; kx < hx; ++kx) {
            const double fx = double(kx) / Lx;
            const double q = 2.0 * pi * std::sqrt(fx * fx + fy * fy);
            stiffness_[ky * hx + kx] = std::max(0.5 * Eprime_ * q, smallestStiffness_) / double(mx_ * my_);
        }
    }
}

HalfSpaceOperator::~HalfSpaceOperator() = default;

void HalfSpaceOperator::convolve(const std::vector<double>& multiplier, const double* in, double* out) const
{
    ++pairs_;
    fftw_complex* c = fft_->spectral.get();
    double* r = fft_->real.get();
    // Periodic: transform the caller's arrays directly when their alignment matches the
    // planned buffers' (FFTW's new-array execute), sparing two copies of the grid.
    const int aligned = fftw_alignment_of(r);
    if (periodic_ && fftw_alignment_of(const_cast<double*>(in)) == aligned) {
        fftw_execute_dft_r2c(fft_->forward, const_cast<double*>(in), c);
    } else if (periodic_) {
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
    if (periodic_ && fftw_alignment_of(out) == aligned) {
        fftw_execute_dft_c2r(fft_->backward, c, out); // c2r overwrites c: scratch
    } else if (periodic_) {
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
