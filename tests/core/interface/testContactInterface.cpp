// SPDX-License-Identifier: GPL-3.0-or-later
// The boundary condition's entry point: an interface built from a plain description gives the
// same numbers as building the pieces by hand, and refuses bad descriptions clearly.
#include "RunCommand.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/X3pReader.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"
#include "roughContact/thermal/CooperMikicYovanovich.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"
#include "roughContact/thermal/Mikic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace {
const std::string standin = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";
const Material steel{179.52e9, 0.32, 0.2e9};
const Material copper{117e9, 0.34, 0.07e9};

InterfaceSpec steelOnCopper()
{
    InterfaceSpec spec;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::profile;
    s.file = standin;
    spec.surfaces = {s};
    spec.side1 = steel;
    spec.side2 = copper;
    spec.model = "jacksonGreen";
    return spec;
}
} // namespace

TEST(ContactInterface, EqualsTheHandBuiltModel)
{
    const ContactInterface ci(steelOnCopper());
    const ContactMaterials mat = ContactMaterials::pair(steel, copper);
    EXPECT_NEAR(ci.reducedModulus(), 1.0 / ((1 - 0.32 * 0.32) / 179.52e9 + (1 - 0.34 * 0.34) / 117e9), 1.0);
    const MultiscaleModel m(Spectrum::fromProfile(readProfile(standin)), mat.reducedModulus(),
                            makeAsperityModel("jacksonGreen", mat));
    // Default table range 1e-9 E' .. E'; the table is within 0.5 % of the direct solve
    // (testConstrictionConductance checks that bound densely); here a few spot checks. The
    // default law (fittedElastoPlastic) on the profile's roughness, capped at H = 2.84 S_y of
    // copper, which yields first; the area the multi-scale model's.
    EXPECT_EQ(defaultConductanceLaw(), "fittedElastoPlastic");
    const SurfaceRoughness r = profileRoughness(readProfile(standin));
    const double W = spectralBandwidthRatio(Spectrum::fromProfile(readProfile(standin)));
    const double s1 = firstLevelShare(Spectrum::fromProfile(readProfile(standin)));
    for (double P : {1e3, 1e5, 1e6, 1e7, 1e8}) {
        SCOPED_TRACE(P);
        const double load = P / mat.reducedModulus();
        EXPECT_NEAR(ci.areaFraction(P), m.areaFraction(load), 0.005 * m.areaFraction(load));
        const double h =
            fittedElastoPlasticConductancePerConductivity(P, r, W, mat.reducedModulus(), 2.84 * 0.07e9, 0.0, s1);
        EXPECT_NEAR(ci.conductancePerConductivity(P), h, 0.005 * h);
    }
    // jacksonBhavnaniFerguson by name: the multi-scale constriction sum of the same model.
    InterfaceSpec jbf = steelOnCopper();
    jbf.conductanceLaw = "jacksonBhavnaniFerguson";
    const ContactInterface cj(jbf);
    for (double P : {1e3, 1e5, 1e6, 1e7, 1e8}) {
        const double h = constrictionConductancePerConductivity(m, P / mat.reducedModulus());
        EXPECT_NEAR(cj.conductancePerConductivity(P), h, 0.005 * h) << P;
    }
    // Copper (S_y 0.07 GPa) yields first: the pair takes copper's S_y, E and nu (whichever side
    // it is on), so complete contact comes at a lower pressure than when copper had steel's
    // S_y. (Was: `< 1e9`, which any S_y between them and either order satisfied.)
    EXPECT_EQ(mat.yieldStrength("jacksonGreen"), 0.07e9);
    EXPECT_EQ(ContactMaterials::pair(copper, steel).yieldStrength("jacksonGreen"), 0.07e9);
    InterfaceSpec swapped = steelOnCopper();
    std::swap(swapped.side1, swapped.side2);
    EXPECT_EQ(ContactInterface(swapped).completeContactPressure(), ci.completeContactPressure());
    InterfaceSpec hardCopper = steelOnCopper();
    hardCopper.side2.Sy = 0.2e9; // steel's
    const double hardComplete = ContactInterface(hardCopper).completeContactPressure();
    std::printf("complete contact: copper S_y %.4g Pa, with steel's S_y %.4g Pa\n",
                ci.completeContactPressure(), hardComplete);
    EXPECT_LT(ci.completeContactPressure(), hardComplete);
    EXPECT_NE(ci.summary().find("jacksonGreen"), std::string::npos);
}

TEST(ContactInterface, TheDefaultLawUnloadsByItsBranch)
{
    // A multi-scale model with the default law and a cap: below a face's peak h_c is the table's
    // loading value times the law's unloading factor (fittedUnloadingFactor on the surfaces'
    // combined m and W, E' and the law's H), A_r/A_n the loading one; at or above the peak, bit for bit
    // the loading values. The note a front-end says once tells it.
    const ContactInterface ci(steelOnCopper());
    const ContactMaterials mat = ContactMaterials::pair(steel, copper);
    const double H = 2.84 * 0.07e9;
    const double m = profileRoughness(readProfile(standin)).meanAbsoluteSlope;
    ASSERT_TRUE(ci.remembersLoad());
    EXPECT_TRUE(ci.loadHistory());
    for (double peak : {1e6, 3e7, 1.5e8}) {
        for (double P : {0.03 * peak, 0.3 * peak}) {
            SCOPED_TRACE(std::to_string(P) + " from " + std::to_string(peak));
            const FaceContact loading = ci.face(P, 50.0, 20.0);
            const FaceContact unloading = ci.face(P, 50.0, 20.0, peak);
            const double R = fittedUnloadingFactor(P, peak, m, spectralBandwidthRatio(ci.surface()), mat.reducedModulus(), H,
                                                   fineHurstExponent(ci.surface()));
            EXPECT_GT(R, 1.0);
            EXPECT_NEAR(unloading.conductance, loading.conductance * R, 1e-14 * unloading.conductance);
            EXPECT_EQ(unloading.areaFraction, loading.areaFraction);
            EXPECT_NEAR(ci.unloadingFactors(P, peak).conductancePerConductivity, R, 1e-14 * R);
        }
        EXPECT_EQ(ci.face(peak, 50.0, 20.0, peak).conductance, ci.face(peak, 50.0, 20.0).conductance);
        EXPECT_EQ(ci.face(2.0 * peak, 50.0, 20.0, peak).conductance, ci.face(2.0 * peak, 50.0, 20.0).conductance);
    }
    EXPECT_NE(ci.loadHistoryNote().find("fittedElastoPlastic's unloading branch"), std::string::npos)
        << ci.loadHistoryNote();
    // Without loadHistory: no memory, a peak changes nothing, nothing to say.
    InterfaceSpec off = steelOnCopper();
    off.loadHistory = false;
    const ContactInterface forgetful(off);
    EXPECT_FALSE(forgetful.remembersLoad());
    EXPECT_EQ(forgetful.face(1e6, 50.0, 20.0, 1e8).conductance, forgetful.face(1e6, 50.0, 20.0).conductance);
    EXPECT_EQ(forgetful.loadHistoryNote(), "");
}

TEST(ContactInterface, ALawWithoutAnUnloadingBranchFollowsThePressureOfTheMoment)
{
    // mikic has no unloading branch: the interface keeps no memory of its own, a peak changes
    // nothing (bit for bit), and the note tells why.
    InterfaceSpec spec = steelOnCopper();
    spec.conductanceLaw = "mikic";
    const ContactInterface ci(spec);
    EXPECT_FALSE(ci.remembersLoad());
    EXPECT_EQ(ci.face(1e6, 50.0, 20.0, 1e8).conductance, ci.face(1e6, 50.0, 20.0).conductance);
    EXPECT_NE(ci.loadHistoryNote().find("mikic has no unloading branch, so h follows the pressure of the moment"),
              std::string::npos)
        << ci.loadHistoryNote();
}

TEST(ContactInterface, ConductanceLawByName)
{
    // `conductance NAME` of the boundary condition: the table's h column is the named law at
    // the table's pressures (interpolated between them to 0.5 %, as for the default law), the
    // area still the multi-scale model's; the summary names both.
    const ContactMaterials mat = ContactMaterials::pair(steel, copper);
    const SurfaceRoughness r = profileRoughness(readProfile(standin));
    const ContactInterface byDefault(steelOnCopper());
    EXPECT_EQ(byDefault.conductanceLaw(), defaultConductanceLaw());
    for (const std::string law : {"mikic", "cooperMikicYovanovich"}) {
        SCOPED_TRACE(law);
        InterfaceSpec spec = steelOnCopper();
        spec.conductanceLaw = law;
        spec.microhardness = 1.5e9;
        const ContactInterface ci(spec);
        EXPECT_EQ(ci.conductanceLaw(), law);
        EXPECT_NE(ci.summary().find("conductance from the law " + law), std::string::npos) << ci.summary();
        EXPECT_NE(ci.summary().find("area from the model jacksonGreen"), std::string::npos);
        for (double P : {1e5, 1e6, 1e7}) {
            const double h = law == std::string("mikic")
                                 ? mikicConductancePerConductivity(P, r, mat.reducedModulus())
                                 : cooperMikicYovanovichConductancePerConductivity(P, r, 1.5e9);
            EXPECT_NEAR(ci.conductancePerConductivity(P), h, 0.005 * h) << P;
            EXPECT_EQ(ci.areaFraction(P), byDefault.areaFraction(P)) << P;
        }
    }
    InterfaceSpec bad = steelOnCopper();
    bad.conductanceLaw = "holm";
    try {
        ContactInterface ci(bad);
        ADD_FAILURE() << "an unknown law was accepted";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("mikic"), std::string::npos) << e.what();
    }
    bad.conductanceLaw = "cooperMikicYovanovich"; // no microhardness
    EXPECT_THROW(ContactInterface ci(bad), ParameterError);
}

TEST(ContactInterface, TwoSurfacesCombine)
{
    // The same profile on both sides is one surface with amplitudes x sqrt(2) (same grid,
    // seed §2.1: beta = hypot(beta1, beta2)); a rougher interface touches less at a pressure.
    InterfaceSpec one = steelOnCopper();
    InterfaceSpec two = one;
    two.surfaces.push_back(two.surfaces.front());
    const ContactInterface a(one);
    const ContactInterface b(two);
    EXPECT_EQ(b.surface().size(), a.surface().size());
    for (std::size_t i = 0; i < a.surface().size(); i += 97) {
        EXPECT_NEAR(b.surface().amplitudes()[i], std::sqrt(2.0) * a.surface().amplitudes()[i],
                    1e-14 * a.surface().amplitudes()[i] + 1e-300);
    }
    EXPECT_LT(b.areaFraction(1e6), a.areaFraction(1e6));
}

TEST(ContactInterface, OtherSurfaceKinds)
{
    InterfaceSpec spec = steelOnCopper();
    spec.surfaces.front().kind = SurfaceSpec::Kind::powerLaw;
    spec.surfaces.front().parameters = {1e-7 * std::pow(2e3, 1.2), 1.2, 2e3, 2e6};
    spec.surfaces.front().length = 5e-4;
    const ContactInterface p(spec);
    EXPECT_EQ(p.surface().size(), 1000U); // f = i/L for i = 1..1000
    // The levels are the ones described (was: only the count, and area > 0 for the fractal):
    // beta_i = b_m f_i^-m, f_i = i/L (Spectrum.hpp); a pow and a product, 1e-14.
    for (std::size_t i : {1u, 10u, 1000u}) {
        const double fi = double(i) / 5e-4;
        const double beta = 1e-7 * std::pow(2e3, 1.2) * std::pow(fi, -1.2);
        EXPECT_NEAR(p.surface().frequencies()[i - 1], fi, 1e-14 * fi) << i;
        EXPECT_NEAR(p.surface().amplitudes()[i - 1], beta, 1e-14 * beta) << i;
    }
    spec.surfaces.front().kind = SurfaceSpec::Kind::fractal;
    spec.surfaces.front().parameters = {1.5, 1e-10, 2e3, 2e6};
    const ContactInterface f(spec);
    EXPECT_GT(f.areaFraction(1e6), 0.0);
    // Weierstrass-Mandelbrot: beta_i^2 = 2 S(f_i)/L, S(f) = G^(2(D-1))/(2 ln 1.5 f^(5-2D)); with
    // D = 1.5, beta_i = sqrt(G/(ln 1.5 f_i^2 L)). A pow, a log and a sqrt: 1e-14.
    ASSERT_EQ(f.surface().size(), 1000U);
    for (std::size_t i : {1u, 10u, 1000u}) {
        const double fi = double(i) / 5e-4;
        const double beta = std::sqrt(1e-10 / (std::log(1.5) * fi * fi * 5e-4));
        EXPECT_NEAR(f.surface().amplitudes()[i - 1], beta, 1e-14 * beta) << i;
    }
}

TEST(ContactInterface, RefusesBadDescriptions)
{
    InterfaceSpec spec = steelOnCopper();
    spec.model = "greenwoodWilliamson"; // not a multi-scale model: the table needs the levels
    EXPECT_THROW(ContactInterface{spec}, std::invalid_argument);
    spec = steelOnCopper();
    spec.surfaces.front().file = "/no/such/profile.csv";
    try {
        ContactInterface{spec};
        ADD_FAILURE() << "read a missing file";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/no/such/profile.csv"), std::string::npos) << e.what();
    }
    spec = steelOnCopper();
    spec.side2.E = -1.0;
    EXPECT_THROW(ContactInterface{spec}, std::invalid_argument);
    spec = steelOnCopper();
    spec.surfaces.clear();
    EXPECT_THROW(ContactInterface{spec}, std::invalid_argument);
    spec = steelOnCopper();
    spec.surfaces.front().kind = SurfaceSpec::Kind::powerLaw;
    spec.surfaces.front().parameters = {1.0, 2.0};
    EXPECT_THROW(ContactInterface{spec}, std::invalid_argument);
    // Issue 18, item 4: pointsPerDecade 2000000000 sat in "building the contact table" (killed
    // after 150 s); the range of Limits.hpp is checked before any point is computed.
    for (std::size_t points : {std::size_t(2000000000), std::size_t(1001), std::size_t(1), std::size_t(0)}) {
        spec = steelOnCopper();
        spec.pointsPerDecade = points;
        try {
            ContactInterface{spec};
            ADD_FAILURE() << points << " points per decade accepted";
        } catch (const ParameterError& e) {
            EXPECT_NE(std::string(e.what()).find("pointsPerDecade: must lie within [2, 1000]"), std::string::npos)
                << e.what();
        }
    }
}

// The per-face evaluation the boundary condition calls: h_c = k_s (h_c/k_s)(P) with
// k_s = 2 k1 k2/(k1 + k2), no contact at P <= 0, complete contact beyond the table, and a
// clear refusal of a non-finite pressure or a bad conductivity (never a NaN passed on).
TEST(ContactInterface, FaceConductanceFromTheTableAndBothConductivities)
{
    const ContactInterface ci(steelOnCopper());
    const double k1 = 45.0;  // steel
    const double k2 = 390.0; // copper
    const double ks = 2 * k1 * k2 / (k1 + k2);
    for (double P : {1e4, 1e6, 3e7}) {
        const FaceContact c = ci.face(P, k1, k2);
        // Same arithmetic as the table's own answers: equal to the last bits of a product.
        EXPECT_DOUBLE_EQ(c.conductance, ks * ci.conductancePerConductivity(P)) << P;
        EXPECT_DOUBLE_EQ(c.areaFraction, ci.areaFraction(P)) << P;
        EXPECT_GT(c.conductance, 0.0);
        // Symmetric in the two solids.
        EXPECT_DOUBLE_EQ(ci.face(P, k2, k1).conductance, c.conductance);
    }
    for (double P : {0.0, -1e5}) {
        EXPECT_EQ(ci.face(P, k1, k2).conductance, 0.0);
        EXPECT_EQ(ci.face(P, k1, k2).areaFraction, 0.0);
    }
    const double complete = ci.completeContactPressure();
    ASSERT_TRUE(std::isfinite(complete)); // jacksonGreen reaches A_r = A_n near H
    EXPECT_TRUE(std::isinf(ci.face(2 * complete, k1, k2).conductance));
    EXPECT_EQ(ci.face(2 * complete, k1, k2).areaFraction, 1.0);
    EXPECT_LE(ci.tableEnd(), complete);

    EXPECT_THROW(ci.face(std::nan(""), k1, k2), ParameterError);
    EXPECT_THROW(ci.face(HUGE_VAL, k1, k2), ParameterError);
    EXPECT_THROW(ci.face(1e6, 0.0, k2), ParameterError);
    EXPECT_THROW(ci.face(1e6, k1, -1.0), ParameterError);
    EXPECT_THROW(ci.face(1e6, k1, std::nan("")), ParameterError);
}

TEST(ContactInterface, HowAMapIsSolvedIsForTheExactModelOrTheCheck)
{
    // periodic, mirror and detrend say how the exact model solves a map: refused with a
    // multi-scale model (nothing of it is solved so), taken with check on an areal map
    // (SurfaceCheck.hpp solves the map as they say: `check yes; mirror true;` in a contact entry);
    // detrend also with check on a 1-D description (the check detrends its synthesized
    // surfaces), periodic and mirror not (the check's surfaces are periodic), and periodic with
    // mirror never.
    InterfaceSpec map = steelOnCopper();
    map.surfaces[0].kind = SurfaceSpec::Kind::areal;
    map.surfaces[0].file = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p";
    const auto refused = [](const InterfaceSpec& spec, const std::string& start) {
        try {
            ContactInterface{spec};
            return std::string("taken");
        } catch (const ParameterError& e) {
            return std::string(e.what()).rfind(start, 0) == 0 ? std::string() : std::string(e.what());
        }
    };
    for (const char* what : {"periodic", "mirror", "detrend"}) {
        SCOPED_TRACE(what);
        for (InterfaceSpec spec : {steelOnCopper(), map}) {
            const bool areal = spec.surfaces[0].kind == SurfaceSpec::Kind::areal;
            if (std::string(what) == "periodic") {
                spec.periodic = false;
            } else if (std::string(what) == "mirror") {
                spec.mirror = true;
            } else {
                spec.detrend = Detrend::plane;
            }
            EXPECT_EQ(refused(spec, std::string(what) + ": is for model boundaryElement (or the check of an areal map"),
                      "");
            spec.check = true;
            if (areal || std::string(what) == "detrend") {
                EXPECT_NO_THROW(ContactInterface{spec}) << (areal ? "map" : "profile");
            } else if (std::string(what) == "mirror") {
                EXPECT_EQ(refused(spec, "mirror: is for areal maps"), "") << "profile";
            } else {
                EXPECT_EQ(refused(spec, std::string(what) + ": is for model boundaryElement"), "") << "profile";
            }
        }
    }
    map.check = true;
    map.periodic = true;
    map.mirror = true;
    EXPECT_EQ(refused(map, "mirror: a mirrored map is its own periodic surface"), "");
}

TEST(ContactInterface, HeldAtTableEndOnlyWhereMaxPressureCutTheTable)
{
    // The boundary condition warns "raise maxPressure" from this; before, it also warned in the
    // gap between the table's last grid point and complete contact, where raising it could
    // not help.
    const ContactInterface full(steelOnCopper());
    ASSERT_NE(full.table().end(), ContactTable::End::maxPressure);
    for (double f : {0.5, 0.9, 0.999, 0.9999999}) {
        EXPECT_FALSE(full.heldAtTableEnd(f * full.completeContactPressure())) << f;
    }
    InterfaceSpec spec = steelOnCopper();
    spec.maxPressure = 1e7;
    const ContactInterface cut(spec);
    ASSERT_EQ(cut.table().end(), ContactTable::End::maxPressure);
    EXPECT_FALSE(cut.heldAtTableEnd(0.5e7));
    EXPECT_TRUE(cut.heldAtTableEnd(2e7));
    EXPECT_FALSE(cut.heldAtTableEnd(2.0 * cut.completeContactPressure()));
}

TEST(ContactInterface, ALengthForAProfileIsRefused)
{
    // Was silently ignored (the boundary condition refuses it too, naming the entry).
    InterfaceSpec spec = steelOnCopper();
    spec.surfaces[0].length = 1e-3;
    EXPECT_THROW(ContactInterface{spec}, ParameterError);
}

TEST(ContactInterface, ArealSurface)
{
    // type areal: the averaged line-scan spectrum of the detrended map, in the chosen direction;
    // a stride, a length or an option of the other format is refused.
    InterfaceSpec spec = steelOnCopper();
    SurfaceSpec& s = spec.surfaces[0];
    s.kind = SurfaceSpec::Kind::areal;
    s.file = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p";
    s.direction = ScanDirection::y;
    const ContactInterface c(spec);
    const ArealSurface map = readX3p(s.file);
    EXPECT_EQ(c.surface().amplitudes(), lineScanSpectrum(map.detrended(), ScanDirection::y).amplitudes());
    EXPECT_EQ(c.surface().size(), 325U); // 650 samples a column: levels 1..325
    EXPECT_GT(c.areaFraction(1e6), 0.0);
    s.stride = 2;
    EXPECT_THROW(ContactInterface{spec}, ParameterError);
    s.stride = 1;
    s.length = 1e-3;
    EXPECT_THROW(ContactInterface{spec}, ParameterError);
    s.length.reset();
    s.arealOptions.dx = 1e-6;
    EXPECT_THROW(ContactInterface{spec}, ParameterError);
}

namespace {
// A profile a cos(2 pi periods i/n) of n = 1024 points 1 um apart (two columns, x and z [m]),
// written to `name` in `dir`: one direction of a surface with a lay.
constexpr std::size_t cosineSamples = 1024;
constexpr double cosineSpacing = 1e-6;
std::string writeCosineProfile(const roughContactTest::TempDir& dir, const std::string& name, double amplitude,
                               int periods)
{
    const double pi = std::acos(-1.0);
    const std::string path = (dir.path() / name).string();
    std::ofstream out(path);
    out.precision(17);
    for (std::size_t i = 0; i < cosineSamples; ++i) {
        out << double(i) * cosineSpacing << ' '
            << amplitude * std::cos(2.0 * pi * periods * double(i) / double(cosineSamples)) << '\n';
    }
    return path;
}
} // namespace

TEST(SurfaceSpec, ProfilesAcrossAndAlongTheLayAreTheIsotropicEquivalent)
{
    // z(x, y) = a cos(2 pi 32 x/L) + a cos(2 pi 4 y/L): a lay along y, features 8 times longer
    // along it. Its areal rms gradient is sqrt(a^2/2 (kx^2 + ky^2)) (docs/theory.md §1.6). The
    // profile across the lay (along x) alone, taken as a line scan of an isotropic surface, says
    // sqrt(2) times its own rms slope, a kx: too rough. Across and along together (alongLay) the
    // averaged line-scan spectrum gives the surface's areal gradient; the 1 % is the detrending
    // of a finite profile (its tilt fit takes a little of the cosine's power).
    const roughContactTest::TempDir dir;
    const double L = double(cosineSamples) * cosineSpacing;
    const double a = 1e-6;
    const double pi = std::acos(-1.0);
    SurfaceSpec across;
    across.kind = SurfaceSpec::Kind::profile;
    across.file = writeCosineProfile(dir, "across.txt", a, 32);
    SurfaceSpec both = across;
    both.alongLay = writeCosineProfile(dir, "along.txt", a, 4);
    const double kx = 2.0 * pi * 32.0 / L;
    const double ky = 2.0 * pi * 4.0 / L;
    const double areal = std::sqrt(0.5 * a * a * (kx * kx + ky * ky));
    const double fromBoth = arealRmsGradient(spectralMoments(both.spectrum()));
    const double fromAcross = arealRmsGradient(spectralMoments(across.spectrum()));
    EXPECT_NEAR(fromBoth, areal, 0.01 * areal);
    EXPECT_NEAR(fromAcross, a * kx, 0.01 * a * kx);
    EXPECT_GT(fromAcross / fromBoth, 1.39); // sqrt(2 * 64/65) = 1.403: what one profile overstates
    // The variance is the surface's (both profiles see a^2/2), the mean absolute slope the mean of
    // the two directions' (2 a k/pi each), as an areal map's `direction both`.
    const SurfaceRoughness r = both.roughness();
    EXPECT_NEAR(r.sigma, a / std::sqrt(2.0), 0.01 * a);
    EXPECT_NEAR(r.meanAbsoluteSlope, (a * kx + a * ky) / pi, 0.01 * (a * kx + a * ky) / pi);
    EXPECT_TRUE(both.skewness().has_value());
    // Only a profile has a second direction.
    SurfaceSpec map;
    map.kind = SurfaceSpec::Kind::areal;
    map.file = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p";
    map.alongLay = both.alongLay;
    try {
        map.check();
        ADD_FAILURE() << "alongLay taken on an areal map";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "alongLay");
        EXPECT_NE(e.message().find("direction both"), std::string::npos) << e.what();
    }
}

TEST(SurfaceSpec, ALaysRatioIsTheProfilesSlopeRatio)
{
    // Profiles a cos(2 pi 32 x/L) across and a cos(2 pi 4 y/L) along: the lay ratio (the rms
    // slope across over along) is 8, and the surface the exact model synthesizes of it is the
    // across spectrum's with dy = 8 dx. Without a lay there is none and the synthesis is
    // isotropic; a second, isotropic side adds its power to both directions; a flat profile along
    // the lay (ratio infinite) is refused naming alongLay.
    const roughContactTest::TempDir dir;
    const double a = 1e-6;
    SurfaceSpec lay;
    lay.kind = SurfaceSpec::Kind::profile;
    lay.file = writeCosineProfile(dir, "across.txt", a, 32);
    lay.alongLay = writeCosineProfile(dir, "along.txt", a, 4);
    const std::optional<LaySpectra> one = equivalentLay({lay});
    ASSERT_TRUE(one.has_value());
    // 8 to 1e-4: the detrending of a finite profile takes a little of each cosine's slope, more
    // of the longer one's.
    EXPECT_NEAR(one->stretch(), 8.0, 8e-4);
    const ArealSurface synthesized = synthesizeEquivalent({lay}, 64, 3);
    EXPECT_NEAR(synthesized.dy() / synthesized.dx(), one->stretch(), 1e-12);
    EXPECT_NE(synthesized.source().find("stretched"), std::string::npos) << synthesized.source();
    // The boundaryElement model's synthesize is that surface.
    InterfaceSpec bem;
    bem.surfaces = {lay};
    bem.side1 = steel;
    bem.side2 = steel;
    bem.model = "boundaryElement";
    bem.synthesize = 64;
    bem.seed = 3;
    EXPECT_EQ(BoundaryElementTable(bem).surface().heights(), synthesized.heights());
    EXPECT_EQ(BoundaryElementTable(bem).surface().dy(), synthesized.dy());

    SurfaceSpec isotropic = lay;
    isotropic.alongLay.clear();
    EXPECT_FALSE(equivalentLay({isotropic}).has_value());
    EXPECT_EQ(synthesizeEquivalent({isotropic}, 64, 3).dy(), synthesizeEquivalent({isotropic}, 64, 3).dx());
    // Two sides: the isotropic side's spectrum in both directions, so the across slope^2 is the
    // two across ones' sum, the along one the along and the isotropic side's across.
    const std::optional<LaySpectra> two = equivalentLay({lay, isotropic});
    ASSERT_TRUE(two.has_value());
    const double across2 = spectralMoments(one->across).m2;
    const double along2 = spectralMoments(one->along).m2;
    EXPECT_NEAR(two->stretch(), std::sqrt(2.0 * across2 / (along2 + across2)), 1e-9);

    SurfaceSpec flat = lay;
    flat.alongLay = writeCosineProfile(dir, "flat.txt", 0.0, 4);
    try {
        (void)equivalentLay({flat})->stretch();
        ADD_FAILURE() << "a flat profile along the lay taken";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "alongLay");
        EXPECT_NE(e.message().find("flat.txt"), std::string::npos) << e.what();
    }
}

TEST(SurfaceSpec, OneProfileSaysWhatItCannotKnow)
{
    // A single profile (no alongLay) gets the note, naming the front-end's option; a profile with
    // its second direction, an areal map and a spectrum do not.
    SurfaceSpec one;
    one.kind = SurfaceSpec::Kind::profile;
    one.file = standin;
    SurfaceSpec two = one;
    two.alongLay = standin;
    SurfaceSpec map;
    map.kind = SurfaceSpec::Kind::areal;
    const std::string note = singleProfileNote({one}, "--profile-along");
    EXPECT_NE(note.find("up to 2.3 times too high"), std::string::npos) << note;
    EXPECT_NE(note.find("(--profile-along)"), std::string::npos) << note;
    EXPECT_EQ(singleProfileNote({two}, "x"), "");
    EXPECT_EQ(singleProfileNote({map}, "x"), "");
    EXPECT_NE(singleProfileNote({map, one}, "x"), "") << "one of two sides a single profile";
}

TEST(SurfaceSpec, TheNotesFactorIsTheAnisotropyStudys)
{
    // singleProfileOverstatement is the largest h that the profiles across the lay (their mean:
    // the lay's effect without one profile's chance) give over the map's h (both directions) on
    // the same surface and load, in the anisotropy study's generated table
    // (docs/validation/anisotropy.md), to the note's two digits.
    std::ifstream in(std::string(ROUGHCONTACT_SOURCE_DIR) + "/docs/validation/generated/anisotropy/inputs.csv");
    ASSERT_TRUE(in) << "the study's inputs.csv";
    std::string line;
    std::vector<std::string> header;
    double largest = 0.0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string c; std::getline(ss, c, ',');) {
            cells.push_back(c);
        }
        if (header.empty()) {
            header = cells;
            continue;
        }
        const auto at = [&](const char* name) {
            return cells.at(std::size_t(std::find(header.begin(), header.end(), name) - header.begin()));
        };
        if (at("input") == "rows") {
            largest = std::max(largest, std::stod(at("over_map_max")));
        }
    }
    ASSERT_GT(largest, 1.0);
    EXPECT_NEAR(singleProfileOverstatement, largest, 0.05) << "the study's largest is " << largest;
}
