// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). Builds on OpenFOAM (Copyright
// OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later).
#include "thermalContactMonitor.H"
#include "thermalContactResistanceFvPatchScalarField.H"

#include "addToRunTimeSelectionTable.H"
#include "foamCompat.H"
#include "fvMesh.H"
#include "thermalContactLine.H"
#include "OSspecific.H"
#include "Time.H"
#include "volFields.H"

#include "roughContact/interface/InterfaceMonitor.hpp"

#include <fstream>
#include <string>

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(thermalContactMonitor, 0);
    addToRunTimeSelectionTable(functionObject, thermalContactMonitor, dictionary);
}
}


namespace
{
    using Foam::thermalContactResistanceFvPatchScalarField;

    //- The fields, in one list: name and dimensions. The constant-h mode
    //  writes the first only; gapConductance is written where the interface
    //  has a gap.
    enum outputField
    {
        outConductance, outAreaFraction, outPressure, outState, outGap, nOutputs
    };
    const char* const outputNames[nOutputs] =
    {
        "contactConductance", "contactAreaFraction", "contactPressure",
        "contactState", "gapConductance"
    };

    //- Counts and area-weighted sums of the side's last update, over all
    //  processors
    ::roughContact::CouplingSummary summary
    (
        const thermalContactResistanceFvPatchScalarField& side
    )
    {
        using namespace Foam;
        ::roughContact::CouplingSummary s;
        if (side.coupling().state.size() == size_t(side.size()))
        {
            s.add
            (
                side.coupling(), side.patch().magSf().cdata(),
                side.totalConductance().cdata()
            );
        }
        // Over all processors: sums, and the extremes where there are any.
        const label nPartialHere = label(s.partial + s.beyondTable);
        scalar hMin = nPartialHere ? s.hPartialMin : GREAT;
        scalar hMax = nPartialHere ? s.hPartialMax : -GREAT;
        reduce(hMin, minOp<scalar>());
        reduce(hMax, maxOp<scalar>());
        s.hPartialMin = hMin;
        s.hPartialMax = hMax;
        for
        (
            scalar* x :
            {
                &s.area, &s.touchingArea, &s.partialArea, &s.pressureArea,
                &s.areaFractionArea, &s.areaFractionPartialArea,
                &s.hTouchingArea, &s.hPartialArea, &s.hAllArea, &s.gapAllArea
            }
        )
        {
            reduce(*x, sumOp<scalar>());
        }
        for
        (
            std::size_t* c : {&s.apart, &s.partial, &s.complete, &s.beyondTable}
        )
        {
            label n = label(*c);
            reduce(n, sumOp<label>());
            *c = std::size_t(n);
        }
        return s;
    }

    //- kappa dT/dn |S_f| summed: the heat [W] entering the side's cells
    //  through the interface (the face flux of the mixed condition)
    Foam::scalar heatIntoCells
    (
        const thermalContactResistanceFvPatchScalarField& side
    )
    {
        return Foam::gSum
        (
            side.sideKappa()*side.snGrad()*side.patch().magSf()
        );
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::thermalContactMonitor::storeFields
(
    const fvMesh& mesh,
    const thermalContactResistanceFvPatchScalarField& side
) const
{
    const label patchi = side.patch().index();
    const dimensionSet hDims(dimPower/dimArea/dimTemperature);
    const dimensionSet dims[nOutputs] =
        {hDims, dimless, dimPressure, dimless, hDims};
    const scalarField* values[nOutputs] =
    {
        &side.conductance(), &side.areaFraction(), &side.contactPressure(),
        &side.contactState(), &side.gapConductance()
    };
    for (label k = 0; k < nOutputs; ++k)
    {
        if
        (
            (side.constantConductance() && k != outConductance)
         || (k == outGap && !side.hasGap())
        )
        {
            continue;
        }
        if (!mesh.foundObject<volScalarField>(outputNames[k]))
        {
            volScalarField* f = new volScalarField
            (
                IOobject
                (
                    outputNames[k],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                mesh,
                dimensionedScalar(dims[k], Zero)
            );
            f->store();
        }
        volScalarField& f =
            mesh.lookupObjectRef<volScalarField>(outputNames[k]);
        f.boundaryFieldRef()[patchi] = *values[k];
    }
}


void Foam::functionObjects::thermalContactMonitor::report
(
    const thermalContactResistanceFvPatchScalarField& side
) const
{
    if (side.constantConductance())
    {
        Info<< "thermalContactResistance: " << side.who().c_str()
            << ": h = " << side.hConstant() << " W/m^2/K (constant)" << endl;
        return;
    }
    const ::roughContact::CouplingSummary s = summary(side);
    const label nPartial = label(s.partial + s.beyondTable);
    Info<< "thermalContactResistance: " << side.who().c_str() << ": ";
    if (nPartial > 0)
    {
        Info<< "h min/mean/max = " << s.hPartialMin << " / "
            << s.hPartialArea/s.partialArea << " / " << s.hPartialMax
            << " W/m^2/K, A_r/A_n mean = "
            << s.areaFractionPartialArea/s.partialArea
            << " (area-weighted over " << nPartial
            << " faces in partial contact)";
    }
    else
    {
        Info<< "no face in partial contact";
    }
    Info<< "; " << label(s.complete) << " faces in complete contact (h infinite),"
        << " " << label(s.apart) << " faces apart (P <= 0)" << endl;
}


void Foam::functionObjects::thermalContactMonitor::writeSeries
(
    const thermalContactResistanceFvPatchScalarField& side
)
{
    const thermalContactLine::neighbourMap nbrMap(side.patch());
    const word region(side.patch().boundaryMesh().mesh().name());
    const word nbrRegion(nbrMap.regionName());
    const word nbrPatchName(nbrMap.patchName());
    // One of the two sides writes: the one whose region (then patch) name
    // comes first.
    if
    (
        nbrRegion < region
     || (nbrRegion == region && nbrPatchName < side.patch().name())
    )
    {
        return;
    }
    const thermalContactResistanceFvPatchScalarField& nbr = side.neighbour();
    // Collective (every processor): the sums, then the master writes.
    const scalar heatFrom = -heatIntoCells(side);
    const scalar heatInto = heatIntoCells(nbr);
    const ::roughContact::CouplingSummary s = summary(side);
    if (!Pstream::master())
    {
        return;
    }
    const fileName dir =
        time_.globalPath()/"postProcessing"/"thermalContactResistance"
       /(region + "_" + side.patch().name())
       /time_.timeName(time_.startTime().value());
    const fileName series = dir/"interface.csv";
    // Started once per run: the header, and the table.
    if (started_.insert(series))
    {
        mkDir(dir);
        const std::string description =
            "interface of contact '" + side.contactName() + "' between "
          + region + "/" + side.patch().name() + " and " + nbrRegion + "/"
          + nbrPatchName;
        std::ofstream header(series, std::ios::trunc);
        header << ::roughContact::interfaceSeriesHeader(region, nbrRegion);
        std::ofstream table(dir/"table.csv", std::ios::trunc);
        ::roughContact::writeInterfaceTable(table, side.contactInterface());
        std::ofstream about(dir/"about.txt", std::ios::trunc);
        about
            << ::roughContact::interfaceAbout
               (
                   description, side.contactInterface()
               );
        if (!header || !table || !about)
        {
            WarningInFunction
                << side.who().c_str() << ": cannot write " << series
                << ", " << dir/"table.csv" << " or " << dir/"about.txt"
                << endl;
        }
        else
        {
            Info<< "thermalContactResistance: " << side.who().c_str()
                << ": writing the interface's time series to " << series
                << ", its table to table.csv and what they are to"
                << " about.txt beside it" << endl;
        }
    }
    std::ofstream os(series, std::ios::app);
    os << ::roughContact::interfaceSeriesRow
          (
              time_.value(), heatFrom, heatInto, s
          );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::thermalContactMonitor::thermalContactMonitor
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
#if defined(ROUGHCONTACT_FOUNDATION)
    functionObject(name, runTime),
#else
    timeFunctionObject(name, runTime),
#endif
    fieldName_("T")
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::thermalContactMonitor::read(const dictionary& dict)
{
    // Its own entry, and the controls every function object takes: anything
    // else (a misspelt control, an entry of another function object such as
    // `patches` or `region`) would be ignored without a word.
    static const char* const known[] =
    {
        "field",
        "type", "libs", "functionObjectLibs", "enabled", "log", "useNamePrefix",
        "timeStart", "timeEnd", "startTime", "endTime", "triggerStart",
        "triggerEnd", "controlMode", "deltaTCoeff", "nStepsToStartTimeChange",
        "executeControl", "executeInterval", "executeTimes", "executeAtStart",
        "writeControl", "writeInterval", "writeTimes", "writeAtStart",
        "outputControl", "outputInterval"
    };
    wordList allowed;
    for (const char* k : known)
    {
        allowed.append(word(k));
    }
    for (const word& key : dict.toc())
    {
        if (!allowed.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "function object '" << name() << "' (thermalContactMonitor):"
                << " unknown entry '" << key << "'; its entry is 'field' (the"
                << " temperature field, default T; every region and every"
                << " thermalContactResistance patch of it are monitored),"
                << " beside the function object controls "
                << foamCompat::listed(allowed) << exit(FatalIOError);
        }
    }
    fieldName_ = foamCompat::getOrDefault<word>(dict, "field", "T");
    dictName_ = dict.name();
    fieldChecked_ = false;
    return true;
}


void Foam::functionObjects::thermalContactMonitor::checkField() const
{
    // Once, at the first execution (the regions' fields exist by then): a
    // field no region has stops the run, one without a
    // thermalContactResistance patch is warned of; either would leave this
    // function object doing nothing, silently.
    if (fieldChecked_)
    {
        return;
    }
    fieldChecked_ = true;
    label patches = 0;
    wordList withField;
    for (const word& region : regions())
    {
        const fvMesh& mesh = time_.lookupObject<fvMesh>(region);
        if (!mesh.foundObject<volScalarField>(fieldName_))
        {
            continue;
        }
        withField.append(region);
        const volScalarField& T = mesh.lookupObject<volScalarField>(fieldName_);
        forAll(T.boundaryField(), patchi)
        {
            if (isA<thermalContactResistanceFvPatchScalarField>(T.boundaryField()[patchi]))
            {
                ++patches;
            }
        }
    }
    if (withField.empty())
    {
        FatalErrorInFunction
            << "function object '" << name() << "' (thermalContactMonitor) in "
            << dictName_ << ": entry 'field " << fieldName_ << "': no region"
            << " has a field '" << fieldName_ << "' (regions: "
            << foamCompat::listed(regions()) << "); the temperature field is"
            << " usually T" << exit(FatalError);
    }
    if (patches == 0)
    {
        // (a case compared with the stock condition keeps the function object)
        WarningInFunction
            << "function object '" << name() << "' (thermalContactMonitor) in "
            << dictName_ << ": the field '" << fieldName_ << "' of regions "
            << foamCompat::listed(withField) << " has no patch of type"
            << " thermalContactResistance: it writes nothing" << endl;
    }
}


Foam::List<const Foam::thermalContactResistanceFvPatchScalarField*>
Foam::functionObjects::thermalContactMonitor::sides(const fvMesh& mesh) const
{
    DynamicList<const thermalContactResistanceFvPatchScalarField*> out;
    if (!mesh.foundObject<volScalarField>(fieldName_))
    {
        return List<const thermalContactResistanceFvPatchScalarField*>();
    }
    const volScalarField& T = mesh.lookupObject<volScalarField>(fieldName_);
    forAll(T.boundaryField(), patchi)
    {
        const auto* side =
            isA<thermalContactResistanceFvPatchScalarField>
            (
                T.boundaryField()[patchi]
            );
        // (not before the solver evaluated it: nothing to show yet)
        if (side && side->evaluated())
        {
            out.append(side);
        }
    }
    return List<const thermalContactResistanceFvPatchScalarField*>(out);
}


Foam::wordList
Foam::functionObjects::thermalContactMonitor::regions() const
{
    // In name order: the same order on every processor (the series' sums
    // are collective).
    return time_.lookupClass<fvMesh>().sortedToc();
}


#if defined(ROUGHCONTACT_FOUNDATION)
Foam::wordList Foam::functionObjects::thermalContactMonitor::fields() const
{
    return wordList(1, fieldName_);
}
#endif


bool Foam::functionObjects::thermalContactMonitor::execute()
{
    checkField();
    // The fields, current after every step (another function object may
    // use them: tutorials/loadRamp averages them over the interface).
    for (const word& region : regions())
    {
        const fvMesh& mesh = time_.lookupObject<fvMesh>(region);
        for (const auto* side : sides(mesh))
        {
            storeFields(mesh, *side);
        }
    }
    return true;
}


bool Foam::functionObjects::thermalContactMonitor::write()
{
    execute(); // (checks the field first)
    for (const word& region : regions())
    {
        const fvMesh& mesh = time_.lookupObject<fvMesh>(region);
        const List<const thermalContactResistanceFvPatchScalarField*> list =
            sides(mesh);
        if (list.empty())
        {
            continue;
        }
        for (const char* name : outputNames)
        {
            if (mesh.foundObject<volScalarField>(name))
            {
                mesh.lookupObject<volScalarField>(name).write();
            }
        }
        for (const auto* side : list)
        {
            report(*side);
            if (!side->constantConductance())
            {
                writeSeries(*side);
            }
        }
    }
    return true;
}
