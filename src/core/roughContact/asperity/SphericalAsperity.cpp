// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/asperity/SphericalAsperity.hpp"

#include "roughContact/surface/Spectrum.hpp"

#include <limits>

namespace roughContact {

Level Level::of(double frequency, double amplitude)
{
    return Level{frequency, amplitude, asperityDensity(frequency), asperityRadius(frequency, amplitude)};
}

double SphericalAsperity::areaRatio(double pbar, const Level& level) const
{
    return level.density * areaAtForce(pbar / level.density, level.radius);
}

double SphericalAsperity::forceBeyondArea(double, double) const
{
    return std::numeric_limits<double>::infinity();
}

double SphericalAsperity::completeContactPressure(const Level& level) const
{
    return level.density * forceBeyondArea(1.0 / level.density, level.radius);
}

} // namespace roughContact
