// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/Constants.hpp"
#include "roughContact/parallel/Threads.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/surface/Profile.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <memory>
#include <sstream>

namespace roughContact {

namespace {
std::string where(const std::string& source)
{
    return source.empty() ? std::string("spectrum") : source;
}
} // namespace

Spectrum::Spectrum(std::vector<double> frequencies, std::vector<double> amplitudes, double length,
                   std::string source)
    : f_(std::move(frequencies)), beta_(std::move(amplitudes)), length_(length),
      source_(std::move(source))
{
    const std::string w = where(source_);
    limits::requireLength(w + ": scan length L (A_n = L^2)", length_);
    if (f_.size() != beta_.size()) {
        throw InputError(w, 0, "frequencies and amplitudes differ in number");
    }
    if (f_.empty()) {
        throw InputError(w, 0, "a spectrum needs at least one level");
    }
    limits::requireLevelCount(w, static_cast<double>(f_.size()));
    for (std::size_t i = 0; i < f_.size(); ++i) {
        if (!std::isfinite(f_[i]) || f_[i] < 1.0 / limits::maximumLength ||
            f_[i] > 1.0 / limits::minimumLength) {
            std::ostringstream os;
            os << "level " << i + 1 << ": frequency " << f_[i] << " 1/m; its wavelength 1/f must lie within ["
               << limits::minimumLength << " m, " << limits::maximumLength << " m]";
            throw InputError(w, 0, os.str());
        }
        if (i > 0 && !(f_[i] > f_[i - 1])) {
            std::ostringstream os;
            os << "level " << i + 1 << ": frequencies must increase strictly (" << f_[i - 1]
               << " then " << f_[i] << ")";
            throw InputError(w, 0, os.str());
        }
        if (!std::isfinite(beta_[i]) || beta_[i] < 0.0 || beta_[i] > limits::maximumHeight) {
            std::ostringstream os;
            os << "level " << i + 1 << ": amplitude must be finite, >= 0 and at most " << limits::maximumHeight
               << " m, got " << beta_[i];
            throw InputError(w, 0, os.str());
        }
    }
}

Spectrum Spectrum::withNyquistLevel(std::vector<double> frequencies, std::vector<double> amplitudes,
                                    double length, std::string source, bool nyquist)
{
    Spectrum s(std::move(frequencies), std::move(amplitudes), length, std::move(source));
    s.nyquist_ = nyquist;
    return s;
}

Spectrum Spectrum::fromProfile(const Profile& profile)
{
    const std::size_t n = profile.size();
    {
        std::ostringstream hint;
        hint << "use every K-th sample (stride K >= "
             << static_cast<std::size_t>(std::ceil(double(n / 2) / double(limits::maximumLevels))) << ")";
        limits::requireLevelCount(where(profile.source()) + ": a profile of " + std::to_string(n) + " samples",
                                  static_cast<double>(n / 2), hint.str());
    }
    const Profile p = profile.detrended();
    std::vector<double> in(p.heights());
    const std::size_t nc = n / 2 + 1;
    std::unique_ptr<fftw_complex, decltype(&fftw_free)> out(
        static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * nc)), &fftw_free);
    if (!out) {
        throw std::bad_alloc();
    }
    // FFTW_ESTIMATE does not overwrite the input and plans in microseconds.
    fftw_plan plan = underFftwPlanner([&] { return fftw_plan_dft_r2c_1d(static_cast<int>(n), in.data(), out.get(), FFTW_ESTIMATE); });
    fftw_execute(plan);
    underFftwPlanner([&] { fftw_destroy_plan(plan); });

    const double L = p.length();
    const double nd = static_cast<double>(n);
    const std::size_t kmax = n / 2;
    std::vector<double> f;
    std::vector<double> beta;
    f.reserve(kmax);
    beta.reserve(kmax);
    for (std::size_t k = 1; k <= kmax; ++k) {
        const double mag = std::hypot(out.get()[k][0], out.get()[k][1]);
        const bool nyquist = (n % 2 == 0) && (k == kmax);
        f.push_back(static_cast<double>(k) / L);
        beta.push_back((nyquist ? 1.0 : 2.0) * mag / nd);
    }
    Spectrum s(std::move(f), std::move(beta), L, profile.source());
    s.nyquist_ = (n % 2 == 0);
    return s;
}

namespace {
// Levels i/L in [fmin, fmax] of amplitude b_m f^-m, checked under the names `what` gives
// ("power law", "fractal"): sizes and ranges before anything is allocated.
Spectrum powerLawLevels(const std::string& what, double bm, double m, double fmin, double fmax, double length)
{
    requirePositive(what + " fmin", fmin);
    requirePositive(what + " fmax", fmax);
    if (!(fmax >= fmin)) {
        throw ParameterError(what + " fmax", "must not be below fmin");
    }
    limits::requireInRange(what + " fmin", fmin, 1.0 / limits::maximumLength, 1.0 / limits::minimumLength, "1/m");
    limits::requireInRange(what + " fmax", fmax, 1.0 / limits::maximumLength, 1.0 / limits::minimumLength, "1/m");
    const double L = limits::requireLength(what + " length", length > 0.0 ? length : 1.0 / fmin);
    // Levels i/L inside [fmin, fmax]; the small slack keeps i = fmin L when it is an integer.
    // fmax L <= 1e15 (the ranges above), exact in a long long.
    const auto i0 = std::max(1LL, static_cast<long long>(std::ceil(fmin * L * (1.0 - 1e-12))));
    const auto i1 = static_cast<long long>(std::floor(fmax * L * (1.0 + 1e-12)));
    if (i1 < i0) {
        throw ParameterError(what, "no level i/L lies between fmin and fmax");
    }
    limits::requireLevelCount(what, static_cast<double>(i1 - i0 + 1),
                              "narrow [fmin, fmax] or shorten the length L (levels are i/L)");
    // beta from its logarithm: b_m f^-m itself can overflow before the range check sees it.
    const double logBm = std::log(bm);
    const double logMax = std::log(limits::maximumHeight);
    std::vector<double> f;
    std::vector<double> beta;
    f.reserve(static_cast<std::size_t>(i1 - i0 + 1));
    beta.reserve(f.capacity());
    for (long long i = i0; i <= i1; ++i) {
        const double fi = static_cast<double>(i) / L;
        const double logBeta = logBm - m * std::log(fi);
        if (logBeta > logMax) {
            std::ostringstream os;
            os << "amplitude b_m f^-m = " << std::exp(logBeta - logMax) * limits::maximumHeight
               << " m at f = " << fi << " 1/m exceeds " << limits::maximumHeight << " m";
            throw ParameterError(what, os.str());
        }
        f.push_back(fi);
        beta.push_back(std::exp(logBeta)); // may underflow to 0 for steep laws: a flat level
    }
    return Spectrum(std::move(f), std::move(beta), L, what);
}
} // namespace

Spectrum Spectrum::powerLaw(double bm, double m, double fmin, double fmax, double length)
{
    requirePositive("power law b_m", bm);
    requireFinite("power law m", m);
    return powerLawLevels("power law", bm, m, fmin, fmax, length);
}

Spectrum Spectrum::fractal(double D, double G, double fmin, double fmax, double length)
{
    requireFinite("fractal dimension D", D);
    if (!(D > 1.0 && D < 2.0)) {
        throw ParameterError("fractal dimension D", "must lie strictly between 1 and 2");
    }
    limits::requireInRange("fractal roughness G", G, 1e-300, limits::maximumHeight, "m");
    requirePositive("fractal fmin", fmin);
    const double L = limits::requireLength("fractal length", length > 0.0 ? length : 1.0 / fmin);
    // beta^2 = 2 S(f) df with df = 1/L and S(f) = G^(2(D-1)) / (2 ln(gamma) f^(5-2D)):
    // a power law beta = b_m f^-m with m = (5-2D)/2, b_m = sqrt(G^(2(D-1)) / (ln(gamma) L)).
    const double lnGamma = std::log(1.5);
    const double bm = std::exp((D - 1.0) * std::log(G) - 0.5 * std::log(lnGamma * L));
    return powerLawLevels("fractal spectrum", bm, 0.5 * (5.0 - 2.0 * D), fmin, fmax, L);
}

double Spectrum::variance() const
{
    double s = 0.0;
    for (double b : beta_) {
        s += 0.5 * b * b;
    }
    return s;
}

double Spectrum::profileVariance() const
{
    double s = variance();
    if (nyquist_) {
        s += 0.5 * beta_.back() * beta_.back();
    }
    return s;
}

Spectrum Spectrum::truncated(double fmax) const
{
    std::vector<double> f;
    std::vector<double> beta;
    for (std::size_t i = 0; i < f_.size() && f_[i] <= fmax; ++i) {
        f.push_back(f_[i]);
        beta.push_back(beta_[i]);
    }
    if (f.empty()) {
        std::ostringstream os;
        os << "no level at or below " << fmax << " 1/m";
        throw ParameterError("fmax", os.str());
    }
    Spectrum s(std::move(f), std::move(beta), length_, source_);
    s.nyquist_ = nyquist_ && s.size() == size();
    return s;
}

Spectrum Spectrum::stretched(double factor) const
{
    if (!std::isfinite(factor) || factor <= 0.0) {
        throw ParameterError("stretch", "lengths are stretched by a positive finite factor, not " +
                                            std::to_string(factor));
    }
    std::vector<double> f = f_;
    for (double& v : f) {
        v /= factor;
    }
    std::ostringstream name;
    name << source_ << " stretched " << factor << " times";
    return withNyquistLevel(std::move(f), beta_, length_ * factor, name.str(), nyquist_);
}

Spectrum Spectrum::onPeriod(std::size_t multiple) const
{
    if (multiple < 1 || multiple > maximumPeriodMultiple) {
        throw ParameterError("period multiple", "a period of 1 to " + std::to_string(maximumPeriodMultiple) +
                                                    " scan lengths, not " + std::to_string(multiple));
    }
    if (multiple == 1) {
        return *this;
    }
    const std::size_t m = f_.size();
    // The bins and densities as IsotropicSpectrum takes them (ArealSynthesis.cpp).
    std::vector<double> density(m);
    std::vector<double> width(m);
    for (std::size_t i = 0; i < m; ++i) {
        width[i] = m == 1          ? 1.0 / length_
                   : i == 0        ? f_[1] - f_[0]
                   : i + 1 == m    ? f_[i] - f_[i - 1]
                                   : 0.5 * (f_[i + 1] - f_[i - 1]);
        const bool nyquistLevel = nyquist_ && i + 1 == m;
        density[i] = beta_[i] * beta_[i] / ((nyquistLevel ? 1.0 : 4.0) * width[i]);
    }
    const double low = std::max(f_[0] - 0.5 * width[0], 0.5 * f_[0]);
    const double high = nyquist_ ? f_[m - 1] : f_[m - 1] + 0.5 * width[m - 1];
    const double L = length_ * static_cast<double>(multiple);
    const double step = 1.0 / L;
    limits::requireLevelCount(source_.empty() ? std::string("spectrum on a longer period") : source_, high * L + 1.0,
                              "a period of " + std::to_string(multiple) + " scan lengths holds " +
                                  std::to_string(multiple) + " times the levels");
    std::vector<double> f;
    std::vector<double> beta;
    std::size_t i = 0; // the segment [f_i, f_{i+1}] holding the level
    for (std::size_t j = 1; (static_cast<double>(j) - 0.5) * step < high; ++j) {
        const double fj = static_cast<double>(j) * step;
        const double inside = std::min(fj + 0.5 * step, high) - std::max(fj - 0.5 * step, low);
        if (!(inside > 1e-9 * step)) { // outside the band, or touching it by rounding
            continue;
        }
        double c = 0.0;
        if (fj <= f_[0]) {
            c = density[0];
        } else if (fj >= f_[m - 1]) {
            c = density[m - 1];
        } else {
            while (f_[i + 1] < fj) {
                ++i;
            }
            const double t = (fj - f_[i]) / (f_[i + 1] - f_[i]);
            c = (1.0 - t) * density[i] + t * density[i + 1];
        }
        f.push_back(fj);
        beta.push_back(std::sqrt(4.0 * c * inside));
    }
    return Spectrum(std::move(f), std::move(beta), L, source_);
}

namespace {
// A level's power spread evenly over its frequency bin, for re-binning.
struct Bin {
    double lo;
    double hi;
    double power;
};

std::vector<Bin> binsOf(const Spectrum& s)
{
    const auto& f = s.frequencies();
    const auto& b = s.amplitudes();
    std::vector<Bin> bins(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double left = i > 0 ? 0.5 * (f[i] + f[i - 1])
                                  : (f.size() > 1 ? f[0] - 0.5 * (f[1] - f[0]) : 0.5 * f[0]);
        const double right = i + 1 < f.size() ? 0.5 * (f[i] + f[i + 1]) : f[i] + (f[i] - left);
        double power = 0.5 * b[i] * b[i];
        if (s.hasNyquistLevel() && i + 1 == f.size()) {
            power *= 2.0;
        }
        bins[i] = {std::max(left, 0.0), right, power};
    }
    return bins;
}

// The power of sorted, contiguous bins falling into intervals asked for in increasing,
// non-overlapping order: one sweep over the bins for all intervals, so re-binning n levels
// onto K costs O(n + K), not O(n K).
class BinSweep {
public:
    explicit BinSweep(const std::vector<Bin>& bins) : bins_(bins) {}

    // Power in [lo, hi).
    double take(double lo, double hi)
    {
        while (next_ < bins_.size() && bins_[next_].hi <= lo) {
            ++next_; // wholly below this interval, hence below every later one
        }
        double p = 0.0;
        for (std::size_t k = next_; k < bins_.size() && bins_[k].lo < hi; ++k) {
            const Bin& b = bins_[k];
            const double overlap = std::min(hi, b.hi) - std::max(lo, b.lo);
            if (overlap > 0.0 && b.hi > b.lo) {
                p += b.power * overlap / (b.hi - b.lo);
            }
        }
        return p;
    }

private:
    const std::vector<Bin>& bins_;
    std::size_t next_ = 0;
};

bool sameGrid(const Spectrum& a, const Spectrum& b)
{
    if (a.size() != b.size() || std::abs(a.length() - b.length()) > 1e-12 * a.length()) {
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::abs(a.frequency(i) - b.frequency(i)) > 1e-12 * a.frequency(i)) {
            return false;
        }
    }
    return true;
}
} // namespace

Spectrum Spectrum::averaged(const Spectrum& a, const Spectrum& b, std::string source)
{
    const Spectrum sum = combine(a, b);
    std::vector<double> beta = sum.amplitudes();
    for (double& v : beta) {
        v *= std::sqrt(0.5);
    }
    return withNyquistLevel(sum.frequencies(), std::move(beta), sum.length(), std::move(source),
                            sum.hasNyquistLevel());
}

Spectrum Spectrum::combine(const Spectrum& a, const Spectrum& b)
{
    const std::string source = a.source() + " + " + b.source();
    if (sameGrid(a, b)) {
        std::vector<double> beta(a.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            beta[i] = std::hypot(a.amplitude(i), b.amplitude(i));
        }
        Spectrum s(a.frequencies(), std::move(beta), a.length(), source);
        s.nyquist_ = a.nyquist_ && b.nyquist_;
        return s;
    }
    // Re-bin both onto k/L, L the longer scan, up to the highest frequency either holds.
    const double L = std::max(a.length(), b.length());
    const std::vector<Bin> ba = binsOf(a);
    const std::vector<Bin> bb = binsOf(b);
    const double top = std::max(ba.back().hi, bb.back().hi);
    // The grid's size before it is built: levels k/L up to the highest frequency either holds.
    limits::requireLevelCount("the combination " + source, top * L + 1.0,
                              "the longer scan sets the level spacing 1/L and the finer one the highest "
                              "level; give two surfaces of similar length and resolution");
    std::vector<double> f;
    std::vector<double> beta;
    f.reserve(static_cast<std::size_t>(top * L + 1.0));
    beta.reserve(f.capacity());
    BinSweep sa(ba);
    BinSweep sb(bb);
    for (long long k = 1;; ++k) {
        const double fk = static_cast<double>(k) / L;
        const double lo = k == 1 ? 0.0 : fk - 0.5 / L;
        const double hi = fk + 0.5 / L;
        if (lo >= top) {
            break;
        }
        const double p = sa.take(lo, hi) + sb.take(lo, hi);
        f.push_back(fk);
        beta.push_back(std::sqrt(2.0 * p));
    }
    return Spectrum(std::move(f), std::move(beta), L, source);
}

double asperityDensity(double frequency)
{
    return 2.0 * frequency * frequency; // seed Eq. 4
}

double asperityRadius(double frequency, double amplitude)
{
    if (amplitude <= 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    return 1.0 / (4.0 * pi * pi * amplitude * frequency * frequency); // seed Eq. 5
}

} // namespace roughContact
