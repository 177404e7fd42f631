// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/ContactTable.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace roughContact {

namespace {

struct Sample {
    double P;
    double area;
    double h;
};

// Table accuracy: the interpolation error at every interval's midpoint is at most this
// (relative), a fifth of the 0.5 % the boundary condition is promised.
constexpr double refineTolerance = 1e-3;
// Narrowest interval: ln(P1/P0) = 1e-7, i.e. a jump of the model itself is located to 1e-7
// relative pressure.
constexpr double minimumLogWidth = 1e-7;
constexpr std::size_t maximumPoints = 200000;
// h_c/k_s beyond 1e9 1/m (the resistance of 1 nm of the solid) is perfect contact for any
// mesh; the table stops there.
constexpr double conductanceCeiling = 1e9;

// The lowest load F/(A_n E') with A_r/A_n = 1, by bisection in log(load) on the monotone
// loading path; +infinity when even 1e3 does not reach it.
double completeContactLoad(const MultiscaleModel& model)
{
    double hi = limits::maximumLoad;
    if (model.areaFraction(hi) < 1.0) {
        return std::numeric_limits<double>::infinity();
    }
    double lo = limits::minimumLoad;
    if (!(model.areaFraction(lo) < 1.0)) {
        return lo;
    }
    while (hi / lo > 1.0 + 1e-10) {
        const double mid = std::sqrt(lo * hi);
        (model.areaFraction(mid) < 1.0 ? lo : hi) = mid;
    }
    return hi;
}

} // namespace

ContactTable::ContactTable(const MultiscaleModel& model, double minPressure, double maxPressure,
                           std::size_t pointsPerDecade, const ConductanceLaw* law)
    : Eprime_(model.reducedModulus())
{
    limits::requireInRange("minimum pressure", minPressure, limits::minimumLoad * Eprime_,
                           limits::maximumLoad * Eprime_, "Pa");
    limits::requireInRange("maximum pressure", maxPressure, limits::minimumLoad * Eprime_,
                           limits::maximumLoad * Eprime_, "Pa");
    if (!(maxPressure > minPressure)) {
        throw ParameterError("maximum pressure", "must exceed the minimum pressure");
    }
    limits::requireInRange("pointsPerDecade", double(pointsPerDecade), double(limits::minimumPointsPerDecade),
                           double(limits::maximumPointsPerDecade), "");
    pComplete_ = completeContactLoad(model) * Eprime_;
    if (!(minPressure < pComplete_)) {
        std::ostringstream os;
        os << "the surface is in complete contact (A_r = A_n) from " << pComplete_
           << " Pa on, at or below the table's lowest pressure " << minPressure
           << " Pa (minPressure; by default 1e-9 E'): at every pressure the table would cover there is no "
              "contact resistance; the surface is too smooth for these materials (check its units), or "
              "lower minPressure";
        throw ParameterError("contact table", os.str());
    }
    // The direct solve at one pressure: {A_r/A_n, h_c/k_s}.
    const auto solve = [&](double P) {
        const std::vector<LevelState> trace = model.trace(P / Eprime_);
        const double area = trace.empty() ? 0.0 : trace.back().area / model.nominalArea();
        const double h = law != nullptr ? law->perConductivity(P)
                                        : constrictionConductancePerConductivity(trace, model.nominalArea());
        // +inf from a law: it says the surfaces conduct perfectly from here on (a law with its
        // own complete contact: fittedElastoPlastic at P = H); the grid ends there
        // as at the conductance ceiling.
        if (!(area > 0.0 && h > 0.0 && (std::isfinite(h) || (law != nullptr && h == HUGE_VAL)))) {
            std::ostringstream os;
            os << "the model gives A_r/A_n = " << area << " and h_c/k_s = " << h << " at " << P
               << " Pa; the table needs positive, finite values";
            throw ParameterError("contact table", os.str());
        }
        return Sample{P, area, h};
    };
    // 1. The log-spaced grid, up to maxPressure, complete contact or the conductance ceiling.
    const double decades = std::log10(maxPressure / minPressure);
    const auto n = static_cast<std::size_t>(std::ceil(decades * double(pointsPerDecade))) + 1;
    std::vector<Sample> samples;
    end_ = End::maxPressure;
    for (std::size_t k = 0; k < n; ++k) {
        const double P = minPressure * std::pow(maxPressure / minPressure, double(k) / double(n - 1));
        if (!(P < pComplete_)) {
            end_ = End::completeContact;
            break;
        }
        samples.push_back(solve(P));
        if (std::isinf(samples.back().h)) {
            samples.pop_back(); // the law's own complete contact: the table ends before it
            pPerfect_ = P;
            end_ = End::conductanceCeiling;
            break;
        }
        if (samples.back().h > conductanceCeiling) {
            end_ = End::conductanceCeiling;
            break;
        }
    }
    // The law's own perfect conductance cut the grid: close the gap to it the same way (the
    // table holds the last finite h up to pPerfect_).
    if (pPerfect_ < std::numeric_limits<double>::infinity()) {
        if (samples.empty()) {
            std::ostringstream os;
            os << "the conductance law " << (law != nullptr ? law->name() : std::string("")) << " gives h_c/k_s = inf "
               << "(perfect conductance) at the table's lowest pressure " << minPressure << " Pa; lower minPressure";
            throw ParameterError("contact table", os.str());
        }
        while (pPerfect_ / samples.back().P - 1.0 > 1e-6) {
            const double P = std::sqrt(samples.back().P * pPerfect_);
            const Sample s = solve(P);
            if (std::isinf(s.h)) {
                pPerfect_ = P;
            } else {
                samples.push_back(s);
            }
        }
    }
    // Complete contact cut the grid: close the gap to it (up to 1e-6 relative), which would
    // otherwise hold h at the last grid point's value over up to one grid step (6 % of P).
    if (end_ == End::completeContact && !samples.empty()) {
        for (double gap = 0.1; gap >= 1e-6; gap *= 0.1) {
            const double P = pComplete_ * (1.0 - gap);
            if (P > samples.back().P) {
                samples.push_back(solve(P));
                if (std::isinf(samples.back().h)) {
                    samples.pop_back();
                    pPerfect_ = P;
                    end_ = End::conductanceCeiling;
                    break;
                }
                if (samples.back().h > conductanceCeiling) {
                    end_ = End::conductanceCeiling;
                    break;
                }
            }
        }
    }
    // 2. Adaptive refinement: bisect (in log P) every interval whose log-log interpolation at
    // the midpoint misses the direct solve by more than refineTolerance, down to a width of
    // minimumLogWidth (which resolves the models' own jumps, e.g. truncation's area doubling).
    std::vector<Sample> refined;
    if (!samples.empty()) {
        refined.push_back(samples.front());
    }
    for (std::size_t k = 1; k < samples.size(); ++k) {
        std::vector<Sample> stack{samples[k]};
        while (!stack.empty() && refined.size() < maximumPoints) {
            const Sample& a = refined.back();
            const Sample& b = stack.back();
            const double logWidth = std::log(b.P / a.P);
            bool accept = logWidth < minimumLogWidth;
            if (!accept) {
                const Sample mid = solve(std::sqrt(a.P * b.P));
                const double area = std::sqrt(a.area * b.area); // log-log linear at the midpoint
                const double h = std::sqrt(a.h * b.h);
                if (std::abs(area / mid.area - 1.0) <= refineTolerance &&
                    std::abs(h / mid.h - 1.0) <= refineTolerance) {
                    accept = true;
                } else {
                    stack.push_back(mid);
                }
            }
            if (accept) {
                refined.push_back(stack.back());
                stack.pop_back();
            }
        }
        if (refined.size() >= maximumPoints) {
            throw ParameterError("contact table",
                                 "needs more than " + std::to_string(maximumPoints) +
                                     " points to reach its accuracy; narrow the pressure range");
        }
    }
    // 3. The loading path: more pressure never loses contact (running maximum).
    double area = 0.0;
    double h = 0.0;
    for (const Sample& smp : refined) {
        area = std::max(area, smp.area);
        h = std::max(h, smp.h);
        p_.push_back(smp.P);
        area_.push_back(area);
        h_.push_back(h);
    }
    if (p_.size() < 2) {
        throw ParameterError("minimum pressure", "is within one table step of complete contact; lower it");
    }
    // 4. The law's mean separation, when it has one, at the refined points (not refined on:
    // linear in log P it is smooth where the area and h are), made non-increasing.
    if (law != nullptr && !std::isnan(law->meanSeparation(p_.front()))) {
        double y = std::numeric_limits<double>::infinity();
        for (const double P : p_) {
            const double raw = law->meanSeparation(P);
            if (!(raw >= 0.0 && std::isfinite(raw))) {
                std::ostringstream os;
                os << "the law " << law->name() << " gives a mean separation of " << raw << " m at " << P
                   << " Pa; the table needs finite values >= 0";
                throw ParameterError("contact table", os.str());
            }
            y = std::min(y, raw);
            separation_.push_back(y);
        }
    }
    index();
}

void ContactTable::index()
{
    for (std::size_t k = 0; k < p_.size(); ++k) {
        logP_.push_back(std::log(p_[k]));
        logArea_.push_back(std::log(area_[k]));
        logH_.push_back(std::log(h_[k]));
    }
    const std::size_t buckets = p_.size();
    bucketScale_ = double(buckets) / (logP_.back() - logP_.front());
    for (std::size_t k = 0; k <= buckets; ++k) {
        const double edge = logP_.front() + double(k) / bucketScale_;
        bucketFirst_.push_back(
            static_cast<std::size_t>(std::upper_bound(logP_.begin(), logP_.end(), edge) - logP_.begin()));
    }
}

ContactTable ContactTable::fromPoints(std::vector<double> pressures, std::vector<double> areaFractions,
                                      std::vector<double> conductancesPerConductivity,
                                      double completeContactPressure, End end, double Eprime,
                                      std::vector<double> separations)
{
    requirePositive("reduced modulus E'", Eprime);
    const std::size_t n = pressures.size();
    if (areaFractions.size() != n || conductancesPerConductivity.size() != n) {
        throw ParameterError("contact table", "the pressures, areas and conductances differ in number");
    }
    if (n < 2) {
        throw ParameterError("contact table", "needs at least 2 points, got " + std::to_string(n));
    }
    for (std::size_t k = 0; k < n; ++k) {
        const double P = pressures[k];
        const double a = areaFractions[k];
        const double h = conductancesPerConductivity[k];
        std::ostringstream os;
        os.precision(17);
        if (!(P > 0.0 && std::isfinite(P)) || (k > 0 && !(P > pressures[k - 1]))) {
            os << "point " << k + 1 << ": the pressure " << P
               << " Pa is not finite, positive and above the one before";
        } else if (!(a > 0.0 && a <= 1.0) || (k > 0 && !(a >= areaFractions[k - 1]))) {
            os << "point " << k + 1 << ": A_r/A_n = " << a << " is not in (0, 1] and non-decreasing";
        } else if (!(h > 0.0 && std::isfinite(h)) || (k > 0 && !(h >= conductancesPerConductivity[k - 1]))) {
            os << "point " << k + 1 << ": h_c/k_s = " << h << " 1/m is not positive, finite and non-decreasing";
        }
        if (!os.str().empty()) {
            throw ParameterError("contact table", os.str());
        }
    }
    if (!(completeContactPressure > pressures.back())) {
        throw ParameterError("contact table", "the complete-contact pressure must lie above the last point");
    }
    if (!separations.empty()) {
        if (separations.size() != n) {
            throw ParameterError("contact table", "the pressures and mean separations differ in number");
        }
        for (std::size_t k = 0; k < n; ++k) {
            const double y = separations[k];
            std::ostringstream os;
            os.precision(17);
            os << "point " << k + 1 << ": the mean separation " << y << " m ";
            if (std::isnan(y)) {
                os << "is NaN";
            } else if (!std::isfinite(y)) {
                os << "is not finite";
            } else if (y < 0.0) {
                os << "is negative";
            } else if (k > 0 && y > separations[k - 1]) {
                os << "exceeds the one before (" << separations[k - 1]
                   << " m): it must be non-increasing in the pressure";
            } else {
                continue;
            }
            throw ParameterError("contact table", os.str());
        }
    }
    ContactTable t;
    t.Eprime_ = Eprime;
    t.pComplete_ = completeContactPressure;
    t.end_ = end;
    t.p_ = std::move(pressures);
    t.area_ = std::move(areaFractions);
    t.h_ = std::move(conductancesPerConductivity);
    t.separation_ = std::move(separations);
    t.index();
    return t;
}

ContactTable::Position ContactTable::locate(double P) const
{
    const double x = std::log(P);
    if (x >= logP_.back()) {
        return {logP_.size() - 1, 1.0, true};
    }
    std::size_t j = 1; // interval [j-1, j]; below the table the first one extrapolates
    if (x > logP_.front()) {
        // The bucket of x holds the answer, unless rounding put x in a neighbouring bucket:
        // then search the whole table.
        const auto k = std::min(static_cast<std::size_t>((x - logP_.front()) * bucketScale_),
                                bucketFirst_.size() - 2);
        const auto first = logP_.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(bucketFirst_[k], 1));
        const auto last = logP_.begin() + static_cast<std::ptrdiff_t>(bucketFirst_[k + 1]) + 1;
        auto it = std::upper_bound(first, std::min(last, logP_.end()), x);
        if (!(it != logP_.end() && *(it - 1) <= x && x < *it)) {
            it = std::upper_bound(logP_.begin(), logP_.end(), x);
        }
        j = static_cast<std::size_t>(it - logP_.begin());
    }
    return {j, (x - logP_[j - 1]) / (logP_[j] - logP_[j - 1]), false};
}

double ContactTable::at(const std::vector<double>& logValues, const Position& where)
{
    const std::size_t j = where.j;
    if (where.end) {
        return std::exp(logValues[j]);
    }
    return std::exp(logValues[j - 1] + where.t * (logValues[j] - logValues[j - 1]));
}

double ContactTable::areaFraction(double P) const
{
    return values(P).areaFraction;
}

double ContactTable::conductancePerConductivity(double P) const
{
    return values(P).conductancePerConductivity;
}

ContactTable::Values ContactTable::values(double P) const
{
    if (std::isnan(P)) {
        throw ParameterError("pressure", "is NaN");
    }
    if (P <= 0.0) {
        return {0.0, 0.0};
    }
    if (P >= pComplete_) {
        return {1.0, std::numeric_limits<double>::infinity()};
    }
    const Position where = locate(P);
    if (P >= pPerfect_) {
        return {std::min(1.0, at(logArea_, where)), std::numeric_limits<double>::infinity()};
    }
    return {std::min(1.0, at(logArea_, where)), at(logH_, where)};
}

double ContactTable::meanSeparation(double P) const
{
    if (std::isnan(P)) {
        throw ParameterError("pressure", "is NaN");
    }
    if (separation_.empty() || P <= 0.0) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    if (P >= pComplete_) {
        return 0.0;
    }
    const Position where = locate(P);
    const std::size_t j = where.j;
    if (where.end) {
        return separation_[j];
    }
    // Linear in log P; below the table the first interval's slope (t < 0), never below 0.
    return std::max(0.0, separation_[j - 1] + where.t * (separation_[j] - separation_[j - 1]));
}

} // namespace roughContact
