// SPDX-License-Identifier: GPL-3.0-or-later
// Reading spectrum tables (io/SpectrumReader): frequency [1/m] and amplitude [m] columns, the
// default scan length L = 1/f_min, and every error (naming file and line).
#include "roughContact/Error.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include "InputErrors.hpp"
#include "TempDirTest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

using namespace roughContact;
namespace fs = std::filesystem;

namespace {

/// A fresh directory per test (tests/support/TempDirTest.hpp).
class SpectrumReaderTest : public roughContactTest::TempDirTest {};

std::string g17(double v)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

using roughContactTest::expectLocated; // tests/support/InputErrors.hpp

/// The InputError that readSpectrum(path, length) throws; fails the test when it throws none.
InputError spectrumError(const std::string& path, std::optional<double> length = std::nullopt)
{
    return roughContactTest::thrownInputError([&] { readSpectrum(path, length); }, path);
}

// A power law beta = 1e-9 m * (f / 1e4 1/m)^-1.2 at f = 1e4, 2e4, ..., 8e4 1/m: the kind of
// table the readers are for, with values that do not print exactly in few digits.
const std::vector<double> freqs{1e4, 2e4, 3e4, 4e4, 5e4, 6e4, 7e4, 8e4};
double amplitudeAt(double f)
{
    return 1e-9 * std::pow(f / 1e4, -1.2);
}

std::string table(const std::string& sep = " ")
{
    std::string s;
    for (double f : freqs) {
        s += g17(f) + sep + g17(amplitudeAt(f)) + "\n";
    }
    return s;
}

} // namespace

// ---- what it reads --------------------------------------------------------------------------

TEST_F(SpectrumReaderTest, readsFrequencyAndAmplitudeExactly)
{
    const std::string path = write("s.txt", table());
    const Spectrum s = readSpectrum(path);
    EXPECT_EQ(s.source(), path);
    ASSERT_EQ(s.size(), freqs.size());
    for (std::size_t i = 0; i < freqs.size(); ++i) {
        // %.17g round-trips a double exactly, and the reader applies no unit factor.
        EXPECT_EQ(s.frequency(i), freqs[i]);
        EXPECT_EQ(s.amplitude(i), amplitudeAt(freqs[i]));
    }
}

TEST_F(SpectrumReaderTest, lengthDefaultsToOneOverTheLowestFrequency)
{
    const Spectrum s = readSpectrum(write("s.txt", table()));
    EXPECT_EQ(s.length(), 1.0 / 1e4); // one division, as the definition: exact to the ulp
    EXPECT_EQ(s.nominalArea(), s.length() * s.length());

    // Another table: L = 1/2500 m = 0.4 mm (one division, within 4 ulps of the literal).
    const std::string other = write("t.txt", "2500 1e-9\n5000 5e-10\n");
    EXPECT_DOUBLE_EQ(readSpectrum(other).length(), 4e-4);
}

TEST_F(SpectrumReaderTest, aGivenLengthIsUsedAsIs)
{
    const std::string path = write("s.txt", table());
    EXPECT_EQ(readSpectrum(path, 2.5e-3).length(), 2.5e-3);
    // Even one shorter than 1/f_min: the caller knows the scan.
    EXPECT_EQ(readSpectrum(path, 1e-5).length(), 1e-5);
}

TEST_F(SpectrumReaderTest, separatorsCommentsAndAHeaderAsForProfiles)
{
    const Spectrum plain = readSpectrum(write("a.txt", table(" ")));
    const std::string text = "# spectrum of sample 3\n"
                             "f [1/m], beta [m]\n"
                             "\n"
                             + table(", ") + "# end\n";
    const Spectrum decorated = readSpectrum(write("b.csv", text));
    EXPECT_EQ(decorated.frequencies(), plain.frequencies());
    EXPECT_EQ(decorated.amplitudes(), plain.amplitudes());
    EXPECT_EQ(readSpectrum(write("c.tsv", table("\t"))).amplitudes(), plain.amplitudes());
    EXPECT_EQ(readSpectrum(write("d.csv", table(";"))).amplitudes(), plain.amplitudes());
}

TEST_F(SpectrumReaderTest, oneLevelAndZeroAmplitudesAreValid)
{
    const Spectrum one = readSpectrum(write("one.txt", "1000 2e-9\n"));
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one.length(), 1e-3);
    const Spectrum zero = readSpectrum(write("zero.txt", "1000 0\n2000 -0\n"));
    EXPECT_EQ(zero.amplitude(0), 0.0);
    EXPECT_EQ(zero.amplitude(1), 0.0);
    EXPECT_EQ(zero.variance(), 0.0);
}

TEST_F(SpectrumReaderTest, varianceOfTheReadSpectrumIsTheSumOfHalfSquares)
{
    // A check on the values through a derived quantity: sum beta^2/2 computed here from the
    // formula; 8 terms, relative rounding ~1e-15, so 1e-12 is generous.
    double expected = 0.0;
    for (double f : freqs) {
        expected += 0.5 * amplitudeAt(f) * amplitudeAt(f);
    }
    EXPECT_NEAR(readSpectrum(write("s.txt", table())).variance(), expected, 1e-12 * expected);
}

// ---- errors ---------------------------------------------------------------------------------

TEST_F(SpectrumReaderTest, missingFile)
{
    const std::string path = (dir_ / "absent.txt").string();
    expectLocated(spectrumError(path), path, 0, "cannot open the file for reading: there is no such file");
}

TEST_F(SpectrumReaderTest, emptyFilesHaveNoLevels)
{
    for (const std::string content : {"", "\n\n", "# comment only\n", "f beta\n"}) {
        const std::string path = write("e.txt", content);
        expectLocated(spectrumError(path), path, 0, "no data rows");
    }
}

TEST_F(SpectrumReaderTest, zeroAndNegativeFrequencies)
{
    for (const std::string f : {"0", "-0", "-1000", "0.0e0"}) {
        const std::string path = write("s.txt", "# c\n" + f + " 1e-9\n2000 1e-9\n");
        expectLocated(spectrumError(path), path, 2, "frequency must be positive");
    }
    // Further down the table too, on its own line.
    const std::string later = write("t.txt", "1000 1e-9\n2000 1e-9\n-3000 1e-9\n");
    expectLocated(spectrumError(later), later, 3, "frequency must be positive, got -3000");
}

TEST_F(SpectrumReaderTest, frequenciesMustIncreaseStrictly)
{
    const std::string down = write("d.txt", "f beta\n1000 1e-9\n3000 1e-9\n2000 1e-9\n");
    expectLocated(spectrumError(down), down, 4,
                  "frequencies must increase strictly: 2000 after 3000 on line 3");
    const std::string same = write("s.txt", "1000 1e-9\n1000 2e-9\n");
    expectLocated(spectrumError(same), same, 2, "frequencies must increase strictly");
}

TEST_F(SpectrumReaderTest, negativeAmplitude)
{
    const std::string path = write("s.txt", "1000 1e-9\n2000 -1e-12\n");
    expectLocated(spectrumError(path), path, 2, "amplitude must be >= 0, got -1e-12");
}

TEST_F(SpectrumReaderTest, nanInfAndNonNumericFields)
{
    for (auto [row, column] : {std::pair{std::string("nan 1e-9"), 1}, std::pair{std::string("2000 nan"), 2},
                               std::pair{std::string("inf 1e-9"), 1}, std::pair{std::string("2000 -inf"), 2},
                               std::pair{std::string("2000 1e999"), 2}}) {
        const std::string path = write("s.txt", "1000 1e-9\n" + row + "\n3000 1e-9\n");
        expectLocated(spectrumError(path), path, 2,
                      "in column " + std::to_string(column) + " is not a finite number");
    }
    const std::string text = write("t.txt", "1000 1e-9\n2000 1e-9m\n");
    expectLocated(spectrumError(text), text, 2, "non-numeric field '1e-9m' in column 2");
}

TEST_F(SpectrumReaderTest, wrongNumberOfColumns)
{
    const std::string one = write("one.txt", "# frequencies only\n1000\n2000\n");
    expectLocated(spectrumError(one), one, 2, "one column; a spectrum needs two");
    const std::string three = write("three.txt", "1000 1e-9\n2000 1e-9 7\n");
    expectLocated(spectrumError(three), three, 2, "3 columns; at most 2 are allowed");
    const std::string mixed = write("mixed.txt", "1000 1e-9\n2000\n");
    expectLocated(spectrumError(mixed), mixed, 2, "1 column where line 1 has 2");
}

TEST_F(SpectrumReaderTest, badLengthIsAParameterErrorEvenForAGoodFile)
{
    const std::string path = write("s.txt", table());
    for (double bad : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
        try {
            readSpectrum(path, bad);
            ADD_FAILURE() << "length " << bad << " accepted";
        } catch (const ParameterError& e) {
            EXPECT_EQ(e.parameter(), "length");
        }
    }
}
