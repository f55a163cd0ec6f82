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
//! **prescribed position** of [`RodBed::solve_gap`]. The matrix form (6-12)
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
//! Equilibrium (6-13), (6-14): P = Σ f_i. Compatibility (6-15) as (6-11),
//! now with the gap unknown. The bulk compression δ_B = P/k_B is known and
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

// Rod arrays (heights, stiffnesses, onsets, forces) are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

use crate::error::{check, Error, Result};
use crate::friction::geometry::{RodLevel, SliderGeometry};
use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::{MatMut, MatRef};

/// Maximum number of breakpoints a warm start walks across before it falls
/// back to the full O(n log n) sweep.
pub const WARM_WALK_LIMIT: u32 = 8;

/// Maximum number of active-set iterations of the dense and coupled solvers.
pub const ACTIVE_SET_MAX_ITERATIONS: u32 = 200;

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
    /// The thesis's proposed weighting function: shares ∝
    /// exp(−Δx²/(2·width²)) over all non-yielded rods, `width` (m) > 0.
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

/// A bed of elastic–perfectly plastic micro-rods on the slider's bulk (see
/// the module docs). Immutable; the heights that change live in
/// [`RodState`].
#[derive(Debug, Clone, PartialEq)]
pub struct RodBed {
    width: f64,
    centers: Vec<f64>,
    heights: Vec<f64>,
    root_depth: f64,
    modulus: f64,
    yield_stress: f64,
    bulk_stiffness: f64,
}

fn invalid(name: &'static str, value: f64, bound: &'static str) -> Error {
    Error::InvalidArgument { name, value, bound }
}

fn check_len(name: &'static str, len: usize, n: usize) -> Result<()> {
    if len == n {
        Ok(())
    } else {
        Err(invalid(name, len as f64, "equal to the number of rods"))
    }
}

impl RodBed {
    /// A bed of rods of `width` w (m; square section A = w²), centred at
    /// `centers` (m, strictly increasing), with free `heights` H_i (m, from
    /// the slider's mean line toward the counter-surface), rooted in the bulk
    /// at `root_depth` d (m) below the mean line (rod length L_i = H_i + d),
    /// effective rod `modulus` E (Pa, thesis (6-8)) and `yield_stress` σ_y
    /// (Pa). The bulk is rigid; see [`Self::with_bulk`].
    ///
    /// Errors (named): `width`, `modulus`, `yield_stress` not finite and > 0;
    /// `yield_stress` ≥ `modulus` (ε_y = σ_y/E < 1); `root_depth` not finite;
    /// `heights.len()` = 0; `centers.len()` ≠ `heights.len()`; a non-finite
    /// or not strictly increasing centre (`centers`); a non-finite height or
    /// one with H_i + d ≤ 0 (`heights`).
    pub fn new(
        width: f64,
        centers: Vec<f64>,
        heights: Vec<f64>,
        root_depth: f64,
        modulus: f64,
        yield_stress: f64,
    ) -> Result<Self> {
        check::positive("width", width)?;
        check::positive("modulus", modulus)?;
        check::positive("yield_stress", yield_stress)?;
        if yield_stress >= modulus {
            return Err(invalid(
                "yield_stress",
                yield_stress,
                "< modulus (yield strain below 1)",
            ));
        }
        check::finite("root_depth", root_depth)?;
        if heights.is_empty() {
            return Err(invalid("heights.len()", 0.0, ">= 1 rod"));
        }
        check_len("centers.len()", centers.len(), heights.len())?;
        for (i, &c) in centers.iter().enumerate() {
            check::finite("centers", c)?;
            if i > 0 && c <= centers[i - 1] {
                return Err(invalid("centers", c, "strictly increasing"));
            }
        }
        check_heights("heights", &heights, root_depth)?;
        Ok(Self {
            width,
            centers,
            heights,
            root_depth,
            modulus,
            yield_stress,
            bulk_stiffness: f64::INFINITY,
        })
    }

    /// A bed from one [`RodLevel`] (centres and heights from the level).
    /// Errors as [`Self::new`].
    pub fn from_level(
        level: &RodLevel,
        root_depth: f64,
        modulus: f64,
        yield_stress: f64,
    ) -> Result<Self> {
        let centers = (0..level.len()).map(|k| level.center(k)).collect();
        Self::new(
            level.width(),
            centers,
            level.heights().to_vec(),
            root_depth,
            modulus,
            yield_stress,
        )
    }

    /// A bed from the finest level of `geometry` (the rods whose tips carry
    /// the nano-asperities; see the module docs on multi-level sliders).
    /// Errors as [`Self::new`].
    pub fn from_geometry(
        geometry: &SliderGeometry,
        root_depth: f64,
        modulus: f64,
        yield_stress: f64,
    ) -> Result<Self> {
        Self::from_level(geometry.tips(), root_depth, modulus, yield_stress)
    }

    /// The same bed on an elastic bulk of modulus `bulk_modulus` E_B (Pa),
    /// section `bulk_area` A_B (m²) and height `bulk_height` H_B (m):
    /// k_B = E_B A_B / H_B, thesis (6-10). Errors: any argument not finite
    /// and > 0 (named).
    pub fn with_bulk(self, bulk_modulus: f64, bulk_area: f64, bulk_height: f64) -> Result<Self> {
        check::positive("bulk_modulus", bulk_modulus)?;
        check::positive("bulk_area", bulk_area)?;
        check::positive("bulk_height", bulk_height)?;
        self.with_bulk_stiffness(bulk_modulus * bulk_area / bulk_height)
    }

    /// The same bed with bulk stiffness `bulk_stiffness` k_B (N/m, > 0;
    /// +∞ for a rigid bulk).
    pub fn with_bulk_stiffness(mut self, bulk_stiffness: f64) -> Result<Self> {
        if bulk_stiffness.is_nan() || bulk_stiffness <= 0.0 {
            return Err(invalid(
                "bulk_stiffness",
                bulk_stiffness,
                "> 0 (+inf for a rigid bulk)",
            ));
        }
        self.bulk_stiffness = bulk_stiffness;
        Ok(self)
    }

    /// Number of rods.
    pub fn len(&self) -> usize {
        self.heights.len()
    }
    /// Always `false`.
    pub fn is_empty(&self) -> bool {
        self.heights.is_empty()
    }
    /// Rod width w (m).
    pub fn width(&self) -> f64 {
        self.width
    }
    /// Rod section A = w² (m²).
    pub fn area(&self) -> f64 {
        self.width * self.width
    }
    /// Rod centres (m).
    pub fn centers(&self) -> &[f64] {
        &self.centers
    }
    /// Initial free heights H_i (m).
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }
    /// Depth d of the bulk face below the slider's mean line (m).
    pub fn root_depth(&self) -> f64 {
        self.root_depth
    }
    /// Effective rod modulus E (Pa).
    pub fn modulus(&self) -> f64 {
        self.modulus
    }
    /// Yield stress σ_y (Pa).
    pub fn yield_stress(&self) -> f64 {
        self.yield_stress
    }
    /// Yield force of one rod F_y = σ_y A (N).
    pub fn yield_force(&self) -> f64 {
        self.yield_stress * self.area()
    }
    /// Load capacity n·F_y (N).
    pub fn capacity(&self) -> f64 {
        self.len() as f64 * self.yield_force()
    }
    /// Bulk stiffness k_B (N/m; +∞ rigid).
    pub fn bulk_stiffness(&self) -> f64 {
        self.bulk_stiffness
    }
    /// Stiffness of a rod of free height `height` (m): E A/(H + d) (N/m),
    /// thesis (4-10).
    pub fn stiffness(&self, height: f64) -> f64 {
        self.modulus * self.area() / (height + self.root_depth)
    }
    /// A fresh state: the initial heights, no stored energy, no position.
    pub fn state(&self) -> RodState {
        RodState {
            heights: self.heights.clone(),
            energy: vec![0.0; self.len()],
            position: None,
        }
    }
    /// Solution buffers sized for this bed.
    pub fn solution(&self) -> RodSolution {
        RodSolution::new(self.len())
    }

    /// Total rod force F(b) = Σ min(k_i max(o_i, 0), F_y) (N) at position
    /// `position` b (m), heights from `state`, counter-surface `counter` (m).
    /// Errors as [`Self::solve_load`].
    pub fn total_force(&self, state: &RodState, counter: &[f64], position: f64) -> Result<f64> {
        check::finite("position", position)?;
        self.check_inputs(state, counter)?;
        let fy = self.yield_force();
        Ok((0..self.len())
            .map(|i| {
                let k = self.stiffness(state.heights[i]);
                let a = counter[i] + state.heights[i];
                rod_force(position, a, a - fy / k, k, fy)
            })
            .sum())
    }

    /// Fixed gap, thesis (6-9)..(6-12): the equilibrium when the slider's
    /// mean line is prescribed at `position` b₀ (m) for an undeformed bulk
    /// (b = b₀ + δ_B, δ_B = F/k_B; b = b₀ for a rigid bulk). Reads `old`,
    /// writes per-rod results into `out` and the updated heights and energies
    /// into `new` (which may be a copy of `old`).
    ///
    /// Errors (named): `position` not finite; the input errors of
    /// [`Self::solve_load`]; a dense solve that does not converge.
    pub fn solve_gap(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        position: f64,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        check::finite("position", position)?;
        self.solve(old, new, counter, 0.0, position, true, options, out)
    }

    /// Fixed load, thesis (6-13)..(6-16): the position b at which the rods
    /// carry `load` P (N). See the module docs for P = 0, P = capacity and
    /// the warm start.
    ///
    /// Errors (named): `load` not finite and ≥ 0; `load` above
    /// [`Self::capacity`] ([`Error::OutOfDomain`]); `counter.len()`,
    /// `state.heights.len()`, `state.energy.len()` ≠ n; a non-finite
    /// `counter`; a state height non-finite or with H_i + d ≤ 0
    /// (`state.heights`); a negative or non-finite `state.energy`; a
    /// non-finite `state.position`; `solution.len()` ≠ n; a Gaussian
    /// `width` not finite and > 0; a dense solve that does not converge
    /// ([`Error::NotConverged`]).
    pub fn solve_load(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        load: f64,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        check::non_negative("load", load)?;
        self.solve(old, new, counter, load, 0.0, false, options, out)
    }

    fn check_inputs(&self, state: &RodState, counter: &[f64]) -> Result<()> {
        let n = self.len();
        check_len("counter.len()", counter.len(), n)?;
        for &g in counter {
            check::finite("counter", g)?;
        }
        check_len("state.heights.len()", state.heights.len(), n)?;
        check_heights("state.heights", &state.heights, self.root_depth)
    }

    fn check_all(
        &self,
        old: &RodState,
        counter: &[f64],
        options: &RodOptions,
        out: &RodSolution,
    ) -> Result<()> {
        self.check_inputs(old, counter)?;
        check_len("state.energy.len()", old.energy.len(), self.len())?;
        for &e in &old.energy {
            check::non_negative("state.energy", e)?;
        }
        if let Some(p) = old.position {
            check::finite("state.position", p)?;
        }
        check_len("solution.len()", out.len(), self.len())?;
        if out.events.len() != 2 * self.len() {
            return Err(invalid(
                "solution.len()",
                out.len() as f64,
                "built by RodSolution::new for this bed",
            ));
        }
        if let PlasticUpdate::Gaussian { width } = options.plastic {
            check::positive("width", width)?;
        }
        Ok(())
    }

    /// Fills k_i, a_i, y_i from the old heights and the counter-surface.
    fn prepare(&self, old: &RodState, counter: &[f64], out: &mut RodSolution) {
        let fy = self.yield_force();
        for i in 0..self.len() {
            let k = self.stiffness(old.heights[i]);
            let a = counter[i] + old.heights[i];
            out.stiffness[i] = k;
            out.contact_at[i] = a;
            out.yield_at[i] = a - fy / k;
            out.displacement[i] = 0.0;
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn solve(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        load: f64,
        b0: f64,
        gap: bool,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        self.check_all(old, counter, options, out)?;
        let fy = self.yield_force();
        if !gap && load > self.capacity() {
            return Err(Error::OutOfDomain {
                name: "load",
                value: load,
                reason: "exceeds the capacity n*sigma_y*A: every rod yields, no equilibrium",
            });
        }
        self.prepare(old, counter, out);
        let c = if gap { self.bulk_stiffness } else { 0.0 };
        let problem = Problem {
            a: &out.contact_at,
            y: &out.yield_at,
            k: &out.stiffness,
            fy,
            p: load,
            c,
            b0,
        };
        let mut report = RodReport::default();
        let mut dense_forces = false;
        let b = if let Some(b) = problem.special() {
            b
        } else {
            match options.solver {
                RodSolver::Sweep => {
                    let warm = if options.warm_start {
                        old.position
                            .and_then(|start| problem.walk(start, WARM_WALK_LIMIT))
                    } else {
                        None
                    };
                    let (m, it) = match warm {
                        Some(w) => {
                            report.warm_started = true;
                            w
                        }
                        None => problem.sweep(&mut out.events),
                    };
                    report.iterations = it;
                    problem.finish(m)
                }
                RodSolver::Dense => {
                    let (b, it) = problem.dense(&mut out.force)?;
                    report.iterations = it;
                    dense_forces = true;
                    b
                }
            }
        };
        // Evaluate the rods at b.
        for i in 0..self.len() {
            out.overlap[i] = out.contact_at[i] - b;
            let f = rod_force(b, out.contact_at[i], out.yield_at[i], out.stiffness[i], fy);
            if !(dense_forces && f > 0.0 && f < fy) {
                out.force[i] = f;
            }
            out.yielded[i] = f >= fy;
        }
        let total: f64 = out.force.iter().sum();
        report.position = b;
        report.total_force = total;
        if gap {
            let db = if c.is_finite() { b - b0 } else { 0.0 };
            report.bulk_compression = db;
            report.residual = if c.is_finite() {
                (total - c * db).abs()
            } else {
                0.0
            };
        } else {
            report.bulk_compression = if self.bulk_stiffness.is_finite() {
                load / self.bulk_stiffness
            } else {
                0.0
            };
            report.residual = (total - load).abs();
        }
        self.check_crush(
            out,
            old,
            if gap {
                ("position", b0)
            } else {
                ("load", load)
            },
        )?;
        self.commit(old, new, options, out, &mut report);
        new.position = Some(b);
        Ok(report)
    }

    /// A yielded rod whose overlap reaches its length would be crushed to
    /// its root by the plastic update: no meaningful state.
    fn check_crush(
        &self,
        out: &RodSolution,
        old: &RodState,
        (name, value): (&'static str, f64),
    ) -> Result<()> {
        for i in 0..self.len() {
            if out.yielded[i] && out.overlap[i] >= old.heights[i] + self.root_depth {
                return Err(Error::OutOfDomain {
                    name,
                    value,
                    reason: "a yielded rod would be crushed to its root (overlap >= rod length)",
                });
            }
        }
        Ok(())
    }

    /// Plastic update (6.2.3), energies (4-15, 4-16), the new state.
    fn commit(
        &self,
        old: &RodState,
        new: &mut RodState,
        options: &RodOptions,
        out: &mut RodSolution,
        report: &mut RodReport,
    ) {
        let n = self.len();
        let fy = self.yield_force();
        let eps_y = self.yield_stress / self.modulus;
        let area = self.area();
        new.heights.clone_from(&old.heights);
        new.energy.resize(n, 0.0);
        let mut in_contact = 0;
        let mut yielded = 0;
        let mut plastic_work = 0.0;
        let mut stored = 0.0;
        let mut released = 0.0;
        let mut volume = 0.0;
        for i in 0..n {
            let f = out.force[i];
            let mut e = f / out.stiffness[i];
            let mut s = 0.0;
            if out.yielded[i] {
                let len = old.heights[i] + self.root_depth;
                s = ((out.overlap[i] - eps_y * len) / (1.0 - eps_y)).max(0.0);
                new.heights[i] = old.heights[i] - s;
                e = eps_y * (len - s);
                yielded += 1;
            }
            if f > 0.0 {
                in_contact += 1;
            }
            out.plastic[i] = s;
            out.compression[i] = e;
            plastic_work += fy * s;
            volume += area * s;
            let u = 0.5 * f * (e + out.displacement[i]);
            stored += u;
            released += (old.energy[i] - u).max(0.0);
            new.energy[i] = u;
        }
        // Pile-up of the removed volume (heights: all rods have the same
        // section, so volume A·s ↔ height s).
        if yielded > 0 && options.plastic != PlasticUpdate::ShortenOnly {
            for i in 0..n {
                let s = out.plastic[i];
                if s > 0.0 {
                    redistribute(
                        i,
                        s,
                        &self.centers,
                        &out.yielded,
                        options.plastic,
                        &mut new.heights,
                    );
                }
            }
        }
        report.in_contact = in_contact;
        report.yielded = yielded;
        report.plastic_work = plastic_work;
        report.elastic_energy = stored;
        report.released_energy = released;
        report.plastic_volume = volume;
    }
}

fn check_heights(name: &'static str, heights: &[f64], root_depth: f64) -> Result<()> {
    for &h in heights {
        check::finite(name, h)?;
        if h + root_depth <= 0.0 {
            return Err(invalid(
                name,
                h,
                "> -root_depth (rod length H + d must be > 0)",
            ));
        }
    }
    Ok(())
}

/// Force of one rod at position `b` (m), with contact onset `a` and yield
/// onset `y` (m, y = a − F_y/k): F_y for b ≤ y, k·(a − b) between, 0 for
/// b ≥ a (N). The regime is decided on the breakpoints, not on the computed
/// force: at b = y the overlap a − y misses F_y/k by the rounding of the
/// subtraction, and such a rod has yielded (at the capacity load, b = min y,
/// every rod has).
#[inline]
fn rod_force(b: f64, a: f64, y: f64, k: f64, fy: f64) -> f64 {
    if b <= y {
        fy
    } else if b < a {
        (k * (a - b)).min(fy)
    } else {
        0.0
    }
}

/// Gives the height `s` (m) removed from yielded rod `i` to the rods that
/// did not yield, by `rule` (see [`PlasticUpdate`]). The shares sum to `s`
/// exactly.
fn redistribute(
    i: usize,
    s: f64,
    centers: &[f64],
    yielded: &[bool],
    rule: PlasticUpdate,
    heights: &mut [f64],
) {
    let n = heights.len();
    let left = (0..i).rev().find(|&j| !yielded[j]);
    let right = (i + 1..n).find(|&j| !yielded[j]);
    if left.is_none() && right.is_none() {
        // Every rod yielded: a uniform rise of all rods.
        let share = s / n as f64;
        let mut given = 0.0;
        for (j, h) in heights.iter_mut().enumerate() {
            let part = if j + 1 == n { s - given } else { share };
            *h += part;
            given += share;
        }
        return;
    }
    match rule {
        PlasticUpdate::ShortenOnly => {}
        PlasticUpdate::NearestNeighbours => match (left, right) {
            (Some(l), Some(r)) => {
                let half = 0.5 * s;
                heights[l] += half;
                heights[r] += s - half;
            }
            (Some(j), None) | (None, Some(j)) => heights[j] += s,
            (None, None) => {}
        },
        PlasticUpdate::Gaussian { width } => {
            let xi = centers[i];
            let dist = |j: usize| centers[j] - xi;
            let dmin = match (left, right) {
                (Some(l), Some(r)) => dist(l).abs().min(dist(r).abs()),
                (Some(j), None) | (None, Some(j)) => dist(j).abs(),
                (None, None) => 0.0,
            };
            // Weights relative to the nearest recipient (weight 1), so the
            // sum never underflows.
            let two_l2 = 2.0 * width * width;
            let weight = |j: usize| {
                let d = dist(j);
                (-(d * d - dmin * dmin) / two_l2).exp()
            };
            let mut total = 0.0;
            let mut last = 0;
            for j in 0..n {
                if !yielded[j] {
                    total += weight(j);
                    last = j;
                }
            }
            let mut given = 0.0;
            for j in 0..n {
                if yielded[j] {
                    continue;
                }
                let part = if j == last {
                    s - given
                } else {
                    s * weight(j) / total
                };
                heights[j] += part;
                given += part;
            }
        }
    }
}

/// The one-dimensional equilibrium R(b) = F(b) − P − c·(b − b₀) = 0 of a
/// bed of independent rods, F the piecewise-linear total force. Fixed load:
/// c = 0. Fixed gap: P = 0, c = k_B.
struct Problem<'a> {
    a: &'a [f64],
    y: &'a [f64],
    k: &'a [f64],
    fy: f64,
    p: f64,
    c: f64,
    b0: f64,
}

/// A distance well away from `b` (for a point inside an unbounded piece).
#[inline]
fn span(b: f64) -> f64 {
    b.abs().max(1.0)
}

impl Problem<'_> {
    fn n(&self) -> usize {
        self.a.len()
    }

    fn force(&self, b: f64) -> f64 {
        let mut f = 0.0;
        for i in 0..self.n() {
            f += rod_force(b, self.a[i], self.y[i], self.k[i], self.fy);
        }
        f
    }

    fn residual(&self, b: f64, f: f64) -> f64 {
        if self.c > 0.0 {
            f - self.p - self.c * (b - self.b0)
        } else {
            f - self.p
        }
    }

    fn max_a(&self) -> f64 {
        self.a.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    }

    fn min_y(&self) -> f64 {
        self.y.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// The cases with a closed answer: rigid bulk at fixed gap; zero load;
    /// load equal to the capacity.
    fn special(&self) -> Option<f64> {
        if self.c == f64::INFINITY {
            return Some(self.b0);
        }
        if self.c == 0.0 {
            if self.p == 0.0 {
                return Some(self.max_a());
            }
            if self.p >= self.n() as f64 * self.fy {
                return Some(self.min_y());
            }
        }
        None
    }

    /// Exact root on the linear piece containing the interior point `m`:
    /// classification at m, anchored at the piece's upper breakpoint (its
    /// lower one when unbounded above), clamped to the piece.
    fn finish(&self, m: f64) -> f64 {
        let mut kk = 0.0;
        let mut hi = f64::INFINITY;
        let mut lo = f64::NEG_INFINITY;
        for i in 0..self.n() {
            let (a, y) = (self.a[i], self.y[i]);
            if y < m && m < a {
                kk += self.k[i];
            }
            for bp in [a, y] {
                if bp > m {
                    hi = hi.min(bp);
                } else if bp < m {
                    lo = lo.max(bp);
                }
            }
        }
        let anchor = if hi.is_finite() { hi } else { lo };
        let r = self.residual(anchor, self.force(anchor));
        let slope = kk + self.c;
        let b = if slope > 0.0 {
            anchor + r / slope
        } else {
            anchor
        };
        b.max(lo).min(hi)
    }

    /// Cold O(n log n) sweep of the sorted breakpoints from the top. Returns
    /// a point inside the piece holding the root and the breakpoints crossed.
    fn sweep(&self, events: &mut [(f64, u32)]) -> (f64, u32) {
        let n = self.n();
        for i in 0..n {
            events[2 * i] = (self.a[i], (2 * i) as u32);
            events[2 * i + 1] = (self.y[i], (2 * i + 1) as u32);
        }
        events.sort_unstable_by(|p, q| q.0.total_cmp(&p.0).then((p.1 & 1).cmp(&(q.1 & 1))));
        let top = events[0].0;
        let mut r = self.residual(top, 0.0);
        if r >= 0.0 {
            return (top + span(top), 0);
        }
        let mut kk = 0.0;
        let mut prev = top;
        for (j, &(e, code)) in events.iter().enumerate() {
            if e < prev {
                r += (kk + self.c) * (prev - e);
                if r >= 0.0 {
                    return (0.5 * (prev + e), j as u32);
                }
                prev = e;
            }
            let i = (code >> 1) as usize;
            if code & 1 == 0 {
                kk += self.k[i];
            } else {
                kk = (kk - self.k[i]).max(0.0);
            }
        }
        (prev - span(prev), (2 * n) as u32)
    }

    /// Warm start: walk from `start` across at most `limit` breakpoints,
    /// O(n) per step. Returns a point inside the piece holding the root, or
    /// `None` (fall back to the sweep).
    fn walk(&self, start: f64, limit: u32) -> Option<(f64, u32)> {
        let mut b = start;
        for step in 0..=limit {
            let mut f = 0.0;
            let mut k_below = 0.0;
            let mut k_above = 0.0;
            let mut bu = f64::INFINITY;
            let mut bl = f64::NEG_INFINITY;
            for i in 0..self.n() {
                let (a, y, k) = (self.a[i], self.y[i], self.k[i]);
                f += rod_force(b, a, y, k, self.fy);
                if y < b && b <= a {
                    k_below += k;
                }
                if y <= b && b < a {
                    k_above += k;
                }
                for bp in [a, y] {
                    if bp > b {
                        bu = bu.min(bp);
                    } else if bp < b {
                        bl = bl.max(bp);
                    }
                }
            }
            let r = self.residual(b, f);
            if r >= 0.0 {
                let slope = k_above + self.c;
                if (slope > 0.0 && b + r / slope <= bu) || !bu.is_finite() {
                    let m = if bu.is_finite() {
                        0.5 * (b + bu)
                    } else {
                        b + span(b)
                    };
                    return Some((m, step));
                }
                b = bu;
            } else {
                let slope = k_below + self.c;
                if slope > 0.0 && b + r / slope >= bl {
                    let m = if bl.is_finite() {
                        0.5 * (bl + b)
                    } else {
                        b - span(b)
                    };
                    return Some((m, step));
                }
                if !bl.is_finite() {
                    return None;
                }
                b = bl;
            }
        }
        None
    }

    /// The thesis's dense formulation, (6-16) at fixed load and (6-12) at
    /// fixed gap with an elastic bulk, iterated over active sets with a
    /// bracket safeguard. Writes the forces of the elastic rods (k_i δ_i from
    /// the LU solution) into `forces`. Returns b and the iterations.
    fn dense(&self, forces: &mut [f64]) -> Result<(f64, u32)> {
        let n = self.n();
        let gap = self.c > 0.0;
        let (mut lo, mut hi) = (self.min_y(), self.max_a());
        if gap {
            lo = lo.min(self.b0);
            hi = hi.max(self.b0);
        }
        let kmax = self.k.iter().copied().fold(0.0, f64::max);
        let mut m = 0.5 * (lo + hi);
        let mut active: Vec<usize> = Vec::with_capacity(n);
        let mut mat: Vec<f64> = Vec::new();
        let mut rhs: Vec<f64> = Vec::new();
        for it in 1..=ACTIVE_SET_MAX_ITERATIONS {
            active.clear();
            let mut n_yield = 0usize;
            for i in 0..n {
                if self.y[i] < m && m < self.a[i] {
                    active.push(i);
                } else if m <= self.y[i] {
                    n_yield += 1;
                }
            }
            let yielded_force = n_yield as f64 * self.fy;
            // The classification point itself narrows the bracket, so that
            // the midpoint fallback always makes progress.
            if self.residual(m, self.force(m)) >= 0.0 {
                lo = lo.max(m);
            } else {
                hi = hi.min(m);
            }
            let na = active.len();
            let candidate = if na == 0 && !gap {
                None
            } else {
                // Unknowns x = (δ_B or b, δ_1..δ_na); row 0 equilibrium
                // scaled by 1/k_max (row equilibration), rows 1.. compatibility.
                let dim = na + 1;
                mat.clear();
                mat.resize(dim * dim, 0.0);
                rhs.clear();
                rhs.resize(dim, 0.0);
                let at = |r: usize, c: usize| r + c * dim;
                if gap {
                    mat[at(0, 0)] = self.c / kmax.max(self.c);
                    rhs[0] = yielded_force / kmax.max(self.c);
                } else {
                    mat[at(0, 0)] = 0.0;
                    rhs[0] = (self.p - yielded_force) / kmax;
                }
                for (j, &i) in active.iter().enumerate() {
                    let scale = if gap { kmax.max(self.c) } else { kmax };
                    mat[at(0, j + 1)] = if gap { -self.k[i] } else { self.k[i] } / scale;
                    mat[at(j + 1, 0)] = 1.0;
                    mat[at(j + 1, j + 1)] = 1.0;
                    rhs[j + 1] = if gap { self.a[i] - self.b0 } else { self.a[i] };
                }
                let lu = PartialPivLu::new(MatRef::from_column_major_slice(&mat, dim, dim));
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut rhs, dim, 1));
                let b = if gap { self.b0 + rhs[0] } else { rhs[0] };
                if b.is_finite() {
                    Some(b)
                } else {
                    None
                }
            };
            if let Some(b) = candidate {
                // Consistent with the active set (closed pieces)?
                let mut consistent = true;
                let mut q = 0;
                for i in 0..n {
                    let is_active = q < na && active[q] == i;
                    if is_active {
                        q += 1;
                        if !(self.y[i] <= b && b <= self.a[i]) {
                            consistent = false;
                        }
                    } else if m <= self.y[i] {
                        if b > self.y[i] {
                            consistent = false;
                        }
                    } else if b < self.a[i] {
                        consistent = false;
                    }
                }
                if consistent {
                    for (j, &i) in active.iter().enumerate() {
                        forces[i] = (self.k[i] * rhs[j + 1]).clamp(0.0, self.fy);
                    }
                    return Ok((b, it));
                }
                let inside = lo < b && b < hi;
                let r = self.residual(b, self.force(b));
                if r >= 0.0 {
                    lo = lo.max(b);
                } else {
                    hi = hi.min(b);
                }
                m = if inside && it % 4 != 0 {
                    b
                } else {
                    0.5 * (lo + hi)
                };
            } else {
                m = 0.5 * (lo + hi);
            }
        }
        Err(Error::NotConverged {
            what: "dense rod active set (6-12)/(6-16)",
            iterations: ACTIVE_SET_MAX_ITERATIONS,
            residual: hi - lo,
        })
    }
}

// ------------------------------------------------------------------------
// Rods on an elastic substrate
// ------------------------------------------------------------------------

/// Gauss–Legendre nodes and weights on [−1, 1], 8 points.
const GL8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// Centre distance (in rod widths) beyond which [`square_influence`] uses
/// quadrature instead of Love's closed form.
pub const INFLUENCE_QUADRATURE_SWITCH: f64 = 6.0;

/// G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|): the mixed antiderivative of
/// 1/√(X² + Y²) (zero terms at X = 0 or Y = 0).
fn love_g(x: f64, y: f64) -> f64 {
    let t1 = if x != 0.0 {
        x * (y / x.abs()).asinh()
    } else {
        0.0
    };
    let t2 = if y != 0.0 {
        y * (x / y.abs()).asinh()
    } else {
        0.0
    };
    t1 + t2
}

/// Compliance of an elastic half-space (m/N): the normal displacement at
/// offset (`dx`, `dy`) (m) from the centre of a square of side `width` (m)
/// carrying a unit force spread uniformly over it, for contact modulus
/// `contact_modulus` E* (Pa) (Boussinesq: a point force f displaces the
/// surface by f/(π E* r) at distance r; E* = E/(1 − ν²) against a rigid
/// counter-surface).
///
/// u = (1/(π E* w²)) ∬_square dA/r: uniform pressure on a rectangle, Love
/// (1929), "The stress produced in a semi-infinite solid by pressure on part
/// of the boundary", Phil. Trans. R. Soc. A 228, 377; Johnson, *Contact
/// Mechanics* (1985), ch. 3 (Boussinesq's point-force solution). In closed form, with G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|),
/// X± = dx ± w/2, Y± = dy ± w/2:
///
/// u = (G(X₊,Y₊) − G(X₋,Y₊) − G(X₊,Y₋) + G(X₋,Y₋)) / (π E* w²).
///
/// At the centre u = 4 ln(1 + √2)/(π E* w) ≈ 1.1222/(E* w); far away
/// u → 1/(π E* r). Beyond [`INFLUENCE_QUADRATURE_SWITCH`] widths the closed
/// form loses digits to cancellation, so the integral is taken by 8 × 8
/// Gauss–Legendre points (relative error < 1e-15 there).
///
/// Errors: `width`, `contact_modulus` not finite and > 0; `dx`, `dy` not
/// finite.
pub fn square_influence(dx: f64, dy: f64, width: f64, contact_modulus: f64) -> Result<f64> {
    check::finite("dx", dx)?;
    check::finite("dy", dy)?;
    check::positive("width", width)?;
    check::positive("contact_modulus", contact_modulus)?;
    Ok(influence_unchecked(dx, dy, width, contact_modulus))
}

fn influence_unchecked(dx: f64, dy: f64, w: f64, e_star: f64) -> f64 {
    let h = 0.5 * w;
    let r = (dx * dx + dy * dy).sqrt();
    let integral = if r <= INFLUENCE_QUADRATURE_SWITCH * w {
        love_g(dx + h, dy + h) - love_g(dx - h, dy + h) - love_g(dx + h, dy - h)
            + love_g(dx - h, dy - h)
    } else {
        let mut s = 0.0;
        for &(xi, wi) in &GL8 {
            for &(eta, wj) in &GL8 {
                let x = dx - h * xi;
                let y = dy - h * eta;
                s += wi * wj / (x * x + y * y).sqrt();
            }
        }
        s * h * h
    };
    integral / (core::f64::consts::PI * e_star * w * w)
}

/// Rods standing on an elastic half-space (see the module docs): the rod bed
/// of a [`RodBed`] (its rigid-bulk stiffness k_B is kept as a series spring
/// at fixed gap) plus the dense influence matrix C (m/N) between the rod
/// sites, rods in a row along x at y = 0. Immutable.
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledRodBed {
    bed: RodBed,
    contact_modulus: f64,
    influence: Vec<f64>,
}

impl CoupledRodBed {
    /// Couples the rods of `bed` through a half-space of contact modulus
    /// `contact_modulus` E* (Pa): C_ij = [`square_influence`](x_i − x_j, 0,
    /// w, E*), symmetric. Errors: `contact_modulus` not finite and > 0.
    pub fn new(bed: RodBed, contact_modulus: f64) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        let n = bed.len();
        let w = bed.width();
        let mut influence = vec![0.0; n * n];
        for j in 0..n {
            for i in 0..=j {
                let c =
                    influence_unchecked(bed.centers[i] - bed.centers[j], 0.0, w, contact_modulus);
                influence[i + j * n] = c;
                influence[j + i * n] = c;
            }
        }
        Ok(Self {
            bed,
            contact_modulus,
            influence,
        })
    }

    /// The rod bed.
    pub fn bed(&self) -> &RodBed {
        &self.bed
    }
    /// Contact modulus E* of the substrate (Pa).
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }
    /// The influence matrix C (m/N), n × n, column-major.
    pub fn influence(&self) -> MatRef<'_, f64> {
        let n = self.bed.len();
        MatRef::from_column_major_slice(&self.influence, n, n)
    }

    /// Fixed gap: as [`RodBed::solve_gap`], with substrate coupling.
    /// Errors as [`RodBed::solve_gap`]; [`Error::NotConverged`] when the
    /// active-set iteration fails.
    pub fn solve_gap(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        position: f64,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        check::finite("position", position)?;
        self.solve(old, new, counter, 0.0, position, true, options, out)
    }

    /// Fixed load: as [`RodBed::solve_load`], with substrate coupling.
    /// Errors as [`RodBed::solve_load`]; [`Error::NotConverged`] when the
    /// active-set iteration fails.
    pub fn solve_load(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        load: f64,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        check::non_negative("load", load)?;
        self.solve(old, new, counter, load, 0.0, false, options, out)
    }

    #[allow(clippy::too_many_arguments)]
    fn solve(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        load: f64,
        b0: f64,
        gap: bool,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        let bed = &self.bed;
        bed.check_all(old, counter, options, out)?;
        if !gap && load > bed.capacity() {
            return Err(Error::OutOfDomain {
                name: "load",
                value: load,
                reason: "exceeds the capacity n*sigma_y*A: every rod yields, no equilibrium",
            });
        }
        bed.prepare(old, counter, out);
        let n = bed.len();
        let fy = bed.yield_force();
        let c = if gap { bed.bulk_stiffness } else { 0.0 };
        let mut inner = Inner::new(n);
        // M·1·F_y per rod: the all-yielded limit.
        let mut all_yield = f64::INFINITY;
        for i in 0..n {
            let row: f64 = (0..n).map(|j| self.influence[i + j * n]).sum();
            let u = fy * (1.0 / out.stiffness[i] + row);
            all_yield = all_yield.min(out.contact_at[i] - u);
        }
        let (closed, start, max_a) = {
            let problem = Problem {
                a: &out.contact_at,
                y: &out.yield_at,
                k: &out.stiffness,
                fy,
                p: load,
                c,
                b0,
            };
            let max_a = problem.max_a();
            let closed = if c == f64::INFINITY {
                Some(b0)
            } else if c == 0.0 && load == 0.0 {
                Some(max_a)
            } else if c == 0.0 && load >= bed.capacity() {
                Some(all_yield)
            } else {
                None
            };
            // Start from the old position, or from the uncoupled bed's
            // equilibrium (a close guess when the substrate is stiff).
            let start = match (closed, options.warm_start, old.position) {
                (Some(b), _, _) => b,
                (None, true, Some(p)) => p,
                (None, _, _) => problem.finish(problem.sweep(&mut out.events).0),
            };
            (closed, start, max_a)
        };
        let (b, iterations) = match closed {
            Some(b) => (b, 0),
            None => {
                let (mut lo, mut hi) = (all_yield, max_a);
                if gap {
                    lo = lo.min(b0);
                    hi = hi.max(b0);
                }
                let target = Target { p: load, c, b0, fy };
                self.outer(&mut inner, out, &target, start, lo, hi)?
            }
        };
        inner.solve(self, out, b, fy)?;
        for i in 0..n {
            let u: f64 = (0..n)
                .map(|j| self.influence[i + j * n] * out.force[j])
                .sum();
            out.displacement[i] = u;
            out.overlap[i] = out.contact_at[i] - b - u;
            out.yielded[i] = out.force[i] >= fy;
        }
        let total: f64 = out.force.iter().sum();
        let mut report = RodReport {
            position: b,
            total_force: total,
            iterations: iterations + inner.iterations,
            ..RodReport::default()
        };
        if gap {
            let db = if c.is_finite() { b - b0 } else { 0.0 };
            report.bulk_compression = db;
            report.residual = if c.is_finite() {
                (total - c * db).abs()
            } else {
                0.0
            };
        } else {
            report.bulk_compression = if bed.bulk_stiffness.is_finite() {
                load / bed.bulk_stiffness
            } else {
                0.0
            };
            report.residual = (total - load).abs();
        }
        bed.check_crush(
            out,
            old,
            if gap {
                ("position", b0)
            } else {
                ("load", load)
            },
        )?;
        bed.commit(old, new, options, out, &mut report);
        new.position = Some(b);
        Ok(report)
    }

    /// Bracketed Newton iteration on b for R(b) = F(b) − P − c (b − b₀),
    /// F(b) from the inner box-constrained solve; slope −(1ᵀM_EE⁻¹1 + c).
    fn outer(
        &self,
        inner: &mut Inner,
        out: &mut RodSolution,
        problem: &Target,
        start: f64,
        mut lo: f64,
        mut hi: f64,
    ) -> Result<(f64, u32)> {
        let fy = problem.fy;
        let scale = problem.p + fy;
        let mut b = start.max(lo).min(hi);
        let mut prev_set: Vec<u8> = Vec::new();
        let mut prev_newton = false;
        for it in 1..=ACTIVE_SET_MAX_ITERATIONS {
            let (f, kk) = inner.solve(self, out, b, fy)?;
            let r = problem.residual(b, f);
            if prev_newton && inner.set == prev_set {
                return Ok((b, it));
            }
            if r.abs() <= 1e-15 * scale * (self.bed.len() as f64) {
                return Ok((b, it));
            }
            if r >= 0.0 {
                lo = lo.max(b);
            } else {
                hi = hi.min(b);
            }
            let slope = kk + problem.c;
            let newton = if slope > 0.0 { b + r / slope } else { f64::NAN };
            prev_set.clone_from(&inner.set);
            if lo < newton && newton < hi && it % 5 != 0 {
                b = newton;
                prev_newton = true;
            } else {
                b = 0.5 * (lo + hi);
                prev_newton = false;
            }
            if hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(lo.abs()) {
                return Ok((0.5 * (lo + hi), it));
            }
        }
        Err(Error::NotConverged {
            what: "coupled rods: position",
            iterations: ACTIVE_SET_MAX_ITERATIONS,
            residual: hi - lo,
        })
    }
}

/// The target of the coupled position iteration: R(b) = F − P − c (b − b₀).
struct Target {
    p: f64,
    c: f64,
    b0: f64,
    fy: f64,
}

impl Target {
    fn residual(&self, b: f64, f: f64) -> f64 {
        if self.c > 0.0 {
            f - self.p - self.c * (b - self.b0)
        } else {
            f - self.p
        }
    }
}

/// Active-set solver of the box-constrained problem at a fixed position.
struct Inner {
    /// 0 off, 1 elastic, 2 yielded.
    set: Vec<u8>,
    idx: Vec<usize>,
    mat: Vec<f64>,
    rhs: Vec<f64>,
    ones: Vec<f64>,
    iterations: u32,
    started: bool,
}

impl Inner {
    fn new(n: usize) -> Self {
        Self {
            set: vec![0; n],
            idx: Vec::with_capacity(n),
            mat: Vec::new(),
            rhs: Vec::new(),
            ones: Vec::new(),
            iterations: 0,
            started: false,
        }
    }

    /// Forces at position `b` into `out.force`; returns (Σ f, 1ᵀ M_EE⁻¹ 1).
    fn solve(
        &mut self,
        bed: &CoupledRodBed,
        out: &mut RodSolution,
        b: f64,
        fy: f64,
    ) -> Result<(f64, f64)> {
        let n = bed.bed.len();
        let c = &bed.influence;
        if !self.started {
            for i in 0..n {
                let o = out.contact_at[i] - b;
                self.set[i] = if o <= 0.0 {
                    0
                } else if b <= out.yield_at[i] {
                    2
                } else {
                    1
                };
            }
            self.started = true;
        }
        for _ in 0..ACTIVE_SET_MAX_ITERATIONS {
            self.iterations += 1;
            self.idx.clear();
            self.idx.extend((0..n).filter(|&i| self.set[i] == 1));
            let m = self.idx.len();
            self.mat.clear();
            self.mat.resize(m * m, 0.0);
            self.rhs.clear();
            self.rhs.resize(m, 0.0);
            self.ones.clear();
            self.ones.resize(m, 1.0);
            for (q, &i) in self.idx.iter().enumerate() {
                for (p, &j) in self.idx.iter().enumerate() {
                    self.mat[p + q * m] = c[j + i * n];
                }
                self.mat[q + q * m] += 1.0 / out.stiffness[i];
                let mut r = out.contact_at[i] - b;
                for j in 0..n {
                    if self.set[j] == 2 {
                        r -= c[i + j * n] * fy;
                    }
                }
                self.rhs[q] = r;
            }
            let mut slope = 0.0;
            if m > 0 {
                let lu = PartialPivLu::new(MatRef::from_column_major_slice(&self.mat, m, m));
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut self.rhs, m, 1));
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut self.ones, m, 1));
                slope = self.ones.iter().sum();
            }
            for i in 0..n {
                out.force[i] = match self.set[i] {
                    2 => fy,
                    _ => 0.0,
                };
            }
            for (q, &i) in self.idx.iter().enumerate() {
                out.force[i] = self.rhs[q];
            }
            // Check and update the sets.
            let mut changed = false;
            for i in 0..n {
                let f = out.force[i];
                let next = match self.set[i] {
                    1 => {
                        if f < 0.0 {
                            0
                        } else if f > fy {
                            2
                        } else {
                            1
                        }
                    }
                    s => {
                        // Remaining interference r_i = o_i − (M f)_i.
                        let mut mf = f / out.stiffness[i];
                        for j in 0..n {
                            mf += c[i + j * n] * out.force[j];
                        }
                        let r = out.contact_at[i] - b - mf;
                        match s {
                            0 if r > 0.0 => 1,
                            2 if r < 0.0 => 1,
                            _ => s,
                        }
                    }
                };
                if next != self.set[i] {
                    self.set[i] = next;
                    changed = true;
                }
            }
            if !changed {
                let total: f64 = out.force.iter().sum();
                return Ok((total, slope));
            }
        }
        Err(Error::NotConverged {
            what: "coupled rods: active set at fixed position",
            iterations: ACTIVE_SET_MAX_ITERATIONS,
            residual: f64::NAN,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problem<'a>(a: &'a [f64], y: &'a [f64], k: &'a [f64], p: f64, c: f64) -> Problem<'a> {
        Problem {
            a,
            y,
            k,
            fy: 1.0,
            p,
            c,
            b0: 0.0,
        }
    }

    #[test]
    fn sweep_walk_and_bisection_agree() {
        // Three rods, F_y = 1: onsets a, yields y = a − 1/k.
        let a = [0.3, -0.2, 0.05];
        let k = [2.0, 5.0, 1.0];
        let y: Vec<f64> = a.iter().zip(&k).map(|(a, k)| a - 1.0 / k).collect();
        let mut events = vec![(0.0, 0); 6];
        for (p, c) in [(0.4, 0.0), (1.7, 0.0), (2.9, 0.0), (0.0, 3.0), (0.0, 0.5)] {
            let pr = problem(&a, &y, &k, p, c);
            let (m, _) = pr.sweep(&mut events);
            let b = pr.finish(m);
            // Bisection on the monotone residual.
            let (mut lo, mut hi) = (-10.0, 10.0);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if pr.residual(mid, pr.force(mid)) >= 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            assert!((b - lo).abs() < 1e-14, "p {p} c {c}: {b} vs {lo}");
            for start in [-3.0, -0.5, 0.0, 0.1, 2.0] {
                if let Some((m, _)) = pr.walk(start, 8) {
                    assert!((pr.finish(m) - b).abs() < 1e-14);
                }
            }
        }
    }

    #[test]
    fn redistribution_shares_sum_exactly() {
        let centers: Vec<f64> = (0..7).map(|i| i as f64 * 1e-6).collect();
        let yielded = [false, true, true, false, false, true, false];
        for rule in [
            PlasticUpdate::NearestNeighbours,
            PlasticUpdate::Gaussian { width: 2e-6 },
        ] {
            let mut h = vec![0.0; 7];
            redistribute(2, 0.3e-7, &centers, &yielded, rule, &mut h);
            let total: f64 = h.iter().sum();
            assert!((total - 0.3e-7).abs() <= 1e-22, "{rule:?}");
            assert!(yielded.iter().zip(&h).all(|(y, h)| !y || *h == 0.0));
        }
        // Nearest: rods 0 and 3 are the nearest non-yielded on each side.
        let mut h = vec![0.0; 7];
        redistribute(
            2,
            1.0,
            &centers,
            &yielded,
            PlasticUpdate::NearestNeighbours,
            &mut h,
        );
        assert_eq!(h, vec![0.5, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0]);
        // Nobody left unyielded: uniform rise.
        let mut h = vec![0.0; 3];
        redistribute(
            1,
            3.0,
            &centers[..3],
            &[true; 3],
            PlasticUpdate::NearestNeighbours,
            &mut h,
        );
        assert_eq!(h, vec![1.0, 1.0, 1.0]);
    }
}
