// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/SyntheticProfile.hpp"
#include "roughContact/Constants.hpp"
#include "roughContact/parallel/Threads.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

namespace roughContact {

namespace {
// Uniform in (0, 1] from the 53 high bits: defined by the standard, unlike the library's
// distributions.
double uniform(std::mt19937_64& gen)
{
    return (static_cast<double>(gen() >> 11) + 1.0) * 0x1.0p-53;
}

// Box-Muller: two independent standard normals.
std::complex<double> gaussianPair(std::mt19937_64& gen)
{
    const double r = std::sqrt(-2.0 * std::log(uniform(gen)));
    const double t = 2.0 * pi * uniform(gen);
    return {r * std::cos(t), r * std::sin(t)};
}
} // namespace

Profile generateSyntheticProfile(const SyntheticProfileSpec& spec)
{
    if (spec.points < Profile::minimumSize) {
        throw ParameterError("points", "a profile needs at least 8 points");
    }
    // Checked before anything is allocated: the longest profile the models accept.
    const std::size_t most = 2 * limits::maximumLevels + 1;
    if (spec.points > most) {
        throw ParameterError("points", "at most " + std::to_string(most) + " (the longest profile the models "
                                                                          "accept: limits::maximumLevels)");
    }
    limits::requireLength("spacing", spec.spacing);
    limits::requireLength("scan length points x spacing", spec.spacing * static_cast<double>(spec.points));
    limits::requireInRange("rms", spec.rms, limits::minimumRoughness, limits::maximumHeight, "m");
    requireFinite("D", spec.D);
    if (!(spec.D > 1.0 && spec.D < 2.0)) {
        throw ParameterError("D", "must lie strictly between 1 and 2");
    }
    const std::size_t n = spec.points;
    const std::size_t nc = n / 2 + 1;
    const double L = spec.spacing * static_cast<double>(n);
    std::mt19937_64 gen(spec.seed);
    std::vector<std::complex<double>> Z(nc, {0.0, 0.0});
    for (std::size_t k = 1; k < nc; ++k) {
        const double f = static_cast<double>(k) / L;
        const double sd = std::pow(f, -0.5 * (5.0 - 2.0 * spec.D)); // sqrt of the PSD shape
        std::complex<double> g = gaussianPair(gen);
        if (n % 2 == 0 && k == nc - 1) {
            g = {g.real() * std::sqrt(2.0), 0.0}; // the Nyquist coefficient is real
        }
        Z[k] = sd * g;
    }
    std::vector<double> z(n);
    fftw_plan plan = underFftwPlanner([&] { return fftw_plan_dft_c2r_1d(static_cast<int>(n), reinterpret_cast<fftw_complex*>(Z.data()),
                                          z.data(), FFTW_ESTIMATE); });
    fftw_execute(plan);
    underFftwPlanner([&] { fftw_destroy_plan(plan); });
    // Remove mean and tilt first (as every reader of the profile will), then scale, so the
    // profile that the models see has exactly the requested rms.
    std::vector<double> h = Profile(std::move(z), spec.spacing).detrended().heights();
    double s = 0.0;
    for (double v : h) {
        s += v * v;
    }
    const double scale = spec.rms / std::sqrt(s / static_cast<double>(n));
    for (double& v : h) {
        v *= scale;
    }
    return Profile(std::move(h), spec.spacing, "synthetic profile");
}

} // namespace roughContact
