// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/ModelFactory.hpp"

#include "roughContact/Limits.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/asperity/Hertz.hpp"
#include "roughContact/asperity/JacksonGreen.hpp"
#include "roughContact/asperity/JohnsonGreenwoodHigginson.hpp"
#include "roughContact/asperity/Truncation.hpp"
#include "roughContact/models/GreenwoodWilliamson.hpp"
#include "roughContact/models/MajumdarBhushan.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/Roughness.hpp"

#include <algorithm>

namespace roughContact {

const std::vector<std::string>& multiscaleModelNames()
{
    static const std::vector<std::string> names{"hertz", "jgh", "jghConsistent", "jacksonGreen",
                                                "truncation"};
    return names;
}

const std::vector<std::string>& modelNames()
{
    static const std::vector<std::string> names{
        "hertz",      "jgh", "jghConsistent", "jacksonGreen", "truncation", "greenwoodWilliamson",
        "greenwoodWilliamsonJG", "majumdarBhushan", "persson"};
    return names;
}

bool isMultiscaleModel(const std::string& name)
{
    const auto& n = multiscaleModelNames();
    return std::find(n.begin(), n.end(), name) != n.end();
}

namespace {
[[noreturn]] void unknown(const std::string& name, const std::vector<std::string>& choices)
{
    std::string list;
    for (const auto& c : choices) {
        list += (list.empty() ? "" : ", ") + c;
    }
    throw ParameterError("model", "unknown model '" + name + "'; choose one of: " + list);
}
} // namespace

std::shared_ptr<const AsperityModel> makeAsperityModel(const std::string& name,
                                                       const ContactMaterials& m)
{
    const double Ep = m.reducedModulus();
    if (name == "hertz") {
        return std::make_shared<Hertz>(Ep);
    }
    if (name == "jgh") {
        return std::make_shared<JohnsonGreenwoodHigginson>(Ep, JohnsonGreenwoodHigginson::Form::seed);
    }
    if (name == "jghConsistent") {
        return std::make_shared<JohnsonGreenwoodHigginson>(Ep, JohnsonGreenwoodHigginson::Form::consistent);
    }
    if (name == "jacksonGreen") {
        return std::make_shared<JacksonGreen>(Ep, m.poissonRatio(name), m.youngModulus(name),
                                              m.yieldStrength(name));
    }
    if (name == "truncation") {
        return std::make_shared<Truncation>(Ep, m.poissonRatio(name), m.yieldStrength(name));
    }
    unknown(name, multiscaleModelNames());
}

std::unique_ptr<ContactModel> makeContactModel(const std::string& name, const Spectrum& spectrum,
                                               const ContactMaterials& m, const ModelOptions& options)
{
    if (isMultiscaleModel(name)) { // the multi-scale model checks the surface itself
        return std::make_unique<MultiscaleModel>(spectrum, m.reducedModulus(), makeAsperityModel(name, m));
    }
    if (name == "greenwoodWilliamson" || name == "greenwoodWilliamsonJG" || name == "majumdarBhushan") {
        requireRoughness(spectrum);
    }
    if (name == "greenwoodWilliamson" || name == "greenwoodWilliamsonJG") {
        return GreenwoodWilliamson::fromSpectrum(spectrum, m, name == "greenwoodWilliamsonJG");
    }
    if (name == "majumdarBhushan") {
        const FractalParameters fp = options.fractal ? *options.fractal : fitFractal(spectrum);
        return std::make_unique<MajumdarBhushan>(fp, spectrum.nominalArea(), m.reducedModulus(),
                                                 m.yieldStrength(name));
    }
    if (name == "persson") { // Persson's theory on the spectrum's isotropic 2-D conversion
        return std::make_unique<PerssonModel>(spectrum, m.reducedModulus());
    }
    unknown(name, modelNames());
}

} // namespace roughContact
