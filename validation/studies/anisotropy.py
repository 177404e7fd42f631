# SPDX-License-Identifier: GPL-3.0-or-later
"""Does the default law hold on anisotropic surfaces, and what does it need of them? The same heights stretched along y by g = 1, 2, 4, 8, exact against the law given one profile across, one along, both, or the map, elastic and capped for the engineering range's pairs.

The laws take one sigma and one m (the mean absolute slope along the rows and the columns
together, --direction both) and the rows' and columns' averaged line-scan spectrum; the exact
model takes the surface as it is. Each of the engineering range's three self-affine spectra
(Hurst 0.8 and 0.3 rolled off at L/4, Hurst 0.5 without a roll-off; h' = 0.1, L = 1 mm, 64
levels) is synthesized isotropically on 512^2 (seeds 1-4, the core's synthesize_isotropic) and the
same heights are given a spacing stretched by g along y (--dy = g --dx): the wavelengths along y g
times longer, the slopes along y g times smaller, the heights the same. The exact model solves
each (one period, periodic), elastic and capped for the engineering range's four pairs, at the
same p/E' = 1e-4 to 1e-2. The default law (the core's) is given what a user would measure of the
surface, as the core reads it: one profile across the lay (a row), one along it (a column), the
two together (alongLay), four of each a surface; or the map (both directions). x = p/(E' h') with
h' the core's areal rms gradient of the map's averaged spectrum. The surfaces and profiles are made
again from their seeds (the scratch folder), never committed.
docs/validation/anisotropy.md reads the tables.
"""
import math
import os

from .. import fitting, materials, pages, solves, spectra, surrogates
from ..tables import Table
from .engineeringRange import SELF_AFFINE, self_affine_spectra, X3P, geometric_mean

DATA = ["anisotropy.csv"]
KEYS = ["surface", "regime", "stretch", "grid", "seed"]
GRADIENT = 0.1  # h' of the isotropic surfaces' spectra: their x = p/(E' h') sets the loads
HEAVY = 0.02  # the stretched ratio over the isotropic one is also given from this x on
DEFAULT = "fittedElastoPlastic"
PROFILES = 4  # single profiles each way a surface
SUMMARY = ("# The default law on stretched (anisotropic) surfaces (written by validation/studies/anisotropy.py):\n"
           "# per spectrum, regime, stretch g of the y spacing and load p/E', the load x = p/(E' h') with the\n"
           "# stretched surface's h', its m_x/m_y, and the geometric means over seeds 1-4 of the exact h_c/k_s\n"
           "# [1/m] and of the default law over exact (with its min and max over the seeds).\n")
INPUTS_HEADER = ("# The default law over exact by what it is given of a stretched surface (written by\n"
                 "# validation/studies/anisotropy.py): per regime, stretch g of the y spacing and input (across: one\n"
                 "# profile across the lay, a row; rows: the mean of all rows; along: one along it, a column;\n"
                 "# columns: their mean; profiles: a row with a column (alongLay); map: the areal map, both\n"
                 "# directions), the geometric mean, min and max over the spectra, seeds 1-4,\n"
                 "# profiles and loads, and the min and max of its h over the map's h on the same surface and load.\n")
SURFACES = ("# The surfaces of validation/studies/anisotropy.py: per spectrum, stretch g of the y spacing and\n"
            "# seed, the areal rms gradient h' and the mean absolute slopes along x, y and both (the laws' m).\n")


class Design:
    def __init__(self, quick):
        if quick:
            self.N, self.seeds, self.stretches = 128, [1], [1, 2]
            self.loads, self.regimes = [1e-3, 1e-2, 1e-1], ["elastic", "steelSteel"]
        else:
            self.N, self.seeds, self.stretches = 512, [1, 2, 3, 4], [1, 2, 4, 8]
            self.loads = [x for x in (10 ** (k / 3.0 - 4.0) for k in range(10)) if x >= 1e-3 * (1 - 1e-9)]
            self.regimes = [key for key, _, _ in materials.REGIMES]
        # The profiles a surface: rows (across the lay) and columns (along it) k N / PROFILES.
        self.profiles = [k * self.N // PROFILES for k in range(PROFILES)]
        self.spectra = [name for name, _, _, _ in SELF_AFFINE]


class Study:
    def __init__(self, ctx):
        self.ctx = ctx
        self.design = d = Design(ctx.quick)
        self.spectrum = self_affine_spectra(ctx, "anisotropy", d.N // 8, GRADIENT)
        self.dx = {name: spectra.length(path) / d.N for name, path in self.spectrum.items()}
        self.store = solves.Store(ctx, "anisotropy", KEYS)
        self._areal = {}
        self._given = {}

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

    def areal(self, name, g, seed):
        """The stretched map as the laws take it (both directions), with its rows' and columns'
        mean absolute slopes."""
        k = (name, g, seed)
        if k not in self._areal:
            dx = self.dx[name]
            self._areal[k] = surrogates.Areal(self.ctx, self.surface(name, seed), dx, g * dx)
            rc = self.ctx.rc()
            self._areal[k].slopes = [rc.SurfaceSpec.areal(self._areal[k].path, dx=dx, dy=g * dx, direction=way)
                                     .roughness().mean_absolute_slope for way in ("x", "y")]
        return self._areal[k]

    def profile(self, name, g, seed, way, k):
        """A profile file of the stretched surface: row k (way "across", spacing dx) or column k
        ("along", spacing g dx), two columns x [m] and z [m] (made when it is not in the scratch
        folder)."""
        import numpy
        surface = self.surface(name, seed)
        path = f"{surface[:-len('.npy')]}-{way}{k}" + (f"-g{g}.txt" if way == "along" else ".txt")
        if not os.path.exists(path):
            z = numpy.load(surface)
            heights, spacing = (z[k, :], self.dx[name]) if way == "across" else (z[:, k], g * self.dx[name])
            temporary = f"{path}.{os.getpid()}.partial"
            numpy.savetxt(temporary, numpy.column_stack([numpy.arange(len(heights)) * spacing, heights]), fmt="%.17g")
            os.replace(temporary, path)
        return path

    def given(self, name, g, seed, way):
        """What the law is given of the surface, as a list of surrogates.LawInputs: the map's one
        (way "map"), its rows' or columns' mean ("rows", "columns": the averaged spectrum of all
        the profiles one way), or one per profile ("across", "along", "profiles": across with
        along)."""
        k = (name, g, seed, way)
        if k not in self._given:
            rc = self.ctx.rc()
            if way == "map":
                self._given[k] = [self.areal(name, g, seed)]
            elif way in ("rows", "columns"):
                dx = self.dx[name]
                self._given[k] = [surrogates.Areal(self.ctx, self.surface(name, seed), dx, g * dx,
                                                   "x" if way == "rows" else "y")]
            elif way == "profiles":
                self._given[k] = [surrogates.LawInputs(rc, rc.SurfaceSpec.profile(
                    self.profile(name, g, seed, "across", i), along_lay=self.profile(name, g, seed, "along", i)))
                    for i in self.design.profiles]
            else:
                self._given[k] = [surrogates.LawInputs(rc, rc.SurfaceSpec.profile(self.profile(name, g, seed, way, i)))
                                  for i in self.design.profiles]
        return self._given[k]

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

    def curve(self, name, regime, g, seed, way="map"):
        """[(p/E' asked, the exact row, the default law there)] (the core's law, built-in constants)
        given the map (or the rows' or columns' mean: "rows", "columns"); for single profiles
        (way "across", "along", "profiles") one such list a profile."""
        pair = materials.regime_pair(self.ctx, regime)
        c = self.store.curve(self.key(name, regime, g, seed))
        rows = [solves.at(c, pe) for pe in self.loads(regime)]
        if not all(rows):
            raise SystemExit(f"anisotropy: {name} g {g} seed {seed} {regime} is not at the loads")
        out = []
        for a in self.given(name, g, seed, way):
            law = fitting.law(self.ctx.rc(), self.ctx.rc().FittedElastoPlasticConstants(),
                              fitting.Points([a.point(float(r["load"]) * pair.Eprime, pair) for r in rows]))
            out.append(list(zip(self.loads(regime), rows, (float(v) for v in law))))
        return out[0] if way in ("map", "rows", "columns") else out


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


INPUTS = {"across": "one profile across the lay", "rows": "the mean of the profiles across (the rows)",
          "along": "one profile along it", "columns": "the mean of the profiles along (the columns)",
          "profiles": "a profile across and one along (alongLay)", "map": "the areal map"}


def inputs(s):
    """The default law over exact when it is given one profile across the lay (a row: the
    wavelengths along y are g times longer) or the mean of all of them (the rows), one along it (a
    column) or the columns, one across with one along (alongLay, their isotropic equivalent), or
    the map (both directions): per regime, stretch and input, over the spectra, seeds, profiles and
    loads; and its h over the map's on the same surface and load."""
    d = s.design
    rows = []
    for regime in d.regimes:
        for g in d.stretches:
            for way in INPUTS:
                ratio, over = [], []
                for name in d.spectra:
                    for seed in d.seeds:
                        law = [v for _, _, v in s.curve(name, regime, g, seed)]
                        one = way in ("map", "rows", "columns")
                        curves = [s.curve(name, regime, g, seed, way)] if one else s.curve(name, regime, g, seed, way)
                        for curve in curves:
                            ratio += [v / float(r["h_per_k_per_m"]) for _, r, v in curve]
                            over += [v / m for (_, _, v), m in zip(curve, law)]
                rows.append({"regime": regime, "stretch": g, "input": way, "points": len(ratio),
                             "ratio_geometric_mean": f"{geometric_mean(ratio):.4f}",
                             "ratio_min": f"{min(ratio):.4f}", "ratio_max": f"{max(ratio):.4f}",
                             "over_map_min": f"{min(over):.4f}", "over_map_max": f"{max(over):.4f}"})
    return rows


def over_map(rows, way, capped, stretches=None):
    """(smallest, largest) h of an input over the map's h on the same surface and load, from rows
    of inputs.csv: elastic or capped (every pair), over the stretches given (None: all)."""
    here = [r for r in rows if r["input"] == way and (r["regime"] != "elastic") == capped
            and (stretches is None or int(r["stretch"]) in stretches)]
    return min(float(r["over_map_min"]) for r in here), max(float(r["over_map_max"]) for r in here)


LAY_INPUTS = ["across", "along", "profiles"]  # the inputs a user gives of a finish with a lay, beside a map


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
            if way != "map":
                text += f"; x {float(r['over_map_min']):.2f}-{float(r['over_map_max']):.2f} of the map's"
            return text
        out.table(f"inputs-{regime}", ["g"] + list(INPUTS.values()),
                  [[g] + [cell(g, way) for way in INPUTS] for g in d.stretches])
    # Per input: its h over the map's without a lay (g = 1: one profile's chance alone) and with
    # lays up to the largest stretch.
    top = max(d.stretches)
    out.table("inputs-summary", ["input", "elastic, g = 1", f"elastic, g = 1 to {top}", "capped, g = 1",
                                 f"capped, g = 1 to {top}"],
              [[INPUTS[way]] + [pages.span(over_map(given, way, capped, stretches))
                                for capped in (False, True) for stretches in ([1], None)]
               for way in INPUTS if way != "map"])
    rc = ctx.rc()
    slopes = [rc.SurfaceSpec.areal(X3P, direction=way).roughness().mean_absolute_slope for way in ("x", "y", "both")]
    out.table("map", ["the X3P map data/x3p-2.x3p", "along x", "along y", "both (the laws' m)"],
              [["mean absolute slope m"] + [f"{m:.3f}" for m in slopes]])
    return out
