# SPDX-License-Identifier: GPL-3.0-or-later
"""What the module refuses before the core sees it (issue 18, items 13 and 14): numbers given as
text or as bools (numpy's forcecast and float() would read '1e6' as 1e6 and True as 1.0), paths
the core must not open (a NUL byte inside, a directory), and conductivities outside the accepted
range (k_s = 2 k1 k2/(k1 + k2) overflowed)."""
import fractions
import math

import numpy as np
import pytest

import roughcontact as rc
from conftest import DEKTAK, STANDIN, STEEL, X3P

STEEL_M = rc.Material(**STEEL)


@pytest.fixture(scope="module")
def spectrum():
    return rc.Spectrum.from_profile(rc.read_profile(STANDIN))


@pytest.fixture(scope="module")
def model(spectrum):
    return rc.Model("hertz", spectrum, STEEL_M)


@pytest.fixture(scope="module")
def interface():
    return rc.ContactInterface(surfaces=[rc.SurfaceSpec.power_law(1e-4, 1.0, 1e3, 1e5)], side1=STEEL_M,
                               side2=STEEL_M, model="hertz", points_per_decade=10)


# ---- "a number or an array of numbers": a TypeError that names the argument

NOT_NUMBERS = [
    "1e6", b"1e6", True, False, np.bool_(True), None,
    np.array(True), np.array([True, False]), np.array(["1e6", "2e6"]), np.array([b"1e6"]),
    ["1e6", "2e6"], [True, False], np.array([1.0, "x"], dtype=object), np.array([1.0, None], dtype=object),
    np.array([1.0, True], dtype=object), np.array([1 + 2j]), object(),
]
NOT_NUMBERS_IDS = [
    "str", "bytes", "True", "False", "numpy.bool_", "None",
    "0-d bool array", "bool array", "str array", "bytes array",
    "list of str", "list of bool", "object array with str", "object array with None",
    "object array with bool", "complex array", "object",
]


def vectorized_calls(model, interface, spectrum):
    """(argument name, call taking that argument) for every function of "a number or an array of
    numbers" (and every array argument) of the module."""
    law = rc.ConductanceLaw("jacksonBhavnaniFerguson", model=model)
    persson = rc.Model("persson", spectrum, STEEL_M)
    gas = rc.GasGap(rc.gas("air"))
    gapped = rc.ContactInterface(surfaces=[rc.SurfaceSpec.power_law(1e-4, 1.0, 1e3, 1e5)], side1=STEEL_M,
                                 side2=STEEL_M, model="hertz", points_per_decade=10,
                                 gap=rc.GapSpec(gas="air"))
    areal = rc.ArealSurface(np.random.default_rng(1).normal(0, 1e-6, (16, 16)), 1e-6)
    bem = rc.BoundaryElement(areal, STEEL_M)
    return [
        ("pressures", lambda x: model.area_fraction(x)),
        ("loads", lambda x: model.area_fraction_at_load(x)),
        ("pressures", lambda x: persson.mean_separation(x)),
        ("pressures", lambda x: persson.conductance_per_conductivity(x)),
        ("pressures", lambda x: law.conductance_per_conductivity(x)),
        ("pressures", lambda x: law.mean_separation(x)),
        ("pressures", lambda x: interface.area_fraction(x)),
        ("pressures", lambda x: interface.conductance_per_conductivity(x)),
        ("pressures", lambda x: interface.conductance(x, 16.0, 16.0)),
        ("pressures", lambda x: interface.mean_separation(x)),
        ("pressures", lambda x: gapped.gap_separation(x)),
        ("separation", lambda x: gapped.gap_conductances(x, 300.0, 300.0)),
        ("pressures", lambda x: bem.area_fraction(x)),
        ("pressures", lambda x: bem.curve(x)),
        ("T", lambda x: gas.conductivity(x)),
        ("T", lambda x: gas.mean_free_path(x)),
        ("T", lambda x: gas.rarefaction(x)),
        ("separation", lambda x: gas.conductance(x, 300.0)),
        ("T1", lambda x: rc.radiative_conductance(x, 300.0, 0.5, 0.5)),
        ("T2", lambda x: rc.radiative_conductance(300.0, x, 0.5, 0.5)),
        ("e1", lambda x: rc.radiative_conductance(300.0, 300.0, x, 0.5)),
        ("e2", lambda x: rc.radiative_conductance(300.0, 300.0, 0.5, x)),
        ("pressures", lambda x: rc.gap_separation(x, 1e-6, 1e9)),
        ("pressures", lambda x: rc.gap_separation_gaussian(x, 1e-6, 1e9)),
        ("heights", lambda x: rc.Profile(x, 1e-6)),
        ("frequencies", lambda x: rc.Spectrum(x, [1e-9, 1e-10], 1e-3)),
        ("amplitudes", lambda x: rc.Spectrum([1e3, 2e3], x, 1e-3)),
        ("heights", lambda x: rc.ArealSurface(x, 1e-6)),
    ]


@pytest.mark.parametrize("bad", NOT_NUMBERS, ids=NOT_NUMBERS_IDS)
def test_numbers_refuse_text_and_bools_naming_the_argument(model, interface, spectrum, bad):
    for name, call in vectorized_calls(model, interface, spectrum):
        with pytest.raises(TypeError, match="^" + name + ": expected a number or an array of numbers, not "):
            call(bad)


def test_numbers_still_take_numbers(model, interface):
    # Floats, ints, numpy real scalars and arrays of any real dtype, lists, object arrays of real
    # numbers (Fraction among them): the same values as the float64 array.
    P = np.array([1e5, 1e6, 1e7])
    expected = model.area_fraction(P)
    assert isinstance(expected, np.ndarray) and expected.dtype == np.float64
    for given in (list(P), tuple(P), P.astype(np.float32).astype(np.float64), P.astype(object),
                  np.array([fractions.Fraction(10**5), 10**6, np.float64(1e7)], dtype=object)):
        np.testing.assert_array_equal(model.area_fraction(given), expected)
    np.testing.assert_array_equal(model.area_fraction(np.array([100000, 1000000, 10000000], dtype=np.int64)),
                                  expected)
    np.testing.assert_array_equal(model.area_fraction(np.array([100000, 1000000, 10000000], dtype=np.uint32)),
                                  expected)
    for scalar in (1e6, 10**6, np.float64(1e6), np.int32(10**6), np.array(1e6), fractions.Fraction(10**6)):
        value = model.area_fraction(scalar)
        assert type(value) is float and value == expected[1]
    assert interface.conductance(1e6, 16, 16) == interface.conductance(1e6, 16.0, 16.0)
    assert rc.radiative_conductance(np.array([300, 400]), 300, 1, 1).shape == (2,)


@pytest.mark.parametrize("bad", ["1e6", b"1e6", True, np.bool_(True), np.array(True), 1j],
                         ids=["str", "bytes", "True", "numpy.bool_", "0-d bool array", "complex"])
def test_scalar_floats_refuse_text_and_bools(interface, bad):
    # Every scalar float argument (a modulus, a spacing, a conductivity, a temperature, in an
    # optional or a pair too): pybind11's TypeError, which lists the signature with the names.
    calls = [
        lambda: interface.conductance(1e6, bad, 16.0),
        lambda: interface.conductance(1e6, 16.0, bad),
        lambda: rc.Material(bad, 0.3),
        lambda: rc.Material(200e9, bad),
        lambda: rc.Material(200e9, 0.3, bad),
        lambda: rc.read_profile(STANDIN, spacing=bad),
        lambda: rc.Spectrum.power_law(bad, 1.0, 1e3, 1e5),
        lambda: rc.gap_separation(1e6, bad, 1e9),
        lambda: rc.GasGap(rc.gas("air"), bad),
        lambda: rc.GasGap(rc.gas("air")).conductance(1e-6, bad),
        lambda: rc.ContactInterface(surfaces=[rc.SurfaceSpec.power_law(1e-4, 1.0, 1e3, 1e5)], side1=STEEL_M,
                                    side2=STEEL_M, model="hertz", min_pressure=bad),
        lambda: rc.ContactInterface(surfaces=[rc.SurfaceSpec.power_law(1e-4, 1.0, 1e3, 1e5)], side1=STEEL_M,
                                    side2=STEEL_M, model="hertz", vickers=(bad, -0.2)),
    ]
    for call in calls:
        with pytest.raises(TypeError, match="incompatible (function|constructor) arguments"):
            call()
    material = rc.Material(200e9, 0.3)
    with pytest.raises(TypeError):
        material.E = bad  # a property's setter too
    assert material.E == 200e9


def test_scalar_floats_still_take_numbers():
    a = rc.Material(200e9, 0.3, 2e8)
    for E in (200e9, 200 * 10**9, np.float64(200e9), np.int64(200 * 10**9), np.array(200e9),
              fractions.Fraction(200 * 10**9)):
        assert rc.Material(E, 0.3, 2e8).E == a.E
    assert rc.Material(200e9, 0, 2e8).nu == 0.0


# ---- k_s = 2 k1 k2/(k1 + k2): conductivities within Limits.hpp's range, where it cannot overflow

def test_conductivities_outside_the_accepted_range_are_refused(interface):
    per_k = interface.conductance_per_conductivity(1e6)
    assert 0 < per_k < math.inf
    # k1 = 1e308 against 16 gave inf (2 k1 k2 overflowed): now refused, naming the side and range.
    for k1, k2 in ((1e308, 16.0), (16.0, 1e308), (1e-5, 16.0), (0.0, 16.0), (16.0, -1.0), (math.inf, 16.0),
                   (16.0, math.nan)):
        with pytest.raises(rc.ParameterError, match=r"^conductivity k[12]: must lie within \[0.0001 W/\(m K\), "):
            interface.conductance(1e6, k1, k2)
    # At the ends of the range: finite, k_s = k for equal sides.
    for k in (1e-4, 1e5):
        assert interface.conductance(1e6, k, k) == pytest.approx(k * per_k, rel=1e-14)
    assert interface.conductance(1e6, 15.0, 200.0) == pytest.approx(2 * 15 * 200 / 215 * per_k, rel=1e-15)


# ---- paths the core must refuse (the core's file opening: a NUL byte, a directory)

def opening_calls(path):
    """Every way of the module to open a file, on path (an areal file: an X3P one by its name,
    else a text matrix, which needs dx)."""
    dx = None if path.lower().endswith(".x3p") else 1e-6
    return {
        "read_profile": lambda: rc.read_profile(path),
        "read_areal": lambda: rc.read_areal(path, dx=dx),
        "Spectrum.read": lambda: rc.Spectrum.read(path),
        "SurfaceSpec.profile": lambda: rc.SurfaceSpec.profile(path).read_spectrum(),
        "SurfaceSpec.spectrum": lambda: rc.SurfaceSpec.spectrum(path).read_spectrum(),
        "SurfaceSpec.areal": lambda: rc.SurfaceSpec.areal(path, dx=dx).read_spectrum(),
        "ContactInterface": lambda: rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(path)], side1=STEEL_M,
                                                        side2=STEEL_M, model="hertz"),
    }


@pytest.mark.parametrize("real", [DEKTAK, STANDIN, X3P])
def test_a_path_with_a_nul_byte_is_refused(real):
    # 'dektak-1.csv\0junk' must not read dektak-1.csv (the C library stops at the NUL).
    path = real + "\0junk"
    for what, call in opening_calls(path).items():
        with pytest.raises(rc.InputError) as e:
            call()
        assert real in str(e.value), what


def test_a_directory_is_an_input_error(tmp_path):
    # Not a bare RuntimeError (nor an IsADirectoryError, nor a read of nothing): InputError
    # naming the path, as for a missing file.
    for name in ("somedir.x3p", "somedir.csv", "somedir"):
        d = tmp_path / name
        d.mkdir()
        for what, call in opening_calls(str(d)).items():
            with pytest.raises(rc.InputError) as e:
                call()
            assert str(d) in str(e.value), what
