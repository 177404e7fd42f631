# SPDX-License-Identifier: GPL-3.0-or-later
"""The map surrogates' tables, summaries and figure (docs/validation/mapSurrogates.md includes
them), made from the exact answers and every law's ratio (mapSurrogates.Study.ratios)."""
from .. import materials, pages
from .engineeringRange import BAND
from .mapSurrogates import DEFAULT, KINDS, name_of, summary_text, surfaces_text

STUDY = "mapSurrogates"


def label(regime):
    return materials.regime_of(regime)[1]


def band(values):
    return f"{min(values):.2f}-{max(values):.2f}" if values else "-"


def figure(s, rows):
    regimes = s.design.regimes

    def draw(path):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import FixedLocator, NullLocator, ScalarFormatter
        columns = 3
        lines = (len(regimes) + columns) // columns
        fig, grid = plt.subplots(lines, columns, figsize=(12, 3.5 * lines), sharey=True, squeeze=False)
        axes = list(grid.ravel())
        for ax, regime in zip(axes, regimes):
            here = [r for r in rows if r[1] == regime]
            for kind, colour, what in (("gaussian", "tab:blue", "random phases"),
                                       ("heights", "tab:orange", "random phases, the map's heights"),
                                       ("map", "black", "the map")):
                names = sorted({r[0] for r in here if r[0].startswith(kind)})
                for i, n in enumerate(names):
                    pts = sorted((r[2], r[5][DEFAULT]) for r in here if r[0] == n)
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o" if kind == "map" else "-",
                            color=colour, lw=2 if kind == "map" else 1, ms=3, label=what if i == 0 else None)
            ax.axhspan(1 - BAND, 1 + BAND, color="0.9", zorder=0)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.yaxis.set_major_locator(FixedLocator([0.5, 0.75, 1.0, 1.25, 1.5, 2.0]))
            ax.yaxis.set_major_formatter(ScalarFormatter())
            ax.yaxis.set_minor_locator(NullLocator())
            ax.set_title(label(regime), fontsize=9)
            ax.set_xlabel("x = p/(E' h')")
            ax.grid(True, which="major", color="0.8", lw=0.5)
        for line in grid:
            line[0].set_ylabel(f"{DEFAULT} / exact")
        handles, labels = axes[0].get_legend_handles_labels()
        for ax in axes[len(regimes):]:
            ax.axis("off")
        axes[-1].legend(handles, labels, loc="center", fontsize=9, title=f"grey: within {100 * BAND:.0f} %")
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
    return draw


def outputs(ctx, s, rows, stats):
    d = s.design
    out = pages.Outputs(ctx, STUDY)
    out.text("summary.csv", summary_text(rows))
    out.text("surfaces.csv", surfaces_text(stats))
    what = dict(KINDS)
    out.table("surfaces", ["surface", "what it keeps of the map", "sigma [nm]", "m", "W", "skewness", "kurtosis"],
              [[name_of(kind, seed), what[kind].format(seed=seed), f"{stats[name_of(kind, seed)][0] * 1e9:.1f}"]
               + [f"{v:{f}}" for v, f in zip(stats[name_of(kind, seed)][1:], (".4f", ".3f", ".2f", ".2f"))]
               for kind, seed in d.surfaces])
    summary = []
    for regime in d.regimes:
        here = [r for r in rows if r[1] == regime]
        xs = sorted({r[2] for r in here})

        def at(kind, x):
            return [r[5][DEFAULT] for r in here if abs(r[2] / x - 1) < 1e-6 and r[0].startswith(kind)]
        out.table(f"law-{regime}", ["x"] + [f"{x:.2g}" for x in xs], [
            ["the map"] + [f"{at('map', x)[0]:.2f}" for x in xs],
            [f"gaussian{d.seeds[0]}-{d.seeds[-1]}"] + [band(at("gaussian", x)) for x in xs],
            [f"heights{d.seeds[0]}-{d.seeds[-1]}"] + [band(at("heights", x)) for x in xs],
            [f"within {100 * BAND:.0f} %"] + [f"{sum(abs(v - 1) <= BAND for v in at('', x))}/{len(at('', x))}"
                                              for x in xs]])
        spread = [max(max(at(k, x)) / min(at(k, x)) for x in xs) for k in ("gaussian", "heights")]
        summary.append([label(regime)] + [band([r[5][DEFAULT] for r in here if r[0].startswith(k)])
                                          for k in ("map", "gaussian", "heights")]
                       + [f"{v:.2f}" for v in spread])
    seeds = f"{d.seeds[0]}-{d.seeds[-1]}"
    out.table("summary", ["regime", "the map", f"gaussian{seeds}", f"heights{seeds}",
                          f"spread at one load: gaussian{seeds}", f"heights{seeds}"], summary)
    mirrored, dx, dy = s.mirrored()
    ny, nx = mirrored.shape
    m = [stats[name_of("gaussian", seed)][1] / stats["map"][1] for seed in d.seeds]
    w = [stats[name_of(kind, seed)][2] / stats["map"][2] for kind in ("gaussian", "heights") for seed in d.seeds]
    out.table("findings", ["what", "measured"], [
        ["the surfaces solved (the mirrored map's period)",
         f"{nx} x {ny} samples, {nx * dx * 1e6:.0f} x {ny * dy * 1e6:.0f} um"],
        ["the map's heights' skewness (less their plane)", f"{stats['map'][3]:.2f}"],
        ["the random-phase surrogates' m over the map's", pages.span(m, 3)],
        ["the surrogates' W over the map's", pages.span(w, 3)]])
    out.figure("mapSurrogates", figure(s, rows))
    return out
