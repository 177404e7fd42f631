// SPDX-License-Identifier: GPL-3.0-or-later
// Elastic and plastic properties of a contact pair (docs/theory.md §1.7, seed Table 1).
#pragma once

#include <optional>
#include <string>

namespace roughContact {

/// One solid: Young's modulus E [Pa], Poisson's ratio nu, yield strength S_y [Pa] (optional:
/// only the elasto-plastic models need it), and whether it is said not to yield.
struct Material {
    double E = 0.0;
    double nu = 0.0;
    std::optional<double> Sy;
    /// Said explicitly not to yield (no S_y: a ceramic, a hard coating): in a pair where the other
    /// solid has a yield strength, only that one yields. Without it a one-sided S_y is an error
    /// (ContactMaterials::pair), as a yield strength left off one side by mistake would otherwise
    /// be taken silently and the other side's would govern.
    bool elastic = false;
};

/// How each front-end says that a solid does not yield (Material::elastic), for the messages.
inline constexpr const char* notYieldingSpelling =
    "'Sy none;' in a dictionary, none in --Sy, Material(..., elastic=True) in Python";

/// Throws ParameterError naming `which` and the property unless E, nu and S_y lie within what
/// the core accepts (Limits.hpp): E in [1e3, 1e13] Pa, nu in (-1, 0.5), S_y/E in [1e-6, 0.1];
/// and when S_y is given for a solid said not to yield.
void checkMaterial(const Material& m, const std::string& which);

/// The flow pressure of a perfectly plastic contact spot over the yield strength: H = 2.84 S_y
/// (seed §3.1, the truncation model's and Majumdar-Bhushan's hardness). The one place of the
/// coefficient: the truncation law, Majumdar-Bhushan, the boundary-element cap
/// (hardnessFromYield) and the CMY microhardness (--hardness-from-yield) all take it from here.
inline constexpr double hardnessPerYieldStrength = 2.84;

/// What the contact models need of the pair:
/// - E' from 1/E' = (1-nu1^2)/E1 + (1-nu2^2)/E2 (docs/theory.md §1.7),
/// - the yield strength S_y, Poisson's ratio nu and modulus E of the material that yields
///   first (seed Eq. 12: C uses "the Poisson ratio of the material that yields first";
///   Eq. 18: e_y = S_y/E).
class ContactMaterials {
public:
    /// A rough solid against a rigid flat: E' = E/(1-nu^2).
    static ContactMaterials againstRigidFlat(const Material& m);
    /// Two solids, named in the errors as `nameA` and `nameB` (side1, side2 of a contact entry);
    /// the one with the lower S_y yields first (the first when neither has S_y). S_y given for one
    /// solid only is a ParameterError naming the other, unless that one is said not to yield
    /// (Material::elastic).
    static ContactMaterials pair(const Material& a, const Material& b, const std::string& nameA = "first material",
                                 const std::string& nameB = "second material");
    /// E' given directly. nu (optional) of the yielding material; its E is taken as
    /// E'(1-nu^2), the rigid-flat reading of the seed's Table 1 (E' = 200 GPa, nu = 0.32).
    static ContactMaterials fromReducedModulus(double Eprime, std::optional<double> nu,
                                               std::optional<double> Sy);

    double reducedModulus() const noexcept { return Eprime_; }
    bool hasYieldStrength() const noexcept { return Sy_.has_value(); }
    bool hasPoissonRatio() const noexcept { return nu_.has_value(); }
    /// Throw ParameterError naming `model` when the property is missing.
    double yieldStrength(const std::string& model) const;
    double poissonRatio(const std::string& model) const;
    /// H = hardnessPerYieldStrength S_y of the yielding material [Pa]; ParameterError naming
    /// `model` without S_y.
    double hardness(const std::string& model) const { return hardnessPerYieldStrength * yieldStrength(model); }
    /// Young's modulus of the yielding material (seed Eq. 18).
    double youngModulus(const std::string& model) const;

private:
    double Eprime_ = 0.0;
    std::optional<double> nu_;
    std::optional<double> E_;
    std::optional<double> Sy_;
};

} // namespace roughContact
