// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later): the
// coupled-baffle arithmetic and structure follow compressible::
// turbulentTemperatureCoupledBaffleMixedFvPatchScalarField and temperatureCoupledBase.
#include "contactInterfaceFromDict.H"
#include "dictionarySpecSource.H"
#include "foamCompat.H"

#include "error.H"
#include "IOstreams.H"
#include "Pstream.H"
#include "ops.H"
#include "Time.H"

#include "roughContact/interface/BoundaryElementTable.hpp"
#include "roughContact/interface/InterfaceSpecReader.hpp"
#include "roughContact/interface/SurfaceCheck.hpp"
#include "roughContact/models/BoundaryElement.hpp"
#include "roughContact/parallel/Threads.hpp"

#include "roughContact/surface/Spectrum.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace Foam
{

namespace
{

// The ranks of this run as the core's table build takes them (TableRanks,
// BoundaryElementTable.hpp): Pstream's broadcast from the master and its sum.
// Serial: one rank, no exchange.
roughContact::TableRanks pstreamRanks()
{
    roughContact::TableRanks ranks;
    if (!Pstream::parRun())
    {
        return ranks;
    }
    ranks.rank = std::size_t(Pstream::myProcNo());
    ranks.count = std::size_t(Pstream::nProcs());
    ranks.broadcast = [](std::vector<double>& v)
    {
        List<scalar> l(label(v.size()));
        forAll(l, i)
        {
            l[i] = v[i];
        }
#if OPENFOAM >= 2212
        // Pstream::scatter is deprecated from v2412 (since 2024-01); broadcast
        // (from v2206) sends the master's values to all the same way
        Pstream::broadcasts(UPstream::worldComm, l);
#else
        Pstream::scatter(l);
#endif
        v.assign(l.begin(), l.end());
    };
    ranks.sum = [](std::vector<double>& v)
    {
        List<scalar> l(label(v.size()));
        forAll(l, i)
        {
            l[i] = v[i];
        }
#if OPENFOAM >= 2212
        // listCombineScatter is deprecated from v2212; listCombineReduce is
        // the gather and the broadcast in one
        Pstream::listCombineReduce(l, plusEqOp<scalar>());
#else
        Pstream::listCombineGather(l, plusEqOp<scalar>());
        Pstream::listCombineScatter(l);
#endif
        v.assign(l.begin(), l.end());
    };
    return ranks;
}

// The points of the boundary-element table of `spec`, the same on every rank:
// the master reads them from the case's cache file
// constant/boundaryElementTable.<name>.csv when its key is this table's;
// otherwise the ranks build them together, each solving its share of the
// loads (BoundaryElementTable::loadOrBuild; the entry's tableRanks limits how
// many), and the master writes the file (atomically). Other ranks never touch
// the file; the master logs its own share's progress.
roughContact::BoundaryElementTablePoints boundaryElementPoints
(
    const roughContact::InterfaceSpec& spec,
    const word& name,
    const fileName& casePath,
    const string& who
)
{
    const roughContact::BoundaryElementTable bem(spec);
    const fileName file =
        casePath/"constant"/("boundaryElementTable." + name + ".csv");
    // The load being solved and how many this rank solves (known after its
    // first load; 0 before), for the progress of a long solve.
    std::size_t current = 1;
    std::size_t share = 0;
    return bem.loadOrBuild
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
            share = total;
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
                Info<< "load " << label(current);
                if (share > 0)
                {
                    Info<< " of " << label(share);
                }
                Info<< ", ";
            }
            Info<< s.stage << " solve: iteration " << label(s.iteration) << ", residual "
                << s.residual << " (tolerance " << s.tolerance << "), "
                << s.seconds << " s" << endl;
        },
        pstreamRanks()
    );
}

} // End anonymous namespace


defineTypeNameAndDebug(contactInterfaces, 0);


contactInterfaces::contactInterfaces(const IOobject& io)
:
    regIOobject(io)
{}


contactInterfaces& contactInterfaces::New(const objectRegistry& db)
{
    const word name("thermalContactInterfaces");
    if (!db.foundObject<contactInterfaces>(name))
    {
        contactInterfaces* p = new contactInterfaces
        (
            IOobject
            (
                name, db.time().constant(), db,
                IOobject::NO_READ, IOobject::NO_WRITE
            )
        );
        p->store();
    }
    return db.lookupObjectRef<contactInterfaces>(name);
}


std::shared_ptr<const roughContact::ContactInterface>
contactInterfaces::find(const word& key) const
{
    const auto i = table_.find(key);
    return i == table_.end() ? nullptr : i->second;
}


void contactInterfaces::insert
(
    const word& key,
    std::shared_ptr<const roughContact::ContactInterface> iface
)
{
    table_[key] = std::move(iface);
}


void contactInterfaces::requestCheck
(
    const word& key,
    const roughContact::InterfaceSpec& spec,
    const word& name,
    const fileName& dictFile
)
{
    checks_.emplace(key, pendingCheck{spec, name, dictFile});
}


void contactInterfaces::checkOnce
(
    const word& key,
    const string& who,
    const std::vector<double>& facePressures
)
{
    const auto found = checks_.find(key);
    if (found == checks_.end())
    {
        return;
    }
    const pendingCheck pending = found->second;
    checks_.erase(found);
    if (!Pstream::master())
    {
        return;
    }
    const roughContact::InterfaceSpec& spec = pending.spec;
    const word& name = pending.name;
    const fileName& dictFile = pending.dictFile;
    // check yes: the exact model on this surface against every law
    // (SurfaceCheck.hpp); its report in the log, a warning when the chosen
    // law misses it by more than 25 %. A check that cannot be made is said,
    // and the run goes on: it is a diagnostic, not a condition of the run.
    roughContact::SurfaceCheckOptions options;
    options.names.lightLoadPeriods = "checkPeriods";
    if (spec.checkPeriods)
    {
        options.lightLoadPeriods = *spec.checkPeriods;
    }
    // The pressures: the entry's, else the faces' at this first evaluation.
    options.names.pressures = "checkPressures";
    options.pressures =
        spec.checkPressures.empty() ? facePressures : spec.checkPressures;
    // The faces' pressures may lie beyond what the check can solve: then it
    // checks the nearer end of its range and says so.
    options.movePressuresIntoRange = spec.checkPressures.empty();
    // checkUnloadFrom: also unloaded from the joint's peak, and judged there.
    options.names.unloadFrom = "checkUnloadFrom";
    options.unloadFrom = spec.checkUnloadFrom;
    options.log = [](const std::string& line)
    {
        Info<< "    " << line.c_str() << endl;
    };
    Info<< "thermalContactResistance: check yes: checking the laws on the"
        << " surface of contact entry '" << name << "' (" << who.c_str()
        << ") at "
        << (
               !spec.checkPressures.empty() ? "its checkPressures"
             : !facePressures.empty()
             ? "the pressures the patch carries now (min, mean, max)"
             : "pressures across the table's range (no face in contact yet;"
               " checkPressures chooses them)"
           )
        << endl;
    try
    {
        const roughContact::SurfaceCheck c =
            roughContact::checkSurface(spec, options);
        Info<< c.report().c_str() << endl;
        if (!c.exactWarning.empty())
        {
            WarningInFunction
                << who.c_str() << ": contact entry '" << name << "' in "
                << dictFile << ": check yes: "
                << c.exactWarning.c_str() << endl;
        }
        for (const std::string& m : c.missWarnings("checkUnloadFrom"))
        {
            WarningInFunction
                << who.c_str() << ": contact entry '" << name << "' in "
                << dictFile << ": " << m.c_str()
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


word contactKey(const fileName& dictFile, const word& name)
{
    return dictFile + "::" + name;
}


std::shared_ptr<const roughContact::ContactInterface> contactInterfaceFromDict
(
    const objectRegistry& db,
    const dictionary& parent,
    const word& name,
    const fileName& dictFile,
    const fileName& casePath,
    const string& who
)
{
    // Built once per entry and file, shared by both sides and every patch
    // that names it: an object on the registry that holds the dictionary
    // (the case's Time), living as long as the run.
    contactInterfaces& shared = contactInterfaces::New(db);
    const word key = contactKey(dictFile, name);
    if (const auto found = shared.find(key))
    {
        return found;
    }

    const dictionary& dict = parent.subDict(name);
    // The entry, read by the core's one reader (InterfaceSpecReader.hpp: every
    // rule of a contact entry); OpenFOAM's own lookups report a value of the
    // wrong kind. Both are thrown, not exiting, so that they are reported
    // below with the patch and field that asked for the entry.
    const dictionarySpecSource source(dict, "", casePath);
    const bool throwing = foamCompat::throwFatalIOErrors();
    try
    {
        const roughContact::InterfaceSpec spec =
            roughContact::readInterfaceSpec(source);
        foamCompat::restoreFatalIOErrors(throwing);

        // The threads of the boundary-element solves (table, check): the
        // entry's; else 1 in a parallel run, where every core has a rank;
        // else what the machine has.
        roughContact::setThreads
        (
            spec.threads ? *spec.threads
          : Pstream::parRun() ? 1
          : roughContact::hardwareThreads()
        );
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
        const std::string note =
            roughContact::singleProfileNote(spec.surfaces, "alongLay");
        if (!note.empty())
        {
            Info<< "    note: " << note.c_str() << nl;
        }
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
        if (spec.check)
        {
            // Made at the first evaluation (contactInterfaces::checkOnce), in
            // the solver alone: decomposePar and reconstructPar build the
            // condition but never evaluate it.
            shared.requestCheck(key, spec, name, dictFile);
        }
        shared.insert(key, iface);
        return iface;
    }
    catch (const IOerror& e)
    {
        foamCompat::restoreFatalIOErrors(throwing);
        FatalIOErrorAt
        (
            e.ioFileName(), e.ioStartLineNumber(), e.ioEndLineNumber()
        )
            << who.c_str() << ": contact entry '" << name << "' in "
            << dictFile << ": " << e.message().c_str()
            << exit(FatalIOError);
    }
    catch (const roughContact::ParameterError& e)
    {
        // The core names an entry of the contact by its key (model,
        // conductance, synthesize, ...): here as the dictionary has it, with
        // its line.
        foamCompat::restoreFatalIOErrors(throwing);
        const std::string message =
            source.has(e.parameter())
          ? source.name(e.parameter()) + ": " + e.message()
          : std::string(e.what());
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": contact entry '" << name << "' in "
            << dictFile << ": " << message.c_str()
            << exit(FatalIOError);
    }
    catch (const std::exception& e)
    {
        foamCompat::restoreFatalIOErrors(throwing);
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": contact entry '" << name << "' in "
            << dictFile << ": " << e.what()
            << exit(FatalIOError);
    }
    return nullptr;
}

} // End namespace Foam
