# SPDX-License-Identifier: GPL-3.0-or-later
"""Each law on surfaces given by their roughness numbers: the CLI's check (--roughness RQ,SLOPE --check) of four stylus-report surfaces.

The band for `type roughness`, `--roughness`, `SurfaceSpec.from_roughness` (issue 22, item 4). Four
surfaces a stylus report could give (Rq and rms slope Rdq; the self-affine power law over the
default band 2.5 um to 0.8 mm, docs/theory.md §1.4), steel on steel, elastic (area model hertz)
and capped (jacksonGreen, H = 2.84 S_y of S_y = 400 MPa): `multiscaleContact --roughness RQ,SLOPE
--check` at 0.1, 1, 10 and 100 MPa (those within p/(E' h') 1e-4 to 1e-1), the exact
boundary-element model on three 512 x 512 surfaces synthesized from the spectrum
(docs/checking.md). Its data are the checks' outputs (their CSV, and from their report the Hurst
exponent, the levels the grid holds and the light-load period), one row a check and pressure:
`run` runs the eight checks again (about half a minute with two at a time on this project's 2-core
machine), and so does `check`, which compares them with the table digit for digit (the laws' ratios
are the check's, on its own surfaces: they are not recomputed from the exact columns). docs/validation/roughness.md reads the table.
"""
import concurrent.futures
import os
import re
import subprocess
import time

from .. import checks, materials, pages, tables
from ..tables import Table, number

DATA = ["roughness.csv"]
STUDY = "roughness"
KEYS = ["regime", "rq_m", "rdq"]
# From the check's report: its seeds and grid, the Hurst exponent found from Rdq/Rq, the levels the
# grid holds of the surface's, the period (scan lengths) it solves at light loads.
REPORT = ["seeds", "grid", "hurst", "levels_kept", "levels_given", "light_load_periods"]
LAWS = ["jacksonBhavnaniFerguson", "multiscaleBarber", "persson", "mikic", "fittedElastoPlastic",
        "cooperMikicYovanovich"]
COLUMNS = ["nominal_pressure", "nominal_pressure_per_Eprime", "area_exact", "h_per_k_exact", "h_per_k_exact_min",
           "h_per_k_exact_max"] + [f"ratio_{law}" for law in LAWS]
SURFACES = [(0.2e-6, 0.05), (0.8e-6, 0.1), (1.6e-6, 0.05), (0.4e-6, 0.2)]  # (Rq [m], Rdq)
SOLID = (materials.STEEL[0], materials.STEEL[1], 400e6)  # steel, S_y = 400 MPa
PRESSURES = [0.1e6, 1e6, 10e6, 100e6]  # [Pa]
# (key, label, area model, capped)
REGIMES = [("elastic", "elastic", "hertz", False), ("capped", "capped", "jacksonGreen", True)]


class Design:
    def __init__(self, quick):
        self.surfaces = SURFACES[:2] if quick else SURFACES
        self.grid = 128 if quick else None  # None: the check's own (512)


def pair(ctx, capped):
    return materials.Pair(ctx, SOLID, SOLID, capped)


def key_of(regime, rq, slope):
    return {"regime": regime, "rq_m": f"{rq:g}", "rdq": f"{slope:g}"}


def run_check(ctx, design, regime, rq, slope):
    """The CLI's check of one surface: its CSV rows, each with the report's facts."""
    _, _, model, capped = next(r for r in REGIMES if r[0] == regime)
    args = ([ctx.cli, "--roughness", f"{rq:g},{slope:g}", "--model", model] + pair(ctx, capped).arguments +
            (["--hardness-from-yield"] if capped else []) +
            ["--pressures", ",".join(f"{p:g}" for p in PRESSURES), "--check", "--threads", "1"] +
            (["--synthesize", str(design.grid)] if design.grid else []))
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"roughness: {' '.join(args)} failed:\n{r.stderr}")
    report = "\n".join(line for line in r.stdout.splitlines() if line.startswith("#"))
    found = [re.search(p, report, re.S) for p in (r"check of the surface: (\d+) seeds of (\d+) x",
                                                   r"self-affine, H = ([0-9.]+)\)",
                                                   r"holds the surface's (\d+) longest levels of (\d+)",
                                                   r"on periods of (\d+) scan lengths")]
    if not all(found):
        raise SystemExit(f"roughness: the check's report no longer says its Hurst exponent, levels or light-load "
                         f"period (update validation/studies/roughness.py):\n{report}")
    facts = dict(zip(REPORT, [v for m in found for v in m.groups()]))
    data = "\n".join(line for line in r.stdout.splitlines() if not line.startswith("#"))
    return [{**key_of(regime, rq, slope), **facts, **row} for row in checks.rows(data, COLUMNS)]


def path_of(ctx):
    return os.path.join(ctx.data, STUDY + ".csv")


def solve(ctx):
    """run: the eight checks again (the table made anew); check: that every check's rows are there."""
    design = Design(ctx.quick)
    jobs = [(regime, rq, slope) for regime, _, _, _ in REGIMES for rq, slope in design.surfaces]
    if ctx.checking:
        committed = Table.read(path_of(ctx), KEYS + REPORT + COLUMNS)
        missing = [j for j in jobs if not committed.where(**key_of(*j))]
        if missing:
            raise SystemExit(f"validation: the checks of {missing[0]} are missing from "
                             f"{ctx.relative(path_of(ctx))}; python3 -m validation run {STUDY} runs them")
    print(f"{STUDY}: {len(jobs)} checks, {ctx.jobs} at a time", flush=True)
    started = time.time()
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=ctx.jobs) as pool:
        for i, (job, found) in enumerate(zip(jobs, pool.map(lambda j: run_check(ctx, design, *j), jobs))):
            rows += found
            print(f"  [{i + 1}/{len(jobs)}, {time.time() - started:.0f} s] {job[0]} Rq {job[1]:g} Rdq {job[2]:g}",
                  flush=True)
    table = Table(KEYS + REPORT + COLUMNS, rows)
    table.sort(KEYS + ["nominal_pressure"])
    if ctx.checking:
        # The data are the CLI's checks' output (their laws on the check's own surfaces, not on the
        # spectrum as given), so the check runs them again: the same build gives them digit for digit.
        differ = [(row, column) for row, old in zip(table.rows, committed.rows) for column in COLUMNS + REPORT
                  if row[column] != old[column]]
        if len(table.rows) != len(committed.rows) or differ:
            where = (f"{differ[0][1]} of {', '.join(differ[0][0][k] for k in KEYS)} at "
                     f"{differ[0][0]['nominal_pressure']} Pa" if differ else "the rows")
            raise SystemExit(f"validation: the checks of this build differ from {ctx.relative(path_of(ctx))} "
                             f"({len(differ)} values; first: {where}); python3 -m validation run {STUDY} reruns them")
        return
    table.write(path_of(ctx))
    if not ctx.quick:
        tables.record(ctx.data, STUDY + ".csv", f"python3 -m validation run {STUDY}")


def outputs(ctx):
    design = Design(ctx.quick)
    table = Table.read(path_of(ctx), KEYS + REPORT + COLUMNS)
    checks = [(regime, rq, slope, sorted(table.where(**key_of(regime, rq, slope)),
                                         key=lambda r: number(r["nominal_pressure"])))
              for regime, _, _, _ in REGIMES for rq, slope in design.surfaces]
    laws = [law for law in LAWS if any(r[f"ratio_{law}"] for _, _, _, rows in checks for r in rows
                                       if rows[0]["regime"] == "elastic")]
    laws += [law for law in LAWS if law not in laws and any(r[f"ratio_{law}"] for *_, rows in checks for r in rows)]
    out = pages.Outputs(ctx, STUDY)
    body = []
    for regime, rq, slope, rows in checks:
        cells = []
        for law in laws:
            r = [number(row["ratio_" + law]) for row in rows if row["ratio_" + law]]
            cells.append(f"{min(r):.2f}-{max(r):.2f}" if r else "-")
        spread = ([number(row["h_per_k_exact_min"]) / number(row["h_per_k_exact"]) for row in rows] +
                  [number(row["h_per_k_exact_max"]) / number(row["h_per_k_exact"]) for row in rows])
        p = [number(row["nominal_pressure"]) / 1e6 for row in rows]
        body.append([regime, f"{rq * 1e6:g}", f"{slope:g}", rows[0]["hurst"], f"{min(p):g}-{max(p):g}",
                     f"{min(spread):.2f}-{max(spread):.2f}"] + cells)
    out.table("laws", ["regime", "Rq [um]", "Rdq", "Hurst", "P [MPa]", "seeds"] + laws, body)
    capped = pair(ctx, True)
    facts = {k: sorted({r[k] for *_, rows in checks for r in rows}) for k in REPORT}
    out.table("parameters", ["what", "value"], [
        ["solids", f"steel on steel: E = {SOLID[0] / 1e9:g} GPa, nu = {SOLID[1]:g}; capped: S_y = "
                   f"{SOLID[2] / 1e6:g} MPa"],
        ["E' (the core's)", f"{capped.Eprime / 1e9:.1f} GPa"],
        ["H = 2.84 S_y (the core's)", f"{capped.hardness / 1e9:.4g} GPa"],
        ["pressures asked", ", ".join(f"{p / 1e6:g} MPa" for p in PRESSURES)],
        ["the check's surfaces", f"{'/'.join(facts['seeds'])} seeds of {'/'.join(facts['grid'])}^2"],
        ["levels the grid holds, of the surface's", f"{'/'.join(facts['levels_kept'])} of "
                                                    f"{'/'.join(facts['levels_given'])}"],
        ["below p/(E' h') = 1e-3, periods of", f"{'/'.join(facts['light_load_periods'])} scan lengths"]])
    return out
