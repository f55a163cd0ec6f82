"""Borodich–Kryukova's block on a belt (thesis 5.3.7) and Schmittbuhl's
renormalised friction law (5.4.3) from Python, against the closed forms and
limits of the Rust module docs: the flat-layer spring 2aε (rest height,
sliding response x*(1 − cos ω_x t), undamped vertical oscillation at
√(2aε/M)), full contact of whole wavelengths carrying −2aεy; the Coulomb law
as the renormalisation's fixed point and the elastic-continuum rescaling."""

import math

import numpy as np
import pytest

import asperity

FLAT = dict(
    half_length=0.01,
    mass=1.0,
    belt_speed=0.1,
    spring_stiffness=1e3,
    layer_stiffness=5e8,
    friction_coefficient=0.3,
    sign_speed=1e-4,
    gravity=9.81,
    nodes=200,
)


def test_flat_layers_follow_the_closed_forms():
    bk = asperity.BorodichKryukova(**FLAT)
    m, g, a, eps = FLAT["mass"], FLAT["gravity"], FLAT["half_length"], FLAT["layer_stiffness"]
    k_layer = 2 * a * eps
    y_rest = -m * g / k_layer
    assert bk.normal_force(0.0, y_rest) == pytest.approx(m * g, rel=1e-12)
    # Sliding from rest at the rest height (x* ω_x < U: the block never sticks).
    x_star = FLAT["friction_coefficient"] * m * g / FLAT["spring_stiffness"]
    wx = math.sqrt(FLAT["spring_stiffness"] / m)
    r = bk.run(1e-5, 30_000, every=100, y=y_rest)
    assert len(r["time"]) == 301
    assert np.allclose(r["x"], x_star * (1 - np.cos(wx * r["time"])), rtol=0, atol=1e-9)
    assert np.allclose(r["y"], y_rest, rtol=1e-12, atol=0)
    assert np.allclose(r["friction_force"], FLAT["friction_coefficient"] * r["normal_force"], rtol=1e-12)
    # Vertical oscillation from 1 % below rest: ω_y = √(2aε/M), no decay.
    wy = math.sqrt(k_layer / m)
    dt = 0.005 / wy
    steps = round(5 * 2 * math.pi / wy / dt)
    r = bk.run(dt, steps, y=1.01 * y_rest)
    want = y_rest + 0.01 * y_rest * np.cos(wy * r["time"])
    assert np.max(np.abs(r["y"] - want)) < 1e-8 * abs(y_rest)


def test_whole_wavelengths_in_full_contact_carry_minus_2a_eps_y():
    # a a multiple of both wavelengths: the cosines integrate (and sum, on
    # the midpoint cells) to zero, so F = −2aε y at any x, t once y lies
    # below −(A_s + A_b), over decades of the layer stiffness.
    p = dict(FLAT, slider_amplitude=2e-7, slider_wavelength=1e-3, belt_amplitude=3e-7, belt_wavelength=0.5e-3)
    for eps in [1e6, 1e8, 1e10]:
        bk = asperity.BorodichKryukova(**dict(p, layer_stiffness=eps))
        for y in [-6e-7, -1e-6, -1e-5]:
            for x, t in [(0.0, 0.0), (1.3e-4, 0.7), (-2e-3, 5.0)]:
                want = -2 * p["half_length"] * eps * y
                assert bk.normal_force(x, y, t) == pytest.approx(want, rel=1e-10)
        # Out of contact: no force.
        assert bk.normal_force(0.0, 5.1e-7, 0.0) == 0.0


def test_borodich_kryukova_errors_name_the_argument():
    with pytest.raises(asperity.Error, match="mass"):
        asperity.BorodichKryukova(**dict(FLAT, mass=-1.0))
    with pytest.raises(asperity.Error, match="nodes"):
        asperity.BorodichKryukova(**dict(FLAT, nodes=0))
    bk = asperity.BorodichKryukova(**FLAT)
    with pytest.raises(asperity.Error, match="dt"):
        bk.run(0.0, 1)
    with pytest.raises(asperity.Error, match="every"):
        bk.run(1e-5, 1, every=0)
    with pytest.raises(asperity.Error, match="start.y"):
        bk.run(1e-5, 1, y=float("nan"))


def test_coulomb_law_is_a_fixed_point_of_the_renormalisation():
    # μ_s = μ_k, no weakening: the chain resists with μ N n at every
    # generation, up to the quasi-static overshoot (≤ 2.5e-3 here).
    for mu in [0.1, 1.2]:
        law = asperity.schmittbuhl_run(mu_static=mu, mu_kinetic=mu, weakening_velocity=math.inf)
        assert [g["index"] for g in law] == [0, 1, 2, 3]
        for g in law:
            assert g["mu_static"] == pytest.approx(mu, rel=2.5e-3)
            assert g["mu_kinetic"] == pytest.approx(mu, rel=2.5e-3)


def test_generations_scale_as_an_elastic_continuum():
    for d in [2, 3]:
        law = asperity.schmittbuhl_run(mu_kinetic=0.5, weakening_velocity=math.inf, dimension=d)
        for g in law:
            s = 3.0 ** g["index"]
            assert g["size"] == s
            assert g["mass"] == pytest.approx(1e-5 * s**d, rel=1e-12)
            assert g["pulling_stiffness"] == pytest.approx(1e3 * s ** (d - 2), rel=1e-12)
            assert g["coupling_stiffness"] == pytest.approx(1e3 * s ** (d - 2), rel=1e-12)
            assert g["normal_force"] == pytest.approx(s, rel=1e-12)
    for g in asperity.schmittbuhl_run(mu_static=0.0, mu_kinetic=0.0):
        assert (g["mu_static"], g["mu_kinetic"], g["kinetic_to_static"], g["events"]) == (0.0, 0.0, 1.0, 0)


def test_velocity_weakening_flows_down():
    law = asperity.schmittbuhl_run()
    assert law[0]["mu_static"] == 0.5 and law[0]["mu_kinetic"] == 0.3
    for a, b in zip(law, law[1:]):
        assert math.isfinite(b["mu_static"]) and math.isfinite(b["mu_kinetic"])
        assert 0.0 <= b["mu_kinetic"] <= b["mu_static"]
        assert b["mu_static"] <= a["mu_static"] * (1 + 1 / 400)
        assert b["kinetic_to_static"] == pytest.approx(b["mu_kinetic"] / b["mu_static"], rel=1e-15)


def test_schmittbuhl_errors_name_the_field():
    for kw, name in [
        (dict(ratio=1), "ratio"),
        (dict(generations=13), "generations"),
        (dict(dimension=4), "dimension"),
        (dict(disorder=1.0), "disorder"),
        (dict(mu_static=0.2, mu_kinetic=0.3), "mu_kinetic"),
        (dict(velocity=0.0), "velocity"),
    ]:
        with pytest.raises(asperity.Error, match=name):
            asperity.schmittbuhl_run(**kw)
