"""Quick start (README): a JKR sphere from Python, one loading step and the
pull-off. Run: pip install ./bindings/python; python examples/python/quick_start.py"""

import math
import sys

import numpy as np

import asperity

# R = 1 µm, E* = 1 GPa, w = 0.05 J/m² (SI units throughout).
law = asperity.Jkr(radius=1e-6, e_star=1e9, work_of_adhesion=0.05)
r = law.eval(2e-9)  # a fresh contact; r.state is its history after the step
print(f"delta = 2 nm: force {r.force:.4e} N, contact radius {r.contact_radius:.4e} m")
p = law.pull_off_force("load")
print(f"pull-off (load control) {p:.6e} N = {p / (math.pi * 0.05e-6):.6f} pi w R")
# Many contacts at once: numpy arrays in and out, one state per contact.
many = law.eval(np.linspace(0.0, 4e-9, 5))
print("forces at 0..4 nm:", np.array2string(many.force, precision=4))
# A bad argument is refused with a message naming it.
try:
    asperity.Jkr(-1e-6, 1e9, 0.05)
    sys.exit(1)
except asperity.Error as e:
    print(f"negative radius: {e}")
sys.exit(0 if abs(p / (math.pi * 0.05e-6) + 1.5) < 1e-9 else 1)
