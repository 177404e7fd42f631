// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a measured line profile z(x) from a text file (columns, or a Bruker Dektak export).
#include "roughContact/io/ProfileReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/io/TableReader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {
/// The line after which a Bruker Dektak CSV export lists its data.
const char* const dektakMarker = "Scan Data";

/// Metres per unit of the first length unit named in one column header of a Dektak export
/// ("Lateral um", "Raw Micrometer", "Total Profile (nm)", "Raw Angstrom"); 0 when none is named.
/// Words are split at ASCII punctuation and spaces; bytes >= 0x80 (micro sign, Angstrom sign in
/// Latin-1 or UTF-8) stay in the word. Matching ignores ASCII case.
double metresNamedIn(const std::string& columnHeader)
{
    std::vector<std::string> words(1);
    for (char c : columnHeader) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x80) {
            words.back() += c;
        } else if (std::isalnum(u)) {
            words.back() += static_cast<char>(std::tolower(u));
        } else if (!words.back().empty()) {
            words.emplace_back();
        }
    }
    for (const std::string& w : words) {
        // "\xB5m": micro sign in Latin-1, as Dektak writes it; then the UTF-8 micro sign and mu.
        if (w == "um" || w == "\xB5m" || w == "\xC2\xB5m" || w == "\xCE\xBCm" || w == "micrometer"
            || w == "micrometers" || w == "micrometre" || w == "micrometres" || w == "micron"
            || w == "microns") {
            return 1e-6;
        }
        if (w == "nm" || w == "nanometer" || w == "nanometers" || w == "nanometre"
            || w == "nanometres") {
            return 1e-9;
        }
        // Angstrom: Latin-1 "\xC5", UTF-8 U+00C5 "\xC3\x85" and U+212B ANGSTROM SIGN.
        if (w == "\xC5" || w == "\xC3\x85" || w == "\xE2\x84\xAB" || w == "angstrom"
            || w == "angstroms") {
            return 1e-10;
        }
        if (w == "mm" || w == "millimeter" || w == "millimeters" || w == "millimetre"
            || w == "millimetres") {
            return 1e-3;
        }
        if (w == "m" || w == "meter" || w == "meters" || w == "metre" || w == "metres") {
            return 1.0;
        }
    }
    return 0.0;
}

/// How a number was printed: its rounding step is 10^-decimals ("0.2" -> 1, "15" -> 0,
/// "1.25e-3" -> 2 + 3 = 5, "1.5E2" -> 1 - 2 = -1); significant counts the mantissa digits from
/// the first non-zero one on, trailing zeros included ("0.00150" -> 3, "1500.0" -> 5; 0 for a
/// zero).
struct PrintedPrecision {
    int decimals = 0;
    int significant = 0;
};

PrintedPrecision printedPrecision(const std::string& field)
{
    PrintedPrecision p;
    const auto e = field.find_first_of("eE");
    const std::string mantissa = field.substr(0, e);
    bool afterDot = false;
    for (char c : mantissa) {
        if (c == '.') {
            afterDot = true;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            if (afterDot) {
                ++p.decimals;
            }
            if (p.significant > 0 || c != '0') {
                ++p.significant;
            }
        }
    }
    if (e != std::string::npos) {
        // Clamped: a finite double has |exponent| < 400 (subnormals included), and a longer
        // exponent must not overflow the int (e.g. "0e99999999999" is a valid zero).
        const long exponent = std::strtol(field.c_str() + e + 1, nullptr, 10);
        p.decimals -= static_cast<int>(std::max(-1000L, std::min(1000L, exponent)));
    }
    return p;
}

/// The rows of a profile file, kept compact (about 8 + 8 + 8 bytes and the printed position a
/// row, instead of a TableRow each): heights, positions, the positions as printed (for their
/// rounding and for error messages) and the line numbers where they do not simply count up.
class ProfileRows : public detail::TableSink {
public:
    void row(const detail::TableRow& r) override
    {
        if (lineJumps_.empty() || r.line != line(size() - 1) + 1) {
            lineJumps_.push_back({size(), r.line});
        }
        z.push_back(r.values.back());
        if (r.values.size() == 2) {
            x.push_back(r.values[0]);
            printed_.append(r.firstField);
            printedEnd_.push_back(printed_.size());
        }
    }
    void restart() override { *this = ProfileRows(); }

    std::size_t size() const { return z.size(); }
    /// The line of row i.
    long line(std::size_t i) const
    {
        const auto jump = std::upper_bound(lineJumps_.begin(), lineJumps_.end(), i,
                                           [](std::size_t row, const LineJump& j) { return row < j.row; })
                          - 1;
        return jump->line + static_cast<long>(i - jump->row);
    }
    /// The position of row i as printed (two-column files).
    std::string printed(std::size_t i) const
    {
        const std::size_t begin = i == 0 ? 0 : printedEnd_[i - 1];
        return printed_.substr(begin, printedEnd_[i] - begin);
    }

    /// Heights (the last column) and positions (the first of two), as read.
    std::vector<double> z;
    std::vector<double> x;

private:
    struct LineJump {
        std::size_t row;
        long line;
    };
    std::vector<LineJump> lineJumps_;
    std::string printed_;
    std::vector<std::size_t> printedEnd_;
};
} // namespace

Profile readProfile(const std::string& path, const ProfileReadOptions& options)
{
    InputFile in(path, fileLimits::maximumTextBytes, "profile");
    return readProfile(in, path, options);
}

Profile readProfile(std::istream& in, const std::string& path, const ProfileReadOptions& options)
{
    detail::TableReadOptions tableOptions;
    tableOptions.maxColumns = 2;
    tableOptions.sectionMarker = dektakMarker;
    ProfileRows rows;
    const detail::Table table = detail::scanTable(in, path, tableOptions, rows);

    if (rows.size() < Profile::minimumSize) {
        std::ostringstream os;
        os << "a profile needs at least " << Profile::minimumSize << " points, got "
           << rows.size();
        throw InputError(path, 0, os.str());
    }
    const std::size_t n = rows.size();
    const bool twoColumns = table.columns == 2;

    // Metres per file unit of the positions (x) and of the heights (z).
    double xScale = 1.0;
    double zScale = 1.0;
    if (options.units) {
        xScale = zScale = metresPer(*options.units);
    } else if (table.sectionFound) {
        // A Dektak export: its data header names the unit of each column, e.g.
        // "Lateral um,Raw Micrometer,". Heights may be in another unit than positions (nm, A).
        if (table.headerLine == 0) {
            throw InputError(path, rows.line(0),
                             "a Bruker Dektak export (it has a \"Scan Data\" line) without the "
                             "data header that names its units; give the units option");
        }
        std::vector<std::string> names(1);
        for (char c : table.header) {
            if (c == ',' || c == ';') {
                names.emplace_back();
            } else {
                names.back() += c;
            }
        }
        names.resize(std::max<std::size_t>(names.size(), 2));
        const double xNamed = metresNamedIn(names[0]);
        const double zNamed = metresNamedIn(names[twoColumns ? 1 : 0]);
        if (xNamed == 0.0 || zNamed == 0.0) {
            const std::size_t column = xNamed == 0.0 ? 1 : 2;
            throw InputError(path, table.headerLine,
                             "the Dektak data header '" + detail::printable(table.header, 80)
                                 + "' names no length unit (um, nm, Angstrom, mm or m) for column "
                                 + std::to_string(column) + "; give the units option");
        }
        xScale = xNamed;
        zScale = twoColumns ? zNamed : xNamed;
    }

    std::vector<double> heights = std::move(rows.z);
    for (double& z : heights) {
        z *= zScale; // finite: read finite, scales <= 1
    }

    if (!twoColumns) {
        if (!options.spacing) {
            throw InputError(path, 0,
                             "one column of heights and no positions: a sample spacing is needed "
                             "(give the spacing option)");
        }
        // The spacing in metres within the accepted lengths (Limits.hpp) before N dx is formed:
        // found by fuzzing, a finite spacing whose scan length N dx overflowed.
        const double dx = limits::requireLength("spacing", requirePositive("spacing", *options.spacing) * xScale);
        limits::requireLength("spacing: the scan length N dx", dx * static_cast<double>(n));
        return Profile(std::move(heights), dx, path);
    }

    if (options.spacing) {
        throw InputError(path, 0,
                         "the file has two columns (x z), so its positions give the spacing; "
                         "a spacing option is only for one-column files");
    }

    const std::string unitName = xScale == 1.0    ? std::string("m")
                                 : xScale == 1e-3 ? std::string("mm")
                                 : xScale == 1e-6 ? std::string("um")
                                 : xScale == 1e-9 ? std::string("nm")
                                                  : std::string("Angstrom");
    for (std::size_t i = 0; i < n; ++i) {
        // Positions within the accepted lengths (Limits.hpp), so that their differences cannot
        // overflow (found by fuzzing: a span of two positions near the largest double).
        if (std::abs(rows.x[i] * xScale) > limits::maximumLength) {
            std::ostringstream os;
            os << "position x = " << detail::printable(rows.printed(i)) << " " << unitName << " lies beyond +-"
               << limits::maximumLength << " m";
            throw InputError(path, rows.line(i), os.str());
        }
        if (i > 0 && !(rows.x[i] > rows.x[i - 1])) {
            std::ostringstream os;
            os.precision(17);
            os << "positions must increase strictly: x = " << detail::printable(rows.printed(i)) << " "
               << unitName << " after x = " << detail::printable(rows.printed(i - 1)) << " " << unitName
               << " on line " << rows.line(i - 1);
            throw InputError(path, rows.line(i), os.str());
        }
    }

    const double x0 = rows.x.front();
    const double xLast = rows.x.back();
    const double dx = (xLast - x0) / static_cast<double>(n - 1);
    // Finite: the positions lie within +-maximumLength. The spacing and the scan length N dx
    // must lie within the accepted lengths too.
    const double length = dx * xScale * static_cast<double>(n);
    if (dx * xScale < limits::minimumLength || length > limits::maximumLength) {
        std::ostringstream os;
        os.precision(17);
        os << "the spacing (x_last - x_first) / (N - 1) = " << dx << " " << unitName << " and the scan length N dx = "
           << length << " m must lie within [" << limits::minimumLength << " m, " << limits::maximumLength << " m]";
        throw InputError(path, rows.line(n - 1), os.str());
    }

    // Uniform-grid check. A printed position x_i is the true t_i plus a rounding error
    // |e_i| <= q_i / 2, q_i its rounding step. The grid is defined by the two end points, so
    // x_i - (x_0 + i dx) = e_i - (1-s) e_0 - s e_last with s = i/(N-1), which is bounded by
    // (q_i + (1-s) q_0 + s q_last) / 2: on a truly uniform grid printed to 0.1 it reaches
    // 0.1, not 0.05 (dektak-1.csv: true step 0.15625 um printed to 0.1 um deviates by 0.094 um).
    // The rounding step of a row depends on how the file was printed, which is not known:
    //  - fixed decimals (%.3f, Dektak): q = 10^-D, D the most decimals of the column (rows with
    //    trailing zeros trimmed show fewer);
    //  - significant digits (%g, a C++ stream's default 6 digits): q_i = 10^-(d_i + P - p_i),
    //    d_i and p_i the decimals and significant digits of the row, P the most significant
    //    digits of the column (trailing zeros trimmed show fewer): 0.00149984 is 8 decimals
    //    while 1.5625e-07 is 11.
    // q_i is the larger of the two, so that no uniform grid printed either way is rejected and
    // q_i never exceeds the row's own last printed digit. A zero is exact under %g and has D
    // decimals under fixed printing: q = 10^-D.
    int mostDecimals = std::numeric_limits<int>::min();
    int mostSignificant = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const PrintedPrecision p = printedPrecision(rows.printed(i));
        mostDecimals = std::max(mostDecimals, p.decimals);
        mostSignificant = std::max(mostSignificant, p.significant);
    }
    const auto step = [&](std::size_t i) {
        const PrintedPrecision p = printedPrecision(rows.printed(i)); // again: not kept, to save memory
        const int d = p.significant == 0
                          ? mostDecimals
                          : std::min(mostDecimals, p.decimals + mostSignificant - p.significant);
        return std::pow(10.0, -d);
    };
    // Floating-point slack: the decimal-to-binary conversion and x_0 + i dx err by a few ulps of
    // max|x|; a writer that accumulated x += dx errs by up to about N ulps. 4 N eps max|x|
    // covers both; 1e-6 |dx| more keeps a little room when all printed values are exact.
    const double slack = 4.0 * static_cast<double>(n) * std::numeric_limits<double>::epsilon()
                             * std::max(std::abs(x0), std::abs(xLast))
                         + 1e-6 * std::abs(dx);
    const double qFirst = step(0);
    const double qLast = step(n - 1);
    for (std::size_t i = 0; i < n; ++i) {
        const double s = static_cast<double>(i) / static_cast<double>(n - 1);
        const double expected = x0 + static_cast<double>(i) * dx;
        const double found = rows.x[i];
        const double tolerance = 0.5 * (step(i) + (1.0 - s) * qFirst + s * qLast) + slack;
        if (!(std::abs(found - expected) <= tolerance)) {
            std::ostringstream os;
            os.precision(10);
            os << "uneven spacing: expected x = " << expected << " " << unitName
               << " on the uniform grid x_0 + i dx (dx = " << dx << " " << unitName
               << "), found " << detail::printable(rows.printed(i)) << "; tolerance " << tolerance << " "
               << unitName << " for positions printed to " << step(i) << " " << unitName;
            throw InputError(path, rows.line(i), os.str());
        }
    }

    return Profile(std::move(heights), dx * xScale, path);
}

} // namespace roughContact
