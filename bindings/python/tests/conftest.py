"""Shared helpers of the Python package's tests.

* ``skip(reason)``: a check that cannot run here prints ``SKIPPED: reason``
  and skips; under ``ASPERITY_REQUIRE_ALL=1`` (set by ``.ci/run``) it fails
  instead, as the Rust tests do.
* ``shared_data(*parts)``: a file of the measured data sets in
  ``../shared/data`` relative to the repository root (skips when absent).
* ``cli_json(*args)``: the ``asperity`` command's ``--json`` output, run
  through ``cargo run --features cli`` in the repository (or the binary named
  by ``ASPERITY_CLI``).
* ``assert_same(a, b)``: two JSON-like values equal, floats to 1e-12
  relative.
"""

import json
import math
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
"""The repository's root (bindings/python/tests -> ../../..)."""


def skip(reason):
    print(f"SKIPPED: {reason}")
    if os.environ.get("ASPERITY_REQUIRE_ALL") == "1":
        pytest.fail(f"this check could not run ({reason}), and ASPERITY_REQUIRE_ALL=1 forbids skipping")
    pytest.skip(reason)


def shared_data(*parts):
    path = ROOT.parent / "shared" / "data"
    path = path.joinpath(*parts)
    if not path.exists():
        skip(f"{path} is absent (the measured data sets live in ../shared/data beside the repository)")
    return path


def example(*parts):
    return ROOT.joinpath("examples", *parts)


def cli_json(*args):
    exe = os.environ.get("ASPERITY_CLI")
    if exe:
        cmd = [exe, *args]
    else:
        cargo = shutil.which("cargo")
        if cargo is None or not (ROOT / "Cargo.toml").exists():
            skip("cargo (or the repository) is not available to run the asperity command; set ASPERITY_CLI to its binary")
        cmd = [cargo, "run", "--quiet", "--features", "cli", "--", *args]
    out = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=1800)
    if out.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed: {out.stderr}")
    return json.loads(out.stdout)


def assert_same(a, b, path="", rel=1e-12):
    if isinstance(a, dict):
        assert isinstance(b, dict), path
        assert sorted(a) == sorted(b), f"{path}: keys {sorted(a)} != {sorted(b)}"
        for k in a:
            assert_same(a[k], b[k], f"{path}.{k}", rel)
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{path}[{i}]", rel)
    elif isinstance(a, float) or isinstance(b, float):
        if a is None or b is None:
            assert a is b, f"{path}: {a} != {b}"
        else:
            assert math.isclose(a, b, rel_tol=rel, abs_tol=0.0) or a == b, f"{path}: {a} != {b}"
    else:
        assert a == b, f"{path}: {a!r} != {b!r}"
