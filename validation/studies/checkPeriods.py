# SPDX-License-Identifier: GPL-3.0-or-later
"""The check's period at light loads: the default law's ratio as check() reports it on periods of 1, 2 and 4 scan lengths, against 8L.

The check (multiscaleContact --check, check() in Python, `check yes;`; SurfaceCheck.hpp) solves a
profile's or spectrum's surface on a 512^2 grid, three seeds. Below p/(E' h') = 1e-3 a period of
one scan length L holds few contact spots, and the default law is fitted on periods of 8L; at the
same cost the check can solve a period of kL on the same grid, the spectrum on that period cut at
wavelengths of 8 cells (kL/64). Measured: the default law's ratio to the exact answer as check()
reports it (light_load_periods = 1, 2, 4) at x = 1e-4, 2.15e-4 and 4.64e-4, against the law's
ratio to the reference, a period of 8L with all 64 levels (docs/validation/generated/fittedElastoPlastic/
exact.csv: the engineering range's four training spectra, elastic, copper and steel; the eight
spectra of spectralShapes, elastic and steel). Its data are the checks' CSVs, one row a check
and pressure (keys: name, regime, periods). docs/validation/checkPeriods.md reads the tables.
"""
import concurrent.futures
import math
import os
import statistics
import time

from .. import checks, materials, pages, spectra, tables
from ..context import ROOT
from ..tables import Table, number
from . import engineeringRange, spectralShapes

DATA = ["checkPeriods.csv"]
STUDY = "checkPeriods"
KEYS = ["name", "regime", "periods"]
COLUMNS = ["nominal_pressure", "nominal_pressure_per_Eprime", "area_exact", "h_per_k_exact", "h_per_k_exact_min",
           "h_per_k_exact_max", "ratio_jacksonBhavnaniFerguson", "ratio_multiscaleBarber", "ratio_persson",
           "ratio_mikic", "ratio_cooperMikicYovanovich", "ratio_fittedElastoPlastic"]
LEVELS = 64  # the spectra as the engineering range and spectralShapes solve them (512/8 levels)
TRAINING = [name for name, _, _, _ in engineeringRange.SELF_AFFINE] + ["dektak"]  # the fit's four
LOADS = ["0.0001", "0.000215443", "0.000464159"]  # x as exact.csv prints it (below 1e-3: the light loads)
BAND = 0.25  # the check's verdict: the law within 25 %
COMMENT = ("# The default law's ratio to the exact conductance as the check reports it (law_over_check; the\n"
           "# check on periods of `periods` scan lengths below p/(E' h') = 1e-3, 3 seeds of 512^2) and to\n"
           "# the reference (law_over_reference: a period of 8L, docs/validation/generated/fittedElastoPlastic/exact.csv),\n"
           "# and the check's seeds' spread (largest over smallest exact h); written by\n"
           "# validation/studies/checkPeriods.py.\n")


class Design:
    """The checks: (name, role, regimes) of each spectrum, the light-load periods, the grid and
    seeds (the check's defaults: 512^2, seeds 1-3)."""

    def __init__(self, quick):
        training = [(n, "training", ("elastic", "copperCopper", "steelSteel")) for n in TRAINING]
        eight = [(n, "eight spectra", ("elastic", "steelSteel")) for n, _, _ in spectralShapes.SHAPES]
        if quick:
            self.cases = [(training[0][0], "training", ("elastic", "steelSteel")), (eight[0][0], "eight spectra",
                                                                                   ("elastic",))]
            self.periods, self.grid, self.seeds = [1, 2, 4], 128, [1, 2]
        else:
            self.cases = training + eight
            self.periods, self.grid, self.seeds = [1, 2, 4], 512, [1, 2, 3]


def spectrum(ctx, name):
    """The spectrum file of a case (the scratch folder's, made again from its definition)."""
    path = ctx.scratch_path(STUDY, name + ".spectrum")
    if name == "dektak":
        return spectra.profile_spectrum(ctx, path, engineeringRange.DEKTAK, LEVELS)
    shape = next((s for s in engineeringRange.SELF_AFFINE if s[0] == name), None)
    if shape:
        return spectra.self_affine(path, shape[1], shape[2], LEVELS)
    _, hurst, rolloff = next(s for s in spectralShapes.SHAPES if s[0] == name)
    return spectra.self_affine(path, hurst, rolloff, LEVELS, spectralShapes.GRADIENT, spectralShapes.LENGTH)


def exact_rows(ctx):
    """{(surface, regime, x): row} of the reference, the fit's exact.csv; the columns used:
    surface, regime, x, gradient and law_over_exact."""
    from . import fittedElastoPlastic
    return {(r["surface"], r["regime"], r["x"]): r for r in fittedElastoPlastic.exact(ctx).rows}


def pressures(ctx, exact, name, regime):
    """The checked pressures [Pa]: x E' h' at LOADS, h' exact.csv's. The lightest, x = 1e-4, is
    the check's range's edge, which it computes from the spectrum's own h' (exact.csv's to six
    digits): 1e-5 above it, every load alike."""
    E = materials.regime_pair(ctx, regime).Eprime
    return [float(x) * E * float(exact[(name, regime, x)]["gradient"]) * (1 + 1e-5) for x in LOADS]


def store(ctx):
    return Table.read(os.path.join(ctx.data, STUDY + ".csv"), KEYS + COLUMNS)


def rows_of(table, name, regime, k):
    return [r for r in table.rows if (r["name"], r["regime"], r["periods"]) == (name, regime, str(k))]


def has(table, key, ps):
    rows = rows_of(table, *key)
    return all(any(abs(number(r["nominal_pressure"]) / p - 1) < 1e-6 for r in rows) for p in ps)


def run_check(ctx, design, name, regime, ps, k):
    """check() of a case on periods of k scan lengths: its CSV rows (one a pressure)."""
    rc = ctx.rc()
    if regime == "elastic":
        a = b = materials.STEEL
        side1, side2 = rc.Material(a[0], a[1]), rc.Material(b[0], b[1])
    else:
        _, _, a, b = materials.pair_of(regime)
        side1, side2 = rc.Material(a[0], a[1], a[2]), rc.Material(b[0], b[1], b[2])
    capped = regime != "elastic"
    c = rc.check(surfaces=[rc.SurfaceSpec.spectrum(spectrum(ctx, name))], side1=side1, side2=side2,
                 model="jacksonGreen" if capped else "hertz", hardness_from_yield=capped, pressures=ps,
                 grid=design.grid, seeds=design.seeds, threads=1, light_load_periods=k)
    if len(c.pressures) != len(ps):
        raise SystemExit(f"checkPeriods: {name} {regime} periods {k}: the check dropped {list(c.dropped)} Pa")
    return checks.rows(c.csv(), COLUMNS)


def solve(ctx):
    """The checks whose rows are missing: run (ctx.jobs at a time, saving after each); in check,
    that none is missing."""
    design = Design(ctx.quick)
    exact = exact_rows(ctx)
    table = store(ctx)
    jobs = [((name, regime, k), pressures(ctx, exact, name, regime)) for name, _, regimes in design.cases
            for regime in regimes for k in design.periods]
    todo = [(key, ps) for key, ps in jobs if not has(table, key, ps)]
    path = os.path.join(ctx.data, STUDY + ".csv")
    if ctx.checking:
        if todo:
            raise SystemExit(f"validation: {len(todo)} checks of {ctx.relative(path)} are missing (the first: "
                             f"{todo[0][0]}); python3 -m validation run {STUDY} runs them")
        return
    if not todo:
        return
    print(f"{STUDY}: {len(todo)} checks, {ctx.jobs} at a time", flush=True)
    started = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=ctx.jobs) as pool:
        done = pool.map(lambda j: (j[0], run_check(ctx, design, j[0][0], j[0][1], j[1], j[0][2])), todo)
        for i, ((name, regime, k), rows) in enumerate(done):
            for r in rows_of(table, name, regime, k):
                table.rows.remove(r)
            table.rows += [{"name": name, "regime": regime, "periods": str(k), **{c: r.get(c, "") for c in COLUMNS}}
                           for r in rows]
            table.sort(KEYS + ["nominal_pressure"])
            table.write(path)
            if not ctx.quick:
                tables.record(ctx.data, STUDY + ".csv", f"python3 -m validation run {STUDY}")
            print(f"  [{i + 1}/{len(todo)}, {time.time() - started:.0f} s] {name} {regime} periods {k}", flush=True)


def summary(ctx, design):
    """summary.csv's rows: per spectrum, regime, periods and load, the law's ratio to the
    reference and as the check reports it, and the check's seeds' spread."""
    exact = exact_rows(ctx)
    table = store(ctx)
    rows = []
    for name, role, regimes in design.cases:
        for regime in regimes:
            E = materials.regime_pair(ctx, regime).Eprime
            for k in design.periods:
                checked = sorted(rows_of(table, name, regime, k), key=lambda r: number(r["nominal_pressure"]))
                for x, c in zip(LOADS, checked):
                    e = exact[(name, regime, x)]
                    if abs(number(c["nominal_pressure"]) / (float(x) * E * float(e["gradient"])) - 1) > 2e-5:
                        raise SystemExit(f"checkPeriods: {name} {regime} periods {k}: checked at "
                                         f"{c['nominal_pressure']} Pa, not x = {x}")
                    rows.append({"surface": name, "role": role, "regime": regime, "x": x, "periods": k,
                                 "law_over_reference": e["law_over_exact"],
                                 "reference": "8L" if float(x) <= 1e-3 * (1 + 1e-9) else "",
                                 "law_over_check": f"{number(c['ratio_fittedElastoPlastic']):.4f}",
                                 "check_spread":
                                     f"{number(c['h_per_k_exact_max']) / number(c['h_per_k_exact_min']):.3f}"})
    return rows


def stats(sel):
    check = [float(r["law_over_check"]) for r in sel]
    reference = [float(r["law_over_reference"]) for r in sel]
    errors = sorted(abs(math.log(a / b)) for a, b in zip(check, reference))
    ratio = sorted(a / b for a, b in zip(check, reference))
    agree = sum((abs(a - 1) <= BAND) == (abs(b - 1) <= BAND) for a, b in zip(check, reference))
    return [len(sel), f"{math.exp(statistics.median(errors)):.2f}", f"{math.exp(errors[-1]):.2f}",
            f"{statistics.median(ratio):.2f}", sum(e <= math.log(1.1) for e in errors),
            sum(e <= math.log(1 + BAND) for e in errors), agree]


def outputs(ctx):
    design = Design(ctx.quick)
    rows = summary(ctx, design)
    out = pages.Outputs(ctx, STUDY)
    out.text("summary.csv", COMMENT + Table(list(rows[0].keys()), rows).text())
    table = []
    for label, keep in (("training", lambda r: r["role"] == "training"),
                        ("eight spectra", lambda r: r["role"] == "eight spectra"), ("all", lambda r: True)):
        for k in design.periods:
            sel = [r for r in rows if keep(r) and r["periods"] == k]
            if sel:
                table.append([label, f"{k}L"] + stats(sel))
    out.table("periods", ["spectra", "periods of the check", "points", "median factor check/reference",
                          "largest factor", "median check / reference", "within 10 %",
                          f"within {100 * BAND:.0f} %", "verdict as the reference's"], table)
    table = []
    for name, role, regimes in design.cases:
        for regime in regimes:
            sel = [r for r in rows if r["surface"] == name and r["regime"] == regime]
            first = [float(r["law_over_reference"]) for r in sel if r["periods"] == design.periods[0]]
            table.append([name, role, regime, pages.span(first)]
                         + [pages.span([float(r["law_over_check"]) for r in sel if r["periods"] == k])
                            for k in design.periods])
    out.table("spectra", ["spectrum", "role", "regime", "law / reference"] + [f"law / check, {k}L"
                                                                              for k in design.periods], table)
    out.table("parameters", ["what", "value"], [
        ["the check's grid and seeds", f"{design.grid}^2, seeds {', '.join(str(s) for s in design.seeds)}"],
        ["its light-load periods (light_load_periods)", ", ".join(f"{k}L" for k in design.periods)],
        ["the loads x = p/(E' h')", ", ".join(f"{float(x):.3g}" for x in LOADS)],
        ["the spectra's levels on L", str(LEVELS)],
        ["the verdict: the law within", f"{100 * BAND:.0f} %"]])
    return out
