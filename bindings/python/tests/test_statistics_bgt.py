"""Bush-Gibson-Thomas (thesis §5.3.3) and Bora et al. (§5.3.9) through the
Python package. BGT: Nayak's
summit density, the small-load limit A = √(2π) P/(E* √(2 m2)), the inverse
and the errors (the Rust tests in tests/statistics_bgt.rs cover the rest)."""

import math

import numpy as np
import pytest

import asperity


def surface(alpha=4.0):
    return asperity.BushGibsonThomas.from_alpha(1e-6, 0.1, alpha, 1e9, 1e-4)


def test_summit_density_and_small_load_limit():
    s = surface()
    assert s.alpha == pytest.approx(4.0, rel=1e-14)
    m2 = 0.01
    m4 = 4.0 * m2**2 / 1e-12
    assert s.summit_density == pytest.approx(m4 / (6 * math.pi * math.sqrt(3) * m2), rel=1e-14)
    # Every summit touches far below the mean plane: Nayak's density.
    assert s.contacts(-14e-6) / 1e-4 == pytest.approx(s.summit_density, rel=1e-8)
    assert s.small_load_area_per_load == pytest.approx(math.sqrt(2 * math.pi) / (1e9 * math.sqrt(2 * m2)), rel=1e-14)
    # A/P approaches the limit from below as d grows (within 2 % at d = 12 σ
    # for α = 4, tests/statistics_bgt.rs).
    r = s.response(np.array([4e-6, 8e-6, 12e-6]))
    ratio = r["area"] / r["load"] / s.small_load_area_per_load
    assert np.all(np.diff(ratio) > 0) and abs(ratio[-1] - 1) < 0.02


def test_arrays_inverse_and_errors():
    s = surface()
    d = np.linspace(-2e-6, 4e-6, 7)
    load = s.load(d)
    assert np.all(np.diff(load) < 0) and np.all(np.isfinite(load))
    assert s.stiffness(float(d[2])) > 0
    sol = s.separation_at_load(float(load[3]))
    assert sol["separation"] == pytest.approx(d[3], rel=1e-9, abs=1e-15)
    with pytest.raises(ValueError, match="m4"):
        asperity.BushGibsonThomas(1e-12, 0.01, 1e6, 1e9, 1e-4)  # α = 0.01
    with pytest.raises(ValueError, match="alpha"):
        asperity.BushGibsonThomas.from_alpha(1e-6, 0.1, 1.5, 1e9, 1e-4)


def test_bora_topography():
    # Two neighbouring springs 2 nm above the rest of a 5 x 5 map.
    h = np.zeros(25)
    h[12] = h[13] = 2e-9
    rigid = asperity.BoraTopography(h, 10e-9, 50.0, nx=5)
    r = rigid.solve(1e-9)
    assert r["load"] == pytest.approx(2 * 50.0 * 1e-9, rel=1e-14)
    assert r["contacts"] == 2 and r["forces"].shape == (25,)
    soft = asperity.BoraTopography(h, 10e-9, 50.0, contact_modulus=1e9, nx=5)
    s = soft.solve(1e-9)
    assert 0 < s["load"] < r["load"] and s["stiffness"] > 0
    sol = soft.separation_at_load(s["load"])
    assert sol["separation"] == pytest.approx(1e-9, rel=1e-6)
    loads = soft.load(np.array([0.0, 1e-9, 3e-9]))
    assert loads[0] > loads[1] > loads[2] == 0.0
    with pytest.raises(ValueError, match="heights"):
        asperity.BoraTopography(np.zeros(7), 10e-9, 50.0, nx=5)
