# SPDX-License-Identifier: GPL-3.0-or-later
"""Is a period of 8L large enough at the lightest loads? True periods of 16L against 8L at the same spacing, x = 1e-4 and 2.15e-4, on three training spectra and a blind one.

The engineering range's reference at x = p/(E' h') <= 1e-3 is the largest period solved there,
8L, checked against 4L. Whether 8L itself is converged is asked at the two lightest loads, where
the period matters most: two of the engineering range's self-affine spectra (Hurst 0.5 without a
roll-off, whose longest wave holds the most of the heights; Hurst 0.8 rolled off at L/4), elastic
and capped for annealed copper on copper (the most plastic pair, where the default law is at the
low end of its band); the Dektak profile's spectrum, elastic, whose 8L is the furthest below its
4L; and blindSpectra's Hurst 0.9 without a roll-off, elastic and copper, whose 4L is furthest
above its 8L and where the law's one light-load miss of the blind four is. True periods of 16L
(--length 16L on 4096^2) and 8L (on 2048^2): the same spacing L/256, so the two differ in their
period alone (a coarser spacing than the references' L/512 keeps 16L on a grid solved in
minutes). Realizations on seeds of their own: four (401-404), eight on the Dektak spectrum
(401-408), whose realizations scatter most.

The 8L reference and the default law's ratio to it are the other studies': engineeringRange's
Results for its spectra, blindSpectra's summary for the blind one. docs/validation/largerPeriods.md.
"""
import math

from .. import materials, pages, solves, spectra
from ..tables import number
from . import blindSpectra, engineeringRange
from .engineeringRange import geometric_mean, standard_error, true_period
from .spectralShapes import Commented

DATA = ["largerPeriods.csv"]
KEYS = ["surface", "regime", "period", "grid", "seed"]
# (name, what it is, regimes, seeds)
SURFACES = [("selfAffine05", "Hurst 0.5, no roll-off", ["elastic", "copperCopper"], list(range(401, 405))),
            ("selfAffine08", "Hurst 0.8, roll-off at L/4", ["elastic", "copperCopper"], list(range(401, 405))),
            ("dektak", "the Dektak profile's spectrum up to 64/L", ["elastic"], list(range(401, 409))),
            ("hurst09rolloff1", "blind: Hurst 0.9, no roll-off", ["elastic", "copperCopper"], list(range(401, 405)))]
LOADS = [1e-4, 10 ** (-11.0 / 3.0)]  # x = 1e-4 and 2.15e-4, the engineering range's two lightest
COMMENT = ("# 16L against 8L at the same spacing L/256 (validation/studies/largerPeriods.py): geometric means of\n"
           "# h_c/k_s [1/m] over the realizations (seeds 401-404), their max/min, the standard error of the\n"
           "# ratio (a factor), the reports' 8L reference (spacing L/512, its own seeds: the engineering range's,\n"
           "# the blind spectra's for hurst09rolloff1) and the\n"
           "# default law over it, and the law over that reference scaled by 16L/8L.\n")


class Design:
    """The spectra's levels and the periods (k, grid) compared, the smaller first, at one spacing."""

    def __init__(self, quick):
        if quick:  # 2L on 64^2 against 4L on 128^2, 8 levels, two realizations
            self.levels, self.periods, self.seeds = 8, [(2, 64), (4, 128)], 2
        else:
            self.levels, self.periods, self.seeds = 64, [(8, 2048), (16, 4096)], None
        self.quick = quick

    def seeds_of(self, seeds):
        return seeds[:self.seeds] if self.seeds else seeds


def spectrum(ctx, name, d):
    """The surface's spectrum file: the engineering range's or blindSpectra's definition, cut at d.levels."""
    path = ctx.scratch_path("largerPeriods", name + ".spectrum")
    if name == "dektak":
        return spectra.profile_spectrum(ctx, path, engineeringRange.DEKTAK, d.levels)
    shapes = [(n, h, r) for n, h, r, _ in engineeringRange.SELF_AFFINE] + blindSpectra.SHAPES
    _, hurst, rolloff = next(s for s in shapes if s[0] == name)
    return spectra.self_affine(path, hurst, rolloff, d.levels)


class Surface:
    def __init__(self, ctx, d, name, what, regimes, seeds):
        self.name, self.what, self.regimes, self.seeds = name, what, regimes, d.seeds_of(seeds)
        self.path = spectrum(ctx, name, d)
        self.gradient = spectra.gradient(ctx, self.path)  # h' of x (the core's)
        self.length = spectra.length(self.path)


def surfaces(ctx, d):
    return [Surface(ctx, d, *s) for s in SURFACES]


def key(s, regime, k, grid, seed):
    return {"surface": s.name, "regime": regime, "period": k, "grid": grid, "seed": seed}


def solve(ctx):
    d = Design(ctx.quick)
    jobs = []
    for s in surfaces(ctx, d):
        for regime in s.regimes:
            pair = materials.regime_pair(ctx, regime)
            mat = pair.arguments + (["--hardness-from-yield"] if pair.hardness else [])
            for k, grid in d.periods:
                spec = spectra.on_period(ctx, s.path, k)
                for seed in s.seeds:
                    jobs.append(solves.Solve(key(s, regime, k, grid, seed), true_period(spec, k, s.length, grid, seed)
                                             + mat, [x * s.gradient for x in LOADS]))
    jobs.sort(key=lambda j: -j.key["grid"])  # the longest first
    solves.Store(ctx, "largerPeriods", KEYS).solve(jobs)


def references(ctx):
    """{(surface, regime, x): (the 8L reference h_c/k_s, the default law over it)}: engineeringRange's
    Results (its reference at x <= 1e-3 is 8L) and blindSpectra's summary, the law's ratio to 4
    decimals as their tables give it. Empty with --quick (the other studies' quick data are not these)."""
    if ctx.quick:
        return {}
    out = {}
    R = engineeringRange.Results(ctx)
    for (name, regime), exact in R.exact.items():
        for x, e in exact.items():
            out[(name, regime, f"{x:.6g}")] = (e["h"], round(R.ratios[(name, regime)][x][R.default], 4))
    for r in blindSpectra.Results(ctx).summary().rows:
        if r["law_over_exact"]:
            out[(r["surface"], r["regime"], r["x"])] = (number(r["h_per_k"]), number(r["law_over_exact"]))
    return out


def summary(ctx):
    """summary.csv (a Table, its comment lines included): per surface, regime and load, each
    period's geometric mean h_c/k_s, their ratio, spreads (max/min) and the ratio's standard
    error (a factor), the 8L reference, the default law over it and over it scaled by 16L/8L."""
    d = Design(ctx.quick)
    data = solves.Store(ctx, "largerPeriods", KEYS)
    known = references(ctx)
    (k1, g1), (k2, g2) = d.periods
    rows = []
    for s in surfaces(ctx, d):
        for regime in s.regimes:
            for x in LOADS:
                h = {}
                for k, grid in d.periods:
                    found = [solves.at(data.curve(key(s, regime, k, grid, seed)), x * s.gradient) for seed in s.seeds]
                    if not all(found):
                        raise SystemExit(f"largerPeriods: {s.name} {regime} {k}L has no solution at x = {x:g}")
                    h[k] = [number(f["h_per_k_per_m"]) for f in found]
                a, b = geometric_mean(h[k1]), geometric_mean(h[k2])
                ref, law = known.get((s.name, regime, f"{x:.6g}"), (float("nan"), float("nan")))
                error = math.exp(math.hypot(*(math.log(standard_error(h[k]) or 1.0) for k in (k1, k2))))
                rows.append({"surface": s.name, "regime": regime, "x": f"{x:.6g}", "realizations": len(s.seeds),
                             f"h_per_k_{k1}L": f"{a:.4g}", f"h_per_k_{k2}L": f"{b:.4g}",
                             f"ratio_{k2}L_{k1}L": f"{b / a:.4f}",
                             f"spread_{k1}L": f"{max(h[k1]) / min(h[k1]):.3f}",
                             f"spread_{k2}L": f"{max(h[k2]) / min(h[k2]):.3f}", f"error_{k2}L_{k1}L": f"{error:.3f}",
                             f"reference_{k1}L": f"{ref:.4g}", "law_over_reference": f"{law:.4f}",
                             f"law_over_{k2}L_scaled": f"{law / (b / a):.4f}"})
    return Commented(COMMENT, list(rows[0]), rows)


def outputs(ctx):
    d = Design(ctx.quick)
    (k1, _), (k2, _) = d.periods
    table = summary(ctx)
    out = pages.Outputs(ctx, "largerPeriods")
    out.text("summary.csv", table.text())
    out.table("surfaces", ["surface", "what", "h'", "regimes", "realizations", "periods"],
              [[s.name, s.what, f"{s.gradient:.2g}", ", ".join(s.regimes), len(s.seeds),
                " and ".join(f"{k}L on {g}^2" for k, g in d.periods)] for s in surfaces(ctx, d)])
    rows = table.rows

    def v(r, c):
        return number(r[c])
    ratio, error = f"ratio_{k2}L_{k1}L", f"error_{k2}L_{k1}L"
    out.table("periods", ["surface", "regime", "x", f"{k1}L h_c/k_s [1/m]", f"{k2}L h_c/k_s [1/m]", f"{k2}L / {k1}L",
                          "its standard error (factor)", f"spread {k1}L, {k2}L (max/min)",
                          f"the default law / the {k1}L reference", f"the same, the reference scaled by {k2}L/{k1}L"],
              [[r["surface"], r["regime"], f"{v(r, 'x'):.2g}", r[f"h_per_k_{k1}L"], r[f"h_per_k_{k2}L"],
                pages.fmt(v(r, ratio)), pages.fmt(v(r, error)),
                f"{pages.fmt(v(r, f'spread_{k1}L'))}, {pages.fmt(v(r, f'spread_{k2}L'))}",
                pages.fmt(v(r, "law_over_reference")), pages.fmt(v(r, f"law_over_{k2}L_scaled"))] for r in rows])
    within = [r for r in rows if abs(math.log(v(r, ratio))) <= 2 * math.log(v(r, error))]
    far = max(rows, key=lambda r: abs(math.log(v(r, ratio))))
    copper = [r for r in rows if r["regime"] == "copperCopper"]
    out.table("findings", ["what", "measured"], [
        [f"{k2}L over {k1}L, over the {len(rows)} points", pages.span(v(r, ratio) for r in rows)],
        [f"points where {k2}L is {k1}L within 10 %",
         f"{sum(abs(v(r, ratio) - 1) <= 0.10 for r in rows)} of {len(rows)}"],
        [f"points where {k2}L is {k1}L within two standard errors", f"{len(within)} of {len(rows)}"],
        ["the largest departure", f"{far['surface']}, {far['regime']}, x = {v(far, 'x'):.2g}: {v(far, ratio):.2f} "
                                  f"(a standard error of a factor {v(far, error):.2f})"],
        [f"points where {k2}L differs from {k1}L beyond two standard errors",
         "; ".join(f"{r['surface']}, {r['regime']}, x = {v(r, 'x'):.2g}: {v(r, ratio):.2f}"
                   for r in rows if r not in within) or "none"],
        [f"annealed copper: {k2}L over {k1}L", pages.span(v(r, ratio) for r in copper)],
        [f"annealed copper: the default law over the {k1}L reference",
         pages.span(v(r, "law_over_reference") for r in copper)]])
    return out
