// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/SpectralMoments.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cmath>
#include <sstream>

namespace roughContact {

SpectralMoments spectralMoments(const Spectrum& spectrum)
{
    // m_n = sum_k (2 pi f_k)^n beta_k^2 / 2 in angular wavenumber (docs/theory.md §4.1, McCool 1986):
    // z = sum beta cos(k x + phase), k = 2 pi f, so <z^2>, <z'^2>, <z''^2> weight beta^2/2 by
    // k^0, k^2, k^4. Cycles instead of radians would scale eta and R by (2 pi)^2.
    SpectralMoments m{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < spectrum.size(); ++i) {
        const double k2 = std::pow(2.0 * pi * spectrum.frequency(i), 2);
        const double power = 0.5 * spectrum.amplitude(i) * spectrum.amplitude(i);
        m.m0 += power;
        m.m2 += k2 * power;
        m.m4 += k2 * k2 * power;
    }
    return m;
}

double spectralBandwidthRatio(const Spectrum& spectrum)
{
    const SpectralMoments m = spectralMoments(spectrum);
    double m1 = 0.0;
    for (std::size_t i = 0; i < spectrum.size(); ++i) {
        m1 += 2.0 * pi * spectrum.frequency(i) * 0.5 * spectrum.amplitude(i) * spectrum.amplitude(i);
    }
    requirePositive("spectral moment m0", m.m0);
    requirePositive("spectral moment m2", m.m2);
    // m1^2 <= m0 m2; rounding can put a single level's ratio a few ulps above 1. The square roots
    // apart: m0 m2 could under- or overflow where neither does.
    const double W = m1 / (std::sqrt(m.m0) * std::sqrt(m.m2));
    return W > 1.0 ? 1.0 : W;
}

double firstLevelShare(const Spectrum& spectrum)
{
    // Every level weighted beta^2 (the 1/2 of m0 cancels); levels strictly increase, so level 0 is
    // the longest wave.
    const double variance = spectralMoments(spectrum).m0;
    requirePositive("spectral moment m0", variance);
    const double share = 0.5 * spectrum.amplitude(0) * spectrum.amplitude(0) / variance;
    return share > 1.0 ? 1.0 : share;
}

SummitParameters mcCoolParameters(const SpectralMoments& m)
{
    requirePositive("spectral moment m0", m.m0);
    requirePositive("spectral moment m2", m.m2);
    requirePositive("spectral moment m4", m.m4);
    SummitParameters p{};
    p.eta = m.m4 / (6.0 * pi * std::sqrt(3.0) * m.m2); // docs/theory.md §4.1 (McCool 1986)
    p.R = 0.375 * std::sqrt(pi / m.m4);                // docs/theory.md §4.1 (McCool 1986)
    p.alpha = m.m0 * m.m4 / (m.m2 * m.m2);             // docs/theory.md §4.1 (McCool 1986)
    const double sigmaS2 = (1.0 - 0.8968 / p.alpha) * m.m0; // docs/theory.md §4.1 (McCool 1986)
    if (!(sigmaS2 > 0.0) || !std::isfinite(sigmaS2)) {
        std::ostringstream os;
        os << "summit height variance (1 - 0.8968/alpha) m0 must be positive, got " << sigmaS2
           << " (alpha = m0 m4 / m2^2 = " << p.alpha << ")";
        throw ParameterError("summit height variance sigma_s^2", os.str());
    }
    p.sigmaS = std::sqrt(sigmaS2);
    requirePositive("summit density eta", p.eta);
    requirePositive("summit radius R", p.R);
    return p;
}

SummitParameters mcCoolParameters(const Spectrum& spectrum)
{
    return mcCoolParameters(spectralMoments(spectrum));
}

double arealRmsGradient(const SpectralMoments& moments)
{
    return std::sqrt(2.0 * moments.m2);
}

} // namespace roughContact
