# SPDX-License-Identifier: GPL-3.0-or-later
"""The module under a locale whose decimal point is a comma (issue 18, item 8): a Python program
that calls locale.setlocale(locale.LC_ALL, 'de_DE.UTF-8') switches the C library's LC_NUMERIC
for the whole process, and a core that parsed with strtod would read '8.2477e-08' as 8 (or
refuse it) and write '1,5' with printf. Every reader gives the same numbers as under the C
locale, and the messages are the same.

The locale must exist or this test means nothing, so it never skips: de_DE.UTF-8 as the system
has it, else built with localedef (libc-bin) from the Debian package 'locales'
(/usr/share/i18n/locales/de_DE, /usr/share/i18n/charmaps/UTF-8.gz; etc/debianPackages) into a
private directory, LOCPATH pointing there only while setlocale loads it. Without the package the
test fails and says so."""
import contextlib
import ctypes
import locale
import os
import shutil
import subprocess

import numpy as np
import pytest

import roughcontact as rc
from conftest import DEKTAK, STANDIN, STEEL, X3P

COMMA_LOCALE = "de_DE.UTF-8"
STEEL_M = rc.Material(**STEEL)


def set_comma_locale(locpath):
    """setlocale(LC_ALL, COMMA_LOCALE), from locpath (a LOCPATH directory) when given. glibc reads
    LOCPATH at each setlocale call, and the data stays loaded once set, so it is unset again."""
    if locpath is None:
        locale.setlocale(locale.LC_ALL, COMMA_LOCALE)
        return
    saved = os.environ.get("LOCPATH")
    os.environ["LOCPATH"] = locpath
    try:
        locale.setlocale(locale.LC_ALL, COMMA_LOCALE)
    finally:
        if saved is None:
            del os.environ["LOCPATH"]
        else:
            os.environ["LOCPATH"] = saved


@pytest.fixture(scope="module")
def comma_locpath(tmp_path_factory):
    """None when the system has COMMA_LOCALE, else a directory holding it (built here)."""
    saved = locale.setlocale(locale.LC_ALL)
    try:
        try:
            set_comma_locale(None)
            return None
        except locale.Error:
            pass
        localedef = shutil.which("localedef") or "/usr/bin/localedef"
        directory = tmp_path_factory.mktemp("locales")
        r = subprocess.run([localedef, "-i", "de_DE", "-f", "UTF-8", str(directory / COMMA_LOCALE)],
                           capture_output=True, text=True, timeout=300)
        try:
            set_comma_locale(str(directory))
        except locale.Error:
            pytest.fail(f"no locale {COMMA_LOCALE}, and localedef could not build one (exit {r.returncode}: "
                        f"{r.stderr.strip()}); install the Debian package 'locales' (its "
                        "/usr/share/i18n/locales/de_DE and charmaps/UTF-8.gz)")
        return str(directory)
    finally:
        locale.setlocale(locale.LC_ALL, saved)


@pytest.fixture
def comma_decimal(comma_locpath):
    """A context manager whose body runs under COMMA_LOCALE (its decimal point a comma). The
    locale the process had is restored on leaving it, and after the test whatever it did."""
    saved = locale.setlocale(locale.LC_ALL)
    assert locale.localeconv()["decimal_point"] == "."

    @contextlib.contextmanager
    def under():
        set_comma_locale(comma_locpath)
        try:
            assert locale.localeconv()["decimal_point"] == ","
            yield
        finally:
            locale.setlocale(locale.LC_ALL, saved)

    try:
        yield under
    finally:
        left = locale.setlocale(locale.LC_ALL)
        locale.setlocale(locale.LC_ALL, saved)
    assert left == saved and locale.localeconv()["decimal_point"] == "."


def test_the_locale_is_real_and_restored(comma_decimal):
    with comma_decimal():
        # What the C library's strtod does in it (the core's parsing before item 8): '1,5' is
        # 1.5 and '8.2477e-08' is read only as far as the '.'.
        strtod = ctypes.CDLL(None).strtod
        strtod.restype, strtod.argtypes = ctypes.c_double, [ctypes.c_char_p, ctypes.c_void_p]
        assert strtod(b"1,5", None) == 1.5
        assert strtod(b"8.2477e-08", None) == 8.0
    assert locale.localeconv()["decimal_point"] == "."


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """Text files of every kind the module reads, written with '.' decimals (repr of floats)."""
    d = tmp_path_factory.mktemp("files")
    spectrum = rc.Spectrum.power_law(1.2345e-9, 0.875, 1.5e3, 2.5e5, 6.75e-4)
    (d / "spectrum.csv").write_text("".join(f"{f!r},{b!r}\n" for f, b in zip(spectrum.frequencies,
                                                                                 spectrum.amplitudes)))
    z = np.random.default_rng(18).normal(0.0, 1.25e-7, (24, 32))
    (d / "matrix.txt").write_text("".join(" ".join(repr(v) for v in row) + "\n" for row in z))
    (d / "heights.txt").write_text("".join(f"{v!r}\n" for v in z[0]))
    return d


def reads(files):
    """Every read, as {name: a tuple of numbers} (arrays flattened to lists)."""
    interface = rc.ContactInterface(
        surfaces=[rc.SurfaceSpec.profile(STANDIN), rc.SurfaceSpec.spectrum(str(files / "spectrum.csv"))],
        side1=STEEL_M, side2=STEEL_M, model="jacksonGreen", points_per_decade=10)
    areal_interface = rc.ContactInterface(
        surfaces=[rc.SurfaceSpec.areal(str(files / "matrix.txt"), units="um", dx=0.5)],
        side1=STEEL_M, side2=STEEL_M, model="hertz", points_per_decade=10)
    out = {}
    for name, profile in (("dektak", rc.read_profile(DEKTAK)), ("standin", rc.read_profile(STANDIN)),
                          ("one column", rc.read_profile(str(files / "heights.txt"), units="nm", spacing=2.5))):
        out[name] = (profile.spacing, *profile.heights)
    for name, areal in (("x3p", rc.read_areal(X3P)),
                        ("matrix", rc.read_areal(str(files / "matrix.txt"), units="um", dx=0.5, dy=0.75))):
        out[name] = (areal.dx, areal.dy, *areal.heights.ravel())
    s = rc.Spectrum.read(str(files / "spectrum.csv"))
    out["spectrum"] = (s.length, *s.frequencies, *s.amplitudes)
    for name, ci in (("interface", interface), ("areal interface", areal_interface)):
        out[name] = (*ci.table_pressures, *ci.table_area_fractions, *ci.table_conductances_per_conductivity,
                     ci.conductance(1e6, 16.0, 50.0))
    return out


def test_reads_give_the_same_numbers_under_a_comma_decimal_locale(files, comma_decimal):
    expected = reads(files)
    with comma_decimal():
        got = reads(files)
    assert got.keys() == expected.keys()
    for name in expected:
        assert got[name] == expected[name], name


def error_messages(files, tmp_path):
    """str() of errors whose messages hold numbers."""
    bad = tmp_path / "bad.csv"
    bad.write_text("x z\n0 1.5e-8\n1e-6 2.5e-8\n2e-6 oops\n")
    spectrum = rc.Spectrum.read(str(files / "spectrum.csv"))
    law = rc.ConductanceLaw("mikic", roughness=rc.SurfaceRoughness(1.5e-6, 0.125), Eprime=1.25e11)
    model = rc.Model("hertz", spectrum, STEEL_M)
    calls = [
        lambda: rc.read_profile(str(bad)),
        lambda: rc.Model("hertz", spectrum, rc.Material(1.5, 0.3)),
        lambda: model.area_fraction(-2.5),
        lambda: law.conductance_per_conductivity(-2.5),
        lambda: rc.Spectrum.power_law(1e-9, 0.5, 1e3, 1e5, 1.5e4),
        lambda: rc.GasGap(rc.gas("air"), 2.5e12),
    ]
    out = []
    for call in calls:
        with pytest.raises(ValueError) as e:
            call()
        out.append(str(e.value))
    return out


def test_messages_are_the_same_under_a_comma_decimal_locale(files, tmp_path, comma_decimal):
    expected = error_messages(files, tmp_path)
    with comma_decimal():
        got = error_messages(files, tmp_path)
    assert got == expected


def test_reprs_are_the_same_under_a_comma_decimal_locale(comma_decimal):
    # The module's own (iostreams: the C++ global locale, not the C library's).
    objects = lambda: [rc.read_profile(STANDIN), rc.Spectrum.power_law(1e-9, 0.5, 1e3, 1e5), STEEL_M,
                       rc.SurfaceRoughness(1.5e-6, 0.125), rc.gas("air")]
    expected = [repr(x) for x in objects()]
    with comma_decimal():
        got = [repr(x) for x in objects()]
    assert got == expected
