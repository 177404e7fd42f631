// SPDX-License-Identifier: GPL-3.0-or-later
// Internal helper of the readers: a text file of numeric columns, tokenised into rows.
// Not part of the public API; ProfileReader and SpectrumReader share it.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace roughContact {
namespace detail {

/// One data row of a table file.
struct TableRow {
    /// 1-based line number in the file.
    long line = 0;
    /// The row's numbers, all finite; one per non-empty column.
    std::vector<double> values;
    /// Column 1 exactly as printed (trimmed), e.g. to count its decimals.
    std::string firstField;
};

/// How to read a table file.
struct TableReadOptions {
    /// Rows with more non-empty fields than this are rejected.
    std::size_t maxColumns = 2;
    /// When non-empty and some line equals it (after trimming), every line up to and including
    /// the first such line is skipped (e.g. "Scan Data" in a Bruker Dektak export).
    std::string sectionMarker;
};

/// The content of a table file.
struct Table {
    std::vector<TableRow> rows;
    /// Columns of every row (all rows have the same count); 0 when there are no rows.
    std::size_t columns = 0;
    /// The header line (comment removed, trimmed); empty when the file has none.
    std::string header;
    /// Its 1-based line number; 0 when there is no header.
    long headerLine = 0;
    /// True when options.sectionMarker was found.
    bool sectionFound = false;
};

/// Where scanTable delivers the data rows, one at a time, as it reads them.
class TableSink {
public:
    virtual ~TableSink() = default;
    /// The next data row (the same object is reused for the following one).
    virtual void row(const TableRow& row) = 0;
    /// options.sectionMarker was found: every row delivered so far came before it; drop them.
    virtual void restart() = 0;
};

/// Reads path as lines of numbers. Separators are commas, semicolons, tabs or spaces in any mix
/// (a run of whitespace is one separator, so is a comma or semicolon with whitespace around it).
/// Empty fields at the end of a line are ignored; `#` starts a comment; blank lines are skipped.
/// The first non-blank, non-comment line is a header when its first field is not a number; any
/// later text is an error. Lines end in "\n" or "\r\n" ("\r" alone when the file has no "\n").
/// Throws InputError(path, line, ...) for an unopenable file (line 0), a non-numeric, empty or
/// non-finite field, too many columns or a column count differing from the first row's.
/// An empty table (no rows) is returned as such: callers decide on the minimum size.
Table readTable(const std::string& path, const TableReadOptions& options = {});

/// The same from a stream; name is the file name that errors give.
Table readTable(std::istream& in, const std::string& name, const TableReadOptions& options = {});

/// readTable without keeping the rows: each goes to sink as it is read, so that the caller keeps
/// only what it needs (the file is never held whole in memory unless it has no "\n"). The same
/// rows, errors and layout; the returned Table has no rows.
Table scanTable(std::istream& in, const std::string& name, const TableReadOptions& options,
                TableSink& sink);

/// text as an error message echoes it: bytes outside printable ASCII as \xNN, and cut with
/// "..." after about maxLength characters (a bad field may be a megabyte long or binary).
std::string printable(const std::string& text, std::size_t maxLength = 40);

/// The fields of one line (comment already removed), split as readTable does; empty fields at
/// the end are dropped.
std::vector<std::string> splitFields(const std::string& line);

/// True when the whole of field (surrounding whitespace ignored) is a decimal number to
/// std::strtod, which then gives value. "nan" and "inf" count as numbers here (value is then
/// not finite); hexadecimal ("0x1p3") does not.
bool parseNumber(const std::string& field, double& value);

} // namespace detail
} // namespace roughContact
