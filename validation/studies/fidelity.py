# SPDX-License-Identifier: GPL-3.0-or-later
"""Every model against the exact answer: the area models and the laws at p/E' = 1e-5 to 0.5 on four surfaces, elastic and capped.

The exact answer is the boundary-element model on the same surface the models are given: elastic
for the elastic models, capped at H = 2.84 S_y (steel on steel, the core's H) for the
elasto-plastic ones. The self-affine spectra are solved on two grids (one realization each, the
finer the reference), the Dektak profile's spectrum as four realizations, the X3P map mirrored
about its edges. Each model or law is run by the CLI on that surface; its ratio to the exact
answer is taken where the exact A_r/A_n is at most 0.9. docs/validation/fidelity.md reads the
tables; docs/models.md includes its summary (generated/fidelity/models.md).

Other studies call ratio_curves(ctx) (law / exact per surface and curve, as the old
fidelity/*-ratio-h-*.dat files held them) and gradients(ctx) (each surface's h', as the page
prints it).
"""
import concurrent.futures
import math

from .. import materials, solves, spectra
from ..tables import number
from .engineeringRange import DEKTAK, X3P

DATA = ["fidelity.csv"]
STUDY = "fidelity"
KEYS = ["surface", "regime", "grid", "seed", "variant"]
TABLE_LOADS = [1e-4, 1e-3, 1e-2]
COMPLETE = 0.9  # ratios only where the exact A_r/A_n is at most this (the conductance diverges)
BAND = 0.25  # the band: model/exact within 0.75 to 1.25
SMOOTH = 0.05  # a surface with h' below this has its loads scaled by h'/0.1
# The regimes: elastic, and steel on steel capped at H (the old files' "plastic"); TAG names a
# curve as the old report's files did.
REGIMES = ["elastic", "steelSteel"]
TAG = {"elastic": "elastic", "steelSteel": "plastic"}
# A law run with the materials without a yield strength (its elastic branch alone).
ELASTIC = "<elastic materials>"
# (label, regime, the CLI's arguments after the surface and materials)
AREA_MODELS = [
    ("MS-Hertz", "elastic", ["--model", "hertz"]),
    ("MS-JGH", "elastic", ["--model", "jgh"]),
    ("MS-JGH consistent", "elastic", ["--model", "jghConsistent"]),
    ("GW", "elastic", ["--model", "greenwoodWilliamson"]),
    ("Persson", "elastic", ["--model", "persson"]),
    ("MS-JG", "steelSteel", ["--model", "jacksonGreen"]),
    ("MS-truncation", "steelSteel", ["--model", "truncation"]),
    ("GW-JG", "steelSteel", ["--model", "greenwoodWilliamsonJG"]),
]
CONDUCTANCE_LAWS = [
    ("jacksonBhavnaniFerguson on MS-Hertz", "elastic",
     ["--model", "hertz", "--conductance-law", "jacksonBhavnaniFerguson"]),
    ("multiscaleBarber on MS-Hertz", "elastic", ["--model", "hertz", "--conductance-law", "multiscaleBarber"]),
    ("persson", "elastic", ["--model", "hertz", "--conductance-law", "persson"]),
    ("mikic", "elastic", ["--model", "hertz", "--conductance-law", "mikic"]),
    ("jacksonBhavnaniFerguson on MS-JG", "steelSteel",
     ["--model", "jacksonGreen", "--conductance-law", "jacksonBhavnaniFerguson"]),
    ("multiscaleBarber on MS-JG", "steelSteel", ["--model", "jacksonGreen", "--conductance-law", "multiscaleBarber"]),
    ("multiscaleBarber on MS-truncation", "steelSteel",
     ["--model", "truncation", "--conductance-law", "multiscaleBarber"]),
    ("jacksonBhavnaniFerguson on MS-truncation", "steelSteel",
     ["--model", "truncation", "--conductance-law", "jacksonBhavnaniFerguson"]),
    ("persson (elastic theory)", "steelSteel", ["--model", "jacksonGreen", "--conductance-law", "persson"]),
    ("mikic (elastic correlation)", "steelSteel", ["--model", "jacksonGreen", "--conductance-law", "mikic"]),
    ("cooperMikicYovanovich (H_c = 2.84 S_y)", "steelSteel",
     ["--model", "jacksonGreen", "--conductance-law", "cooperMikicYovanovich", "--hardness-from-yield"]),
    ("fittedElastoPlastic", "elastic", ["--model", "hertz", "--conductance-law", "fittedElastoPlastic", ELASTIC]),
    ("fittedElastoPlastic (H = 2.84 S_y)", "steelSteel",
     ["--model", "jacksonGreen", "--conductance-law", "fittedElastoPlastic"]),
]


class Design:
    """Two grids n1 < n2 (the spectra cut at n1/8 levels), the Dektak spectrum's seeds, the base
    loads p/E' (three a decade from 1e-5, then 0.2 and 0.5) and whether the map is solved."""

    def __init__(self, quick):
        self.n1, self.n2 = (128, 256) if quick else (512, 1024)
        self.cut = self.n1 // 8
        self.seeds = [1, 2] if quick else [1, 2, 3, 4]
        self.loads = [1e-4, 1e-3, 1e-2, 1e-1] if quick else [10 ** (k / 3.0 - 5.0) for k in range(13)] + [0.2, 0.5]
        self.map = not quick


class Surface:
    """How the models see a surface (model: the CLI's surface arguments) and its reference
    solves (references: [(tag, key, the CLI's arguments)]); ratio_tags: the tags the ratios are
    taken against (None: all)."""

    def __init__(self, ctx, name, label, model, references, ratio_tags=None):
        self.name, self.label, self.model, self.references, self.ratio_tags = name, label, model, references, ratio_tags
        if model[0] == "--spectrum":
            self.gradient = spectra.gradient(ctx, model[1])
        else:
            rc = ctx.rc()
            self.gradient = rc.areal_rms_gradient(rc.SurfaceSpec.areal(X3P, direction="both").read_spectrum())


def surfaces(ctx, design):
    out = []
    for hurst in (0.8, 0.3):
        name = f"selfAffine{int(hurst * 10):02d}"
        path = spectra.self_affine(ctx.scratch_path(STUDY, name + ".spectrum"), hurst, 4, design.cut)
        model = ["--spectrum", path]
        refs = [(f"{n}x{n}", {"grid": n, "seed": 1}, model + ["--synthesize", f"{n},1"])
                for n in (design.n1, design.n2)]
        out.append(Surface(ctx, name, f"self-affine, Hurst {hurst}, roll-off at L/4, rms gradient 0.1 (L = 1 mm, "
                                      f"{design.cut} levels; reference on {design.n2}^2, and on {design.n1}^2 to show "
                                      f"its convergence)", model, refs, [f"{design.n2}x{design.n2}"]))
    path = spectra.profile_spectrum(ctx, ctx.scratch_path(STUDY, "dektak.spectrum"), DEKTAK, design.cut)
    model = ["--spectrum", path]
    refs = [(f"seed{s}", {"grid": design.n1, "seed": s}, model + ["--synthesize", f"{design.n1},{s}"])
            for s in design.seeds]
    out.append(Surface(ctx, "dektak", f"the measured profile {DEKTAK}, its spectrum up to {design.cut}/L (reference: "
                                      f"{len(design.seeds)} synthesized {design.n1}^2 surfaces, seeds "
                                      f"1-{len(design.seeds)})", model, refs))
    if design.map:
        out.append(Surface(ctx, "x3p", "the measured areal map data/x3p-2.x3p (650^2; reference on the map, mirrored "
                                       "about its edges (--mirror); models: its rows' and columns' averaged spectrum)",
                           ["--areal", X3P, "--direction", "both"],
                           [("mirrored", {"variant": "mirrored"}, ["--areal", X3P, "--mirror"])]))
    return out


def steel(ctx, capped):
    return materials.Pair(ctx, materials.STEEL, materials.STEEL, capped)


def loads_for(ctx, design, surface, regime):
    """The loads p/E' of a surface: the base list, scaled by h'/0.1 for a surface smoother than
    h' = SMOOTH (it reaches complete contact at far lower loads), and TABLE_LOADS; at most 0.5,
    and below 0.9 H/E' capped."""
    scale = surface.gradient / 0.1 if surface.gradient < SMOOTH else 1.0
    loads = sorted({float(f"{p * scale:.6g}") for p in design.loads} | set(TABLE_LOADS))
    pair = steel(ctx, True)
    top = 0.9 * pair.hardness / pair.Eprime if regime != "elastic" else 0.5
    return [p for p in loads if p <= top]


def solves_of(ctx, design, surface):
    out = []
    for regime in REGIMES:
        pair = steel(ctx, regime != "elastic")
        mat = pair.arguments + (["--hardness-from-yield"] if pair.hardness else [])
        for tag, key, args in surface.references:
            out.append(solves.Solve({"surface": surface.name, "regime": regime, **key},
                                    args + ["--model", "boundaryElement"] + mat,
                                    loads_for(ctx, design, surface, regime)))
    return out


def store(ctx):
    return solves.Store(ctx, STUDY, KEYS)


def solve(ctx):
    design = Design(ctx.quick)
    jobs = [s for surface in surfaces(ctx, design) for s in solves_of(ctx, design, surface)]
    jobs.sort(key=lambda s: -(s.key.get("grid") or 2048))  # the largest first
    store(ctx).solve(jobs)


def slug(label):
    return "".join(c if c.isalnum() else "-" for c in label).strip("-")


def model_curve(ctx, design, surface, regime, args):
    """The CLI's curve of a model or law on the surface: [row] in load order."""
    elastic = ELASTIC in args
    args = [a for a in args if a != ELASTIC]
    pes = loads_for(ctx, design, surface, regime)
    return solves.run_cli(ctx, surface.model + args + steel(ctx, not elastic).arguments +
                          ["--loads", ",".join(f"{p:.6g}" for p in pes)], f"{surface.name} {' '.join(args)}")


def geometric_mean(values):
    v = [math.log(x) if x > 0 else -math.inf for x in values]
    v = [x for x in v if math.isfinite(x)]
    return math.exp(sum(v) / len(v)) if v else float("nan")


def ratio_series(model_rows, reference, what, loads, tags=None):
    """{p/E': (geometric mean, min, max)} of model/exact over the reference's curves ({tag:
    curve}: all, or the tags given), where the exact A_r/A_n is at most COMPLETE."""
    model_column, reference_column = ("area_fraction", "area_fraction") if what == "area" else (
        "h_per_k", "h_per_k_per_m")
    out = {}
    for p in loads:
        row = next((r for r in model_rows if abs(number(r["nominal_pressure_per_Eprime"]) / p - 1) < 1e-5), None)
        if row is None:
            continue
        m = number(row[model_column])
        ratios = []
        for tag, curve in reference.items():
            exact = solves.at(curve, p)
            if (tags is None or tag in tags) and exact is not None and number(exact["area_fraction"]) <= COMPLETE:
                r = number(exact[reference_column])
                if r > 0 and math.isfinite(r) and math.isfinite(m):
                    ratios.append(m / r)
        if ratios:
            out[p] = (geometric_mean(ratios), min(ratios), max(ratios))
    return out


class Results:
    """The reference curves (reference[(surface, regime)] = {tag: curve}), each surface's loads
    (loads[(surface, regime)]) and every model's ratio to the reference:
    ratios[(what, label, regime)][surface] = {p/E': (geometric mean, min, max)}, what "area"
    (A_r/A_n) or "h" (h_c/k_s), in the order of AREA_MODELS and CONDUCTANCE_LAWS."""

    def __init__(self, ctx):
        self.design = Design(ctx.quick)
        self.surfaces = surfaces(ctx, self.design)
        data = store(ctx)
        self.loads = {(s.name, regime): loads_for(ctx, self.design, s, regime) for s in self.surfaces
                      for regime in REGIMES}
        self.reference = {(s.name, regime): {tag: data.curve({"surface": s.name, "regime": regime, **key})
                                             for tag, key, _ in s.references}
                          for s in self.surfaces for regime in REGIMES}
        runs = [(s, what, label, regime, args) for s in self.surfaces
                for what, entries in (("area", AREA_MODELS), ("h", CONDUCTANCE_LAWS))
                for label, regime, args in entries]
        with concurrent.futures.ThreadPoolExecutor(max_workers=ctx.jobs) as pool:
            curves = list(pool.map(lambda r: model_curve(ctx, self.design, r[0], r[3], r[4]), runs))
        self.ratios = {}
        for (s, what, label, regime, _), rows in zip(runs, curves):
            self.ratios.setdefault((what, label, regime), {})[s.name] = ratio_series(
                rows, self.reference[(s.name, regime)], what, self.loads[(s.name, regime)], s.ratio_tags)


def results(ctx):
    """The Results of this context (made once: the models' runs take a few seconds)."""
    if getattr(ctx, "_fidelity", None) is None:
        ctx._fidelity = Results(ctx)
    return ctx._fidelity


def ratio_curves(ctx, what="h"):
    """{(surface, tag): [(p/E', geometric mean, min, max)]} of every law's (what="h", h_c/k_s) or
    area model's (what="area", A_r/A_n) ratio to the exact answer, in load order, each number to
    six significant digits: the old docs/validation/fidelity/{surface}-ratio-{what}-{tag}.dat
    files' rows. tag: "elastic-" or "plastic-" (capped at H) and the curve's label with every
    character but letters and digits as "-" (e.g. "plastic-jacksonBhavnaniFerguson-on-MS-JG",
    "elastic-persson", "plastic-cooperMikicYovanovich--H-c---2-84-S-y")."""
    out = {}
    for (w, label, regime), per_surface in results(ctx).ratios.items():
        if w != what:
            continue
        for surface, series in per_surface.items():
            out[(surface, f"{TAG[regime]}-{slug(label)}")] = [
                tuple(float(f"{v:.6g}") for v in (p,) + series[p]) for p in sorted(series)]
    return out


def gradients(ctx, digits=3):
    """{surface: h'} of the surfaces the models see (the core's areal rms gradient), to `digits`
    significant digits as the page prints them (3: the numbers the old page gave; None: as the
    core computes them)."""
    design = Design(ctx.quick)
    return {s.name: s.gradient if digits is None else float(f"{s.gradient:.{digits}g}")
            for s in surfaces(ctx, design)}


def outputs(ctx):
    from .fidelityTables import outputs as write
    return write(ctx, results(ctx))
