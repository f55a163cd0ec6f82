#!/usr/bin/env python3
"""Asserts the figures of the FEniCSx models (issue 32) from the JSON that
run.sh writes: check.py DIR. Prints a table; exits 1 on a failed check."""

from __future__ import annotations

import json
import os
import sys

failures = []


def check(ok: bool, what: str):
    print(("ok    " if ok else "FAIL  ") + what)
    if not ok:
        failures.append(what)


def close(a: float, b: float, rel: float) -> bool:
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def load(directory, name):
    with open(os.path.join(directory, name + ".json")) as f:
        return json.load(f)


def main():
    d = sys.argv[1]
    cm1, cm2 = load(d, "cattaneo_mindlin_1"), load(d, "cattaneo_mindlin_2")
    print("Cattaneo-Mindlin (c/a against sqrt(1 - Q/(mu P))):")
    print(f"  {'cells':>7} {'nodes':>6} {'c/a':>9} {'analytical':>10} {'error':>8} {'bracket':>17} "
          f"{'q rms err':>9} {'Newton solves per step'}")
    for m in cm1["meshes"]:
        lo, hi = m["stick_ratio_bracket"]
        print(f"  {m['cells']:>7} {m['contact_nodes_total']:>6} {m['stick_ratio']:>9.5f} "
              f"{m['stick_ratio_analytical']:>10.5f} {100 * m['stick_ratio_error']:>+7.2f}% "
              f"[{lo:.4f}, {hi:.4f}] {100 * m['shear_traction_error_rms']:>8.2f}% {m['newton_iterations']}")
    fine = cm1["meshes"][-1]
    check(len(cm1["meshes"]) >= 3, "at least three meshes")
    check(abs(cm1["stick_ratio"] / cm1["stick_ratio_analytical"] - 1.0) <= 0.03,
          f"c/a within 3 % at the finest mesh ({100 * fine['stick_ratio_error']:+.2f} %)")
    check(0.0 < cm1["tangential_load"] < cm1["mu"] * cm1["normal_load"], "0 < Q < mu P")
    widths = [m["stick_ratio_bracket"][1] - m["stick_ratio_bracket"][0] for m in cm1["meshes"]]
    check(all(b < a for a, b in zip(widths, widths[1:])),
          f"the node bracket of c/a narrows with refinement ({', '.join(f'{w:.4f}' for w in widths)})")
    lo, hi = fine["stick_ratio_bracket"]
    spacing = fine["node_spacing"] / fine["half_width_hertz"]
    check(lo - spacing <= fine["stick_ratio_analytical"] <= hi + spacing,
          "the analytical c/a lies in the finest bracket (within one node spacing)")
    errs = [m["shear_traction_error_rms"] for m in cm1["meshes"]]
    check(errs[-1] < errs[0], f"rms shear traction error falls with refinement ({errs[0]:.4f} -> {errs[-1]:.4f})")
    check(errs[-1] < 0.02, "rms shear traction error below 2 % of mu p0 at the finest mesh")
    for m in cm1["meshes"]:
        check(m["converged"] and max(m["newton_iterations"]) <= 8,
              f"{m['cells']} cells: every load step converged to 1e-10 in <= 8 solves")
    comp = cm1.get("iterations_by_jacobian")
    if comp:
        print("  Newton solves per load step by Jacobian "
              f"({comp['cells_per_half_width']} cells per half-width; normal steps are frictionless):")
        for k in ("law", "no_dfdn", "stick"):
            conv = comp.get(k + "_converged", True)
            print(f"    {k:>8}: {comp[k]} (total {sum(comp[k])}{'' if conv else ', NOT converged'})")
        check(sum(comp["law"]) < sum(comp["stick"]), "the law's tangents need fewer solves than the stick-stiffness update")
    check(cm2["ranks"] == 2 and cm1["ranks"] == 1, "runs on 1 and 2 ranks")
    for key in ("stick_ratio", "normal_load", "tangential_load"):
        check(close(cm1[key], cm2[key], 1e-8), f"{key}: 1 rank {cm1[key]:.12g}, 2 ranks {cm2[key]:.12g}")
    check(cm1["newton_iterations"] == cm2["newton_iterations"], "the same Newton iterations on 1 and 2 ranks")

    for law in ("homogenised", "maxwell_slip"):
        e1, e2 = load(d, f"energy_{law}_1"), load(d, f"energy_{law}_2")
        print(f"Energy balance, {law} (J/m, tangential loading-unloading-reloading):")
        print(f"  work {e1['work']:.6e} = stored change {e1['elastic_energy_change']:.6e} "
              f"+ dissipation {e1['dissipation']:.6e} + imbalance {e1['energy_imbalance']:+.3e}")
        print(f"  normal loading: {e1['normal_loading']}")
        print(f"  closed cycle: {e1['cycle']}")
        check(e1["converged"] and max(e1["newton_iterations"]) <= 8,
              f"{law}: every load step converged to 1e-10 in <= 8 solves (max {max(e1['newton_iterations'])})")
        check(e1["dissipation"] > 0 and e1["cycle"]["dissipation"] > 0, f"{law}: the cycle dissipates")
        check(abs(e1["energy_imbalance_over_dissipation"]) <= 0.01,
              f"{law}: work = stored change + dissipation within 1 % of the dissipation "
              f"({100 * e1['energy_imbalance_over_dissipation']:+.3f} %)")
        check(e1["loop_area"] > 0, f"{law}: the Q-s loop encloses a positive area (hysteresis)")
        for key in ("work", "dissipation", "elastic_energy_change"):
            check(close(e1[key], e2[key], 1e-7), f"{law} {key}: 1 rank {e1[key]:.12g}, 2 ranks {e2[key]:.12g}")
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
