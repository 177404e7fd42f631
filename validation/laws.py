# SPDX-License-Identifier: GPL-3.0-or-later
"""Every conductance law on a surface, as the CLI computes them (--conductance-law all): the
laws are the core's, evaluated again each time a study needs them (they take a fraction of a
second), never stored beside the exact solves.

The laws and how the CLI names their columns; the multi-scale ones on the regime's area model
(hertz elastic, jacksonGreen capped at the pair's H).
"""
import math

from . import solves, tables

LAWS = [
    ("jacksonBhavnaniFerguson", "jacksonBhavnaniFerguson on the multi-scale levels"),
    ("fittedElastoPlastic", "fittedElastoPlastic"),
    ("mikic", "mikic"),
    ("persson", "persson"),
    ("multiscaleBarber", "multiscaleBarber on the multi-scale levels"),
    ("cooperMikicYovanovich", "cooperMikicYovanovich (H_c = 2.84 S_y)"),
]


def on(ctx, description, pair, loads):
    """[{law: h_c/k_s [1/m]}] at each load p/E' of `loads`, for the CLI's surface arguments
    `description` and the Pair `pair` (nan where a law gives no finite value)."""
    model = ["--model", "jacksonGreen", "--hardness-from-yield"] if pair.hardness else ["--model", "hertz"]
    rows = solves.run_cli(ctx, description + model + pair.arguments + ["--conductance-law", "all", "--loads",
                                                                      ",".join(f"{pe:.6g}" for pe in loads)],
                          "the laws on " + " ".join(description))
    out = []
    for r in rows:
        values = {}
        for key, _ in LAWS:
            v = tables.number(r.get(f"h_per_k_{key}"))
            values[key] = v if math.isfinite(v) else float("nan")
        values["default"] = tables.number(r.get("h_per_k"))
        out.append(values)
    return out


def default_law(values):
    """The CLI's default law: the one whose column its h_per_k equals on every row given."""
    for key, _ in LAWS:
        if all(v[key] == v["default"] for v in values):
            return key
    raise SystemExit("validation: the CLI's default law is none of the laws compared")
