# SPDX-License-Identifier: GPL-3.0-or-later
"""The unloading branch on a measured map it never saw: the X3P map loaded, unloaded, exact against the law.

The default law's unloading branch was fitted on synthesized spectra and held to others
(unloading.py). Here it meets a measured surface: the areal map data/x3p-2.x3p (650^2, less its
plane, h' = 0.080), solved mirrored about its edges as in the engineering range, for the four
capped pairs. Loaded to x = p/(E' h') = 1e-3, 1e-2 and 0.1 (peaks above 0.9 H left out), then
unloaded to a half, a fifth, a tenth and a thirtieth of the peak; the exact ratio R = h_u/h_l at
each fraction against the branch's R on the map's own inputs (W, H_f, m as the condition reads
the map, direction both). One map is one surface: no seeds. The table is
validation/data/unloadingMap.csv; docs/validation/unloading.md reads the page's tables.
"""
from .. import materials, pages, solves, surrogates
from ..fitting import BAND
from ..tables import Table
from .engineeringRange import X3P
from .unloading import FRACTIONS, Ratios, branch, pair_label

DATA = ["unloadingMap.csv"]
KEYS = ["surface", "regime", "peak", "branch"]
SURFACE = "x3p"


def design(ctx):
    """(peaks x = p/(E' h'), regimes)."""
    if ctx.quick:
        return [1e-2], ["steelSteel"]
    return [1e-3, 1e-2, 1e-1], [key for key, _, _, _ in materials.PAIRS]


def inputs(ctx):
    """What the default law takes of the map (the condition's reading of it, direction both)."""
    rc = ctx.rc()
    return surrogates.LawInputs(rc, rc.SurfaceSpec.areal(X3P, direction="both"))


def peaks(ctx, regime, given):
    """The regime's peaks p/E' (x h'), those up to 0.9 H."""
    pair = materials.regime_pair(ctx, regime)
    xs, _ = design(ctx)
    return [x * given.gradient for x in xs if x * given.gradient * pair.Eprime <= 0.9 * pair.hardness]


def solve_list(ctx, given):
    out = []
    for regime in design(ctx)[1]:
        pair = materials.regime_pair(ctx, regime)
        base = ["--areal", X3P, "--mirror", "--model", "boundaryElement"] + pair.arguments + ["--hardness-from-yield"]
        for peak in peaks(ctx, regime, given):
            loads = [f * peak for f in FRACTIONS]
            key = {"surface": SURFACE, "regime": regime, "peak": peak}
            out.append(solves.Solve({**key, "branch": "loading"}, base, loads))
            out.append(solves.Solve({**key, "branch": "unloading"},
                                    base + ["--unload-from", f"{peak * pair.Eprime:.17g}"], loads,
                                    solves.UNLOADING_COLUMNS))
    return out


def solve(ctx):
    solves.Store(ctx, "unloadingMap", KEYS).solve(solve_list(ctx, inputs(ctx)))


def points(ctx, given):
    """Ratios at every solved peak and fraction below it (exact R from the table)."""
    store = solves.Store(ctx, "unloadingMap", KEYS)
    rows = []
    for regime in design(ctx)[1]:
        pair = materials.regime_pair(ctx, regime)
        for peak in peaks(ctx, regime, given):
            key = {"surface": SURFACE, "regime": regime, "peak": peak}
            curves = {b: store.curve({**key, "branch": b}) for b in ("loading", "unloading")}
            for f in FRACTIONS[1:]:
                at = {b: solves.at(c, f * peak) for b, c in curves.items()}
                if not all(at.values()):
                    raise SystemExit(f"unloadingMap: {regime} peak {peak:.6g} has no solve at {f:g} of it")
                ratio = float(at["unloading"]["h_per_k_per_m"]) / float(at["loading"]["h_per_k_per_m"])
                rows.append({**given.point(f * peak * pair.Eprime, pair, exact=ratio), "peak": peak * pair.Eprime,
                             "regime": regime, "x": peak / given.gradient, "fraction": f,
                             "over_H": peak * pair.Eprime / pair.hardness})
    return Ratios(rows)


def outputs(ctx):
    rc = ctx.rc()
    given = inputs(ctx)
    pts = points(ctx, given)
    R = branch(rc, rc.FittedElastoPlasticConstants(), pts)
    q = R / pts.exact
    summary, table = [], []
    for r, b, v in zip(pts.rows, R, q):
        summary.append({"surface": SURFACE, "regime": r["regime"], "peak_x": f"{r['x']:.6g}",
                        "peak_over_H": f"{r['over_H']:.4f}", "fraction": f"{r['fraction']:.6g}",
                        "exact_ratio": f"{r['exact']:.4f}", "branch_ratio": f"{b:.4f}",
                        "branch_over_exact_ratio": f"{v:.4f}"})
    for regime in dict.fromkeys(r["regime"] for r in pts.rows):
        for x in dict.fromkeys(r["x"] for r in pts.rows if r["regime"] == regime):
            mine = [(r, b, v) for r, b, v in zip(pts.rows, R, q) if r["regime"] == regime and r["x"] == x]
            table.append([pair_label(regime), f"{x:.0e}", f"{mine[0][0]['over_H']:.3f}"] +
                         [f"{r['exact']:.2f} / {b:.2f}" for r, b, _ in mine] +
                         [pages.span([v for _, _, v in mine])])
    within = sum(abs(v - 1) <= BAND for v in q)
    out = pages.Outputs(ctx, "unloadingMap")
    out.table("ratios", ["pair", "peak x", "P_max/H"] +
              [f"P/P_max = {f:.2g}: exact R / branch R" for f in FRACTIONS[1:]] + ["branch R / exact R"], table)
    out.table("inputs", ["W", "H_f", "m", "h'", "points within 25 %", "branch R / exact R"],
              [[f"{given.bandwidth:.3f}", f"{given.fine_hurst:.2f}", f"{given.m:.3f}", f"{given.gradient:.3f}",
                f"{within} of {len(q)}", pages.span(q)]])
    out.text("summary.csv", Table(list(summary[0].keys()), summary).text())
    out.figure("ratios", lambda path: draw_ratios(ctx, pts, R, path))
    return out


def draw_ratios(ctx, pts, R, path):
    """The branch's R against the exact R: the unloading study's counted points (grey) and the
    map's (by pair), with the 25 % band."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    from .unloading import COUNTED
    study = [r for r in pages.generated(ctx, "unloading", "summary.csv").rows
             if r["role"] in COUNTED and float(r["fraction"]) < 1]
    fig, ax = plt.subplots(figsize=(5.6, 5.0))
    ax.loglog([float(r["unloading_over_loading_h"]) for r in study], [float(r["branch_ratio"]) for r in study],
              ".", color="0.7", label=f"synthesized spectra, unloading study ({len(study)})")
    for k, regime in enumerate(dict.fromkeys(r["regime"] for r in pts.rows)):
        mine = [i for i, r in enumerate(pts.rows) if r["regime"] == regime]
        ax.loglog([pts.exact[i] for i in mine], [R[i] for i in mine], "o", color=f"C{k}",
                  label=f"X3P map: {pair_label(regime)}")
    lo, hi = 0.7, 7.0
    line = [lo, hi]
    ax.loglog(line, line, "k-", lw=0.8)
    ax.loglog(line, [v * (1 + BAND) for v in line], "k:", lw=0.8, label=f"{100 * BAND:.0f} % of the exact R")
    ax.loglog(line, [v * (1 - BAND) for v in line], "k:", lw=0.8)
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ticks = [0.8, 1, 1.5, 2, 3, 4, 6]
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(matplotlib.ticker.FixedLocator(ticks))
        axis.set_major_formatter(matplotlib.ticker.FixedFormatter([f"{t:g}" for t in ticks]))
        axis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("exact R = h_unloading / h_loading")
    ax.set_ylabel("the default law's branch R")
    ax.set_title("The unloading branch on a measured map it never saw", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)
