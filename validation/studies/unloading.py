# SPDX-License-Identifier: GPL-3.0-or-later
"""How much more does a joint conduct once unloaded? The exact model loaded to a peak with the cap and unloaded, on the engineering range's spectra and pairs, and today's law against it.

Each of the engineering range's three self-affine spectra (h' = 0.1, L = 1 mm; N/8 levels) is
synthesized on one period of N^2 (the CLI's --synthesize, seeds 1-2) and solved exactly for the
four capped pairs (H = 2.84 S_y of the softer): loaded to a peak p/E' = 1e-4, 1e-3 and 1e-2
(x = p/(E' h') = 1e-3 to 0.1; only peaks up to 0.9 H), then unloaded to a half, a fifth, a
tenth and a thirtieth of it (the CLI's --unload-from: the cap's overlap at the peak kept as
permanent set, the deformed surface unloaded elastically; docs/theory.md §7.3). The loading
curve is solved at the same pressures. Today's default law (the core's, built-in constants) takes
h from the pressure of the moment, the loading value: its ratio to the exact unloading h is the
error the condition makes on a joint that was once loaded harder. The multi-scale model
(jacksonGreen on the same spectrum, each level unloading as a Hertzian contact of its peak,
docs/theory.md §3.6) is held to the exact unloading area. The surfaces are made again from their
seeds by the CLI, never committed. docs/validation/unloading.md reads the tables.
"""
from .. import fitting, materials, pages, solves, surrogates
from ..tables import Table
from .engineeringRange import SELF_AFFINE, self_affine_spectra, geometric_mean

DATA = ["unloading.csv"]
KEYS = ["surface", "regime", "grid", "seed", "peak", "branch"]
GRADIENT = 0.1  # h' of the spectra: x = p/(E' h') sets the peaks
FRACTIONS = [1.0, 0.5, 0.2, 0.1, 1.0 / 30.0]  # P/P_max of the unloading
SUMMARY = ("# The exact unloading of a capped joint (written by validation/studies/unloading.py): per spectrum,\n"
           "# regime, peak p/E' and fraction P/P_max, the geometric means over the seeds of the exact loading and\n"
           "# unloading h_c/k_s [1/m] and A_r/A_n, their ratios (with min and max over the seeds), and the\n"
           "# default law (loading, the pressure of the moment) over the exact unloading h; the multi-scale model's\n"
           "# (jacksonGreen) unloading over loading A_r/A_n and its unloading A_r/A_n over the exact one.\n")


class Design:
    def __init__(self, quick):
        if quick:
            self.N, self.seeds, self.peaks = 64, [1], [1e-3]
            self.regimes = ["steelSteel"]
        else:
            self.N, self.seeds, self.peaks = 512, [1, 2], [1e-4, 1e-3, 1e-2]
            self.regimes = [key for key, _, pair in materials.REGIMES if pair is not None]
        self.spectra = [name for name, _, _, _ in SELF_AFFINE]


class Study:
    def __init__(self, ctx):
        self.ctx = ctx
        self.design = d = Design(ctx.quick)
        self.spectrum = self_affine_spectra(ctx, "unloading", d.N // 8, GRADIENT)
        self.store = solves.Store(ctx, "unloading", KEYS)
        rc = ctx.rc()
        self.given = {name: surrogates.LawInputs(rc, rc.SurfaceSpec.spectrum(path))
                      for name, path in self.spectrum.items()}
        self.levels = {name: rc.SurfaceSpec.spectrum(path).read_spectrum() for name, path in self.spectrum.items()}

    def multiscale(self, name, regime, peak):
        """[(loading, unloading A_r/A_n)] of the multi-scale model (jacksonGreen on the spectrum)
        at the FRACTIONS of the peak p/E'."""
        pair = materials.regime_pair(self.ctx, regime)
        model = self.ctx.rc().Model("jacksonGreen", self.levels[name], pair.materials)
        P = [f * peak * pair.Eprime for f in FRACTIONS]
        return list(zip((float(a) for a in model.area_fraction(P)),
                        (float(a) for a in model.area_fraction(P, unload_from=peak * pair.Eprime))))

    def peaks(self, regime):
        """The peaks p/E' of the regime: up to 0.9 H."""
        pair = materials.regime_pair(self.ctx, regime)
        return [pe for pe in self.design.peaks if pe * pair.Eprime <= 0.9 * pair.hardness]

    def key(self, name, regime, seed, peak, branch):
        return {"surface": name, "regime": regime, "grid": self.design.N, "seed": seed, "peak": peak,
                "branch": branch}

    def solves(self):
        out = []
        d = self.design
        for name in d.spectra:
            for regime in d.regimes:
                pair = materials.regime_pair(self.ctx, regime)
                for seed in d.seeds:
                    base = (["--spectrum", self.spectrum[name], "--synthesize", f"{d.N},{seed}", "--model",
                             "boundaryElement"] + pair.arguments + ["--hardness-from-yield"])
                    for peak in self.peaks(regime):
                        loads = [f * peak for f in FRACTIONS]
                        out.append(solves.Solve(self.key(name, regime, seed, peak, "loading"), base, loads))
                        out.append(solves.Solve(self.key(name, regime, seed, peak, "unloading"),
                                                base + ["--unload-from", f"{peak * pair.Eprime:.17g}"], loads,
                                                solves.UNLOADING_COLUMNS))
        return out

    def points(self, name, regime, seed, peak):
        """[(P/P_max, loading row, unloading row, the default law's h_c/k_s there)]."""
        pair = materials.regime_pair(self.ctx, regime)
        rows = {}
        for branch in ("loading", "unloading"):
            c = self.store.curve(self.key(name, regime, seed, peak, branch))
            rows[branch] = [solves.at(c, f * peak) for f in FRACTIONS]
            if not all(rows[branch]):
                raise SystemExit(f"unloading: {name} {regime} seed {seed} peak {peak} {branch} is not at the loads")
        law = fitting.law(self.ctx.rc(), self.ctx.rc().FittedElastoPlasticConstants(),
                          fitting.Points([self.given[name].point(f * peak * pair.Eprime, pair) for f in FRACTIONS]))
        return list(zip(FRACTIONS, rows["loading"], rows["unloading"], (float(v) for v in law)))


def solve(ctx):
    s = Study(ctx)
    s.store.solve(s.solves())


def summary(s):
    d = s.design
    rows = []
    for name in d.spectra:
        for regime in d.regimes:
            for peak in s.peaks(regime):
                per_seed = [s.points(name, regime, seed, peak) for seed in d.seeds]
                ms = s.multiscale(name, regime, peak)
                for i, f in enumerate(FRACTIONS):
                    load = [float(p[i][1]["h_per_k_per_m"]) for p in per_seed]
                    unload = [float(p[i][2]["h_per_k_per_m"]) for p in per_seed]
                    area = [float(p[i][2]["area_fraction"]) / float(p[i][1]["area_fraction"]) for p in per_seed]
                    ratio = [u / v for u, v in zip(unload, load)]
                    law = [p[i][3] / u for p, u in zip(per_seed, unload)]
                    exact_area = geometric_mean([float(p[i][2]["area_fraction"]) for p in per_seed])
                    rows.append({"spectrum": name, "regime": regime, "peak_p_per_Eprime": f"{peak:.6g}",
                                 "fraction": f"{f:.6g}", "exact_loading_h_per_k": f"{geometric_mean(load):.6g}",
                                 "exact_unloading_h_per_k": f"{geometric_mean(unload):.6g}",
                                 "unloading_over_loading_h": f"{geometric_mean(ratio):.4f}",
                                 "ratio_min": f"{min(ratio):.4f}", "ratio_max": f"{max(ratio):.4f}",
                                 "unloading_over_loading_area": f"{geometric_mean(area):.4f}",
                                 "law_over_exact_unloading": f"{geometric_mean(law):.4f}",
                                 "law_min": f"{min(law):.4f}", "law_max": f"{max(law):.4f}",
                                 "multiscale_unloading_over_loading_area": f"{ms[i][1] / ms[i][0]:.4f}",
                                 "multiscale_over_exact_unloading_area": f"{ms[i][1] / exact_area:.4f}"})
    return rows


def outputs(ctx):
    s = Study(ctx)
    d = s.design
    out = pages.Outputs(ctx, "unloading")
    rows = summary(s)
    out.text("summary.csv", SUMMARY + Table(list(rows[0]), rows).text())
    for regime in d.regimes:
        table = []
        for peak in s.peaks(regime):
            for f in FRACTIONS[1:]:
                here = [r for r in rows if r["regime"] == regime and float(r["peak_p_per_Eprime"]) == peak
                        and abs(float(r["fraction"]) / f - 1) < 1e-5]
                table.append([f"{peak:.0e}", f"{f:.2g}",
                              pages.span([float(r["ratio_min"]) for r in here] + [float(r["ratio_max"]) for r in here]),
                              pages.span([float(r["unloading_over_loading_area"]) for r in here]),
                              pages.span([float(r["law_min"]) for r in here] + [float(r["law_max"]) for r in here]),
                              pages.span([float(r["multiscale_unloading_over_loading_area"]) for r in here]),
                              pages.span([float(r["multiscale_over_exact_unloading_area"]) for r in here])])
        out.table(f"ratios-{regime}", ["peak p/E'", "P/P_max", "unloading / loading h", "unloading / loading A_r",
                                       "today's law / exact unloading h", "multi-scale: unloading / loading A_r",
                                       "multi-scale / exact unloading A_r"], table)
    # In short: per regime, over the peaks, spectra and seeds, from a half to a thirtieth of the peak.
    short = []
    for key, label, pair in materials.REGIMES:
        here = [r for r in rows if r["regime"] == key and float(r["fraction"]) < 1.0]
        if here:
            short.append([label, pages.span([float(r["ratio_min"]) for r in here] +
                                            [float(r["ratio_max"]) for r in here]),
                          pages.span([float(r["law_min"]) for r in here] + [float(r["law_max"]) for r in here]),
                          pages.span([float(r["unloading_over_loading_area"]) for r in here]),
                          pages.span([float(r["multiscale_unloading_over_loading_area"]) for r in here])])
    out.table("short", ["regime", "unloading / loading h", "today's law / exact unloading h",
                        "exact: unloading / loading A_r", "multi-scale: unloading / loading A_r"], short)
    out.figure("loops", lambda path: draw_loops(s, path))
    return out


def draw_loops(s, path):
    """h_c/k_s against p/E' for each capped pair: the loading curve and the unloading branch from
    each peak, on the first spectrum (geometric mean over the seeds)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    d = s.design
    name = d.spectra[0]
    fig, axes = plt.subplots(1, len(d.regimes), figsize=(4.2 * len(d.regimes), 4.2), squeeze=False)
    for ax, regime in zip(axes[0], d.regimes):
        label = next(lab for key, lab, _ in materials.REGIMES if key == regime)
        for k, peak in enumerate(s.peaks(regime)):
            per_seed = [s.points(name, regime, seed, peak) for seed in d.seeds]
            loads = [f * peak for f in FRACTIONS]
            mean = [[geometric_mean([float(p[i][j]["h_per_k_per_m"]) for p in per_seed]) for i in range(len(loads))]
                    for j in (1, 2)]
            ax.loglog(loads, mean[0], "o-", color="0.5", label="loading" if k == 0 else None)
            ax.loglog(loads, mean[1], "s--", color=f"C{k}", label=f"unloading from {peak:.0e}")
        ax.set_title(label.replace("capped: ", ""), fontsize=10)
        ax.set_xlabel("p/E'")
        ax.grid(True, which="major", alpha=0.3)
    axes[0][0].set_ylabel("exact h_c/k_s [1/m]")
    axes[0][0].legend(fontsize=8)
    fig.suptitle(f"The joint that carried a peak ({name}, 512^2, seeds' geometric mean)", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)
