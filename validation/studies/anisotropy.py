# SPDX-License-Identifier: GPL-3.0-or-later
"""Does the default law hold on anisotropic surfaces? The same heights stretched along y by g = 1, 2, 4, exact against the law, elastic and capped for two pairs.

The laws take one sigma and one m (the mean absolute slope along the rows and the columns
together, --direction both) and the rows' and columns' averaged line-scan spectrum; the exact
model takes the surface as it is. Each of the engineering range's three self-affine spectra
(Hurst 0.8 and 0.3 rolled off at L/4, Hurst 0.5 without a roll-off; h' = 0.1, L = 1 mm, 64
levels) is synthesized isotropically on 512^2 (seeds 1-4, the core's synthesize_isotropic) and the
same heights are given a spacing stretched by g along y (--dy = g --dx): the wavelengths along y g
times longer, the slopes along y g times smaller, the heights the same. The exact model solves
each (one period, periodic), elastic and capped for steel on steel and hardened steel, at the same
p/E' = 1e-4 to 1e-2; the default law (the core's) takes each surface's own sigma, m, spectrum and
skewness. x = p/(E' h') with h' the core's areal rms gradient of the averaged spectrum. The
surfaces are made again from their seeds (the scratch folder), never committed.
docs/validation/anisotropy.md reads the tables.
"""
import math

from .. import fitting, materials, pages, solves, spectra, surrogates
from ..tables import Table
from .engineeringRange import SELF_AFFINE, X3P, geometric_mean

DATA = ["anisotropy.csv"]
KEYS = ["surface", "regime", "stretch", "grid", "seed"]
GRADIENT = 0.1  # h' of the isotropic surfaces' spectra: their x = p/(E' h') sets the loads
HEAVY = 0.02  # the stretched ratio over the isotropic one is also given from this x on
DEFAULT = "fittedElastoPlastic"
SUMMARY = ("# The default law on stretched (anisotropic) surfaces (written by validation/studies/anisotropy.py):\n"
           "# per spectrum, regime, stretch g of the y spacing and load p/E', the load x = p/(E' h') with the\n"
           "# stretched surface's h', its m_x/m_y, and the geometric means over seeds 1-4 of the exact h_c/k_s\n"
           "# [1/m] and of the default law over exact (with its min and max over the seeds).\n")
INPUTS_HEADER = ("# The default law over exact by what it is given of a stretched surface (written by\n"
                 "# validation/studies/anisotropy.py): per regime, stretch g of the y spacing and input (x: the rows,\n"
                 "# profiles across the lay; y: the columns, along it; both: the map), the geometric mean, min and\n"
                 "# max over the spectra, seeds 1-4 and loads, and the min and max of its h over the h of both\n"
                 "# directions on the same surface and load.\n")
SURFACES = ("# The surfaces of validation/studies/anisotropy.py: per spectrum, stretch g of the y spacing and\n"
            "# seed, the areal rms gradient h' and the mean absolute slopes along x, y and both (the laws' m).\n")


class Design:
    def __init__(self, quick):
        if quick:
            self.N, self.seeds, self.stretches = 128, [1], [1, 2]
            self.loads, self.regimes = [1e-3, 1e-2, 1e-1], ["elastic", "steelSteel"]
        else:
            self.N, self.seeds, self.stretches = 512, [1, 2, 3, 4], [1, 2, 4]
            self.loads = [x for x in (10 ** (k / 3.0 - 4.0) for k in range(10)) if x >= 1e-3 * (1 - 1e-9)]
            self.regimes = ["elastic", "steelSteel", "hardSteel"]
        self.spectra = [name for name, _, _, _ in SELF_AFFINE]


class Study:
    def __init__(self, ctx):
        self.ctx = ctx
        self.design = d = Design(ctx.quick)
        self.spectrum = {name: spectra.self_affine(ctx.scratch_path("anisotropy", name + ".spectrum"), hurst, rolloff,
                                                   d.N // 8, GRADIENT)
                         for name, hurst, rolloff, _ in SELF_AFFINE}
        self.dx = {name: spectra.length(path) / d.N for name, path in self.spectrum.items()}
        self.store = solves.Store(ctx, "anisotropy", KEYS)
        self._areal = {}

    def loads(self, regime):
        """p/E' of the regime (the same on every stretch): up to 0.9 H with the cap."""
        pair = materials.regime_pair(self.ctx, regime)
        return [x * GRADIENT for x in self.design.loads
                if pair.hardness is None or x * pair.Eprime * GRADIENT <= 0.9 * pair.hardness]

    def surface(self, name, seed):
        """The isotropic surface's .npy file (made when it is not in the scratch folder)."""
        spec = self.spectrum[name]

        def make():
            import numpy
            rc = self.ctx.rc()
            a = rc.synthesize_isotropic(rc.SurfaceSpec.spectrum(spec).read_spectrum(), self.design.N, seed)
            if abs(a.dx / self.dx[name] - 1) > 1e-12:
                raise SystemExit(f"anisotropy: the synthesized spacing {a.dx} is not L/N = {self.dx[name]}")
            return numpy.asarray(a.heights)
        return surrogates.heights(self.ctx, "anisotropy", f"{name}-seed{seed}",
                                  f"anisotropy: synthesize_isotropic of {surrogates.file_digest(spec)} on "
                                  f"{self.design.N}^2, seed {seed}", make)

    def areal(self, name, g, seed, direction="both"):
        """The stretched map as the laws take it: from both directions (the map), or from the rows
        (x: profiles across the lay) or the columns (y: along it) alone."""
        k = (name, g, seed, direction)
        if k not in self._areal:
            dx = self.dx[name]
            self._areal[k] = surrogates.Areal(self.ctx, self.surface(name, seed), dx, g * dx, direction)
            rc = self.ctx.rc()
            self._areal[k].slopes = [rc.SurfaceSpec.areal(self._areal[k].path, dx=dx, dy=g * dx, direction=way)
                                     .roughness().mean_absolute_slope for way in ("x", "y")]
        return self._areal[k]

    def key(self, name, regime, g, seed):
        return {"surface": name, "regime": regime, "stretch": g, "grid": self.design.N, "seed": seed}

    def solves(self):
        out = []
        d = self.design
        for name in d.spectra:
            for g in d.stretches:
                for seed in d.seeds:
                    dx = self.dx[name]
                    areal = ["--areal", self.surface(name, seed), "--dx", f"{dx:.15g}", "--dy", f"{g * dx:.15g}"]
                    for regime in d.regimes:
                        pair = materials.regime_pair(self.ctx, regime)
                        out.append(solves.Solve(self.key(name, regime, g, seed),
                                                areal + ["--periodic", "--model", "boundaryElement"] + pair.arguments
                                                + (["--hardness-from-yield"] if pair.hardness else []),
                                                self.loads(regime)))
        return out

    def curve(self, name, regime, g, seed, direction="both"):
        """[(p/E' asked, the exact row, the default law there)] (the core's law, built-in constants),
        the law given the map's both directions, or its rows (x) or columns (y) alone."""
        pair = materials.regime_pair(self.ctx, regime)
        a = self.areal(name, g, seed, direction)
        c = self.store.curve(self.key(name, regime, g, seed))
        rows = [solves.at(c, pe) for pe in self.loads(regime)]
        if not all(rows):
            raise SystemExit(f"anisotropy: {name} g {g} seed {seed} {regime} is not at the loads")
        law = fitting.law(self.ctx.rc(), self.ctx.rc().FittedElastoPlasticConstants(),
                          fitting.Points([a.point(float(r["load"]) * pair.Eprime, pair) for r in rows]))
        return list(zip(self.loads(regime), rows, (float(v) for v in law)))


def solve(ctx):
    s = Study(ctx)
    s.store.solve(s.solves())


def summary(s):
    d = s.design
    rows = []
    for name in d.spectra:
        for regime in d.regimes:
            for g in d.stretches:
                grad = geometric_mean([s.areal(name, g, seed).gradient for seed in d.seeds])
                m_x = geometric_mean([s.areal(name, g, seed).slopes[0] for seed in d.seeds])
                m_y = geometric_mean([s.areal(name, g, seed).slopes[1] for seed in d.seeds])
                curves = [s.curve(name, regime, g, seed) for seed in d.seeds]
                for i, p in enumerate(s.loads(regime)):
                    h = [float(c[i][1]["h_per_k_per_m"]) for c in curves]
                    ratio = [c[i][2] / v for c, v in zip(curves, h)]
                    rows.append({"spectrum": name, "regime": regime, "stretch": g, "p_per_Eprime": f"{p:.6g}",
                                 "x": f"{p / grad:.6g}", "m_x_over_m_y": f"{m_x / m_y:.4f}",
                                 "exact_h_per_k": f"{geometric_mean(h):.6g}",
                                 "ratio_" + DEFAULT: f"{geometric_mean(ratio):.4f}",
                                 "ratio_min": f"{min(ratio):.4f}", "ratio_max": f"{max(ratio):.4f}"})
    return rows


INPUTS = {"x": "profiles across the lay", "y": "profiles along the lay", "both": "both directions (the map)"}


def inputs(s):
    """The default law over exact when it is given the rows alone (profiles across the lay: the
    wavelengths along y are g times longer), the columns alone (along it), or both (the map, the
    isotropic equivalent of the two directions): per regime, stretch and input, over the spectra,
    seeds and loads."""
    d = s.design
    rows = []
    for regime in d.regimes:
        for g in d.stretches:
            law = {direction: [v for name in d.spectra for seed in d.seeds
                               for _, _, v in s.curve(name, regime, g, seed, direction)] for direction in INPUTS}
            exact = [float(r["h_per_k_per_m"]) for name in d.spectra for seed in d.seeds
                     for _, r, _ in s.curve(name, regime, g, seed)]
            for direction in INPUTS:
                ratio = [v / e for v, e in zip(law[direction], exact)]
                # The same surface and load given both directions: what this input alone changes.
                over = [v / b for v, b in zip(law[direction], law["both"])]
                rows.append({"regime": regime, "stretch": g, "input": direction, "points": len(ratio),
                             "ratio_geometric_mean": f"{geometric_mean(ratio):.4f}",
                             "ratio_min": f"{min(ratio):.4f}", "ratio_max": f"{max(ratio):.4f}",
                             "over_both_min": f"{min(over):.4f}", "over_both_max": f"{max(over):.4f}"})
    return rows


def surfaces_text(s):
    d = s.design
    rows = []
    for name in d.spectra:
        for seed in d.seeds:
            for g in d.stretches:
                a = s.areal(name, g, seed)
                rows.append({"spectrum": name, "stretch": g, "seed": seed, "gradient": f"{a.gradient:.8g}",
                             "m_x": f"{a.slopes[0]:.8g}", "m_y": f"{a.slopes[1]:.8g}", "m": f"{a.m:.8g}"})
    return SURFACES + Table(list(rows[0]), rows).text()


def paired(s, regime):
    """{g: [(x, ratio_g / ratio_1 at the same x)]} seed by seed: the stretched surface's law/exact
    over the same heights' isotropic law/exact interpolated in ln x to the stretched surface's x
    (within the isotropic loads only)."""
    d = s.design
    out = {}
    for name in d.spectra:
        for seed in d.seeds:
            def curve(g):
                grad = s.areal(name, g, seed).gradient
                return [(float(r["load"]) / grad, v / float(r["h_per_k_per_m"])) for _, r, v in
                        s.curve(name, regime, g, seed)]
            iso = curve(1)
            for g in d.stretches[1:]:
                for x, r in curve(g):
                    for (x0, r0), (x1, r1) in zip(iso, iso[1:]):
                        if x0 <= x <= x1:
                            t = math.log(x / x0) / math.log(x1 / x0)
                            out.setdefault(g, []).append((x, r / math.exp((1 - t) * math.log(r0) + t * math.log(r1))))
                            break
    return out


def outputs(ctx):
    s = Study(ctx)
    d = s.design
    out = pages.Outputs(ctx, "anisotropy")
    rows = summary(s)
    out.text("summary.csv", SUMMARY + Table(list(rows[0]), rows).text())
    out.text("surfaces.csv", surfaces_text(s))
    for regime in d.regimes:
        here = [r for r in rows if r["regime"] == regime]
        ps = sorted({float(r["p_per_Eprime"]) for r in here})
        table = []
        for name in d.spectra:
            for g in d.stretches:
                found = {float(r["p_per_Eprime"]): r for r in here if r["spectrum"] == name and r["stretch"] == g}
                table.append([name, g, f"{float(found[ps[0]]['m_x_over_m_y']):.2f}"] + [
                    f"{float(r['ratio_' + DEFAULT]):.2f} ({float(r['ratio_min']):.2f}-{float(r['ratio_max']):.2f}), "
                    f"x = {float(r['x']):.2g}" for r in (found[p] for p in ps)])
        out.table(f"ratios-{regime}", ["spectrum", "g", "m_x/m_y"] + [f"p/E' = {p:.2g}" for p in ps], table)
        table = []
        for g, v in sorted(paired(s, regime).items()):
            heavy = [q for x, q in v if x >= HEAVY]
            table.append([g, f"{min(x for x, _ in v):.2g} to {max(x for x, _ in v):.2g}", len(v),
                          pages.span([q for _, q in v]), f"{math.exp(sum(math.log(q) for _, q in v) / len(v)):.2f}",
                          pages.span(heavy)])
        out.table(f"stretch-{regime}", ["g", "x", "seed-loads", "stretched over isotropic", "geometric mean",
                                        f"at x >= {HEAVY:g}"], table)
    given = inputs(s)
    out.text("inputs.csv", INPUTS_HEADER + Table(list(given[0]), given).text())
    for regime in d.regimes:
        def cell(g, way, regime=regime):
            r = next(r for r in given if r["regime"] == regime and r["stretch"] == g and r["input"] == way)
            text = f"{float(r['ratio_geometric_mean']):.2f} ({float(r['ratio_min']):.2f}-{float(r['ratio_max']):.2f})"
            if way != "both":
                text += f"; x {float(r['over_both_min']):.2f}-{float(r['over_both_max']):.2f} of both"
            return text
        out.table(f"inputs-{regime}", ["g"] + list(INPUTS.values()),
                  [[g] + [cell(g, way) for way in INPUTS] for g in d.stretches])
    rc = ctx.rc()
    slopes = [rc.SurfaceSpec.areal(X3P, direction=way).roughness().mean_absolute_slope for way in ("x", "y", "both")]
    out.table("map", ["the X3P map data/x3p-2.x3p", "along x", "along y", "both (the laws' m)"],
              [["mean absolute slope m"] + [f"{m:.3f}" for m in slopes]])
    return out
