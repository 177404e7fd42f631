# SPDX-License-Identifier: GPL-3.0-or-later
"""The engineering-range report's joint (docs/validation/engineeringRangeReport, `joint`): periodic
cells side by side under one rigid flat share its separation, so the joint's p and h_c are the
cells' means at one separation. Held to cells whose ln p and ln h_c are exactly linear in the
separation d, where the joint has a closed form: p_i = a_i exp(-d/s), h_i = b_i exp(-d/t) give,
at the mean pressure pe, d = s ln(mean a / pe) and h = mean b exp(-d/t)."""
import importlib.machinery
import importlib.util
import math
import sys

import pytest

from conftest import SOURCE_DIR


@pytest.fixture(scope="module")
def report():
    argv = sys.argv
    sys.argv = ["engineeringRangeReport", "--reuse"]  # its options are read on import; main() does not run
    try:
        loader = importlib.machinery.SourceFileLoader(
            "engineeringRangeReport", str(SOURCE_DIR / "docs" / "validation" / "engineeringRangeReport"))
        spec = importlib.util.spec_from_loader("engineeringRangeReport", loader)
        module = importlib.util.module_from_spec(spec)
        loader.exec_module(module)
    finally:
        sys.argv = argv
    return module


S, T = 0.4e-6, 0.7e-6  # the decay lengths of p and h_c in the separation [m]


def cell(a, b, separations):
    return [{"nominal_pressure_per_Eprime": repr(a * math.exp(-d / S)), "h_per_k": repr(b * math.exp(-d / T)),
             "separation": repr(d)} for d in separations]


def closed_form(cells, pe):
    a = sum(c[0] for c in cells) / len(cells)
    b = sum(c[1] for c in cells) / len(cells)
    d = S * math.log(a / pe)
    return b * math.exp(-d / T)


DS = [1e-6 + 0.3e-6 * k for k in range(6)]  # each cell's solved separations, heaviest load first
# rel=1e-9 below: on these cells the linear interpolation in ln p and ln h_c is exact, and the
# bisection halves its bracket 100 times, so only rounding is left (about 1e-15); any error of
# the method (a wrong mean, a wrong segment) moves h by percents.


def test_one_cell_is_that_cell(report):
    pe = 1e-3 * math.exp(-2.2e-6 / S)
    j = report.joint([cell(1e-3, 500.0, DS)], pe, 8e-3)
    h, steps = j["h"], j["steps"]
    assert h == pytest.approx(500.0 * math.exp(-2.2e-6 / T), rel=1e-9)
    assert steps == 0.0


def test_cells_at_one_separation_not_one_pressure(report):
    # Two cells, one with taller summits (it carries 5 times the other's load at any separation).
    cells = [(5e-3, 800.0), (1e-3, 300.0)]
    pe = 2e-3 * math.exp(-2.0e-6 / S)
    j = report.joint([cell(a, b, DS) for a, b in cells], pe, 8e-3)
    h, steps = j["h"], j["steps"]
    assert h == pytest.approx(closed_form(cells, pe), rel=1e-9)
    assert steps == 0.0
    # The cells' pull on each other: kappa = pe period / s, s = -dd/d ln p = S for these cells.
    assert j["kappa"] == pytest.approx(pe * 8e-3 / S, rel=1e-9)
    # Not the cells' mean at the joint's pressure each (what a periodic cell alone is held to): for
    # these cells the two differ by 5.1 % (h / at_pressure = 0.949), so a joint that averaged at one
    # pressure would fail here as well as above.
    at_pressure = sum(b * (pe / a) ** (S / T) for a, b in cells) / len(cells)
    assert abs(h / at_pressure - 1) > 0.05


def test_beyond_the_solved_loads_it_extrapolates_and_says_how_far(report):
    cells = [(5e-3, 800.0), (1e-3, 300.0)]
    # A load so light that the second cell's share lies beyond its largest solved separation.
    d_star = DS[-1] + 0.45e-6  # the joint's separation: 1.5 of the cells' steps (0.3 um) beyond
    pe = 3e-3 * math.exp(-d_star / S)
    j = report.joint([cell(a, b, DS) for a, b in cells], pe, 8e-3)
    h, steps = j["h"], j["steps"]
    assert h == pytest.approx(closed_form(cells, pe), rel=1e-9)  # ln p, ln h_c linear: exact
    assert steps == pytest.approx(1.5, rel=1e-6)


def test_a_cell_with_one_load_or_no_cell_gives_none(report):
    assert report.joint([], 1e-5, 8e-3) is None
    assert report.joint([cell(1e-3, 500.0, DS[:1]), cell(1e-3, 500.0, DS)], 1e-5, 8e-3) is None
