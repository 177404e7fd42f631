// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later): the
// coupled-baffle arithmetic and structure follow compressible::
// turbulentTemperatureCoupledBaffleMixedFvPatchScalarField and temperatureCoupledBase.
#include "contactInterfaceFromDict.H"

#include "error.H"
#include "IOstreams.H"
#include "PtrList.H"
#include "Pstream.H"

#include "roughContact/Limits.hpp"
#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/models/BoundaryElement.hpp"

#include "roughContact/io/Units.hpp"
#include "roughContact/surface/ArealSurface.hpp"
#include "roughContact/surface/Spectrum.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

namespace Foam
{

namespace
{

roughContact::SurfaceSpec readSurface
(
    const dictionary& d,
    const fileName& casePath
)
{
    roughContact::SurfaceSpec s;
    const word type = d.get<word>("type");
    if (type == "profile" || type == "spectrum")
    {
        s.kind =
            type == "profile"
          ? roughContact::SurfaceSpec::Kind::profile
          : roughContact::SurfaceSpec::Kind::spectrum;
        fileName f = d.get<fileName>("file");
        f.expand();
        if (!f.isAbsolute())
        {
            f = casePath/f;
        }
        s.file = f;
        word units;
        if (d.readIfPresent("units", units))
        {
            s.profileOptions.units = roughContact::parseLengthUnit(units);
        }
        scalar dx;
        if (d.readIfPresent("spacing", dx))
        {
            s.profileOptions.spacing = dx;
        }
        label stride = 1;
        d.readIfPresent("stride", stride);
        if (stride < 1)
        {
            FatalIOErrorInFunction(d)
                << "stride must be >= 1, got " << stride << exit(FatalIOError);
        }
        s.stride = stride;
    }
    else if (type == "areal")
    {
        // A height map: an X3P file, or a text matrix with dx (and dy, units).
        s.kind = roughContact::SurfaceSpec::Kind::areal;
        fileName f = d.get<fileName>("file");
        f.expand();
        if (!f.isAbsolute())
        {
            f = casePath/f;
        }
        s.file = f;
        for (const char* profileOnly : {"spacing", "stride"})
        {
            if (d.found(profileOnly))
            {
                FatalIOErrorInFunction(d)
                    << "entry '" << profileOnly << "' is for a surface of type"
                    << " profile; an areal surface takes dx (and dy) for a"
                    << " text matrix, and an X3P file carries its own spacings"
                    << exit(FatalIOError);
            }
        }
        word units;
        if (d.readIfPresent("units", units))
        {
            s.arealOptions.units = roughContact::parseLengthUnit(units);
        }
        scalar spacing;
        if (d.readIfPresent("dx", spacing))
        {
            s.arealOptions.dx = spacing;
        }
        if (d.readIfPresent("dy", spacing))
        {
            s.arealOptions.dy = spacing;
        }
        s.arealOptions.fillInvalid = d.getOrDefault<bool>("fillInvalid", false);
        const word direction = d.getOrDefault<word>("direction", "x");
        if (direction != "x" && direction != "y" && direction != "both")
        {
            FatalIOErrorInFunction(d)
                << "entry 'direction' is '" << direction << "': the line"
                << " scans of an areal surface are x (rows), y (columns) or"
                << " both" << exit(FatalIOError);
        }
        s.direction = roughContact::parseScanDirection(direction);
    }
    else if (type == "powerLaw" || type == "fractal")
    {
        s.kind =
            type == "powerLaw"
          ? roughContact::SurfaceSpec::Kind::powerLaw
          : roughContact::SurfaceSpec::Kind::fractal;
        const bool power = type == "powerLaw";
        s.parameters =
        {
            d.get<scalar>(power ? "bm" : "D"),
            d.get<scalar>(power ? "m" : "G"),
            d.get<scalar>("fmin"),
            d.get<scalar>("fmax")
        };
    }
    else
    {
        FatalIOErrorInFunction(d)
            << "unknown surface type '" << type
            << "' (profile, areal, spectrum, powerLaw or fractal)"
            << exit(FatalIOError);
    }
    if (d.found("length"))
    {
        if (s.kind == roughContact::SurfaceSpec::Kind::profile)
        {
            FatalIOErrorInFunction(d)
                << "entry 'length' has no meaning for a surface of type"
                << " profile: a profile's length is its number of samples"
                << " times their spacing. 'length' is the scan length of a"
                << " spectrum, powerLaw or fractal surface; remove it"
                << exit(FatalIOError);
        }
        if (s.kind == roughContact::SurfaceSpec::Kind::areal)
        {
            FatalIOErrorInFunction(d)
                << "entry 'length' has no meaning for a surface of type"
                << " areal: its scan lengths are nx dx and ny dy. 'length'"
                << " is the scan length of a spectrum, powerLaw or fractal"
                << " surface; remove it" << exit(FatalIOError);
        }
        const scalar L = d.get<scalar>("length");
        if (!(L > 0) || !std::isfinite(L))
        {
            FatalIOErrorInFunction(d)
                << "entry 'length' must be a finite scan length > 0 [m],"
                << " got " << L << exit(FatalIOError);
        }
        s.length = L;
    }
    return s;
}

roughContact::Material readMaterial(const dictionary& d)
{
    // Read here, checked by the core (roughContact::checkMaterial: the one
    // place for the accepted ranges), reported here so that the error names
    // the sub-dictionary as written (side1/side2) and points at its lines.
    roughContact::Material m;
    m.E = d.get<scalar>("E");
    m.nu = d.get<scalar>("nu");
    // Sy [Pa], or 'Sy none;': this solid does not yield (the core's
    // Material::elastic; S_y on one side only is otherwise an error).
    if (d.found("Sy"))
    {
        ITstream& is = d.lookup("Sy");
        if (is.size() && is[0].isWord())
        {
            if (is[0].wordToken() != "none")
            {
                FatalIOErrorInFunction(d)
                    << "entry 'Sy' of " << d.dictName() << " must be a yield"
                    << " strength [Pa] or 'none' (the solid does not yield),"
                    << " got '" << is[0].wordToken() << "'" << exit(FatalIOError);
            }
            m.elastic = true;
        }
        else
        {
            m.Sy = d.get<scalar>("Sy");
        }
    }
    try
    {
        roughContact::checkMaterial(m, d.dictName());
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(d)
            << "entry " << e.what() << " (entries E, nu, Sy of "
            << d.dictName() << ")" << exit(FatalIOError);
    }
    return m;
}


// The gap sub-dictionary: gas (a name, or a dictionary of its properties),
// its pressure, the accommodation coefficients and the emissivities. Checked
// by the core (roughContact::InterfaceGap: the one place of the rules),
// reported here naming the sub-dictionary and its lines.
roughContact::GapSpec readGap(const dictionary& d)
{
    roughContact::GapSpec g;
    if (d.found("gas"))
    {
        roughContact::GasGapSpec gas;
        if (d.isDict("gas"))
        {
            const dictionary& p = d.subDict("gas");
            roughContact::GasProperties& q = gas.gas;
            q.name = "user";
            q.conductivity = p.get<scalar>("conductivity");
            q.conductivityExponent =
                p.getOrDefault<scalar>("conductivityExponent", 0);
            q.referenceTemperature = p.get<scalar>("referenceTemperature");
            q.heatCapacityRatio = p.get<scalar>("heatCapacityRatio");
            q.prandtl = p.get<scalar>("prandtl");
            q.meanFreePath = p.get<scalar>("meanFreePath");
            q.referencePressure =
                p.getOrDefault<scalar>("referencePressure", roughContact::standardAtmosphere);
            q.accommodation = p.get<scalar>("accommodation");
        }
        else
        {
            const word name(d.get<word>("gas"));
            try
            {
                gas.gas = roughContact::gasByName(name);
            }
            catch (const std::exception& e)
            {
                FatalIOErrorInFunction(d)
                    << "entry " << e.what() << exit(FatalIOError);
            }
        }
        gas.pressure = d.getOrDefault<scalar>("pressure", roughContact::standardAtmosphere);
        if (d.found("accommodation"))
        {
            const List<scalar> a(d.lookup("accommodation"));
            if (a.size() != 2)
            {
                FatalIOErrorInFunction(d)
                    << "entry accommodation: expected (a1 a2), the thermal"
                    << " accommodation coefficients of the two surfaces; got "
                    << a.size() << " values" << exit(FatalIOError);
            }
            gas.accommodation1 = a[0];
            gas.accommodation2 = a[1];
        }
        g.gas = gas;
    }
    if (d.found("emissivity"))
    {
        const List<scalar> e(d.lookup("emissivity"));
        if (e.size() != 2)
        {
            FatalIOErrorInFunction(d)
                << "entry emissivity: expected (e1 e2), the emissivities of"
                << " the two surfaces; got " << e.size() << " values"
                << exit(FatalIOError);
        }
        g.emissivity1 = e[0];
        g.emissivity2 = e[1];
    }
    try
    {
        // The rules, checked once (a unit separation stands in for the
        // contact's, which is not built yet).
        roughContact::InterfaceGap(g, [](double) { return 1.0; }, 1, 1, 1);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(d)
            << "entry " << e.what() << " (sub-dictionary " << d.dictName()
            << ": gas, pressure, accommodation, emissivity)"
            << exit(FatalIOError);
    }
    return g;
}


// The points of the boundary-element table of `spec`: the master reads them
// from the case's cache file constant/boundaryElementTable.<name>.csv when its
// key is this table's, or builds them (logging each load) and writes the file
// (atomically); then every processor receives them from the master, so that
// the table is built once and all ranks hold the same numbers. Other ranks
// never touch the file.
roughContact::BoundaryElementTablePoints boundaryElementPoints
(
    const roughContact::InterfaceSpec& spec,
    const word& name,
    const fileName& casePath,
    const string& who
)
{
    const roughContact::BoundaryElementTable bem(spec);
    roughContact::BoundaryElementTablePoints points;
    if (Pstream::master())
    {
        // The core reads the file when it holds this table (key and digest),
        // else builds and writes it; here only the log and the broadcast.
        const fileName file =
            casePath/"constant"/("boundaryElementTable." + name + ".csv");
        // The load being solved, for the progress of a long solve.
        std::size_t current = 1;
        points = bem.loadOrBuild
        (
            file,
            [&]
            (
                std::size_t done, std::size_t total, double P,
                const roughContact::BoundaryElementPoint& p,
                double seconds
            )
            {
                current = done + 1;
                Info<< "    building the boundary-element table for '"
                    << name << "': load " << label(done) << " of "
                    << label(total) << ", P = " << P << " Pa, A_r/A_n = "
                    << p.areaFraction << ", " << seconds << " s" << endl;
            },
            [&](const std::string& line, bool warning)
            {
                if (warning)
                {
                    WarningInFunction
                        << who.c_str() << ": contact entry '" << name
                        << "': " << line.c_str() << endl;
                }
                else
                {
                    Info<< "    " << line.c_str() << " ('" << name << "')"
                        << endl;
                }
            },
            [&](const roughContact::SolveProgress& s)
            {
                const bool patch = s.stage[0] == 'b';
                Info<< "    building the boundary-element table for '"
                    << name << "': ";
                if (!patch)
                {
                    Info<< "load " << label(current) << " of "
                        << label(bem.pressures().size()) << ", ";
                }
                Info<< s.stage << " solve: iteration " << label(s.iteration) << ", residual "
                    << s.residual << " (tolerance " << s.tolerance << "), "
                    << s.seconds << " s" << endl;
            }
        );
    }
    if (Pstream::parRun())
    {
        List<scalar> P(points.pressures.size());
        List<scalar> A(points.areaFractions.size());
        List<scalar> H(points.conductancesPerConductivity.size());
        List<scalar> Y(points.separations.size());
        forAll(P, i)
        {
            P[i] = points.pressures[i];
            A[i] = points.areaFractions[i];
            H[i] = points.conductancesPerConductivity[i];
        }
        forAll(Y, i)
        {
            Y[i] = points.separations[i];
        }
        // +inf (no complete contact) as -1: a stream need not carry inf.
        scalar complete =
            std::isinf(points.completeContactPressure)
          ? -1 : points.completeContactPressure;
        label end = label(points.end);
#if OPENFOAM >= 2212
        // Pstream::scatter is deprecated from v2412 (since 2024-01); broadcast
        // (from v2206) sends the master's values to all the same way
        Pstream::broadcasts(UPstream::worldComm, P, A, H, Y, complete, end);
#else
        Pstream::scatter(P);
        Pstream::scatter(A);
        Pstream::scatter(H);
        Pstream::scatter(Y);
        Pstream::scatter(complete);
        Pstream::scatter(end);
#endif
        points.pressures.assign(P.begin(), P.end());
        points.areaFractions.assign(A.begin(), A.end());
        points.conductancesPerConductivity.assign(H.begin(), H.end());
        points.separations.assign(Y.begin(), Y.end());
        points.completeContactPressure =
            complete < 0 ? std::numeric_limits<double>::infinity() : complete;
        points.end = roughContact::ContactTable::End(end);
    }
    return points;
}

} // End anonymous namespace


std::shared_ptr<const roughContact::ContactInterface> contactInterfaceFromDict
(
    const dictionary& parent,
    const word& name,
    const fileName& dictFile,
    const fileName& casePath,
    const string& who
)
{
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const roughContact::ContactInterface>> cache;

    const std::string key = dictFile + "::" + name;
    std::lock_guard<std::mutex> lock(mutex);
    const auto found = cache.find(key);
    if (found != cache.end())
    {
        return found->second;
    }

    const dictionary& dict = parent.subDict(name);
    roughContact::InterfaceSpec spec;
    // A missing or bad entry of the dictionary (OpenFOAM's own lookups, and
    // readSurface/readMaterial) is a FatalIOError; thrown, not exiting, so
    // that it is reported below with the patch and field that asked for it.
    const bool throwing = FatalIOError.throwExceptions();
    try
    {
        if (dict.found("surfaces"))
        {
            const PtrList<dictionary> list(dict.lookup("surfaces"));
            forAll(list, i)
            {
                spec.surfaces.push_back(readSurface(list[i], casePath));
            }
        }
        else
        {
            spec.surfaces.push_back(readSurface(dict.subDict("surface"), casePath));
        }
        spec.side1 = readMaterial(dict.subDict("side1"));
        spec.side2 = readMaterial(dict.subDict("side2"));
        spec.model = dict.get<word>("model");
        // The conductance law (roughContact::conductanceLawNames()); the
        // core's default when absent.
        word law;
        if (dict.readIfPresent("conductance", law))
        {
            spec.conductanceLaw = law;
        }
        scalar Hc;
        if (dict.readIfPresent("microhardness", Hc))
        {
            spec.microhardness = Hc;
        }
        if (dict.found("vickers"))
        {
            const List<scalar> c(dict.lookup("vickers"));
            if (c.size() != 2)
            {
                FatalIOErrorInFunction(dict)
                    << "entry vickers: expected (c1 c2), c1 [Pa] and c2 of"
                    << " H_v = c1 (d_v/1 um)^c2; got " << c.size()
                    << " values" << exit(FatalIOError);
            }
            spec.vickers = roughContact::VickersCoefficients{c[0], c[1]};
        }
        scalar p;
        if (dict.readIfPresent("minPressure", p))
        {
            spec.minPressure = p;
        }
        if (dict.readIfPresent("maxPressure", p))
        {
            spec.maxPressure = p;
        }
        // model boundaryElement: the surface it solves and its table's loads.
        label n;
        if (dict.readIfPresent("synthesize", n))
        {
            if (n < 0)
            {
                FatalIOErrorInFunction(dict)
                    << "entry synthesize: expected a grid size N > 0, got "
                    << n << exit(FatalIOError);
            }
            spec.synthesize = std::size_t(n);
        }
        if (dict.readIfPresent("seed", n))
        {
            if (n < 0)
            {
                FatalIOErrorInFunction(dict)
                    << "entry seed: expected a whole number >= 0, got " << n
                    << exit(FatalIOError);
            }
            spec.seed = std::uint64_t(n);
        }
        bool flag;
        if (dict.readIfPresent("periodic", flag))
        {
            spec.periodic = flag;
        }
        word detrend;
        if (dict.readIfPresent("detrend", detrend))
        {
            spec.detrend = roughContact::parseDetrend(detrend, "detrend");
        }
        scalar H;
        if (dict.readIfPresent("hardness", H))
        {
            spec.hardness = H;
        }
        spec.hardnessFromYield =
            dict.getOrDefault<bool>("hardnessFromYield", false);
        if (dict.readIfPresent("pointsPerDecade", n))
        {
            // (its range is the core's: Limits.hpp)
            if (n < 0)
            {
                FatalIOErrorInFunction(dict)
                    << "entry pointsPerDecade: expected a whole number from "
                    << label(roughContact::limits::minimumPointsPerDecade)
                    << " to "
                    << label(roughContact::limits::maximumPointsPerDecade)
                    << ", got " << n << exit(FatalIOError);
            }
            (spec.model == "boundaryElement"
                ? spec.bemPointsPerDecade : spec.pointsPerDecade) =
                std::size_t(n);
        }
        if (dict.found("gap"))
        {
            spec.gap = readGap(dict.subDict("gap"));
        }
        const bool check = dict.getOrDefault<bool>("check", false);
        FatalIOError.throwExceptions(throwing);

        Info<< "thermalContactResistance: building the contact table for '"
            << name << "' (" << who.c_str() << ")" << endl;
        std::shared_ptr<const roughContact::ContactInterface> iface;
        if (spec.model == "boundaryElement")
        {
            const roughContact::BoundaryElementTablePoints points =
                boundaryElementPoints(spec, name, casePath, who);
            iface = std::make_shared<const roughContact::ContactInterface>
            (
                spec, &points
            );
        }
        else
        {
            iface = std::make_shared<const roughContact::ContactInterface>(spec);
        }
        Info<< "    " << iface->summary().c_str() << nl;
        // What this run uses, so that a run can be traced to its surface (the
        // condition writes the checksum into its field file, too).
        const roughContact::Spectrum& surface = iface->surface();
        Info<< "    surface checksum "
            << iface->surfaceChecksum().c_str() << ", "
            << label(surface.size()) << " levels, rms height "
            << std::sqrt(surface.profileVariance()) << " m, L = "
            << surface.length() << " m" << nl
            << "    " << dictFile << " is read once: changes to it"
            << " (and to the surface files) during the run are not used"
            << " until the run is restarted" << endl;
        if (check && Pstream::master())
        {
            // check yes: the exact model on this surface against every
            // law (SurfaceCheck.hpp); its report in the log, a warning when
            // the chosen law misses it by more than 25 %.
            roughContact::SurfaceCheckOptions options;
            options.log = [](const std::string& line)
            {
                Info<< "    " << line.c_str() << endl;
            };
            // A check that cannot be made is said, and the run goes on:
            // it is a diagnostic, not a condition of the run.
            try
            {
            const roughContact::SurfaceCheck c =
                roughContact::checkSurface(spec, options);
            Info<< c.report().c_str() << endl;
            const std::vector<double> misses = c.chosenMisses();
            if (!misses.empty())
            {
                WarningInFunction
                    << who.c_str() << ": contact entry '" << name << "' in "
                    << dictFile << ": the conductance law "
                    << c.chosenLaw.c_str() << " is off the exact conductance"
                    << " of this surface by more than "
                    << label(roughContact::checkTolerance*100 + 0.5)
                    << " % at " << label(misses.size()) << " of "
                    << label(c.pressures.size()) << " checked pressures;"
                    << " the closest law here is " << c.closestLaw.c_str()
                    << " (the check's table is above)" << endl;
            }
            }
            catch (const std::exception& e)
            {
                WarningInFunction
                    << who.c_str() << ": contact entry '" << name << "' in "
                    << dictFile << ": check yes: the check could not be"
                    << " made: " << e.what() << "; the run goes on"
                    << " without it" << endl;
            }
        }
        cache.emplace(key, iface);
        return iface;
    }
    catch (const IOerror& e)
    {
        FatalIOError.throwExceptions(throwing);
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            e.ioFileName(), e.ioStartLineNumber(), e.ioEndLineNumber()
        )
            << who.c_str() << ": contact entry '" << name << "' in "
            << dictFile << ": " << e.message().c_str()
            << exit(FatalIOError);
    }
    catch (const std::exception& e)
    {
        FatalIOError.throwExceptions(throwing);
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": contact entry '" << name << "' in "
            << dictFile << ": " << e.what()
            << exit(FatalIOError);
    }
    return nullptr;
}

} // End namespace Foam
