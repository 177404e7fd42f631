// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/io/NpyReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {

// The value of `key` in the header's dictionary literal ({'descr': '<f8', 'fortran_order':
// False, 'shape': (3, 4), }): the text after "'key':" up to the next top-level comma.
std::string headerValue(const std::string& header, const std::string& key, const std::string& path)
{
    const std::string quoted = "'" + key + "'";
    std::size_t at = header.find(quoted);
    if (at == std::string::npos) {
        throw InputError(path, 0, "the .npy header has no '" + key + "': " + header);
    }
    if (header.find(quoted, at + quoted.size()) != std::string::npos) {
        // numpy's literal_eval would take the last; a header numpy.save wrote has each key once.
        throw InputError(path, 0, "the .npy header gives '" + key + "' more than once: " + header);
    }
    at = header.find(':', at + quoted.size());
    if (at == std::string::npos) {
        throw InputError(path, 0, "the .npy header is malformed: " + header);
    }
    ++at;
    int depth = 0;
    std::size_t end = at;
    for (; end < header.size(); ++end) {
        const char c = header[end];
        if (c == '(') {
            ++depth;
        } else if (c == ')') {
            --depth;
        } else if ((c == ',' || c == '}') && depth == 0) {
            break;
        }
    }
    std::string value = header.substr(at, end - at);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t") + 1);
    return value;
}

bool bigEndianHost()
{
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 0;
}

} // namespace

bool isNpyPath(const std::string& path)
{
    if (path.size() < 4) {
        return false;
    }
    std::string end = path.substr(path.size() - 4);
    std::transform(end.begin(), end.end(), end.begin(), [](unsigned char c) { return std::tolower(c); });
    return end == ".npy";
}

ArealSurface readNpy(const std::string& path, const MatrixReadOptions& options)
{
    if (!options.dx) {
        throw ParameterError("dx", "a .npy array of heights needs its spacing dx (and dy when it differs)");
    }
    const double scale = metresPer(options.units);
    const double dx = limits::requireLength("dx", requirePositive("dx", *options.dx) * scale);
    const double dy = options.dy ? limits::requireLength("dy", requirePositive("dy", *options.dy) * scale) : dx;

    InputFile in(path, fileLimits::maximumNpyBytes, ".npy");
    char magic[8] = {};
    in.read(magic, 8);
    if (!in || std::memcmp(magic, "\x93NUMPY", 6) != 0) {
        throw InputError(path, 0, "not a NumPy .npy file (no \\x93NUMPY magic string)");
    }
    const int major = static_cast<unsigned char>(magic[6]);
    std::uint32_t headerLength = 0;
    unsigned char bytes[4] = {};
    if (major == 1) {
        in.read(reinterpret_cast<char*>(bytes), 2);
        headerLength = bytes[0] | (std::uint32_t(bytes[1]) << 8);
    } else if (major == 2 || major == 3) {
        in.read(reinterpret_cast<char*>(bytes), 4);
        headerLength = bytes[0] | (std::uint32_t(bytes[1]) << 8) | (std::uint32_t(bytes[2]) << 16) |
                       (std::uint32_t(bytes[3]) << 24);
    } else {
        throw InputError(path, 0, "unknown .npy format version " + std::to_string(major) + " (1, 2 or 3)");
    }
    if (!in || headerLength > (1u << 20)) {
        throw InputError(path, 0, "the .npy header is truncated or too long");
    }
    std::string header(headerLength, '\0');
    in.read(&header[0], headerLength);
    if (!in) {
        throw InputError(path, 0, "the .npy header is truncated");
    }
    const std::string descr = headerValue(header, "descr", path);
    const std::string order = headerValue(header, "fortran_order", path);
    const std::string shape = headerValue(header, "shape", path);
    std::size_t width = 0;
    bool swap = false;
    if (descr == "'<f8'" || descr == "'>f8'") {
        width = 8;
    } else if (descr == "'<f4'" || descr == "'>f4'") {
        width = 4;
    } else {
        throw InputError(path, 0, "the array's dtype is " + descr +
                                      "; heights are read as float64 or float32 ('<f8', '>f8', '<f4', "
                                      "'>f4': numpy.save(path, heights.astype('float64')))");
    }
    swap = (descr[1] == '>') != bigEndianHost();
    if (order != "False" && order != "True") {
        throw InputError(path, 0, "the .npy header's fortran_order is " + order);
    }
    const bool fortran = order == "True";
    // shape: (ny, nx)
    std::vector<std::uint64_t> dims;
    {
        std::string s = shape;
        if (s.size() < 2 || s.front() != '(' || s.back() != ')') {
            throw InputError(path, 0, "the .npy header's shape is " + shape);
        }
        std::stringstream ss(s.substr(1, s.size() - 2));
        std::string item;
        while (std::getline(ss, item, ',')) {
            item.erase(0, item.find_first_not_of(" \t"));
            item.erase(item.find_last_not_of(" \t") + 1);
            if (item.empty()) {
                continue;
            }
            if (item.find_first_not_of("0123456789") != std::string::npos || item.size() > 12) {
                throw InputError(path, 0, "the .npy header's shape is " + shape);
            }
            dims.push_back(std::stoull(item));
        }
    }
    if (dims.size() != 2) {
        throw InputError(path, 0, "the array has shape " + shape + "; a height map is 2-D (ny, nx)");
    }
    const std::uint64_t ny = dims[0];
    const std::uint64_t nx = dims[1];
    if (nx < ArealSurface::minimumSize || ny < ArealSurface::minimumSize) {
        std::ostringstream os;
        os << "an areal surface needs at least " << ArealSurface::minimumSize << " x " << ArealSurface::minimumSize
           << " points, got " << nx << " x " << ny << " (nx x ny: shape " << shape << ")";
        throw InputError(path, 0, os.str());
    }
    if (static_cast<double>(nx) * static_cast<double>(ny) > static_cast<double>(limits::maximumGridPoints)) {
        std::ostringstream os;
        os << "the array has " << nx << " x " << ny << " points, more than the " << limits::maximumGridPoints
           << " an areal surface may have";
        throw InputError(path, 0, os.str());
    }
    const std::size_t n = static_cast<std::size_t>(nx * ny);
    std::vector<double> heights(n);
    const auto finite = [&](double v, std::size_t iy, std::size_t ix) {
        if (!std::isfinite(v)) {
            std::ostringstream os;
            os << "the height at [" << iy << ", " << ix << "] is " << v << ": every height must be finite";
            throw InputError(path, 0, os.str());
        }
    };
    if (width == 8 && !swap && !fortran) {
        // numpy.save's usual layout (float64, this machine's byte order, C order) is the
        // surface's own: read straight into the heights (one copy of the map in memory).
        in.read(reinterpret_cast<char*>(heights.data()), static_cast<std::streamsize>(n * 8));
        if (static_cast<std::size_t>(in.gcount()) != n * 8) {
            std::ostringstream os;
            os << "the data block is truncated: " << in.gcount() << " of " << n * 8 << " bytes";
            throw InputError(path, 0, os.str());
        }
        for (std::size_t k = 0; k < n; ++k) {
            finite(heights[k], k / nx, k % nx);
            heights[k] *= scale;
        }
        limits::requireLength(path + ": scan length nx dx", dx * static_cast<double>(nx));
        limits::requireLength(path + ": scan length ny dy", dy * static_cast<double>(ny));
        return ArealSurface(std::move(heights), nx, ny, dx, dy, path);
    }
    std::vector<unsigned char> raw(n * width);
    in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size()));
    if (static_cast<std::size_t>(in.gcount()) != raw.size()) {
        std::ostringstream os;
        os << "the data block is truncated: " << in.gcount() << " of " << raw.size() << " bytes";
        throw InputError(path, 0, os.str());
    }
    for (std::size_t k = 0; k < n; ++k) {
        unsigned char* p = raw.data() + k * width;
        if (swap) {
            std::reverse(p, p + width);
        }
        double v = 0.0;
        if (width == 8) {
            std::memcpy(&v, p, 8);
        } else {
            float f = 0.0f;
            std::memcpy(&f, p, 4);
            v = f;
        }
        // C order: k = iy nx + ix; Fortran order: k = ix ny + iy.
        const std::size_t iy = fortran ? k % ny : k / nx;
        const std::size_t ix = fortran ? k / ny : k % nx;
        finite(v, iy, ix);
        heights[iy * nx + ix] = v * scale;
    }
    limits::requireLength(path + ": scan length nx dx", dx * static_cast<double>(nx));
    limits::requireLength(path + ": scan length ny dy", dy * static_cast<double>(ny));
    return ArealSurface(std::move(heights), nx, ny, dx, dy, path);
}

} // namespace roughContact
