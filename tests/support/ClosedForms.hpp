// SPDX-License-Identifier: GPL-3.0-or-later
// Closed-form reference solutions the core tests hold the code to, each with its source as the
// tests and docs/theory.md (§6, §7.5 and its references) cite it. Header-only; the expressions
// are written exactly as the tests wrote them, so that each test's numbers are the same to the
// last bit. The tests name them closedForm::... (namespace closedForm =
// roughContactTest::closedForm).
//
// Conventions: E' is the reduced modulus of the contact (a rigid body against a half-space of
// modulus E'), k_s the harmonic-mean conductivity 2 k1 k2/(k1 + k2); "per conductivity" is a
// conductance divided by k_s.
#pragma once

#include <cmath>

namespace roughContactTest::closedForm {

namespace detail {
inline constexpr double pi = 3.14159265358979323846;
} // namespace detail

// ---- Love's uniformly loaded rectangle and the point force ----------------------------------
// (Love, Phil. Trans. R. Soc. Lond. A 228 (1929) 377; Johnson 1985 §3.3 for the rectangle,
// Boussinesq's point force; docs/theory.md §7.1.)

/// Normal displacement at the centre of a square of side 2a under a uniform pressure p: the
/// integral of 1/r over the square is 8 a ln(1 + sqrt 2), so u = p 8 a ln(1 + sqrt 2)/(pi E').
inline double loveSquareCentreDisplacement(double p, double a, double Eprime)
{
    return p * 8 * a * std::log(1 + std::sqrt(2.0)) / (detail::pi * Eprime);
}

/// Normal displacement at distance r from a point force F: u = F/(pi E' r) (the far field of any
/// loaded patch, to O((size/r)^2)).
inline double pointForceDisplacement(double F, double r, double Eprime)
{
    return F / (detail::pi * Eprime * r);
}

// ---- The periodic half-space ------------------------------------------------------------------
// (Johnson 1985 Eq. 12.39 for one wave, as docs/theory.md §7.1 cites it.)

/// Displacement under a pressure wave p cos(q x) of wavenumber q: u = 2 p cos(q x)/(E' q)
/// (p the local pressure, the cosine included).
inline double periodicWaveDisplacement(double p, double q, double Eprime)
{
    return 2 * p / (Eprime * q);
}

// ---- Westergaard's sinusoidal ridge z = D cos(2 pi x/lambda) -----------------------------------
// (Westergaard, ASME J. Appl. Mech. 6 (1939) 49, as the seed cites it; Johnson 1985 §13.2.)

/// The complete-contact pressure p* = pi E' D/lambda.
inline double westergaardCompleteContactPressure(double Eprime, double D, double lambda)
{
    return detail::pi * Eprime * D / lambda;
}

/// Below p*, the contact half-width a has P/p* = sin^2(pi a/lambda): the area fraction
/// 2a/lambda = (2/pi) asin sqrt(P/p*), at ratio = P/p*.
inline double westergaardAreaFraction(double ratio)
{
    return 2 * std::asin(std::sqrt(ratio)) / detail::pi;
}

/// Below p*, the pressure peaks at 2 P/sin(pi a/lambda) = 2 P/sqrt(P/p*), at mean pressure P and
/// ratio = P/p*.
inline double westergaardPeakPressure(double P, double ratio)
{
    return 2 * P / std::sqrt(ratio);
}

/// In complete contact (P >= p*) the pressure is p = P + p* cos(2 pi x/lambda) everywhere (x and
/// lambda in one unit: cells, say).
inline double westergaardCompleteContactPressureAt(double P, double pStar, double x, double lambda)
{
    return P + pStar * std::cos(2 * detail::pi * x / lambda);
}

/// The conductance per conductivity and nominal area of the partial contact: Westergaard's
/// mean gap at P/p* = s^2 is D (1 - s^2 + s^2 ln s^2), and Barber's relation h_c/k_s =
/// -(1/E') dP/d(mean gap) gives pi/(2 lambda ln(1/s)), s = sin(pi a/lambda) = sqrt(P/p*).
inline double westergaardConductancePerConductivity(double lambda, double sinHalfWidth)
{
    return detail::pi / (2.0 * lambda * std::log(1.0 / sinHalfWidth));
}

// ---- Hertz: a paraboloid z = r^2/(2R) pressed by F -----------------------------------------------
// (Hertz; Johnson 1985 §4.2; the seed's Eq. 20 for the asperity.)

/// The contact radius a = (3 F R/(4 E'))^(1/3).
inline double hertzContactRadius(double F, double R, double Eprime)
{
    return std::cbrt(3.0 * F * R / (4.0 * Eprime));
}

/// The force that makes the contact radius a: F = 4 E' a^3/(3 R).
inline double hertzForce(double a, double R, double Eprime)
{
    return 4 * Eprime * a * a * a / (3 * R);
}

/// The central (peak) pressure p0 = 3 F/(2 pi a^2).
inline double hertzPeakPressure(double F, double a)
{
    return 3 * F / (2 * detail::pi * a * a);
}

// ---- The bisinusoid z = D cos(2 pi x/lambda) cos(2 pi y/lambda) ------------------------------------
// (Johnson, Greenwood & Higginson, The contact of elastic regular wavy surfaces, Int. J. Mech.
// Sci. 27 (1985) 383.)

/// The complete-contact pressure p* = sqrt(2) pi E' D/lambda.
inline double bisinusoidCompleteContactPressure(double Eprime, double D, double lambda)
{
    return std::sqrt(2.0) * detail::pi * Eprime * D / lambda;
}

/// In complete contact (P >= p*) the pressure is P + p* z/D, z the surface's height there.
inline double bisinusoidCompleteContactPressureAt(double P, double pStar, double z, double D)
{
    return P + pStar * z / D;
}

// ---- Holm's single spot -----------------------------------------------------------------------
// (Holm, Electric Contacts, 1967, §4; docs/theory.md §6.2: the analogue of the flat punch's
// stiffness 2 E' a.)

/// One circular spot of radius a between two half-spaces: the conductance h_c A_n = 2 a k_s, per
/// conductivity 2 a.
inline double holmSpotConductancePerConductivity(double a)
{
    return 2 * a;
}

/// The same spot's resistance between half-spaces of conductivities k1 and k2:
/// R = (1/(4a))(1/k1 + 1/k2) (= 1/(2 k_s a)).
inline double holmSpotResistance(double a, double k1, double k2)
{
    return (1.0 / (4.0 * a)) * (1.0 / k1 + 1.0 / k2);
}

// ---- Greenwood-Williamson with Gaussian summit heights --------------------------------------------
// (Greenwood & Williamson, Proc. R. Soc. Lond. A 295 (1966) 300; docs/theory.md §4.2.)

/// The standard normal density phi(s) of the summit heights (in units of their rms).
inline double gaussianDensity(double s)
{
    return std::exp(-0.5 * s * s) / std::sqrt(2.0 * detail::pi);
}

/// F_1(h) = int_h^inf (s - h) phi(s) ds = phi(h) - h Q(h), Q(h) = erfc(h/sqrt 2)/2.
inline double gaussianF1(double h)
{
    return gaussianDensity(h) - h * 0.5 * std::erfc(h / std::sqrt(2.0));
}

// ---- Persson's light-load area ------------------------------------------------------------------
// (Persson, J. Chem. Phys. 115 (2001) 3840; docs/theory.md §6.3, the tests' (P3).)

/// A/A_n -> sqrt(8/pi) p/(E' h') at light load: load = p/E', rmsGradient = h' the rms areal
/// gradient.
inline double perssonLightLoadAreaFraction(double load, double rmsGradient)
{
    return std::sqrt(8.0 / detail::pi) * load / rmsGradient;
}

} // namespace roughContactTest::closedForm
