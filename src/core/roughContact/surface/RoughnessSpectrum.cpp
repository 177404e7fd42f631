// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/RoughnessSpectrum.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {

/// (Rdq/Rq)^2 of the power law of exponent m on the levels f (b_m cancels).
double slopeRatioSquared(const std::vector<double>& f, double m)
{
    double heights = 0.0;
    double slopes = 0.0;
    for (double fi : f) {
        const double b2 = std::exp(-2.0 * m * std::log(fi));
        heights += b2;
        slopes += (2.0 * pi * fi) * (2.0 * pi * fi) * b2;
    }
    return slopes / heights;
}

} // namespace

double rqFromRa(double Ra)
{
    // In range first: sqrt(pi/2) Ra of an Ra near the largest double would overflow (a trap in
    // OpenFOAM).
    return std::sqrt(pi / 2.0) * limits::requireInRange("Ra", Ra, limits::minimumRoughness, limits::maximumHeight, "m");
}

RoughnessSpectrum roughnessSpectrum(double Rq, double rmsSlope, double longCutoff, double shortCutoff)
{
    limits::requireInRange("Rq", Rq, limits::minimumRoughness, limits::maximumHeight, "m");
    limits::requireInRange("slope", rmsSlope, limits::minimumSlope, limits::maximumSlope, "");
    const double L = limits::requireLength("cutoff", longCutoff);
    limits::requireLength("shortCutoff", shortCutoff);
    if (!(shortCutoff < L)) {
        throw ParameterError("shortCutoff", "must be below the cutoff (the band is [1/cutoff, 1/shortCutoff])");
    }
    // Levels i/L, i = 1 .. floor(L/lambda_s).
    const double n = std::floor(L / shortCutoff * (1.0 + 1e-12));
    limits::requireLevelCount("roughness surface", n, "raise shortCutoff or lower cutoff");
    std::vector<double> f(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < f.size(); ++i) {
        f[i] = static_cast<double>(i + 1) / L;
    }
    const double target = (rmsSlope / Rq) * (rmsSlope / Rq);
    // The ratio falls as H rises: from H near 0 (m = 1/2) to H = 1 (m = 3/2).
    const double hLow = 1e-6;
    const double rHigh = slopeRatioSquared(f, hLow + 0.5);
    const double rLow = slopeRatioSquared(f, 1.5);
    if (!(target <= rHigh && target >= rLow)) {
        std::ostringstream os;
        os.precision(3);
        os << "Rdq/Rq = " << rmsSlope / Rq << " 1/m is not that of a self-affine surface over wavelengths "
           << shortCutoff << " to " << L << " m: a Hurst exponent in (0, 1] gives " << std::sqrt(rLow) << " to "
           << std::sqrt(rHigh) << " 1/m; check the units of Rq and the slope, or give the cut-offs the "
           << "numbers were measured with";
        throw ParameterError("slope", os.str());
    }
    double lo = hLow;
    double hi = 1.0;
    for (int k = 0; k < 200 && hi - lo > 1e-14; ++k) {
        const double mid = 0.5 * (lo + hi);
        (slopeRatioSquared(f, mid + 0.5) > target ? lo : hi) = mid;
    }
    const double hurst = 0.5 * (lo + hi);
    const double m = hurst + 0.5;
    double heights = 0.0;
    for (double fi : f) {
        heights += 0.5 * std::exp(-2.0 * m * std::log(fi));
    }
    const double bm = Rq / std::sqrt(heights);
    const Spectrum law = Spectrum::powerLaw(bm, m, f.front(), f.back(), L);
    std::ostringstream source;
    source.precision(4);
    source << "roughness Rq = " << Rq << " m, Rdq = " << rmsSlope << " over " << shortCutoff << " to " << L
           << " m (self-affine, H = " << hurst << ")";
    return RoughnessSpectrum{Spectrum(law.frequencies(), law.amplitudes(), L, source.str()), hurst, bm};
}

} // namespace roughContact
