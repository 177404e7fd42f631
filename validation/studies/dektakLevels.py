# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the levels run out: the Dektak profile's surfaces with a quarter, a half and all of 256 levels, the same long waves, elastic.

A grid of N points holds N/8 of a spectrum's levels. The same synthesized surfaces (two seeds)
are made with the finest levels on 2048^2 (--synthesize) and without their finer wavelengths on
coarser grids (--resample M,K), so only the levels change; steel on steel, elastic, at 0.1, 1
and 10 MPa. docs/validation/engineeringRange.md reads the table.
"""
from .. import materials, pages, solves, spectra
from ..tables import Table, number
from .engineeringRange import DEKTAK, geometric_mean

DATA = ["dektakLevels.csv"]
KEYS = ["surface", "regime", "levels", "grid", "seed"]
PRESSURES = [0.1e6, 1e6, 10e6]  # [Pa]


def design(ctx):
    top = 256 if ctx.quick else 2048  # the finest grid: top/8 levels
    kmax = top // 8
    return top, [kmax // 4, kmax // 2, kmax], [1, 2]


def solve(ctx):
    top, counts, seeds = design(ctx)
    pair = materials.regime_pair(ctx, "elastic")
    spec = spectra.profile_spectrum(ctx, ctx.scratch_path("dektakLevels", f"dektak-{counts[-1]}.spectrum"), DEKTAK,
                                    counts[-1])
    jobs = [solves.Solve({"surface": "dektak", "regime": "elastic", "levels": k, "grid": 8 * k, "seed": s},
                         ["--spectrum", spec, "--synthesize", f"{top},{s}", "--resample", f"{8 * k},{k}",
                          "--model", "boundaryElement"] + pair.arguments, [p / pair.Eprime for p in PRESSURES])
            for s in seeds for k in counts]
    solves.Store(ctx, "dektakLevels", KEYS).solve(jobs)


def outputs(ctx):
    top, counts, seeds = design(ctx)
    data = solves.Store(ctx, "dektakLevels", KEYS)
    Ep = materials.regime_pair(ctx, "elastic").Eprime
    rows, summary = [], []
    for k in counts:
        gradient = spectra.gradient(ctx, spectra.profile_spectrum(
            ctx, ctx.scratch_path("dektakLevels", f"dektak-{k}.spectrum"), DEKTAK, k))
        cells = []
        for p in PRESSURES:
            found = [solves.at(data.curve({"surface": "dektak", "regime": "elastic", "levels": k, "grid": 8 * k,
                                           "seed": s}), p / Ep) for s in seeds]
            h = geometric_mean([number(r["h_per_k_per_m"]) for r in found])
            area = sum(number(r["area_fraction"]) for r in found) / len(found)
            cells.append(f"{h:.4g} ({area:.2g})")
            summary.append({"levels": k, "grid": 8 * k, "gradient": f"{gradient:.6g}", "pressure_MPa": f"{p / 1e6:g}",
                            "h_per_k_per_m": f"{h:.6g}", "area_fraction": f"{area:.6g}", "seeds": len(seeds)})
        rows.append([k, f"{8 * k}^2", f"{gradient:.3g}"] + cells)
    out = pages.Outputs(ctx, "dektakLevels")
    out.table("levels", ["levels", "grid", "h'"] + [f"{p / 1e6:g} MPa" for p in PRESSURES], rows)
    first = {r["pressure_MPa"]: number(r["h_per_k_per_m"]) for r in summary if r["levels"] == counts[0]}
    last = {r["pressure_MPa"]: number(r["h_per_k_per_m"]) for r in summary if r["levels"] == counts[-1]}
    out.table("change", ["pressure", f"h_c with {counts[-1]} levels over h_c with {counts[0]}"],
              [[f"{p} MPa", f"{last[p] / first[p]:.2f}"] for p in first])
    out.text("summary.csv", Table(list(summary[0].keys()), summary).text())
    return out
