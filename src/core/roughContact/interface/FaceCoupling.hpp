// SPDX-License-Identifier: GPL-3.0-or-later
// The per-face coupling of the two solids across a rough interface: everything the boundary
// condition decides per face, in one call on plain arrays. The OpenFOAM glue only gathers the
// arrays (its own side's and, exchanged once, the neighbour's) and hands the results to the
// mixed condition; a bad face comes back as a FaceError naming it.
//
// Per face i, with this side "1" and the neighbour "2" (their values mapped onto this side's
// faces):
//   P        = nominalPressure(P1, P2)                       the rule for the two sides' pressures
//   state    = apart (P <= 0), partial, beyondTable (held at the table's end, see
//              ContactInterface::heldAtTableEnd) or complete (P >= complete contact)
//   A_r/A_n, h_c = k_s (h_c/k_s)(P)  from the interface's table (ContactInterface), 0 apart,
//              +inf at complete contact; k_s = 2 k1 k2/(k1 + k2)
//   P_max    = max(P, peak1, peak2)  the heaviest load the face has carried (with a load history:
//              each side keeps it, and takes the larger of the two so that both agree)
//   A_r/A_n, h_c, Y  times the unloading factors at (P, P_max) (ContactInterface::
//              unloadingFactors: 1 at P = P_max and for a model without unloading curves)
//   h        = h_c + h_g + h_r       (docs/theory.md §5.12, "Interface conductance"), the gap terms
//              (interface/InterfaceGap.hpp) where the interface has a gap, 0 otherwise; at
//              complete contact there is no gap left and h = +inf
//   w        = coupledValueFraction(h, kappa1 delta1, kappa2 delta2)  (thermal/InterfaceCoupling)
//   refValue = the neighbour's cell temperature
// so the face flux is (T_cell2 - T_cell1)/(1/(kappa1 delta1) + 1/h + 1/(kappa2 delta2)) on both
// sides alike.
//
// The constant-h mode (a given h instead of a contact) is the stock coupled baffle with
// thicknessLayers/kappaLayers, as that condition computes it: refValue = the neighbour's FACE
// temperature, w = h/(h + kappa1 delta1). At convergence it is the same law (the face
// temperatures jump by q/h); on the way it iterates differently from the contact mode. It is
// kept as the stock computes it so that it reproduces that condition to round-off.
#pragma once

#include "roughContact/Error.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace roughContact {

class ContactInterface;

/// Bad input at one face of a batch (couple, coupleConstant): what() reads
/// "face I: PARAMETER: message".
class FaceError : public ParameterError {
public:
    FaceError(std::size_t face, const ParameterError& why)
        : ParameterError("face " + std::to_string(face), why.what()), face_(face)
    {
    }
    std::size_t face() const noexcept { return face_; }

private:
    std::size_t face_;
};

/// What a face is doing. The contactState field writes int(state) for the first three;
/// beyondTable is written as partial (1): it is in partial contact, with h held at the table's
/// last value (the boundary condition warns once).
enum class FaceState : int { apart = 0, partial = 1, complete = 2, beyondTable = 3 };

/// The written code of a state: 0 apart, 1 partial (and beyondTable), 2 complete.
inline int contactStateCode(FaceState s) { return s == FaceState::beyondTable ? 1 : static_cast<int>(s); }

/// The nominal pressure of a face from the pressures both sides give for it [Pa]: their mean,
/// so that both sides compute the same h (a side that knows the pressure and one that does not,
/// giving 0, see half of it). Each half first: 0.5 (a + b) overflows for pressures near the
/// largest double, 0.5 a + 0.5 b does not.
inline double nominalPressure(double P, double Pnbr) { return 0.5 * P + 0.5 * Pnbr; }

/// The rule of a face's memory (CouplingInputs::peakPressure, the condition's peakPressure and
/// initialPeakPressure, Python's peak=): a finite pressure >= 0 [Pa]. Finiteness first: no
/// ordered comparison with a NaN, which OpenFOAM's floating-point trap would end.
inline bool isPeakPressure(double p) { return std::isfinite(p) && p >= 0.0; }

/// The gap width of a face apart from the widths both sides give [m]: their mean, as for the
/// pressure (both sides get the same h).
inline double nominalGapWidth(double w, double wNbr) { return 0.5 * w + 0.5 * wNbr; }

/// The arrays of one side's faces (n each). The neighbour's are mapped onto this side's faces.
struct CouplingInputs {
    std::size_t n = 0;
    const double* pressure = nullptr;           ///< this side's pressure [Pa] (contact mode)
    const double* pressureNbr = nullptr;        ///< the neighbour's [Pa] (contact mode)
    const double* faceTemperature = nullptr;    ///< [K] (the gap terms; may be null without gap)
    const double* faceTemperatureNbr = nullptr; ///< [K] (the gap terms; the constant-h mode's refValue)
    const double* cellTemperatureNbr = nullptr; ///< [K] the contact mode's refValue
    const double* kappa = nullptr;              ///< [W/(m K)] at the face
    const double* kappaNbr = nullptr;
    const double* deltaCoeffs = nullptr;        ///< 1/(face to cell centre) [1/m]
    const double* deltaCoeffsNbr = nullptr;
    /// The separation of faces apart [m] that each side gives (the condition's gap or gapField
    /// entry): a face apart takes their mean, nominalGapWidth. Both null: the interface's
    /// separation at first touch (InterfaceGap). Only with a gap.
    const double* gapWidth = nullptr;
    const double* gapWidthNbr = nullptr;
    /// The heaviest nominal pressure each side's face has carried so far [Pa] (the condition's
    /// memory, >= 0). Both null: no load history (every face loading).
    const double* peakPressure = nullptr;
    const double* peakPressureNbr = nullptr;
};

/// Per-face results (n each). Every array is written.
struct CouplingOutputs {
    std::vector<FaceState> state;
    std::vector<double> pressure;             ///< P [Pa]
    std::vector<double> areaFraction;         ///< A_r/A_n
    std::vector<double> contactConductance;   ///< h_c [W/(m^2 K)], +inf at complete contact
    std::vector<double> gapConductance;       ///< h_g [W/(m^2 K)] (0 without a gas)
    std::vector<double> radiativeConductance; ///< h_r [W/(m^2 K)] (0 without radiation)
    std::vector<double> conductance;          ///< h = h_c + h_g + h_r, +inf at complete contact
    std::vector<double> valueFraction;        ///< the mixed condition's w
    std::vector<double> refValue;             ///< the mixed condition's reference temperature [K]
    /// With a load history: P_max = max(P, both sides' peaks) [Pa], each face's memory after this
    /// evaluation; without one: P.
    std::vector<double> peakPressure;
    std::size_t apart = 0;                    ///< faces apart (couple(); 0 in coupleConstant)
    /// Faces in contact below their peak (unloaded or reloading; couple()).
    std::size_t unloading = 0;
    std::size_t beyondTable = 0;              ///< faces beyond the table (couple())
    /// Input that is probably a mistake (couple(); CouplingDiagnostics turns them into words):
    /// faces in contact below the table's first pressure (their values extrapolated), and the
    /// sum of their pressures [Pa];
    std::size_t belowTable = 0;
    double belowTablePressureSum = 0.0;
    /// faces whose two sides give pressures differing by more than pressureMismatchTolerance of
    /// the larger (the mean is used), and the largest such relative difference;
    std::size_t pressureMismatch = 0;
    double largestPressureMismatch = 0.0;
    /// faces apart with a gas in the gap and no gap width given (their separation is then the
    /// interface's at first touch, which may not be what is meant).
    std::size_t apartAtFirstTouch = 0;

    void resize(std::size_t n);
};

/// Two sides' pressures further apart than this, relative to the larger, are reported
/// (CouplingOutputs::pressureMismatch): a side that gives another pressure field than the other
/// (a unit, a sign, a field name) would otherwise be averaged away without a word. A mapped
/// field interpolated onto the other side's faces differs by far less on a conforming mesh.
inline constexpr double pressureMismatchTolerance = 0.05;

/// The warnings a boundary condition gives for CouplingOutputs' counts, summed over the faces
/// of every processor: one message each (empty when the count is 0), naming what was seen, the
/// likely cause and what to do. ContactInterface: the table's range and first-touch separation.
struct CouplingDiagnostics {
    std::size_t belowTable = 0;
    double belowTablePressureSum = 0.0;
    std::size_t pressureMismatch = 0;
    double largestPressureMismatch = 0.0;
    std::size_t apartAtFirstTouch = 0;
    /// Adds one processor's counts.
    void add(const CouplingOutputs& out);
    std::string belowTableMessage(const ContactInterface& iface) const;
    std::string pressureMismatchMessage() const;
    std::string apartAtFirstTouchMessage(const ContactInterface& iface) const;
};

/// Per-face memory of couple(): each face's last pressure and its table values, re-used while
/// the face's pressure holds (the common case: a pressure constant in time, or several
/// evaluations per time step). The results are the same as without it, bit for bit. A cache of
/// another size starts over.
struct CouplingCache {
    std::vector<double> pressure;
    std::vector<double> peak;
    std::vector<double> areaFraction;
    std::vector<double> conductancePerConductivity;
    std::vector<double> separation;
};

/// The contact mode, as described above. FaceError (a ParameterError naming the face) on a
/// non-finite pressure, a kappa or deltaCoeffs that is not finite and > 0, a bad temperature or
/// gap width where the gap terms need them, a peak pressure that is negative or not finite.
void couple(const ContactInterface& iface, const CouplingInputs& in, CouplingCache& cache, CouplingOutputs& out);

/// The constant-h mode (h finite and > 0): state partial, h_c = h, h_g = h_r = 0, area 1 (not
/// meaningful), w = h/(h + kappa delta), refValue = the neighbour's face temperature.
void coupleConstant(double h, const CouplingInputs& in, CouplingOutputs& out);

/// The counts and area-weighted means of a set of faces (one processor's; a caller reduces
/// the sums over processors and then calls finish()), what the boundary condition reports.
struct CouplingSummary {
    std::size_t apart = 0, partial = 0, complete = 0, beyondTable = 0;
    double area = 0.0;                 ///< sum of face areas [m^2]
    double touchingArea = 0.0;         ///< of faces partial, beyondTable or complete
    double partialArea = 0.0;          ///< of faces partial or beyondTable
    double pressureArea = 0.0;         ///< sum P a
    double peakPressureArea = 0.0;     ///< sum P_max a (CouplingOutputs::peakPressure)
    std::size_t unloading = 0;         ///< faces in contact below their peak
    double areaFractionArea = 0.0;     ///< sum (A_r/A_n) a over touching faces
    double areaFractionPartialArea = 0.0; ///< sum (A_r/A_n) a over faces in partial contact
    double hTouchingArea = 0.0;        ///< sum h_shown a over touching faces
    double hPartialArea = 0.0;         ///< sum h_shown a over faces in partial contact
    double hAllArea = 0.0;             ///< sum h_shown a over all faces
    double gapAllArea = 0.0;           ///< sum (h_g + h_r) a over all faces
    double hPartialMin = 0.0, hPartialMax = 0.0; ///< of h over faces in partial contact
    /// Adds faces with areas `magSf`; h_shown is shownConductance(...).
    void add(const CouplingOutputs& out, const double* magSf, const double* shownConductance);
};

/// What the contactConductance field shows for a face: h where finite; at complete contact
/// (h infinite: the interface adds no resistance) the conductance of the two half-cells beside
/// the face, 1/(1/(kappa1 delta1) + 1/(kappa2 delta2)): the most the mesh passes there per
/// kelvin, a finite number of the same order as its neighbours' so that averages stay
/// meaningful. contactState tells such a face apart.
/// Inline: called per face and per evaluation.
inline double shownConductance(double h, double kDelta, double kDeltaNbr)
{
    // effectiveConductance(kDelta, kDeltaNbr) of thermal/InterfaceCoupling.hpp, for kDelta and
    // kDeltaNbr that couple() has checked (finite, > 0).
    return h < std::numeric_limits<double>::infinity() ? h : kDelta * kDeltaNbr / (kDelta + kDeltaNbr);
}

} // namespace roughContact
