// SPDX-License-Identifier: GPL-3.0-or-later
#include "roughContact/models/BoundaryElement.hpp"

#include "roughContact/Constants.hpp"
#include "roughContact/Error.hpp"
#include "roughContact/Limits.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace roughContact {

BoundaryElementModel::BoundaryElementModel(const ArealSurface& surface, double Eprime,
                                           BoundaryElementOptions options)
    : surface_(surface.detrended(options.detrend.value_or(defaultDetrend(options.periodic)))), Eprime_(requirePositive("reduced modulus E'", Eprime)), options_(options)
{
    const HalfSpaceOperator::Edges edges = edgesOf(options_.periodic, options_.mirrored);
    const bool interface = options_.periodic || options_.mirrored; // no patch of its own
    // The roughness floor of every model (Limits.hpp): a smaller rms is a unit mistake or a
    // constant map (a mask with one valid point, filled), which the solver cannot resolve.
    double mean = 0.0;
    for (double z : surface_.heights()) {
        mean += z;
    }
    mean /= double(surface_.heights().size());
    double rms = 0.0;
    for (double z : surface_.heights()) {
        rms += (z - mean) * (z - mean);
    }
    rms = std::sqrt(rms / double(surface_.heights().size()));
    if (rms == 0.0) {
        throw ParameterError("surface " + surface_.source(), "has zero roughness: nothing to solve");
    }
    if (rms < limits::minimumRoughness) {
        std::ostringstream os;
        os << "rms height " << rms << " m (detrended: "
           << detrendName(options_.detrend.value_or(defaultDetrend(options_.periodic))) << ") is below "
           << limits::minimumRoughness
           << " m (a femtometre): not a physical roughness (a constant map?); check the units";
        throw ParameterError("surface " + surface_.source(), os.str());
    }
    const double bytes =
        boundaryElementBytes(surface_.nx(), surface_.ny(), interface, options_.hardness.has_value());
    if (bytes > options_.memoryLimit) {
        std::ostringstream os;
        os.precision(3);
        os << surface_.nx() << " x " << surface_.ny() << " points"
           << (interface ? "" : " (padded to twice each way)") << " would need about " << bytes / 1e9
           << " GB, more than the limit of " << options_.memoryLimit / 1e9
           << " GB; resample the map coarser or cut a part of it";
        throw ParameterError("boundary-element grid", os.str());
    }
    op_ = std::make_unique<HalfSpaceOperator>(surface_.nx(), surface_.ny(), surface_.dx(), surface_.dy(),
                                              Eprime_, edges);
    PolonskyKeerOptions po;
    po.tolerance = options_.tolerance;
    po.maxIterations = options_.maxIterations;
    po.hardness = options_.hardness;
    po.precondition = options_.precondition;
    po.progress = options_.progress;
    po.progressEvery = options_.progressEvery;
    solver_ = std::make_unique<PolonskyKeer>(*op_, surface_.heights(), po);
    patchConductance_ = std::numeric_limits<double>::infinity();
    if (!interface) {
        SolveProgressCallback patchProgress;
        if (options_.progress) {
            patchProgress = [this](const SolveProgress& s) {
                SolveProgress p = s;
                p.stage = "bonded-patch conductance";
                options_.progress(p);
            };
        }
        const SpotConductance patch = spotConductance(*op_, std::vector<bool>(surface_.nx() * surface_.ny(), true), conductanceTolerance,
                                                      options_.maxIterations, nullptr, nullptr,
                                                      options_.precondition, patchProgress, options_.progressEvery);
        if (!patch.converged || !(patch.perConductivity > 0.0)) {
            throw ParameterError("boundaryElement", "the conductance of the bonded patch did not converge");
        }
        patchConductance_ = patch.perConductivity;
    }
}

BoundaryElementPoint BoundaryElementModel::solve(double load, std::vector<double>* pressure,
                                                 const std::vector<double>* warmStart,
                                                 std::vector<double>* flux,
                                                 const std::vector<double>* warmFlux) const
{
    BoundaryElementPoint out;
    out.load = checkLoad(load);
    if (load == 0.0) {
        return out;
    }
    const double P = load * Eprime_;
    if (options_.hardness && P >= *options_.hardness) {
        // Every point flows: complete contact, nothing constricts the flow.
        out.areaFraction = 1.0;
        out.plasticFraction = 1.0;
        out.conductancePerConductivity = std::numeric_limits<double>::infinity();
        out.spotsConductancePerConductivity = patchConductance_;
        out.patchCorrectionGain = 1.0; // nothing is subtracted: complete contact is exact
        const double nominalArea = static_cast<double>(op_->size()) * op_->dx() * op_->dy();
        out.spots = {1, std::sqrt(nominalArea / pi), nominalArea};
        return out;
    }
    ContactSolution s = solver_->solve(P, warmStart);
    if (!s.converged) {
        std::ostringstream os;
        os << "the contact solve at F/(A_n E') = " << load << " did not converge in " << s.iterations
           << " iterations (residual " << s.residual << ", tolerance " << s.tolerance << ")";
        throw ParameterError("boundaryElement", os.str());
    }
    out.areaFraction = s.areaFraction;
    out.plasticFraction = s.plasticFraction;
    out.meanSeparation = s.meanSeparation;
    out.iterations = s.iterations;
    out.residual = s.residual;
    std::vector<bool> contact(s.pressure.size());
    for (std::size_t i = 0; i < contact.size(); ++i) {
        contact[i] = s.pressure[i] > 0.0;
    }
    out.spots = contactSpots(contact, op_->nx(), op_->ny(), op_->dx(), op_->dy(),
                             op_->periodic() && !op_->mirrored());
    const SpotConductance c = spotConductance(*op_, contact, conductanceTolerance, options_.maxIterations,
                                              warmFlux, flux, options_.precondition, options_.progress,
                                              options_.progressEvery);
    if (!c.converged) {
        std::ostringstream os;
        os << "the conductance solve at F/(A_n E') = " << load << " did not converge in " << c.iterations
           << " iterations (residual " << c.residual << ")";
        throw ParameterError("boundaryElement", os.str());
    }
    out.spotsConductancePerConductivity = c.perConductivity;
    // The patch's own constriction removed (the header): 1/h = 1/h_spots - 1/h_patch; the
    // spots of a patch conduct at most as the bonded patch does.
    const double interfaceResistance = 1.0 / c.perConductivity - 1.0 / patchConductance_;
    out.conductancePerConductivity =
        interfaceResistance > 0.0 ? 1.0 / interfaceResistance : std::numeric_limits<double>::infinity();
    // 1/(1 - h_spots/h_patch) = 1 + h_c/h_patch; 1 periodic or mirrored (h_patch = inf).
    out.patchCorrectionGain =
        std::isfinite(patchConductance_) ? 1.0 + out.conductancePerConductivity / patchConductance_ : 1.0;
    out.conductanceIterations = c.iterations;
    out.conductanceResidual = c.residual;
    if (pressure != nullptr) {
        *pressure = std::move(s.pressure);
    }
    return out;
}

double requireUnloadingPeak(double peakPressure, const std::optional<double>& hardness, const std::string& name,
                            const std::string& capName)
{
    if (!hardness) {
        throw ParameterError(name, "unloads a joint the cap has flattened: give " + capName +
                                       " (elastic, unloading is loading)");
    }
    if (!std::isfinite(peakPressure) || peakPressure <= 0.0 || peakPressure >= *hardness) {
        std::ostringstream os;
        os << "the peak is a pressure above 0 and below the cap H = " << *hardness << " Pa, not " << peakPressure
           << " Pa";
        throw ParameterError(name, os.str());
    }
    return peakPressure;
}

ArealSurface BoundaryElementModel::deformedSurface(double peakLoad) const
{
    checkLoad(peakLoad);
    if (!options_.hardness || peakLoad == 0.0) {
        return surface_;
    }
    const double P = peakLoad * Eprime_;
    if (P >= *options_.hardness) {
        std::ostringstream os;
        os << "a peak of F/(A_n E') = " << peakLoad << " is at or above the hardness (" << *options_.hardness
           << " Pa): the whole surface flows, and no surface is left to unload";
        throw ParameterError("peak load", os.str());
    }
    const ContactSolution s = solver_->solve(P);
    if (!s.converged) {
        std::ostringstream os;
        os << "the contact solve at the peak F/(A_n E') = " << peakLoad << " did not converge in " << s.iterations
           << " iterations (residual " << s.residual << ", tolerance " << s.tolerance << ")";
        throw ParameterError("boundaryElement", os.str());
    }
    std::vector<double> z = surface_.heights();
    for (std::size_t i = 0; i < z.size(); ++i) {
        z[i] += std::min(0.0, s.gap[i]); // the depth flattened at p = H (ContactSolution::gap)
    }
    std::ostringstream name;
    name << surface_.source() << " deformed at F/(A_n E') = " << peakLoad;
    return ArealSurface(std::move(z), surface_.nx(), surface_.ny(), surface_.dx(), surface_.dy(), name.str());
}

std::vector<BoundaryElementPoint> BoundaryElementModel::loadPath(
    double peakLoad, const std::vector<double>& loads,
    const std::function<void(std::size_t, std::size_t, const BoundaryElementPoint&)>& progress) const
{
    for (double l : loads) {
        checkLoad(l);
    }
    if (!options_.hardness) {
        return curve(loads, progress);
    }
    // The deformed surface as solved: no detrending again (a plane removed from the flattened
    // heights would tilt them; a periodic surface's mean is a uniform shift, removed as before).
    BoundaryElementOptions o = options_;
    o.detrend = options_.periodic ? Detrend::mean : Detrend::none;
    const ArealSurface deformed = deformedSurface(peakLoad);
    std::vector<std::size_t> below;
    std::vector<std::size_t> above;
    for (std::size_t k = 0; k < loads.size(); ++k) {
        (loads[k] <= peakLoad ? below : above).push_back(k);
    }
    std::vector<BoundaryElementPoint> out(loads.size());
    std::size_t done = 0;
    const auto part = [&](const std::vector<std::size_t>& at, bool capped) {
        if (at.empty()) {
            return;
        }
        BoundaryElementOptions po = o;
        if (!capped) {
            po.hardness.reset();
        }
        std::vector<double> these;
        for (std::size_t k : at) {
            these.push_back(loads[k]);
        }
        const std::vector<BoundaryElementPoint> points =
            BoundaryElementModel(deformed, Eprime_, po)
                .curve(these, [&](std::size_t, std::size_t, const BoundaryElementPoint& p) {
                    ++done;
                    if (progress) {
                        progress(done, loads.size(), p);
                    }
                });
        for (std::size_t j = 0; j < at.size(); ++j) {
            out[at[j]] = points[j];
        }
    };
    part(below, false);
    part(above, true);
    return out;
}

double BoundaryElementModel::areaFraction(double load) const
{
    return solve(load).areaFraction;
}

std::vector<BoundaryElementPoint> BoundaryElementModel::curve(
    const std::vector<double>& loads,
    const std::function<void(std::size_t, std::size_t, const BoundaryElementPoint&)>& progress) const
{
    for (double l : loads) {
        checkLoad(l);
    }
    std::vector<std::size_t> order(loads.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return loads[a] < loads[b]; });
    std::vector<BoundaryElementPoint> out(loads.size());
    std::vector<double> previous;
    std::vector<double> previousFlux;
    double previousLoad = 0.0;
    std::size_t done = 0;
    for (std::size_t k : order) {
        std::vector<double> pressure;
        std::vector<double> flux;
        // The first guess: the previous pressure moved along the tangent of the curve. The
        // conductance solve's x (K x = 1 on the contact set) is the pressure increment of a
        // unit rigid approach on that contact set, so p + c x with c = n (P - P_previous) / sum x
        // carries the new load (PolonskyKeer rescales and finds the new contact points).
        if (!previous.empty() && previousFlux.size() == previous.size()) {
            const double sum = std::accumulate(previousFlux.begin(), previousFlux.end(), 0.0);
            if (sum > 0.0) {
                const double c = double(previous.size()) * (loads[k] - previousLoad) * Eprime_ / sum;
                for (std::size_t i = 0; i < previous.size(); ++i) {
                    previous[i] += c * previousFlux[i];
                }
            }
        }
        out[k] = solve(loads[k], &pressure, previous.empty() ? nullptr : &previous, &flux,
                       previousFlux.empty() ? nullptr : &previousFlux);
        if (!pressure.empty()) {
            previous = std::move(pressure);
            previousLoad = loads[k];
        }
        if (!flux.empty()) {
            previousFlux = std::move(flux);
        }
        ++done;
        if (progress) {
            progress(done, loads.size(), out[k]);
        }
    }
    return out;
}

std::string patchCorrectionWarning(const std::vector<BoundaryElementPoint>& points, double Eprime,
                                   const std::string& mirror)
{
    std::size_t count = 0;
    const BoundaryElementPoint* lowest = nullptr;
    double largest = 0.0;
    for (const BoundaryElementPoint& p : points) {
        if (p.patchCorrectionGain > patchCorrectionGainLimit) {
            ++count;
            if (lowest == nullptr || p.load < lowest->load) {
                lowest = &p;
            }
            largest = std::max(largest, p.patchCorrectionGain);
        }
    }
    if (count == 0) {
        return {};
    }
    std::ostringstream os;
    os.precision(3);
    os << "the map's h_c is not to be trusted at " << count << " of " << points.size() << " loads, from P = "
       << lowest->load * Eprime << " Pa (F/(A_n E') = " << lowest->load << ", A_r/A_n = " << lowest->areaFraction
       << ") on: its spots conduct nearly as the whole map bonded does, and 1/h_c = 1/h_spots - 1/h_patch ";
    if (std::isinf(largest)) {
        os << "multiplies their error without bound (at some load the spots conduct as the bonded map: h_c infinite)";
    } else {
        os << "multiplies their error up to " << largest << " times";
    }
    os << " (above " << patchCorrectionGainLimit
       << "; on a measured map such points were 1.06-1.96 times the map solved mirrored). Solve the map mirrored ("
       << mirror << ") for the interface's h_c there";
    return os.str();
}

HalfSpaceOperator::Edges edgesOf(bool periodic, bool mirrored)
{
    if (periodic && mirrored) {
        throw ParameterError("mirror", "a mirrored map is its own periodic surface: give periodic or mirror, not both");
    }
    return mirrored ? HalfSpaceOperator::Edges::mirrored
                    : (periodic ? HalfSpaceOperator::Edges::periodic : HalfSpaceOperator::Edges::padded);
}

double boundaryElementBytes(std::size_t nx, std::size_t ny, bool periodic, bool capped)
{
    // The operator's FFT buffers and multipliers, and the solves' own arrays of n doubles at
    // their peak: 11 elastic, 13 with the cap (the projected gradients' fallback frees the
    // conjugate gradients' arrays first). Measured with /usr/bin/time at 512^2 to 4096^2 on
    // periodic surfaces: docs/benchmarks.md, "Memory of the exact model".
    const double arrays = capped ? 13.0 : 11.0;
    return HalfSpaceOperator::bytesFor(nx, ny, periodic) + arrays * 8.0 * double(nx) * double(ny);
}

// What estimatedCurveSeconds() counts a curve's solves as, in displacement evaluations (K or S,
// each an FFT pair): the first load from a cold start, each further one warm-started, and a
// non-periodic map's bonded patch.
constexpr double firstLoadEvaluations = 150.0;
constexpr double perLoadEvaluations = 100.0;
constexpr double patchEvaluations = 60.0;

double estimatedCurveSeconds(const HalfSpaceOperator& op, std::size_t loads)
{
    GridField p(op.size(), 1.0);
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const auto start = std::chrono::steady_clock::now();
        op.apply(p.data(), p.data());
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    const double evaluations = (loads > 0 ? firstLoadEvaluations + perLoadEvaluations * double(loads - 1) : 0.0) +
                               (op.periodic() ? 0.0 : patchEvaluations);
    return best * evaluations;
}

ArealSurface compositeSurface(const ArealSurface& a, const ArealSurface& b)
{
    if (a.nx() != b.nx() || a.ny() != b.ny() || std::abs(a.dx() - b.dx()) > 1e-12 * a.dx() ||
        std::abs(a.dy() - b.dy()) > 1e-12 * a.dy()) {
        std::ostringstream os;
        os << "the two surfaces must share one grid for their composite: " << a.nx() << " x " << a.ny()
           << " at " << a.dx() << " x " << a.dy() << " m and " << b.nx() << " x " << b.ny() << " at "
           << b.dx() << " x " << b.dy() << " m";
        throw InputError(b.source(), 0, os.str());
    }
    std::vector<double> z(a.heights().size());
    for (std::size_t i = 0; i < z.size(); ++i) {
        z[i] = a.heights()[i] + b.heights()[i];
    }
    return ArealSurface(std::move(z), a.nx(), a.ny(), a.dx(), a.dy(), a.source() + " + " + b.source());
}

} // namespace roughContact
