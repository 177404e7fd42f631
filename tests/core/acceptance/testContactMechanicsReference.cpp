// SPDX-License-Identifier: GPL-3.0-or-later
// The exact solver held to an independent one (issue 19, item 2): ContactMechanics' constrained
// conjugate gradients (the ContactEngineering group's code), run on the same heights, elastic and
// with a plastic cap, gave the numbers of tests/reference/contactMechanics/reference.csv (that
// folder's README: the code's commit, how it was run, how the numbers were checked). Here the
// project solves the same surfaces (its own synthesizer rebuilds them from their recipe; the
// X3P map is read) at its own tolerance and must find:
//  - the contact cells and the cells at the cap within one cell: an edge cell whose pressure is
//    within round-off of 0 (or of H) may fall either way between two solvers; the plane that
//    was removed from periodic surfaces before issue 19 moved 2-3 cells at the lightest load;
//  - the mean gap within 1e-7 (relative): the reference is converged to about 1e-10, the
//    project's solve at 1e-10 agrees to 4e-10 and at its default 1e-8 to 5e-9.
#include "roughContact/bem/PolonskyKeer.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

const std::string folder = std::string(ROUGHCONTACT_SOURCE_DIR) + "/tests/reference/contactMechanics";
constexpr double Eprime = 2.2e11; // the reference's E' (its README: units)

struct Row {
    std::string surface;
    bool periodic = true;
    double load = 0.0;
    std::optional<double> hardness;
    double contactFraction = 0.0;
    double meanGap = 0.0;
    double plasticFraction = 0.0;
};

std::vector<Row> rows(const std::string& surface)
{
    std::ifstream in(folder + "/reference.csv");
    EXPECT_TRUE(in.good()) << folder << "/reference.csv";
    std::string line;
    std::getline(in, line); // header
    EXPECT_EQ(line.rfind("surface,n,periodic,load,hardness,contact_fraction,mean_gap,mean_contact_pressure,"
                         "plastic_fraction",
                         0),
              0u)
        << line;
    std::vector<Row> out;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) {
            f.push_back(cell);
        }
        if (f.size() < 9 || f[0] != surface) {
            continue;
        }
        Row r;
        r.surface = f[0];
        r.periodic = f[2] == "true";
        double v = 0.0;
        EXPECT_TRUE(parseNumber(f[3], r.load)) << line;
        if (!f[4].empty() && parseNumber(f[4], v)) {
            r.hardness = v;
        }
        EXPECT_TRUE(parseNumber(f[5], r.contactFraction)) << line;
        EXPECT_TRUE(parseNumber(f[6], r.meanGap)) << line;
        EXPECT_TRUE(parseNumber(f[8], r.plasticFraction)) << line;
        out.push_back(r);
    }
    return out;
}

// The synthesized surfaces' recipe (the reference's README): a power law of Hurst exponent 0.8,
// L = 1 mm, 1000 to 128000 1/m.
ArealSurface powerLaw(std::size_t n, std::uint64_t seed)
{
    return synthesizeIsotropic(Spectrum::powerLaw(0.032, 1.3, 1000.0, 128000.0, 1e-3), n, seed);
}

void holdTo(const ArealSurface& surface, const std::string& name, std::size_t expectedRows)
{
    const std::vector<Row> reference = rows(name);
    ASSERT_EQ(reference.size(), expectedRows) << name;
    const double cells = double(surface.nx() * surface.ny());
    std::map<std::optional<double>, std::unique_ptr<BoundaryElementModel>> models;
    for (const Row& r : reference) {
        SCOPED_TRACE(name + " at p/E' = " + formatNumber(r.load, 6) +
                     (r.hardness ? ", H = " + formatNumber(*r.hardness, 6) + " Pa" : ", elastic"));
        auto& model = models[r.hardness];
        if (!model) {
            BoundaryElementOptions o;
            o.periodic = r.periodic; // and by default: the mean removed (periodic), the plane (a map)
            o.hardness = r.hardness;
            model = std::make_unique<BoundaryElementModel>(surface, Eprime, o);
        }
        const BoundaryElementPoint p = model->solve(r.load);
        EXPECT_NEAR(p.areaFraction * cells, r.contactFraction * cells, 1.0);
        EXPECT_NEAR(p.plasticFraction * cells, r.plasticFraction * cells, 1.0);
        EXPECT_NEAR(p.meanSeparation / r.meanGap, 1.0, 1e-7) << p.meanSeparation << " m, reference " << r.meanGap;
    }
}

} // namespace

TEST(ContactMechanicsReference, PeriodicPowerLaw256)
{
    holdTo(powerLaw(256, 1), "powerlaw256", 12);
}

TEST(ContactMechanicsReference, PeriodicPowerLaw512)
{
    holdTo(powerLaw(512, 2), "powerlaw512", 12);
}

TEST(ContactMechanicsReference, TheX3pMapNonPeriodic)
{
    holdTo(readAreal(std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p", ArealReadOptions{}), "x3p-2", 3);
}
