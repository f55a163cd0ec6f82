"""Friction: the mechanisms and ledger against the thesis's copper values
the Rust tests use, and a scene run equal to ``asperity slide --json``."""

import json
from pathlib import Path

import numpy as np
import pytest

import asperity

from conftest import assert_same, cli_json, example


def test_copper_material():
    cu = asperity.FrictionMaterial.copper()
    assert cu.e_star() == pytest.approx(120e9 / (2 * (1 - 0.355**2)), rel=1e-12)
    assert cu.c_ns() == pytest.approx(1.017376, rel=1e-6)
    assert cu.work_of_adhesion == pytest.approx(0.10928, rel=1e-4)
    again = asperity.FrictionMaterial.from_dict(cu.to_dict())
    assert again.to_dict() == cu.to_dict()
    assert asperity.coefficient_of_friction(1.0, 2.0) == 0.5
    assert asperity.coefficient_of_friction(1.0, 2.0, 1.0, form="derjaguin") == pytest.approx(1 / 3)
    assert asperity.bond_energy_from_molar(202e3) == pytest.approx(3.35429e-19, rel=1e-5)
    with pytest.raises(asperity.Error, match="`normal_load`"):
        asperity.coefficient_of_friction(1.0, 0.0)


@pytest.mark.parametrize("scene", ["dynamic_models.json", "chapter6_copper.json"])
def test_scene_equals_cli(scene):
    path = example("scenes", scene)
    run = asperity.run_scene(str(path))
    cli = cli_json("slide", str(path), "--json")
    assert_same(cli, run.summary)
    s = run.steps
    n = cli["steps"]
    assert all(len(v) == n for v in s.values())
    assert np.mean(s["cof"]) == pytest.approx(cli["mean_cof"], rel=1e-12)
    total = sum(float(np.sum(s[k])) for k in ["chemical", "van_der_waals", "elastic", "plastic"])
    assert total == pytest.approx(sum(cli["dissipation"].values()), rel=1e-9)
    for m, c in zip(run.models, cli.get("friction_models", [])):
        assert m["name"] == c["name"]
        assert np.mean(m["steps"]["cof"]) == pytest.approx(c["mean_cof"], rel=1e-12)


def test_scene_from_dict_equals_file():
    path = example("scenes", "dynamic_models.json")
    d = json.loads(path.read_text())
    a = asperity.run_scene(d, base=path.parent)
    b = asperity.run_scene(path)
    assert_same(a.summary, b.summary, rel=0.0)
    bad = dict(d)
    bad["nonsense"] = 1
    with pytest.raises(asperity.Error, match="nonsense"):
        asperity.run_scene(bad, base=path.parent)
