# SPDX-License-Identifier: GPL-3.0-or-later
"""The exact conductance of eight more self-affine spectra (other Hurst exponents and roll-offs), elastic and capped for three pairs, x = 1e-4 to 1e-1.

The engineering range fits the default law on three synthesized spectra; its light-load slope
A_s1 is fitted on these eight too (their loads up to x = 0.01), no other constant
(docs/validation/fittedElastoPlastic.md, "The spectrum's shape"). The same h' = 0.1, L = 1 mm
and 64 levels as the engineering range's, with other roll-offs and Hurst exponents; elastic and
capped at H = 2.84 S_y for annealed copper, steel and hardened steel; x = p/(E' h') = 1e-4 to
1e-1 (up to 0.9 H). On realizations of their own (seeds 101-108: a seed fixes the phases whatever
the spectrum, so the engineering range's seeds would share its references' sampling error).

The reference at a load is the largest period solved there: a true period of 8L (--length 8L on
4096^2, spacing L/512, two realizations) at x <= 1e-3, 2L on 1024^2 up to 1e-2, L on 512^2 above
(four each). The cells solved without --length below 1e-3 are kept beside the true periods: the
period meant as 4L was solved as 2L on 2048^2 (its spectrum file begins at 1/(2L), and without
--length a spectrum's period is 1/(its lowest frequency)); it was the reference until 2026-11-29,
and periods.csv sets it beside the true periods of 4L and 8L. docs/validation/spectralShapes.md.

The study's machinery is a class, Shapes, that blindSpectra runs on four other spectra.
"""
import math

from .. import materials, pages, solves, spectra
from ..tables import Table, number
from .engineeringRange import geometric_mean, standard_error, true_period

DATA = ["spectralShapes.csv"]
KEYS = ["surface", "regime", "period", "grid", "seed", "variant"]
# (name, Hurst exponent, roll-off level: C1 flat below it; 1 is none). The last two, the steepest
# without a roll-off, were solved after the light-load factor's variable was chosen.
SHAPES = [("hurst03rolloff1", 0.3, 1), ("hurst08rolloff1", 0.8, 1), ("hurst05rolloff2", 0.5, 2),
          ("hurst05rolloff4", 0.5, 4), ("hurst05rolloff8", 0.5, 8), ("hurst08rolloff16", 0.8, 16),
          ("hurst065rolloff1", 0.65, 1), ("hurst10rolloff1", 1.0, 1)]
REGIMES = ["elastic", "copperCopper", "steelSteel", "hardSteel"]
GRADIENT, LENGTH = 0.1, 1e-3
MEANT = "meant as 4L"  # the variant of the cell solved as 2L from the 4L spectrum file, without --length
COMMENT = {
    "summary": "# The exact (boundary-element) conductance of {what}, h' = 0.1, L = 1 mm,\n"
               "# 64 levels (written by {writer}): per shape (Hurst exponent, roll-off\n"
               "# level; 1: none), regime and load x = p/(E' h'), the reference's period and realizations (the\n"
               "# largest period solved at the load: a true period of 8L at x <= 1e-3 where one is solved),\n"
               "# sigma [m], m and the bandwidth ratio W as the law fittedElastoPlastic takes them, E' and H\n"
               "# [Pa] (empty: elastic), the geometric means of the exact A_r/A_n and h_c/k_s [1/m] and the\n"
               "# standard error of the latter over the realizations, as a factor.\n",
    "periods": "# The {few} on true periods (--length kL, spacing L/512), beside the cells that were their\n"
               "# reference before (the period meant as 4L, solved as 2L on 2048^2: spacing L/1024), written by\n"
               "# {writer}: per shape, regime and load x = p/(E' h'), the cell's\n"
               "# h_c/k_s [1/m] and each true period's, geometric means over their realizations. summary.csv's\n"
               "# reference at these loads is the largest true period.\n"}
# The summaries' comment lines as the scripts before this package wrote them (kept byte for byte).
WORDS = {"what": "eight self-affine spectra", "few": "eight spectra", "writer": "validation/studies/spectralShapes.py"}


class Commented(Table):
    """A Table whose text begins with comment lines (# ...), as the studies' summaries did."""

    def __init__(self, comment, columns, rows=None):
        super().__init__(columns, rows)
        self.comment = comment

    def text(self):
        return self.comment + super().text()


class Cell:
    """Solves of one kind: the label the summaries give it, the period solved (key), the spectrum
    file's multiple k (on_period; 1: the spectrum), the grid, seeds, the loads x it holds (low <=
    x <= top), the key's variant and whether --length makes the period the true one."""

    def __init__(self, label, period, k, grid, seeds, low, top, variant="", true=False):
        self.label, self.period, self.k, self.grid, self.seeds = label, period, k, grid, seeds
        self.low, self.top, self.variant, self.true = low, top, variant, true

    def holds(self, x):
        return self.low * (1 - 1e-9) <= x <= self.top * (1 + 1e-9)


class Design:
    """The solves' sizes, from the first seed of the study's own: the cells L on N^2, 2L on
    (2N)^2 and the 2L meant as 4L on (4N)^2 (CELLS), the true periods (PERIODS, the largest the
    reference where solved), the spectra's levels N/8, the loads."""

    def __init__(self, quick, first):
        seeds = [first + i for i in range(8)]
        if quick:  # grids of 128 at most (one true period, 4L), two realizations, four loads
            self.N, self.loads, few, many = 32, [1e-4, 1e-3, 1e-2, 1e-1], seeds[:2], seeds[:2]
            ks = (4,)
        else:
            self.N, self.loads, few, many = 512, [10 ** (k / 3.0 - 4.0) for k in range(10)], seeds[:4], seeds
            ks = (4, 8)
        self.levels = self.N // 8
        self.cells = [Cell("1L", 1, 1, self.N, few, 1e-3, math.inf), Cell("2L", 2, 2, 2 * self.N, few, 1e-3, 1e-2),
                      Cell("4L", 2, 4, 4 * self.N, many, 0.0, 1e-3, MEANT)]
        self.periods = [Cell(f"{k}L", k, k, k * self.N, seeds[:2], 0.0, 1e-3, true=True) for k in ks]
        self.quick = quick


class Shapes:
    """The study on a list of shapes: spectralShapes' eight (seeds 101 on), blindSpectra's four
    (seeds 201 on). `name` is the study's (its table, its scratch folder); `words` fills the
    summaries' comment lines."""

    def __init__(self, ctx, name, shapes, first_seed, words):
        self.ctx, self.name, self.words = ctx, name, words
        self.design = Design(ctx.quick, first_seed)
        self.shapes = shapes[:2] if ctx.quick else shapes
        self._store = None

    def spectrum(self, name, k=1):
        """The shape's spectrum file (levels i/L up to N/8), on a period of kL for k > 1 (the core's on_period)."""
        _, hurst, rolloff = next(s for s in self.shapes if s[0] == name)
        path = spectra.self_affine(self.ctx.scratch_path(self.name, name + ".spectrum"), hurst, rolloff,
                                   self.design.levels, GRADIENT, LENGTH)
        return path if k == 1 else spectra.on_period(self.ctx, path, k)

    def loads(self, regime):
        """x of the regime: up to 0.9 H with the cap."""
        pair = materials.regime_pair(self.ctx, regime)
        return [x for x in self.design.loads
                if pair.hardness is None or x * pair.Eprime * GRADIENT <= 0.9 * pair.hardness]

    def key(self, name, regime, cell, seed):
        return {"surface": name, "regime": regime, "period": cell.period, "grid": cell.grid, "seed": seed,
                "variant": cell.variant}

    def solves(self):
        out = []
        for name, _, _ in self.shapes:
            for regime in REGIMES:
                pair = materials.regime_pair(self.ctx, regime)
                mat = pair.arguments + (["--hardness-from-yield"] if pair.hardness else [])
                for cell in self.design.cells + self.design.periods:
                    spec = self.spectrum(name, cell.k)
                    xs = [x for x in self.loads(regime) if cell.holds(x)]
                    for s in cell.seeds:
                        args = (true_period(spec, cell.k, LENGTH, cell.grid, s) if cell.true else
                                ["--spectrum", spec, "--synthesize", f"{cell.grid},{s}", "--model", "boundaryElement"])
                        out.append(solves.Solve(self.key(name, regime, cell, s), args + mat,
                                                [x * GRADIENT for x in xs]))
        # The largest periods first, so that the pool ends together.
        out.sort(key=lambda s: -s.key["grid"])
        return out

    def store(self):
        if self._store is None:
            self._store = solves.Store(self.ctx, self.name, KEYS)
        return self._store

    def cell(self, x):
        """The largest cell solved at the load x (at x <= 1e-3 the period meant as 4L, solved as 2L)."""
        return max((c for c in self.design.cells if c.holds(x)), key=lambda c: c.k)

    def reference(self, x):
        """The reference at the load x: the largest true period solved there, else the largest cell."""
        periods = [c for c in self.design.periods if c.holds(x)]
        return max(periods, key=lambda c: c.k) if periods else self.cell(x)

    def solved(self, name, regime, cell, x):
        """(h_c/k_s, A_r/A_n) of each realization of the cell at the load x."""
        h, area = [], []
        for s in cell.seeds:
            row = solves.at(self.store().curve(self.key(name, regime, cell, s)), x * GRADIENT)
            if row is None:
                raise SystemExit(f"{self.name}: {name} {regime} {cell.label} seed {s} has no solution at x = {x:.3g}")
            h.append(number(row["h_per_k_per_m"]))
            area.append(number(row["area_fraction"]))
        return h, area

    def summary(self):
        """Per shape, regime and load: the reference's period and realizations, sigma, m and W of
        the spectrum (the core's), E' and H, the geometric means of A_r/A_n and h_c/k_s and the
        latter's standard error (a factor)."""
        rc = self.ctx.rc()
        rows = []
        for name, hurst, rolloff in self.shapes:
            spec = rc.SurfaceSpec.spectrum(self.spectrum(name))
            r = spec.roughness()
            W = rc.spectral_bandwidth_ratio(spec.read_spectrum())
            for regime in REGIMES:
                pair = materials.regime_pair(self.ctx, regime)
                for x in self.loads(regime):
                    ref = self.reference(x)
                    h, area = self.solved(name, regime, ref, x)
                    se = standard_error(h)
                    rows.append({"surface": name, "hurst": hurst, "rolloff": rolloff, "regime": regime,
                                 "x": f"{x:.6g}", "reference": ref.label, "realizations": len(h),
                                 "sigma": f"{r.sigma:.6g}", "m": f"{r.mean_absolute_slope:.6g}",
                                 "bandwidth": f"{W:.6g}",
                                 "gradient": GRADIENT, "Eprime": f"{pair.Eprime:.6g}",
                                 "H": f"{pair.hardness:.6g}" if pair.hardness else "",
                                 "area": f"{geometric_mean(area):.6g}", "h_per_k": f"{geometric_mean(h):.6g}",
                                 "standard_error": f"{se:.4f}" if se else ""})
        return Commented(COMMENT["summary"].format(**self.words), list(rows[0]), rows)

    def periods(self):
        """Per shape, regime and load of the true periods: the cell that was the reference there
        before and each true period, the geometric means of h_c/k_s over their realizations."""
        rows = []
        top = max(c.top for c in self.design.periods)
        for name, _, _ in self.shapes:
            for regime in REGIMES:
                for x in [x for x in self.loads(regime) if x <= top * (1 + 1e-9)]:
                    cell = self.cell(x)
                    h, _ = self.solved(name, regime, cell, x)
                    row = {"surface": name, "regime": regime, "x": f"{x:.6g}",
                           "cell": f"{cell.label} (solved as 2L)" if cell.variant == MEANT else cell.label,
                           "cell_h_per_k": f"{geometric_mean(h):.6g}", "cell_realizations": len(h)}
                    for p in self.design.periods:
                        if p.holds(x):
                            h, _ = self.solved(name, regime, p, x)
                            row[f"h_per_k_{p.label}"] = f"{geometric_mean(h):.6g}"
                            row[f"realizations_{p.label}"] = len(h)
                    rows.append(row)
        return Commented(COMMENT["periods"].format(**self.words), list(rows[0]), rows)


def shapes(ctx):
    return Shapes(ctx, "spectralShapes", SHAPES, 101, WORDS)


def spectrum(ctx, name):
    """The spectrum file of one of the eight shapes (the scratch folder's)."""
    return shapes(ctx).spectrum(name)


def summary(ctx):
    """summary.csv (a Table, its comment lines included): the exact answer per shape, regime and load."""
    return shapes(ctx).summary()


def periods(ctx):
    """periods.csv (a Table, its comment lines included): the true periods beside the cells."""
    return shapes(ctx).periods()


def solve(ctx):
    s = shapes(ctx)
    s.store().solve(s.solves())


def label(hurst, rolloff):
    return f"Hurst {hurst:g}, " + ("no roll-off" if rolloff == 1 else f"roll-off at L/{rolloff}")


def tables(out, s, summary_table, periods_table):
    """The markdown tables of a Shapes study: its spectra, its summary and its periods."""
    rc = s.ctx.rc()
    first = {}
    for r in summary_table.rows:
        first.setdefault(r["surface"], r)
    top = s.design.periods[-1].label
    rows = []
    for name, hurst, rolloff in s.shapes:
        r = first[name]
        s1 = rc.first_level_share(rc.Spectrum.read(s.spectrum(name)))
        light = [number(p[f"h_per_k_{top}"]) / number(p["cell_h_per_k"]) for p in periods_table.rows
                 if p["surface"] == name]
        rows.append([name, label(hurst, rolloff), r["sigma"], r["m"], r["bandwidth"], f"{s1:.3f}", pages.span(light)])
    out.table("spectra", ["surface", "spectrum", "sigma [m]", "m", "W", "s1",
                          f"{top} / the cell at x <= 1e-3 (min-max)"], rows)
    out.table("summary", ["surface", "regime", "x", "reference", "realizations", "A_r/A_n", "h_c/k_s [1/m]",
                          "standard error (factor)"],
              [[r["surface"], r["regime"], r["x"], r["reference"], r["realizations"], r["area"], r["h_per_k"],
                r["standard_error"] or "-"] for r in summary_table.rows])
    ks = [p.label for p in s.design.periods]
    out.table("periods", ["surface", "regime", "x", "the cell", "cell h_c/k_s [1/m] (realizations)"] +
              [f"{k} h_c/k_s [1/m] (realizations)" for k in ks] + [f"{k} / the cell" for k in ks],
              [[r["surface"], r["regime"], r["x"], r["cell"], f"{r['cell_h_per_k']} ({r['cell_realizations']})"] +
               [f"{r[f'h_per_k_{k}']} ({r[f'realizations_{k}']})" if r.get(f"h_per_k_{k}") else "-" for k in ks] +
               [pages.fmt(number(r.get(f"h_per_k_{k}")) / number(r["cell_h_per_k"])) for k in ks]
               for r in periods_table.rows])


def outputs(ctx):
    s = shapes(ctx)
    out = pages.Outputs(ctx, "spectralShapes")
    summary_table, periods_table = s.summary(), s.periods()
    out.text("summary.csv", summary_table.text())
    out.text("periods.csv", periods_table.text())
    tables(out, s, summary_table, periods_table)
    return out
