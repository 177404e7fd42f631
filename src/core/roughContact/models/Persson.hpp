// SPDX-License-Identifier: GPL-3.0-or-later
// Persson's contact theory (B.N.J. Persson, J. Chem. Phys. 115 (2001) 3840) with the mean
// interfacial separation of Persson (Phys. Rev. Lett. 99 (2007) 125502) and Yang & Persson
// (J. Phys.: Condens. Matter 20 (2008) 215214), and the contact conductance by Barber's relation
// (Persson, Lorenz & Volokitin, Eur. Phys. J. E 31 (2010) 3), fed by the same line-scan spectrum
// as the multi-scale models.
//
// 1. The spectrum. Persson writes the isotropic 2-D power spectrum C(q) of the heights with the
// wavevector q in rad/m, normalised so that <h^2> = integral over R^2 of C(q) d^2q =
// 2 pi integral q C(q) dq. IsotropicSpectrum (ArealSynthesis.hpp) gives C2(f) with f in cycles/m
// and <h^2> = integral over R^2 of C2(f) d^2f. With q = 2 pi f the area element is
// d^2q = (2 pi)^2 d^2f, so the same variance needs
//     C(q) = C2(q / (2 pi)) / (2 pi)^2.                                                   (P1)
// Checks (testPersson): 2 pi int q C dq is the IsotropicSpectrum's variance powerOutside(0), and
// 2 pi int q^3 C dq, the mean square of the areal gradient |grad h|^2, its gradient computed from
// powerOutside by parts, both to 1e-8. Twice the line scans' slope variance (an isotropic
// gradient has two equal components) is met to 0.8 % only, and the line scans' own variance
// not at all (32 % below, levels from 1/L): the IsotropicSpectrum's C2 lives on the band only,
// where the Abel inversion of the band-limited C1 would be negative below it, and the band's C2
// holds more power than the line scans. Persson and the synthesized surfaces see the same C2.
//
// 2. Moduli. E' here is this project's reduced modulus 1/((1-nu1^2)/E1 + (1-nu2^2)/E2), the
// modulus of an elastic half-space against a rigid rough one (Johnson 1985 §13.1). Persson's
// papers take an elastic solid of E, nu against a rigid rough surface and write
// E* = E/(1-nu^2) (Persson 2001, Yang & Persson 2008); that is the same number, so E* = E' below.
// The dimensionless load is load = p/E' with p = F/A_n the nominal pressure.
//
// Equation numbers. The papers were not at hand while this was written: the forms below are
// taken from their restatements in later work and public implementations and checked by the
// derivations given here and by testPersson (closed-form limits, Barber, the boundary-element
// reference), not against the papers' numbered equations; (P1)-(P8) are this header's own.
//
// 3. Contact area (Persson 2001; restated by Yang & Persson 2008 and Almqvist et al. 2011): the
// stress distribution diffuses with magnification; with the boundary condition P(sigma = 0) = 0
// its solution gives at the highest wavenumber q1
//     A/A_n = P(p) = erf(p / (2 sqrt(G))),  G = (pi/4) E'^2 int_{q0}^{q1} q^3 C(q) dq.     (P2)
// (The same as erf(p/sqrt(2 V)) with the pressure variance of complete contact
// V = (pi/2) E'^2 int q^3 C dq = 2 G, as some restatements write it.)
// Write w(q) = (pi int_{q0}^{q} q'^3 C(q') dq')^(-1/2); then p/(2 sqrt(G(q))) = w(q) p/E' and
// P(q, p) = erf(w(q) p/E') is the area seen at magnification q/q0. Light load: erf(x) ~ 2x/sqrt(pi)
// and int q^3 C dq = h'^2/(2 pi) (h' the rms areal gradient), so G = E'^2 h'^2/8 and
//     A/A_n -> sqrt(8/pi) p/(E' h') = kappa p/(E' h'),  kappa = sqrt(8/pi) = 1.596.         (P3)
// Complete contact only asymptotically: 1 - P ~ exp(-x^2)/(x sqrt(pi)), x = w(q1) p/E'.
//
// 4. Mean separation (Persson 2007; Yang & Persson 2008; the same form in Almqvist, Campana,
// Prodanov & Persson, J. Mech. Phys. Solids 59 (2011) 2355, their comparison with numerics).
// The elastic energy stored at the interface is (Yang & Persson 2008)
//     U_el/A_n = (pi/2) E' int_{q0}^{q1} q^2 C(q) W(q, p) dq,
//     W(q, p) = P(q, p) [gamma + (1 - gamma) P^2(q, p)],                                  (P4)
// which is the energy of the full contact (pi/2) E' int q^2 C dq (half-space stiffness E'|q|/2)
// weighted by the contact at each scale. gamma is Yang & Persson's correction: the factor P^2 of
// Persson's original energy (gamma = 0 there) underestimates the elastic energy stored at partial
// contact; a gamma of about 0.4 fits their molecular-dynamics simulations (0.42 here, the value
// used after them; the paper's own number not checked, see Equation numbers). The load follows from the energy: p = -dU_el/(A_n du), so
// u(p) = int_p^inf (dp'/p') (1/A_n) dU_el/dp', and since dW/dp = (dP/dp) [gamma + 3 (1-gamma) P^2],
//     u(p) = sqrt(pi) int_{q0}^{q1} dq q^2 C(q) w(q) int_p^inf (dp'/p')
//            [gamma + 3 (1 - gamma) P^2(q, p')] exp(-(w(q) p'/E')^2).                     (P5)
// Which form. (a) The factor 3 in front of (1-gamma) P^2 is the derivative of P^3 in (P4); a 1
// there would not be the derivative of any energy (the "1" in some restatements is W's own
// factor). (b) The lower limit (as recalled, not checked against the paper): Persson 2007
// writes p(zeta) = p A_n/A(zeta), the mean pressure in
// the contact seen at the magnification zeta at which the separation is observed, with the
// wavenumbers integrated from zeta q0. The separation of the whole interface is zeta = 1, where
// A(1) = A_n and the limit is p itself. Taking p/P(q, p) with q the integration variable instead
// makes the inner integral start at x >= sqrt(pi)/2 for every q, so u(0) would be finite; that
// contradicts the exponential law below, which those papers derive from the same equation.
// This model implements (P5) with the limit p, the factor 3 and gamma in the energy only: the
// area is (P2) unchanged. (Some later papers also let gamma reshape the area by accumulating G
// with the weight gamma + (1-gamma) P^2; that variant is not implemented.)
// With s = w(q) p/E' the inner integral is a function of s alone,
//     J(s) = int_s^inf (dx/x) [gamma + 3 (1-gamma) erf^2(x)] exp(-x^2),                    (P6)
// and u(p) = sqrt(pi) int dq q^2 C w J(w p/E'). Light load (s -> 0): J(s) = -gamma ln s + O(1),
// so u = -u0 ln(p) + const, i.e. p = beta E' exp(-u/u0) with
//     u0 = sqrt(pi) gamma int_{q0}^{q1} q^2 C(q) w(q) dq                                  (P7)
// (Persson 2007); lightLoadDecayLength() returns it.
//
// 5. Conductance. Barber's relation (J.R. Barber, Proc. R. Soc. Lond. A 459 (2003) 53; used with
// Persson's u(p) by Persson, Lorenz & Volokitin 2010): the conductance per
// nominal area over k_s = 2 k1 k2/(k1 + k2) is h_c/k_s = -(1/E') dp/du. Differentiating (P5)
// under the integral, dJ/ds = -(1/s)[...] exp(-s^2) and ds/dp = w/E' give the exact
//     du/dp = -(sqrt(pi)/p) int dq q^2 C w [gamma + 3 (1-gamma) erf^2(s)] exp(-s^2),
//     h_c/k_s = load / (sqrt(pi) int dq q^2 C w [gamma + 3 (1-gamma) erf^2(s)] exp(-s^2)),  (P8)
// no finite difference. At light load h_c/k_s -> load/u0 (linear in p). Near complete contact
// (load >> h') u and 1/h_c fall like exp(-s1^2), s1 = w(q1) p/E' = sqrt(2) load/h': both are
// finite but leave the range of a double beyond load ~ 19 h'; u then underflows to 0 and h_c/k_s
// is returned as +inf (as BoundaryElementModel's complete contact). The area is 1 to double
// precision from load ~ 4 h' on. At load 0: area 0, u = +inf (the exponential law), h_c = 0.
//
// 6. Quadrature. The integrals run over f = q/(2 pi) in the band of the IsotropicSpectrum
// [lowestFrequency, highestFrequency] (q0, q1 = 2 pi times them: the magnification range is the
// spectrum's band). C2 has a square-root kink at every node of the interpolated line-scan
// spectrum and an inverse-square-root pile-up at the top (ArealSynthesis.hpp), and w(q) ~
// (q - q0)^(-1/2) at the bottom, so each bin between nodes is mapped by f = a + (b - a)(3t^2 - 2t^3),
// which makes all three smooth in t, and integrated by Gauss-Legendre (pointsPerBin points,
// default 12; the lowest bin also in geometrically graded pieces, for the logarithm of J near
// q0 at light load). On a power law of 1000 levels, relative to 32 points: 12 points are exact
// to ~1e-9 in u and h_c, 8 to ~1e-7, 6 to 1e-4 (in h_c). IsotropicSpectrum::c2 costs one
// term per bin, so beyond about 4000 bins (12 points) the bins are grouped into log-spaced
// panels whose edges are levels, keeping the construction near 5e7 terms (16 panels at least);
// the kinks inside a panel are then not resolved: testPersson measures 4e-5 on 3000 levels.
// int q^3 C dq up to each node, for w, is exact on the interpolating polynomial of the same
// points. J(s) is evaluated by persson::scaledSeparationKernel below.
#pragma once

#include "roughContact/models/ContactModel.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace roughContact {

class Spectrum;

struct PerssonOptions {
    /// Yang & Persson's (2008) gamma in the elastic energy (P4), within (0, 1].
    double gamma = 0.42;
    /// Gauss-Legendre points per frequency bin, within [2, 32].
    std::size_t pointsPerBin = 12;
    /// C2 terms the construction may take (points x bins x bins); more bins than fit are grouped
    /// into log-spaced panels (6 above). Within [1e5, 1e12]; 5e7 is about half a second.
    double workBudget = 5e7;
};

/// One load point of Persson's theory.
struct PerssonPoint {
    double load = 0.0;                       ///< F/(A_n E')
    double areaFraction = 0.0;               ///< A_r/A_n, (P2)
    double meanSeparation = 0.0;             ///< u [m], (P5); +inf at load 0
    double conductancePerConductivity = 0.0; ///< h_c/k_s [1/m], (P8); +inf beyond double range
};

class PerssonModel final : public ContactModel {
public:
    /// lineScan: the (combined) line-scan spectrum, converted to the isotropic 2-D one by
    /// IsotropicSpectrum; Eprime: E' of the pair [Pa]. ParameterError naming the entry for a
    /// surface without roughness, E' out of range or options out of range.
    PerssonModel(const Spectrum& lineScan, double Eprime, PerssonOptions options = {});

    std::string name() const override { return "persson"; }
    /// (P2).
    double areaFraction(double load) const override;
    /// (P5) [m].
    double meanSeparation(double load) const;
    /// (P8) [1/m].
    double conductancePerConductivity(double load) const;
    /// All three at one load.
    PerssonPoint evaluate(double load) const;

    /// From Persson's C(q) by the model's quadrature: sqrt(2 pi int q C dq) [m] and
    /// sqrt(2 pi int q^3 C dq) (rms areal gradient).
    double rmsHeight() const noexcept { return rmsHeight_; }
    double rmsGradient() const noexcept { return rmsGradient_; }
    /// u0 of (P7) [m].
    double lightLoadDecayLength() const noexcept { return u0_; }
    /// q0, q1 [rad/m].
    double lowestWavenumber() const noexcept { return q0_; }
    double highestWavenumber() const noexcept { return q1_; }
    double reducedModulus() const noexcept { return Eprime_; }
    const PerssonOptions& options() const noexcept { return options_; }

private:
    struct Sums {
        double logSeparation;  // ln u
        double logConductance; // ln(h_c/k_s)
    };
    Sums sums(double load) const;

    double Eprime_;
    PerssonOptions options_;
    double q0_ = 0.0;
    double q1_ = 0.0;
    double rmsHeight_ = 0.0;
    double rmsGradient_ = 0.0;
    double u0_ = 0.0;
    double w1_ = 0.0;           // w(q1)
    std::vector<double> w_;     // w(q) at the nodes
    std::vector<double> mass_;  // dq q^2 C(q) w(q) at the nodes (weight included) [m]
};

namespace persson {
/// exp(s^2) J(s) of (P6), s > 0 finite, gamma in [0, 1]: for s < 1 by the series of E1 and
/// a 16-point Gauss-Legendre rule, for s >= 1 by the continued fraction of exp(z) E1(z) and
/// graded Gauss-Legendre panels for the erf correction (absent, below 1e-16, from s = 6 on).
double scaledSeparationKernel(double s, double gamma);
/// exp(z) E1(z) for z > 0 (E1 the exponential integral).
double scaledExponentialIntegral(double z);
} // namespace persson

} // namespace roughContact
