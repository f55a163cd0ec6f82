#!/usr/bin/env python3
"""The library's friction physics inside the FE model of cattaneo_mindlin.py:
a rigid cylinder pressed into a copper block (with friction from the first
contact on), then moved sideways and back, and forward again (loading,
unloading, reloading), with

* `--law homogenised`: the homogenised energy-dissipation law, mu(p), the
  adhesive pressure and the dissipation shares tabulated from runs of the
  chapter-6 copper slider (examples/scenes/chapter6_copper.json) at nominal
  pressures spanning the interface's, as `Slider::homogenise` builds it; or
* `--law maxwell_slip`: Maxwell-slip elements (thesis 5.3.8; Al-Bender,
  Lampaert and Swevers 2004), whose pre-sliding hysteresis is in the law.

Per node the law reports its dissipation; the script checks the balance
work of the indenter = change of the stored energy (strain energy, normal
penalty, the law's stored energy) + dissipation, writes the slip and
dissipation along the interface and the Q-s hysteresis loop. `--json`
prints one JSON object (README.md in this folder).
"""

from __future__ import annotations

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact2d import COMM, Geometry, Material, Model, dump_json, log, pyplot, timer  # noqa: E402

import asperity  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "scenes", "chapter6_copper.json")


def homogenised_law(stick_stiffness: float, samples: int):
    """The homogenised law of the chapter-6 copper slider, sampled at
    `samples` nominal pressures from 0.5 % to 50 % of the slider's capacity
    (its rods' yield load over its nominal area), each from a slide over
    60 um in 1.5 um steps."""
    slider = asperity.Slider.from_scene(SCENE)
    cap = slider.capacity / slider.nominal_area
    pressures = list(np.geomspace(0.005 * cap, 0.5 * cap, samples))
    return slider.homogenise(pressures, 60e-6, 1.5e-6, stick_stiffness=stick_stiffness)


def maxwell_slip_law(mu: float, reach: list):
    """Maxwell-slip elements of equal break-away coefficients mu/n and the
    slip deflections `reach` (m): element stiffness k_i = mu_i/r_i per unit
    normal force."""
    n = len(reach)
    cap = [mu / n] * n
    return asperity.MaxwellSlip(stiffness=[c / r for c, r in zip(cap, reach)], capacity=cap)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--law", choices=["homogenised", "maxwell_slip"], default="homogenised")
    ap.add_argument("--cells", type=int, default=12, help="mesh cells across the contact half-width")
    ap.add_argument("--young", type=float, default=120e9, help="E of the block (Pa; copper)")
    ap.add_argument("--poisson", type=float, default=0.34)
    ap.add_argument("--radius", type=float, default=0.1, help="indenter radius R (m); p0 = E* a/2R = 68 MPa, within the slider table")
    ap.add_argument("--half-width", type=float, default=1e-4, help="target contact half-width a (m)")
    ap.add_argument("--size", type=float, default=20.0, help="block half-width and depth, in a")
    ap.add_argument("--penalty", type=float, default=1e2, help="normal penalty, in E*/(node spacing)")
    ap.add_argument("--stick-factor", type=float, default=10.0,
                    help="homogenised law: stick stiffness, in E*/(node spacing)")
    ap.add_argument("--samples", type=int, default=8, help="homogenised law: slider runs (pressures)")
    ap.add_argument("--mu", type=float, default=0.3, help="Maxwell-slip: static coefficient sum mu_i")
    ap.add_argument("--reach", default="2e-9,1e-8,3e-8,1e-7",
                    help="Maxwell-slip: element slip deflections r_i (m)")
    ap.add_argument("--amplitude", type=float, default=0.7,
                    help="tangential amplitude, in units of the full-stick shift for mu P")
    ap.add_argument("--normal-steps", type=int, default=8)
    ap.add_argument("--steps", type=int, default=8, help="steps per quarter of the tangential cycle")
    ap.add_argument("--depth-factor", type=float, default=2.1)
    ap.add_argument("--tolerance", type=float, default=1e-10)
    ap.add_argument("--frictionless-normal-loading", action="store_true",
                    help="apply the normal load without friction (the law is stepped from the first tangential step)")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--plot", metavar="DIR")
    args = ap.parse_args()

    mat = Material(args.young, args.poisson)
    estar = mat.plane_strain_modulus
    a = args.half_width
    h_node = a / args.cells / 2.0
    geo = Geometry(radius=args.radius, half_width=a, size=args.size * a, cells_per_half_width=args.cells)
    clock = timer()
    if args.law == "homogenised":
        law = homogenised_law(args.stick_factor * estar / h_node, args.samples)
        mu_ref = None
    else:
        law = maxwell_slip_law(args.mu, [float(r) for r in args.reach.split(",")])
        mu_ref = args.mu
    build_seconds = clock()
    model = Model(geo, mat, law, penalty_factor=args.penalty, tolerance=args.tolerance)
    P_target = math.pi * estar * a**2 / (4.0 * args.radius)
    delta = P_target / estar * args.depth_factor
    snap = {"normal": (0.0, model.stored_energy(), 0.0)}
    path = []

    def record(rec, phase):
        path.append({"phase": phase, "delta": rec.delta, "shift": rec.shift,
                     "normal_load": rec.normal_load, "tangential_load": rec.tangential_load,
                     "iterations": rec.iterations, "converged": rec.converged})
        log(f"  {phase}: s = {rec.shift:.3e} m, P = {rec.normal_load:.5e}, Q = {rec.tangential_load:.5e} N/m, "
            f"{rec.iterations} it, residuals {' '.join(f'{x:.1e}' for x in rec.residuals)}")

    model.friction_active = not args.frictionless_normal_loading
    for k in range(1, args.normal_steps + 1):
        record(model.step(delta * k / args.normal_steps, 0.0), "normal")
    if not model.friction_active:
        model.start_friction()
    P = model.normal_load
    kt = model.tangential_stiffness()
    # The limit force of the interface: mu P (Maxwell-slip), or the
    # homogenised law's slip force summed over the nodes.
    if mu_ref is None:
        w, p = model.weight, model.pressure
        limit = 0.0
        for wi, pi in zip(w, p):
            if pi > 0:
                smp = law.sample_at(pi)
                limit += wi * smp["cof"] * (pi + smp["adhesion_pressure"])
        limit = COMM.allreduce(limit)
    else:
        limit = mu_ref * P
    amplitude = args.amplitude * limit / kt
    n = args.steps
    legs = [("loading", 0.0, amplitude), ("unloading", amplitude, -amplitude),
            ("reloading", -amplitude, amplitude)]
    for phase, s0, s1 in legs:
        snap[phase] = (model.work, model.stored_energy(), model.dissipation)
        m = n if phase == "loading" else 2 * n
        for k in range(1, m + 1):
            record(model.step(delta, s0 + (s1 - s0) * k / m), phase)
    snap["end"] = (model.work, model.stored_energy(), model.dissipation)
    f = model.interface()
    # Collective: every rank takes part.
    energies = {
        "strain_energy": model.strain_energy(),
        "penalty_energy": model.penalty_energy(),
        "law_stored_energy": model.friction_stored_energy(),
    }
    seconds = clock()
    if COMM.rank != 0:
        return
    def balance(a, b):
        w = snap[b][0] - snap[a][0]
        e = snap[b][1] - snap[a][1]
        d = snap[b][2] - snap[a][2]
        return {"work": w, "elastic_energy_change": e, "dissipation": d,
                "imbalance": w - e - d, "imbalance_over_dissipation": (w - e - d) / d if d else None}

    # The normal loading against the tangential part, and the closed cycle
    # (unloading + reloading, from s = +A back to +A): its work is the
    # area of the Q-s loop.
    normal = balance("normal", "loading")
    tangential = balance("loading", "end")
    cycle = balance("unloading", "end")
    cyc = [r for r in path if r["phase"] in ("unloading", "reloading")]
    s_arr = np.array([path[len(path) - len(cyc) - 1]["shift"]] + [r["shift"] for r in cyc])
    q_arr = np.array([path[len(path) - len(cyc) - 1]["tangential_load"]] + [r["tangential_load"] for r in cyc])
    loop_area = float(np.sum(0.5 * (q_arr[1:] + q_arr[:-1]) * np.diff(s_arr)))
    out = {
        "law": args.law,
        # The balance over the tangential history (loading, unloading,
        # reloading at constant indenter depth), J per unit length.
        "work": tangential["work"],
        "elastic_energy_change": tangential["elastic_energy_change"],
        "dissipation": tangential["dissipation"],
        "energy_imbalance": tangential["imbalance"],
        "energy_imbalance_over_dissipation": tangential["imbalance_over_dissipation"],
        **energies,
        "loop_area": loop_area,
        "normal_loading": normal,
        "cycle": cycle,
        "normal_load": P,
        "tangential_amplitude": amplitude,
        "limit_force": limit,
        "max_tangential_load": max(abs(r["tangential_load"]) for r in path),
        "newton_iterations": [r["iterations"] for r in path],
        "converged": all(r["converged"] for r in path),
        "cells": model.cells,
        "ranks": COMM.size,
        "law_build_seconds": build_seconds,
        "seconds": seconds,
        "path": path,
        "interface": {k: f[k] for k in ("x", "pressure", "shear", "regime", "slip_path", "dissipation_density")},
    }
    for name, b in (("normal loading", normal), ("tangential loading, unloading, reloading", tangential),
                    ("closed cycle", cycle)):
        ratio = b["imbalance_over_dissipation"]
        log(f"{name}: work {b['work']:.6e} J/m = stored change {b['elastic_energy_change']:.6e} + dissipation "
            f"{b['dissipation']:.6e} + imbalance {b['imbalance']:+.3e}"
            + (f" ({100 * ratio:+.3f} % of the dissipation)" if ratio is not None else ""))
    log(f"loop area {loop_area:.6e} J/m")
    if args.plot:
        plot(out, args.plot)
    if args.json:
        print(dump_json(out))


def plot(out, directory):
    plt = pyplot()
    if plt is None:
        return
    os.makedirs(directory, exist_ok=True)
    law = out["law"]
    fig, ax = plt.subplots(figsize=(5.4, 4.0))
    s = [0.0] + [r["shift"] for r in out["path"] if r["phase"] != "normal"]
    q = [0.0] + [r["tangential_load"] for r in out["path"] if r["phase"] != "normal"]
    ax.plot(np.array(s) * 1e9, np.array(q) / out["normal_load"], "o-", ms=3)
    ax.set_xlabel("indenter shift s (nm)")
    ax.set_ylabel("Q / P")
    ax.set_title(f"{law}: Q-s loop, dissipation {out['dissipation']:.3g} J/m")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, f"energy_law_{law}_loop.svg"))
    f = out["interface"]
    fig2, ax2 = plt.subplots(2, 1, figsize=(5.4, 5.2), sharex=True)
    x = np.array(f["x"]) * 1e6
    ax2[0].plot(x, np.array(f["slip_path"]) * 1e9, ".-", ms=3)
    ax2[0].set_ylabel("slip path (nm)")
    ax2[1].plot(x, np.array(f["dissipation_density"]), ".-", ms=3)
    ax2[1].set_ylabel("dissipation (J/m$^2$)")
    ax2[1].set_xlabel("x (um)")
    lim = 1.5 * max(abs(xx) for xx, pp in zip(x, f["pressure"]) if pp > 0)
    ax2[1].set_xlim(-lim, lim)
    ax2[0].set_title(f"{law}: along the interface after the cycle")
    fig2.tight_layout()
    fig2.savefig(os.path.join(directory, f"energy_law_{law}_interface.svg"))


if __name__ == "__main__":
    main()
