// SPDX-License-Identifier: GPL-3.0-or-later
// Numbers as text (io/Numbers.hpp): parsed and formatted the same under a comma-decimal locale
// as under "C" (issue 18, item 8: strtod followed the process's locale, so a program that set
// de_DE.UTF-8 read "8.2477e-08" as 8), and without a floating-point trap on overflow (this
// main traps as OpenFOAM does).
#include "roughContact/Error.hpp"
#include "roughContact/io/Numbers.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/surface/Profile.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

using namespace roughContact;

namespace {

constexpr const char* commaLocale = "de_DE.UTF-8";

// Sets LC_ALL to de_DE.UTF-8: the system's, or one built with localedef (Debian's package
// locales, etc/debianPackages) into a private directory named by LOCPATH while setlocale loads
// it. Never skips: without the locale the test would assert nothing.
class CommaLocale {
public:
    CommaLocale()
    {
        saved_ = std::setlocale(LC_ALL, nullptr);
        if (std::setlocale(LC_ALL, commaLocale) != nullptr) {
            return;
        }
        dir_ = std::filesystem::temp_directory_path() / ("roughContact-locale-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
        const std::string command = "localedef -i de_DE -f UTF-8 '" + (dir_ / commaLocale).string() + "' 2>&1";
        const int rc = std::system(command.c_str());
        ::setenv("LOCPATH", dir_.c_str(), 1);
        const char* set = std::setlocale(LC_ALL, commaLocale);
        ::unsetenv("LOCPATH");
        if (set == nullptr) {
            ADD_FAILURE() << "no locale " << commaLocale << " and localedef could not build one (exit " << rc
                          << "); install the Debian package 'locales'";
        }
    }
    ~CommaLocale()
    {
        std::setlocale(LC_ALL, saved_.c_str());
        if (!dir_.empty()) {
            std::error_code ec;
            std::filesystem::remove_all(dir_, ec);
        }
    }
    bool active() const { return std::string(std::setlocale(LC_ALL, nullptr)) == commaLocale; }

private:
    std::string saved_;
    std::filesystem::path dir_;
};

} // namespace

TEST(Numbers, ParseAndFormatInTheCLocale)
{
    double v = 0.0;
    EXPECT_TRUE(parseNumber("8.2477e-08", v));
    EXPECT_EQ(v, 8.2477e-08);
    EXPECT_TRUE(parseNumber("  -1.5\t", v)); // surrounding whitespace
    EXPECT_EQ(v, -1.5);
    EXPECT_TRUE(parseNumber("+2", v));
    EXPECT_EQ(v, 2.0);
    EXPECT_TRUE(parseNumber("1e999", v)); // overflow: inf, and no trap (this main traps overflow)
    EXPECT_TRUE(std::isinf(v));
    EXPECT_TRUE(parseNumber("-1e999", v));
    EXPECT_TRUE(std::isinf(v) && v < 0.0);
    EXPECT_TRUE(parseNumber("1e-400", v)); // underflow: 0, what the text means
    EXPECT_EQ(v, 0.0);
    EXPECT_TRUE(parseNumber("nan", v));
    EXPECT_TRUE(std::isnan(v));
    for (const char* bad : {"", " ", "1,5", "0x10", "1.5x", "1 2", "abc", "--1", "1e", "1.5.2"}) {
        EXPECT_FALSE(parseNumber(bad, v)) << "'" << bad << "'";
    }
    EXPECT_FALSE(parseNumber(std::string("1\0" "5", 3), v)); // a NUL inside is not a number
    EXPECT_EQ(formatNumber(0.1), "0.10000000000000001");
    EXPECT_EQ(formatNumber(1.5, 10), "1.5");
    EXPECT_EQ(formatNumber(1e21), "1e+21");
    EXPECT_EQ(formatNumber(-0.0), "-0");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity()), "inf");
    // 17 digits read back exactly.
    for (double x : {1.0 / 3.0, 6.02214076e23, 5e-324, 1.7976931348623157e308}) {
        ASSERT_TRUE(parseNumber(formatNumber(x), v));
        EXPECT_EQ(v, x);
    }
}

TEST(Numbers, TheSameUnderACommaDecimalLocale)
{
    // The reference first, in the "C" locale.
    const std::string file = testing::TempDir() + "/numbersLocale-" + std::to_string(::getpid()) + ".txt";
    {
        std::ofstream out(file);
        out << "0 8.2477e-08\n1.5e-6 -3.25e-08\n3e-6 1.0e-07\n4.5e-6 2.5e-09\n"
            << "6e-6 -1.25e-08\n7.5e-6 4.5e-08\n9e-6 -6.5e-08\n10.5e-6 1.75e-08\n";
    }
    const Profile reference = readProfile(file);
    const CommaLocale comma;
    ASSERT_TRUE(comma.active());
    // The C library's own strtod now reads a comma: the locale is real.
    EXPECT_EQ(std::strtod("8.2477e-08", nullptr), 8.0);
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%.1f", 1.5);
    EXPECT_EQ(std::string(buffer), "1,5");
    double v = 0.0;
    EXPECT_TRUE(parseNumber("8.2477e-08", v));
    EXPECT_EQ(v, 8.2477e-08);
    EXPECT_FALSE(parseNumber("1,5", v));
    EXPECT_EQ(formatNumber(1.5, 10), "1.5");
    EXPECT_EQ(formatNumber(0.1), "0.10000000000000001");
    const Profile p = readProfile(file);
    EXPECT_EQ(p.heights(), reference.heights());
    EXPECT_EQ(p.spacing(), reference.spacing());
    std::remove(file.c_str());
}

TEST(Numbers, WholeNumbersInDecimalDigitsOnly)
{
    // The one reading of a whole number written as text (the CLI's --synthesize N,SEED, a
    // SpecValues' whole()): 0 .. 2^64 - 1 exactly, nothing else.
    EXPECT_EQ(parseWholeNumber("0", "n", "N"), 0u);
    EXPECT_EQ(parseWholeNumber("18446744073709551615", "n", "N"), 18446744073709551615ull);
    const auto message = [](const std::string& text) {
        try {
            parseWholeNumber(text, "--seed", "the seed");
        } catch (const ParameterError& e) {
            EXPECT_EQ(e.parameter(), "--seed");
            return e.message();
        }
        return std::string("accepted");
    };
    for (const char* bad : {"", "-1", "+1", "1e3", "8.5", " 8", "8 ", "0x10", "x"}) {
        EXPECT_EQ(message(bad), std::string("the seed must be a whole number of decimal digits, got '") + bad + "'");
    }
    EXPECT_EQ(message("18446744073709551616"),
              "the seed 18446744073709551616 is beyond the largest, 2^64 - 1 = 18446744073709551615");
}
