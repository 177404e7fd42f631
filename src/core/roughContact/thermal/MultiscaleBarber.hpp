// SPDX-License-Identifier: GPL-3.0-or-later
// A contact conductance built on the multi-scale model: Barber's relation applied to the
// elastic energy stored in the model's levels.
//
// Barber (Proc. R. Soc. A 459 (2003) 53): for elastic contact h_c/k_s = -(1/E') dp/du, u the mean
// separation. The separation follows from the elastic energy stored at the interface,
// p = -dU_el/(A_n du) (the work of the load), so
//     h_c/k_s = p / (E' d(U_el/A_n)/dp) = load / (dU/d load),   U = U_el/(A_n E'),      (B1)
// with load = p/E'. Yang & Persson (J. Phys.: Condens. Matter 20 (2008) 215214) write the
// energy as the full-contact energy of the roughness at each scale weighted by the contact seen
// at that scale, P:
//     U_el/A_n = (pi/2) E' int q^2 C(q) W(P(q)) dq,  W(P) = P [gamma + (1 - gamma) P^2]       (B2)
// (the same form as models/Persson.hpp, (P4), gamma = 0.42; (B1)-(B3) are this header's own
// labels: the papers' equation numbers were not at hand, as Persson.hpp says). Here P(q) is not Persson's but the
// multi-scale model's: in the frequency bin of level i the area seen is a_i = A_i/A_n, the area
// after level i (MultiscaleModel::trace). The bin's full-contact energy over E' is
// (pi/2) int_bin q^2 C dq = q_i V_i/4, V_i the 2-D variance in the bin (q = 2 pi f; with
// Persson's C(q) = C2(q/2pi)/(2pi)^2, (pi/2) q^2 C dq = q V/4 for the annulus of variance V), taken
// from the isotropic 2-D spectrum of the line scans (IsotropicSpectrum: powerOutside at the bin's
// edges, the midpoints between levels). So
//     U(load) = sum_i (q_i V_i / 4) W(a_i(load)),                                        (B3)
// and (B1) with dU/d load by a central difference of the traces at load (1 +- 1e-3).
// Limits (testMultiscaleBarber): every level in complete contact (a_i = 1, U constant): +inf;
// one level: the closed form of (B1)-(B3) with its own a(load); the bins hold the whole 2-D
// variance. At light load h_c is not linear in the load although the multi-scale area is: the
// coarse levels close one after another (assumption 5) and the energy that still changes moves
// to finer levels (h_c ~ load^1.3 on a Hurst 0.8 power law), where Persson's theory and the
// boundary elements give h_c ~ load.
// The mean separation. The same relation p = -dU_el/(A_n du) gives u itself: with
// U = U_el/(A_n E') and load = p/E' it reads dU = -load du, so du = -dU/load and
//     u(load) = int_{load}^{load_c} (dU/dl) dl / l,                                      (B4)
// load_c the load of complete contact (every level at a_i = 1: U is constant beyond it, the
// surfaces touch everywhere, u = 0). Assumptions: (i) the separation is 0 at complete contact
// and the loading path is the model's monotone one (U non-decreasing in the load); (ii) (B4) is
// a Stieltjes integral: U built on the traces is only piecewise smooth (a level closes, an
// asperity law switches, truncation's area doubles), and a jump of U by dU at l adds dU/l to u
// (the separation drops at once, h_c is infinite there); (iii) the model reaches complete
// contact below limits::maximumLoad, else the part of (B4) above it is unknown and u is NaN.
// So that jumps and kinks need no derivative, (B4) is integrated by parts,
//     u(load) = U_c/load_c - U(load)/load + int_{load}^{load_c} U(l) dl / l^2,           (B5)
// U_c = U(load_c), the last integral in t = ln l (integrand U e^-t, bounded) over panels of a
// hundredth of a decade down from load_c by adaptive Gauss-Kronrod (15 points, relative 1e-10),
// their sums kept (extended down lazily as lower loads are asked, under a lock) so that one u
// costs one partial panel (10-point Gauss-Legendre: 11 traces, ~10 us). Barber's relation holds for u by construction: -(d load/du) =
// load/(dU/d load), the conductance above; its central difference (step 1e-3) against the
// difference of (B5) is met to O(1e-6) where U is smooth (testMultiscaleBarber).
// What it rests on and how right it is: Barber's relation is exact for elastic contact; (B2) is
// Yang & Persson's approximation; the multi-scale areas are the model's (2-3 times the exact ones
// on the synthetic surfaces of docs/validation/fidelity.md), so this law is measured there, not
// trusted: see docs/models.md, "How right each model is". Elastic contact only.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

namespace roughContact {

class MultiscaleModel;
class Spectrum;

class MultiscaleBarber {
public:
    /// model: the multi-scale model (its levels); lineScan: the spectrum it was built from.
    MultiscaleBarber(const MultiscaleModel& model, const Spectrum& lineScan, double gamma = 0.42);

    /// h_c/k_s [1/m] at load = p/E' (>= 0; 0 gives 0; +inf at complete contact).
    double conductancePerConductivity(double load) const;
    /// U of (B3) [m]: the elastic energy per nominal area over E'.
    double energy(double load) const;
    /// q_i V_i / 4 [m] of every spectrum level (index as LevelState::index).
    const std::vector<double>& binEnergies() const noexcept { return binEnergy_; }
    /// u of (B4)-(B5) [m], the mean-plane separation at load = p/E' (> 0): non-increasing, 0
    /// from completeContactLoad() on; +inf at load 0; NaN when the model does not reach
    /// complete contact below limits::maximumLoad (assumption iii). Thread-safe.
    double meanSeparation(double load) const;
    /// load_c: the lowest load with A_r/A_n = 1 (bisection in log load to 1e-10 relative, as
    /// ContactTable's), +inf when the model does not reach it below limits::maximumLoad.
    double completeContactLoad() const;

private:
    const MultiscaleModel& model_;
    double gamma_;
    std::vector<double> binEnergy_;
    // (B5)'s panels, built lazily: load_c, U_c and the sums of int U e^-t dt from load_c down
    // to the bottom of each panel.
    struct Separation {
        std::mutex lock;
        bool started = false;
        double loadC = 0.0;
        double energyC = 0.0;
        std::vector<double> below;
    };
    std::unique_ptr<Separation> separation_ = std::make_unique<Separation>();
    void startSeparation() const; // with separation_->lock held
};

} // namespace roughContact
