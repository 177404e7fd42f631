# SPDX-License-Identifier: GPL-3.0-or-later
"""The default law beyond the engineering range: the exact elastic conductance at x = p/(E' h') = 0.1 to 0.9 on twelve spectra, and the heavy-load growth rate beta_2(W) fitted there.

The law's constants are fitted up to x = 0.1, its elastic branch growing there as exp(beta x);
smooth or hard surfaces stay elastic well beyond. The exact model, elastic, steel on steel, at
x = 0.1, 0.15, 0.2, 0.3, 0.45, 0.64 and 0.9 on
  - the engineering range's four training spectra (Hurst 0.8 and 0.3 rolled off at L/4, Hurst
    0.5 without a roll-off, the Dektak profile's spectrum; 64 levels): four realizations of one
    period L on 512^2 (seeds 1-4) and seed 1's Fourier series on 1024^2 (--resample), the grid's
    check;
  - the eight spectra of the spectralShapes study (h' = 0.1, 64 levels), held out: two
    realizations each on 512^2 (seeds 101-102, that study's own).
One period suffices: the engineering range measures the domain within 10 % from x = 0.01 on.
fit(ctx) fits beta_2(W) = B_0 + B_W (W - W_0), the growth's rate beyond x_g, to the training
surfaces alone: a minimax of |law/exact - 1| over their points beyond x_g where the exact A_r/A_n
<= 0.9, every other constant the core's (validation/fitting.py: the core's law with chosen
constants); the fittedElastoPlastic study writes them into the core. docs/validation/heavyLoads.md
reads the tables.
"""
from .. import fitting, materials, solves, spectra
from .engineeringRange import COMPLETE, DEKTAK, SELF_AFFINE, geometric_mean, standard_error
from .spectralShapes import GRADIENT as SHAPES_GRADIENT, LENGTH as SHAPES_LENGTH, SHAPES

DATA = ["heavyLoads.csv"]
KEYS = ["surface", "regime", "grid", "seed", "variant"]
FITTED = ["heavyLoadGrowth", "heavyLoadGrowthSlope"]
START = {"heavyLoadGrowth": 4.4, "heavyLoadGrowthSlope": 0.0}  # one rate about beta's, no slope
# The rate's own parameters (FittedElastoPlasticConstants.inc): where it takes over, W_0 about the
# middle of the spectra solved here, and their W (0.465-0.788) that beta_2 holds W within.
FIXED = {"heavyLoadStart": 0.1, "heavyLoadBandwidthPivot": 0.55, "heavyLoadBandwidthLeast": 0.45,
         "heavyLoadBandwidthMost": 0.8}
WHAT = {"heavyLoadStart": "x_g: the engineering range's end, where beta_2(W) takes over from beta",
        "heavyLoadGrowth": "B_0: beta_2 at W_0 (fitted: heavyLoads)",
        "heavyLoadGrowthSlope": "B_W: beta_2's slope in W (fitted: heavyLoads)",
        "heavyLoadBandwidthPivot": "W_0: about the middle of the heavy-load spectra's W",
        "heavyLoadBandwidthLeast": "the heavy-load spectra's least W: beta_2 holds W there below it",
        "heavyLoadBandwidthMost": "the heavy-load spectra's largest W: beta_2 holds W there above it"}


class Design:
    def __init__(self, quick):
        if quick:
            self.N, self.seeds, self.holdout_seeds = 128, [1], [101]
            self.loads, self.shapes = [0.1, 0.3, 0.64], SHAPES[:2]
        else:
            self.N, self.seeds, self.holdout_seeds = 512, [1, 2, 3, 4], [101, 102]
            self.loads, self.shapes = [0.1, 0.15, 0.2, 0.3, 0.45, 0.64, 0.9], SHAPES
        self.fine = 2 * self.N
        self.cut = self.N // 8


class Surface:
    """A spectrum solved here: its file, role (training or holdout), seeds and h' (the core's)."""

    def __init__(self, ctx, name, role, path, seeds):
        self.name, self.role, self.path, self.seeds = name, role, path, seeds
        self.gradient = spectra.gradient(ctx, path)


def surfaces(ctx, design):
    """The engineering range's four training spectra, then spectralShapes' eight (the scratch folder's)."""
    out = [Surface(ctx, name, "training", spectra.self_affine(ctx.scratch_path("heavyLoads", name + ".spectrum"),
                                                               hurst, rolloff, design.cut), design.seeds)
           for name, hurst, rolloff, _ in SELF_AFFINE]
    out.append(Surface(ctx, "dektak", "training", spectra.profile_spectrum(
        ctx, ctx.scratch_path("heavyLoads", "dektak.spectrum"), DEKTAK, design.cut), design.seeds))
    out += [Surface(ctx, name, "holdout", spectra.self_affine(ctx.scratch_path("heavyLoads", name + ".spectrum"),
                                                              hurst, rolloff, design.cut, SHAPES_GRADIENT,
                                                              SHAPES_LENGTH), design.holdout_seeds)
            for name, hurst, rolloff in design.shapes]
    return out


def key(s, grid, seed, design):
    return {"surface": s.name, "regime": "elastic", "grid": grid, "seed": seed,
            "variant": "resampled" if grid != design.N else ""}


def solve(ctx):
    design = Design(ctx.quick)
    pair = materials.regime_pair(ctx, "elastic")
    jobs = []
    for s in surfaces(ctx, design):
        base = ["--spectrum", s.path, "--model", "boundaryElement"] + pair.arguments
        loads = [x * s.gradient for x in design.loads]
        for seed in s.seeds:
            jobs.append(solves.Solve(key(s, design.N, seed, design), base + ["--synthesize", f"{design.N},{seed}"],
                                     loads))
        if s.role == "training":
            jobs.append(solves.Solve(key(s, design.fine, s.seeds[0], design), base + [
                "--synthesize", f"{design.N},{s.seeds[0]}", "--resample", str(design.fine)], loads))
    jobs.sort(key=lambda j: -j.key["grid"])
    solves.Store(ctx, "heavyLoads", KEYS).solve(jobs)


def points(ctx):
    """One row a surface and load where the exact A_r/A_n <= COMPLETE: the law's inputs (the
    surface's sigma, m, W and s1 as the core takes them from its spectrum), the exact answer (the
    geometric mean over the realizations), its standard error and the grid's check."""
    rc = ctx.rc()
    design = Design(ctx.quick)
    data = solves.Store(ctx, "heavyLoads", KEYS)
    pair = materials.regime_pair(ctx, "elastic")
    out = []
    for s in surfaces(ctx, design):
        spec = rc.SurfaceSpec.spectrum(s.path)
        r, levels = spec.roughness(), spec.read_spectrum()
        w, s1 = rc.spectral_bandwidth_ratio(levels), rc.first_level_share(levels)

        def at(grid, seed, x):
            row = solves.at(data.curve(key(s, grid, seed, design)), x * s.gradient)
            if row is None:
                raise SystemExit(f"heavyLoads: no solve of {s.name}, seed {seed}, {grid}^2 at x = {x:g}")
            return float(row["h_per_k_per_m"]), float(row["area_fraction"])
        for x in design.loads:
            found = [at(design.N, seed, x) for seed in s.seeds]
            h = [v for v, _ in found]
            area = geometric_mean([a for _, a in found])
            if area > COMPLETE:
                continue
            out.append({"surface": s.name, "role": s.role, "regime": "elastic", "x": x, "sigma": r.sigma,
                        "m": r.mean_absolute_slope, "w": w, "s1": s1, "E": pair.Eprime, "H": None,
                        "P": x * pair.Eprime * s.gradient, "s": 0.0, "n": len(h), "area": area,
                        "exact": geometric_mean(h), "standard_error": standard_error(h),
                        "grid": at(design.fine, s.seeds[0], x)[0] / h[0] if s.role == "training" else None})
    return fitting.Points(out)


def past(row):
    """Beyond x_g: the loads above it (at x = x_g the law's x comes out a hair either side)."""
    return row["x"] > FIXED["heavyLoadStart"] * (1 + 1e-9)


def beyond(pts, role="training"):
    return pts.where(lambda r: r["role"] == role and past(r))


def start(rc, base=None):
    """The constants the rate is fitted from: base's (default: the core's built-in ones) with the
    rate's own parameters and START."""
    return fitting.constants(rc, {**FIXED, **START}, base)


def rate_of(form, y, c):
    """{name: value} of a form of the rate beyond x_g with constants y, as a function of the
    point: "W" (the law's: B_0 + B_W (W - W_0)), "one" (one rate B_0) or "s1" (B_0 + B_s1
    (s1 - s1_0), s1 held within the light-load factor's range, as that factor holds it: a variant
    the core does not have, its rate given to the core's law surface by surface)."""
    if form == "W":
        return lambda row: {"heavyLoadGrowth": y[0], "heavyLoadGrowthSlope": y[1]}
    if form == "one":
        return lambda row: {"heavyLoadGrowth": y[0], "heavyLoadGrowthSlope": 0.0}
    return lambda row: {"heavyLoadGrowth": y[0] + y[1] * (min(max(row["s1"], c.lightLoadShareLeast),
                                                              c.lightLoadShareMost) - c.lightLoadSharePivot),
                        "heavyLoadGrowthSlope": 0.0}


def ratios_of(rc, form, y, c, pts):
    """law/exact at each point with a form's rate (the core's law; one call per surface)."""
    import numpy
    rate = rate_of(form, y, c)
    out = numpy.empty(len(pts))
    for name in dict.fromkeys(r["surface"] for r in pts.rows):
        index = [i for i, r in enumerate(pts.rows) if r["surface"] == name]
        group = fitting.Points([pts.rows[i] for i in index])
        out[index] = fitting.ratios(rc, fitting.constants(rc, rate(group.rows[0]), c), group)
    return out


def fit_rate(rc, form, train, c):
    """A form's constants: the minimax of |law/exact - 1| over `train` through q-norms of
    increasing q, three Nelder-Mead runs each (as fitting.minimax), from one rate 4.4."""
    import numpy
    y = numpy.array([START["heavyLoadGrowth"]] + ([] if form == "one" else [START["heavyLoadGrowthSlope"]]))
    for q in (4, 8, 16, 32, 64):
        def objective(v):
            miss = numpy.abs(ratios_of(rc, form, v, c, train) - 1.0)
            return float(numpy.mean(numpy.where(numpy.isfinite(miss), miss, 10.0) ** q) ** (1.0 / q))
        for _ in range(3):
            y, _ = fitting.nelder_mead(objective, y)
    return [float(v) for v in y]


def fit(ctx, base=None):
    """{name: (value, what it is)}: B_0 and B_W fitted on the training points beyond x_g (unrounded),
    every other constant base's (default: the core's built-in ones), and the rate's own parameters."""
    rc = ctx.rc()
    y = fit_rate(rc, "W", beyond(points(ctx)), start(rc, base))
    return {n: (v, WHAT[n]) for n, v in {**dict(zip(FITTED, y)), **FIXED}.items()}


def outputs(ctx):
    from . import heavyLoadsTables
    return heavyLoadsTables.outputs(ctx, Design(ctx.quick), points(ctx))
