//! The hierarchical slider that slides (thesis chapter 6, 6.3–6.5): micro-rods
//! with nano-asperities on their tips, pressed against a rigid counter-surface
//! profile at fixed gap or fixed load, moved along the track in increments,
//! with the energy ledger of every increment.
//!
//! # One step
//!
//! [`Slider::step`] moves the slider by a slip Δx (m) along the track and
//!
//! 1. interpolates the counter-surface under every rod centre at the new
//!    position: g_i = g(x_i + X), X the slider position, g the counter profile
//!    (heights m, spacing m, sample j at x = j·dx), linearly between samples
//!    (the thesis's h_i, "the heights of the asperities corresponding to each
//!    of the micro-asperities", 6.3 input list); [`CounterHeight`] can take
//!    the highest counter point under the rod's face instead. Past the profile's end the
//!    [`TrackEnd`] option decides: an error naming `position`
//!    ([`TrackEnd::Error`], the default) or a periodic counter-surface of
//!    period n·dx ([`TrackEnd::Periodic`], sample n wraps to sample 0);
//! 2. solves the rod equilibrium ([`RodBed::solve`] under the increment's
//!    [`Loading`], thesis (6-9)..(6-16)), warm-started from the
//!    old state's position, with volume-conserving plasticity (6.2.3);
//! 3. counts the nano-asperities in contact (thesis 4.2, 4.3.1 and 6.3: "we
//!    determine which of the nano-asperities are within the adhesive layer
//!    and thus brought into contact by the van der Waals forces", 6.3;
//!    "when one micro-asperity deforms plastically, all nano-asperities on
//!    its tip establish contact", 6.5.1);
//! 4. books the increment with [`ledger_step`] (REFERENCE.md §5 "per-step
//!    ledger"): chemical and van der Waals bonds of the nano-asperities in
//!    contact (4-6..4-9), plastic work of the rods yielding (4-16) and the
//!    elastic energy released by rods unloading (4-15); F = ΔU/Δx (4-1) and
//!    μ in the chosen [`CofForm`] (Derjaguin μ = F/(N + A), (4-3), by
//!    default, A = N_c F_adh,1).
//!
//! # The nano-asperities of a rod
//!
//! The counter-surface is a profile extruded in depth ("The support surface
//! is extruded to a depth equal to the width of the micro-asperity", 6.5),
//! so its height varies along the sliding direction only. A rod of
//! width w (along the track) and depth D carries m_x × m_y nano-asperities,
//! m_x = ⌊w/λ⌋ columns along the track and m_y = ⌊D/λ⌋ rows in depth (λ the
//! nano-asperity spacing, (6-3); for a square tip this is
//! [`nano_per_rod`](super::geometry::nano_per_rod)). Column j sits at the
//! centre of its cell, x_ij = x_i − w/2 + (j + ½)·w/m_x, and all m_y
//! nano-asperities of a column see the same counter height g(x_ij).
//!
//! The nano-asperity tips of rod i form its flat face. In the frame of
//! [`super::rods`] (upward heights), the face is at
//! t_i = g_i + max(−o_i, 0): on the counter-surface at the rod centre when
//! the rod is in contact (overlap o_i > 0), at its free height b − H_i
//! otherwise. The separation of column j is s_ij = t_i − g(x_ij). A
//! nano-asperity is **in contact** when s_ij ≤ the adhesive layer (5 nm for
//! copper), and every nano-asperity of a yielded rod is in contact. Those with
//! 0 < s_ij ≤ layer on a rod that did not yield are in contact **only thanks
//! to adhesion** (snap-in, thesis 4.2): they make the adhesion share of the
//! true contact area (Figure 6-59). A column with s_ij ≤ 0 (the counter
//! rises above the face, away from the rod centre) counts as mechanical
//! contact: the rod model sees the counter at the rod centre only.
//!
//! The nano-asperities are elastic–perfectly rigid (4.3.2, threshold strain
//! 10 %): at the rod scale they are rigid, their compliance being lumped in
//! the rod (the thesis's rod stiffness (4-10) is the only compliance of
//! (6-12)/(6-16)).
//!
//! # True contact area (thesis 6.5.3)
//!
//! "The true contact area was obtained by multiplying the area of the van der
//! Waals interaction domain of one nano-asperity with the number of
//! nano-asperities in contact": A_r = N_c·w_vdW² (m²).
//! That definition is used here; [`SlideStep::adhesion_area_share`] is the
//! fraction of N_c in contact only thanks to adhesion.
//!
//! # Rod sections and root depth
//!
//! Rod i has section w × D (m²). D defaults to w (square rods, the
//! ten 13.5 µm rods of 6.5); the thesis's fine discretisation keeps the
//! slider's depth at 13.5 µm while narrowing the rods to 1.5 µm (A_m =
//! 20.25 µm² = 1.5 µm × 13.5 µm, Table 6-2), so give
//! [`SliderOptions::depth`] = 13.5 µm there. The [`RodBed`] takes square
//! sections, so the bed is built with the equivalent side √(wD) (same area,
//! hence the same stiffness EA/L and yield force σ_y A).
//!
//! The rods are rooted in the bulk at depth d below the slider's mean line:
//! d = max(0, −min_i H_i) + margin, i.e. the deepest rod (valley) of the
//! slider profile plus a margin, [`SliderOptions::root_margin`], by default
//! the tip width w (so the shortest rod has length ≥ w). The rod modulus is
//! the effective modulus of (6-8), 1/E = 1/E₁ + 1/E₂, of the material's slider
//! and counter-surface moduli ("The slider reflects the mechanical
//! characteristics for the rubbing pair", 6.2.2).
//!
//! # The step per time increment of a host code
//!
//! The slider implements [`FrictionLaw`]: the whole slider as the friction
//! law of one surface patch of an FE (or DEM) host, a pure function of the
//! slider, a caller-owned state of `f64`s (9 + 2n values for n rods;
//! all-zero = fresh; layout at [`FrictionLaw for Slider`](Slider#impl-FrictionLaw-for-Slider))
//! and a [`FrictionIncrement`](super::FrictionIncrement) (normal load, 2-D slip, time increment,
//! tangents wanted) to the new state and a [`FrictionResponse`](super::FrictionResponse): tangential
//! force opposing the slip, μ, adhesion, dissipation by mechanism, true
//! contact area, stored energy and finite-difference tangents when asked.
//! A fresh state is seated first; a zero slip increment is stick; the
//! slider advances along its track by the slip path length |Δs|. The full
//! record of a step (positions, counts of contacts) is
//! [`SliderWork::record`]. [`Slider::slide`] runs the same step along the
//! track under the slider's own loading (fixed load or fixed gap).
//!
//! # Memory
//!
//! [`Slider`] is immutable and `Send + Sync`. The caller owns the state (old
//! and new separate, or stepped in place) and the work
//! ([`FrictionLaw::work`], one per thread); a step does not allocate once the
//! work exists (tested with a counting allocator).
//!
//! # Mismatched profiles
//!
//! The counter-surface may be sampled at another spacing than the rods
//! (it is interpolated). With [`TrackEnd::Error`] it must lie under the whole
//! slider at position 0 (else [`Slider::new`] names `counter.len()`); a
//! shorter one needs [`TrackEnd::Periodic`].

// Rod arrays (counter heights, overlaps, yield flags) are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

mod patch;

use super::geometry::{SliderGeometry, MAX_NANO_PER_ROD};
use super::homogenised::{HomogenisedFriction, HomogenisedSample};
use super::law::FrictionLaw;
use super::ledger::{coefficient_of_friction, ledger_step, CofForm, Dissipation, Mechanisms};
use super::mechanisms::{FrictionMaterial, NanoAsperityBonds};
/// How the slider is loaded: a rod-bed boundary condition, defined with the
/// rods (thesis 6.3, 6.4).
pub use super::rods::Loading;
use super::rods::{RodBed, RodOptions, RodReport, RodSolution, RodState};
use crate::error::{check, Error, Result};
use crate::material::rod_effective_modulus;
use serde::{Deserialize, Serialize};

/// Relative slack when counting whole nano-asperity cells on a rod.
const COUNT_SLACK: f64 = 1e-9;
/// Largest number of steps [`Slider::slide`] accepts.
pub const MAX_STEPS: usize = 10_000_000;

/// What the counter-surface is past the end of its profile.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TrackEnd {
    /// A rod or nano-asperity past the sampled profile [0, (n−1)·dx] is an
    /// error naming `position` (the default).
    #[default]
    Error,
    /// The counter-surface repeats with period n·dx (sample n is sample 0).
    Periodic,
}

/// Which height of the counter-surface under a rod's flat face the rod
/// equilibrium sees (the h_i of the thesis's compatibility conditions (6-11),
/// (6-15), "the heights of the asperities corresponding to each of the
/// micro-asperities").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CounterHeight {
    /// The counter height at the rod centre, linear between samples: for a
    /// rod one sample wide the mean of the two samples it spans, the thesis's
    /// rule (6-1) for the slider's own rods applied to the counter-surface
    /// (the default). Where the counter rises above the face away from the
    /// centre the face and the counter overlap; those nano-asperity columns
    /// count as in contact.
    #[default]
    RodCentre,
    /// Not stated by the thesis: the highest counter height under the face
    /// (the samples inside it and the interpolated ends), so that the rigid
    /// counter-surface never passes through a rod's flat face. A rod then
    /// touches at its highest counter point and only the nano-asperity
    /// columns within the adhesive layer of that point are in contact;
    /// wider rods touch with a smaller share of their columns (the study of
    /// thesis Table 6-3 in `examples/chapter6.rs`).
    HighestPoint,
}

/// Options of a [`Slider`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderOptions {
    /// Fixed gap or fixed load.
    pub loading: Loading,
    /// Rod solver, warm start and plastic update (defaults of [`RodOptions`]).
    pub rod: RodOptions,
    /// Which dissipation mechanisms are computed (default all).
    pub mechanisms: Mechanisms,
    /// The form of μ (default Derjaguin, (4-3)).
    pub cof_form: CofForm,
    /// Depth D of the rods across the track (m); `None` = square rods
    /// (D = w).
    pub depth: Option<f64>,
    /// Margin of the root depth below the deepest rod (m, ≥ 0); `None` = the
    /// tip width w.
    pub root_margin: Option<f64>,
    /// Counter-surface past its end (default [`TrackEnd::Error`]).
    pub track_end: TrackEnd,
    /// The counter height a rod sees (default [`CounterHeight::RodCentre`]).
    pub counter_height: CounterHeight,
}

impl SliderOptions {
    /// Defaults with the given loading.
    pub fn new(loading: Loading) -> Self {
        Self {
            loading,
            rod: RodOptions::default(),
            mechanisms: Mechanisms::all(),
            cof_form: CofForm::Derjaguin,
            depth: None,
            root_margin: None,
            track_end: TrackEnd::Error,
            counter_height: CounterHeight::RodCentre,
        }
    }
}

/// A slider state unpacked from its flat form (the caller's state, layout
/// at [`Slider::STATE_FLAG`]) into the rod bed's terms.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SliderState {
    /// Rod heights, stored energies and last equilibrium position.
    pub(crate) rod: RodState,
    /// Position X of the slider along the track (m): rod i's centre is over
    /// the counter-surface at x_i + X.
    pub(crate) position: f64,
}

/// Scratch of a slider's step, kept at capacity (inside the
/// [`FrictionWork`](super::FrictionWork) of [`FrictionLaw::work`]); after a step it also holds
/// that step's full record.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderWork {
    solution: RodSolution,
    counter: Vec<f64>,
    base: SliderState,
    new: SliderState,
    trial: SliderState,
    record: SlideStep,
    seated: bool,
}

impl SliderWork {
    /// Per-rod results of the last solve.
    pub fn solution(&self) -> &RodSolution {
        &self.solution
    }
    /// Counter-surface heights under the rod centres at the last solve (m).
    pub fn counter(&self) -> &[f64] {
        &self.counter
    }
    /// The full record of the last step (position, rod-bed position, counts
    /// of nano-asperities and rods, …); with tangents asked for, still the
    /// step's own, not a tangent evaluation's.
    pub fn record(&self) -> &SlideStep {
        &self.record
    }
    /// Whether the last step seated a fresh state first.
    pub fn seated(&self) -> bool {
        self.seated
    }
}

/// The record of one increment (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct SlideStep {
    /// Slider position X along the track after the increment (m).
    pub position: f64,
    /// Rod-bed position b: height of the slider's mean line above the
    /// counter-surface's mean line (m).
    pub rod_position: f64,
    /// Normal load N carried by the rods (N).
    pub normal_load: f64,
    /// Friction force F = ΔU/Δx (N), (4-1).
    pub friction_force: f64,
    /// Coefficient of friction in the slider's [`CofForm`]; 0 when
    /// [`Self::no_contact`].
    pub cof: f64,
    /// Whether μ is undefined (N + A ≤ 0 for Derjaguin, N ≤ 0 otherwise):
    /// then `cof` = 0, never NaN.
    pub no_contact: bool,
    /// Adhesive holding force A = N_c F_adh,1 (N), 4.4.
    pub adhesion: f64,
    /// Energy dissipated in the increment, by mechanism (J), each ≥ 0.
    pub dissipation: Dissipation,
    /// True contact area N_c·w_vdW² (m²), thesis 6.5.3.
    pub true_contact_area: f64,
    /// Fraction of the nano-asperities in contact that touch only thanks to
    /// adhesion (snap-in within the adhesive layer), in [0, 1]; 0 without
    /// contact.
    pub adhesion_area_share: f64,
    /// Nano-asperities in contact N_c.
    pub nano_contacts: usize,
    /// Of those, in contact only thanks to adhesion.
    pub adhesive_contacts: usize,
    /// Rods carrying force.
    pub rods_in_contact: usize,
    /// Rods at the yield force.
    pub yielded_rods: usize,
}

/// Averages and totals of a run (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct SlideSummary {
    /// Number of increments.
    pub steps: usize,
    /// Distance slid (m).
    pub distance: f64,
    /// Mean μ over all increments (no-contact increments count as 0).
    pub mean_cof: f64,
    /// Mean friction force (N) = total dissipation / distance.
    pub mean_friction_force: f64,
    /// Mean normal load (N).
    pub normal_load: f64,
    /// Total dissipation by mechanism (J).
    pub dissipation: Dissipation,
    /// Mean dissipation per increment (J).
    pub mean_step_dissipation: f64,
    /// Mean true contact area (m²).
    pub mean_true_contact_area: f64,
    /// Mean adhesion share of the true contact area (over increments with
    /// contact).
    pub mean_adhesion_area_share: f64,
    /// Mean number of nano-asperities in contact.
    pub mean_nano_contacts: f64,
    /// Increments without contact (μ undefined, reported 0).
    pub no_contact_steps: usize,
    /// Largest number of yielded rods in one increment.
    pub max_yielded_rods: usize,
}

/// A run: every increment and the summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SlideRun {
    /// Records of the increments, in order.
    pub steps: Vec<SlideStep>,
    /// Averages and totals.
    pub summary: SlideSummary,
}

/// The hierarchical slider against a rigid counter-surface profile (see the
/// module docs). Immutable, `Send + Sync`.
#[derive(Debug, Clone, PartialEq)]
pub struct Slider {
    geometry: SliderGeometry,
    material: FrictionMaterial,
    counter: Vec<f64>,
    counter_dx: f64,
    bed: RodBed,
    bonds: NanoAsperityBonds,
    options: SliderOptions,
    tip_width: f64,
    depth: f64,
    columns: usize,
    rows: usize,
}

fn invalid(name: &'static str, value: f64, bound: &'static str) -> Error {
    Error::InvalidArgument { name, value, bound }
}

/// Validates a loading against the bed's `capacity` (N); errors name
/// `load_name` (a fixed load not finite, negative or above the capacity)
/// or `gap_name` (a fixed-gap position not finite).
fn check_loading(
    loading: Loading,
    capacity: f64,
    load_name: &'static str,
    gap_name: &'static str,
) -> Result<Loading> {
    match loading {
        Loading::FixedGap { position } => {
            check::finite(gap_name, position)?;
        }
        Loading::FixedLoad { load } => {
            check::non_negative(load_name, load)?;
            if load > capacity {
                return Err(Error::OutOfDomain {
                    name: load_name,
                    value: load,
                    reason: "above the capacity of the rods n*sigma_y*A: no equilibrium (the slider would flow without bound)",
                });
            }
        }
    }
    Ok(loading)
}

impl Slider {
    /// A slider of `geometry` (its finest level are the rods) and `material`
    /// against the rigid counter-surface `counter` (heights from its mean
    /// line, m, ≥ 2 samples) sampled at `counter_dx` (m), with `options`.
    ///
    /// Errors (named): `counter_dx` not finite and > 0; `counter.len()` < 2,
    /// or (with [`TrackEnd::Error`]) too short to lie under the whole slider
    /// at position 0; a non-finite `counter`; the material ([`FrictionMaterial::validate`]);
    /// `depth` or `root_margin` not finite and > 0 (≥ 0 for the margin);
    /// `depth` narrower than the nano-asperity spacing; more than
    /// [`MAX_NANO_PER_ROD`]
    /// nano-asperities per rod, ⌊w/λ⌋·⌊D/λ⌋ (`depth` when the depth makes
    /// the excess, `spacing` otherwise); a fixed-gap
    /// `position` not finite; a fixed `load` not finite, negative or above
    /// the bed's capacity ([`Error::OutOfDomain`]); a Gaussian plastic
    /// `width` not finite and > 0.
    pub fn new(
        geometry: SliderGeometry,
        material: FrictionMaterial,
        counter: Vec<f64>,
        counter_dx: f64,
        options: SliderOptions,
    ) -> Result<Self> {
        check::positive("counter_dx", counter_dx)?;
        if counter.len() < 2 {
            return Err(invalid(
                "counter.len()",
                counter.len() as f64,
                ">= 2 points",
            ));
        }
        for &g in &counter {
            check::finite("counter", g)?;
        }
        material.validate()?;
        let bonds = NanoAsperityBonds::new(&material, geometry.nano())?;
        let tips = geometry.tips();
        let w = tips.width();
        let depth = match options.depth {
            None => w,
            Some(d) => check::positive("depth", d)?,
        };
        let margin = match options.root_margin {
            None => w,
            Some(m) => check::non_negative("root_margin", m)?,
        };
        let spacing = geometry.nano().spacing;
        // Counted in f64: a spacing far below the width or depth would
        // saturate a usize cast and overflow m_x·m_y.
        let columns = (w / spacing * (1.0 + COUNT_SLACK)).floor().max(1.0);
        let rows = (depth / spacing * (1.0 + COUNT_SLACK)).floor();
        if rows < 1.0 {
            return Err(invalid(
                "depth",
                depth,
                ">= the nano-asperity spacing (a rod must carry a nano-asperity)",
            ));
        }
        if columns * rows > MAX_NANO_PER_ROD as f64 {
            // The depth when a square tip would be within the bound.
            let square = columns * columns <= MAX_NANO_PER_ROD as f64;
            let (name, value) = if options.depth.is_some() && square {
                ("depth", depth)
            } else {
                ("spacing", spacing)
            };
            return Err(invalid(
                name,
                value,
                "at most MAX_NANO_PER_ROD = 2^24 nano-asperities per rod, floor(width/spacing) * floor(depth/spacing) (a nano-asperity spacing far below the rod width or depth)",
            ));
        }
        let (columns, rows) = (columns as usize, rows as usize);
        let heights = tips.heights().to_vec();
        let deepest = heights.iter().copied().fold(f64::INFINITY, f64::min);
        let root_depth = (-deepest).max(0.0) + margin;
        if root_depth <= 0.0 {
            return Err(invalid(
                "root_margin",
                margin,
                "> 0 when no rod lies below the mean line",
            ));
        }
        let centers = (0..tips.len()).map(|k| tips.center(k)).collect();
        let modulus =
            rod_effective_modulus(material.youngs_modulus, material.counter_youngs_modulus)?;
        let bed = RodBed::new(
            (w * depth).sqrt(),
            centers,
            heights,
            root_depth,
            modulus,
            material.yield_stress,
        )?;
        check_loading(options.loading, bed.capacity(), "load", "position")?;
        if options.track_end == TrackEnd::Error {
            // Mismatched profile lengths: the counter-surface must lie under
            // every nano-asperity column of the slider at position 0.
            let cell = w / columns as f64;
            let first = tips.center(0) - 0.5 * w + 0.5 * cell;
            let last = tips.center(tips.len() - 1) + 0.5 * w - 0.5 * cell;
            let end = (counter.len() - 1) as f64 * counter_dx;
            if first < 0.0 || last > end * (1.0 + COUNT_SLACK) {
                return Err(invalid(
                    "counter.len()",
                    counter.len() as f64,
                    "enough samples for the counter-surface to lie under the whole slider at position 0 ((len - 1)*counter_dx >= the slider's length), or TrackEnd::Periodic",
                ));
            }
        }
        if let super::rods::PlasticUpdate::Gaussian { width } = options.rod.plastic {
            check::positive("width", width)?;
        }
        Ok(Self {
            geometry,
            material,
            counter,
            counter_dx,
            bed,
            bonds,
            options,
            tip_width: w,
            depth,
            columns,
            rows,
        })
    }

    /// The slider geometry.
    pub fn geometry(&self) -> &SliderGeometry {
        &self.geometry
    }
    /// The material.
    pub fn material(&self) -> &FrictionMaterial {
        &self.material
    }
    /// The options.
    pub fn options(&self) -> &SliderOptions {
        &self.options
    }
    /// The rod bed (equivalent square side √(wD), see the module docs).
    pub fn bed(&self) -> &RodBed {
        &self.bed
    }
    /// Counter-surface heights (m).
    pub fn counter(&self) -> &[f64] {
        &self.counter
    }
    /// Counter-surface spacing (m).
    pub fn counter_dx(&self) -> f64 {
        self.counter_dx
    }
    /// Bond counts, dissipation per slip and holding force of one
    /// nano-asperity.
    pub fn bonds(&self) -> &NanoAsperityBonds {
        &self.bonds
    }
    /// Rod width w along the track (m).
    pub fn rod_width(&self) -> f64 {
        self.tip_width
    }
    /// Rod depth D across the track (m).
    pub fn depth(&self) -> f64 {
        self.depth
    }
    /// Number of rods.
    pub fn rods(&self) -> usize {
        self.bed.len()
    }
    /// Nano-asperities per rod m_x·m_y.
    pub fn nano_per_rod(&self) -> usize {
        self.columns * self.rows
    }
    /// Nominal area of the slider n·w·D (m²).
    pub fn nominal_area(&self) -> f64 {
        self.bed.len() as f64 * self.tip_width * self.depth
    }
    /// Load capacity n·σ_y·w·D (N).
    pub fn capacity(&self) -> f64 {
        self.bed.capacity()
    }

    fn fresh_state(&self) -> SliderState {
        SliderState {
            rod: self.bed.state(),
            position: 0.0,
        }
    }

    /// Scratch for [`Self::slide`]'s and the friction step's solves.
    fn buffers(&self) -> SliderWork {
        let fresh = self.fresh_state();
        SliderWork {
            solution: self.bed.solution(),
            counter: vec![0.0; self.bed.len()],
            base: fresh.clone(),
            new: fresh.clone(),
            trial: fresh,
            record: SlideStep::default(),
            seated: false,
        }
    }

    /// Counter height at track coordinate `x` (m), linear between samples.
    fn counter_at(&self, x: f64) -> Result<f64> {
        let n = self.counter.len();
        let t = x / self.counter_dx;
        let t = match self.options.track_end {
            TrackEnd::Periodic => {
                let p = n as f64;
                let r = t.rem_euclid(p);
                if r >= p {
                    0.0
                } else {
                    r
                }
            }
            TrackEnd::Error => {
                if !(t >= 0.0 && t <= (n - 1) as f64 * (1.0 + COUNT_SLACK)) {
                    return Err(Error::OutOfDomain {
                        name: "position",
                        value: x,
                        reason: "a rod lies past the end of the counter-surface profile (use a longer profile or TrackEnd::Periodic)",
                    });
                }
                t.min((n - 1) as f64)
            }
        };
        let j = (t.floor() as usize).min(n - 1);
        let f = t - j as f64;
        let a = self.counter[j];
        let b = if j + 1 < n {
            self.counter[j + 1]
        } else {
            self.counter[0]
        };
        Ok(a + f * (b - a))
    }

    /// The counter height the rod centred at track coordinate `x` (m) sees,
    /// by [`SliderOptions::counter_height`].
    fn counter_under(&self, x: f64) -> Result<f64> {
        match self.options.counter_height {
            CounterHeight::RodCentre => self.counter_at(x),
            CounterHeight::HighestPoint => {
                let (a, b) = (x - 0.5 * self.tip_width, x + 0.5 * self.tip_width);
                let mut top = self.counter_at(a)?.max(self.counter_at(b)?);
                // Samples strictly inside the face (linear interpolation
                // peaks at samples only).
                let (first, last) = (
                    (a / self.counter_dx).floor() + 1.0,
                    (b / self.counter_dx).ceil() - 1.0,
                );
                let mut j = first;
                while j <= last {
                    top = top.max(self.counter_at(j * self.counter_dx)?);
                    j += 1.0;
                }
                Ok(top)
            }
        }
    }

    /// The body of every increment (module docs): counter heights, rod
    /// equilibrium under `loading`, nano-asperities in contact, the ledger
    /// when `slip` is given (nothing booked otherwise: a seat).
    #[allow(clippy::too_many_arguments)]
    fn evaluate_in(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        position: f64,
        slip: Option<f64>,
        loading: Loading,
        solution: &mut RodSolution,
        counter: &mut [f64],
    ) -> Result<SlideStep> {
        let n = self.bed.len();
        if counter.len() != n {
            return Err(invalid(
                "work.counter.len()",
                counter.len() as f64,
                "equal to the number of rods (build it with Slider::work)",
            ));
        }
        let centers = self.bed.centers();
        for i in 0..n {
            counter[i] = self.counter_under(centers[i] + position)?;
        }
        let opts = &self.options.rod;
        let report: RodReport =
            self.bed
                .solve(&old.rod, &mut new.rod, counter, loading, opts, solution)?;
        new.position = position;

        // Nano-asperities in contact (module docs).
        let layer = self.material.adhesive_layer;
        let w = self.tip_width;
        let cell = w / self.columns as f64;
        let overlaps = solution.overlaps();
        let yielded = solution.yielded();
        let (mut contact_cols, mut adhesive_cols) = (0usize, 0usize);
        for i in 0..n {
            if yielded[i] {
                contact_cols += self.columns;
                continue;
            }
            let face = counter[i] + (-overlaps[i]).max(0.0);
            let left = centers[i] + position - 0.5 * w;
            for j in 0..self.columns {
                let g = self.counter_at(left + (j as f64 + 0.5) * cell)?;
                let s = face - g;
                if s <= layer {
                    contact_cols += 1;
                    if s > 0.0 {
                        adhesive_cols += 1;
                    }
                }
            }
        }
        let nano_contacts = contact_cols * self.rows;
        let adhesive_contacts = adhesive_cols * self.rows;
        let normal_load = match loading {
            Loading::FixedGap { .. } => report.total_force,
            Loading::FixedLoad { load } => load,
        };
        let nano = self.geometry.nano();
        let true_contact_area = nano_contacts as f64 * nano.w_vdw * nano.w_vdw;
        let adhesion_area_share = if nano_contacts > 0 {
            adhesive_contacts as f64 / nano_contacts as f64
        } else {
            0.0
        };
        let adhesion = nano_contacts as f64 * self.bonds.holding_force();
        let mut record = SlideStep {
            position,
            rod_position: report.position,
            normal_load,
            friction_force: 0.0,
            cof: 0.0,
            no_contact: true,
            adhesion,
            dissipation: Dissipation::default(),
            true_contact_area,
            adhesion_area_share,
            nano_contacts,
            adhesive_contacts,
            rods_in_contact: report.in_contact,
            yielded_rods: report.yielded,
        };
        let Some(slip) = slip else {
            return Ok(record);
        };
        let ledger = ledger_step(
            &self.bonds,
            self.options.mechanisms,
            nano_contacts,
            slip,
            report.plastic_work,
            report.released_energy,
        )?;
        record.dissipation = ledger.dissipation;
        record.friction_force = ledger.friction_force;
        let denominator = match self.options.cof_form {
            CofForm::Derjaguin => normal_load + ledger.adhesion,
            CofForm::DerjaguinDoubleAdhesion => normal_load + 2.0 * ledger.adhesion,
            CofForm::Amontons | CofForm::Coulomb => normal_load,
        };
        if denominator > 0.0 {
            record.cof = ledger.cof(self.options.cof_form, normal_load)?;
            record.no_contact = false;
        }
        Ok(record)
    }

    /// Slides a fresh slider over `distance` (m, finite and > 0) in equal
    /// increments of about `step` (m, finite and > 0): n = round(distance /
    /// step) ≥ 1 increments of exactly distance/n. The slider is first
    /// seated at position 0 (the rod equilibrium there, not booked). No-contact
    /// increments give friction 0, μ = 0 and [`SlideStep::no_contact`].
    ///
    /// Errors: `distance`, `step` not finite and > 0; more than
    /// [`MAX_STEPS`] increments (`step`); the errors of the friction step
    /// ([`FrictionLaw for Slider`](Slider#impl-FrictionLaw-for-Slider)).
    pub fn slide(&self, distance: f64, step: f64) -> Result<SlideRun> {
        self.slide_with(distance, step, |_, _| {})
    }

    /// [`Self::slide`] calling `progress(k, n)` after increment k of n (for a
    /// progress bar).
    pub fn slide_with(
        &self,
        distance: f64,
        step: f64,
        mut progress: impl FnMut(usize, usize),
    ) -> Result<SlideRun> {
        check::positive("distance", distance)?;
        check::positive("step", step)?;
        let steps = (distance / step).round().max(1.0);
        if steps > MAX_STEPS as f64 {
            return Err(invalid(
                "step",
                step,
                "such that distance/step <= 1e7 increments",
            ));
        }
        let n = steps as usize;
        let dx = distance / n as f64;
        let mut work = self.buffers();
        let mut state = vec![0.0; self.state_len()];
        let mut records = Vec::with_capacity(n);
        for k in 0..n {
            self.flat_step(
                None,
                &mut state,
                [dx, 0.0],
                self.options.loading,
                0,
                &mut work,
            )?;
            records.push(work.record);
            progress(k + 1, n);
        }
        let summary = summarize(&records, distance);
        Ok(SlideRun {
            steps: records,
            summary,
        })
    }
}

impl Slider {
    /// The same slider under another loading (validated as in
    /// [`Self::new`]: a fixed load must lie within the bed's capacity).
    pub fn with_loading(&self, loading: Loading) -> Result<Slider> {
        let mut options = self.options;
        options.loading = loading;
        Slider::new(
            self.geometry.clone(),
            self.material,
            self.counter.clone(),
            self.counter_dx,
            options,
        )
    }

    /// The homogenised friction law of this slider for FE integration
    /// points: one run ([`Self::slide`] over `distance` in
    /// increments of `step`) at the fixed load p·A_n for each nominal
    /// pressure p of `pressures` (Pa, increasing, ≥ 0, each within the
    /// capacity σ_y·A_rods/A_n), tabulated by [`HomogenisedFriction`] in this
    /// slider's COF form.
    ///
    /// Each sample is built from the run's means so that the homogenised
    /// slip force reproduces the run's mean friction force: with F̄ the mean
    /// friction force (total dissipation / distance), N the load and Ā the
    /// mean adhesive holding force N_c·F_adh,1, μ = F̄/(N + Ā) (Derjaguin;
    /// F̄/N, (F̄ − Ā)/N for the other forms, [`coefficient_of_friction`]),
    /// adhesion pressure Ā/A_n, contact fraction = mean true contact area /
    /// A_n, and the dissipation shares of the run's totals. A run that
    /// dissipates nothing (no contact) gets μ = 0 and its shares all on the
    /// chemical bonds (they are then never used: the slip force is 0).
    ///
    /// Errors: the errors of [`Self::with_loading`], [`Self::slide`],
    /// [`coefficient_of_friction`] (a Coulomb or Amontons form at zero load)
    /// and [`HomogenisedFriction::from_fn`] (pressures not increasing).
    pub fn homogenise(
        &self,
        pressures: &[f64],
        distance: f64,
        step: f64,
    ) -> Result<HomogenisedFriction> {
        let area = self.nominal_area();
        let form = self.options.cof_form;
        HomogenisedFriction::from_fn(pressures, form, |p| {
            let load = p * area;
            let run = self
                .with_loading(Loading::FixedLoad { load })?
                .slide(distance, step)?;
            let sum = &run.summary;
            let n = run.steps.len().max(1) as f64;
            let adhesion = run.steps.iter().map(|r| r.adhesion).sum::<f64>() / n;
            let total = sum.dissipation.total();
            let (cof, shares) = if total > 0.0 {
                let d = sum.dissipation;
                (
                    coefficient_of_friction(form, sum.mean_friction_force, load, adhesion)?,
                    Dissipation {
                        chemical: d.chemical / total,
                        van_der_waals: d.van_der_waals / total,
                        elastic: d.elastic / total,
                        plastic: d.plastic / total,
                    },
                )
            } else {
                (
                    0.0,
                    Dissipation {
                        chemical: 1.0,
                        ..Dissipation::default()
                    },
                )
            };
            Ok(HomogenisedSample {
                pressure: p,
                cof,
                adhesion_pressure: adhesion / area,
                contact_fraction: (sum.mean_true_contact_area / area).min(1.0),
                shares,
            })
        })
    }
}

/// The summary of a list of increments over `distance` (m).
pub fn summarize(records: &[SlideStep], distance: f64) -> SlideSummary {
    let n = records.len();
    let mut s = SlideSummary {
        steps: n,
        distance,
        ..SlideSummary::default()
    };
    if n == 0 {
        return s;
    }
    let mut contact = 0usize;
    for r in records {
        s.mean_cof += r.cof;
        s.normal_load += r.normal_load;
        s.dissipation += r.dissipation;
        s.mean_true_contact_area += r.true_contact_area;
        s.mean_nano_contacts += r.nano_contacts as f64;
        if r.nano_contacts > 0 {
            s.mean_adhesion_area_share += r.adhesion_area_share;
            contact += 1;
        }
        if r.no_contact {
            s.no_contact_steps += 1;
        }
        s.max_yielded_rods = s.max_yielded_rods.max(r.yielded_rods);
    }
    let nf = n as f64;
    s.mean_cof /= nf;
    s.normal_load /= nf;
    s.mean_true_contact_area /= nf;
    s.mean_nano_contacts /= nf;
    if contact > 0 {
        s.mean_adhesion_area_share /= contact as f64;
    }
    s.mean_step_dissipation = s.dissipation.total() / nf;
    s.mean_friction_force = if distance > 0.0 {
        s.dissipation.total() / distance
    } else {
        0.0
    };
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn send_sync() {
        fn is<T: Send + Sync>() {}
        is::<Slider>();
        is::<SliderState>();
    }
}
