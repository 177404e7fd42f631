# SPDX-License-Identifier: GPL-3.0-or-later
"""check() from Python: the exact model on the user's own surface against every law, the same
numbers as the CLI's --check (one core, two front-ends), its arguments mapped as named."""
import csv
import io

import numpy as np
import pytest

import roughcontact as rc
from conftest import STANDIN, STEEL, X3P

STEEL_M = rc.Material(**STEEL)


def cli_check(cli, *args):
    r = cli("--profile", STANDIN, "--model", "jacksonGreen", "--check", *args)
    assert r.status == 0, r.err
    rows = list(csv.DictReader(io.StringIO("".join(l + "\n" for l in r.out.splitlines() if not l.startswith("#")))))
    return {k: np.array([float(row[k]) for row in rows]) for k in rows[0]}


def test_check_is_the_clis(cli):
    # Two steel solids in both (the CLI's one --E is a rigid flat, which ContactInterface's two
    # sides cannot say).
    Ep = rc.ContactMaterials.pair(STEEL_M, STEEL_M).reduced_modulus
    pressures = [2e-4 * Ep * 0.02, 2e-3 * Ep * 0.02]
    lines = []
    c = rc.check(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M, grid=128,
                 pressures=pressures, progress=lines.append)
    cli_numbers = cli_check(cli, "--synthesize", "128", "--pressures", ",".join(repr(p) for p in pressures),
                            "--E", "179.52e9,179.52e9", "--nu", "0.32,0.32", "--Sy", "0.2e9,0.2e9")
    np.testing.assert_array_equal(c.pressures, cli_numbers["nominal_pressure"])
    np.testing.assert_array_equal(c.checked_exact, cli_numbers["h_per_k_checked_surface"])
    np.testing.assert_array_equal(c.checked_area, cli_numbers["area_checked_surface"])
    np.testing.assert_array_equal(c.answer, cli_numbers["h_per_k_answer"])
    for law, ratio in c.ratios.items():
        np.testing.assert_array_equal(ratio, cli_numbers["ratio_" + law])
    # Capped at 2.84 S_y (the materials yield), three seeds of 128^2, a progress line per solve.
    assert c.hardness == pytest.approx(2.84 * 0.2e9, rel=1e-15)
    assert c.surface.startswith("3 seeds of 128 x 128")
    # The light pressure on periods of four scan lengths (the default), the other where the periods
    # join, on both: 3 surfaces of one scan length with one pressure, 3 of 4L with two.
    assert c.light_load_periods == 4 and c.light_levels_kept == 15  # j/(4L) from 2/(4L) to 16/(4L)
    assert c.light_levels_of_given == 4
    assert c.long_period_weights[0] == 1 and 0 < c.long_period_weights[1] < 1
    assert len(lines) == 1 + 3 * 1 + 3 * 2 and lines[-1].startswith("check: surface 6 of 6, pressure 2 of 2")
    assert c.chosen_law == rc.default_conductance_law()
    assert c.closest_law in c.ratios
    assert ("closest: " + c.closest_law in c.report()) == c.closest_holds
    assert np.all(c.checked_exact_low <= c.checked_exact) and np.all(c.checked_exact <= c.checked_exact_high)
    assert np.all(c.exact_trusted) and len(c.untrusted) == 0
    assert c.exact_warning == ""  # synthesized surfaces are periodic: no patch correction
    # Up to p/(E' h') = 1e-3 the exact answer is a periodic cell's (four scan lengths): the check says so.
    light = sum(p < 1e-3 * Ep * c.gradient for p in c.pressures)
    assert light == 1, c.gradient
    assert "a periodic cell 4 scan lengths on a side" in c.small_cell_note
    assert "note: " + c.small_cell_note in c.report()


def test_check_unloads_from_a_peak_as_the_cli(cli):
    """unload_from: the check also unloads each surface from the peak (the same numbers as the CLI's
    --check --unload-from); the flattened summits conduct more, and the chosen law's h on unloading
    is its unloading branch: its loading ratio times a factor R > 1 that grows the deeper the
    unloading."""
    kw = dict(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M, grid=64,
              light_load_periods=1, pressures=[2e7, 6e7])
    c = rc.check(**kw, unload_from=3e8)
    assert c.unload_from == 3e8
    assert np.all(c.exact_unloading_h_per_k > c.checked_exact)
    assert c.chosen_unloads
    R = c.chosen_unloading_ratio / (c.ratios[c.chosen_law] * c.checked_exact / c.exact_unloading_h_per_k)
    assert R[0] > R[1] > 1.05, R  # 2e7 and 6e7 Pa unloaded from 3e8
    assert "unloaded from 3e+08 Pa" in c.report()
    off = [p for p, r in zip(c.pressures, c.chosen_unloading_ratio) if abs(r - 1) > 0.25]
    np.testing.assert_array_equal(c.chosen_unloading_misses, off)
    cli_numbers = cli_check(cli, "--synthesize", "64", "--pressures", "2e7,6e7", "--check-periods", "1",
                            "--E", "179.52e9,179.52e9", "--nu", "0.32,0.32", "--Sy", "0.2e9,0.2e9", "--unload-from", "3e8")
    np.testing.assert_array_equal(c.exact_unloading_h_per_k, cli_numbers["h_per_k_checked_surface_unloading"])
    np.testing.assert_array_equal(c.chosen_unloading_ratio, cli_numbers["ratio_chosen_unloading"])
    plain = rc.check(**kw)
    assert plain.unload_from is None and len(plain.exact_unloading_h_per_k) == 0
    assert len(plain.chosen_unloading_misses) == 0
    with pytest.raises(rc.ParameterError, match="^unload_from"):
        rc.check(**kw, unload_from=1e9)  # at or above H = 0.57 GPa


def test_check_of_a_padded_map_near_complete_contact_warns(tmp_path):
    """A map checked padded (no mirror) up to near complete contact: exact_warning says where its
    exact h_c is not to be trusted (and the report repeats it); mirror=True: none. The map of
    test_models' patch-correction test, capped soft (H = 2.84 x 20 MPa) so that 50 MPa is at 88 %
    contact."""
    spectrum = rc.Spectrum.from_profile(rc.read_profile(STANDIN))
    path = tmp_path / "map.npy"
    np.save(path, np.asarray(rc.synthesize_isotropic(spectrum, 64, 3).heights))
    soft = rc.Material(E=200e9, nu=0.3, Sy=20e6)
    surfaces = [rc.SurfaceSpec.areal(str(path), dx=2e-6)]
    padded = rc.check(surfaces=surfaces, side1=soft, side2=soft, pressures=[1e6, 5e7])
    assert "not to be trusted" in padded.exact_warning and "mirror=True" in padded.exact_warning
    assert "warning: " + padded.exact_warning in padded.report()
    # 50 MPa is that pressure: reported apart, counted for no law (not a miss, not for the closest),
    # and no exact answer implied there.
    np.testing.assert_array_equal(padded.exact_trusted, [True, False])
    np.testing.assert_array_equal(padded.untrusted, [5e7])
    assert 5e7 not in padded.chosen_misses
    assert np.isnan(padded.answer_exact_low[1]) and np.isfinite(padded.answer_exact_low[0])
    assert "not counted (*): 1 of 2 pressures" in padded.report()
    trusted = {law: r[0] for law, r in padded.ratios.items()}
    closest = min(trusted, key=lambda law: max(trusted[law], 1 / trusted[law]))
    assert padded.closest_law == closest
    mirrored = rc.check(surfaces=surfaces, side1=soft, side2=soft, pressures=[1e6, 5e7], mirror=True)
    assert mirrored.exact_warning == ""
    assert np.all(mirrored.exact_trusted)


def test_check_refuses_what_it_cannot_check():
    spec = dict(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M, grid=32)
    with pytest.raises(rc.ParameterError, match="none of the pressures given lies in the checked range"):
        rc.check(pressures=[1.0], **spec)
    with pytest.raises(TypeError, match="progress: expected a callable"):
        rc.check(progress=3, **spec)
    with pytest.raises(rc.ParameterError, match="^pressures: check 1 to 5 pressures"):
        rc.check(count=6, **spec)
    # Issue 49, item 13: six pressures, a NaN and a seed given twice are refused as such.
    with pytest.raises(rc.ParameterError, match="^pressures: the check solves at most 5 pressures, 6 were given"):
        rc.check(pressures=[1e6, 2e6, 3e6, 4e6, 5e6, 6e6], **spec)
    with pytest.raises(rc.ParameterError, match=r"^pressures: a pressure is nan \(not a number\)"):
        rc.check(pressures=[1e6, float("nan")], **spec)
    with pytest.raises(rc.ParameterError, match="^seeds: seed 1 is given twice"):
        rc.check(seeds=[1, 1, 1], **spec)
    # Issue 49, item 10: a grid that keeps fewer than 4 of the surface's levels, named as Python names it.
    with pytest.raises(rc.ParameterError, match="^grid: the check's surfaces would hold 1 of the surface's"):
        rc.check(**dict(spec, grid=8))
    with pytest.raises(rc.ParameterError, match="^light_load_periods: .* or a shorter light-load period "
                                                r"\(light_load_periods\)"):
        rc.check(light_load_periods=32, **spec)
    # Issue 49, item 15: True is not a whole number (it was taken as 1).
    with pytest.raises(TypeError):
        rc.check(count=True, **spec)
    with pytest.raises(TypeError):
        rc.check(seeds=[True, 2], **spec)
    # light_load_periods: 1 to 64, and not for a map (checked as itself); the error names it.
    with pytest.raises(rc.ParameterError, match="light_load_periods.*must be 1 to 64"):
        rc.check(light_load_periods=0, **spec)
    with pytest.raises(rc.ParameterError, match="light_load_periods.*must be 1 to 64"):
        rc.check(light_load_periods=65, **spec)
    areal = dict(spec, surfaces=[rc.SurfaceSpec.areal(X3P)])
    with pytest.raises(rc.ParameterError, match="light_load_periods.*an areal map is solved as itself"):
        rc.check(light_load_periods=2, **areal)


def test_threads_keyword_sets_the_solves_threads():
    """threads= on check() and ContactInterface() (issue 23, item 2) sets the process's threads,
    as set_threads does; the answer does not change with it (Threads.hpp)."""
    spec = dict(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M)
    before = rc.threads()
    try:
        rc.set_threads(2)
        two = rc.check(grid=32, seeds=[1], count=2, light_load_periods=1, **spec)
        one = rc.check(grid=32, seeds=[1], count=2, light_load_periods=1, threads=1, **spec)
        assert rc.threads() == 1
        np.testing.assert_array_equal(one.checked_exact, two.checked_exact)
        rc.ContactInterface(model="boundaryElement", synthesize=16, min_pressure=1e7, max_pressure=1e8,
                            threads=2, **spec)
        assert rc.threads() == 2
        with pytest.raises(rc.ParameterError, match="^threads: must be 1 to 4096"):
            rc.check(grid=32, seeds=[1], count=2, threads=0, **spec)
    finally:
        rc.set_threads(before)


def test_the_regime_and_the_measured_band():
    ci = rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                             min_pressure=1e5, max_pressure=1e8)
    assert ci.regime in ci.summary()
    assert "(capped reference)" in ci.regime and "plasticity index" in ci.regime
    band = rc.measured_accuracy("jacksonBhavnaniFerguson", "jacksonGreen", True, 3e-3)
    assert band == {"low": 0.197, "high": 1.31, "from": 1e-3, "to": 1e-2, "surfaces": 5,
                    "report": "engineering-range study"}
    assert rc.measured_accuracy("cooperMikicYovanovich", "", False, 3e-3) is None


def test_check_of_a_lay_is_the_clis_on_stretched_surfaces(cli, tmp_path):
    # Issue 53: profiles across and along a lay (a row and a column, its spacing 3 times longer,
    # of an isotropic surface): the check solves the across spectrum's surfaces stretched along y
    # by the profiles' lay ratio, Python and the CLI the same numbers.
    spectrum = rc.Spectrum.from_profile(rc.read_profile(STANDIN))
    surface = rc.synthesize_isotropic(spectrum, 256, 9)
    heights = np.asarray(surface.heights).reshape(256, 256)
    across, along = tmp_path / "across.txt", tmp_path / "along.txt"
    np.savetxt(across, np.column_stack([np.arange(256) * surface.dx, heights[0, :]]))
    np.savetxt(along, np.column_stack([np.arange(256) * 3 * surface.dx, heights[:, 0]]))
    c = rc.check(surfaces=[rc.SurfaceSpec.profile(str(across), along_lay=str(along))], side1=STEEL_M,
                 side2=STEEL_M, grid=64, count=2, light_load_periods=1)
    assert 2 < c.lay_stretch < 4.5, c.lay_stretch  # 3 with the scatter of two single profiles' slopes
    assert "times along the lay" in c.surface
    r = cli("--profile", str(across), "--profile-along", str(along), "--model", "jacksonGreen", "--check",
            "--synthesize", "64", "--check-periods", "1", "--pressures", ",".join(repr(p) for p in c.pressures),
            "--E", "179.52e9,179.52e9", "--nu", "0.32,0.32", "--Sy", "0.2e9,0.2e9")
    assert r.status == 0, r.err
    rows = list(csv.DictReader(io.StringIO("".join(l + "\n" for l in r.out.splitlines() if not l.startswith("#")))))
    np.testing.assert_array_equal(c.checked_exact, [float(row["h_per_k_checked_surface"]) for row in rows])
    assert "times along the lay" in r.out + r.err
    # synthesize_stretched: the isotropic surface's heights with dy = stretch dx.
    s = rc.synthesize_stretched(spectrum, 3.0, 64, 1)
    np.testing.assert_array_equal(s.heights, rc.synthesize_isotropic(spectrum, 64, 1).heights)
    assert s.dy == pytest.approx(3 * s.dx, rel=1e-15)
