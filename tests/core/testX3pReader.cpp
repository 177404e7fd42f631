// SPDX-License-Identifier: GPL-3.0-or-later
// Reading X3P (ISO 25178-72) height maps (io/X3pReader): small archives built here with libzip
// (main.xml written as text, data little-endian byte by byte, MD5 by OpenSSL) for each data
// type, binary and inline data, every error (named after the file), invalid points with and
// without filling, and the real map data/x3p-2.x3p.
#include "roughContact/Error.hpp"
#include "roughContact/io/X3pReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include "TempDirTest.hpp"

#include <gtest/gtest.h>
#include <openssl/evp.h>
#include <zip.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace roughContact;

namespace {

const std::string x3p2Path = std::string(ROUGHCONTACT_SOURCE_DIR) + "/data/x3p-2.x3p";

/// A small X3P file to build: nx x ny points of raw values (x fastest) of one data type.
struct X3pFile {
    char type = 'D';
    std::size_t nx = 8;
    std::size_t ny = 10;
    std::string dx = "1.5e-6";
    std::string dy = "2.5e-6";
    std::string axisTypeX = "I";
    std::string zIncrement; ///< "" leaves the element out
    std::string zOffset;
    std::vector<double> raw; ///< NaN for an invalid point (D, F or inline)
    bool inlineData = false; ///< Record3/DataList instead of bin/data.bin
    std::string md5;         ///< "" : the right one
    std::string mask;        ///< bin/valid.bin; "" : none
    std::string sizeZ = "1";
};

/// Raw value of point i: distinct at every point, integral so that I and L hold it exactly.
double rawValue(std::size_t i)
{
    return std::round(1000.0 * std::sin(0.3 * static_cast<double>(i)) + 7.0 * static_cast<double>(i % 5));
}

std::string md5Hex(const std::string& data)
{
    unsigned char d[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    EVP_Digest(data.data(), data.size(), d, &n, EVP_md5(), nullptr);
    std::string out;
    char b[3];
    for (unsigned int i = 0; i < n; ++i) {
        std::snprintf(b, sizeof b, "%02x", d[i]);
        out += b;
    }
    return out;
}

/// The bytes of value v as type t, little-endian.
std::string bytesOf(char t, double v)
{
    std::uint64_t bits = 0;
    std::size_t n = 0;
    if (t == 'D') {
        std::memcpy(&bits, &v, 8);
        n = 8;
    } else if (t == 'F') {
        const float f = static_cast<float>(v);
        std::uint32_t b = 0;
        std::memcpy(&b, &f, 4);
        bits = b;
        n = 4;
    } else if (t == 'L') {
        bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(v));
        n = 4;
    } else {
        bits = static_cast<std::uint16_t>(static_cast<std::int16_t>(v));
        n = 2;
    }
    std::string out;
    for (std::size_t k = 0; k < n; ++k) {
        out += static_cast<char>((bits >> (8 * k)) & 0xFF);
    }
    return out;
}

std::string dataBin(const X3pFile& f)
{
    std::string out;
    for (double v : f.raw) {
        out += bytesOf(f.type, v);
    }
    return out;
}

std::string mainXml(const X3pFile& f)
{
    std::ostringstream os;
    os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
       << "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n"
       << "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>\n"
       << "<CX><AxisType>" << f.axisTypeX << "</AxisType><DataType>D</DataType><Increment>" << f.dx
       << "</Increment><Offset>0.001</Offset></CX>\n"
       << "<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>" << f.dy
       << "</Increment><Offset>0</Offset></CY>\n"
       << "<CZ><AxisType>A</AxisType><DataType>" << f.type << "</DataType>"
       << (f.zIncrement.empty() ? "" : "<Increment>" + f.zIncrement + "</Increment>")
       << (f.zOffset.empty() ? "" : "<Offset>" + f.zOffset + "</Offset>") << "</CZ>\n"
       << "</Axes></Record1>\n<Record2><Date>2026-01-01T00:00:00</Date></Record2>\n<Record3>\n"
       << "<MatrixDimension><SizeX>" << f.nx << "</SizeX><SizeY>" << f.ny << "</SizeY><SizeZ>" << f.sizeZ
       << "</SizeZ></MatrixDimension>\n";
    if (f.inlineData) {
        os << "<DataList>\n";
        for (double v : f.raw) {
            os << "<Datum>";
            if (!std::isnan(v)) {
                char b[40];
                std::snprintf(b, sizeof b, "%.17g", v);
                os << b;
            }
            os << "</Datum>\n";
        }
        os << "</DataList>\n";
    } else {
        os << "<DataLink><PointDataLink>bin/data.bin</PointDataLink><MD5ChecksumPointData>"
           << (f.md5.empty() ? md5Hex(dataBin(f)) : f.md5) << "</MD5ChecksumPointData>";
        if (!f.mask.empty()) {
            os << "<ValidPointsLink>bin/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>" << md5Hex(f.mask)
               << "</MD5ChecksumValidPoints>";
        }
        os << "</DataLink>\n";
    }
    os << "</Record3>\n<Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>\n</p:ISO5436_2>\n";
    return os.str();
}

/// xml without its first <element>...</element>.
std::string without(const std::string& xml, const std::string& element)
{
    const auto a = xml.find("<" + element + ">");
    const auto b = xml.find("</" + element + ">", a);
    EXPECT_NE(a, std::string::npos) << element;
    return xml.substr(0, a) + xml.substr(b + element.size() + 3);
}

class X3pReaderTest : public roughContactTest::TempDirTest {
protected:
    /// A zip archive at name holding the given entries (stored uncompressed when store).
    std::string zipFile(const std::string& name,
                        const std::vector<std::pair<std::string, std::string>>& entries, bool store = false)
    {
        const std::string path = (dir_ / name).string();
        int error = 0;
        zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
        EXPECT_NE(z, nullptr);
        for (const auto& e : entries) {
            zip_source_t* s = zip_source_buffer(z, e.second.data(), e.second.size(), 0);
            const zip_int64_t i = zip_file_add(z, e.first.c_str(), s, ZIP_FL_ENC_UTF_8);
            EXPECT_GE(i, 0);
            if (store) {
                zip_set_file_compression(z, static_cast<zip_uint64_t>(i), ZIP_CM_STORE, 0);
            }
        }
        EXPECT_EQ(zip_close(z), 0);
        return path;
    }
    /// The X3P file f (main.xml as given when xml is not empty).
    std::string x3p(const std::string& name, const X3pFile& f, const std::string& xml = "",
                    bool store = false)
    {
        std::vector<std::pair<std::string, std::string>> entries{
            {"main.xml", xml.empty() ? mainXml(f) : xml}};
        if (!f.inlineData) {
            entries.emplace_back("bin/data.bin", dataBin(f));
        }
        if (!f.mask.empty()) {
            entries.emplace_back("bin/valid.bin", f.mask);
        }
        return zipFile(name, entries, store);
    }
    static X3pFile sample(char type)
    {
        X3pFile f;
        f.type = type;
        f.zIncrement = "1e-9";
        for (std::size_t i = 0; i < f.nx * f.ny; ++i) {
            f.raw.push_back(rawValue(i));
        }
        return f;
    }
};

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Runs f, which must throw InputError naming file; returns its message.
std::string inputError(const std::function<void()>& f, const std::string& file)
{
    try {
        f();
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), file);
        return e.message();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

bool has(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

TEST_F(X3pReaderTest, eachDataTypeBinaryScaledByIncrementAndOffset)
{
    for (char type : {'D', 'F', 'I', 'L'}) {
        X3pFile f = sample(type);
        f.zIncrement = "2e-9";
        f.zOffset = "1e-6";
        const std::string path = x3p(std::string("t") + type + ".x3p", f);
        const ArealSurface s = readX3p(path);
        ASSERT_EQ(s.nx(), 8u) << type;
        ASSERT_EQ(s.ny(), 10u) << type;
        EXPECT_EQ(s.dx(), 1.5e-6);
        EXPECT_EQ(s.dy(), 2.5e-6);
        EXPECT_EQ(s.source(), path);
        for (std::size_t iy = 0; iy < 10; ++iy) {
            for (std::size_t ix = 0; ix < 8; ++ix) {
                // x fastest: point iy * nx + ix. The raw values are integers below 2^11, exact in
                // every type, so the only rounding is that of offset + increment * raw.
                EXPECT_EQ(s.at(ix, iy), 1e-6 + 2e-9 * rawValue(iy * 8 + ix))
                    << type << " " << ix << " " << iy;
            }
        }
    }
}

TEST_F(X3pReaderTest, doubleWithoutIncrementIsMetres)
{
    X3pFile f = sample('D');
    f.zIncrement.clear();
    for (double& v : f.raw) {
        v *= 1.25e-10;
    }
    const ArealSurface s = readX3p(x3p("d.x3p", f));
    EXPECT_EQ(s.at(3, 7), rawValue(7 * 8 + 3) * 1.25e-10);
}

TEST_F(X3pReaderTest, inlineDataList)
{
    X3pFile f = sample('D');
    f.inlineData = true;
    f.zIncrement = "1e-9";
    const ArealSurface s = readX3p(x3p("inline.x3p", f));
    ASSERT_EQ(s.nx(), 8u);
    EXPECT_EQ(s.at(5, 9), 1e-9 * rawValue(9 * 8 + 5));
    EXPECT_EQ(s.at(0, 0), 1e-9 * rawValue(0));
    // One Datum short.
    const std::string xml = mainXml(f);
    const std::string path = x3p("short.x3p", f, without(xml, "Datum"));
    EXPECT_TRUE(has(inputError([&] { readX3p(path); }, path), "has 79 Datum elements"));
}

TEST_F(X3pReaderTest, wrongChecksum)
{
    X3pFile f = sample('D');
    f.md5 = md5Hex("something else");
    const std::string path = x3p("md5.x3p", f);
    const std::string m = inputError([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "checksum mismatch")) << m;
    EXPECT_TRUE(has(m, "bin/data.bin")) << m;
    // The checksum in lower case is the same checksum.
    X3pFile lower = sample('D');
    EXPECT_NO_THROW(readX3p(x3p("lower.x3p", lower)));
}

TEST_F(X3pReaderTest, missingElementIsNamed)
{
    const X3pFile f = sample('L');
    const std::string xml = mainXml(f);
    const std::vector<std::pair<std::string, std::string>> cases{
        {"Increment", "Record1/Axes/CX/Increment"},
        {"SizeY", "Record3/MatrixDimension/SizeY"},
        {"MD5ChecksumPointData", "Record3/DataLink/MD5ChecksumPointData"},
        {"PointDataLink", "Record3/DataLink/PointDataLink"},
        {"CZ", "Record1/Axes/CZ"},
        {"Record1", "Record1"}};
    for (const auto& c : cases) {
        const std::string path = x3p("missing.x3p", f, without(xml, c.first));
        const std::string m = inputError([&] { readX3p(path); }, path);
        EXPECT_TRUE(has(m, "no " + c.second + " element")) << c.first << ": " << m;
    }
    const std::string noData = x3p("nodata.x3p", f, without(xml, "DataLink"));
    EXPECT_TRUE(has(inputError([&] { readX3p(noData); }, noData), "neither Record3/DataLink nor"));
    // No main.xml at all, or no data file.
    const std::string noXml = zipFile("noxml.x3p", {{"bin/data.bin", dataBin(f)}});
    EXPECT_TRUE(has(inputError([&] { readX3p(noXml); }, noXml), "no main.xml"));
    const std::string noBin = zipFile("nobin.x3p", {{"main.xml", xml}});
    EXPECT_TRUE(has(inputError([&] { readX3p(noBin); }, noBin), "no bin/data.bin"));
}

TEST_F(X3pReaderTest, truncatedOrCorruptArchive)
{
    const std::string good = readFile(x3p("good.x3p", sample('D'), "", true));
    for (std::size_t keep : {good.size() / 2, good.size() - 10, std::size_t(1)}) {
        const std::string path = write("cut.x3p", good.substr(0, keep));
        const std::string m = inputError([&] { readX3p(path); }, path);
        EXPECT_TRUE(has(m, "not a readable zip archive")) << keep << ": " << m;
    }
    const std::string empty = write("empty.x3p", "");
    EXPECT_TRUE(has(inputError([&] { readX3p(empty); }, empty), "the file is empty"));
    // A flipped byte inside the (stored) point data: the zip's CRC catches it.
    const std::string data = dataBin(sample('D'));
    std::string corrupt = good;
    const auto at = corrupt.find(data);
    ASSERT_NE(at, std::string::npos);
    corrupt[at + 100] = static_cast<char>(corrupt[at + 100] ^ 0x10);
    const std::string path = write("crc.x3p", corrupt);
    const std::string m = inputError([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "corrupt")) << m;
    const std::string text = write("text.x3p", "not a zip at all\n");
    EXPECT_TRUE(has(inputError([&] { readX3p(text); }, text), "not a readable zip archive"));
}

TEST_F(X3pReaderTest, sizesThatDisagreeWithTheData)
{
    X3pFile f = sample('F');
    f.raw.pop_back();
    const std::string path = x3p("size.x3p", f);
    const std::string m = inputError([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "has 316 bytes")) << m;
    EXPECT_TRUE(has(m, "need 320")) << m;
    X3pFile big = sample('I');
    big.raw.push_back(1.0);
    const std::string path2 = x3p("big.x3p", big);
    EXPECT_TRUE(has(inputError([&] { readX3p(path2); }, path2), "at most 160"));
}

TEST_F(X3pReaderTest, unsupportedAxesAndLayouts)
{
    X3pFile absolute = sample('D');
    absolute.axisTypeX = "A";
    const std::string a = x3p("absolute.x3p", absolute);
    EXPECT_TRUE(has(inputError([&] { readX3p(a); }, a), "Record1/Axes/CX/AxisType is A"));
    X3pFile layers = sample('D');
    layers.sizeZ = "2";
    const std::string z = x3p("layers.x3p", layers);
    EXPECT_TRUE(has(inputError([&] { readX3p(z); }, z), "SizeZ is 2"));
    X3pFile badType = sample('D');
    const std::string xml = mainXml(badType);
    const std::string cz = "<CZ><AxisType>A</AxisType><DataType>D</DataType>";
    std::string xmlQ = xml;
    xmlQ.replace(xml.find(cz), cz.size(), "<CZ><AxisType>A</AxisType><DataType>Q</DataType>");
    const std::string q = x3p("type.x3p", badType, xmlQ);
    EXPECT_TRUE(has(inputError([&] { readX3p(q); }, q), "CZ/DataType is 'Q'"));
    X3pFile small = sample('D');
    small.nx = 7;
    small.raw.resize(70);
    const std::string s = x3p("small.x3p", small);
    EXPECT_TRUE(has(inputError([&] { readX3p(s); }, s), "at least 8 x 8"));
    const std::string broken =
        x3p("xml.x3p", sample('D'), "<?xml version=\"1.0\"?>\n<p:ISO5436_2>\n<Record1>\n");
    EXPECT_TRUE(has(inputError([&] { readX3p(broken); }, broken), "main.xml line"));
}

/// The mean of z at the given (ix, iy) points of an 8-wide map.
double meanAt(const std::vector<double>& z, const std::vector<std::pair<int, int>>& points)
{
    double s = 0.0;
    for (const auto& p : points) {
        s += z[static_cast<std::size_t>(p.second * 8 + p.first)];
    }
    return s / static_cast<double>(points.size());
}

TEST_F(X3pReaderTest, invalidPointsAreAnErrorUnlessFilled)
{
    // NaN at (2, 3) (all 8 neighbours valid) and a 3 x 3 hole centred on (5, 6).
    X3pFile f = sample('D');
    f.zIncrement.clear();
    for (double& v : f.raw) {
        v *= 1e-9;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    f.raw[3 * 8 + 2] = nan;
    for (int y = 5; y <= 7; ++y) {
        for (int x = 4; x <= 6; ++x) {
            f.raw[static_cast<std::size_t>(y * 8 + x)] = nan;
        }
    }
    const std::string path = x3p("nan.x3p", f);
    const std::string m = inputError([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "10 of 80 points are invalid")) << m;

    X3pReadOptions fill;
    fill.fillInvalid = true;
    const ArealSurface s = readX3p(path, fill);
    std::vector<double> z = f.raw;
    EXPECT_EQ(s.at(2, 3), meanAt(z, {{1, 2}, {2, 2}, {3, 2}, {1, 3}, {3, 3}, {1, 4}, {2, 4}, {3, 4}}));
    // The hole's rim first, from the valid points around it; its centre then from the rim.
    z[3 * 8 + 2] = s.at(2, 3);
    const auto rim = [&](int x, int y) {
        std::vector<std::pair<int, int>> p;
        for (int j = y - 1; j <= y + 1; ++j) {
            for (int i = x - 1; i <= x + 1; ++i) {
                const bool inHole = i >= 4 && i <= 6 && j >= 5 && j <= 7;
                if (i >= 0 && i < 8 && j >= 0 && j < 10 && !inHole) {
                    p.emplace_back(i, j);
                }
            }
        }
        return meanAt(z, p);
    };
    double ringSum = 0.0;
    for (int y = 5; y <= 7; ++y) {
        for (int x = 4; x <= 6; ++x) {
            if (x != 5 || y != 6) {
                EXPECT_DOUBLE_EQ(s.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y)), rim(x, y))
                    << x << " " << y;
                ringSum += rim(x, y);
            }
        }
    }
    EXPECT_DOUBLE_EQ(s.at(5, 6), ringSum / 8.0);
    EXPECT_EQ(s.at(0, 0), 1e-9 * rawValue(0));

    // Inline data: an empty Datum is an invalid point.
    X3pFile text = sample('D');
    text.inlineData = true;
    text.raw[10] = nan;
    const std::string inlinePath = x3p("inline.x3p", text);
    EXPECT_TRUE(has(inputError([&] { readX3p(inlinePath); }, inlinePath), "1 of 80 points are invalid"));
}

TEST_F(X3pReaderTest, validPointsMask)
{
    X3pFile f = sample('I');
    f.mask.assign(10, '\xFF');
    f.mask[2] = static_cast<char>(0xFF & ~(1 << 1)); // point 17 = (1, 2): byte 2, bit 1
    const std::string path = x3p("mask.x3p", f);
    EXPECT_TRUE(has(inputError([&] { readX3p(path); }, path), "1 of 80 points are invalid"));
    X3pReadOptions fill;
    fill.fillInvalid = true;
    const ArealSurface s = readX3p(path, fill);
    std::vector<double> z;
    for (double v : f.raw) {
        z.push_back(1e-9 * v);
    }
    EXPECT_DOUBLE_EQ(s.at(1, 2), meanAt(z, {{0, 1}, {1, 1}, {2, 1}, {0, 2}, {2, 2}, {0, 3}, {1, 3}, {2, 3}}));
    EXPECT_EQ(s.at(2, 2), 1e-9 * rawValue(18));
    // A mask of the wrong length.
    X3pFile shortMask = sample('I');
    shortMask.mask.assign(9, '\xFF');
    const std::string p2 = x3p("shortmask.x3p", shortMask);
    EXPECT_TRUE(has(inputError([&] { readX3p(p2); }, p2), "needs 10"));
}

// The real map. Its sizes and increments are those of its main.xml; the heights below were read
// independently of this code with python3:
//   z = zipfile.ZipFile('data/x3p-2.x3p'); d = z.read('bindata/data.bin')
//   v = struct.unpack('<422500d', d); repr(v[iy * 650 + ix])
// and hashlib.md5(d).hexdigest() equals its Record3/DataLink/MD5ChecksumPointData (which the
// reader checks).
TEST(X3pReaderReal, x3p2)
{
    const ArealSurface s = readX3p(x3p2Path);
    ASSERT_EQ(s.nx(), 650u);
    ASSERT_EQ(s.ny(), 650u);
    EXPECT_EQ(s.dx(), 1.27656509837346e-007);
    EXPECT_EQ(s.dy(), 3.14582113527746e-007);
    EXPECT_EQ(s.at(0, 0), 6.579781341223288e-08);
    EXPECT_EQ(s.at(649, 0), -4.133318658776711e-08);
    EXPECT_EQ(s.at(0, 1), 6.233641341223288e-08);
    EXPECT_EQ(s.at(325, 400), 8.098171341223286e-08);
    EXPECT_EQ(s.at(649, 649), -3.276918658776711e-08);
}

} // namespace
