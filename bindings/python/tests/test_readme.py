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


def test_quick_start_of_the_main_readme():
    """examples/python/quick_start.py (a block of the repository's README,
    kept equal to the file by tests/readme.rs) runs and exits 0."""
    import subprocess
    import sys

    out = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "quick_start.py")], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert "-1.500000 pi w R" in out.stdout
