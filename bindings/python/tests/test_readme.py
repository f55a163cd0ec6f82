"""The example of bindings/python/README.md runs as printed (from the
repository root, where its relative paths point)."""

import os
import re
from pathlib import Path

from conftest import ROOT


def test_readme_example_runs(capsys):
    text = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    code = re.search(r"## Example\n\n```python\n(.*?)```", text, re.S).group(1)
    here = os.getcwd()
    os.chdir(ROOT)
    try:
        exec(compile(code, "README.md", "exec"), {})
    finally:
        os.chdir(here)
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "-1.5"
    assert "invalid argument `radius`" in out
