// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface from an ISO 25178-72 X3P file: libzip opens the archive, pugixml
// parses main.xml, OpenSSL's EVP computes the MD5 checksums.
#include "roughContact/io/X3pReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/FloatingPoint.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/io/TableReader.hpp"

#include <openssl/evp.h>
#include <pugixml.hpp>
#include <zip.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {
/// The largest main.xml read: inline data of a full-size map at about 60 characters a point.
constexpr std::uint64_t maximumXmlBytes = 64ull * limits::maximumGridPoints;

struct ZipDiscard {
    void operator()(zip_t* z) const { zip_discard(z); }
};
struct ZipFileClose {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

/// The archive's entry `entry`, at most maxBytes long (more is an error naming both sizes).
std::string readEntry(zip_t* zip, const std::string& entry, std::uint64_t maxBytes, const std::string& name,
                      const std::string& linkedBy)
{
    const zip_int64_t index = zip_name_locate(zip, entry.c_str(), 0);
    if (index < 0) {
        throw InputError(name, 0,
                         "the archive has no " + detail::printable(entry, 80) +
                             (linkedBy.empty() ? std::string() : " (named by " + linkedBy + ")"));
    }
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(zip, static_cast<zip_uint64_t>(index), 0, &st) != 0 || !(st.valid & ZIP_STAT_SIZE)) {
        throw InputError(name, 0, "corrupt archive: cannot read the size of " + detail::printable(entry, 80));
    }
    if (st.size > maxBytes) {
        std::ostringstream os;
        os << detail::printable(entry, 80) << " has " << st.size << " bytes; at most " << maxBytes
           << " are expected";
        throw InputError(name, 0, os.str());
    }
    std::unique_ptr<zip_file_t, ZipFileClose> file(zip_fopen_index(zip, static_cast<zip_uint64_t>(index), 0));
    if (!file) {
        throw InputError(name, 0,
                         "corrupt archive: cannot open " + detail::printable(entry, 80) + ": " +
                             zip_strerror(zip));
    }
    // Read in pieces, so that memory grows with what the archive really holds, not with the size
    // its header claims (a lying header in a tiny file must not allocate a gigabyte).
    const auto size = static_cast<std::size_t>(st.size);
    std::string data;
    std::size_t done = 0;
    constexpr std::size_t piece = std::size_t(1) << 20;
    while (done < size) {
        data.resize(done + std::min(piece, size - done));
        const zip_int64_t n = zip_fread(file.get(), &data[done], data.size() - done);
        if (n < 0) {
            throw InputError(name, 0,
                             "corrupt or truncated archive: reading " + detail::printable(entry, 80) +
                                 " failed: " + zip_file_strerror(file.get()));
        }
        if (n == 0) {
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    data.resize(done);
    if (done != size) {
        std::ostringstream os;
        os << "truncated archive: " << detail::printable(entry, 80) << " ends after " << done << " of its "
           << size << " bytes";
        throw InputError(name, 0, os.str());
    }
    // The CRC of a stored entry is checked once its end has been read: ask for one more byte.
    char extra = 0;
    if (zip_fread(file.get(), &extra, 1) < 0) {
        throw InputError(name, 0,
                         "corrupt archive: " + detail::printable(entry, 80) + ": " +
                             zip_file_strerror(file.get()));
    }
    return data;
}

std::string md5Hex(const std::string& data)
{
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_Digest(data.data(), data.size(), digest, &length, EVP_md5(), nullptr) != 1) {
        throw std::runtime_error("OpenSSL could not compute an MD5 checksum");
    }
    static const char* const hex = "0123456789ABCDEF";
    std::string out;
    for (unsigned int i = 0; i < length; ++i) {
        out += hex[digest[i] >> 4];
        out += hex[digest[i] & 15];
    }
    return out;
}

std::string trimmed(const std::string& s)
{
    const char* space = " \t\r\n\f\v";
    const auto first = s.find_first_not_of(space);
    if (first == std::string::npos) {
        return std::string();
    }
    return s.substr(first, s.find_last_not_of(space) - first + 1);
}

/// main.xml, with the path of each element for messages (Record1/Axes/CX).
class Xml {
public:
    explicit Xml(const std::string& name) : name_(name) {}

    pugi::xml_node child(const pugi::xml_node& parent, const std::string& parentPath,
                         const char* element) const
    {
        const pugi::xml_node node = parent.child(element);
        if (!node) {
            throw InputError(name_, 0, "main.xml has no " + join(parentPath, element) + " element");
        }
        return node;
    }
    /// The trimmed text of parent/element (an error when the element is missing).
    std::string text(const pugi::xml_node& parent, const std::string& parentPath, const char* element) const
    {
        return trimmed(child(parent, parentPath, element).child_value());
    }
    /// parent/element as a finite number; fallback when the element is absent and a fallback is given.
    double number(const pugi::xml_node& parent, const std::string& parentPath, const char* element,
                  const double* fallback = nullptr) const
    {
        if (fallback && !parent.child(element)) {
            return *fallback;
        }
        const std::string t = text(parent, parentPath, element);
        double v = 0.0;
        if (!detail::parseNumber(t, v) || !std::isfinite(v)) {
            throw InputError(name_, 0,
                             "main.xml: " + join(parentPath, element) + " is '" + detail::printable(t) +
                                 "', not a finite number");
        }
        return v;
    }
    /// parent/element as a count (decimal digits only).
    std::uint64_t count(const pugi::xml_node& parent, const std::string& parentPath,
                        const char* element) const
    {
        const std::string t = text(parent, parentPath, element);
        std::uint64_t v = 0;
        bool ok = !t.empty() && t.size() <= 12;
        for (char c : t) {
            ok = ok && std::isdigit(static_cast<unsigned char>(c));
            v = 10 * v + static_cast<std::uint64_t>(c - '0');
        }
        if (!ok) {
            throw InputError(name_, 0,
                             "main.xml: " + join(parentPath, element) + " is '" + detail::printable(t) +
                                 "', not a count of points");
        }
        return v;
    }
    static std::string join(const std::string& parentPath, const char* element)
    {
        return parentPath.empty() ? std::string(element) : parentPath + "/" + element;
    }

private:
    const std::string& name_;
};

/// Bytes per value of an X3P data type.
std::size_t bytesOf(char type)
{
    return type == 'D' ? 8 : type == 'L' || type == 'F' ? 4 : 2;
}

/// Value i of little-endian binary data of `type`; false for a NaN (an invalid point). An
/// infinity is returned as such (the caller refuses it).
bool decode(const std::string& data, std::size_t i, char type, double& value)
{
    const auto* p = reinterpret_cast<const unsigned char*>(data.data()) + i * bytesOf(type);
    std::uint64_t bits = 0;
    for (std::size_t b = bytesOf(type); b-- > 0;) {
        bits = (bits << 8) | p[b];
    }
    switch (type) {
    case 'D': {
        // NaNs told apart by their bits: a signalling NaN must not reach a floating-point
        // instruction (it raises the invalid-operation trap).
        if ((bits & 0x7FF0000000000000ull) == 0x7FF0000000000000ull && (bits & 0x000FFFFFFFFFFFFFull) != 0) {
            return false;
        }
        std::memcpy(&value, &bits, sizeof value);
        return true;
    }
    case 'F': {
        const auto b32 = static_cast<std::uint32_t>(bits);
        if ((b32 & 0x7F800000u) == 0x7F800000u && (b32 & 0x007FFFFFu) != 0) {
            return false;
        }
        float f = 0.0f;
        std::memcpy(&f, &b32, sizeof f);
        value = static_cast<double>(f);
        return true;
    }
    case 'L':
        value = static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(bits)));
        return true;
    default:
        value = static_cast<double>(static_cast<std::int16_t>(static_cast<std::uint16_t>(bits)));
        return true;
    }
}

/// Gives each invalid point the mean of its valid neighbours (8-neighbourhood), in layers from
/// the valid points inwards. At least one point is valid.
void fillInvalidPoints(std::vector<double>& z, std::vector<char>& valid, std::size_t nx, std::size_t ny)
{
    std::vector<char> queued(valid);
    std::vector<std::size_t> layer;
    const auto neighbours = [&](std::size_t i, auto visit) {
        const std::size_t ix = i % nx;
        const std::size_t iy = i / nx;
        for (std::size_t jy = iy == 0 ? 0 : iy - 1; jy <= std::min(iy + 1, ny - 1); ++jy) {
            for (std::size_t jx = ix == 0 ? 0 : ix - 1; jx <= std::min(ix + 1, nx - 1); ++jx) {
                if (jx != ix || jy != iy) {
                    visit(jy * nx + jx);
                }
            }
        }
    };
    for (std::size_t i = 0; i < z.size(); ++i) {
        if (!valid[i]) {
            bool rim = false;
            neighbours(i, [&](std::size_t j) { rim = rim || valid[j]; });
            if (rim) {
                layer.push_back(i);
                queued[i] = 1;
            }
        }
    }
    std::vector<double> values;
    while (!layer.empty()) {
        values.assign(layer.size(), 0.0);
        for (std::size_t k = 0; k < layer.size(); ++k) {
            double sum = 0.0;
            int n = 0;
            neighbours(layer[k], [&](std::size_t j) {
                if (valid[j]) {
                    sum += z[j];
                    ++n;
                }
            });
            values[k] = sum / n; // n >= 1: each point of a layer touches a valid one
        }
        std::vector<std::size_t> next;
        for (std::size_t k = 0; k < layer.size(); ++k) {
            z[layer[k]] = values[k];
            valid[layer[k]] = 1;
        }
        for (std::size_t i : layer) {
            neighbours(i, [&](std::size_t j) {
                if (!queued[j]) {
                    queued[j] = 1;
                    next.push_back(j);
                }
            });
        }
        layer.swap(next);
    }
}
} // namespace

ArealSurface readX3p(const std::string& path, const X3pReadOptions& options)
{
    std::ifstream in = detail::openInputFile(path);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        throw InputError(path, 0, "cannot read the file (read error)");
    }
    return readX3pBytes(bytes, path, options);
}

ArealSurface readX3pBytes(const std::string& bytes, const std::string& name, const X3pReadOptions& options)
{
    // The archive (libzip takes an empty buffer for an empty archive).
    if (bytes.empty()) {
        throw InputError(name, 0, "not an X3P file: the file is empty");
    }
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
    if (!source) {
        const std::string why = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw std::runtime_error(name + ": libzip: " + why);
    }
    std::unique_ptr<zip_t, ZipDiscard> zip(zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error));
    if (!zip) {
        zip_source_free(source);
        const std::string why = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw InputError(name, 0,
                         "not an X3P file: not a readable zip archive (" + why + "); corrupt or truncated?");
    }
    zip_error_fini(&error);

    // main.xml.
    const std::string xmlText = readEntry(zip.get(), "main.xml", maximumXmlBytes, name, "");
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(xmlText.data(), xmlText.size());
    if (!parsed) {
        long line = 1;
        for (std::ptrdiff_t i = 0; i < parsed.offset && static_cast<std::size_t>(i) < xmlText.size(); ++i) {
            line += xmlText[static_cast<std::size_t>(i)] == '\n';
        }
        throw InputError(name, 0,
                         "main.xml line " + std::to_string(line) + ": not well-formed XML (" +
                             parsed.description() + ")");
    }
    const Xml xml(name);
    const pugi::xml_node root = doc.document_element();
    const std::string rootName = root.name();
    const std::string expectedRoot = "ISO5436_2";
    if (rootName.size() < expectedRoot.size() ||
        rootName.compare(rootName.size() - expectedRoot.size(), expectedRoot.size(), expectedRoot) != 0 ||
        (rootName.size() > expectedRoot.size() &&
         rootName[rootName.size() - expectedRoot.size() - 1] != ':')) {
        throw InputError(name, 0,
                         "main.xml: the root element is '" + detail::printable(rootName) +
                             "', not ISO5436_2 (an ISO 5436-2 / ISO 25178-72 X3P file)");
    }

    // Record1: the axes.
    const pugi::xml_node axes = xml.child(xml.child(root, "", "Record1"), "Record1", "Axes");
    double spacing[2] = {0.0, 0.0};
    const char* const lateral[2] = {"CX", "CY"};
    for (int a = 0; a < 2; ++a) {
        const std::string path = std::string("Record1/Axes/") + lateral[a];
        const pugi::xml_node axis = xml.child(axes, "Record1/Axes", lateral[a]);
        const std::string type = xml.text(axis, path, "AxisType");
        if (type == "A") {
            throw InputError(name, 0,
                             "main.xml: " + path +
                                 "/AxisType is A (absolute: a list of positions); only "
                                 "incremental axes (I) on a uniform grid are supported for x and y");
        }
        if (type != "I") {
            throw InputError(
                name, 0, "main.xml: " + path + "/AxisType is '" + detail::printable(type) + "', not I or A");
        }
        spacing[a] = xml.number(axis, path, "Increment");
        if (!(spacing[a] > 0.0)) {
            std::ostringstream os;
            os << "main.xml: " << path << "/Increment is " << spacing[a] << "; a spacing must be > 0 m";
            throw InputError(name, 0, os.str());
        }
    }
    const pugi::xml_node cz = xml.child(axes, "Record1/Axes", "CZ");
    const std::string typeText = xml.text(cz, "Record1/Axes/CZ", "DataType");
    if (typeText != "D" && typeText != "F" && typeText != "I" && typeText != "L") {
        throw InputError(name, 0,
                         "main.xml: Record1/Axes/CZ/DataType is '" + detail::printable(typeText) +
                             "'; D (double), F (float), I (int16) or L (int32) are supported");
    }
    const char type = typeText[0];
    const double one = 1.0;
    const double zero = 0.0;
    const double zIncrement = xml.number(cz, "Record1/Axes/CZ", "Increment", &one);
    const double zOffset = xml.number(cz, "Record1/Axes/CZ", "Offset", &zero);

    // Record3: sizes and the data.
    const pugi::xml_node record3 = xml.child(root, "", "Record3");
    const pugi::xml_node dimension = xml.child(record3, "Record3", "MatrixDimension");
    const std::uint64_t nx = xml.count(dimension, "Record3/MatrixDimension", "SizeX");
    const std::uint64_t ny = xml.count(dimension, "Record3/MatrixDimension", "SizeY");
    const std::uint64_t nz = xml.count(dimension, "Record3/MatrixDimension", "SizeZ");
    if (nz != 1) {
        throw InputError(name, 0,
                         "main.xml: Record3/MatrixDimension/SizeZ is " + std::to_string(nz) +
                             "; one layer (1) is supported");
    }
    if (nx < ArealSurface::minimumSize || ny < ArealSurface::minimumSize || nx > limits::maximumGridPoints ||
        ny > limits::maximumGridPoints / nx) {
        std::ostringstream os;
        os << "main.xml: Record3/MatrixDimension is " << nx << " x " << ny
           << " points; an areal surface needs at least " << ArealSurface::minimumSize << " x "
           << ArealSurface::minimumSize << " and at most " << limits::maximumGridPoints
           << " points (4096 x 4096)";
        throw InputError(name, 0, os.str());
    }
    const std::size_t n = static_cast<std::size_t>(nx * ny);

    std::vector<double> raw(n, 0.0);
    std::vector<char> valid(n, 1);
    const pugi::xml_node link = record3.child("DataLink");
    const pugi::xml_node list = record3.child("DataList");
    if (link) {
        const std::string dataName = xml.text(link, "Record3/DataLink", "PointDataLink");
        const std::string expectedMd5 = xml.text(link, "Record3/DataLink", "MD5ChecksumPointData");
        const std::uint64_t expectedBytes = n * bytesOf(type);
        const std::string data =
            readEntry(zip.get(), dataName, expectedBytes, name, "Record3/DataLink/PointDataLink");
        if (data.size() != expectedBytes) {
            std::ostringstream os;
            os << detail::printable(dataName, 80) << " has " << data.size() << " bytes; " << nx << " x " << ny
               << " points (Record3/MatrixDimension) of type " << type << " need " << expectedBytes;
            throw InputError(name, 0, os.str());
        }
        const auto checkMd5 = [&](const std::string& content, const std::string& file,
                                  const std::string& expected, const char* element) {
            const std::string actual = md5Hex(content);
            std::string upper = expected;
            for (char& c : upper) {
                c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            }
            if (upper != actual) {
                throw InputError(name, 0,
                                 "checksum mismatch: the MD5 of " + detail::printable(file, 80) + " is " +
                                     actual + " but " + element + " says '" + detail::printable(expected) +
                                     "'");
            }
        };
        checkMd5(data, dataName, expectedMd5, "Record3/DataLink/MD5ChecksumPointData");
        for (std::size_t i = 0; i < n; ++i) {
            valid[i] = decode(data, i, type, raw[i]);
        }
        if (const pugi::xml_node mask = link.child("ValidPointsLink")) {
            const std::string maskName = trimmed(mask.child_value());
            const std::uint64_t maskBytes = (n + 7) / 8;
            const std::string bits =
                readEntry(zip.get(), maskName, maskBytes, name, "Record3/DataLink/ValidPointsLink");
            if (bits.size() != maskBytes) {
                std::ostringstream os;
                os << detail::printable(maskName, 80) << " has " << bits.size() << " bytes; a mask of " << n
                   << " points needs " << maskBytes;
                throw InputError(name, 0, os.str());
            }
            if (link.child("MD5ChecksumValidPoints")) {
                checkMd5(bits, maskName, xml.text(link, "Record3/DataLink", "MD5ChecksumValidPoints"),
                         "Record3/DataLink/MD5ChecksumValidPoints");
            }
            for (std::size_t i = 0; i < n; ++i) {
                if (!((static_cast<unsigned char>(bits[i / 8]) >> (i % 8)) & 1u)) {
                    valid[i] = 0;
                }
            }
        }
    } else if (list) {
        std::size_t count = 0;
        for (pugi::xml_node datum = list.child("Datum"); datum && count <= n;
             datum = datum.next_sibling("Datum")) {
            ++count;
        }
        if (count != n) {
            std::ostringstream os;
            os << "main.xml: Record3/DataList has " << (count > n ? "more than " : "")
               << (count > n ? n : count) << " Datum elements; " << nx << " x " << ny
               << " points (Record3/MatrixDimension) need " << n;
            throw InputError(name, 0, os.str());
        }
        std::size_t i = 0;
        for (pugi::xml_node datum = list.child("Datum"); datum; datum = datum.next_sibling("Datum"), ++i) {
            const std::string t = trimmed(datum.child_value());
            double v = 0.0;
            if (t.empty()) {
                valid[i] = 0;
            } else if (!detail::parseNumber(t, v)) {
                std::ostringstream os;
                os << "main.xml: Record3/DataList/Datum " << i + 1 << " is '" << detail::printable(t)
                   << "', not a number";
                throw InputError(name, 0, os.str());
            } else if (std::isnan(v)) { // a quiet NaN from strtod: no trap
                valid[i] = 0;
            } else {
                raw[i] = v;
            }
        }
    } else {
        throw InputError(name, 0,
                         "main.xml has neither Record3/DataLink nor Record3/DataList (the point data)");
    }

    // Heights [m] = offset + increment * value, checked before any trap can see them.
    std::vector<double> z(n, 0.0);
    std::size_t invalid = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!valid[i]) {
            ++invalid;
            continue;
        }
        double h = 0.0;
        {
            const QuietFloatingPoint quiet; // an infinite value, or an overflow of the scaling
            h = zOffset + zIncrement * raw[i];
        }
        if (!std::isfinite(h) || std::abs(h) > limits::maximumHeight) {
            std::ostringstream os;
            os << "height at x index " << i % nx << ", y index " << i / nx << " is "
               << (std::isfinite(h) ? std::to_string(h) : std::string("not finite"))
               << " m; heights must be finite and within +-" << limits::maximumHeight << " m";
            throw InputError(name, 0, os.str());
        }
        z[i] = h;
    }
    raw = std::vector<double>();
    if (invalid == n) {
        throw InputError(name, 0, "all " + std::to_string(n) + " points are invalid: no height to read");
    }
    if (invalid > 0) {
        if (!options.fillInvalid) {
            std::ostringstream os;
            os << invalid << " of " << n << " points are invalid (NaN or masked out); give the fill-invalid "
               << "option to fill each with the mean of its valid neighbours";
            throw InputError(name, 0, os.str());
        }
        fillInvalidPoints(z, valid, static_cast<std::size_t>(nx), static_cast<std::size_t>(ny));
    }
    return ArealSurface(std::move(z), static_cast<std::size_t>(nx), static_cast<std::size_t>(ny), spacing[0],
                        spacing[1], name);
}

} // namespace roughContact
