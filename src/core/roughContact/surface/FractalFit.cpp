// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/surface/FractalFit.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {

struct PsdLine {
    std::size_t levels; ///< the levels fitted
    double slope;       ///< NaN with fewer than 3
    double intercept;   ///< NaN with fewer than 3
};

/// ln S = c + s ln f by least squares over the levels in [fmin, fmax] with beta > 0, S the one-
/// sided PSD beta^2/(2 df), df = 1/L (docs/theory.md §4.3; Spectrum::fractal).
PsdLine fitPsdLine(const Spectrum& spectrum, double fmin, double fmax)
{
    const double L = spectrum.length();
    std::vector<double> x;
    std::vector<double> y;
    for (std::size_t i = 0; i < spectrum.size(); ++i) {
        const double f = spectrum.frequency(i);
        const double beta = spectrum.amplitude(i);
        if (f < fmin || f > fmax || !(beta > 0.0)) {
            continue; // outside the band, or a level that carries nothing (docs/theory.md §1.2)
        }
        x.push_back(std::log(f));
        y.push_back(std::log(0.5 * beta * beta * L));
    }
    if (x.size() < 3) {
        return {x.size(), std::nan(""), std::nan("")};
    }
    // ln f centred on its mean for conditioning.
    const auto n = static_cast<Eigen::Index>(x.size());
    const Eigen::Map<const Eigen::VectorXd> lnF(x.data(), n);
    const Eigen::Map<const Eigen::VectorXd> lnS(y.data(), n);
    const double xMean = lnF.mean();
    Eigen::MatrixXd A(n, 2);
    A.col(0).setOnes();
    A.col(1) = lnF.array() - xMean;
    const Eigen::Vector2d coef = A.colPivHouseholderQr().solve(lnS);
    return {x.size(), coef[1], coef[0] - coef[1] * xMean};
}

} // namespace

std::optional<double> fineHurstExponent(const Spectrum& spectrum)
{
    if (spectrum.size() == 0) {
        return std::nullopt;
    }
    const double fmax = spectrum.frequency(spectrum.size() - 1);
    const PsdLine line = fitPsdLine(spectrum, 0.5 * fmax, fmax);
    if (!std::isfinite(line.slope)) {
        return std::nullopt;
    }
    return -0.5 * (1.0 + line.slope);
}

FractalParameters fitFractal(const Spectrum& spectrum, double fmin, double fmax)
{
    if (std::isnan(fmin) || fmin < 0.0 || fmin == std::numeric_limits<double>::infinity()) {
        std::ostringstream os;
        os << "must be finite and >= 0, got " << fmin;
        throw ParameterError("fractal fit fmin", os.str());
    }
    if (std::isnan(fmax) || !(fmax > fmin)) {
        std::ostringstream os;
        os << "must exceed fmin = " << fmin << ", got " << fmax;
        throw ParameterError("fractal fit fmax", os.str());
    }
    const PsdLine line = fitPsdLine(spectrum, fmin, fmax);
    if (line.levels < 3) {
        std::ostringstream os;
        os << "needs at least 3 levels with beta > 0 in [" << fmin << ", " << fmax << "] 1/m, found "
           << line.levels;
        throw ParameterError("fractal fit frequency range", os.str());
    }
    const double s = line.slope;
    const double c = line.intercept;

    FractalParameters p{};
    p.D = 0.5 * (5.0 + s); // slope -(5 - 2D) of the W-M PSD (docs/theory.md §4.3)
    if (!std::isfinite(p.D) || !(p.D > 1.0 && p.D < 2.0)) {
        std::ostringstream os;
        os << "the fitted PSD slope " << s << " gives D = " << p.D
           << ", outside (1, 2): not a W-M fractal in this band";
        throw ParameterError("fractal dimension D", os.str());
    }
    // Intercept: ln S(1) = 2 (D-1) ln G - ln(2 ln gamma), gamma = 1.5 (docs/theory.md §4.3).
    const double lnGamma = std::log(1.5);
    p.G = std::exp((c + std::log(2.0 * lnGamma)) / (2.0 * (p.D - 1.0)));
    requirePositive("fractal roughness G", p.G);
    return p;
}

} // namespace roughContact
