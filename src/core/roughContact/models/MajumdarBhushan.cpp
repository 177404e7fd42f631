// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/MajumdarBhushan.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace roughContact {

MajumdarBhushan::MajumdarBhushan(const FractalParameters& fractal, double nominalArea,
                                 double Eprime, double Sy)
    : fractal_(fractal), An_(requirePositive("nominal area A_n", nominalArea)),
      Eprime_(requirePositive("reduced modulus E'", Eprime)),
      Sy_(requirePositive("yield strength S_y", Sy)), H_(hardnessCoefficient * Sy)
{
    const double D = requireFinite("fractal dimension D", fractal_.D);
    if (!(D > 1.0 && D < 2.0)) {
        throw ParameterError("fractal dimension D", "must lie strictly between 1 and 2");
    }
    requirePositive("fractal roughness G", fractal_.G);
    // a_c = G^2 / (K phi/2)^(2/(D-1)), phi = S_y/E, K = H/S_y (docs/theory.md §4.4), with MB's
    // composite modulus E = E'. In logarithms: (K phi/2)^(2/(D-1)) under- or overflows for D
    // near 1.
    const double phi = Sy_ / Eprime_;
    const double K = H_ / Sy_;
    logAc_ = 2.0 * std::log(fractal_.G) - 2.0 / (D - 1.0) * std::log(0.5 * K * phi);
    ac_ = std::exp(logAc_);
}

double MajumdarBhushan::realArea(double aL) const
{
    requireFinite("largest spot area a_L", aL);
    if (aL < 0.0) {
        throw ParameterError("largest spot area a_L", "must be >= 0");
    }
    const double D = fractal_.D;
    return D * aL / (2.0 - D); // A_r = int_0^a_L a n(a) da (docs/theory.md §4.4)
}

double MajumdarBhushan::load(double aL) const
{
    const double Ar = realArea(aL);
    const double D = fractal_.D;
    const double G = fractal_.G;
    const double E = Eprime_; // MB's E is the composite modulus (docs/theory.md §4.4)
    if (aL == 0.0) {
        return 0.0;
    }
    const double logAL = std::log(aL);
    if (logAL <= logAc_) {
        return H_ * Ar; // every spot plastic: F = H A_r (docs/theory.md §4.4)
    }
    const double l = logAL - logAc_; // ln(a_L / a_c) > 0
    // Plastic spots a < a_c: H [D/(2-D)] a_L^(D/2) a_c^((2-D)/2) (docs/theory.md §4.4).
    const double plastic = H_ * D / (2.0 - D) * std::exp(0.5 * D * logAL + 0.5 * (2.0 - D) * logAc_);
    // Elastic spots a_c < a < a_L (docs/theory.md §4.4):
    // D != 1.5: (4 sqrt(pi)/3) E G^(D-1) [D/(3-2D)] a_L^(D/2) [a_L^x - a_c^x], x = (3-2D)/2;
    // D = 1.5:  sqrt(pi) E G^(1/2) a_L^(3/4) ln(a_L/a_c).
    // [a_L^x - a_c^x] / x = a_c^x expm1(x l) / x, the same closed form without the
    // cancellation near D = 1.5; it tends to l as x -> 0, where the D = 1.5 form takes over.
    double elastic;
    if (D == 1.5) {
        elastic = std::sqrt(pi) * E * std::sqrt(G) * std::exp(0.75 * logAL) * l;
    } else {
        const double x = 0.5 * (3.0 - 2.0 * D);
        const double bracketOverX = std::exp(x * logAc_) * std::expm1(x * l) / x;
        // (4 sqrt(pi)/3) [D/(3-2D)] = (4 sqrt(pi)/3) (D/2) / x
        elastic = (4.0 * std::sqrt(pi) / 3.0) * E * std::pow(G, D - 1.0) * 0.5 * D *
                  std::exp(0.5 * D * logAL) * bracketOverX;
    }
    return elastic + plastic;
}

double MajumdarBhushan::largestSpot(double F) const
{
    requirePositive("contact force F", F);
    const double D = fractal_.D;
    // All spots plastic while F <= F(a_c) = H D a_c/(2-D): a_L = F (2-D)/(H D) (docs/theory.md §4.4).
    const double logFc = std::log(H_ * D / (2.0 - D)) + logAc_;
    if (std::log(F) <= logFc) {
        return F * (2.0 - D) / (H_ * D);
    }
    // Otherwise a_L > a_c and F(a_L) rises strictly. The plastic part alone reaches F at
    // a_U = [F (2-D) / (H D a_c^((2-D)/2))]^(2/D), so the root lies in [a_c, a_U]; solve in
    // ln a_L.
    const double logAU =
        2.0 / D * (std::log(F * (2.0 - D) / (H_ * D)) - 0.5 * (2.0 - D) * logAc_);
    const double logF = std::log(F);
    const auto g = [&](double u) { return std::log(load(std::exp(u))) - logF; };
    double lo = logAc_;
    double hi = std::max(logAU, logAc_);
    const double glo = g(lo);
    const double ghi = g(hi);
    if (ghi <= 0.0) {
        return std::exp(hi);
    }
    std::uintmax_t iterations = 200;
    const auto r = boost::math::tools::toms748_solve(
        g, lo, hi, glo, ghi, boost::math::tools::eps_tolerance<double>(52), iterations);
    return std::exp(0.5 * (r.first + r.second));
}

double MajumdarBhushan::areaFraction(double loadRatio) const
{
    if (checkLoad(loadRatio) == 0.0) {
        return 0.0;
    }
    const double F = loadRatio * An_ * Eprime_; // F/(A_n E') -> F [N]
    // A_r/A_n; the spot sum ignores A_n, so above 1 the model reports complete contact.
    return std::min(realArea(largestSpot(F)) / An_, 1.0);
}

} // namespace roughContact
