# SPDX-License-Identifier: GPL-3.0-or-later
"""The heavy loads' tables and summary (docs/validation/heavyLoads.md includes them): the exact
answers, the law's ratio with the core's built-in constants and with one rate beta throughout,
and the three forms of the rate beyond x_g."""
import math

from .. import fitting, materials, pages
from ..tables import Table
from .engineeringRange import BAND, X3P, Surface
from .heavyLoads import FIXED, FITTED, WHAT, beyond, fit_rate, ratios_of, start, surfaces

STUDY = "heavyLoads"
SUMMARY = ("# The exact elastic conductance at heavy loads and the law fittedElastoPlastic's ratio to it (written by\n"
           "# validation/studies/heavyLoads.py): per surface (role: training, fitted beta_2; holdout, never fitted)\n"
           "# and load x = p/(E' h') where the exact A_r/A_n <= 0.9, the realizations, the geometric means of the\n"
           "# exact A_r/A_n and h_c/k_s [1/m] and the standard error of the latter as a factor, the grid check\n"
           "# (seed 1's Fourier series on 1024^2 over 512^2), the law's ratio, and the ratio of the law with one\n"
           "# growth rate beta = {beta:g} throughout (the law before beta_2(W)).\n")
FORMS = [("one", "one rate"), ("s1", "a rate linear in s1"), ("W", "a rate linear in W (the law's)")]
DEKTAK_PRESSURE = 110e6  # [Pa]: a heavy load on the Dektak profile's spectrum, steel on steel


def band(values):
    return f"{min(values):.2f}-{max(values):.2f}" if len(values) else "-"


def within(values):
    return int(sum(1 for v in values if abs(v - 1) <= BAND))


def forms(rc, pts, c):
    """[(label, constants, training ratios, held-out ratios, each training surface left out:
    within 25 % of its points beyond x_g)], and the counts of training and held-out points."""
    train, held = beyond(pts), beyond(pts, "holdout")
    names = list(dict.fromkeys(r["surface"] for r in train.rows))
    out = []
    for form, label in FORMS:
        y = fit_rate(rc, form, train, c)
        left = 0
        for name in names:
            z = fit_rate(rc, form, train.where(lambda r: r["surface"] != name), c)
            left += within(ratios_of(rc, form, z, c, train.where(lambda r: r["surface"] == name)))
        out.append((label, y, ratios_of(rc, form, y, c, train), ratios_of(rc, form, y, c, held), left))
    return out, len(train), len(held)


def outputs(ctx, design, pts):
    rc = ctx.rc()
    out = pages.Outputs(ctx, STUDY)
    built = rc.FittedElastoPlasticConstants()
    beta = built.elasticGrowth
    one = fitting.constants(rc, {"heavyLoadGrowth": beta, "heavyLoadGrowthSlope": 0.0})
    law = fitting.ratios(rc, built, pts)
    before = fitting.ratios(rc, one, pts)
    rows = []
    for r, a, b in zip(pts.rows, law, before):
        rows.append({"surface": r["surface"], "role": r["role"], "x": f"{r['x']:g}", "realizations": r["n"],
                     "area": f"{r['area']:.6g}", "h_per_k": f"{r['exact']:.6g}",
                     "standard_error": f"{r['standard_error']:.4f}" if r["standard_error"] else "",
                     "grid": f"{r['grid']:.4f}" if r["grid"] else "", "law_over_exact": f"{a:.4f}",
                     "one_rate_over_exact": f"{b:.4f}"})
    out.text("summary.csv", SUMMARY.format(beta=beta) + Table(list(rows[0]), rows).text())

    train, held = beyond(pts), beyond(pts, "holdout")
    fitted = fit_rate(rc, "W", train, start(rc))
    out.table("constants", ["constant", "what it is", "fitted here", "the core's (FittedElastoPlasticConstants.inc)"],
              [[f"`{n}`", WHAT[n].split(" (fitted")[0], f"{v:.4f}", f"{getattr(built, n):g}"]
               for n, v in zip(FITTED, fitted)]
              + [[f"`{n}`", WHAT[n], f"{v:g} (this study's)", f"{getattr(built, n):g}"] for n, v in FIXED.items()]
              + [["`elasticGrowth`", "beta: the elastic growth's rate up to x_g (fitted: fittedElastoPlastic)", "-",
                  f"{beta:g}"]])
    out.table("beyond", ["surfaces", "points", "law / exact", f"within {100 * BAND:.0f} %",
                         "one rate beta throughout (the law before)", f"within {100 * BAND:.0f} %"],
              [[label, len(sel), band(fitting.ratios(rc, built, sel)), within(fitting.ratios(rc, built, sel)),
                band(fitting.ratios(rc, one, sel)), within(fitting.ratios(rc, one, sel))]
               for label, sel in (("training (fitted beta_2)", train), (f"the {len(design.shapes)} spectra (held out)",
                                                                         held))])
    table = []
    for name in dict.fromkeys(r["surface"] for r in pts.rows):
        here = {r["x"]: (r, a, b) for r, a, b in zip(pts.rows, law, before) if r["surface"] == name}
        table.append([name, next(iter(here.values()))[0]["role"]] + [
            f"A {here[x][0]['area']:.2f}: {here[x][1]:.2f} ({here[x][2]:.2f})" if x in here else "-"
            for x in design.loads])
    out.table("surfaces", ["surface", "role"] + [f"x = {x:g}" for x in design.loads], table)
    table, n_train, n_held = forms(rc, pts, start(rc))
    out.table("forms", ["the rate beyond x_g", "constants", f"training: law / exact, within {100 * BAND:.0f} %",
                        "held out", "each training surface left out"],
              [[label, ", ".join(f"{v:.3f}" for v in y), f"{band(tr)}, {within(tr)}", f"{band(ho)}, {within(ho)}",
                f"{left} of {n_train}"] for label, y, tr, ho, left in table])

    # What the page's prose says in numbers.
    grids = [r["grid"] for r in train.rows if r["grid"]]
    ses = [r["standard_error"] for r in pts.rows if r["standard_error"]]
    pair = materials.regime_pair(ctx, "elastic")
    dektak = next(s for s in surfaces(ctx, design) if s.name == "dektak")
    x3p = Surface(ctx, "x3p", "", ["--areal", X3P, "--direction", "both"], False)
    m = rc.SurfaceSpec.areal(X3P, direction="both").roughness().mean_absolute_slope
    out.table("findings", ["what", "measured"], [
        ["beta, the elastic growth's rate up to x_g (the core's)", f"{beta:g}"],
        [f"the Dektak profile's spectrum ({design.cut} levels): h', and x at {DEKTAK_PRESSURE / 1e6:.0f} MPa, "
         "steel on steel", f"{dektak.gradient:.2g}, {DEKTAK_PRESSURE / (pair.Eprime * dektak.gradient):.2f}"],
        ["the X3P map's x in the law's terms, P/(sqrt(pi) E' m), over p/(E' h')",
         f"{x3p.gradient / (math.sqrt(math.pi) * m):.2f}"],
        [f"the grid: seed {design.seeds[0]}'s Fourier series on {design.fine}^2 over {design.N}^2, training "
         "surfaces", band(grids)],
        ["the sample: the standard error of a geometric mean over the realizations, a factor", band(ses)],
        ["the training points beyond x_g (fitted) and the held-out ones",
         f"{n_train}, {n_held}"],
        ["the law beyond x_g, training and held out", band(list(fitting.ratios(rc, built, train))
                                                           + list(fitting.ratios(rc, built, held)))]])
    return out
