"""Normal laws: published values the Rust tests use, arrays against scalar
calls element by element, hysteresis through the state, ``out=``."""

import math

import numpy as np
import pytest

import asperity

PI = math.pi
R, E, W = 1e-6, 1e10, 0.1


def laws():
    return {
        "hertz": asperity.Hertz(R, E),
        "dmt": asperity.Dmt(R, E, W),
        "jkr": asperity.Jkr(R, E, W),
        "md": asperity.MaugisDugdale.from_maugis_parameter(R, E, W, 1.0),
        "kendall": asperity.Kendall(R, E, W),
        "flat": asperity.FlatPunch(R, E),
        "power": asperity.PowerPunch(50.0, 1.5, E),
        "cone": asperity.PowerPunch.cone(asperity.BERKOVICH_EQUIVALENT_HALF_ANGLE, E),
        "jkr_power": asperity.JkrPowerPunch(50.0, 1.5, E, W),
        "derjaguin": asperity.Derjaguin(R, asperity.SurfaceLaw.lennard_jones(W, 0.3e-9)),
    }


def test_version_and_error_class():
    # The package's version is the Rust crate's it wraps.
    from conftest import ROOT
    import re
    crate = re.search(r'^version = "([^"]+)"', (ROOT / "Cargo.toml").read_text(), re.M).group(1)
    assert asperity.__version__ == crate
    assert issubclass(asperity.Error, ValueError)


def test_jkr_pull_off_published():
    law = asperity.Jkr(radius=R, e_star=E, work_of_adhesion=W)
    assert law.pull_off_force("load") / (PI * W * R) == pytest.approx(-1.5, rel=1e-12)
    assert law.pull_off_force("displacement") / (PI * W * R) == pytest.approx(-5 / 6, rel=1e-9)
    assert law.pull_off_force() == law.pull_off_force("load")
    # Critical overlap -(3/4)(π²w²R/E*²)^(1/3) (REFERENCE §1).
    assert law.critical_delta == pytest.approx(-0.75 * (PI**2 * W**2 * R / E**2) ** (1 / 3), rel=1e-12)


def test_dmt_and_hertz_closed_forms():
    d = 2e-9
    h = asperity.Hertz(R, E).eval(d)
    p = 4 / 3 * E * math.sqrt(R) * d**1.5
    assert h.force == pytest.approx(p, rel=1e-14)
    assert h.contact_radius == pytest.approx(math.sqrt(R * d), rel=1e-14)
    assert h.stiffness == pytest.approx(2 * E * math.sqrt(R * d), rel=1e-14)
    dm = asperity.Dmt(R, E, W)
    assert dm.eval(d).force == pytest.approx(p - 2 * PI * W * R, rel=1e-13)
    assert dm.pull_off_force("load") == pytest.approx(-2 * PI * W * R, rel=1e-14)


def test_maugis_dugdale_published():
    md = asperity.MaugisDugdale.from_maugis_parameter(R, E, W, 1.0)
    assert md.lambda_ == pytest.approx(1.0, rel=1e-13)
    # tests/maugis_dugdale.rs: P̄_c(λ = 1) = -1.600734911254091.
    assert md.pull_off_force("load") / (PI * W * R) == pytest.approx(-1.600734911254091, rel=1e-10)
    # λ/μ = 1.157012 with σ0 the Lennard-Jones theoretical stress.
    z0 = 0.3e-9
    mdt = asperity.MaugisDugdale.from_tabor(R, E, W, z0)
    mu = asperity.tabor_parameter(R, W, E, z0)
    assert mdt.lambda_ / mu == pytest.approx(1.157012, rel=1e-6)
    assert asperity.maugis_over_tabor() == pytest.approx(1.157012, rel=1e-6)
    # The same law by sigma0 (positional, keyword) and cohesive_stress.
    s0 = md.cohesive_stress
    for other in (
        asperity.MaugisDugdale(R, E, W, s0),
        asperity.MaugisDugdale(R, E, W, sigma0=s0),
        asperity.MaugisDugdale(R, E, W, cohesive_stress=s0),
    ):
        assert other.pull_off_force("load") == md.pull_off_force("load")


def test_kendall_and_flat_punch():
    k = asperity.Kendall(R, E, W)
    assert k.pull_off_force("load") == pytest.approx(-math.sqrt(8 * PI * W * E * R**3), rel=1e-13)
    f = asperity.FlatPunch(R, E)
    assert f.eval(1e-9).force == pytest.approx(2 * E * R * 1e-9, rel=1e-14)
    ns = asperity.FlatPunch.no_slip(R, E, 0.355)
    assert ns.stiffness / f.stiffness == pytest.approx(1.017376, rel=1e-6)


def test_galin_coefficients():
    # REFERENCE §1 table.
    for d, c, dd in [(1, 1.570796327, 1.570796327), (1.5, 2.156652423, 1.797210352), (2, 2.666666667, 2), (3, 3.534291735, 2.356194490)]:
        assert asperity.galin_c(d) == pytest.approx(c, rel=1e-9)
        assert asperity.galin_d(d) == pytest.approx(dd, rel=1e-9)


def test_derjaguin_rigid_limit():
    z0 = 0.3e-9
    law = asperity.Derjaguin(R, asperity.SurfaceLaw.lennard_jones(W, z0))
    assert law.pull_off_force("load") == pytest.approx(-2 * PI * W * R, rel=1e-9)
    assert law.adhesive_force() == pytest.approx(2 * PI * W * R, rel=1e-14)


@pytest.mark.parametrize("name", list(laws()))
def test_array_equals_scalar_calls(name):
    law = laws()[name]
    scale = abs(law.length_scale())
    hi = 0.9 if name == "derjaguin" else 6.0  # the rigid LJ sphere: δ < z0
    d = np.linspace(-2.0, hi, 257) * scale
    fresh = law.eval(d)
    assert fresh.force.shape == (257,) and fresh.force.dtype == np.float64
    for i, di in enumerate(d):
        r = law.eval(float(di))
        assert r.force == fresh.force[i]
        assert r.contact_radius == fresh.contact_radius[i]
        assert r.stiffness == fresh.stiffness[i]
        assert r.state == fresh.state[i]
    # From the states of the first call (hysteretic laws follow their branch).
    again = law.eval(d[::-1].copy(), state=fresh.state)
    for i, di in enumerate(d[::-1]):
        r = law.eval(float(di), state=fresh.state[i])
        assert r.force == again.force[i]
        assert r.state == again.state[i]


def test_state_carries_hysteresis():
    law = asperity.Jkr(R, E, W)
    dc = law.critical_delta
    fresh = law.eval(0.5 * dc)  # approaching from afar: not yet in contact
    assert fresh.force == 0.0 and fresh.state.in_contact == 0
    touched = law.eval(1e-9)
    assert touched.state.in_contact == 1
    pulled = law.eval(0.5 * dc, state=touched.state)  # retracting: still stuck
    assert pulled.force < 0 and pulled.state.in_contact == 1
    gone = law.eval(1.01 * dc, state=pulled.state)
    assert gone.force == 0.0 and gone.state.in_contact == 0


def test_eval_path_is_a_cycle():
    law = asperity.Jkr(R, E, W)
    dc = law.critical_delta
    path = np.concatenate([np.linspace(2 * dc, 4 * abs(dc), 2000), np.linspace(4 * abs(dc), 2 * dc, 2000)])
    r = law.eval_path(path)
    state = None
    for i, di in enumerate(path):
        s = law.eval(float(di), state=state)
        state = s.state
        assert s.force == r.force[i]
    assert r.state == state
    # The retraction passes the load-controlled minimum and lets go near the
    # displacement-controlled pull-off (-5/6 πwR; the grid is coarse).
    assert r.force.min() == pytest.approx(law.pull_off_force("load"), rel=1e-3)
    last = r.force[2000:][r.in_contact[2000:] == 1][-1]
    assert last == pytest.approx(law.pull_off_force("displacement"), rel=0.15)  # √ approach to the fold


def test_out_reuses_the_arrays():
    law = asperity.Jkr(R, E, W)
    d = np.linspace(1e-10, 1e-8, 1000)
    a = law.eval(d)
    b = law.eval(d)
    fa = a.force
    c = law.eval(d * 0.5, state=a.state, out=a)
    assert c.force is fa  # written in place
    ref = law.eval(d * 0.5, state=b.state)
    assert np.array_equal(c.force, ref.force)
    assert np.array_equal(c.contact_radius, ref.contact_radius)
    assert np.array_equal(c.state.contact_radius, ref.state.contact_radius)
    # In place from its own states.
    d2 = d * 0.25
    ref2 = law.eval(d2, state=ref.state)
    c2 = law.eval(d2, state=a.state, out=a)
    assert np.array_equal(c2.force, ref2.force)
    assert np.array_equal(c2.state.branch, ref2.state.branch)


def test_eval_at_load_and_energy():
    law = asperity.Jkr(R, E, W)
    r = law.eval(3e-9)
    back = law.eval_at_load(r.force)
    assert back.delta == pytest.approx(3e-9, rel=1e-9)
    loads = np.array([0.0, 1e-7, r.force])
    arr = law.eval_at_load(loads)
    for i, p in enumerate(loads):
        assert arr.delta[i] == law.eval_at_load(float(p)).delta
    assert arr.state is None
    h = asperity.Hertz(R, E)
    u = h.energy(np.array([1e-9, 2e-9]))
    assert u[1] == pytest.approx(8 / 15 * E * math.sqrt(R) * (2e-9) ** 2.5, rel=1e-13)
    with pytest.raises(asperity.Error, match="`force`"):
        law.eval_at_load(-1.0)  # below the pull-off
    assert h.reach() == 0.0
    assert law.reach("displacement") == pytest.approx(law.critical_delta, rel=1e-12)


def test_contact_state_constructors():
    s = asperity.ContactState.fresh(3)
    assert len(s) == 3 and not s.is_scalar
    assert np.array_equal(s.in_contact, np.zeros(3, dtype=np.int32))
    t = asperity.ContactState.from_arrays(np.ones(2), np.zeros(2), [1, 1], [1, 1])
    assert t[1] == asperity.ContactState(contact_radius=1.0, in_contact=1, branch=1)
    law = asperity.Jkr(R, E, W)
    r = law.eval(np.array([-1e-10, -1e-10]), state=asperity.ContactState.from_arrays(
        np.full(2, 5e-8), np.zeros(2), [1, 0], [1, 0]))
    assert r.state.in_contact.tolist() == [1, 0]
