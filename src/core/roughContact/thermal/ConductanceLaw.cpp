// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/thermal/ConductanceLaw.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"
#include "roughContact/thermal/CooperMikicYovanovich.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"
#include "roughContact/thermal/Mikic.hpp"
#include "roughContact/thermal/MultiscaleBarber.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roughContact {

namespace {

double checkPressure(double P)
{
    requireFinite("contact pressure P", P);
    if (P < 0.0) {
        throw ParameterError("contact pressure P", "must be >= 0, got " + std::to_string(P));
    }
    return P;
}

class JacksonBhavnaniFerguson final : public ConductanceLaw {
public:
    explicit JacksonBhavnaniFerguson(const MultiscaleModel& model) : model_(model) {}
    std::string name() const override { return "jacksonBhavnaniFerguson"; }
    double perConductivity(double P) const override
    {
        return constrictionConductancePerConductivity(model_, checkPressure(P) / model_.reducedModulus());
    }

private:
    const MultiscaleModel& model_;
};

class MultiscaleBarberLaw final : public ConductanceLaw {
public:
    MultiscaleBarberLaw(const MultiscaleModel& model, const Spectrum& spectrum) : law_(model, spectrum), model_(model)
    {
    }
    std::string name() const override { return "multiscaleBarber"; }
    double perConductivity(double P) const override
    {
        return law_.conductancePerConductivity(checkPressure(P) / model_.reducedModulus());
    }
    double meanSeparation(double P) const override
    {
        return law_.meanSeparation(checkPressure(P) / model_.reducedModulus());
    }

private:
    MultiscaleBarber law_;
    const MultiscaleModel& model_;
};

class MikicLaw final : public ConductanceLaw {
public:
    MikicLaw(const SurfaceRoughness& r, double Eprime) : r_(r), Eprime_(Eprime)
    {
        mikicConductancePerConductivity(0.0, r_, Eprime_); // checks the inputs once
    }
    std::string name() const override { return "mikic"; }
    double perConductivity(double P) const override { return mikicConductancePerConductivity(P, r_, Eprime_); }

private:
    SurfaceRoughness r_;
    double Eprime_;
};

class CooperMikicYovanovichLaw final : public ConductanceLaw {
public:
    CooperMikicYovanovichLaw(const SurfaceRoughness& r, std::optional<double> Hc,
                             std::optional<VickersCoefficients> vickers)
        : r_(r), Hc_(Hc), vickers_(vickers)
    {
        checkRoughness(r_);
        if (Hc_) {
            limits::requireInRange("microhardness H_c", *Hc_, limits::minimumHardness, limits::maximumHardness, "Pa");
        } else {
            checkVickersCoefficients(*vickers_);
        }
    }
    std::string name() const override { return "cooperMikicYovanovich"; }
    double perConductivity(double P) const override
    {
        return Hc_ ? cooperMikicYovanovichConductancePerConductivity(P, r_, *Hc_)
                   : cooperMikicYovanovichConductancePerConductivity(P, r_, *vickers_);
    }

private:
    SurfaceRoughness r_;
    std::optional<double> Hc_;
    std::optional<VickersCoefficients> vickers_;
};

class FittedElastoPlasticLaw final : public ConductanceLaw {
public:
    // W spaces the plastic spots and sets the elastic growth's rate beyond x_g (beta_2(W));
    // without a spectrum (then no cap either) the pivot stands in: beta_2 = B_0.
    // The skewness, chance's share taken out (shrunkSkewness); none: Gaussian heights.
    FittedElastoPlasticLaw(const SurfaceRoughness& r, const Spectrum* spectrum, double Eprime,
                           std::optional<double> H, const std::optional<HeightSkewness>& skewness)
        : r_(r),
          W_(spectrum != nullptr ? spectralBandwidthRatio(*spectrum) : FittedElastoPlasticConstants{}.heavyLoadBandwidthPivot),
          Eprime_(Eprime), H_(H),
          s_(skewness ? shrunkSkewness(*skewness) : 0.0),
          s1_(spectrum != nullptr ? std::optional<double>(firstLevelShare(*spectrum)) : std::nullopt),
          Hf_(spectrum != nullptr ? fineHurstExponent(*spectrum) : std::nullopt)
    {
        fittedElastoPlasticConductancePerConductivity(0.0, r_, W_, Eprime_, H_, s_, s1_); // checks the inputs once
    }
    std::string name() const override { return "fittedElastoPlastic"; }
    double perConductivity(double P) const override
    {
        return fittedElastoPlasticConductancePerConductivity(P, r_, W_, Eprime_, H_, s_, s1_);
    }
    bool unloads() const override { return H_.has_value(); }
    double unloadingFactor(double P, double peak) const override
    {
        // The branch over the loading value (1 where that is 0 or infinite: nothing to scale),
        // the law evaluated once at P.
        const FittedUnloading h = fittedElastoPlasticUnloading(P, peak, r_, W_, Eprime_, H_, s_, s1_, Hf_);
        return h.loading > 0.0 && std::isfinite(h.loading) ? h.unloading / h.loading : 1.0;
    }

private:
    SurfaceRoughness r_;
    double W_;
    double Eprime_;
    std::optional<double> H_;
    double s_;
    std::optional<double> s1_; // the spectrum's first level's share; none without a spectrum: no light-load factor
    // The Hurst exponent of the spectrum's finest octave; none without a spectrum (or fewer than
    // three levels there): the unloading branch takes H_0, where neither of its terms acts.
    std::optional<double> Hf_;
};

class PerssonLaw final : public ConductanceLaw {
public:
    PerssonLaw(const Spectrum& spectrum, double Eprime) : model_(spectrum, Eprime) {}
    std::string name() const override { return "persson"; }
    double perConductivity(double P) const override
    {
        return model_.conductancePerConductivity(checkPressure(P) / model_.reducedModulus());
    }
    double meanSeparation(double P) const override
    {
        return model_.meanSeparation(checkPressure(P) / model_.reducedModulus());
    }

private:
    PerssonModel model_;
};

const SurfaceRoughness& needRoughness(const std::string& law, const ConductanceLawInputs& in)
{
    if (!in.roughness) {
        throw ParameterError(law, "needs the surfaces' rms height sigma and mean absolute slope m");
    }
    return *in.roughness;
}

} // namespace

double ConductanceLaw::meanSeparation(double P) const
{
    checkPressure(P);
    return std::numeric_limits<double>::quiet_NaN();
}

double ConductanceLaw::unloadingFactor(double P, double peak) const
{
    checkPressure(P);
    requireFinite("peak pressure P_max", peak);
    if (peak < 0.0) {
        throw ParameterError("peak pressure P_max", "must be >= 0, got " + std::to_string(peak));
    }
    return 1.0;
}

std::optional<double> conductanceLawHardness(std::optional<double> microhardness, const ContactMaterials& materials)
{
    if (microhardness) {
        return microhardness;
    }
    if (materials.hasYieldStrength()) {
        return materials.hardness("conductance law");
    }
    return std::nullopt;
}

const std::vector<std::string>& conductanceLawNames()
{
    static const std::vector<std::string> names = {"jacksonBhavnaniFerguson", "multiscaleBarber", "persson",
                                                   "mikic", "cooperMikicYovanovich", "fittedElastoPlastic"};
    return names;
}

const std::string& defaultConductanceLaw()
{
    static const std::string name = "fittedElastoPlastic";
    return name;
}

bool isConductanceLaw(const std::string& name)
{
    const auto& n = conductanceLawNames();
    return std::find(n.begin(), n.end(), name) != n.end();
}

bool conductanceLawNeedsRoughness(const std::string& name)
{
    return name == "mikic" || name == "cooperMikicYovanovich" || name == "fittedElastoPlastic";
}

std::unique_ptr<ConductanceLaw> makeConductanceLaw(const std::string& name, const ConductanceLawInputs& in)
{
    if (name == "jacksonBhavnaniFerguson") {
        if (in.multiscale == nullptr) {
            throw ParameterError(name, "needs a multi-scale contact model (hertz, jgh, jghConsistent, "
                                       "jacksonGreen or truncation)");
        }
        return std::make_unique<JacksonBhavnaniFerguson>(*in.multiscale);
    }
    if (name == "multiscaleBarber") {
        if (in.multiscale == nullptr || in.spectrum == nullptr) {
            throw ParameterError(name, "needs a multi-scale contact model (hertz, jgh, jghConsistent, "
                                       "jacksonGreen or truncation) and its spectrum");
        }
        return std::make_unique<MultiscaleBarberLaw>(*in.multiscale, *in.spectrum);
    }
    if (name == "persson") {
        if (in.spectrum == nullptr) {
            throw ParameterError(name, "needs the surface's line-scan spectrum");
        }
        return std::make_unique<PerssonLaw>(*in.spectrum, in.Eprime);
    }
    if (name == "mikic") {
        return std::make_unique<MikicLaw>(needRoughness(name, in), in.Eprime);
    }
    if (name == "cooperMikicYovanovich") {
        if (!in.microhardness && !in.vickers) {
            throw ParameterError(name, "needs the microhardness H_c, or the Vickers coefficients c1, c2 to "
                                       "compute it from");
        }
        if (in.microhardness && in.vickers) {
            throw ParameterError(name, "give the microhardness H_c or the Vickers coefficients, not both");
        }
        return std::make_unique<CooperMikicYovanovichLaw>(needRoughness(name, in), in.microhardness, in.vickers);
    }
    if (name == "fittedElastoPlastic") {
        if (in.hardness && in.spectrum == nullptr) {
            throw ParameterError(
                name, "needs the surfaces' line-scan spectrum (its bandwidth ratio W) beside sigma "
                      "and m for its plastic branch (the cap H)");
        }
        return std::make_unique<FittedElastoPlasticLaw>(needRoughness(name, in), in.spectrum, in.Eprime,
                                                        in.hardness, in.skewness);
    }
    std::string known;
    for (const auto& n : conductanceLawNames()) {
        known += (known.empty() ? "" : ", ") + n;
    }
    throw ParameterError("conductance law", "unknown law '" + name + "'; known: " + known);
}

} // namespace roughContact
