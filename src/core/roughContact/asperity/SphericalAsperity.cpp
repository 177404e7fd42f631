#include "roughContact/asperity/SphericalAsperity.hpp"

#include "roughContact/surface/Spectrum.hpp"

namespace roughContact {

Level Level::of(double frequency, double amplitude)
{
    return Level{frequency, amplitude, asperityDensity(frequency), asperityRadius(frequency, amplitude)};
}

double SphericalAsperity::areaRatio(double pbar, const Level& level) const
{
    return level.density * areaAtForce(pbar / level.density, level.radius);
}

} // namespace roughContact
