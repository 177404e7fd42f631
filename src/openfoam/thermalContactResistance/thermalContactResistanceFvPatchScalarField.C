// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later): the
// coupled-baffle arithmetic and structure follow compressible::
// turbulentTemperatureCoupledBaffleMixedFvPatchScalarField and temperatureCoupledBase.
#include "thermalContactResistanceFvPatchScalarField.H"

#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "mappedPatchBase.H"

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
        FUNCTION_NAME, __FILE__, __LINE__, settings_.dictName, settings_.dictStart, settings_.dictEnd     \
    )

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::thermalContactResistanceFvPatchScalarField::who() const
{
    return
        "patch " + patch().name() + " of field " + internalField().name()
      + " in region " + patch().boundaryMesh().mesh().name();
}


void Foam::thermalContactResistanceFvPatchScalarField::checkPatch
(
    const dictionary& dict
) const
{
    if (!isA<mappedPatchBase>(patch().patch()))
    {
        FatalIOErrorInFunction(dict)
            << who().c_str() << ": thermalContactResistance needs a mapped"
            << " patch (mappedWall) coupling two regions; this patch is of"
            << " type '" << patch().patch().type() << "'"
            << exit(FatalIOError);
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
    if (settings_.mode != nbr.settings_.mode)
    {
        problem = "one side gives 'h', the other 'contact'";
    }
    else if (settings_.mode == thermalContactSettings::conductanceMode::constantH && settings_.hConstant != nbr.settings_.hConstant)
    {
        problem =
            "the two sides give different 'h' (" + Foam::name(settings_.hConstant)
          + " and " + Foam::name(nbr.settings_.hConstant) + ")";
    }
    else if (settings_.mode == thermalContactSettings::conductanceMode::contact && settings_.contactName != nbr.settings_.contactName)
    {
        problem =
            "the two sides name different 'contact' entries ('"
          + settings_.contactName + "' and '" + nbr.settings_.contactName + "')";
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
    if (!nbrMesh.foundObject<volScalarField>(settings_.Tnbr))
    {
        if (!mustExist)
        {
            return nullptr;
        }
        RuntimeIOError
            << who().c_str() << ": entry 'Tnbr " << settings_.Tnbr << "': the"
            << " neighbour region " << nbrMesh.name() << " has no"
            << " volScalarField '" << settings_.Tnbr << "' (it has: "
            << flatOutput(nbrMesh.sortedNames<volScalarField>()) << ")"
            << exit(FatalIOError);
    }
    const fvPatchScalarField& nbrPf =
        nbrMesh.lookupObject<volScalarField>(settings_.Tnbr)
       .boundaryField()[mpp.samplePolyPatch().index()];
    if (!isA<thermalContactResistanceFvPatchScalarField>(nbrPf))
    {
        RuntimeIOError
            << who().c_str() << ": the neighbour patch "
            << nbrPf.patch().name() << " of region " << nbrMesh.name()
            << " has " << settings_.Tnbr << " of type '" << nbrPf.type()
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
    settings_(),
    pressure_(),
    areaFraction_(p.size(), Zero),
    conductance_(p.size(), Zero),
    contactPressure_(p.size(), Zero),
    contactState_(p.size(), Zero),
    gapConductance_(p.size(), Zero),
    totalConductance_(p.size(), Zero),
    evaluated_(false),
    checkedNeighbour_(false),
    warnedNoContact_(false),
    warnedBeyondTable_(false),
    warnedInput_(0)
{
    settings_.dictName = iF.objectPath();
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
    settings_(),
    pressure_(),
    areaFraction_(p.size(), Zero),
    conductance_(p.size(), Zero),
    contactPressure_(p.size(), Zero),
    contactState_(p.size(), Zero),
    gapConductance_(p.size(), Zero),
    totalConductance_(p.size(), Zero),
    evaluated_(false),
    checkedNeighbour_(false),
    warnedNoContact_(false),
    warnedBeyondTable_(false),
    warnedInput_(0)
{
    checkPatch(dict);
    settings_ = thermalContactSettings
    (
        dict, db().time(), who(), internalField().objectPath()
    );
    if (settings_.pressureGiven)
    {
        pressure_ =
            PatchFunction1<scalar>::New(patch().patch(), "pressure", dict);
    }
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
    settings_(ptf.settings_),
    pressure_(),
    areaFraction_(ptf.areaFraction_, mapper),
    conductance_(ptf.conductance_, mapper),
    contactPressure_(ptf.contactPressure_, mapper),
    contactState_(ptf.contactState_, mapper),
    gapConductance_(ptf.gapConductance_, mapper),
    totalConductance_(ptf.totalConductance_, mapper),
    evaluated_(ptf.evaluated_),
    checkedNeighbour_(false),
    warnedNoContact_(ptf.warnedNoContact_),
    warnedBeyondTable_(ptf.warnedBeyondTable_),
    warnedInput_(ptf.warnedInput_)
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
    settings_(ptf.settings_),
    pressure_
    (
        ptf.pressure_.valid()
      ? ptf.pressure_().clone(patch().patch()).ptr()
      : nullptr
    ),
    areaFraction_(ptf.areaFraction_),
    conductance_(ptf.conductance_),
    contactPressure_(ptf.contactPressure_),
    contactState_(ptf.contactState_),
    gapConductance_(ptf.gapConductance_),
    totalConductance_(ptf.totalConductance_),
    evaluated_(ptf.evaluated_),
    checkedNeighbour_(ptf.checkedNeighbour_),
    warnedNoContact_(ptf.warnedNoContact_),
    warnedBeyondTable_(ptf.warnedBeyondTable_),
    warnedInput_(ptf.warnedInput_)
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
    settings_(ptf.settings_),
    pressure_
    (
        ptf.pressure_.valid()
      ? ptf.pressure_().clone(patch().patch()).ptr()
      : nullptr
    ),
    areaFraction_(ptf.areaFraction_),
    conductance_(ptf.conductance_),
    contactPressure_(ptf.contactPressure_),
    contactState_(ptf.contactState_),
    gapConductance_(ptf.gapConductance_),
    totalConductance_(ptf.totalConductance_),
    evaluated_(ptf.evaluated_),
    checkedNeighbour_(ptf.checkedNeighbour_),
    warnedNoContact_(ptf.warnedNoContact_),
    warnedBeyondTable_(ptf.warnedBeyondTable_),
    warnedInput_(ptf.warnedInput_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfacePressure() const
{
    if (pressure_.valid())
    {
        return pressure_->value(db().time().timeOutputValue());
    }
    if (!settings_.pressureFieldName.empty())
    {
        const fvMesh& mesh = patch().boundaryMesh().mesh();
        if (!mesh.foundObject<volScalarField>(settings_.pressureFieldName))
        {
            RuntimeIOError
                << who().c_str() << ": entry 'pressureField "
                << settings_.pressureFieldName << "': region " << mesh.name()
                << " has no volScalarField '" << settings_.pressureFieldName
                << "' (read it, e.g. with the readFields function object,"
                << " or let a solver or function object create it)"
                << exit(FatalIOError);
        }
        return
            mesh.lookupObject<volScalarField>(settings_.pressureFieldName)
           .boundaryField()[patch().index()];
    }
    return tmp<scalarField>(new scalarField(size(), Zero));
}


Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfaceGapWidth() const
{
    if (!settings_.gapFieldName.empty())
    {
        const fvMesh& mesh = patch().boundaryMesh().mesh();
        if (!mesh.foundObject<volScalarField>(settings_.gapFieldName))
        {
            RuntimeIOError
                << who().c_str() << ": entry 'gapField "
                << settings_.gapFieldName << "': region " << mesh.name()
                << " has no volScalarField '" << settings_.gapFieldName
                << "' (read it, e.g. with the readFields function object,"
                << " or let a solver or function object create it)"
                << exit(FatalIOError);
        }
        return
            mesh.lookupObject<volScalarField>(settings_.gapFieldName)
           .boundaryField()[patch().index()];
    }
    return tmp<scalarField>(new scalarField(size(), max(settings_.gapWidth, 0.0)));
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
    const bool withGap = settings_.mode == thermalContactSettings::conductanceMode::contact && settings_.interface->hasGap();
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
            settings_.mode == thermalContactSettings::conductanceMode::constantH
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
        if (settings_.mode == thermalContactSettings::conductanceMode::constantH)
        {
            in.faceTemperatureNbr = nbrT.cdata();
            roughContact::coupleConstant(settings_.hConstant, in, coupling_);
        }
        else
        {
            settings_.checkContactUnchanged(db().time(), [this] { return who(); });
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
            roughContact::couple(*settings_.interface, in, couplingCache_, coupling_);
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
            << (settings_.contactName.empty() ? "" : " (contact '" + settings_.contactName + "')")
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

    if (settings_.mode == thermalContactSettings::conductanceMode::contact)
    {
        if (returnReduce(apart, orOp<bool>()) && !warnedNoContact_)
        {
            Info<< "thermalContactResistance: " << who().c_str()
                << ": zero or negative pressure on some faces: the surfaces"
                << " do not touch there ("
                << (settings_.interface->hasGap()
                    ? "only the gap's conductance remains)"
                    : "h = 0, no heat crosses)") << endl;
            warnedNoContact_ = true;
        }
        if (returnReduce(beyondTable, orOp<bool>()) && !warnedBeyondTable_)
        {
            WarningInFunction
                << who().c_str() << ": pressures above "
                << settings_.interface->tableEnd()
                << " Pa, the end of the table of contact '" << settings_.contactName
                << "' (its maxPressure), and below complete contact ("
                << settings_.interface->completeContactPressure()
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
            d.belowTableMessage(*settings_.interface),
            d.pressureMismatchMessage(),
            d.apartAtFirstTouchMessage(*settings_.interface)
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
    settings_.write(os);
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
    else if (!settings_.pressureFieldName.empty())
    {
        os.writeEntry("pressureField", settings_.pressureFieldName);
    }
    settings_.writeGap(os);
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
