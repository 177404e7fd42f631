// SPDX-License-Identifier: GPL-3.0-or-later
// The contact conductance laws a user selects by name: the one list of their names, what each
// needs, and a factory. Each law turns the nominal pressure P into h_c/k_s [1/m]; the real
// contact area is the contact model's business (the multi-scale model's in the boundary
// condition), the conductance the law's. docs/validation/fidelity.md measures every law against
// the exact (boundary-element) conductance; docs/models.md quotes the result.
//
//   jacksonBhavnaniFerguson  the multi-scale constriction resistances in series, each level's
//                            spots in flux tubes (ConstrictionConductance.hpp; Jackson,
//                            Bhavnani & Ferguson, J. Heat Transfer 130 (2008) 081301). Needs a
//                            multi-scale model.
//   multiscaleBarber         Barber's relation on the elastic energy of the multi-scale levels
//                            (MultiscaleBarber.hpp). Needs a multi-scale model and its spectrum.
//   persson                  Persson's theory's conductance (models/Persson.hpp: Barber's
//                            relation with Persson's mean separation). Needs the spectrum and E'.
//   mikic                    Mikic's elastic correlation (Mikic.hpp). Needs sigma, m and E'.
//   cooperMikicYovanovich    the Cooper-Mikic-Yovanovich plastic correlation
//                            (CooperMikicYovanovich.hpp). Needs sigma, m and the microhardness
//                            H_c, given or from Vickers coefficients (Microhardness.hpp).
//   fittedElastoPlastic      Mikic's elastic form and the CMY plastic-spot geometry, refitted to
//                            the exact conductance and blended (FittedElastoPlastic.hpp). Needs
//                            sigma, m, E' and, for the plastic branch, the cap H and the
//                            line-scan spectrum (its bandwidth ratio W; its finest octave's
//                            Hurst exponent for the unloading branch); takes a measured
//                            surface's heights' skewness where it is more than chance.
#pragma once

#include "roughContact/material/Materials.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/thermal/Microhardness.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace roughContact {

class MultiscaleModel;
class Spectrum;

class ConductanceLaw {
public:
    virtual ~ConductanceLaw() = default;
    /// The name users select it by (conductanceLawNames()).
    virtual std::string name() const = 0;
    /// h_c/k_s [1/m] at the nominal pressure P [Pa] (finite, >= 0; 0 gives 0). +infinity where
    /// the law says the surfaces are in complete contact (nothing constricts the flow).
    virtual double perConductivity(double P) const = 0;
    /// The mean-plane separation Y [m] of the two surfaces at the nominal pressure P [Pa]
    /// (finite, >= 0 where defined; +inf at P = 0), the gap a gas-gap conductance k_g/(Y + M)
    /// needs; NaN when the law defines none (this default: mikic, cooperMikicYovanovich,
    /// jacksonBhavnaniFerguson). persson: PerssonModel::meanSeparation(P/E'); multiscaleBarber:
    /// MultiscaleBarber::meanSeparation(P/E'), from the energy its conductance differentiates,
    /// NaN when its model does not reach complete contact. Both are Barber-consistent with
    /// perConductivity: h_c/k_s = -(1/E') dP/dY.
    virtual double meanSeparation(double P) const;
    /// True when the law has an unloading branch: below the heaviest pressure a joint has carried
    /// it conducts unloadingFactor times its loading value (fittedElastoPlastic with a cap,
    /// docs/theory.md §5.7c). false (this default): h follows the pressure of the moment.
    virtual bool unloads() const { return false; }
    /// The factor on perConductivity(P) at the nominal pressure P [Pa] of a joint that has carried
    /// peak [Pa]: 1 at P >= peak and for a law without an unloading branch (this default).
    virtual double unloadingFactor(double P, double peak) const;
};

/// What the laws are built from; each law takes what it needs and refuses (ParameterError
/// naming the entry) to be built without it.
struct ConductanceLawInputs {
    const MultiscaleModel* multiscale = nullptr; ///< jacksonBhavnaniFerguson
    const Spectrum* spectrum = nullptr;           ///< persson, fittedElastoPlastic (with a cap): the line-scan spectrum
    std::optional<SurfaceRoughness> roughness;    ///< mikic, cooperMikicYovanovich: combined
    double Eprime = 0.0;                          ///< E' [Pa]: mikic, persson
    std::optional<double> microhardness;          ///< H_c [Pa]: cooperMikicYovanovich
    std::optional<VickersCoefficients> vickers;   ///< or H_c from these
    /// fittedElastoPlastic: the plastic cap H [Pa] (the microhardness where given, else 2.84 S_y
    /// of the yielding material); none: its elastic branch alone.
    std::optional<double> hardness;
    /// fittedElastoPlastic: the heights' skewness with its spread (equivalentSkewness of a measured
    /// profile or map), taken with chance's share out (shrunkSkewness); none: Gaussian heights.
    /// The other laws assume Gaussian heights and take none.
    std::optional<HeightSkewness> skewness;
};

/// The cap H [Pa] of the laws that take one (ConductanceLawInputs::hardness): the microhardness
/// where given, else 2.84 S_y of the yielding material, else none (elastic). The one rule for the
/// condition, the CLI and the check.
std::optional<double> conductanceLawHardness(std::optional<double> microhardness, const ContactMaterials& materials);

/// Every law's name, in the order the documentation lists them.
const std::vector<std::string>& conductanceLawNames();
/// The law the boundary condition and the CLI use unless told otherwise (docs/models.md says why).
const std::string& defaultConductanceLaw();
/// True for a name in conductanceLawNames().
bool isConductanceLaw(const std::string& name);
/// True for the laws that take the surfaces' sigma and m (ConductanceLawInputs::roughness), which
/// callers compute only for them (it reads the surface files again).
bool conductanceLawNeedsRoughness(const std::string& name);
/// The law `name` built from `inputs`. ParameterError for an unknown name (listing the known
/// ones) or a missing input.
std::unique_ptr<ConductanceLaw> makeConductanceLaw(const std::string& name, const ConductanceLawInputs& inputs);

} // namespace roughContact
