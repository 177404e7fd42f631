// SPDX-License-Identifier: GPL-3.0-or-later
// Tokenising of table files shared by ProfileReader and SpectrumReader.
#include "roughContact/io/TableReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/io/Numbers.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <memory>
#include <sstream>

namespace roughContact {
namespace detail {

namespace {
bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

bool isDelimiter(char c)
{
    return c == ',' || c == ';';
}

std::string trim(const std::string& s)
{
    std::size_t first = 0;
    std::size_t last = s.size();
    while (first < last && isSpace(s[first])) {
        ++first;
    }
    while (last > first && isSpace(s[last - 1])) {
        --last;
    }
    return s.substr(first, last - first);
}

std::string withoutComment(const std::string& line)
{
    const auto hash = line.find('#');
    return trim(hash == std::string::npos ? line : line.substr(0, hash));
}

std::string quoted(const std::string& field)
{
    return "'" + printable(field) + "'";
}
} // namespace

std::vector<std::string> splitFields(const std::string& line)
{
    const std::string s = trim(line);
    std::vector<std::string> fields;
    std::size_t pos = 0;
    const std::size_t n = s.size();
    while (pos < n) {
        const std::size_t start = pos;
        while (pos < n && !isSpace(s[pos]) && !isDelimiter(s[pos])) {
            ++pos;
        }
        fields.push_back(s.substr(start, pos - start));
        // The separator: whitespace, optionally one comma or semicolon, whitespace.
        while (pos < n && isSpace(s[pos])) {
            ++pos;
        }
        if (pos < n && isDelimiter(s[pos])) {
            ++pos;
            while (pos < n && isSpace(s[pos])) {
                ++pos;
            }
            if (pos == n) {
                fields.emplace_back(); // "1,2," ends in an empty field
            }
        }
    }
    while (!fields.empty() && fields.back().empty()) {
        fields.pop_back();
    }
    return fields;
}

bool parseNumber(const std::string& field, double& value)
{
    return roughContact::parseNumber(field, value);
}

namespace {
/// The table being read, line by line: its layout so far, and the first error while the
/// section marker may still come (the error is then thrown at the end, unless the marker comes).
class TableScanner {
public:
    TableScanner(const std::string& name, const TableReadOptions& options, TableSink& sink)
        : name_(name), options_(options), sink_(sink)
    {
    }

    void line(long lineNo, const std::string& line)
    {
        if (!options_.sectionMarker.empty() && !table_.sectionFound
            && trim(line) == options_.sectionMarker) {
            // Everything up to and including the marker is skipped, errors too.
            table_ = Table();
            table_.sectionFound = true;
            rows_ = 0;
            firstRowLine_ = 0;
            deferred_.reset();
            sink_.restart();
            return;
        }
        if (deferred_) {
            return; // only looking for the marker
        }
        try {
            data(lineNo, withoutComment(line));
        } catch (const InputError& e) {
            if (options_.sectionMarker.empty() || table_.sectionFound) {
                throw;
            }
            deferred_ = std::make_unique<InputError>(e);
        }
    }

    Table finish()
    {
        if (deferred_) {
            throw *deferred_;
        }
        return table_;
    }

private:
    void data(long lineNo, const std::string& text)
    {
        if (text.empty()) {
            return;
        }
        const std::vector<std::string> fields = splitFields(text);
        if (fields.empty()) {
            return; // only separators, e.g. ",,,"
        }
        double value = 0.0;
        if (rows_ == 0 && table_.headerLine == 0 && !parseNumber(fields[0], value)) {
            table_.header = text;
            table_.headerLine = lineNo;
            return;
        }

        row_.line = lineNo;
        row_.firstField = fields[0];
        row_.values.clear();
        const std::size_t checked = std::min(fields.size(), options_.maxColumns);
        for (std::size_t c = 0; c < checked; ++c) {
            const std::string& field = fields[c];
            std::ostringstream os;
            if (field.empty()) {
                os << "empty field in column " << c + 1;
                throw InputError(name_, lineNo, os.str());
            }
            if (!parseNumber(field, value)) {
                os << "non-numeric field " << quoted(field) << " in column " << c + 1;
                bool anyNumber = false;
                double ignored = 0.0;
                for (const std::string& f : fields) {
                    anyNumber = anyNumber || parseNumber(f, ignored);
                }
                if (!anyNumber && table_.headerLine != 0) {
                    os << " (only one header line is allowed; the header is line "
                       << table_.headerLine << ")";
                } else if (!anyNumber) {
                    os << " (a header line is allowed only before the first data row)";
                }
                throw InputError(name_, lineNo, os.str());
            }
            if (!std::isfinite(value)) {
                os << "field " << quoted(field) << " in column " << c + 1 << " is not a finite number";
                throw InputError(name_, lineNo, os.str());
            }
            row_.values.push_back(value);
        }
        if (fields.size() > options_.maxColumns) {
            std::ostringstream os;
            os << fields.size() << " columns; at most " << options_.maxColumns << " are allowed";
            throw InputError(name_, lineNo, os.str());
        }
        if (rows_ == 0) {
            table_.columns = fields.size();
            firstRowLine_ = lineNo;
        } else if (fields.size() != table_.columns) {
            std::ostringstream os;
            os << fields.size() << (fields.size() == 1 ? " column" : " columns") << " where line "
               << firstRowLine_ << " has " << table_.columns;
            throw InputError(name_, lineNo, os.str());
        }
        ++rows_;
        sink_.row(row_);
    }

    const std::string& name_;
    const TableReadOptions& options_;
    TableSink& sink_;
    Table table_;
    std::size_t rows_ = 0;
    long firstRowLine_ = 0;
    TableRow row_;
    std::unique_ptr<InputError> deferred_;
};

/// Keeps every row: readTable.
class RowsSink : public TableSink {
public:
    void row(const TableRow& row) override { rows.push_back(row); }
    void restart() override { rows.clear(); }
    std::vector<TableRow> rows;
};

void checkNotBad(const std::istream& in, const std::string& name)
{
    if (in.bad()) {
        // E.g. a directory: it opens, but reading fails.
        throw InputError(name, 0, "cannot open the file for reading (read error)");
    }
}

void dropByteOrderMark(std::string& line)
{
    if (line.compare(0, 3, "\xEF\xBB\xBF") == 0) {
        line.erase(0, 3); // UTF-8 byte-order mark
    }
}
} // namespace

std::string printable(const std::string& text, std::size_t maxLength)
{
    std::string shown;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto u = static_cast<unsigned char>(text[i]);
        char piece[5] = {static_cast<char>(u), '\0'};
        if (u < 0x20 || u > 0x7E) {
            static const char hex[] = "0123456789ABCDEF";
            piece[0] = '\\';
            piece[1] = 'x';
            piece[2] = hex[u >> 4];
            piece[3] = hex[u & 0xF];
            piece[4] = '\0';
        }
        const std::size_t length = u < 0x20 || u > 0x7E ? 4 : 1;
        if (shown.size() + length > maxLength) {
            return shown + "...";
        }
        shown.append(piece, length);
    }
    return shown;
}

Table scanTable(std::istream& in, const std::string& name, const TableReadOptions& options,
                TableSink& sink)
{
    // "\n" ends a line; a "\r" before it (or several: some exports write "\r\r\n") is trailing
    // whitespace, so line numbers agree with wc, grep -n and sed. A file without any "\n" uses
    // classic Mac "\r" endings: then the first getline reads all of it.
    TableScanner scanner(name, options, sink);
    std::string line;
    if (std::getline(in, line)) {
        dropByteOrderMark(line);
        if (!in.eof()) {
            long lineNo = 1;
            scanner.line(lineNo, line);
            while (std::getline(in, line)) {
                scanner.line(++lineNo, line);
            }
        } else {
            const std::string content = std::move(line);
            long lineNo = 0;
            std::size_t start = 0;
            while (start < content.size()) {
                std::size_t stop = content.find('\r', start);
                if (stop == std::string::npos) {
                    stop = content.size();
                }
                line.assign(content, start, stop - start);
                scanner.line(++lineNo, line);
                start = stop + 1;
            }
        }
    }
    checkNotBad(in, name);
    return scanner.finish();
}

Table readTable(std::istream& in, const std::string& name, const TableReadOptions& options)
{
    RowsSink sink;
    Table table = scanTable(in, name, options, sink);
    table.rows = std::move(sink.rows);
    return table;
}

Table readTable(const std::string& path, const TableReadOptions& options)
{
    InputFile in(path, fileLimits::maximumTextBytes, "table");
    return readTable(in, path, options);
}

} // namespace detail
} // namespace roughContact
