// SPDX-License-Identifier: GPL-3.0-or-later
// Every contact model by the name users select it by.
#pragma once

#include "roughContact/asperity/AsperityModel.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ContactModel.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace roughContact {

struct ModelOptions {
    /// Majumdar-Bhushan D and G; fitted to the spectrum's PSD (all levels) when unset.
    std::optional<FractalParameters> fractal;
};

/// The multi-scale models (hertz, jgh, jghConsistent, jacksonGreen, truncation).
const std::vector<std::string>& multiscaleModelNames();
/// Those and the comparison models (greenwoodWilliamson, greenwoodWilliamsonJG,
/// majumdarBhushan, persson).
const std::vector<std::string>& modelNames();
bool isMultiscaleModel(const std::string& name);

/// The asperity law of a multi-scale model. ParameterError for an unknown name or a
/// missing material property (S_y, nu).
std::shared_ptr<const AsperityModel> makeAsperityModel(const std::string& name,
                                                       const ContactMaterials& materials);

/// Any model by name, built once for this surface and these materials.
std::unique_ptr<ContactModel> makeContactModel(const std::string& name, const Spectrum& spectrum,
                                               const ContactMaterials& materials,
                                               const ModelOptions& options = {});

} // namespace roughContact
