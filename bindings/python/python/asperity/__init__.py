"""asperity: physics of dry contact between rough surfaces.

Single-asperity normal laws (Hertz, DMT, JKR, Maugis–Dugdale, Kendall, flat and
power-law punches, Derjaguin), the numerical Lennard-Jones sphere, tabulated
laws, the fidelity advisor, Borodich rescaling and indentation analysis,
surface profiles and maps, statistical multi-asperity models and friction
(energy-dissipation mechanisms, the hierarchical slider, scenes, the
per-increment friction laws and the chapter-5 dynamic models).

SI units throughout: m, N, Pa, J, J/m². Arrays in and out are numpy float64.
Every error is :class:`asperity.Error` (a subclass of ValueError) whose
message names the argument and its bound.

The Rust crate's documentation (``cargo doc``) gives every formula and its
source; the Python names are the Rust API's.
"""

from ._asperity import *  # noqa: F401,F403
from ._asperity import Error, __version__  # noqa: F401

__all__ = [name for name in dir() if not name.startswith("_")]
