"""The friction contract (asperity::friction::FrictionLaw) on numpy states:
the per-increment step, in place and as a block, for the homogenised law, the
slider as a patch law and the dynamic models; values against closed forms
and against the slider's own slide and the scene's models."""

import concurrent.futures as cf
import json
import math

import numpy as np
import pytest

import asperity

from conftest import example

LUGRE = dict(mu_coulomb=0.9, mu_static=1.2, stribeck_velocity=1e-3, stribeck_exponent=2, sigma0=3e5, sigma1=100, damping_velocity=0.01, sigma2=0)
MAXWELL = dict(stiffness=[4e5, 2e5, 1e5, 5e4], capacity=[0.3, 0.3, 0.25, 0.2], sigma2=0)
SAMPLES = [
    dict(pressure=0.0, cof=0.5, adhesion_pressure=1e4, contact_fraction=0.01, shares=dict(chemical=0.7, van_der_waals=0.1, elastic=0.05, plastic=0.15)),
    dict(pressure=1e6, cof=0.3, adhesion_pressure=1e4, contact_fraction=0.1, shares=dict(chemical=0.5, van_der_waals=0.1, elastic=0.1, plastic=0.3)),
]


def laws():
    return {
        "lugre": asperity.LuGre(**LUGRE),
        "maxwell": asperity.MaxwellSlip(**MAXWELL),
        "homogenised": asperity.HomogenisedFriction(SAMPLES, stick_stiffness=1e6),
    }


def test_constants_and_state_layout():
    assert (asperity.STATE_DISSIPATION, asperity.STATE_SLIP_PATH, asperity.STATE_MODEL) == (0, 1, 2)
    assert (asperity.TANGENT_NORMAL, asperity.TANGENT_SLIP) == (1, 2)
    h = laws()["homogenised"]
    assert isinstance(h, asperity.FrictionLaw) and h.state_len == 9
    assert np.array_equal(h.fresh_state(), np.zeros(9))
    assert h.fresh_state(3).shape == (3, 9)


def test_lugre_steady_sliding_is_stribeck():
    m = asperity.LuGre(**LUGRE)
    v, n = 1e-3, 2.0
    state = None
    for _ in range(2000):
        r, state = m.step(state, normal_force=n, slip=v * 1e-3, dt=1e-3)
    # μ(v) = μc + (μs - μc) exp(-(v/vs)²) at steady state (σ2 = 0).
    mu = LUGRE["mu_coulomb"] + (LUGRE["mu_static"] - LUGRE["mu_coulomb"]) * math.exp(-1.0)
    assert r.cof == pytest.approx(mu, rel=1e-6)
    assert r.force[0] == pytest.approx(-mu * n, rel=1e-6)  # opposes the slip
    assert r.regime_name == "slip"
    assert state[asperity.STATE_SLIP_PATH] == pytest.approx(2000 * v * 1e-3, rel=1e-12)


def test_maxwell_slip_gross_sliding():
    m = asperity.MaxwellSlip(**MAXWELL)
    state = None
    for _ in range(200):
        r, state = m.step(state, normal_force=1.0, slip=1e-6, dt=1e-3)
    assert r.cof == pytest.approx(sum(MAXWELL["capacity"]), rel=1e-12)


def test_homogenised_stick_then_slip():
    h = asperity.HomogenisedFriction(SAMPLES, stick_stiffness=1e6)
    assert h.stick_stiffness == 1e6
    n, area = 1.0, 1e-6  # 1 MPa: the second sample
    r, s = h.step(None, normal_force=n, slip=1e-9, area=area)
    assert r.regime_name == "stick"
    assert r.force[0] == pytest.approx(-1e6 * 1e-9, rel=1e-12)
    assert r.stored_energy == pytest.approx((1e6 * 1e-9) ** 2 / (2 * 1e6), rel=1e-12)
    r, s = h.step(s, normal_force=n, slip=1e-5, area=area)
    assert r.regime_name == "slip"
    limit = 0.3 * (n + 1e4 * area)  # Derjaguin: μ (N + A)
    assert r.force_magnitude == pytest.approx(limit, rel=1e-12)
    assert r.dissipated > 0 and sum(r.dissipation.values()) == pytest.approx(r.dissipated, rel=1e-12)
    back = asperity.HomogenisedFriction.from_json(h.to_json(), stick_stiffness=1e6)
    assert back.sample_at(5e5) == h.sample_at(5e5)
    with pytest.raises(asperity.Error, match="`area`"):
        h.step(None, normal_force=1.0, slip=1e-6, area=0.0)


@pytest.mark.parametrize("name", ["lugre", "maxwell", "homogenised"])
def test_step_in_place_and_block_agree(name):
    law = laws()[name]
    rng = np.random.default_rng(3)
    n = 64
    normal = rng.uniform(0.1, 2.0, n)
    slip = rng.uniform(-2e-6, 2e-6, (n, 2))
    area = np.full(n, 1e-6)
    dt = 1e-3
    states = law.fresh_state(n)
    for _ in range(3):
        block = law.step_block(states, normal, slip, dt, area=area)
        for i in range(n):
            r, new = law.step(states[i], normal_force=normal[i], slip=slip[i], dt=dt, area=area[i])
            assert np.array_equal(r.force, block.tangential_force[i])
            assert r.dissipated == block.dissipation[i]
            assert np.array_equal(new, block.state[i])
            same = states[i].copy()
            r2 = law.step_in_place(same, normal_force=normal[i], slip=slip[i], dt=dt, area=area[i])
            assert np.array_equal(same, new) and np.array_equal(r2.force, r.force)
        in_place = states.copy()
        b2 = law.step_block(in_place, normal, slip.ravel(), dt, area=area, in_place=True)
        assert b2.state is in_place and np.array_equal(in_place, block.state)
        states = block.state


@pytest.mark.parametrize("name", ["lugre", "maxwell", "homogenised"])
def test_block_responses_equal_the_steps(name):
    # An implicit host's block (issue 32): per point the regime, the stored
    # energy and the tangents, equal to step(..., tangents=3) point by point;
    # without tangents asked, the tangent arrays are zeros.
    law = laws()[name]
    rng = np.random.default_rng(7)
    n = 48
    both = asperity.TANGENT_NORMAL | asperity.TANGENT_SLIP
    normal = rng.uniform(0.1, 2.0, n)
    normal[5] = 0.0
    area = np.full(n, 1e-6)
    dt = 1e-3
    states = law.fresh_state(n)
    regimes = set()
    for k in range(4):
        slip = rng.uniform(-2e-6, 2e-6, (n, 2)) * (1e-3 if k == 1 else 1.0)
        slip[3] = 0.0
        block = law.step_block(states, normal, slip, dt, area=area, tangents=both)
        assert block.regime.dtype == np.int32 and block.regime.shape == (n,)
        assert block.stored_energy.shape == (n,)
        assert block.dforce_dslip.shape == (n, 2, 2) and block.dforce_dnormal.shape == (n, 2)
        for i in range(n):
            r, new = law.step(states[i], normal_force=normal[i], slip=slip[i], dt=dt, area=area[i], tangents=both)
            assert block.regime[i] == r.regime
            assert block.stored_energy[i] == r.stored_energy
            assert np.array_equal(block.dforce_dslip[i], r.dforce_dslip)
            assert np.array_equal(block.dforce_dnormal[i], r.dforce_dnormal)
            assert np.array_equal(block.tangential_force[i], r.force)
            assert block.dissipation[i] == r.dissipated
            assert np.array_equal(block.state[i], new)
            regimes.add(int(r.regime))
        assert np.any(block.dforce_dslip != 0)
        # In place: the same; no tangents asked: zeros (the rest unchanged).
        in_place = states.copy()
        b2 = law.step_block(in_place, normal, slip, dt, area=area, in_place=True, tangents=both)
        assert b2.state is in_place and np.array_equal(in_place, block.state)
        assert np.array_equal(b2.dforce_dslip, block.dforce_dslip) and np.array_equal(b2.regime, block.regime)
        plain = law.step_block(states, normal, slip, dt, area=area)
        assert not plain.dforce_dslip.any() and not plain.dforce_dnormal.any()
        assert np.array_equal(plain.regime, block.regime) and np.array_equal(plain.stored_energy, block.stored_energy)
        assert np.array_equal(plain.tangential_force, block.tangential_force)
        states = block.state
    assert len(regimes) >= 2, regimes
    with pytest.raises(asperity.Error, match="`tangents`"):
        law.step_block(states, normal, slip, dt, area=area, tangents=4)


def test_same_old_state_gives_identical_results():
    m = asperity.LuGre(**LUGRE)
    r, s = m.step(None, normal_force=1.0, slip=1e-6, dt=1e-3)
    a = m.step(s, normal_force=1.0, slip=-3e-7, dt=1e-3, tangents=asperity.TANGENT_NORMAL | asperity.TANGENT_SLIP)
    b = m.step(s, normal_force=1.0, slip=-3e-7, dt=1e-3, tangents=asperity.TANGENT_NORMAL | asperity.TANGENT_SLIP)
    assert np.array_equal(a[1], b[1]) and np.array_equal(a[0].dforce_dslip, b[0].dforce_dslip)
    assert a[0].dforce_dslip.shape == (2, 2)


def test_slider_patch_law_equals_its_slide():
    path = example("scenes", "chapter6_copper.json")
    scene = json.loads(path.read_text())
    load, step = scene["loading"]["fixed_load"]["load"], scene["sliding"]["step"]
    slider = asperity.Slider.from_scene(path)
    assert slider.state_len >= 9
    run = slider.slide(20 * step, step)
    state = None
    for k in range(20):
        r, state = slider.step(state, normal_force=load, slip=step)
        assert r.cof == run["steps"]["cof"][k]
        assert r.record["nano_contacts"] == run["steps"]["nano_contacts"][k]
    assert state[asperity.STATE_DISSIPATION] == pytest.approx(sum(run["summary"]["dissipation"].values()), rel=1e-12)
    full = asperity.run_scene(path)
    whole = slider.slide(scene["sliding"]["distance"], step)
    assert whole["summary"]["mean_cof"] == full.summary["mean_cof"]


def test_slider_homogenise_reproduces_a_run():
    """The homogenised law built from the slider's runs (Rust
    Slider::homogenise): at each sampled pressure its slip force equals the
    mean friction force of a separate fixed-load run of the slider."""
    path = example("scenes", "chapter6_copper.json")
    slider = asperity.Slider.from_scene(path)
    area, cap = slider.nominal_area, slider.capacity
    assert area > 0 and cap > 0
    pressures = [0.1 * cap / area, 0.3 * cap / area]
    distance, step = 30e-6, 1.5e-6
    law = slider.homogenise(pressures, distance, step, stick_stiffness=1e6)
    assert law.stick_stiffness == 1e6
    assert [s["pressure"] for s in law.samples()] == pressures
    rigid = asperity.HomogenisedFriction(law.samples(), form="derjaguin")
    for p in pressures:
        scene = json.loads(path.read_text())
        scene["loading"] = {"fixed_load": {"load": p * area}}
        run = asperity.Slider.from_scene(scene, base=path.parent).slide(distance, step)
        r, _ = rigid.step(None, normal_force=p * area, area=area, slip=1e-7)
        assert r.force_magnitude == pytest.approx(run["summary"]["mean_friction_force"], rel=1e-12)
    with pytest.raises(asperity.Error, match="capacity"):
        slider.homogenise([2.0 * cap / area], distance, step)


def test_dynamic_models_equal_the_scene_tracks():
    path = example("scenes", "dynamic_models.json")
    scene = json.loads(path.read_text())
    run = asperity.run_scene(path)
    step, v = scene["sliding"]["step"], scene["sliding"]["velocity"]
    for spec, track in zip(scene["friction_models"], run.models):
        m = asperity.friction_model(spec)
        state = None
        for k in range(10):
            r, state = m.step(state, normal_force=run.steps["normal_load"][k], slip=step, dt=step / v)
            assert -r.force[0] == pytest.approx(track["steps"]["friction_force"][k], rel=1e-12, abs=1e-300)


def test_errors_name_the_argument():
    m = asperity.LuGre(**LUGRE)
    with pytest.raises(asperity.Error, match="`old_state`"):
        m.step(np.zeros(3), normal_force=1.0, slip=1e-6, dt=1e-3)
    with pytest.raises(asperity.Error, match="`normal_force`"):
        m.step(None, normal_force=math.nan, slip=1e-6, dt=1e-3)
    with pytest.raises(asperity.Error, match="`normal_force`"):
        m.step(None, normal_force="1", slip=1e-6, dt=1e-3)
    with pytest.raises(asperity.Error, match="`dt`"):
        m.step(None, normal_force=1.0, slip=1e-6, dt=0.0)  # rate dependent
    with pytest.raises(asperity.Error, match="`slip`"):
        m.step(None, normal_force=1.0, slip=[1e-6, 0, 0], dt=1e-3)
    with pytest.raises(asperity.Error, match="`mu_static`"):
        asperity.LuGre(mu_coulomb=0.3)
    with pytest.raises(asperity.Error, match="`colour`"):
        asperity.LuGre(colour=1, **LUGRE)
    states = m.fresh_state(4)
    with pytest.raises(asperity.Error, match="`slip`"):
        m.step_block(states, np.ones(4), np.zeros(6), 1e-3)
    with pytest.raises(asperity.Error, match="`states`"):
        m.step_block(m.fresh_state(3), np.ones(4), np.zeros(8), 1e-3)
    with pytest.raises(asperity.Error, match="contiguous"):
        m.step_block(np.zeros((4, 8))[:, ::2], np.ones(4), np.zeros(8), 1e-3)
    bad = np.ones(4)
    bad[2] = -1.0
    before = states.copy()
    with pytest.raises(asperity.Error, match="^element 2:.*`normal_force`"):
        m.step_block(states, bad, np.full(8, 1e-6), 1e-3)
    assert np.array_equal(states, before)  # the old states are never written


def test_shared_law_across_threads():
    m = asperity.MaxwellSlip(**MAXWELL)
    rng = np.random.default_rng(5)
    slips = [rng.uniform(-1e-6, 1e-6, (1000, 2)) for _ in range(8)]

    def run(s):
        states = m.fresh_state(1000)
        out = []
        for _ in range(5):
            b = m.step_block(states, np.ones(1000), s, 1e-3)
            states = b.state
            out.append(b.tangential_force)
        return np.array(out)

    serial = [run(s) for s in slips]
    with cf.ThreadPoolExecutor(max_workers=4) as ex:
        parallel = list(ex.map(run, slips))
    for a, b in zip(serial, parallel):
        assert np.array_equal(a, b)
