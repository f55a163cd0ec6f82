//! Mechanical equilibrium of the micro-rods against the rigid counter-surface
//! (thesis 4.3.1, 6.2.2, 6.2.3, 6.3 and 6.4).
//!
//! # The model
//!
//! The slider's micro-asperities are `n` flat-ended rods of square
//! cross-section A = w² (thesis 6.2.1: "rods having square
//! cross-section"; the chapter-6 loads P = 0.05 σ_y A_n = 25 mN for ten
//! 13.5 µm rods only come out with A_n = 10·w², so the model is 3-D, not per
//! unit depth). Each rod is elastic–perfectly plastic (thesis 4.3.1, Figure
//! 4-3, (4-10)):
//!
//! * stiffness k_i (N/m, *Formulas*), thesis (4-10) and the input list of 6.3
//!   ("k_i = E A_i / L_i … L_i is the height of the asperity"), with E the
//!   effective rod modulus of (6-8), 1/E = 1/E₁ + 1/E₂
//!   ([`crate::material::rod_effective_modulus`]; with a rigid
//!   counter-surface E is the slider's own modulus);
//! * yield force F_y (N); past it the force stays F_y ("constant
//!   stress is assumed even if strain increases", 4.3.1).
//!
//! The rod length L_i is measured from the face of the bulk to the rod tip.
//! The thesis calls it "the height of the asperity" H_i but never says where
//! the bulk face lies; rod heights here are measured from the slider's mean
//! line (as in [`SliderGeometry`]), so the bed takes a `root_depth` d (m):
//! the bulk face lies d below the slider's mean line, and L_i = H_i + d must
//! be > 0 for every rod (for example d = the depth of the deepest valley of
//! the micro profile plus a margin). L_i follows the rod's *current* free
//! height: a rod shortened by plasticity, or lengthened by pile-up, is
//! stiffer or softer accordingly ((6-10) uses "the corresponding height of
//! each of the deformed micro-asperity").
//!
//! ## Frame and sign conventions
//!
//! Heights are vertical distances in m. The rigid counter-surface lies below
//! the slider; `counter[i]` = g_i is its height under rod i at the current
//! slider position, measured upward from its mean line (the thesis's h_i).
//! The slider's free rod heights H_i are measured from the slider's mean line
//! *toward* the counter-surface (downward). The **position** b (m) is the
//! height of the slider's mean line above the counter-surface's mean line.
//! Rod i's free tip is then at height b − H_i, and its **overlap** o_i
//! (*Formulas*) is positive when the free rod would penetrate the counter-surface (then
//! it is compressed by o_i) and negative when there is a clearance. Lowering
//! the slider (decreasing b) increases every overlap, so the total force
//! F(b) is nonincreasing in b. Forces f_i are compressive-positive, the rod
//! law of *Formulas*, which is (6-9)/(6-13) with (4-10) and the yield cap of
//! 4.3.1. Each rod has
//! two breakpoints in b: contact onset a_i = g_i + H_i (o_i = 0) and yield
//! onset y_i = a_i − F_y/k_i (o_i = F_y/k_i). Between breakpoints F is linear.
//!
//! The thesis's gap G (top of the slider to the counter-surface mean line,
//! 6.3) relates to b by G = b + d + H_B − δ_B, with H_B the bulk height and
//! δ_B = F/k_B its compression, k_B = E_B·A_B/H_B ((6-10)).
//!
//! ## Fixed gap, thesis (6-9)..(6-12)
//!
//! Equilibrium (6-9), (6-10): the bulk force k_B·δ_B equals Σ f_i.
//! Compatibility (6-11) for a rod in contact: (H_B − δ_B) + (H_i − δ_i) + h_i
//! = G, i.e. δ_i = o_i with b = b₀ + δ_B, where b₀ = G − H_B − d is the
//! position the slider's mean line would have with an undeformed bulk: the
//! **prescribed position** of [`RodBed::solve`] ([`Loading::FixedGap`]).
//! The matrix form (6-12)
//! reads, for the rods in elastic contact (unknowns δ_B, δ_1, δ_2, …):
//!
//! ```text
//! [ k_B  −k_1  −k_2  … ] [δ_B]   [ Σ_yielded F_y ]
//! [ 1     1     0    … ] [δ_1] = [ a_1 − b₀      ]
//! [ 1     0     1    … ] [δ_2]   [ a_2 − b₀      ]
//! ```
//!
//! (the thesis's right-hand sides h_i + H_i + H_B − G are our a_i − b₀; the
//! yielded rods, which the thesis's elastic system does not have, enter the
//! equilibrium row with their constant force F_y). A rigid bulk
//! (k_B = +∞, the default) gives b = b₀.
//!
//! ## Fixed load, thesis (6-13)..(6-16)
//!
//! Equilibrium (6-13), (6-14): P = Σ f_i ([`RodBed::solve`] with [`Loading::FixedLoad`],
//! [`Loading::FixedLoad`]). Compatibility (6-15) as (6-11), now with the gap
//! unknown. The bulk compression δ_B = P/k_B is known and
//! only shifts G. The matrix form (6-16), unknowns (b, δ_1, δ_2, …):
//!
//! ```text
//! [ 0   k_1  k_2  … ] [ b ]   [ P − Σ_yielded F_y ]
//! [ 1   1    0    … ] [δ_1] = [ a_1               ]
//! [ 1   0    1    … ] [δ_2]   [ a_2               ]
//! ```
//!
//! (the printed right-hand side "h_i + H_i + H_B + δ_B" is read as
//! h_i + H_i + H_B − δ_B, the only sign consistent with (6-15); in our frame
//! it is a_i = g_i + H_i because b already absorbs d + H_B − δ_B).
//!
//! The thesis solves (6-12)/(6-16) for the rods in contact. Which rods are in
//! contact, and which have yielded, is itself unknown: [`RodSolver::Dense`]
//! iterates over active sets, assembling and factoring the system with faer's
//! partial-pivoting LU each time (the reference). [`RodSolver::Sweep`] (the
//! default) uses that F(b) is nondecreasing as b falls and piecewise linear:
//! it sorts the 2n breakpoints and sweeps them from the top, which gives the
//! exact piece in O(n log n); a warm start from the previous step's position
//! walks from there to neighbouring breakpoints in O(n) per breakpoint
//! crossed (typically zero or one), falling back to the sweep after
//! [`WARM_WALK_LIMIT`] crossings. Both finish with the same exact O(n)
//! evaluation on the identified piece, so they agree to rounding.
//!
//! Defined limits (fixed load): P = 0 gives the highest position at which the
//! first rod just touches (b = max a_i, no rod in contact); P equal to the
//! capacity n·F_y gives the highest position at which every rod has yielded
//! (b = min y_i); P above the capacity has no equilibrium (the bed would
//! flow without bound) and returns [`Error::OutOfDomain`] naming `load`.
//! Where F has a plateau at exactly the prescribed load (some rods yielded,
//! no rod elastic), the highest equilibrium position is returned.
//!
//! ## Plasticity with volume conservation, thesis 6.2.3
//!
//! After the equilibrium is found, each yielded rod is shortened
//! permanently by s_i ≥ 0 (*Formulas*) so that, at the solved position, it
//! carries exactly F_y elastically: (o_i − s_i) = ε_y·(L_i − s_i).
//!
//! The removed volume A·s_i is given to rods that did not yield in the same
//! solve ("equally distributed to the closest neighbouring
//! micro-asperities which did not deform plastically", 6.2.3):
//!
//! * [`PlasticUpdate::NearestNeighbours`] (the thesis): the nearest
//!   non-yielded rod on each side gets half (all of it when only one side
//!   has one);
//! * [`PlasticUpdate::Gaussian`] (the thesis's proposed improvement, "a
//!   weighting function to define how the dislocated material will be
//!   reallocated", 6.2.3): every non-yielded rod j gets a share
//!   proportional to exp(−(x_j − x_i)²/(2ℓ²)), ℓ the given width;
//! * [`PlasticUpdate::ShortenOnly`]: no pile-up (volume not conserved).
//!
//! When no rod is left unyielded, the volume is spread uniformly over all
//! rods. Shares are computed so that they sum to A·s_i exactly; total volume
//! is conserved to rounding. The pile-up changes the free heights for the
//! *next* solve (the thesis updates the profile "every time-step"); the
//! forces reported are those of the solved equilibrium.
//!
//! ## Energies (thesis 4-15, 4-16)
//!
//! * Plastic work of the increment (4-16), U_p,i per rod (σ_y ε_p V_d).
//! * Elastic strain energy stored (4-15), U_e,i, with e_i the elastic
//!   compression after the plastic update.
//! * Released energy: for each rod, the drop between the stored energy
//!   recorded in the old state and the new one — the strain energy
//!   given back by rods that unload, for a dissipation ledger. Energy stored
//!   on loading is not dissipated. Every term is ≥ 0.
//!
//! ## Rods on an elastic substrate
//!
//! [`CoupledRodBed`] couples the rod bases through an elastic half-space of
//! contact modulus E* (Boussinesq): the base of rod i sinks by u_i
//! (*Formulas*), C_ij the displacement at the centre of square i due to a
//! unit force spread uniformly over square j ([`square_influence`]: Love's
//! closed form for near pairs, Gauss–Legendre quadrature of the Boussinesq
//! kernel for far ones). The rod forces solve the box-constrained problem
//! 0 ≤ f ≤ F_y of *Formulas*; an active-set iteration with dense LU
//! solves it, and an outer bracketed Newton iteration on b gives fixed load.
//! This replaces the rigid bulk of (6-9)..(6-16) by an elastic one that
//! couples the asperities ("the behaviour of the bulk of the body, which will
//! couple the micro-asperities together", 5.1).
//!
//! ## Multi-level sliders
//!
//! The mechanics of chapter 6 has one generation of rods standing on the
//! bulk, at different heights ("multi-level with respect to the
//! micro-asperities"). A [`RodBed`] is one such generation:
//! [`RodBed::from_geometry`] takes the finest level of a [`SliderGeometry`]
//! (the one whose tips carry the nano-asperities, the one that contacts),
//! each tip rod rooted in the bulk. Coarser levels are not put in series:
//! a parent shared by several tips would couple them, which (6-9)..(6-16) do
//! not model.
//!
//! ## Cost and memory
//!
//! [`RodSolution`] holds every per-rod buffer; after it is built once
//! ([`RodBed::solution`]) the sweep and warm-start solves do not allocate
//! (the new state's vectors are resized only when their length differs).
//! The dense reference and the coupled model allocate their matrices.
//!
//! # Formulas
//!
//! Rod $i$ (stiffness $k_i = EA/L_i$, yield force $F_y = \sigma_y A$, overlap
//! $o_i = g_i + H_i - b$):
//!
//! $$f_i = \min\bigl(k_i\max(o_i, 0),\ F_y\bigr), \qquad F(b) = \sum_i f_i(o_i), \qquad s_i = \frac{o_i - \varepsilon_y L_i}{1 - \varepsilon_y}, \quad \varepsilon_y = \frac{\sigma_y}{E},$$
//!
//! fixed gap (6-9)–(6-12): $k_B\\,\delta_B = \sum_i f_i$ with $b = b_0 + \delta_B$;
//! fixed load (6-13)–(6-16): $P = \sum_i f_i$. Energies (4-15), (4-16):
//!
//! $$U_{e,i} = \tfrac12 f_i e_i, \quad e_i = \frac{f_i}{k_i}, \qquad U_{p,i} = F_y\\, s_i, \qquad U_\mathrm{released} = \sum_i \max(0,\ U_{e,i}^\mathrm{old} - U_{e,i}^\mathrm{new}) .$$
//!
//! On an elastic substrate the base of rod $i$ sinks by
//! $u_i = \sum_j C_{ij} f_j$, with the Boussinesq kernel $1/(\pi E^\ast r)$ and
//! $(M f)_i = o_i$ for $0 < f_i < F_y$, $M = \mathrm{diag}(1/k) + C$.
//!
//! # References
//!
//! * Thesis §4.3.1 ((4-10), (4-15), (4-16)), §6.2.2–6.2.3, §6.3–6.4
//!   ((6-8)–(6-16)); REFERENCE.md §5.
//! * I. V. Kragelsky, M. N. Dobychin, V. S. Kombalov (1982), *Friction and Wear:
//!   Calculation Methods*, Pergamon Press, Oxford (rod models).
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   §3.2, [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731)
//!   (Boussinesq point load; uniformly loaded rectangle, after Love 1929).
//! * A. E. H. Love (1929), "The stress produced in a semi-infinite solid by
//!   pressure on part of the boundary", Phil. Trans. R. Soc. Lond. A 228,
//!   377–420.
//!
//! [`SliderGeometry`]: crate::friction::geometry::SliderGeometry
//! [`Error::OutOfDomain`]: crate::error::Error::OutOfDomain

// The code, by concept: `bed.rs` the independent-rod bed (`RodBed`: checks,
// solves, plastic update and pile-up, energies); `equilibrium.rs` its
// position (breakpoint sweep, warm walk, dense reference); `influence.rs`
// Love's square-load compliance of the half-space; `coupled.rs` the rods on
// an elastic substrate (`CoupledRodBed`). The types they share are here.

mod bed;
mod coupled;
mod equilibrium;
mod influence;

pub use bed::RodBed;
pub use coupled::CoupledRodBed;
pub use influence::{square_influence, INFLUENCE_QUADRATURE_SWITCH};

use serde::{Deserialize, Serialize};

/// Maximum number of breakpoints a warm start walks across before it falls
/// back to the full O(n log n) sweep.
pub const WARM_WALK_LIMIT: u32 = 8;

/// Maximum number of active-set iterations of the dense and coupled solvers.
pub const ACTIVE_SET_MAX_ITERATIONS: u32 = 200;

/// How a rod bed is loaded (thesis 6.3 and 6.4): the two boundary conditions
/// of the equilibrium (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum Loading {
    /// Fixed gap (6-9)..(6-12): the slider's mean line is held at `position`
    /// b₀ (m) above the counter-surface's mean line.
    FixedGap {
        /// Prescribed position b₀ (m), finite.
        position: f64,
    },
    /// Fixed load (6-13)..(6-16): the rods carry `load` P (N), finite, ≥ 0
    /// and ≤ the bed's capacity n·σ_y·A.
    FixedLoad {
        /// Normal load P (N).
        load: f64,
    },
}

/// How the position of the rod bed is found ([`RodBed`] only).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RodSolver {
    /// Exact breakpoint sweep, O(n log n), with an O(n)-typical warm start
    /// from the old state's position when [`RodOptions::warm_start`] is set.
    #[default]
    Sweep,
    /// The thesis's dense formulation (6-12)/(6-16) iterated over active
    /// sets, faer LU (reference; O(n³) per iteration, allocates).
    Dense,
}

/// What happens to the free heights of yielded rods (thesis 6.2.3).
///
/// The choice matters when sliding. With [`Self::NearestNeighbours`] the
/// displaced volume lands on the rods next to a contact spot, which the
/// moving counter-surface reaches at the next steps: they yield again and
/// pass the volume on, so the same material is plastically worked over and
/// over. On the chapter-6 copper slider (90 rods of 1.5 µm, seeded
/// self-affine profiles of rms slope 0.07) the plastic share of the
/// dissipation grows from 3 % at 0.05 σ_y A_n to 43 % at 0.65 σ_y A_n, and
/// the COF with it (1.17 → 1.69), against the load-independent COF of thesis
/// Table 6-1. Spreading the volume with [`Self::Gaussian`] over a width
/// larger than the contact spots (ℓ ≳ 15 µm there) keeps it out of the
/// contacts' path: the plastic share stays 2–8 % and the COF 1.05–1.19 over
/// the same loads, and the result no longer depends on ℓ (the same within
/// 5 % for ℓ = 15, 20 and 40 µm). `examples/chapter6.rs` prints this study;
/// the chapter-6 scenes use ℓ = 20 µm. [`Self::ShortenOnly`] gives the
/// geometric ploughing alone (plastic share 2–3 %) but erodes the slider:
/// at 0.25 σ_y A_n a rod is crushed to its root within 150 µm.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum PlasticUpdate {
    /// Yielded rods shorten; their volume is lost (no pile-up).
    ShortenOnly,
    /// The thesis's rule: the volume goes in equal halves to the nearest
    /// non-yielded rod on each side.
    #[default]
    NearestNeighbours,
    /// Not the thesis's rule: shares ∝ exp(−Δx²/(2·width²)) over all
    /// non-yielded rods, `width` (m) > 0. Thesis 6.2.3 only announces "a
    /// weighting function" for future versions without giving one; this
    /// Gaussian is the project's extension (the chapter-6 scenes use
    /// 20 µm, THESIS.md "The pile-up rule").
    Gaussian {
        /// Width ℓ of the Gaussian weight (m).
        width: f64,
    },
}

/// Options of a solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RodOptions {
    /// Position solver (default [`RodSolver::Sweep`]).
    pub solver: RodSolver,
    /// Start from the old state's position when it has one (default true).
    pub warm_start: bool,
    /// Plastic update rule (default [`PlasticUpdate::NearestNeighbours`]).
    pub plastic: PlasticUpdate,
}

impl Default for RodOptions {
    fn default() -> Self {
        Self {
            solver: RodSolver::Sweep,
            warm_start: true,
            plastic: PlasticUpdate::NearestNeighbours,
        }
    }
}

/// The history of a rod bed, owned by the caller: a solve reads an old state
/// and writes a new one, so an increment can be re-evaluated or cut back.
#[derive(Debug, Clone, PartialEq)]
pub struct RodState {
    /// Current free heights H_i of the rods (m), from the slider's mean line
    /// toward the counter-surface; H_i + root_depth > 0.
    pub heights: Vec<f64>,
    /// Elastic strain energy stored in each rod at the end of the last solve
    /// (J), ≥ 0 (all zero for a fresh state).
    pub energy: Vec<f64>,
    /// Equilibrium position b of the last solve (m); `None` for a fresh
    /// state (no warm start).
    pub position: Option<f64>,
}

/// Scalar results of one solve.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RodReport {
    /// Equilibrium position b (m): height of the slider's mean line above the
    /// counter-surface's mean line.
    pub position: f64,
    /// Bulk compression δ_B = F/k_B (m), 0 for a rigid bulk.
    pub bulk_compression: f64,
    /// Total rod force Σ f_i (N).
    pub total_force: f64,
    /// Equilibrium residual (N): |Σ f − P| at fixed load,
    /// |Σ f − k_B·δ_B| at fixed gap.
    pub residual: f64,
    /// Rods carrying force (f_i > 0).
    pub in_contact: usize,
    /// Rods at the yield force.
    pub yielded: usize,
    /// Plastic work of the increment Σ F_y·s_i (J), thesis (4-16).
    pub plastic_work: f64,
    /// Elastic strain energy stored Σ ½ f_i e_i (J), thesis (4-15)
    /// (including the substrate's ½ f·u for [`CoupledRodBed`]).
    pub elastic_energy: f64,
    /// Strain energy released by rods that unloaded since the old state,
    /// Σ max(0, U_old,i − U_new,i) (J), ≥ 0.
    pub released_energy: f64,
    /// Volume removed from yielded rods, Σ A·s_i (m³).
    pub plastic_volume: f64,
    /// Breakpoints crossed (sweep, warm walk) or active-set iterations
    /// (dense, coupled).
    pub iterations: u32,
    /// Whether the warm start found the solution (no fallback to the sweep).
    pub warm_started: bool,
}

/// Per-rod results and the work buffers of a solve, sized for one bed.
#[derive(Debug, Clone, PartialEq)]
pub struct RodSolution {
    force: Vec<f64>,
    overlap: Vec<f64>,
    compression: Vec<f64>,
    plastic: Vec<f64>,
    yielded: Vec<bool>,
    stiffness: Vec<f64>,
    contact_at: Vec<f64>,
    yield_at: Vec<f64>,
    displacement: Vec<f64>,
    events: Vec<(f64, u32)>,
}

impl RodSolution {
    /// Buffers for `n` rods.
    pub fn new(n: usize) -> Self {
        Self {
            force: vec![0.0; n],
            overlap: vec![0.0; n],
            compression: vec![0.0; n],
            plastic: vec![0.0; n],
            yielded: vec![false; n],
            stiffness: vec![0.0; n],
            contact_at: vec![0.0; n],
            yield_at: vec![0.0; n],
            displacement: vec![0.0; n],
            events: vec![(0.0, 0); 2 * n],
        }
    }
    /// Number of rods.
    pub fn len(&self) -> usize {
        self.force.len()
    }
    /// Whether sized for no rod.
    pub fn is_empty(&self) -> bool {
        self.force.is_empty()
    }
    /// Rod forces f_i (N), compressive positive.
    pub fn forces(&self) -> &[f64] {
        &self.force
    }
    /// Overlaps at the solved position (m), o_i = g_i + H_i − b (minus the
    /// substrate displacement u_i for [`CoupledRodBed`]), with the heights of
    /// the old state; negative = clearance.
    pub fn overlaps(&self) -> &[f64] {
        &self.overlap
    }
    /// Elastic compressions e_i = f_i/k_i after the plastic update (m).
    pub fn compressions(&self) -> &[f64] {
        &self.compression
    }
    /// Plastic shortening s_i of this increment (m), ≥ 0.
    pub fn plastic_shortening(&self) -> &[f64] {
        &self.plastic
    }
    /// Whether each rod is at the yield force.
    pub fn yielded(&self) -> &[bool] {
        &self.yielded
    }
    /// Rod stiffnesses k_i = E A/(H_i + d) used by the solve (N/m).
    pub fn stiffnesses(&self) -> &[f64] {
        &self.stiffness
    }
    /// Substrate displacements u_i at the rod bases (m); zero for [`RodBed`].
    pub fn substrate_displacements(&self) -> &[f64] {
        &self.displacement
    }
}
