#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""profileCurve.py: a measured profile's real contact area and contact conductance against the
nominal pressure, from Python (docs/python.md).

Reads the Dektak export data/dektak-1.csv (MIT licence: data/dektak-1.LICENSE.md; its header
names its units, micrometres, and read_profile returns metres), builds the multi-scale model
jacksonGreen and Persson's theory for two steel blocks, and plots A_r/A_n and h_c [W/(m^2 K)]
against the nominal pressure P [Pa] into a PNG.

    PYTHONPATH=build/python python3 docs/python/profileCurve.py --output profileCurve.png
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import roughcontact as rc  # noqa: E402

top = pathlib.Path(__file__).resolve().parents[2]
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--profile", default=str(top / "data" / "dektak-1.csv"), help="profile file")
parser.add_argument("--output", default="profileCurve.png", help="the PNG to write")
args = parser.parse_args()

profile = rc.read_profile(args.profile)          # heights [m], spacing [m]
spectrum = rc.Spectrum.from_profile(profile)     # detrended, FFT: levels f_i = i/L
steel = rc.Material(E=200e9, nu=0.3, Sy=0.5e9)   # [Pa]
k = 16.0                                         # stainless steel, W/(m K)
materials = rc.ContactMaterials.pair(steel, steel)
k_s = 2 * k * k / (k + k)                        # the harmonic mean of the two sides

P = np.logspace(4, 8, 81)                        # nominal pressure F/A_n [Pa]
multiscale = rc.Model("jacksonGreen", spectrum, materials)
law = rc.ConductanceLaw("jacksonBhavnaniFerguson", model=multiscale)
persson = rc.Model("persson", spectrum, materials)
curves = {
    "jacksonGreen + jacksonBhavnaniFerguson": (multiscale.area_fraction(P), k_s * law.conductance_per_conductivity(P)),
    "persson": (persson.area_fraction(P), k_s * persson.conductance_per_conductivity(P)),
}

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
for label, (area, h) in curves.items():
    left.loglog(P, area, label=label)
    right.loglog(P, h, label=label)
left.set(xlabel="nominal pressure P [Pa]", ylabel="A_r/A_n", title="real contact area")
right.set(xlabel="nominal pressure P [Pa]", ylabel="h_c [W/(m² K)]", title=f"contact conductance, k = {k} W/(m K)")
for ax in (left, right):
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.suptitle(f"{pathlib.Path(args.profile).name}: {len(profile)} samples, L = {profile.length * 1e3:.3g} mm, "
             f"E' = {materials.reduced_modulus / 1e9:.4g} GPa")
fig.savefig(args.output, dpi=100)
print(f"profileCurve: wrote {args.output}")
for p in (1e5, 1e6, 1e7):
    print(f"  P = {p:.0e} Pa: A_r/A_n = {multiscale.area_fraction(p):.4g}, "
          f"h_c = {k_s * law.conductance_per_conductivity(p):.4g} W/(m^2 K)")
