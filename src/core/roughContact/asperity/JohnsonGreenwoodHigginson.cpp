#include "roughContact/asperity/JohnsonGreenwoodHigginson.hpp"

#include "roughContact/Error.hpp"

#include <cmath>

namespace roughContact {

namespace {
constexpr double pi = 3.14159265358979323846;
}

JohnsonGreenwoodHigginson::JohnsonGreenwoodHigginson(double Eprime, Form form)
    : Eprime_(requirePositive("reduced modulus E'", Eprime)), form_(form)
{
}

std::string JohnsonGreenwoodHigginson::name() const
{
    return form_ == Form::seed ? "jgh" : "jghConsistent";
}

double JohnsonGreenwoodHigginson::completeContactPressure(const Level& level) const
{
    const double c = form_ == Form::seed ? 2.0 * pi : std::sqrt(2.0) * pi;
    return c * Eprime_ * level.amplitude * level.frequency;
}

double JohnsonGreenwoodHigginson::areaRatioAt(double x) const
{
    // Areas in units of the asperity cell 1/eta = 1/(2 f^2), so eta * Abar is dimensionless.
    const double perCell = form_ == Form::seed ? 1.0 : 0.5;
    const double a1 = perCell * 2.0 * pi * std::cbrt(std::pow(3.0 * x / (8.0 * pi), 2.0)); // Eq. 7
    const double a2 = 1.0 - 3.0 / (2.0 * pi) * (1.0 - x);                                // Eq. 8
    if (x < blendLimit) {
        return a1 * (1.0 - std::pow(x, 1.51)) + a2 * std::pow(x, 1.04); // Eq. 9
    }
    return a2; // Eq. 10
}

double JohnsonGreenwoodHigginson::areaRatio(double pbar, const Level& level) const
{
    const double pstar = completeContactPressure(level);
    if (!(pbar < pstar)) {
        return 1.0; // complete contact (seed §2.2)
    }
    return areaRatioAt(pbar / pstar);
}

} // namespace roughContact
