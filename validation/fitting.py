# SPDX-License-Identifier: GPL-3.0-or-later
"""Fitting the default law, fittedElastoPlastic, as the core runs it: the law evaluated by the
core (roughcontact.fitted_elasto_plastic with a FittedElastoPlasticConstants of one's choosing),
never a copy of its formula; the points it is held to; a Nelder-Mead minimax of |law/exact - 1|.
"""
import math

import numpy

BAND = 0.25  # within 25 %: |law/exact - 1| <= 0.25


class Points:
    """Exact answers the law is held to, as arrays: P [Pa], sigma [m], m, W, E' [Pa], H [Pa] (nan:
    elastic), the heights' shrunk skewness s, the first level's share s1 (nan: none), the exact
    h_c/k_s [1/m]; and per point a dict of what else it is (surface, regime, role, x, ...)."""

    FIELDS = ["P", "sigma", "m", "w", "E", "H", "s", "s1", "exact"]

    def __init__(self, rows):
        self.rows = list(rows)
        for f in self.FIELDS:
            setattr(self, f, numpy.array([numpy.nan if r[f] is None else float(r[f]) for r in self.rows]))
        # x as the law takes it: P/(sqrt(pi) E' m) (h' = sqrt(pi) m for Gaussian slopes)
        self.xl = self.P / (math.sqrt(math.pi) * self.E * self.m)

    def where(self, keep):
        return Points([r for r in self.rows if keep(r)])

    def __len__(self):
        return len(self.rows)


def constants(rc, values=None, base=None):
    """A FittedElastoPlasticConstants: base's (default: the built-in ones) with `values` ({name: v})."""
    c = rc.FittedElastoPlasticConstants()
    if base is not None:
        for name in rc.FittedElastoPlasticConstants.names():
            setattr(c, name, getattr(base, name))
    for name, v in (values or {}).items():
        setattr(c, name, float(v))
    return c


def law(rc, c, pts):
    """h_c/k_s of the core's law with constants c at every point."""
    return rc.fitted_elasto_plastic(pts.P, pts.sigma, pts.m, pts.w, pts.E, pts.H, pts.s, pts.s1, c)


def ratios(rc, c, pts):
    return law(rc, c, pts) / pts.exact


def residuals(rc, c, pts):
    """ln(law/exact) at each point; 10 where the law gives no finite positive value."""
    v = law(rc, c, pts)
    ok = numpy.isfinite(v) & (v > 0)
    return numpy.where(ok, numpy.log(numpy.where(ok, v, 1.0) / pts.exact), 10.0)


def misses(rc, c, pts):
    """|law/exact - 1| at each point: what the fit makes small; a miss below counts as much as
    the same miss above, as "within 25 %" counts them."""
    return numpy.abs(numpy.expm1(residuals(rc, c, pts)))


def nelder_mead(f, x0, step=0.1, iterations=4000):
    """The minimum of f from x0 (a simplex of steps of `step` of each coordinate); deterministic."""
    n = len(x0)
    simplex = [numpy.array(x0, float)]
    for i in range(n):
        y = numpy.array(x0, float)
        y[i] = y[i] * (1 + step) if y[i] != 0 else step
        simplex.append(y)
    values = [f(s) for s in simplex]
    for _ in range(iterations):
        order = numpy.argsort(values)
        simplex = [simplex[i] for i in order]
        values = [values[i] for i in order]
        centre = numpy.mean(simplex[:-1], axis=0)
        xr = centre + (centre - simplex[-1])
        fr = f(xr)
        if fr < values[0]:
            xe = centre + 2.0 * (centre - simplex[-1])
            fe = f(xe)
            simplex[-1], values[-1] = (xe, fe) if fe < fr else (xr, fr)
        elif fr < values[-2]:
            simplex[-1], values[-1] = xr, fr
        else:
            xc = centre + 0.5 * (simplex[-1] - centre)
            fc = f(xc)
            if fc < values[-1]:
                simplex[-1], values[-1] = xc, fc
            else:
                simplex = [simplex[0] + 0.5 * (s - simplex[0]) for s in simplex]
                values = [f(s) for s in simplex]
        if abs(values[-1] - values[0]) < 1e-13 * max(1.0, abs(values[0])):
            break
    i = int(numpy.argmin(values))
    return simplex[i], values[i]


def minimax(rc, c, free, pts, valid=lambda c: True, top=64, miss=misses):
    """c with the constants named in `free` fitted: a minimax of |law/exact - 1| over pts,
    approached through q-norms of increasing q (4, 8, ... up to top), three Nelder-Mead runs
    each; `valid(c)` refuses constants outside the law's domain. miss(rc, c, pts): the misses
    made small (default: the loading law's, misses)."""
    def objective(y, q):
        z = constants(rc, dict(zip(free, y)), c)
        if not valid(z):
            return 1e9
        return float(numpy.mean(miss(rc, z, pts) ** q) ** (1.0 / q))
    y = numpy.array([getattr(c, name) for name in free], float)
    for q in (q for q in (4, 8, 16, 32, 64) if q <= top):
        for _ in range(3):
            y, _ = nelder_mead(lambda v: objective(v, q), y)
    return constants(rc, dict(zip(free, y)), c)


def worst(rc, c, pts):
    """The largest |law/exact - 1| over pts: what the minimax makes small."""
    return float(numpy.max(misses(rc, c, pts)))


def within(rc, c, pts):
    """How many points the law holds within BAND."""
    return int(numpy.sum(misses(rc, c, pts) <= BAND))
