// SPDX-License-Identifier: GPL-3.0-or-later
// The regime of an interface, said out loud: at the two ends of its pressure
// range, the load p/E', the load over the rms gradient p/(E' h') (the axis on which rough
// surfaces of different roughness compare: the elastic A_r/A_n is about 2 p/(E' h') at light
// load), the plastic load P/H, and the surface's plasticity index; with the measured accuracy
// band of the chosen law there (MeasuredAccuracy.hpp).
//
// h' is the areal rms gradient sqrt(2 m2) of an isotropic surface whose line scans have the rms
// slope sqrt(m2) (SpectralMoments.hpp). The plasticity index is Greenwood & Williamson's
// psi = (E'/H) sqrt(sigma_s/R) (Proc. R. Soc. A 295 (1966) 300, with H for the flow pressure;
// the equation number not checked: docs/theory.md §5.15), sigma_s and R McCool's summit parameters of the spectrum (SpectralMoments.hpp):
// below about 0.6 the summits stay elastic, above 1 they flow. For a multi-scale spectrum it
// depends on the finest level kept (sqrt(sigma_s/R) grows with the slopes); H/(E' h') is printed
// beside it as the scale-free measure (the engineering range's pairs: 0.03 to 0.3).
#pragma once

#include "roughContact/surface/Roughness.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace roughContact {

class ContactMaterials;
class Spectrum;

struct RegimeAt {
    double pressure = 0.0;            ///< P [Pa]
    double load = 0.0;                ///< P/E'
    double loadPerGradient = 0.0;     ///< P/(E' h')
    std::optional<double> perHardness; ///< P/H where there is a hardness
    std::optional<AccuracyBand> band; ///< the chosen law's measured band there
};

struct InterfaceRegime {
    double reducedModulus = 0.0;               ///< E' [Pa]
    double gradient = 0.0;                     ///< h'
    std::optional<double> hardness;            ///< H [Pa]
    std::optional<double> plasticityIndex;     ///< psi, with a hardness
    /// The heights' skewness (equivalentSkewness: a measured profile's or map's; none for a
    /// spectrum): the law fittedElastoPlastic takes it with chance's share out (shrunkSkewness),
    /// every other law and model assumes 0 (Gaussian heights); the log says which.
    std::optional<HeightSkewness> skewness;
    /// The spectrum's first level's share s1 of the heights' variance (firstLevelShare): the law
    /// fittedElastoPlastic's light-load factor below p/(E' h') = 0.01 takes it; the log says it,
    /// with the factor it gives at p/(E' h') = 1e-4, for that law.
    std::optional<double> firstLevelShare;
    /// The Hurst exponent H_f of the spectrum's finest octave (fineHurstExponent): the law
    /// fittedElastoPlastic's unloading branch takes it; the log says it for that law with a cap.
    std::optional<double> fineHurst;
    std::string law;                           ///< the chosen law ("boundaryElement (exact)" for the exact model)
    std::string areaModel;                     ///< the area model
    bool capped = false;                       ///< compared with the capped reference
    RegimeAt low;                              ///< at the range's lowest pressure
    RegimeAt high;                             ///< at its highest

    /// Lines for a log: the surface and materials (describeSurface), then the regime at both
    /// ends and the band of the law there.
    std::string describe() const;

    /// One line: h', H, H/(E' h'), the plasticity index, the heights' skewness, s1 and H_f as the
    /// law takes them.
    std::string describeSurface() const;

    /// The regime at the pressure P [Pa] (> 0), and the chosen law's band there.
    RegimeAt at(double P) const;

    /// A line a pressure: "at P Pa (label): p/E' = ..., p/(E' h') = ..., P/H = ...; the law's
    /// band", for the pressures a run or the faces carry (labels such as "min", "mean", "max";
    /// none: the pressure alone). No line for a pressure <= 0.
    std::string describeAt(const std::vector<std::pair<std::string, double>>& labelledPressures) const;

    /// The default law's unloading branch's measured band for joints loaded to peaks from
    /// peakMin to peakMax [Pa] (measuredUnloadingAccuracy at their p/(E' h')); none where not
    /// measured. Only the band: whether the interface unloads by the branch is the caller's.
    std::optional<UnloadingAccuracyBand> unloadingBand(double peakMin, double peakMax) const;
    /// That band as a line (describeUnloadingAccuracy).
    std::string describeUnloading(double peakMin, double peakMax) const;

private:
    std::string describeLine(const RegimeAt& r, const std::string& label) const;
};

/// What is known of the accuracy of the gap's gas and radiation conductance: no measurement or
/// reference solution has been held to them (docs/gapConductance.md), and the log says so in
/// these words beside their share of h.
inline constexpr const char* gapConductanceAccuracy = "not validated";

/// Whether a law on an area model is held to the capped reference: when the model caps the
/// pressure (jacksonGreen, truncation), or when the law has a plastic branch (fittedElastoPlastic,
/// cooperMikicYovanovich) and a cap to use. The one rule for the condition and the CLI.
bool heldToCappedReference(const std::string& areaModel, const std::string& law, bool hasCap);

/// The regime of an interface on `surface` (its spectrum) between `materials` at the pressures
/// Plow and Phigh [Pa], with the hardness H [Pa] (none: elastic; compared with the elastic
/// reference), the chosen law and area model (a multi-scale model's name, or boundaryElement,
/// whose answer is the exact one). capped: the area model limits the pressure (jacksonGreen,
/// truncation), so the law is held to the capped reference.
InterfaceRegime interfaceRegime(const Spectrum& surface, double Eprime, std::optional<double> hardness,
                                const std::string& law, const std::string& areaModel, bool capped, double Plow,
                                double Phigh);

} // namespace roughContact
