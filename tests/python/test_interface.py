# SPDX-License-Identifier: GPL-3.0-or-later
"""ContactInterface from Python: the table the OpenFOAM condition interpolates, from keyword
arguments; its values at its own pressures are the model's and the law's there."""
import math
import warnings

import numpy as np
import pytest

import roughcontact as rc
from conftest import STANDIN, STEEL

STEEL_M = rc.Material(**STEEL)


@pytest.fixture(scope="module")
def interface():
    return rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                               model="jacksonGreen")


def test_table_is_the_model_and_the_law(interface):
    pair = rc.ContactMaterials.pair(STEEL_M, STEEL_M)
    assert interface.reduced_modulus == pytest.approx(pair.reduced_modulus, rel=1e-15)
    assert interface.model_name == "jacksonGreen"
    assert interface.conductance_law == rc.default_conductance_law()
    P = interface.table_pressures
    assert P.dtype == np.float64 and P.ndim == 1 and len(P) > 10 and np.all(np.diff(P) > 0)
    np.testing.assert_allclose(interface.area_fraction(P), interface.table_area_fractions, rtol=1e-12)
    np.testing.assert_allclose(interface.conductance_per_conductivity(P),
                               interface.table_conductances_per_conductivity, rtol=1e-12)
    model = rc.Model("jacksonGreen", interface.surface, pair)
    law = rc.ConductanceLaw(rc.default_conductance_law(), model=model, Eprime=pair.reduced_modulus,
                            roughness=rc.profile_roughness(rc.read_profile(STANDIN)),
                            hardness=2.84 * STEEL_M.Sy)
    some = P[::37]
    np.testing.assert_allclose(interface.table_area_fractions[::37], model.area_fraction(some), rtol=1e-12)
    np.testing.assert_allclose(interface.table_conductances_per_conductivity[::37],
                               law.conductance_per_conductivity(some), rtol=1e-12)


def test_the_default_law_unloads_by_its_branch(interface):
    """A multi-scale interface with the default law and a cap: below a peak h_c is the loading
    value times the law's unloading factor (roughcontact.fitted_unloading_factor on the profile's
    m, its spectrum's W, E', H = 2.84 S_y and its spectrum's H_f), A_r/A_n the loading one; the law alone gives the same with
    unload_from; a law without a branch refuses it."""
    pair = rc.ContactMaterials.pair(STEEL_M, STEEL_M)
    m = rc.profile_roughness(rc.read_profile(STANDIN)).mean_absolute_slope
    H = 2.84 * STEEL_M.Sy
    peak = 1e8
    P = np.array([1e6, 1e7, 5e7])
    Hf = rc.fine_hurst_exponent(interface.surface)
    assert Hf is not None
    W = rc.spectral_bandwidth_ratio(interface.surface)
    R = rc.fitted_unloading_factor(P, np.full(3, peak), np.full(3, m), np.full(3, W), np.full(3, pair.reduced_modulus),
                                   np.full(3, H), np.full(3, Hf))
    assert np.all(R > 1.0)
    assert interface.remembers_load and "unloading branch" in interface.load_history_note
    np.testing.assert_allclose(interface.conductance_per_conductivity(P, peak=peak),
                               R * interface.conductance_per_conductivity(P), rtol=1e-14)
    assert np.array_equal(interface.area_fraction(P, peak=peak), interface.area_fraction(P))
    model = rc.Model("jacksonGreen", interface.surface, pair)
    law = rc.ConductanceLaw(rc.default_conductance_law(), model=model, Eprime=pair.reduced_modulus,
                            roughness=rc.profile_roughness(rc.read_profile(STANDIN)), hardness=H)
    assert law.unloads
    np.testing.assert_allclose(law.conductance_per_conductivity(P, unload_from=peak),
                               R * law.conductance_per_conductivity(P), rtol=1e-14)
    assert np.array_equal(law.conductance_per_conductivity([2e8], unload_from=peak),
                          law.conductance_per_conductivity([2e8]))
    mikic = rc.ConductanceLaw("mikic", Eprime=pair.reduced_modulus,
                              roughness=rc.profile_roughness(rc.read_profile(STANDIN)))
    assert not mikic.unloads
    with pytest.raises(rc.ParameterError, match="^unload_from.*mikic has no unloading branch"):
        mikic.conductance_per_conductivity(P, unload_from=peak)


def test_queries(interface):
    assert interface.area_fraction(0.0) == 0.0 and interface.conductance_per_conductivity(-1.0) == 0.0
    P = np.array([[1e4, 1e5], [1e6, 1e7]])
    a = interface.area_fraction(P)
    assert a.shape == (2, 2) and a[1, 1] == interface.area_fraction(1e7)
    k1, k2 = 50.0, 16.0
    ks = 2 * k1 * k2 / (k1 + k2)
    np.testing.assert_allclose(interface.conductance(P, k1, k2), ks * interface.conductance_per_conductivity(P),
                               rtol=1e-14)
    assert not interface.has_separation
    assert np.all(np.isnan(interface.mean_separation(P)))
    assert interface.table_separations.shape == (0,)
    assert "jacksonGreen" in interface.summary()
    assert interface.table_end == interface.table_pressures[-1]
    assert interface.complete_contact_pressure > 0


def test_keywords_and_laws():
    ci = rc.ContactInterface(surfaces=[rc.SurfaceSpec.power_law(1e-4, 1.0, 1e3, 1e5)], side1=STEEL_M,
                             side2=STEEL_M, model="hertz", conductance="persson", min_pressure=1e3,
                             max_pressure=1e8, points_per_decade=10)
    assert ci.conductance_law == "persson" and ci.has_separation
    assert ci.table_pressures[0] == pytest.approx(1e3)
    assert ci.table_separations.shape == ci.table_pressures.shape
    model = rc.Model("persson", ci.surface, rc.ContactMaterials.pair(STEEL_M, STEEL_M))
    P = ci.table_pressures[:5]
    np.testing.assert_allclose(ci.conductance_per_conductivity(P), model.conductance_per_conductivity(P), rtol=1e-9)
    two = rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN), rc.SurfaceSpec.profile(STANDIN)],
                              side1=STEEL_M, side2=STEEL_M, model="hertz")
    assert two.surface.variance() == pytest.approx(2 * rc.SurfaceSpec.profile(STANDIN).read_spectrum().variance(),
                                                   rel=1e-12)


def test_boundary_element_interface():
    ci = rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                             model="boundaryElement", synthesize=16, seed=2, bem_points_per_decade=2)
    assert ci.model_name == "boundaryElement" and ci.has_separation
    assert np.all(np.diff(ci.table_area_fractions) >= 0)


def test_a_capped_boundary_element_interface_unloads():
    """With a hardness the table holds unloading curves (load_history, default True): below its
    peak a joint conducts as they say, more than on loading; at the peak, and without memory,
    the loading value; the peak keyword is checked."""
    kw = dict(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M, model="boundaryElement",
              synthesize=32, seed=2, hardness_from_yield=True)
    ci = rc.ContactInterface(**kw)
    assert ci.remembers_load and len(ci.unloading_peaks) >= 4
    assert "exact unloading curves" in ci.load_history_note
    peak = ci.unloading_peaks[-2]
    P = np.array([0.1, 0.3, 1.0]) * peak
    loading = ci.conductance(P, 50.0, 50.0)
    unloading = ci.conductance(P, 50.0, 50.0, peak=peak)
    assert unloading[0] > 1.05 * loading[0]  # a tenth of the peak: the flattened summits conduct more
    assert unloading[-1] == loading[-1]  # at the peak: the loading curve
    assert np.array_equal(ci.conductance_per_conductivity(P), ci.conductance_per_conductivity(P, peak=0.0))
    assert ci.area_fraction(P[0], peak=peak) > ci.area_fraction(P[0])
    with pytest.raises(rc.ParameterError, match="^peak"):
        ci.conductance(P, 50.0, 50.0, peak=float("nan"))
    with pytest.raises(rc.ParameterError, match="^peak"):
        ci.area_fraction(P, peak=-1.0)
    forgetful = rc.ContactInterface(**kw, load_history=False)
    assert not forgetful.remembers_load and forgetful.load_history_note == ""
    assert np.array_equal(forgetful.conductance(P, 50.0, 50.0, peak=peak), loading)


def test_boundary_element_table_file(tmp_path):
    """table_file (issue 21, item 3): the core's cache, as the condition keeps it in
    constant/boundaryElementTable.NAME.csv: written by the first build, read by the next (the same
    table to the last bit, its 17 digits read back exactly), rebuilt when it is not this table's."""
    kw = dict(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M, model="boundaryElement",
              synthesize=16, seed=2, bem_points_per_decade=2)
    path = tmp_path / "boundaryElementTable.slabs.csv"
    built = rc.ContactInterface(**kw, table_file=str(path))
    text = path.read_text()
    assert text.startswith("# roughContact boundary-element table v4") and "# sha256 " in text
    inode = path.stat().st_ino  # a rewrite is a new file renamed over it: a new inode
    again = rc.ContactInterface(**kw, table_file=str(path))
    assert path.read_text() == text and path.stat().st_ino == inode  # reused, not rewritten
    plain = rc.ContactInterface(**kw)
    for ci in (again, plain):
        assert np.array_equal(ci.table_pressures, built.table_pressures)
        assert np.array_equal(ci.table_conductances_per_conductivity, built.table_conductances_per_conductivity)
    # Another surface (seed 3) has another key: the file is rebuilt for it, not trusted.
    other = rc.ContactInterface(**dict(kw, seed=3), table_file=str(path))
    assert path.read_text() != text
    assert not np.array_equal(other.table_area_fractions, built.table_area_fractions)
    # The cache is the boundary-element model's only.
    with pytest.raises(rc.ParameterError, match="^table_file: .*boundaryElement"):
        rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                            model="hertz", table_file=str(path))
    # Issue 49, items 8 and 15: a file that is not a table of this project is refused and left as
    # it is (it was replaced after a warning); an empty name is refused before anything is built
    # (it was built, then "cannot rename '.tmp.PID' to ''").
    mine = tmp_path / "mydata.csv"
    mine.write_text("x,y\n1,2\n")
    with pytest.raises(rc.ParameterError, match="not a table of this project, so it is left as it is"):
        rc.ContactInterface(**kw, table_file=str(mine))
    assert mine.read_text() == "x,y\n1,2\n"
    with pytest.raises(rc.ParameterError, match="^table_file: is empty"):
        rc.ContactInterface(**kw, table_file="")


def test_errors():
    with pytest.raises(rc.ParameterError) as e:
        rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M, model="nope")
    assert e.value.parameter == "model" and "unknown multi-scale model 'nope'" in str(e.value)
    with pytest.raises(rc.InputError, match="cannot open the file for reading"):
        rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile("/nonexistent.csv")], side1=STEEL_M, side2=STEEL_M)
    with pytest.raises(rc.ParameterError, match="^surfaces: "):
        rc.ContactInterface(surfaces=[], side1=STEEL_M, side2=STEEL_M)
    with pytest.raises(TypeError):
        rc.ContactInterface([rc.SurfaceSpec.profile(STANDIN)], STEEL_M, STEEL_M)  # keywords only


def _described(doc):
    """pybind11 puts the signature first: a docstring must say more than that."""
    lines = [l for l in (doc or "").strip().splitlines() if l.strip()]
    return len(lines) > 1 or (len(lines) == 1 and "(" not in lines[0].split()[0])


def test_version():
    assert rc.__version__.count(".") == 2


def test_docstrings():
    # Every function, class, method and property of the module has its own docstring.
    assert "Pa" in rc.__doc__
    missing = []
    for name in dir(rc):
        if name.startswith("_"):
            continue
        obj = getattr(rc, name)
        if isinstance(obj, str):
            continue
        if not _described(obj.__doc__):
            missing.append(name)
        if isinstance(obj, type) and not issubclass(obj, Exception):
            for member, value in vars(obj).items():
                if member.startswith("_"):
                    continue
                doc = value.__doc__ if isinstance(value, property) else getattr(getattr(obj, member), "__doc__", None)
                if not _described(doc):
                    missing.append(f"{name}.{member}")
    assert missing == []


def test_roughness_surface_is_the_clis(cli):
    # SurfaceSpec.from_roughness and --roughness read the same entries through the core's reader:
    # the same table, so the same h_c/k_s (the table is within 0.5 % of the CLI's direct solve).
    steel = rc.Material(200e9, 0.3, 0.4e9)
    ci = rc.ContactInterface(surfaces=[rc.SurfaceSpec.from_roughness(Ra=0.4e-6, slope=0.1, cutoff=2.5e-3)],
                             side1=steel, side2=steel)
    r = cli("--roughness", f"{math.sqrt(math.pi / 2) * 0.4e-6!r},0.1,2.5e-3", "--model", "jacksonGreen",
            "--E", "200e9,200e9", "--nu", "0.3,0.3", "--Sy", "0.4e9,0.4e9", "--pressures", "1e6", "--conductance")
    assert r.status == 0, r.err
    header, row = r.out.strip().split("\n")[:2]
    h_cli = float(row.split(",")[header.split(",").index("h_per_k")])
    assert ci.conductance_per_conductivity(1e6) == pytest.approx(h_cli, rel=5e-3)
    assert "H = " in ci.surface.source  # the Hurst exponent found is said
    with pytest.raises(rc.ParameterError, match="^Ra: give one of Rq"):
        rc.SurfaceSpec.from_roughness(Rq=1e-6, Ra=1e-6, slope=0.1)
    with pytest.raises(rc.ParameterError, match="^slope: .*a Hurst exponent in"):
        rc.SurfaceSpec.from_roughness(Rq=1e-6, slope=1e-3).read_spectrum()


def _bands_page():
    """The bands table the validation study accuracyTable generates (law, reference, decade, band)."""
    import os
    path = os.path.join(os.environ["ROUGHCONTACT_SOURCE_DIR"], "docs", "validation", "generated", "accuracyTable",
                        "bands.md")
    rows = []
    for line in open(path).read().splitlines()[2:]:
        law, model, reference, decade, band = [c.strip() for c in line.strip("|").split("|")][:5]
        a = float(decade.split()[0])
        b = a * 1.000001 if decade.endswith("only") else float(decade.split()[-1])
        lo, hi = (float(v) for v in band.split("-"))
        rows.append((law, model, reference, a, b, lo, hi))
    return rows


def test_regime_and_band_at_pressures(interface):
    # The default law on jacksonGreen with a hardness: held to the capped reference. At each pressure
    # the band is the generated table's row for the decade of x = P/(E' h') that holds it.
    Ep = interface.reduced_modulus
    gradient = rc.areal_rms_gradient(interface.surface)
    rows = [r for r in _bands_page() if r[0] == rc.default_conductance_law() and r[2] == "capped"]
    x = np.array([2e-4, 3e-3, 5e-2])
    P = x * Ep * gradient
    low, high = interface.accuracy_band(P)
    for xi, lo, hi in zip(x, low, high):
        row = next(r for r in rows if r[3] * (1 - 1e-9) <= xi < r[4])
        assert (lo, hi) == (row[5], row[6])
    text = interface.regime_at(P)
    assert text.count("\n    at ") == 3 and "capped reference" in text
    assert f"{low[1]:.3g}-{high[1]:.3g} of exact" in text
    # Lighter than anything measured: NaN and "not measured"; no line for P <= 0.
    lo, hi = interface.accuracy_band(1e-9 * Ep * gradient)
    assert math.isnan(lo) and math.isnan(hi)
    assert "not measured" in interface.regime_at([1e-9 * Ep * gradient])
    assert interface.regime_at([0.0, -1.0]) == ""
    assert np.all(np.isnan(interface.accuracy_band([0.0])[0]))


def test_unloading_band_at_peaks(interface):
    # The default law's unloading branch: at a peak the band of R / exact R over the unloading
    # study's counted points (its smaller periods shown beside a larger one left out) and the
    # measured map's (unloadingMap) whose peak lies in the same decade of x, read here from the
    # studies' summary.csv themselves.
    import csv
    import os

    def summary(study):
        path = os.path.join(os.environ["ROUGHCONTACT_SOURCE_DIR"], "docs", "validation", "generated", study,
                            "summary.csv")
        with open(path) as f:
            return list(csv.DictReader(line for line in f if not line.startswith("#")))
    rows = [r for r in summary("unloading") if "beside" not in r["role"] and float(r["fraction"]) < 1]
    rows += summary("unloadingMap")
    Ep = interface.reduced_modulus
    gradient = rc.areal_rms_gradient(interface.surface)
    x = np.array([3e-4, 3e-3, 3e-2])
    low, high = interface.unloading_accuracy_band(x * Ep * gradient)
    for xi, lo, hi in zip(x, low, high):
        a = 10.0 ** math.floor(math.log10(xi))
        ratios = [float(r["branch_over_exact_ratio"]) for r in rows if a * (1 - 1e-9) <= float(r["peak_x"]) < 10 * a]
        assert len(ratios) > 10
        assert (lo, hi) == (float(f"{min(ratios):.3g}"), float(f"{max(ratios):.3g}"))
    # Beyond the study's heaviest peak, for a peak <= 0, and for a law without a branch: NaN.
    assert np.all(np.isnan(interface.unloading_accuracy_band([0.5 * Ep * gradient, 0.0])[0]))
    plain = rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                                conductance="mikic")
    assert np.all(np.isnan(plain.unloading_accuracy_band([3e-3 * Ep * gradient])[1]))


def test_keywords_left_out_are_the_cores_defaults():
    # Issue 52: the keywords default to None, "the core's default", not to copies of its values:
    # left out, the interface is the one the dictionary gives without those entries.
    surfaces = [rc.SurfaceSpec.profile(STANDIN)]
    plain = rc.ContactInterface(surfaces=surfaces, side1=STEEL_M, side2=STEEL_M)
    assert plain.model_name == "jacksonGreen" and plain.conductance_law == rc.default_conductance_law()
    named = rc.ContactInterface(surfaces=surfaces, side1=STEEL_M, side2=STEEL_M, model="jacksonGreen",
                                conductance=rc.default_conductance_law(), points_per_decade=40)
    np.testing.assert_array_equal(plain.table_pressures, named.table_pressures)
    np.testing.assert_array_equal(plain.table_conductances_per_conductivity,
                                  named.table_conductances_per_conductivity)
    # The docstring names the core's defaults, taken from the core.
    assert "model=None" in rc.ContactInterface.__init__.__doc__
    assert "(None: jacksonGreen)" in rc.ContactInterface.__init__.__doc__
    assert "(None: " + rc.default_conductance_law() + ")" in rc.ContactInterface.__init__.__doc__
    # A seed is of synthesize N: given alone, even as 1, it is refused (1 was a sentinel).
    with pytest.raises(rc.ParameterError, match="^seed: is the phases' seed of synthesize N"):
        rc.ContactInterface(surfaces=surfaces, side1=STEEL_M, side2=STEEL_M, model="boundaryElement", seed=1)
    # The model's rules with the entries of another, named as Python writes them.
    with pytest.raises(rc.ParameterError, match="^hardness_from_yield: is for model boundaryElement"):
        rc.ContactInterface(surfaces=surfaces, side1=STEEL_M, side2=STEEL_M, hardness_from_yield=True)


def test_a_profile_along_the_lay_makes_the_isotropic_equivalent(tmp_path):
    # Issue 53: a profile across the lay with one along it is the isotropic surface of their
    # averaged line-scan spectrum (docs/theory.md §1.6): z = a cos(kx x) + a cos(ky y), kx = 8 ky,
    # has the areal rms gradient a sqrt((kx^2 + ky^2)/2), which one profile across overstates.
    n, dx, a = 1024, 1e-6, 1e-6
    x = np.arange(n) * dx
    across = tmp_path / "across.txt"
    along = tmp_path / "along.txt"
    np.savetxt(across, np.column_stack([x, a * np.cos(2 * np.pi * 32 * np.arange(n) / n)]))
    np.savetxt(along, np.column_stack([x, a * np.cos(2 * np.pi * 4 * np.arange(n) / n)]))
    kx, ky = 2 * np.pi * 32 / (n * dx), 2 * np.pi * 4 / (n * dx)
    both = rc.SurfaceSpec.profile(str(across), along_lay=str(along))
    one = rc.SurfaceSpec.profile(str(across))
    # One profile says what it cannot know (a UserWarning naming along_lay); two directions do not.
    with pytest.warns(UserWarning, match=r"one profile is taken as a line scan.*along_lay"):
        rc.ContactInterface(surfaces=[one], side1=STEEL_M, side2=STEEL_M)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rc.ContactInterface(surfaces=[both], side1=STEEL_M, side2=STEEL_M)
    r = both.roughness()
    assert r.sigma == pytest.approx(a / math.sqrt(2), rel=0.01)
    assert r.mean_absolute_slope == pytest.approx(a * (kx + ky) / math.pi, rel=0.01)
    assert one.roughness().mean_absolute_slope == pytest.approx(2 * a * kx / math.pi, rel=0.01)
    two = rc.ContactInterface(surfaces=[both], side1=STEEL_M, side2=STEEL_M)
    single = rc.ContactInterface(surfaces=[one], side1=STEEL_M, side2=STEEL_M)
    assert two.surface.source.endswith("along.txt along the lay")
    assert not np.allclose(two.table_area_fractions[:10], single.table_area_fractions[:10])
    with pytest.raises(rc.InputError, match="missing.txt: cannot open"):  # named as the file it is
        rc.SurfaceSpec.profile(str(across), along_lay=str(tmp_path / "missing.txt")).roughness()
