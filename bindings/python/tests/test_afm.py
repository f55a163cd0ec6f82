"""analyze_afm on a synthetic JKR curve built here from the closed form
(Johnson, Kendall & Roberts 1971, parametric in the contact radius), the
JSON keys of ``asperity afm --json``, the errors, and the measured SiN curve
of ../shared/data/afm (skipped when absent)."""

import math

import numpy as np
import pytest

import asperity
from conftest import shared_data

R, E, W, K = 50e-9, 0.5e9, 0.5, 40.0


def jkr_curve(sigma=0.2e-9, seed=3):
    """Approach (free, then the stable branch from P = 0) and retract (the
    branch down to the load-controlled pull-off, then free), position
    decreasing towards the sample, offset and tilt."""
    a_po = (9 * math.pi * W * R**2 / (8 * E)) ** (1 / 3)
    a_max = 60e-9

    def branch(a):
        p = 4 * E * a**3 / (3 * R) - np.sqrt(8 * math.pi * W * E * a**3)
        d = a**2 / R - np.sqrt(2 * math.pi * W * a / E)
        return p, 1e-6 + d + p / K

    a = np.linspace(a_po, a_max, 300)
    p, u = branch(a)
    keep = p >= 0
    u_app = np.concatenate([u[keep][0] - 200e-9 + 200e-9 * np.arange(400) / 400, u[keep]])
    f_app = np.concatenate([np.zeros(400), p[keep]])
    u_ret = np.concatenate([u[::-1], u[0] - 200e-9 * np.arange(1, 401) / 400])
    f_ret = np.concatenate([p[::-1], np.zeros(400)])
    z = -np.concatenate([u_app, u_ret])
    f = np.concatenate([f_app, f_ret])
    rng = np.random.default_rng(seed)
    raw = f + sigma * rng.standard_normal(f.size) - 20e-9 - 0.01 * z
    return z, raw, len(u_app)


def test_jkr_parameters_within_their_standard_errors():
    z, f, rs = jkr_curve()
    r = asperity.analyze_afm(position=z, force=f, retract_start=rs, spring_constant=K, tip_radius=R)
    for key in ("pull_off_force", "jump_in_distance", "adhesion_energy", "contact_point", "fits", "recommended_model"):
        assert key in r
    assert set(r["baseline"]) >= {"offset", "slope"}
    assert r["recommended_model"] == "jkr"
    jkr = next(x for x in r["fits"] if x["model"] == "jkr")
    assert abs(jkr["e_star"] - E) <= 3 * jkr["e_star_stderr"]
    assert abs(jkr["work_of_adhesion"] - W) <= 3 * jkr["work_of_adhesion_stderr"]
    assert jkr["e_star_stderr"] < 0.1 * E
    # −(3/2)πwR from the baseline, within the noise.
    assert r["pull_off_force"] == pytest.approx(-1.5 * math.pi * W * R, abs=1e-9)
    assert r["baseline"]["slope"] == pytest.approx(-0.01, abs=2e-3)
    assert "no_jump_in" in r["flags"]


def test_deflection_and_unknown_radius():
    z, f, rs = jkr_curve()
    r = asperity.analyze_afm(position=z, deflection=f / K, spring_constant=K, model="jkr")
    assert len(r["fits"]) == 1
    fit = r["fits"][0]
    assert fit["e_star"] is None and fit["work_of_adhesion"] is None
    assert "radius_unknown" in r["flags"]
    assert abs(fit["work_of_adhesion_times_radius"] - W * R) <= 3 * fit["work_of_adhesion_times_radius_stderr"]


def test_lennard_jones_sphere_fit():
    # The JKR curve (μ ≈ 12) fitted by the numerical Lennard-Jones sphere:
    # close to the JKR values (the LJ sphere tends to JKR at large μ).
    z, f, rs = jkr_curve()
    r = asperity.analyze_afm(position=z, force=f, retract_start=rs, spring_constant=K, tip_radius=R, model="lj")
    assert [x["model"] for x in r["fits"]] == ["lj"]
    lj = r["fits"][0]
    assert lj["e_star"] == pytest.approx(E, rel=0.1)
    assert lj["work_of_adhesion"] == pytest.approx(W, rel=0.1)
    assert lj["tabor_parameter"] > 5 and lj["e_star_stderr"] > 0
    # auto leaves it out at this μ and says why.
    a = asperity.analyze_afm(position=z, force=f, retract_start=rs, spring_constant=K, tip_radius=R)
    assert [m for m, _ in a["skipped_fits"]] == ["lj"]


def test_errors_name_the_argument():
    z, f, rs = jkr_curve()
    with pytest.raises(asperity.Error, match="model"):
        asperity.analyze_afm(position=z, force=f, spring_constant=K, model="banana")
    with pytest.raises(asperity.Error, match="spring_constant"):
        asperity.analyze_afm(position=z, force=f)
    with pytest.raises(asperity.Error, match="spring_constant"):
        asperity.analyze_afm(position=z, deflection=f)
    with pytest.raises(asperity.Error, match="tip_radius"):
        asperity.analyze_afm(position=z, force=f, spring_constant=K, tip_radius=-1.0)
    with pytest.raises(asperity.Error, match="source"):
        asperity.analyze_afm()


def test_measured_sin_curve():
    path = shared_data("afm", "afm_force_curve_asylum_mfp3d_SiN.csv")
    c = asperity.read_afm_curve(path)
    assert c["retract_start"] == 1009 and c["spring_constant"] == 1.1841
    r = asperity.analyze_afm(path)
    # README: adhesion ≈ 12.9 nN above the baseline.
    assert r["pull_off_force"] == pytest.approx(-12.9e-9, rel=0.02)
    assert r["jump_in_distance"] > 0
    assert "radius_unknown" in r["flags"]
    assert all(math.isfinite(x["rms_residual"]) for x in r["fits"])
