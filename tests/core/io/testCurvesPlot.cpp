// SPDX-License-Identifier: GPL-3.0-or-later
// The picture (CurvesPlot.hpp): its script carries every available law's numbers and the band,
// gnuplot writes a PNG, it replaces only a PNG, and a missing gnuplot is said, not a crash.
#include "RunCommand.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/interface/InterfaceCurves.hpp"
#include "roughContact/io/CurvesPlot.hpp"
#include "roughContact/io/Numbers.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace roughContact;
using roughContactTest::TempDir;

namespace {

// Two pressures, two laws (one unavailable), a band measured at the second pressure only.
InterfaceCurves smallCurves()
{
    InterfaceCurves c;
    c.pressures = {1e6, 1e7};
    c.laws = {{"lawA", {10.0, 100.0}, ""}, {"lawB", {}, "needs a microhardness"}, {"lawC", {12.5, 90.0}, ""}};
    c.chosenLaw = "lawC";
    c.exactLow = {std::nan(""), 75.0};
    c.exactHigh = {std::nan(""), 105.0};
    return c;
}

std::string contents(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// Sets an environment variable for one scope.
struct ScopedEnv {
    std::string name, old;
    bool had;
    ScopedEnv(const std::string& n, const std::string& value) : name(n), had(std::getenv(n.c_str()) != nullptr)
    {
        if (had) {
            old = std::getenv(n.c_str());
        }
        ::setenv(n.c_str(), value.c_str(), 1);
    }
    ~ScopedEnv() { had ? ::setenv(name.c_str(), old.c_str(), 1) : ::unsetenv(name.c_str()); }
};

} // namespace

TEST(CurvesPlot, TheScriptCarriesEveryAvailableLawAndTheBand)
{
    PlotExtras extras;
    extras.conductivity = 2.0; // h = 2 h_c/k_s
    const std::string s = curvesPlotScript(smallCurves(), extras, "/tmp/it's.png");
    EXPECT_NE(s.find("set output '/tmp/it''s.png'"), std::string::npos) << s;
    EXPECT_NE(s.find("h [W/(m^2 K)]"), std::string::npos);
    // Rows: P, lawA, lawC, band low, band high (times k_s); lawB has no column and no title.
    EXPECT_NE(s.find(formatNumber(1e6, 10) + " 20 25 NaN NaN\n"), std::string::npos) << s;
    EXPECT_NE(s.find(formatNumber(1e7, 10) + " 200 180 150 210\n"), std::string::npos) << s;
    EXPECT_EQ(s.find("lawB"), std::string::npos);
    EXPECT_NE(s.find("using 1:4:5 with filledcurves"), std::string::npos) << s;
    EXPECT_NE(s.find("title 'lawC (chosen)'"), std::string::npos);
    EXPECT_EQ(s.find("$check"), std::string::npos); // no check given
}

TEST(CurvesPlot, WritesAPngAndReplacesOnlyAPng)
{
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        GTEST_SKIP() << "gnuplot is not installed (etc/debianPackages: gnuplot-nox)";
    }
    TempDir dir;
    const std::filesystem::path png = dir.path() / "h.png";
    writeCurvesPlot(smallCurves(), {}, png.string(), "--plot");
    const std::string first = contents(png);
    ASSERT_TRUE(isPngStart(first));
    EXPECT_GT(first.size(), 1000U);
    writeCurvesPlot(smallCurves(), {}, png.string(), "--plot"); // a PNG is replaced
    EXPECT_TRUE(isPngStart(contents(png)));
    // A file that is not a PNG is left byte for byte, and the error names the option.
    const std::filesystem::path other = dir.path() / "notes.txt";
    std::ofstream(other) << "my notes\n";
    try {
        writeCurvesPlot(smallCurves(), {}, other.string(), "--plot");
        ADD_FAILURE() << "replaced a file that is not a PNG";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("--plot"), std::string::npos) << e.what();
    }
    EXPECT_EQ(contents(other), "my notes\n");
}

TEST(CurvesPlot, AMissingGnuplotIsSaid)
{
    TempDir dir;
    const std::filesystem::path png = dir.path() / "h.png";
    const ScopedEnv noPath("PATH", (dir.path() / "empty").string());
    try {
        writeCurvesPlot(smallCurves(), {}, png.string(), "file");
        ADD_FAILURE() << "drew without gnuplot";
    } catch (const ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("needs gnuplot, which is not installed"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(CurvesPlot, PngSignature)
{
    EXPECT_TRUE(isPngStart(std::string("\x89PNG\r\n\x1a\n", 8) + "rest"));
    EXPECT_FALSE(isPngStart("\x89PNG"));
    EXPECT_FALSE(isPngStart("my notes"));
}
