// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line tool multiscaleContact: its fixed interface, that its numbers are the
// library's, and its error paths (stderr, non-zero exit, nothing on stdout).
#include "RunCommand.hpp"

#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/X3pReader.hpp"
#include "roughContact/material/Materials.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/models/ModelFactory.hpp"
#include "roughContact/models/MultiscaleModel.hpp"
#include "roughContact/models/Persson.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/Spectrum.hpp"
#include "roughContact/thermal/ConductanceLaw.hpp"
#include "roughContact/thermal/ConstrictionConductance.hpp"
#include "roughContact/thermal/FittedElastoPlastic.hpp"
#include "roughContact/thermal/GapConductance.hpp"
#include "roughContact/thermal/Gas.hpp"
#include "roughContact/thermal/MeasuredAccuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;
using roughContactTest::cli;
using roughContactTest::CommandResult;
using roughContactTest::runCommand;
using roughContactTest::standin;
using roughContactTest::TempDir;

namespace {

constexpr auto& run = roughContactTest::runCli;

// The seed's materials (§3.2): E = 179.52 GPa, nu = 0.32, S_y = 0.2 GPa (against a rigid flat).
const std::string steel = " --E 179.52e9 --nu 0.32 --Sy 0.2e9";

struct Csv {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

Csv parseCsv(const std::string& text)
{
    Csv csv;
    std::istringstream in(text);
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::istringstream ls(line);
        std::string cell;
        while (std::getline(ls, cell, ',')) {
            cells.push_back(cell);
        }
        if (!line.empty() && line.back() == ',') {
            cells.emplace_back(); // an empty last column
        }
        (first ? csv.header : csv.rows.emplace_back()) = cells;
        first = false;
    }
    return csv;
}

int column(const Csv& csv, const std::string& name)
{
    for (std::size_t i = 0; i < csv.header.size(); ++i) {
        if (csv.header[i] == name) {
            return static_cast<int>(i);
        }
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
}

// An error: exit status 1 (docs/cli.md), nothing on stdout, a message on stderr containing each
// of `needles`.
void expectError(const std::string& args, const std::vector<std::string>& needles)
{
    SCOPED_TRACE("multiscaleContact " + args);
    const CommandResult r = run(args);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "") << "an error must not print a partial CSV";
    for (const std::string& n : needles) {
        EXPECT_NE(r.err.find(n), std::string::npos) << "stderr lacks '" << n << "':\n" << r.err;
    }
}

} // namespace

TEST(Cli, HelpDocumentsEveryOptionAndModel)
{
    const CommandResult r = run("--help");
    EXPECT_EQ(r.status, 0);
    for (const char* opt : {"--profile", "--units", "--spectrum", "--length", "--power-law", "--fractal",
                            "--model", "--E", "--nu", "--Eprime", "--Sy", "--loads", "--load-range", "--pressures",
                            "--levels", "--stride", "--areal", "--dy", "--direction", "--fill-invalid",
                            "--conductance-law", "--vickers", "--hardness-from-yield", "--check", "--k1", "--k2",
                            "--table"}) {
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
    }
    for (const std::string& m : modelNames()) {
        EXPECT_NE(r.out.find(m), std::string::npos) << m;
    }
    for (const std::string& law : conductanceLawNames()) {
        EXPECT_NE(r.out.find(law), std::string::npos) << law;
    }
}

TEST(Cli, LoadCurveIsTheLibrarysForEveryModel)
{
    // The CLI is plumbing: for every model its CSV must equal the C++ API's answer on the same
    // surface and materials, to the 10 significant digits it prints (relative 1e-9 allows for
    // the last printed digit's rounding).
    const Spectrum s = Spectrum::fromProfile(readProfile(standin));
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    for (const std::string& name : modelNames()) {
        SCOPED_TRACE(name);
        const CommandResult r =
            run("--profile '" + standin + "' --model " + name + steel + " --load-range 1e-6:1e-2:9");
        ASSERT_EQ(r.status, 0) << r.err;
        const Csv csv = parseCsv(r.out);
        const int li = column(csv, "nominal_pressure_per_Eprime");
        const int ai = column(csv, "area_fraction");
        const int pi = column(csv, "contact_pressure_per_Eprime");
        ASSERT_EQ(csv.rows.size(), 9U);
        const auto model = makeContactModel(name, s, mat);
        double previousArea = 0.0;
        for (std::size_t k = 0; k < csv.rows.size(); ++k) {
            const double load = std::stod(csv.rows[k].at(li));
            const double area = std::stod(csv.rows[k].at(ai));
            // Log spacing: load_k = 1e-6 * 10^(4k/8).
            EXPECT_NEAR(load, 1e-6 * std::pow(10.0, 0.5 * double(k)), 1e-9 * load);
            EXPECT_NEAR(area, model->areaFraction(load), 1e-9 * area + 1e-300);
            EXPECT_GE(area, previousArea);
            EXPECT_LE(area, 1.0);
            previousArea = area;
            EXPECT_NEAR(std::stod(csv.rows[k].at(pi)), load / area, 1e-9 * load / area);
        }
    }
}

TEST(Cli, LevelTraceSumsToTheArea)
{
    // Seed Eq. 4/5: the area at the last level is the model's answer A_r/A_n; each level's area
    // is at most the previous one's (a_i = A_i/A_{i-1} <= 1 once capped).
    const CommandResult curve = run("--profile '" + standin + "' --model hertz" + steel + " --loads 7.94e-5");
    const CommandResult trace =
        run("--profile '" + standin + "' --model hertz" + steel + " --loads 7.94e-5 --levels");
    ASSERT_EQ(curve.status, 0) << curve.err;
    ASSERT_EQ(trace.status, 0) << trace.err;
    const Csv c = parseCsv(curve.out);
    const Csv t = parseCsv(trace.out);
    ASSERT_GT(t.rows.size(), 100U);
    const int ai = column(t, "area_fraction");
    double previous = 1.0;
    for (const auto& row : t.rows) {
        const double a = std::stod(row.at(ai));
        EXPECT_LE(a, previous * (1 + 1e-9));
        previous = a;
    }
    EXPECT_NEAR(previous, std::stod(c.rows.at(0).at(column(c, "area_fraction"))), 1e-9 * previous);
}

TEST(Cli, ConductanceColumnIsTheLibrarys)
{
    // --conductance adds h_per_k = h_c/k_s [1/m] of the default law (fittedElastoPlastic on the
    // profile's roughness, capped at H = 2.84 S_y); the CLI prints the library's value to 10 digits.
    const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                " --loads 1e-6,1e-4,1e-3 --conductance");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    const int hi = column(csv, "h_per_k");
    const Spectrum s = Spectrum::fromProfile(readProfile(standin));
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    const MultiscaleModel m(s, mat.reducedModulus(), makeAsperityModel("jacksonGreen", mat));
    ASSERT_EQ(csv.rows.size(), 3U);
    const int sep = column(csv, "separation");
    for (const auto& row : csv.rows) {
        const double load = std::stod(row.at(0));
        const double expected = fittedElastoPlasticConductancePerConductivity(
            load * mat.reducedModulus(), profileRoughness(readProfile(standin)), spectralBandwidthRatio(s),
            mat.reducedModulus(), 2.84 * 0.2e9, 0.0, firstLevelShare(s));
        EXPECT_NEAR(std::stod(row.at(hi)), expected, 1e-9 * expected);
        EXPECT_EQ(row.at(sep), ""); // neither the multi-scale model nor the law defines a mean separation
    }
    // The multi-scale laws need the multi-scale levels; the default law does not.
    expectError("--profile '" + standin + "' --model greenwoodWilliamson" + steel +
                    " --loads 1e-4 --conductance-law jacksonBhavnaniFerguson",
                {"--conductance"});
    EXPECT_EQ(run("--profile '" + standin + "' --model greenwoodWilliamson" + steel + " --loads 1e-4 --conductance")
                  .status,
              0);
}

// The stand-in under jacksonGreen on steel, as the CLI builds it, and every conductance law's
// inputs from it (the microhardness from --hardness-from-yield).
struct StandinLaws {
    Profile profile = readProfile(standin);
    Spectrum spectrum = Spectrum::fromProfile(profile);
    ContactMaterials materials = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    MultiscaleModel model{spectrum, materials.reducedModulus(), makeAsperityModel("jacksonGreen", materials)};
    ConductanceLawInputs inputs() const
    {
        ConductanceLawInputs in;
        in.multiscale = &model;
        in.spectrum = &spectrum;
        in.roughness = profileRoughness(profile);
        in.Eprime = materials.reducedModulus();
        in.microhardness = materials.hardness("--hardness-from-yield");
        in.hardness = conductanceLawHardness(in.microhardness, materials); // fittedElastoPlastic's cap
        return in;
    }
};

TEST(Cli, ConductanceLawColumnIsTheLibrarys)
{
    // --conductance-law NAME: the h_per_k column is the library's law, built from the same
    // surface (its sigma and m from the profile's heights), for every law, to 10 digits; the
    // separation column the law's mean separation where it has one (persson, multiscaleBarber),
    // else empty.
    const StandinLaws standinLaws;
    const ContactMaterials& mat = standinLaws.materials;
    const ConductanceLawInputs in = standinLaws.inputs();
    for (const std::string& name : conductanceLawNames()) {
        const std::string extra = name == "cooperMikicYovanovich" ? " --hardness-from-yield" : "";
        const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                    " --loads 1e-6,1e-4,1e-3 --conductance-law " + name + extra);
        ASSERT_EQ(r.status, 0) << name << ": " << r.err;
        const Csv csv = parseCsv(r.out);
        const int hi = column(csv, "h_per_k");
        const int sep = column(csv, "separation");
        const auto law = makeConductanceLaw(name, in);
        ASSERT_EQ(csv.rows.size(), 3U);
        for (const auto& row : csv.rows) {
            const double load = std::stod(row.at(0));
            const double expected = law->perConductivity(load * mat.reducedModulus());
            EXPECT_NEAR(std::stod(row.at(hi)), expected, 1e-9 * expected) << name << " at " << load;
            const double Y = law->meanSeparation(load * mat.reducedModulus());
            if (name == "persson" || name == "multiscaleBarber") {
                ASSERT_GT(Y, 0.0) << name;
                EXPECT_NEAR(std::stod(row.at(sep)), Y, 1e-9 * Y) << name << " at " << load;
            } else {
                EXPECT_EQ(row.at(sep), "") << name;
            }
        }
    }
    // The correlations work with any area model; the default law needs a multi-scale one.
    const CommandResult gw = run("--profile '" + standin + "' --model greenwoodWilliamson" + steel +
                                 " --loads 1e-4 --conductance-law mikic");
    EXPECT_EQ(gw.status, 0) << gw.err;
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel +
                    " --loads 1e-4 --conductance-law cooperMikicYovanovich",
                {"--hardness", "--vickers"});
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --loads 1e-4 --conductance-law holm",
                {"holm", "mikic"});
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --loads 1e-4 --hardness 1e9",
                {"--hardness", "cooperMikicYovanovich"});
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel +
                    " --loads 1e-4 --conductance-law cooperMikicYovanovich --vickers 5e9",
                {"--vickers", "two values"});
    // The rules of the specification (InterfaceSpec::checkEntries), as the condition's: --vickers
    // beside the default law, which it does not change; with all it is cooperMikicYovanovich's.
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --loads 1e-4 --conductance --vickers 5e9,-0.2",
                {"--vickers", "is for the conductance law cooperMikicYovanovich, not " + defaultConductanceLaw()});
    const CommandResult all = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                  " --loads 1e-4 --conductance-law all --vickers 5e9,-0.2");
    EXPECT_EQ(all.status, 0) << all.err;
    EXPECT_GE(column(parseCsv(all.out), "h_per_k_cooperMikicYovanovich"), 0);
    // --hardness with the default law is its cap H (conductanceLawHardness), as the condition's
    // microhardness: taken, and it changes h where the cap binds (a load near 0.1 H/E').
    const std::string capped = "--profile '" + standin + "' --model jacksonGreen" + steel + " --loads 1e-3 --conductance";
    const CommandResult sy = run(capped);
    const CommandResult soft = run(capped + " --hardness 5e8");
    ASSERT_EQ(sy.status, 0) << sy.err;
    ASSERT_EQ(soft.status, 0) << soft.err;
    const auto hOf = [](const CommandResult& r) {
        const Csv csv = parseCsv(r.out);
        return std::stod(csv.rows.at(0).at(column(csv, "h_per_k")));
    };
    EXPECT_NE(hOf(sy), hOf(soft)) << "--hardness did not reach the default law's cap";
}

TEST(Cli, EveryConductanceLawSideBySide)
{
    // --conductance-law all: one h_per_k_NAME column per law, each the library's law (10
    // digits), h_per_k the default's; a law that cannot be built here (no microhardness; a
    // model that is not multi-scale) has no column, and stderr says why.
    const StandinLaws standinLaws;
    const ContactMaterials& mat = standinLaws.materials;
    const ConductanceLawInputs in = standinLaws.inputs();
    const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                " --loads 1e-5,1e-4 --conductance-law all --hardness-from-yield");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 2U);
    for (const std::string& name : conductanceLawNames()) {
        const int c = column(csv, "h_per_k_" + name);
        const auto law = makeConductanceLaw(name, in);
        for (const auto& row : csv.rows) {
            const double load = std::stod(row.at(0));
            const double expected = law->perConductivity(load * mat.reducedModulus());
            EXPECT_NEAR(std::stod(row.at(c)), expected, 1e-9 * expected) << name;
            if (name == defaultConductanceLaw()) {
                EXPECT_EQ(row.at(column(csv, "h_per_k")), row.at(c));
            }
        }
    }
    const CommandResult gw = run("--profile '" + standin + "' --model greenwoodWilliamson" + steel +
                                 " --loads 1e-4 --conductance-law all");
    ASSERT_EQ(gw.status, 0) << gw.err;
    EXPECT_EQ(gw.out.substr(0, gw.out.find('\n')),
              "nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime,separation,h_per_k,"
              "h_per_k_persson,h_per_k_mikic,h_per_k_fittedElastoPlastic");
    EXPECT_NE(gw.err.find("no column for jacksonBhavnaniFerguson"), std::string::npos) << gw.err;
    EXPECT_NE(gw.err.find("no column for cooperMikicYovanovich"), std::string::npos) << gw.err;
}

TEST(Cli, PerssonFillsEveryConductanceColumn)
{
    // --model persson --conductance: nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime,separation,h_per_k all filled, each the
    // library's PerssonModel::evaluate to the 10 digits printed (relative 1e-9).
    const CommandResult r = run("--profile '" + standin + "' --model persson" + steel +
                                " --loads 1e-6,1e-4,1e-3,1e-2 --conductance");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    const Spectrum s = Spectrum::fromProfile(readProfile(standin));
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    const PerssonModel m(s, mat.reducedModulus());
    ASSERT_EQ(csv.rows.size(), 4U);
    for (const auto& row : csv.rows) {
        const double load = std::stod(row.at(column(csv, "nominal_pressure_per_Eprime")));
        const PerssonPoint p = m.evaluate(load);
        EXPECT_NEAR(std::stod(row.at(column(csv, "area_fraction"))), p.areaFraction, 1e-9 * p.areaFraction);
        EXPECT_NEAR(std::stod(row.at(column(csv, "contact_pressure_per_Eprime"))), load / p.areaFraction,
                    1e-9 * load / p.areaFraction);
        EXPECT_NEAR(std::stod(row.at(column(csv, "separation"))), p.meanSeparation, 1e-9 * p.meanSeparation);
        EXPECT_NEAR(std::stod(row.at(column(csv, "h_per_k"))), p.conductancePerConductivity,
                    1e-9 * p.conductancePerConductivity);
    }
    // Without --conductance: the usual three columns.
    const CommandResult plain = run("--profile '" + standin + "' --model persson" + steel + " --loads 1e-4");
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(plain.out.substr(0, plain.out.find('\n')), "nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime");
}

TEST(Cli, SurfaceDescriptions)
{
    // A power law and the spectrum table that lists the same levels give the same curve.
    TempDir dir;
    const double L = 1e-3;
    std::ostringstream table;
    table << "# frequency [1/m], amplitude [m]\n";
    table.precision(17);
    for (int i = 1; i <= 200; ++i) {
        const double f = i / L;
        table << f << ',' << 1e-7 * std::pow(f / 1e3, -1.2) << '\n';
    }
    const auto path = dir.write("spectrum.csv", table.str());
    const CommandResult a =
        run("--spectrum '" + path.string() + "' --model jacksonGreen" + steel + " --loads 1e-4");
    std::ostringstream bm;
    bm.precision(17);
    bm << 1e-7 * std::pow(1e3, 1.2);
    const CommandResult b =
        run("--power-law " + bm.str() + ",1.2,1000,200000 --length 1e-3 --model jacksonGreen" + steel +
            " --loads 1e-4");
    ASSERT_EQ(a.status, 0) << a.err;
    ASSERT_EQ(b.status, 0) << b.err;
    const double areaA = std::stod(parseCsv(a.out).rows.at(0).at(1));
    const double areaB = std::stod(parseCsv(b.out).rows.at(0).at(1));
    // Both describe the same 200 levels to 17 digits; the CLI prints 10 digits.
    EXPECT_NEAR(areaA, areaB, 1e-9 * areaA);
    EXPECT_GT(areaA, 0.0);
}

TEST(Cli, ArealSurfaceIsTheLibrarys)
{
    // --areal on the real X3P map: the CLI's curve is the core's (SurfaceSpec::Kind::areal, as
    // the boundary condition builds it, and lineScanSpectrum of the detrended map read by
    // readX3p) for each direction, to the 10 digits printed; without --direction, both.
    const std::string x3p = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p";
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    const ArealSurface map = readX3p(x3p);
    for (const std::string direction : {"x", "y", "both"}) {
        SCOPED_TRACE(direction);
        SurfaceSpec spec;
        spec.kind = SurfaceSpec::Kind::areal;
        spec.file = x3p;
        spec.direction = parseScanDirection(direction);
        const Spectrum s = spec.spectrum();
        const Spectrum direct = lineScanSpectrum(map.detrended(), parseScanDirection(direction));
        ASSERT_EQ(s.amplitudes(), direct.amplitudes());
        const auto model = makeContactModel("jacksonGreen", s, mat);
        // both is the default (the direction the engineering range's bands are measured with).
        const std::string flag = direction == "both" ? "" : " --direction " + direction;
        const CommandResult r = run("--areal '" + x3p + "'" + flag + " --model jacksonGreen" + steel +
                                    " --load-range 1e-5:1e-2:4");
        ASSERT_EQ(r.status, 0) << r.err;
        const Csv csv = parseCsv(r.out);
        ASSERT_EQ(csv.rows.size(), 4U);
        for (const auto& row : csv.rows) {
            const double load = std::stod(row.at(0));
            const double area = std::stod(row.at(1));
            EXPECT_GT(area, 0.0);
            EXPECT_NEAR(area, model->areaFraction(load), 1e-9 * area);
        }
    }
    // The same heights as a text matrix in nanometres (--dx, --dy, --units) give the same curve.
    TempDir dir;
    std::ostringstream text;
    text.precision(17);
    for (std::size_t iy = 0; iy < map.ny(); ++iy) {
        for (std::size_t ix = 0; ix < map.nx(); ++ix) {
            text << (ix ? " " : "") << map.at(ix, iy) * 1e9;
        }
        text << "\n";
    }
    const auto matrix = dir.write("map.txt", text.str());
    std::ostringstream spacing;
    spacing.precision(17);
    spacing << " --units nm --dx " << map.dx() * 1e9 << " --dy " << map.dy() * 1e9;
    const CommandResult a =
        run("--areal '" + x3p + "' --direction both --model hertz" + steel + " --loads 1e-3");
    const CommandResult b = run("--areal '" + matrix.string() + "'" + spacing.str() +
                                " --direction both --model hertz" + steel + " --loads 1e-3");
    ASSERT_EQ(a.status, 0) << a.err;
    ASSERT_EQ(b.status, 0) << b.err;
    const double areaA = std::stod(parseCsv(a.out).rows.at(0).at(1));
    EXPECT_NEAR(areaA, std::stod(parseCsv(b.out).rows.at(0).at(1)), 1e-8 * areaA);

    expectError("--areal '" + x3p + "' --dx 1e-6 --model hertz" + steel + " --loads 1e-3", {"dx", "X3P"});
    expectError("--areal '" + matrix.string() + "' --model hertz" + steel + " --loads 1e-3", {"dx"});
    expectError("--areal '" + matrix.string() + "' --dx 1 --fill-invalid --model hertz" + steel +
                    " --loads 1e-3",
                {"fillInvalid"});
    expectError("--areal '" + x3p + "' --direction z --model hertz" + steel + " --loads 1e-3",
                {"--direction", "'z'"});
    expectError("--areal '" + x3p + "' --stride 2 --model hertz" + steel + " --loads 1e-3", {"--stride"});
    expectError("--profile '" + standin + "' --direction y --model hertz" + steel + " --loads 1e-3",
                {"--direction"});
    expectError("--profile '" + standin + "' --dy 1 --model hertz" + steel + " --loads 1e-3", {"--dy"});
    expectError("--profile '" + standin + "' --fill-invalid --model hertz" + steel + " --loads 1e-3",
                {"--fill-invalid"});
}

TEST(Cli, ErrorPaths)
{
    const std::string p = "--profile '" + standin + "'";
    expectError("--profile /no/such/file.csv --model hertz --Eprime 2e11 --loads 1e-4",
                {"/no/such/file.csv"});
    expectError(p + " --model nosuchmodel --Eprime 2e11 --loads 1e-4", {"nosuchmodel"});
    expectError(p + " --model hertz --Eprime 2e11", {"--loads"});
    expectError(p + " --model hertz --E 2e11 --loads 1e-4", {"--nu"});
    expectError(p + " --model hertz --E -2e11 --nu 0.3 --loads 1e-4", {"E"});
    expectError(p + " --model hertz --E 2e11 --nu 0.3 --Eprime 2e11 --loads 1e-4", {"--Eprime"});
    expectError(p + " --model hertz --Eprime 2e11 --loads -1e-4", {"load"});
    expectError(p + " --model hertz --Eprime 2e11 --loads 1e-4,abc", {"--loads"});
    expectError(p + " --model hertz --Eprime 2e11 --load-range 1e-2:1e-4:10", {"--load-range"});
    expectError(p + " --model hertz --Eprime 2e11 --load-range 1e-4:1e-2", {"--load-range"});
    expectError(p + " --model hertz --Eprime 2e11 --loads 1e-4 --load-range 1e-4:1e-2:3", {"--load-range"});
    expectError(p + " --model jacksonGreen --E 2e11 --nu 0.3 --loads 1e-4", {"S_y"});
    expectError(p + " --model truncation --E 2e11 --nu 0.3 --loads 1e-4", {"S_y"});
    expectError(p + " --model greenwoodWilliamson --Eprime 2e11 --loads 1e-4 --levels", {"--levels"});
    expectError(p + " --model majumdarBhushan --Eprime 2e11 --Sy 2e8 --D 1.5 --loads 1e-4", {"--D/--G"});
    expectError(p + " --spectrum '" + standin + "' --model hertz --Eprime 2e11 --loads 1e-4", {"Exactly 1"});
    expectError(
        "--power-law 1e-4,1.2,1e3,1e6 --length 1e-3 --stride 2 --model hertz --Eprime 2e11 --loads 1e-4",
        {"--stride"});
    expectError(p + " --units furlong --model hertz --Eprime 2e11 --loads 1e-4", {"furlong"});

    // A bad file: the message names the file and the line.
    TempDir dir;
    const auto bad = dir.write("bad.csv", "x,z\n0,1\n1,2\n2,oops\n3,4\n4,5\n5,6\n6,7\n7,8\n8,9\n");
    expectError("--profile '" + bad.string() + "' --model hertz --Eprime 2e11 --loads 1e-4",
                {bad.string(), ":4:"});
    const auto nan = dir.write("nan.csv", "0,1\n1,2\n2,3\n3,nan\n4,5\n5,6\n6,7\n7,8\n8,9\n");
    expectError("--profile '" + nan.string() + "' --model hertz --Eprime 2e11 --loads 1e-4",
                {nan.string(), ":4:"});
    const auto shortFile = dir.write("short.csv", "0,1\n1,2\n2,3\n");
    expectError("--profile '" + shortFile.string() + "' --model hertz --Eprime 2e11 --loads 1e-4",
                {shortFile.string(), "8"});
}

TEST(Cli, BadInputFoundByAHostileUser)
{
    // Each was accepted, printed nonsense, or exited with CLI11's own codes (104-114).
    const std::string p = "--profile '" + standin + "'";
    const std::string hertz = " --model hertz --Eprime 2e11";
    expectError(p + hertz + " --loads ''", {"--loads", "empty value"}); // was: load 0
    expectError(p + hertz + " --loads 1e-4,", {"--loads", "empty item"});
    expectError(p + hertz + " --loads 1e-4 --units ''", {"--units", "empty value"}); // was: accepted
    // CLI11 writes the range "1 to 1000000000" (Debian 12) or "[1 - 1000000000]" (Debian 13).
    expectError(p + hertz + " --loads 1e-4 --stride 0", {"--stride: Value 0 not in range", "1000000000"}); // was: 300 digits
    expectError(p + hertz + " --loads 1e-4 --no-such-option", {"--no-such-option"});    // was: exit 109
    expectError(p + " --model nosuchmodel --Eprime 2e11 --loads 1e-4", {"nosuchmodel"}); // was: exit 105
    expectError("--fractal 1.5,1e-9,10,1" + hertz + " --loads 1e-4", {"fractal"}); // was: "power law"
    // A_n out of range: was "-nan" and exit 0, or area 0.
    for (const char* dx : {"1e-300", "1e-150", "1e300"}) {
        TempDir dir;
        const auto z = dir.write("z.csv", "1\n2\n3\n2\n1\n2\n3\n4\n3\n2\n");
        expectError("--profile '" + z.string() + "' --dx " + dx + hertz + " --loads 1e-4", {"spacing", "must lie within"});
    }
    expectError("--power-law 1e-8,1,1,10 --length 1e300" + hertz + " --loads 1e-4", {"length"});
    // Rows were printed before the failing load: now nothing reaches stdout.
    expectError(p + hertz + " --load-range 1e-300:1e300:5", {"load", "1e-300"});
    expectError(p + hertz + " --loads 1e-4,1e-3,1e300", {"load", "1e+300"});
    // A surface too large for the cap: the count and the memory in the message.
    expectError("--power-law 1e-8,1,1,1e9" + hertz + " --loads 1e-4", {"1e+09 frequency levels", "MB"});
    // --units with a surface in metres: was accepted and ignored (a spectrum in um read as m).
    expectError("--power-law 1e-8,1,1e3,1e5" + hertz + " --units um --loads 1e-4", {"--units", "metres"});
    // Materials outside the fitted range: was SIGFPE under OpenFOAM, area 0 here.
    expectError(p + " --model jacksonGreen --E 2e11 --nu 0.3 --Sy 1e65 --loads 1e-4", {"S_y/E"});
    // Help is not an error.
    EXPECT_EQ(run("--help").status, 0);
}

TEST(Cli, BoundaryElementIsTheLibrarys)
{
    const std::string p0 = "--profile '" + standin + "'";
    // --model boundaryElement on a surface synthesized from the stand-in: the CLI's columns are
    // the library's BoundaryElementModel on synthesizeIsotropic of the same spectrum and seed.
    const CommandResult r = run("--profile '" + standin + "' --synthesize 64,7 --model boundaryElement" + steel +
                                " --loads 1e-4,1e-3");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 2U);
    const Spectrum s = Spectrum::fromProfile(readProfile(standin));
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    BoundaryElementOptions o;
    o.periodic = true;
    const BoundaryElementModel m(synthesizeIsotropic(s, 64, 7), mat.reducedModulus(), o);
    for (const auto& row : csv.rows) {
        const BoundaryElementPoint p = m.solve(std::stod(row.at(0)));
        // Cold solves here, warm starts in the CLI's curve: the same solution to the solver's
        // tolerance (1e-8), printed to 10 digits; the contact set may differ by a cell.
        EXPECT_NEAR(std::stod(row.at(column(csv, "area_fraction"))), p.areaFraction, 2.0 / (64 * 64));
        const double h = std::stod(row.at(column(csv, "h_per_k")));
        EXPECT_NEAR(h, p.conductancePerConductivity, 1e-3 * p.conductancePerConductivity);
        EXPECT_NEAR(std::stod(row.at(column(csv, "separation"))), p.meanSeparation, 1e-3 * p.meanSeparation);
        EXPECT_GT(std::stod(row.at(column(csv, "iterations"))), 0.0);
        EXPECT_LE(std::stod(row.at(column(csv, "residual"))), 1e-8);
        // The contact set's spots (ContactSpots): a cell that differs may make or join a spot,
        // so the count is held to within one and the mean radius where the counts agree, to 1 %:
        // a cell more or less moves one spot's radius by at most 41 % (one cell to two), the mean
        // of this surface's 46 and 160 spots by under 1 %. Here the cold and warm solves give
        // the same set: equal to the digits printed.
        const double spots = std::stod(row.at(column(csv, "spots")));
        EXPECT_GT(spots, 0.0);
        EXPECT_NEAR(spots, double(p.spots.count), 1.0);
        if (spots == double(p.spots.count)) {
            EXPECT_NEAR(std::stod(row.at(column(csv, "mean_spot_radius"))), p.spots.meanRadius(),
                        1e-2 * p.spots.meanRadius());
        }
    }
    // --pressure-map: the field at the highest load, a matrix the areal reader reads back,
    // whose mean is the nominal pressure F/A_n = load E' (to the solver's load balance, 1e-9).
    {
        TempDir dir;
        const std::string map = (dir.path() / "p.txt").string();
        const CommandResult pm = run("--profile '" + standin + "' --synthesize 32,7 --model boundaryElement" +
                                     steel + " --loads 1e-4,1e-3 --pressure-map '" + map + "'");
        ASSERT_EQ(pm.status, 0) << pm.err;
        ArealReadOptions ro; // read as a height map in nm (so that GPa stay within its +-1 km)
        ro.dx = 1.0; // 1 nm
        ro.units = LengthUnit::nm;
        const ArealSurface field = readAreal(map, ro);
        ASSERT_EQ(field.nx(), 32U);
        double mean = 0.0;
        for (double v : field.heights()) {
            EXPECT_GE(v, 0.0);
            mean += 1e9 * v / double(field.heights().size());
        }
        EXPECT_NEAR(mean, 1e-3 * mat.reducedModulus(), 1e-6 * 1e-3 * mat.reducedModulus());
        expectError(p0 + " --model hertz" + steel + " --loads 1e-4 --pressure-map '" + map + "'", {"--pressure-map"});
    }
    // A hardness cap below the pressure: complete contact, h infinite.
    const CommandResult full = run("--profile '" + standin + "' --synthesize 32 --model boundaryElement" + steel +
                                   " --hardness 1e6 --loads 1e-3");
    ASSERT_EQ(full.status, 0) << full.err;
    EXPECT_EQ(parseCsv(full.out).rows.at(0).at(1), "1");
    EXPECT_EQ(parseCsv(full.out).rows.at(0).at(4), "inf");
    // Its errors.
    const std::string p = "--profile '" + standin + "'";
    expectError(p + " --model boundaryElement" + steel + " --loads 1e-4", {"--areal", "--synthesize"});
    expectError(p + " --synthesize 64 --model hertz" + steel + " --loads 1e-4", {"--synthesize", "boundaryElement"});
    expectError(p + " --model hertz --periodic" + steel + " --loads 1e-4", {"--periodic"});
    expectError(p + " --synthesize 63 --model boundaryElement" + steel + " --loads 1e-4", {"n"});
    expectError(p + " --synthesize 64,x --model boundaryElement" + steel + " --loads 1e-4", {"--synthesize"});
    expectError(p + " --synthesize 64 --model boundaryElement --Eprime 2e11 --hardness-from-yield --loads 1e-4",
                {"S_y"});
    expectError(p + " --synthesize 64 --model boundaryElement" + steel + " --loads 1e-4 --levels", {"--levels"});
}

TEST(Cli, UnloadFromAddsTheJointThatCarriedThePeak)
{
    // --unload-from PMAX: the columns unloading_area_fraction and unloading_h_per_k are the
    // library's loadPath from PMAX on the same surface (to the solver's tolerance, as the loading
    // columns); at PMAX itself they are the loading point's, below it the flattened summits keep
    // more contact and conduct more. The stand-in on steel against a rigid flat, capped at
    // 2.84 S_y = 568 MPa.
    const std::string p = "--profile '" + standin + "' --synthesize 64,7 --model boundaryElement" + steel;
    const CommandResult r = run(p + " --hardness-from-yield --pressures 20MPa,60MPa,200MPa --unload-from 200MPa");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 3U);
    const Spectrum s = Spectrum::fromProfile(readProfile(standin));
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    BoundaryElementOptions o;
    o.periodic = true;
    o.hardness = mat.hardness("test");
    const BoundaryElementModel m(synthesizeIsotropic(s, 64, 7), mat.reducedModulus(), o);
    const std::vector<double> loads{20e6 / mat.reducedModulus(), 60e6 / mat.reducedModulus(),
                                    200e6 / mat.reducedModulus()};
    const std::vector<BoundaryElementPoint> path = m.loadPath(loads[2], loads);
    for (std::size_t i = 0; i < 3; ++i) {
        const auto value = [&](const char* name) { return std::stod(csv.rows[i].at(column(csv, name))); };
        EXPECT_NEAR(value("unloading_area_fraction"), path[i].areaFraction, 2.0 / (64 * 64));
        EXPECT_NEAR(value("unloading_h_per_k"), path[i].conductancePerConductivity,
                    1e-3 * path[i].conductancePerConductivity);
        // The same load path as the library's: its spots to the digit printed.
        EXPECT_EQ(value("unloading_spots"), double(path[i].spots.count));
        EXPECT_NEAR(value("unloading_mean_spot_radius"), path[i].spots.meanRadius(),
                    1e-9 * path[i].spots.meanRadius());
        if (i < 2) {
            EXPECT_GT(value("unloading_h_per_k"), value("h_per_k"));
        } else {
            EXPECT_NEAR(value("unloading_h_per_k"), value("h_per_k"), 1e-3 * value("h_per_k"));
        }
    }
    // Its errors: no cap, the peak at or above it, a model without an unloading curve, --levels,
    // --check.
    expectError("--profile '" + standin + "' --synthesize 32 --model boundaryElement --Eprime 2e11 --loads 1e-4 "
                "--unload-from 1MPa",
                {"--unload-from", "--hardness"});
    expectError(p + " --hardness-from-yield --loads 1e-4 --unload-from 1GPa", {"--unload-from", "below the cap"});
    expectError("--profile '" + standin + "' --model persson" + steel + " --loads 1e-4 --unload-from 1MPa",
                {"--unload-from", "persson has no unloading curve"});
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --conductance-law mikic --loads 1e-4 "
                "--unload-from 1MPa",
                {"--unload-from", "mikic has no unloading branch"});
    expectError("--profile '" + standin + "' --model hertz --E 179.52e9 --nu 0.32 --conductance --loads 1e-4 "
                "--unload-from 1MPa",
                {"--unload-from", "fittedElastoPlastic has no unloading branch without a cap"});
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --loads 1e-4 --levels "
                "--unload-from 1MPa",
                {"--unload-from", "--levels"});
    expectError("--profile '" + standin + "' --model hertz --E 179.52e9 --nu 0.32 --check --loads 1e-4 "
                "--unload-from 1MPa",
                {"--unload-from", "hardness"});
}

TEST(Cli, UnloadFromGivesTheUnloadedJointsGap)
{
    // With a gas and radiation the unloaded joint's gap is taken at its own mean separation
    // (unloading_separation): the same gap columns (h_gas, h_radiation) as the loading curve's at
    // that separation, so equal at the peak; below it the flattened summits sit closer, the gas
    // conducts more, and unloading_h_total is their sum with unloading_h. The rows' own load curve
    // at each row's unloading separation is the reference: the same run with --gap-width Y at
    // load 0 gives the gap at Y (InterfaceGap::conductances depends on Y and T alone).
    const std::string p = "--profile '" + standin + "' --synthesize 64,7 --model boundaryElement" + steel +
                          " --hardness-from-yield --k1 50 --k2 50 --gas air --gas-pressure 1e5 --emissivity 0.3,0.3 "
                          "--temperature 400,300";
    const CommandResult r = run(p + " --pressures 20MPa,60MPa,200MPa --unload-from 200MPa");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 3U);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        const auto value = [&](const char* name) { return std::stod(csv.rows[i].at(column(csv, name))); };
        EXPECT_NEAR(value("unloading_h_total"),
                    value("unloading_h") + value("unloading_h_gas") + value("unloading_h_radiation"),
                    1e-9 * value("unloading_h_total"));
        EXPECT_EQ(csv.rows[i].at(column(csv, "unloading_h_radiation")), csv.rows[i].at(column(csv, "h_radiation")));
        if (i < 2) {
            EXPECT_LT(value("unloading_separation"), value("separation"));
            EXPECT_GT(value("unloading_h_gas"), value("h_gas"));
        } else {
            EXPECT_NEAR(value("unloading_h_gas"), value("h_gas"), 1e-3 * value("h_gas"));
        }
        // The gas at the unloaded separation Y: the gap of faces apart by Y (load 0, --gap-width).
        const std::string Y = csv.rows[i].at(column(csv, "unloading_separation"));
        const CommandResult apart = run(p + " --loads 0 --gap-width " + Y);
        ASSERT_EQ(apart.status, 0) << apart.err;
        const Csv a = parseCsv(apart.out);
        EXPECT_NEAR(std::stod(a.rows[0].at(column(a, "h_gas"))), value("unloading_h_gas"), 1e-8 * value("unloading_h_gas"));
    }
}

TEST(Cli, UnloadFromGivesAMultiscaleModelsUnloadingArea)
{
    // A multi-scale model's unloading area (docs/theory.md §3.6) is the library's, to the 10
    // digits the CLI prints; hertz unloads along its loading curve.
    for (const char* model : {"jacksonGreen", "hertz"}) {
        SCOPED_TRACE(model);
        const CommandResult r = run("--profile '" + standin + "' --model " + model + steel +
                                    " --pressures 1MPa,10MPa,30MPa --unload-from 30MPa");
        ASSERT_EQ(r.status, 0) << r.err;
        const Csv csv = parseCsv(r.out);
        ASSERT_EQ(csv.rows.size(), 3U);
        const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
        const Spectrum s = Spectrum::fromProfile(readProfile(standin));
        const auto m = makeContactModel(model, s, mat, {});
        const auto& ms = dynamic_cast<const MultiscaleModel&>(*m);
        const double Ep = mat.reducedModulus();
        for (std::size_t i = 0; i < 3; ++i) {
            const double P = std::stod(csv.rows[i].at(column(csv, "nominal_pressure")));
            EXPECT_EQ(csv.rows[i].at(column(csv, "unloading_area_fraction")),
                      formatNumber(ms.unloadingAreaFraction(P / Ep, 30e6 / Ep), 10));
        }
        if (std::string(model) == "hertz") {
            EXPECT_EQ(csv.rows[0].at(column(csv, "unloading_area_fraction")), csv.rows[0].at(column(csv, "area_fraction")));
        }
    }
}

TEST(Cli, UnloadFromGivesTheDefaultLawsUnloadingBranch)
{
    // With a conductance the default law's unloading branch (docs/theory.md §5.7c) stands beside
    // the loading h: the law's h at P times its unloading factor from the peak, to the 10 digits
    // the CLI prints; above the loading h below the peak, equal to it at and above the peak.
    const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                " --conductance --k1 50 --k2 50 --pressures 1MPa,10MPa,30MPa,40MPa --unload-from 30MPa");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 4U);
    const double Ep = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9}).reducedModulus();
    const double m = profileRoughness(readProfile(standin)).meanAbsoluteSlope;
    const std::optional<double> Hf = fineHurstExponent(Spectrum::fromProfile(readProfile(standin)));
    const double W = spectralBandwidthRatio(Spectrum::fromProfile(readProfile(standin)));
    ASSERT_TRUE(Hf.has_value());
    for (std::size_t i = 0; i < 4; ++i) {
        const double P = std::stod(csv.rows[i].at(column(csv, "nominal_pressure")));
        SCOPED_TRACE(P);
        // h_per_k as printed (10 digits) times the factor: within the printing's rounding.
        const double loading = std::stod(csv.rows[i].at(column(csv, "h_per_k")));
        const double hk = loading * fittedUnloadingFactor(P, 30e6, m, W, Ep, 2.84 * 0.2e9, Hf);
        const double printed = std::stod(csv.rows[i].at(column(csv, "unloading_h_per_k")));
        EXPECT_NEAR(printed, hk, 2e-9 * hk);
        EXPECT_NEAR(std::stod(csv.rows[i].at(column(csv, "unloading_h"))), 50.0 * printed, 2e-9 * 50.0 * printed);
        if (P < 30e6) {
            EXPECT_GT(hk, 1.05 * loading);
        } else {
            EXPECT_EQ(csv.rows[i].at(column(csv, "unloading_h_per_k")), csv.rows[i].at(column(csv, "h_per_k")));
        }
    }
    // stderr gives the branch's measured band at the peak's p/(E' h') (MeasuredAccuracy.hpp).
    const double x =
        30e6 / (Ep * arealRmsGradient(spectralMoments(Spectrum::fromProfile(readProfile(standin)))));
    const auto band = measuredUnloadingAccuracy(x, x);
    ASSERT_TRUE(band.has_value()) << "a peak at p/(E' h') = " << x;
    EXPECT_NE(r.err.find("unloading_h_per_k is h_per_k times fittedElastoPlastic's unloading branch R; " +
                         describeUnloadingAccuracy(band, x, x)),
              std::string::npos)
        << r.err;
    // With a gas the law's unloaded joint keeps the gap of the moment, as the condition does
    // (ContactInterface::loadHistoryNote): unloading_h_total = unloading_h + h_gas + h_radiation.
    const CommandResult g = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                " --conductance --k1 50 --k2 50 --pressures 1MPa,10MPa,30MPa --unload-from 30MPa "
                                "--gas air --gas-pressure 1e5 --temperature 300");
    ASSERT_EQ(g.status, 0) << g.err;
    const Csv gc = parseCsv(g.out);
    ASSERT_EQ(gc.rows.size(), 3U);
    for (std::size_t i = 0; i < 3; ++i) {
        const auto value = [&](const char* name) { return std::stod(gc.rows[i].at(column(gc, name))); };
        EXPECT_NEAR(value("unloading_h_total"), value("unloading_h") + value("h_gas") + value("h_radiation"),
                    1e-9 * value("unloading_h_total"));
        EXPECT_NEAR(value("h_total") - value("h") + value("unloading_h"), value("unloading_h_total"),
                    1e-9 * value("unloading_h_total"));
    }
}

TEST(Cli, BoundaryElementInputsAHostileUserTried)
{
    const std::string p = "--profile '" + standin + "'";
    const std::string bem = " --model boundaryElement" + steel;
    // Issue 18, item 1: a hardness beyond any solid's is a unit mistake, refused with its range
    // (1e80 gave area 1 and h inf, 1e100 area 0, exit 0).
    for (const char* H : {"1e80", "1e100", "1e30", "1"}) {
        expectError(p + " --synthesize 16" + bem + " --hardness " + H + " --loads 1e-6",
                    {"--hardness: must lie within [1000 Pa, 1e+12 Pa]"});
    }
    // Item 11: N and SEED are whole numbers read as such: 2^64 was seed 0's surface (a double
    // converted to uint64_t), 1e20 as N "got 1000000000".
    expectError(p + " --synthesize 8,18446744073709551616" + bem + " --loads 1e-4",
                {"--synthesize", "the seed SEED 18446744073709551616 is beyond the largest"});
    expectError(p + " --synthesize 99999999999999999999" + bem + " --loads 1e-4",
                {"--synthesize", "99999999999999999999"});
    expectError(p + " --synthesize 8,1e3" + bem + " --loads 1e-4", {"--synthesize", "'1e3'"});
    expectError(p + " --synthesize 8,-1" + bem + " --loads 1e-4", {"--synthesize", "'-1'"});
    expectError(p + " --synthesize 8.5" + bem + " --loads 1e-4", {"--synthesize", "'8.5'"});
    expectError(p + " --synthesize 4" + bem + " --loads 1e-4", {"--synthesize", "within [8, 4096], got 4"});
    const CommandResult largest = run(p + " --synthesize 16,18446744073709551615" + bem + " --loads 1e-3");
    const CommandResult zero = run(p + " --synthesize 16,0" + bem + " --loads 1e-3");
    ASSERT_EQ(largest.status, 0) << largest.err;
    ASSERT_EQ(zero.status, 0) << zero.err;
    EXPECT_NE(largest.out, zero.out); // another seed, another surface
    // Issue 19, item 1: --detrend chooses what is removed before the solve (default: mean for a
    // periodic solve, plane for a map); it is for boundaryElement only.
    expectError(p + " --synthesize 16" + bem + " --detrend tilt --loads 1e-3", {"--detrend", "'tilt' is not a detrending"});
    expectError(p + " --model hertz --Eprime 2e11 --detrend mean --loads 1e-3", {"--detrend", "boundaryElement"});
    {
        const CommandResult byDefault = run(p + " --synthesize 16,3" + bem + " --loads 1e-3");
        const CommandResult mean = run(p + " --synthesize 16,3" + bem + " --detrend mean --loads 1e-3");
        const CommandResult plane = run(p + " --synthesize 16,3" + bem + " --detrend plane --loads 1e-3");
        ASSERT_EQ(plane.status, 0) << plane.err;
        EXPECT_EQ(byDefault.out, mean.out); // a synthesized surface is periodic: its mean only
        EXPECT_NE(byDefault.out, plane.out);
    }
    // Item 9: --pressure-map never replaces an input, and a failed run writes nothing.
    TempDir dir;
    const ArealSurface a = synthesizeIsotropic(Spectrum::fromProfile(readProfile(standin)), 16, 3);
    std::ostringstream matrix;
    matrix.precision(17);
    for (std::size_t iy = 0; iy < 16; ++iy) {
        for (std::size_t ix = 0; ix < 16; ++ix) {
            matrix << (ix ? " " : "") << a.at(ix, iy);
        }
        matrix << '\n';
    }
    const std::string input = dir.write("map.txt", matrix.str()).string();
    const std::string areal = "--areal '" + input + "' --dx 1e-6" + bem;
    expectError(areal + " --loads 1e-3 --pressure-map '" + input + "'", {"--pressure-map", "is an input of this run"});
    expectError(areal + " --loads 1e-3 --pressure-map '" + dir.path().string() + "/./map.txt'",
                {"--pressure-map", "is an input of this run"});
    {
        std::ifstream in(input);
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), matrix.str()) << "the input was changed";
    }
    expectError(areal + " --loads 1e-3 --pressure-map '" + dir.path().string() + "'", {"is a directory"});
    expectError(areal + " --loads 1e-3 --pressure-map '" + dir.path().string() + "/no/such/dir/p.txt'",
                {"cannot write into the directory"});
    const std::string out = (dir.path() / "p.txt").string();
    expectError(areal + " --hardness 1e80 --loads 1e-3 --pressure-map '" + out + "'", {"--hardness"});
    expectError(areal + " --loads 1e-3,1e300 --pressure-map '" + out + "'", {"load"});
    EXPECT_FALSE(std::filesystem::exists(out)) << "a failed run left " << out;
    const CommandResult ok = run(areal + " --loads 1e-3 --pressure-map '" + out + "'");
    ASSERT_EQ(ok.status, 0) << ok.err;
    EXPECT_TRUE(std::filesystem::exists(out));
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << "a temporary was left: " << entry.path();
    }
}

// Issue 20, items 1 and 5: --resample N[,K] solves the --synthesize'd surface put on N x N (and
// without its wavelengths shorter than L/K): the library's resampledPeriodic of the same surface.
TEST(Cli, ResampleIsTheLibrarysResampledSurface)
{
    const std::string p = "--profile '" + standin + "'";
    const std::string bem = " --model boundaryElement" + steel;
    const CommandResult r = run(p + " --synthesize 32,4 --resample 64,6" + bem + " --loads 1e-3");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 1U);
    const ContactMaterials mat = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    BoundaryElementOptions o;
    o.periodic = true;
    const ArealSurface coarse = synthesizeIsotropic(Spectrum::fromProfile(readProfile(standin)), 32, 4);
    const BoundaryElementPoint resampled =
        BoundaryElementModel(resampledPeriodic(coarse, 64, 6.0), mat.reducedModulus(), o).solve(1e-3);
    const BoundaryElementPoint asIs = BoundaryElementModel(coarse, mat.reducedModulus(), o).solve(1e-3);
    const double h = std::stod(csv.rows[0].at(column(csv, "h_per_k")));
    // To the solver's tolerance, printed to 10 digits (the same solve as the library's).
    EXPECT_NEAR(h, resampled.conductancePerConductivity, 1e-6 * h);
    EXPECT_NEAR(std::stod(csv.rows[0].at(column(csv, "area_fraction"))), resampled.areaFraction, 1e-9);
    // Not the surface as synthesized (another grid and fewer levels: another answer).
    EXPECT_GT(std::abs(h / asIs.conductancePerConductivity - 1.0), 1e-3);
    expectError(p + " --synthesize 32 --resample 63" + bem + " --loads 1e-3", {"--resample", "even", "got 63"});
    expectError(p + " --synthesize 32 --resample 64,0" + bem + " --loads 1e-3", {"--resample", "K >= 1"});
    expectError(p + " --synthesize 32 --resample 64,x" + bem + " --loads 1e-3", {"--resample", "'x'"});
    expectError(p + " --model hertz --Eprime 2e11 --resample 64 --loads 1e-3", {"--resample", "boundaryElement"});
    expectError(p + " --synthesize 32 --resample 64" + bem + " --check --loads 1e-3", {"--resample"});
}

TEST(Cli, PressuresAreTheLoadsAtPOverEprime)
{
    // --pressures P [Pa] computes the load P/E' and prints the same row as --loads P/E', after a
    // first column nominal_pressure holding P. E' from --E/--nu (the library's) and from --Eprime.
    const double Ep = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9}).reducedModulus();
    const std::vector<double> P = {0.0, 1e4, 3e5, 1e6, 2.5e7};
    std::ostringstream ps;
    std::ostringstream ls;
    ls.precision(17);
    for (std::size_t k = 0; k < P.size(); ++k) {
        ps << (k ? "," : "") << P[k];
        ls << (k ? "," : "") << P[k] / Ep;
    }
    for (const std::string& model : {std::string("jacksonGreen"), std::string("persson")}) {
        SCOPED_TRACE(model);
        const std::string common = "--profile '" + standin + "' --model " + model + steel + " --conductance";
        const CommandResult a = run(common + " --pressures " + ps.str());
        const CommandResult b = run(common + " --loads " + ls.str());
        ASSERT_EQ(a.status, 0) << a.err;
        ASSERT_EQ(b.status, 0) << b.err;
        const Csv ca = parseCsv(a.out);
        const Csv cb = parseCsv(b.out);
        ASSERT_EQ(ca.header.size(), cb.header.size() + 1);
        EXPECT_EQ(ca.header[0], "nominal_pressure");
        ASSERT_EQ(ca.rows.size(), P.size());
        ASSERT_EQ(cb.rows.size(), P.size());
        for (std::size_t k = 0; k < P.size(); ++k) {
            EXPECT_DOUBLE_EQ(std::stod(ca.rows[k][0]), P[k]);
            const std::vector<std::string> rest(ca.rows[k].begin() + 1, ca.rows[k].end());
            EXPECT_EQ(rest, cb.rows[k]) << "row " << k;
        }
    }
    // --Eprime: E' given.
    const CommandResult c = run("--profile '" + standin + "' --model hertz --Eprime 2e11 --pressures 2e6,2e7");
    const CommandResult d = run("--profile '" + standin + "' --model hertz --Eprime 2e11 --loads 1e-5,1e-4");
    ASSERT_EQ(c.status, 0) << c.err;
    ASSERT_EQ(d.status, 0) << d.err;
    const Csv cc = parseCsv(c.out);
    const Csv cd = parseCsv(d.out);
    ASSERT_EQ(cc.rows.size(), 2U);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(std::vector<std::string>(cc.rows[k].begin() + 1, cc.rows[k].end()), cd.rows[k]);
    }
    // boundaryElement too (a small synthesized surface).
    const std::string bem = "--profile '" + standin + "' --synthesize 16 --model boundaryElement --Eprime 2e11";
    const CommandResult e = run(bem + " --pressures 2e6,2e7");
    const CommandResult f = run(bem + " --loads 1e-5,1e-4");
    ASSERT_EQ(e.status, 0) << e.err;
    ASSERT_EQ(f.status, 0) << f.err;
    const Csv ce = parseCsv(e.out);
    const Csv cf = parseCsv(f.out);
    ASSERT_EQ(ce.rows.size(), 2U);
    EXPECT_EQ(ce.header[0], "nominal_pressure");
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(std::vector<std::string>(ce.rows[k].begin() + 1, ce.rows[k].end()), cf.rows[k]);
    }
    // The per-level trace carries the column as well.
    const CommandResult t = run("--profile '" + standin + "' --model hertz --Eprime 2e11 --pressures 2e6 --levels");
    ASSERT_EQ(t.status, 0) << t.err;
    EXPECT_EQ(t.out.rfind("nominal_pressure,nominal_pressure_per_Eprime,level,", 0), 0U) << t.out.substr(0, 80);
}

TEST(Cli, PressuresErrors)
{
    const std::string surface = "--profile '" + standin + "' --model hertz";
    expectError(surface + " --pressures 1e6", {"--pressures", "--E", "--Eprime"});
    expectError(surface + " --Eprime 2e11 --pressures 1e6 --loads 1e-5", {"--loads", "--pressures"});
    expectError(surface + " --Eprime 2e11 --pressures 1e6 --load-range 1e-5:1e-4:3", {"--pressures"});
    expectError(surface + " --Eprime 2e11 --pressures=-1", {"--pressures", ">= 0 Pa"});
    // (a word is read as a number with a unit, which it is not: the units' message)
    expectError(surface + " --Eprime 2e11 --pressures 1e6,oops", {"--pressures", "'oops' is not a number with an optional unit"});
    expectError(surface + " --Eprime 2e11 --pressures 1e6,", {"--pressures", "empty item"});
    expectError(surface + " --Eprime 2e11 --pressures 1e20", {"--pressures", "1e+20 Pa", "E' = 2e+11 Pa"});
    expectError(surface + " --Eprime 2e11", {"--loads, --load-range or --pressures"});
}

namespace {

// The CLI's --profile standin with the steel of `steel` (against a rigid flat) and --model
// jacksonGreen, as checkSurface takes them (the pressures are the caller's).
SurfaceCheckInputs standinCheckInputs()
{
    SurfaceCheckInputs inputs;
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::profile;
    s.file = standin;
    inputs.surfaces = {s};
    inputs.materials = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    inputs.model = "jacksonGreen";
    return inputs;
}

} // namespace

TEST(Cli, CheckIsTheLibrarysSurfaceCheck)
{
    // --check: the report as # lines, then the library's checkSurface as CSV, on the same surface
    // (the stand-in synthesized on 128^2, seeds 1-3: the fewest levels a check takes on the
    // light loads' period of 4L, 128/(8 x 4) = 4) and pressures; progress on stderr.
    const double Ep = 179.52e9 / (1 - 0.32 * 0.32);
    const std::vector<double> pressures{0.3e-3 * Ep * 0.05, 3e-3 * Ep * 0.05};
    std::ostringstream given;
    given.precision(17);
    given << pressures[0] << ',' << pressures[1];
    const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel + " --synthesize 128 --check --pressures " + given.str());
    ASSERT_EQ(r.status, 0) << r.err;
    // 3 seeds on one scan length and 3 on 4L (the lighter pressure lies where the periods join).
    EXPECT_NE(r.err.find("check: surface 6 of 6, pressure 1 of 1"), std::string::npos) << r.err;
    std::istringstream in(r.out);
    std::string csvText;
    std::string report;
    for (std::string line; std::getline(in, line);) {
        (line.rfind("# ", 0) == 0 ? report : csvText) += line + "\n";
    }
    SurfaceCheckInputs inputs = standinCheckInputs();
    inputs.minPressure = pressures[0];
    inputs.maxPressure = pressures[1];
    SurfaceCheckOptions options;
    options.gridSize = 128;
    options.pressures = pressures;
    const SurfaceCheck c = checkSurface(inputs, options);
    ASSERT_EQ(c.pressures.size(), 2U) << c.report();
    EXPECT_EQ(csvText, c.csv());
    EXPECT_NE(report.find("# check of the surface: 3 seeds of 128 x 128"), std::string::npos) << report;
    EXPECT_NE(report.find("closest: " + c.closestLaw), std::string::npos) << report;
    const std::string p = "--profile '" + standin + "' --model jacksonGreen" + steel + " --check";
    expectError(p + " --conductance-law all --loads 1e-4", {"--check", "every law"});
    expectError(p + " --levels --loads 1e-4", {"--check", "--levels"});
    expectError("--profile '" + standin + "' --model persson" + steel + " --check --loads 1e-4", {"--check", "multi-scale"});
    expectError(p + " --loads 1e-12", {"none of the pressures given lies in the checked range"});
    expectError(p + " --synthesize 32,4 --loads 1e-4", {"--synthesize", "grid size N only"});
    expectError(p + " --check-periods 0 --loads 1e-4", {"--check-periods", "must be 1 to 64"});
    expectError(p + " --check-periods 65 --loads 1e-4", {"--check-periods", "must be 1 to 64"});
    expectError(p + " --check-periods -1 --loads 1e-4", {"--check-periods", "whole number of decimal digits, got '-1'"});
    expectError(p + " --check-periods 2x --loads 1e-4", {"--check-periods", "whole number of decimal digits, got '2x'"});
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --check-periods 2 --loads 1e-4",
                {"--check-periods", "give it with --check"});
}

TEST(Cli, CheckPeriodsSetsTheLightLoadPeriodAsTheLibrarysOption)
{
    // --check-periods K is SurfaceCheckOptions::lightLoadPeriods: at a light pressure (below
    // p/(E' h') = 1e-3) the CLI's check on K = 1 and K = 2 is the library's with that option, and
    // the two differ (another period is another surface), so the option reaches the solve.
    const double Ep = 179.52e9 / (1 - 0.32 * 0.32);
    SurfaceCheckInputs inputs = standinCheckInputs();
    inputs.minPressure = 1e-9 * Ep;
    inputs.maxPressure = 1e-3 * Ep;
    const double h = checkSurface(inputs, [] {
                         SurfaceCheckOptions o;
                         o.gridSize = 64; // h' of the surface the check solves: cut at 64/8 levels
                         o.lightLoadPeriods = 1;
                         o.seeds = {1};
                         o.pressureCount = 1;
                         return o;
                     }()).gradient;
    std::ostringstream given;
    given.precision(17);
    given << 3e-4 * Ep * h;
    std::map<std::size_t, std::string> csvOf;
    for (const std::size_t k : {1U, 2U}) {
        const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                    " --synthesize 64 --check --check-periods " + std::to_string(k) +
                                    " --pressures " + given.str());
        ASSERT_EQ(r.status, 0) << r.err;
        std::istringstream in(r.out);
        std::string csvText;
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("# ", 0) != 0) {
                csvText += line + "\n";
            }
        }
        SurfaceCheckOptions options;
        options.gridSize = 64; // on 2L, 64/(8 x 2) = 4 of the levels: the fewest a check takes
        options.pressures = {std::stod(given.str())};
        options.lightLoadPeriods = k;
        inputs.minPressure = inputs.maxPressure = options.pressures[0];
        const SurfaceCheck c = checkSurface(inputs, options);
        ASSERT_EQ(c.lightLoadPeriods, k) << c.report();
        EXPECT_EQ(csvText, c.csv());
        csvOf[k] = csvText;
    }
    EXPECT_NE(csvOf[1], csvOf[2]);
    expectError("--areal '" + std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p' --model jacksonGreen" + steel +
                    " --check --check-periods 2 --loads 1e-4",
                {"--check-periods", "an areal map is solved as itself"});
}

TEST(Cli, ConductivitiesGiveTheConductanceInWattsPerSquareMetreKelvin)
{
    // --k1 --k2: a column h after h_per_k, h = k_s h_per_k with k_s = 2 k1 k2/(k1 + k2) (50 and 200:
    // 80 W/(m K)), for the load curve and boundaryElement; both or neither, within the accepted
    // conductivities, and only beside an h_per_k column.
    const CommandResult r = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                " --pressures 1e5,1e6 --conductance --k1 50 --k2 200");
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 2U);
    EXPECT_EQ(column(csv, "h"), column(csv, "h_per_k") + 1);
    for (const auto& row : csv.rows) {
        const double hk = std::stod(row.at(column(csv, "h_per_k")));
        EXPECT_NEAR(std::stod(row.at(column(csv, "h"))), 80.0 * hk, 1e-9 * 80.0 * hk); // 10 digits written
    }
    const CommandResult b = run("--profile '" + standin + "' --synthesize 32 --model boundaryElement" + steel +
                                " --pressures 1e7 --k1 50 --k2 200");
    ASSERT_EQ(b.status, 0) << b.err;
    const Csv bc = parseCsv(b.out);
    ASSERT_EQ(bc.rows.size(), 1U);
    const double hk = std::stod(bc.rows[0].at(column(bc, "h_per_k")));
    EXPECT_NEAR(std::stod(bc.rows[0].at(column(bc, "h"))), 80.0 * hk, 1e-9 * 80.0 * hk);
    const std::string p = "--profile '" + standin + "' --model jacksonGreen" + steel + " --pressures 1e6";
    expectError(p + " --conductance --k1 50", {"--k2", "both conductivities"});
    expectError(p + " --k1 50 --k2 200", {"--k1", "--conductance"});
    expectError(p + " --conductance --k1 50 --k2 1e6", {"--k2", "W/(m K)"});
    expectError(p + " --check --k1 50 --k2 200", {"--k1", "--check"});
}

TEST(Cli, YieldStrengthNoneSaysASolidDoesNotYield)
{
    // --Sy S1,none (issue 21): the second solid does not yield, so the first's S_y governs; the
    // same materials through the library (ContactMaterials::pair with the second marked elastic)
    // give the same curve to the 10 digits printed (1e-9, as LoadCurveIsTheLibrarysForEveryModel).
    const std::string p = "--profile '" + standin + "' --model jacksonGreen --loads 1e-5,1e-4,1e-3";
    const CommandResult said = run(p + " --E 200e9,300e9 --nu 0.3,0.25 --Sy 0.4e9,none");
    ASSERT_EQ(said.status, 0) << said.err;
    Material a{200e9, 0.3, 0.4e9};
    Material b{300e9, 0.25, std::nullopt};
    b.elastic = true;
    const auto model = makeContactModel("jacksonGreen", Spectrum::fromProfile(readProfile(standin)),
                                        ContactMaterials::pair(a, b));
    const Csv csv = parseCsv(said.out);
    ASSERT_EQ(csv.rows.size(), 3U);
    const double loads[] = {1e-5, 1e-4, 1e-3};
    for (std::size_t i = 0; i < 3; ++i) {
        const double area = std::stod(csv.rows[i][column(csv, "area_fraction")]);
        EXPECT_NEAR(area, model->areaFraction(loads[i]), 1e-9 * area) << loads[i];
    }
    // The yielding solid is the first: S_y 0.4 GPa of E 200 GPa, not the second's modulus (a
    // pair with both yielding at 0.4 GPa gives the same; one at 0.8 GPa on the first does not).
    EXPECT_EQ(run(p + " --E 200e9,300e9 --nu 0.3,0.25 --Sy 0.4e9,0.9e9").out, said.out);
    EXPECT_NE(run(p + " --E 200e9,300e9 --nu 0.3,0.25 --Sy 0.8e9,none").out, said.out);
    // A word other than none is not a yield strength.
    expectError(p + " --E 200e9,300e9 --nu 0.3,0.25 --Sy 0.4e9,soft", {"--Sy", "soft"});
    // Said not to yield and then needed: jacksonGreen needs the S_y of some solid.
    expectError(p + " --E 200e9,300e9 --nu 0.3,0.25 --Sy none,none", {"yield strength S_y", "jacksonGreen"});
}

TEST(Cli, TableIsTheLibrarysBoundaryElementCache)
{
    // --table FILE (issue 21, item 3): the interface's boundary-element table through the core's
    // loadOrBuild, as the condition makes it (tests/cases/boundaryElementCache: the same file byte
    // for byte): the file the library writes for the same InterfaceSpec, the points printed to
    // the 10 digits the CLI prints, and the file reused by a second run.
    TempDir dir;
    const std::string file = (dir.path() / "table.csv").string();
    const std::string args = "--power-law 2.56e-4,0.8,1e3,32e3 --length 1e-3 --model boundaryElement --synthesize 32,3 "
                             "--E 200e9,120e9 --nu 0.3,0.34 --Sy 0.4e9,none --hardness-from-yield --table '" + file + "'";
    const CommandResult first = run(args);
    ASSERT_EQ(first.status, 0) << first.err;
    InterfaceSpec spec;
    spec.model = "boundaryElement";
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::powerLaw;
    s.parameters = {2.56e-4, 0.8, 1e3, 32e3};
    s.length = 1e-3;
    spec.surfaces = {s};
    spec.side1 = Material{200e9, 0.3, 0.4e9};
    spec.side2 = Material{120e9, 0.34, std::nullopt};
    spec.side2.elastic = true;
    spec.synthesize = 32;
    spec.seed = 3;
    spec.hardnessFromYield = true;
    const BoundaryElementTable table(spec);
    const BoundaryElementTablePoints points = table.build();
    std::ifstream in(file);
    const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(written, table.write(points));
    const Csv csv = parseCsv(first.out);
    ASSERT_EQ(csv.rows.size(), points.pressures.size());
    for (std::size_t i = 0; i < points.pressures.size(); ++i) {
        EXPECT_EQ(csv.rows[i][column(csv, "pressure")], formatNumber(points.pressures[i], 10));
        EXPECT_EQ(csv.rows[i][column(csv, "h_per_k")], formatNumber(points.conductancesPerConductivity[i], 10));
    }
    const CommandResult second = run(args);
    EXPECT_EQ(second.out, first.out);
    EXPECT_NE(second.err.find("reusing"), std::string::npos) << second.err;
    // What the table is not.
    expectError("--power-law 2.56e-4,0.8,1e3,32e3 --model hertz --E 2e11,2e11 --nu 0.3,0.3 --table '" + file + "'",
                {"--table", "boundaryElement"});
    expectError("--power-law 2.56e-4,0.8,1e3,32e3 --length 1e-3 --model boundaryElement --synthesize 32 --E 2e11 "
                "--nu 0.3 --table '" + file + "'",
                {"--table", "two solids"});
    expectError(args + " --loads 1e-4", {"--loads", "--table"});
}

// Unit suffixes (roughContact::parseQuantity): --E 200GPa, --Sy 400MPa, --pressures 1MPa and
// --length 0.5mm give the bytes the SI numbers give; a unit of another quantity or an unknown
// one is an error naming the option.
TEST(Cli, UnitSuffixesAreTheSINumbers)
{
    const std::string p = "--profile '" + standin + "' --model jacksonGreen --nu 0.3,0.3 --conductance";
    const CommandResult si = run(p + " --E 200e9,70e9 --Sy 4e8,none --pressures 1e6,2.5e5");
    const CommandResult units = run(p + " --E 200GPa,70GPa --Sy 400MPa,none --pressures 1MPa,250kPa");
    ASSERT_EQ(si.status, 0) << si.err;
    EXPECT_EQ(units.status, 0) << units.err;
    EXPECT_EQ(units.out, si.out);
    const std::string w = "--power-law 6e-4,1.3,2e3,2e6 --model hertz --E 200e9 --nu 0.3 --loads 1e-4";
    EXPECT_EQ(run(w + " --length 0.5mm").out, run(w + " --length 5e-4").out);
    expectError(p + " --E 200GPa,70GPa --pressures 1um", {"--pressures", "is not a pressure"});
    expectError(p + " --E 200Gpa,70GPa --pressures 1e6", {"--E", "unknown unit 'Gpa'"});
    expectError(p + " --E 200GPa,70GPa --Sy 400MPa,soft --pressures 1e6", {"--Sy", "soft"});
    // --roughness: RQ and the cut-offs are lengths, SLOPE a plain number
    const std::string r = " --model hertz --E 200e9 --nu 0.3 --loads 1e-4";
    const CommandResult rsi = run("--roughness 8e-7,0.1,8e-4,2.5e-6" + r);
    ASSERT_EQ(rsi.status, 0) << rsi.err;
    EXPECT_EQ(run("--roughness 0.8um,0.1,0.8mm,2.5um" + r).out, rsi.out);
    expectError("--roughness 0.8um,0.1um" + r, {"--roughness", "SLOPE", "0.1um"});
    expectError("--roughness 0.8MPa,0.1" + r, {"--roughness", "is not a length"});
}

TEST(Cli, ColumnNamesSayWhatTheyAre)
{
    // Issue 22: the load curve's columns are named for what they are (F/(A_n E'), A_r/A_n,
    // F/(A_r E')), in every kind of run; --table keeps the condition's cache format.
    const std::string p = "--profile '" + standin + "' --model jacksonGreen" + steel;
    const auto header = [](const CommandResult& r) { return r.out.substr(0, r.out.find('\n')); };
    const CommandResult curve = run(p + " --pressures 1e6 --conductance --k1 50 --k2 50");
    ASSERT_EQ(curve.status, 0) << curve.err;
    EXPECT_EQ(header(curve), "nominal_pressure,nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime,"
                             "separation,h_per_k,h");
    const CommandResult trace = run(p + " --loads 1e-5 --levels");
    ASSERT_EQ(trace.status, 0) << trace.err;
    EXPECT_EQ(header(trace), "nominal_pressure_per_Eprime,level,frequency,amplitude,eta,radius,asperities,"
                             "asperity_force,area_fraction,complete");
    const CommandResult bem =
        run("--profile '" + standin + "' --synthesize 16 --model boundaryElement --Eprime 2e11 --loads 1e-4");
    ASSERT_EQ(bem.status, 0) << bem.err;
    EXPECT_EQ(header(bem),
              "nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime,separation,h_per_k,"
              "spots,mean_spot_radius,iterations,residual");
    const CommandResult gap = run(p + " --loads 1e-5 --gas air --temperature 300 --k1 50 --k2 50");
    ASSERT_EQ(gap.status, 0) << gap.err;
    EXPECT_EQ(header(gap), "nominal_pressure_per_Eprime,area_fraction,contact_pressure_per_Eprime,separation,h_per_k,h,"
                           "gap_separation,h_gas,h_radiation,h_total");
    const CommandResult check = run("--profile '" + standin + "' --model jacksonGreen --E 200e9,200e9 --nu 0.3,0.3 "
                                    "--Sy 0.4e9,0.4e9 --check --synthesize 128 --pressures 1e6");
    ASSERT_EQ(check.status, 0) << check.err;
    EXPECT_NE(check.out.find("\nnominal_pressure,nominal_pressure_per_Eprime,h_per_k_answer,"), std::string::npos)
        << check.out;
}

TEST(Cli, GapColumnsAreTheCoresConductances)
{
    // The gap options are the condition's gap entries; h_gas and h_radiation are the core's
    // GasGap::conductance and radiativeConductance at the separation ContactInterface would use:
    // the correlation of sigma and P/H_c (jacksonGreen and its default law define none), the
    // --gap-width at load 0; h_total = k_s h_per_k + h_gas + h_radiation. The cells hold 10
    // significant digits: each is the core's value written so (formatNumber(v, 10)).
    const std::vector<double> P = {0.0, 1e5, 1e6, 1e7};
    const std::string args = "--profile '" + standin + "' --model jacksonGreen" + steel +
                             " --pressures 0,1e5,1e6,1e7 --gas air --gas-pressure 50kPa --accommodation 0.8,0.9"
                             " --emissivity 0.3,0.6 --temperature 320,360 --gap-width 10um --k1 50 --k2 20";
    const CommandResult r = run(args);
    ASSERT_EQ(r.status, 0) << r.err;
    const Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), P.size());
    GasGapSpec g;
    g.gas = gasByName("air");
    g.pressure = 5e4;
    g.accommodation1 = 0.8;
    g.accommodation2 = 0.9;
    const GasGap gas(g);
    SurfaceSpec s;
    s.kind = SurfaceSpec::Kind::profile;
    s.file = standin;
    const double sigma = equivalentRoughness({s}).sigma;
    const double Hc = 2.84 * 0.2e9;
    const double hr = radiativeConductance(320.0, 360.0, 0.3, 0.6);
    const double ks = harmonicMeanConductivity(50.0, 20.0);
    for (std::size_t i = 0; i < P.size(); ++i) {
        SCOPED_TRACE(P[i]);
        const std::vector<std::string>& row = csv.rows[i];
        const double Y = P[i] > 0.0 ? gapSeparationCorrelation(P[i], sigma, Hc) : 10e-6;
        const double hg = gas.conductance(Y, 340.0);
        EXPECT_EQ(row.at(column(csv, "gap_separation")), formatNumber(Y, 10));
        EXPECT_EQ(row.at(column(csv, "h_gas")), formatNumber(hg, 10));
        EXPECT_EQ(row.at(column(csv, "h_radiation")), formatNumber(hr, 10));
        const double hc = ks * std::stod(row.at(column(csv, "h_per_k")));
        const double total = std::stod(row.at(column(csv, "h_total")));
        EXPECT_NEAR(total, hc + hg + hr, 1e-9 * total);
        EXPECT_NEAR(std::stod(row.at(column(csv, "h"))), hc, 1e-9 * hc + 1e-300);
    }
    // The rest of the row is the run's without a gap.
    const CommandResult plain = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                    " --pressures 0,1e5,1e6,1e7 --conductance --k1 50 --k2 20");
    ASSERT_EQ(plain.status, 0) << plain.err;
    const Csv c0 = parseCsv(plain.out);
    for (std::size_t i = 0; i < P.size(); ++i) {
        EXPECT_EQ(std::vector<std::string>(csv.rows[i].begin(), csv.rows[i].begin() + c0.header.size()), c0.rows[i]);
    }
    // Where the law defines a mean separation (multiscaleBarber), the gap takes it: gap_separation
    // is the separation column, h_gas the core's there.
    const CommandResult b = run("--profile '" + standin + "' --model jacksonGreen" + steel +
                                " --pressures 1e6 --conductance-law multiscaleBarber --gas helium --temperature 300");
    ASSERT_EQ(b.status, 0) << b.err;
    const Csv cb = parseCsv(b.out);
    const std::string Yb = cb.rows.at(0).at(column(cb, "separation"));
    ASSERT_FALSE(Yb.empty());
    EXPECT_EQ(cb.rows[0].at(column(cb, "gap_separation")), Yb);
    const Spectrum spectrum = Spectrum::fromProfile(readProfile(standin));
    const ContactMaterials materials = ContactMaterials::againstRigidFlat(Material{179.52e9, 0.32, 0.2e9});
    const auto model = makeContactModel("jacksonGreen", spectrum, materials);
    ConductanceLawInputs in; // as the CLI's load curve fills them
    in.multiscale = dynamic_cast<const MultiscaleModel*>(model.get());
    in.spectrum = &spectrum;
    in.Eprime = materials.reducedModulus();
    in.hardness = conductanceLawHardness(std::nullopt, materials);
    const auto law = makeConductanceLaw("multiscaleBarber", in);
    GasGapSpec he;
    he.gas = gasByName("helium");
    EXPECT_EQ(cb.rows[0].at(column(cb, "h_gas")),
              formatNumber(GasGap(he).conductance(law->meanSeparation(1e6), 300.0), 10));
    EXPECT_EQ(cb.rows[0].at(column(cb, "h_radiation")), "0");
}

TEST(Cli, GapErrors)
{
    const std::string p = "--profile '" + standin + "' --model jacksonGreen" + steel + " --pressures 1e6";
    // The temperature is required with a gap, and named.
    expectError(p + " --gas air", {"--temperature", "give --temperature T [K]"});
    expectError(p + " --emissivity 0.3,0.3", {"--temperature"});
    // An unknown gas is named, with the gases known.
    expectError(p + " --gas xenon --temperature 300", {"--gas", "xenon", "air helium argon nitrogen"});
    // The reader's rules, named by the options.
    expectError(p + " --gas air --accommodation 0.5 --temperature 300", {"--accommodation", "two values"});
    expectError(p + " --gas air --accommodation 0,1 --temperature 300", {"accommodation"});
    expectError(p + " --emissivity 0.3,1.5 --temperature 300", {"emissivity e2", "(0, 1]"});
    expectError(p + " --emissivity 0.3,0.3 --gas-pressure 1e5 --temperature 300", {"--gas-pressure", "is for a gas"});
    expectError(p + " --gas air --gas-pressure 1um --temperature 300", {"--gas-pressure", "is not a pressure"});
    expectError(p + " --gas air --temperature 0.001", {"--temperature"});
    // Gap-only options without a gap.
    expectError(p + " --temperature 300", {"--temperature", "is for the gap"});
    expectError(p + " --gap-width 1e-6", {"--gap-width", "is for the gap"});
    // --check and --table have no gap columns.
    expectError(p + " --check --gas air --temperature 300", {"--gas", "--check"});
    // At load 0 a gas gap needs its width.
    expectError("--profile '" + standin + "' --model jacksonGreen" + steel + " --loads 0 --gas air --temperature 300",
                {"--gap-width"});
    // The correlation needs H_c: without --Sy (hertz is elastic), --hardness gives it.
    const std::string hertz = "--profile '" + standin + "' --model hertz --E 179.52e9 --nu 0.32 --pressures 1e6";
    expectError(hertz + " --gas air --temperature 300", {"--gas", "microhardness", "--hardness"});
    EXPECT_EQ(run(hertz + " --gas air --temperature 300 --hardness 1GPa").status, 0);
}

TEST(Cli, ProfileAlongTheLayIsTheAveragedSpectrum)
{
    // --profile (across the lay) with --profile-along: the surface is the two directions'
    // averaged line-scan spectrum (Spectrum::averaged, docs/theory.md §1.6), the same numbers as
    // that spectrum given as a table.
    TempDir dir;
    std::ostringstream across;
    std::ostringstream along;
    across.precision(17);
    along.precision(17);
    const double pi = std::acos(-1.0);
    for (int i = 0; i < 1024; ++i) {
        const double x = i * 1e-6;
        across << x << ' ' << 1e-6 * std::cos(2 * pi * 32 * i / 1024.0) + 2e-7 * std::cos(2 * pi * 200 * i / 1024.0)
               << '\n';
        along << x << ' ' << 1e-6 * std::cos(2 * pi * 4 * i / 1024.0) + 2e-7 * std::cos(2 * pi * 25 * i / 1024.0) << '\n';
    }
    const auto a = dir.write("across.txt", across.str());
    const auto b = dir.write("along.txt", along.str());
    SurfaceSpec both;
    both.kind = SurfaceSpec::Kind::profile;
    both.file = a.string();
    both.alongLay = b.string();
    const Spectrum s = both.spectrum();
    std::ostringstream table;
    table.precision(17);
    for (std::size_t i = 0; i < s.size(); ++i) {
        table << s.frequency(i) << ',' << s.amplitude(i) << '\n';
    }
    const auto t = dir.write("averaged.csv", table.str());
    const std::string rest = " --model jacksonGreen" + steel + " --loads 1e-4,1e-3 --conductance";
    const CommandResult two = run("--profile '" + a.string() + "' --profile-along '" + b.string() + "'" + rest);
    const CommandResult table1 = run("--spectrum '" + t.string() + "' --length 1.024e-3" + rest);
    const CommandResult one = run("--profile '" + a.string() + "'" + rest);
    ASSERT_EQ(two.status, 0) << two.err;
    ASSERT_EQ(table1.status, 0) << table1.err;
    ASSERT_EQ(one.status, 0) << one.err;
    const Csv c2 = parseCsv(two.out);
    const Csv ct = parseCsv(table1.out);
    const Csv c1 = parseCsv(one.out);
    // The area is the spectrum's alone; h also takes the heights' sigma, slope and skewness, which
    // a table has not (its heights are Gaussian). The profile across alone is another surface:
    // here its area differs by 3 % and 33 %, its h by a factor of two (the along profile's long
    // waves carry half the averaged power).
    for (std::size_t r = 0; r < 2; ++r) {
        const auto at = [r](const Csv& c, const char* col) { return std::stod(c.rows.at(r).at(column(c, col))); };
        EXPECT_NEAR(at(c2, "area_fraction"), at(ct, "area_fraction"), 1e-9 * at(ct, "area_fraction")) << r;
        EXPECT_GT(std::abs(std::log(at(c2, "area_fraction") / at(c1, "area_fraction"))), 0.02) << r;
        EXPECT_GT(std::abs(std::log(at(c2, "h_per_k") / at(c1, "h_per_k"))), 0.3) << r;
    }
    expectError("--profile '" + a.string() + "' --profile-along '" + b.string() + "' --profile-along '" + b.string() +
                    "'" + rest,
                {"--profile-along", "one --profile"});
    // One profile says once, after the run, what it cannot know; two directions do not.
    const std::string note = "multiscaleContact: note: one profile is taken as a line scan of an isotropic surface";
    EXPECT_NE(one.err.find(note), std::string::npos) << one.err;
    EXPECT_EQ(one.err.find(note), one.err.rfind(note)) << "said once";
    EXPECT_NE(one.err.find("(--profile-along)"), std::string::npos) << one.err;
    EXPECT_EQ(two.err.find(note), std::string::npos) << two.err;
    EXPECT_EQ(table1.err.find(note), std::string::npos) << table1.err;
}
