// SPDX-License-Identifier: GPL-3.0-or-later
// What the fuzz targets (tests/fuzz/fuzz*.cpp) and the corpus replay
// (tests/core/acceptance/testFuzzCorpus.cpp) check of one input: the reader either returns sound
// data or throws InputError/ParameterError with a short, printable message. Anything else is a
// bug, described by the returned text.
//
// An input is the file's content after a few option bytes, so that one input also chooses the
// reader's options:
//  - profile:  byte 1 the units option ('m', 'u', 'n'; anything else: unset), byte 2 the
//              spacing option ('0'-'9': spacingChoices[digit]; anything else: unset);
//  - spectrum: byte 1 the length option ('0'-'9': lengthChoices[digit]; anything else: unset);
//  - table:    byte 1 the options: maxColumns = 1 + byte % 4, and the section marker
//              "Scan Data" when byte & 4;
//  - matrix:   byte 1 the units ('u' um, 'n' nm; anything else: m), byte 2 the dx option and
//              byte 3 the dy option ('0'-'9': choice(digit); anything else: unset);
//  - x3p:      byte 1 the fillInvalid option ('f': set); the rest is the X3P (zip) file.
//  - boundaryElementTable: no option byte; the text of a cache file of the table of
//              boundaryElementTableSpec(), in which "@KEY@" stands for that table's key and a
//              last line "# sha256 @DIGEST@" for the digest of the text above it (so that the
//              fuzzer, and seeds made on another machine, reach the numbers past the key and
//              the digest).
#pragma once

#include "roughContact/Error.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/ContactInterface.hpp"
#include "roughContact/io/MatrixReader.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/TableReader.hpp"
#include "roughContact/io/X3pReader.hpp"
#include "roughContact/surface/ArealSurface.hpp"

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

namespace roughContactFuzz {

/// The file name the readers are given (errors name it).
inline const std::string inputName = "fuzz-input";

/// The longest error message accepted, file name included: a message echoes at most a few
/// short fields (io/TableReader printable: about 40 characters each, 80 for a header).
constexpr std::size_t longestMessage = 400;

/// Spacing and length options a digit chooses: ordinary, huge, tiny, zero, negative, NaN, inf.
inline double choice(char digit)
{
    const double choices[10] = {1e-7,
                                1.0,
                                2.5e-6,
                                1e300,
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::denorm_min(),
                                0.0,
                                -1.0,
                                std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::infinity()};
    return choices[digit - '0'];
}

inline std::optional<double> digitChoice(char c)
{
    return c >= '0' && c <= '9' ? std::optional<double>(choice(c)) : std::nullopt;
}

/// "" when an expected error's text is sound: short, printable ASCII, and for an InputError
/// naming the input. An InputError's message() is checked, not what(): what() is a C string and
/// ends at the first NUL byte of an echoed field.
inline std::string checkMessage(const std::exception& e)
{
    const auto* input = dynamic_cast<const roughContact::InputError*>(&e);
    if (input && input->file() != inputName) {
        return "InputError not naming the file: " + input->file();
    }
    const std::string what = input ? input->message() : std::string(e.what());
    if (what.size() > longestMessage) {
        return "error message of " + std::to_string(what.size()) +
               " characters: " + roughContact::detail::printable(what, 200);
    }
    for (char c : what) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u > 0x7E) {
            return "error message with a non-printable byte: " + roughContact::detail::printable(what, 400);
        }
    }
    return "";
}

inline bool finite(double v)
{
    return std::isfinite(v);
}

/// Runs read(in) on the content and checks it with check(result); "" when all is well.
template <class Read, class Check> std::string checkReader(const std::string& content, Read read, Check check)
{
    std::istringstream in(content);
    try {
        return check(read(in));
    } catch (const roughContact::InputError& e) {
        return checkMessage(e);
    } catch (const roughContact::ParameterError& e) {
        return checkMessage(e);
    } catch (const std::exception& e) {
        return std::string("unexpected exception: ") + e.what();
    }
}

inline std::string checkProfileInput(const std::string& input)
{
    roughContact::ProfileReadOptions options;
    const char u = input.size() > 0 ? input[0] : '-';
    if (u == 'm' || u == 'u' || u == 'n') {
        options.units = u == 'm'   ? roughContact::LengthUnit::m
                        : u == 'u' ? roughContact::LengthUnit::um
                                   : roughContact::LengthUnit::nm;
    }
    options.spacing = digitChoice(input.size() > 1 ? input[1] : '-');
    const std::string content = input.size() > 2 ? input.substr(2) : std::string();
    return checkReader(
        content, [&](std::istream& in) { return roughContact::readProfile(in, inputName, options); },
        [](const roughContact::Profile& p) -> std::string {
            if (p.size() < roughContact::Profile::minimumSize) {
                return "profile of " + std::to_string(p.size()) + " points";
            }
            if (!finite(p.spacing()) || !(p.spacing() > 0.0) || !finite(p.length())) {
                std::ostringstream os;
                os.precision(17);
                os << "profile with spacing " << p.spacing() << " and length " << p.length();
                return os.str();
            }
            for (double z : p.heights()) {
                if (!finite(z)) {
                    return "profile with a non-finite height";
                }
            }
            return "";
        });
}

inline std::string checkSpectrumInput(const std::string& input)
{
    const std::optional<double> length = digitChoice(input.empty() ? '-' : input[0]);
    const std::string content = input.size() > 1 ? input.substr(1) : std::string();
    return checkReader(
        content, [&](std::istream& in) { return roughContact::readSpectrum(in, inputName, length); },
        [](const roughContact::Spectrum& s) -> std::string {
            if (s.size() == 0 || s.frequencies().size() != s.amplitudes().size()) {
                return "spectrum without levels or with unequal columns";
            }
            if (!finite(s.length()) || !(s.length() > 0.0)) {
                return "spectrum with a non-finite or non-positive length";
            }
            for (std::size_t i = 0; i < s.size(); ++i) {
                if (!finite(s.frequency(i)) || !finite(s.amplitude(i))) {
                    return "spectrum with a non-finite level";
                }
            }
            return "";
        });
}

inline std::string checkTableInput(const std::string& input)
{
    const auto byte = static_cast<unsigned char>(input.empty() ? 0 : input[0]);
    roughContact::detail::TableReadOptions options;
    options.maxColumns = 1 + byte % 4;
    if (byte & 4) {
        options.sectionMarker = "Scan Data";
    }
    const std::string content = input.size() > 1 ? input.substr(1) : std::string();
    return checkReader(
        content, [&](std::istream& in) { return roughContact::detail::readTable(in, inputName, options); },
        [&](const roughContact::detail::Table& t) -> std::string {
            if (t.rows.empty() != (t.columns == 0) || t.columns > options.maxColumns) {
                return "table with " + std::to_string(t.columns) + " columns";
            }
            long previous = t.headerLine;
            for (const roughContact::detail::TableRow& row : t.rows) {
                if (row.values.size() != t.columns || !(row.line > previous)) {
                    return "row on line " + std::to_string(row.line) + " out of order or of a wrong size";
                }
                previous = row.line;
                for (double v : row.values) {
                    if (!finite(v)) {
                        return "row on line " + std::to_string(row.line) + " with a non-finite value";
                    }
                }
            }
            return "";
        });
}

/// "" when an areal surface is sound: at least 8 x 8 points, as many heights, finite positive
/// spacings and lengths, finite heights.
inline std::string checkArealSurface(const roughContact::ArealSurface& a)
{
    if (a.nx() < roughContact::ArealSurface::minimumSize ||
        a.ny() < roughContact::ArealSurface::minimumSize || a.heights().size() != a.nx() * a.ny()) {
        return "areal surface of " + std::to_string(a.nx()) + " x " + std::to_string(a.ny()) +
               " points and " + std::to_string(a.heights().size()) + " heights";
    }
    if (!finite(a.dx()) || !(a.dx() > 0.0) || !finite(a.dy()) || !(a.dy() > 0.0) || !finite(a.lengthX()) ||
        !finite(a.lengthY())) {
        return "areal surface with a bad spacing or length";
    }
    for (double z : a.heights()) {
        if (!finite(z)) {
            return "areal surface with a non-finite height";
        }
    }
    return "";
}

inline std::string checkMatrixInput(const std::string& input)
{
    roughContact::MatrixReadOptions options;
    const char u = input.size() > 0 ? input[0] : '-';
    options.units = u == 'u'   ? roughContact::LengthUnit::um
                    : u == 'n' ? roughContact::LengthUnit::nm
                               : roughContact::LengthUnit::m;
    options.dx = digitChoice(input.size() > 1 ? input[1] : '-');
    options.dy = digitChoice(input.size() > 2 ? input[2] : '-');
    const std::string content = input.size() > 3 ? input.substr(3) : std::string();
    return checkReader(
        content, [&](std::istream& in) { return roughContact::readMatrix(in, inputName, options); },
        checkArealSurface);
}

inline std::string checkX3pInput(const std::string& input)
{
    roughContact::X3pReadOptions options;
    options.fillInvalid = !input.empty() && input[0] == 'f';
    const std::string content = input.size() > 1 ? input.substr(1) : std::string();
    return checkReader(
        content, [&](std::istream&) { return roughContact::readX3pBytes(content, inputName, options); },
        [](const roughContact::ArealSurface& s) { return checkArealSurface(s); });
}

/// The table whose cache files boundaryElementTable inputs are: a power law synthesized on a
/// 32 x 32 periodic grid, steel on steel, 17 loads from 1e5 to 1e9 Pa.
inline roughContact::InterfaceSpec boundaryElementTableSpec()
{
    roughContact::InterfaceSpec spec;
    roughContact::SurfaceSpec s;
    s.kind = roughContact::SurfaceSpec::Kind::powerLaw;
    s.parameters = {2.56e-4, 0.8, 1e3, 16e3};
    s.length = 1e-3;
    spec.surfaces = {s};
    spec.side1 = roughContact::Material{200e9, 0.3, 0.4e9};
    spec.side2 = spec.side1;
    spec.model = "boundaryElement";
    spec.synthesize = 32;
    spec.minPressure = 1e5;
    spec.maxPressure = 1e9;
    spec.bemPointsPerDecade = 4;
    return spec;
}

/// The table of boundaryElementTableSpec() (built once: it synthesizes the surface).
inline const roughContact::BoundaryElementTable& boundaryElementTable()
{
    static const roughContact::BoundaryElementTable table(boundaryElementTableSpec());
    return table;
}

/// A boundaryElementTable input with "@KEY@" and a last line "# sha256 @DIGEST@" replaced by the
/// table's key and the digest of the text above (the seeds of tests/fuzz/corpus/
/// boundaryElementTable are files the table wrote, with those two stood in for).
inline std::string boundaryElementTableText(const std::string& input)
{
    const roughContact::BoundaryElementTable& table = boundaryElementTable();
    std::string text = input;
    for (std::size_t at = text.find("@KEY@"); at != std::string::npos; at = text.find("@KEY@", at)) {
        text.replace(at, 5, table.key());
    }
    const std::string digestLine = "# sha256 @DIGEST@\n";
    if (text.size() >= digestLine.size() &&
        text.compare(text.size() - digestLine.size(), digestLine.size(), digestLine) == 0) {
        const std::string above = text.substr(0, text.size() - digestLine.size());
        text = above + "# sha256 " + roughContact::BoundaryElementTable::digest(above) + "\n";
    }
    return text;
}

/// The cache reader (BoundaryElementTable::parse) never throws, and either finds a table whose
/// points are sound (increasing pressures of the table's loads, areas in (0, 1], positive finite
/// conductances, finite separations >= 0) or says why not in a short printable reason.
inline std::string checkBoundaryElementTableInput(const std::string& input)
{
    const roughContact::BoundaryElementTable& table = boundaryElementTable();
    roughContact::BoundaryElementTableRead r;
    try {
        r = table.parse(boundaryElementTableText(input));
    } catch (const std::exception& e) {
        return std::string("parse threw: ") + e.what();
    }
    using Status = roughContact::BoundaryElementTableRead::Status;
    if (r.status != Status::ok) {
        if (r.points || r.reason.empty() || r.status == Status::missing) {
            return "a refusal without its reason, or with points";
        }
        const roughContact::ParameterError e("cache", r.reason);
        return checkMessage(e);
    }
    if (!r.points) {
        return "ok without points";
    }
    const roughContact::BoundaryElementTablePoints& p = *r.points;
    const std::size_t n = p.pressures.size();
    if (n < 2 || n > table.pressures().size() || p.areaFractions.size() != n ||
        p.conductancesPerConductivity.size() != n || p.separations.size() != n) {
        return "a table of " + std::to_string(n) + " points with columns of other sizes";
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (p.pressures[k] != table.pressures()[k] || !(p.areaFractions[k] > 0.0 && p.areaFractions[k] <= 1.0) ||
            !(p.conductancesPerConductivity[k] > 0.0) || !finite(p.conductancesPerConductivity[k]) ||
            !(p.separations[k] >= 0.0) || !finite(p.separations[k])) {
            return "point " + std::to_string(k + 1) + " is not sound";
        }
    }
    return "";
}

} // namespace roughContactFuzz

/// The two entry points of a libFuzzer target that runs CHECK (one of the check*Input functions
/// above) on each input, with floating-point traps on as OpenFOAM runs the readers (overflow,
/// invalid operations and division by zero are a crash here too); any bug aborts, naming NAME.
#define ROUGHCONTACT_FUZZ_TARGET(NAME, CHECK)                                                              \
    extern "C" int LLVMFuzzerInitialize(int*, char***)                                                     \
    {                                                                                                      \
        feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);                                            \
        return 0;                                                                                          \
    }                                                                                                      \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)                      \
    {                                                                                                      \
        const std::string bug = (CHECK)(std::string(reinterpret_cast<const char*>(data), size));           \
        if (!bug.empty()) {                                                                                \
            std::fprintf(stderr, "%s: %s\n", NAME, bug.c_str());                                           \
            std::abort();                                                                                  \
        }                                                                                                  \
        return 0;                                                                                          \
    }
