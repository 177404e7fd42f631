// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later): the
// coupled-baffle arithmetic and structure follow compressible::
// turbulentTemperatureCoupledBaffleMixedFvPatchScalarField (ESI) and
// coupledTemperatureFvPatchScalarField (Foundation). One body for both lines: what a line does
// its own way is thermalContactLine.H of the folder wmake builds in; `#if` marks the lines where
// the patch-field API differs (most of them in ...Mapping.C: construction and mapping).
#include "thermalContactResistanceFvPatchScalarField.H"

#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "foamCompat.H"

#include <algorithm>
#include <string>

// An error found at run time (not while reading the dictionary): FatalIOError
// naming the file and lines the condition was read from.
#define RuntimeIOError                                                         \
    FatalIOErrorAt(settings_->dictName, settings_->dictStart, settings_->dictEnd)

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
    const string problem = settings_->disagreement(*nbr.settings_);
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
    const thermalContactLine::neighbourMap nbrMap(patch());
    if (!mustExist && !nbrMap.ready(db().time()))
    {
        return nullptr;
    }
    const fvMesh& nbrMesh = nbrMap.mesh();
    const word& Tnbr = settings_->Tnbr;
    if (!nbrMesh.foundObject<volScalarField>(Tnbr))
    {
        if (!mustExist)
        {
            return nullptr;
        }
        RuntimeIOError
            << who().c_str() << ": entry 'Tnbr " << Tnbr << "': the"
            << " neighbour region " << nbrMesh.name() << " has no"
            << " volScalarField '" << Tnbr << "' (it has: "
            << foamCompat::listed(foamCompat::namesOf<volScalarField>(nbrMesh)).c_str()
            << ")" << exit(FatalIOError);
    }
    const fvPatchScalarField& nbrPf =
        nbrMesh.lookupObject<volScalarField>(Tnbr)
       .boundaryField()[nbrMap.patchIndex()];
    if (!isA<thermalContactResistanceFvPatchScalarField>(nbrPf))
    {
        RuntimeIOError
            << who().c_str() << ": the neighbour patch "
            << nbrPf.patch().name() << " of region " << nbrMesh.name()
            << " has " << Tnbr << " of type '" << nbrPf.type()
            << "' (" << nbrPf.internalField().objectPath() << "); both sides"
            << " of the interface must be thermalContactResistance"
            << exit(FatalIOError);
    }
    return &nbrPf;
}


Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::sideKappa() const
{
    return kappaOf
    (
        *this,
        [this] { return who(); },
        [this]() -> OSstream& { return RuntimeIOError; }
    );
}


void Foam::thermalContactResistanceFvPatchScalarField::forgetMapped()
{
    coupling_.clearCache();
    nbrDeltaCoeffs_.clear();
    haveNbrDeltaCoeffs_ = false;
}


const Foam::thermalContactResistanceFvPatchScalarField&
Foam::thermalContactResistanceFvPatchScalarField::neighbour() const
{
    return refCast<const thermalContactResistanceFvPatchScalarField>
    (
        *neighbourField(true)
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfacePressure() const
{
    if (pressure_.valid())
    {
        return
            thermalContactLine::pressureValues(pressure_(), patch(), db().time());
    }
    if (!settings_->pressureFieldName.empty())
    {
        return settings_->patchValues
        (
            patch(), settings_->pressureFieldName, "pressureField",
            [this] { return who(); }
        );
    }
    return tmp<scalarField>(new scalarField(size(), Zero));
}


Foam::tmp<Foam::scalarField>
Foam::thermalContactResistanceFvPatchScalarField::interfaceGapWidth() const
{
    if (!settings_->gapFieldName.empty())
    {
        return settings_->patchValues
        (
            patch(), settings_->gapFieldName, "gapField",
            [this] { return who(); }
        );
    }
    return tmp<scalarField>
    (
        new scalarField(size(), max(settings_->gapWidth, scalar(0)))
    );
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

    const thermalContactLine::neighbourMap nbrMap(patch());
    const fvPatch& nbrPatch = nbrMap.mesh().boundary()[nbrMap.patchIndex()];
    const auto& nbrField =
        refCast<const thermalContactResistanceFvPatchScalarField>
        (
            *neighbourField(true)
        );
    if (!checkedNeighbour_)
    {
        checkNeighbour(nbrField);
    }
    const scalarField myKappa(sideKappa());

    // What this side needs of the neighbour, in one exchange: its cell
    // temperature (contact) or face temperature (h), kappa and pressure per
    // face; with a gap also its face temperature and gap width. Then (once,
    // while the mesh does not change) its deltaCoeffs.
    const bool withGap = settings_->withGap();
    const scalarField nbrT
    (
        settings_->mode == conductanceMode::constantH
      ? scalarField(nbrField)
      : nbrField.patchInternalField()()
    );
    const scalarField nbrK(nbrField.sideKappa());
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
                withGap && nbrField.hasGapWidth() ? &nbrW : nullptr,
                loadHistory() ? &nbrField.peakPressure() : nullptr
            },
            size(),
            [&nbrMap](const auto& f)
            {
                return std::decay_t<decltype(f)>(nbrMap.toThisSide(f));
            }
        );
    // The exchange is collective: decide on what every processor knows
    // alike (not on this processor's, possibly empty, face count).
    if (!haveNbrDeltaCoeffs_ || nbrMap.mesh().changing())
    {
        nbrDeltaCoeffs_ = nbrMap.toThisSide(nbrPatch.deltaCoeffs());
        haveNbrDeltaCoeffs_ = true;
    }

    const scalarField myP(interfacePressure());
    const scalarField myW
    (
        withGap && hasGapWidth() ? interfaceGapWidth()() : scalarField()
    );
    coupling_.couple
    (
        *settings_, db().time(), [this] { return who(); },
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
    refGrad() = 0.0;

    mixedFvPatchScalarField::updateCoeffs();

    evaluated_ = true;

    UPstream::msgType() = oldTag;
}


void Foam::thermalContactResistanceFvPatchScalarField::write(Ostream& os) const
{
    mixedFvPatchScalarField::write(os);
    settings_->write(os);
    if (pressure_.valid())
    {
        thermalContactLine::writePressure(os, pressure_(), db().time());
    }
    else if (!settings_->pressureFieldName.empty())
    {
        foamCompat::writeEntry(os, "pressureField", settings_->pressureFieldName);
    }
    settings_->writeGap(os);
    if (loadHistory())
    {
        foamCompat::writeFieldEntry(os, "peakPressure", coupling_.peakPressure);
    }
    writeKappa(os);
}


namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        thermalContactResistanceFvPatchScalarField
    );
}
