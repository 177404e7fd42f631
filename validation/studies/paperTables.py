# SPDX-License-Identifier: GPL-3.0-or-later
"""The seed paper's tables and figures (docs/validation/paper.md includes them), from the runs
of paper.Paper. Numbers are printed as the seed's text states them: slopes to 3 decimals,
pressures and areas to 4 significant digits."""
import math

from .. import pages
from .paper import (AT, FIT, GW_RANGES, LABEL, LOAD_RANGE, MODELS, MONOTONE_LOADS, MULTISCALE, SEED, SEED_COARSE,
                    SEED_COARSE_DX, SEED_COARSE_SURFACE, SEED_D, SEED_DX, SEED_EPRIME, SEED_FIG5_LOAD, SEED_G,
                    SEED_GW_SLOPE, SEED_HERTZ_PRESSURE, SEED_MS_SLOPE, SEED_NU, SEED_SURFACE, SEED_SY, STRIDES,
                    SURFACES, SYNTHETIC)

STRIDE_MODELS = ["hertz", "jacksonGreen", "truncation", "greenwoodWilliamson", "greenwoodWilliamsonJG"]
SPREAD_STRIDES = [2, 5, 10, 20, 50, 100]


def g(v, digits=4):
    return f"{v:.{digits}g}"


def f3(v):
    return f"{v:.3f}"


def e(x, digits=3):
    """A load or a frequency as the page writes it: 1e-4, 7.94e-5, 2.5e5."""
    m, ex = f"{x:.{digits - 1}e}".split("e")
    m = m.rstrip("0").rstrip(".") if "." in m else m
    return f"{m}e{int(ex)}"


def um(dx):
    """A sampling interval [m] as the page gives it, in um to 3 digits."""
    return float(f"{dx * 1e6:.3g}")


def fit_text(fit):
    slope, at, lo, hi = fit
    return f3(slope), g(at), f"{g(lo)}-{g(hi)}"


def materials_table(P, out):
    out.table("materials", ["E' [Pa]", "nu", "S_y [Pa]", "H = 2.84 S_y [Pa] (the core)", "H/E'"],
              [[g(SEED_EPRIME), g(SEED_NU), g(SEED_SY), g(P.hardness), g(P.hardness / SEED_EPRIME)]])


def slopes_table(P, out):
    rows = []
    for m in MODELS:
        s = fit_text(P.curve("standin", m).fit())
        d = fit_text(P.curve("dektak", m).fit())
        rows.append([f"{LABEL[m]} (`{m}`)"] + list(s) + list(d))
    rows.append(["GW with the seed's Table 1 sigma, eta, R (the CLI's GW on a spectrum with those McCool parameters)"]
                + list(fit_text(P.curve(SEED, "greenwoodWilliamson").fit())) + ["", "", ""])
    out.table("slopes", ["model", "stand-in slope", "stand-in F/(A_r E') at 1e-4", "(min-max over fit range)",
                         "Dektak slope", "Dektak F/(A_r E') at 1e-4", "(min-max)"], rows)


def gw_range_table(P, out):
    rows = []
    for lo, hi in GW_RANGES:
        loads = (min(lo, LOAD_RANGE[0]), max(hi, LOAD_RANGE[1]),
                 1 + round(10 * math.log10(max(hi, LOAD_RANGE[1]) / min(lo, LOAD_RANGE[0]))))
        rows.append([f"{e(lo)}..{e(hi)}", f3(P.curve(SEED, "greenwoodWilliamson", loads=loads).fit(lo, hi)[0])])
    out.table("gw-range", ["fit range F/(A_n E')", "GW slope, seed's Table 1 sigma, eta, R"], rows)


def order(P, surface):
    """Fig. 6 and 7's orderings at the load AT: MS-Hertz above GW, MS-JGH above MS-Hertz, MS-JG
    and MS-truncation between MB and GW-JG."""
    a = {m: P.area(surface, m, load=AT) for m in MODELS}
    lo, hi = sorted([a["majumdarBhushan"], a["greenwoodWilliamsonJG"]])
    between = all(lo <= a[m] <= hi for m in ("jacksonGreen", "truncation"))
    yes = lambda c: "yes" if c else "no"
    return (yes(a["hertz"] > a["greenwoodWilliamson"]), yes(a["jgh"] > a["hertz"]),
            "yes" if between else f"no: MS-JG {g(a['jacksonGreen'], 3)}, MS-trunc {g(a['truncation'], 3)}, "
                                  f"MB {g(a['majumdarBhushan'], 3)}, GW-JG {g(a['greenwoodWilliamsonJG'], 3)}")


def headline_table(P, out):
    def slope(surface, m):
        return f3(P.curve(surface, m).fit()[0])

    def plastic(surface):  # the elasto-plastic multi-scale slopes, as one value or a span
        s = sorted(slope(surface, m) for m in ("jacksonGreen", "truncation"))
        return s[0] if s[0] == s[-1] else f"{s[0]}-{s[-1]}"

    def x10(surface):
        r = [P.area(surface, m, 10) / P.area(surface, m) for m in ("jacksonGreen", "greenwoodWilliamson")]
        return f"{r[0]:.3f} / {r[1]:.2f}"

    o = {s: order(P, s) for s in ("standin", "dektak")}
    gw_seed = slope(SEED, "greenwoodWilliamson")
    rows = [
        ["MS-Hertz slope", f"{SEED_MS_SLOPE} (§3.2, Fig. 6)", slope("standin", "hertz"), slope("dektak", "hertz")],
        ["MS-JGH slope", f"{SEED_MS_SLOPE} (§3.2, Fig. 6)", slope("standin", "jgh"), slope("dektak", "jgh")],
        ["MS-JG, MS-truncation slopes", "\"nearly unity\" (§3.2, Fig. 7; no number)", plastic("standin"),
         plastic("dektak")],
        ["GW slope", f"{SEED_GW_SLOPE} (§3.2, Fig. 6)",
         f"{slope('standin', 'greenwoodWilliamson')} (Table 1 parameters: {gw_seed})",
         slope("dektak", "greenwoodWilliamson")],
        ["MS-Hertz F/(A_r E')", f"{g(SEED_HERTZ_PRESSURE)} (§3.2, after Eq. 34)",
         g(P.curve("standin", "hertz").fit()[1]), g(P.curve("dektak", "hertz").fit()[1])],
        ["MS above GW (elastic)", "yes (§3.2, Fig. 6)", o["standin"][0], o["dektak"][0]],
        ["MS-JGH slightly above MS-Hertz", "yes (§3.2, Fig. 6)", o["standin"][1], o["dektak"][1]],
        [f"MS-JG and MS-truncation between MB and GW-JG (A_r/A_n at load {e(AT)})", "yes (§3.2, Fig. 7)",
         o["standin"][2], o["dektak"][2]],
        [f"A(x10)/A(x1) at load {e(SEED_FIG5_LOAD)}, MS-JG / GW",
         "\"only a minute change\" / \"significantly affected\" (§3.2, Fig. 8; no numbers)", x10("standin"),
         x10("dektak")],
    ]
    out.table("headline", ["quantity", "seed (where stated)", "stand-in", "Dektak"], rows)


def surfaces_table(P, out):
    def row(label, sigma, eta, R, info, slope, D="", G="", p=None):
        beta = info["eta"] * info["R"] * info["sigma_s"]
        return [label, g(sigma), g(eta), g(R), g(info["alpha"]), g(beta), g(slope), D, G,
                "" if p is None else g(p), "" if p is None else f3(p / slope)]

    rows = [row(f"seed Table 1, dx {SEED_DX * 1e6:g} um", *SEED_SURFACE, P.info(SEED), P.rms_slope(SEED),
                g(SEED_D), g(SEED_G, 3), SEED_HERTZ_PRESSURE),
            row(f"seed §3.2, dx {SEED_COARSE_DX * 1e6:g} um", *SEED_COARSE, P.info(SEED_COARSE_SURFACE),
                P.rms_slope(SEED_COARSE_SURFACE))]
    for key, label, _, _ in SURFACES:
        dx = um(P.spacing(key))
        for k in (1, 2):
            i = P.info(key, k)
            rows.append(row(f"{label}, dx {dx:g} um" if k == 1 else f"{label}, x2 ({2 * dx:.3g} um)", i["sigma"],
                            i["eta"], i["R"], i, P.rms_slope(key, k), g(i["D"]), g(i["G"], 3),
                            P.curve(key, "hertz").fit()[1] if k == 1 else None))
    out.table("surfaces", ["surface", "sigma [m]", "eta [1/m^2]", "R [m]", "alpha", "beta = eta R sigma_s",
                           "rms slope sqrt(m2)", "D", "G [m]", "MS-Hertz F/(A_r E')", "F/(A_r E') / rms slope"], rows)
    return rows


def halving_table(P, out):
    """What doubling the sampling interval does to sigma, eta and R (the seed's §3.2 pair of
    intervals; every second sample of the profiles)."""
    rows = [["seed (0.204 to 0.4 um, §3.2)", f"{SEED_COARSE[0] / SEED_SURFACE[0]:.2f}",
             f"{SEED_COARSE[1] / SEED_SURFACE[1]:.2f}", f"{SEED_COARSE[2] / SEED_SURFACE[2]:.2f}"]]
    for key, label, _, _ in SURFACES:
        a, b = P.info(key, 1), P.info(key, 2)
        rows.append([f"{label} (x2)", f"{b['sigma'] / a['sigma']:.2f}", f"{b['eta'] / a['eta']:.2f}",
                     f"{b['R'] / a['R']:.2f}"])
    out.table("halving", ["surface", "sigma coarse/fine", "eta coarse/fine", "R coarse/fine"], rows)


def levels_tables(P, out):
    """The Fig. 5 traces read at the levels of SURFACES: A_i/A_n after them and at the end."""
    for key, label, _, marks in SURFACES:
        rows = []
        trace0 = P.levels(key, MULTISCALE[0])
        freq = {i: f for i, f, _ in trace0}
        last = trace0[-1][0]
        for m in MULTISCALE:
            a = {i: x for i, _, x in P.levels(key, m)}
            after = [max(a[j] for j in a if j > marks[-1]), min(a[j] for j in a if j > marks[-1])]
            rows.append([LABEL[m]] + [g(a[i], 3) for i in marks] + [g(a[last], 3), f"{a[marks[-1]] / a[last]:.2f}",
                                                                     f"{after[0] / after[1]:.2f}"])
        out.table(f"levels-{key}", ["form"] + [f"after level {i} (f = {e(freq[i], 2)} /m)" for i in marks] +
                  [f"at the end (level {last})", f"level {marks[-1]} / end", f"max/min after level {marks[-1]}"],
                  rows)


def stride_table(P, out, key):
    dx = um(P.spacing(key))
    a = {(k, m): P.area(key, m, k) for k in STRIDES for m in STRIDE_MODELS}
    rows = [[f"x{k} ({k * dx:.3g} um)"] + [g(a[k, m]) for m in STRIDE_MODELS] for k in STRIDES]
    rows += [[f"**A(x{k})/A(x1)**"] + [f"**{a[k, m] / a[1, m]:.3f}**" for m in STRIDE_MODELS] for k in (10, 100)]
    out.table(f"stride-{key}", ["sampling interval"] + [LABEL[m] for m in STRIDE_MODELS], rows)
    return a


def spread(P, model, k):
    """The largest |ln(A_xK/A_x1)| over the fit range, stand-in."""
    one, other = P.curve("standin", model), P.curve("standin", model, k)
    return max(abs(math.log(b / a)) for x, a, b in zip(one.loads, one.areas, other.areas)
               if FIT[0] * 0.999 <= x <= FIT[1] * 1.001)


def spread_table(P, out):
    rows = []
    for k in SPREAD_STRIDES:
        jg, gw = f3(spread(P, "jacksonGreen", k)), f3(spread(P, "greenwoodWilliamson", k))
        # the ratio of the values shown
        rows.append([f"x{k}", jg, gw, f"{float(gw) / float(jg):.0f}" if float(jg) > 0 else "inf"])
    out.table("stride-spread", ["stride", "MS-JG max \\|ln(A_xK/A_x1)\\|", "GW max \\|ln(A_xK/A_x1)\\|",
                                "GW / MS-JG"], rows)


def slope_experiment_table(P, out):
    rows = []
    for D in SYNTHETIC[0]:
        for seed in SYNTHETIC[1]:
            path = P.synthetic[(D, seed)]
            i = P.info(path)
            slope = P.rms_slope(path)
            ph, pj = P.pressure(path, "hertz"), P.pressure(path, "jacksonGreen")
            rows.append([f"D = {D:g} ({seed})", g(i["eta"], 3), g(i["R"], 3), f"{slope:.4f}", g(ph), g(pj),
                         f3(ph / slope)])
    out.table("slope-experiment", ["synthetic profile (seed)", "eta [1/m^2]", "R [m]", "rms slope",
                                   "MS-Hertz F/(A_r E')", "MS-JG F/(A_r E')", "MS-Hertz / rms slope"], rows)


def checks_table(P, out):
    rows = []
    for m in ("jgh", "jghConsistent"):
        row = [f"{m}: decreasing steps of A_r/A_n on {MONOTONE_LOADS[2]} loads {e(MONOTONE_LOADS[0])}.."
               f"{e(MONOTONE_LOADS[1])} (largest drop, at load)"]
        for key in ("standin", "dektak"):
            c = P.curve(key, m, loads=MONOTONE_LOADS)
            drops = [((a - b) / a, x) for x, a, b in zip(c.loads[1:], c.areas, c.areas[1:]) if b < a]
            if drops:
                d, x = max(drops)
                row.append(f"{len(drops)} ({100 * d:.2g} %, at {x:.3g})")
            else:
                row.append("0")
        rows.append(row)
    i = P.info(SEED)
    worst = max(abs(i[k] / v - 1) for k, v in zip(("sigma", "eta", "R"), SEED_SURFACE))
    rows.append(["the seed's Table 1 surface (a two-level spectrum): its sigma, eta, R as the core reads them "
                 "against Table 1, largest relative difference", f"{worst:.1e}", ""])
    out.table("checks", ["check", "stand-in", "Dektak"], rows)


def findings_table(P, out, strides):
    """The numbers the page's prose leans on, stand-in and Dektak side by side."""
    seed_slope, seed_R = P.rms_slope(SEED), SEED_SURFACE[2]
    h_E = P.hardness / SEED_EPRIME
    at = {(s, m): P.area(s, m, load=AT) for s in ("standin", "dektak") for m in MODELS}

    def both(f):
        return [f("standin"), f("dektak")]

    def same(s):  # MS-JG against MS-Hertz over the whole load range
        a, b = P.curve(s, "jacksonGreen"), P.curve(s, "hertz")
        return f"{max(abs(x / y - 1) for x, y in zip(a.areas, b.areas)):.2g}"

    def truncation(s):  # F/(A_r E') of MS-truncation over H/E', its range over the fit range
        _, _, lo, hi = P.curve(s, "truncation").fit()
        return f"{lo / h_E:.3f}-{hi / h_E:.3f}"

    def sampling(s, ks):  # the multi-scale areas' largest factor either way over x1 at these strides
        r = [strides[s][k, m] / strides[s][1, m] for k in ks for m in ("hertz", "jacksonGreen", "truncation")]
        return f"{max(max(r), 1 / min(r)):.2f}"

    dx = {s: P.spacing(s) for s in ("standin", "dektak")}
    rows = [
        ["rms slope over the seed's (Table 1)"] + both(lambda s: f"{P.rms_slope(s) / seed_slope:.2f}"),
        ["McCool curvature 1/R over the seed's (Table 1)"] + both(lambda s: f"{seed_R / P.info(s)['R']:.2f}"),
        [f"MS-Hertz F/(A_r E') at {e(AT)} over H/E' (seed: {SEED_HERTZ_PRESSURE / h_E:.2f})"]
        + both(lambda s: f"{P.pressure(s, 'hertz') / h_E:.2f}"),
        [f"MS-JG F/(A_r E') at {e(AT)} over S_y/E'"]
        + both(lambda s: f"{P.pressure(s, 'jacksonGreen') * SEED_EPRIME / SEED_SY:.2f}"),
        ["MS-truncation F/(A_r E') over H/E', over the fit range"] + both(truncation),
        [f"MS-JG against MS-Hertz, largest relative difference of A_r/A_n, {e(LOAD_RANGE[0])}..{e(LOAD_RANGE[1])}"]
        + both(same),
        [f"A_r/A_n at {e(AT)}: MS-JG / MB, MS-truncation / MB, GW-JG / MS-JG"]
        + both(lambda s: f"{at[s, 'jacksonGreen'] / at[s, 'majumdarBhushan']:.2f}, "
                         f"{at[s, 'truncation'] / at[s, 'majumdarBhushan']:.2f}, "
                         f"{at[s, 'greenwoodWilliamsonJG'] / at[s, 'jacksonGreen']:.2f}"),
        [f"A_r/A_n at {e(AT)} over MS-Hertz's: MS-JGH consistent (seed form)"]
        + both(lambda s: f"{at[s, 'jghConsistent'] / at[s, 'hertz']:.2f} ({at[s, 'jgh'] / at[s, 'hertz']:.2f})"),
        [f"A(x100)/A(x1) at {e(SEED_FIG5_LOAD)}, MS-JGH (seed form)"]
        + both(lambda s: f"{P.area(s, 'jgh', 100) / P.area(s, 'jgh'):.2f}"),
        ["MS-Hertz, MS-JG, MS-truncation at x2-x10: largest factor either way over x1"]
        + both(lambda s: sampling(s, [2, 5, 10])),
        ["the same at x20-x100"] + both(lambda s: sampling(s, [20, 50, 100])),
        ["Nyquist frequency 1/(2 K dx) at x20, x50, x100 [1/m]"]
        + both(lambda s: ", ".join(e(1 / (2 * k * dx[s]), 2) for k in (20, 50, 100))),
    ]
    out.table("findings", ["what", "stand-in", "Dektak"], rows)


def figures(P, out):
    def setup():
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt

    def area_axes(ax):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(LOAD_RANGE[0], LOAD_RANGE[1])
        ax.set_ylim(1e-6, 2)
        ax.set_xlabel("load F/(A_n E') [-]")
        ax.set_ylabel("real contact area A_r/A_n [-]")
        ax.grid(True, which="major", alpha=0.3)

    def curves(name, title, lines, legend="upper left"):
        def draw(path):
            plt = setup()
            fig, ax = plt.subplots(figsize=(8, 5.6))
            for surface, model, label, style in lines:
                c = P.curve(surface, model)
                ax.plot(c.loads, c.areas, style, lw=2, label=label)
            area_axes(ax)
            ax.set_title(title)
            ax.legend(loc=legend)
            fig.tight_layout()
            fig.savefig(path, dpi=100)
            plt.close(fig)
        out.figure(name, draw)

    def levels(name, surface, title):
        def draw(path):
            plt = setup()
            fig, ax = plt.subplots(figsize=(8, 5.6))
            for m in MULTISCALE:
                t = P.levels(surface, m)
                ax.step([f for _, f, _ in t], [a for _, _, a in t], where="post", lw=2, label=LABEL[m])
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("frequency f_i = i/L [1/m]")
            ax.set_ylabel("A_i/A_n after level i [-]")
            ax.grid(True, which="major", alpha=0.3)
            ax.set_title(title)
            ax.legend(loc="lower left")
            fig.tight_layout()
            fig.savefig(path, dpi=100)
            plt.close(fig)
        out.figure(name, draw)

    def sampling(path):
        plt = setup()
        fig, axes = plt.subplots(1, 2, figsize=(10, 5.2))
        for ax, model, title in zip(axes, ("jacksonGreen", "greenwoodWilliamson"),
                                    ("multi-scale, JG asperities", "Greenwood-Williamson")):
            for k in STRIDES:
                c = P.curve("standin", model, k)
                ax.plot(c.loads, c.areas, lw=2, color=plt.cm.coolwarm(math.log(k) / math.log(STRIDES[-1])),
                        label=f"x{k}")
            area_axes(ax)
            ax.set_title(title)
            ax.legend(loc="upper left")
        fig.suptitle(f"Sampling interval dx = {um(P.spacing('standin')):g} um x K (stand-in; seed Fig. 8)")
        fig.tight_layout()
        fig.savefig(path, dpi=100)
        plt.close(fig)

    load = e(SEED_FIG5_LOAD)
    levels("fig5-levels", "standin", f"Area after each frequency level, F/(A_n E') = {load} (stand-in; seed Fig. 5)")
    levels("dektak-levels", "dektak", f"Area after each frequency level, F/(A_n E') = {load} (Dektak profile)")
    curves("fig6-elastic", "Elastic models (stand-in; seed Fig. 6)",
           [("standin", "hertz", "MS-Hertz", "-"), ("standin", "jgh", LABEL["jgh"], "-"),
            ("standin", "jghConsistent", LABEL["jghConsistent"], "--"),
            ("standin", "greenwoodWilliamson", "GW (stand-in McCool)", "-"),
            (SEED, "greenwoodWilliamson", "GW (seed Table 1 sigma, eta, R)", "k--")])
    curves("fig7-elastoplastic", "Elasto-plastic models (stand-in; seed Fig. 7)",
           [("standin", "jacksonGreen", "MS-JG", "-"), ("standin", "truncation", "MS-truncation", "--"),
            ("standin", "greenwoodWilliamsonJG", "GW-JG", "-"),
            ("standin", "majumdarBhushan", LABEL["majumdarBhushan"], "-"),
            ("standin", "majumdarBhushanFitted", "MB (D, G fitted)", "k--")])
    out.figure("fig8-sampling", sampling)
    curves("dektak", "The measured Dektak profile (data/dektak-1.csv), all models",
           [("dektak", "hertz", "MS-Hertz", "-"), ("dektak", "jgh", LABEL["jgh"], "-"),
            ("dektak", "jghConsistent", LABEL["jghConsistent"], "--"), ("dektak", "jacksonGreen", "MS-JG", ":"),
            ("dektak", "truncation", "MS-truncation", "-"), ("dektak", "greenwoodWilliamson", "GW", "-"),
            ("dektak", "greenwoodWilliamsonJG", "GW-JG", "-"),
            ("dektak", "majumdarBhushanFitted", "MB (D, G fitted)", "--")], legend="lower right")


def outputs(ctx, P):
    out = pages.Outputs(ctx, "paper")
    materials_table(P, out)
    surfaces_table(P, out)
    halving_table(P, out)
    headline_table(P, out)
    slopes_table(P, out)
    gw_range_table(P, out)
    levels_tables(P, out)
    strides = {key: stride_table(P, out, key) for key in ("standin", "dektak")}
    spread_table(P, out)
    slope_experiment_table(P, out)
    checks_table(P, out)
    findings_table(P, out, strides)
    figures(P, out)
    return out
