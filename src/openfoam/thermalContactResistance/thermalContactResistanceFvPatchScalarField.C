// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later): the
// coupled-baffle arithmetic and structure follow compressible::
// turbulentTemperatureCoupledBaffleMixedFvPatchScalarField and temperatureCoupledBase.
#include "thermalContactResistanceFvPatchScalarField.H"
#include "contactInterfaceFromDict.H"

#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "mappedPatchBase.H"
#include "IOdictionary.H"
#include "StringStream.H"

#include "roughContact/thermal/InterfaceCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

// An error found at run time (not while reading the dictionary): FatalIOError
// naming the file and lines the condition was read from.
#define RuntimeIOError                                                         \
    ::Foam::FatalIOError                                                       \
    (                                                                          \
        FUNCTION_NAME, __FILE__, __LINE__, dictName_, dictStart_, dictEnd_     \
    )

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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::thermalContactResistanceFvPatchScalarField::who() const
{
    return
        "patch " + patch().name() + " of field " + internalField().name()
      + " in region " + patch().boundaryMesh().mesh().name();
}


void Foam::thermalContactResistanceFvPatchScalarField::checkPatch() const
{
    if (!isA<mappedPatchBase>(patch().patch()))
    {
        RuntimeIOError
            << who().c_str() << ": thermalContactResistance needs a mapped"
            << " patch (mappedWall) coupling two regions; this patch is of"
            << " type '" << patch().patch().type() << "'"
            << exit(FatalIOError);
    }
}


void Foam::thermalContactResistanceFvPatchScalarField::readContact
(
    const dictionary& dict
)
{
    const bool hasH = dict.found("h");
    const bool hasContact = dict.found("contact");
    if (hasH == hasContact)
    {
        FatalIOErrorInFunction(dict)
            << who().c_str() << ": give exactly one of the entries 'h' (a"
            << " constant conductance [W/m^2/K]) and 'contact' (an entry of"
            << " constant/thermalContactProperties)" << exit(FatalIOError);
    }
    mode_ = hasH ? conductanceMode::constantH : conductanceMode::contact;
    if (hasH)
    {
        hConstant_ = dict.get<scalar>("h");
        if (!(hConstant_ > 0) || !std::isfinite(hConstant_))
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry 'h' must be a finite conductance"
                << " > 0 [W/m^2/K], got " << hConstant_ << exit(FatalIOError);
        }
        for (const char* other : {"pressure", "pressureField", "gap", "gapField"})
        {
            if (dict.found(other))
            {
                FatalIOErrorInFunction(dict)
                    << who().c_str() << ": entry '" << other << "' has no"
                    << " meaning with a constant 'h'; remove one of them"
                    << exit(FatalIOError);
            }
        }
        return;
    }

    contactName_ = dict.get<word>("contact");
    const bool hasP = dict.found("pressure");
    const bool hasPField = dict.found("pressureField");
    if (hasP == hasPField)
    {
        FatalIOErrorInFunction(dict)
            << who().c_str() << ": give exactly one of the entries 'pressure'"
            << " (a PatchFunction1, Pa) and 'pressureField' (the name of a"
            << " volScalarField, Pa)" << exit(FatalIOError);
    }
    if (hasP)
    {
        pressure_ =
            PatchFunction1<scalar>::New(patch().patch(), "pressure", dict);
    }
    else
    {
        pressureFieldName_ = dict.get<word>("pressureField");
    }

    // One place both sides read: constant/thermalContactProperties.
    const Time& runTime = db().time();
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
        if (!io.typeHeaderOk<IOdictionary>(true))
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry 'contact " << contactName_
                << "' needs the file constant/" << propsName << " of the"
                << " case (" << runTime.globalPath()/"constant"/propsName
                << "), which cannot be read" << exit(FatalIOError);
        }
        IOdictionary* props = new IOdictionary(io);
        props->store();
    }
    const IOdictionary& props =
        runTime.lookupObject<IOdictionary>(propsName);
    if (!props.isDict(contactName_))
    {
        FatalIOErrorInFunction(dict)
            << who().c_str() << ": entry 'contact " << contactName_
            << "': there is no dictionary '" << contactName_ << "' in "
            << props.objectPath() << " (it has: "
            << flatOutput(props.toc()) << ")" << exit(FatalIOError);
    }
    interface_ = contactInterfaceFromDict
    (
        runTime, props, contactName_, props.objectPath(), runTime.globalPath(),
        who()
    );
    try
    {
        surfaceChecksum_ = interface_->surfaceChecksum();
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(dict)
            << who().c_str() << ": entry 'contact " << contactName_
            << "' (" << props.objectPath() << "): the surface's checksum: "
            << e.what() << exit(FatalIOError);
    }
    contactDigest_ = entryText(props.subDict(contactName_));
    contactCheckedTimeIndex_ = runTime.timeIndex();
    checkRecordedSurface(dict);

    // The width of the gap where the surfaces do not touch (P <= 0).
    const bool hasGap = dict.found("gap");
    const bool hasGapField = dict.found("gapField");
    if (hasGap || hasGapField)
    {
        if (hasGap && hasGapField)
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": give at most one of the entries 'gap'"
                << " (a uniform gap width [m] of faces apart) and 'gapField'"
                << " (the name of a volScalarField of gap widths [m])"
                << exit(FatalIOError);
        }
        if (!interface_->hasGap())
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry '"
                << (hasGap ? "gap" : "gapField") << "': the contact '"
                << contactName_ << "' of " << props.objectPath() << " has no"
                << " gap sub-dictionary (gas, emissivity), so nothing would"
                << " cross the gap: add one, or remove this entry"
                << exit(FatalIOError);
        }
        if (hasGap)
        {
            gapWidth_ = dict.get<scalar>("gap");
            if (!(gapWidth_ >= 0) || !std::isfinite(gapWidth_))
            {
                FatalIOErrorInFunction(dict)
                    << who().c_str() << ": entry 'gap' must be a finite gap"
                    << " width >= 0 [m], got " << gapWidth_
                    << exit(FatalIOError);
            }
        }
        else
        {
            gapFieldName_ = dict.get<word>("gapField");
        }
    }
}


void Foam::thermalContactResistanceFvPatchScalarField::checkRecordedSurface
(
    const dictionary& dict
) const
{
    string recorded;
    if (!dict.readIfPresent("surfaceChecksum", recorded))
    {
        return;
    }
    if (recorded != surfaceChecksum_)
    {
        WarningInFunction
            << who().c_str() << ": the field file "
            << internalField().objectPath() << " records the surface of"
            << " the run that wrote it as surfaceChecksum " << recorded.c_str()
            << ", but the surface of contact '" << contactName_
            << "' now read (" << interface_->surface().source().c_str()
            << ") has the checksum " << surfaceChecksum_.c_str() << "."
            << " The surface has changed since the recorded run: h and"
            << " A_r/A_n will change from that run's." << endl;
    }
}


void Foam::thermalContactResistanceFvPatchScalarField::checkContactUnchanged()
{
    const Time& runTime = db().time();
    if
    (
        warnedContactChanged_
     || runTime.timeIndex() == contactCheckedTimeIndex_
    )
    {
        return;
    }
    // Files are re-read between time steps: one comparison per step.
    contactCheckedTimeIndex_ = runTime.timeIndex();
    const IOdictionary& props =
        runTime.lookupObject<IOdictionary>("thermalContactProperties");
    const dictionary* entry = props.findDict(contactName_);
    if (!entry || entryText(*entry) != contactDigest_)
    {
        WarningInFunction
            << who().c_str() << ": entry '" << contactName_ << "' of "
            << props.objectPath() << " has been "
            << (entry ? "changed" : "removed") << " during the run. The"
            << " change is ignored: the contact table stays as it was built"
            << " at the start (surface, materials, model, pressure range)"
            << " until the run is restarted." << endl;
        warnedContactChanged_ = true;
    }
}


void Foam::thermalContactResistanceFvPatchScalarField::checkKappaField() const
{
    if (method_ != mtLookup)
    {
        return;
    }
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    if
    (
        !mesh.foundObject<volScalarField>(kappaName_)
     && !mesh.foundObject<volSymmTensorField>(kappaName_)
    )
    {
        RuntimeIOError
            << who().c_str() << ": entry 'kappa " << kappaName_ << "'"
            << " (kappaMethod lookup): region " << mesh.name() << " has no"
            << " volScalarField or volSymmTensorField '" << kappaName_
            << "' (volScalarFields: "
            << flatOutput(mesh.sortedNames<volScalarField>()) << ")"
            << exit(FatalIOError);
    }
}


void Foam::thermalContactResistanceFvPatchScalarField::checkNeighbour
(
    const thermalContactResistanceFvPatchScalarField& nbr
)
{
    string problem;
    if (mode_ != nbr.mode_)
    {
        problem = "one side gives 'h', the other 'contact'";
    }
    else if (mode_ == conductanceMode::constantH && hConstant_ != nbr.hConstant_)
    {
        problem =
            "the two sides give different 'h' (" + Foam::name(hConstant_)
          + " and " + Foam::name(nbr.hConstant_) + ")";
    }
    else if (mode_ == conductanceMode::contact && contactName_ != nbr.contactName_)
    {
        problem =
            "the two sides name different 'contact' entries ('"
          + contactName_ + "' and '" + nbr.contactName_ + "')";
    }
    else if (hasGapWidth() != nbr.hasGapWidth())
    {
        problem =
            "one side gives the gap width of faces apart ('gap' or"
            " 'gapField'), the other does not";
    }
    if (!problem.empty())
    {
        RuntimeIOError
            << who().c_str() << " and its neighbour " << nbr.who().c_str()
            << ": " << problem.c_str() << "; both sides of an interface must"
            << " agree (one conductance, or the heat leaving one side would"
            << " not be the heat entering the other)" << exit(FatalIOError);
    }
    checkedNeighbour_ = true;
}


const Foam::fvPatchScalarField*
Foam::thermalContactResistanceFvPatchScalarField::neighbourField
(
    const bool mustExist
) const
{
    const mappedPatchBase& mpp =
        refCast<const mappedPatchBase>(patch().patch());
    if
    (
        !mustExist
     && (
            mpp.sameRegion()
         || !db().time().foundObject<polyMesh>(mpp.sampleRegion())
        )
    )
    {
        return nullptr;
    }
    const polyMesh& nbrMesh = mpp.sampleMesh();
    if (!nbrMesh.foundObject<volScalarField>(TnbrName_))
    {
        if (!mustExist)
        {
            return nullptr;
        }
        RuntimeIOError
            << who().c_str() << ": entry 'Tnbr " << TnbrName_ << "': the"
            << " neighbour region " << nbrMesh.name() << " has no"
            << " volScalarField '" << TnbrName_ << "' (it has: "
            << flatOutput(nbrMesh.sortedNames<volScalarField>()) << ")"
            << exit(FatalIOError);
    }
    const fvPatchScalarField& nbrPf =
        nbrMesh.lookupObject<volScalarField>(TnbrName_)
       .boundaryField()[mpp.samplePolyPatch().index()];
    if (!isA<thermalContactResistanceFvPatchScalarField>(nbrPf))
    {
        RuntimeIOError
            << who().c_str() << ": the neighbour patch "
            << nbrPf.patch().name() << " of region " << nbrMesh.name()
            << " has " << TnbrName_ << " of type '" << nbrPf.type()
            << "' (" << nbrPf.internalField().objectPath() << "); both sides"
            << " of the interface must be thermalContactResistance"
            << exit(FatalIOError);
    }
    return &nbrPf;
}


const Foam::dictionary&
Foam::thermalContactResistanceFvPatchScalarField::checkedKappaMethod
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
{
    const word method(dict.get<word>("kappaMethod"));
    if (!temperatureCoupledBase::KMethodTypeNames_.found(method))
    {
        FatalIOErrorInFunction(dict)
            << "patch " << p.name() << " of field " << iF.name()
            << " in region " << p.boundaryMesh().mesh().name()
            << ": entry 'kappaMethod " << method << "': unknown; one of "
            << flatOutput(temperatureCoupledBase::KMethodTypeNames_.sortedToc())
            << exit(FatalIOError);
    }
    return dict;
}


const Foam::thermalContactResistanceFvPatchScalarField&
Foam::thermalContactResistanceFvPatchScalarField::neighbour() const
{
    return refCast<const thermalContactResistanceFvPatchScalarField>
    (
        *neighbourField(true)
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(p, iF),
#if OPENFOAM >= 2212
    // The word-based constructor was removed in v2212; as the stock
    // turbulentTemperatureCoupledBaffleMixed: the default method (fluidThermo)
    temperatureCoupledBase(patch()),
#else
    temperatureCoupledBase
    (
        patch(), "undefined", "undefined", "undefined-K", "undefined-alpha"
    ),
#endif
    TnbrName_("undefined-Tnbr"),
    contactName_(),
    mode_(conductanceMode::contact),
    hConstant_(0),
    pressure_(),
    pressureFieldName_(),
    gapWidth_(-1),
    gapFieldName_(),
    interface_(),
    surfaceChecksum_(),
    contactDigest_(),
    contactCheckedTimeIndex_(-1),
    areaFraction_(p.size(), Zero),
    conductance_(p.size(), Zero),
    contactPressure_(p.size(), Zero),
    contactState_(p.size(), Zero),
    gapConductance_(p.size(), Zero),
    totalConductance_(p.size(), Zero),
    evaluated_(false),
    dictName_(iF.objectPath()),
    dictStart_(-1),
    dictEnd_(-1),
    checkedNeighbour_(false),
    warnedNoContact_(false),
    warnedBeyondTable_(false),
    warnedInput_(0),
    warnedContactChanged_(false)
{
    this->refValue() = 0.0;
    this->refGrad() = 0.0;
    this->valueFraction() = 1.0;
}


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    mixedFvPatchScalarField(p, iF),
    temperatureCoupledBase(patch(), checkedKappaMethod(p, iF, dict)),
    TnbrName_(dict.get<word>("Tnbr")),
    contactName_(),
    mode_(conductanceMode::contact),
    hConstant_(0),
    pressure_(),
    pressureFieldName_(),
    gapWidth_(-1),
    gapFieldName_(),
    interface_(),
    surfaceChecksum_(),
    contactDigest_(),
    contactCheckedTimeIndex_(-1),
    areaFraction_(p.size(), Zero),
    conductance_(p.size(), Zero),
    contactPressure_(p.size(), Zero),
    contactState_(p.size(), Zero),
    gapConductance_(p.size(), Zero),
    totalConductance_(p.size(), Zero),
    evaluated_(false),
    dictName_(dict.name()),
    dictStart_(dict.startLineNumber()),
    dictEnd_(dict.endLineNumber()),
    checkedNeighbour_(false),
    warnedNoContact_(false),
    warnedBeyondTable_(false),
    warnedInput_(0),
    warnedContactChanged_(false)
{
    checkPatch();
    readContact(dict);
    // The neighbour's field exists already when this region is read after
    // it: a neighbour of another type is reported here, before that other
    // condition (evaluated first) fails on it with no patch or file named.
    neighbourField(false);

    fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    if (dict.found("refValue"))
    {
        // Restart: the mixed condition's state as written
        refValue() = scalarField("refValue", dict, p.size());
        refGrad() = scalarField("refGradient", dict, p.size());
        valueFraction() = scalarField("valueFraction", dict, p.size());
    }
    else
    {
        refValue() = *this;
        refGrad() = 0.0;
        valueFraction() = 1.0;
    }
}


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    temperatureCoupledBase(patch(), ptf),
    TnbrName_(ptf.TnbrName_),
    contactName_(ptf.contactName_),
    mode_(ptf.mode_),
    hConstant_(ptf.hConstant_),
    pressure_(),
    pressureFieldName_(ptf.pressureFieldName_),
    gapWidth_(ptf.gapWidth_),
    gapFieldName_(ptf.gapFieldName_),
    interface_(ptf.interface_),
    surfaceChecksum_(ptf.surfaceChecksum_),
    contactDigest_(ptf.contactDigest_),
    contactCheckedTimeIndex_(ptf.contactCheckedTimeIndex_),
    areaFraction_(ptf.areaFraction_, mapper),
    conductance_(ptf.conductance_, mapper),
    contactPressure_(ptf.contactPressure_, mapper),
    contactState_(ptf.contactState_, mapper),
    gapConductance_(ptf.gapConductance_, mapper),
    totalConductance_(ptf.totalConductance_, mapper),
    evaluated_(ptf.evaluated_),
    dictName_(ptf.dictName_),
    dictStart_(ptf.dictStart_),
    dictEnd_(ptf.dictEnd_),
    checkedNeighbour_(false),
    warnedNoContact_(ptf.warnedNoContact_),
    warnedBeyondTable_(ptf.warnedBeyondTable_),
    warnedInput_(ptf.warnedInput_),
    warnedContactChanged_(ptf.warnedContactChanged_)
{
    if (ptf.pressure_.valid())
    {
        // Map the values on the old patch (a nonuniform list must follow its
        // faces into, e.g., a processor patch), then rebind to the new patch.
        // v1912's clone(newPatch) alone would truncate the list to the new size.
        autoPtr<PatchFunction1<scalar>> onOld(ptf.pressure_().clone().ptr());
        onOld->autoMap(mapper);
        pressure_.reset(onOld().clone(p.patch()).ptr());
    }
}


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf
)
:
    mixedFvPatchScalarField(ptf),
    temperatureCoupledBase(patch(), ptf),
    TnbrName_(ptf.TnbrName_),
    contactName_(ptf.contactName_),
    mode_(ptf.mode_),
    hConstant_(ptf.hConstant_),
    pressure_
    (
        ptf.pressure_.valid()
      ? ptf.pressure_().clone(patch().patch()).ptr()
      : nullptr
    ),
    pressureFieldName_(ptf.pressureFieldName_),
    gapWidth_(ptf.gapWidth_),
    gapFieldName_(ptf.gapFieldName_),
    interface_(ptf.interface_),
    surfaceChecksum_(ptf.surfaceChecksum_),
    contactDigest_(ptf.contactDigest_),
    contactCheckedTimeIndex_(ptf.contactCheckedTimeIndex_),
    areaFraction_(ptf.areaFraction_),
    conductance_(ptf.conductance_),
    contactPressure_(ptf.contactPressure_),
    contactState_(ptf.contactState_),
    gapConductance_(ptf.gapConductance_),
    totalConductance_(ptf.totalConductance_),
    evaluated_(ptf.evaluated_),
    dictName_(ptf.dictName_),
    dictStart_(ptf.dictStart_),
    dictEnd_(ptf.dictEnd_),
    checkedNeighbour_(ptf.checkedNeighbour_),
    warnedNoContact_(ptf.warnedNoContact_),
    warnedBeyondTable_(ptf.warnedBeyondTable_),
    warnedInput_(ptf.warnedInput_),
    warnedContactChanged_(ptf.warnedContactChanged_)
{}


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    temperatureCoupledBase(patch(), ptf),
    TnbrName_(ptf.TnbrName_),
    contactName_(ptf.contactName_),
    mode_(ptf.mode_),
    hConstant_(ptf.hConstant_),
    pressure_
    (
        ptf.pressure_.valid()
      ? ptf.pressure_().clone(patch().patch()).ptr()
      : nullptr
    ),
    pressureFieldName_(ptf.pressureFieldName_),
    gapWidth_(ptf.gapWidth_),
    gapFieldName_(ptf.gapFieldName_),
    interface_(ptf.interface_),
    surfaceChecksum_(ptf.surfaceChecksum_),
    contactDigest_(ptf.contactDigest_),
    contactCheckedTimeIndex_(ptf.contactCheckedTimeIndex_),
    areaFraction_(ptf.areaFraction_),
    conductance_(ptf.conductance_),
    contactPressure_(ptf.contactPressure_),
    contactState_(ptf.contactState_),
    gapConductance_(ptf.gapConductance_),
    totalConductance_(ptf.totalConductance_),
    evaluated_(ptf.evaluated_),
    dictName_(ptf.dictName_),
    dictStart_(ptf.dictStart_),
    dictEnd_(ptf.dictEnd_),
    checkedNeighbour_(ptf.checkedNeighbour_),
    warnedNoContact_(ptf.warnedNoContact_),
    warnedBeyondTable_(ptf.warnedBeyondTable_),
    warnedInput_(ptf.warnedInput_),
    warnedContactChanged_(ptf.warnedContactChanged_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfacePressure() const
{
    if (pressure_.valid())
    {
        return pressure_->value(db().time().timeOutputValue());
    }
    if (!pressureFieldName_.empty())
    {
        const fvMesh& mesh = patch().boundaryMesh().mesh();
        if (!mesh.foundObject<volScalarField>(pressureFieldName_))
        {
            RuntimeIOError
                << who().c_str() << ": entry 'pressureField "
                << pressureFieldName_ << "': region " << mesh.name()
                << " has no volScalarField '" << pressureFieldName_
                << "' (read it, e.g. with the readFields function object,"
                << " or let a solver or function object create it)"
                << exit(FatalIOError);
        }
        return
            mesh.lookupObject<volScalarField>(pressureFieldName_)
           .boundaryField()[patch().index()];
    }
    return tmp<scalarField>(new scalarField(size(), Zero));
}


Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfaceGapWidth() const
{
    if (!gapFieldName_.empty())
    {
        const fvMesh& mesh = patch().boundaryMesh().mesh();
        if (!mesh.foundObject<volScalarField>(gapFieldName_))
        {
            RuntimeIOError
                << who().c_str() << ": entry 'gapField "
                << gapFieldName_ << "': region " << mesh.name()
                << " has no volScalarField '" << gapFieldName_
                << "' (read it, e.g. with the readFields function object,"
                << " or let a solver or function object create it)"
                << exit(FatalIOError);
        }
        return
            mesh.lookupObject<volScalarField>(gapFieldName_)
           .boundaryField()[patch().index()];
    }
    return tmp<scalarField>(new scalarField(size(), max(gapWidth_, 0.0)));
}


void Foam::thermalContactResistanceFvPatchScalarField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    mixedFvPatchScalarField::autoMap(m);
#if OPENFOAM >= 2112
    // kappaMethod function (v2112): its PatchFunction1 is mapped by the base
    temperatureCoupledBase::autoMap(m);
#endif
    if (pressure_.valid())
    {
        pressure_->autoMap(m);
    }
    areaFraction_.autoMap(m);
    conductance_.autoMap(m);
    contactPressure_.autoMap(m);
    contactState_.autoMap(m);
    gapConductance_.autoMap(m);
    totalConductance_.autoMap(m);
    coupling_ = {};
    couplingCache_ = {};
    nbrDeltaCoeffs_.clear();
    haveNbrDeltaCoeffs_ = false;
}


void Foam::thermalContactResistanceFvPatchScalarField::rmap
(
    const fvPatchScalarField& ptf,
    const labelList& addr
)
{
    mixedFvPatchScalarField::rmap(ptf, addr);
#if OPENFOAM >= 2112
    temperatureCoupledBase::rmap(ptf, addr);
#endif
    const auto& tiptf =
        refCast<const thermalContactResistanceFvPatchScalarField>(ptf);
    if (pressure_.valid() && tiptf.pressure_.valid())
    {
        pressure_->rmap(tiptf.pressure_(), addr);
    }
    areaFraction_.rmap(tiptf.areaFraction_, addr);
    conductance_.rmap(tiptf.conductance_, addr);
    contactPressure_.rmap(tiptf.contactPressure_, addr);
    contactState_.rmap(tiptf.contactState_, addr);
    gapConductance_.rmap(tiptf.gapConductance_, addr);
    totalConductance_.rmap(tiptf.totalConductance_, addr);
    coupling_ = {};
    couplingCache_ = {};
    nbrDeltaCoeffs_.clear();
    haveNbrDeltaCoeffs_ = false;
}


void Foam::thermalContactResistanceFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    // Inside initEvaluate/evaluate there may be processor comms underway.
    const int oldTag = UPstream::msgType();
    UPstream::msgType() = oldTag + 1;

    const mappedPatchBase& mpp =
        refCast<const mappedPatchBase>(patch().patch());
    const polyMesh& nbrMesh = mpp.sampleMesh();
    const label samplePatchi = mpp.samplePolyPatch().index();
    const fvPatch& nbrPatch =
        refCast<const fvMesh>(nbrMesh).boundary()[samplePatchi];

    const auto& nbrField =
        refCast<const thermalContactResistanceFvPatchScalarField>
        (
            *neighbourField(true)
        );
    if (!checkedNeighbour_)
    {
        checkNeighbour(nbrField);
    }

    checkKappaField();
    const scalarField myKappa(kappa(*this));
    const scalarField& myDeltaCoeffs = patch().deltaCoeffs();

    // The per-face physics is the core's (roughContact::couple and
    // coupleConstant, interface/FaceCoupling.hpp): this gathers both sides'
    // arrays, calls it once and hands its results to the mixed condition.
    roughContact::CouplingInputs in;
    in.n = size();
    in.kappa = myKappa.cdata();
    in.deltaCoeffs = myDeltaCoeffs.cdata();

    // What this side needs of the neighbour, in one exchange: its cell
    // temperature (contact) or face temperature (h), kappa and pressure per
    // face; with a gap also its face temperature and gap width (a
    // symmTensor's six components carry the five); and (once, while the mesh
    // does not change) its deltaCoeffs.
    const bool withGap = mode_ == conductanceMode::contact && interface_->hasGap();
    const label nNbr = nbrPatch.size();
    scalarField nbrT(size());
    scalarField nbrKappa(size());
    scalarField nbrP(size());
    scalarField nbrTface;
    scalarField nbrGapWidth;
    nbrField.checkKappaField();
    {
        const scalarField T
        (
            mode_ == conductanceMode::constantH
          ? scalarField(nbrField)
          : nbrField.patchInternalField()()
        );
        const scalarField K(nbrField.kappa(nbrField));
        const scalarField P(nbrField.interfacePressure());
        if (!withGap)
        {
            vectorField nbrData(nNbr);
            for (label i = 0; i < nNbr; ++i)
            {
                nbrData[i] = vector(T[i], K[i], P[i]);
            }
            mpp.distribute(nbrData);
            forAll(nbrData, i)
            {
                nbrT[i] = nbrData[i].x();
                nbrKappa[i] = nbrData[i].y();
                nbrP[i] = nbrData[i].z();
            }
        }
        else
        {
            const bool widths = nbrField.hasGapWidth();
            const scalarField W
            (
                widths ? nbrField.interfaceGapWidth()() : scalarField(nNbr, Zero)
            );
            const scalarField& Tf = nbrField;
            symmTensorField nbrData(nNbr);
            for (label i = 0; i < nNbr; ++i)
            {
                nbrData[i] = symmTensor(T[i], K[i], P[i], Tf[i], W[i], 0);
            }
            mpp.distribute(nbrData);
            nbrTface.setSize(size());
            nbrGapWidth.setSize(size());
            forAll(nbrData, i)
            {
                const symmTensor& d = nbrData[i];
                nbrT[i] = d.xx();
                nbrKappa[i] = d.xy();
                nbrP[i] = d.xz();
                nbrTface[i] = d.yy();
                nbrGapWidth[i] = d.yz();
            }
        }
    }
    // distribute() is collective: decide on what every processor knows
    // alike (not on this processor's, possibly empty, face count).
    if (!haveNbrDeltaCoeffs_ || nbrMesh.changing())
    {
        nbrDeltaCoeffs_ = nbrPatch.deltaCoeffs();
        mpp.distribute(nbrDeltaCoeffs_);
        haveNbrDeltaCoeffs_ = true;
    }
    in.kappaNbr = nbrKappa.cdata();
    in.deltaCoeffsNbr = nbrDeltaCoeffs_.cdata();

    const scalarField myP(interfacePressure());
    scalarField myGapWidth;
    if (withGap && hasGapWidth())
    {
        myGapWidth = interfaceGapWidth();
    }
    try
    {
        if (mode_ == conductanceMode::constantH)
        {
            in.faceTemperatureNbr = nbrT.cdata();
            roughContact::coupleConstant(hConstant_, in, coupling_);
        }
        else
        {
            checkContactUnchanged();
            in.pressure = myP.cdata();
            in.pressureNbr = nbrP.cdata();
            in.cellTemperatureNbr = nbrT.cdata();
            if (withGap)
            {
                // The gap's terms need both face temperatures and the widths
                // both sides give (exchanged with the rest above).
                in.faceTemperature = this->cdata();
                in.faceTemperatureNbr = nbrTface.cdata();
                if (hasGapWidth())
                {
                    in.gapWidth = myGapWidth.cdata();
                    in.gapWidthNbr = nbrGapWidth.cdata();
                }
            }
            roughContact::couple(*interface_, in, couplingCache_, coupling_);
        }
    }
    catch (const roughContact::FaceError& e)
    {
        const label facei = label(e.face());
        RuntimeIOError
            << who().c_str() << ": face " << facei << " at "
            << patch().Cf()[facei] << ": pressure " << myP[facei]
            << " Pa on this side and " << nbrP[facei] << " Pa on the"
            << " neighbour's, kappa " << myKappa[facei] << " and "
            << nbrKappa[facei] << " W/m/K, deltaCoeffs "
            << myDeltaCoeffs[facei] << " and " << nbrDeltaCoeffs_[facei]
            << " 1/m: " << e.what() << exit(FatalIOError);
    }
    catch (const std::exception& e)
    {
        RuntimeIOError
            << who().c_str() << ": the interface coupling of the faces"
            << (contactName_.empty() ? "" : " (contact '" + contactName_ + "')")
            << " failed: " << e.what() << exit(FatalIOError);
    }

    const roughContact::CouplingOutputs& out = coupling_;
    std::copy(out.refValue.begin(), out.refValue.end(), this->refValue().begin());
    std::copy
    (
        out.valueFraction.begin(), out.valueFraction.end(),
        this->valueFraction().begin()
    );
    const bool apart = out.apart > 0;
    const bool beyondTable = out.beyondTable > 0;

    // The output fields, at every evaluation: function objects may sample
    // them at any time step (a history of contactConductance, say).
    forAll(conductance_, facei)
    {
        const scalar kDelta = myKappa[facei]*myDeltaCoeffs[facei];
        const scalar kDeltaNbr = nbrKappa[facei]*nbrDeltaCoeffs_[facei];
        conductance_[facei] = roughContact::shownConductance
        (
            out.contactConductance[facei], kDelta, kDeltaNbr
        );
        totalConductance_[facei] = roughContact::shownConductance
        (
            out.conductance[facei], kDelta, kDeltaNbr
        );
        areaFraction_[facei] = out.areaFraction[facei];
        contactPressure_[facei] = out.pressure[facei];
        contactState_[facei] = roughContact::contactStateCode(out.state[facei]);
        gapConductance_[facei] =
            out.gapConductance[facei] + out.radiativeConductance[facei];
    }

    if (mode_ == conductanceMode::contact)
    {
        if (returnReduce(apart, orOp<bool>()) && !warnedNoContact_)
        {
            Info<< "thermalContactResistance: " << who().c_str()
                << ": zero or negative pressure on some faces: the surfaces"
                << " do not touch there ("
                << (interface_->hasGap()
                    ? "only the gap's conductance remains)"
                    : "h = 0, no heat crosses)") << endl;
            warnedNoContact_ = true;
        }
        if (returnReduce(beyondTable, orOp<bool>()) && !warnedBeyondTable_)
        {
            WarningInFunction
                << who().c_str() << ": pressures above "
                << interface_->tableEnd()
                << " Pa, the end of the table of contact '" << contactName_
                << "' (its maxPressure), and below complete contact ("
                << interface_->completeContactPressure()
                << " Pa): h is held at the table's last value"
                << " there. Raise maxPressure." << endl;
            warnedBeyondTable_ = true;
        }
        // Input that is probably a mistake: the core counts it, says it in
        // words; here the sums over processors and one warning of each kind.
        roughContact::CouplingDiagnostics d;
        d.add(out);
        scalar belowTable(d.belowTable);
        scalar mismatch(d.pressureMismatch);
        scalar firstTouch(d.apartAtFirstTouch);
        reduce(belowTable, sumOp<scalar>());
        reduce(d.belowTablePressureSum, sumOp<scalar>());
        reduce(mismatch, sumOp<scalar>());
        reduce(d.largestPressureMismatch, maxOp<scalar>());
        reduce(firstTouch, sumOp<scalar>());
        d.belowTable = std::size_t(belowTable);
        d.pressureMismatch = std::size_t(mismatch);
        d.apartAtFirstTouch = std::size_t(firstTouch);
        const std::string messages[3] =
        {
            d.belowTableMessage(*interface_),
            d.pressureMismatchMessage(),
            d.apartAtFirstTouchMessage(*interface_)
        };
        for (label k = 0; k < 3; ++k)
        {
            if (!messages[k].empty() && !(warnedInput_ & (1 << k)))
            {
                WarningInFunction
                    << who().c_str() << ": " << messages[k].c_str() << endl;
                warnedInput_ |= (1 << k);
            }
        }
    }
    this->refGrad() = 0.0;

    mixedFvPatchScalarField::updateCoeffs();

    evaluated_ = true;

    UPstream::msgType() = oldTag;
}


void Foam::thermalContactResistanceFvPatchScalarField::write(Ostream& os) const
{
    mixedFvPatchScalarField::write(os);
    os.writeEntry("Tnbr", TnbrName_);
    if (mode_ == conductanceMode::constantH)
    {
        os.writeEntry("h", hConstant_);
    }
    else
    {
        os.writeEntry("contact", contactName_);
        // What this run used: a restart compares it (checkRecordedSurface).
        os.writeEntry("surfaceChecksum", surfaceChecksum_);
        if (pressure_.valid())
        {
            if (pressure_->type() == "uniformValue")
            {
                // v1912's UniformValueField writes only its Function1
                // ("pressure table (...)"), which does not read back as a
                // PatchFunction1; the dictionary form does.
                os.beginBlock("pressure");
                os.writeEntry("type", pressure_->type());
                pressure_->writeData(os);
                os.endBlock();
            }
            else
            {
                pressure_->writeData(os);
            }
        }
        else
        {
            os.writeEntry("pressureField", pressureFieldName_);
        }
        if (!gapFieldName_.empty())
        {
            os.writeEntry("gapField", gapFieldName_);
        }
        else if (gapWidth_ >= 0)
        {
            os.writeEntry("gap", gapWidth_);
        }
    }
    temperatureCoupledBase::write(os);
}


namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        thermalContactResistanceFvPatchScalarField
    );
}
