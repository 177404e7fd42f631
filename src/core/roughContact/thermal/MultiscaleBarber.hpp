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
// What it rests on and how right it is: Barber's relation is exact for elastic contact; (B2) is
// Yang & Persson's approximation; the multi-scale areas are the model's (2-3 times the exact ones
// on the synthetic surfaces of docs/validation/fidelity.md), so this law is measured there, not
// trusted: see README "How right each model is". Elastic contact only.
#pragma once

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

private:
    const MultiscaleModel& model_;
    double gamma_;
    std::vector<double> binEnergy_;
};

} // namespace roughContact
