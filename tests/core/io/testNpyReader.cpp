// SPDX-License-Identifier: GPL-3.0-or-later
// NumPy .npy height maps (NpyReader.hpp): the bytes numpy.save writes for a 2-D array, built here
// (format versions 1 and 2, float64 and float32, either byte order, C and Fortran order), give
// the heights of the same matrix as text; what is not such an array is an InputError naming the
// file and why. (tests/python/test_npy.py checks against numpy itself.)
#include "InputErrors.hpp"
#include "TempDirTest.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/MatrixReader.hpp"
#include "roughContact/io/NpyReader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace roughContact;
using namespace roughContactTest;

namespace {

// A .npy file's bytes: magic, version, header (padded so the data starts at a multiple of 64, as
// numpy writes it), data.
std::string npy(const std::string& descr, bool fortran, const std::string& shape, const std::string& data,
                int major = 1)
{
    std::string header = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                         ", 'shape': " + shape + ", }";
    const std::size_t prefix = major == 1 ? 10 : 12;
    while ((prefix + header.size() + 1) % 64 != 0) {
        header += ' ';
    }
    header += '\n';
    std::string out = "\x93NUMPY";
    out += static_cast<char>(major);
    out += '\0';
    const std::uint32_t n = static_cast<std::uint32_t>(header.size());
    out += static_cast<char>(n & 0xff);
    out += static_cast<char>((n >> 8) & 0xff);
    if (major != 1) {
        out += static_cast<char>((n >> 16) & 0xff);
        out += static_cast<char>((n >> 24) & 0xff);
    }
    return out + header + data;
}

template <class T>
std::string bytes(const std::vector<T>& v, bool bigEndian)
{
    std::string out;
    for (T x : v) {
        char b[sizeof(T)];
        std::memcpy(b, &x, sizeof(T));
        if (bigEndian) {
            std::reverse(b, b + sizeof(T));
        }
        out.append(b, sizeof(T));
    }
    return out;
}

// A 10 x 9 map (ny = 9 rows along y, nx = 10 columns along x: the smallest areal surface is
// 8 x 8) of distinct heights [um].
constexpr std::size_t nx = 10, ny = 9;
double z(std::size_t ix, std::size_t iy)
{
    return 0.25 * double(ix) - 1.5 * double(iy) + 0.125 * double(ix * iy);
}

std::string matrixText()
{
    std::string t;
    for (std::size_t iy = 0; iy < ny; ++iy) {
        for (std::size_t ix = 0; ix < nx; ++ix) {
            t += std::to_string(z(ix, iy)) + (ix + 1 < nx ? " " : "\n");
        }
    }
    return t;
}

template <class T>
std::vector<T> values(bool fortran)
{
    std::vector<T> v;
    if (fortran) {
        for (std::size_t ix = 0; ix < nx; ++ix) {
            for (std::size_t iy = 0; iy < ny; ++iy) {
                v.push_back(static_cast<T>(z(ix, iy)));
            }
        }
    } else {
        for (std::size_t iy = 0; iy < ny; ++iy) {
            for (std::size_t ix = 0; ix < nx; ++ix) {
                v.push_back(static_cast<T>(z(ix, iy)));
            }
        }
    }
    return v;
}

class NpyReader : public TempDirTest {
protected:
    ArealReadOptions options() const
    {
        ArealReadOptions o;
        o.units = LengthUnit::um;
        o.dx = 2.0;
        o.dy = 3.0;
        return o;
    }
};

} // namespace

TEST_F(NpyReader, EveryLayoutGivesTheTextMatrixHeights)
{
    const ArealSurface text = readAreal(write("m.txt", matrixText()), options());
    struct Case {
        const char* name;
        std::string content;
    };
    const Case cases[] = {
        {"c8.npy", npy("<f8", false, "(9, 10)", bytes(values<double>(false), false))},
        {"f8.npy", npy("<f8", true, "(9, 10)", bytes(values<double>(true), false))},
        {"be8.npy", npy(">f8", false, "(9, 10)", bytes(values<double>(false), true))},
        {"c4.npy", npy("<f4", false, "(9, 10)", bytes(values<float>(false), false))},
        {"be4f.npy", npy(">f4", true, "(9, 10)", bytes(values<float>(true), true))},
        {"v2.NPY", npy("<f8", false, "(9, 10)", bytes(values<double>(false), false), 2)},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const ArealSurface s = readAreal(write(c.name, c.content), options());
        ASSERT_EQ(s.nx(), nx);
        ASSERT_EQ(s.ny(), ny);
        EXPECT_DOUBLE_EQ(s.dx(), 2e-6);
        EXPECT_DOUBLE_EQ(s.dy(), 3e-6);
        for (std::size_t k = 0; k < nx * ny; ++k) {
            // std::to_string keeps 6 decimals: the quarter steps here are exact in both.
            EXPECT_DOUBLE_EQ(s.heights()[k], text.heights()[k]) << k;
        }
    }
}

TEST_F(NpyReader, WhatIsNotAHeightArrayIsNamed)
{
    const std::string data = bytes(values<double>(false), false);
    struct Case {
        const char* name;
        std::string content;
        const char* says;
    };
    const Case cases[] = {
        {"magic.npy", "PK\x03\x04 not numpy", "not a NumPy .npy file"},
        {"int.npy", npy("<i8", false, "(9, 10)", data), "dtype is '<i8'"},
        {"oneD.npy", npy("<f8", false, "(90,)", data), "2-D"},
        {"threeD.npy", npy("<f8", false, "(3, 3, 10)", data), "2-D"},
        {"small.npy", npy("<f8", false, "(2, 10)", data), "at least"},
        {"short.npy", npy("<f8", false, "(9, 10)", data.substr(0, 100)), "truncated: 100 of 720 bytes"},
        {"version.npy", npy("<f8", false, "(9, 10)", data, 7), "version 7"},
        // Issue 49, item 15: a key given twice was read first-wins (numpy takes the last): the
        // header is not one numpy.save writes, and is refused.
        {"twice.npy", npy("<f8", false, "(9, 10), 'shape': (10, 9)", data), "gives 'shape' more than once"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = write(c.name, c.content);
        expectLocated(thrownInputError([&] { readAreal(path, options()); }, path), path, 0, c.says);
    }
    std::vector<double> nan = values<double>(false);
    nan[2 * nx + 3] = std::numeric_limits<double>::quiet_NaN();
    const std::string path = write("nan.npy", npy("<f8", false, "(9, 10)", bytes(nan, false)));
    expectLocated(thrownInputError([&] { readAreal(path, options()); }, path), path, 0, "[2, 3]");
}

TEST_F(NpyReader, NeedsItsSpacingAndTakesNoX3pOption)
{
    const std::string path = write("c8.npy", npy("<f8", false, "(9, 10)", bytes(values<double>(false), false)));
    ArealReadOptions o;
    EXPECT_THROW(readAreal(path, o), ParameterError);
    o.dx = 1e-6;
    o.fillInvalid = true;
    EXPECT_THROW(readAreal(path, o), ParameterError);
    EXPECT_TRUE(isNpyPath("a/b.NpY"));
    EXPECT_FALSE(isNpyPath("npy"));
}
