// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/UnloadingTable.hpp"

#include "roughContact/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace roughContact {

namespace {

std::string where(std::size_t curve, double peak, std::size_t point = std::size_t(-1))
{
    std::ostringstream os;
    os << "unloading curve " << curve + 1 << " (from " << peak << " Pa)";
    if (point != std::size_t(-1)) {
        os << ", point " << point + 1;
    }
    return os.str();
}

// ln(a/b), or 0 where either is not a positive finite number (a separation of 0 or none).
double logRatio(double a, double b)
{
    return std::isfinite(a) && std::isfinite(b) && a > 0.0 && b > 0.0 ? std::log(a / b) : 0.0;
}

// The value at ln s of a curve's ratios (linear in ln s, held below the lowest fraction).
double at(const std::vector<double>& logFraction, const std::vector<double>& values, double logS)
{
    if (logS <= logFraction.front()) {
        return values.front();
    }
    const auto hi = std::upper_bound(logFraction.begin(), logFraction.end(), logS);
    if (hi == logFraction.end()) {
        return values.back(); // ln s = 0: the peak
    }
    const std::size_t j = std::size_t(hi - logFraction.begin());
    const double t = (logS - logFraction[j - 1]) / (logFraction[j] - logFraction[j - 1]);
    return values[j - 1] + t * (values[j] - values[j - 1]);
}

} // namespace

double UnloadingTable::coordinate(double peak) const
{
    if (!hardness_) {
        return std::log(peak);
    }
    return peak < *hardness_ ? -std::log1p(-peak / *hardness_) : std::numeric_limits<double>::infinity();
}

void UnloadingTable::check(const std::vector<double>& loadingArea, const std::vector<double>& loadingH,
                           const std::vector<double>& loadingSeparation)
{
    std::size_t flat = 0;
    for (std::size_t c = 0; c < curves_.size(); ++c) {
        const UnloadingCurve& u = curves_[c];
        if (!(std::isfinite(u.peak) && u.peak > 0.0)) {
            throw ParameterError(where(c, u.peak), "the peak must be a finite pressure > 0");
        }
        if (c > 0 && !(u.peak > curves_[c - 1].peak)) {
            throw ParameterError(where(c, u.peak), "the peaks must increase");
        }
        if (hardness_ && !(u.peak < *hardness_)) {
            throw ParameterError(where(c, u.peak), "the peak must lie below the hardness");
        }
        const std::size_t n = u.pressures.size();
        if (n == 0 || u.areaFractions.size() != n || u.conductancesPerConductivity.size() != n ||
            !(u.separations.empty() || u.separations.size() == n)) {
            throw ParameterError(where(c, u.peak), "needs at least one point and as many values of each column");
        }
        LogRatios r;
        for (std::size_t k = 0; k < n; ++k, ++flat) {
            const double P = u.pressures[k];
            if (!std::isfinite(P) || !(P > 0.0 && P < u.peak) || (k > 0 && !(P > u.pressures[k - 1]))) {
                throw ParameterError(where(c, u.peak, k), "pressures must increase within (0, the peak)");
            }
            const double a = u.areaFractions[k];
            const double h = u.conductancesPerConductivity[k];
            if (!(std::isfinite(a) && a > 0.0 && a <= 1.0) || !(std::isfinite(h) && h > 0.0)) {
                throw ParameterError(where(c, u.peak, k), "needs A_r/A_n in (0, 1] and a finite h_c/k_s > 0");
            }
            if (!(std::isfinite(loadingArea[flat]) && std::isfinite(loadingH[flat]) && loadingArea[flat] > 0.0 &&
                  loadingH[flat] > 0.0)) {
                throw ParameterError(where(c, u.peak, k), "the loading curve has no contact at its pressure");
            }
            const double Y = u.separations.empty() ? 0.0 : u.separations[k];
            if (!(std::isfinite(Y) && Y >= 0.0)) {
                throw ParameterError(where(c, u.peak, k), "needs a finite separation >= 0");
            }
            r.logFraction.push_back(std::log(P / u.peak));
            r.area.push_back(std::log(a / loadingArea[flat]));
            r.h.push_back(std::log(h / loadingH[flat]));
            r.separation.push_back(logRatio(Y, loadingSeparation[flat]));
        }
        // At the peak the joint is on its loading curve.
        r.logFraction.push_back(0.0);
        r.area.push_back(0.0);
        r.h.push_back(0.0);
        r.separation.push_back(0.0);
        peakCoordinates_.push_back(coordinate(u.peak));
        ratios_.push_back(std::move(r));
    }
}

UnloadingFactors UnloadingTable::factors(double P, double peak) const
{
    if (curves_.empty() || !std::isfinite(P) || !std::isfinite(peak) || !(P > 0.0) || !(P < peak)) {
        return {};
    }
    const double logS = std::log(P / peak);
    const double c = coordinate(peak);
    const std::vector<double>& cs = peakCoordinates_;
    // The solved peaks around P_max, and the weight of the upper one (held beyond the ends).
    std::size_t lo = 0;
    std::size_t hi = 0;
    double t = 0.0;
    if (c >= cs.back()) {
        lo = hi = cs.size() - 1;
    } else if (c > cs.front()) {
        hi = std::size_t(std::upper_bound(cs.begin(), cs.end(), c) - cs.begin());
        lo = hi - 1;
        t = (c - cs[lo]) / (cs[hi] - cs[lo]);
    }
    const auto rho = [&](std::vector<double> LogRatios::*column) {
        const double a = at(ratios_[lo].logFraction, ratios_[lo].*column, logS);
        const double b = at(ratios_[hi].logFraction, ratios_[hi].*column, logS);
        return std::exp(a + t * (b - a));
    };
    return {rho(&LogRatios::area), rho(&LogRatios::h), rho(&LogRatios::separation)};
}

} // namespace roughContact
