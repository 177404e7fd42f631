// Reading a surface spectrum (frequency levels and their amplitudes) from a text file.
#include "roughContact/io/SpectrumReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/TableReader.hpp"

#include <sstream>
#include <vector>

namespace roughContact {

Spectrum readSpectrum(const std::string& path, std::optional<double> length)
{
    if (length) {
        requirePositive("length", *length);
    }
    detail::TableReadOptions tableOptions;
    tableOptions.maxColumns = 2;
    const detail::Table table = detail::readTable(path, tableOptions);
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
        os.precision(17);
        if (!(fi > 0.0)) {
            os << "frequency must be positive, got " << fi;
            throw InputError(path, row.line, os.str());
        }
        if (i > 0 && !(fi > f.back())) {
            os << "frequencies must increase strictly: " << fi << " after " << f.back()
               << " on line " << table.rows[i - 1].line;
            throw InputError(path, row.line, os.str());
        }
        if (!(bi >= 0.0)) {
            os << "amplitude must be >= 0, got " << bi;
            throw InputError(path, row.line, os.str());
        }
        f.push_back(fi);
        beta.push_back(bi);
    }
    const double L = length ? *length : 1.0 / f.front();
    return Spectrum(std::move(f), std::move(beta), L, path);
}

} // namespace roughContact
