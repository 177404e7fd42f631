// SPDX-License-Identifier: GPL-3.0-or-later
// Reading X3P (ISO 25178-72) height maps (io/X3pReader): small archives built here with libzip
// (main.xml written as text, data little-endian byte by byte, MD5 by OpenSSL) for each data
// type, binary and inline data, every error (named after the file), invalid points with and
// without filling, and the real map data/x3p-2.x3p.
#include "roughContact/Error.hpp"
#include "roughContact/io/X3pReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include "FileContents.hpp"
#include "InputErrors.hpp"
#include "TempDirTest.hpp"

#include <gtest/gtest.h>
#include <openssl/evp.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zip.h>

#include <chrono>
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

using roughContactTest::slurp; // tests/support/FileContents.hpp

// inputErrorMessage(f, file): runs f, which must throw InputError naming file; returns its
// message (tests/support/InputErrors.hpp).
using roughContactTest::inputErrorMessage;

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
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(path); }, path), "has 79 Datum elements"));
}

TEST_F(X3pReaderTest, wrongChecksum)
{
    X3pFile f = sample('D');
    f.md5 = md5Hex("something else");
    const std::string path = x3p("md5.x3p", f);
    const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
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
        const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
        EXPECT_TRUE(has(m, "no " + c.second + " element")) << c.first << ": " << m;
    }
    const std::string noData = x3p("nodata.x3p", f, without(xml, "DataLink"));
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(noData); }, noData), "neither Record3/DataLink nor"));
    // No main.xml at all, or no data file.
    const std::string noXml = zipFile("noxml.x3p", {{"bin/data.bin", dataBin(f)}});
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(noXml); }, noXml), "no main.xml"));
    const std::string noBin = zipFile("nobin.x3p", {{"main.xml", xml}});
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(noBin); }, noBin), "no bin/data.bin"));
}

TEST_F(X3pReaderTest, truncatedOrCorruptArchive)
{
    const std::string good = slurp(x3p("good.x3p", sample('D'), "", true));
    for (std::size_t keep : {good.size() / 2, good.size() - 10, std::size_t(1)}) {
        const std::string path = write("cut.x3p", good.substr(0, keep));
        const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
        EXPECT_TRUE(has(m, "not a readable zip archive")) << keep << ": " << m;
    }
    const std::string empty = write("empty.x3p", "");
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(empty); }, empty), "the file is empty"));
    // A flipped byte inside the (stored) point data: the zip's CRC catches it.
    const std::string data = dataBin(sample('D'));
    std::string corrupt = good;
    const auto at = corrupt.find(data);
    ASSERT_NE(at, std::string::npos);
    corrupt[at + 100] = static_cast<char>(corrupt[at + 100] ^ 0x10);
    const std::string path = write("crc.x3p", corrupt);
    const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "corrupt")) << m;
    const std::string text = write("text.x3p", "not a zip at all\n");
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(text); }, text), "not a readable zip archive"));
}

TEST_F(X3pReaderTest, sizesThatDisagreeWithTheData)
{
    X3pFile f = sample('F');
    f.raw.pop_back();
    const std::string path = x3p("size.x3p", f);
    const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "has 316 bytes")) << m;
    EXPECT_TRUE(has(m, "need 320")) << m;
    X3pFile big = sample('I');
    big.raw.push_back(1.0);
    const std::string path2 = x3p("big.x3p", big);
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(path2); }, path2), "at most 160"));
}

TEST_F(X3pReaderTest, unsupportedAxesAndLayouts)
{
    X3pFile absolute = sample('D');
    absolute.axisTypeX = "A";
    const std::string a = x3p("absolute.x3p", absolute);
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(a); }, a), "Record1/Axes/CX/AxisType is A"));
    X3pFile layers = sample('D');
    layers.sizeZ = "2";
    const std::string z = x3p("layers.x3p", layers);
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(z); }, z), "SizeZ is 2"));
    X3pFile badType = sample('D');
    const std::string xml = mainXml(badType);
    const std::string cz = "<CZ><AxisType>A</AxisType><DataType>D</DataType>";
    std::string xmlQ = xml;
    xmlQ.replace(xml.find(cz), cz.size(), "<CZ><AxisType>A</AxisType><DataType>Q</DataType>");
    const std::string q = x3p("type.x3p", badType, xmlQ);
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(q); }, q), "CZ/DataType is 'Q'"));
    X3pFile small = sample('D');
    small.nx = 7;
    small.raw.resize(70);
    const std::string s = x3p("small.x3p", small);
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(s); }, s), "at least 8 x 8"));
    const std::string broken =
        x3p("xml.x3p", sample('D'), "<?xml version=\"1.0\"?>\n<p:ISO5436_2>\n<Record1>\n");
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(broken); }, broken), "main.xml line"));
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
    const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
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
    EXPECT_TRUE(
        has(inputErrorMessage([&] { readX3p(inlinePath); }, inlinePath), "1 of 80 points are invalid"));
}

TEST_F(X3pReaderTest, validPointsMask)
{
    X3pFile f = sample('I');
    f.mask.assign(10, '\xFF');
    f.mask[2] = static_cast<char>(0xFF & ~(1 << 1)); // point 17 = (1, 2): byte 2, bit 1
    const std::string path = x3p("mask.x3p", f);
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(path); }, path), "1 of 80 points are invalid"));
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
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(p2); }, p2), "needs 10"));
}

/// zip (an archive's bytes) with the inflated size of entry, in its local and its central header,
/// set to size: a header that lies.
void declareSize(std::string& zip, const std::string& entry, std::uint32_t size)
{
    const auto put = [&](std::size_t at) {
        for (int k = 0; k < 4; ++k) {
            zip[at + static_cast<std::size_t>(k)] = static_cast<char>((size >> (8 * k)) & 0xFF);
        }
    };
    int patched = 0;
    for (std::size_t i = 0; i + 46 < zip.size(); ++i) {
        if (zip.compare(i, 4, "PK\x03\x04") == 0 && zip.compare(i + 30, entry.size(), entry) == 0) {
            put(i + 22);
            ++patched;
        } else if (zip.compare(i, 4, "PK\x01\x02") == 0 && zip.compare(i + 46, entry.size(), entry) == 0) {
            put(i + 24);
            ++patched;
        }
    }
    EXPECT_EQ(patched, 2) << entry;
}

/// What readX3p(path) gives in a child process whose address space may grow by at most
/// extraBytes: "ok NX x NY", "InputError: message" or "error: what" (a failed allocation among
/// them); "child died" when it did not exit.
std::string readX3pWithin(const std::string& path, std::size_t extraBytes)
{
    int fds[2];
    if (pipe(fds) != 0) {
        return "pipe failed";
    }
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        std::string out;
        std::ifstream statm("/proc/self/statm");
        std::size_t pages = 0;
        statm >> pages;
        const rlim_t cap =
            static_cast<rlim_t>(pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE)) + extraBytes);
        const struct rlimit limit {
            cap, cap
        };
        if (setrlimit(RLIMIT_AS, &limit) != 0) {
            out = "setrlimit failed";
        } else {
            try {
                const ArealSurface s = readX3p(path);
                out = "ok " + std::to_string(s.nx()) + " x " + std::to_string(s.ny());
            } catch (const InputError& e) {
                out = std::string("InputError: ") + e.message();
            } catch (const std::exception& e) {
                out = std::string("error: ") + e.what();
            }
        }
        const ssize_t w = ::write(fds[1], out.data(), out.size());
        (void)w;
        close(fds[1]);
        _exit(0);
    }
    close(fds[1]);
    std::string result;
    char buffer[4096];
    ssize_t n = 0;
    while ((n = read(fds[0], buffer, sizeof buffer)) > 0) {
        result.append(buffer, static_cast<std::size_t>(n));
    }
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? result : "child died";
}

double secondsSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Issue 18, item 5: a small file whose main.xml inflates to gigabytes of whitespace took 2.1 GB
// (main.xml held whole, then copied by pugixml). The markup outside the Datum values is now
// refused past x3pLimits::maximumMarkupBytes, as it inflates, before any tree is built; here a
// little more than that cap of whitespace (a 5 kB archive).
TEST_F(X3pReaderTest, markupBeyondItsCapIsRefusedAsItInflates)
{
    const X3pFile f = sample('D');
    std::string xml = mainXml(f);
    xml.insert(xml.find("</Record3>"), std::string(x3pLimits::maximumMarkupBytes + 1, ' '));
    const std::string path = x3p("whitespace.x3p", f, xml);
    const auto t0 = std::chrono::steady_clock::now();
    const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
    EXPECT_LT(secondsSince(t0), 5.0);
    EXPECT_TRUE(
        has(m, "main.xml has more than 4194304 bytes (the cap) outside the Datum values of Record3/DataList"))
        << m;
    EXPECT_TRUE(has(m, "refused before being parsed")) << m;
    EXPECT_TRUE(has(m, "binary point data (Record3/DataLink)")) << m;
    // Whitespace inside the list, between the Datum elements, is skipped as it passes: no cap.
    X3pFile text = sample('D');
    text.inlineData = true;
    std::string listXml = mainXml(text);
    listXml.insert(listXml.find("<Datum>"), std::string(2 * x3pLimits::maximumMarkupBytes, '\n'));
    const std::string listPath = x3p("listspace.x3p", text, listXml);
    EXPECT_EQ(readX3p(listPath).at(5, 9), 1e-9 * rawValue(9 * 8 + 5));
}

// Issue 18, item 5: an inline DataList of 4096^2 points took 4.4 GB (its text, pugixml's copy,
// two tree nodes of 64 bytes a Datum) and failed under a 4 GB cap with "not well-formed XML
// (Could not allocate memory)". The values are now read as main.xml inflates: a 1024^2 map
// (17 MB of XML, which took about 200 MB of address space) reads within 128 MB more.
TEST_F(X3pReaderTest, inlineDataListIsReadAsItInflates)
{
    X3pFile f = sample('D');
    f.nx = 1024;
    f.ny = 1024;
    std::string xml = mainXml(f);
    xml.erase(xml.find("<DataLink>"), xml.find("</Record3>") - xml.find("<DataLink>"));
    std::string list = "<DataList>\n";
    list.reserve(18 * f.nx * f.ny);
    for (std::size_t i = 0; i < f.nx * f.ny; ++i) {
        list += "<Datum>" + std::to_string(i % 1000) + "</Datum>\n";
    }
    list += "</DataList>\n";
    xml.insert(xml.find("</Record3>"), list);
    list = std::string();
    const std::string path = x3p("large.x3p", f, xml);
    xml = std::string();
    const auto t0 = std::chrono::steady_clock::now();
    const std::string r = readX3pWithin(path, std::size_t(128) << 20);
    EXPECT_EQ(r, "ok 1024 x 1024");
    EXPECT_LT(secondsSince(t0), 30.0);
    const ArealSurface s = readX3p(path);
    EXPECT_EQ(s.at(1023, 1023), 1e-9 * static_cast<double>((1024 * 1024 - 1) % 1000));
    EXPECT_EQ(s.at(7, 1), 1e-9 * static_cast<double>(1031 % 1000));
}

// Issue 18, item 5: zip headers are checked before inflating, and not trusted while inflating.
TEST_F(X3pReaderTest, zipHeadersThatLie)
{
    const X3pFile f = sample('D');
    const std::string good = slurp(x3p("good.x3p", f));
    // main.xml declared larger than the cap: refused before inflating, at once.
    std::string big = good;
    declareSize(big, "main.xml", static_cast<std::uint32_t>(x3pLimits::maximumXmlBytes + 1));
    const std::string bigPath = write("big.x3p", big);
    auto t0 = std::chrono::steady_clock::now();
    std::string m = inputErrorMessage([&] { readX3p(bigPath); }, bigPath);
    EXPECT_LT(secondsSince(t0), 1.0);
    EXPECT_TRUE(
        has(m, "main.xml has 1073741825 bytes (inflated, as its zip header says); at most 1073741824"))
        << m;
    EXPECT_TRUE(has(m, "refused before inflating")) << m;
    EXPECT_TRUE(has(m, "Export the map again, with binary point data")) << m;
    // The point data declared larger than Record3/MatrixDimension needs: the same.
    std::string bin = good;
    declareSize(bin, "bin/data.bin", 2000000000u);
    const std::string binPath = write("bin.x3p", bin);
    m = inputErrorMessage([&] { readX3p(binPath); }, binPath);
    EXPECT_TRUE(has(m, "bin/data.bin has 2000000000 bytes (inflated, as its zip header says); at most 640"))
        << m;
    EXPECT_TRUE(has(m, "refused before inflating")) << m;
    EXPECT_TRUE(has(m, "8 x 10 points (Record3/MatrixDimension) of type D need 640")) << m;
    // main.xml declared smaller than it inflates to: refused at the first byte beyond (it was
    // read cut short, and the rest ignored).
    std::string small = good;
    declareSize(small, "main.xml", 100);
    const std::string smallPath = write("small.x3p", small);
    m = inputErrorMessage([&] { readX3p(smallPath); }, smallPath);
    EXPECT_TRUE(has(m, "main.xml inflates to more than the 100 bytes its zip header declares")) << m;
    // Declared as large as allowed but small: nothing allocated by the header's word.
    std::string claim = good;
    declareSize(claim, "main.xml", static_cast<std::uint32_t>(x3pLimits::maximumXmlBytes));
    const std::string claimPath = write("claim.x3p", claim);
    t0 = std::chrono::steady_clock::now();
    const std::string r = readX3pWithin(claimPath, std::size_t(64) << 20);
    EXPECT_LT(secondsSince(t0), 5.0);
    EXPECT_TRUE(has(r, "InputError: ") && has(r, "main.xml")) << r;
}

// What Record3/DataList may hold, now that it is read as it passes: Datum elements (empty or
// <Datum/> is an invalid point; attributes ignored), comments, processing instructions and
// whitespace, split anywhere by the pieces main.xml inflates in; anything else is an error
// on its line.
TEST_F(X3pReaderTest, dataListContent)
{
    X3pFile f = sample('D');
    f.inlineData = true;
    f.nx = 200;
    f.ny = 150; // 30 000 points, about 0.8 MB of XML: pieces of 256 kB end inside elements
    f.raw.clear();
    for (std::size_t i = 0; i < f.nx * f.ny; ++i) {
        f.raw.push_back(rawValue(i));
    }
    std::string xml = mainXml(f);
    const auto replaceDatum = [&](std::size_t index, const std::string& with) {
        std::size_t at = xml.find("<Datum>");
        for (std::size_t k = 0; k < index; ++k) {
            at = xml.find("<Datum>", at + 1);
        }
        const std::size_t end = xml.find("</Datum>", at) + 8;
        xml.replace(at, end - at, with);
    };
    replaceDatum(29999, "<Datum unit=\"m\" >  " + std::to_string(rawValue(29999)) + "\n</Datum >");
    replaceDatum(20000, "<!-- a comment > with <Datum>9</Datum> in it --><?pi x?><Datum/>");
    replaceDatum(10000, "<Datum>\t" + std::to_string(rawValue(10000)) + " </Datum><!---->");
    replaceDatum(3, "<Datum></Datum>");
    const std::string path = x3p("content.x3p", f, xml);
    const std::string m = inputErrorMessage([&] { readX3p(path); }, path);
    EXPECT_TRUE(has(m, "2 of 30000 points are invalid")) << m;
    X3pReadOptions fill;
    fill.fillInvalid = true;
    const ArealSurface s = readX3p(path, fill);
    EXPECT_EQ(s.at(0, 0), 1e-9 * rawValue(0));
    EXPECT_EQ(s.at(199, 149), 1e-9 * rawValue(29999));
    EXPECT_EQ(s.at(0, 50), 1e-9 * rawValue(10000));
    EXPECT_EQ(s.at(1, 100), 1e-9 * rawValue(20001));

    // Errors, each on its line of main.xml (one Datum a line from line 12).
    X3pFile small = sample('D');
    small.inlineData = true;
    const std::string base = mainXml(small);
    const std::size_t second = base.find("<Datum>", base.find("<Datum>") + 1); // line 13
    const std::vector<std::pair<std::string, std::string>> cases{
        {"<Value>1</Value>", "main.xml line 13: Record3/DataList: a <Value> element; only Datum elements"},
        {"text", "main.xml line 13: Record3/DataList: text outside a Datum element ('text<Datum>"},
        {"<![CDATA[1]]>", "main.xml line 13: Record3/DataList: a CDATA section"},
        {"<Datum>1<b/></Datum>", "main.xml line 13: Record3/DataList: Datum 2 holds markup ('<b/>"},
        {"<Datum>1</Datu>", "main.xml line 13: Record3/DataList: not well-formed XML (end tag </Datu>"},
        {"</Record3>", "main.xml line 13: Record3/DataList: not well-formed XML (end tag </Record3>"},
        {"<Datum>x1</Datum>", "main.xml: Record3/DataList/Datum 2 is 'x1', not a number"},
        {"<Datum>" + std::string(2000, '1') + "</Datum>", "Datum 2 is longer than 1024 characters"},
        {"<Datum>1</Datum>", "Record3/DataList has 81 Datum elements; 8 x 10 points"}};
    for (const auto& c : cases) {
        std::string bad = base;
        bad.insert(second, c.first);
        const std::string p = x3p("list.x3p", small, bad);
        const std::string e = inputErrorMessage([&] { readX3p(p); }, p);
        EXPECT_TRUE(has(e, c.second)) << c.first << ": " << e;
    }
    // main.xml ends inside the list; markup broken after it is on its own line.
    const std::string cut = x3p("cut.x3p", small, base.substr(0, second));
    EXPECT_TRUE(has(inputErrorMessage([&] { readX3p(cut); }, cut),
                    "main.xml line 13: not well-formed XML (the file ends inside Record3/DataList)"));
    std::string after = base;
    after.replace(after.find("</Record3>"), 10, "</Record5>");
    const std::string afterPath = x3p("after.x3p", small, after);
    const std::string a = inputErrorMessage([&] { readX3p(afterPath); }, afterPath);
    EXPECT_TRUE(has(a, "main.xml line 93: not well-formed XML")) << a;
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
