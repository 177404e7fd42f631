// Tokenising of table files shared by ProfileReader and SpectrumReader.
#include "roughContact/io/TableReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/FloatingPoint.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
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

std::string readWholeFile(const std::string& path)
{
    std::ifstream in(path, std::ios::in | std::ios::binary);
    if (!in) {
        throw InputError(path, 0, "cannot open the file for reading");
    }
    std::string content;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        content.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        // E.g. a directory: it opens, but reading fails.
        throw InputError(path, 0, "cannot open the file for reading (read error)");
    }
    return content;
}

/// The lines of content; line k (1-based) is element k-1.
std::vector<std::string> splitLines(const std::string& content)
{
    // "\n" ends a line; a "\r" before it (or several: some exports write "\r\r\n") is trailing
    // whitespace, so line numbers agree with wc, grep -n and sed. A file without any "\n" uses
    // classic Mac "\r" endings.
    const char end = content.find('\n') != std::string::npos ? '\n' : '\r';
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < content.size()) {
        std::size_t stop = content.find(end, start);
        if (stop == std::string::npos) {
            stop = content.size();
        }
        lines.push_back(content.substr(start, stop - start));
        start = stop + 1;
    }
    if (!lines.empty() && lines.front().compare(0, 3, "\xEF\xBB\xBF") == 0) {
        lines.front().erase(0, 3); // UTF-8 byte-order mark
    }
    return lines;
}

std::string withoutComment(const std::string& line)
{
    const auto hash = line.find('#');
    return trim(hash == std::string::npos ? line : line.substr(0, hash));
}

std::string quoted(const std::string& field)
{
    return "'" + field + "'";
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
    const std::string t = trim(field);
    if (t.empty() || t.find_first_of("xX") != std::string::npos) {
        return false;
    }
    const char* begin = t.c_str();
    char* end = nullptr;
    errno = 0;
    double v = 0.0;
    {
        const QuietFloatingPoint quiet; // "1e999" raises overflow on its way to inf
        v = std::strtod(begin, &end);
    }
    if (end != begin + t.size()) {
        return false;
    }
    // Overflow gives +-HUGE_VAL (infinite) and is rejected as non-finite by the caller;
    // underflow gives a tiny or zero value, which is what the field means.
    value = v;
    return true;
}

Table readTable(const std::string& path, const TableReadOptions& options)
{
    const std::vector<std::string> lines = splitLines(readWholeFile(path));
    Table table;

    std::size_t first = 0; // index of the first line to read
    if (!options.sectionMarker.empty()) {
        for (std::size_t k = 0; k < lines.size(); ++k) {
            if (trim(lines[k]) == options.sectionMarker) {
                first = k + 1;
                table.sectionFound = true;
                break;
            }
        }
    }

    for (std::size_t k = first; k < lines.size(); ++k) {
        const long lineNo = static_cast<long>(k) + 1;
        const std::string text = withoutComment(lines[k]);
        if (text.empty()) {
            continue;
        }
        const std::vector<std::string> fields = splitFields(text);
        if (fields.empty()) {
            continue; // only separators, e.g. ",,,"
        }
        double value = 0.0;
        if (table.rows.empty() && table.headerLine == 0 && !parseNumber(fields[0], value)) {
            table.header = text;
            table.headerLine = lineNo;
            continue;
        }

        TableRow row;
        row.line = lineNo;
        row.firstField = fields[0];
        const std::size_t checked = std::min(fields.size(), options.maxColumns);
        for (std::size_t c = 0; c < checked; ++c) {
            const std::string& field = fields[c];
            std::ostringstream os;
            if (field.empty()) {
                os << "empty field in column " << c + 1;
                throw InputError(path, lineNo, os.str());
            }
            if (!parseNumber(field, value)) {
                os << "non-numeric field " << quoted(field) << " in column " << c + 1;
                bool anyNumber = false;
                double ignored = 0.0;
                for (const std::string& f : fields) {
                    anyNumber = anyNumber || parseNumber(f, ignored);
                }
                if (!anyNumber && table.headerLine != 0) {
                    os << " (only one header line is allowed; the header is line "
                       << table.headerLine << ")";
                } else if (!anyNumber) {
                    os << " (a header line is allowed only before the first data row)";
                }
                throw InputError(path, lineNo, os.str());
            }
            if (!std::isfinite(value)) {
                os << "field " << quoted(field) << " in column " << c + 1
                   << " is not a finite number";
                throw InputError(path, lineNo, os.str());
            }
            row.values.push_back(value);
        }
        if (fields.size() > options.maxColumns) {
            std::ostringstream os;
            os << fields.size() << " columns; at most " << options.maxColumns
               << " are allowed";
            throw InputError(path, lineNo, os.str());
        }
        if (table.rows.empty()) {
            table.columns = fields.size();
        } else if (fields.size() != table.columns) {
            std::ostringstream os;
            os << fields.size() << (fields.size() == 1 ? " column" : " columns") << " where line "
               << table.rows.front().line << " has " << table.columns;
            throw InputError(path, lineNo, os.str());
        }
        table.rows.push_back(std::move(row));
    }
    return table;
}

} // namespace detail
} // namespace roughContact
