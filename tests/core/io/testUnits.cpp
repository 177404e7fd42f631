// SPDX-License-Identifier: GPL-3.0-or-later
// Length units of input files (io/Units): names, conversion factors, errors.
#include "roughContact/Error.hpp"
#include "roughContact/io/Units.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace roughContact;

namespace {
/// The ParameterError that parseLengthUnit(text) throws; fails the test when it throws none.
std::string parseError(const std::string& text)
{
    try {
        const LengthUnit u = parseLengthUnit(text);
        ADD_FAILURE() << "'" << text << "' was accepted as " << toString(u);
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "units");
        return e.what();
    }
    return "";
}
} // namespace

TEST(Units, parsesTheCanonicalNames)
{
    EXPECT_EQ(parseLengthUnit("m"), LengthUnit::m);
    EXPECT_EQ(parseLengthUnit("um"), LengthUnit::um);
    EXPECT_EQ(parseLengthUnit("nm"), LengthUnit::nm);
}

TEST(Units, parsesTheMicroSpellings)
{
    EXPECT_EQ(parseLengthUnit("\xC2\xB5m"), LengthUnit::um); // U+00B5 MICRO SIGN, UTF-8
    EXPECT_EQ(parseLengthUnit("\xCE\xBCm"), LengthUnit::um); // U+03BC GREEK SMALL LETTER MU
    EXPECT_EQ(parseLengthUnit("micron"), LengthUnit::um);
}

TEST(Units, ignoresSurroundingWhitespace)
{
    EXPECT_EQ(parseLengthUnit("  nm"), LengthUnit::nm);
    EXPECT_EQ(parseLengthUnit("um \t\r\n"), LengthUnit::um);
    EXPECT_EQ(parseLengthUnit("\tm "), LengthUnit::m);
}

TEST(Units, rejectsUnknownNamesNamingTheParameterAndTheText)
{
    // Case matters: "M" would be mega in SI, so it must not silently mean metres.
    for (const std::string bad : {"M", "UM", "Nm", "NM", "mm", "cm", "pm", "A", "u m", "m m",
                                  "metre", "", "   ", "1e-6", "\xB5m" /* Latin-1 micro */}) {
        const std::string what = parseError(bad);
        EXPECT_EQ(what.rfind("units: ", 0), 0u) << what;
        EXPECT_NE(what.find("'" + bad + "'"), std::string::npos) << what;
        EXPECT_NE(what.find("use m, um or nm"), std::string::npos) << what;
    }
}

TEST(Units, convertsToMetres)
{
    // Exact: the factors are the decimal literals themselves, rounded once to double.
    EXPECT_EQ(metresPer(LengthUnit::m), 1.0);
    EXPECT_EQ(metresPer(LengthUnit::um), 1e-6);
    EXPECT_EQ(metresPer(LengthUnit::nm), 1e-9);
    // The three are a factor 1000 apart (to rounding of the two literals: 4 ulp).
    EXPECT_DOUBLE_EQ(metresPer(LengthUnit::um) / metresPer(LengthUnit::nm), 1000.0);
}

TEST(Units, canonicalNamesRoundTrip)
{
    EXPECT_EQ(toString(LengthUnit::m), "m");
    EXPECT_EQ(toString(LengthUnit::um), "um");
    EXPECT_EQ(toString(LengthUnit::nm), "nm");
    for (LengthUnit u : {LengthUnit::m, LengthUnit::um, LengthUnit::nm}) {
        EXPECT_EQ(parseLengthUnit(toString(u)), u);
    }
}

TEST(Units, anInvalidEnumValueThrowsRatherThanReturningGarbage)
{
    const auto bad = static_cast<LengthUnit>(42);
    EXPECT_THROW(metresPer(bad), ParameterError);
    EXPECT_THROW(toString(bad), ParameterError);
}

// Numbers with a unit suffix (parseQuantity): SI without one; each unit's factor; a space
// allowed; the unit of another quantity, an unknown one (case matters) or no number refused,
// naming the entry.
TEST(Units, quantitiesWithASuffixAreSI)
{
    using roughContact::Quantity;
    using roughContact::parseQuantity;
    EXPECT_EQ(parseQuantity("1e6", Quantity::pressure, "p"), 1e6);
    EXPECT_EQ(parseQuantity("1MPa", Quantity::pressure, "p"), 1e6);
    EXPECT_EQ(parseQuantity("1 MPa", Quantity::pressure, "p"), 1e6);
    EXPECT_EQ(parseQuantity("200GPa", Quantity::pressure, "p"), 200e9);
    EXPECT_EQ(parseQuantity("400kPa", Quantity::pressure, "p"), 400e3);
    EXPECT_EQ(parseQuantity("0.4e9Pa", Quantity::pressure, "p"), 0.4e9);
    EXPECT_EQ(parseQuantity("0.8um", Quantity::length, "L"), 0.8 * 1e-6);
    EXPECT_EQ(parseQuantity("2.5 \xC2\xB5m", Quantity::length, "L"), 2.5 * 1e-6);
    EXPECT_EQ(parseQuantity("2.5\xCE\xBCm", Quantity::length, "L"), 2.5 * 1e-6);
    EXPECT_EQ(parseQuantity("1mm", Quantity::length, "L"), 1e-3);
    EXPECT_EQ(parseQuantity("5e-4m", Quantity::length, "L"), 5e-4);
    EXPECT_EQ(parseQuantity("20nm", Quantity::length, "L"), 20 * 1e-9);
    for (const char* bad : {"1um", "1mPa", "1Gpa", "MPa", "", "1e6 MPa x", "abcPa"}) {
        try {
            parseQuantity(bad, Quantity::pressure, "--pressures");
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const roughContact::ParameterError& e) {
            EXPECT_EQ(e.parameter(), "--pressures") << e.what();
        }
    }
    try {
        parseQuantity("1um", Quantity::pressure, "--E");
    } catch (const roughContact::ParameterError& e) {
        EXPECT_NE(std::string(e.what()).find("is not a pressure"), std::string::npos) << e.what();
    }
}
