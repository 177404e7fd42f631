# SPDX-License-Identifier: GPL-3.0-or-later
"""The skewness study's tables, summaries and figure (docs/validation/skewness.md includes them),
made from skewness.Study: the exact factor over Gaussian heights, the fit of the law's factor, the
capped forms it was chosen from, and the default law (the core's, built-in constants) over exact."""
import math

from .. import fitting, materials, pages
from ..tables import Table
from .engineeringRange import geometric_mean
from .skewness import GRADIENT, fit_factor

STUDY = "skewness"
DEFAULT = "fittedElastoPlastic"
FORMS = ["f^w", "f", "f^(w^2)"]  # how the elastic factor f enters the capped law; f^w is the law's
SUMMARY = ("# The exact conductance against the heights' skewness at a fixed spectrum (written by\n"
           "# validation/studies/skewness.py): per spectrum, regime, skewness and x = p/(E' h'), the geometric\n"
           "# means over seeds 1-4 of the exact A_r/A_n and h_c/k_s [1/m], of the default law over exact, and\n"
           "# of the exact answer over that of the same seed's Gaussian surface (with its min and max).\n")
SURFACES = ("# The skewed surfaces of validation/studies/skewness.py as the law fittedElastoPlastic takes them:\n"
            "# sigma [m], m (mean absolute slope, both directions), W (the line scans' bandwidth ratio), the\n"
            "# heights' skewness (what the exact model sees; the fit of the skewness factor reads it), its spread\n"
            "# by chance, the shrunk skewness the law takes and the line scans' first level's share s1.\n")


def label(regime):
    return materials.regime_of(regime)[1]


def law_values(s, regime, c):
    """{(spectrum, skewness, seed, x): the default law with constants c} on every surface's inputs."""
    pts = s.points(regime)
    values = fitting.law(s.ctx.rc(), c, pts)
    return {(r["surface"], r["skew"], r["seed"], r["x"]): (v, r) for r, v in zip(pts.rows, values)}


def summary(s, laws):
    d = s.design
    rows = []
    for name in d.spectra:
        for regime in d.regimes:
            for skew in d.skews:
                for x in s.loads(regime):
                    at = [laws[regime][(name, skew, seed, x)] for seed in d.seeds]
                    h = [r["exact"] for _, r in at]
                    factor = [r["exact"] / laws[regime][(name, 0.0, r["seed"], x)][1]["exact"] for _, r in at]
                    rows.append({"spectrum": name, "regime": regime, "skewness": f"{skew:.1f}", "x": f"{x:.6g}",
                                 "exact_area": f"{geometric_mean([r['area'] for _, r in at]):.6g}",
                                 "exact_h_per_k": f"{geometric_mean(h):.6g}",
                                 "ratio_" + DEFAULT: f"{geometric_mean([v / r['exact'] for v, r in at]):.4f}",
                                 "over_gaussian": f"{geometric_mean(factor):.4f}",
                                 "over_gaussian_min": f"{min(factor):.4f}", "over_gaussian_max": f"{max(factor):.4f}"})
    return rows


def surfaces_text(s):
    d = s.design
    rows = []
    for name in d.spectra:
        for skew in d.skews:
            for seed in d.seeds:
                a = s.areal(name, skew, seed)
                rows.append({"spectrum": name, "target": f"{skew:+.1f}", "seed": seed, "sigma": f"{a.sigma:.8g}",
                             "m": f"{a.m:.8g}", "bandwidth": f"{a.bandwidth:.8g}", "skewness": f"{a.skewness:.8g}",
                             "spread": f"{a.spread:.8g}", "shrunk": f"{a.shrunk:.8g}",
                             "first_level_share": f"{a.s1:.8g}"})
    return SURFACES + Table(list(rows[0]), rows).text()


def capped_forms(s, fitted):
    """How the exact capped factor (a skewed surface's h over its Gaussian twin's) compares with
    the law's for three ways of carrying the elastic factor f into the capped law: on the elastic
    branch f^w (w that branch's share of the Gaussian blend: the law's), f itself and f^(w^2); with
    the fitted factor and the surfaces' sample skewness. Every value is the core's law: f is its
    elastic law with the skewness over that without, w its Gaussian elastic branch over its blend
    (to the power N), and each form the capped law with Gaussian heights and its elastic prefactor
    times f^e. {regime: {form: [ln(law factor / exact factor)]}}."""
    rc = s.ctx.rc()
    c = fitting.constants(rc, fitted)
    d = s.design

    def law(a, P, H, skew, k=c):  # the core's law on the surface a (E: the regime's, below)
        return float(rc.fitted_elasto_plastic(P, a.sigma, a.m, a.bandwidth, E, H, skew, a.s1, k))

    out = {}
    for regime in d.regimes[1:]:
        pair = materials.regime_pair(s.ctx, regime)
        E, H = pair.Eprime, pair.hardness
        res = out.setdefault(regime, {f: [] for f in FORMS})
        for name in d.spectra:
            for seed in d.seeds:
                for skew in d.skewed:
                    for x in s.loads(regime):
                        factors = {}
                        for sk in (skew, 0.0):
                            a = s.areal(name, sk, seed)
                            P = float(s.exact(name, regime, sk, seed, x)["load"]) * E
                            el = law(a, P, math.nan, 0.0)
                            f = law(a, P, math.nan, a.skewness) / el
                            w = (el / law(a, P, H, 0.0)) ** c.blend
                            factors[sk] = {form: law(a, P, H, 0.0, fitting.constants(
                                rc, {"elasticPrefactor": c.elasticPrefactor * f ** e}, c))
                                for form, e in zip(FORMS, (w, 1.0, w * w))}
                            if abs(factors[sk]["f^w"] / law(a, P, H, a.skewness) - 1) > 1e-9:
                                raise SystemExit(f"skewness: the form f^w is not the core's law on {name} skewness "
                                                 f"{sk} seed {seed} {regime} x = {x:g}")
                        exact = math.log(float(s.exact(name, regime, skew, seed, x)["h_per_k_per_m"]) /
                                         float(s.exact(name, regime, 0.0, seed, x)["h_per_k_per_m"]))
                        for form in FORMS:
                            res[form].append(math.log(factors[skew][form] / factors[0.0][form]) - exact)
    return out


def follows(s, laws, regime):
    """ln of (the default law's h on a skewed surface over that on the same seed's Gaussian one)
    over the exact factor, at every skewed surface and load of the regime."""
    d = s.design
    out = []
    for name in d.spectra:
        for seed in d.seeds:
            for skew in d.skewed:
                for x in s.loads(regime):
                    (v, r), (v0, r0) = laws[regime][(name, skew, seed, x)], laws[regime][(name, 0.0, seed, x)]
                    out.append(math.log(v / v0) - math.log(r["exact"] / r0["exact"]))
    return out


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def grid(s, rows, regime, cell, skews):
    """A table of one regime: a row per spectrum and skewness, a column per load."""
    here = [r for r in rows if r["regime"] == regime]
    xs = sorted({float(r["x"]) for r in here})
    out = []
    for name in s.design.spectra:
        for skew in skews:
            found = {float(r["x"]): r for r in here if r["spectrum"] == name and float(r["skewness"]) == skew}
            out.append([name, f"{skew:+.1f}"] + [cell(found[x]) for x in xs])
    return ["spectrum", "skewness"] + [f"{x:.2g}" for x in xs], out


def figure(s, rows):
    d = s.design

    def draw(path):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import FixedLocator, NullLocator, ScalarFormatter
        fig, axes = plt.subplots(1, len(d.regimes), figsize=(4 * len(d.regimes), 3.8), sharey=True)
        colours = plt.cm.viridis([i / max(1, len(d.loads) - 1) for i in range(len(d.loads))])
        for ax, regime in zip(axes, d.regimes):
            here = [r for r in rows if r["regime"] == regime]
            for x, colour in zip(d.loads, colours):
                for k, name in enumerate(d.spectra):
                    pts = sorted((float(r["skewness"]), float(r["over_gaussian"])) for r in here
                                 if r["spectrum"] == name and abs(float(r["x"]) / x - 1) < 1e-5)
                    if pts:
                        ax.plot([p[0] for p in pts], [p[1] for p in pts], ["-o", "--s", ":^"][k % 3], color=colour,
                                ms=3, lw=1, label=f"x = {x:.2g}" if k == 0 else None)
            ax.set_yscale("log")
            ax.yaxis.set_major_locator(FixedLocator([0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2, 1.4, 1.6, 1.8]))
            ax.yaxis.set_major_formatter(ScalarFormatter())
            ax.yaxis.set_minor_locator(NullLocator())
            ax.set_title(label(regime), fontsize=9)
            ax.set_xlabel("skewness of the heights")
            ax.grid(True, color="0.85", lw=0.5)
        axes[0].set_ylabel("exact h_c / that with Gaussian heights")
        axes[0].legend(fontsize=7, title="solid, dashed, dotted:\nHurst 0.8, 0.3, 0.5", title_fontsize=7)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
    return draw


def outputs(ctx, s):
    rc = ctx.rc()
    d = s.design
    out = pages.Outputs(ctx, STUDY)
    built = rc.FittedElastoPlasticConstants()
    laws = {regime: law_values(s, regime, built) for regime in d.regimes}
    rows = summary(s, laws)
    out.text("summary.csv", SUMMARY + Table(list(rows[0]), rows).text())
    out.text("surfaces.csv", surfaces_text(s))
    for regime in d.regimes:
        out.table(f"factor-{regime}", *grid(s, rows, regime, lambda r: (
            f"{float(r['over_gaussian']):.2f} "
            f"({float(r['over_gaussian_min']):.2f}-{float(r['over_gaussian_max']):.2f})"), d.skewed))
        out.table(f"law-{regime}", *grid(s, rows, regime, lambda r: f"{float(r['ratio_' + DEFAULT]):.2f}", d.skews))

    fitted, by, count = fit_factor(s)
    out.table("fit", ["constant", "what it is", "fitted here", "the core's (FittedElastoPlasticConstants.inc)"],
              [[f"`{n}`", s_what(n), f"{v:.4f}", f"{getattr(built, n):g}"] for n, v in fitted.items()])
    out.table("residuals", ["x", "points", "rms", "largest"],
              [[f"{x:.2g}", len(e), f"{math.exp(rms(e)):.2f}", f"{math.exp(max(abs(v) for v in e)):.2f}"]
               for x, e in sorted(by.items())])
    forms = capped_forms(s, fitted)
    pooled = {f: [v for regime in forms for v in forms[regime][f]] for f in FORMS}
    best = min(pooled, key=lambda f: rms(pooled[f]))

    def cells(values):
        return [f"{rms(values[f]):.3f}, {max(abs(v) for v in values[f]):.3f}" for f in FORMS]
    out.table("forms", ["regime", "points"] + FORMS,
              [[label(regime), len(forms[regime]["f"])] + cells(forms[regime]) for regime in forms]
              + [["all capped", len(pooled["f"])] + cells(pooled)])
    table = []
    for regime in d.regimes:
        e = follows(s, laws, regime)
        table.append([label(regime), len(e), f"{math.exp(sum(e) / len(e)):.3f}", f"{math.exp(min(e)):.2f}",
                      f"{math.exp(max(e)):.2f}"])
    out.table("follows", ["regime", "points", "geometric mean", "lowest", "highest"], table)

    surf = [s.areal(name, skew, seed) for name in d.spectra for skew in d.skews for seed in d.seeds]
    taken = [s.areal(name, skew, seed).shrunk for name in d.spectra for skew in d.skews if abs(skew + 0.3) < 1e-9
             for seed in d.seeds]
    last = d.spectra[-1]
    findings = [["the elastic points the factor is fitted on (spectra x seeds x skewed surfaces x loads)", count],
                ["the form with the smallest rms over all capped points",
                 f"{best}" + (" (the law's)" if best == "f^w" else " (NOT the law's form f^w)")],
                [f"the {d.N}^2 surfaces' spread of the skewness by chance", pages.span([a.spread for a in surf])]]
    if taken:
        findings.append(["the skewness -0.3 as the law takes it (shrunk)", f"{min(taken):.2f} to {max(taken):.2f}"])
    findings.append([f"{last}'s spread by chance",
                     pages.span([s.areal(last, skew, seed).spread for skew in d.skews for seed in d.seeds])])
    out.table("findings", ["what", "measured"], findings)
    out.figure("skewness", figure(s, rows))
    out.text("parameters.md", pages.markdown_table(["what", "value"], [
        ["spectra", ", ".join(d.spectra) + f" (h' = {GRADIENT:g}, {d.N // 8} levels)"],
        ["grid, seeds", f"{d.N}^2, {', '.join(str(v) for v in d.seeds)}"],
        ["skewness imposed", ", ".join(f"{v:+.1f}" for v in d.skews)],
        ["rank-ordering iterations", d.iterations],
        ["loads x = p/(E' h')", ", ".join(f"{x:.2g}" for x in d.loads)],
        ["regimes", ", ".join(label(r) for r in d.regimes)]]))
    return out


def s_what(name):
    from .skewness import WHAT
    return WHAT[name].split(" (fitted")[0]
