// SPDX-License-Identifier: GPL-3.0-or-later
// Reading measured profiles (io/ProfileReader): layouts, units, the uniform-grid check, every
// error (naming file and line), and the real Dektak export tests/data/io/dektak-1.csv.
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include "FileContents.hpp"
#include "InputErrors.hpp"
#include "TempDirTest.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace roughContact;
namespace fs = std::filesystem;

namespace {

constexpr double pi = 3.14159265358979323846;
const std::string dektakPath = std::string(ROUGHCONTACT_SOURCE_DIR) + "/tests/data/io/dektak-1.csv";

/// A fresh directory per test (tests/support/TempDirTest.hpp).
class ProfileReaderTest : public roughContactTest::TempDirTest {};

/// printf-formatted number.
std::string fmt(const char* format, double v)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

/// Rows "x<sep>z\n" with x = x0 + i dx and z = height(i), i = 0..n-1, printed with format.
std::string columns(std::size_t n, double x0, double dx, const std::function<double(std::size_t)>& height,
                    const char* format = "%.17g", const std::string& sep = " ")
{
    std::string s;
    for (std::size_t i = 0; i < n; ++i) {
        s += fmt(format, x0 + static_cast<double>(i) * dx) + sep + fmt("%.17g", height(i)) + "\n";
    }
    return s;
}

double ramp(std::size_t i)
{
    return 1e-6 * (static_cast<double>(i % 5) - 2.0) + 3e-7 * static_cast<double>(i);
}

using roughContactTest::expectLocated; // tests/support/InputErrors.hpp
using roughContactTest::slurp;         // tests/support/FileContents.hpp

/// The InputError that readProfile(path, options) throws; fails the test when it throws none.
InputError profileError(const std::string& path, const ProfileReadOptions& options = {})
{
    return roughContactTest::thrownInputError([&] { readProfile(path, options); }, path);
}

/// The lines of text split at "\n" (the "\r" kept), and joined back.
std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t stop = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, stop - start));
        start = stop + 1;
    }
    return lines;
}

std::string joined(const std::vector<std::string>& lines)
{
    std::string s;
    for (const std::string& l : lines) {
        s += l + "\n";
    }
    return s;
}

} // namespace

// ---- layouts --------------------------------------------------------------------------------

TEST_F(ProfileReaderTest, twoColumnsInMetresAreReadAsIs)
{
    const std::size_t n = 16;
    const double dx = 2.5e-7; // x printed with %.17g read back exactly (round trip)
    const std::string path = write("p.txt", columns(n, 1e-3, dx, ramp));
    const Profile p = readProfile(path);
    EXPECT_EQ(p.source(), path);
    ASSERT_EQ(p.size(), n);
    // (x_last - x_0)/(N-1): a few ulps of x ~ 1e-3 over 15 steps, relative ~1e-13 of dx.
    EXPECT_NEAR(p.spacing(), dx, 1e-12 * dx);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(p.heights()[i], ramp(i)) << i; // %.17g round-trips; scale 1 is exact
    }
}

TEST_F(ProfileReaderTest, commaAndWhitespaceSeparatedFilesReadTheSame)
{
    const std::size_t n = 12;
    const double dx = std::ldexp(1.0, -20); // ~0.95 um, a power of 2: every x = i dx is exact
    const Profile a = readProfile(write("a.txt", columns(n, 0.0, dx, ramp, "%.17g", " ")));
    const Profile b = readProfile(write("b.csv", columns(n, 0.0, dx, ramp, "%.17g", ",")));
    const Profile c = readProfile(write("c.tsv", columns(n, 0.0, dx, ramp, "%.17g", "\t")));
    const Profile d = readProfile(write("d.csv", columns(n, 0.0, dx, ramp, "%.17g", " ; ")));
    for (const Profile* q : {&b, &c, &d}) {
        EXPECT_EQ(q->heights(), a.heights());
        EXPECT_EQ(q->spacing(), a.spacing());
    }
    EXPECT_EQ(a.spacing(), dx); // exact x, exact difference, (N-1) dx / (N-1) exact
}

TEST_F(ProfileReaderTest, commentsAndOneHeaderLineAreTolerated)
{
    const std::string text = "# profilometer export, sample 3\n"
                             "\n"
                             "x [m]  z [m]   # one header line\n"
                             + columns(4, 0.0, 1e-6, ramp, "%.6e") + "# a comment between rows\n"
                             + columns(4, 4e-6, 1e-6, [](std::size_t i) { return ramp(i + 4); },
                                       "%.6e");
    const Profile p = readProfile(write("p.txt", text));
    ASSERT_EQ(p.size(), 8u);
    EXPECT_NEAR(p.spacing(), 1e-6, 1e-6 * 1e-12); // x printed exactly to 7 digits
    EXPECT_EQ(p.heights()[5], ramp(5));
}

TEST_F(ProfileReaderTest, oneColumnWithAGivenSpacing)
{
    std::string text = "z\n";
    for (std::size_t i = 0; i < 10; ++i) {
        text += fmt("%.17g", ramp(i)) + "\n";
    }
    const std::string path = write("z.txt", text);
    ProfileReadOptions o;
    o.spacing = 3e-7;
    const Profile p = readProfile(path, o);
    ASSERT_EQ(p.size(), 10u);
    EXPECT_EQ(p.spacing(), 3e-7); // given in metres, scale 1: exact
    EXPECT_EQ(p.heights()[9], ramp(9));

    // Without the spacing there are no positions: an error, naming the file.
    const InputError e = profileError(path);
    expectLocated(e, path, 0, "a sample spacing is needed");
}

TEST_F(ProfileReaderTest, badSpacingOptionIsAParameterError)
{
    const std::string path = write("z.txt", "1\n2\n3\n4\n5\n6\n7\n8\n");
    for (double bad : {0.0, -1e-6, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
        ProfileReadOptions o;
        o.spacing = bad;
        try {
            readProfile(path, o);
            ADD_FAILURE() << "spacing " << bad << " accepted";
        } catch (const ParameterError& e) {
            EXPECT_EQ(e.parameter(), "spacing");
        }
    }
}

// Found by fuzzing (tests/fuzz/corpus/profileReader/crash-one-column-spacing-max-double-
// length-inf): a finite spacing whose scan length N dx overflows gave a Profile of length inf.
TEST_F(ProfileReaderTest, spacingWhoseScanLengthOverflowsIsAParameterError)
{
    // Found by fuzzing: a finite spacing whose scan length N dx overflowed. Spacing and scan
    // length must lie within the accepted lengths (roughContact/Limits.hpp), checked before
    // N dx is formed.
    const std::string path = write("z.txt", "1\n2\n3\n4\n5\n6\n7\n8\n");
    ProfileReadOptions o;
    for (double dx : {std::numeric_limits<double>::max() / 4.0, 2.0 * limits::maximumLength,
                      limits::maximumLength / 4.0, 0.5 * limits::minimumLength}) {
        o.spacing = dx;
        try {
            const Profile p = readProfile(path, o);
            ADD_FAILURE() << "accepted: length " << p.length();
        } catch (const ParameterError& e) {
            EXPECT_NE(e.parameter().find("spacing"), std::string::npos) << e.what();
        }
    }
    o.spacing = limits::maximumLength / 8.0; // 8 of them are the longest scan accepted
    EXPECT_EQ(readProfile(path, o).length(), limits::maximumLength);
}

TEST_F(ProfileReaderTest, positionsWhoseScanLengthOverflowsAreAnInputError)
{
    // Found by fuzzing: two positions near the largest double, whose span overflowed. Positions
    // beyond +-maximumLength are refused on their line, before any difference is taken.
    const double half = 0.45 * std::numeric_limits<double>::max();
    const std::string path = write("xz.txt", columns(8, -half, 2.0 * half / 7.0, ramp));
    expectLocated(profileError(path), path, 1, "lies beyond");
    // Within the accepted lengths, a span of most of them is read.
    const std::string fine = write("fine.txt", columns(8, -400.0, 100.0, ramp));
    EXPECT_EQ(readProfile(fine).length(), 800.0);
    const std::string tooLong = write("long.txt", columns(8, -400.0, 140.0, ramp));
    expectLocated(profileError(tooLong), tooLong, 8, "scan length");
}

TEST_F(ProfileReaderTest, spacingGivenForATwoColumnFileIsAnError)
{
    const std::string path = write("p.txt", columns(8, 0.0, 1e-6, ramp));
    ProfileReadOptions o;
    o.spacing = 1e-6;
    expectLocated(profileError(path, o), path, 0, "a spacing option is only for one-column files");
}

// ---- units ----------------------------------------------------------------------------------

TEST_F(ProfileReaderTest, unitsOptionScalesPositionsAndHeights)
{
    // The same numbers read as m, um and nm: heights and spacing scale by exactly the factor
    // (to one rounding of the product: relative 1e-15 is a few ulps).
    const std::size_t n = 10;
    const auto z = [](std::size_t i) { return 0.25 * static_cast<double>(i) - 1.0; };
    const std::string path = write("p.csv", "x,z\n" + columns(n, 0.0, 0.5, z, "%.1f", ","));
    const Profile metres = readProfile(path);
    EXPECT_EQ(metres.spacing(), 0.5); // the default is metres
    for (auto [unit, factor] : {std::pair{LengthUnit::um, 1e-6}, std::pair{LengthUnit::nm, 1e-9},
                                std::pair{LengthUnit::m, 1.0}}) {
        ProfileReadOptions o;
        o.units = unit;
        const Profile p = readProfile(path, o);
        EXPECT_NEAR(p.spacing(), 0.5 * factor, 1e-15 * 0.5 * factor);
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_NEAR(p.heights()[i], z(i) * factor, 1e-15 * std::abs(z(i) * factor));
        }
    }
}

TEST_F(ProfileReaderTest, unitsOptionAlsoScalesTheGivenSpacingOfOneColumnFiles)
{
    const std::string path = write("z.txt", "5\n-5\n5\n-5\n5\n-5\n5\n-5\n");
    ProfileReadOptions o;
    o.units = LengthUnit::um;
    o.spacing = 0.2; // um
    const Profile p = readProfile(path, o);
    EXPECT_NEAR(p.spacing(), 0.2e-6, 1e-15 * 0.2e-6); // one rounding of 0.2 * 1e-6
    EXPECT_NEAR(p.heights()[1], -5e-6, 1e-15 * 5e-6);
}

TEST_F(ProfileReaderTest, aHeaderNamingUnitsDoesNotChangeTheDefaultOutsideDektakExports)
{
    // Only a Dektak export (with its "Scan Data" section) declares units; any other header is
    // just skipped and the documented default, metres, holds.
    const std::string path = write("p.csv", "x [um], z [um]\n" + columns(8, 0.0, 0.5, ramp, "%.1f", ","));
    EXPECT_EQ(readProfile(path).spacing(), 0.5);
}

// ---- uniform grid ---------------------------------------------------------------------------

TEST_F(ProfileReaderTest, fixedDecimalsCoarserThanTheStepAreAccepted)
{
    // A true step of 0.15625 printed to 0.1 (as the Dektak export does): the printed x deviate
    // from any uniform grid by up to a whole 0.1, yet the grid is uniform.
    const std::size_t n = 1000;
    const double dx = 0.15625;
    const std::string path = write("p.csv", columns(n, 0.0, dx, ramp, "%.1f", ","));
    ProfileReadOptions o;
    o.units = LengthUnit::um;
    const Profile p = readProfile(path, o);
    // dx from the end points, each off by at most half the printed step 0.1: |error| <= 0.1/(N-1).
    EXPECT_NEAR(p.spacing() * 1e6, dx, 0.1 / static_cast<double>(n - 1));
}

TEST_F(ProfileReaderTest, significantDigitsAsAStreamPrintsThemAreAccepted)
{
    // Regression: positions written by `std::ofstream << x` (6 significant digits, trailing
    // zeros dropped) were rejected as uneven: 1.5625e-07 shows 11 decimals, 0.00149984 only 8,
    // and the check used the finest step of the column for every row.
    const std::size_t n = 9600;
    const double dx = 1.5625e-7;
    std::ostringstream os;
    for (std::size_t i = 0; i < n; ++i) {
        os << static_cast<double>(i) * dx << " " << ramp(i) << "\n";
    }
    const Profile p = readProfile(write("p.txt", os.str()));
    ASSERT_EQ(p.size(), n);
    // The last x, about 1.5e-3, is printed to 6 significant digits: off by at most 0.5e-8, so
    // dx = x_last/(N-1) is off by at most 0.5e-8/(N-1) (x_0 = 0 is exact).
    EXPECT_NEAR(p.spacing(), dx, 0.5e-8 / static_cast<double>(n - 1));
}

TEST_F(ProfileReaderTest, oneDisplacedPositionIsUnevenSpacingOnItsLine)
{
    // x = i * 1e-6 printed to 1e-12: a shift of 0.2 dx at row 10 (line 12, after the header)
    // is far above the printing precision; the ends are untouched, so no other row deviates.
    std::string text = "x z\n";
    for (std::size_t i = 0; i < 20; ++i) {
        const double x = (static_cast<double>(i) + (i == 10 ? 0.2 : 0.0)) * 1e-6;
        text += fmt("%.12f", x) + " " + fmt("%.17g", ramp(i)) + "\n";
    }
    const std::string path = write("p.txt", text);
    expectLocated(profileError(path), path, 12, "uneven spacing");
    expectLocated(profileError(path), path, 12, "found 0.000010200000");
}

TEST_F(ProfileReaderTest, aMissingSampleIsUnevenSpacing)
{
    // Positions 0..40 um, 1 um apart, printed to 1 nm, with x = 20 um left out: 40 rows, so the
    // grid through the ends has dx = 40/39 um and row 1 (x = 1 um, line 2) is 1/39 = 0.026 um
    // off it, 26 printed steps: the first row off the grid.
    std::string text;
    for (std::size_t i = 0; i <= 40; ++i) {
        if (i != 20) {
            text += fmt("%.3f", static_cast<double>(i)) + " 0\n";
        }
    }
    const std::string path = write("p.txt", text);
    ProfileReadOptions o;
    o.units = LengthUnit::um;
    expectLocated(profileError(path, o), path, 2, "uneven spacing: expected x = 1.025641026 um");
}

TEST_F(ProfileReaderTest, aPositionThreePrintedStepsOffIsRejectedEvenWhenCoarse)
{
    // A true step of 0.55 printed to 0.1; row 50 moved by +0.3 (still below row 51). Its
    // deviation from the grid through the printed ends is at least 0.3 - 2 * 0.05 = 0.2, above
    // the largest a uniform grid can show (0.1: half a step at the row, half at the ends).
    std::vector<std::string> lines = linesOf(columns(100, 0.0, 0.55, ramp, "%.1f", ","));
    lines[50] = fmt("%.1f", 50 * 0.55 + 0.3) + ",0";
    const std::string path = write("p.csv", joined(lines));
    expectLocated(profileError(path), path, 51, "uneven spacing");
    // Unmoved, the same file is a uniform grid.
    const std::string good = write("good.csv", columns(100, 0.0, 0.55, ramp, "%.1f", ","));
    EXPECT_EQ(readProfile(good).size(), 100u);
}

TEST_F(ProfileReaderTest, positionsMustIncreaseStrictly)
{
    std::vector<std::string> lines = linesOf(columns(10, 0.0, 1e-6, ramp, "%.3e"));
    const std::string decreasing = write("d.txt", "x z\n" + [&] {
        auto l = lines;
        std::swap(l[4], l[5]); // rows 5 and 6: lines 6 and 7 after the header
        return joined(l);
    }());
    expectLocated(profileError(decreasing), decreasing, 7,
                  "positions must increase strictly: x = 4.000e-06 m after x = 5.000e-06 m on line 6");

    auto dup = lines;
    dup[3] = lines[2]; // a repeated position
    const std::string repeated = write("r.txt", joined(dup));
    expectLocated(profileError(repeated), repeated, 4, "positions must increase strictly");

    // Entirely decreasing (a scan saved backwards) is not silently reversed.
    std::vector<std::string> rev(lines.rbegin(), lines.rend());
    const std::string backwards = write("b.txt", joined(rev));
    expectLocated(profileError(backwards), backwards, 2, "positions must increase strictly");
}

// ---- bad files ------------------------------------------------------------------------------

// The reader keeps line numbers only where they jump (blank and comment lines): errors after
// a jump still name the right lines.
TEST_F(ProfileReaderTest, errorsAfterBlankAndCommentLinesNameTheirLines)
{
    const std::string path =
        write("gap.txt", "x z\n0 1\n1 2\n\n# comment\n2 3\n3 4\n\n4 5\n3.5 6\n5 7\n6 8\n7 9\n");
    expectLocated(profileError(path), path, 10, "x = 3.5 m after x = 4 m on line 9");
}

TEST_F(ProfileReaderTest, fewerThanEightPoints)
{
    const std::string seven = write("seven.txt", "x z\n" + columns(7, 0.0, 1e-6, ramp));
    expectLocated(profileError(seven), seven, 0, "a profile needs at least 8 points, got 7");
    const std::string eight = write("eight.txt", "x z\n" + columns(8, 0.0, 1e-6, ramp));
    EXPECT_EQ(readProfile(eight).size(), 8u);

    ProfileReadOptions o;
    o.spacing = 1e-6;
    const std::string one = write("one.txt", "1\n2\n");
    expectLocated(profileError(one, o), one, 0, "a profile needs at least 8 points, got 2");
}

TEST_F(ProfileReaderTest, emptyFilesAndHeaderOnlyFiles)
{
    for (const std::string content : {"", "\n\r\n", "# only a comment\n", "x,z\n"}) {
        const std::string path = write("e.csv", content);
        expectLocated(profileError(path), path, 0, "a profile needs at least 8 points, got 0");
    }
}

TEST_F(ProfileReaderTest, missingFile)
{
    const std::string path = (dir_ / "absent.csv").string();
    expectLocated(profileError(path), path, 0, "cannot open the file for reading: there is no such file");
}

TEST_F(ProfileReaderTest, nonNumericNanAndInfFieldsNameTheirLine)
{
    const std::string body = columns(10, 0.0, 1e-6, ramp, "%.3e");
    for (auto [bad, column] : {std::pair{std::string("nan"), 2}, std::pair{std::string("inf"), 2},
                               std::pair{std::string("-inf"), 1}, std::pair{std::string("1e309"), 1},
                               std::pair{std::string("abc"), 2}, std::pair{std::string("1.2.3"), 1}}) {
        std::vector<std::string> lines = linesOf(body);
        lines[6] = column == 1 ? bad + " 1e-9" : "6.000e-06 " + bad;
        const std::string path = write("p.txt", "x z\n" + joined(lines));
        const InputError e = profileError(path);
        expectLocated(e, path, 8, "in column " + std::to_string(column));
        EXPECT_NE(std::string(e.what()).find("'" + bad + "'"), std::string::npos) << e.what();
    }
}

TEST_F(ProfileReaderTest, wrongNumberOfColumns)
{
    std::vector<std::string> lines = linesOf(columns(10, 0.0, 1e-6, ramp, "%.3e"));
    auto three = lines;
    three[3] += " 7";
    const std::string p3 = write("three.txt", joined(three));
    expectLocated(profileError(p3), p3, 4, "3 columns; at most 2 are allowed");

    auto one = lines;
    one[5] = "1e-9";
    const std::string p1 = write("one.txt", "# c\n" + joined(one));
    expectLocated(profileError(p1), p1, 7, "1 column where line 2 has 2");
}

// ---- mean and tilt are for Profile::detrended, downstream -----------------------------------

TEST_F(ProfileReaderTest, meanAndTiltAreKeptByTheReaderAndRemovedDownstream)
{
    // z = c0 + c1 x + A cos(2 pi k (i - m) / N), m = (N-1)/2. The cosine is symmetric about the
    // middle, so it has no mean and no tilt: detrending removes c0 + c1 x exactly and leaves
    // the cosine, whose spectrum is A at level k and 0 elsewhere.
    const std::size_t n = 256;
    const double dx = 0.5e-6;
    const double c0 = 3e-6;
    const double c1 = 0.02; // 20 nm per um: the tilt over the scan is 2.56 um, >> A
    const double A = 50e-9;
    const std::size_t k = 9;
    const double m = 0.5 * static_cast<double>(n - 1);
    const auto cosine = [&](std::size_t i) {
        return A * std::cos(2.0 * pi * static_cast<double>(k) * (static_cast<double>(i) - m)
                            / static_cast<double>(n));
    };
    const auto tilted = [&](std::size_t i) {
        return c0 + c1 * static_cast<double>(i) * dx + cosine(i);
    };
    const Profile p = readProfile(write("p.txt", columns(n, 0.0, dx, tilted)));

    // The reader does not detrend: its mean is c0 + c1 * mean(x), the cosine adding nothing.
    double mean = 0.0;
    for (double z : p.heights()) {
        mean += z;
    }
    mean /= static_cast<double>(n);
    const double expectedMean = c0 + c1 * m * dx;
    EXPECT_NEAR(mean, expectedMean, 1e-12 * expectedMean); // sums of 256 values: ~1e-14

    // Detrended: the cosine alone. Removing c0 + c1 x (up to 5.6 um) leaves the rounding of
    // sums over N = 256 values, <= N eps 5.6 um = 3e-19 m; 1e-15 m is far above that and far
    // below A = 5e-8 m.
    const Profile d = p.detrended();
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_NEAR(d.heights()[i], cosine(i), 1e-15) << i;
    }

    // And its spectrum: beta_k = A (level k is frequency k/L), the rest ~0. FFT rounding is
    // ~eps log N of the largest amplitude; 1e-9 A is far above it and far below any real error.
    const Spectrum s = Spectrum::fromProfile(p);
    const double L = static_cast<double>(n) * dx;
    ASSERT_GE(s.size(), k);
    EXPECT_NEAR(s.frequency(k - 1), static_cast<double>(k) / L, 1e-12 / L);
    for (std::size_t j = 0; j < s.size(); ++j) {
        EXPECT_NEAR(s.amplitude(j), j + 1 == k ? A : 0.0, 1e-9 * A) << "level " << j + 1;
    }
}

// ---- the real Dektak export -----------------------------------------------------------------
//
// tests/data/io/dektak-1.csv (Bruker Dektak, "\r\n" and "\r\r\n" line ends): metadata, then
// "Scan Data" on line 27, the data header "Lateral um,Raw Micrometer," on line 28 and 9600 rows
// "x,z,," on lines 29-9628, x printed to 0.1 um from 0.0 to 1499.8. Its metadata says
// "Length,1500.0 um" and "Resolution,0.156 um/sample": 9600 samples of 1500/9600 = 0.15625 um
// (the last at 9599 * 0.15625 = 1499.84375, printed 1499.8, as the file has it).

namespace {
constexpr std::size_t dektakRows = 9600;
constexpr double dektakStep = 1500e-6 / 9600.0; // m
} // namespace

TEST(DektakProfile, isRecognisedAndReadInMicrometres)
{
    const Profile p = readProfile(dektakPath);
    EXPECT_EQ(p.source(), dektakPath);
    ASSERT_EQ(p.size(), dektakRows);
    // First and last rows "0.0,-0.00933,," and "1499.8,16.58112,,": micrometres to metres,
    // one rounding of the product (4 ulps allowed by EXPECT_DOUBLE_EQ).
    EXPECT_DOUBLE_EQ(p.heights().front(), -0.00933e-6);
    EXPECT_DOUBLE_EQ(p.heights()[1], -0.00760e-6);
    EXPECT_DOUBLE_EQ(p.heights().back(), 16.58112e-6);
}

TEST(DektakProfile, spacingIsTheTrueStepNotThePrintedOne)
{
    const Profile p = readProfile(dektakPath);
    // dx = (x_last - x_0)/(N-1) from the printed ends, each within 0.05 um of the true position
    // (printed to 0.1 um): |dx - 0.15625 um| <= 0.1 um / (N-1) = 1.04e-5 um, 67 ppm.
    EXPECT_NEAR(p.spacing(), dektakStep, 0.1e-6 / static_cast<double>(dektakRows - 1));
    // The metadata's own "0.156 um/sample", good to its printed 0.0005 um.
    EXPECT_NEAR(p.spacing(), 0.156e-6, 0.0005e-6);
    // Not the printed grid: consecutive printed x differ by 0.1 or 0.2 um, never 0.156.
    EXPECT_GT(std::abs(p.spacing() - 0.1e-6), 0.05e-6);
    EXPECT_GT(std::abs(p.spacing() - 0.2e-6), 0.04e-6);
    // Scan length N dx = 1500.0 um ("Length,1500.0 um"), to N times the bound on dx.
    EXPECT_NEAR(p.length(), 1500e-6, 0.1e-6 * static_cast<double>(dektakRows) / (dektakRows - 1));
}

TEST(DektakProfile, roughnessBetweenTheCursorsMatchesTheInstrumentsOwnResults)
{
    // The export's "Analytical Results" give Ra = 0.00525 um and Rq = 0.01143 um between the
    // cursors at 468 um and 733 um. Levelling that stretch by its least-squares line (as the
    // instrument does between cursors) must reproduce them: this checks the units of x and z
    // and the spacing at once (a wrong unit is a factor 1000, a wrong step moves the stretch).
    // Tolerance 1%: the results are printed to 3 significant digits (0.1%), and whether the
    // samples at the cursors are included changes 2 of ~1700 samples (0.1%); 1% leaves room
    // for the instrument's exact levelling. A step 10% off moves the stretch enough to change
    // Ra or Rq by 5% or more (tried: 0.9 dx gives Ra -9%, 1.1 dx gives Rq -37%).
    const Profile p = readProfile(dektakPath);
    const double dx = p.spacing();
    std::vector<double> xs;
    std::vector<double> zs;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double x = static_cast<double>(i) * dx;
        if (x >= 468e-6 && x <= 733e-6) {
            xs.push_back(x);
            zs.push_back(p.heights()[i]);
        }
    }
    const double m = static_cast<double>(xs.size());
    double sx = 0.0, sz = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        sx += xs[i];
        sz += zs[i];
    }
    const double xm = sx / m;
    const double zm = sz / m;
    double sxx = 0.0, sxz = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        sxx += (xs[i] - xm) * (xs[i] - xm);
        sxz += (xs[i] - xm) * (zs[i] - zm);
    }
    const double slope = sxz / sxx;
    double ra = 0.0, rq = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double r = zs[i] - zm - slope * (xs[i] - xm);
        ra += std::abs(r);
        rq += r * r;
    }
    ra /= m;
    rq = std::sqrt(rq / m);
    EXPECT_NEAR(ra, 0.00525e-6, 0.01 * 0.00525e-6);
    EXPECT_NEAR(rq, 0.01143e-6, 0.01 * 0.01143e-6);
}

// The stream overload is what the path version reads through: the same profile, and errors
// name the given file name.
TEST(DektakProfile, aStreamReadsTheSameAsThePath)
{
    const Profile fromPath = readProfile(dektakPath);
    std::ifstream in(dektakPath, std::ios::binary);
    const Profile fromStream = readProfile(in, "export.csv");
    EXPECT_EQ(fromStream.heights(), fromPath.heights());
    EXPECT_EQ(fromStream.spacing(), fromPath.spacing());
    EXPECT_EQ(fromStream.source(), "export.csv");
    std::istringstream bad("0 1\n1 2\n2 x\n");
    try {
        readProfile(bad, "bad.csv");
        ADD_FAILURE() << "bad.csv was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("bad.csv:3: ", 0), 0u) << e.what();
    }
}

TEST(DektakProfile, unitsOptionOverridesTheHeader)
{
    const Profile um = readProfile(dektakPath);
    ProfileReadOptions o;
    o.units = LengthUnit::nm;
    const Profile nm = readProfile(dektakPath, o);
    ASSERT_EQ(nm.size(), um.size());
    // The same numbers, scaled by 1e-9 instead of 1e-6: a ratio of 1000 to a few ulps.
    EXPECT_NEAR(um.spacing() / nm.spacing(), 1000.0, 1e-12);
    EXPECT_NEAR(um.heights().back() / nm.heights().back(), 1000.0, 1e-12);
}

TEST_F(ProfileReaderTest, dektakHeaderNamesEachColumnsUnit)
{
    // The same export with heights declared in Angstrom or nm (other Dektak software versions):
    // x stays in um, z follows its own header. Before the fix any header naming "um" anywhere
    // made both columns um, and a header naming none made them metres.
    std::vector<std::string> lines = linesOf(slurp(dektakPath));
    ASSERT_GT(lines.size(), 28u);
    ASSERT_EQ(lines[27].rfind("Lateral um,Raw Micrometer,", 0), 0u); // line 28
    const Profile reference = readProfile(dektakPath);

    for (auto [header, factor] : {std::pair{std::string("Lateral um,Raw Angstrom,\r"), 1e-4},
                                  std::pair{std::string("Lateral(\xB5m),Total Profile(nm)\r"), 1e-3},
                                  std::pair{std::string("Lateral um,Raw \xC3\x85,\r"), 1e-4}}) {
        auto edited = lines;
        edited[27] = header;
        const Profile p = readProfile(write("d.csv", joined(edited)));
        ASSERT_EQ(p.size(), reference.size());
        EXPECT_DOUBLE_EQ(p.spacing(), reference.spacing()) << header;
        // One rounding each of z*1e-6 and z*1e-10 (or 1e-9): relative 1e-14 is generous.
        EXPECT_NEAR(p.heights().back(), reference.heights().back() * factor,
                    1e-14 * reference.heights().back() * factor)
            << header;
    }

    // A header naming no unit: an error at that line, not a guess of metres.
    auto bare = lines;
    bare[27] = "Lateral,Raw,\r";
    const std::string path = write("bare.csv", joined(bare));
    expectLocated(profileError(path), path, 28, "names no length unit");
    // Unless the units option says what they are.
    ProfileReadOptions o;
    o.units = LengthUnit::um;
    EXPECT_DOUBLE_EQ(readProfile(path, o).spacing(), reference.spacing());
}

TEST_F(ProfileReaderTest, dektakErrorsNameTheLineOfTheExport)
{
    std::vector<std::string> lines = linesOf(slurp(dektakPath));
    // Line 5000 (index 4999) holds row 4972; make its height unreadable, then swap it with
    // the next line.
    auto bad = lines;
    bad[4999] = lines[4999].substr(0, lines[4999].find(',')) + ",1.2.3,,\r";
    const std::string p1 = write("bad.csv", joined(bad));
    expectLocated(profileError(p1), p1, 5000, "non-numeric field '1.2.3' in column 2");

    auto swapped = lines;
    std::swap(swapped[4999], swapped[5000]);
    const std::string p2 = write("swapped.csv", joined(swapped));
    expectLocated(profileError(p2), p2, 5001, "positions must increase strictly");
}
