# SPDX-License-Identifier: GPL-3.0-or-later
"""The studies' surfaces as line-scan spectra: self-affine shapes, a measured profile's spectrum,
the same spectrum on a longer period, and what the core says of them (h', W, s1).

Spectrum files (frequency [1/m], amplitude [m], the CLI's --spectrum) are written into the
context's scratch folder: they are made again from their definitions, never committed.
"""
import math
import os

from .context import ROOT


def write(path, frequencies, amplitudes, who="validation/spectra.py"):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(f"# frequency [1/m], amplitude [m] (written by {who})\n")
        for fr, a in zip(frequencies, amplitudes):
            f.write(f"{fr:.10g} {a:.10g}\n")
    return path


def levels(path):
    """(frequency, amplitude) of every level of a spectrum file."""
    with open(path) as f:
        return [tuple(float(v) for v in line.split()) for line in f if line.strip() and not line.startswith("#")]


def self_affine_shape(hurst, rolloff, cutoff):
    """C1 of the levels i = 1..cutoff up to its scale: flat below the roll-off level, then
    (i/rolloff)^-(1 + 2H)."""
    return [1.0 if i < rolloff else (i / rolloff) ** -(1.0 + 2.0 * hurst) for i in range(1, cutoff + 1)]


def self_affine(path, hurst, rolloff, cutoff, gradient=0.1, length=1e-3):
    """A self-affine line-scan spectrum (self_affine_shape) on levels f_i = i/L, amplitudes
    beta_i = sqrt(4 C1(f_i) df) (ArealSynthesis.hpp), scaled to the areal rms gradient h'
    (sqrt 2 times the profile's rms slope), written to `path`."""
    f = [i / length for i in range(1, cutoff + 1)]
    beta = [math.sqrt(4.0 * c / length) for c in self_affine_shape(hurst, rolloff, cutoff)]
    slope2 = sum((2 * math.pi * fr * b) ** 2 / 2.0 for fr, b in zip(f, beta))
    scale = (gradient / math.sqrt(2.0)) / math.sqrt(slope2)
    return write(path, f, [b * scale for b in beta])


def profile_spectrum(ctx, path, profile, cutoff):
    """A measured profile's periodogram (the core's Spectrum::fromProfile) cut at `cutoff` levels
    (f <= cutoff/L), written to `path`."""
    rc = ctx.rc()
    s = rc.Spectrum.from_profile(rc.read_profile(os.path.join(ROOT, profile)))
    keep = [(f, a) for f, a in zip(s.frequencies, s.amplitudes) if f * s.length <= cutoff * (1 + 1e-9)]
    return write(path, [k[0] for k in keep], [k[1] for k in keep])


def on_period(ctx, path, k):
    """The spectrum file `path` on a period k times as long (the core's Spectrum::onPeriod),
    written beside it as NAME-kL.spectrum."""
    rc = ctx.rc()
    s = rc.Spectrum.read(path).on_period(k)
    return write(path.replace(".spectrum", f"-{k}L.spectrum"), s.frequencies, s.amplitudes)


def gradient(ctx, path):
    """h' of a spectrum file: the core's areal rms gradient, the x axis p/(E' h') is taken with."""
    rc = ctx.rc()
    return rc.areal_rms_gradient(rc.Spectrum.read(path))


def length(path):
    """The period L [m] of a spectrum file: 1/its first frequency."""
    return 1.0 / levels(path)[0][0]
