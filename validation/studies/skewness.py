# SPDX-License-Identifier: GPL-3.0-or-later
"""How the heights' skewness moves the exact conductance at a fixed spectrum: five skewnesses imposed on three self-affine spectra, elastic and capped for three pairs; the default law's skewness factor is fitted here.

On each of the engineering range's three self-affine spectra (Hurst 0.8 and 0.3 rolled off at
L/4, Hurst 0.5 without a roll-off; h' = 0.1, L = 1 mm, 64 levels) four Gaussian surfaces of
512^2 are synthesized (seeds 1-4, the core's synthesize_isotropic) and given, by iterated rank
ordering (validation/surrogates.py; 200 iterations from the surface itself, so the features stay
where they are), a height distribution of skewness -0.6, -0.3, 0, +0.3, +0.6: exactly Gaussian
for 0, otherwise (exp(lambda z) - 1)/lambda of Gaussian z (a lognormal family), scaled to the
surface's sigma; the spectrum is kept to about 1e-5. The exact model solves each (one period,
periodic), elastic and capped at H = 2.84 S_y for annealed copper, steel and hardened steel, at
x = p/(E' h') = 1e-3 to 1e-1. The surfaces are made again from their seeds (the scratch folder),
never committed. fit(ctx) fits the default law's skewness factor on the elastic points (the
fittedElastoPlastic study writes its constants into the core); the tables take the law with the
core's built-in constants. docs/validation/skewness.md reads the tables.
"""
import math
import os
import statistics

import numpy

from .. import fitting, materials, solves, spectra, surrogates, tables
from ..tables import Table
from .engineeringRange import SELF_AFFINE, self_affine_spectra

# The exact solves, and what the laws take of each surface (so that check need not make the
# surfaces again: about five minutes of rank orderings).
DATA = ["skewness.csv", "skewnessSurfaces.csv"]
SURFACE_KEYS = ["surface", "imposed_skewness", "grid", "seed"]
KEYS = ["surface", "regime", "skewness", "grid", "seed"]
GRADIENT = 0.1  # h' of the spectra: x = p/(E' h') sets the loads
# The skewness factor f(s, x) = exp(s (a_0 + a_1 ln x_c) + b s^2) of the default law: its three
# fitted constants, and the ranges it holds its inputs to, this study's own (the loads solved, the
# largest |s| imposed), as the core names them (FittedElastoPlasticConstants.inc).
FITTED = ["skewnessSlope", "skewnessSlopeLog", "skewnessCurvature"]
RANGES = {"skewnessLightestLoad": 1e-3, "skewnessHeaviestLoad": 0.1, "skewnessLargest": 0.6}
WHAT = {"skewnessSlope": "a_0: the skewness factor's slope (fitted: skewness)",
        "skewnessSlopeLog": "a_1: the skewness factor's slope per ln x (fitted: skewness)",
        "skewnessCurvature": "b: the skewness factor's curvature (fitted: skewness)",
        "skewnessLightestLoad": "the lightest x the skewed surfaces were solved at: f holds x there below it",
        "skewnessHeaviestLoad": "the heaviest x the skewed surfaces were solved at: f holds x there above it",
        "skewnessLargest": "the largest |s| the skewed surfaces reached: f holds s there beyond it"}


class Design:
    """The surfaces and solves: grids of N (the spectra cut at N/8 levels), seeds, the imposed
    skewnesses, the rank-ordering iterations, the loads x and the regimes."""

    def __init__(self, quick):
        if quick:
            self.N, self.seeds, self.skews, self.iterations = 128, [1], [-0.6, 0.0, 0.6], 50
            self.loads, self.regimes = [1e-3, 1e-2, 1e-1], ["elastic", "steelSteel"]
        else:
            self.N, self.seeds, self.skews, self.iterations = 512, [1, 2, 3, 4], [-0.6, -0.3, 0.0, 0.3, 0.6], 200
            self.loads = [x for x in (10 ** (k / 3.0 - 4.0) for k in range(10)) if x >= 1e-3 * (1 - 1e-9)]
            self.regimes = ["elastic", "copperCopper", "steelSteel", "hardSteel"]
        self.spectra = [name for name, _, _, _ in SELF_AFFINE]
        self.skewed = [s for s in self.skews if s != 0.0]


def target(z, skew):
    """Sorted heights of unit variance and the given skewness: z (sorted Gaussian quantiles) for
    0, else (exp(lambda z) - 1)/lambda with lambda found by bisection."""
    def shaped(lam):
        y = z if lam == 0 else numpy.expm1(lam * z) / lam
        y = y - y.mean()
        return y / y.std()

    if skew == 0:
        return shaped(0.0)
    lo, hi = (0.0, 1.0) if skew > 0 else (-1.0, 0.0)
    for _ in range(60):  # the skewness grows with lambda
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if float((shaped(mid) ** 3).mean()) < skew else (lo, mid)
    return shaped(0.5 * (lo + hi))


class Study:
    """The skewed surfaces (made on first use), their exact solutions and the law's inputs."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.design = d = Design(ctx.quick)
        self.spectrum = self_affine_spectra(ctx, "skewness", d.N // 8, GRADIENT)
        self.dx = {name: spectra.length(path) / d.N for name, path in self.spectrum.items()}
        self.store = solves.Store(ctx, "skewness", KEYS)
        self._areal = {}
        self._z = None
        self.surfaces_path = os.path.join(ctx.data, DATA[1])
        self._stored = {(r["surface"], float(r["imposed_skewness"]), int(r["seed"])): r
                        for r in Table.read(self.surfaces_path, SURFACE_KEYS + surrogates.Areal.FIELDS).rows
                        if int(r["grid"]) == d.N}

    def loads(self, regime):
        """x of the regime: up to 0.9 H with the cap."""
        pair = materials.regime_pair(self.ctx, regime)
        return [x for x in self.design.loads
                if pair.hardness is None or x * pair.Eprime * GRADIENT <= 0.9 * pair.hardness]

    def surface(self, name, skew, seed):
        """The .npy file of a skewed surface (made when it is not in the scratch folder)."""
        d = self.design
        spec = self.spectrum[name]

        def make():
            rc = self.ctx.rc()
            a = rc.synthesize_isotropic(rc.SurfaceSpec.spectrum(spec).read_spectrum(), d.N, seed)
            if abs(a.dx / self.dx[name] - 1) > 1e-12:
                raise SystemExit(f"skewness: the synthesized spacing {a.dx} is not L/N = {self.dx[name]}")
            h0 = numpy.asarray(a.heights)
            h0 = h0 - h0.mean()
            if self._z is None:  # N^2 Gaussian quantiles
                self._z = numpy.array([statistics.NormalDist().inv_cdf((i + 0.5) / (d.N * d.N))
                                       for i in range(d.N * d.N)])
            ranked = numpy.sort(target(self._z, skew) * h0.std())
            return surrogates.rank_ordered_surrogate(h0, numpy.abs(numpy.fft.rfft2(h0)), ranked, d.iterations,
                                                     rank_first=True)
        definition = (f"skewness: synthesize_isotropic of {surrogates.file_digest(spec)} on {d.N}^2, seed {seed}, "
                      f"skewness {skew:+.1f} imposed by {d.iterations} rank orderings")
        return surrogates.heights(self.ctx, "skewness", f"{name}-skew{skew:+.1f}-seed{seed}", definition, make)

    def areal(self, name, skew, seed):
        """What the law takes of a surface (surrogates.Areal): made from the surface in run, read
        from the table of the surfaces in check."""
        k = (name, skew, seed)
        if k not in self._areal:
            if self.ctx.checking:
                if k not in self._stored:
                    raise SystemExit(f"skewness: {DATA[1]} has no surface {name}, skewness {skew}, seed {seed}; "
                                     "python3 -m validation run skewness makes it")
                self._areal[k] = surrogates.Areal.stored(self._stored[k], self.dx[name])
            else:
                self._areal[k] = surrogates.Areal(self.ctx, self.surface(*k), self.dx[name])
        return self._areal[k]

    def save_surfaces(self):
        """The table of what the laws take of every surface (run)."""
        d = self.design
        rows = [{"surface": name, "imposed_skewness": f"{skew:+.1f}", "grid": d.N, "seed": seed,
                 **self.areal(name, skew, seed).values()}
                for name in d.spectra for skew in d.skews for seed in d.seeds]
        Table(SURFACE_KEYS + surrogates.Areal.FIELDS, rows).write(self.surfaces_path)
        if not self.ctx.quick:
            tables.record(self.ctx.data, DATA[1], "python3 -m validation run skewness")

    def key(self, name, regime, skew, seed):
        return {"surface": name, "regime": regime, "skewness": skew, "grid": self.design.N, "seed": seed}

    def solves(self):
        out = []
        d = self.design
        for name in d.spectra:
            for skew in d.skews:
                for seed in d.seeds:
                    # (check only asks whether a solve is there: no surface is made for it)
                    path = "-" if self.ctx.checking else self.surface(name, skew, seed)
                    for regime in d.regimes:
                        pair = materials.regime_pair(self.ctx, regime)
                        out.append(solves.Solve(self.key(name, regime, skew, seed),
                                                ["--areal", path, "--dx", f"{self.dx[name]:.15g}", "--periodic",
                                                 "--model", "boundaryElement"] + pair.arguments
                                                + (["--hardness-from-yield"] if pair.hardness else []),
                                                [x * GRADIENT for x in self.loads(regime)]))
        return out

    def exact(self, name, regime, skew, seed, x):
        """The solved row at the load x."""
        row = solves.at(self.store.curve(self.key(name, regime, skew, seed)), x * GRADIENT)
        if row is None:
            raise SystemExit(f"skewness: no solve of {name}, {regime}, skewness {skew}, seed {seed} at x = {x:g}")
        return row

    def point(self, name, regime, skew, seed, x, **more):
        """A row of fitting.Points: the exact answer at x and the surface's inputs to the law."""
        pair = materials.regime_pair(self.ctx, regime)
        row = self.exact(name, regime, skew, seed, x)
        return self.areal(name, skew, seed).point(float(row["load"]) * pair.Eprime, pair,
                                                  exact=float(row["h_per_k_per_m"]), area=float(row["area_fraction"]),
                                                  surface=name, regime=regime, skew=skew, seed=seed, x=x, **more)

    def points(self, regime):
        d = self.design
        return fitting.Points([self.point(name, regime, skew, seed, x) for name in d.spectra for skew in d.skews
                               for seed in d.seeds for x in self.loads(regime)])


def solve(ctx):
    s = Study(ctx)
    s.store.solve(s.solves())
    if not ctx.checking:
        s.save_surfaces()


def factor_terms(skewness, m, pe):
    """The factor's terms in ln f (s, s ln x_c, s^2) of a surface of sample skewness s and mean
    absolute slope m at p/E' = pe: x = P/(sqrt(pi) E' m), the law's own, held within the loads."""
    x = min(max(pe / (math.sqrt(math.pi) * m), RANGES["skewnessLightestLoad"]), RANGES["skewnessHeaviestLoad"])
    return [skewness, skewness * math.log(x), skewness * skewness]


def fit_factor(s):
    """The factor's constants by least squares in ln f on every elastic point: ln of the exact h
    over that of the same seed's Gaussian surface = ln f(s) - ln f(s_0), s and s_0 the two
    surfaces' sample skewness (what the exact model sees: imposed here, none of it chance), each
    with its own m. Returns the constants, the residuals (ln) by load and the points."""
    d = s.design
    rows, y, where = [], [], []
    for name in d.spectra:
        for seed in d.seeds:
            b = s.areal(name, 0.0, seed)
            for skew in d.skewed:
                k = s.areal(name, skew, seed)
                for x in s.loads("elastic"):
                    e, e0 = s.exact(name, "elastic", skew, seed, x), s.exact(name, "elastic", 0.0, seed, x)
                    pe = float(e["load"])
                    rows.append([u - v for u, v in zip(factor_terms(k.skewness, k.m, pe),
                                                       factor_terms(b.skewness, b.m, pe))])
                    y.append(math.log(float(e["h_per_k_per_m"]) / float(e0["h_per_k_per_m"])))
                    where.append(x)
    X, Y = numpy.array(rows), numpy.array(y)
    c = numpy.linalg.lstsq(X, Y, rcond=None)[0]
    by = {}
    for x, r in zip(where, Y - X @ c):
        by.setdefault(x, []).append(float(r))
    return dict(zip(FITTED, (float(v) for v in c))), by, len(Y)


def fit(ctx):
    """{name: (value, what it is)} of the default law's skewness factor: the three constants this
    study fits (unrounded) and the ranges it holds its inputs to (the study's parameters)."""
    values, _, _ = fit_factor(Study(ctx))
    return {n: (v, WHAT[n]) for n, v in {**values, **RANGES}.items()}


def outputs(ctx):
    from . import skewnessTables
    return skewnessTables.outputs(ctx, Study(ctx))
