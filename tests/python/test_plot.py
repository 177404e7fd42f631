# SPDX-License-Identifier: GPL-3.0-or-later
"""plot() from Python: every law's h_c/k_s on the whole surface against pressure, the same numbers
as the CLI's --conductance-law all (one core, two front-ends), the band the regime quotes, the
gap's parts, and the PNG the CLI's --plot draws."""
import shutil

import numpy as np
import pytest

import roughcontact as rc
from conftest import STANDIN

STEEL_M = rc.Material(E=200e9, nu=0.3, Sy=0.4e9)
PNG = b"\x89PNG\r\n\x1a\n"


def test_plot_is_every_law_the_cli_prints(cli):
    curves = rc.plot(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                     pressures=[1e5, 1e8], points=7)
    p = curves["pressures"]
    assert len(p) == 7 and p[0] == 1e5 and p[-1] == 1e8
    r = cli("--profile", STANDIN, "--model", "jacksonGreen", "--E", "200e9,200e9", "--nu", "0.3,0.3",
            "--Sy", "0.4e9,0.4e9", "--hardness-from-yield", "--conductance-law", "all",
            "--pressures", ",".join(repr(x) for x in p))
    assert r.status == 0, r.err
    columns = r.columns()
    for law in rc.conductance_law_names():
        # The CLI prints 10 significant digits.
        np.testing.assert_allclose(curves[law], columns["h_per_k_" + law], rtol=1e-9, err_msg=law)
    # The band: the default law over its measured band's ends where the studies measured, NaN
    # below their lightest load (1e5 Pa here is p/(E' h') ~ 7e-6).
    chosen = curves[rc.default_conductance_law()]
    measured = np.isfinite(curves["exact_low"])
    assert not measured[0] and measured[-1]
    assert np.all(curves["exact_low"][measured] <= chosen[measured] * 1.25)
    assert np.all(curves["exact_low"][measured] < curves["exact_high"][measured])
    assert "h_gas" not in curves  # no gap given


def test_plot_with_a_gap_and_a_png(tmp_path):
    if shutil.which("gnuplot") is None:
        pytest.skip("gnuplot is not installed (etc/debianPackages: gnuplot-nox)")
    gap = rc.GapSpec(gas="air", emissivity=(0.3, 0.3))
    path = tmp_path / "h.png"
    curves = rc.plot(str(path), surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                     pressures=[1e6], k1=50, k2=50, gap=gap, temperatures=(350, 350))
    assert path.read_bytes().startswith(PNG)
    # One pressure: a decade each way of it, 60 points; the gap's parts at each.
    assert curves["pressures"][0] == pytest.approx(1e5) and curves["pressures"][-1] == pytest.approx(1e7)
    assert len(curves["h_gas"]) == 60 and np.all(curves["h_gas"] > 0) and np.all(curves["h_rad"] > 0)
    # A file that is not a PNG is left as it is.
    notes = tmp_path / "notes.txt"
    notes.write_text("my notes\n")
    with pytest.raises(rc.ParameterError, match="file"):
        rc.plot(str(notes), surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                pressures=[1e6])
    assert notes.read_text() == "my notes\n"


def test_plot_refuses_what_it_cannot_draw():
    s = [rc.SurfaceSpec.profile(STANDIN)]
    with pytest.raises(rc.ParameterError, match="pressures"):
        rc.plot(surfaces=s, side1=STEEL_M, side2=STEEL_M, pressures=[])
    with pytest.raises(rc.ParameterError, match="pressures"):
        rc.plot(surfaces=s, side1=STEEL_M, side2=STEEL_M, pressures=[0.0, 1e6])
    with pytest.raises(rc.ParameterError, match="k2"):
        rc.plot(surfaces=s, side1=STEEL_M, side2=STEEL_M, pressures=[1e6], k1=50)
