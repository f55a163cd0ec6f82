"""Bad input raises asperity.Error (a ValueError) naming the argument and
its bound: bad types, NaN, negative radius, wrong array lengths, non-contiguous
arrays, wrong dtypes and shapes, unknown selectors. Nothing half-written."""

import math

import numpy as np
import pytest

import asperity


def raises(name, fn, *args, **kw):
    with pytest.raises(asperity.Error) as e:
        fn(*args, **kw)
    assert f"`{name}`" in str(e.value), str(e.value)
    assert isinstance(e.value, ValueError)
    return str(e.value)


def test_negative_radius_names_argument_and_bound():
    msg = raises("radius", asperity.Jkr, -1e-6, 1e10, 0.1)
    assert "> 0" in msg
    raises("radius", asperity.Hertz, radius=-1.0, e_star=1e9)
    raises("e_star", asperity.Dmt, 1e-6, 0.0, 0.1)
    raises("sigma0", asperity.MaugisDugdale, 1e-6, 1e10, 0.1, -1.0)
    raises("cohesive_stress", asperity.MaugisDugdale, 1e-6, 1e10, 0.1, cohesive_stress=-1.0)
    raises("nu1", asperity.effective_modulus, 1e9, 0.7, 1e9, 0.3)


def test_nan_and_inf():
    raises("radius", asperity.Jkr, math.nan, 1e10, 0.1)
    raises("work_of_adhesion", asperity.Jkr, 1e-6, 1e10, math.inf)
    law = asperity.Jkr(1e-6, 1e10, 0.1)
    raises("delta", law.eval, math.nan)
    msg = raises("delta", law.eval, np.array([1e-9, math.nan, 1e-9]))
    assert msg.startswith("element 1:"), msg


def test_bad_types():
    raises("radius", asperity.Jkr, "1e-6", 1e10, 0.1)
    raises("e_star", asperity.Hertz, 1e-6, None)
    raises("e1", asperity.effective_modulus, [1.0], 0.3, 1e9, 0.3)
    law = asperity.Hertz(1e-6, 1e10)
    raises("delta", law.eval, "0.1")
    raises("delta", law.eval, {"a": 1})
    raises("control", law.pull_off_force, "sideways")
    raises("control", law.pull_off_force, 3)
    raises("n", asperity.ContactState.fresh, 2.5)
    raises("x", asperity.profile_parameters, "x", np.zeros(10))


def test_arrays_shape_dtype_contiguity():
    law = asperity.Hertz(1e-6, 1e10)
    d = np.linspace(0, 1e-9, 20)
    msg = raises("delta", law.eval, d[::2])
    assert "contiguous" in msg
    raises("delta", law.eval, d.reshape(4, 5))
    raises("delta", law.eval, d.astype(np.float32))
    raises("delta", law.eval, np.arange(5))
    assert law.eval([0.0, 1e-9]).force.shape == (2,)  # a list is converted


def test_wrong_lengths():
    law = asperity.Jkr(1e-6, 1e10, 0.1)
    s = law.eval(np.zeros(3)).state
    raises("state", law.eval, np.zeros(4), state=s)
    raises("state", law.eval, 1e-9, state=s)
    raises("state", law.eval, np.zeros(1), state=law.eval(1e-9).state)
    out = law.eval(np.zeros(3))
    raises("out", law.eval, np.zeros(5), out=out)
    raises("out", law.eval, np.zeros(1), out=law.eval_at_load(np.array([0.0])))
    raises("cohesive_radius", asperity.ContactState.from_arrays, np.zeros(2), np.zeros(3), [0, 0], [0, 0])
    raises("z", asperity.profile_parameters, np.arange(10.0), np.zeros(9))
    raises("x", asperity.profile_parameters, np.array([0.0, 1.0, 0.5, 2.0]), np.zeros(4))


def test_nothing_half_written_on_error():
    law = asperity.Jkr(1e-6, 1e10, 0.1)
    d = np.linspace(1e-10, 1e-9, 8)
    out = law.eval(d)
    before = out.force.copy()
    bad = d.copy()
    bad[5] = math.nan
    with pytest.raises(asperity.Error):
        law.eval(bad, out=out)
    # out= is the caller's own buffer: elements before the failing one may be
    # written (as the C batch documents), never those after it.
    assert np.array_equal(out.force[6:], before[6:])
    # Without out= no result object exists at all.
    with pytest.raises(asperity.Error):
        r = law.eval(bad)  # noqa: F841


def test_other_modules_name_arguments():
    raises("sigma", asperity.HeightDistribution.gaussian, -1.0)
    raises("detrend", asperity.profile_parameters, 1e-6, np.zeros(16), detrend="cubic")
    raises("z", asperity.psd, np.zeros(1), 1e-6)
    raises("mu", asperity.LjSphere.from_tabor, -1.0)
    raises("kappa", asperity.Rescaling, -1.0, 2.0)
    raises("indenter", asperity.analyze_indentation, depth=np.zeros(3), load=np.zeros(3), indenter="banana")
    raises("scene", asperity.run_scene, 42)
