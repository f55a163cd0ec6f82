#!/usr/bin/env python3
"""Speed of the asperity Python package, measured side by side (issue 31 §4).

Three measurements, each printed as a Markdown table (BENCHMARKS.md §10):

1. ``law.eval(array)`` per element on 10⁴–10⁶ overlaps against the Rust batch
   (``asperity::contact::eval_batch`` into preallocated buffers, timed inside
   the same extension and build by ``asperity._asperity._rust_eval_batch_seconds``).
   Two Python columns: fresh output arrays (every call allocates its force,
   radius, stiffness and state arrays) and ``out=`` (a previous response's
   arrays rewritten, as a time-stepping host does). Bar: ≤ 1.5× the Rust batch.
2. The cost of one scalar call ``law.eval(float)`` (Python call, argument
   check, Rust evaluation, response object). Bar: ≤ 1 µs.
3. A Maugis–Dugdale load–approach curve of 10⁴ points against the reference
   solution of the Adhesion package (ContactEngineering,
   ``Adhesion.ReferenceSolutions.MaugisDugdale.load_and_displacement``, which
   solves Maugis' equation for m by brentq point by point), in the same
   process and at equal values. The curve: asperity's
   ``MaugisDugdale.contact_point(s)`` on an array of 10⁴ branch parameters
   (closed form per point), Adhesion's at the same 10⁴ contact radii; the
   loads and approaches must agree. Bar: ≥ 100× faster. A second row times
   ``MaugisDugdale.eval`` at Adhesion's 10⁴ approaches (the displacement-
   controlled law, which solves for the branch point at each δ).

Every figure is the fastest of ``--repeats`` runs (the machine is shared).

Run (the Adhesion package only in the benchmark's environment)::

    python3 -m venv ~/.cache/asperity/bench-venv
    ~/.cache/asperity/bench-venv/bin/pip install ./bindings/python Adhesion
    ~/.cache/asperity/bench-venv/bin/python benches/python/bench.py
"""

import argparse
import datetime
import os
import platform
import time

import numpy as np

import asperity
from asperity import _asperity as native


def best(fn, repeats):
    t = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        t = min(t, time.perf_counter() - t0)
    return t


def machine():
    cpu = platform.processor() or "?"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return (
        f"{cpu}, {os.cpu_count()} cores, load average {load:.2f} at start; "
        f"Python {platform.python_version()}, numpy {np.__version__}, asperity {asperity.__version__}; "
        f"{datetime.date.today().isoformat()}"
    )


R, E, W = 10e-6, 1e9, 0.05


def laws():
    md = asperity.MaugisDugdale.from_maugis_parameter(R, E, W, 1.0)
    jkr = asperity.Jkr(R, E, W)
    return [
        # (name, law, overlaps as in benches/laws.rs: the in-contact branch)
        ("Hertz", asperity.Hertz(10e-6, 100e9), lambda n: np.geomspace(1e-10, 1e-8, n)),
        ("DMT", asperity.Dmt(10e-6, 100e9, 0.1), lambda n: np.geomspace(1e-10, 1e-8, n)),
        ("JKR", jkr, lambda n: np.linspace(0.9 * jkr.critical_delta, -4 * jkr.critical_delta, n)),
        ("Maugis-Dugdale λ = 1", md, lambda n: np.linspace(-1.0, 4.0, n) * md.length_scale()),
    ]


def arrays(repeats, sizes):
    rows = []
    # Warm-up: one call of every size first, so that the allocator has
    # served (and taken back) arrays of these sizes before the timing, as in
    # a running session; the first large allocations of a process are
    # page-faulted in fresh from the kernel.
    for _, law, overlaps in laws():
        for n in sizes:
            law.eval(np.ascontiguousarray(overlaps(n)))
    for name, law, overlaps in laws():
        for n in sizes:
            if name.startswith("Maugis") and n > 100_000:
                continue  # 0.7 µs a point: 10⁵ is already a 70 ms call
            d = np.ascontiguousarray(overlaps(n))
            # Hysteretic laws step from the states they return (as the Rust bench).
            state = law.eval(d).state
            out = law.eval(d, state=state)
            t_fresh = best(lambda: law.eval(d, state=state), repeats)
            t_out = best(lambda: law.eval(d, state=state, out=out), repeats)
            t_rust = native._rust_eval_batch_seconds(law, d, repeats, True, state)
            rows.append((name, n, t_rust / n * 1e9, t_fresh / n * 1e9, t_out / n * 1e9))
    return rows


def scalar(repeats, calls=200_000):
    rows = []
    for name, law, overlaps in laws():
        x = float(overlaps(3)[1])
        f = law.eval

        def loop():
            for _ in range(calls):
                f(x)

        t = best(loop, max(1, repeats // 2))
        rows.append((name, t / calls * 1e9))
    return rows


def rel(x, ref, unit):
    """Largest |x - ref| relative to max(|ref|, unit)."""
    return float(np.max(np.abs(x - ref) / np.maximum(np.abs(ref), unit)))


def maugis_dugdale_vs_adhesion(repeats, points=10_000):
    try:
        from Adhesion.ReferenceSolutions import MaugisDugdale as ref
    except ModuleNotFoundError:
        return None
    lam = 1.0
    md = asperity.MaugisDugdale.from_maugis_parameter(R, E, W, lam)
    sigma0 = md.cohesive_stress
    scale = np.pi * W * R
    rows = []
    # The curve by its parameter s = √(m² - 1), m = c/a: the contact branch
    # a displacement-controlled test follows, from deep contact (s → 0,
    # Ā ≈ 5) to the jump-out point.
    jo = md.jump_out_point()
    s_hi = np.sqrt((jo["c_bar"] / jo["a_bar"]) ** 2 - 1.0)
    # (The jump-out point itself is left out: there eval separates or not
    # on the rounding of δ.)
    s = np.geomspace(0.05, s_hi, points + 1)[:-1]
    curve = md.contact_point(s)
    t_asp = best(lambda: md.contact_point(s), repeats)
    a = curve["contact_radius"]
    t_ref = best(lambda: ref.load_and_displacement(a, R, E, W, sigma0), max(1, repeats // 3))
    p_ref, d_ref = ref.load_and_displacement(a, R, E, W, sigma0)
    rows.append((
        "curve: `contact_point(s)` at 10⁴ s; Adhesion at the same a",
        points, t_ref, t_asp,
        rel(curve["force"], p_ref, scale),
        rel(curve["delta"], d_ref, md.length_scale()),
    ))
    # The displacement-controlled law at Adhesion's approaches, on the contact
    # branch (states of a deep contact).
    d_ref = np.ascontiguousarray(d_ref)
    deep = md.eval(2.0 * float(np.abs(d_ref).max()))
    states = asperity.ContactState.from_arrays(
        np.full(points, deep.state.contact_radius),
        np.full(points, deep.state.cohesive_radius),
        [deep.state.in_contact] * points,
        [deep.state.branch] * points,
    )
    t_eval = best(lambda: md.eval(d_ref, state=states), repeats)
    r = md.eval(d_ref, state=states)
    rows.append((
        "law: `eval(delta)` at Adhesion's 10⁴ δ",
        points, t_ref, t_eval,
        rel(r.force, p_ref, scale),
        rel(r.contact_radius, a, md.radius_scale()),
    ))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=9)
    ap.add_argument("--sizes", type=int, nargs="*", default=[10_000, 100_000, 1_000_000])
    args = ap.parse_args()
    print(f"Machine: {machine()}\n")

    print("### Array eval, ns per element (fastest of", args.repeats, "calls)\n")
    print("| law | n | Rust batch | Python `eval` (fresh arrays) | ratio | Python `eval(out=)` | ratio |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, n, tr, tf, to in arrays(args.repeats, args.sizes):
        print(f"| {name} | {n:.0e} | {tr:.2f} | {tf:.2f} | {tf / tr:.2f} | {to:.2f} | {to / tr:.2f} |")

    print("\n### One scalar call `law.eval(x)`, ns\n")
    print("| law | ns per call |")
    print("|---|---:|")
    for name, t in scalar(args.repeats):
        print(f"| {name} | {t:.0f} |")

    print("\n### Maugis-Dugdale curve against Adhesion\n")
    res = maugis_dugdale_vs_adhesion(args.repeats)
    if res is None:
        print("SKIPPED: the Adhesion package is not installed (pip install Adhesion in this environment)")
        return
    print("Differences: largest |asperity - Adhesion| / max(|Adhesion|, unit), units πwR, the")
    print("Maugis-Dugdale overlap and radius scales; 'other' is δ for the curve, a for eval.\n")
    print("| asperity call | points | Adhesion `load_and_displacement` | asperity | speed-up | force difference | other difference |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for what, points, t_ref, t_asp, fdev, odev in res:
        print(f"| {what} | {points} | {t_ref * 1e3:.1f} ms | {t_asp * 1e3:.3f} ms | {t_ref / t_asp:.0f}× | {fdev:.1e} | {odev:.1e} |")


if __name__ == "__main__":
    main()
