#!/usr/bin/env python3
"""Cattaneo-Mindlin partial slip in FEniCSx with asperity's friction law in
its Coulomb limit: a rigid cylinder pressed into an elastic block by P per
unit length, then moved sideways until Q < mu P, solved by Newton with the
law's consistent tangents on a sequence of meshes, against the analytical
solution (Johnson, Contact Mechanics, 1985, section 7.1: the stick zone
|x| < c with c/a = sqrt(1 - Q/(mu P)) and the shear traction
q(x) = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)] in it, mu p(x)
outside).

Run serially or with `mpirun -np 2`; `--json` prints one JSON object (see
README.md in this folder). The law: asperity.HomogenisedFriction with one
sample (constant mu, Amontons form, no adhesion) and a stick stiffness, the
homogenised law's regularised Coulomb limit.
"""

from __future__ import annotations

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from contact2d import (  # noqa: E402
    COMM, Geometry, Material, Model, dump_json, fit_elliptic_edge,
    hertz_half_width, log, pyplot, timer,
)

import asperity  # noqa: E402


def coulomb_law(mu: float, stick_stiffness: float):
    """The homogenised law with constant mu (per unit area: stick stiffness
    in Pa/m)."""
    sample = {
        "pressure": 0.0,
        "cof": mu,
        "adhesion_pressure": 0.0,
        "contact_fraction": 1.0,
        "shares": {"chemical": 0.0, "van_der_waals": 0.0, "elastic": 0.0, "plastic": 1.0},
    }
    return asperity.HomogenisedFriction([sample], form="amontons", stick_stiffness=stick_stiffness)


def analytical_shear(x, a, c, p0, mu):
    """Cattaneo-Mindlin shear traction on the block (Pa), for Q > 0."""
    x = np.asarray(x)
    full = mu * p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))
    corr = mu * p0 * (c / a) * np.sqrt(np.clip(1.0 - (x / c) ** 2, 0.0, None))
    return full - np.where(np.abs(x) < c, corr, 0.0)


def rms(v) -> float:
    return float(np.sqrt(np.mean(np.square(v))))


def run(args, cells_per_half_width: int, tangent: str = "law", max_iterations: int = 30):
    mat = Material(args.young, args.poisson)
    a_target = args.half_width
    estar = mat.plane_strain_modulus
    P_target = math.pi * estar * a_target**2 / (4.0 * args.radius)
    geo = Geometry(
        radius=args.radius, half_width=a_target, size=args.size * a_target,
        cells_per_half_width=cells_per_half_width,
    )
    h_node = a_target / cells_per_half_width / 2.0
    law = coulomb_law(args.mu, args.stick_factor * estar / h_node)
    model = Model(geo, mat, law, penalty_factor=args.penalty, tangent=tangent,
                  tolerance=args.tolerance, max_iterations=max_iterations)
    clock = timer()
    # Normal loading, displacement control: the depth that gives P_target
    # on this block (calibrated, see README), in equal steps.
    delta = P_target / estar * args.depth_factor
    # Cattaneo-Mindlin: the normal load is applied without shear tractions
    # (on a half-plane with beta = 0 friction would add none; on the finite
    # block the free sides bulge and would lock some in), then friction
    # acts from the first tangential increment on.
    model.friction_active = args.friction_in_normal_loading
    for k in range(1, args.normal_steps + 1):
        rec = model.step(delta * k / args.normal_steps, 0.0)
        log(f"  normal step {k}: P = {rec.normal_load:.6e} N/m, {rec.iterations} it, "
            f"residuals {' '.join(f'{r:.1e}' for r in rec.residuals)}")
    P = model.normal_load
    model.start_friction()
    # Tangential loading: sized from the stick stiffness dQ/ds at full
    # stick so that Q/(mu P) ends near args.ratio.
    kt = model.tangential_stiffness()
    s_final = args.shift_factor * args.ratio * args.mu * P / kt
    for k in range(1, args.tangential_steps + 1):
        rec = model.step(delta, s_final * k / args.tangential_steps)
        log(f"  tangential step {k}: Q/(mu P) = {rec.tangential_load / (args.mu * P):.4f}, "
            f"{rec.iterations} it, residuals {' '.join(f'{r:.1e}' for r in rec.residuals)}")
    elapsed = clock()
    Q = model.tangential_load
    out = {
        "cells": model.cells,
        "cells_per_half_width": cells_per_half_width,
        "contact_nodes_total": model.contact_nodes,
        "node_spacing": h_node,
        "normal_load": P,
        "tangential_load": Q,
        "newton_iterations": [r.iterations for r in model.history],
        "converged": all(r.converged for r in model.history),
        "residual_history": [r.residuals for r in model.history],
        "seconds": elapsed,
    }
    f = model.interface()
    if COMM.rank == 0:
        x, p, t, regime = f["x"], f["pressure"], f["shear"], f["regime"]
        inside = p > 0
        a_fit, p0_fit = fit_elliptic_edge(x[inside], p[inside])
        stick = inside & (regime == 0)
        slipping = inside & (regime == 2)
        # mu p - q = mu p0 (c/a) sqrt(1 - x^2/c^2) in the stick zone.
        c_fit, _ = fit_elliptic_edge(x[stick], args.mu * p[stick] - t[stick])
        ratio_analytical = math.sqrt(1.0 - Q / (args.mu * P))
        a_hertz = hertz_half_width(P, args.radius, estar)
        p0 = 2.0 * P / (math.pi * a_hertz)
        c_an = ratio_analytical * a_hertz
        # The node bracket: the outermost stick node and the innermost
        # slipping node on each side.
        xs_stick = np.abs(x[stick]).max()
        xs_slip = np.abs(x[slipping]).min() if slipping.any() else float("nan")
        xa_in = np.abs(x[inside]).max()
        xa_out = np.abs(x[~inside & (np.abs(x) > xa_in)]).min()
        q_an = analytical_shear(x, a_hertz, c_an, p0, args.mu)
        p_an = p0 * np.sqrt(np.clip(1.0 - (x / a_hertz) ** 2, 0.0, None))
        out.update({
            "stick_ratio": c_fit / a_fit,
            "stick_ratio_analytical": ratio_analytical,
            "stick_ratio_error": c_fit / a_fit / ratio_analytical - 1.0,
            "stick_ratio_bracket": [xs_stick / xa_out, xs_slip / xa_in],
            "half_width": a_fit,
            "half_width_hertz": a_hertz,
            "stick_half_width": c_fit,
            "peak_pressure": p0_fit,
            "peak_pressure_hertz": p0,
            # Over the nodes in |x| <= a_Hertz: max and rms differences.
            "pressure_error": float(np.max(np.abs(p - p_an)[np.abs(x) <= a_hertz]) / p0),
            "pressure_error_rms": rms((p - p_an)[np.abs(x) <= a_hertz]) / p0,
            "shear_traction_error": float(np.max(np.abs(t - q_an)[np.abs(x) <= a_hertz]) / (args.mu * p0)),
            "shear_traction_error_rms": rms((t - q_an)[np.abs(x) <= a_hertz]) / (args.mu * p0),
            "profile": {"x": x, "pressure": p, "shear": t, "regime": regime,
                        "shear_analytical": q_an, "pressure_analytical": p_an},
        })
        log(f"  {model.cells} cells: c/a = {c_fit / a_fit:.5f} (analytical {ratio_analytical:.5f}, "
            f"error {100 * out['stick_ratio_error']:+.2f} %), a/a_Hertz = {a_fit / a_hertz:.5f}, "
            f"{elapsed:.1f} s")
    return out


def plot(results, directory):
    plt = pyplot()
    if plt is None:
        return
    os.makedirs(directory, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    fine = results[-1]
    prof = fine["profile"]
    a = fine["half_width_hertz"]
    p0 = fine["peak_pressure_hertz"]
    for r in results:
        pr = r["profile"]
        ax.plot(np.array(pr["x"]) / a, np.array(pr["shear"]) / p0, ".", ms=3,
                label=f"q, FE {r['cells']} cells")
    xx = np.linspace(-1.2, 1.2, 801)
    mu = fine["mu"]
    ax.plot(xx, analytical_shear(xx * a, a, fine["stick_ratio_analytical"] * a, p0, mu) / p0, "k-", lw=1,
            label="q, Cattaneo-Mindlin")
    ax.plot(np.array(prof["x"]) / a, mu * np.array(prof["pressure"]) / p0, "C3--", lw=1,
            label=r"$\mu p$, FE")
    ax.set_xlabel("x / a")
    ax.set_ylabel("traction / p0")
    ax.set_xlim(-1.2, 1.2)
    ax.legend(fontsize=8)
    ax.set_title(f"Cattaneo-Mindlin: Q/(mu P) = {fine['tangential_load'] / (mu * fine['normal_load']):.3f}")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "cattaneo_mindlin_shear.svg"))
    fig2, ax2 = plt.subplots(figsize=(5.0, 3.6))
    h = [r["node_spacing"] / r["half_width_hertz"] for r in results]
    e = [abs(r["stick_ratio_error"]) for r in results]
    ax2.loglog(h, e, "o-")
    ax2.set_xlabel("node spacing / a")
    ax2.set_ylabel("|c/a error| (relative)")
    ax2.set_title("Mesh convergence of the stick zone")
    fig2.tight_layout()
    fig2.savefig(os.path.join(directory, "cattaneo_mindlin_convergence.svg"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--meshes", default="8,16,32",
                    help="mesh cells across the contact half-width a, one run each (default 8,16,32)")
    ap.add_argument("--mu", type=float, default=0.3)
    ap.add_argument("--young", type=float, default=70e9, help="E of the block (Pa)")
    ap.add_argument("--poisson", type=float, default=0.5,
                    help="nu of the block (0.5: Dundurs' beta = 0 against a rigid indenter)")
    ap.add_argument("--radius", type=float, default=0.01, help="indenter radius R (m)")
    ap.add_argument("--half-width", type=float, default=1e-4, help="target contact half-width a (m)")
    ap.add_argument("--size", type=float, default=20.0, help="block half-width and depth, in a")
    ap.add_argument("--ratio", type=float, default=0.5, help="target Q/(mu P)")
    ap.add_argument("--penalty", type=float, default=1e2,
                    help="normal penalty k_n, in E*/(node spacing)")
    ap.add_argument("--stick-factor", type=float, default=10.0,
                    help="the law's stick stiffness k_t, in E*/(node spacing)")
    ap.add_argument("--normal-steps", type=int, default=4)
    ap.add_argument("--tangential-steps", type=int, default=4)
    ap.add_argument("--tolerance", type=float, default=1e-10, help="Newton: relative residual")
    ap.add_argument("--depth-factor", type=float, default=2.1,
                    help="indenter depth = factor * P/E* for the target load")
    ap.add_argument("--shift-factor", type=float, default=1.05,
                    help="final shift = factor * ratio * mu P / (stick stiffness dQ/ds)")
    ap.add_argument("--compare-tangents", action="store_true",
                    help="also solve the coarsest mesh with the stick (fixed-point) and no-dF/dN Jacobians")
    ap.add_argument("--friction-in-normal-loading", action="store_true",
                    help="step the law during the normal loading too (shear locked in by the finite block)")
    ap.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    ap.add_argument("--plot", metavar="DIR", help="write SVG plots into DIR (needs matplotlib)")
    args = ap.parse_args()
    meshes = [int(m) for m in args.meshes.split(",")]
    results = []
    for n in meshes:
        log(f"mesh: {n} cells per half-width, Newton with the law's tangents")
        r = run(args, n)
        if COMM.rank == 0:
            r["mu"] = args.mu
        results.append(r)
    comparison = None
    if args.compare_tangents:
        comparison = {"cells_per_half_width": meshes[0], "law": results[0]["newton_iterations"]}
        for kind in ("no_dfdn", "stick"):
            log(f"mesh: {meshes[0]} cells per half-width, Jacobian '{kind}'")
            r = run(args, meshes[0], tangent=kind, max_iterations=200)
            comparison[kind] = r["newton_iterations"]
            comparison[kind + "_converged"] = r["converged"]
    if COMM.rank != 0:
        return
    fine = results[-1]
    summary = {
        "stick_ratio": fine["stick_ratio"],
        "stick_ratio_analytical": fine["stick_ratio_analytical"],
        "stick_ratio_error": fine["stick_ratio_error"],
        "normal_load": fine["normal_load"],
        "tangential_load": fine["tangential_load"],
        "mu": args.mu,
        "poisson": args.poisson,
        "newton_iterations": fine["newton_iterations"],
        "converged": all(r["converged"] for r in results),
        "cells": fine["cells"],
        "ranks": COMM.size,
        "meshes": [{k: v for k, v in r.items() if k not in ("profile", "residual_history")}
                   for r in results],
        "residual_history": fine["residual_history"],
    }
    if comparison:
        summary["iterations_by_jacobian"] = comparison
    if args.plot:
        plot(results, args.plot)
    if args.json:
        print(dump_json(summary))


if __name__ == "__main__":
    main()
