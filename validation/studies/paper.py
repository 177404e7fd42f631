# SPDX-License-Identifier: GPL-3.0-or-later
"""The seed paper reproduced (Jackson & Streator 2006): its Figs. 5-8 and the numbers of its §3.2, on the stand-in profile and on the measured Dektak profile.

Model curves of the CLI (the multi-scale forms, Greenwood-Williamson, Majumdar-Bhushan), not
exact solves: they take seconds, so nothing is stored (DATA is empty, solve does nothing) and
outputs(ctx) runs the CLI each time and makes the tables (paperTables.py) and figures. The
seed's values (its Table 1 and §3.2) are constants here, stated once; everything else comes from
the core: the curves, the level traces and the McCool and fractal parameters (--info), the rms
slope (areal_rms_gradient), H (ContactMaterials), the synthetic profiles (syntheticProfile).
The seed's Table 1 surface is a spectrum the core reads, two levels whose McCool parameters the
core finds to be Table 1's, so that its Greenwood-Williamson curve is the CLI's.
docs/validation/paper.md reads the tables.
"""
import concurrent.futures
import math
import os
import re
import subprocess

from .. import spectra
from ..context import ROOT

DATA = []

# The seed paper's values (Jackson & Streator, Wear 261 (2006) 1337-1347).
SEED_EPRIME, SEED_NU, SEED_SY = 200e9, 0.32, 0.2e9  # Table 1: E' [Pa], nu, S_y [Pa]
SEED_D, SEED_G = 1.597, 2.86e-10  # Table 1: Majumdar-Bhushan D, G [m]
SEED_SURFACE = (0.115e-6, 3.880e11, 9.299e-6)  # Table 1: sigma [m], eta [1/m^2], R [m] at dx 0.204 um
SEED_COARSE = (0.0815e-6, 1.20e11, 25.0e-6)  # §3.2: the same at dx 0.4 um
SEED_DX, SEED_COARSE_DX = 0.204e-6, 0.4e-6  # [m]
SEED_FIG5_LOAD = 7.94e-5  # F/(A_n E') of Fig. 5 (§3.2)
SEED_GW_SLOPE = "0.969"  # §3.2, Fig. 6
SEED_MS_SLOPE = "1.00"  # §3.2, Fig. 6: MS-Hertz and MS-JGH
SEED_HERTZ_PRESSURE = 0.00255  # F/(A_r E') of MS-Hertz, §3.2 after Eq. 34

# The study's choices.
LOAD_RANGE = (1e-6, 1e-2, 41)  # F/(A_n E'), 10 a decade: the curves
FIT = (1e-6, 1e-3)  # the slopes' least-squares range (below complete contact at H/E')
GW_RANGES = [(1e-6, 1e-2), (1e-6, 1e-3), (1e-6, 1e-4), (1e-7, 1e-4)]  # how the seed's GW slope depends on it
AT = 1e-4  # where F/(A_r E') and the areas of Fig. 7 are read
STRIDES = [1, 2, 5, 10, 20, 50, 100]  # --stride K: the sampling interval K dx (Fig. 8)
MONOTONE_LOADS = (1e-6, 1e-2, 2001)  # the JGH forms' monotonicity check
SYNTHETIC = ([1.1, 1.3, 1.5, SEED_D], [2006, 7])  # syntheticProfile --D, --seed (2006: the stand-in's)
# (key, label, profile, the levels a person reads the Fig. 5 trace at)
SURFACES = [("standin", "stand-in", os.path.join("data", "standin-2454.csv"), [5]),
            ("dektak", "Dektak", os.path.join("data", "dektak-1.csv"), [2, 60, 375])]
MULTISCALE = ["hertz", "jgh", "jghConsistent", "jacksonGreen", "truncation"]
MODELS = MULTISCALE + ["greenwoodWilliamson", "greenwoodWilliamsonJG", "majumdarBhushan", "majumdarBhushanFitted"]
LABEL = {"hertz": "MS-Hertz", "jgh": "MS-JGH (seed Eqs. 9-10)", "jghConsistent": "MS-JGH (consistent)",
         "jacksonGreen": "MS-JG", "truncation": "MS-truncation", "greenwoodWilliamson": "GW",
         "greenwoodWilliamsonJG": "GW-JG", "majumdarBhushan": "MB (Table 1 D, G)",
         "majumdarBhushanFitted": "MB (D, G fitted to the profile)"}
# The seed's surfaces as the runs name them: spectra with Table 1's and §3.2's McCool parameters.
SEED, SEED_COARSE_SURFACE = "seed", "seedCoarse"


def materials():
    return ["--Eprime", f"{SEED_EPRIME:g}", "--nu", f"{SEED_NU:g}", "--Sy", f"{SEED_SY:g}"]


def load_range(r):
    return ["--load-range", f"{r[0]:g}:{r[1]:g}:{r[2]}"]


class Curve:
    """A load curve of the CLI: loads F/(A_n E'), areas A_r/A_n, F/(A_r E') as it printed them."""

    def __init__(self, rows):
        self.loads = [float(r["nominal_pressure_per_Eprime"]) for r in rows]
        self.areas = [float(r["area_fraction"]) for r in rows]
        self.pressures = [float(r["contact_pressure_per_Eprime"]) for r in rows]

    def fit(self, lo=FIT[0], hi=FIT[1]):
        """(slope, F/(A_r E') at AT, its min and max): the least-squares slope of ln A on ln F over
        [lo, hi] and F/(A_r E') = load/area there, the points in partial contact (0 < A < 1) only."""
        pts = [(x, a) for x, a in zip(self.loads, self.areas) if lo * 0.999 <= x <= hi * 1.001 and 0 < a < 1]
        n, sx, sy, sxx, sxy = len(pts), 0.0, 0.0, 0.0, 0.0
        for x, a in pts:
            lx, ly = math.log(x), math.log(a)
            sx, sy, sxx, sxy = sx + lx, sy + ly, sxx + lx * lx, sxy + lx * ly
        slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
        p = [x / a for x, a in pts]
        at = next((q for x, q in zip(self.loads, self.pressures) if 0.99 * AT < x < 1.01 * AT), float("nan"))
        return slope, at, min(p), max(p)


class Runs:
    """The CLI's runs this study makes, each once (run several at a time, ctx.jobs)."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.done = {}

    def run(self, args):
        """(rows of its CSV output as text, its stderr) of one run of the CLI."""
        r = subprocess.run([self.ctx.cli] + list(args), capture_output=True, text=True)
        if r.returncode != 0:
            raise SystemExit(f"validation: paper: failed:\n  {' '.join([self.ctx.cli] + list(args))}\n{r.stderr}")
        lines = [ln for ln in r.stdout.splitlines() if ln and not ln.startswith("#")]
        return [dict(zip(lines[0].split(","), ln.split(","))) for ln in lines[1:]], r.stderr

    def prefetch(self, many):
        todo = list(dict.fromkeys(tuple(a) for a in many if tuple(a) not in self.done))
        with concurrent.futures.ThreadPoolExecutor(max_workers=self.ctx.jobs) as pool:
            for a, result in zip(todo, pool.map(self.run, todo)):
                self.done[a] = result

    def rows(self, args):
        if tuple(args) not in self.done:
            self.done[tuple(args)] = self.run(args)
        return self.done[tuple(args)]


class Paper:
    """The runs and what the core says of the surfaces: the tables' and figures' numbers."""

    def __init__(self, ctx):
        self.ctx = ctx
        self.rc = ctx.rc()
        self.runs = Runs(ctx)
        self.paths = {key: os.path.join(ROOT, path) for key, _, path, _ in SURFACES}
        self.spectra = {SEED: seed_surface(ctx, self.runs, SEED, SEED_SURFACE),
                        SEED_COARSE_SURFACE: seed_surface(ctx, self.runs, SEED_COARSE_SURFACE, SEED_COARSE)}
        self.synthetic = {(D, s): self._synthesize(D, s) for D in SYNTHETIC[0] for s in SYNTHETIC[1]}
        self.runs.prefetch(self._everything())
        m = self.rc.ContactMaterials.from_reduced_modulus(SEED_EPRIME, SEED_NU, SEED_SY)
        self.hardness = m.hardness

    def _synthesize(self, D, seed):
        path = self.ctx.scratch_path("paper", f"synthetic-D{D:g}-{seed}.csv")
        tool = os.path.join(os.path.dirname(self.ctx.cli), "syntheticProfile")
        r = subprocess.run([tool, "--D", f"{D:g}", "--seed", str(seed)], capture_output=True, text=True)
        if r.returncode != 0:
            raise SystemExit(f"validation: paper: {tool} failed:\n{r.stderr}")
        with open(path, "w") as f:
            f.write(r.stdout)
        return path

    # The CLI's arguments of each run.
    def _surface(self, surface, stride):
        if surface in self.spectra:
            return ["--spectrum", self.spectra[surface]]
        path = self.paths.get(surface, surface)
        return ["--profile", path] + (["--stride", str(stride)] if stride != 1 else [])

    def _contact(self, surface, stride, model, loads):
        extra = []
        if model == "majumdarBhushan":
            extra = ["--D", f"{SEED_D:g}", "--G", f"{SEED_G:g}"]
        elif model == "majumdarBhushanFitted":
            model = "majumdarBhushan"
        return self._surface(surface, stride) + ["--model", model] + materials() + extra + loads

    def _info(self, surface, stride):
        return self._surface(surface, stride) + ["--model", "hertz"] + materials() + ["--loads", "0.0001", "--info"]

    def _levels(self, surface, model):
        return self._surface(surface, 1) + ["--model", model] + materials() + ["--loads", f"{SEED_FIG5_LOAD:g}",
                                                                               "--levels"]

    def _everything(self):
        out = []
        for key, _, _, _ in SURFACES:
            out += [self._contact(key, 1, m, load_range(LOAD_RANGE)) for m in MODELS]
            out += [self._levels(key, m) for m in MULTISCALE]
            out += [self._contact(key, k, m, ["--loads", f"{SEED_FIG5_LOAD:g}"]) for k in STRIDES
                    for m in MULTISCALE + ["greenwoodWilliamson", "greenwoodWilliamsonJG"]]
            out += [self._info(key, k) for k in (1, 2)]
            out += [self._contact(key, 1, m, load_range(MONOTONE_LOADS)) for m in ("jgh", "jghConsistent")]
        out += [self._contact("standin", k, m, load_range(LOAD_RANGE)) for k in STRIDES
                for m in ("jacksonGreen", "greenwoodWilliamson")]
        for path in self.synthetic.values():
            out += [self._info(path, 1)] + [self._contact(path, 1, m, ["--loads", f"{AT:g}"])
                                            for m in ("hertz", "jacksonGreen")]
        out += [self._contact(SEED, 1, "greenwoodWilliamson", load_range(LOAD_RANGE))]
        out += [self._info(s, 1) for s in self.spectra]
        return out

    # What the tables read.
    def curve(self, surface, model, stride=1, loads=LOAD_RANGE):
        return Curve(self.runs.rows(self._contact(surface, stride, model, load_range(loads)))[0])

    def area(self, surface, model, stride=1, load=SEED_FIG5_LOAD):
        """A_r/A_n at one load (the Fig. 5 load unless given)."""
        rows = self.runs.rows(self._contact(surface, stride, model, ["--loads", f"{load:g}"]))[0]
        return float(rows[0]["area_fraction"])

    def pressure(self, surface, model, load=AT):
        rows = self.runs.rows(self._contact(surface, 1, model, ["--loads", f"{load:g}"]))[0]
        return float(rows[0]["contact_pressure_per_Eprime"])

    def levels(self, surface, model):
        """The Fig. 5 trace: (level, frequency [1/m], A_i/A_n after level i) of every level."""
        rows = self.runs.rows(self._levels(surface, model))[0]
        return [(int(r["level"]), float(r["frequency"]), float(r["area_fraction"])) for r in rows]

    def info(self, surface, stride=1):
        """The surface's parameters as the core prints them (--info): sigma (rms height), eta, R,
        sigma_s, alpha (McCool), D, G (the fractal fit)."""
        return parse_info(self.runs.rows(self._info(surface, stride))[1])

    def rms_slope(self, surface, stride=1):
        """The profile's rms slope sqrt(m2): the core's areal rms gradient h' over sqrt 2."""
        if surface in self.spectra:
            s = self.rc.Spectrum.read(self.spectra[surface])
        else:
            p = self.rc.read_profile(self.paths.get(surface, surface))
            s = self.rc.Spectrum.from_profile(p.subsampled(stride) if stride != 1 else p)
        return self.rc.areal_rms_gradient(s) / math.sqrt(2.0)

    def spacing(self, surface):
        """The profile's sample spacing dx [m] (the core's reader)."""
        return self.rc.read_profile(self.paths[surface]).spacing


def parse_info(text):
    def value(pattern, needed=True):
        m = re.search(pattern, text)
        if not m and needed:
            raise SystemExit(f"validation: paper: --info printed no {pattern}:\n{text}")
        return float(m.group(1)) if m else float("nan")
    return {"sigma": value(r"rms height \(Parseval\): (\S+) m"), "eta": value(r"McCool: eta = (\S+) 1/m"),
            "R": value(r"R = (\S+) m,"), "sigma_s": value(r"sigma_s = (\S+) m"), "alpha": value(r"alpha = (\S+)"),
            "D": value(r"fractal fit: D = (\S+),", False), "G": value(r"G = (\S+) m", False)}


def seed_surface(ctx, runs, name, parameters):
    """A spectrum file whose McCool parameters (the core's, --info) are sigma, eta, R =
    `parameters`: two levels f and 1000 f with powers 1 and x/1000^2. eta R sigma does not change
    when the levels or amplitudes are scaled, so x is found first (bisection on the core's eta R
    sigma), then the amplitudes are scaled to sigma and the levels to eta; R follows."""
    rc = ctx.rc()
    sigma, eta, R = parameters
    path = ctx.scratch_path("paper", f"seed-{name}.spectrum")

    def shape(x, f_scale=1.0, a_scale=1.0):
        spectra.write(path, [f_scale, 1000.0 * f_scale], [a_scale, a_scale * math.sqrt(x) / 1000.0],
                      "validation/studies/paper.py")
        s = rc.Spectrum.read(path)
        i = parse_info(runs.run(["--spectrum", path, "--model", "hertz"] + materials() +
                                 ["--loads", "0.0001", "--info"])[1])
        return s, i

    def invariant(x):
        s, i = shape(x)
        return i["eta"] * i["R"] * math.sqrt(s.variance())

    lo, hi = 1e-9, 1.0  # eta R sigma grows with x on (0, 1)
    target = eta * R * sigma
    if not invariant(lo) < target < invariant(hi):
        raise SystemExit(f"validation: paper: no two-level spectrum has the McCool parameters {parameters}")
    while hi / lo - 1 > 1e-12:
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if invariant(mid) < target else (lo, mid)
    s, i = shape(lo)
    shape(lo, math.sqrt(eta / i["eta"]), sigma / math.sqrt(s.variance()))
    return path


def solve(ctx):
    """Nothing: the study's curves are the CLI's models, made again by outputs."""
    return 0


def outputs(ctx):
    from . import paperTables
    return paperTables.outputs(ctx, Paper(ctx))
