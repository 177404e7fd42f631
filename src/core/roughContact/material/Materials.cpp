// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/material/Materials.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <sstream>

namespace roughContact {

namespace {
void checkModulus(const std::string& what, double E)
{
    limits::requireInRange(what, E, limits::minimumModulus, limits::maximumModulus, "Pa");
}

// S_y/E within the yield strains the elasto-plastic laws are defined for (Limits.hpp).
void checkYieldStrain(const std::string& which, double Sy, double E, const char* modulusName)
{
    requirePositive(which + " yield strength S_y", Sy);
    const double strain = Sy / E;
    if (strain < limits::minimumYieldStrain || strain > limits::maximumYieldStrain) {
        std::ostringstream os;
        os << "S_y/" << modulusName << " = " << Sy << " Pa / " << E << " Pa = " << strain << " must lie within ["
           << limits::minimumYieldStrain << ", " << limits::maximumYieldStrain
           << "]: the elasto-plastic asperity laws (seed Eqs. 11-19) are fitted for yield strains of "
              "metals and hard polymers; check the units of S_y and " << modulusName;
        throw ParameterError(which + " yield strength S_y", os.str());
    }
}

} // namespace

void checkMaterial(const Material& m, const std::string& which)
{
    checkModulus(which + " Young's modulus E", m.E);
    requireFinite(which + " Poisson's ratio nu", m.nu);
    if (!(m.nu > -1.0 && m.nu < 0.5)) {
        std::ostringstream os;
        os << "must lie in (-1, 0.5), got " << m.nu;
        throw ParameterError(which + " Poisson's ratio nu", os.str());
    }
    if (m.Sy) {
        checkYieldStrain(which, *m.Sy, m.E, "E");
        if (m.elastic) {
            throw ParameterError(which + " yield strength S_y",
                                 "is given for a solid also said not to yield: give one or the other");
        }
    }
}

namespace {

void checkReducedModulus(double Eprime)
{
    limits::requireInRange("reduced modulus E'", Eprime, limits::minimumReducedModulus,
                           limits::maximumReducedModulus, "Pa");
}
} // namespace

ContactMaterials ContactMaterials::againstRigidFlat(const Material& m)
{
    checkMaterial(m, "material");
    ContactMaterials c;
    c.Eprime_ = m.E / (1.0 - m.nu * m.nu);
    checkReducedModulus(c.Eprime_);
    c.nu_ = m.nu;
    c.E_ = m.E;
    c.Sy_ = m.Sy;
    return c;
}

ContactMaterials ContactMaterials::pair(const Material& a, const Material& b, const std::string& nameA,
                                        const std::string& nameB)
{
    checkMaterial(a, nameA);
    checkMaterial(b, nameB);
    if (a.Sy.has_value() != b.Sy.has_value()) {
        const bool aMissing = !a.Sy;
        const Material& with = aMissing ? b : a;
        const std::string& missing = aMissing ? nameA : nameB;
        if (!(aMissing ? a : b).elastic) {
            std::ostringstream os;
            os << "is not given, while " << (aMissing ? nameB : nameA) << " has one (S_y = " << *with.Sy
               << " Pa): give it, or say that " << missing << " does not yield (" << notYieldingSpelling << ")";
            throw ParameterError(missing + " yield strength S_y", os.str());
        }
    }
    ContactMaterials c;
    c.Eprime_ = 1.0 / ((1.0 - a.nu * a.nu) / a.E + (1.0 - b.nu * b.nu) / b.E);
    checkReducedModulus(c.Eprime_);
    const bool bYieldsFirst = b.Sy && (!a.Sy || *b.Sy < *a.Sy);
    const Material& y = bYieldsFirst ? b : a;
    c.nu_ = y.nu;
    c.E_ = y.E;
    c.Sy_ = y.Sy;
    return c;
}

ContactMaterials ContactMaterials::fromReducedModulus(double Eprime, std::optional<double> nu,
                                                      std::optional<double> Sy)
{
    ContactMaterials c;
    checkReducedModulus(Eprime);
    c.Eprime_ = Eprime;
    if (nu) {
        requireFinite("Poisson's ratio nu", *nu);
        if (!(*nu > -1.0 && *nu < 0.5)) {
            throw ParameterError("Poisson's ratio nu", "must lie in (-1, 0.5)");
        }
        c.nu_ = nu;
        c.E_ = Eprime * (1.0 - *nu * *nu);
    }
    if (Sy) {
        // With nu, S_y/E of the yielding material; without, S_y/E' (E is then unknown).
        checkYieldStrain("material", *Sy, c.E_ ? *c.E_ : Eprime, c.E_ ? "E" : "E'");
        c.Sy_ = *Sy;
    }
    return c;
}

double ContactMaterials::yieldStrength(const std::string& model) const
{
    if (!Sy_) {
        throw ParameterError("yield strength S_y", "the model '" + model + "' needs it");
    }
    return *Sy_;
}

double ContactMaterials::poissonRatio(const std::string& model) const
{
    if (!nu_) {
        throw ParameterError("Poisson's ratio nu",
                             "the model '" + model + "' needs it (seed Eq. 12)");
    }
    return *nu_;
}

double ContactMaterials::youngModulus(const std::string& model) const
{
    if (!E_) {
        throw ParameterError("Poisson's ratio nu",
                             "the model '" + model + "' needs it to find E = E'(1-nu^2) (seed Eq. 18)");
    }
    return *E_;
}

} // namespace roughContact
