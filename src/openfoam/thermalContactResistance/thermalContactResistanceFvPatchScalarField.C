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
#include "foamCompat.H"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

// An error found at run time (not while reading the dictionary): FatalIOError
// naming the file and lines the condition was read from.
#define RuntimeIOError                                                         \
    FatalIOErrorAt(settings_.dictName, settings_.dictStart, settings_.dictEnd)

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
    const string problem = settings_.disagreement(nbr.settings_);
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
    coupling_(p.size()),
    evaluated_(false),
    checkedNeighbour_(false)
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
    coupling_(p.size()),
    evaluated_(false),
    checkedNeighbour_(false)
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
    coupling_(ptf.coupling_),
    evaluated_(ptf.evaluated_),
    checkedNeighbour_(false)
{
    // The output fields follow their faces; the core's results and cache
    // are rebuilt at the next evaluation
    coupling_.areaFraction = scalarField(ptf.coupling_.areaFraction, mapper);
    coupling_.conductance = scalarField(ptf.coupling_.conductance, mapper);
    coupling_.contactPressure =
        scalarField(ptf.coupling_.contactPressure, mapper);
    coupling_.contactState = scalarField(ptf.coupling_.contactState, mapper);
    coupling_.gapConductance =
        scalarField(ptf.coupling_.gapConductance, mapper);
    coupling_.totalConductance =
        scalarField(ptf.coupling_.totalConductance, mapper);
    coupling_.clearCache();
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
    coupling_(ptf.coupling_),
    evaluated_(ptf.evaluated_),
    checkedNeighbour_(ptf.checkedNeighbour_)
{
    // The core's results and cache start empty (rebuilt at the next
    // evaluation), as before they were shared
    coupling_.clearCache();
}


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
    coupling_(ptf.coupling_),
    evaluated_(ptf.evaluated_),
    checkedNeighbour_(ptf.checkedNeighbour_)
{
    // The core's results and cache start empty (rebuilt at the next
    // evaluation), as before they were shared
    coupling_.clearCache();
}


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
        return settings_.patchValues
        (
            patch(), settings_.pressureFieldName, "pressureField",
            [this] { return who(); }
        );
    }
    return tmp<scalarField>(new scalarField(size(), Zero));
}


Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfaceGapWidth() const
{
    if (!settings_.gapFieldName.empty())
    {
        return settings_.patchValues
        (
            patch(), settings_.gapFieldName, "gapField",
            [this] { return who(); }
        );
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
    coupling_.areaFraction.autoMap(m);
    coupling_.conductance.autoMap(m);
    coupling_.contactPressure.autoMap(m);
    coupling_.contactState.autoMap(m);
    coupling_.gapConductance.autoMap(m);
    coupling_.totalConductance.autoMap(m);
    coupling_.clearCache();
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
    coupling_.areaFraction.rmap(tiptf.coupling_.areaFraction, addr);
    coupling_.conductance.rmap(tiptf.coupling_.conductance, addr);
    coupling_.contactPressure.rmap(tiptf.coupling_.contactPressure, addr);
    coupling_.contactState.rmap(tiptf.coupling_.contactState, addr);
    coupling_.gapConductance.rmap(tiptf.coupling_.gapConductance, addr);
    coupling_.totalConductance.rmap(tiptf.coupling_.totalConductance, addr);
    coupling_.clearCache();
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
    nbrField.checkKappaField();
    const scalarField myKappa(kappa(*this));

    // What this side needs of the neighbour, in one exchange: its cell
    // temperature (contact) or face temperature (h), kappa and pressure per
    // face; with a gap also its face temperature and gap width. Then (once,
    // while the mesh does not change) its deltaCoeffs.
    const bool withGap = settings_.withGap();
    const scalarField nbrT
    (
        settings_.mode == thermalContactSettings::conductanceMode::constantH
      ? scalarField(nbrField)
      : nbrField.patchInternalField()()
    );
    const scalarField nbrK(nbrField.kappa(nbrField));
    const scalarField nbrP(nbrField.interfacePressure());
    const scalarField nbrW
    (
        withGap && nbrField.hasGapWidth()
      ? nbrField.interfaceGapWidth()()
      : scalarField()
    );
    const thermalContactCoupling::neighbourValues nbr =
        thermalContactCoupling::exchange
        (
            {
                nbrT, nbrK, nbrP,
                withGap ? &static_cast<const scalarField&>(nbrField) : nullptr,
                withGap && nbrField.hasGapWidth() ? &nbrW : nullptr
            },
            size(),
            [&mpp](auto f)
            {
                mpp.distribute(f);
                return f;
            }
        );
    // distribute() is collective: decide on what every processor knows
    // alike (not on this processor's, possibly empty, face count).
    if (!haveNbrDeltaCoeffs_ || nbrMesh.changing())
    {
        nbrDeltaCoeffs_ = nbrPatch.deltaCoeffs();
        mpp.distribute(nbrDeltaCoeffs_);
        haveNbrDeltaCoeffs_ = true;
    }

    const scalarField myP(interfacePressure());
    const scalarField myW
    (
        withGap && hasGapWidth() ? interfaceGapWidth()() : scalarField()
    );
    coupling_.couple
    (
        settings_, db().time(), [this] { return who(); },
        myKappa, patch().deltaCoeffs(), *this, patch().Cf(), myP,
        withGap && hasGapWidth() ? &myW : nullptr,
        nbr, nbrDeltaCoeffs_
    );

    const roughContact::CouplingOutputs& out = coupling_.outputs;
    std::copy(out.refValue.begin(), out.refValue.end(), this->refValue().begin());
    std::copy
    (
        out.valueFraction.begin(), out.valueFraction.end(),
        this->valueFraction().begin()
    );
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
