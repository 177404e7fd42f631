// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright The OpenFOAM Foundation; GPL-3.0-or-later): the coupled-temperature
// structure follows the Foundation's coupledTemperatureFvPatchScalarField.
#include "thermalContactResistanceFvPatchScalarField.H"

#include "addToRunTimeSelectionTable.H"
#include "fieldMapper.H"
#include "foamCompat.H"
#include "mappedFvPatchBaseBase.H"
#include "thermophysicalTransportModel.H"
#include "volFields.H"

#include <algorithm>

// An error found at run time (not while reading the dictionary): FatalIOError
// naming the file and lines the condition was read from.
#define RuntimeIOError                                                         \
    FatalIOErrorAt(settings_.dictName, settings_.dictStart, settings_.dictEnd)

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::string Foam::thermalContactResistanceFvPatchScalarField::who() const
{
    return
        "patch " + patch().name() + " of field " + internalField().name()
      + " in region " + patch().boundaryMesh().mesh().name();
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
    const mappedFvPatchBaseBase& mapper =
        mappedFvPatchBaseBase::getMap(patch());
    if
    (
        !mustExist
     && (
            !mapper.haveNbr()
            // Both patches in one region: its boundary field may not be
            // complete while this region's T is being read
         || &mapper.nbrMesh() == &patch().boundaryMesh().mesh()
        )
    )
    {
        return nullptr;
    }
    const fvMesh& nbrMesh = mapper.nbrMesh();
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
            << foamCompat::listed(nbrMesh.toc<volScalarField>()).c_str()
            << ")" << exit(FatalIOError);
    }
    const fvPatchScalarField& nbrPf =
        nbrMesh.lookupObject<volScalarField>(settings_.Tnbr)
       .boundaryField()[mapper.nbrFvPatch().index()];
    if (!isA<thermalContactResistanceFvPatchScalarField>(nbrPf))
    {
        RuntimeIOError
            << who().c_str() << ": the neighbour patch "
            << nbrPf.patch().name() << " of region " << nbrMesh.name()
            << " has " << settings_.Tnbr << " of type '" << nbrPf.type()
            << "'; both sides of the interface must be"
            << " thermalContactResistance" << exit(FatalIOError);
    }
    return &nbrPf;
}


Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::kappa() const
{
    const fvMesh& mesh = patch().boundaryMesh().mesh();
    if (!mesh.foundType<thermophysicalTransportModel>())
    {
        RuntimeIOError
            << who().c_str() << ": region " << mesh.name() << " has no"
            << " thermophysicalTransportModel, which gives kappa on the"
            << " patch (a solid or fluid region of the solver foamMultiRun)"
            << exit(FatalIOError);
    }
    return
        mesh.lookupType<thermophysicalTransportModel>()
       .kappaEff(patch().index());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    mixedFvPatchScalarField(p, iF, dict, false),
    settings_(),
    pressure_(),
    coupling_(p.size()),
    evaluated_(false),
    haveNbrDeltaCoeffs_(false),
    checkedNeighbour_(false)
{
    mappedPatchBaseBase::validateMapForField
    (
        *this,
        iF,
        dict,
        mappedPatchBaseBase::from::differentPatch
    );
    settings_ = thermalContactSettings
    (
        dict, db().time(), who(), internalField().objectPath()
    );
    if (dict.found("kappaMethod") || dict.found("kappa"))
    {
        IOWarningInFunction(dict)
            << who().c_str() << ": kappaMethod and kappa are not read by"
            << " this OpenFOAM: kappa is the region's"
            << " thermophysicalTransportModel's" << endl;
    }
    if (settings_.pressureGiven)
    {
        pressure_ = Function1<scalar>::New
        (
            "pressure",
            db().time().userUnits(),
            dimPressure,
            dict
        );
    }
    // The neighbour's field exists already when this region is read after
    // it: a neighbour of another type is reported here.
    neighbourField(false);

    fvPatchScalarField::operator=
    (
        scalarField("value", iF.dimensions(), dict, p.size())
    );
    if (dict.found("refValue"))
    {
        // Restart: the mixed condition's state as written
        refValue() = scalarField("refValue", iF.dimensions(), dict, p.size());
        refGrad() =
            scalarField
            (
                "refGradient", iF.dimensions()/dimLength, dict, p.size()
            );
        valueFraction() =
            scalarField("valueFraction", unitFraction, dict, p.size());
    }
    else
    {
        refValue() = *this;
        refGrad() = 0;
        valueFraction() = 1;
    }
}


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fieldMapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    settings_(ptf.settings_),
    pressure_(ptf.pressure_, false),
    coupling_(p.size()),
    evaluated_(ptf.evaluated_),
    haveNbrDeltaCoeffs_(false),
    checkedNeighbour_(false)
{
    coupling_.warnedNoContact = ptf.coupling_.warnedNoContact;
    coupling_.warnedBeyondTable = ptf.coupling_.warnedBeyondTable;
    coupling_.warnedInput = ptf.coupling_.warnedInput;
    map(ptf, mapper);
}


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    settings_(ptf.settings_),
    pressure_(ptf.pressure_, false),
    coupling_(ptf.coupling_),
    evaluated_(ptf.evaluated_),
    nbrDeltaCoeffs_(ptf.nbrDeltaCoeffs_),
    haveNbrDeltaCoeffs_(ptf.haveNbrDeltaCoeffs_),
    checkedNeighbour_(ptf.checkedNeighbour_)
{
    // The core's results and cache start empty, as in the ESI adapter
    coupling_.clearCache();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfacePressure() const
{
    if (pressure_.valid())
    {
        return tmp<scalarField>
        (
            new scalarField(size(), pressure_->value(db().time().value()))
        );
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
    return tmp<scalarField>
    (
        new scalarField(size(), max(settings_.gapWidth, scalar(0)))
    );
}


void Foam::thermalContactResistanceFvPatchScalarField::map
(
    const fvPatchScalarField& ptf,
    const fieldMapper& mapper
)
{
    const auto& tiptf =
        refCast<const thermalContactResistanceFvPatchScalarField>(ptf);
    // As the stock coupledTemperature: faces with no source (a topology
    // change) are adiabatic, at the cell's temperature
    mapper(*this, tiptf, [&](){ return patchInternalField(); });
    mapper(refValue(), tiptf.refValue(), [&](){ return patchInternalField(); });
    mapper(refGrad(), tiptf.refGrad(), scalar(0));
    mapper(valueFraction(), tiptf.valueFraction(), scalar(0));
    mapOutputs(tiptf, mapper);
}


void Foam::thermalContactResistanceFvPatchScalarField::mapOutputs
(
    const thermalContactResistanceFvPatchScalarField& ptf,
    const fieldMapper& mapper
)
{
    const thermalContactCoupling& from = ptf.coupling_;
    mapper(coupling_.areaFraction, from.areaFraction);
    mapper(coupling_.conductance, from.conductance);
    mapper(coupling_.contactPressure, from.contactPressure);
    mapper(coupling_.contactState, from.contactState);
    mapper(coupling_.gapConductance, from.gapConductance);
    mapper(coupling_.totalConductance, from.totalConductance);
    coupling_.clearCache();
    nbrDeltaCoeffs_.clear();
    haveNbrDeltaCoeffs_ = false;
}


void Foam::thermalContactResistanceFvPatchScalarField::reset
(
    const fvPatchScalarField& ptf
)
{
    mixedFvPatchScalarField::reset(ptf);
    const auto& tiptf =
        refCast<const thermalContactResistanceFvPatchScalarField>(ptf);
    const thermalContactCoupling& from = tiptf.coupling_;
    coupling_.areaFraction.reset(from.areaFraction);
    coupling_.conductance.reset(from.conductance);
    coupling_.contactPressure.reset(from.contactPressure);
    coupling_.contactState.reset(from.contactState);
    coupling_.gapConductance.reset(from.gapConductance);
    coupling_.totalConductance.reset(from.totalConductance);
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

    const mappedFvPatchBaseBase& mapper =
        mappedFvPatchBaseBase::getMap(patch());
    const fvPatch& nbrPatch = mapper.nbrFvPatch();
    const auto& nbrField =
        refCast<const thermalContactResistanceFvPatchScalarField>
        (
            *neighbourField(true)
        );
    if (!checkedNeighbour_)
    {
        checkNeighbour(nbrField);
    }
    const scalarField myKappa(kappa());

    // What this side needs of the neighbour, in one exchange
    // (thermalContactCoupling::exchange), then its deltaCoeffs once while
    // the mesh does not change.
    const bool withGap = settings_.withGap();
    const scalarField nbrT
    (
        settings_.mode == thermalContactSettings::conductanceMode::constantH
      ? scalarField(nbrField)
      : nbrField.patchInternalField()()
    );
    const scalarField nbrK(nbrField.kappa());
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
            [&mapper](const auto& f)
            {
                return std::decay_t<decltype(f)>(mapper.fromNeighbour(f));
            }
        );
    if (!haveNbrDeltaCoeffs_ || mapper.nbrMesh().changing())
    {
        nbrDeltaCoeffs_ = mapper.fromNeighbour(nbrPatch.deltaCoeffs());
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
    std::copy(out.refValue.begin(), out.refValue.end(), refValue().begin());
    std::copy
    (
        out.valueFraction.begin(), out.valueFraction.end(),
        valueFraction().begin()
    );
    refGrad() = 0;

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
        writeEntry(os, db().time().userUnits(), dimPressure, pressure_());
    }
    else if (!settings_.pressureFieldName.empty())
    {
        writeEntry(os, "pressureField", settings_.pressureFieldName);
    }
    settings_.writeGap(os);
}


namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        thermalContactResistanceFvPatchScalarField
    );
}
