// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface (height map) from a plain text matrix of heights.
#include "roughContact/io/MatrixReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/Limits.hpp"
#include "roughContact/io/TableReader.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {
/// Keeps the heights of the rows as they are read, in metres, and refuses a map beyond the
/// point cap or a height beyond the accepted range on the line that holds it.
class MatrixRows : public detail::TableSink {
public:
    MatrixRows(const std::string& path, double scale) : path_(path), scale_(scale) {}

    void row(const detail::TableRow& r) override
    {
        if (rows == 0) {
            columns = r.values.size();
        }
        if (heights.size() + r.values.size() > limits::maximumGridPoints) {
            std::ostringstream os;
            os << "more than " << limits::maximumGridPoints
               << " points (4096 x 4096, the cap of an areal surface); resample the map coarser or cut a "
                  "part of it";
            throw InputError(path_, r.line, os.str());
        }
        for (std::size_t c = 0; c < r.values.size(); ++c) {
            const double z = r.values[c] * scale_; // finite: read finite, scale <= 1
            if (std::abs(z) > limits::maximumHeight) {
                std::ostringstream os;
                os << "height " << r.values[c] << " in column " << c + 1 << " lies beyond +-"
                   << limits::maximumHeight << " m";
                throw InputError(path_, r.line, os.str());
            }
            heights.push_back(z);
        }
        ++rows;
    }
    void restart() override {}

    std::vector<double> heights;
    std::size_t rows = 0;
    std::size_t columns = 0;

private:
    const std::string& path_;
    double scale_;
};
} // namespace

ArealSurface readMatrix(const std::string& path, const MatrixReadOptions& options)
{
    InputFile in(path, fileLimits::maximumTextBytes, "height map");
    return readMatrix(in, path, options);
}

ArealSurface readMatrix(std::istream& in, const std::string& path, const MatrixReadOptions& options)
{
    if (!options.dx) {
        throw ParameterError("dx", "a matrix file of heights needs its spacing dx (and dy when it differs)");
    }
    const double scale = metresPer(options.units);
    // The spacings in metres within the accepted lengths before any N dx is formed.
    const double dx = limits::requireLength("dx", requirePositive("dx", *options.dx) * scale);
    const double dy =
        options.dy ? limits::requireLength("dy", requirePositive("dy", *options.dy) * scale) : dx;

    detail::TableReadOptions tableOptions;
    tableOptions.maxColumns = limits::maximumGridPoints / ArealSurface::minimumSize;
    MatrixRows rows(path, scale);
    const detail::Table table = detail::scanTable(in, path, tableOptions, rows);
    if (table.headerLine != 0) {
        // The table reader takes a first line of text for a header; a matrix has none.
        const std::vector<std::string> fields = detail::splitFields(table.header);
        std::string bad = fields.empty() ? table.header : fields[0];
        double ignored = 0.0;
        for (const std::string& f : fields) {
            if (!detail::parseNumber(f, ignored)) {
                bad = f;
                break;
            }
        }
        throw InputError(path, table.headerLine,
                         "non-numeric field '" + detail::printable(bad) +
                             "': a matrix file holds heights only (use # for comments)");
    }
    if (rows.rows < ArealSurface::minimumSize || rows.columns < ArealSurface::minimumSize) {
        std::ostringstream os;
        os << "an areal surface needs at least " << ArealSurface::minimumSize << " x "
           << ArealSurface::minimumSize << " points, got " << rows.columns << " x " << rows.rows
           << " (columns x rows)";
        throw InputError(path, 0, os.str());
    }
    limits::requireLength(path + ": scan length nx dx", dx * static_cast<double>(rows.columns));
    limits::requireLength(path + ": scan length ny dy", dy * static_cast<double>(rows.rows));
    return ArealSurface(std::move(rows.heights), rows.columns, rows.rows, dx, dy, path);
}

} // namespace roughContact
