// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/Constants.hpp"
#include "roughContact/parallel/Threads.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <sstream>

namespace roughContact {

namespace {
// Uniform in [0, 1) from the 53 high bits: defined by the standard, unlike the library's
// distributions (as in SyntheticProfile.cpp).
double uniform(std::mt19937_64& gen)
{
    return static_cast<double>(gen() >> 11) * 0x1.0p-53;
}

// Integral of sqrt(k^2 - r^2) dk, for k >= r >= 0.
double rootIntegral(double k, double r)
{
    if (r == 0.0) {
        return 0.5 * k * k;
    }
    return 0.5 * (k * std::sqrt(k * k - r * r) - r * r * std::acosh(k / r));
}
} // namespace

IsotropicSpectrum::IsotropicSpectrum(const Spectrum& lineScan, double cutoff) : L_(lineScan.length())
{
    const std::vector<double>& f = lineScan.frequencies();
    const std::vector<double>& beta = lineScan.amplitudes();
    std::size_t m = f.size();
    if (cutoff > 0.0) {
        m = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), cutoff) - f.begin());
    }
    if (m == 0) {
        std::ostringstream os;
        os << "no level at or below the cutoff " << cutoff << " 1/m (lowest level " << f.front() << " 1/m)";
        throw ParameterError(lineScan.source().empty() ? std::string("spectrum") : lineScan.source(),
                             os.str());
    }
    const bool nyquist = lineScan.hasNyquistLevel() && m == f.size();
    // Levels in units of 1/L, their bin widths and the two-sided densities C1 = beta^2 / (4 dk).
    std::vector<double> k(m), width(m), density(m);
    for (std::size_t i = 0; i < m; ++i) {
        k[i] = f[i] * L_;
    }
    for (std::size_t i = 0; i < m; ++i) {
        if (m == 1) {
            width[i] = 1.0;
        } else if (i == 0) {
            width[i] = k[1] - k[0];
        } else if (i + 1 == m) {
            width[i] = k[i] - k[i - 1];
        } else {
            width[i] = 0.5 * (k[i + 1] - k[i - 1]);
        }
        density[i] = beta[i] * beta[i] / (4.0 * width[i]);
    }
    if (nyquist) {
        density[m - 1] = beta[m - 1] * beta[m - 1] / width[m - 1];
    }
    // Pool adjacent violators: a non-increasing density, each pooled run at its weighted mean
    // (weights: the part of each bin inside the band), so the variance of each run is kept.
    std::vector<double> weight = width;
    if (nyquist) {
        weight[m - 1] *= 0.5;
    }
    std::vector<double> blockValue, blockWeight;
    std::vector<std::size_t> blockCount;
    for (std::size_t i = 0; i < m; ++i) {
        double v = density[i];
        double w = weight[i];
        std::size_t c = 1;
        while (!blockValue.empty() && blockValue.back() < v) {
            v = (v * w + blockValue.back() * blockWeight.back()) / (w + blockWeight.back());
            w += blockWeight.back();
            c += blockCount.back();
            blockValue.pop_back();
            blockWeight.pop_back();
            blockCount.pop_back();
        }
        blockValue.push_back(v);
        blockWeight.push_back(w);
        blockCount.push_back(c);
    }
    std::vector<double> pooled;
    pooled.reserve(m);
    for (std::size_t b = 0; b < blockValue.size(); ++b) {
        pooled.insert(pooled.end(), blockCount[b], blockValue[b]);
    }
    // Nodes: half a bin below the first level (at least halfway to 0), the levels, and half a
    // bin above the last unless it is a Nyquist level (the profile's spectrum ends there);
    // never beyond the cutoff.
    const double low = std::max(k[0] - 0.5 * width[0], 0.5 * k[0]);
    double high = nyquist ? k[m - 1] : k[m - 1] + 0.5 * width[m - 1];
    if (cutoff > 0.0) {
        high = std::min(high, cutoff * L_);
    }
    k_.push_back(low);
    c_.push_back(pooled[0]);
    for (std::size_t i = 0; i < m; ++i) {
        if (k[i] > k_.back()) {
            k_.push_back(k[i]);
            c_.push_back(pooled[i]);
        }
    }
    if (high > k_.back()) {
        k_.push_back(high);
        c_.push_back(pooled[m - 1]);
    }
    for (std::size_t j = 0; j + 1 < k_.size(); ++j) {
        s_.push_back((c_[j + 1] - c_[j]) / (k_[j + 1] - k_[j]));
    }
}

double IsotropicSpectrum::c1(double f) const
{
    const double k = f * L_;
    if (!(k >= k_.front() && k <= k_.back())) {
        return 0.0;
    }
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(k_.begin(), k_.end(), k) - k_.begin());
    if (j >= k_.size()) {
        return c_.back() * L_;
    }
    return (c_[j - 1] + s_[j - 1] * (k - k_[j - 1])) * L_;
}

double IsotropicSpectrum::c2(double q) const
{
    const double r = q * L_;
    const double kc = k_.back();
    if (!(r >= k_.front() && r < kc)) {
        return 0.0;
    }
    // Eq. (2): the jump at kc, then each segment's slope times integral dk / sqrt(k^2 - r^2).
    double sum = c_.back() / std::sqrt(kc * kc - r * r);
    for (std::size_t j = 0; j + 1 < k_.size(); ++j) {
        const double hi = k_[j + 1];
        if (hi <= r) {
            continue;
        }
        const double lo = std::max(k_[j], r);
        sum -= s_[j] * (std::acosh(hi / r) - std::acosh(lo / r));
    }
    return sum / pi * L_ * L_;
}

double IsotropicSpectrum::powerOutside(double q) const
{
    const double kc = k_.back();
    const double r = std::max(q * L_, k_.front()); // C2 = 0 below the band
    if (r >= kc) {
        return 0.0;
    }
    // Eq. (3) for the piecewise linear C1 and its jump at kc.
    double sum = 2.0 * c_.back() * std::sqrt(kc * kc - r * r);
    for (std::size_t j = 0; j + 1 < k_.size(); ++j) {
        const double hi = k_[j + 1];
        if (hi <= r) {
            continue;
        }
        const double lo = std::max(k_[j], r);
        sum -= 2.0 * s_[j] * (rootIntegral(hi, r) - rootIntegral(lo, r));
    }
    return sum;
}

std::vector<double> isotropicGridPower(const Spectrum& lineScan, std::size_t n)
{
    limits::requireSynthesisSize("n", n);
    const double L = lineScan.length();
    limits::requireLength("spacing L/n", L / static_cast<double>(n));
    // The grid's Nyquist frequency n/(2L), with a relative 1e-12 so that a level computed as
    // (n/2)/L in another order of operations is kept.
    const IsotropicSpectrum iso(lineScan, 0.5 * static_cast<double>(n) / L * (1.0 + 1e-12));
    // T(r) tabulated at steps of h (units of 1/L) up to the cutoff + 1, interpolated linearly.
    constexpr double h = 0.25;
    const double kc = iso.highestFrequency() * L;
    const std::size_t rows = static_cast<std::size_t>(std::ceil((kc + 1.0) / h)) + 2;
    std::vector<double> T(rows);
    for (std::size_t m = 0; m < rows; ++m) {
        T[m] = iso.powerOutside(static_cast<double>(m) * h / L);
    }
    const auto outside = [&](double r) {
        const double x = r / h;
        const std::size_t m = static_cast<std::size_t>(x);
        if (m + 1 >= rows) {
            return 0.0;
        }
        const double t = x - static_cast<double>(m);
        return (1.0 - t) * T[m] + t * T[m + 1];
    };
    const std::size_t nc = n / 2 + 1;
    std::vector<double> power(n * nc, 0.0);
    for (std::size_t iy = 0; iy < n; ++iy) {
        const double ky =
            iy <= n / 2 ? static_cast<double>(iy) : static_cast<double>(iy) - static_cast<double>(n);
        for (std::size_t ix = 0; ix < nc; ++ix) {
            const double kx = static_cast<double>(ix);
            const double rho = std::sqrt(kx * kx + ky * ky);
            if (rho < 0.5 || rho - 0.5 >= kc) {
                continue;
            }
            power[iy * nc + ix] = std::max(0.0, outside(rho - 0.5) - outside(rho + 0.5)) / (2.0 * pi * rho);
            // A cell on a Nyquist line k = n/2 also holds its mirror image at -n/2 (the same
            // cell of the periodic grid): the power of both halves.
            if (ix == n / 2 || iy == n / 2) {
                power[iy * nc + ix] *= 2.0;
            }
        }
    }
    return power;
}

ArealSurface synthesizeIsotropic(const Spectrum& lineScan, std::size_t n, std::uint64_t seed,
                                 std::string source)
{
    limits::requireSynthesisSize("n", n); // before anything is allocated
    std::vector<double> power = isotropicGridPower(lineScan, n);
    const std::size_t nc = n / 2 + 1;
    std::vector<std::complex<double>> A(n * nc);
    std::mt19937_64 gen(seed);
    for (std::size_t i = 0; i < A.size(); ++i) {
        const double phase = 2.0 * pi * uniform(gen);
        A[i] = std::polar(std::sqrt(power[i]), phase);
    }
    std::vector<double>().swap(power); // its memory back before the heights are allocated
    // Hermitian symmetry in the columns k_x = 0 and n/2, which are their own mirror images:
    // A(k_x, -k_y) = conj(A(k_x, k_y)); the four self-conjugate coefficients real.
    for (std::size_t ix : {std::size_t(0), n / 2}) {
        for (std::size_t iy = n / 2 + 1; iy < n; ++iy) {
            A[iy * nc + ix] = std::conj(A[(n - iy) * nc + ix]);
        }
        for (std::size_t iy : {std::size_t(0), n / 2}) {
            std::complex<double>& a = A[iy * nc + ix];
            a = {a.real() >= 0.0 ? std::abs(a) : -std::abs(a), 0.0};
        }
    }
    std::vector<double> z(n * n);
    fftw_plan plan = underFftwPlanner([&] { return fftw_plan_dft_c2r_2d(static_cast<int>(n), static_cast<int>(n),
                                          reinterpret_cast<fftw_complex*>(A.data()), z.data(), FFTW_ESTIMATE); });
    fftw_execute(plan);
    underFftwPlanner([&] { fftw_destroy_plan(plan); });
    const double dx = lineScan.length() / static_cast<double>(n);
    if (source.empty()) {
        source = "isotropic synthesis of " +
                 (lineScan.source().empty() ? std::string("a spectrum") : lineScan.source());
    }
    return ArealSurface(std::move(z), n, n, dx, dx, std::move(source));
}

ArealSurface synthesizeStretched(const Spectrum& across, double stretch, std::size_t n, std::uint64_t seed,
                                 std::string source)
{
    if (!std::isfinite(stretch) || stretch <= 0.0) {
        throw ParameterError("stretch", "a lay stretches the surface by a positive finite factor, not " +
                                            std::to_string(stretch));
    }
    ArealSurface isotropic = synthesizeIsotropic(across, n, seed, source);
    if (stretch == 1.0) {
        return isotropic;
    }
    return ArealSurface(isotropic.heights(), n, n, isotropic.dx(), isotropic.dx() * stretch, isotropic.source());
}

} // namespace roughContact
