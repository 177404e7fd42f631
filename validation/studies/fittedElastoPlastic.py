# SPDX-License-Identifier: GPL-3.0-or-later
"""The default law fittedElastoPlastic fitted to the exact answers, and held to the surfaces it was not fitted on.

The fit evaluates the law as the core runs it (validation/fitting.py: the core's law with the
constants being fitted). Its seven constants are fitted as the law is built: the elastic branch
(C_E, A, beta) on the engineering range's four training spectra, elastic; the plastic branch and
the blend (C_P, K, N) on their capped points; the light-load slope A_s1 on the light loads of
those four and of the eight spectra of spectralShapes; in turn until none moves. The skewness
factor's constants are the skewness study's fit, the heavy-load rate's the heavyLoads study's, the
unloading branch's the unloading study's.
`run` writes all of them into src/core/roughContact/thermal/FittedElastoPlasticConstants.inc;
`check` fits again from the committed data and fails where that file differs (docs/validation/
fittedElastoPlastic.md). Held out: the X3P map and the second hold-out, never fitted.
"""
import math
import os

import numpy

from .. import fitting, materials, pages, spectra
from ..context import ROOT
from ..tables import Table, number
from . import engineeringRange

DATA = ["secondHoldOutEarlier.csv"]
CONSTANTS = os.path.join("src", "core", "roughContact", "thermal", "FittedElastoPlasticConstants.inc")
FITTED = ["elasticPrefactor", "elasticExponent", "elasticGrowth", "plasticPrefactor", "plasticExponent", "blend",
          "lightLoadShareSlope"]
# Where the fit starts (the minimax is flat near its optimum, so the start is part of the result):
# the first fit's constants (one-period references), with a growth for the former pole; the plastic
# prefactor the first fit's over W = 0.6; the light-load slope 0 (the law without its factor l).
START = dict(zip(FITTED, [0.5199, 0.7920, 12.0, 0.8588, 0.1997, 1.2605, 0.0]))
# The light-load factor's own parameters (FittedElastoPlastic.hpp, l(s1, x)): s1_0 about the middle
# of the training spectra's s1, x_r the load below which l acts, and the training spectra's s1.
LIGHT = {"lightLoadSharePivot": 0.3, "lightLoadEnd": 0.01, "lightLoadShareLeast": 0.11, "lightLoadShareMost": 0.86}
ELASTIC, PLASTIC, SLOPE = FITTED[:3], FITTED[3:6], FITTED[6:]
# The alternation's end: no constant moves by more than this share of itself in a round, within ROUNDS.
SETTLED, ROUNDS = 2e-5, 40
HOLDOUT = {"x3p"}  # the engineering range's surface never fitted
SECOND = "selfAffine06ro2"  # the second hold-out (validation/studies/secondHoldOut.py)
WHAT = {
    "elasticPrefactor": "C_E: the elastic branch's prefactor", "elasticExponent": "A: the elastic branch's power of P",
    "elasticGrowth": "beta: the elastic growth's rate up to x_g", "plasticPrefactor": "C_P: the plastic branch's prefactor",
    "plasticExponent": "K: the plastic branch's power of 1 - P/H", "blend": "N: the smooth maximum's power",
    "lightLoadShareSlope": "A_s1: the light-load factor's slope in s1",
    "lightLoadSharePivot": "s1_0: l = 1 there, about the middle of the training spectra's s1",
    "lightLoadEnd": "x_r: l acts below it",
    "lightLoadShareLeast": "the training spectra's least s1: l holds s1 there below it",
    "lightLoadShareMost": "the training spectra's largest s1: l holds s1 there above it",
}


def valid(c):
    return c.elasticExponent > 0 and c.blend > 0.2 and c.elasticPrefactor > 0 and c.plasticPrefactor > 0


def engineering_points(ctx):
    """The engineering range's exact answers with what the law takes of each surface."""
    rc = ctx.rc()
    exact = engineeringRange.Exact(ctx)
    rough = {}
    for s in exact.surfaces:
        d = s.description
        spec = (rc.SurfaceSpec.spectrum(d[1]) if d[0] == "--spectrum"
                else rc.SurfaceSpec.areal(d[1], direction=d[d.index("--direction") + 1]))
        r = spec.roughness()
        k = spec.skewness()  # a map's heights' (a spectrum's surfaces are Gaussian)
        spectrum = spec.read_spectrum()
        rough[s.name] = (r.sigma, r.mean_absolute_slope, rc.spectral_bandwidth_ratio(spectrum),
                         rc.shrunk_skewness(k) if k is not None else 0.0, rc.first_level_share(spectrum))
    out = []
    for row in exact.rows():
        pair = materials.regime_pair(ctx, row["regime"])
        sigma, m, w, skew, s1 = rough[row["surface"]]
        x, gradient = float(row["x"]), float(row["gradient"])
        out.append({"surface": row["surface"], "regime": row["regime"], "x": x, "gradient": gradient,
                    "sigma": sigma, "m": m, "w": w, "s1": s1, "E": pair.Eprime, "H": pair.hardness,
                    "P": x * pair.Eprime * gradient, "s": skew, "n": int(row["realizations"]),
                    "area": float(row["exact_area"]), "exact": float(row["exact_h_per_k"]),
                    "role": "holdout" if row["surface"] in HOLDOUT else "training"})
    return out


def second_points(ctx):
    """The second hold-out: an earlier study's one-period answers (validation/data/
    secondHoldOutEarlier.csv), its light loads replaced by the secondHoldOut study's periods of 8L."""
    from . import secondHoldOut
    rc = ctx.rc()
    spec = secondHoldOut.spectrum(ctx)
    w, s1 = rc.spectral_bandwidth_ratio(rc.Spectrum.read(spec)), rc.first_level_share(rc.Spectrum.read(spec))
    light = {(r["regime"], float(r["x"])): r for r in secondHoldOut.summary(ctx).rows}
    E = materials.regime_pair(ctx, "elastic").Eprime
    out, replaced = [], 0
    for row in Table.read(os.path.join(ctx.data if not ctx.quick else os.path.join(ROOT, "validation", "data"),
                                       DATA[0])).rows:
        sigma, m, gradient, x = (float(row[k]) for k in ("sigma_m", "m", "gradient", "x"))
        match = [r for (regime, xl), r in light.items() if regime == row["regime"] and abs(xl / x - 1) < 1e-6]
        realizations, area, h = row["realizations"], row["area_fraction"], row["h_per_k_per_m"]
        if match:
            realizations, area, h = match[0]["realizations"], match[0]["area"], match[0]["h_per_k"]
            replaced += 1
        H = None if row["regime"] == "elastic" else float(row["regime"][3:]) * E * gradient
        P = x * E * gradient
        out.append({"surface": row["surface"], "regime": row["regime"], "x": x, "gradient": gradient, "sigma": sigma,
                    "m": m, "w": w, "s1": s1, "E": E, "H": H, "P": P, "s": 0.0, "n": int(realizations),
                    "area": float(area), "exact": float(h), "role": "holdout"})
    if replaced != len(light):
        raise SystemExit(f"fittedElastoPlastic: the second hold-out's periods have {len(light)} loads, "
                         f"{replaced} of them in {DATA[0]}")
    return out


def slope_points(ctx):
    """The eight spectra of spectralShapes: the light-load slope A_s1 is fitted on them too."""
    from . import spectralShapes
    rc = ctx.rc()
    out, shares = [], {}
    for row in spectralShapes.summary(ctx).rows:
        sigma, m, w, gradient, x, E = (float(row[k]) for k in ("sigma", "m", "bandwidth", "gradient", "x", "Eprime"))
        if float(row["area"]) > engineeringRange.COMPLETE:  # as the engineering range: no ratio there
            continue
        if row["surface"] not in shares:
            shares[row["surface"]] = rc.first_level_share(rc.Spectrum.read(spectralShapes.spectrum(ctx, row["surface"])))
        out.append({"surface": row["surface"], "regime": row["regime"], "x": x, "gradient": gradient, "sigma": sigma,
                    "m": m, "w": w, "s1": shares[row["surface"]], "E": E, "H": float(row["H"]) if row["H"] else None,
                    "P": x * E * gradient, "s": 0.0, "n": int(row["realizations"]), "area": float(row["area"]),
                    "exact": float(row["h_per_k"]), "role": "slope"})
    return out


def points(ctx):
    return fitting.Points(engineering_points(ctx) + second_points(ctx) + slope_points(ctx))


def fit(ctx, pts):
    """The seven constants, fitted in turn until settled (the module's doc), the others the core's."""
    rc = ctx.rc()
    c = fitting.constants(rc, {**START, **LIGHT})
    training = pts.where(lambda r: r["role"] == "training")
    elastic = training.where(lambda r: r["H"] is None)
    capped = training.where(lambda r: r["H"] is not None)
    slope = pts.where(lambda r: r["role"] in ("training", "slope"))
    light = fitting.Points([r for r, xl in zip(slope.rows, slope.xl) if xl <= LIGHT["lightLoadEnd"] * (1 + 1e-9)])
    c = fitting.minimax(rc, c, ELASTIC + SLOPE, elastic, valid)
    c = fitting.minimax(rc, c, PLASTIC, capped, valid)
    for _ in range(ROUNDS):
        before = numpy.array([getattr(c, n) for n in FITTED])
        c = fitting.minimax(rc, c, SLOPE, light, valid)
        c = fitting.minimax(rc, c, ELASTIC, elastic, valid)
        c = fitting.minimax(rc, c, PLASTIC, capped, valid)
        after = numpy.array([getattr(c, n) for n in FITTED])
        if numpy.all(numpy.abs(after - before) <= SETTLED * numpy.abs(before)):
            return fitting.minimax(rc, c, SLOPE, light, valid), (elastic, capped, light)
    if ctx.quick:  # small grids' answers: the fit's code has run, its constants mean nothing
        print(f"fittedElastoPlastic: the light-load slope and the branches did not settle in {ROUNDS} rounds "
              "on the quick data (a smoke test: the constants are not the product's)", flush=True)
        return fitting.minimax(rc, c, SLOPE, light, valid), (elastic, capped, light)
    raise SystemExit(f"fittedElastoPlastic: the light-load slope and the branches did not settle in {ROUNDS} rounds")


def constant_sets(ctx):
    """[(name, value, what)] of every constant of the law in the order of the core's
    FittedElastoPlasticConstants.inc: the fit's (rounded to 4 decimals, as the file keeps them),
    the light-load factor's parameters, and the skewness and heavyLoads studies' (their fits,
    rounded, and their own ranges)."""
    from . import heavyLoads, skewness, unloading
    pts = points(ctx)
    fitted, _ = fit(ctx, pts)
    values = {n: round(getattr(fitted, n), 4) for n in FITTED}
    values.update(LIGHT)
    what = dict(WHAT)
    for study in (skewness, heavyLoads, unloading):
        found = study.fit(ctx)
        for name, (value, description) in found.items():
            values[name] = round(value, 4)
            what[name] = description
    names = ctx.rc().FittedElastoPlasticConstants.names()
    missing = [n for n in names if n not in values]
    if missing:
        raise SystemExit(f"fittedElastoPlastic: no study gives the constants {missing}")
    return [(n, values[n], what[n] + (" (fitted: fittedElastoPlastic)" if n in FITTED else "")) for n in names], pts


def constants_text(sets):
    lines = ["// SPDX-License-Identifier: GPL-3.0-or-later",
             "// Written by `python3 -m validation run fittedElastoPlastic` (validation/studies/fittedElastoPlastic.py)",
             "// from the studies' committed data: do not edit. `python3 -m validation check fittedElastoPlastic`",
             "// fits them again and fails where they differ (docs/validation/fittedElastoPlastic.md).",
             "// ROUGHCONTACT_FITTED_CONSTANT(name, value, what it is)"]
    lines += [f'ROUGHCONTACT_FITTED_CONSTANT({n}, {v!r}, "{w}")' for n, v, w in sets]
    return "\n".join(lines) + "\n"


def outputs(ctx):
    from . import fittedElastoPlasticTables
    rc = ctx.rc()
    sets, pts = constant_sets(ctx)
    chosen = fitting.constants(rc, {n: v for n, v, _ in sets})
    if ctx.checking:
        # The minimax is flat near its optimum: another numpy or libm may walk the simplex to other
        # constants with the same worst miss. Then the committed constants (the core's) stand when
        # they miss by no more than the fit's own (1e-3 in |law/exact - 1|) on each stage's points.
        built = rc.FittedElastoPlasticConstants()
        differ = [n for n, v, _ in sets if abs(v - getattr(built, n)) > max(5e-4 * abs(getattr(built, n)), 6e-5)]
        if differ:
            _, stages = fit(ctx, pts)
            if all(fitting.worst(rc, built, s) <= fitting.worst(rc, chosen, s) + 1e-3 for s in stages):
                print(f"fittedElastoPlastic: the fit walked to other values of {differ}; the committed constants "
                      "miss no more than those, and stand")
                sets = [(n, getattr(built, n) if n in differ else v, w) for n, v, w in sets]
                chosen = built
    out = pages.Outputs(ctx, "fittedElastoPlastic")
    out.source(CONSTANTS, constants_text(sets))
    for name, names in THEORY_LINES.items():
        out.block(os.path.join("docs", "theory.md"), name, constants_line(sets, names))
    fittedElastoPlasticTables.tables(ctx, out, chosen, pts, sets)
    return out


# The lines of docs/theory.md that give the fitted constants, by block name: each its constants.
THEORY_LINES = {"loading-constants": FITTED,
                "heavy-load-constants": ["heavyLoadGrowth", "heavyLoadGrowthSlope"],
                "skewness-constants": ["skewnessSlope", "skewnessSlopeLog", "skewnessCurvature"],
                "unloading-constants": ["unloadingBase", "unloadingBandwidthLeast", "unloadingFlow", "unloadingTail",
                                        "unloadingHurstPivot", "unloadingFlowHurst", "unloadingSpread",
                                        "unloadingCrowded"]}


def constants_line(sets, names):
    """"C_E = 0.8515, A = 0.8715, ... and K = 0.5142.": the constants' symbols (what each is
    says first, before its colon) with their values as the core holds them."""
    given = {n: (v, w.split(":")[0]) for n, v, w in sets}
    terms = [f"{given[n][1]} = {given[n][0]!r}" for n in names]
    return ", ".join(terms[:-1]) + f" and {terms[-1]}.\n"


def solve(ctx):
    """No solves of its own: it fits what the other studies solved."""
    return 0


def exact(ctx):
    """The fit's points as its generated exact.csv holds them (a Table: surface, role, sigma_m, m,
    bandwidth, gradient, regime, Eprime_Pa, H_Pa, x, realizations, area_fraction, h_per_k_per_m,
    law_over_exact, skewness, first_level_share; x as %.6g text): what the studies after it read
    (`check fittedElastoPlastic` keeps it the fit's)."""
    return pages.generated(ctx, "fittedElastoPlastic", "exact.csv")
