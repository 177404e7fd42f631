// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/GreenwoodWilliamson.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/asperity/Hertz.hpp"
#include "roughContact/asperity/JacksonGreen.hpp"
#include "roughContact/asperity/Truncation.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace roughContact {

namespace {
// Integration cut-off: beyond t_max the Gaussian weight, relative to its largest value on
// [0, inf), is below exp(-tailExponent) = 2e-22, far below the quadrature tolerance.
constexpr double tailExponent = 50.0;
// Relative tolerance and bisection depth of the adaptive Gauss-Kronrod rule. The Jackson-Green
// law has kinks inside the panels (the F >= A S_y floor, the hardness cubic's start): a tighter
// tolerance with deep bisection spends millions of evaluations resolving them for nothing.
constexpr double quadratureTolerance = 1e-10;
constexpr unsigned quadratureDepth = 10;
// Growth of ln(load) below which a step of >= 1 in h counts as saturation (complete contact
// of every summit the Gaussian weight reaches): well above the quadrature's 1e-10 noise, and
// a step of 1 from a separation where more than ~1e-8 of the force still grows gives more.
constexpr double saturationGrowth = 1e-9;

// ln phi(x) of the standard normal density.
double logPhi(double x)
{
    return -0.5 * x * x - 0.5 * std::log(2.0 * pi);
}
} // namespace

GreenwoodWilliamson::GreenwoodWilliamson(const SummitParameters& summits, double nominalArea,
                                         double Eprime,
                                         std::shared_ptr<const SphericalAsperity> asperity,
                                         std::string name)
    : summits_(summits), An_(requirePositive("nominal area A_n", nominalArea)),
      Eprime_(requirePositive("reduced modulus E'", Eprime)), asperity_(std::move(asperity)),
      name_(std::move(name))
{
    requirePositive("summit density eta", summits_.eta);
    requirePositive("summit radius R", summits_.R);
    requirePositive("summit height deviation sigma_s", summits_.sigmaS);
    if (!asperity_) {
        throw ParameterError("asperity model", "none given");
    }
    if (name_.empty()) {
        throw ParameterError("model name", "must not be empty");
    }
    // Where the asperity law jumps or kinks, in t = w / sigma_s, so that no quadrature panel
    // straddles them (docs/theory.md §3-4): Jackson-Green at w = 1.9 w_c (force jump, area kink)
    // and at complete contact a/R = 1 (area and force stop growing); truncation at w_c (area
    // doubles, force jumps).
    const double R = summits_.R;
    const double s = summits_.sigmaS;
    if (const auto* jg = dynamic_cast<const JacksonGreen*>(asperity_.get())) {
        const double wc = jg->onset().interference(R);
        const double complete = jg->completeContactInterference();
        if (JacksonGreen::elasticLimit < complete) {
            breaks_.push_back(JacksonGreen::elasticLimit * wc / s);
        }
        breaks_.push_back(complete * wc / s);
    } else if (const auto* tr = dynamic_cast<const Truncation*>(asperity_.get())) {
        breaks_.push_back(tr->onset().interference(R) / s);
    }
    std::sort(breaks_.begin(), breaks_.end());
}

std::unique_ptr<GreenwoodWilliamson> GreenwoodWilliamson::fromSpectrum(
    const Spectrum& spectrum, const ContactMaterials& materials, bool jacksonGreen)
{
    const SummitParameters p = mcCoolParameters(spectrum); // docs/theory.md §4.1
    const double Ep = materials.reducedModulus();
    if (jacksonGreen) {
        const std::string name = "greenwoodWilliamsonJG";
        auto jg = std::make_shared<const JacksonGreen>(Ep, materials.poissonRatio(name),
                                                       materials.youngModulus(name),
                                                       materials.yieldStrength(name));
        return std::make_unique<GreenwoodWilliamson>(p, spectrum.nominalArea(), Ep, std::move(jg),
                                                     name);
    }
    return std::make_unique<GreenwoodWilliamson>(p, spectrum.nominalArea(), Ep,
                                                 std::make_shared<const Hertz>(Ep),
                                                 "greenwoodWilliamson");
}

double GreenwoodWilliamson::logIntegral(Quantity q, double h) const
{
    requireFinite("separation h", h);
    // eta int_h^inf Q((s-h) sigma_s, R) phi(s) ds with t = s - h (docs/theory.md §4.2). The largest
    // Gaussian weight on t >= 0 is phi(hp), hp = max(h, 0); it is taken out analytically:
    // phi(t + h) / phi(hp) = exp(-((t+h)^2 - hp^2) / 2) <= 1, so nothing underflows at light
    // loads (large h) and ln of the result is exact in the factor.
    const double hp = std::max(h, 0.0);
    const double sigma = summits_.sigmaS;
    const double R = summits_.R;
    const SphericalAsperity& law = *asperity_;
    const auto weight = [h, hp](double t) {
        return std::exp(-0.5 * ((t + h) * (t + h) - hp * hp));
    };
    const auto integrand = [&](double t) {
        const double w = t * sigma;
        const double value = q == Quantity::area ? law.area(w, R) : law.force(w, R);
        return value * weight(t);
    };
    // The Gaussian weight falls below exp(-tailExponent) of its largest value outside
    // [t_min, t_max]: for h <= 0 it peaks at t = -h and (t + h)^2/2 >= tailExponent outside
    // -h -+ sqrt(2 tailExponent); for h > 0 it peaks at t = 0 and t h + t^2/2 >= tailExponent
    // beyond -h + sqrt(h^2 + 2 tailExponent) = 2 tailExponent / (h + sqrt(h^2 + 2 tailExponent)).
    // Cutting on both sides matters at heavy loads (h << 0): integrating [0, 2|h|] for a peak
    // of width 1 at |h| = 1e4 lets the adaptive rule miss the peak altogether.
    const double halfWidth = std::sqrt(2.0 * tailExponent);
    const double tMin = h < 0.0 ? std::max(0.0, -h - halfWidth) : 0.0;
    const double tMax = h < 0.0 ? -h + halfWidth
                                : 2.0 * tailExponent / (h + std::sqrt(h * h + 2.0 * tailExponent));
    if (h < 0.0 && !(tMax - tMin >= halfWidth)) { // -h -+ halfWidth no longer resolved
        std::ostringstream os;
        os << "|h| = " << std::abs(h) << " is too large to resolve the Gaussian summit heights";
        throw ParameterError("separation h", os.str());
    }
    double sum = 0.0;
    double a = tMin;
    const auto panel = [&](double b) {
        if (b > a) {
            sum += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                integrand, a, b, quadratureDepth, quadratureTolerance);
            a = b;
        }
    };
    for (double b : breaks_) {
        if (b >= tMax) {
            break;
        }
        panel(b);
    }
    panel(tMax);
    if (!(sum > 0.0) || !std::isfinite(sum)) {
        std::ostringstream os;
        os << "the Greenwood-Williamson integral at h = " << h << " is " << sum;
        throw ParameterError("separation h", os.str());
    }
    return std::log(summits_.eta) + std::log(sum) + logPhi(hp);
}

double GreenwoodWilliamson::areaFractionAt(double h) const
{
    return std::exp(logIntegral(Quantity::area, h)); // A_r/A_n, docs/theory.md §4.2
}

double GreenwoodWilliamson::loadAt(double h) const
{
    return std::exp(logIntegral(Quantity::force, h)) / Eprime_; // F/(A_n E'), docs/theory.md §4.2
}

double GreenwoodWilliamson::solveSeparation(double load, double* saturated) const
{
    requirePositive("load", checkLoad(load));
    // g(h) = ln(eta int F phi) - ln(load E') falls with h (summits leave contact). It falls
    // strictly while some summit is below complete contact; a law whose force stops growing
    // at complete contact (Jackson-Green) saturates as h -> -inf, so loads above
    // eta F_complete / E' are unreachable.
    const double target = std::log(load) + std::log(Eprime_);
    const auto g = [&](double h) { return logIntegral(Quantity::force, h) - target; };
    // Bracket [lo, hi] with g(lo) >= 0 > g(hi) by steps doubling away from h = 0.
    double lo = 0.0;
    double hi = 0.0;
    double glo = g(0.0);
    double ghi = glo;
    double step = 1.0;
    if (glo >= 0.0) {
        for (;;) { // root at h > 0: lighter loads
            hi = lo + step;
            ghi = g(hi);
            if (ghi < 0.0) {
                break;
            }
            lo = hi;
            glo = ghi;
            step *= 2.0;
        }
    } else {
        for (;;) { // root at h < 0: heavier loads
            lo = hi - step;
            glo = g(lo);
            if (glo >= 0.0) {
                break;
            }
            // No growth over a step of >= 1 in h: every summit that the Gaussian weight
            // reaches is in complete contact, the load has saturated below the target.
            if (!(glo - ghi > saturationGrowth)) {
                if (saturated != nullptr) {
                    *saturated = lo;
                    return std::numeric_limits<double>::quiet_NaN();
                }
                std::ostringstream os;
                os << "F/(A_n E') = " << load << " exceeds the largest load the summits carry, "
                   << std::exp(glo + target) / Eprime_ << " (every summit in complete contact)";
                throw ParameterError("load", os.str());
            }
            hi = lo;
            ghi = glo;
            step *= 2.0;
        }
    }
    // To a few ulp of max(|h|, 1): relative far out, absolute near h = 0.
    const auto converged = [](double a, double b) {
        const double eps = std::numeric_limits<double>::epsilon();
        return std::abs(b - a) <= 4.0 * eps * std::max(1.0, std::min(std::abs(a), std::abs(b)));
    };
    std::uintmax_t iterations = 200;
    std::pair<double, double> r;
    try {
        r = boost::math::tools::toms748_solve(g, lo, hi, glo, ghi, converged, iterations);
    } catch (const std::exception& e) {
        std::ostringstream os;
        os << "no separation gives F/(A_n E') = " << load << " (" << e.what() << ")";
        throw ParameterError("load", os.str());
    }
    const double h = 0.5 * (r.first + r.second);
    if (!std::isfinite(h)) {
        std::ostringstream os;
        os << "no finite separation gives F/(A_n E') = " << load;
        throw ParameterError("load", os.str());
    }
    return h;
}

double GreenwoodWilliamson::separation(double load) const
{
    return solveSeparation(load, nullptr);
}

double GreenwoodWilliamson::areaFraction(double load) const
{
    if (checkLoad(load) == 0.0) {
        return 0.0;
    }
    // The independent summits' areas add without bound; a fraction above 1 means the GW
    // picture has broken down, and the model reports complete contact.
    double saturatedAt = 0.0;
    const double h = solveSeparation(load, &saturatedAt);
    if (std::isnan(h)) {
        // Beyond the largest load the summits carry: complete contact if, all summits
        // flattened, their areas already cover A_n; otherwise the model has no answer.
        if (areaFractionAt(saturatedAt) >= 1.0) {
            return 1.0;
        }
        solveSeparation(load, nullptr); // throws, naming the largest load
    }
    return std::min(areaFractionAt(h), 1.0);
}

} // namespace roughContact
