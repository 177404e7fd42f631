// SPDX-License-Identifier: GPL-3.0-or-later
// Greenwood-Williamson: Gaussian summits of one radius R with a spherical-asperity law
// (Greenwood & Williamson 1966; seed §3.1; docs/theory.md §4.2).
#pragma once

#include "roughContact/asperity/SphericalAsperity.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/surface/SpectralMoments.hpp"

#include <memory>
#include <string>
#include <vector>

namespace roughContact {

class ContactMaterials;
class Spectrum;

/// Summit heights z are Gaussian with standard deviation sigma_s (s = z / sigma_s standard
/// normal, density phi); the flat sits at h = d / sigma_s above the mean summit height. A summit
/// of height s carries the asperity law's area A(w, R) and force F(w, R) at w = (s - h) sigma_s
/// (docs/theory.md §4.2):
///   A_r/A_n   = eta int_h^inf A((s-h) sigma_s, R) phi(s) ds,
///   F/(A_n E') = eta/E' int_h^inf F((s-h) sigma_s, R) phi(s) ds.
/// With Hertz these are pi beta F_1(h) and (4/3) beta (sigma_s/R)^(1/2) F_3/2(h),
/// beta = eta R sigma_s. The integrals are evaluated by adaptive Gauss-Kronrod quadrature,
/// split where a Jackson-Green summit reaches 1.9 w_c and complete contact (a/R = 1).
class GreenwoodWilliamson final : public ContactModel {
public:
    /// summits from McCool (or given); nominalArea A_n [m^2]; Eprime [Pa]; asperity the
    /// spherical-asperity law (Hertz, JacksonGreen, ...); name the name users select it by.
    GreenwoodWilliamson(const SummitParameters& summits, double nominalArea, double Eprime,
                        std::shared_ptr<const SphericalAsperity> asperity, std::string name);

    /// McCool's parameters of the spectrum, A_n = L^2, E' of the materials; Hertz asperities
    /// ("greenwoodWilliamson") or Jackson-Green ones ("greenwoodWilliamsonJG", which needs
    /// materials.poissonRatio, youngModulus and yieldStrength).
    static std::unique_ptr<GreenwoodWilliamson> fromSpectrum(const Spectrum& spectrum,
                                                             const ContactMaterials& materials,
                                                             bool jacksonGreen);

    std::string name() const override { return name_; }
    /// A_r/A_n at the load F/(A_n E'), capped at 1 (the GW integral itself exceeds 1 at heavy
    /// loads: summits are independent and their areas simply add). load 0 gives 0. Above the
    /// largest load the summits carry: 1 when their areas at complete contact cover A_n,
    /// ParameterError otherwise.
    double areaFraction(double load) const override;

    /// Separation h = d / sigma_s at which F/(A_n E') = load (> 0; bracketed root find).
    /// ParameterError when the load exceeds the largest the summits carry (an asperity law
    /// whose force stops growing at complete contact, as Jackson-Green's, saturates).
    double separation(double load) const;
    /// A_r/A_n at separation h, not capped.
    double areaFractionAt(double h) const;
    /// F/(A_n E') at separation h.
    double loadAt(double h) const;

    const SummitParameters& summits() const noexcept { return summits_; }
    double nominalArea() const noexcept { return An_; }
    double reducedModulus() const noexcept { return Eprime_; }
    const SphericalAsperity& asperityModel() const noexcept { return *asperity_; }

private:
    enum class Quantity { area, force };
    /// ln of eta int_0^inf Q(t sigma_s, R) phi(t + h) dt (Q the area or the force), computed
    /// with the Gaussian factor phi(max(h, 0)) taken out so that nothing underflows.
    double logIntegral(Quantity q, double h) const;
    /// separation(); when the load is unreachable and saturated != nullptr, returns NaN and
    /// stores in *saturated a separation at which the load has saturated.
    double solveSeparation(double load, double* saturated) const;

    SummitParameters summits_;
    double An_;
    double Eprime_;
    std::shared_ptr<const SphericalAsperity> asperity_;
    std::string name_;
    /// Interferences t = w / sigma_s where the asperity law has a jump or a kink (sorted).
    std::vector<double> breaks_;
};

} // namespace roughContact
