// Reading a measured line profile z(x) from a text file (columns, or a Bruker Dektak export).
#include "roughContact/io/ProfileReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/TableReader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace roughContact {

namespace {
/// The line after which a Bruker Dektak CSV export lists its data.
const char* const dektakMarker = "Scan Data";

/// True when the Dektak data header ("Lateral um,Raw Micrometer,") names micrometres.
bool namesMicrometres(const std::string& header)
{
    for (std::string field : detail::splitFields(header)) {
        field.erase(std::remove_if(field.begin(), field.end(),
                                   [](char c) { return c == '[' || c == ']' || c == '(' || c == ')'; }),
                    field.end());
        std::transform(field.begin(), field.end(), field.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        // "\xB5m": micro sign in Latin-1, as Dektak writes it; then the UTF-8 micro sign and mu.
        if (field == "um" || field == "\xB5m" || field == "\xC2\xB5m" || field == "\xCE\xBCm"
            || field == "micrometer" || field == "micrometers" || field == "micrometre"
            || field == "micrometres" || field == "micron" || field == "microns") {
            return true;
        }
    }
    return false;
}

/// Decimal places of a printed number, so that its rounding step is 10^-decimals:
/// "0.2" -> 1, "15" -> 0, "1.25e-3" -> 2 + 3 = 5, "1.5E2" -> 1 - 2 = -1.
int printedDecimals(const std::string& field)
{
    const auto e = field.find_first_of("eE");
    const std::string mantissa = field.substr(0, e);
    const auto dot = mantissa.find('.');
    int decimals = 0;
    if (dot != std::string::npos) {
        for (std::size_t i = dot + 1; i < mantissa.size() && std::isdigit(static_cast<unsigned char>(mantissa[i])); ++i) {
            ++decimals;
        }
    }
    if (e != std::string::npos) {
        decimals -= static_cast<int>(std::strtol(field.c_str() + e + 1, nullptr, 10));
    }
    return decimals;
}
} // namespace

Profile readProfile(const std::string& path, const ProfileReadOptions& options)
{
    detail::TableReadOptions tableOptions;
    tableOptions.maxColumns = 2;
    tableOptions.sectionMarker = dektakMarker;
    const detail::Table table = detail::readTable(path, tableOptions);
    const std::vector<detail::TableRow>& rows = table.rows;

    LengthUnit unit = LengthUnit::m;
    if (options.units) {
        unit = *options.units;
    } else if (table.sectionFound && namesMicrometres(table.header)) {
        unit = LengthUnit::um;
    }
    const double scale = metresPer(unit);
    const std::string unitName = toString(unit);

    if (rows.size() < Profile::minimumSize) {
        std::ostringstream os;
        os << "a profile needs at least " << Profile::minimumSize << " points, got "
           << rows.size();
        throw InputError(path, 0, os.str());
    }
    const std::size_t n = rows.size();
    std::vector<double> heights(n);

    if (table.columns == 1) {
        if (!options.spacing) {
            throw InputError(path, 0,
                             "one column of heights and no positions: a sample spacing is needed "
                             "(give the spacing option)");
        }
        const double dx = requirePositive("spacing", *options.spacing) * scale;
        for (std::size_t i = 0; i < n; ++i) {
            heights[i] = rows[i].values[0] * scale;
        }
        return Profile(std::move(heights), dx, path);
    }

    if (options.spacing) {
        throw InputError(path, 0,
                         "the file has two columns (x z), so its positions give the spacing; "
                         "a spacing option is only for one-column files");
    }
    for (std::size_t i = 1; i < n; ++i) {
        if (!(rows[i].values[0] > rows[i - 1].values[0])) {
            std::ostringstream os;
            os.precision(17);
            os << "positions must increase strictly: x = " << rows[i].values[0] << " " << unitName
               << " after x = " << rows[i - 1].values[0] << " " << unitName << " on line "
               << rows[i - 1].line;
            throw InputError(path, rows[i].line, os.str());
        }
    }

    const double x0 = rows.front().values[0];
    const double dx = (rows.back().values[0] - x0) / static_cast<double>(n - 1);
    // Uniform-grid check. Positions are printed rounded to a step q = 10^-d, d the most decimals
    // printed in the x column (exponent form counted: "1.25e-3" has 5). Each printed x_i is the
    // true position t_i plus an error |e_i| <= q/2, and so are the two end points that define
    // the grid: x_0 + i dx = t_i + (1-s) e_0 + s e_last with s = i/(N-1). The deviation
    // x_i - (x_0 + i dx) = e_i - (1-s) e_0 - s e_last therefore reaches up to q, not q/2, on a
    // truly uniform grid: dektak-1.csv (true step 0.15625 um printed to 0.1 um) deviates by
    // 0.094 um. Tolerance: q, plus 1e-9 q for the decimal-to-binary conversion of the printed
    // values and 1e-6 |dx| for the floating-point error of x_0 + i dx.
    int decimals = printedDecimals(rows.front().firstField);
    for (const detail::TableRow& row : rows) {
        decimals = std::max(decimals, printedDecimals(row.firstField));
    }
    const double q = std::pow(10.0, -decimals);
    const double tolerance = q * (1.0 + 1e-9) + 1e-6 * std::abs(dx);
    for (std::size_t i = 0; i < n; ++i) {
        const double expected = x0 + static_cast<double>(i) * dx;
        const double found = rows[i].values[0];
        if (std::abs(found - expected) > tolerance) {
            std::ostringstream os;
            os.precision(10);
            os << "uneven spacing: expected x = " << expected << " " << unitName
               << " on the uniform grid x_0 + i dx (dx = " << dx << " " << unitName
               << "), found " << rows[i].firstField << "; tolerance " << tolerance << " "
               << unitName << " for positions printed to " << q << " " << unitName;
            throw InputError(path, rows[i].line, os.str());
        }
    }

    for (std::size_t i = 0; i < n; ++i) {
        heights[i] = rows[i].values[1] * scale;
    }
    return Profile(std::move(heights), dx * scale, path);
}

} // namespace roughContact
