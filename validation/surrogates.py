# SPDX-License-Identifier: GPL-3.0-or-later
"""Height maps made from a seed and kept as NumPy files in the scratch folder: surrogate surfaces
by iterated rank ordering (the skewed surfaces of the skewness study, the X3P map's surrogates),
and what the laws take of such a map (sigma, m, W, s1, the heights' skewness), as the CLI takes
them from `--areal PATH --dx DX --dy DY --direction both`.

A map is made again from its definition, never committed: `heights` names its file by a digest
of the definition, makes it when it is not there (deterministically: the same numpy makes the
same bits) and keeps it for the next run or check.
"""
import hashlib
import os
import threading


def rank_ordered_surrogate(start, amplitude, ranked, iterations, rank_first=False):
    """Iterated rank ordering (Schreiber & Schmitz, Phys. Rev. Lett. 77 (1996) 635: the iterative
    amplitude-adjusted Fourier transform): `iterations` times the two-dimensional Fourier
    amplitudes `amplitude` (of numpy.fft.rfft2) with the surface's own phases, then the sorted
    heights `ranked` put in the surface's order; from `start` (ranked first with rank_first). Ends
    on the ranks: the heights' distribution exactly, the spectrum to the iterations' convergence.

    The order of the heights is found from the last one (a stable sort of nearly sorted heights,
    several times faster); without ties it is the only order, so the surface is the one a stable
    sort of the heights as they stand gives, to the bit, and with ties that sort is taken."""
    import numpy
    order = numpy.empty(start.size, dtype=numpy.int64)
    last = None

    def with_ranks(x):
        nonlocal last
        flat = x.ravel()
        p = numpy.argsort(flat, kind="stable") if last is None else last[numpy.argsort(flat[last], kind="stable")]
        s = flat[p]
        if (s[1:] == s[:-1]).any():
            p = numpy.argsort(flat, kind="stable")
        last = p
        order[p] = numpy.arange(x.size)
        return ranked[order].reshape(start.shape)
    x = with_ranks(start) if rank_first else start
    for _ in range(iterations):
        f = numpy.fft.rfft2(x)
        x = with_ranks(numpy.fft.irfft2(amplitude * f / numpy.maximum(numpy.abs(f), 1e-300), s=start.shape))
    return x


def heights(ctx, study, name, definition, make):
    """The scratch file (.npy) of a height map: `definition` (text: everything the map is made
    from) names it with `name`; make() gives the heights [m] when the file is not there yet."""
    import numpy
    digest = hashlib.sha256(definition.encode()).hexdigest()[:12]
    path = ctx.scratch_path(study, f"{name}-{digest}.npy")
    if not os.path.exists(path):
        temporary = f"{path[:-len('.npy')]}.{os.getpid()}-{threading.get_ident()}.partial.npy"
        numpy.save(temporary, make())
        os.replace(temporary, path)
    return path


def file_digest(path):
    """A file's SHA-256 (a spectrum file's, for a definition)."""
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


class LawInputs:
    """What the default law takes of a surface (any roughcontact.SurfaceSpec: a map, a profile, two
    profiles across and along a lay), as the core reads it: sigma [m], m (the mean absolute slope),
    the line scans' bandwidth ratio W and first level's share s1, h' (the core's areal rms gradient
    of that spectrum), the heights' skewness, its spread by chance and the shrunk skewness the
    default law takes; and the Hurst exponent of the spectrum's finest octave H_f its unloading
    branch takes (fine_hurst; NaN: none), which values() leaves out (no study's table of
    surfaces unloads them)."""

    FIELDS = ["sigma", "m", "bandwidth", "s1", "gradient", "skewness", "spread", "shrunk"]

    def __init__(self, rc, spec):
        r, k, levels = spec.roughness(), spec.skewness(), spec.read_spectrum()
        self.sigma, self.m = r.sigma, r.mean_absolute_slope
        self.bandwidth, self.s1 = rc.spectral_bandwidth_ratio(levels), rc.first_level_share(levels)
        self.gradient = rc.areal_rms_gradient(levels)
        hf = rc.fine_hurst_exponent(levels)
        self.fine_hurst = float("nan") if hf is None else hf
        if k is None:  # a spectrum: Gaussian heights, skewness 0 as the core's equivalentSkewness takes it
            self.skewness, self.spread, self.shrunk = 0.0, 0.0, 0.0
        else:
            self.skewness, self.spread, self.shrunk = k.skewness, k.spread, rc.shrunk_skewness(k)

    def values(self):
        """What the laws take of the surface as text that reads back to the same doubles (a row of
        a study's table of its surfaces)."""
        return {f: repr(float(getattr(self, f))) for f in self.FIELDS}

    def point(self, P, pair, exact=1.0, **more):
        """A row of fitting.Points: the default law's inputs at the pressure P [Pa] for the Pair."""
        return {"P": P, "sigma": self.sigma, "m": self.m, "w": self.bandwidth, "E": pair.Eprime, "H": pair.hardness,
                "s": self.shrunk, "s1": self.s1, "hf": self.fine_hurst, "exact": exact, **more}


class Areal(LawInputs):
    """A height map as the laws take it (the core's SurfaceSpec.areal, direction both unless told).
    direction "x" or "y": what the rows or the columns alone tell."""

    def __init__(self, ctx, path, dx, dy=None, direction="both"):
        rc = ctx.rc()
        self.path, self.dx, self.dy = path, dx, dy if dy is not None else dx
        super().__init__(rc, rc.SurfaceSpec.areal(path, dx=dx, dy=dy, direction=direction))

    @classmethod
    def stored(cls, row, dx, dy=None):
        """The same from a row of values() (no file behind it: check reads a study's table of its
        surfaces instead of making them)."""
        a = cls.__new__(cls)
        a.path, a.dx, a.dy = None, dx, dy if dy is not None else dx
        for f in cls.FIELDS:
            setattr(a, f, float(row[f]))
        a.fine_hurst = float("nan")  # not in the tables (values())
        return a

    def arguments(self):
        """The CLI's surface arguments of the map."""
        out = ["--areal", self.path, "--dx", f"{self.dx:.15g}"]
        return out + (["--dy", f"{self.dy:.15g}"] if self.dy != self.dx else [])

