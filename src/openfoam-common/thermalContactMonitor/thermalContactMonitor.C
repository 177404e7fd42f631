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

#include <algorithm>
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
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
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
            dynamic_cast<const thermalContactResistanceFvPatchScalarField*>
            (
                &T.boundaryField()[patchi]
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
