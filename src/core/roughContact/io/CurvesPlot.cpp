// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/io/CurvesPlot.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/io/Files.hpp"
#include "roughContact/io/Numbers.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace roughContact {

namespace {

const std::string pngSignature("\x89PNG\r\n\x1a\n", 8);

std::string cell(double v)
{
    return std::isfinite(v) ? formatNumber(v, 10) : std::string("NaN");
}

/// A POSIX shell single-quoted word.
std::string shellQuoted(const std::string& s)
{
    std::string out = "'";
    for (char c : s) {
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

const char* const gnuplotMissing = "drawing the picture needs gnuplot, which is not installed (Debian: apt-get "
                                  "install gnuplot-nox)";

/// A gnuplot single-quoted string: ' doubled.
std::string quoted(const std::string& s)
{
    std::string out = "'";
    for (char c : s) {
        out += c == '\'' ? std::string("''") : std::string(1, c);
    }
    return out + "'";
}

} // namespace

bool isPngStart(const std::string& start)
{
    return start.rfind(pngSignature, 0) == 0;
}

void requireGnuplot(const std::string& parameter)
{
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        throw ParameterError(parameter, gnuplotMissing);
    }
}

std::string curvesPlotScript(const InterfaceCurves& curves, const PlotExtras& extras, const std::string& pngPath)
{
    const double ks = extras.conductivity.value_or(1.0);
    const bool asH = extras.conductivity.has_value();
    std::ostringstream os;
    os << "set terminal pngcairo size 1000,800 noenhanced font ',10'\n"
       << "set output " << quoted(pngPath) << "\n"
       << "set datafile missing 'NaN'\n"
       << "set logscale xy\nset autoscale xfix\nset grid\nset key top left opaque box\n"
       << "set xlabel 'nominal pressure P [Pa]'\n"
       << "set ylabel " << quoted(asH ? "h [W/(m^2 K)]" : "h_c/k_s [1/m]") << "\n"
       << "set title " << quoted(extras.title) << "\n";
    os << "$laws << EOD\n";
    for (std::size_t i = 0; i < curves.pressures.size(); ++i) {
        os << cell(curves.pressures[i]);
        for (const LawCurve& l : curves.laws) {
            if (l.unavailable.empty()) {
                os << ' ' << cell(ks * l.hPerK[i]);
            }
        }
        os << ' ' << cell(ks * curves.exactLow[i]) << ' ' << cell(ks * curves.exactHigh[i]);
        if (asH && !extras.gas.empty()) {
            os << ' ' << cell(extras.gas[i]) << ' ' << cell(extras.radiation[i]);
        }
        os << '\n';
    }
    os << "EOD\n";
    if (!extras.check.pressures.empty()) {
        os << "$check << EOD\n";
        for (std::size_t i = 0; i < extras.check.pressures.size(); ++i) {
            const double lo = extras.check.exactLow[i], hi = extras.check.exactHigh[i];
            os << cell(extras.check.pressures[i]) << ' ' << cell(ks * std::sqrt(lo * hi)) << ' ' << cell(ks * lo)
               << ' ' << cell(ks * hi) << '\n';
        }
        os << "EOD\n";
    }
    std::size_t column = 2;
    std::vector<std::string> parts;
    std::size_t bandLow = column;
    for (const LawCurve& l : curves.laws) {
        bandLow += l.unavailable.empty() ? 1 : 0;
    }
    parts.push_back("$laws using 1:" + std::to_string(bandLow) + ":" + std::to_string(bandLow + 1) +
                    " with filledcurves fillcolor rgb '#d8e6f5' title " +
                    quoted("exact, by the measured band of " + curves.chosenLaw));
    for (const LawCurve& l : curves.laws) {
        if (!l.unavailable.empty()) {
            continue;
        }
        const bool chosen = l.name == curves.chosenLaw;
        parts.push_back("$laws using 1:" + std::to_string(column++) + " with lines " +
                        (chosen ? "linewidth 3 linecolor rgb '#1f4e9c'" : "linewidth 1.2") + " title " +
                        quoted(chosen ? l.name + " (chosen)" : l.name));
    }
    if (asH && !extras.gas.empty()) {
        parts.push_back("$laws using 1:" + std::to_string(bandLow + 2) +
                        " with lines dashtype 2 linecolor rgb '#2a9d3a' title 'h_gas (not validated)'");
        parts.push_back("$laws using 1:" + std::to_string(bandLow + 3) +
                        " with lines dashtype 3 linecolor rgb '#c77c02' title 'h_rad (not validated)'");
    }
    if (!extras.check.pressures.empty()) {
        parts.push_back("$check using 1:2:3:4 with yerrorbars pointtype 7 pointsize 1.3 linecolor rgb '#c0392b' "
                        "title 'exact, as the check implies it'");
    }
    os << "plot ";
    for (std::size_t i = 0; i < parts.size(); ++i) {
        os << (i ? ", \\\n     " : "") << parts[i];
    }
    os << "\n";
    return os.str();
}

void writeCurvesPlot(const InterfaceCurves& curves, const PlotExtras& extras, const std::string& path,
                     const std::string& parameter)
{
    requireReplaceable(path, parameter, "PNG picture", isPngStart);
    std::error_code ec;
    std::string pattern = (std::filesystem::temp_directory_path(ec) / "roughContactPlot.XXXXXX").string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (ec || !::mkdtemp(buffer.data())) {
        throw ParameterError(parameter, "cannot make a temporary folder for gnuplot's picture");
    }
    const std::string folder(buffer.data());
    const std::string png = folder + "/picture.png";
    const std::string scriptPath = folder + "/picture.gp";
    int status = -1;
    {
        std::ofstream out(scriptPath, std::ios::binary);
        out << curvesPlotScript(curves, extras, png);
        if (out.flush()) {
            // A file, not a pipe: a missing gnuplot is an exit status of 127, not a SIGPIPE.
            // gnuplot's messages to stderr: stdout is the caller's (the CLI's CSV).
            status = std::system(("gnuplot " + shellQuoted(scriptPath) + " 1>&2").c_str());
        }
    }
    std::string bytes;
    try {
        if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            const bool missing = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 127;
            throw ParameterError(parameter, missing ? std::string(gnuplotMissing)
                                                    : std::string("gnuplot failed to draw the picture (above)"));
        }
        bytes = readWholeFile(png, std::uint64_t(64) << 20, "PNG picture");
        if (!isPngStart(bytes)) {
            throw ParameterError(parameter, "gnuplot wrote no PNG picture");
        }
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove_all(folder, ignored);
        throw;
    }
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
    replaceFile(path, bytes, parameter, "PNG picture", isPngStart);
}

} // namespace roughContact
