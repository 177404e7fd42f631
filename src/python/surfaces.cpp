// SPDX-License-Identifier: GPL-3.0-or-later
// The module's surfaces: Profile and read_profile, Spectrum, ArealSurface and read_areal, the
// synthesis of an areal surface from a spectrum, SurfaceRoughness and the roughness functions.
#include <pybind11/pybind11.h>

#include "numberCasters.hpp" // first after pybind11.h: see there

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"

#include "roughContact/io/ArealReader.hpp"
#include "roughContact/io/ProfileReader.hpp"
#include "roughContact/io/SpectrumReader.hpp"
#include "roughContact/io/Units.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/ArealSynthesis.hpp"
#include "roughContact/surface/FractalFit.hpp"
#include "roughContact/surface/SpectralMoments.hpp"
#include "roughContact/surface/SpectralResampling.hpp"
#include "roughContact/surface/Profile.hpp"
#include "roughContact/surface/Roughness.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

using namespace roughContact;

namespace roughcontact_py {

void bindSurfaces(py::module_& m)
{
    py::class_<Profile>(m, "Profile", "A measured line profile: heights [m] at a uniform spacing [m].")
        .def(py::init([](const py::handle& heights, double spacing, const std::string& source) {
                 return Profile(toVector(heights, "heights"), spacing, source);
             }),
             py::arg("heights"), py::arg("spacing"), py::arg("source") = "",
             "Profile(heights, spacing, source=''): heights [m] (1-D array, at least 8 finite values) at the "
             "sample spacing [m] (> 0); source names the data in error messages.")
        .def_property_readonly("heights", [](const Profile& p) { return toArray(p.heights()); },
                               "The heights [m] as read (not detrended), a 1-D float64 array (a copy).")
        .def_property_readonly("spacing", &Profile::spacing, "The sample spacing dx [m].")
        .def_property_readonly("length", &Profile::length, "The scan length L = N dx [m].")
        .def_property_readonly("source", &Profile::source, "Where the data came from (a file path).")
        .def("__len__", &Profile::size, "The number of samples.")
        .def("detrended", &Profile::detrended, "The profile less its least-squares line (mean and tilt).")
        .def("subsampled", &Profile::subsampled, py::arg("stride"),
             "Every stride-th sample (spacing stride*dx).")
        .def("rms", &Profile::rms, "Root-mean-square height about zero [m] (detrend first for Rq).")
        .def("__repr__", [](const Profile& p) {
            return "<roughcontact.Profile " + std::to_string(p.size()) + " samples, dx = " +
                   number(p.spacing()) + " m>";
        });

    m.def(
        "read_profile",
        [](const std::string& path, std::optional<std::string> units, std::optional<double> spacing) {
            ProfileReadOptions o;
            o.units = unitsOf(units);
            o.spacing = spacing;
            return readProfile(path, o);
        },
        py::arg("path"), py::arg("units") = py::none(), py::arg("spacing") = py::none(),
        "read_profile(path, units=None, spacing=None) -> Profile\n\n"
        "Reads a profile file as multiscaleContact --profile does: columns 'x z', or 'z' alone with "
        "spacing; comma, semicolon, tab or space separated; '#' comments and one header line allowed; a "
        "Dektak CSV export as it is (its header names the units). units: 'm', 'um' or 'nm' for both "
        "columns (default m; a Dektak export's own header otherwise); spacing: the sample spacing of a "
        "one-column file, in units. Heights are returned in metres, not detrended. InputError "
        "('FILE:LINE: message') on bad content or a missing file, ParameterError on a bad option.");

    py::class_<Spectrum>(m, "Spectrum",
                         "A surface as its spectrum: levels f_i [1/m] with single-sided amplitudes beta_i [m] "
                         "for a scan of length L [m] (A_n = L^2).")
        .def(py::init([](const py::handle& f, const py::handle& beta, double length, const std::string& source) {
                 return Spectrum(toVector(f, "frequencies"), toVector(beta, "amplitudes"), length, source);
             }),
             py::arg("frequencies"), py::arg("amplitudes"), py::arg("length"), py::arg("source") = "",
             "Spectrum(frequencies, amplitudes, length, source=''): levels [1/m] (positive, strictly "
             "increasing), amplitudes [m] (>= 0), scan length [m].")
        .def_static("from_profile", &Spectrum::fromProfile, py::arg("profile"),
                    "The FFT of a profile after removing its mean and tilt: f_k = k/L, beta_k = 2|Z_k|/N "
                    "(|Z_{N/2}|/N at Nyquist).")
        .def_static("power_law", &Spectrum::powerLaw, py::arg("bm"), py::arg("m"), py::arg("fmin"),
                    py::arg("fmax"), py::arg("length") = 0.0,
                    "Power law beta = bm f^-m [m] at f_i = i/L within [fmin, fmax] [1/m]; length [m] "
                    "defaults (0) to 1/fmin (multiscaleContact --power-law).")
        .def_static("fractal", &Spectrum::fractal, py::arg("D"), py::arg("G"), py::arg("fmin"), py::arg("fmax"),
                    py::arg("length") = 0.0,
                    "Weierstrass-Mandelbrot (Majumdar-Bhushan) spectrum of fractal dimension D and roughness "
                    "G [m] at f_i = i/L within [fmin, fmax] [1/m]; length [m] defaults (0) to 1/fmin.")
        .def_static(
            "read",
            [](const std::string& path, std::optional<double> length) { return readSpectrum(path, length); },
            py::arg("path"), py::arg("length") = py::none(),
            "Reads a spectrum table (multiscaleContact --spectrum): columns frequency [1/m], amplitude "
            "[m]; length [m] defaults to 1/lowest frequency.")
        .def_static("combine", &Spectrum::combine, py::arg("a"), py::arg("b"),
                    "The equivalent surface of two rough surfaces in contact (powers add level by level).")
        .def_property_readonly("frequencies", [](const Spectrum& s) { return toArray(s.frequencies()); },
                               "The levels f_i [1/m], a 1-D float64 array.")
        .def_property_readonly("amplitudes", [](const Spectrum& s) { return toArray(s.amplitudes()); },
                               "The amplitudes beta_i [m], a 1-D float64 array.")
        .def_property_readonly("length", &Spectrum::length, "The scan length L [m].")
        .def_property_readonly("nominal_area", &Spectrum::nominalArea, "A_n = L^2 [m^2].")
        .def_property_readonly("source", &Spectrum::source, "Where the spectrum came from.")
        .def("__len__", &Spectrum::size, "The number of levels.")
        .def("variance", &Spectrum::variance, "Sum of beta_i^2/2 [m^2]: the variance of the sinusoids.")
        .def("profile_variance", &Spectrum::profileVariance,
             "The variance [m^2] of the profile the spectrum came from (Parseval; the Nyquist level counted "
             "in full).")
        .def("truncated", &Spectrum::truncated, py::arg("fmax"), "The levels with f <= fmax [1/m] only.")
        .def("on_period", &Spectrum::onPeriod, py::arg("multiple"),
             "The same line-scan spectrum on a period of `multiple` (1 to 64) times its length "
             "(Spectrum::onPeriod): its density sampled at the levels j/(multiple L).")
        .def("__repr__", [](const Spectrum& s) {
            return "<roughcontact.Spectrum " + std::to_string(s.size()) + " levels, L = " +
                   number(s.length()) + " m>";
        });

    py::class_<ArealSurface>(m, "ArealSurface",
                             "A height map: heights [m] on nx points along x by ny along y, spacings dx, dy [m].")
        .def(py::init([](const py::handle& heights, double dx, std::optional<double> dy, const std::string& source) {
                 const Array a = numbers(heights, "heights");
                 if (a.ndim() != 2) {
                     throw py::type_error("heights: expected a 2-D array of numbers, shape (ny, nx)");
                 }
                 const auto ny = static_cast<std::size_t>(a.shape(0));
                 const auto nx = static_cast<std::size_t>(a.shape(1));
                 return ArealSurface(std::vector<double>(a.data(), a.data() + a.size()), nx, ny, dx, dy.value_or(dx),
                                     source);
             }),
             py::arg("heights"), py::arg("dx"), py::arg("dy") = py::none(), py::arg("source") = "",
             "ArealSurface(heights, dx, dy=None, source=''): heights [m] as a 2-D array of shape (ny, nx) "
             "(heights[iy, ix]: rows run along x), spacings dx, dy [m] (dy defaults to dx).")
        .def_property_readonly(
            "heights",
            [](const ArealSurface& s) {
                Array out({static_cast<py::ssize_t>(s.ny()), static_cast<py::ssize_t>(s.nx())});
                std::copy(s.heights().begin(), s.heights().end(), out.mutable_data());
                return out;
            },
            "The heights [m], a float64 array of shape (ny, nx) (a copy): heights[iy, ix].")
        .def_property_readonly("nx", &ArealSurface::nx, "Points along x.")
        .def_property_readonly("ny", &ArealSurface::ny, "Points along y.")
        .def_property_readonly("dx", &ArealSurface::dx, "Spacing along x [m].")
        .def_property_readonly("dy", &ArealSurface::dy, "Spacing along y [m].")
        .def_property_readonly("length_x", &ArealSurface::lengthX, "L_x = nx dx [m].")
        .def_property_readonly("length_y", &ArealSurface::lengthY, "L_y = ny dy [m].")
        .def_property_readonly("nominal_area", &ArealSurface::nominalArea, "A_n = L_x L_y [m^2].")
        .def_property_readonly("source", &ArealSurface::source, "Where the data came from.")
        .def(
            "detrended",
            [](const ArealSurface& a, const std::string& how) { return a.detrended(parseDetrend(how, "how")); },
            py::arg("how") = "plane",
            "The surface less its least-squares plane (how='plane'), its mean (how='mean') or nothing "
            "(how='none').")
        .def("rms", &ArealSurface::rms, "Root-mean-square height about zero [m].")
        .def("row", &ArealSurface::row, py::arg("iy"), "Row iy (along x) as a Profile.")
        .def("column", &ArealSurface::column, py::arg("ix"), "Column ix (along y) as a Profile.")
        .def(
            "line_scan_spectrum",
            [](const ArealSurface& s, const std::optional<std::string>& direction) {
                return lineScanSpectrum(s, direction ? parseScanDirection(*direction) : defaultScanDirection);
            },
            py::arg("direction") = py::none(),
            "The averaged spectrum of the line scans 'x' (rows), 'y' (columns) or 'both' (None: both), each detrended "
            "(multiscaleContact --areal --direction); detrend the surface first as the CLI does.")
        .def("__repr__", [](const ArealSurface& s) {
            return "<roughcontact.ArealSurface " + std::to_string(s.nx()) + " x " + std::to_string(s.ny()) + ">";
        });

    m.def(
        "read_areal",
        [](const std::string& path, std::optional<std::string> units, std::optional<double> dx,
           std::optional<double> dy, bool fillInvalid) {
            ArealReadOptions o;
            o.units = unitsOf(units);
            o.dx = dx;
            o.dy = dy;
            o.fillInvalid = fillInvalid;
            return readAreal(path, o);
        },
        py::arg("path"), py::arg("units") = py::none(), py::arg("dx") = py::none(), py::arg("dy") = py::none(),
        py::arg("fill_invalid") = false,
        "read_areal(path, units=None, dx=None, dy=None, fill_invalid=False) -> ArealSurface\n\n"
        "An X3P file (.x3p: metres, its own spacings; fill_invalid fills its invalid points) or a text "
        "matrix of heights (one row along x per line; dx required, dy defaults to dx, both in units: "
        "'m' default, 'um', 'nm'), as multiscaleContact --areal reads it. Not detrended.");

    m.def(
        "synthesize_isotropic",
        [](const Spectrum& spectrum, std::size_t n, std::uint64_t seed) { return synthesizeIsotropic(spectrum, n, seed); },
        py::arg("spectrum"), py::arg("n"), py::arg("seed") = 1,
        "synthesize_isotropic(spectrum, n, seed=1) -> ArealSurface\n\n"
        "An n x n periodic isotropic Gaussian surface on L x L (L the spectrum's length, spacing L/n) whose "
        "line scans have the spectrum's power; random phases from seed (multiscaleContact --synthesize "
        "N,SEED). n even, 8 to 4096.");

    m.def(
        "synthesize_stretched",
        [](const Spectrum& across, double stretch, std::size_t n, std::uint64_t seed) {
            return synthesizeStretched(across, stretch, n, seed);
        },
        py::arg("across"), py::arg("stretch"), py::arg("n"), py::arg("seed") = 1,
        "synthesize_stretched(across, stretch, n, seed=1) -> ArealSurface\n\n"
        "A finish with a lay along y: synthesize_isotropic(across, n, seed) with its y spacing stretch times "
        "its x spacing, so its features are stretch times longer along y; the surface the check and "
        "boundaryElement's synthesize solve for profiles across and along a lay (stretch: their rms "
        "slopes' ratio).");

    m.def(
        "resample_periodic",
        [](const ArealSurface& surface, std::size_t n, std::optional<double> levels) {
            return resampledPeriodic(surface, n, levels);
        },
        py::arg("surface"), py::arg("n"), py::arg("levels") = py::none(),
        "resample_periodic(surface, n, levels=None) -> ArealSurface\n\n"
        "One period of a square periodic surface (as synthesize_isotropic makes) as the n x n samples of its "
        "Fourier series: the same surface on a finer or coarser grid, without the wavelengths shorter than "
        "L/levels when levels is given (multiscaleContact --resample N,K). n even, 8 to 4096.");

    py::class_<SurfaceRoughness>(m, "SurfaceRoughness",
                                 "The rms height sigma [m] and mean absolute slope m of a surface (the "
                                 "correlations' inputs).")
        .def(py::init([](double sigma, double slope) { return SurfaceRoughness{sigma, slope}; }), py::arg("sigma"),
             py::arg("mean_absolute_slope"), "SurfaceRoughness(sigma [m], mean_absolute_slope).")
        .def_readwrite("sigma", &SurfaceRoughness::sigma, "rms height about the mean plane [m]")
        .def_readwrite("mean_absolute_slope", &SurfaceRoughness::meanAbsoluteSlope, "m = <|dz/dx|>")
        .def("__repr__", [](const SurfaceRoughness& r) {
            return "<roughcontact.SurfaceRoughness sigma = " + number(r.sigma) +
                   " m, m = " + number(r.meanAbsoluteSlope) + ">";
        });
    py::class_<HeightSkewness>(m, "HeightSkewness",
                               "A surface's heights' skewness and the spread (standard deviation) Gaussian heights "
                               "of the same autocorrelation and size give it by chance.")
        .def(py::init([](double skewness, double spread) { return HeightSkewness{skewness, spread}; }),
             py::arg("skewness"), py::arg("spread"), "HeightSkewness(skewness, spread).")
        .def_readonly("skewness", &HeightSkewness::skewness, "mu3/sigma^3 of the detrended heights")
        .def_readonly("spread", &HeightSkewness::spread,
                      "what chance gives Gaussian heights: sqrt((6/N) sum_k rho(k)^3)")
        .def("__repr__", [](const HeightSkewness& h) {
            return "<roughcontact.HeightSkewness skewness = " + number(h.skewness) + " +- " + number(h.spread) + ">";
        });
    m.def("profile_roughness", &profileRoughness, py::arg("profile"),
          "sigma [m] and the mean absolute slope of a profile after removing its mean and tilt.");
    m.def(
        "areal_roughness",
        [](const ArealSurface& s, const std::optional<std::string>& direction) {
            return arealRoughness(s, direction ? parseScanDirection(*direction) : defaultScanDirection);
        },
        py::arg("surface"), py::arg("direction") = py::none(),
        "sigma [m] and the mean absolute slope of an areal surface along 'x', 'y' or 'both' (None: both).");
    m.def("spectrum_roughness", &spectrumRoughness, py::arg("spectrum"),
          "sigma [m] and the mean absolute slope of a spectrum (Gaussian slopes assumed).");
    m.def("combined_roughness", &combined, py::arg("a"), py::arg("b"),
          "The equivalent roughness of two surfaces: sigma and m added in quadrature.");
    m.def("shrunk_skewness", &shrunkSkewness, py::arg("skewness"),
          "A HeightSkewness with chance's share taken out, s (1 - spread^2/s^2) where |s| > spread, else "
          "0: the skewness the conductance law fittedElastoPlastic takes.");
    m.def("spectral_bandwidth_ratio", &spectralBandwidthRatio, py::arg("spectrum"),
          "W = m1/sqrt(m0 m2) of a line-scan spectrum (0 < W <= 1, 1 for a single level): the "
          "conductance law fittedElastoPlastic's plastic spots are spaced by W m/sigma, and beyond "
          "p/(E' h') = 0.1 its elastic growth's rate falls with W.");
    m.def(
        "areal_rms_gradient", [](const Spectrum& s) { return arealRmsGradient(spectralMoments(s)); },
        py::arg("spectrum"),
        "h' = sqrt(2 m2): the areal rms gradient of the isotropic surface whose line scans have this spectrum "
        "(m2 = sum (2 pi f)^2 beta^2/2, SpectralMoments.hpp): the gradient p/(E' h') is taken with.");
    m.def("first_level_share", &firstLevelShare, py::arg("spectrum"),
          "s1 = beta_1^2 / sum beta_k^2: the first (longest-wave) level's share of a line-scan spectrum's "
          "height variance (0 <= s1 <= 1: 0 where the first amplitude is 0, 1 for a single level): the conductance law fittedElastoPlastic's "
          "light-load exponent follows it.");
    m.def("fine_hurst_exponent", &fineHurstExponent, py::arg("spectrum"),
          "H_f: the Hurst exponent of a line-scan spectrum's finest octave, -(1 + s)/2 with s the slope of "
          "ln PSD against ln f over the levels from f_max/2 to f_max (None with fewer than 3 levels there): "
          "the conductance law fittedElastoPlastic's unloading branch follows it.");
}

} // namespace roughcontact_py
