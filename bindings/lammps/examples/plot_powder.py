#!/usr/bin/env python3
"""Plot the in.powder runs: coordination number and energy dissipated by
friction against time, one line per law.

    plot_powder.py OUT.svg log.jkr log.md log.lj

Each log is a LAMMPS log of in.powder (`-log log.jkr -var law jkr ...`).
Needs matplotlib (pip install matplotlib)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from lammps_log import thermo as rows  # noqa: E402

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit("plot_powder.py needs matplotlib: pip install matplotlib")

LABELS = {"jkr": "JKR", "md": "Maugis-Dugdale, lambda = 1", "lj": "tabulated Lennard-Jones, Tabor mu = 2.0"}


def main():
    out, logs = sys.argv[1], sys.argv[2:]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for path in logs:
        law = path.rsplit(".", 1)[-1]
        r = rows(path)
        t = [1e3 * x["Step"] * 1e-8 for x in r]    # ms (timestep 10 ns)
        ax1.plot(t, [x["v_coord"] for x in r], label=LABELS.get(law, law))
        ax2.plot(t, [1e9 * x["v_dissipated"] for x in r], label=LABELS.get(law, law))
    for ax in (ax1, ax2):
        ax.axvline(0.2, color="grey", lw=0.8, ls=":")
    ax1.set_ylabel("contacts per powder sphere")
    ax1.text(0.05, 0.95, "pour", transform=ax1.transAxes, va="top")
    ax1.text(0.58, 0.45, "compaction by the lid", transform=ax1.transAxes, va="top")
    ax2.set_ylabel("dissipated by friction (nJ)")
    ax2.set_xlabel("time (ms)")
    ax1.legend(loc="lower right", fontsize=8)
    fig.suptitle("pair_style asperity: 600 adhesive spheres of 10 um (in.powder)")
    fig.tight_layout()
    fig.savefig(out)


if __name__ == "__main__":
    main()
