// SPDX-License-Identifier: GPL-3.0-or-later
// The surface compliance of an elastic half-space on a grid: the normal displacement u that a
// pressure p causes, u = K p, evaluated with FFTs (FFTW, plans made once and reused).
#pragma once

#include "roughContact/bem/GridMemory.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace roughContact {

/// How HalfSpaceOperator plans its FFTs. Empty (the default): blocked transforms, the 2-D
/// transform done by the core as FFTW's 1-D transforms of the rows and then of the columns, 8
/// columns at a time through a small buffer (the multiplier applied there), each 1-D plan
/// chosen with FFTW_ESTIMATE (no timing runs). Every run gets the same answer bit for bit, for
/// any number of threads (a processor with other SIMD instructions may get other codelets from
/// FFTW: answers then agree to round-off). A cold solve on one core is 1.12-1.16 times faster
/// at 1024^2 and 1.5 times at 2048^2 than with FFTW's own estimated 2-D plan (docs/benchmarks.md).
/// A file: FFTW_MEASURE 2-D plans (timed once per grid size and thread count), kept in that file
/// as FFTW's wisdom. The planning of a grid holds a lock on the file's folder (one process at a
/// time): the file read in, the plans made (found there, or timed), the file rewritten when it
/// gained a plan (io/Files.hpp's rules). So every run sharing the file, at once or one after
/// another, plans a grid of a size and thread count as the first did, and gets the same answer
/// bit for bit (a run without the file, or on another machine, may choose other plans: the
/// answers then agree to round-off). The file is created when missing; a file there that is not
/// FFTW wisdom, or not a regular file, is refused (ParameterError) and left as it is; a folder
/// that is missing is refused. Operators made after the call use it.
void setFftWisdom(const std::string& path);
const std::string& fftWisdom() noexcept;

/// u = K p on an nx x ny grid of spacings dx, dy (row by row: index iy * nx + ix), for a
/// half-space of reduced modulus E' = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2) (two elastic bodies
/// reduce to one rigid and one of modulus E': Johnson, Contact Mechanics, 1985, §4.2).
///  - periodic: the grid is one period of a periodic surface; in Fourier space
///    u(q) = 2 p(q) / (E' |q|) (Johnson 1985 Eq. 12.39 for one wave; Stanley & Kato, J. Tribol.
///    119 (1997) 481), |q| = 2 pi sqrt((kx/Lx)^2 + (ky/Ly)^2). The mean (q = 0) displacement of
///    a periodic half-space is unbounded and is set to 0: displacements are relative to their mean.
///  - non-periodic: the grid is a patch of an unbounded surface, pressure zero outside it. Each
///    cell carries a uniform pressure; the displacement of a uniformly loaded rectangle is
///    Love's closed form (Love, Phil. Trans. A 228 (1929) 377; Johnson 1985 §3.3):
///    u(x, y) = p/(pi E') [F(x+a, y+b) - F(x+a, y-b) - F(x-a, y+b) + F(x-a, y-b)],
///    F(x, y) = x asinh(y/|x|) + y asinh(x/|y|), a = dx/2, b = dy/2 (the integral of 1/r over
///    the rectangle). The sum over cells is a discrete convolution, evaluated without
///    wrap-around on a grid padded to 2nx x 2ny (Liu, Wang & Liu, Wear 243 (2000) 101, DC-FFT).
///  - mirrored: the grid mirrored about its edges, 2nx x 2ny, is one period of a periodic
///    surface (an interface with a measured map's heights and neither edges nor a patch of its
///    own). A field even about the edges (p(-1-i) = p(i), p(2n-1-i) = p(i)) has a real Fourier
///    series of cosines: the periodic multiplier above on the 2nx x 2ny grid acts on it as
///    u = DCT-III(K(q) DCT-II(p)) / (4 nx ny), q = pi sqrt((kx/(nx dx))^2 + (ky/(ny dy))^2)
///    (FFTW's REDFT10 and REDFT01; Strang, SIAM Rev. 41 (1999) 135, the DCT-II's even
///    extension). The same answer as the periodic operator on the mirrored grid, with
///    transforms of nx x ny points, not 4 nx ny (blocked as the periodic ones; a cosine
///    transform costs FFTW 2-3 real ones: a pair is about a padded one's, docs/benchmarks.md).
class HalfSpaceOperator {
public:
    /// The grid's edges: a patch zero-padded, one period, or mirrored (above).
    enum class Edges { padded, periodic, mirrored };
    HalfSpaceOperator(std::size_t nx, std::size_t ny, double dx, double dy, double Eprime, Edges edges);
    /// periodic ? Edges::periodic : Edges::padded.
    HalfSpaceOperator(std::size_t nx, std::size_t ny, double dx, double dy, double Eprime, bool periodic);
    ~HalfSpaceOperator();
    HalfSpaceOperator(const HalfSpaceOperator&) = delete;
    HalfSpaceOperator& operator=(const HalfSpaceOperator&) = delete;

    /// u = K p; p and u hold nx * ny values (they may be the same array).
    void apply(const double* p, double* u) const;
    std::vector<double> apply(const std::vector<double>& p) const;
    /// p = S u with the multiplier E'|q|/2 (the same FFTs), the preconditioner of the solvers
    /// (the FFT-based preconditioner of Vollebregt, J. Comput. Phys. 257 (2014) 333):
    /// periodic, the exact inverse of K on every mode but the mean (which K maps to 0 and S
    /// gives the stiffness of the longest wavelength); non-periodic, the periodic stiffness of
    /// the padded grid, an approximate inverse. Symmetric positive definite.
    void applyStiffness(const double* u, double* p) const;
    /// The forward/inverse transform pairs done so far (apply and applyStiffness: one each),
    /// for the solvers' cost analysis (bench/boundaryElement/transformBound).
    std::size_t transformPairs() const noexcept { return pairs_; }
    /// S's smallest multiplier [Pa/m]: the stiffness of the longest wavelength of the grid
    /// (the mean mode's).
    double smallestStiffness() const noexcept { return smallestStiffness_; }

    std::size_t nx() const noexcept { return nx_; }
    std::size_t ny() const noexcept { return ny_; }
    std::size_t size() const noexcept { return nx_ * ny_; }
    double dx() const noexcept { return dx_; }
    double dy() const noexcept { return dy_; }
    double reducedModulus() const noexcept { return Eprime_; }
    /// Periodic or mirrored: an interface without edges (mirrored() says which).
    bool periodic() const noexcept { return edges_ != Edges::padded; }
    bool mirrored() const noexcept { return edges_ == Edges::mirrored; }
    /// The largest eigenvalue of K [m/Pa] (the largest magnitude of its Fourier multiplier),
    /// the step bound of gradient methods.
    double largestEigenvalue() const noexcept { return largest_; }
    /// Bytes the operator holds (kernel and FFT buffers), for the memory check of its callers.
    static double bytesFor(std::size_t nx, std::size_t ny, bool periodic);

    /// Love's displacement [m] at (x, y) of a pressure p [Pa] uniform over |x'| <= a, |y'| <= b.
    static double loveRectangle(double x, double y, double a, double b, double p, double Eprime);

private:
    struct Fft;
    struct Dct;
    void makeStiffness();
    void makeMirrored();
    void convolve(const GridField& multiplier, const double* in, double* out) const;
    mutable std::size_t pairs_ = 0; // convolve() calls (an operator is used by one solve at a time)
    std::size_t nx_;
    std::size_t ny_;
    double dx_;
    double dy_;
    double Eprime_;
    Edges edges_;
    std::size_t mx_; ///< FFT grid: nx (periodic, mirrored) or 2 nx (padded)
    std::size_t my_;
    GridField kernel_; ///< the real, symmetric kernel's transform, my x (mx/2 + 1); mirrored: ny x nx
    GridField stiffness_; ///< S's multiplier, the same layout
    double smallestStiffness_ = 0.0;
    std::unique_ptr<Fft> fft_; ///< padded, periodic
    std::unique_ptr<Dct> dct_; ///< mirrored
    double largest_ = 0.0;
};

} // namespace roughContact
