# SPDX-License-Identifier: GPL-3.0-or-later
"""The gap beside the contact from Python: gases, h_g, h_r, the separation, ContactInterface's gap.

Independent numbers (as tests/core/interface/testFaceCoupling.cpp): air at 300 K and 1 atm has
k_g = 0.0262 W/(m K) and, with the default accommodation 0.9 on both sides, M = [2 (2 - 0.9)/0.9]
[2 (1.4)/2.4] 61.52 nm/0.712 = 246.4 nm; at Y = 10 um, h_g = 0.0262/10.2464e-6 = 2557.0 W/(m^2 K).
Two grey plates at 300 K with e = 0.5: h_r = 4 sigma_SB T^3/3 = 2.0413 W/(m^2 K). Tolerance
1e-3 relative: the constants are written here to four or five digits.
"""
import math

import numpy as np
import pytest
import roughcontact as rc
from conftest import STANDIN, STEEL

STEEL_M = rc.Material(**STEEL)
SIGMA_SB = 5.670374419e-8


def test_gases_by_name():
    assert rc.gas_names() == ["air", "helium", "argon", "nitrogen"]
    air = rc.gas("air")
    assert air.name == "air" and air.conductivity == pytest.approx(0.0262, rel=1e-12)
    with pytest.raises(rc.ParameterError, match="unknown gas"):
        rc.gas("xenon")


def test_air_gap_closed_forms():
    air = rc.GasGap(rc.gas("air"))
    assert air.accommodation == (0.9, 0.9)
    assert rc.GasGap(rc.gas("air"), accommodation=(1.0, 0.5)).accommodation == (1.0, 0.5)
    # The default is None (left out); 0 is outside (0, 1] like any other (issue 18, item 15).
    for bad in ((0.0, 0.9), (0.9, 0.0), (1e-300, 0.9), (1.5, 0.9)):
        with pytest.raises(rc.ParameterError, match="^accommodation coefficient a[12]: must lie in"):
            rc.GasGap(rc.gas("air"), accommodation=bad)
    with pytest.raises(rc.ParameterError, match="^accommodation: is for a gas"):
        rc.GapSpec(gas=None, accommodation=(0.9, 0.9), emissivity=(0.5, 0.5))
    assert air.rarefaction(300.0) == pytest.approx(246.4e-9, rel=1e-3)
    assert air.conductance(10e-6, 300.0) == pytest.approx(2557.0, rel=1e-3)
    # Vectorized over Y: h_g = k_g/(Y + M) for each.
    Y = np.array([0.0, 1e-6, 1e-5])
    np.testing.assert_allclose(air.conductance(Y, 300.0), air.conductivity(300.0) / (Y + air.rarefaction(300.0)),
                               rtol=1e-14)
    # M ~ Lambda ~ 1/P_g: a hundredth of an atmosphere makes M 101.325 times larger.
    thin = rc.GasGap(rc.gas("air"), pressure=1000.0)
    assert thin.rarefaction(300.0) / air.rarefaction(300.0) == pytest.approx(101.325, rel=1e-12)


def test_radiation_closed_forms():
    assert rc.radiative_conductance(300.0, 300.0, 0.5, 0.5) == pytest.approx(2.0413, rel=1e-3)
    T = np.array([300.0, 600.0])
    h = rc.radiative_conductance(T, T, 1.0, 1.0)   # black plates at equal T: 4 sigma T^3
    np.testing.assert_allclose(h, 4 * SIGMA_SB * T**3, rtol=1e-14)
    with pytest.raises(rc.ParameterError, match="emissivity e1"):
        rc.radiative_conductance(300.0, 300.0, 0.0, 0.5)


def test_separation_correlation_and_gaussian():
    sigma, Hc = 1e-6, 1e9
    P = np.array([1e3, 1e5, 1e7])   # P/Hc 1e-6 .. 1e-2: the fit's range
    exact = rc.gap_separation_gaussian(P, sigma, Hc)
    # the Gaussian form written out: Y = sqrt(2) sigma erfc^-1(2 P/Hc); at P/Hc = 1e-6,
    # erfc^-1(2e-6) = 3.3612 (normal quantile 4.7534/sqrt(2)).
    assert exact[0] == pytest.approx(math.sqrt(2) * sigma * 3.36117, rel=1e-5)
    # the published fit within 0.9 % of it there (docs/gapConductance.md)
    np.testing.assert_allclose(rc.gap_separation(P, sigma, Hc), exact, rtol=9e-3)
    assert rc.gap_separation(P[1], sigma, Hc) == pytest.approx(1.184 * sigma * (-math.log(3.132e-4)) ** 0.547,
                                                               rel=1e-12)


def test_interface_with_a_gap():
    ci = rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                             model="jacksonGreen",
                             gap=rc.GapSpec(gas="air", emissivity=(0.5, 0.5)))
    assert ci.has_gap
    # Y from the correlation of the surface's sigma (the stand-in: 0.115 um) and H_c = 2.84 S_y.
    sigma = rc.profile_roughness(rc.read_profile(STANDIN).detrended()).sigma
    assert sigma == pytest.approx(0.115e-6, rel=1e-9)
    assert ci.gap_separation(1e6) == pytest.approx(rc.gap_separation(1e6, sigma, 2.84 * STEEL["Sy"]), rel=1e-12)
    assert ci.gap_first_touch_separation == pytest.approx(ci.gap_separation(ci.table_pressures[0]), rel=1e-15)
    hg, hr = ci.gap_conductances(np.array([10e-6, 5e-6]), 300.0, 300.0)
    np.testing.assert_allclose(hg, [2557.0, 0.0262 / (5e-6 + 246.4e-9)], rtol=1e-3)
    assert hr == pytest.approx(2.0413, rel=1e-3)
    # the gas at the mean of the two face temperatures
    assert ci.gap_conductances(10e-6, 280.0, 320.0)[0] == pytest.approx(2557.0, rel=1e-3)
    with pytest.raises(rc.ParameterError, match="face temperature"):
        ci.gap_conductances(10e-6, 0.0, 300.0)

    plain = rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                                model="jacksonGreen")
    assert not plain.has_gap
    with pytest.raises(rc.ParameterError):
        plain.gap_separation(1e6)
    with pytest.raises(rc.ParameterError, match="neither a gas nor emissivities"):
        rc.ContactInterface(surfaces=[rc.SurfaceSpec.profile(STANDIN)], side1=STEEL_M, side2=STEEL_M,
                            model="jacksonGreen", gap=rc.GapSpec())
