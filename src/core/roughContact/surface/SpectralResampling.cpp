// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/parallel/Threads.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {
// The signed wavenumber of row iy of an n-point transform (rows above n/2 are negative).
long signedWavenumber(std::size_t i, std::size_t n)
{
    return i <= n / 2 ? static_cast<long>(i) : static_cast<long>(i) - static_cast<long>(n);
}
} // namespace

ArealSurface resampledPeriodic(const ArealSurface& periodic, std::size_t n, std::optional<double> levels)
{
    const std::string what = periodic.source().empty() ? std::string("surface") : periodic.source();
    limits::requireSynthesisSize("n", n);
    if (levels && !(*levels >= 1.0)) {
        std::ostringstream os;
        os << "the number of levels kept must be at least 1, got " << *levels;
        throw ParameterError("levels", os.str());
    }
    const std::size_t m = periodic.nx();
    if (periodic.ny() != m || periodic.dx() != periodic.dy() || m % 2 != 0) {
        std::ostringstream os;
        os << "resampling needs one period of a square periodic surface on an even square grid (as "
              "synthesized), got "
           << periodic.nx() << " x " << periodic.ny() << " points";
        throw ParameterError(what, os.str());
    }
    // The coefficients of the given surface, divided by m^2.
    const std::size_t mc = m / 2 + 1;
    std::vector<std::complex<double>> a(m * mc);
    {
        std::vector<double> z = periodic.heights();
        fftw_plan plan = underFftwPlanner([&] { return fftw_plan_dft_r2c_2d(static_cast<int>(m), static_cast<int>(m), z.data(),
                                              reinterpret_cast<fftw_complex*>(a.data()), FFTW_ESTIMATE); });
        fftw_execute(plan);
        underFftwPlanner([&] { fftw_destroy_plan(plan); });
    }
    const double scale = 1.0 / (static_cast<double>(m) * static_cast<double>(m));
    const long half = static_cast<long>(m / 2);
    const long newHalf = static_cast<long>(n / 2);
    const std::size_t nc = n / 2 + 1;
    std::vector<std::complex<double>> b(n * nc, 0.0);
    const auto rowOf = [&](long ky) { return static_cast<std::size_t>(ky >= 0 ? ky : ky + static_cast<long>(n)); };
    for (std::size_t iy = 0; iy < m; ++iy) {
        const long ky = signedWavenumber(iy, m);
        for (std::size_t ix = 0; ix < mc; ++ix) {
            const long kx = static_cast<long>(ix);
            const std::complex<double> c = a[iy * mc + ix] * scale;
            if (c == 0.0) {
                continue;
            }
            if (levels && std::hypot(static_cast<double>(kx), static_cast<double>(ky)) > *levels) {
                continue;
            }
            // A coarse Nyquist line stands for +n/2 and -n/2: on a grid that holds both apart,
            // each gets half (a cosine sampled at its crests stays that cosine). On the same grid
            // it stays one cell.
            long kys[2] = {ky, ky};
            std::size_t count = 1;
            double weight = 1.0;
            if (ky == half && newHalf != half) {
                kys[1] = -half;
                count = 2;
                weight *= 0.5;
            }
            const bool splitX = kx == half && newHalf != half;
            if (splitX) {
                weight *= 0.5;
            }
            for (std::size_t i = 0; i < count; ++i) {
                const long y = kys[i];
                // What the new grid cannot hold apart from its own Nyquist alias is dropped.
                const bool beyond = kx > newHalf || y > newHalf || y < -newHalf;
                const bool onNewNyquist = newHalf < half && (kx == newHalf || y == newHalf || y == -newHalf);
                if (beyond || onNewNyquist) {
                    continue;
                }
                // The half-complex layout keeps k_x >= 0: the -n/2 half of a split column,
                // (-half, y), is implied by Hermitian symmetry as conj(b(half, -y)), which for a
                // real surface is this cell's own half again.
                b[rowOf(y) * nc + static_cast<std::size_t>(kx)] += weight * c;
            }
        }
    }
    std::vector<double> z(n * n);
    fftw_plan plan = underFftwPlanner([&] { return fftw_plan_dft_c2r_2d(static_cast<int>(n), static_cast<int>(n),
                                          reinterpret_cast<fftw_complex*>(b.data()), z.data(), FFTW_ESTIMATE); });
    fftw_execute(plan);
    underFftwPlanner([&] { fftw_destroy_plan(plan); });
    const double dx = periodic.lengthX() / static_cast<double>(n);
    std::ostringstream source;
    source << what << ", resampled to " << n << " x " << n;
    if (levels) {
        source << " with wavelengths down to L/" << *levels;
    }
    return ArealSurface(std::move(z), n, n, dx, dx, source.str());
}

} // namespace roughContact
