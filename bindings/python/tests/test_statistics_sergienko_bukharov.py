"""Sergienko-Bukharov (thesis §5.3.5, the library's formulation from the
thesis's description) through the Python package: the quasi-static
quadrature on uniformly spread springs, the friction drop and the lift with
the amplitude, the record, and the errors (the Rust tests in
tests/statistics_sergienko_bukharov.rs cover the rest)."""

import math

import numpy as np
import pytest

import asperity

K, AREA, LOAD, MU, P0 = 1e4, 1e-12, 1.0, 0.2, 1e9


def uniform(count=20000, span=1e-5):
    dz = span / count
    h = asperity.HeightDistribution.empirical((np.arange(count) + 0.5) * dz)
    return asperity.KragelskyRods(count, AREA, K, h)


def test_quasi_static_quadrature_and_drop():
    count, span = 20000, 1e-5
    rho = count / span
    top = (count - 0.5) * span / count
    y_s = math.sqrt(2 * LOAD / (K * rho))
    m = asperity.SergienkoBukharov(uniform(count, span), 1.0, LOAD, MU, damping_ratio=0.5, attractive_pressure=P0)
    w0 = m.natural_frequency
    assert (top - m.static_separation) / y_s == pytest.approx(1.0, rel=3e-3)
    phi = np.linspace(0, 2 * math.pi, 4096, endpoint=False)
    last = 1.0
    for a in (0.3, 0.6, 0.9):
        r = m.run(force_amplitude=a * LOAD, frequency=0.01 * w0, transient_periods=2, average_periods=2)
        want = y_s * np.mean(np.sqrt(1 + a * np.sin(phi)))
        assert (top - r["mean_separation"]) / want == pytest.approx(1.0, rel=1e-2)
        assert r["mean_load"] == pytest.approx(LOAD, rel=1e-3)
        assert r["friction_ratio"] < last and r["lift"] > 0
        last = r["friction_ratio"]


def test_record_and_lift_off():
    m = asperity.SergienkoBukharov(uniform(5000), 1e-3, LOAD, MU, damping_ratio=0.2, attractive_pressure=P0)
    r = m.run(force_amplitude=1.5 * LOAD, frequency=0.3 * m.natural_frequency, transient_periods=10,
              average_periods=2, record_every=10)
    assert r["lift_off_fraction"] > 0
    s = r["samples"]
    assert set(s) == {"time", "separation", "velocity", "load", "contacts", "friction"}
    assert len(s["time"]) == r["steps"] // 10 + 1
    assert np.all(np.isfinite(s["separation"])) and np.all(s["load"] >= 0)
    # Off the springs the friction and the count are zero.
    off = s["load"] == 0
    assert off.any() and np.all(s["contacts"][off] == 0) and np.all(s["friction"][off] == 0)


def test_errors_name_the_argument():
    rods = uniform(100, 1e-6)
    with pytest.raises(asperity.Error, match="mass"):
        asperity.SergienkoBukharov(rods, 0.0, LOAD, MU)
    with pytest.raises(asperity.Error, match="friction_coefficient"):
        asperity.SergienkoBukharov(rods, 1.0, LOAD, 0.0)
    m = asperity.SergienkoBukharov(rods, 1.0, LOAD, MU)
    with pytest.raises(asperity.Error, match="frequency"):
        m.run(force_amplitude=0.5)
    with pytest.raises(asperity.Error, match="average_periods"):
        m.run(average_periods=0)
    with pytest.raises(asperity.Error, match="transient_periods"):
        m.run(transient_periods=-1)
