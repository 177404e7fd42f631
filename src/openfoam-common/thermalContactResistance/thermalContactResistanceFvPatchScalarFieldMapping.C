// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). This OpenFOAM glue builds on
// OpenFOAM (Copyright OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later).
// The condition's construction (from its dictionary, by mapping, as a copy) and the mapping of
// its state: where the two lines' patch-field APIs differ most, so the `#if` lines gather here;
// the per-step work is thermalContactResistanceFvPatchScalarField.C.
#include "thermalContactResistanceFvPatchScalarField.H"

#include "volFields.H"
#include "foamCompat.H"

#include <memory>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::thermalContactResistanceFvPatchScalarField::readPeakPressure
(
    const dictionary& dict
)
{
    const bool recorded = dict.found("peakPressure");
    const bool initial = dict.found("initialPeakPressure");
    if (!loadHistory())
    {
        if (initial)
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry 'initialPeakPressure' is the"
                << " load a joint carried before the run, for a load history;"
                << (
                       settings_->mode == conductanceMode::contact
                     ? " the contact entry has loadHistory no"
                     : " a constant 'h' has none"
                   )
                << exit(FatalIOError);
        }
        return;
    }
    scalarField& peak = coupling_.peakPressure;
    const char* entry = recorded ? "peakPressure" : "initialPeakPressure";
    // OpenFOAM's own errors of the entry (a list of another size than the
    // patch, a word for a number) thrown, then reported naming it here
    const bool throwing = foamCompat::throwFatalIOErrors();
    try
    {
        if (recorded)
        {
            // A restart (or a decomposed or mapped field): the memory as
            // written
#if defined(ROUGHCONTACT_FOUNDATION)
            peak = scalarField("peakPressure", dimPressure, dict, patch().size());
#else
            peak = scalarField("peakPressure", dict, patch().size());
#endif
        }
        else if (initial)
        {
            peak = thermalContactLine::pressureValues
            (
                thermalContactLine::newPressure
                (
                    patch(), dict, db().time(), "initialPeakPressure"
                )(),
                patch(),
                db().time()
            );
        }
        foamCompat::restoreFatalIOErrors(throwing);
    }
    catch (const IOerror& e)
    {
        foamCompat::restoreFatalIOErrors(throwing);
        FatalIOErrorAt
        (
            e.ioFileName(), e.ioStartLineNumber(), e.ioEndLineNumber()
        )
            << who().c_str() << ": entry '" << entry << "' ("
            << patch().size() << " faces): " << e.message().c_str()
            << exit(FatalIOError);
    }
    forAll(peak, facei)
    {
        if (!roughContact::isPeakPressure(peak[facei]))
        {
            FatalIOErrorInFunction(dict)
                << who().c_str() << ": entry '" << entry << "' gives "
                << peak[facei] << " Pa at face " << facei << " ("
                << patch().Cf()[facei] << "); a peak pressure must be"
                << " finite and >= 0" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

#if !defined(ROUGHCONTACT_FOUNDATION)
Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(p, iF),
    thermalContactLine::kappaSource(patch()),
    settings_(std::make_shared<const thermalContactSettings>(iF.objectPath())),
    coupling_(p.size())
{
    this->refValue() = 0.0;
    this->refGrad() = 0.0;
    this->valueFraction() = 1.0;
}
#endif


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
#if defined(ROUGHCONTACT_FOUNDATION)
    mixedFvPatchScalarField(p, iF, dict, false),
#else
    mixedFvPatchScalarField(p, iF),
#endif
    thermalContactLine::kappaSource(patch(), dict, who()),
    coupling_(p.size())
{
    // FatalIOError unless the patch is a mapped one
    const thermalContactLine::neighbourMap mapped(patch(), &dict, who());
#if defined(ROUGHCONTACT_FOUNDATION)
    mappedPatchBaseBase::validateMapForField
    (
        *this, iF, dict, mappedPatchBaseBase::from::differentPatch
    );
#endif
    settings_ = std::make_shared<const thermalContactSettings>
    (
        dict, db().time(), who(), internalField().objectPath()
    );
    if (settings_->pressureGiven)
    {
        pressure_ = thermalContactLine::newPressure(patch(), dict, db().time());
    }
    readPeakPressure(dict);
    // The neighbour's field exists already when this region is read after
    // it: a neighbour of another type is reported here, before that other
    // condition (evaluated first) fails on it with no patch or file named.
    neighbourField(false);

#if defined(ROUGHCONTACT_FOUNDATION)
    const dimensionSet& dims = iF.dimensions();
    fvPatchScalarField::operator=(scalarField("value", dims, dict, p.size()));
    if (dict.found("refValue"))
    {
        // Restart: the mixed condition's state as written
        refValue() = scalarField("refValue", dims, dict, p.size());
        refGrad() = scalarField("refGradient", dims/dimLength, dict, p.size());
        valueFraction() =
            scalarField("valueFraction", unitFraction, dict, p.size());
    }
#else
    fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    if (dict.found("refValue"))
    {
        // Restart: the mixed condition's state as written
        refValue() = scalarField("refValue", dict, p.size());
        refGrad() = scalarField("refGradient", dict, p.size());
        valueFraction() = scalarField("valueFraction", dict, p.size());
    }
#endif
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
    const thermalContactLine::mapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    thermalContactLine::kappaSource(patch(), ptf),
    settings_(ptf.settings_),
    coupling_(ptf.coupling_),
    evaluated_(ptf.evaluated_)
{
#if defined(ROUGHCONTACT_FOUNDATION)
    // As the stock coupledTemperature: the mixed condition's faces without a
    // source take the cell's temperature; the output fields follow their
    // faces, the core's results and cache are rebuilt at the next evaluation
    if (ptf.pressure_.valid())
    {
        pressure_.reset(ptf.pressure_().clone().ptr());
    }
    map(ptf, mapper);
#else
    // The output fields follow their faces; the core's results and cache
    // are rebuilt at the next evaluation
    coupling_.forEachField
    (
        ptf.coupling_,
        [&](scalarField& mine, const scalarField& theirs)
        {
            mine = scalarField(theirs, mapper);
        }
    );
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
#endif
}


#if !defined(ROUGHCONTACT_FOUNDATION)
Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf
)
:
    mixedFvPatchScalarField(ptf),
    thermalContactLine::kappaSource(patch(), ptf),
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
#endif


Foam::thermalContactResistanceFvPatchScalarField::
thermalContactResistanceFvPatchScalarField
(
    const thermalContactResistanceFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    thermalContactLine::kappaSource(patch(), ptf),
    settings_(ptf.settings_),
    pressure_
    (
        ptf.pressure_.valid()
#if defined(ROUGHCONTACT_FOUNDATION)
      ? ptf.pressure_().clone().ptr()
#else
      ? ptf.pressure_().clone(patch().patch()).ptr()
#endif
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


// * * * * * * * * * * * * * * * * * Mapping * * * * * * * * * * * * * * * * //

#if defined(ROUGHCONTACT_FOUNDATION)
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
    coupling_.forEachField
    (
        tiptf.coupling_,
        [&](scalarField& mine, const scalarField& theirs)
        {
            mapper(mine, theirs);
        }
    );
    forgetMapped();
}


void Foam::thermalContactResistanceFvPatchScalarField::reset
(
    const fvPatchScalarField& ptf
)
{
    mixedFvPatchScalarField::reset(ptf);
    const auto& tiptf =
        refCast<const thermalContactResistanceFvPatchScalarField>(ptf);
    coupling_.forEachField
    (
        tiptf.coupling_,
        [](scalarField& mine, const scalarField& theirs)
        {
            mine.reset(theirs);
        }
    );
    forgetMapped();
}
#else
void Foam::thermalContactResistanceFvPatchScalarField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    mixedFvPatchScalarField::autoMap(m);
    mapKappa(m);
    if (pressure_.valid())
    {
        pressure_->autoMap(m);
    }
    coupling_.forEachField
    (
        coupling_,
        [&](scalarField& mine, const scalarField&)
        {
            mine.autoMap(m);
        }
    );
    forgetMapped();
}


void Foam::thermalContactResistanceFvPatchScalarField::rmap
(
    const fvPatchScalarField& ptf,
    const labelList& addr
)
{
    mixedFvPatchScalarField::rmap(ptf, addr);
    rmapKappa(ptf, addr);
    const auto& tiptf =
        refCast<const thermalContactResistanceFvPatchScalarField>(ptf);
    if (pressure_.valid() && tiptf.pressure_.valid())
    {
        pressure_->rmap(tiptf.pressure_(), addr);
    }
    coupling_.forEachField
    (
        tiptf.coupling_,
        [&](scalarField& mine, const scalarField& theirs)
        {
            mine.rmap(theirs, addr);
        }
    );
    forgetMapped();
}
#endif
