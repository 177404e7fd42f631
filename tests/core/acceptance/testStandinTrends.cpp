// SPDX-License-Identifier: GPL-3.0-or-later
// The trends the seed reports that must hold on our stand-in for its measured profile
// (data/standin-2454.csv, made by syntheticProfile with its defaults): the shipped file is the
// generator's output, multi-scale log-log slopes are ~1 (seed §3.2: 1.00), and the multi-scale
// area barely moves when the sampling interval grows 10x while GW's moves a lot (seed Fig. 8).
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/surface/SyntheticProfile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

const std::string standinPath = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";
// Seed §3.2 materials against a rigid flat.
const ContactMaterials steel = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});

Profile standin()
{
    return readProfile(standinPath);
}

// Least-squares slope of ln(area) against ln(load), n loads log spaced in [lo, hi].
double logLogSlope(const ContactModel& m, double lo, double hi, int n)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < n; ++k) {
        const double load = lo * std::pow(hi / lo, double(k) / (n - 1));
        const double x = std::log(load);
        const double y = std::log(m.areaFraction(load));
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

TEST(Standin, ShippedFileIsTheGeneratorsOutput)
{
    // The file holds the generator's doubles printed with 17 significant digits, which
    // round-trip exactly; 1e-15 relative of the rms allows for libm differences between
    // platforms in exp/log/cos of Box-Muller and FFTW's plan.
    const Profile shipped = standin();
    const Profile generated = generateSyntheticProfile(SyntheticProfileSpec{});
    ASSERT_EQ(shipped.size(), generated.size());
    EXPECT_NEAR(shipped.spacing(), generated.spacing(), 1e-12 * generated.spacing());
    double worst = 0.0;
    for (std::size_t i = 0; i < shipped.size(); ++i) {
        worst = std::max(worst, std::abs(shipped.heights()[i] - generated.heights()[i]));
    }
    EXPECT_LT(worst, 1e-15 * 0.115e-6 * 1e3);
}

TEST(Standin, MatchesTheSeedsDescription)
{
    // Seed §3.2: about 2454 points at 0.204 um; Table 1: sigma = 0.115 um. The rms after mean
    // and tilt removal is what the generator scales, so it is exact to round-off.
    const Profile p = standin().detrended();
    EXPECT_EQ(p.size(), 2454U);
    EXPECT_NEAR(p.spacing(), 0.204e-6, 1e-12 * 0.204e-6);
    EXPECT_NEAR(p.rms(), 0.115e-6, 1e-12 * 0.115e-6);
    // Parseval on its spectrum (the models' input): the same variance.
    const Spectrum s = Spectrum::fromProfile(p);
    EXPECT_NEAR(std::sqrt(s.profileVariance()), 0.115e-6, 1e-10 * 0.115e-6);
}

TEST(Standin, GeneratorIsSeededAndScaled)
{
    SyntheticProfileSpec spec;
    spec.points = 1000;
    spec.rms = 2e-6;
    const Profile a = generateSyntheticProfile(spec);
    const Profile b = generateSyntheticProfile(spec);
    spec.seed += 1;
    const Profile c = generateSyntheticProfile(spec);
    EXPECT_EQ(a.heights(), b.heights());
    EXPECT_NE(a.heights(), c.heights());
    EXPECT_NEAR(a.detrended().rms(), 2e-6, 1e-12 * 2e-6);
    spec.D = 2.5;
    EXPECT_THROW(generateSyntheticProfile(spec), std::invalid_argument);
}

TEST(Standin, MultiscaleSlopesAreNearUnity)
{
    // Seed §3.2 (Figs. 6, 7): log-log slopes 1.00 for every multi-scale curve. The issue sets
    // the band 0.95-1.05 for the stand-in. Range 1e-6..1e-3: below it the curves are as linear;
    // above it the elasto-plastic curves approach complete contact (A_r/A_n > 0.3) and bend.
    const Spectrum s = Spectrum::fromProfile(standin());
    for (const std::string& name : multiscaleModelNames()) {
        SCOPED_TRACE(name);
        const auto m = makeContactModel(name, s, steel);
        const double slope = logLogSlope(*m, 1e-6, 1e-3, 16);
        EXPECT_GE(slope, 0.95);
        EXPECT_LE(slope, 1.05);
    }
    // GW (Hertz) is visibly sub-linear over the same range (seed: 0.969).
    const auto gw = makeContactModel("greenwoodWilliamson", s, steel);
    EXPECT_LT(logLogSlope(*gw, 1e-6, 1e-3, 16), 0.99);
}

TEST(Standin, MultiscaleIsFarLessSensitiveToSamplingThanGW)
{
    // Seed Fig. 8: growing the sampling interval 10x changes GW's area a lot (its eta and R
    // come from the spectral moments m2, m4, dominated by the highest frequencies) and the
    // multi-scale area very little (the low levels set it, seed Fig. 5). "Far less": the
    // multi-scale change in ln(area) is under a third of GW's. Measured on the stand-in:
    // GW 1.59; hertz 0.17, jghConsistent 0.21, jacksonGreen 0.02, truncation 0.00 and the
    // seed's jgh 0.42 (its area drop at the Eq. 9/10 switch, docs/theory.md §3.2, makes it the most
    // sensitive multi-scale form).
    const Profile fine = standin();
    const Profile coarse = fine.subsampled(10);
    const Spectrum sf = Spectrum::fromProfile(fine);
    const Spectrum sc = Spectrum::fromProfile(coarse);
    const double load = 7.94e-5; // the seed's Fig. 5 load
    const auto change = [&](const std::string& name) {
        return std::abs(std::log(makeContactModel(name, sc, steel)->areaFraction(load) /
                                 makeContactModel(name, sf, steel)->areaFraction(load)));
    };
    const double gw = change("greenwoodWilliamson");
    EXPECT_GT(gw, std::log(2.0)) << "GW's area should move by more than 2x";
    for (const std::string& name : multiscaleModelNames()) {
        SCOPED_TRACE(name);
        EXPECT_LT(change(name), gw / 3.0);
    }
}
