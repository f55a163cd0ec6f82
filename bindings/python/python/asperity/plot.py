"""Figures of the ``asperity`` command, drawn with matplotlib.

Each function draws on ``ax`` (a new figure when None) and returns the axes
(or a tuple of axes). The figures are those the CLI writes as SVG:

* :func:`force_approach` — DMT, JKR and Maugis–Dugdale force–approach cycles
  (``asperity curve``), or :func:`law_cycle` for any law;
* :func:`lj_curve` — the numerical Lennard-Jones sphere (``asperity lj``);
* :func:`profile`, :func:`acf`, :func:`psd`, :func:`material_ratio` — a
  measured line scan (``asperity profile --svg``);
* :func:`slider` and :func:`friction_models` — a scene's coefficient of
  friction and dissipation per increment, and the dynamic models along the
  same track (``asperity slide``);
* :func:`indentation` — a load–depth curve with its loading fit.

matplotlib is an optional dependency: ``pip install 'asperity[plot]'`` (or
``pip install matplotlib``). Without it every function raises
ModuleNotFoundError saying so.
"""

import math

import numpy as np

import asperity

_HOW = "asperity.plot needs matplotlib: pip install 'asperity[plot]' (or: pip install matplotlib)"


def _plt():
    try:
        import matplotlib.pyplot as plt
    except ModuleNotFoundError as e:  # pragma: no cover - depends on the environment
        raise ModuleNotFoundError(_HOW) from e
    return plt


def _axes(ax, n=1):
    plt = _plt()
    if ax is not None:
        return ax
    fig, axes = plt.subplots(n, 1, figsize=(8, 4.5 if n == 1 else 3.2 * n), squeeze=True)
    return axes


def _cycle_path(lo, hi, points):
    up = np.linspace(lo, hi, points + 1)
    return np.concatenate([up, up[::-1]])


def law_cycle(law, delta, ax=None, label=None, force_scale=1.0, length_scale=1.0):
    """Force (N) against overlap (m) along the displacement-controlled path
    ``delta`` (approach then retraction: hysteresis shows), divided by
    ``force_scale`` (N) and ``length_scale`` (m)."""
    ax = _axes(ax)
    r = law.eval_path(np.ascontiguousarray(delta, dtype=float))
    ax.plot(np.asarray(delta) / length_scale, r.force / force_scale, label=label or type(law).__name__)
    ax.set_xlabel("overlap δ" + (" (m)" if length_scale == 1.0 else " / length scale"))
    ax.set_ylabel("force P" + (" (N)" if force_scale == 1.0 else " / (π w R)"))
    ax.axhline(0.0, color="0.7", lw=0.5)
    ax.legend()
    return ax


def force_approach(radius, e_star, work_of_adhesion, z0=0.3e-9, points=200, ax=None):
    """The figure of ``asperity curve``: DMT, JKR and Maugis–Dugdale
    (λ = 1.157 μ) force–approach cycles under displacement control for a
    sphere of radius R (m), contact modulus E* (Pa), work of adhesion w
    (J/m²) and Lennard-Jones z0 (m), in units of πwR and the Maugis–Dugdale
    length scale."""
    ax = _axes(ax)
    md = asperity.MaugisDugdale.from_tabor(radius, e_star, work_of_adhesion, z0)
    length = md.length_scale()
    scale = math.pi * radius * work_of_adhesion
    path = _cycle_path(-3.0 * length - md.range(), 4.0 * length, points)
    for name, law in [
        ("DMT", asperity.Dmt(radius, e_star, work_of_adhesion)),
        ("JKR", asperity.Jkr(radius, e_star, work_of_adhesion)),
        ("Maugis-Dugdale", md),
    ]:
        law_cycle(law, path, ax=ax, label=name, force_scale=scale, length_scale=length)
    mu = asperity.tabor_parameter(radius, work_of_adhesion, e_star, z0)
    ax.set_title(f"Force-approach cycle (Tabor μ = {mu:.3g}, Maugis λ = {md.lambda_:.3g})")
    return ax


def lj_curve(curve_or_sphere, ax=None, n_grid=0):
    """The figure of ``asperity lj``: force/(πwR) against approach/z0 of the
    Lennard-Jones sphere, with the jump points and the load-controlled
    pull-off. Takes an ``LjCurve`` or an ``LjSphere`` (solved on ``n_grid``)."""
    c = curve_or_sphere.curve(n_grid) if isinstance(curve_or_sphere, asperity.LjSphere) else curve_or_sphere
    ax = _axes(ax)
    ax.plot(c.approach_bar, c.force_bar, label="Lennard-Jones")
    for name, p, m in [("jump-in", c.jump_in, "v"), ("jump-out", c.jump_out, "^"), ("pull-off (load)", c.pull_off_load, "o")]:
        if p is not None:
            ax.plot([p["approach_bar"]], [p["force_bar"]], m, label=name)
    ax.set_xlabel("approach / z0")
    ax.set_ylabel("force / (π w R)")
    ax.axhline(0.0, color="0.7", lw=0.5)
    ax.set_title("Lennard-Jones sphere")
    ax.legend()
    return ax


def profile(x, z, detrend="linear", ax=None):
    """The profile figure of ``asperity profile --svg``: the measured heights
    (µm) with the removed form, and the profile about it. ``x`` positions (m)
    or the spacing dx (m); ``z`` heights (m)."""
    z = np.ascontiguousarray(z, dtype=float)
    x = np.arange(z.size) * float(x) if np.ndim(x) == 0 else np.asarray(x, dtype=float)
    axes = _axes(ax, 2)
    form = {"none": None, "mean": "mean", "linear": "linear", "quadratic": "quadratic"}[detrend]
    resid = z if form is None else asperity.remove_form(z, form)
    axes[0].plot(x * 1e3, z * 1e6, lw=0.6, label="measured")
    axes[0].plot(x * 1e3, (z - resid) * 1e6, lw=1.0, label=f"form ({detrend})")
    axes[0].set_ylabel("height (µm)")
    axes[0].legend()
    axes[1].plot(x * 1e3, resid * 1e6, lw=0.6)
    axes[1].axhline(0.0, color="0.5", lw=0.5)
    axes[1].set_xlabel("position (mm)")
    axes[1].set_ylabel("about the mean line (µm)")
    p = asperity.profile_parameters(x if x.size == z.size else float(x[1] - x[0]), z, detrend=detrend)
    axes[0].set_title(f"Ra = {p['Ra'] * 1e6:.4g} µm, Rq = {p['Rq'] * 1e6:.4g} µm, Rz = {p['Rz'] * 1e6:.4g} µm")
    return axes


def acf(z, dx, ax=None):
    """Normalised autocorrelation against lag (µm), up to half the length."""
    a = asperity.acf(np.ascontiguousarray(z, dtype=float), dx)
    ax = _axes(ax)
    half = a["lag"].size // 2
    ax.plot(a["lag"][:half] * 1e6, a["normalized"][:half])
    ax.axhline(1 / math.e, color="0.6", lw=0.5, ls="--", label="1/e")
    ax.set_xlabel("lag (µm)")
    ax.set_ylabel("ACF / Rq²")
    ax.legend()
    return ax


def psd(z, dx, ax=None):
    """The Hann-windowed PSD on log-log axes with the fitted power law when
    one applies (as ``asperity profile --svg``)."""
    z = np.ascontiguousarray(z, dtype=float)
    s = asperity.psd(z, dx, window="hann")
    ax = _axes(ax)
    ax.loglog(s["q"][1:], s["psd"][1:], lw=0.6, label="PSD (Hann)")
    try:
        f = asperity.hurst_fit(z, dx)
    except asperity.Error:
        f = None
    if f is not None and f["r_squared"] >= 0.9 and 0.0 <= f["hurst"] <= 1.0:
        q = np.geomspace(f["q_min"], f["q_max"], 50)
        ax.loglog(q, f["prefactor"] * q ** f["slope"], "r", label=f"G ∝ q^{f['slope']:.3f} (H = {f['hurst']:.3f})")
    ax.set_xlabel("q (rad/m)")
    ax.set_ylabel("G(q) (m³)")
    ax.legend()
    return ax


def material_ratio(z, ax=None):
    """The Abbott-Firestone (material ratio) curve of heights ``z`` (m)."""
    c = asperity.material_ratio_curve(np.ascontiguousarray(z, dtype=float), 201)
    ax = _axes(ax)
    ax.plot(c["ratio"] * 100, c["level"] * 1e6)
    ax.set_xlabel("material ratio Rmr (%)")
    ax.set_ylabel("level c (µm)")
    return ax


def slider(run, ax=None):
    """A scene's run (``asperity.run_scene``): the coefficient of friction per
    increment against the sliding distance, and the energy dissipated per
    increment by mechanism (the CLI's *_cof.svg and *_dissipation.svg)."""
    axes = _axes(ax, 2)
    s = run.steps
    x = s["position"] * 1e6
    axes[0].plot(x, s["cof"], lw=0.8)
    axes[0].axhline(run.summary["mean_cof"], color="r", lw=0.6, ls="--", label=f"mean {run.summary['mean_cof']:.3f}")
    axes[0].set_ylabel("COF μ")
    axes[0].legend()
    for k in ["chemical", "van_der_waals", "elastic", "plastic"]:
        axes[1].plot(x, s[k], lw=0.8, label=k.replace("_", " "))
    axes[1].set_xlabel("sliding distance (µm)")
    axes[1].set_ylabel("dissipated per increment (J)")
    axes[1].legend()
    return axes


def friction_models(run, ax=None):
    """μ along the track of every dynamic model of a scene next to the
    energy-dissipation model (the CLI's *_models_cof.svg)."""
    ax = _axes(ax)
    x = run.steps["position"] * 1e6
    ax.plot(x, run.steps["cof"], lw=1.0, label="energy dissipation")
    for m in run.models:
        ax.plot(x, m["steps"]["cof"], lw=0.8, label=m["name"])
    ax.set_xlabel("sliding distance (µm)")
    ax.set_ylabel("COF μ")
    ax.legend()
    return ax


def indentation(depth, load, result=None, ax=None):
    """A load-depth curve (nm, mN) with the loading power law of
    ``analyze_indentation`` when ``result`` is given."""
    ax = _axes(ax)
    depth = np.asarray(depth, dtype=float)
    load = np.asarray(load, dtype=float)
    ax.plot(depth * 1e9, load * 1e3, ".", ms=2, label="data")
    if result is not None and result.get("loading"):
        fit = result["loading"]
        h = np.linspace(depth[depth > 0].min(), depth.max(), 200)
        p = fit["reference_load"] * (h / fit["reference_depth"]) ** fit["slope"]
        ax.plot(h * 1e9, p * 1e3, "r", label=f"loading fit P ∝ h^{fit['slope']:.3f}")
    ax.set_xlabel("depth (nm)")
    ax.set_ylabel("load (mN)")
    ax.legend()
    return ax
