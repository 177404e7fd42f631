# SPDX-License-Identifier: GPL-3.0-or-later
"""Models and conductance laws from Python: the same numbers as multiscaleContact at the same
input (parsed from its CSV), vectorized calls equal to scalar calls, SI pressures = loads times E'."""
import math
import warnings

import numpy as np
import pytest

import roughcontact as rc
from conftest import STANDIN, STEEL, STEEL_ARGS

LOADS = [1e-6, 1e-5, 1e-4, 1e-3]


@pytest.fixture(scope="module")
def spectrum():
    return rc.Spectrum.from_profile(rc.read_profile(STANDIN))


@pytest.fixture(scope="module")
def steel():
    return rc.ContactMaterials.against_rigid_flat(rc.Material(**STEEL))


def test_names():
    assert rc.model_names()[:5] == rc.multiscale_model_names()
    assert "persson" in rc.model_names() and "jacksonGreen" in rc.multiscale_model_names()
    assert rc.conductance_law_names() == [
        "jacksonBhavnaniFerguson", "multiscaleBarber", "persson", "mikic", "cooperMikicYovanovich",
        "fittedElastoPlastic"]
    assert rc.default_conductance_law() in rc.conductance_law_names()


def test_reduced_modulus(steel):
    assert steel.reduced_modulus == pytest.approx(179.52e9 / (1 - 0.32 ** 2), rel=1e-15)
    a, b = rc.Material(200e9, 0.3), rc.Material(100e9, 0.25)
    pair = rc.ContactMaterials.pair(a, b)
    assert pair.reduced_modulus == pytest.approx(1 / ((1 - 0.09) / 200e9 + (1 - 0.0625) / 100e9), rel=1e-15)
    assert rc.ContactMaterials.from_reduced_modulus(2e11).reduced_modulus == 2e11


@pytest.mark.parametrize("name", rc.model_names())
def test_area_equals_the_cli(cli, spectrum, steel, name):
    r = cli("--profile", STANDIN, "--model", name, *STEEL_ARGS, "--loads", ",".join(map(repr, LOADS)))
    assert r.status == 0, r.err
    area = r.columns()["area_fraction"]
    model = rc.Model(name, spectrum, rc.Material(**STEEL))
    assert model.name == name
    Ep = steel.reduced_modulus
    got = model.area_fraction(np.array(LOADS) * Ep)
    np.testing.assert_allclose(got, area, rtol=1e-9)
    np.testing.assert_allclose(model.area_fraction_at_load(LOADS), area, rtol=1e-9)


def test_pressures_equal_the_cli_pressures_option(cli, spectrum, steel):
    P = [1e4, 1e5, 1e6, 1e7]
    r = cli("--profile", STANDIN, "--model", "jacksonGreen", *STEEL_ARGS, "--pressures", ",".join(map(repr, P)),
            "--conductance-law", "jacksonBhavnaniFerguson")
    assert r.status == 0, r.err
    c = r.columns()
    np.testing.assert_array_equal(c["nominal_pressure"], P)
    model = rc.Model("jacksonGreen", spectrum, steel)
    np.testing.assert_allclose(model.area_fraction(P), c["area_fraction"], rtol=1e-9)
    law = rc.ConductanceLaw("jacksonBhavnaniFerguson", model=model)
    np.testing.assert_allclose(law.conductance_per_conductivity(P), c["h_per_k"], rtol=1e-9)


def test_a_multiscale_model_unloads(spectrum, steel):
    """unload_from: each level a Hertzian contact of its peak (docs/theory.md §3.6): hertz retraces its
    loading curve, jacksonGreen never falls below it and equals it at the peak; the other models refuse."""
    P = np.array([1e5, 1e6, 1e7])
    hertz = rc.Model("hertz", spectrum, steel)
    np.testing.assert_allclose(hertz.area_fraction(P, unload_from=3e7), hertz.area_fraction(P), rtol=1e-12)
    jg = rc.Model("jacksonGreen", spectrum, steel)
    assert np.all(jg.area_fraction(P, unload_from=3e7) >= jg.area_fraction(P) * (1 - 1e-12))
    assert jg.area_fraction(3e7, unload_from=3e7) == jg.area_fraction(3e7)
    with pytest.raises(rc.ParameterError, match="^unload_from: is for the multi-scale models"):
        rc.Model("persson", spectrum, steel).area_fraction(P, unload_from=3e7)
    with pytest.raises(rc.ParameterError, match="^unload_from"):
        jg.area_fraction(P, unload_from=-1.0)


def test_fitted_elasto_plastic_takes_the_spectrums_bandwidth_ratio(spectrum):
    # W = m1/sqrt(m0 m2) of the line-scan spectrum: by hand from its levels (beta^2/2 weights).
    k = 2 * np.pi * np.asarray(spectrum.frequencies)
    w = 0.5 * np.asarray(spectrum.amplitudes) ** 2
    W = (k * w).sum() / np.sqrt(w.sum() * (k * k * w).sum())
    assert rc.spectral_bandwidth_ratio(spectrum) == pytest.approx(W, rel=1e-12)
    assert 0 < W < 1
    assert rc.spectral_bandwidth_ratio(rc.Spectrum([2e3], [1e-7], 1e-3)) == pytest.approx(1.0, rel=1e-15)
    # The law needs the spectrum beside sigma and m, and says so without one.
    r = rc.spectrum_roughness(spectrum)
    with pytest.raises(rc.ParameterError, match="line-scan spectrum"):
        rc.ConductanceLaw("fittedElastoPlastic", roughness=r, Eprime=1e11, hardness=1e9)
    # Elastic (no cap): no spectrum needed. From x = P/(sqrt(pi) E' m) = 0.01 to 0.1, where neither
    # s1 nor W acts elastically, the same h (here x = 0.08 at 1e9 Pa; beyond 0.1 W sets the growth's
    # rate, 0.55 standing in without a spectrum); below it the spectrum's first level's share s1 sets the
    # light-load factor, which needs the spectrum (x = 0.008 at 1e8 Pa; this spectrum's s1 is not
    # the pivot 0.3).
    alone = rc.ConductanceLaw("fittedElastoPlastic", roughness=r, Eprime=1e11)
    given = rc.ConductanceLaw("fittedElastoPlastic", spectrum=spectrum, roughness=r, Eprime=1e11)
    assert alone.conductance_per_conductivity(1e9) == given.conductance_per_conductivity(1e9)
    assert alone.conductance_per_conductivity(1e8) != given.conductance_per_conductivity(1e8)
    s1 = rc.first_level_share(spectrum)
    assert s1 == pytest.approx(spectrum.amplitudes[0] ** 2 / (np.asarray(spectrum.amplitudes) ** 2).sum(), rel=1e-12)
    assert abs(s1 - 0.3) > 0.05
    # Capped, a narrower spectrum (a larger W) of the same sigma and m conducts more.
    broad = rc.ConductanceLaw("fittedElastoPlastic", spectrum=spectrum, roughness=r, Eprime=1e11, hardness=1e9)
    narrow = rc.ConductanceLaw("fittedElastoPlastic", spectrum=rc.Spectrum([2e3], [1e-7], 1e-3), roughness=r,
                               Eprime=1e11, hardness=1e9)
    assert narrow.conductance_per_conductivity(1e8) > broad.conductance_per_conductivity(1e8)
    # Elastically two spectra of one s1 (1/2: two equal levels) and different W give one h.
    elastic = [rc.ConductanceLaw("fittedElastoPlastic", spectrum=s, roughness=r, Eprime=1e11)
               for s in (rc.Spectrum([2e3, 6e3], [1e-7, 1e-7], 1e-3), rc.Spectrum([2e3, 2e4], [1e-7, 1e-7], 1e-3))]
    assert elastic[0].conductance_per_conductivity(1e8) == elastic[1].conductance_per_conductivity(1e8)


@pytest.mark.parametrize("law_name", ["jacksonBhavnaniFerguson", "multiscaleBarber", "persson", "mikic"])
def test_conductance_laws_equal_the_cli(cli, spectrum, steel, law_name):
    r = cli("--profile", STANDIN, "--model", "jacksonGreen", *STEEL_ARGS, "--loads", ",".join(map(repr, LOADS)),
            "--conductance-law", law_name)
    assert r.status == 0, r.err
    c = r.columns()
    model = rc.Model("jacksonGreen", spectrum, steel)
    roughness = rc.profile_roughness(rc.read_profile(STANDIN)) if law_name == "mikic" else None
    law = rc.ConductanceLaw(law_name, model=model, roughness=roughness)
    assert law.name == law_name
    P = np.array(LOADS) * steel.reduced_modulus
    np.testing.assert_allclose(law.conductance_per_conductivity(P), c["h_per_k"], rtol=1e-9)
    sep = law.mean_separation(P)
    if c["separation"][0] is None:
        assert np.all(np.isnan(sep))
    else:
        np.testing.assert_allclose(sep, c["separation"], rtol=1e-9)


def test_persson_own_conductance_equals_the_cli(cli, spectrum, steel):
    r = cli("--profile", STANDIN, "--model", "persson", *STEEL_ARGS, "--loads", ",".join(map(repr, LOADS)),
            "--conductance")
    assert r.status == 0, r.err
    c = r.columns()
    model = rc.Model("persson", spectrum, steel)
    P = np.array(LOADS) * steel.reduced_modulus
    np.testing.assert_allclose(model.conductance_per_conductivity(P), c["h_per_k"], rtol=1e-9)
    np.testing.assert_allclose(model.mean_separation(P), c["separation"], rtol=1e-9)


def test_vectorized_equals_scalar(spectrum, steel):
    model = rc.Model("jacksonGreen", spectrum, steel)
    P = np.logspace(3, 8, 6).reshape(2, 3)
    a = model.area_fraction(P)
    assert isinstance(a, np.ndarray) and a.shape == (2, 3) and a.dtype == np.float64
    for idx in np.ndindex(P.shape):
        s = model.area_fraction(float(P[idx]))
        assert isinstance(s, float)
        assert s == a[idx]
    assert isinstance(model.area_fraction(np.float64(1e6)), float)
    np.testing.assert_array_equal(model.area_fraction(list(P.ravel())), a.ravel())
    assert model.area_fraction(np.array([])).shape == (0,)
    # Integers are pressures too; P = 0 is no contact.
    assert model.area_fraction(0) == 0.0
    law = rc.ConductanceLaw("jacksonBhavnaniFerguson", model=model)
    h = law.conductance_per_conductivity(P)
    assert h.shape == (2, 3)
    assert law.conductance_per_conductivity(float(P[1, 2])) == h[1, 2]


def test_persson_only_methods(spectrum, steel):
    with pytest.raises(rc.ParameterError, match="persson only"):
        rc.Model("hertz", spectrum, steel).mean_separation(1e6)


def test_boundary_element_equals_the_cli(cli, spectrum):
    r = cli("--profile", STANDIN, "--synthesize", "16,3", "--model", "boundaryElement", "--Eprime", "2e11",
            "--loads", "1e-5,1e-4")
    assert r.status == 0, r.err
    c = r.columns()
    surface = rc.synthesize_isotropic(spectrum, 16, 3)
    bem = rc.BoundaryElement(surface, rc.ContactMaterials.from_reduced_modulus(2e11), periodic=True)
    assert bem.reduced_modulus == 2e11
    curve = bem.curve([2e6, 2e7])
    for key in ("pressure", "load", "area_fraction", "mean_separation", "conductance_per_conductivity"):
        assert curve[key].shape == (2,) and curve[key].dtype == np.float64
    np.testing.assert_allclose(curve["load"], [1e-5, 1e-4], rtol=1e-15)
    np.testing.assert_allclose(curve["area_fraction"], c["area_fraction"], rtol=1e-9)
    np.testing.assert_allclose(curve["mean_separation"], c["separation"], rtol=1e-9)
    np.testing.assert_allclose(curve["conductance_per_conductivity"], c["h_per_k"], rtol=1e-9)
    np.testing.assert_array_equal(curve["spots"], c["spots"])
    np.testing.assert_allclose(curve["mean_spot_radius"], c["mean_spot_radius"], rtol=1e-9)
    assert math.isinf(bem.patch_conductance_per_conductivity)
    # area_fraction solves each pressure from scratch: the same contact set up to the tolerance.
    np.testing.assert_allclose(bem.area_fraction([2e6, 2e7]), c["area_fraction"], rtol=1e-6)


def test_boundary_element_unloads_as_the_cli(cli, spectrum):
    # unload_from (issue 54): the joint that has carried the peak, the CLI's --unload-from columns;
    # at the peak the loading point, below it more contact and more conductance.
    r = cli("--profile", STANDIN, "--synthesize", "32,3", "--model", "boundaryElement", "--Eprime", "2e11",
            "--hardness", "4e8", "--pressures", "2e7,1e8,2e8", "--unload-from", "2e8")
    assert r.status == 0, r.err
    c = r.columns()
    surface = rc.synthesize_isotropic(spectrum, 32, 3)
    bem = rc.BoundaryElement(surface, rc.ContactMaterials.from_reduced_modulus(2e11), periodic=True, hardness=4e8)
    loading = bem.curve([2e7, 1e8, 2e8])
    unloading = bem.curve([2e7, 1e8, 2e8], unload_from=2e8)
    np.testing.assert_allclose(unloading["area_fraction"], c["unloading_area_fraction"], rtol=1e-9)
    np.testing.assert_allclose(unloading["conductance_per_conductivity"], c["unloading_h_per_k"], rtol=1e-9)
    np.testing.assert_array_equal(unloading["spots"], c["unloading_spots"])
    assert np.all(unloading["conductance_per_conductivity"][:2] > loading["conductance_per_conductivity"][:2])
    assert unloading["conductance_per_conductivity"][2] == pytest.approx(loading["conductance_per_conductivity"][2],
                                                                        rel=1e-3)
    with pytest.raises(rc.ParameterError, match="^unload_from: the peak is a pressure above 0 and below the cap"):
        bem.curve([2e7], unload_from=5e8)
    elastic = rc.BoundaryElement(surface, rc.ContactMaterials.from_reduced_modulus(2e11), periodic=True)
    with pytest.raises(rc.ParameterError, match="^unload_from: unloads a joint the cap has flattened"):
        elastic.curve([2e7], unload_from=1e8)


def test_boundary_element_detrend(cli, spectrum):
    """detrend: what is removed before the solve (issue 19): by default the mean of a periodic
    surface and the plane of a map; the CLI's --detrend gives the same numbers."""
    surface = rc.synthesize_isotropic(spectrum, 16, 3)
    materials = rc.ContactMaterials.from_reduced_modulus(2e11)
    default = rc.BoundaryElement(surface, materials, periodic=True).curve([2e7])
    mean = rc.BoundaryElement(surface, materials, periodic=True, detrend="mean").curve([2e7])
    plane = rc.BoundaryElement(surface, materials, periodic=True, detrend="plane").curve([2e7])
    assert default["area_fraction"][0] == mean["area_fraction"][0]
    assert default["mean_separation"][0] == mean["mean_separation"][0]
    assert plane["mean_separation"][0] != mean["mean_separation"][0]
    r = cli("--profile", STANDIN, "--synthesize", "16,3", "--model", "boundaryElement", "--Eprime", "2e11",
            "--detrend", "plane", "--loads", "1e-4")
    assert r.status == 0, r.err
    np.testing.assert_allclose(plane["mean_separation"], r.columns()["separation"], rtol=1e-9)
    with pytest.raises(rc.ParameterError, match="^detrend: 'tilt' is not a detrending"):
        rc.BoundaryElement(surface, materials, periodic=True, detrend="tilt")


def test_boundary_element_progress(spectrum, capsys):
    """A long solve reports where it is (issue 19, item 4): progress(dict) every progress_every
    seconds (3 by default; 0 here: every iteration), or verbose=True on sys.stderr."""
    surface = rc.synthesize_isotropic(spectrum, 32, 3)
    materials = rc.ContactMaterials.from_reduced_modulus(2e11)
    seen = []
    bem = rc.BoundaryElement(surface, materials, periodic=True, progress=seen.append, progress_every=0)
    curve = bem.curve([2e7])
    assert len(seen) >= curve["iterations"][0] - 1 > 0
    assert {d["stage"] for d in seen} <= {"contact", "conductance"}
    assert all(set(d) == {"stage", "iteration", "residual", "tolerance", "seconds"} for d in seen)
    assert seen[0]["stage"] == "contact" and seen[0]["iteration"] == 1
    quiet = []
    rc.BoundaryElement(surface, materials, periodic=True, progress=quiet.append).curve([2e7])
    assert quiet == []  # a solve shorter than 3 s says nothing
    rc.BoundaryElement(surface, materials, periodic=True, verbose=True, progress_every=0).curve([2e7])
    assert "roughcontact: boundaryElement contact solve: iteration 1, residual" in capsys.readouterr().err
    with pytest.raises(TypeError, match="progress: expected a callable"):
        rc.BoundaryElement(surface, materials, periodic=True, progress=3)

    def stop(d):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rc.BoundaryElement(surface, materials, periodic=True, progress=stop, progress_every=0).curve([2e7])


def test_threads_change_nothing_in_the_answer(spectrum):
    """set_threads / threads= (issue 23): the boundary-element answer is the same bit for bit
    for 1 and 2 threads (a 160 x 160 grid: the loops and FFTs run threaded), and a count below 1
    is refused with the parameter named."""
    surface = rc.synthesize_isotropic(spectrum, 160, 3)
    materials = rc.ContactMaterials.from_reduced_modulus(2e11)
    before = rc.threads()
    try:
        one = rc.BoundaryElement(surface, materials, periodic=True, threads=1).curve([2e7])
        assert rc.threads() == 1
        rc.set_threads(2)
        two = rc.BoundaryElement(surface, materials, periodic=True).curve([2e7])
        for key in ("area_fraction", "mean_separation", "conductance_per_conductivity", "iterations"):
            assert one[key].tobytes() == two[key].tobytes(), key
        with pytest.raises(rc.ParameterError, match="^threads: must be 1 to 4096"):
            rc.set_threads(0)
    finally:
        rc.set_threads(before)


def test_boundary_element_patch_correction_warning(cli, spectrum, tmp_path):
    """A map solved padded near complete contact: its h_c = 1/(1/h_spots - 1/h_patch) multiplies
    the spots' error by patch_correction_gain = 1 + h_c/h_patch, and above 50 the curve warns (a
    RuntimeWarning; the CLI on stderr) and names the mirrored solve; mirrored, no gain and no
    warning. On this 64^2 map the gains are 1.05, 31 and 163 at 0.1 %, 40 % and 68 % contact."""
    heights = np.asarray(rc.synthesize_isotropic(spectrum, 64, 3).heights)
    surface = rc.ArealSurface(heights, 2e-6, 2e-6)
    materials = rc.ContactMaterials.from_reduced_modulus(2e11)
    padded = rc.BoundaryElement(surface, materials)
    with pytest.warns(RuntimeWarning, match=r"not to be trusted at 1 of 3 loads, from P = 5e\+09 Pa \(F/\(A_n E'\) = 0.025, .*mirror=True"):
        curve = padded.curve([2e6, 2e9, 5e9])
    gain = curve["patch_correction_gain"]
    np.testing.assert_allclose(gain, 1 + curve["conductance_per_conductivity"] / padded.patch_conductance_per_conductivity,
                               rtol=1e-12)
    assert gain[1] < 50 < gain[2]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        light = padded.curve([2e6, 2e9])  # every gain below 50: no warning
        mirrored = rc.BoundaryElement(surface, materials, mirror=True).curve([2e6, 2e9, 5e9])
    assert np.all(light["patch_correction_gain"] < 50)
    np.testing.assert_array_equal(mirrored["patch_correction_gain"], [1.0, 1.0, 1.0])
    path = tmp_path / "map.npy"
    np.save(path, heights)
    # The interface of model boundaryElement on the map: its table warns when it is built (also
    # into a table_file), not when it is read back from that file.
    steel = rc.Material(E=200e9, nu=0.3)
    spec = dict(surfaces=[rc.SurfaceSpec.areal(str(path), dx=2e-6)], side1=steel, side2=steel,
                model="boundaryElement", max_pressure=5e9)
    with pytest.warns(RuntimeWarning, match="boundary-element table: the map's h_c is not to be trusted"):
        built = rc.ContactInterface(**spec)
    assert built.table_warning.startswith("the map's h_c is not to be trusted")
    table = tmp_path / "table.csv"
    with pytest.warns(RuntimeWarning, match="boundary-element table: the map's h_c is not to be trusted"):
        rc.ContactInterface(**spec, table_file=str(table))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert rc.ContactInterface(**spec, table_file=str(table)).table_warning == ""  # read back: none
        assert rc.ContactInterface(**spec, mirror=True).table_warning == ""
    for mirror, warned in (([], True), (["--mirror"], False)):
        r = cli("--areal", str(path), "--dx", "2e-6", "--model", "boundaryElement", "--Eprime", "2e11",
                "--loads", "1e-5,2.5e-2", *mirror)
        assert r.status == 0, r.err
        assert ("warning: the map's h_c is not to be trusted at 1 of 2 loads" in r.err) == warned, r.err
        assert ("Solve the map mirrored (--mirror)" in r.err) == warned, r.err


def test_boundary_element_mirror(cli, spectrum, tmp_path):
    """mirror=True (--mirror): a map solved mirrored about its edges into one period of a periodic
    surface equals the map mirrored by hand (numpy) and solved periodic, and the CLI; no patch."""
    full = np.asarray(rc.synthesize_isotropic(spectrum, 32, 3).heights)
    heights = full[:14, :18]  # a corner: not periodic; dy != dx
    dx, dy = 2e-6, 3e-6
    surface = rc.ArealSurface(heights, dx, dy)
    materials = rc.ContactMaterials.from_reduced_modulus(2e11)
    bem = rc.BoundaryElement(surface, materials, mirror=True)
    assert math.isinf(bem.patch_conductance_per_conductivity)
    curve = bem.curve([2e6, 2e7])
    flat = np.asarray(surface.detrended("plane").heights)
    row = np.hstack([flat, flat[:, ::-1]])
    by_hand = rc.ArealSurface(np.vstack([row, row[::-1, :]]), dx, dy)
    periodic = rc.BoundaryElement(by_hand, materials, periodic=True, detrend="none").curve([2e6, 2e7])
    # Two solves of one problem, each stopped at its tolerance: the contact set to a cell in a
    # thousand, h_c to 1e-6 (its error falls as the square of the residual: BoundaryElement.hpp).
    np.testing.assert_allclose(curve["area_fraction"], periodic["area_fraction"], rtol=1e-3)
    np.testing.assert_allclose(curve["conductance_per_conductivity"], periodic["conductance_per_conductivity"],
                               rtol=1e-6)
    path = tmp_path / "corner.npy"
    np.save(path, heights)
    r = cli("--areal", str(path), "--dx", f"{dx!r}", "--dy", f"{dy!r}", "--mirror", "--model", "boundaryElement",
            "--Eprime", "2e11", "--loads", "1e-5,1e-4")
    assert r.status == 0, r.err
    np.testing.assert_allclose(curve["conductance_per_conductivity"], r.columns()["h_per_k"], rtol=1e-9)
    with pytest.raises(rc.ParameterError, match="^mirror: "):
        rc.BoundaryElement(surface, materials, mirror=True, periodic=True)
