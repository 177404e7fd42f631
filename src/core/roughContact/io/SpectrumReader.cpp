// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a surface spectrum (frequency levels and their amplitudes) from a text file.
#include "roughContact/io/SpectrumReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/TableReader.hpp"

#include <cstdlib>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace roughContact {

namespace {
/// v in the fewest significant digits (at least 6) that read back as v: "-1e-12", not
/// "-9.9999999999999998e-13".
std::string shortest(double v)
{
    std::string text;
    for (int digits = 6; digits <= 17; ++digits) { // from 6, the stream default: "2000", not "2e+03"
        std::ostringstream os;
        os.precision(digits);
        os << v;
        text = os.str();
        double back = 0.0;
        if (parseNumber(text, back) && back == v) {
            break;
        }
    }
    return text;
}
} // namespace

Spectrum readSpectrum(const std::string& path, std::optional<double> length)
{
    if (length) {
        requirePositive("length", *length);
    }
    InputFile in(path, fileLimits::maximumTextBytes, "spectrum");
    return readSpectrum(in, path, length);
}

Spectrum readSpectrum(std::istream& in, const std::string& path, std::optional<double> length)
{
    if (length) {
        requirePositive("length", *length);
    }
    detail::TableReadOptions tableOptions;
    tableOptions.maxColumns = 2;
    const detail::Table table = detail::readTable(in, path, tableOptions);
    if (table.rows.empty()) {
        throw InputError(path, 0, "no data rows; a spectrum needs at least one level");
    }
    if (table.columns != 2) {
        throw InputError(path, table.rows.front().line,
                         "one column; a spectrum needs two: frequency [1/m] and amplitude [m]");
    }

    std::vector<double> f;
    std::vector<double> beta;
    f.reserve(table.rows.size());
    beta.reserve(table.rows.size());
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const detail::TableRow& row = table.rows[i];
        const double fi = row.values[0];
        const double bi = row.values[1];
        std::ostringstream os;
        if (!(fi > 0.0)) {
            os << "frequency must be positive, got " << shortest(fi);
            throw InputError(path, row.line, os.str());
        }
        if (i > 0 && !(fi > f.back())) {
            os << "frequencies must increase strictly: " << shortest(fi) << " after " << shortest(f.back())
               << " on line " << table.rows[i - 1].line;
            throw InputError(path, row.line, os.str());
        }
        if (!(bi >= 0.0)) {
            os << "amplitude must be >= 0, got " << shortest(bi);
            throw InputError(path, row.line, os.str());
        }
        f.push_back(fi);
        beta.push_back(bi);
    }
    if (!length && !(f.front() >= 1.0 / limits::maximumLength)) {
        // (checked before 1/f: the reciprocal of a subnormal frequency overflows, a trap under
        // OpenFOAM; found by fuzz.spectrumReader)
        std::ostringstream os;
        os << "the lowest frequency " << shortest(f.front()) << " 1/m makes the scan length 1/f beyond "
           << limits::maximumLength << " m; give the length, or check the units";
        throw InputError(path, table.rows.front().line, os.str());
    }
    const double L = length ? *length : 1.0 / f.front();
    return Spectrum(std::move(f), std::move(beta), L, path);
}

} // namespace roughContact
