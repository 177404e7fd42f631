# SPDX-License-Identifier: GPL-3.0-or-later
"""How far the X3P map's spectrum and heights decide its conductance: the exact answer on surrogates of the map (its Fourier amplitudes, random phases; and with its heights), against every law.

From the map data/x3p-2.x3p mirrored about its edges (the engineering range's reference surface,
1300^2 samples of 0.128 x 0.315 um) it makes
  - gaussian1..4: the map's two-dimensional Fourier amplitudes with random phases (numpy's
    RandomState seeds 1-4): the same power spectrum, anisotropy included, so the same sigma and
    rms slopes; heights and slopes close to Gaussian, whatever the map's are;
  - heights1..4: each gaussianK with the map's own height distribution imposed by iterated rank
    ordering (validation/surrogates.py; 200 iterations from gaussianK): the map's spectrum and
    skewed heights, gaussianK's arrangement, so each pair differs in its heights' distribution alone;
and solves the exact model on each and on the map (periodic, the engineering range's loads and
material pairs), elastic and capped; the laws (the CLI's, every one) take each surface's own sigma,
m, line scans' spectrum and skewness. The surfaces are made again from the map and the seeds (the
scratch folder), never committed. docs/validation/mapSurrogates.md reads the tables.
"""
import concurrent.futures
import csv
import io
import math

from .. import laws, materials, solves, surrogates
from . import engineeringRange
from .engineeringRange import COMPLETE, X3P

DATA = ["mapSurrogates.csv"]
KEYS = ["surface", "regime", "seed"]
DEFAULT = "fittedElastoPlastic"
KINDS = [("map", "the map mirrored about its edges (the report's reference)"),
         ("gaussian", "its Fourier amplitudes, random phases"),
         ("heights", "gaussian{seed} with the map's height distribution")]
SUMMARY = ("# law / exact on the X3P map and its surrogates (written by validation/studies/mapSurrogates.py):\n"
           "# surface, regime, x = p/(E' h') with the report's h' of the map, the exact h_c/k_s [1/m] and\n"
           "# A_r/A_n, and each law's ratio to the exact answer (empty: the law has no value there).\n")


class Design:
    """The map (its first `cut` x `cut` samples in quick: a grid of 2 cut after mirroring), the
    seeds, the rank-ordering iterations, the regimes and (quick) the loads x."""

    def __init__(self, quick):
        if quick:
            self.cut, self.seeds, self.iterations = 64, [1], 20
            self.regimes, self.loads = ["elastic", "steelSteel"], [1e-3, 1e-2, 1e-1]
        else:
            self.cut, self.seeds, self.iterations = None, [1, 2, 3, 4], 200
            self.regimes, self.loads = [r for r, _, _ in materials.REGIMES], None
        self.surfaces = [("map", None)] + [(kind, s) for kind in ("gaussian", "heights") for s in self.seeds]


def name_of(kind, seed):
    return kind if seed is None else f"{kind}{seed}"


class Study:
    def __init__(self, ctx):
        self.ctx = ctx
        self.design = Design(ctx.quick)
        # The engineering range's map: its h' (the x axis) and its loads.
        self.map = engineeringRange.Surface(ctx, "x3p", "the measured areal map",
                                            ["--areal", X3P, "--direction", "both"], False)
        self.store = solves.Store(ctx, "mapSurrogates", KEYS)
        self._map = None
        self._areal = {}

    def mirrored(self):
        """(heights of the map less its plane, mirrored about its edges; dx, dy)."""
        if self._map is None:
            import numpy
            a = self.ctx.rc().read_areal(X3P).detrended()
            z = numpy.asarray(a.heights)
            if self.design.cut:
                z = z[:self.design.cut, :self.design.cut]
            self._map = numpy.block([[z, z[:, ::-1]], [z[::-1, :], z[::-1, ::-1]]]), a.dx, a.dy
        return self._map

    def surface(self, kind, seed):
        """(the .npy file of a surface, made when it is not in the scratch folder; dx, dy)."""
        import numpy
        d = self.design
        _, dx, dy = self.mirrored()

        def make():
            mirrored, _, _ = self.mirrored()
            if kind == "map":
                return mirrored
            amplitude = numpy.abs(numpy.fft.rfft2(mirrored))
            amplitude[0, 0] = 0.0
            white = numpy.fft.rfft2(numpy.random.RandomState(seed).standard_normal(mirrored.shape))
            phases = numpy.fft.irfft2(amplitude * white / numpy.abs(white), s=mirrored.shape)
            if kind == "gaussian":
                return phases
            return surrogates.rank_ordered_surrogate(phases, amplitude, numpy.sort(mirrored.ravel()), d.iterations)
        definition = (f"mapSurrogates: {kind} of {surrogates.file_digest(X3P)} less its plane"
                      + (f", its first {d.cut}^2 samples" if d.cut else "") + ", mirrored"
                      + (f", RandomState({seed}) phases" if seed else "")
                      + (f", its heights by {d.iterations} rank orderings" if kind == "heights" else ""))
        return surrogates.heights(self.ctx, "mapSurrogates", name_of(kind, seed), definition, make), dx, dy

    def areal_arguments(self, kind, seed):
        path, dx, dy = self.surface(kind, seed)
        return ["--areal", path, "--dx", f"{dx:.15g}", "--dy", f"{dy:.15g}"]

    def loads(self, regime):
        """p/E' of a regime: the engineering range's on the map (quick: the design's x)."""
        if self.design.loads is not None:
            pair = materials.regime_pair(self.ctx, regime)
            return [x * self.map.gradient for x in self.design.loads
                    if pair.hardness is None or x * pair.Eprime * self.map.gradient <= 0.9 * pair.hardness]
        return [pe for _, pe in engineeringRange.loads_of(self.ctx, self.map, regime, engineeringRange.Design(False))]

    def gradient(self):
        """The map's h' as the engineering range's summary gives it (6 digits): x = p/(E' h') on the
        same axis as that study's rows of the map."""
        return float(f"{self.map.gradient:.6g}")

    def key(self, kind, regime, seed):
        return {"surface": kind, "regime": regime, "seed": seed}

    def solves(self):
        out = []
        for kind, seed in self.design.surfaces:
            for regime in self.design.regimes:
                pair = materials.regime_pair(self.ctx, regime)
                out.append(solves.Solve(self.key(kind, regime, seed),
                                        self.areal_arguments(kind, seed) + ["--periodic", "--model", "boundaryElement"]
                                        + pair.arguments + (["--hardness-from-yield"] if pair.hardness else []),
                                        self.loads(regime)))
        return out

    def ratios(self):
        """[(surface, regime, x, exact h_c/k_s, A_r/A_n, {law: law/exact})] where A_r/A_n <= COMPLETE
        (the laws of each surface and regime one CLI run, ctx.jobs at a time)."""
        def one(job):
            kind, seed, regime = job
            pair = materials.regime_pair(self.ctx, regime)
            exact = [solves.at(self.store.curve(self.key(kind, regime, seed)), pe) for pe in self.loads(regime)]
            if not all(exact):
                raise SystemExit(f"mapSurrogates: {name_of(kind, seed)} {regime} is not at the loads")
            values = laws.on(self.ctx, self.areal_arguments(kind, seed) + ["--direction", "both"], pair,
                             [float(e["load"]) for e in exact])
            out = []
            for e, v in zip(exact, values):
                h, area = float(e["h_per_k_per_m"]), float(e["area_fraction"])
                if area <= COMPLETE:
                    out.append((name_of(kind, seed), regime, float(e["load"]) / self.gradient(), h, area,
                                {k: v[k] / h for k, _ in laws.LAWS if math.isfinite(v[k])}))
            return out
        self.mirrored()
        jobs = [(kind, seed, regime) for kind, seed in self.design.surfaces for regime in self.design.regimes]
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.ctx.jobs) as pool:
            return [row for rows in pool.map(one, jobs) for row in rows]

    def statistics(self):
        """{surface: (sigma, m, W, skewness, kurtosis)} (sigma, m and W the core's, of both directions)."""
        import numpy
        rc = self.ctx.rc()
        out = {}
        for kind, seed in self.design.surfaces:
            path, dx, dy = self.surface(kind, seed)
            h = numpy.load(path)
            s = rc.ArealSurface(h, dx, dy)
            r = rc.areal_roughness(s, "both")
            d = h - h.mean()
            sd = d.std()
            out[name_of(kind, seed)] = (r.sigma, r.mean_absolute_slope,
                                        rc.spectral_bandwidth_ratio(s.line_scan_spectrum("both")),
                                        (d ** 3).mean() / sd ** 3, (d ** 4).mean() / sd ** 4)
        return out


def solve(ctx):
    s = Study(ctx)
    s.store.solve(s.solves())


def summary_text(rows):
    text = io.StringIO()
    keys = [k for k, _ in laws.LAWS]
    w = csv.writer(text, lineterminator="\n")
    w.writerow(["surface", "regime", "x", "exact_h_per_k", "exact_area"] + [f"ratio_{k}" for k in keys])
    for name, regime, x, h, area, r in rows:
        w.writerow([name, regime, f"{x:.6g}", f"{h:.6g}", f"{area:.6g}"]
                   + [f"{r[k]:.4f}" if k in r else "" for k in keys])
    return SUMMARY + text.getvalue()


def surfaces_text(stats):
    """The surfaces' statistics (as the script before this package wrote them, with newline line ends)."""
    text = io.StringIO()
    w = csv.writer(text, lineterminator="\n")
    w.writerow(["surface", "sigma", "m", "bandwidth", "skewness", "kurtosis"])
    for name, (sigma, m, bandwidth, skewness, kurtosis) in stats.items():
        w.writerow([name, f"{sigma:.6g}", f"{m:.6g}", f"{bandwidth:.6g}", f"{skewness:.4f}", f"{kurtosis:.4f}"])
    return text.getvalue()


def outputs(ctx):
    from . import mapSurrogatesTables
    s = Study(ctx)
    return mapSurrogatesTables.outputs(ctx, s, s.ratios(), s.statistics())
