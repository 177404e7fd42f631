// SPDX-License-Identifier: GPL-3.0-or-later
// The regime at the pressures an interface's faces carry, for the boundary condition's log: the
// min, mean and max pressure of the faces in contact, p/(E' h') and P/H there and the chosen
// law's measured band (InterfaceRegime::describeAt), and h split into its contact, gas and
// radiation parts with what is known of each one's accuracy; with a load history, the faces
// below their peak and the measured band of the unloading they follow. Said at the first
// evaluation with a face in contact, again whenever the min, mean or max has moved by more than
// a factor of two since it was last said, and when faces start or stop being below their peak
// (docs/checking.md, "The regime at your pressures").
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace roughContact {

class ContactInterface;
struct CouplingOutputs;

/// One processor's faces, as sums a parallel run reduces (min, max, sums) before the log.
struct FaceSums {
    double pressureMin = std::numeric_limits<double>::infinity(); ///< of the faces in contact [Pa]
    double pressureMax = 0.0;
    double pressureSum = 0.0;   ///< of P * pressureScale: no overflow for any finite pressures
    std::size_t inContact = 0;  ///< faces with P > 0 (partial, complete or beyond the table)
    std::size_t complete = 0;   ///< faces in complete contact (h_c infinite: not in the means)
    std::size_t faces = 0;      ///< every face (the means of h's parts are over those not complete)
    double contactSum = 0.0;    ///< sums of h_c, h_g, h_r [W/(m^2 K)] over the faces not complete
    double gasSum = 0.0;
    double radiationSum = 0.0;
    /// Faces in contact below their peak (CouplingOutputs::peakPressure: unloaded or reloading;
    /// by more than 1e-9 of it, not a held load's round-off), their least and largest peak [Pa]
    /// and their least P/P_max.
    std::size_t unloading = 0;
    double unloadingPeakMin = std::numeric_limits<double>::infinity();
    double unloadingPeakMax = 0.0;
    double unloadingFractionMin = 1.0;

    /// pressureSum's scale, 2^-64: a sum of pressures up to the largest double stays finite.
    static constexpr double pressureScale = 1.0 / 18446744073709551616.0;

    /// Adds the faces of one evaluation (couple()'s outputs): addPressures and addConductances.
    void add(const CouplingOutputs& out);
    /// Their count and pressures alone (faces, inContact, the pressures, and those below their
    /// peak): what decides whether the log is due, at every evaluation.
    void addPressures(const CouplingOutputs& out);
    /// Their h's parts alone (complete and the sums of h_c, h_g, h_r): what the log says, only
    /// when it is due.
    void addConductances(const CouplingOutputs& out);

    /// The mean pressure of the faces in contact [Pa] (0 with none).
    double meanPressure() const;

    /// The pressures the condition's check takes by default (checkPressures unset): the min, mean
    /// and max of the faces in contact, each kept when more than 1 % from the one before; none
    /// without a face in contact.
    std::vector<double> pressuresToCheck() const;
};

/// When and what the log says of the faces' regime; one per patch.
class FaceRegimeLog {
public:
    /// factor: how far (a ratio) the min, mean or max pressure must move before it is said again.
    explicit FaceRegimeLog(double factor = 2.0);

    /// The lines to log for the faces of every processor `all`, or "" when the pressures have not
    /// moved by more than the factor since they were last said (nothing either while no face is
    /// in contact): due(all), then describe.
    std::string update(const ContactInterface& iface, const FaceSums& all);

    /// True (and the pressures taken as said) when the log is due for `all`, of which only the
    /// counts and pressures are read (FaceSums::addPressures): at the first evaluation with a face
    /// in contact, when the min, mean or max pressure has moved by more than the factor, and when
    /// the first face falls below its peak or the last one leaves it.
    bool due(const FaceSums& all);

    /// The lines for `all`, whatever was said before.
    static std::string describe(const ContactInterface& iface, const FaceSums& all);

private:
    double factor_;
    std::optional<std::array<double, 3>> said_; ///< min, mean, max when last said
    bool saidUnloading_ = false;                ///< whether faces were below their peak then
};

} // namespace roughContact
