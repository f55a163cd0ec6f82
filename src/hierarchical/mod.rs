//! Hierarchical models of roughness (thesis 5.4): asperities on asperities,
//! whose load–area law follows from the hierarchy rather than from a height
//! distribution.
//!
//! * [`archard`]: Archard's spheres on spheres (1957; thesis 1.6.2, 5.4.1),
//!   A = c W^a with a = 2/3, 8/9, 26/27, … (equal heights) or 4/5, 14/15,
//!   44/45, … (the finest protuberances at distributed heights): a → 1 as
//!   generations are added.
//! * [`cantor`]: the Cantor–Liu and Cantor–Borodich profiles (Liu et al.
//!   1986; Borodich and Mosolov 1991; thesis 5.4.2) pressed into a
//!   Winkler–Fuss elastic foundation (Borodich and Onishchenko) or a
//!   rigid-perfectly plastic one (Warren and Krajcinovic 1995), and the
//!   series-spring compliance of Plesha and Ni (5-13).
//! * [`schmittbuhl`]: Schmittbuhl, Vilotte and Roux's hierarchical model
//!   (1996; thesis 5.4.3): blocks N times larger per generation, each
//!   generation's law found from a Burridge–Knopoff chain of N blocks of the
//!   finer one (static friction: the mean break-away peak; kinetic: the
//!   friction work per unit slip), springs and masses rescaled as an
//!   elastic continuum of dimension 2 or 3. Coulomb friction is a fixed
//!   point; identical blocks keep a stick-slip law; a pre-stress drives
//!   μ_s towards μ_k; velocity weakening lowers both.
//!
//! Units: SI; loads W (N), areas A (m²) for Archard's three-dimensional
//! spheres; for the two-dimensional Cantor profiles loads and contact widths
//! per unit length out of the plane (N/m, m).
//!
//! # References
//!
//! * J. F. Archard, "Elastic deformation and the laws of friction", Proc.
//!   R. Soc. Lond. A 243 (1957) 190–205.
//! * F. M. Borodich, A. B. Mosolov, "Fractal contact of solids", Sov. Phys.
//!   Tech. Phys. 36 (1991) 1043–1046.
//! * F. M. Borodich, D. A. Onishchenko, "Similarity and fractality in the
//!   modelling of roughness by a multilevel profile with hierarchical
//!   structure", Int. J. Solids Struct. 36 (1999) 2585–2612.
//! * T. L. Warren, D. Krajcinovic, "Fractal models of elastic-perfectly
//!   plastic contact of rough surfaces based on the Cantor set", Int. J.
//!   Solids Struct. 32 (1995) 2907–2922.
//! * J. Schmittbuhl, J.-P. Vilotte, S. Roux, "Velocity weakening friction:
//!   a renormalization approach", J. Geophys. Res. 101(B12) (1996)
//!   27741–27764.
//! * M. E. Plesha, D. Ni, "Scaling of geological discontinuity normal load–
//!   deformation response using fractal geometry", Int. J. Numer. Anal.
//!   Meth. Geomech. 25 (2001) 741–756.

pub mod archard;
pub mod cantor;
pub mod schmittbuhl;

pub use archard::{archard_exponent, Archard, ArchardModel};
pub use cantor::{CantorContact, CantorProfile};
pub use schmittbuhl::{Generation, Schmittbuhl};
