// SPDX-License-Identifier: GPL-3.0-or-later
// Part of roughContact, licensed GPL-3.0-or-later (LICENSE). Builds on OpenFOAM (Copyright
// OpenCFD Ltd. and The OpenFOAM Foundation; GPL-3.0-or-later).
#include "thermalContactCoupling.H"
#include "contactInterfaceFromDict.H"
#include "foamCompat.H"

#include "Pstream.H"
#include "Time.H"

#include "roughContact/thermal/InterfaceCoupling.hpp"

#include <algorithm>
#include <exception>
#include <string>

// An error found at run time (not while reading the dictionary): FatalIOError
// naming the file and lines the condition was read from.
#define RuntimeIOError                                                         \
    FatalIOErrorAt(settings.dictName, settings.dictStart, settings.dictEnd)

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::thermalContactCoupling::thermalContactCoupling(const label n)
:
    areaFraction(n, Zero),
    conductance(n, Zero),
    contactPressure(n, Zero),
    contactState(n, Zero),
    gapConductance(n, Zero),
    totalConductance(n, Zero),
    peakPressure(n, Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::thermalContactCoupling::couple
(
    const thermalContactSettings& settings,
    const Time& runTime,
    const std::function<string()>& who,
    const scalarField& kappa,
    const scalarField& deltaCoeffs,
    const scalarField& faceTemperature,
    const vectorField& faceCentres,
    const scalarField& pressure,
    const scalarField* gapWidth,
    const neighbourValues& nbr,
    const scalarField& nbrDeltaCoeffs
)
{
    using mode = thermalContactSettings::conductanceMode;
    roughContact::CouplingInputs in;
    in.n = kappa.size();
    in.kappa = kappa.cdata();
    in.deltaCoeffs = deltaCoeffs.cdata();
    in.kappaNbr = nbr.kappa.cdata();
    in.deltaCoeffsNbr = nbrDeltaCoeffs.cdata();
    try
    {
        if (settings.mode == mode::constantH)
        {
            in.faceTemperatureNbr = nbr.T.cdata();
            roughContact::coupleConstant(settings.hConstant, in, outputs);
        }
        else
        {
            settings.checkContactUnchanged(runTime, who, contactWatch);
            in.pressure = pressure.cdata();
            in.pressureNbr = nbr.pressure.cdata();
            in.cellTemperatureNbr = nbr.T.cdata();
            if (settings.withGap())
            {
                // The gap's terms need both face temperatures and the widths
                // both sides give.
                in.faceTemperature = faceTemperature.cdata();
                in.faceTemperatureNbr = nbr.faceTemperature.cdata();
                if (gapWidth)
                {
                    in.gapWidth = gapWidth->cdata();
                    in.gapWidthNbr = nbr.gapWidth.cdata();
                }
            }
            if (settings.interface->loadHistory())
            {
                in.peakPressure = peakPressure.cdata();
                in.peakPressureNbr = nbr.peakPressure.cdata();
            }
            roughContact::couple(*settings.interface, in, cache, outputs);
            if (settings.interface->loadHistory())
            {
                std::copy
                (
                    outputs.peakPressure.begin(), outputs.peakPressure.end(),
                    peakPressure.begin()
                );
            }
        }
    }
    catch (const roughContact::FaceError& e)
    {
        const label facei = label(e.face());
        RuntimeIOError
            << who().c_str() << ": face " << facei << " at "
            << faceCentres[facei] << ": pressure " << pressure[facei]
            << " Pa on this side and " << nbr.pressure[facei] << " Pa on the"
            << " neighbour's, kappa " << kappa[facei] << " and "
            << nbr.kappa[facei] << " W/m/K, deltaCoeffs "
            << deltaCoeffs[facei] << " and " << nbrDeltaCoeffs[facei]
            << " 1/m: " << e.what() << exit(FatalIOError);
    }
    catch (const std::exception& e)
    {
        RuntimeIOError
            << who().c_str() << ": the interface coupling of the faces"
            << (
                   settings.contactName.empty()
                 ? std::string()
                 : " (contact '" + settings.contactName + "')"
               ).c_str()
            << " failed: " << e.what() << exit(FatalIOError);
    }

    // The output fields, at every evaluation: function objects may sample
    // them at any time step (a history of contactConductance, say).
    const roughContact::CouplingOutputs& out = outputs;
    forAll(conductance, facei)
    {
        const scalar kDelta = kappa[facei]*deltaCoeffs[facei];
        const scalar kDeltaNbr = nbr.kappa[facei]*nbrDeltaCoeffs[facei];
        conductance[facei] = roughContact::shownConductance
        (
            out.contactConductance[facei], kDelta, kDeltaNbr
        );
        totalConductance[facei] = roughContact::shownConductance
        (
            out.conductance[facei], kDelta, kDeltaNbr
        );
        areaFraction[facei] = out.areaFraction[facei];
        contactPressure[facei] = out.pressure[facei];
        contactState[facei] = roughContact::contactStateCode(out.state[facei]);
        gapConductance[facei] =
            out.gapConductance[facei] + out.radiativeConductance[facei];
    }

    if (settings.mode != mode::contact)
    {
        return;
    }
    if (!saidLoadHistory)
    {
        const std::string note = settings.interface->loadHistoryNote();
        if (!note.empty())
        {
            Info<< "thermalContactResistance: " << who().c_str() << ": "
                << note.c_str() << endl;
        }
        saidLoadHistory = true;
    }
    const bool apart = out.apart > 0;
    const bool beyondTable = out.beyondTable > 0;
    if (returnReduce(apart, orOp<bool>()) && !warnedNoContact)
    {
        Info<< "thermalContactResistance: " << who().c_str()
            << ": zero or negative pressure on some faces: the surfaces"
            << " do not touch there ("
            << (settings.interface->hasGap()
                ? "only the gap's conductance remains)"
                : "h = 0, no heat crosses)") << endl;
        warnedNoContact = true;
    }
    if (returnReduce(beyondTable, orOp<bool>()) && !warnedBeyondTable)
    {
        WarningInFunction
            << who().c_str() << ": pressures above "
            << settings.interface->tableEnd()
            << " Pa, the end of the table of contact '" << settings.contactName
            << "' (its maxPressure), and below complete contact ("
            << settings.interface->completeContactPressure()
            << " Pa): h is held at the table's last value"
            << " there. Raise maxPressure." << endl;
        warnedBeyondTable = true;
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
        d.belowTableMessage(*settings.interface),
        d.pressureMismatchMessage(),
        d.apartAtFirstTouchMessage(*settings.interface)
    };
    for (label k = 0; k < 3; ++k)
    {
        if (!messages[k].empty() && !(warnedInput & (1 << k)))
        {
            WarningInFunction
                << who().c_str() << ": " << messages[k].c_str() << endl;
            warnedInput |= (1 << k);
        }
    }
    // The regime at the faces' pressures, summed over processors: their
    // pressures at every evaluation, h's parts only when the core's log says
    // it is due (the same on every processor: it is of the reduced sums).
    roughContact::FaceSums s;
    s.addPressures(out);
    scalar counts[3] =
        {scalar(s.inContact), scalar(s.faces), scalar(s.unloading)};
    for (scalar& c : counts)
    {
        reduce(c, sumOp<scalar>());
    }
    reduce(s.pressureMin, minOp<scalar>());
    reduce(s.pressureMax, maxOp<scalar>());
    reduce(s.pressureSum, sumOp<scalar>());
    reduce(s.unloadingPeakMin, minOp<scalar>());
    reduce(s.unloadingPeakMax, maxOp<scalar>());
    reduce(s.unloadingFractionMin, minOp<scalar>());
    s.inContact = std::size_t(counts[0]);
    s.faces = std::size_t(counts[1]);
    s.unloading = std::size_t(counts[2]);
    // check yes: made once, at the first evaluation, at the faces' pressures
    // unless the entry gives checkPressures.
    contactInterfaces::New(runTime).checkOnce
    (
        settings.contactKey, who(), s.pressuresToCheck()
    );
    if (regimeLog.due(s))
    {
        s.addConductances(out);
        scalar complete = scalar(s.complete);
        reduce(complete, sumOp<scalar>());
        reduce(s.contactSum, sumOp<scalar>());
        reduce(s.gasSum, sumOp<scalar>());
        reduce(s.radiationSum, sumOp<scalar>());
        s.complete = std::size_t(complete);
        Info<< "thermalContactResistance: " << who().c_str() << ": "
            << roughContact::FaceRegimeLog::describe(*settings.interface, s).c_str()
            << endl;
    }
}
