// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). Builds on OpenFOAM (Copyright
// OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later).
#include "thermalContactSettings.H"
#include "contactInterfaceFromDict.H"

#include "IOdictionary.H"
#include "foamCompat.H"
#include "Time.H"
#include "volFields.H"

#include <cmath>
#include <exception>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- A dictionary's contents as text, to tell whether it changed. Not
    //  dictionary::digest(): Debian 13's build of v1912 fails in its SHA1
    //  stream ("error in IOstream sha1"), and a comparison needs no hash.
    std::string entryText(const Foam::dictionary& dict)
    {
        Foam::OStringStream os;
        dict.write(os, false);
        return os.str();
    }
}



// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::thermalContactSettings::thermalContactSettings(const fileName& file)
:
    Tnbr("undefined-Tnbr"),
    dictName(file)
{}


Foam::thermalContactSettings::thermalContactSettings
(
    const dictionary& dict,
    const Time& runTime,
    const string& who,
    const fileName& fieldFile
)
:
    Tnbr(foamCompat::get<word>(dict, "Tnbr")),
    dictName(dict.name()),
    dictStart(dict.startLineNumber()),
    dictEnd(dict.endLineNumber())
{
    const bool hasH = dict.found("h");
    const bool hasContact = dict.found("contact");
    if (hasH == hasContact)
    {
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": give exactly one of the entries 'h' (a"
            << " constant conductance [W/m^2/K]) and 'contact' (an entry of"
            << " constant/thermalContactProperties)" << exit(FatalIOError);
    }
    mode = hasH ? conductanceMode::constantH : conductanceMode::contact;
    if (hasH)
    {
        hConstant = foamCompat::get<scalar>(dict, "h");
        if (!(hConstant > 0) || !std::isfinite(hConstant))
        {
            FatalIOErrorInFunction(dict)
                << who.c_str() << ": entry 'h' must be a finite conductance"
                << " > 0 [W/m^2/K], got " << hConstant << exit(FatalIOError);
        }
        for (const char* other : {"pressure", "pressureField", "gap", "gapField"})
        {
            if (dict.found(other))
            {
                FatalIOErrorInFunction(dict)
                    << who.c_str() << ": entry '" << other << "' has no"
                    << " meaning with a constant 'h'; remove one of them"
                    << exit(FatalIOError);
            }
        }
        return;
    }

    contactName = foamCompat::get<word>(dict, "contact");
    const bool hasP = dict.found("pressure");
    const bool hasPField = dict.found("pressureField");
    if (hasP == hasPField)
    {
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": give exactly one of the entries 'pressure'"
            << " (a PatchFunction1, Pa) and 'pressureField' (the name of a"
            << " volScalarField, Pa)" << exit(FatalIOError);
    }
    if (hasP)
    {
        // (built by the condition: a PatchFunction1 is bound to its patch)
        pressureGiven = true;
    }
    else
    {
        pressureFieldName = foamCompat::get<word>(dict, "pressureField");
    }

    // One place both sides read: constant/thermalContactProperties.
    const word propsName("thermalContactProperties");
    if (!runTime.foundObject<IOdictionary>(propsName))
    {
        IOobject io
        (
            propsName,
            runTime.constant(),
            runTime,
            // Re-read when modified (runTimeModifiable yes), only so that
            // checkContactUnchanged() can say that a change is ignored.
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        );
        if (!foamCompat::dictionaryHeaderOk(io))
        {
            FatalIOErrorInFunction(dict)
                << who.c_str() << ": entry 'contact " << contactName
                << "' needs the file constant/" << propsName << " of the"
                << " case (" << runTime.globalPath()/"constant"/propsName
                << "), which cannot be read" << exit(FatalIOError);
        }
        IOdictionary* props = new IOdictionary(io);
        props->store();
    }
    const IOdictionary& props =
        runTime.lookupObject<IOdictionary>(propsName);
    if (!props.isDict(contactName))
    {
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": entry 'contact " << contactName
            << "': there is no dictionary '" << contactName << "' in "
            << props.objectPath() << " (it has: "
            << foamCompat::listed(props.toc()) << ")" << exit(FatalIOError);
    }
    interface = contactInterfaceFromDict
    (
        runTime, props, contactName, props.objectPath(), runTime.globalPath(),
        who
    );
    contactKey = Foam::contactKey(props.objectPath(), contactName);
    try
    {
        surfaceChecksum = interface->surfaceChecksum();
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(dict)
            << who.c_str() << ": entry 'contact " << contactName
            << "' (" << props.objectPath() << "): the surface's checksum: "
            << e.what() << exit(FatalIOError);
    }
    contactDigest = entryText(props.subDict(contactName));
    readTimeIndex = runTime.timeIndex();
    checkRecordedSurface(dict, who, fieldFile);

    // The width of the gap where the surfaces do not touch (P <= 0).
    const bool hasGap = dict.found("gap");
    const bool hasGapField = dict.found("gapField");
    if (hasGap || hasGapField)
    {
        if (hasGap && hasGapField)
        {
            FatalIOErrorInFunction(dict)
                << who.c_str() << ": give at most one of the entries 'gap'"
                << " (a uniform gap width [m] of faces apart) and 'gapField'"
                << " (the name of a volScalarField of gap widths [m])"
                << exit(FatalIOError);
        }
        if (!interface->hasGap())
        {
            FatalIOErrorInFunction(dict)
                << who.c_str() << ": entry '"
                << (hasGap ? "gap" : "gapField") << "': the contact '"
                << contactName << "' of " << props.objectPath() << " has no"
                << " gap sub-dictionary (gas, emissivity), so nothing would"
                << " cross the gap: add one, or remove this entry"
                << exit(FatalIOError);
        }
        if (hasGap)
        {
            gapWidth = foamCompat::get<scalar>(dict, "gap");
            if (!(gapWidth >= 0) || !std::isfinite(gapWidth))
            {
                FatalIOErrorInFunction(dict)
                    << who.c_str() << ": entry 'gap' must be a finite gap"
                    << " width >= 0 [m], got " << gapWidth
                    << exit(FatalIOError);
            }
        }
        else
        {
            gapFieldName = foamCompat::get<word>(dict, "gapField");
        }
    }
}



// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::thermalContactSettings::checkRecordedSurface
(
    const dictionary& dict,
    const string& who,
    const fileName& fieldFile
) const
{
    string recorded;
    if (!dict.readIfPresent("surfaceChecksum", recorded))
    {
        return;
    }
    if (recorded != surfaceChecksum)
    {
        WarningInFunction
            << who.c_str() << ": the field file "
            << fieldFile << " records the surface of"
            << " the run that wrote it as surfaceChecksum " << recorded.c_str()
            << ", but the surface of contact '" << contactName
            << "' now read (" << interface->surface().source().c_str()
            << ") has the checksum " << surfaceChecksum.c_str() << "."
            << " The surface has changed since the recorded run: h and"
            << " A_r/A_n will change from that run's." << endl;
    }
}


void Foam::thermalContactSettings::checkContactUnchanged
(
    const Time& runTime,
    const std::function<string()>& who,
    contactWatch& watch
) const
{
    if
    (
        watch.warned
     || runTime.timeIndex() == watch.checkedTimeIndex
     || runTime.timeIndex() == readTimeIndex
    )
    {
        return;
    }
    // Files are re-read between time steps: one comparison per step.
    watch.checkedTimeIndex = runTime.timeIndex();
    const IOdictionary& props =
        runTime.lookupObject<IOdictionary>("thermalContactProperties");
    const dictionary* entry = foamCompat::findDict(props, contactName);
    if (!entry || entryText(*entry) != contactDigest)
    {
        WarningInFunction
            << who().c_str() << ": entry '" << contactName << "' of "
            << props.objectPath() << " has been "
            << (entry ? "changed" : "removed") << " during the run. The"
            << " change is ignored: the contact table stays as it was built"
            << " at the start (surface, materials, model, pressure range)"
            << " until the run is restarted." << endl;
        watch.warned = true;
    }
}



Foam::tmp<Foam::scalarField> Foam::thermalContactSettings::patchValues
(
    const fvPatch& patch,
    const word& fieldName,
    const char* entry,
    const std::function<string()>& who
) const
{
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    if (!mesh.foundObject<volScalarField>(fieldName))
    {
        FatalIOErrorAt(dictName, dictStart, dictEnd)
            << who().c_str() << ": entry '" << entry << " " << fieldName
            << "': region " << mesh.name() << " has no volScalarField '"
            << fieldName << "' (read it, e.g. with the readFields function"
            << " object, or let a solver or function object create it)"
            << exit(FatalIOError);
    }
    return
        mesh.lookupObject<volScalarField>(fieldName)
       .boundaryField()[patch.index()];
}


Foam::string Foam::thermalContactSettings::disagreement
(
    const thermalContactSettings& nbr
) const
{
    if (mode != nbr.mode)
    {
        return "one side gives 'h', the other 'contact'";
    }
    if (mode == conductanceMode::constantH && hConstant != nbr.hConstant)
    {
        return
            "the two sides give different 'h' (" + Foam::name(hConstant)
          + " and " + Foam::name(nbr.hConstant) + ")";
    }
    if (mode == conductanceMode::contact && contactName != nbr.contactName)
    {
        return
            "the two sides name different 'contact' entries ('"
          + contactName + "' and '" + nbr.contactName + "')";
    }
    if (hasGapWidth() != nbr.hasGapWidth())
    {
        return
            "one side gives the gap width of faces apart ('gap' or"
            " 'gapField'), the other does not";
    }
    return string();
}


void Foam::thermalContactSettings::write(Ostream& os) const
{
    foamCompat::writeEntry(os, "Tnbr", Tnbr);
    if (mode == conductanceMode::constantH)
    {
        foamCompat::writeEntry(os, "h", hConstant);
        return;
    }
    foamCompat::writeEntry(os, "contact", contactName);
    // What this run used: a restart compares it (checkRecordedSurface).
    foamCompat::writeEntry(os, "surfaceChecksum", surfaceChecksum);
}


void Foam::thermalContactSettings::writeGap(Ostream& os) const
{
    if (!gapFieldName.empty())
    {
        foamCompat::writeEntry(os, "gapField", gapFieldName);
    }
    else if (gapWidth >= 0)
    {
        foamCompat::writeEntry(os, "gap", gapWidth);
    }
}
