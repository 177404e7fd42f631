#include "roughContact/models/GreenwoodWilliamson.hpp"

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
constexpr double pi = 3.14159265358979323846;

// Integration cut-off: beyond t_max the Gaussian weight, relative to its largest value on
// [0, inf), is below exp(-tailExponent) = 2e-22, far below the quadrature tolerance.
constexpr double tailExponent = 50.0;
// Relative tolerance and bisection depth of the adaptive Gauss-Kronrod rule. The Jackson-Green
// law has kinks inside the panels (the F >= A S_y floor, the hardness cubic's start): a tighter
// tolerance with deep bisection spends millions of evaluations resolving them for nothing.
constexpr double quadratureTolerance = 1e-10;
constexpr unsigned quadratureDepth = 10;

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
    // straddles them (physics.md §3-4): Jackson-Green at w = 1.9 w_c (force jump, area kink)
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
    const SummitParameters p = mcCoolParameters(spectrum); // physics.md §4
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
    // eta int_h^inf Q((s-h) sigma_s, R) phi(s) ds with t = s - h (physics.md §4). The largest
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
    // (t + h)^2/2 - hp^2/2 >= tailExponent beyond t_max = -h + sqrt(h^2 + 2 tailExponent)
    // for h <= 0, and t h + t^2/2 >= tailExponent beyond the same t_max for h > 0.
    const double tMax = -h + std::sqrt(h * h + 2.0 * tailExponent);
    double sum = 0.0;
    double a = 0.0;
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
    return std::exp(logIntegral(Quantity::area, h)); // A_r/A_n, physics.md §4
}

double GreenwoodWilliamson::loadAt(double h) const
{
    return std::exp(logIntegral(Quantity::force, h)) / Eprime_; // F/(A_n E'), physics.md §4
}

double GreenwoodWilliamson::separation(double load) const
{
    requirePositive("load", checkLoad(load));
    // ln(F/(A_n E')) falls strictly and smoothly with h (summits leave contact); solve for
    // x = exp(h) so that Boost's multiplicative bracketing covers h of either sign.
    const double target = std::log(load) + std::log(Eprime_);
    const auto g = [&](double x) { return logIntegral(Quantity::force, std::log(x)) - target; };
    std::uintmax_t iterations = 400;
    std::pair<double, double> r;
    try {
        r = boost::math::tools::bracket_and_solve_root(
            g, 1.0, 2.0, false, boost::math::tools::eps_tolerance<double>(52), iterations);
    } catch (const std::exception& e) {
        std::ostringstream os;
        os << "no separation gives F/(A_n E') = " << load << " (" << e.what() << ")";
        throw ParameterError("load", os.str());
    }
    const double h = std::log(0.5 * (r.first + r.second));
    if (!std::isfinite(h)) {
        std::ostringstream os;
        os << "no finite separation gives F/(A_n E') = " << load;
        throw ParameterError("load", os.str());
    }
    return h;
}

double GreenwoodWilliamson::areaFraction(double load) const
{
    if (checkLoad(load) == 0.0) {
        return 0.0;
    }
    // The independent summits' areas add without bound; a fraction above 1 means the GW
    // picture has broken down, and the model reports complete contact.
    return std::min(areaFractionAt(separation(load)), 1.0);
}

} // namespace roughContact
