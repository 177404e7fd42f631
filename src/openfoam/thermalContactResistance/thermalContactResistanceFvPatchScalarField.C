#include "thermalContactResistanceFvPatchScalarField.H"
#include "contactInterfaceFromDict.H"

#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "mappedPatchBase.H"
#include "IOdictionary.H"

#include <cmath>

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
        FatalErrorInFunction
            << who().c_str() << " (file " << internalField().objectPath()
            << "): thermalContactResistance needs a mapped patch (mappedWall),"
            << " this one is '" << patch().patch().type() << "'"
            << exit(FatalError);
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
            << who().c_str() << ": give exactly one of 'h' (a constant"
            << " conductance) and 'contact' (an entry of"
            << " constant/thermalContactProperties)" << exit(FatalIOError);
    }
    if (hasH)
    {
        hConstant_ = dict.get<scalar>("h");
        if (!(hConstant_ > 0) || !std::isfinite(hConstant_))
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry 'h' must be a finite conductance"
                << " > 0 [W/m^2/K], got " << hConstant_ << exit(FatalIOError);
        }
        return;
    }

    contactName_ = dict.get<word>("contact");
    const bool hasP = dict.found("pressure");
    const bool hasPField = dict.found("pressureField");
    if (hasP == hasPField)
    {
        FatalIOErrorInFunction(dict)
            << who().c_str() << ": give exactly one of 'pressure' (a"
            << " PatchFunction1, Pa) and 'pressureField' (a volScalarField"
            << " name)" << exit(FatalIOError);
    }
    if (hasP)
    {
        pressure_ = PatchFunction1<scalar>::New(patch().patch(), "pressure", dict);
    }
    else
    {
        pressureFieldName_ = dict.get<word>("pressureField");
    }

    // One place both sides read: constant/thermalContactProperties of the case.
    const Time& runTime = db().time();
    const word propsName("thermalContactProperties");
    if (!runTime.foundObject<IOdictionary>(propsName))
    {
        IOobject io
        (
            propsName,
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        );
        if (!io.typeHeaderOk<IOdictionary>(true))
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry 'contact " << contactName_
                << "' needs the file " << io.objectPath()
                << ", which cannot be read" << exit(FatalIOError);
        }
        IOdictionary* props = new IOdictionary(io);
        props->store();
    }
    const IOdictionary& props = runTime.lookupObject<IOdictionary>(propsName);
    if (!props.isDict(contactName_))
    {
        FatalIOErrorInFunction(props)
            << who().c_str() << ": no entry '" << contactName_ << "' in "
            << props.objectPath() << exit(FatalIOError);
    }
    interface_ = contactInterfaceFromDict
    (
        props, contactName_, props.objectPath(), runTime.path(), who()
    );
}


void Foam::thermalContactResistanceFvPatchScalarField::storeOutput()
{
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    const label patchi = patch().index();
    const word names[2] = {"contactAreaFraction", "contactConductance"};
    const scalarField* values[2] = {&areaFraction_, &conductance_};
    const dimensionSet dims[2] =
        {dimless, dimPower/dimArea/dimTemperature};
    for (int k = 0; k < 2; ++k)
    {
        if (!mesh.foundObject<volScalarField>(names[k]))
        {
            volScalarField* f = new volScalarField
            (
                IOobject
                (
                    names[k],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(dims[k], Zero)
            );
            f->store();
        }
        volScalarField& f =
            const_cast<volScalarField&>
            (
                mesh.lookupObject<volScalarField>(names[k])
            );
        f.boundaryFieldRef()[patchi] == *values[k];
    }
}


void Foam::thermalContactResistanceFvPatchScalarField::report() const
{
    const scalarField finiteH(min(conductance_, scalar(GREAT)));
    Info<< "thermalContactResistance: " << who().c_str()
        << ": h min/mean/max = " << gMin(finiteH) << " / "
        << gAverage(finiteH) << " / " << gMax(finiteH)
        << " W/m^2/K, A_r/A_n mean = " << gAverage(areaFraction_) << endl;
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
    temperatureCoupledBase
    (
        patch(), "undefined", "undefined", "undefined-K", "undefined-alpha"
    ),
    TnbrName_("undefined-Tnbr"),
    contactName_(),
    hConstant_(-1),
    pressure_(),
    pressureFieldName_(),
    interface_(),
    areaFraction_(p.size(), Zero),
    conductance_(p.size(), Zero),
    warnedNoContact_(false),
    lastReportTime_(-GREAT)
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
    temperatureCoupledBase(patch(), dict),
    TnbrName_(dict.get<word>("Tnbr")),
    contactName_(),
    hConstant_(-1),
    pressure_(),
    pressureFieldName_(),
    interface_(),
    areaFraction_(p.size(), Zero),
    conductance_(p.size(), Zero),
    warnedNoContact_(false),
    lastReportTime_(-GREAT)
{
    checkPatch();
    readContact(dict);

    fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    if (dict.found("refValue"))
    {
        // Full restart
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
    hConstant_(ptf.hConstant_),
    pressure_(ptf.pressure_.valid() ? ptf.pressure_().clone(p.patch()).ptr() : nullptr),
    pressureFieldName_(ptf.pressureFieldName_),
    interface_(ptf.interface_),
    areaFraction_(ptf.areaFraction_, mapper),
    conductance_(ptf.conductance_, mapper),
    warnedNoContact_(ptf.warnedNoContact_),
    lastReportTime_(ptf.lastReportTime_)
{}


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
    hConstant_(ptf.hConstant_),
    pressure_(ptf.pressure_.valid() ? ptf.pressure_().clone(patch().patch()).ptr() : nullptr),
    pressureFieldName_(ptf.pressureFieldName_),
    interface_(ptf.interface_),
    areaFraction_(ptf.areaFraction_),
    conductance_(ptf.conductance_),
    warnedNoContact_(ptf.warnedNoContact_),
    lastReportTime_(ptf.lastReportTime_)
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
    hConstant_(ptf.hConstant_),
    pressure_(ptf.pressure_.valid() ? ptf.pressure_().clone(patch().patch()).ptr() : nullptr),
    pressureFieldName_(ptf.pressureFieldName_),
    interface_(ptf.interface_),
    areaFraction_(ptf.areaFraction_),
    conductance_(ptf.conductance_),
    warnedNoContact_(ptf.warnedNoContact_),
    lastReportTime_(ptf.lastReportTime_)
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
            FatalErrorInFunction
                << who().c_str() << ": pressureField '" << pressureFieldName_
                << "' is not a volScalarField of region " << mesh.name()
                << " (file " << internalField().objectPath() << ")"
                << exit(FatalError);
        }
        return
            mesh.lookupObject<volScalarField>(pressureFieldName_)
           .boundaryField()[patch().index()];
    }
    return tmp<scalarField>(new scalarField(size(), Zero));
}


void Foam::thermalContactResistanceFvPatchScalarField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    mixedFvPatchScalarField::autoMap(m);
    if (pressure_.valid())
    {
        pressure_->autoMap(m);
    }
    areaFraction_.autoMap(m);
    conductance_.autoMap(m);
}


void Foam::thermalContactResistanceFvPatchScalarField::rmap
(
    const fvPatchScalarField& ptf,
    const labelList& addr
)
{
    mixedFvPatchScalarField::rmap(ptf, addr);
    const auto& tiptf =
        refCast<const thermalContactResistanceFvPatchScalarField>(ptf);
    if (pressure_.valid() && tiptf.pressure_.valid())
    {
        pressure_->rmap(tiptf.pressure_(), addr);
    }
    areaFraction_.rmap(tiptf.areaFraction_, addr);
    conductance_.rmap(tiptf.conductance_, addr);
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

    const fvPatchScalarField& nbrPf =
        nbrPatch.lookupPatchField<volScalarField, scalar>(TnbrName_);
    if (!isA<thermalContactResistanceFvPatchScalarField>(nbrPf))
    {
        FatalErrorInFunction
            << who().c_str() << ": the neighbour patch " << nbrPatch.name()
            << " of region " << nbrMesh.name() << " has field " << TnbrName_
            << " of type " << nbrPf.type()
            << "; both sides must be thermalContactResistance"
            << exit(FatalError);
    }
    const auto& nbrField =
        refCast<const thermalContactResistanceFvPatchScalarField>(nbrPf);

    // Neighbour face temperatures, on this side's faces.
    scalarField nbrT(nbrField);
    mpp.distribute(nbrT);

    const scalarField myKappa(kappa(*this));
    scalarField h(size(), Zero);
    if (hConstant_ > 0)
    {
        h = hConstant_;
        areaFraction_ = 1.0;
    }
    else
    {
        // Both sides' pressures, averaged: both sides see the same h.
        scalarField nbrP(nbrField.interfacePressure());
        mpp.distribute(nbrP);
        const scalarField P(0.5*(interfacePressure() + nbrP));

        scalarField nbrKappa(nbrField.kappa(nbrField));
        mpp.distribute(nbrKappa);

        bool noContact = false;
        forAll(h, facei)
        {
            const scalar p = P[facei];
            if (!std::isfinite(p))
            {
                FatalErrorInFunction
                    << who().c_str() << ": pressure " << p << " at face "
                    << facei << exit(FatalError);
            }
            if (p <= 0)
            {
                noContact = true;
            }
            const scalar k1 = myKappa[facei];
            const scalar k2 = nbrKappa[facei];
            const scalar ks = 2*k1*k2/(k1 + k2);
            h[facei] = ks*interface_->conductancePerConductivity(p);
            areaFraction_[facei] = interface_->areaFraction(p);
        }
        if (returnReduce(noContact, orOp<bool>()) && !warnedNoContact_)
        {
            Info<< "thermalContactResistance: " << who().c_str()
                << ": zero or negative pressure on some faces: the surfaces"
                << " do not touch there (h_c = 0)" << endl;
            warnedNoContact_ = true;
        }
    }
    conductance_ = h;

    const scalarField myKDelta(myKappa*patch().deltaCoeffs());
    this->refValue() = nbrT;
    this->refGrad() = 0.0;
    scalarField& f = this->valueFraction();
    forAll(f, facei)
    {
        // Complete contact (h infinite): the solids are joined.
        f[facei] =
            std::isfinite(h[facei])
          ? h[facei]/(h[facei] + myKDelta[facei])
          : 1.0;
    }

    mixedFvPatchScalarField::updateCoeffs();

    storeOutput();
    const Time& runTime = db().time();
    if (runTime.writeTime() && runTime.value() != lastReportTime_)
    {
        lastReportTime_ = runTime.value();
        report();
    }

    UPstream::msgType() = oldTag;
}


void Foam::thermalContactResistanceFvPatchScalarField::write(Ostream& os) const
{
    mixedFvPatchScalarField::write(os);
    os.writeEntry("Tnbr", TnbrName_);
    if (hConstant_ > 0)
    {
        os.writeEntry("h", hConstant_);
    }
    else
    {
        os.writeEntry("contact", contactName_);
        if (pressure_.valid())
        {
            pressure_->writeData(os);
        }
        else
        {
            os.writeEntry("pressureField", pressureFieldName_);
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
