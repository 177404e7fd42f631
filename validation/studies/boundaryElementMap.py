# SPDX-License-Identifier: GPL-3.0-or-later
"""The measured X3P map on a steel flat at F/(A_n E') = 1e-3, solved exactly: its contact pressure as a picture, its load point.

The boundary-element model on data/x3p-2.x3p (650^2, non-periodic, the plane removed) against
steel, elastic; the load point (A_r/A_n, mean separation, h_c/k_s) is the study's data, the
pressure field at that load (--pressure-map) the figure, made by run.
docs/validation/boundaryElement.md shows both.
"""
from .. import materials, pages, solves
from ..tables import number
from .engineeringRange import X3P

DATA = ["boundaryElementMap.csv"]
KEYS = ["surface", "regime"]
LOAD = 1e-3  # F/(A_n E')
STEEL = ["--E", "200e9", "--nu", "0.3"]  # one steel solid against a rigid flat


def store(ctx):
    return solves.Store(ctx, "boundaryElementMap", KEYS)


def solve(ctx):
    store(ctx).solve([solves.Solve({"surface": "x3p", "regime": "elastic"},
                                   ["--areal", X3P, "--model", "boundaryElement"] + STEEL, [LOAD])])


def outputs(ctx):
    row = store(ctx).curve({"surface": "x3p", "regime": "elastic"})[0]
    out = pages.Outputs(ctx, "boundaryElementMap")
    out.table("point", ["F/(A_n E')", "A_r/A_n", "mean separation [nm]", "h_c/k_s [1/m]", "iterations"],
              [[row["load"], f"{number(row['area_fraction']):.4f}", f"{number(row['separation_m']) * 1e9:.0f}",
                f"{number(row['h_per_k_per_m']):.4g}", row["iterations"]]])
    area = number(row["area_fraction"])

    def draw(path):
        import numpy
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        field = ctx.scratch_path("boundaryElementMap", "pressure.txt")
        solves.run_cli(ctx, ["--areal", X3P, "--model", "boundaryElement"] + STEEL +
                       ["--loads", f"{LOAD:g}", "--pressure-map", field], "the map's pressure field")
        with open(field) as f:
            header = f.readline().split()
        dx = float(header[header.index("dx") + 2])
        p = numpy.loadtxt(field, comments="#") / 1e9
        ny, nx = p.shape
        fig, ax = plt.subplots(figsize=(9, 8))
        image = ax.imshow(numpy.ma.masked_equal(p, 0.0), origin="lower", cmap="Reds",
                          extent=[0, nx * dx * 1e3, 0, ny * dx * 1e3])
        fig.colorbar(image, ax=ax, label="contact pressure [GPa]")
        ax.set_title(f"x3p-2.x3p ({nx} x {ny}, {nx * dx * 1e3:.2f} mm square) on a steel flat,\n"
                     f"F/(A_n E') = {LOAD:g}: A_r/A_n = {area:.4f}")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        fig.tight_layout()
        fig.savefig(path, dpi=90)
        plt.close(fig)
    out.figure("pressure", draw)
    return out
