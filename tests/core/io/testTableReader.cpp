// SPDX-License-Identifier: GPL-3.0-or-later
// Tokenising of table files (io/TableReader, the internal layer under the profile and
// spectrum readers): separators, comments, the header, line numbers and every error.
#include "roughContact/Error.hpp"
#include "roughContact/io/TableReader.hpp"

#include "InputErrors.hpp"
#include "TempDirTest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace roughContact;
using namespace roughContact::detail;
namespace fs = std::filesystem;

namespace {

/// A fresh directory per test (tests/support/TempDirTest.hpp).
class TableReaderTest : public roughContactTest::TempDirTest {};

// The error names the file and the line as "FILE:LINE: " and its message contains text (every
// line checked here is >= 1).
using roughContactTest::expectLocated; // tests/support/InputErrors.hpp

/// The InputError that readTable(path) throws; fails the test when it throws none.
InputError tableError(const std::string& path, const TableReadOptions& options = {})
{
    return roughContactTest::thrownInputError([&] { readTable(path, options); }, path);
}

using Fields = std::vector<std::string>;
} // namespace

// ---- splitFields ----------------------------------------------------------------------------

TEST(SplitFields, whitespaceRunsAreOneSeparator)
{
    EXPECT_EQ(splitFields("1 2"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("  1 \t  2\t"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("1\t2\t3"), (Fields{"1", "2", "3"}));
}

TEST(SplitFields, commaOrSemicolonWithOptionalWhitespace)
{
    EXPECT_EQ(splitFields("1,2"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("1 , 2"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("1;2"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("1\t;\t2"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("-1.5e-3,+2E4"), (Fields{"-1.5e-3", "+2E4"}));
}

TEST(SplitFields, emptyFieldsInsideAreKeptAtTheEndDropped)
{
    EXPECT_EQ(splitFields("1,,2"), (Fields{"1", "", "2"}));
    EXPECT_EQ(splitFields(",1"), (Fields{"", "1"}));
    EXPECT_EQ(splitFields("1,2,"), (Fields{"1", "2"}));
    EXPECT_EQ(splitFields("0.0,-0.00933,,"), (Fields{"0.0", "-0.00933"})); // Dektak rows
    EXPECT_EQ(splitFields(",,,"), Fields{});
    EXPECT_EQ(splitFields(""), Fields{});
    EXPECT_EQ(splitFields(" \t "), Fields{});
}

// ---- parseNumber ----------------------------------------------------------------------------

TEST(ParseNumber, acceptsDecimalNumbers)
{
    double v = -1.0;
    EXPECT_TRUE(parseNumber("1.5", v));
    EXPECT_EQ(v, 1.5);
    EXPECT_TRUE(parseNumber(" -2e3 ", v));
    EXPECT_EQ(v, -2000.0);
    EXPECT_TRUE(parseNumber("+.5", v));
    EXPECT_EQ(v, 0.5);
    EXPECT_TRUE(parseNumber("7.", v));
    EXPECT_EQ(v, 7.0);
    EXPECT_TRUE(parseNumber("1.25E-3", v));
    EXPECT_EQ(v, 1.25e-3); // strtod rounds correctly, as the compiler does the literal
}

TEST(ParseNumber, underflowIsZeroOverflowAndNanAreNotFinite)
{
    double v = -1.0;
    EXPECT_TRUE(parseNumber("1e-400", v));
    EXPECT_EQ(v, 0.0);
    EXPECT_TRUE(parseNumber("1e400", v));
    EXPECT_TRUE(std::isinf(v));
    EXPECT_TRUE(parseNumber("nan", v));
    EXPECT_TRUE(std::isnan(v));
    EXPECT_TRUE(parseNumber("-inf", v));
    EXPECT_TRUE(std::isinf(v));
}

TEST(ParseNumber, rejectsEverythingElse)
{
    double v = 0.0;
    for (const std::string bad : {"", " ", "abc", "1.5.2", "1,5", "1e", "e5", "--1", "0x10",
                                  "0x1p3", "1 2", "1.5m", "\xE2\x88\x92" "1" /* U+2212 minus */}) {
        EXPECT_FALSE(parseNumber(bad, v)) << "'" << bad << "'";
    }
}

// ---- readTable: what it accepts ---------------------------------------------------------------

TEST_F(TableReaderTest, readsRowsWithMixedSeparatorsCommentsAndBlankLines)
{
    const std::string path = write("t.txt", "# a comment line\n"
                                            "\n"
                                            "1 2\n"
                                            "3,4   # trailing comment\n"
                                            "   \t  \n"
                                            "5 ; 6\n"
                                            "7\t8,\n");
    const Table t = readTable(path);
    ASSERT_EQ(t.rows.size(), 4u);
    EXPECT_EQ(t.columns, 2u);
    EXPECT_TRUE(t.header.empty());
    EXPECT_EQ(t.headerLine, 0);
    EXPECT_FALSE(t.sectionFound);
    const std::vector<long> lines{3, 4, 6, 7};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(t.rows[i].line, lines[i]);
        ASSERT_EQ(t.rows[i].values.size(), 2u);
        EXPECT_EQ(t.rows[i].values[0], 2.0 * static_cast<double>(i) + 1.0);
        EXPECT_EQ(t.rows[i].values[1], 2.0 * static_cast<double>(i) + 2.0);
    }
}

TEST_F(TableReaderTest, oneHeaderLineBeforeTheDataIsKept)
{
    const std::string path = write("t.csv", "# exported by hand\n"
                                            "x [m], z [m]  # columns\n"
                                            "0.0, 1.0\n"
                                            "0.1, 2.0\n");
    const Table t = readTable(path);
    EXPECT_EQ(t.header, "x [m], z [m]");
    EXPECT_EQ(t.headerLine, 2);
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0].line, 3);
}

TEST_F(TableReaderTest, keepsTheFirstFieldAsPrinted)
{
    const std::string path = write("t.txt", "0.10 1\n  2.500e-03\t4\n");
    const Table t = readTable(path);
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0].firstField, "0.10");
    EXPECT_EQ(t.rows[1].firstField, "2.500e-03");
}

TEST_F(TableReaderTest, oneColumnTables)
{
    const std::string path = write("z.txt", "z\n1\n2\n3\n");
    const Table t = readTable(path);
    EXPECT_EQ(t.columns, 1u);
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.rows[2].values, std::vector<double>{3.0});
}

TEST_F(TableReaderTest, lineNumbersAgreeWithWcForEveryLineEnding)
{
    // "\r\n" (Windows), "\r\r\n" (as the Dektak software writes some lines), no final newline.
    const std::string path = write("crlf.txt", "x,z\r\n1,1\r\r\n\r\n2,2\r\n3,3");
    const Table t = readTable(path);
    ASSERT_EQ(t.rows.size(), 3u);
    EXPECT_EQ(t.headerLine, 1);
    EXPECT_EQ(t.rows[0].line, 2);
    EXPECT_EQ(t.rows[1].line, 4);
    EXPECT_EQ(t.rows[2].line, 5);
    EXPECT_EQ(t.rows[2].values[1], 3.0);

    // Classic Mac: "\r" alone ends the lines of a file without any "\n".
    const std::string mac = write("mac.txt", "1 1\r2 2\r\rbad 3\r");
    expectLocated(tableError(mac), mac, 4, "non-numeric field 'bad' in column 1");
}

TEST_F(TableReaderTest, skipsAUtf8ByteOrderMark)
{
    const std::string path = write("bom.csv", "\xEF\xBB\xBF" "1,2\n3,4\n");
    const Table t = readTable(path);
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0].values[0], 1.0);
    EXPECT_EQ(t.rows[0].line, 1);
}

TEST_F(TableReaderTest, emptyAndCommentOnlyFilesGiveAnEmptyTable)
{
    for (const std::string content : {"", "\n\n", "# nothing\n  # here\n", ",,,\n", "x z\n"}) {
        const Table t = readTable(write("e.txt", content));
        EXPECT_TRUE(t.rows.empty()) << content;
        EXPECT_EQ(t.columns, 0u) << content;
    }
}

TEST_F(TableReaderTest, sectionMarkerSkipsEverythingUpToIt)
{
    TableReadOptions o;
    o.sectionMarker = "Scan Data";
    // Before the marker: text that would be an error as data. The marker line has trailing
    // whitespace and "\r" as the Dektak export writes it.
    const std::string path = write("d.csv", "Scan Parameters\r\r\n"
                                            "Length,1500.0 um\r\n"
                                            "Ra,1.0 um,2.0 um,3\r\n"
                                            "  Scan Data \r\r\n"
                                            "Lateral um,Raw Micrometer,\r\n"
                                            "0.0,-0.5,,\r\n"
                                            "0.2,0.25,,\r\n");
    const Table t = readTable(path, o);
    EXPECT_TRUE(t.sectionFound);
    EXPECT_EQ(t.header, "Lateral um,Raw Micrometer,");
    EXPECT_EQ(t.headerLine, 5);
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0].line, 6);
    EXPECT_EQ(t.rows[1].values, (std::vector<double>{0.2, 0.25}));
    EXPECT_EQ(t.columns, 2u);

    // Without the marker in the file the whole file is data.
    const std::string plain = write("p.csv", "x,z\n1,2\n");
    const Table u = readTable(plain, o);
    EXPECT_FALSE(u.sectionFound);
    EXPECT_EQ(u.rows.size(), 1u);
    // A marker in a comment is not the marker.
    const std::string commented = write("c.csv", "# Scan Data\n1,2\n");
    EXPECT_FALSE(readTable(commented, o).sectionFound);
}

// ---- readTable: errors, each naming the file and the line ------------------------------------

TEST_F(TableReaderTest, missingFileNamesThePath)
{
    const std::string path = (dir_ / "no-such-file.txt").string();
    const InputError e = tableError(path);
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 0); // there is no line to name
    EXPECT_EQ(std::string(e.what()), path + ": cannot open the file for reading: there is no such file");
}

TEST_F(TableReaderTest, aDirectoryIsNotReadAsAnEmptyFile)
{
    const InputError e = tableError(dir_.string());
    EXPECT_EQ(e.file(), dir_.string());
    EXPECT_EQ(std::string(e.what()), dir_.string() + ": is a directory, not a table file: the tools read regular files only");
}

TEST_F(TableReaderTest, aNameWithANulByteIsRefused)
{
    // Issue 18, item 14: "file.txt\0junk" opened "file.txt", a file that was not named.
    const std::string path = write("t.txt", "1 2\n3 4\n");
    const std::string named = path + std::string(1, '\0') + "junk";
    const InputError e = tableError(named);
    EXPECT_NE(std::string(e.what()).find("the file name holds a NUL byte"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("t.txt\\x00junk"), std::string::npos) << e.what();
}

TEST_F(TableReaderTest, nonNumericField)
{
    const std::string path = write("t.txt", "1 2\n3 4\n5 x6\n");
    expectLocated(tableError(path), path, 3, "non-numeric field 'x6' in column 2");
}

TEST(Printable, escapesNonPrintableBytesAndCutsLongText)
{
    EXPECT_EQ(printable("1.5e-3"), "1.5e-3");
    EXPECT_EQ(printable(std::string("a\0b\tc\xB5m\x7F", 8)), "a\\x00b\\x09c\\xB5m\\x7F");
    EXPECT_EQ(printable(std::string(40, 'x')), std::string(40, 'x'));
    EXPECT_EQ(printable(std::string(41, 'x')), std::string(40, 'x') + "...");
    // An escape is never cut in two: 10 escapes (40 characters) fit, the 11th does not.
    EXPECT_EQ(printable(std::string(11, '\0')), [] {
        std::string s;
        for (int i = 0; i < 10; ++i) {
            s += "\\x00";
        }
        return s + "...";
    }());
    EXPECT_EQ(printable(std::string(100, 'y'), 80), std::string(80, 'y') + "...");
}

// A megabyte of junk (NUL bytes included) in one field: the message shows its first 40
// characters, escaped, not the megabyte.
TEST_F(TableReaderTest, aHugeBinaryFieldIsEchoedShortAndPrintable)
{
    std::string junk = "abc";
    junk += std::string("\0\x01", 2);
    junk += std::string(1 << 20, 'q');
    const std::string path = write("junk.txt", "1 2\n3 " + junk + "\n");
    const InputError e = tableError(path);
    expectLocated(e, path, 2, "non-numeric field 'abc\\x00\\x01" + std::string(29, 'q') + "...' in column 2");
    EXPECT_LT(std::string(e.what()).size(), path.size() + 100);
}

TEST_F(TableReaderTest, decimalCommaIsNotSilentlyMisread)
{
    // "0,5;1,5" (a European spreadsheet) splits into four fields: too many columns, not 0 and 5.
    const std::string path = write("t.csv", "0,5;1,5\n");
    expectLocated(tableError(path), path, 1, "4 columns; at most 2 are allowed");
}

TEST_F(TableReaderTest, aSecondHeaderLineIsAnError)
{
    const std::string path = write("t.txt", "x z\nunits: m m\n1 2\n");
    expectLocated(tableError(path), path, 2,
                  "non-numeric field 'units:' in column 1 (only one header line is allowed; the "
                  "header is line 1)");
}

TEST_F(TableReaderTest, textAfterTheDataIsAnError)
{
    const std::string path = write("t.txt", "1 2\n3 4\nend of data\n");
    expectLocated(tableError(path), path, 3,
                  "(a header line is allowed only before the first data row)");
}

TEST_F(TableReaderTest, nonFiniteFields)
{
    for (const std::string bad : {"nan", "NaN", "inf", "-Infinity", "1e999", "-1e400"}) {
        const std::string path = write("t.txt", "1 2\n3 " + bad + "\n");
        expectLocated(tableError(path), path, 2,
                      "field '" + bad + "' in column 2 is not a finite number");
        // In column 1 too; a NaN is never a header either.
        const std::string first = write("u.txt", bad + " 2\n3 4\n");
        expectLocated(tableError(first), first, 1,
                      "field '" + bad + "' in column 1 is not a finite number");
    }
}

TEST_F(TableReaderTest, emptyFieldInsideARow)
{
    const std::string path = write("t.csv", "1,2\n3,,4\n");
    expectLocated(tableError(path), path, 2, "empty field in column 2");
    const std::string lead = write("u.csv", "1,2\n,4\n");
    expectLocated(tableError(lead), lead, 2, "empty field in column 1");
}

TEST_F(TableReaderTest, tooManyColumns)
{
    const std::string path = write("t.txt", "# c\n1 2 3\n");
    expectLocated(tableError(path), path, 2, "3 columns; at most 2 are allowed");
    TableReadOptions one;
    one.maxColumns = 1;
    const std::string two = write("u.txt", "1\n2 3\n");
    expectLocated(tableError(two, one), two, 2, "2 columns; at most 1 are allowed");
}

TEST_F(TableReaderTest, columnCountMustNotChange)
{
    const std::string path = write("t.txt", "x z\n1 2\n\n3\n");
    expectLocated(tableError(path), path, 4, "1 column where line 2 has 2");
    const std::string more = write("u.txt", "1\n2\n3 4\n");
    expectLocated(tableError(more), more, 3, "2 columns where line 1 has 1");
}
