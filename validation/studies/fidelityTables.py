# SPDX-License-Identifier: GPL-3.0-or-later
"""The fidelity study's tables, summary and figures (validation/studies/fidelity.py measures)."""
import math

from .. import materials, pages, solves
from ..tables import Table, number
from .fidelity import BAND, COMPLETE, REGIMES, SMOOTH, STUDY, TABLE_LOADS, TAG, slug, steel

# docs/models.md's summary ("How right each model is"): (row, area (label, regime) or None or a
# text, h_c (label, regime) or None, a second h_c (label, regime) after "capped" or None), at
# TABLE_LOADS on SUMMARY_SURFACES.
SUMMARY_SURFACES = ["selfAffine08", "selfAffine03", "x3p"]
SUMMARY_ROWS = [
    ("`hertz` + `jacksonBhavnaniFerguson` (elastic)", ("MS-Hertz", "elastic"),
     ("jacksonBhavnaniFerguson on MS-Hertz", "elastic"), None),
    ("`hertz` + `multiscaleBarber` (elastic)", "as `hertz`", ("multiscaleBarber on MS-Hertz", "elastic"), None),
    ("`persson` (elastic)", ("Persson", "elastic"), ("persson", "elastic"), None),
    ("`mikic` (elastic correlation)", None, ("mikic", "elastic"), None),
    ("`greenwoodWilliamson` (elastic)", ("GW", "elastic"), None, None),
    ("`jacksonGreen` + `jacksonBhavnaniFerguson` (the boundary condition's former default)", ("MS-JG", "steelSteel"),
     ("jacksonBhavnaniFerguson on MS-JG", "steelSteel"), None),
    ("`truncation` + `jacksonBhavnaniFerguson`", ("MS-truncation", "steelSteel"),
     ("jacksonBhavnaniFerguson on MS-truncation", "steelSteel"), None),
    ("`jacksonGreen` + `multiscaleBarber`", None, ("multiscaleBarber on MS-JG", "steelSteel"), None),
    ("`cooperMikicYovanovich`, H_c = 2.84 S_y (plastic correlation)", None,
     ("cooperMikicYovanovich (H_c = 2.84 S_y)", "steelSteel"), None),
    ("`fittedElastoPlastic`, the default (elastic; capped at H = 2.84 S_y)", None, ("fittedElastoPlastic", "elastic"),
     ("fittedElastoPlastic (H = 2.84 S_y)", "steelSteel")),
]


def noun(what, regime):
    return ("A_r/A_n" if what == "area" else "h_c/k_s") + ("" if regime == "elastic" else ", capped")


def summary_number(v):
    """Two significant figures, as a reader compares ratios: 0.76, 1.1, 14."""
    return f"{v:.2f}" if v < 1 else f"{v:.1f}" if v < 10 else f"{v:.0f}"


def complete_from(R, s, regime):
    """The lightest load p/E' where a reference curve's exact A_r/A_n exceeds COMPLETE, or None."""
    loads = [p for p in R.loads[(s.name, regime)] for c in R.reference[(s.name, regime)].values()
             if solves.at(c, p) is not None and number(solves.at(c, p)["area_fraction"]) > COMPLETE]
    return min(loads) if loads else None


def materials_table(ctx, out):
    a = materials.STEEL
    pair = steel(ctx, True)
    out.table("materials", ["what", "value"], [
        ["solids", f"steel on steel: E = {a[0] / 1e9:g} GPa, nu = {a[1]:g}, S_y = {a[2] / 1e9:g} GPa"],
        ["E' (the core's)", f"{pair.Eprime / 1e9:.1f} GPa"],
        ["H = 2.84 S_y (the core's), the capped reference's cap", f"{pair.hardness / 1e9:.2f} GPa"],
        ["ratios where the exact A_r/A_n is at most", f"{COMPLETE:g}"],
        ["a model trusted within", f"{100 * BAND:.0f} % (model/exact {1 - BAND:g} to {1 + BAND:g})"]])


def surfaces_table(R, out):
    rows = []
    for s in R.surfaces:
        loads = R.loads[(s.name, "elastic")]
        scale = f"scaled by h'/0.1 = {s.gradient / 0.1:.3g}" if s.gradient < SMOOTH else "not scaled"
        complete = complete_from(R, s, "elastic")
        rows.append([s.name, s.label, f"{s.gradient:.3g}", f"{loads[0]:.3g}-{loads[-1]:.3g} ({scale})",
                     f"{complete:.3g}" if complete else "-"])
    out.table("surfaces", ["surface", "what", "h'", "loads p/E' (elastic)",
                           f"elastic: the exact A_r/A_n above {COMPLETE:g} from p/E'"], rows)


def reference_findings(R, out):
    """How far apart the two grids' self-affine references are (min/max of A_r/A_n and h)."""
    rows = []
    pairs = [(s, regime) for s in R.surfaces for regime in REGIMES if s.ratio_tags]
    for p in TABLE_LOADS:
        h, area = [], []
        for s, regime in pairs:
            rs = [solves.at(c, p) for c in R.reference[(s.name, regime)].values()]
            if all(rs):
                hs = [number(r["h_per_k_per_m"]) for r in rs]
                a = [number(r["area_fraction"]) for r in rs]
                h.append(min(hs) / max(hs))
                area.append(min(a) / max(a))
        rows.append([f"{p:g}", pages.span(area, 3), pages.span(h, 3)])
    out.table("references", ["p/E'", "A_r/A_n: smaller / larger of the two grids' references",
                             "h_c/k_s: smaller / larger"], rows)


def trust(R, out):
    """Where each model stays within BAND on every surface, and its ratio over p/E' = 1e-4 to 1e-2."""
    rows = []
    for (what, label, regime), per_surface in R.ratios.items():
        loads = sorted({p for per in per_surface.values() for p in per})
        good = [p for p in loads if all(p in per and 1 - BAND <= per[p][0] <= 1 + BAND for per in per_surface.values())]
        band = [per[p][0] for per in per_surface.values() for p in per if 1e-4 * 0.99 <= p <= 1e-2 * 1.01]
        runs = []
        for p in good:  # runs of consecutive loads as ranges
            if runs and loads.index(p) == loads.index(runs[-1][-1]) + 1:
                runs[-1].append(p)
            else:
                runs.append([p])
        where = ", ".join(f"{r[0]:.2g}" if len(r) == 1 else f"{r[0]:.2g} to {r[-1]:.2g}" for r in runs) or "none"
        worst = max(band, key=lambda r: abs(math.log(r))) if band else float("nan")
        rows.append([label, noun(what, regime), where, f"{min(band):.2f}-{max(band):.2f}" if band else "-",
                     pages.fmt(worst)])
    out.table("trust", ["model or law", "quantity", f"within {100 * BAND:.0f} % on every surface at p/E'",
                        "ratio over p/E' = 1e-4 to 1e-2", "worst there"], rows)


def surface_table(R, s, out):
    rows = []
    for (what, label, regime), per_surface in R.ratios.items():
        series = per_surface.get(s.name, {})
        reference = R.reference[(s.name, regime)]
        several = len(s.ratio_tags or reference) > 1
        cells = []
        for p in TABLE_LOADS:
            if p in series:
                g, lo, hi = series[p]
                cells.append(f"{g:.2f}" + (f" ({lo:.2f}-{hi:.2f})" if several else ""))
            elif any(solves.at(c, p) is not None and number(solves.at(c, p)["area_fraction"]) > COMPLETE
                     for c in reference.values()):
                cells.append("complete")
            else:
                cells.append("-")
        rows.append([label, noun(what, regime)] + cells)
    for regime in REGIMES:
        reference = R.reference[(s.name, regime)]
        if len(reference) < 2:
            continue
        cells = []
        for p in TABLE_LOADS:
            found = [solves.at(c, p) for c in reference.values()]
            a = [number(r["area_fraction"]) for r in found if r]
            h = [number(r["h_per_k_per_m"]) for r in found if r]
            cells.append(f"area {min(a) / max(a):.3f}, h {min(h) / max(h):.3f}" if a else "-")
        rows.append([f"the reference, {TAG[regime]} ({', '.join(reference)})", "min/max"] + cells)
    out.table(f"surface-{s.name}", ["model or law", "quantity"] + [f"p/E' = {p:g}" for p in TABLE_LOADS], rows)


def models_summary(R, out):
    """docs/models.md's table: model / exact at TABLE_LOADS on SUMMARY_SURFACES ('-' where the
    reference is in complete contact or the model infinite), and each row's span over them."""
    names = [n for n in SUMMARY_SURFACES if any(s.name == n for s in R.surfaces)]

    def cells(what, key):
        label, regime = key
        per = R.ratios[(what, label, regime)]
        groups, values = [], []
        for name in names:
            series = per[name]
            groups.append(" ".join(summary_number(series[p][0]) if p in series else "-" for p in TABLE_LOADS))
            values += [series[p][0] for p in TABLE_LOADS if p in series]
        return " \\| ".join(groups), values

    def span(values):
        return f"{summary_number(min(values))}-{summary_number(max(values))}"
    rows = []
    for row, area, h, capped in SUMMARY_ROWS:
        area_cell = (area if isinstance(area, str) else cells("area", area)[0]) if area else ""
        h_cell, spans = "", ""
        if h:
            h_cell, values = cells("h", h)
            spans = span(values)
            if capped:
                capped_cell, capped_values = cells("h", capped)
                h_cell += "; capped " + capped_cell
                spans += "; capped " + span(capped_values)
        rows.append([row, area_cell, h_cell, spans])
    out.text("models.md", f"Model / exact at p/E' = {', '.join(f'{p:g}' for p in TABLE_LOADS)} "
                          f"({' | '.join(names)}; - : complete contact, h infinite):\n\n" +
             pages.markdown_table(["model or law", "A_r/A_n", "h_c/k_s", "span of h_c/k_s"], rows))


def summary(R):
    """One row per surface, model or law and load: the ratio model/exact (the geometric mean over
    the reference's curves), its min and max; tag: the old report's name of the curve."""
    rows = []
    for (what, label, regime), per_surface in R.ratios.items():
        for surface, series in per_surface.items():
            for p in sorted(series):
                g, lo, hi = series[p]
                rows.append({"surface": surface, "quantity": "area_fraction" if what == "area" else "h_per_k",
                             "model": label, "regime": regime, "tag": f"{TAG[regime]}-{slug(label)}",
                             "load": f"{p:.6g}", "ratio": f"{g:.6g}", "min": f"{lo:.6g}", "max": f"{hi:.6g}"})
    return Table(list(rows[0].keys()), rows)


def figure(R, s):
    def draw(path):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(2, 2, figsize=(12, 9))
        panels = [("area", "elastic", "A_r/A_n, elastic"), ("h", "elastic", "h_c/k_s, elastic"),
                  ("area", "steelSteel", "A_r/A_n, elasto-plastic (H = 2.84 S_y)"),
                  ("h", "steelSteel", "h_c/k_s, elasto-plastic (H = 2.84 S_y)")]
        for ax, (what, regime, title) in zip(axes.flat, panels):
            for (w, label, reg), per_surface in R.ratios.items():
                if w == what and reg == regime and s.name in per_surface:
                    series = per_surface[s.name]
                    ps = sorted(series)
                    ax.plot(ps, [series[p][0] for p in ps], marker="o", ms=3, label=label)
            ax.axhspan(1 - BAND, 1 + BAND, color="0.9")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlim(8e-6 * (s.gradient / 0.1 if s.gradient < SMOOTH else 1), 0.6)
            ax.set_ylim(0.1, 10)
            ax.grid(True, which="major", color="0.85")
            ax.set_title(title, fontsize=10)
            ax.set_xlabel("p/E'")
            ax.set_ylabel("model / exact")
            ax.legend(fontsize=7, loc="upper left")
        fig.suptitle(f"{s.name}: model / exact (boundary elements)")
        fig.tight_layout()
        fig.savefig(path, dpi=80)
        plt.close(fig)
    return draw


def outputs(ctx, R):
    out = pages.Outputs(ctx, STUDY)
    materials_table(ctx, out)
    surfaces_table(R, out)
    reference_findings(R, out)
    trust(R, out)
    for s in R.surfaces:
        surface_table(R, s, out)
        out.figure(s.name, figure(R, s))
    models_summary(R, out)
    out.text("summary.csv", summary(R).text())
    return out
