# SPDX-License-Identifier: GPL-3.0-or-later
"""The engineering range's tables and figures (docs/validation/engineeringRange.md includes them),
made from engineeringRange.Results."""
import math

from .. import laws, materials, pages
from .engineeringRange import BAND, COMPLETE, DOMAIN_TOLERANCE, geometric_mean, seeds_of

STUDY = "engineeringRange"


def label_of(key, default):
    label = next(l for k, l in laws.LAWS if k == key)
    return label + " (the default)" if key == default else label


def mpa(ctx, x, surface, pair_key):
    _, _, a, b = materials.pair_of(pair_key)
    return x * materials.Pair(ctx, a, b, True).Eprime * surface.gradient / 1e6


def mpa_text(p):
    return f"{p:.2g}" if p < 10 else f"{p:.0f}"


def seeds_text(seeds):
    """How many realizations a domain has: 8, or 8 elastic and 2 capped."""
    if not isinstance(seeds, dict):
        return f"{len(seeds)}"
    return ", ".join(f"{len(v)} {k}" for k, v in seeds.items() if k is not None) + f" and {len(seeds[None])} capped"


def pairs_table(ctx, out):
    rows = []
    for _, label, a, b in materials.PAIRS:
        p = materials.Pair(ctx, a, b, True)
        rows.append([label, f"{p.Eprime / 1e9:.1f}", f"{p.hardness / 1e6:.0f}", f"{p.hardness / (p.Eprime * 0.1):.3f}"])
    out.table("pairs", ["pair", "E' [GPa]", "H [MPa]", "H/(E' h') at h' = 0.1"], rows)


def surfaces_table(R, out):
    d = R.design
    rows = []
    for s in R.surfaces:
        doms = "; ".join(f"{seeds_text(seeds)} periods of {k}L on {k * d.N}^2 up to x = {top:g}"
                         for k, seeds, top in d.domains)
        how = (f"{len(d.seeds)} periods L on {d.N}^2 (seeds {d.seeds[0]}-{d.seeds[-1]}; 1-{d.checked} also on "
               f"{d.fine}^2); {doms}" if s.synthesized else "the map mirrored; its four quadrants mirrored; the map as a patch")
        rows.append([s.name, s.label, f"{s.gradient:.3g}", how])
    out.table("surfaces", ["surface", "what", "h'", "the exact answer"], rows)


def light_loads(R, out):
    """Each period over the reference 8L at the loads where it is 8L; what they say; the true
    periods beside a smaller reference."""
    d = R.design
    synthesized = [s for s in R.surfaces if s.synthesized]
    if d.quick:
        return
    ks = [k for k, _, _ in d.domains]
    rows, table = [], []
    for s in synthesized:
        for regime, _, _ in materials.REGIMES:
            ex = R.exact[(s.name, regime)]
            curves = {1: [R.data.curve({"surface": s.name, "regime": regime, "period": 1, "grid": d.N, "seed": n})
                          for n in d.seeds]}
            for k, seeds, _ in d.domains:
                curves[k] = [R.data.curve({"surface": s.name, "regime": regime, "period": k, "grid": k * d.N,
                                           "seed": n}) for n in seeds_of(seeds, regime)]
            for x in sorted(ex):
                if ex[x]["reference"] != "8L":
                    continue
                h = {}
                for k, cs in curves.items():
                    hs = [h_at(c, x * s.gradient) for c in cs]
                    if all(v is not None for v in hs):
                        h[k] = hs
                ref = geometric_mean(h[8])
                row = {"surface": s.name, "regime": regime, "x": x, "spread": max(h[8]) / min(h[8]), "h8": ref,
                       "law": R.ratios[(s.name, regime)][x][R.default],
                       **{k: geometric_mean(h[k]) / ref for k in h if k != 8}}
                rows.append(row)
                table.append([s.name, regime, f"{x:.2g}"] + [pages.fmt(row.get(k)) for k in [1] + ks[:-1]]
                             + [f"{row['spread']:.2f}", pages.fmt(row["law"])])
    out.table("lightLoads", ["surface", "regime", "x"] + [f"{k if k > 1 else ''}L / 8L" for k in [1] + ks[:-1]]
              + ["spread of 8L", "the default law / 8L"], table)

    def at(x):
        return [r for r in rows if abs(r["x"] / x - 1) < 1e-6]
    low, top = at(1e-4), at(1e-3)
    pairs = [(a, b) for a in low for b in top if (a["surface"], a["regime"]) == (b["surface"], b["regime"])]

    def growth(a, b, k):  # from x = 1e-4 to 1e-3, of period k (8: 8L), as a power of x
        return math.log10(b.get(k, 1.0) * b["h8"] / (a.get(k, 1.0) * a["h8"])) / math.log10(b["x"] / a["x"])
    apart = sorted({r["surface"] for r in low if abs(1 / r[4] - 1) > DOMAIN_TOLERANCE},
                   key=[s.name for s in synthesized].index)
    widest = max(rows, key=lambda r: r["spread"])
    g8 = [growth(a, b, 8) for a, b in pairs]
    g1 = [growth(a, b, 1) for a, b in pairs]
    findings = [
        ["one period L over 8L, x = 1e-4", pages.span([r[1] for r in low])],
        ["one period L over 8L, x = 1e-3", pages.span([r[1] for r in top])],
        ["8L over 4L, x = 1e-4", pages.span([1 / r[4] for r in low])],
        [f"8L over 4L, x = 1e-4: not within {100 * DOMAIN_TOLERANCE:.0f} % on", ", ".join(apart) or "none"],
        ["8L over 4L, x = 1e-3", pages.span([1 / r[4] for r in top])],
        ["the widest spread of 8L's realizations (max/min)",
         f"{widest['spread']:.2f} ({widest['surface']}, {widest['regime']}, x = {widest['x']:.2g})"],
        ["8L's growth from x = 1e-4 to 1e-3", f"x^{min(g8):.2f} to x^{max(g8):.2f}"],
        ["one period L's growth from x = 1e-4 to 1e-3", f"x^{min(g1):.2f} to x^{max(g1):.2f}"],
        ["the default law over 8L, x = 1e-4", pages.span([r["law"] for r in low])],
        ["the default law over 8L, x = 1e-3", pages.span([r["law"] for r in top])],
    ]
    for k, seeds, regimes, xs, variant in d.periods:
        beside = []
        for s in synthesized:
            for regime in regimes:
                cs = [R.data.curve({"surface": s.name, "regime": regime, "period": k, "grid": k * d.N, "seed": n,
                                    "variant": variant}) for n in seeds]
                ex = R.exact[(s.name, regime)]
                for x in xs:
                    hs = [h_at(c, x * s.gradient) for c in cs]
                    if x in ex and all(v is not None for v in hs):
                        beside.append((geometric_mean(hs) / ex[x]["h"], ex[x]["reference"]))
        findings.append([f"{len(seeds)} periods of {k}L, {', '.join(regimes)}, x = {min(xs):.2g}-{max(xs):.2g}, over "
                         f"the reference there ({', '.join(sorted({r for _, r in beside}))})",
                         pages.span([v for v, _ in beside])])
    out.table("lightLoadFindings", ["what", "measured"], findings)


def h_at(curve, pe):
    from ..solves import at
    from ..tables import number
    row = at(curve, pe)
    return number(row["h_per_k_per_m"]) if row is not None and number(row["h_per_k_per_m"]) > 0 else None


def convergence(R, out):
    """The checks of the reference, in numbers."""
    d = R.design
    synthesized = {s.name for s in R.surfaces if s.synthesized}
    everything = [(sn, rn, x, e) for (sn, rn), t in R.exact.items() for x, e in t.items()]
    grids = [e["grid"] for sn, _, _, e in everything if e["grid"] and sn in synthesized]
    map_grids = [e["grid"] for sn, _, _, e in everything if e["grid"] and sn not in synthesized]
    bad = sorted((sn, rn, x) for sn, rn, x, e in everything if e["grid"] and abs(e["grid"] - 1) > 0.10)
    rows = []
    if grids:
        rows.append([f"grid: {d.fine}^2 over {d.N}^2, the same synthesized surfaces", pages.span(grids, 3),
                     "; ".join(f"{sn} {rn} x = {x:.2g}" for sn, rn, x in bad if sn in synthesized) or "none"])
    if map_grids:
        rows.append(["grid: the mirrored map's Fourier series on a grid twice as fine over the map",
                     pages.span(map_grids, 3), "; ".join(f"{rn} x = {x:.2g}" for sn, rn, x in bad
                                                         if sn not in synthesized) or "none"])
    undone = {}
    for sn, rn, x, e in everything:
        if e["domain"] and abs(e["domain"] - 1) > DOMAIN_TOLERANCE:
            undone.setdefault(sn, []).append((x, e["domain"]))
    domains = [e["domain"] for _, _, _, e in everything if e["domain"]]
    rows.append([f"domain: the reference over the next smaller period (the map: over its quadrants)",
                 pages.span(domains), "; ".join(f"{sn} at x = " + ", ".join(f"{x:.2g}" for x in sorted({x for x, _ in v}))
                                                + f" ({pages.span([dd for _, dd in v])})" for sn, v in undone.items())
                 or "none"])
    ses = [e["se"] for _, _, _, e in everything if e["se"]]
    if ses:
        rows.append(["sample: the standard error of the geometric mean over the realizations (a factor)",
                     pages.span(ses), "-"])
    edges = [e["edges"] for _, _, _, e in everything if e.get("edges")]
    if edges:
        off = [v for v in edges if abs(v - 1) > DOMAIN_TOLERANCE]
        rows.append(["edges: the map as a patch over mirrored", pages.span(edges),
                     f"{len(off)} of {len(edges)} points ({pages.span(off)})" if off else "none"])
    out.table("convergence", ["check", "range", f"not within {100 * DOMAIN_TOLERANCE:.0f} %"], rows)


def decision(ctx, R, out):
    """Per pair and pressure decade: the laws by their worst miss over every surface solved in
    that decade (capped reference), the closest two, and the default's band."""
    rows = []
    for key, label, _, _ in materials.PAIRS:
        for lo, hi in [(0.1, 1), (1, 10), (10, 100), (100, 1000)]:
            points = [(s.name, row) for s in R.surfaces for x, row in R.ratios[(s.name, key)].items()
                      if lo <= mpa(ctx, x, s, key) < hi]
            if not points:
                continue
            ranked = []
            for lk, _ in laws.LAWS:
                vals = [row[lk] for _, row in points]
                if all(math.isfinite(v) for v in vals):
                    ranked.append((max(abs(math.log(v)) for v in vals), lk, min(vals), max(vals)))
            ranked.sort()
            cells = [f"`{r[1]}`: {r[2]:.2f}-{r[3]:.2f}" for r in ranked[:2]] + ["-", "-"]
            default = [row[R.default] for _, row in points if math.isfinite(row[R.default])]
            rows.append([label, f"{lo:g}-{hi:g}", ", ".join(sorted({p[0] for p in points})), cells[0], cells[1],
                         f"`{R.default}`: {min(default):.2f}-{max(default):.2f}" if default else "-"])
    out.table("decision", ["pair", "p [MPa]", "surfaces", "closest law: band (min-max of law/exact)",
                           "next closest", "the default"], rows)


def bands(R, out):
    """Each law's band, min-max of law/exact over every surface and load, and its share within 25 %."""
    names = [s.name for s in R.surfaces]
    synth = [s.name for s in R.surfaces if s.synthesized]
    capped = [p[0] for p in materials.PAIRS]

    def band(key, regimes, surface_names):
        values = [row[key] for (sn, rn), t in R.ratios.items() if sn in surface_names and rn in regimes
                  for row in t.values() if math.isfinite(row[key])]
        if not values:
            return "-"
        within = sum(1 for v in values if abs(v - 1) <= BAND) / len(values)
        return f"{min(values):.2f}-{max(values):.2f} ({100 * within:.0f} %)"
    rows = [[label_of(key, R.default)] + [band(key, regs, nm) for regs, nm in
                                          ((["elastic"], names), (capped, names), (capped, synth), (capped, ["x3p"]))]
            for key, _ in laws.LAWS]
    out.table("bands", ["law", "elastic", f"capped ({len(capped)} pairs)", "capped, synthesized surfaces",
                        "capped, X3P map"], rows)


def surface_tables(ctx, R, s, out):
    d = R.design
    text = []
    for regime, label, pair_key in materials.REGIMES:
        ex = R.exact[(s.name, regime)]
        ratio = R.ratios[(s.name, regime)]
        xs = sorted(ratio)
        if not xs:
            continue
        pair = materials.regime_pair(ctx, regime)
        c = f", H/(E' h') = {pair.hardness / (pair.Eprime * s.gradient):.3g}" if pair.hardness else ""
        rows = []
        for key in ([p[0] for p in materials.PAIRS] if pair_key is None else [pair_key]):
            rows.append([f"p [MPa], {materials.pair_of(key)[1]}"] + [mpa_text(mpa(ctx, x, s, key)) for x in xs])
        rows.append(["exact h_c/k_s [1/m]"] + [f"{ex[x]['h']:.4g}" for x in xs])
        rows.append(["exact A_r/A_n"] + [f"{ex[x]['area']:.3g}" for x in xs])
        if s.synthesized:
            rows.append(["+- (standard error over the reference's realizations)"] + [pages.fmt(ex[x]["se"]) for x in xs])
            rows.append([f"grid: {d.fine}^2 / {d.N}^2, same surfaces"] + [pages.fmt(ex[x]["grid"]) for x in xs])
        rows.append(["reference: the domain (realizations)"] + [f"{ex[x]['reference']} ({ex[x]['n']})" for x in xs])
        rows.append(["domain: the two largest"] + [pages.fmt(ex[x]["domain"]) for x in xs])
        if not s.synthesized and not d.quick:
            rows.append(["grid: the mirrored map's Fourier series on a grid twice as fine / the map"]
                        + [pages.fmt(ex[x]["grid"]) for x in xs])
        if not s.synthesized:
            rows.append(["edges: the map as a patch / mirrored"] + [pages.fmt(ex[x]["edges"]) for x in xs])
        for key, _ in laws.LAWS:
            rows.append([label_of(key, R.default)] + [pages.fmt(ratio[x][key]) for x in xs])
        text.append(f"#### {s.name}, {label}{c}\n\n" + pages.markdown_table([""] + [f"{x:.2g}" for x in xs], rows))
    out.text(f"surface-{s.name}.md", "\n".join(text))


def figure(R, regime, label):
    def draw(path):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, len(R.surfaces), figsize=(3.2 * len(R.surfaces), 3.4), sharey=True)
        for ax, s in zip(axes, R.surfaces):
            table = R.ratios[(s.name, regime)]
            xs = sorted(table)
            for key, _ in laws.LAWS:
                ax.plot(xs, [table[x][key] for x in xs], marker="o", ms=3,
                        label=key + (" (default)" if key == R.default else ""))
            ax.axhspan(1 - BAND, 1 + BAND, color="0.9")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_ylim(0.05, 20)
            ax.set_title(s.name, fontsize=9)
            ax.set_xlabel("p/(E' h')")
        axes[0].set_ylabel("law / exact h_c")
        axes[-1].legend(fontsize=6, loc="upper right")
        fig.suptitle(label, fontsize=10)
        fig.tight_layout()
        fig.savefig(path, dpi=90)
        plt.close(fig)
    return draw


def outputs(ctx, R):
    out = pages.Outputs(ctx, STUDY)
    out.text("summary.csv", R.summary().text())
    pairs_table(ctx, out)
    surfaces_table(R, out)
    light_loads(R, out)
    convergence(R, out)
    decision(ctx, R, out)
    bands(R, out)
    for s in R.surfaces:
        surface_tables(ctx, R, s, out)
    for regime, label, _ in materials.REGIMES:
        out.figure(regime, figure(R, regime, label))
    out.text("parameters.md", pages.markdown_table(["what", "value"], [
        ["loads x = p/(E' h')", ", ".join(f"{x:.2g}" for x in R.design.loads)],
        ["no ratio where the exact A_r/A_n exceeds", f"{COMPLETE}"],
        ["a law within", f"{100 * BAND:.0f} %"]]))
    return out
