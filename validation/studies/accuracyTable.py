# SPDX-License-Identifier: GPL-3.0-or-later
"""The measured accuracy bands of the conductance laws the core states (the regime line, the check): the studies' ratios by decade of p/(E' h').

For each law on its area model and reference (elastic, or capped at H = 2.84 S_y) and each decade
[a, 10 a) of x = p/(E' h') from 1e-5 to 1: the smallest and largest law/exact over the surfaces
with a point there, and how many surfaces. From the engineering range (its capped pairs count as
one capped reference), and for the area models it does not run the fidelity study's curves; for
the default law beyond the engineering range, elastic, the heavy-load study's ratios up to the
heaviest load it measured. `run` writes src/core/roughContact/thermal/MeasuredAccuracyTable.inc,
the bands as a page's table, and the default law's bands by regime, with its unloading branch's
from the unloading study and the measured map's (unloadingMap), as README.md's "Which h to trust"
(`trust`); `check` fails when they are not what the studies' data give.
"""
import math
import os

from .. import materials, pages
from ..tables import Table

DATA = []
TABLE = os.path.join("src", "core", "roughContact", "thermal", "MeasuredAccuracyTable.inc")
UNLOADING_TABLE = os.path.join("src", "core", "roughContact", "thermal", "MeasuredUnloadingAccuracy.inc")
DECADES = [10.0 ** k for k in range(-5, 1)]  # edges 1e-5 .. 1
# (the fidelity study's curve, law, area model, capped): its curves turned into the names users select
CURVES = [
    ("elastic-jacksonBhavnaniFerguson-on-MS-Hertz", "jacksonBhavnaniFerguson", "hertz", False),
    ("elastic-multiscaleBarber-on-MS-Hertz", "multiscaleBarber", "hertz", False),
    ("elastic-persson", "persson", "", False),
    ("elastic-mikic", "mikic", "", False),
    ("plastic-jacksonBhavnaniFerguson-on-MS-JG", "jacksonBhavnaniFerguson", "jacksonGreen", True),
    ("plastic-jacksonBhavnaniFerguson-on-MS-truncation", "jacksonBhavnaniFerguson", "truncation", True),
    ("plastic-multiscaleBarber-on-MS-JG", "multiscaleBarber", "jacksonGreen", True),
    ("plastic-multiscaleBarber-on-MS-truncation", "multiscaleBarber", "truncation", True),
    ("plastic-persson--elastic-theory", "persson", "", True),
    ("plastic-mikic--elastic-correlation", "mikic", "", True),
    ("plastic-cooperMikicYovanovich--H-c---2-84-S-y", "cooperMikicYovanovich", "", True),
    ("elastic-fittedElastoPlastic", "fittedElastoPlastic", "", False),
    ("plastic-fittedElastoPlastic--H---2-84-S-y", "fittedElastoPlastic", "", True),
]
# The engineering range's law columns: (column, law, area model when elastic, when capped).
ENGINEERING_LAWS = [
    ("ratio_jacksonBhavnaniFerguson", "jacksonBhavnaniFerguson", "hertz", "jacksonGreen"),
    ("ratio_multiscaleBarber", "multiscaleBarber", "hertz", "jacksonGreen"),
    ("ratio_persson", "persson", "", ""),
    ("ratio_mikic", "mikic", "", ""),
    ("ratio_fittedElastoPlastic", "fittedElastoPlastic", "", ""),
    ("ratio_cooperMikicYovanovich", "cooperMikicYovanovich", "", ""),
]


def engineering_bands(ctx):
    """{(law, model, capped): {decade: [lo, hi, surfaces, the largest x]}} of the engineering range."""
    from . import engineeringRange
    out = {}
    for r in engineeringRange.Results(ctx).summary().rows:
        capped = r["regime"] != "elastic"
        x = float(r["x"])
        for column, law, elastic_model, capped_model in ENGINEERING_LAWS:
            try:
                v = float(r[column])
            except ValueError:
                continue
            if not math.isfinite(v):
                continue
            for a, b in zip(DECADES, DECADES[1:]):
                # [a, b): a load on a decade's edge (x = 1e-4) opens the decade above it.
                if a * (1 - 1e-9) <= x < b * (1 - 1e-9):
                    band = out.setdefault((law, capped_model if capped else elastic_model, capped), {}).setdefault(
                        a, [math.inf, 0.0, set(), 0.0])
                    band[0], band[1], band[3] = min(band[0], v), max(band[1], v), max(band[3], x)
                    band[2].add(r["surface"])
                    break
    return out


def heavy_rows(ctx, engineering_top):
    """The default law, elastic, beyond the engineering range: the heavy-load study's ratios."""
    lo, hi, surfaces, top = math.inf, 0.0, set(), 0.0
    for r in pages.generated(ctx, "heavyLoads", "summary.csv").rows:
        x = float(r["x"])
        if x <= engineering_top:
            continue
        v = float(r["law_over_exact"])
        lo, hi, top = min(lo, v), max(hi, v), max(top, x)
        surfaces.add(r["surface"])
    if not surfaces:
        return []
    return [("fittedElastoPlastic", "", False, engineering_top, top * (1 + 1e-6), lo, hi, len(surfaces),
             "heavy-load study")]


def bands(ctx):
    from . import fidelity
    rows = []
    engineering = engineering_bands(ctx)
    for (law, model, capped), per_decade in engineering.items():
        for a in sorted(per_decade):
            lo, hi, surfaces, top = per_decade[a]
            # Up to the decade's end when its last load (three a decade: a, 2.15 a, 4.64 a) was
            # measured; else only up to the largest load measured, and beyond it nothing is claimed.
            b = a * 10 if top >= a * 10 ** (2 / 3) * (1 - 1e-6) else top * (1 + 1e-6)
            rows.append((law, model, capped, a, b, lo, hi, len(surfaces), "engineering-range study"))
    top = max(r[4] for r in rows if r[:3] == ("fittedElastoPlastic", "", False))
    rows += heavy_rows(ctx, top)
    gradients = fidelity.gradients(ctx)
    curves = fidelity.ratio_curves(ctx)
    for tag, law, model, capped in CURVES:
        if (law, model, capped) in engineering:
            continue
        per_decade = {}
        for surface, gradient in sorted(gradients.items()):
            for load, _, lo, hi in curves.get((surface, tag), []):
                x = load / gradient
                for a, b in zip(DECADES, DECADES[1:]):
                    if a <= x < b * (1 + 1e-9):
                        band = per_decade.setdefault(a, [math.inf, 0.0, set()])
                        band[0], band[1] = min(band[0], lo), max(band[1], hi)
                        band[2].add(surface)
        for a in sorted(per_decade):
            lo, hi, surfaces = per_decade[a]
            rows.append((law, model, capped, a, a * 10, lo, hi, len(surfaces), "fidelity study"))
    return rows


def solve(ctx):
    """No solves of its own: it reads what the other studies solved."""
    return 0


# The regimes of README.md's table: (words, from x, to x); x = p/(E' h').
REGIMES = [("lighter than measured", None, 1e-4), ("light load", 1e-4, 1e-3), ("moderate load", 1e-3, 1e-2),
           ("heavy load", 1e-2, 1e-1), ("a smooth surface at high pressure", 1e-1, None)]
SIGN = 0.25  # a band within 1 -+ SIGN of exact: the default law's h can be signed with it


def capped_loads(ctx):
    """P/H of the engineering range's capped points, by the decade of x they are in."""
    from . import engineeringRange
    out = {}
    pairs = {}
    for r in engineeringRange.Results(ctx).summary().rows:
        if r["regime"] == "elastic":
            continue
        pair = pairs.setdefault(r["regime"], materials.regime_pair(ctx, r["regime"]))
        x = float(r["x"])
        a = max(d for d in DECADES if d <= x * (1 + 1e-9))
        out.setdefault(a, []).append(x * pair.Eprime * float(r["gradient"]) / pair.hardness)
    return out


def short(v):
    """Two significant digits, as a reader writes them: 1e-4, 0.0052, 0.15, 11, 110, 7000."""
    if v <= 0:
        return f"{v:g}"
    e = math.floor(math.log10(v) + 1e-9)
    r = round(v, 1 - e)
    if r < 1e-3:
        return f"{r:.1e}".replace("e-0", "e-").replace(".0e", "e")
    return f"{r:g}" if r < 1e6 else f"{r:.1e}"


def trust(ctx, rows):
    """README.md's table: the default law's measured band against exact in each regime, elastic and
    capped, with P/H where capped points were measured and what to do there."""
    law = [r for r in rows if r[0] == "fittedElastoPlastic"]
    steel = materials.Pair(ctx, materials.STEEL, materials.STEEL, False).Eprime
    ph = capped_loads(ctx)
    body = []
    for words, lo, hi in REGIMES:
        inside = [r for r in law if (lo is None or r[3] >= lo * (1 - 1e-9)) and (hi is None or r[3] < hi * (1 - 1e-9))]
        elastic = [r for r in inside if not r[2]]
        capped = [r for r in inside if r[2]]
        top = max((r[4] for r in inside), default=None)
        end = (min(hi, top) if hi else top) if top else None
        x = f"below {short(hi)}" if lo is None else f"{short(lo)} to {short(end)}"
        p = (f"below {short(hi * steel * 0.1 / 1e6)}" if lo is None else
             f"{short(lo * steel * 0.1 / 1e6)}-{short(end * steel * 0.1 / 1e6)}")
        loads = [v for a, vs in ph.items() if lo is not None and a >= lo * (1 - 1e-9) and (hi is None or a < hi)
                 for v in vs]
        band = {}
        for name, rs in (("elastic", elastic), ("capped", capped)):
            band[name] = (min(r[5] for r in rs), max(r[6] for r in rs)) if rs else None
        shown = [b for b in band.values() if b]
        if not shown:
            todo = "not measured: `model boundaryElement;` (the exact model) or `check yes;`"
        elif all(1 - SIGN <= b[0] and b[1] <= 1 + SIGN for b in shown):
            todo = "use the default law; sign h with this band"
        else:
            todo = "wider than 25 %: `check yes;` on your surface, or `model boundaryElement;`"
        body.append([words, x, p, f"{short(min(loads))} to {short(max(loads))}" if loads else "-",
                     f"{band['elastic'][0]:.3g}-{band['elastic'][1]:.3g}" if band["elastic"] else "not measured",
                     f"{band['capped'][0]:.3g}-{band['capped'][1]:.3g}" if band["capped"] else "not measured", todo])
    body.append(unloading_row(ctx, steel))
    body += lay_rows(ctx)
    return pages.markdown_table(["regime", "p/(E' h')", "p [MPa], steel, h' = 0.1", "P/H", "elastic: h / exact",
                                 "yielding: h / exact", "what to do"], body)


def unloading_points(ctx):
    """The points the unloading branch is held to below the peak: the unloading study's counted
    ones and every one of the measured map's (unloadingMap): [(peak x, P/P_max, P_max/H, the
    branch's R over the exact unloading-to-loading ratio)]."""
    from .unloading import COUNTED
    rows = [r for r in pages.generated(ctx, "unloading", "summary.csv").rows
            if r["role"] in COUNTED and float(r["fraction"]) < 1]
    rows += pages.generated(ctx, "unloadingMap", "summary.csv").rows
    return [(float(r["peak_x"]), float(r["fraction"]), float(r["peak_over_H"]), float(r["branch_over_exact_ratio"]))
            for r in rows]


def unloading_bands(ctx):
    """The branch's R / exact R by decade [a, 10 a) of the peak's x, to the decade's end where the
    next decade's first peak was measured too (the branch is held at both ends), else up to the
    largest peak measured: [(from, to, the least P/P_max, lo, hi, points, outside BAND)]."""
    from ..fitting import BAND
    per = {}
    for x, f, _, v in unloading_points(ctx):
        a = max(d for d in DECADES if d <= x * (1 + 1e-9))
        per.setdefault(a, []).append((x, f, v))
    out = []
    for a in sorted(per):
        xs, fs, vs = zip(*per[a])
        b = a * 10 if any(abs(d / (a * 10) - 1) < 1e-9 for d in per) else max(xs) * (1 + 1e-6)
        out.append((a, b, min(fs), min(vs), max(vs), len(vs), sum(abs(v - 1) > BAND for v in vs)))
    return out


def unloading_row(ctx, steel):
    """The row of a joint below the heaviest load it carried: the unloading study's summary.csv,
    the branch's ratio R over the exact unloading-to-loading ratio at its counted points (below
    the peak), on top of the loading rows' band at the pressure of the moment."""
    from ..fitting import BAND
    x, fractions, over, ratio = zip(*unloading_points(ctx))
    outside = sum(abs(v - 1) > BAND for v in ratio)
    held = (f"within {100 * BAND:.0f} % at all {len(ratio)} points" if not outside else
            f"outside {100 * BAND:.0f} % at {outside} of {len(ratio)} points")
    if outside:
        todo = (f"wider than {100 * BAND:.0f} % (R {held}): `--check --unload-from PMAX` on your surface, or "
                "`model boundaryElement;`")
    else:
        todo = (f"sign h with the loading row's band at P times R's (R {held}); other peaks or P/P_max: "
                "`model boundaryElement;`")
    return [f"unloaded below its heaviest load P_max (P/P_max {short(min(fractions))} to {short(max(fractions))})",
            f"peaks {short(min(x))} to {short(max(x))}",
            f"peaks {short(min(x) * steel * 0.1 / 1e6)}-{short(max(x) * steel * 0.1 / 1e6)}",
            f"peaks {short(min(over))} to {short(max(over))}",
            "no memory: the rows above",
            f"R / exact R {min(ratio):.3f}-{max(ratio):.3f}", todo]


def lay_rows(ctx):
    """The table's last rows: a finish with a lay given as one profile across it, one along it, or
    the two (alongLay), from the anisotropy study's inputs.csv: its h over the map's h on the same
    surface and load (the map's own accuracy is the rows above)."""
    from .anisotropy import LAY_INPUTS, over_map
    rows = Table.read(os.path.join(ctx.generated, "anisotropy", "inputs.csv")).rows
    lay = max(int(r["stretch"]) for r in rows)
    xs = [float(r["x"]) for r in Table.read(os.path.join(ctx.generated, "anisotropy", "summary.csv")).rows]
    what = {"across": ("one profile across it", "give a profile along the lay too (`alongLay`) or an areal map"),
            "along": ("one profile along it", "not alone: it is `alongLay` beside a profile across"),
            "profiles": ("a profile across and one along (`alongLay`)",
                         "the lay is accounted for; the rest is two profiles' chance: an areal map narrows it")}
    out = []
    for way in LAY_INPUTS:
        words, todo = what[way]
        spans = [over_map(rows, way, capped) for capped in (False, True)]
        out.append([f"a finish with a lay (1:1 to {lay}:1), {words}", f"{min(xs):.2g} to {max(xs):.2g}", "-", "-"]
                   + [f"{a:.2f}-{b:.2f} x the map's h" for a, b in spans] + [todo])
    return out


def decade(a, b):
    """A band's range of x as the page shows it: "1e-04 to 0.001", or "0.1 only" where the
    decade was measured at its first load alone."""
    return f"{a:.3g} only" if b <= a * (1 + 1e-5) else f"{a:.0e} to {b:.3g}"


def outputs(ctx):
    rows = bands(ctx)
    lines = ["// SPDX-License-Identifier: GPL-3.0-or-later",
             "// Written by `python3 -m validation run accuracyTable` (validation/studies/accuracyTable.py) from",
             "// the studies' committed data: do not edit. `python3 -m validation check accuracyTable` fails when",
             "// it is not what they give. One AccuracyRow a line (MeasuredAccuracyTable.hpp)."]
    for law, model, capped, a, b, lo, hi, n, report in rows:
        start = f"{a:.0e}" if float(f"{a:.0e}") == a else f"{a:.7g}"
        lines.append(f'{{"{law}", "{model}", {"true" if capped else "false"}, {start}, {b:.7g}, '
                     f'{lo:.3g}, {hi:.3g}, {n}, "{report}"}},')
    out = pages.Outputs(ctx, "accuracyTable")
    out.source(TABLE, "\n".join(lines) + "\n")
    unloading = ["// SPDX-License-Identifier: GPL-3.0-or-later",
                 "// Written by `python3 -m validation run accuracyTable` (validation/studies/accuracyTable.py) from",
                 "// the unloading and unloadingMap studies' summary.csv: do not edit. `python3 -m validation check",
                 "// accuracyTable` fails when it is not what they give. One UnloadingAccuracyRow a line",
                 "// (MeasuredAccuracyTable.hpp)."]
    for a, b, least, lo, hi, n, outside in unloading_bands(ctx):
        start = f"{a:.0e}" if float(f"{a:.0e}") == a else f"{a:.7g}"
        unloading.append(f"{{{start}, {b:.7g}, {least:.4g}, {lo:.3g}, {hi:.3g}, {n}, {outside}}},")
    out.source(UNLOADING_TABLE, "\n".join(unloading) + "\n")
    out.table("bands", ["law", "area model", "reference", "p/(E' h')", "law / exact", "surfaces", "measured by"],
              [[law, model or "-", "capped" if capped else "elastic", decade(a, b), f"{lo:.3g}-{hi:.3g}", n,
                report] for law, model, capped, a, b, lo, hi, n, report in rows])
    out.block("README.md", "trust", trust(ctx, rows))
    return out
