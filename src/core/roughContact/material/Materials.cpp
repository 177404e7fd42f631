#include "roughContact/material/Materials.hpp"

#include "roughContact/Error.hpp"

namespace roughContact {

namespace {
void check(const Material& m, const std::string& which)
{
    requirePositive(which + " Young's modulus E", m.E);
    requireFinite(which + " Poisson's ratio nu", m.nu);
    if (!(m.nu > -1.0 && m.nu < 0.5)) {
        throw ParameterError(which + " Poisson's ratio nu", "must lie in (-1, 0.5)");
    }
    if (m.Sy) {
        requirePositive(which + " yield strength S_y", *m.Sy);
    }
}
} // namespace

ContactMaterials ContactMaterials::againstRigidFlat(const Material& m)
{
    check(m, "material");
    ContactMaterials c;
    c.Eprime_ = m.E / (1.0 - m.nu * m.nu);
    c.nu_ = m.nu;
    c.E_ = m.E;
    c.Sy_ = m.Sy;
    return c;
}

ContactMaterials ContactMaterials::pair(const Material& a, const Material& b)
{
    check(a, "first material");
    check(b, "second material");
    ContactMaterials c;
    c.Eprime_ = 1.0 / ((1.0 - a.nu * a.nu) / a.E + (1.0 - b.nu * b.nu) / b.E);
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
    c.Eprime_ = requirePositive("reduced modulus E'", Eprime);
    if (nu) {
        requireFinite("Poisson's ratio nu", *nu);
        if (!(*nu > -1.0 && *nu < 0.5)) {
            throw ParameterError("Poisson's ratio nu", "must lie in (-1, 0.5)");
        }
        c.nu_ = nu;
        c.E_ = Eprime * (1.0 - *nu * *nu);
    }
    if (Sy) {
        c.Sy_ = requirePositive("yield strength S_y", *Sy);
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
