// SPDX-License-Identifier: GPL-3.0-or-later
// A monotone table of the real contact area and the contact conductance against the nominal
// interface pressure, built once from a multi-scale model and interpolated cheaply: what a
// boundary condition asks per face and per iteration.
#pragma once

#include "roughContact/models/MultiscaleModel.hpp"

#include <cstddef>
#include <limits>
#include <vector>

namespace roughContact {

class ConductanceLaw;

/// Pressures P = F/A_n [Pa] log spaced from minPressure to the end of the table (maxPressure,
/// or the last point below complete contact, whichever is lower), pointsPerDecade per decade.
/// At each point the direct solve gives A_r/A_n (MultiscaleModel::areaFraction at P/E') and
/// h_c/k_s (constrictionConductancePerConductivity); a running maximum makes both
/// non-decreasing (it only acts on the seed's jgh form, whose area can dip by <= 0.4 %).
/// Between points both are interpolated linearly in log-log (the curves are near power laws
/// in P, slope ~1). Queries:
///   P <= 0                         no contact: 0;
///   0 < P < minPressure            power-law extrapolation with the first interval's slope;
///   P beyond the last point but below complete contact: the last point's values (a
///                                  conservative floor; choose maxPressure to cover the case);
///   P >= completeContactPressure() complete contact: area 1 and h_c/k_s = +infinity (no
///                                  constriction left).
///
/// The separation column (optional): the mean-plane separation Y [m] of the two surfaces, which
/// a gas-gap conductance k_g/(Y + M) needs. Built from ConductanceLaw::meanSeparation at every
/// point when the law defines one (persson, multiscaleBarber; none for the default table, whose
/// multi-scale constriction sum has no separation), given to fromPoints by a boundary-element
/// table. Y falls with P and reaches 0 at complete contact, where log Y would diverge, and is
/// near linear in log P at light load (Persson's p ~ exp(-Y/u0)), so between points Y is
/// interpolated linearly in log P (not log-log; on persson's table within 2.1e-5 of the law
/// between points). The table is not refined for Y. A running minimum makes the column
/// non-increasing (the loading path never opens the gap); on the persson and multiscaleBarber
/// tables of testSeparation it never acts (the column is the law's bit for bit). Queries
/// (meanSeparation):
///   P <= 0                         NaN: the faces are apart, the gap is not the contact's; the
///                                  caller must handle that case (it has no finite Y);
///   0 < P < minPressure            the first interval's slope in log P (Y rises as P falls;
///                                  never below 0), exact for Persson's light-load law;
///   P beyond the last point but below complete contact: the last point's value, as the other
///                                  columns (a ceiling-ended table holds it as well);
///   P >= completeContactPressure() 0: complete contact, the surfaces touch everywhere. It is
///                                  the area model's complete contact: a law's own Y need not
///                                  vanish there, and the column then jumps to 0 as h_c/k_s
///                                  jumps to +inf (persson on the Hurst-0.8 surface of
///                                  testSeparation: from 2.9 um with jacksonGreen, 8 % of its
///                                  Y at 1e-9 E', and from 0.3 um with hertz).
class ContactTable {
public:
    /// law: the conductance law of the h column (ConductanceLaw.hpp); none: the multi-scale
    /// constriction sum (jacksonBhavnaniFerguson) of `model`. Used only while building.
    ContactTable(const MultiscaleModel& model, double minPressure, double maxPressure,
                 std::size_t pointsPerDecade = 40, const ConductanceLaw* law = nullptr);

    /// What ended the table (end() below).
    enum class End { maxPressure, completeContact, conductanceCeiling };
    /// A table of precomputed points (e.g. a boundary-element curve, BoundaryElementTable.hpp),
    /// interpolated and queried exactly as the table above: pressures [Pa] strictly increasing
    /// and > 0, at least 2; A_r/A_n in (0, 1] and h_c/k_s > 0, finite, both non-decreasing;
    /// completeContactPressure above the last pressure (+infinity: none); Eprime [Pa] > 0;
    /// separations [m] (optional; empty: no separation column): one per point, finite, >= 0
    /// and non-increasing. ParameterError naming what is wrong otherwise.
    static ContactTable fromPoints(std::vector<double> pressures, std::vector<double> areaFractions,
                                   std::vector<double> conductancesPerConductivity,
                                   double completeContactPressure, End end, double Eprime,
                                   std::vector<double> separations = {});

    /// A_r/A_n at the nominal pressure P [Pa].
    double areaFraction(double P) const;
    /// h_c/k_s [1/m] at the nominal pressure P [Pa].
    double conductancePerConductivity(double P) const;
    /// Both at once (one search of the table): {A_r/A_n, h_c/k_s}; the two calls above are its
    /// parts.
    struct Values {
        double areaFraction;
        double conductancePerConductivity;
    };
    Values values(double P) const;

    /// True when the table carries a mean separation (above).
    bool hasSeparation() const noexcept { return !separation_.empty(); }
    /// The mean-plane separation Y [m] at the nominal pressure P [Pa] by the rules above: NaN
    /// for P <= 0 and for a table without the column; 0 from complete contact on.
    /// ParameterError for a NaN P.
    double meanSeparation(double P) const;

    /// The lowest pressure [Pa] of complete contact (A_r = A_n), to 1e-10 relative; +infinity
    /// when the model does not reach it below limits::maximumLoad E' (Limits.hpp).
    double completeContactPressure() const noexcept { return pComplete_; }
    /// The pressure [Pa] from which the law says the conductance is infinite before the model's
    /// complete contact (fittedElastoPlastic at P = H): h_c/k_s is +inf there,
    /// A_r/A_n the model's (held at the table's end); +infinity: none.
    double perfectConductancePressure() const noexcept { return pPerfect_; }
    /// The table's points: pressures [Pa] and the values there.
    const std::vector<double>& pressures() const noexcept { return p_; }
    const std::vector<double>& areaFractions() const noexcept { return area_; }
    const std::vector<double>& conductancesPerConductivity() const noexcept { return h_; }
    /// Y [m] at the points; empty without the column.
    const std::vector<double>& separations() const noexcept { return separation_; }
    double reducedModulus() const noexcept { return Eprime_; }

    /// What ended the table: the maximum pressure asked for (then the values beyond it, up to
    /// complete contact, are held at the last point's: a caller should say so and suggest a
    /// higher maximum), complete contact (the table reaches to within 1e-6 of it), or h_c/k_s
    /// beyond 1e9 1/m (perfect contact for any mesh; nothing to gain beyond).
    End end() const noexcept { return end_; }

private:
    ContactTable() = default;
    /// The logarithms and the bucket index of p_, area_, h_ (both constructors end with it).
    void index();

    /// The interval [j - 1, j] of log P and the position t in it; `end`: at or beyond the last
    /// point, where its values hold.
    struct Position {
        std::size_t j;
        double t;
        bool end;
    };
    Position locate(double P) const;
    static double at(const std::vector<double>& logValues, const Position& where);

    double Eprime_ = 0.0;
    double pComplete_ = 0.0;
    double pPerfect_ = std::numeric_limits<double>::infinity();
    End end_ = End::maxPressure;
    std::vector<double> p_;
    std::vector<double> logP_;
    /// An index over log P in equal buckets (as many as points): bucketFirst_[k] is the first
    /// point above the bucket's lower edge, so a lookup searches one bucket, not the table.
    std::vector<std::size_t> bucketFirst_;
    double bucketScale_ = 0.0; ///< buckets per unit of log P
    std::vector<double> area_;
    std::vector<double> h_;
    std::vector<double> logArea_;
    std::vector<double> logH_;
    std::vector<double> separation_; ///< Y [m] (empty: none), interpolated linearly in log P
};

} // namespace roughContact
