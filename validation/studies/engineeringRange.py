# SPDX-License-Identifier: GPL-3.0-or-later
"""Every conductance law against the exact conductance where joints live: x = p/(E' h') = 1e-4 to 1e-1, elastic and capped for four pairs.

The exact answer is the boundary-element model on the same surface the laws are given, elastic
or capped at H = 2.84 S_y of the pair's softer solid (loads up to 0.9 H). A synthesized surface
is solved as several realizations (seeds) of one spectrum; the exact value at a load is their
geometric mean, on the largest period solved there (the domain), each checked on a grid twice
as fine. The measured X3P map is solved mirrored about its edges; its quadrants, the map as a
patch and a finer grid are its checks. docs/validation/engineeringRange.md reads the tables.
"""
import math
import os

from .. import laws, materials, pages, solves, spectra
from ..context import ROOT
from ..tables import Table, number

DATA = ["engineeringRange.csv"]
KEYS = ["surface", "regime", "period", "grid", "seed", "variant"]
COMPLETE = 0.9  # no ratio where the exact A_r/A_n is above this (the conductance diverges)
BAND = 0.25  # within 25 %: what a default law is held to
DOMAIN_TOLERANCE = 0.10  # the two largest domains within 10 %: converged
X3P = os.path.join(ROOT, "data", "x3p-2.x3p")
DEKTAK = os.path.join("data", "dektak-1.csv")
# (name, Hurst, roll-off level, label) of the synthesized spectra
SELF_AFFINE = [("selfAffine08", 0.8, 4, "self-affine, Hurst 0.8, roll-off at L/4"),
               ("selfAffine03", 0.3, 4, "self-affine, Hurst 0.3, roll-off at L/4"),
               ("selfAffine05", 0.5, 1, "self-affine, Hurst 0.5, no roll-off (power law from L on)")]


def self_affine_spectra(ctx, study, levels, gradient=0.1):
    """{name: the spectrum file} of SELF_AFFINE's spectra on `levels` levels with the areal rms
    gradient h' = gradient (spectra.self_affine), in the study's scratch folder."""
    return {name: spectra.self_affine(ctx.scratch_path(study, name + ".spectrum"), hurst, rolloff, levels, gradient)
            for name, hurst, rolloff, _ in SELF_AFFINE}


class Design:
    """The solves' sizes: a grid of N (the spectra cut at N/8 levels: 8 cells the shortest
    wave), SEEDS realizations, the first CHECKED also on a grid twice as fine; periods of kL on
    grids of kN (DOMAINS: k, seeds, {regime: seeds} with None for the rest, the largest x);
    PERIODS: true periods beside a smaller reference at heavier loads."""

    def __init__(self, quick):
        self.N, self.seeds, self.checked = (128, [1, 2, 3], 1) if quick else (512, list(range(1, 9)), 2)
        self.fine = 2 * self.N
        self.cut = self.N // 8
        self.domains = [(2, [1, 2], 1e-2), (4, [1], 1e-3)] if quick else [
            (2, [1, 2, 3, 4], 1e-2), (4, [1, 2], 1e-3), (8, {"elastic": list(range(1, 9)), None: [1, 2]}, 1e-3)]
        self.loads = [1e-4, 1e-3, 1e-2, 1e-1] if quick else [10 ** (k / 3.0 - 4.0) for k in range(10)]
        heavy = [x for x in self.loads if 1e-3 * (1 + 1e-9) < x <= 1e-2 * (1 + 1e-9)]
        self.periods = [] if quick else [(8, [1, 2], ("elastic",), heavy, "heavy loads")]
        self.quick = quick


def seeds_of(seeds, regime):
    return seeds.get(regime, seeds[None]) if isinstance(seeds, dict) else seeds


class Surface:
    def __init__(self, ctx, name, label, description, synthesized):
        self.name = name
        self.label = label
        self.description = description  # the CLI's surface arguments of the laws
        self.synthesized = synthesized
        if synthesized:
            self.gradient = spectra.gradient(ctx, description[1])
            self.length = spectra.length(description[1])
        else:
            rc = ctx.rc()
            self.gradient = rc.areal_rms_gradient(rc.SurfaceSpec.areal(X3P, direction="both").read_spectrum())


def surfaces(ctx, design):
    """The four spectra (three synthesized shapes, the Dektak profile's) and the X3P map."""
    out = []
    for name, hurst, rolloff, label in SELF_AFFINE:
        path = spectra.self_affine(ctx.scratch_path("engineeringRange", name + ".spectrum"), hurst, rolloff, design.cut)
        out.append(Surface(ctx, name, f"{label}, h' = 0.1, L = 1 mm, {design.cut} levels", ["--spectrum", path], True))
    path = spectra.profile_spectrum(ctx, ctx.scratch_path("engineeringRange", "dektak.spectrum"), DEKTAK, design.cut)
    out.append(Surface(ctx, "dektak", f"the measured profile data/dektak-1.csv, its spectrum up to {design.cut}/L",
                       ["--spectrum", path], True))
    out.append(Surface(ctx, "x3p", "the measured areal map data/x3p-2.x3p (650^2, less its plane), solved mirrored "
                                   "about its edges as one period of a periodic surface of 1300^2; the multi-scale "
                                   "laws get its rows' and columns' averaged spectrum, the laws on sigma and m its "
                                   "heights' sigma and mean absolute slope",
                       ["--areal", X3P, "--direction", "both"], False))
    return out


def loads_of(ctx, surface, regime, design):
    """(x, p/E') of the regime's loads: up to 0.9 H with the cap."""
    pair = materials.regime_pair(ctx, regime)
    top = 0.9 * pair.hardness / (pair.Eprime * surface.gradient) if pair.hardness else float("inf")
    return [(x, x * surface.gradient) for x in design.loads if x <= top]


def solves_of(ctx, surface, regime, design):
    """Every exact solve of a surface in a regime."""
    pair = materials.regime_pair(ctx, regime)
    mat = pair.arguments + (["--hardness-from-yield"] if pair.hardness else [])
    common = ["--model", "boundaryElement"] + mat
    pes = [pe for _, pe in loads_of(ctx, surface, regime, design)]
    key = {"surface": surface.name, "regime": regime}
    out = []
    if surface.synthesized:
        for s in design.seeds:
            base = surface.description + ["--synthesize", f"{design.N},{s}"]
            out.append(solves.Solve({**key, "period": 1, "grid": design.N, "seed": s}, base + common, pes))
            if s <= design.checked:
                out.append(solves.Solve({**key, "period": 1, "grid": design.fine, "seed": s, "variant": "resampled"},
                                        base + ["--resample", str(design.fine)] + common, pes))
        for k, seeds, top in design.domains:
            spec = spectra.on_period(ctx, surface.description[1], k)
            for s in seeds_of(seeds, regime):
                out.append(solves.Solve({**key, "period": k, "grid": k * design.N, "seed": s},
                                        true_period(spec, k, surface.length, k * design.N, s) + mat,
                                        [pe for x, pe in loads_of(ctx, surface, regime, design) if x <= top * (1 + 1e-9)]))
        for k, seeds, regimes, xs, variant in design.periods:
            if regime not in regimes:
                continue
            spec = spectra.on_period(ctx, surface.description[1], k)
            for s in seeds:
                out.append(solves.Solve({**key, "period": k, "grid": k * design.N, "seed": s, "variant": variant},
                                        true_period(spec, k, surface.length, k * design.N, s) + mat,
                                        [x * surface.gradient for x in xs]))
    else:
        areal = ["--areal", X3P]
        out.append(solves.Solve({**key, "variant": "mirrored"}, areal + ["--mirror"] + common, pes))
        if not design.quick:
            out.append(solves.Solve({**key, "variant": "patch"}, areal + common, pes))
            for q, (path, dx, dy) in enumerate(quadrants(ctx)):
                out.append(solves.Solve({**key, "variant": f"quadrant{q + 1} mirrored"},
                                        ["--areal", path, "--dx", f"{dx:.10g}", "--dy", f"{dy:.10g}", "--mirror"]
                                        + common, pes))
            path, dx, dy = fine_map(ctx)
            out.append(solves.Solve({**key, "variant": "mirrored fine"},
                                    ["--areal", path, "--dx", f"{dx:.10g}", "--dy", f"{dy:.10g}", "--periodic"]
                                    + common, pes))
    return out


def true_period(spec, k, length, grid, seed):
    """The CLI's arguments of a period of k times `length` [m] of the spectrum file `spec` on
    grid^2: --length makes the period the true one (without it the CLI takes 1/(the file's
    lowest frequency))."""
    return ["--spectrum", spec, "--length", f"{k * length:.10g}", "--synthesize", f"{grid},{seed}",
            "--model", "boundaryElement"]


def quadrants(ctx):
    """The map's four quadrants (.npy of its heights as read, metres), for its domain check:
    [(path, dx, dy)]. Made in run only (check solves nothing)."""
    paths = [ctx.scratch_path("engineeringRange", f"x3p-quadrant{q + 1}.npy") for q in range(4)]
    if ctx.checking:
        return [(p, 0.0, 0.0) for p in paths]
    import numpy
    a = ctx.rc().read_areal(X3P)
    z = numpy.asarray(a.heights)
    ny, nx = z.shape
    cuts = [(slice(0, ny // 2), slice(0, nx // 2)), (slice(0, ny // 2), slice(nx // 2, nx)),
            (slice(ny // 2, ny), slice(0, nx // 2)), (slice(ny // 2, ny), slice(nx // 2, nx))]
    for path, (ys, xs) in zip(paths, cuts):
        numpy.save(path, z[ys, xs])
    return [(p, a.dx, a.dy) for p in paths]


def fine_map(ctx):
    """The map mirrored about its edges (as --mirror makes it: less its plane, 2n x 2n, one
    period) as the samples of its Fourier series on a grid twice as fine each way (.npy), for the
    map's grid check: (path, dx, dy). A mirrored surface has no Nyquist component, so padding its
    spectrum with zeros is exact: the fine grid's even samples are the map's."""
    path = ctx.scratch_path("engineeringRange", "x3p-mirrored-fine.npy")
    if ctx.checking:
        return path, 0.0, 0.0
    import numpy
    a = ctx.rc().read_areal(X3P)
    z = numpy.asarray(a.detrended().heights)
    mirrored = numpy.block([[z, z[:, ::-1]], [z[::-1, :], z[::-1, ::-1]]])
    n0, n1 = mirrored.shape
    spectrum = numpy.fft.rfft2(mirrored)
    padded = numpy.zeros((2 * n0, n1 + 1), complex)
    padded[:n0 // 2, :n1 // 2 + 1] = spectrum[:n0 // 2]
    padded[-(n0 // 2):, :n1 // 2 + 1] = spectrum[-(n0 // 2):]
    fine = numpy.fft.irfft2(padded, s=(2 * n0, 2 * n1)) * 4.0
    if numpy.abs(fine[::2, ::2] - mirrored).max() > 1e-9 * mirrored.std():
        raise SystemExit("engineeringRange: the mirrored map's Fourier series does not return its samples")
    numpy.save(path, fine)
    return path, a.dx / 2, a.dy / 2


def store(ctx):
    return solves.Store(ctx, "engineeringRange", KEYS)


def solve(ctx):
    design = Design(ctx.quick)
    jobs = [s for surface in surfaces(ctx, design) for regime, _, _ in materials.REGIMES
            for s in solves_of(ctx, surface, regime, design)]
    # The long solves first (the map's, the fine grids, the largest periods), so that the pool ends together.
    jobs.sort(key=lambda s: -(s.key.get("period", 1) ** 2 * (4 if s.key.get("variant") else 1)))
    store(ctx).solve(jobs)


def geometric_mean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


def standard_error(values):
    """The standard error of the geometric mean, as a factor; None for fewer than two values."""
    if len(values) < 2:
        return None
    h = geometric_mean(values)
    logs = [math.log(v / h) for v in values]
    return math.exp(math.sqrt(sum(v * v for v in logs) / (len(logs) - 1) / len(logs)))


def exact_at(ctx, data, surface, regime, design):
    """{x: the exact answer} at each load: h (the geometric mean of h_c/k_s over the reference's
    realizations), area (their mean A_r/A_n), se (the standard error of h, a factor), grid (h on
    the grid twice as fine over h, the same surfaces), n, reference (the largest domain solved
    there), domain (its h over the next smaller one's), edges (the map as a patch over mirrored)."""
    def curves(**key):
        return data.curve({"surface": surface.name, "regime": regime, **key})
    patch = None
    if surface.synthesized:
        domains = [("L", [curves(period=1, grid=design.N, seed=s) for s in design.seeds])]
        domains += [(f"{k}L", [curves(period=k, grid=k * design.N, seed=s) for s in seeds_of(seeds, regime)])
                    for k, seeds, _ in design.domains]
        fine = [curves(period=1, grid=design.fine, seed=s, variant="resampled") for s in design.seeds
                if s <= design.checked]
        coarse = domains[0][1]
    else:
        domains = [("map", [curves(variant="mirrored")])]
        fine = []
        coarse = domains[0][1]
        if not design.quick:
            domains.insert(0, ("quadrant", [curves(variant=f"quadrant{q} mirrored") for q in range(1, 5)]))
            fine = [curves(variant="mirrored fine")]
            patch = curves(variant="patch")

    def h_of(curve, pe):
        row = solves.at(curve, pe)
        return number(row["h_per_k_per_m"]) if row else None

    out = {}
    for x, pe in loads_of(ctx, surface, regime, design):
        solved = []
        for label, cs in domains:
            rows = [solves.at(c, pe) for c in cs]
            if all(rows):
                hs = [number(r["h_per_k_per_m"]) for r in rows]
                if all(h > 0 and math.isfinite(h) for h in hs):
                    solved.append((label, hs, [number(r["area_fraction"]) for r in rows]))
        if not solved or solved[-1][0] == "quadrant":
            continue
        label, hs, areas = solved[-1]
        h = geometric_mean(hs)
        grid = geometric_mean([h_of(f, pe) / h_of(c, pe) for f, c in zip(fine, coarse)]) if fine else None
        hp = h_of(patch, pe) if patch else None
        out[x] = {"h": h, "area": sum(areas) / len(areas), "se": standard_error(hs), "grid": grid, "n": len(hs),
                  "reference": label, "domain": h / geometric_mean(solved[-2][1]) if len(solved) > 1 else None,
                  "edges": hp / h if hp and math.isfinite(hp) else None}
    return out


class Exact:
    """The exact answers, surface by surface and regime by regime, where the exact A_r/A_n is at
    most COMPLETE (no law evaluated: what the default law's fit takes)."""

    def __init__(self, ctx):
        self.design = Design(ctx.quick)
        self.surfaces = surfaces(ctx, self.design)
        self.data = store(ctx)
        self.exact = {}  # (surface, regime) -> {x: exact}
        for s in self.surfaces:
            for regime, _, _ in materials.REGIMES:
                exact = exact_at(ctx, self.data, s, regime, self.design)
                self.exact[(s.name, regime)] = {x: e for x, e in exact.items() if e["area"] <= COMPLETE}

    def rows(self):
        """One row per surface, regime and load: the exact columns of the summary, as it prints them."""
        out = []
        for s in self.surfaces:
            for regime, _, _ in materials.REGIMES:
                for x, e in sorted(self.exact[(s.name, regime)].items()):
                    out.append({"surface": s.name, "regime": regime, "x": f"{x:.6g}", "gradient": f"{s.gradient:.6g}",
                                "exact_h_per_k": f"{e['h']:.6g}", "exact_area": f"{e['area']:.6g}",
                                "standard_error": pages.fmt(e["se"], 4), "grid": pages.fmt(e["grid"], 4),
                                "realizations": e["n"], "reference": e["reference"],
                                "domain": pages.fmt(e["domain"], 4), "edges": pages.fmt(e["edges"], 4)})
        return out


class Results(Exact):
    """The exact answers and every law's ratio to them."""

    def __init__(self, ctx):
        super().__init__(ctx)
        self.ratios = {}  # (surface, regime) -> {x: {law: law/exact}}
        defaults = []
        for s in self.surfaces:
            for regime, _, _ in materials.REGIMES:
                exact = self.exact[(s.name, regime)]
                loads = loads_of(ctx, s, regime, self.design)
                values = laws.on(ctx, s.description, materials.regime_pair(ctx, regime), [pe for _, pe in loads])
                if regime == materials.REGIMES[1][0]:
                    defaults += values
                self.ratios[(s.name, regime)] = {
                    x: {key: v[key] / exact[x]["h"] if v[key] > 0 else float("nan") for key, _ in laws.LAWS}
                    for (x, _), v in zip(loads, values) if x in exact}
        self.default = laws.default_law(defaults)

    def summary(self):
        """One row per surface, regime and load: the exact answer, its checks and every law's ratio."""
        rows = self.rows()
        for row in rows:
            x = next(x for x in self.ratios[(row["surface"], row["regime"])] if f"{x:.6g}" == row["x"])
            row.update({f"ratio_{k}": pages.fmt(self.ratios[(row["surface"], row["regime"])][x][k], 4)
                        for k, _ in laws.LAWS})
        return Table(list(rows[0].keys()), rows)


def outputs(ctx):
    from . import engineeringRangeTables
    return engineeringRangeTables.outputs(ctx, Results(ctx))
