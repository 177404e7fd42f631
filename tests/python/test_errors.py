# SPDX-License-Identifier: GPL-3.0-or-later
"""Errors from Python: the core's InputError and ParameterError as roughcontact.InputError and
roughcontact.ParameterError (subclasses of ValueError) with the same message as the C++ what(),
which multiscaleContact prints after 'multiscaleContact: error: '."""
import numpy as np
import pytest

import roughcontact as rc
from conftest import STANDIN, STEEL, STEEL_ARGS


def test_exception_types():
    assert issubclass(rc.InputError, ValueError)
    assert issubclass(rc.ParameterError, ValueError)
    assert not issubclass(rc.InputError, rc.ParameterError)
    assert rc.InputError.__module__ == "roughcontact" and rc.InputError.__doc__


def test_missing_file(tmp_path, cli):
    path = str(tmp_path / "missing.csv")
    with pytest.raises(rc.InputError) as e:
        rc.read_profile(path)
    # InputError(path, 0, ...): "FILE: message" (no line).
    assert str(e.value) == path + ": cannot open the file for reading: there is no such file"
    assert (e.value.file, e.value.line, e.value.message) == (path, 0, "cannot open the file for reading: there is no such file")
    for reader in (lambda: rc.Spectrum.read(path), lambda: rc.read_areal(path, dx=1e-6)):
        with pytest.raises(rc.InputError, match="cannot open the file for reading"):
            reader()
    # The CLI refuses a missing file before the core reads it (its option check), naming it too.
    r = cli("--profile", path, "--model", "hertz", *STEEL_ARGS, "--loads", "1e-4")
    assert r.status == 1 and r.out == "" and path in r.err


def test_bad_file_content_same_message_as_the_cli(tmp_path, cli):
    f = tmp_path / "bad.csv"
    f.write_text("x z\n0 1e-8\n1e-6 2e-8\n2e-6 oops\n")
    with pytest.raises(rc.InputError) as e:
        rc.read_profile(str(f))
    assert e.value.line == 4 and str(e.value).startswith(str(f) + ":4: ")
    r = cli("--profile", f, "--model", "hertz", *STEEL_ARGS, "--loads", "1e-4")
    assert r.status == 1 and r.out == ""
    assert r.error() == str(e.value)


@pytest.mark.parametrize("python, args", [
    (lambda s: rc.Model("hertz", s, rc.Material(1.0, 0.3)), ["--model", "hertz", "--E", "1", "--nu", "0.3"]),
    (lambda s: rc.Model("jacksonGreen", s, rc.Material(200e9, 0.3)),
     ["--model", "jacksonGreen", "--E", "200e9", "--nu", "0.3"]),
    (lambda s: rc.Model("hertz", s, rc.Material(**STEEL)).area_fraction_at_load(1e5),
     ["--model", "hertz", *STEEL_ARGS, "--loads", "1e5"]),
    (lambda s: rc.ConductanceLaw("noSuchLaw", model=rc.Model("hertz", s, rc.Material(**STEEL))),
     ["--model", "hertz", *STEEL_ARGS, "--conductance-law", "noSuchLaw"]),
])
def test_bad_parameter_same_message_as_the_cli(cli, python, args):
    spectrum = rc.Spectrum.from_profile(rc.read_profile(STANDIN))
    with pytest.raises(rc.ParameterError) as e:
        python(spectrum)
    full = ["--profile", STANDIN, *args]
    if "--loads" not in full:
        full += ["--loads", "1e-4"]
    r = cli(*full)
    assert r.status == 1 and r.out == ""
    assert r.error() == str(e.value)
    assert str(e.value).startswith(e.value.parameter + ": ")


def test_bad_unit_same_message_as_the_cli_naming_each_its_own_way(cli):
    # The same rule and words (parseLengthUnit); the CLI names its option, Python its argument.
    with pytest.raises(rc.ParameterError) as e:
        rc.read_profile(STANDIN, units="inch")
    assert str(e.value) == "units: unknown unit 'inch'; use m, um or nm"
    r = cli("--profile", STANDIN, "--model", "hertz", *STEEL_ARGS, "--units", "inch", "--loads", "1e-4")
    assert r.status == 1 and r.out == ""
    assert r.error() == "--" + str(e.value)


def test_parameter_errors_in_vectorized_calls():
    model = rc.Model("hertz", rc.Spectrum.from_profile(rc.read_profile(STANDIN)), rc.Material(**STEEL))
    with pytest.raises(rc.ParameterError, match="^load: "):
        model.area_fraction(np.array([1e6, np.nan]))
    with pytest.raises(rc.ParameterError):
        model.area_fraction(-1.0)
    with pytest.raises(TypeError):
        model.area_fraction(object())
    # ValueError catches both (the Pythonic way).
    with pytest.raises(ValueError):
        rc.Profile(np.zeros(3), 1e-6)
    with pytest.raises(ValueError):
        rc.synthesize_isotropic(rc.Spectrum.power_law(1e-9, 1, 1e3, 1e5), 7)


def test_yield_strength_on_one_side_only():
    """Issue 21: S_y given for one side only is an error naming the other side, unless that side
    is said not to yield (elastic=True); then the first side's S_y governs."""
    surfaces = [rc.SurfaceSpec.profile(STANDIN)]
    steel = rc.Material(**STEEL)
    forgot = rc.Material(STEEL["E"], STEEL["nu"])
    with pytest.raises(rc.ParameterError) as e:
        rc.ContactInterface(surfaces=surfaces, side1=steel, side2=forgot)
    assert str(e.value).startswith("side2 yield strength S_y: is not given, while side1 has one")
    assert "elastic=True" in str(e.value)
    ceramic = rc.Material(STEEL["E"], STEEL["nu"], elastic=True)
    assert ceramic.elastic and ceramic.Sy is None and "elastic" in repr(ceramic)
    one = rc.ContactInterface(surfaces=surfaces, side1=steel, side2=ceramic)
    both = rc.ContactInterface(surfaces=surfaces, side1=steel, side2=steel)
    # Same E and nu, and the same S_y yields: the same interface.
    assert list(one.conductance_per_conductivity([1e5, 1e6, 1e7])) == \
        list(both.conductance_per_conductivity([1e5, 1e6, 1e7]))
    with pytest.raises(rc.ParameterError, match="also said not to yield"):
        rc.ContactInterface(surfaces=surfaces, side1=steel, side2=rc.Material(**STEEL, elastic=True))
    with pytest.raises(rc.ParameterError, match="second material yield strength S_y"):
        rc.ContactMaterials.pair(steel, forgot)
