// SPDX-License-Identifier: GPL-3.0-or-later
// Reading an areal surface from an ISO 25178-72 X3P file: libzip opens the archive, pugixml
// parses main.xml, OpenSSL's EVP computes the MD5 checksums.
#include "roughContact/io/X3pReader.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
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
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {
struct ZipDiscard {
    void operator()(zip_t* z) const { zip_discard(z); }
};
struct ZipFileClose {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

/// Inflates the archive's entry `entry` piece by piece into consume(const char*, std::size_t).
/// Its size as its zip header declares it must be at most maxBytes: more is refused before
/// inflating, with `advice` (what to do) at the end of the message. The running count must not
/// pass that declared size (a header that lies: refused at the first byte beyond) and must reach
/// it; the entry's CRC is checked at its end.
template <class Consume>
std::uint64_t inflateEntry(zip_t* zip, const std::string& entry, std::uint64_t maxBytes,
                           const std::string& name, const std::string& linkedBy, const std::string& advice,
                           Consume consume)
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
        os << detail::printable(entry, 80) << " has " << st.size
           << " bytes (inflated, as its zip header says); at most " << maxBytes
           << " are expected, so it is refused before inflating: " << advice;
        throw InputError(name, 0, os.str());
    }
    std::unique_ptr<zip_file_t, ZipFileClose> file(zip_fopen_index(zip, static_cast<zip_uint64_t>(index), 0));
    if (!file) {
        throw InputError(name, 0,
                         "corrupt archive: cannot open " + detail::printable(entry, 80) + ": " +
                             zip_strerror(zip));
    }
    // In pieces, so that memory grows with what the archive really holds, not with the size its
    // header claims; and to its end (a read of 0 bytes), where libzip checks the CRC.
    const std::uint64_t size = st.size;
    std::vector<char> piece(std::size_t(1) << 18);
    std::uint64_t done = 0;
    for (;;) {
        const zip_int64_t n = zip_fread(file.get(), piece.data(), piece.size());
        if (n < 0) {
            std::ostringstream os;
            os << "corrupt or truncated archive: reading " << detail::printable(entry, 80) << " failed after "
               << done << " of its " << size << " bytes: " << zip_file_strerror(file.get());
            throw InputError(name, 0, os.str());
        }
        if (n == 0) {
            break;
        }
        if (static_cast<std::uint64_t>(n) > size - done) {
            std::ostringstream os;
            os << "corrupt archive: " << detail::printable(entry, 80) << " inflates to more than the " << size
               << " bytes its zip header declares (refused at the first byte beyond)";
            throw InputError(name, 0, os.str());
        }
        consume(piece.data(), static_cast<std::size_t>(n));
        done += static_cast<std::uint64_t>(n);
    }
    if (done != size) {
        std::ostringstream os;
        os << "truncated archive: " << detail::printable(entry, 80) << " ends after " << done << " of its "
           << size << " bytes";
        throw InputError(name, 0, os.str());
    }
    return done;
}

/// The archive's entry `entry` whole, at most maxBytes long (see inflateEntry).
std::string readEntry(zip_t* zip, const std::string& entry, std::uint64_t maxBytes, const std::string& name,
                      const std::string& linkedBy, const std::string& advice)
{
    std::string data;
    // Room for what the header declares, which is at most maxBytes (the size the main.xml expects
    // of point data or a mask: at most 8 bytes a point of the largest map); a header that lies
    // gets no more.
    zip_stat_t st;
    zip_stat_init(&st);
    const zip_int64_t index = zip_name_locate(zip, entry.c_str(), 0);
    if (index >= 0 && zip_stat_index(zip, static_cast<zip_uint64_t>(index), 0, &st) == 0 &&
        (st.valid & ZIP_STAT_SIZE) && st.size <= maxBytes) {
        data.reserve(static_cast<std::size_t>(st.size));
    }
    inflateEntry(zip, entry, maxBytes, name, linkedBy, advice,
                 [&](const char* p, std::size_t k) { data.append(p, k); });
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

/// main.xml as it inflates, never held whole. The content of the first DataList element of the
/// first Record3 element of the root (Record3/DataList, the inline heights) is read as it
/// passes: Datum by Datum into values of 8 bytes a point (comments and whitespace between them
/// skipped; ISO 5436-2 allows nothing else there). The rest, the markup (with an empty
/// <DataList ...></DataList> in place of the list), is kept for pugixml, at most
/// x3pLimits::maximumMarkupBytes of it. Markup is only scanned here for where elements begin and
/// end (comments, CDATA sections, processing instructions, DOCTYPE and quoted attribute values
/// skipped); pugixml checks that it is well-formed.
class MainXmlStream {
public:
    explicit MainXmlStream(const std::string& name) : name_(name) {}

    void feed(const char* p, std::size_t k)
    {
        inflated_ += k;
        if (state_ == State::list) {
            list_.append(p, k);
            readList();
        } else {
            appendMarkup(p, k);
            if (state_ == State::markup) {
                scanMarkup();
            }
        }
    }
    /// After the last piece.
    void finish()
    {
        if (state_ == State::list) {
            throw InputError(name_, 0,
                             "main.xml line " + std::to_string(line(list_.size())) +
                                 ": not well-formed XML (the file ends inside Record3/DataList)");
        }
    }
    /// The markup, to be parsed in place.
    std::string& markup() { return markup_; }
    /// The line in main.xml of byte offset of the markup.
    long markupLine(std::size_t offset) const
    {
        long l =
            1 + static_cast<long>(std::count(
                    markup_.begin(),
                    markup_.begin() + static_cast<std::ptrdiff_t>(std::min(offset, markup_.size())), '\n'));
        return offset >= listAt_ ? l + listLines_ : l;
    }
    /// Whether Record3/DataList's content was read here (else it is in the markup, if anywhere).
    bool listRead() const { return listAt_ != npos; }
    /// One more Datum, of text t (untrimmed): empty is an invalid point.
    void addDatum(const std::string& text)
    {
        if (count_ == limits::maximumGridPoints) {
            std::ostringstream os;
            os << "main.xml: Record3/DataList has more than " << limits::maximumGridPoints
               << " Datum elements; an areal surface has at most " << limits::maximumGridPoints
               << " points (4096 x 4096)";
            throw InputError(name_, 0, os.str());
        }
        const std::string t = trimmed(text);
        double v = 0.0;
        bool ok = true;
        if (t.empty()) {
            ok = false;
        } else if (!detail::parseNumber(t, v)) {
            std::ostringstream os;
            os << "main.xml: Record3/DataList/Datum " << count_ + 1 << " is '" << detail::printable(t)
               << "', not a number";
            throw InputError(name_, 0, os.str());
        } else if (std::isnan(v)) { // a quiet NaN from strtod: no trap
            ok = false;
            v = 0.0;
        }
        if (chunks_.empty() || chunks_.back().size() == chunks_.back().capacity()) {
            // Growing pieces, from 512 kB to 32 MB: takeValues frees them as it copies them, and
            // glibc gives the largest (mapped, at least its 32 MB threshold) back to the system
            // at once, so that the copy does not double the peak.
            chunks_.emplace_back();
            chunks_.back().reserve(firstChunk << std::min<std::size_t>(chunks_.size() - 1, 6));
        }
        chunks_.back().push_back(v);
        valid_.push_back(ok ? 1 : 0);
        ++count_;
    }
    std::size_t count() const { return count_; }
    /// Moves the values read into raw and valid (one a point), freeing them as it goes.
    void takeValues(std::vector<double>& raw, std::vector<char>& valid)
    {
        raw.clear();
        raw.reserve(count_);
        for (auto& chunk : chunks_) {
            raw.insert(raw.end(), chunk.begin(), chunk.end());
            std::vector<double>().swap(chunk);
        }
        chunks_.clear();
        valid.swap(valid_);
        std::vector<char>().swap(valid_);
    }

private:
    enum class State { markup, list, tail };
    static constexpr std::size_t npos = std::string::npos;
    static constexpr std::size_t firstChunk = std::size_t(1) << 16; ///< values
    /// The longest tag read inside the list (a Datum with attributes).
    static constexpr std::size_t maximumTagBytes = 4096;

    static bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

    void appendMarkup(const char* p, std::size_t k)
    {
        if (k > x3pLimits::maximumMarkupBytes - markup_.size()) {
            std::ostringstream os;
            os << "main.xml has more than " << x3pLimits::maximumMarkupBytes
               << " bytes (the cap) outside the Datum values of Record3/DataList, after " << inflated_
               << " bytes inflated: refused before being parsed. An X3P file's metadata takes a few kB; this "
                  "is whitespace or elements by the million (a corrupt file or a zip bomb). Export the map "
                  "again, with binary point data (Record3/DataLink)";
            throw InputError(name_, 0, os.str());
        }
        markup_.append(p, k);
    }

    /// One past the '>' that ends the tag whose name begins at q, in text (quoted attribute
    /// values skipped); npos when it is not all there yet.
    static std::size_t tagEnd(const std::string& text, std::size_t q)
    {
        char quote = 0;
        for (; q < text.size(); ++q) {
            const char c = text[q];
            if (quote != 0) {
                quote = c == quote ? 0 : quote;
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '>') {
                return q + 1;
            }
        }
        return npos;
    }
    static std::string tagName(const std::string& text, std::size_t q)
    {
        std::size_t e = q;
        while (e < text.size() && !space(text[e]) && text[e] != '/' && text[e] != '>') {
            ++e;
        }
        return text.substr(q, e - q);
    }
    static bool at(const std::string& text, std::size_t p, const char* s)
    {
        return text.compare(p, std::strlen(s), s) == 0;
    }
    static std::size_t after(const std::string& text, std::size_t from, const char* end)
    {
        const std::size_t f = text.find(end, from);
        return f == npos ? npos : f + std::strlen(end);
    }
    /// One past the '>' that ends a <!DOCTYPE ...> (with its internal subset in [...]) from q.
    static std::size_t declarationEnd(const std::string& text, std::size_t q)
    {
        char quote = 0;
        int bracket = 0;
        for (; q < text.size(); ++q) {
            const char c = text[q];
            if (quote != 0) {
                quote = c == quote ? 0 : quote;
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '[') {
                ++bracket;
            } else if (c == ']') {
                --bracket;
            } else if (c == '>' && bracket <= 0) {
                return q + 1;
            }
        }
        return npos;
    }

    /// Follows the markup's elements from scan_ on, as far as whole tokens have arrived, to the
    /// start tag of Record3/DataList; its content then goes to the list.
    void scanMarkup()
    {
        const std::string& m = markup_;
        while (scan_ < m.size()) {
            const std::size_t p = scan_;
            if (m[p] != '<') {
                const std::size_t lt = m.find('<', p);
                scan_ = lt == npos ? m.size() : lt;
                continue;
            }
            if (m.size() - p < 9) { // "<![CDATA[" is the longest opening told apart
                return;
            }
            std::size_t end = npos;
            if (at(m, p, "<!--")) {
                end = after(m, p + 4, "-->");
            } else if (at(m, p, "<![CDATA[")) {
                end = after(m, p + 9, "]]>");
            } else if (at(m, p, "<?")) {
                end = after(m, p + 2, "?>");
            } else if (at(m, p, "<!")) {
                end = declarationEnd(m, p + 2);
            } else {
                end = tagEnd(m, p + 1);
            }
            if (end == npos) {
                return;
            }
            scan_ = end;
            if (m[p + 1] == '!' || m[p + 1] == '?') {
                continue;
            }
            if (m[p + 1] == '/') {
                if (depth_ > 0) {
                    --depth_;
                    if (depth_ == 1 && inRecord3_) {
                        inRecord3_ = false;
                        record3Done_ = true;
                    }
                }
                continue;
            }
            const bool empty = m[end - 2] == '/';
            const std::string element = tagName(m, p + 1);
            if (depth_ == 0) {
                ++roots_;
            } else if (depth_ == 1 && roots_ == 1 && element == "Record3" && !record3Done_) {
                inRecord3_ = !empty;
                record3Done_ = empty;
            } else if (depth_ == 2 && inRecord3_ && element == "DataList" && !listDone_) {
                listDone_ = true;
                if (!empty) {
                    // The list's content (what has arrived of it) leaves the markup.
                    std::string rest = m.substr(end);
                    markup_.resize(end);
                    listAt_ = end;
                    state_ = State::list;
                    list_ = std::move(rest);
                    readList();
                    return;
                }
            }
            if (!empty) {
                ++depth_;
            }
        }
    }

    /// The line in main.xml at byte pos of list_ (at or after listPos_).
    long line(std::size_t pos) const
    {
        return markupLine(listAt_) +
               static_cast<long>(std::count(list_.begin() + static_cast<std::ptrdiff_t>(listPos_),
                                            list_.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    }
    [[noreturn]] void listError(std::size_t pos, const std::string& what) const
    {
        throw InputError(name_, 0,
                         "main.xml line " + std::to_string(line(pos)) + ": Record3/DataList: " + what);
    }

    /// Reads the list's Datum values from list_, as far as whole elements have arrived; the end
    /// tag </DataList> and all after it go back to the markup.
    void readList()
    {
        std::string& b = list_;
        std::size_t& i = listPos_;
        i = 0;
        const auto consumeTo = [&](std::size_t j) {
            listLines_ += static_cast<long>(std::count(b.begin() + static_cast<std::ptrdiff_t>(i),
                                                       b.begin() + static_cast<std::ptrdiff_t>(j), '\n'));
            i = j;
        };
        while (i < b.size()) {
            if (skipping_ != nullptr) { // inside a comment or processing instruction
                const std::size_t e = after(b, i, skipping_);
                if (e == npos) {
                    consumeTo(std::max(i, b.size() - std::min<std::size_t>(b.size(), 2)));
                    break;
                }
                consumeTo(e);
                skipping_ = nullptr;
                continue;
            }
            if (space(b[i])) {
                std::size_t j = i + 1;
                while (j < b.size() && space(b[j])) {
                    ++j;
                }
                consumeTo(j);
                continue;
            }
            if (b[i] != '<') {
                listError(i, "text outside a Datum element ('" + detail::printable(b.substr(i, 20)) +
                                 "'); only Datum elements are allowed there");
            }
            if (b.size() - i < 4) {
                break;
            }
            if (at(b, i, "<!--")) {
                consumeTo(i + 4);
                skipping_ = "-->";
                continue;
            }
            if (at(b, i, "<?")) {
                consumeTo(i + 2);
                skipping_ = "?>";
                continue;
            }
            if (b[i + 1] == '!') {
                listError(i, "a CDATA section or declaration ('" + detail::printable(b.substr(i, 12)) +
                                 "'); only Datum elements are allowed there");
            }
            const std::size_t end = tagEnd(b, i + 1);
            if (end == npos) {
                if (b.size() - i > maximumTagBytes) {
                    listError(i, "a tag longer than " + std::to_string(maximumTagBytes) + " bytes");
                }
                break;
            }
            if (b[i + 1] == '/') {
                const std::string element = tagName(b, i + 2);
                if (element != "DataList") {
                    listError(i, "not well-formed XML (end tag </" + detail::printable(element) +
                                     "> where </DataList> or a Datum was expected)");
                }
                // The end of the list: the rest is markup again.
                const std::size_t from = i;
                consumeTo(i); // (no newline before it left uncounted)
                state_ = State::tail;
                appendMarkup(b.data() + from, b.size() - from);
                b.clear();
                b.shrink_to_fit();
                i = 0;
                return;
            }
            const std::string element = tagName(b, i + 1);
            if (element != "Datum") {
                listError(i, "a <" + detail::printable(element) +
                                 "> element; only Datum elements (one number each) are allowed there");
            }
            if (b[end - 2] == '/') { // <Datum/>: an invalid point
                addDatum(std::string());
                consumeTo(end);
                continue;
            }
            const std::size_t lt = b.find('<', end);
            if (lt == npos || b.size() - lt < 2) {
                if (b.size() - end > x3pLimits::maximumDatumCharacters) {
                    listError(i, "Datum " + std::to_string(count_ + 1) + " is longer than " +
                                     std::to_string(x3pLimits::maximumDatumCharacters) +
                                     " characters: not a number");
                }
                break;
            }
            if (b[lt + 1] != '/') {
                listError(lt, "Datum " + std::to_string(count_ + 1) + " holds markup ('" +
                                  detail::printable(b.substr(lt, 12)) + "'); only a number is allowed there");
            }
            const std::size_t close = tagEnd(b, lt + 2);
            if (close == npos) {
                if (b.size() - lt > maximumTagBytes) {
                    listError(lt, "a tag longer than " + std::to_string(maximumTagBytes) + " bytes");
                }
                break;
            }
            const std::string closing = tagName(b, lt + 2);
            if (closing != "Datum") {
                listError(lt, "not well-formed XML (end tag </" + detail::printable(closing) +
                                  "> of a Datum element)");
            }
            if (lt - end > x3pLimits::maximumDatumCharacters) {
                listError(i, "Datum " + std::to_string(count_ + 1) + " is longer than " +
                                 std::to_string(x3pLimits::maximumDatumCharacters) +
                                 " characters: not a number");
            }
            addDatum(b.substr(end, lt - end));
            consumeTo(close);
        }
        b.erase(0, i);
        i = 0;
    }

    const std::string& name_;
    State state_ = State::markup;
    std::string markup_;
    std::size_t scan_ = 0;      ///< where scanMarkup goes on
    int depth_ = 0;             ///< elements open at scan_
    int roots_ = 0;             ///< elements at depth 0 so far
    bool inRecord3_ = false;    ///< inside the root's first Record3
    bool record3Done_ = false;  ///< past it
    bool listDone_ = false;     ///< its first DataList found
    std::size_t listAt_ = npos; ///< where the list's content was in the markup
    std::string list_;          ///< what has arrived of the list and is not read yet
    std::size_t listPos_ = 0;   ///< where readList is in list_ (the line ends before it counted)
    long listLines_ = 0;        ///< line ends in the list's content read so far
    const char* skipping_ = nullptr;
    std::uint64_t inflated_ = 0;
    std::vector<std::vector<double>> chunks_;
    std::vector<char> valid_;
    std::size_t count_ = 0;
};

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
    return readX3pBytes(readWholeFile(path, fileLimits::maximumX3pBytes, "X3P"), path, options);
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

    // main.xml, inflated piece by piece: the inline Datum values read as they pass, the rest
    // (the metadata) parsed in place, without a copy.
    MainXmlStream xmlStream(name);
    inflateEntry(
        zip.get(), "main.xml", x3pLimits::maximumXmlBytes, name, "",
        "that is more than 64 bytes a point of the largest map (4096 x 4096 points, inline); a "
        "corrupt file or a zip bomb. Export the map again, with binary point data (Record3/DataLink)",
        [&](const char* p, std::size_t k) { xmlStream.feed(p, k); });
    xmlStream.finish();
    std::string& xmlText = xmlStream.markup();
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer_inplace(&xmlText[0], xmlText.size());
    if (!parsed) {
        throw InputError(name, 0,
                         "main.xml line " +
                             std::to_string(xmlStream.markupLine(
                                 static_cast<std::size_t>(std::max<std::ptrdiff_t>(parsed.offset, 0)))) +
                             ": not well-formed XML (" + parsed.description() + ")");
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

    std::vector<double> raw; // the values read, then the heights in place
    std::vector<char> valid;
    const pugi::xml_node link = record3.child("DataLink");
    const pugi::xml_node list = record3.child("DataList");
    if (link) {
        const std::string dataName = xml.text(link, "Record3/DataLink", "PointDataLink");
        const std::string expectedMd5 = xml.text(link, "Record3/DataLink", "MD5ChecksumPointData");
        const std::uint64_t expectedBytes = n * bytesOf(type);
        std::ostringstream need;
        need << nx << " x " << ny << " points (Record3/MatrixDimension) of type " << type << " need "
             << expectedBytes << "; the archive does not match its main.xml (a corrupt file or a zip bomb)";
        const std::string data =
            readEntry(zip.get(), dataName, expectedBytes, name, "Record3/DataLink/PointDataLink", need.str());
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
        raw.assign(n, 0.0);
        valid.assign(n, 1);
        for (std::size_t i = 0; i < n; ++i) {
            valid[i] = decode(data, i, type, raw[i]);
        }
        if (const pugi::xml_node mask = link.child("ValidPointsLink")) {
            const std::string maskName = trimmed(mask.child_value());
            const std::uint64_t maskBytes = (n + 7) / 8;
            const std::string bits =
                readEntry(zip.get(), maskName, maskBytes, name, "Record3/DataLink/ValidPointsLink",
                          "a mask of " + std::to_string(n) + " points needs " + std::to_string(maskBytes) +
                              "; the archive does not match its main.xml (a corrupt file or a zip bomb)");
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
        if (!xmlStream.listRead()) { // not seen as it passed (e.g. main.xml in UTF-16): from the tree
            for (pugi::xml_node datum = list.child("Datum"); datum; datum = datum.next_sibling("Datum")) {
                xmlStream.addDatum(datum.child_value());
            }
        }
        if (xmlStream.count() != n) {
            std::ostringstream os;
            os << "main.xml: Record3/DataList has " << xmlStream.count() << " Datum elements; " << nx << " x "
               << ny << " points (Record3/MatrixDimension) need " << n;
            throw InputError(name, 0, os.str());
        }
        xmlStream.takeValues(raw, valid);
    } else {
        throw InputError(name, 0,
                         "main.xml has neither Record3/DataLink nor Record3/DataList (the point data)");
    }

    // Heights [m] = offset + increment * value, in place, checked before any trap can see them.
    std::vector<double>& z = raw;
    std::size_t invalid = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!valid[i]) {
            ++invalid;
            z[i] = 0.0;
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
               << limits::valueText(h, "m") << "; heights must be finite and within +-" << limits::maximumHeight
               << " m";
            throw InputError(name, 0, os.str());
        }
        z[i] = h;
    }
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
