#!/usr/bin/env python3
"""asperity's Oliver–Pharr chain against the micromechanics package (issue 34 §2).

A benchmark script, not a test: it makes no assertions. For each measured
curve of ``../shared/data/indentation`` (README there; the CSVs are
conversions of micromechanics' own example data) it runs

* ``asperity indent FILE --json`` (the CLI, release build), and
* micromechanics 1.3.5 (``micromechanics.indentation.Indentation``): the
  same time, depth and load arrays from the CSV (converted to its units, µm,
  mN, s) handed to ``setRawData`` after the duplicate-time clean-up its file
  readers apply (``_removeTooCloseInputPoints``), then its own
  ``identifyLoadHoldUnload`` (segments from the force rate),
  ``stiffnessFromUnloading`` (power-law fit ``P = B(h − h_f)^m``, S at the
  start of unloading), ``OliverPharrMethod`` and ``YoungsModulus``; the same
  area-function coefficients through ``Tip([C0, C1, C2])``.

Both run with the same settings: ε = 0.75, β = 1 (micromechanics has no β,
so asperity gets ``--beta 1``), diamond tip 1140 GPa / 0.07 (micromechanics'
value; asperity's default is 1141 GPa), the sample's Poisson ratio of the
data README, and micromechanics' vendor unloading window (Agilent
0.5–0.999, Hysitron 0.4–0.95 of the peak load) as asperity's
``--fit-window``. A third column repeats micromechanics' fit on asperity's
unloading segment (the file's labels), which separates the segment
detection from the fit, and a row runs micromechanics' fit (scipy
``curve_fit``, stopped at ``ftol = 1e-4``) to convergence. The last rows
repeat S and E with asperity's window 0.2–0.98 in both, and compare each
package with its own defaults (asperity: β = 1.034, window 0.2–0.98,
1141 GPa).

For each file it prints a Markdown table: stage, asperity, micromechanics,
relative difference (asperity − micromechanics)/micromechanics. A file whose
stage fails in either package is skipped with the reason.

Setup (micromechanics only in this script's environment, outside the tree)::

    python3 -m venv ~/.cache/asperity/micro-venv
    ~/.cache/asperity/micro-venv/bin/pip install micromechanics==1.3.5
    cargo build --release --features cli

Run (from the repository root)::

    ~/.cache/asperity/micro-venv/bin/python benches/python/micromechanics_compare.py
    # --asperity PATH (default $CARGO_TARGET_DIR/release/asperity, else
    # target/release/asperity), --data DIR (default ../shared/data/indentation)

BENCHMARKS.md "Indentation against micromechanics" holds the current tables.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import math
import os
import subprocess
import sys
from pathlib import Path

try:
    import numpy as np
except ImportError:  # reported by main()
    np = None

ROOT = Path(__file__).resolve().parents[2]

# name, file, micromechanics vendor, area coefficients (NanoSuite: h_c in nm,
# A in nm²), sample Poisson ratio -- all from the data README.
FILES = [
    (
        "fused silica XP",
        "fused_silica_berkovich_XP_test001.csv",
        "Agilent",
        [24.6954, 395.7700812, -16.13158277],
        0.18,
    ),
    (
        "fused silica calibration",
        "fused_silica_berkovich_agilent_calibration_test001.csv",
        "Agilent",
        [27.3136, 152.6988585, -494.1823171],
        0.18,
    ),
    (
        "NiAl",
        "NiAl_berkovich_agilent_test001.csv",
        "Agilent",
        [27.3136, 152.6988585, -494.1823171],
        0.3,
    ),
    # The indenter is not documented (data README): an ideal Berkovich
    # 24.5 h_c² is assumed, the same for both packages.
    ("steel Hysitron", "steel_hysitron_RobinSteel0000LC.csv", "Hysitron", [24.5], 0.3),
]

EPSILON = 0.75
TIP_MODULUS_GPA = 1140.0
TIP_POISSON = 0.07


class Skip(Exception):
    """A stage failed: the file is skipped with this reason."""


def read_csv(path: Path):
    """time (s), depth (m), load (N) and the segment labels of a data file."""
    rows = [line for line in path.open() if not line.startswith("#")]
    d = np.genfromtxt(rows, delimiter=",", names=True, dtype=None, encoding=None)
    return (
        d["time_s"].astype(float),
        d["depth_m"].astype(float),
        d["load_N"].astype(float),
        np.asarray(d["segment"]).astype(str),
    )


def run_asperity(exe: Path, csv: Path, area, nu, extra):
    cmd = [
        str(exe),
        "indent",
        str(csv),
        "--indenter",
        "berkovich",
        "--area",
        ",".join(repr(c) for c in area),
        "--nu-sample",
        repr(nu),
        "--json",
        *extra,
    ]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise Skip(f"asperity indent failed: {r.stderr.strip()[:200]}")
    j = json.loads(r.stdout)
    if not j.get("unloading"):
        raise Skip("asperity: no Oliver–Pharr evaluation of the unloading branch")
    return j


def micromechanics_indentation(vendor_name: str, area, nu, window=None):
    """An empty Indentation with the vendor's defaults and the tip's area
    (and the unloading window (low, high) when given)."""
    from micromechanics.indentation import Indentation, Tip
    from micromechanics.indentation.definitions import Vendor

    # A file name that does not exist gives an object without data (the
    # constructor prints an error for it, silenced here).
    with contextlib.redirect_stdout(io.StringIO()):
        ind = Indentation(
            "/nonexistent/micromechanics_compare.xls",
            nuMat=nu,
            tip=Tip(list(area)),
            model={"beta": EPSILON, "modulusTip": TIP_MODULUS_GPA, "nuTip": TIP_POISSON}
            | ({} if window is None else {"unloadPMin": window[0], "unloadPMax": window[1]}),
        )
    ind.vendor = Vendor[vendor_name]
    ind.fillVendorDefaults()
    ind.output["verbose"] = 0
    return ind


def run_micromechanics(ind, t, h_m, p_n, ilhu=None):
    """micromechanics' chain on the arrays; `ilhu` replaces its segments.

    Returns a dict of the stages in SI units and the CSV row of the start
    of unloading."""
    h, p = h_m * 1e6, p_n * 1e3  # µm, mN
    # The clean-up micromechanics' readers apply: drops the first point and
    # points closer in time than 1e-3 of the 80th percentile step.
    keep = np.arange(len(t))
    if hasattr(ind, "_removeTooCloseInputPoints"):
        h, p, tt, idx = ind._removeTooCloseInputPoints(h, p, t, keep.astype(float))
        keep = np.asarray(idx, dtype=int)
    else:
        tt = t
    ind.setRawData(h, p, tt)
    e_analyse = None
    if ilhu is None:
        # Its whole chain in one call, to check the stage calls below.
        with contextlib.redirect_stdout(io.StringIO()):
            ind.analyse()
        e_analyse = ind.metaUser.get("E_GPa", [None])[0]
        ind.setRawData(h, p, tt)
    with contextlib.redirect_stdout(io.StringIO()) as out:
        if ilhu is None:
            ind.identifyLoadHoldUnload()
        else:
            # CSV rows -> rows of the cleaned arrays.
            ind.iLHU = [[int(np.searchsorted(keep, i)) for i in ilhu]]
        if len(ind.iLHU) != 1 or not ind.iLHU[0]:
            raise Skip(
                f"micromechanics found {len(ind.iLHU)} load-hold-unload cycles "
                f"({out.getvalue().strip()[:120] or 'no message'})"
            )
        s, valid, mask, opt, ok = ind.stiffnessFromUnloading(ind.p, ind.h)
    if s is None or opt is None:
        raise Skip(f"micromechanics stiffnessFromUnloading failed ({out.getvalue().strip()[:120]})")
    if not ok[0]:
        raise Skip("micromechanics: power-law fit failed, it fell back to a line")
    _, load_end, unload_start, _ = ind.iLHU[0]
    s = np.asarray(s, dtype=float)
    er, a, hc = ind.OliverPharrMethod(s, ind.p[valid], ind.h[valid])
    e = float(np.asarray(ind.YoungsModulus(er)).ravel()[0])
    b, hf, m = (float(x) for x in opt)
    pmax = float(ind.p[unload_start])
    resid = ind.p[mask] - ind.unloadingPowerFunc(ind.h[mask], b, hf, m)
    # The same fit run to convergence (micromechanics stops at ftol = 1e-4).
    from scipy.optimize import curve_fit

    try:
        conv, _ = curve_fit(
            ind.unloadingPowerFunc, ind.h[mask], ind.p[mask], p0=opt, ftol=1e-14, xtol=1e-14, maxfev=100000
        )
        m_conv = float(conv[2])
    except (RuntimeError, ValueError):
        m_conv = None
    return {
        "unload_row": int(keep[unload_start]),
        "window_ref_row": int(keep[load_end]),
        "pmax": pmax * 1e-3,
        "hmax": float(ind.h[unload_start]) * 1e-6,
        "window": (float(ind.model["unloadPMin"]), float(ind.model["unloadPMax"])),
        "n": int(np.count_nonzero(mask)),
        "m": m,
        "hf": hf * 1e-6,
        "B": b,  # mN/µm^m
        "m_conv": m_conv,
        "sse": float(np.sum(resid**2)) * 1e-6,  # N²
        "S": float(s[0]) * 1e3,  # mN/µm = 1e3 N/m
        "hc": float(np.ravel(hc)[0]) * 1e-6,
        "A": float(np.ravel(a)[0]) * 1e-12,
        "Er": float(np.ravel(er)[0]) * 1e9,
        "E": e * 1e9,
        "E_analyse": None if e_analyse is None else float(e_analyse) * 1e9,
        "H": pmax / float(np.ravel(a)[0]) * 1e9,
    }


def asperity_stages(j):
    u = j["unloading"]
    f = u["fit"]
    seg = j["segmentation"]["unloading"]
    m = f["exponent"]
    return {
        "unload_row": None,  # filled by the caller: the row of (h_max, P_max)
        "seg": seg,
        "pmax": u["peak_load"],
        "hmax": u["peak_depth"],
        "window": tuple(f["window"]),
        "n": f["n_points"],
        "m": m,
        "hf": f["final_depth"],
        # α in N/m^m -> mN/µm^m, micromechanics' B.
        "B": f["prefactor"] * 1e3 / 1e6**m,
        "sse": float(np.sum(np.square(f["residuals"]))),
        "m_conv": m,
        "S": u["stiffness"],
        "hc": u["contact_depth"],
        "A": u["contact_area"],
        "Er": u["reduced_modulus"],
        "E": j["sample_modulus"],
        "H": u["hardness"],
    }


def rel(a, b):
    if a is None or b is None or not (math.isfinite(a) and math.isfinite(b)) or b == 0:
        return "—"
    r = (a - b) / b * 100
    return "0.00 %" if abs(r) < 0.005 else f"{r:+.2f} %"


ROWS = [
    # key, label, scale, format
    ("unload_row", "start of unloading (CSV row)", 1, "{:.0f}"),
    ("pmax", "P_max at that row (mN)", 1e3, "{:.3f}"),
    ("hmax", "h_max at that row (nm)", 1e9, "{:.2f}"),
    ("window", "fit window (fraction of P)", 1, None),
    ("n", "points fitted", 1, "{:.0f}"),
    ("m", "exponent m", 1, "{:.6f}"),
    ("m_conv", "m, micromechanics' fit run to convergence (ftol 1e-14)", 1, "{:.6f}"),
    ("hf", "h_f (nm)", 1e9, "{:.2f}"),
    ("B", "B of P = B(h − h_f)^m (mN/µm^m)", 1, "{:.4g}"),
    ("sse", "sum of squared residuals (mN²)", 1e6, "{:.6g}"),
    ("S", "S = dP/dh at h_max (kN/m)", 1e-3, "{:.4f}"),
    ("hc", "h_c (nm)", 1e9, "{:.2f}"),
    ("A", "A(h_c) (µm²)", 1e12, "{:.4f}"),
    ("Er", "E_r (GPa)", 1e-9, "{:.3f}"),
    ("E", "E sample (GPa)", 1e-9, "{:.3f}"),
    ("H", "H (GPa)", 1e-9, "{:.4f}"),
    ("E_analyse", "E sample, micromechanics' own analyse() (GPa)", 1e-9, "{:.3f}"),
]


def cell(key, scale, fmt, d):
    v = d.get(key)
    if v is None:
        return "—"
    if key == "window":
        return f"{v[0]:g}–{v[1]:g}"
    return fmt.format(v * scale)


def table(name, ours, theirs, theirs_same_seg, wide, defaults):
    lines = [
        f"**{name}**",
        "",
        "| stage | asperity | micromechanics | rel. diff. | micromechanics on asperity's segment | rel. diff. |",
        "|---|---|---|---|---|---|",
    ]
    for key, label, scale, fmt in ROWS:
        a = cell(key, scale, fmt, ours)
        b = cell(key, scale, fmt, theirs)
        c = cell(key, scale, fmt, theirs_same_seg)
        numeric = key not in ("window", "unload_row")
        ra = rel(ours.get(key), theirs.get(key)) if numeric else "—"
        rc = rel(ours.get(key), theirs_same_seg.get(key)) if numeric else "—"
        lines.append(f"| {label} | {a} | {b} | {ra} | {c} | {rc} |")
    (aw, mw), (ad, md) = wide, defaults
    for label, key, scale, x, y in (
        ("S, window 0.2–0.98 in both (kN/m)", "S", 1e-3, aw, mw),
        ("E sample, window 0.2–0.98 in both (GPa)", "E", 1e-9, aw, mw),
        ("E sample, each with its own defaults (GPa)", "E", 1e-9, ad, md),
        ("H, each with its own defaults (GPa)", "H", 1e-9, ad, md),
    ):
        lines.append(f"| {label} | {x[key] * scale:.3f} | {y[key] * scale:.3f} | {rel(x[key], y[key])} | | |")
    return "\n".join(lines)


def summary(results):
    """Two compact tables over all files (BENCHMARKS.md)."""
    out = [
        "Same settings (ε 0.75, β 1, tip 1140 GPa / 0.07, micromechanics' window); "
        "a / mm = asperity / micromechanics, Δ = (a − mm)/mm:",
        "",
        "| file | window | unloading from row a / mm | m a / mm | S (kN/m) a / mm | E (GPa) a / mm | ΔE | "
        "H (GPa) a / mm | ΔH | ΔE, mm on a's segment | m, mm on a's segment converged |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, (a, m, ms, _w, _d) in results:
        out.append(
            f"| {name} | {a['window'][0]:g}–{a['window'][1]:g} | {a['unload_row']} / {m['unload_row']} "
            f"| {a['m']:.4f} / {m['m']:.4f} | {a['S'] * 1e-3:.2f} / {m['S'] * 1e-3:.2f} "
            f"| {a['E'] * 1e-9:.2f} / {m['E'] * 1e-9:.2f} | {rel(a['E'], m['E'])} "
            f"| {a['H'] * 1e-9:.3f} / {m['H'] * 1e-9:.3f} | {rel(a['H'], m['H'])} "
            f"| {rel(a['E'], ms['E'])} | {ms['m_conv']:.4f} |"
        )
    out += [
        "",
        "| file | E (GPa), window 0.2–0.98 in both, a / mm | ΔE | E (GPa), own defaults, a / mm | ΔE | "
        "H (GPa), own defaults, a / mm | ΔH |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, (_a, _m, _ms, (aw, mw), (ad, md)) in results:
        out.append(
            f"| {name} | {aw['E'] * 1e-9:.2f} / {mw['E'] * 1e-9:.2f} | {rel(aw['E'], mw['E'])} "
            f"| {ad['E'] * 1e-9:.2f} / {md['E'] * 1e-9:.2f} | {rel(ad['E'], md['E'])} "
            f"| {ad['H'] * 1e-9:.3f} / {md['H'] * 1e-9:.3f} | {rel(ad['H'], md['H'])} |"
        )
    return "\n".join(out)


def compare(exe: Path, data: Path, entry):
    name, fname, vendor, area, nu = entry
    csv = data / fname
    if not csv.exists():
        raise Skip(f"{csv} is absent")
    t, h, p, _labels = read_csv(csv)
    # micromechanics with its own segments, then on asperity's (the labels).
    ind = micromechanics_indentation(vendor, area, nu)
    window = (float(ind.model["unloadPMin"]), float(ind.model["unloadPMax"]))
    theirs = run_micromechanics(ind, t, h, p)
    aligned = [
        "--beta",
        "1",
        "--epsilon",
        repr(EPSILON),
        "--tip-modulus",
        repr(TIP_MODULUS_GPA * 1e9),
        "--tip-poisson",
        repr(TIP_POISSON),
        "--fit-window",
        f"{window[0]!r},{window[1]!r}",
    ]
    j = run_asperity(exe, csv, area, nu, aligned)
    ours = asperity_stages(j)
    u0, u1 = ours["seg"]
    # The row asperity starts unloading from: the one with its (h_max,
    # P_max) (the end of the hold, src/indentation/branches.rs).
    rows = np.flatnonzero((h == ours["hmax"]) & (p == ours["pmax"]))
    if len(rows) == 0:
        raise Skip("asperity's (h_max, P_max) is not a row of the file")
    start = int(rows[0])
    ours["unload_row"] = start
    # Its window is a fraction of the load at the end of loading (loadEnd);
    # loadEnd = the start of unloading makes it asperity's P_max.
    ind2 = micromechanics_indentation(vendor, area, nu)
    same_seg = run_micromechanics(ind2, t, h, p, ilhu=[0, start, start, u1 - 1])
    # Each with its own defaults: asperity's (β 1.034, window 0.2–0.98,
    # 1141 GPa) against micromechanics' (the run above).
    jd = run_asperity(exe, csv, area, nu, [])
    defaults = (asperity_stages(jd), theirs)
    # asperity's default window 0.2–0.98 in both, the other settings aligned.
    wide_args = aligned[:-1] + ["0.2,0.98"]
    ind3 = micromechanics_indentation(vendor, area, nu, window=(0.2, 0.98))
    wide = (asperity_stages(run_asperity(exe, csv, area, nu, wide_args)), run_micromechanics(ind3, t, h, p))
    return ours, theirs, same_seg, wide, defaults


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    ap.add_argument("--asperity", type=Path, default=target / "release" / "asperity")
    ap.add_argument("--data", type=Path, default=ROOT.parent / "shared" / "data" / "indentation")
    ap.add_argument("--summary", action="store_true", help="two compact tables over all files (BENCHMARKS.md)")
    args = ap.parse_args()
    try:
        if np is None:
            raise ImportError("numpy is missing")
        import micromechanics  # noqa: F401
    except ImportError as e:
        print(f"SKIPPED: micromechanics is not installed ({e}); see the docstring for the setup")
        return 0
    if not args.asperity.exists():
        print(f"SKIPPED: {args.asperity} not found (cargo build --release --features cli)")
        return 0
    if not args.summary:
        print(
            "Settings of both: ε = 0.75, β = 1, tip 1140 GPa / ν 0.07, micromechanics' vendor window; "
            "rel. diff. = (asperity − micromechanics)/micromechanics.\n"
        )
    results = []
    for entry in FILES:
        try:
            r = compare(args.asperity, args.data, entry)
        except Skip as e:
            print(f"**{entry[0]}**: SKIPPED: {e}\n")
            continue
        except Exception as e:  # a stage of either package broke: report, go on
            print(f"**{entry[0]}**: SKIPPED: {type(e).__name__}: {e}\n")
            continue
        results.append((entry[0], r))
        if not args.summary:
            print(table(entry[0], *r))
            print()
    if args.summary and results:
        print(summary(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
