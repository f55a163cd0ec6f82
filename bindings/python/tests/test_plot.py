"""asperity.plot draws the CLI's figures with matplotlib (the ``plot``
extra) and says how to get it when it is missing."""

import builtins
import importlib

import numpy as np
import pytest

import asperity
from conftest import example, skip


def matplotlib_or_skip():
    try:
        import matplotlib
    except ModuleNotFoundError:
        skip("matplotlib is not installed (pip install 'asperity[plot]')")
    matplotlib.use("Agg")


def test_figures_draw(tmp_path):
    matplotlib_or_skip()
    import matplotlib.pyplot as plt

    from asperity import plot

    ax = plot.force_approach(1e-6, 1e9, 0.05)
    assert len(ax.lines) >= 3
    plot.law_cycle(asperity.Jkr(1e-6, 1e9, 0.05), np.linspace(-5e-9, 2e-8, 100))
    plot.lj_curve(asperity.LjSphere(1e-6, 1e10, 0.05, 0.3e-9), n_grid=64)
    z = asperity.self_affine_profile(2048, 1e-6, 0.8, 1e-6, seed=1)
    plot.profile(1e-6, z)
    plot.psd(z, 1e-6)
    plot.acf(z, 1e-6)
    plot.material_ratio(z)
    run = asperity.run_scene(example("scenes", "dynamic_models.json"))
    plot.slider(run)
    ax = plot.friction_models(run)
    assert len(ax.lines) == 1 + len(run.models)
    c = asperity.read_indentation_curve(example("data", "synthetic_berkovich.csv"))
    r = asperity.analyze_indentation(example("data", "synthetic_berkovich.csv"), nu_sample=0.17)
    plot.indentation(c["depth"], c["load"], r)
    plt.gcf().savefig(tmp_path / "fig.png")
    plt.close("all")


def test_missing_matplotlib_says_how(monkeypatch):
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kw):
        if name.startswith("matplotlib"):
            raise ModuleNotFoundError("No module named 'matplotlib'")
        return real_import(name, *args, **kw)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    import asperity.plot as plot

    plot = importlib.reload(plot)
    with pytest.raises(ModuleNotFoundError, match=r"pip install 'asperity\[plot\]'"):
        plot.force_approach(1e-6, 1e9, 0.05)
