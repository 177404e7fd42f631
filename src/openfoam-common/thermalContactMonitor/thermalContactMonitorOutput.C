// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). Builds on OpenFOAM (Copyright
// OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later).
// What the monitor writes: each side's fields, its log line and its interface's series (the
// numbers are the core's InterfaceMonitor; here they are gathered over the processors).
#include "thermalContactMonitor.H"
#include "thermalContactResistanceFvPatchScalarField.H"

#include "foamCompat.H"
#include "fvMesh.H"
#include "thermalContactLine.H"
#include "OSspecific.H"
#include "Time.H"
#include "volFields.H"

#include "roughContact/interface/InterfaceMonitor.hpp"

#include <fstream>
#include <string>

const char* const
Foam::functionObjects::thermalContactMonitor::outputNames[nOutputs] =
{
    "contactConductance", "contactAreaFraction", "contactPressure",
    "contactState", "gapConductance", "contactPeakPressure",
    "contactUnloading"
};


namespace
{
    using Foam::thermalContactResistanceFvPatchScalarField;

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
                &s.peakPressureArea,
                &s.areaFractionArea, &s.areaFractionPartialArea,
                &s.hTouchingArea, &s.hPartialArea, &s.hAllArea, &s.gapAllArea
            }
        )
        {
            reduce(*x, sumOp<scalar>());
        }
        for
        (
            std::size_t* c :
            {&s.apart, &s.partial, &s.complete, &s.beyondTable, &s.unloading}
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
        {hDims, dimless, dimPressure, dimless, hDims, dimPressure, dimless};
    // 1 where a face in contact is below its peak (unloaded or reloading)
    scalarField unloading(side.size(), Zero);
    if (side.loadHistory())
    {
        forAll(unloading, facei)
        {
            const scalar P = side.contactPressure()[facei];
            unloading[facei] = P > 0 && P < side.peakPressure()[facei];
        }
    }
    const scalarField* values[nOutputs] =
    {
        &side.conductance(), &side.areaFraction(), &side.contactPressure(),
        &side.contactState(), &side.gapConductance(),
        side.loadHistory() ? &side.peakPressure() : &side.contactPressure(),
        &unloading
    };
    for (label k = 0; k < nOutputs; ++k)
    {
        if
        (
            (side.constantConductance() && k != outConductance)
         || (k == outGap && !side.hasGap())
         || (k == outUnloading && !side.loadHistory())
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
                    foamCompat::timeName(mesh.time()),
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
