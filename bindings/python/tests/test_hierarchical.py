"""Generalised Maxwell-slip and the hierarchical roughness models (thesis
5.3.8, 5.4) from Python: Archard's exponent sequences and load-area slope,
the Cantor-Borodich power law, the GMS Stribeck steady state."""

import math

import numpy as np
import pytest

import asperity


def test_archard_exponents_are_archards_fractions():
    for n, a in [(1, 2 / 3), (2, 8 / 9), (3, 26 / 27)]:
        assert asperity.archard_exponent("uniform", n) == pytest.approx(a, abs=1e-15)
    for n, a in [(2, 4 / 5), (3, 14 / 15), (4, 44 / 45)]:
        assert asperity.archard_exponent("non_uniform", n) == pytest.approx(a, abs=1e-15)
    with pytest.raises(asperity.Error, match="model"):
        asperity.archard_exponent("flat", 2)


def test_archard_area_slope_over_decades():
    loads = np.logspace(-3, 3, 7)
    a = asperity.archard_area("uniform", [1e-2, 1e-5, 1e-8], [1e12, 1e16], 1e11, loads)
    slopes = np.diff(np.log(a)) / np.diff(np.log(loads))
    assert np.allclose(slopes, 26 / 27, atol=1e-12)
    # One sphere: Hertz.
    w, r, e = 2.0, 5e-3, 1e11
    hertz = math.pi * (3 * w * r / (4 * e)) ** (2 / 3)
    assert asperity.archard_area("uniform", [r], [], e, w) == pytest.approx(hertz, rel=1e-13)
    with pytest.raises(asperity.Error, match="densities"):
        asperity.archard_area("uniform", [1e-2, 1e-5], [], 1e11, 1.0)


def test_cantor_borodich_load_is_a_power_law():
    p = dict(descendants=2, width_ratio=1 / 3, height_ratio=0.5, base_width=1e-3, base_height=1e-5, generations=80)
    q = 0.5
    d = 1e-5 * q**np.arange(5, 25) * 1.37
    c = asperity.cantor_contact(**p, depth=d, stiffness=1e10)
    c_half = asperity.cantor_contact(**p, depth=q * d, stiffness=1e10)
    beta = math.log(2 / 3) / math.log(0.5)
    slope = np.log(c["winkler_load"] / c_half["winkler_load"]) / math.log(1 / q)
    assert np.allclose(slope, 1 + beta, atol=1e-9)
    e = asperity.cantor_exponents(**p)
    assert e["width_exponent"] == pytest.approx(beta)
    assert e["load_area_exponent"] == pytest.approx(beta / (1 + beta))
    with pytest.raises(asperity.Error, match="width_ratio"):
        asperity.cantor_exponents(**{**p, "width_ratio": 0.6})


def test_generalized_maxwell_slip_follows_the_stribeck_curve():
    law = asperity.GeneralizedMaxwellSlip(
        stiffness=[2e5, 5e4], weight=[0.6, 0.4], mu_coulomb=0.3, mu_static=0.5,
        stribeck_velocity=1e-3, attraction=50.0, sigma2=0.2,
    )
    v = 2e-3
    state = None
    for _ in range(400):
        r, state = law.step(state, normal_force=2.0, slip=1e-6, dt=1e-6 / v)
    s = 0.3 + 0.2 * math.exp(-((v / 1e-3) ** 2))
    assert -r.force[0] == pytest.approx(2.0 * s + 0.2 * v, rel=1e-12)
    spec = asperity.friction_model({"generalized_maxwell_slip": {
        "stiffness": [2e5, 5e4], "weight": [0.6, 0.4], "mu_coulomb": 0.3, "mu_static": 0.5,
        "stribeck_velocity": 1e-3}})
    assert isinstance(spec, asperity.GeneralizedMaxwellSlip)
    with pytest.raises(asperity.Error, match="attraction"):
        asperity.GeneralizedMaxwellSlip(
            stiffness=[1e5], weight=[1.0], mu_coulomb=0.3, mu_static=0.5,
            stribeck_velocity=1e-3, attraction=-1.0,
        )
