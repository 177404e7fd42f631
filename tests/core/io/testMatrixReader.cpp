// SPDX-License-Identifier: GPL-3.0-or-later
// Reading height maps from text matrices (io/MatrixReader): layout (rows along y, columns along
// x), separators, comments, spacings and units, and every error naming the file and line.
#include "roughContact/Error.hpp"
#include "roughContact/io/MatrixReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include "InputErrors.hpp"
#include "TempDirTest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace roughContact;

namespace {

class MatrixReaderTest : public roughContactTest::TempDirTest {};

/// A height that differs at every point and prints with 17 digits: z(ix, iy).
double height(std::size_t ix, std::size_t iy)
{
    return 1e-7 * std::sin(0.37 * static_cast<double>(ix) + 1.1 * static_cast<double>(iy)) +
           1e-9 * static_cast<double>(ix);
}

/// nx columns by ny rows of height(), each row on a line, separated by sep.
std::string matrix(std::size_t nx, std::size_t ny, const std::string& sep = " ", double scale = 1.0)
{
    std::ostringstream os;
    for (std::size_t iy = 0; iy < ny; ++iy) {
        for (std::size_t ix = 0; ix < nx; ++ix) {
            char buffer[40];
            std::snprintf(buffer, sizeof buffer, "%.17g", height(ix, iy) * scale);
            os << (ix > 0 ? sep : "") << buffer;
        }
        os << "\n";
    }
    return os.str();
}

MatrixReadOptions spacing(double dx)
{
    MatrixReadOptions o;
    o.dx = dx;
    return o;
}

// inputErrorMessage(f, file, line): runs f, which must throw InputError naming file and line;
// returns its message (tests/support/InputErrors.hpp).
using roughContactTest::inputErrorMessage;

TEST_F(MatrixReaderTest, readsBackExactlyRowsAlongY)
{
    const std::string path = write("map.txt", matrix(12, 9));
    const ArealSurface s = readMatrix(path, spacing(2e-6));
    ASSERT_EQ(s.nx(), 12u);
    ASSERT_EQ(s.ny(), 9u);
    EXPECT_EQ(s.dx(), 2e-6);
    EXPECT_EQ(s.dy(), 2e-6); // dy defaults to dx
    EXPECT_EQ(s.source(), path);
    for (std::size_t iy = 0; iy < 9; ++iy) {
        for (std::size_t ix = 0; ix < 12; ++ix) {
            EXPECT_EQ(s.at(ix, iy), height(ix, iy)) << ix << " " << iy; // %.17g round-trips
        }
    }
}

TEST_F(MatrixReaderTest, commasCommentsAndBlankLines)
{
    const std::string text = "# a height map\n\n" + matrix(8, 8, ", ") + "\n# end\n";
    const ArealSurface s = readMatrix(write("map.csv", text), spacing(1e-6));
    ASSERT_EQ(s.nx(), 8u);
    ASSERT_EQ(s.ny(), 8u);
    EXPECT_EQ(s.at(7, 0), height(7, 0));
    EXPECT_EQ(s.at(0, 7), height(0, 7));
    const ArealSurface tabs = readMatrix(write("map.tsv", matrix(8, 8, "\t")), spacing(1e-6));
    EXPECT_EQ(tabs.at(5, 6), height(5, 6));
}

TEST_F(MatrixReaderTest, spacingsAndUnits)
{
    MatrixReadOptions o;
    o.units = LengthUnit::um;
    o.dx = 0.5;
    o.dy = 2.0;
    const ArealSurface um = readMatrix(write("um.txt", matrix(8, 10, " ", 1e6)), o);
    EXPECT_DOUBLE_EQ(um.dx(), 0.5e-6);
    EXPECT_DOUBLE_EQ(um.dy(), 2e-6);
    EXPECT_NEAR(um.at(3, 9), height(3, 9), 1e-22);
    o.units = LengthUnit::nm;
    o.dy.reset();
    const ArealSurface nm = readMatrix(write("nm.txt", matrix(8, 10, " ", 1e9)), o);
    EXPECT_DOUBLE_EQ(nm.dx(), 0.5e-9);
    EXPECT_DOUBLE_EQ(nm.dy(), 0.5e-9);
    EXPECT_NEAR(nm.at(7, 2), height(7, 2), 1e-22);
}

TEST_F(MatrixReaderTest, spacingRequiredAndPositive)
{
    const std::string path = write("map.txt", matrix(8, 8));
    EXPECT_THROW(readMatrix(path, MatrixReadOptions()), ParameterError);
    EXPECT_THROW(readMatrix(path, spacing(0.0)), ParameterError);
    EXPECT_THROW(readMatrix(path, spacing(-1e-6)), ParameterError);
    MatrixReadOptions o = spacing(1e-6);
    o.dy = std::nan("");
    EXPECT_THROW(readMatrix(path, o), ParameterError);
}

TEST_F(MatrixReaderTest, raggedRowNamesItsLine)
{
    std::string text = "# comment\n" + matrix(8, 8); // data rows on lines 2..9
    text += "1 2 3 4 5 6 7\n";                       // line 10: one short
    const std::string path = write("ragged.txt", text);
    const std::string m = inputErrorMessage([&] { readMatrix(path, spacing(1e-6)); }, path, 10);
    EXPECT_NE(m.find("7 columns where line 2 has 8"), std::string::npos) << m;
}

TEST_F(MatrixReaderTest, nonNumericFieldNamesItsLine)
{
    std::string text = matrix(8, 3) + "1 2 3 x4 5 6 7 8\n" + matrix(8, 5); // line 4
    const std::string path = write("text.txt", text);
    const std::string m = inputErrorMessage([&] { readMatrix(path, spacing(1e-6)); }, path, 4);
    EXPECT_NE(m.find("'x4'"), std::string::npos) << m;
    // A first line of text is no header in a matrix.
    const std::string headed = write("headed.txt", "\n  z0 z1 z2\n" + matrix(8, 8));
    const std::string h = inputErrorMessage([&] { readMatrix(headed, spacing(1e-6)); }, headed, 2);
    EXPECT_NE(h.find("'z0'"), std::string::npos) << h;
}

TEST_F(MatrixReaderTest, nanAndInfinityNameTheirLine)
{
    for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
        const std::string text = matrix(8, 5) + "1 2 3 4 " + std::string(bad) + " 6 7 8\n" + matrix(8, 3);
        const std::string path = write("bad.txt", text);
        const std::string m = inputErrorMessage([&] { readMatrix(path, spacing(1e-6)); }, path, 6);
        EXPECT_NE(m.find("not a finite number"), std::string::npos) << bad << ": " << m;
    }
}

TEST_F(MatrixReaderTest, fewerThanEightByEightPoints)
{
    for (const auto& size : {std::pair<int, int>{7, 8}, {8, 7}, {0, 0}}) {
        const std::string path = write(
            "small.txt", matrix(static_cast<std::size_t>(size.first), static_cast<std::size_t>(size.second)));
        const std::string m = inputErrorMessage([&] { readMatrix(path, spacing(1e-6)); }, path, 0);
        EXPECT_NE(m.find("at least 8 x 8"), std::string::npos) << m;
    }
    EXPECT_NO_THROW(readMatrix(write("eight.txt", matrix(8, 8)), spacing(1e-6)));
}

TEST_F(MatrixReaderTest, heightBeyondRangeNamesItsLine)
{
    const std::string path = write("tall.txt", matrix(8, 2) + "1 2 3 4 5 6 7 2e3\n" + matrix(8, 6));
    inputErrorMessage([&] { readMatrix(path, spacing(1e-6)); }, path, 3);
}

TEST_F(MatrixReaderTest, missingFileNamesIt)
{
    const std::string path = (dir_ / "none.txt").string();
    inputErrorMessage([&] { readMatrix(path, spacing(1e-6)); }, path, 0);
}

} // namespace
