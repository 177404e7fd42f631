// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs at and beyond the edges of what the core accepts (roughContact/Limits.hpp). This test
// runs, like every core test, with the floating-point traps OpenFOAM runs with
// (support/trappingMain.cpp): an overflow, a division by zero or a NaN anywhere below kills it.
// Each input that once crashed the solver, hung, or gave NaN or nonsense is named after what it
// did (issue: "No input makes it hang, run out of memory, crash the solver or print NaN").
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/asperity/Hertz.hpp"
#include "roughContact/asperity/JacksonGreen.hpp"
#include "roughContact/asperity/JohnsonGreenwoodHigginson.hpp"
#include "roughContact/asperity/Truncation.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace roughContact;

namespace {
const std::string standinPath = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/standin-2454.csv";
const Material steel{179.52e9, 0.32, 0.2e9};

const Profile& standinProfile()
{
    static const Profile p = readProfile(standinPath);
    return p;
}

Profile scaled(double factor)
{
    std::vector<double> z = standinProfile().heights();
    for (double& v : z) {
        v *= factor;
    }
    return Profile(std::move(z), standinProfile().spacing(), "standin x " + std::to_string(factor));
}

Spectrum withAmplitude(const Spectrum& s, std::size_t level, double amplitude)
{
    std::vector<double> b = s.amplitudes();
    b.at(level) = amplitude;
    return Spectrum(s.frequencies(), std::move(b), s.length(), "modified");
}

// Expects `f` to throw E whose message contains `words`.
template <class E, class F> void expectError(F&& f, const std::string& words)
{
    try {
        f();
        ADD_FAILURE() << "no error; expected one mentioning '" << words << "'";
    } catch (const E& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

// The promise of every model at every accepted load: A_r/A_n in [0, 1] (never NaN), and for the
// multi-scale models h_c/k_s consistent with it: 0 without contact, +inf exactly at complete
// contact, finite and positive in between.
void expectConsistent(const ContactModel& model, double load)
{
    const double a = model.areaFraction(load);
    ASSERT_TRUE(a >= 0.0 && a <= 1.0) << model.name() << " load " << load << ": area " << a;
    const auto* ms = dynamic_cast<const MultiscaleModel*>(&model);
    if (ms == nullptr) {
        return;
    }
    const double h = constrictionConductancePerConductivity(*ms, load);
    if (load == 0.0) {
        EXPECT_EQ(a, 0.0);
        EXPECT_EQ(h, 0.0);
    } else if (a == 1.0) {
        EXPECT_EQ(h, std::numeric_limits<double>::infinity()) << model.name() << " load " << load;
    } else {
        EXPECT_GT(a, 0.0) << model.name() << " load " << load;
        EXPECT_TRUE(std::isfinite(h) && h > 0.0) << model.name() << " load " << load << ": h_c/k_s " << h;
    }
}
} // namespace

// 1. Unbounded work: refused before anything large is allocated, with the count and the memory.

TEST(ExtremeInputs, combinationOfFarApartSpectraIsRefusedBeforeItsGridIsBuilt)
{
    // Was: two one-row spectra re-binned onto top frequency x longest length levels, 23.6 GB,
    // killed by the kernel after 158 s. Now the grid's size (1e15 levels) is known first.
    const Spectrum a({1e-3}, {1e-6}, 1e3, "a.csv");
    const Spectrum b({1e12}, {1e-12}, 1e-12, "b.csv");
    expectError<ParameterError>([&] { Spectrum::combine(a, b); }, "frequency levels, more than the cap");
    expectError<ParameterError>([&] { Spectrum::combine(a, b); }, "MB");
}

TEST(ExtremeInputs, powerLawOfABillionLevelsIsRefused)
{
    // Was: the boundary condition with powerLaw { bm 1e-8; m 1; fmin 1; fmax 1e9; } ran out of
    // memory. The message says how many levels and what to change.
    expectError<ParameterError>([] { Spectrum::powerLaw(1e-8, 1.0, 1.0, 1e9); }, "1e+09 frequency levels");
    expectError<ParameterError>([] { Spectrum::powerLaw(1e-8, 1.0, 1.0, 1e9); }, "narrow [fmin, fmax]");
    EXPECT_EQ(Spectrum::powerLaw(1e-8, 1.0, 1.0, double(limits::maximumLevels)).size(),
              limits::maximumLevels);
}

TEST(ExtremeInputs, profileCombinedWithALongSpectrumIsRefused)
{
    // Was: a measured profile (L = 0.5 mm) and a 4-level spectrum from 1 /m (L = 1 m) made
    // 2.45 million levels and a 117 s start.
    const Spectrum profile = Spectrum::fromProfile(standinProfile());
    const Spectrum coarse({1.0, 2.0, 3.0, 4.0}, {1e-6, 5e-7, 3e-7, 2e-7}, 1.0, "coarse.csv");
    expectError<ParameterError>([&] { Spectrum::combine(profile, coarse); }, "2.45e+06 frequency levels");
}

TEST(ExtremeInputs, profileWithMoreLevelsThanTheCapIsRefusedBeforeItsFFT)
{
    const std::size_t n = 2 * limits::maximumLevels + 2;
    const Profile p(std::vector<double>(n, 0.0), 1e-9, "long.csv");
    expectError<ParameterError>([&] { Spectrum::fromProfile(p); }, "stride K >= 2");
    expectError<ParameterError>([&] { Spectrum::fromProfile(p); }, "long.csv");
}

TEST(ExtremeInputs, combineOnDifferentGridsEqualsTheDirectOverlapSum)
{
    // The O(n + K) sweep against the definition: each output bin's power is the sum over every
    // input bin of its power times the overlapping fraction (O(n K), written out here).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.1, 1.0);
    auto randomSpectrum = [&](std::size_t n, double L) {
        std::vector<double> f(n);
        std::vector<double> b(n);
        for (std::size_t i = 0; i < n; ++i) {
            f[i] = double(i + 1) / L;
            b[i] = 1e-8 * u(rng) / double(i + 1);
        }
        return Spectrum(f, b, L, "random");
    };
    const Spectrum a = randomSpectrum(300, 1e-3);
    const Spectrum b = randomSpectrum(170, 0.37e-3);
    const Spectrum c = Spectrum::combine(a, b);
    struct Bin {
        double lo, hi, power;
    };
    auto bins = [](const Spectrum& s) {
        std::vector<Bin> out;
        const auto& f = s.frequencies();
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double lo = i > 0 ? 0.5 * (f[i] + f[i - 1]) : f[0] - 0.5 * (f[1] - f[0]);
            const double hi = i + 1 < f.size() ? 0.5 * (f[i] + f[i + 1]) : f[i] + (f[i] - lo);
            out.push_back({std::max(lo, 0.0), hi, 0.5 * s.amplitude(i) * s.amplitude(i)});
        }
        return out;
    };
    const std::vector<Bin> all[] = {bins(a), bins(b)};
    ASSERT_EQ(c.length(), 1e-3);
    double total = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const double fk = c.frequency(k);
        const double lo = k == 0 ? 0.0 : fk - 0.5e3;
        const double hi = fk + 0.5e3;
        double p = 0.0;
        for (const auto& list : all) {
            for (const Bin& bin : list) {
                const double overlap = std::min(hi, bin.hi) - std::max(lo, bin.lo);
                if (overlap > 0.0) {
                    p += bin.power * overlap / (bin.hi - bin.lo);
                }
            }
        }
        // Sums of the same terms in another order: round-off only.
        EXPECT_NEAR(0.5 * c.amplitude(k) * c.amplitude(k), p, 1e-12 * p) << "level " << k;
        total += p;
    }
    EXPECT_NEAR(c.variance(), a.variance() + b.variance(), 1e-12 * c.variance()); // power conserved
    EXPECT_NEAR(total, c.variance(), 1e-12 * total);
}

// 2. Out of floating-point range: refused, naming the input.

TEST(ExtremeInputs, nominalAreaOutOfRangeIsRefused)
{
    // Was: --dx 1e-300 / 1e300 (A_n = L^2 underflows or overflows) printed "-nan"; --dx 1e-150
    // silently gave area 0; a spectrum row at 1e-300 /m and --length 1e300 gave NaN.
    const std::vector<double> z = standinProfile().heights();
    for (double dx : {1e-300, 1e-150, 1e-13, 1e300}) {
        expectError<ParameterError>([&] { Profile(z, dx, "p.csv"); }, "p.csv: spacing");
    }
    expectError<ParameterError>([&] { Profile(z, 1.0, "p.csv"); }, "scan length N dx");
    expectError<InputError>([] { Spectrum({1e-300, 1.0}, {1e-6, 1e-7}, 1.0, "s.csv"); }, "wavelength 1/f");
    expectError<ParameterError>([] { Spectrum({1.0, 2.0}, {1e-6, 1e-7}, 1e300, "s.csv"); }, "scan length L");
    expectError<ParameterError>([] { Spectrum::powerLaw(1e-8, 1.0, 1.0, 10.0, 1e300); }, "power law length");
    expectError<ParameterError>([] { Spectrum::fractal(1.5, 1e-9, 1.0, 10.0, 1e300); }, "fractal length");
}

TEST(ExtremeInputs, fractalErrorsSayFractal)
{
    // Was: --fractal errors said "power law".
    expectError<ParameterError>([] { Spectrum::fractal(1.5, 1e-9, 10.0, 1.0); }, "fractal spectrum fmax");
    expectError<ParameterError>([] { Spectrum::fractal(1.5, 1e-9, 0.0, 1.0); }, "fractal fmin");
    expectError<ParameterError>([] { Spectrum::fractal(1.5, 0.0, 1.0, 10.0); }, "fractal roughness G");
}

TEST(ExtremeInputs, materialsOutOfRangeAreRefused)
{
    // Was SIGFPE in the solver: E 1e7 with S_y 0.4e9 (B = 0.14 exp(23 S_y/E) overflows once
    // S_y/E > 30.9), E 1e300, S_y 1e100; S_y 1e65 gave area 0 at a positive load.
    expectError<ParameterError>([] { ContactMaterials::againstRigidFlat({1e7, 0.3, 0.4e9}); }, "S_y/E = ");
    expectError<ParameterError>(
        [] {
            ContactMaterials::againstRigidFlat({1e300, 0.3, 0.4e9});
        },
        "Young's modulus E: must lie within");
    expectError<ParameterError>(
        [] {
            ContactMaterials::againstRigidFlat({2e11, 0.3, 1e100});
        },
        "yield strength");
    expectError<ParameterError>(
        [] {
            ContactMaterials::againstRigidFlat({2e11, 0.3, 1e65});
        },
        "yield strength");
    expectError<ParameterError>(
        [] {
            ContactMaterials::pair({2e11, 0.3, 0.2e9}, {2e11, 0.3, 1e-3});
        },
        "second material yield strength");
    expectError<ParameterError>([] { ContactMaterials::fromReducedModulus(1e300, 0.3, 0.2e9); },
                                "reduced modulus");
    // The edges themselves are accepted.
    EXPECT_NO_THROW(ContactMaterials::againstRigidFlat(
        {limits::maximumModulus / 2, 0.3, limits::maximumYieldStrain * limits::maximumModulus / 2}));
}

TEST(ExtremeInputs, loadsOutOfRangeAreRefused)
{
    // Was: --load-range 1e-300:1e300:5 and GW/MB at 1e300 printed rows before failing.
    const Spectrum s = Spectrum::fromProfile(standinProfile());
    const auto materials = ContactMaterials::againstRigidFlat(steel);
    for (const std::string& name : modelNames()) {
        const auto m = makeContactModel(name, s, materials);
        for (double load : {1e-300, 1e300, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
            expectError<ParameterError>([&] { m->areaFraction(load); }, "load");
        }
    }
}

// 3. Silent NaN and nonsense: a defined result or an error, the same for every model.

TEST(ExtremeInputs, zeroRoughnessIsAnErrorForEveryModel)
{
    // Was: area 1 with h_per_k 0 (multi-scale), unclear errors (GW, MB).
    const Spectrum flat = Spectrum::fromProfile(scaled(0.0));
    const auto materials = ContactMaterials::againstRigidFlat(steel);
    for (const std::string& name : modelNames()) {
        SCOPED_TRACE(name);
        expectError<ParameterError>([&] { makeContactModel(name, flat, materials); }, "zero roughness");
    }
}

TEST(ExtremeInputs, roughnessBelowAFemtometreIsAnErrorForEveryModel)
{
    // Was SIGFPE (heights scaled by 1e-153), and "very smooth surfaces give area 0 with
    // jacksonGreen and 1 with hertz".
    const auto materials = ContactMaterials::againstRigidFlat(steel);
    for (double factor : {1e-153, 1e-30, 1e-12}) {
        const Spectrum s = Spectrum::fromProfile(scaled(factor));
        for (const std::string& name : modelNames()) {
            SCOPED_TRACE(name);
            expectError<ParameterError>([&] { makeContactModel(name, s, materials); }, "below 1e-15 m");
        }
    }
}

TEST(ExtremeInputs, aLevelOfTinyAmplitudeCountsAsZero)
{
    // Was SIGFPE (jacksonGreen, a spectrum amplitude of 1e-160): q^2 of the level's force ratio
    // underflowed to 0, the area after it was 0 and the next level divided by it. A flat level is
    // skipped (Limits.hpp), so the result equals that of amplitude 0, bit for bit.
    const Spectrum s = Spectrum::fromProfile(standinProfile());
    const auto materials = ContactMaterials::againstRigidFlat(steel);
    // The smallest double (4.9e-324) would make the level's radius 1/(4 pi^2 beta f^2) overflow.
    for (double amplitude : {1e-160, 1e-300, std::numeric_limits<double>::denorm_min()}) {
        for (const std::string& name : multiscaleModelNames()) {
            SCOPED_TRACE(name);
            const auto tiny = makeContactModel(name, withAmplitude(s, 5, amplitude), materials);
            const auto zero = makeContactModel(name, withAmplitude(s, 5, 0.0), materials);
            for (double load : {1e-30, 1e-9, 1e-6, 1e-3}) {
                EXPECT_EQ(tiny->areaFraction(load), zero->areaFraction(load))
                    << amplitude << " load " << load;
                expectConsistent(*tiny, load);
            }
        }
    }
}

TEST(ExtremeInputs, flatLevelsAreInCompleteContactAtTheSmallestLoad)
{
    // The premise of limits::flatSlope: every asperity law puts a level in complete contact from
    // a mean pressure of 8 E' beta f on. Checked for every law on levels of slopes 1e-8 to 1
    // and frequencies 1e-2 to 1e9 /m, at the moduli and yield strains the core accepts.
    for (double E : {1e5, 2e11, 5e12}) {
        for (double strain : {limits::minimumYieldStrain, 1e-3, limits::maximumYieldStrain}) {
            const double nu = 0.3;
            const double Ep = E / (1 - nu * nu);
            const double Sy = strain * E;
            using Form = JohnsonGreenwoodHigginson::Form;
            const std::shared_ptr<const AsperityModel> laws[] = {
                std::make_shared<Hertz>(Ep), std::make_shared<JohnsonGreenwoodHigginson>(Ep, Form::seed),
                std::make_shared<JohnsonGreenwoodHigginson>(Ep, Form::consistent),
                std::make_shared<JacksonGreen>(Ep, nu, E, Sy), std::make_shared<Truncation>(Ep, nu, Sy)};
            for (const auto& law : laws) {
                for (double f = 1e-2; f <= 1e9; f *= 31.6) {
                    for (double slope = 1e-8; slope <= 1.0; slope *= 10.0) {
                        const Level level = Level::of(f, slope / f);
                        const double r = law->areaRatio(8.0 * Ep * slope, level);
                        EXPECT_GE(r, 1.0) << law->name() << " E " << E << " S_y/E " << strain << " f " << f
                                          << " slope " << slope;
                    }
                }
            }
        }
    }
}

TEST(ExtremeInputs, everyModelIsFiniteAndConsistentAtTheCornersOfTheAcceptedRanges)
{
    // Surfaces from 0.1 pm to 0.1 mm rms, a steep power law (m = 30: most amplitudes underflow),
    // materials at the extremes of modulus and yield strain, loads from the smallest accepted to
    // the largest. Each either gives a consistent answer or refuses with a ParameterError (the
    // Greenwood-Williamson-JG summits saturate, Majumdar-Bhushan cannot fit every spectrum);
    // never a trap (overflow, division by zero, NaN), which would end this test.
    const std::vector<Spectrum> surfaces = {
        Spectrum::fromProfile(standinProfile()), Spectrum::fromProfile(scaled(1e-3)),
        Spectrum::fromProfile(scaled(1e3)),      Spectrum::powerLaw(1e-8, 30.0, 1.0, 1e3),
        Spectrum::fractal(1.2, 1e-12, 1e2, 1e7), Spectrum::fractal(1.9, 1e-9, 1e2, 1e7)};
    const std::vector<Material> materials = {
        {limits::minimumModulus, 0.49, 0.05 * limits::minimumModulus},
        {limits::maximumModulus, -0.9, limits::maximumYieldStrain * limits::maximumModulus},
        {2e11, 0.3, limits::minimumYieldStrain * 2e11},
        {2e11, 0.3, limits::maximumYieldStrain * 2e11}};
    const double loads[] = {0.0, limits::minimumLoad, 1e-12, 1e-6, 1e-2, 1.0, limits::maximumLoad};
    std::size_t answered = 0;
    std::size_t refused = 0;
    for (const Spectrum& s : surfaces) {
        for (const Material& mat : materials) {
            const auto cm = ContactMaterials::againstRigidFlat(mat);
            for (const std::string& name : modelNames()) {
                std::unique_ptr<ContactModel> model;
                try {
                    model = makeContactModel(name, s, cm);
                } catch (const ParameterError&) {
                    ++refused; // e.g. no fractal fit for majumdarBhushan
                    continue;
                }
                for (double load : loads) {
                    try {
                        expectConsistent(*model, load);
                        ++answered;
                    } catch (const ParameterError&) {
                        ++refused; // greenwoodWilliamsonJG beyond its summits' capacity
                    }
                }
            }
        }
    }
    EXPECT_GT(answered, 5 * refused) << answered << " answered, " << refused << " refused";
}

TEST(ExtremeInputs, theBoundaryConditionEntryRefusesTheInputsThatCrashedTheSolver)
{
    // ContactInterface is what the boundary condition calls; each of these was a SIGFPE there.
    const auto interfaceWith = [](const Material& m, SurfaceSpec surface) {
        InterfaceSpec spec;
        spec.surfaces = {std::move(surface)};
        spec.side1 = m;
        spec.side2 = m;
        spec.model = "jacksonGreen";
        return ContactInterface(spec);
    };
    SurfaceSpec standin;
    standin.file = standinPath;
    SurfaceSpec steep;
    steep.kind = SurfaceSpec::Kind::powerLaw;
    steep.parameters = {1e-8, 30.0, 1.0, 1e3};
    SurfaceSpec huge;
    huge.kind = SurfaceSpec::Kind::powerLaw;
    huge.parameters = {1e-8, 1.0, 1.0, 1e9};
    expectError<ParameterError>([&] { interfaceWith({1e7, 0.3, 0.4e9}, standin); }, "S_y/E");
    expectError<ParameterError>([&] { interfaceWith({1e300, 0.3, 0.4e9}, standin); }, "Young's modulus");
    expectError<ParameterError>([&] { interfaceWith({2e11, 0.3, 1e100}, standin); }, "yield strength");
    expectError<ParameterError>([&] { interfaceWith(steel, huge); }, "frequency levels");
    // A steep power law is a valid surface: most of its levels are flat.
    const ContactInterface ci = interfaceWith(steel, steep);
    for (double P : {1e-3, 1e3, 1e6, 1e9, 1e300, std::numeric_limits<double>::max()}) {
        const FaceContact c = ci.face(P, 45.0, 45.0);
        EXPECT_TRUE(c.areaFraction >= 0.0 && c.areaFraction <= 1.0) << P;
        EXPECT_GE(c.conductance, 0.0) << P; // never NaN
        // Complete contact joins the solids; the law may join them earlier (fittedElastoPlastic
        // at P = H), never later.
        if (c.areaFraction == 1.0) {
            EXPECT_TRUE(std::isinf(c.conductance)) << P;
        }
    }
}
