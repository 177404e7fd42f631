# SPDX-License-Identifier: GPL-3.0-or-later
"""The second hold-out's light loads on true periods of 8L: a self-affine surface (Hurst 0.6, roll-off at L/2, h' = 0.2), steel on steel, elastic and capped at c = H/(E' h') = 0.03, 0.1, 0.3.

The second hold-out of the default law fittedElastoPlastic was solved by an earlier study as one
period L (validation/data/secondHoldOutEarlier.csv, which the fit reads), whose exact answer at
light loads is too high for a large joint (docs/validation/engineeringRange.md, "Light loads: how
large a period"). Its spectrum was not kept; it is written again from its form (C1 flat below the
2nd level, f^-(1 + 2H) above, 56 levels i/L, L = 1 mm, scaled to h' = 0.2: 56 levels give its
recorded sigma), and its loads x = p/(E' h') <= 1e-3 are solved on true periods of 8L (--length
8L on 4096^2, spacing L/512, as the engineering range's references there), two realizations on
seeds of its own (301, 302), in every regime. The cap is the hardness H = c E' h' itself (--hardness),
not a pair's. The fit takes these as the second hold-out's reference at those loads.
docs/validation/secondHoldOut.md.
"""
import os

from .. import materials, pages, solves, spectra
from ..context import ROOT
from ..tables import Table, number
from .engineeringRange import geometric_mean, true_period
from .spectralShapes import Commented

DATA = ["secondHoldOut.csv"]
KEYS = ["surface", "regime", "period", "grid", "seed"]
NAME = "selfAffine06ro2"
HURST, ROLLOFF, LEVELS, GRADIENT, LENGTH = 0.6, 2, 56, 0.2, 1e-3  # its spectrum's form
REGIMES = [("elastic", None), ("cap0.03", 0.03), ("cap0.1", 0.1), ("cap0.3", 0.3)]  # (key, c = H/(E' h'))
# The earlier study's one-period answers (committed, never solved again; the fit reads them too).
EARLIER = os.path.join(ROOT, "validation", "data", "secondHoldOutEarlier.csv")
COMMENT = ("# The second hold-out's light loads (x = p/(E' h') <= 1e-3) on true periods of 8L (--length 8L on\n"
           "# 4096^2, spacing L/512; seeds 301-302), written by validation/studies/secondHoldOut.py: the\n"
           "# columns of selfAffine06ro2.csv (sigma [m] and m of its spectrum, the realizations, the mean\n"
           "# exact A_r/A_n and the geometric mean h_c/k_s [1/m]); the fit's reference at these loads.\n")


class Design:
    """A period of K L on (K N)^2 (spacing L/N), the spectrum's levels, the seeds, the loads x."""

    def __init__(self, quick):
        if quick:  # a period of 2L on 128^2, the spectrum cut at 8 levels, one realization
            self.N, self.K, self.levels, self.seeds, self.loads = 64, 2, 8, [301], [1e-4, 1e-3]
        else:
            self.N, self.K, self.levels, self.seeds = 512, 8, LEVELS, [301, 302]
            self.loads = [10 ** (k / 3.0 - 4.0) for k in range(4)]  # x = 1e-4 .. 1e-3, the light loads


def spectrum(ctx, k=1):
    """The surface's spectrum file (levels i/L), on a period of kL for k > 1 (the core's on_period)."""
    path = spectra.self_affine(ctx.scratch_path("secondHoldOut", NAME + ".spectrum"), HURST, ROLLOFF,
                               Design(ctx.quick).levels, GRADIENT, LENGTH)
    return path if k == 1 else spectra.on_period(ctx, path, k)


def materials_of(ctx, c):
    """The CLI's material arguments of a regime: steel on steel, capped at H = c E' h'."""
    pair = materials.regime_pair(ctx, "elastic")
    return pair.arguments + ([] if c is None else ["--hardness", f"{c * pair.Eprime * GRADIENT:.10g}"])


def key(d, regime, seed):
    return {"surface": NAME, "regime": regime, "period": d.K, "grid": d.K * d.N, "seed": seed}


def solve(ctx):
    d = Design(ctx.quick)
    spec = spectrum(ctx, d.K)
    jobs = [solves.Solve(key(d, regime, s), true_period(spec, d.K, LENGTH, d.K * d.N, s) + materials_of(ctx, c),
                         [x * GRADIENT for x in d.loads]) for regime, c in REGIMES for s in d.seeds]
    solves.Store(ctx, "secondHoldOut", KEYS).solve(jobs)


def summary(ctx):
    """summary.csv (a Table, its four comment lines included): per regime and load, sigma [m] and
    m of the spectrum (the core's), h', the realizations, the mean A_r/A_n and the geometric mean
    h_c/k_s [1/m] over them."""
    d = Design(ctx.quick)
    data = solves.Store(ctx, "secondHoldOut", KEYS)
    r = ctx.rc().SurfaceSpec.spectrum(spectrum(ctx)).roughness()
    rows = []
    for regime, _ in REGIMES:
        for x in d.loads:
            found = [solves.at(data.curve(key(d, regime, s)), x * GRADIENT) for s in d.seeds]
            if not all(found):
                raise SystemExit(f"secondHoldOut: {regime} x = {x:g}: {sum(map(bool, found))} of {len(d.seeds)} "
                                 "realizations have the load")
            h = [number(f["h_per_k_per_m"]) for f in found]
            area = [number(f["area_fraction"]) for f in found]
            rows.append({"surface": NAME, "sigma": f"{r.sigma:.4g}", "m": f"{r.mean_absolute_slope:.6g}",
                         "gradient": f"{GRADIENT:g}", "regime": regime, "x": f"{x:.10g}", "realizations": len(h),
                         "area": f"{sum(area) / len(area):.4g}", "h_per_k": f"{geometric_mean(h):.4g}"})
    return Commented(COMMENT, list(rows[0]), rows)


def outputs(ctx):
    d = Design(ctx.quick)
    table = summary(ctx)
    out = pages.Outputs(ctx, "secondHoldOut")
    out.text("summary.csv", table.text())
    pair = materials.regime_pair(ctx, "elastic")
    out.table("regimes", ["regime", "c = H/(E' h')", "H [MPa]"],
              [[regime, "-" if c is None else f"{c:g}", "-" if c is None else f"{c * pair.Eprime * GRADIENT / 1e6:.0f}"]
               for regime, c in REGIMES])
    r = table.rows[0]
    out.table("surface", ["what", "value"],
              [["spectrum", f"Hurst {HURST:g}, C1 flat below level {ROLLOFF}, {d.levels} levels i/L, "
                            f"L = {LENGTH * 1e3:g} mm"],
               ["h'", r["gradient"]], ["sigma [m]", r["sigma"]], ["m", r["m"]],
               ["solved", f"true periods of {d.K}L on {d.K * d.N}^2 (spacing L/{d.N}), seeds "
                          f"{', '.join(str(s) for s in d.seeds)}"]])
    out.table("summary", ["regime", "x", "realizations", "A_r/A_n", "h_c/k_s [1/m]"],
              [[r["regime"], f"{float(r['x']):.3g}", r["realizations"], r["area"], r["h_per_k"]] for r in table.rows])
    if not os.path.exists(EARLIER):
        raise SystemExit(f"secondHoldOut: there is no {ctx.relative(EARLIER)} (the earlier study's answers)")
    earlier = Table.read(EARLIER).rows
    rows, ratios = [], []
    for r in table.rows:
        e = next(e for e in earlier if e["regime"] == r["regime"] and abs(number(e["x"]) / number(r["x"]) - 1) < 1e-6)
        ratios.append(number(r["h_per_k"]) / number(e["h_per_k_per_m"]))
        rows.append([r["regime"], f"{number(r['x']):.3g}", f"{e['h_per_k_per_m']} ({e['realizations']})",
                     f"{r['h_per_k']} ({r['realizations']})", pages.fmt(ratios[-1])])
    out.table("earlier", ["regime", "x", "one period L: h_c/k_s [1/m] (realizations)",
                          f"{d.K}L: h_c/k_s [1/m] (realizations)", f"{d.K}L / one period"], rows)
    out.table("findings", ["what", "measured"], [[f"{d.K}L over one period L, over the {len(ratios)} light loads",
                                                  pages.span(ratios)]])
    return out
