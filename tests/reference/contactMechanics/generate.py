# SPDX-License-Identifier: GPL-3.0-or-later
"""Reference contact solutions from ContactMechanics (ContactEngineering), for the project's
boundary-element solver (issue 19, item 2).

ContactMechanics is NOT part of this project and is not committed here. Give the path of a
checkout of its repository (the folder that holds the package folder `ContactMechanics/`):

    CONTACTMECHANICS_PATH=/path/to/ContactMechanics \
    PYTHONPATH=build/python python3 tests/reference/contactMechanics/generate.py [options]

or `--cm /path/to/ContactMechanics`. Its full install needs muGrid/muFFT, NuMPI and
SurfaceTopography; none of them is needed by the two things used here, which run unchanged:
  - ContactMechanics/Optimization/ConstrainedConjugateGradients.py:
    constrained_conjugate_gradients (Polonsky & Keer CCG, with its plastic `hardness` cap);
  - ContactMechanics/FFTElasticHalfSpace.py: PeriodicFFTElasticHalfSpace and
    FreeFFTElasticHalfSpace (their Green's functions, evaluate_disp/evaluate_force).
The modules they import from those packages are replaced by the minimal serial shims below
(`install_shims`): muGrid's FFTEngine by numpy's FFT with muGrid's layout and normalisation
(documented at the top of FFTElasticHalfSpace.py), NuMPI's Reduction by numpy reductions, and
SurfaceTopography's `doi` decorator by a no-op and its Topography by a holder of the heights.
The package's own __init__ (which imports everything, muGrid included) is not executed: a bare
package module pointing at the checkout's folder is registered instead.

An independent substrate (`NumpyHalfSpace`: the kernels exactly as the project's
src/core/roughContact/bem/HalfSpaceOperator.hpp documents them, in numpy) is used by
`--check-kernels` to verify ContactMechanics' half-spaces (run through the shims) against the
project's conventions.

The surfaces are made by the project itself (roughcontact, the Python bindings) so that the
C++ test can rebuild identical heights: Spectrum::powerLaw + synthesizeIsotropic, and the X3P
map data/x3p-2.x3p.
"""

import argparse
import csv
import importlib
import os
import sys
import time
import types

import numpy as np

# ---------------------------------------------------------------------------------------------
# The recipes (README.md states them; the C++ test rebuilds the same heights).
E_PRIME = 2.2e11                      # Pa: the E' of the brief (README.md: Units)
LENGTH = 1e-3                         # m: side L of the periodic surfaces
BM = 3.2e-2                           # Spectrum::powerLaw(bm, m, fmin, fmax, L): beta = bm f^-m
M_EXPONENT = 1.3                      # m = H + 1/2, Hurst exponent H = 0.8
F_MIN = 1.0 / LENGTH                  # 1/m
F_MAX = 128.0 / LENGTH                # 1/m: the Nyquist frequency of the 256 grid
SURFACES = (("powerlaw256", 256, 1), ("powerlaw512", 512, 2))   # name, n, seed
LOADS = (1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2)                     # p/E'
HARDNESS_OVER_EPRIME = 0.02           # H = 0.02 E' = 4.4e9 Pa (0.2 E' h', h' ~ 0.1)
X3P_PATH = "data/x3p-2.x3p"
X3P_LOADS = (1e-4, 1e-3, 1e-2)
REL_TOL = 1e-10
CSV_HEADER = ["surface", "n", "periodic", "load", "hardness", "contact_fraction", "mean_gap",
              "mean_contact_pressure", "plastic_fraction", "iterations", "tolerance"]


# ---------------------------------------------------------------------------------------------
# Shims for ContactMechanics' dependencies (serial, numpy only).
class _Field:
    def __init__(self, shape, dtype):
        self.p = np.zeros(shape, dtype=dtype)


class _Cpp:
    def __init__(self, shape):
        self.nb_fourier_subdomain_grid_pts = (shape[0] // 2 + 1,) + tuple(shape[1:])
        self.fourier_subdomain_locations = (0,) * len(shape)


class FFTEngine:
    """muGrid.FFTEngine, serial, on numpy: the half-complex axis is the first one
    (fourier <-> np.fft.rfft2(a, axes=(1, 0))), fft and ifft unnormalised, normalisation 1/N
    (FFTElasticHalfSpace.py, module docstring)."""

    def __init__(self, nb_domain_grid_pts, communicator=None):
        self.nb_domain_grid_pts = tuple(int(n) for n in nb_domain_grid_pts)
        self.nb_subdomain_grid_pts = self.nb_domain_grid_pts
        self.subdomain_locations = (0,) * len(self.nb_domain_grid_pts)
        self._cpp = _Cpp(self.nb_domain_grid_pts)
        self.normalisation = 1.0 / float(np.prod(self.nb_domain_grid_pts))
        self._axes = tuple(reversed(range(len(self.nb_domain_grid_pts))))

    def real_space_field(self, name):
        return _Field(self.nb_domain_grid_pts, float)

    def fourier_space_field(self, name):
        return _Field(self._cpp.nb_fourier_subdomain_grid_pts, complex)

    def fft(self, real, fourier):
        fourier.p[...] = np.fft.rfftn(real.p, axes=self._axes)

    def ifft(self, fourier, real):
        real.p[...] = np.fft.irfftn(fourier.p, s=[self.nb_domain_grid_pts[a] for a in self._axes],
                                    axes=self._axes) / self.normalisation


class Reduction:
    """NuMPI.Tools.Reduction, serial."""

    def __init__(self, communicator=None):
        pass

    def sum(self, x, *args, **kwargs):
        return np.sum(x, *args, **kwargs)

    def max(self, x, *args, **kwargs):
        return np.max(x, *args, **kwargs)

    def min(self, x, *args, **kwargs):
        return np.min(x, *args, **kwargs)

    def mean(self, x, *args, **kwargs):
        return np.mean(x, *args, **kwargs)

    def dot(self, a, b):
        return np.dot(a, b)


class Topography:
    """SurfaceTopography.Topography reduced to what constrained_conjugate_gradients reads."""

    def __init__(self, heights, physical_sizes=None):
        self._h = np.asarray(heights)
        self.nb_grid_pts = self._h.shape
        self.nb_subdomain_grid_pts = self._h.shape
        self.physical_sizes = physical_sizes

    def heights(self):
        return self._h

    def rms_height_from_area(self):
        return float(np.sqrt(np.mean((self._h - self._h.mean()) ** 2)))


def _doi(*args, **kwargs):
    def decorate(f):
        return f
    return decorate


def install_shims(cm_root):
    """Registers the shims and a bare `ContactMechanics` package on cm_root/ContactMechanics;
    returns (constrained_conjugate_gradients, FFTElasticHalfSpace module)."""
    pkg_dir = os.path.join(cm_root, "ContactMechanics")
    if not os.path.isfile(os.path.join(pkg_dir, "Optimization", "ConstrainedConjugateGradients.py")):
        sys.exit(f"no ContactMechanics checkout at {cm_root} (ContactMechanics/Optimization/"
                 "ConstrainedConjugateGradients.py not found)")
    mugrid = types.ModuleType("muGrid")
    mugrid.FFTEngine = FFTEngine
    mugrid.Communicator = lambda comm=None: None
    numpi = types.ModuleType("NuMPI")
    numpi_tools = types.ModuleType("NuMPI.Tools")
    numpi_tools.Reduction = Reduction
    numpi.Tools = numpi_tools
    st = types.ModuleType("SurfaceTopography")
    st_support = types.ModuleType("SurfaceTopography.Support")
    st_support.doi = _doi
    st.Support = st_support
    st.Topography = Topography
    for name, mod in (("muGrid", mugrid), ("NuMPI", numpi), ("NuMPI.Tools", numpi_tools),
                      ("SurfaceTopography", st), ("SurfaceTopography.Support", st_support)):
        sys.modules[name] = mod
    pkg = types.ModuleType("ContactMechanics")
    pkg.__path__ = [pkg_dir]
    sys.modules["ContactMechanics"] = pkg
    ccg = importlib.import_module("ContactMechanics.Optimization.ConstrainedConjugateGradients")
    hs = importlib.import_module("ContactMechanics.FFTElasticHalfSpace")
    return ccg.constrained_conjugate_gradients, hs


# ---------------------------------------------------------------------------------------------
# The project's kernels in numpy (HalfSpaceOperator.hpp), to check ContactMechanics' against.
class NumpyHalfSpace:
    """u = K p on an nx x ny grid (arrays indexed [ix, iy]), spacings dx, dy, modulus E'.
    Periodic: u(q) = 2 p(q)/(E'|q|), mean 0. Non-periodic: Love's rectangle, padded 2nx x 2ny."""

    def __init__(self, nx, ny, dx, dy, eprime, periodic):
        self.nx, self.ny, self.dx, self.dy, self.periodic = nx, ny, dx, dy, periodic
        if periodic:
            qx = 2 * np.pi * np.fft.fftfreq(nx, dx)
            qy = 2 * np.pi * np.fft.rfftfreq(ny, dy)
            q = np.sqrt(qx[:, None] ** 2 + qy[None, :] ** 2)
            with np.errstate(divide="ignore"):
                self.kq = np.where(q > 0, 2.0 / (eprime * q), 0.0)
        else:
            mx, my = 2 * nx, 2 * ny
            jx = np.arange(mx)
            jy = np.arange(my)
            ix = np.where(jx < nx, jx, jx - mx).astype(float)
            iy = np.where(jy < ny, jy, jy - my).astype(float)
            X = ix[:, None] * dx
            Y = iy[None, :] * dy
            k = self.love(X, Y, 0.5 * dx, 0.5 * dy, 1.0, eprime)
            k[nx, :] = 0.0
            k[:, ny] = 0.0
            self.kq = np.fft.rfft2(k)

    @staticmethod
    def love(x, y, a, b, p, eprime):
        def term(x, y):
            with np.errstate(divide="ignore", invalid="ignore"):
                return np.where(x == 0.0, 0.0, x * np.arcsinh(y / np.abs(x)))

        def F(x, y):
            return term(x, y) + term(y, x)
        return p / (np.pi * eprime) * (F(x + a, y + b) - F(x + a, y - b) - F(x - a, y + b) + F(x - a, y - b))

    def apply(self, p):
        if self.periodic:
            return np.fft.irfft2(np.fft.rfft2(p) * self.kq, s=p.shape)
        pad = np.zeros((2 * self.nx, 2 * self.ny))
        pad[:self.nx, :self.ny] = p
        return np.fft.irfft2(np.fft.rfft2(pad) * self.kq, s=pad.shape)[:self.nx, :self.ny]


def check_kernels(hs):
    """ContactMechanics' half-spaces (through the shims) against NumpyHalfSpace: the periodic
    one up to its mean (q = 0) mode, the free one exactly. Returns the relative differences."""
    rng = np.random.default_rng(7)
    out = {}
    for (nx, ny, dx, dy) in ((64, 48, 1.0e-6, 1.5e-6), (40, 40, 2.0e-7, 2.0e-7)):
        p = rng.random((nx, ny)) * 1e8
        area = dx * dy
        ref = NumpyHalfSpace(nx, ny, dx, dy, E_PRIME, True).apply(p)
        sub = hs.PeriodicFFTElasticHalfSpace((nx, ny), E_PRIME, physical_sizes=(nx * dx, ny * dy))
        u = sub.evaluate_disp(-p * area)          # ContactMechanics: forces, compressive < 0
        u -= u.mean()
        out[f"periodic {nx}x{ny}"] = float(np.max(np.abs(u - ref)) / np.max(np.abs(ref)))
        ref = NumpyHalfSpace(nx, ny, dx, dy, E_PRIME, False).apply(p)
        sub = hs.FreeFFTElasticHalfSpace((nx, ny), E_PRIME, physical_sizes=(nx * dx, ny * dy))
        u = sub.evaluate_disp(-p * area)
        out[f"free {nx}x{ny}"] = float(np.max(np.abs(u - ref)) / np.max(np.abs(ref)))
        # force -> displacement -> force round trip of the periodic substrate (mean excluded)
        sub = hs.PeriodicFFTElasticHalfSpace((nx, ny), E_PRIME, physical_sizes=(nx * dx, ny * dy))
        f = -(p - p.mean()) * area
        back = sub.evaluate_force(sub.evaluate_disp(f))
        out[f"periodic round trip {nx}x{ny}"] = float(np.max(np.abs(back - f)) / np.max(np.abs(f)))
    # "free" compares Love's closed form in the project's asinh form with ContactMechanics' log
    # form over every offset of the grid (the same p on the same grid).
    return out


# ---------------------------------------------------------------------------------------------
def solve_cm(ccg, hs, heights_xy, dx, dy, periodic, load, hardness=None, rel_tol=None,
             maxiter=100000):
    """One ContactMechanics CCG solve at mean pressure load*E' on heights [m] indexed [ix, iy]
    (peaks positive). Returns a dict of the reference quantities."""
    rel_tol = REL_TOL if rel_tol is None else rel_tol
    nx, ny = heights_xy.shape
    sizes = (nx * dx, ny * dy)
    if periodic:
        sub = hs.PeriodicFFTElasticHalfSpace((nx, ny), E_PRIME, physical_sizes=sizes)
    else:
        sub = hs.FreeFFTElasticHalfSpace((nx, ny), E_PRIME, physical_sizes=sizes)
    area = dx * dy
    P = load * E_PRIME
    W = P * nx * ny * area                           # total force [N]
    h = np.ascontiguousarray(heights_xy, dtype=float)
    rms = float(np.sqrt(np.mean((h - h.mean()) ** 2)))
    pentol = rel_tol * rms                           # m
    forcetol = rel_tol * P * area                    # N per cell
    kwargs = dict(external_force=W, pentol=pentol, forcetol=forcetol, thermotol=rel_tol,
                  maxiter=maxiter)
    if hardness is not None:
        kwargs["hardness"] = hardness * area         # their cap is a force per cell
    t0 = time.time()
    res = ccg(sub, h, **kwargs)
    seconds = time.time() - t0
    f = np.asarray(res.jac)                          # force per cell, compressive > 0
    p = f / area
    u = np.asarray(res.x)[:nx, :ny]
    g = u - h - res.offset                           # separation (their sign: u - h - offset)
    contact = p > 0
    sep = np.where(contact, 0.0, np.maximum(g, 0.0))
    frac = float(np.mean(contact))
    out = dict(converged=bool(res.success), iterations=int(res.nit), seconds=seconds,
               contact_fraction=frac, mean_gap=float(np.mean(sep)),
               mean_contact_pressure=P / frac if frac > 0 else float("nan"),
               total_pressure_error=float(p.mean() / P - 1.0),
               max_penetration_outside=float(max(0.0, -np.min(np.where(contact, 0.0, g)))) / rms,
               rms=rms, pentol=pentol, forcetol=forcetol, message=res.message)
    if hardness is not None:
        at_cap = p >= hardness * (1.0 - rel_tol)
        out["plastic_fraction"] = float(np.mean(at_cap))
        out["plastic_fraction_cm"] = float(np.mean(res.plastic)) if hasattr(res, "plastic") else float("nan")
    else:
        out["plastic_fraction"] = 0.0
    # the elastic contact's gap on the contact set (only the non-flowing part for the capped)
    inner = contact & ~(p >= hardness * (1.0 - rel_tol)) if hardness is not None else contact
    out["rms_gap_on_contact"] = float(np.sqrt(np.mean(g[inner] ** 2))) / rms if inner.any() else 0.0
    return out


def project_surfaces():
    import roughcontact as rc
    spectrum = rc.Spectrum.power_law(BM, M_EXPONENT, F_MIN, F_MAX, LENGTH)
    out = []
    for name, n, seed in SURFACES:
        s = rc.synthesize_isotropic(spectrum, n, seed)
        out.append((name, n, seed, s))
    return out


def run_project(args, rc):
    """The project's solver (roughcontact.BoundaryElement) on the same heights as the reference
    (the mean-only periodic heights; the X3P map with its plane removed), in reference.csv's
    format. BoundaryElement detrends what it is given: see README.md."""
    rows = []
    mat = rc.ContactMaterials.from_reduced_modulus(E_PRIME)
    only = set(args.only.split(",")) if args.only else None
    cases = []
    for name, n, seed, s in project_surfaces():
        if only and name not in only:
            continue
        surf = s.detrended() if args.plane_removed else s
        h = np.asarray(surf.heights, dtype=float)
        cases.append((name, n, True, rc.ArealSurface(h - h.mean(), s.dx, s.dy), LOADS,
                      (None, HARDNESS_OVER_EPRIME * E_PRIME)))
    if not only or "x3p-2" in only:
        s = rc.read_areal(args.x3p).detrended()
        cases.append(("x3p-2", s.nx, False, s, X3P_LOADS, (None,)))
    for name, n, periodic, surf, loads, hardnesses in cases:
        for H in hardnesses:
            t0 = time.time()
            be = rc.BoundaryElement(surf, mat, periodic=periodic, hardness=H, tolerance=REL_TOL,
                                    max_iterations=1000000)
            c = be.curve(np.asarray(loads) * E_PRIME)
            print(f"{name} H {H}: {time.time() - t0:.1f} s", flush=True)
            for i, load in enumerate(loads):
                frac = float(c["area_fraction"][i])
                rows.append([name, n, "true" if periodic else "false", repr(load), "" if H is None else repr(H),
                             f"{frac:.15g}", f"{float(c['mean_separation'][i]):.15g}",
                             f"{load * E_PRIME / frac:.15g}", f"{float(c['plastic_fraction'][i]):.15g}",
                             int(c["iterations"][i]), repr(REL_TOL)])
    return rows


def read_rows(path):
    with open(path) as fh:
        return list(csv.DictReader(fh))


def compare(a_path, b_path):
    """A markdown table of b relative to a, point by point (contact fraction, mean gap, mean
    contact pressure: relative differences; plastic fraction: absolute; also in cells)."""
    a = {(r["surface"], r["load"], r["hardness"]): r for r in read_rows(a_path)}
    print("| surface | p/E' | H [Pa] | A_r/A_n (a) | rel. diff | cells | mean gap (a) [m] | rel. diff "
          "| p_c rel. diff | plastic (a) | plastic cells diff |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in read_rows(b_path):
        k = (r["surface"], r["load"], r["hardness"])
        if k not in a:
            continue
        q = a[k]
        n = int(q["n"])
        cells = n * n if q["periodic"] == "true" else None
        fa, fb = float(q["contact_fraction"]), float(r["contact_fraction"])
        ga, gb = float(q["mean_gap"]), float(r["mean_gap"])
        pa, pb = float(q["mean_contact_pressure"]), float(r["mean_contact_pressure"])
        la, lb = float(q["plastic_fraction"]), float(r["plastic_fraction"])
        if cells is None:   # the X3P map: nx x ny from the surface itself
            cells = n * n
        print(f"| {r['surface']} | {float(r['load']):g} | {r['hardness'] or '-'} | {fa:.6g} | {fb / fa - 1:+.2e} | "
              f"{round((fb - fa) * cells):+d} | {ga:.6g} | {gb / ga - 1:+.2e} | {pb / pa - 1:+.2e} | "
              f"{la:.6g} | {round((lb - la) * cells):+d} |")


def main():
    global REL_TOL
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cm", default=os.environ.get("CONTACTMECHANICS_PATH"),
                    help="a ContactMechanics checkout (default: $CONTACTMECHANICS_PATH)")
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "reference.csv"))
    ap.add_argument("--x3p", default=X3P_PATH)
    ap.add_argument("--only", default=None, help="comma-separated surface names (powerlaw256, powerlaw512, x3p-2)")
    ap.add_argument("--check-kernels", action="store_true", help="only compare the half-spaces and exit")
    ap.add_argument("--plane-removed", action="store_true",
                    help="solve the periodic surfaces with their least-squares plane removed instead of "
                         "only their mean (for the comparison with the project's current build); "
                         "writes to --out as given")
    ap.add_argument("--log", default=None, help="a CSV of every solve's diagnostics")
    ap.add_argument("--project", action="store_true",
                    help="run the project's solver (roughcontact) instead of ContactMechanics; no --cm needed")
    ap.add_argument("--tolerance", type=float, default=REL_TOL,
                    help="the relative convergence tolerance (README.md: what it bounds in each solver)")
    ap.add_argument("--compare", nargs=2, metavar=("A", "B"), help="print B relative to A (two CSVs) and exit")
    args = ap.parse_args()
    REL_TOL = args.tolerance
    if args.compare:
        compare(*args.compare)
        return
    if args.project:
        import roughcontact as rc
        rows = run_project(args, rc)
        with open(args.out, "w", newline="") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(CSV_HEADER)
            w.writerows(rows)
        return
    if not args.cm:
        sys.exit("give the ContactMechanics checkout with --cm or CONTACTMECHANICS_PATH")
    ccg, hs = install_shims(args.cm)
    if args.check_kernels:
        for k, v in check_kernels(hs).items():
            print(f"{k}: max relative difference {v:.3e}")
        return
    import roughcontact as rc
    only = set(args.only.split(",")) if args.only else None
    rows = []
    diag = []

    def record(name, n, periodic, load, H, r):
        rows.append([name, n, "true" if periodic else "false", repr(load), "" if H is None else repr(H),
                     f"{r['contact_fraction']:.15g}", f"{r['mean_gap']:.15g}",
                     f"{r['mean_contact_pressure']:.15g}", f"{r['plastic_fraction']:.15g}",
                     r["iterations"], repr(REL_TOL)])
        d = dict(surface=name, n=n, load=load, hardness=H)
        d.update(r)
        diag.append(d)
        print(f"{name} load {load:g} H {H} -> frac {r['contact_fraction']:.9g} gap {r['mean_gap']:.9g} "
              f"plastic {r['plastic_fraction']:.6g} it {r['iterations']} {r['seconds']:.1f}s "
              f"conv {r['converged']} loaderr {r['total_pressure_error']:.2e} "
              f"pen_out {r['max_penetration_outside']:.2e} gap_on_c {r['rms_gap_on_contact']:.2e}", flush=True)

    for name, n, seed, s in project_surfaces():
        if only and name not in only:
            continue
        surf = s.detrended() if args.plane_removed else s
        h = np.asarray(surf.heights, dtype=float)          # (ny, nx)
        h = (h - h.mean()).T                                # CM's [ix, iy]
        for H in (None, HARDNESS_OVER_EPRIME * E_PRIME):
            for load in LOADS:
                r = solve_cm(ccg, hs, h, s.dx, s.dy, True, load, H)
                record(name, n, True, load, H, r)
    if not only or "x3p-2" in only:
        s = rc.read_areal(args.x3p).detrended()
        h = np.asarray(s.heights, dtype=float).T
        for load in X3P_LOADS:
            r = solve_cm(ccg, hs, h, s.dx, s.dy, False, load, None)
            record("x3p-2", s.nx, False, load, None, r)
    with open(args.out, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(CSV_HEADER)
        w.writerows(rows)
    if args.log:
        keys = sorted({k for d in diag for k in d})
        with open(args.log, "w", newline="") as fh:
            w = csv.DictWriter(fh, keys, lineterminator="\n")
            w.writeheader()
            w.writerows(diag)


if __name__ == "__main__":
    main()
