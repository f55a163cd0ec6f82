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
//!    of the micro-asperities", 6.3 input list). Past the profile's end the
//!    [`TrackEnd`] option decides: an error naming `position`
//!    ([`TrackEnd::Error`], the default) or a periodic counter-surface of
//!    period n·dx ([`TrackEnd::Periodic`], sample n wraps to sample 0);
//! 2. solves the rod equilibrium ([`RodBed::solve_gap`] /
//!    [`RodBed::solve_load`], thesis (6-9)..(6-16)), warm-started from the
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
//! [`Slider::step_flat`] is the whole slider as the friction law of one
//! surface patch of an FE (or DEM) host: a pure function of the slider, a
//! caller-owned flat state of `f64`s ([`Slider::state_len`] = 8 + 2n values
//! for n rods; all-zero = fresh; layout in [`Slider::state_len`]) and a
//! [`SliderIncrement`] — the increment's normal load or gap (or the slider's
//! own loading), its 2-D slip vector and time increment, the tangents
//! wanted — to the new state and a [`SliderResponse`]: tangential force
//! opposing the slip, normal force, μ, dissipation by mechanism, true
//! contact area, counts of contacts, and finite-difference tangents dF/dN
//! and dF/dΔs when asked. A fresh state is seated first (as
//! [`Slider::seat`]); a zero slip increment is stick (force 0, nothing
//! dissipated); the slider advances along its track by the slip path
//! length |Δs|. [`Slider::step_flat_block`] steps n patches in the shape of
//! Abaqus VFRIC. [`Slider::step_loaded`] and [`Slider::seat_loaded`] take the
//! loading per call, so one slider serves patches under different loads.
//!
//! # Memory
//!
//! [`Slider`] is immutable and `Send + Sync`. The caller owns the state
//! ([`SliderState`] or the flat state, old and new separate) and the work
//! buffers ([`SliderWork`], built once by [`Slider::work`], one per thread);
//! [`Slider::step`] and [`Slider::step_flat`] do not allocate (tested with a
//! counting allocator).
//!
//! # Mismatched profiles
//!
//! The counter-surface may be sampled at another spacing than the rods
//! (it is interpolated). With [`TrackEnd::Error`] it must lie under the whole
//! slider at position 0 (else [`Slider::new`] names `counter.len()`); a
//! shorter one needs [`TrackEnd::Periodic`].

// Rod arrays (counter heights, overlaps, yield flags) are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

use super::geometry::{SliderGeometry, MAX_NANO_PER_ROD};
use super::homogenised::{FrictionRegime, HomogenisedFriction, HomogenisedSample};
use super::ledger::{coefficient_of_friction, ledger_step, CofForm, Dissipation, Mechanisms};
use super::mechanisms::{FrictionMaterial, NanoAsperityBonds};
/// How the slider is loaded: a rod-bed boundary condition, defined with the
/// rods (thesis 6.3, 6.4).
pub use super::rods::Loading;
use super::rods::{RodBed, RodOptions, RodReport, RodSolution, RodState};
use crate::contact::BatchError;
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
        }
    }
}

/// The state of a slider, owned by the caller: the rods' history and the
/// slider's position along the track.
#[derive(Debug, Clone, PartialEq)]
pub struct SliderState {
    /// Rod heights, stored energies and last equilibrium position.
    pub rod: RodState,
    /// Position X of the slider along the track (m): rod i's centre is over
    /// the counter-surface at x_i + X.
    pub position: f64,
}

/// Work buffers of [`Slider::step`], built once by [`Slider::work`].
#[derive(Debug, Clone, PartialEq)]
pub struct SliderWork {
    /// Per-rod results of the last solve.
    pub solution: RodSolution,
    counter: Vec<f64>,
    flat: FlatWork,
}

impl SliderWork {
    /// Counter-surface heights under the rod centres at the last step (m).
    pub fn counter(&self) -> &[f64] {
        &self.counter
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

    /// A fresh state at track position 0.
    pub fn fresh_state(&self) -> SliderState {
        SliderState {
            rod: self.bed.state(),
            position: 0.0,
        }
    }

    /// Work buffers for [`Self::step`] and [`Self::step_flat`] (one per
    /// thread).
    pub fn work(&self) -> SliderWork {
        let fresh = self.fresh_state();
        SliderWork {
            solution: self.bed.solution(),
            counter: vec![0.0; self.bed.len()],
            flat: FlatWork {
                base: fresh.clone(),
                new: fresh.clone(),
                trial: fresh,
            },
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

    /// The equilibrium at the state's own position, with nothing booked: the
    /// slider is put down on the counter-surface before sliding. Its plastic
    /// work is the initial indentation, not friction. Writes `new`.
    pub fn seat(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        work: &mut SliderWork,
    ) -> Result<SlideStep> {
        let loading = self.options.loading;
        self.evaluate(old, new, old.position, None, loading, work)
    }

    /// [`Self::seat`] under `loading` instead of the slider's own (a
    /// per-increment normal load or gap, e.g. from an FE host), without
    /// building a new slider.
    ///
    /// Errors: a fixed `load` not finite, negative or above
    /// [`Self::capacity`]; a fixed-gap `position` not finite; the errors of
    /// [`Self::step`].
    pub fn seat_loaded(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        loading: Loading,
        work: &mut SliderWork,
    ) -> Result<SlideStep> {
        check_loading(loading, self.capacity(), "load", "position")?;
        self.evaluate(old, new, old.position, None, loading, work)
    }

    /// One increment: the slider moves by `slip` Δx (m, finite and > 0)
    /// along the track from `old`; the result is written into `new` (which
    /// may be a clone of `old`, and is overwritten) and returned. See the
    /// module docs. No allocation.
    ///
    /// Errors (named): `slip`; `position` past the counter profile with
    /// [`TrackEnd::Error`]; a state of the wrong size or with invalid
    /// heights (`state.heights`, …, see [`RodBed::solve_load`]); `work`
    /// buffers of another slider (`solution.len()`).
    pub fn step(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        slip: f64,
        work: &mut SliderWork,
    ) -> Result<SlideStep> {
        let loading = self.options.loading;
        self.step_unchecked(old, new, slip, loading, work)
    }

    /// [`Self::step`] under `loading` instead of the slider's own (the
    /// normal load or gap of this increment), without building a new
    /// slider. No allocation.
    ///
    /// Errors: those of [`Self::seat_loaded`] and [`Self::step`].
    pub fn step_loaded(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        slip: f64,
        loading: Loading,
        work: &mut SliderWork,
    ) -> Result<SlideStep> {
        check_loading(loading, self.capacity(), "load", "position")?;
        self.step_unchecked(old, new, slip, loading, work)
    }

    fn step_unchecked(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        slip: f64,
        loading: Loading,
        work: &mut SliderWork,
    ) -> Result<SlideStep> {
        check::positive("slip", slip)?;
        check::finite("state.position", old.position)?;
        let position = old.position + slip;
        check::finite("position", position)?;
        self.evaluate(old, new, position, Some(slip), loading, work)
    }

    fn evaluate(
        &self,
        old: &SliderState,
        new: &mut SliderState,
        position: f64,
        slip: Option<f64>,
        loading: Loading,
        work: &mut SliderWork,
    ) -> Result<SlideStep> {
        self.evaluate_in(
            old,
            new,
            position,
            slip,
            loading,
            &mut work.solution,
            &mut work.counter,
        )
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
            counter[i] = self.counter_at(centers[i] + position)?;
        }
        let opts = &self.options.rod;
        let report: RodReport = match loading {
            Loading::FixedGap { position: b0 } => {
                self.bed
                    .solve_gap(&old.rod, &mut new.rod, counter, b0, opts, solution)?
            }
            Loading::FixedLoad { load } => {
                self.bed
                    .solve_load(&old.rod, &mut new.rod, counter, load, opts, solution)?
            }
        };
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
    /// seated at position 0 ([`Self::seat`], not booked). No-contact
    /// increments give friction 0, μ = 0 and [`SlideStep::no_contact`].
    ///
    /// Errors: `distance`, `step` not finite and > 0; more than
    /// [`MAX_STEPS`] increments (`step`); the errors of [`Self::step`].
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
        let mut work = self.work();
        let fresh = self.fresh_state();
        let mut a = fresh.clone();
        self.seat(&fresh, &mut a, &mut work)?;
        let mut b = a.clone();
        let mut records = Vec::with_capacity(n);
        for k in 0..n {
            let r = self.step(&a, &mut b, dx, &mut work)?;
            records.push(r);
            core::mem::swap(&mut a, &mut b);
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

// ------------------------------------------------------ the flat step

/// Which finite-difference tangents [`Slider::step_flat`] computes. Each
/// costs two more evaluations of the increment; nothing is computed that is
/// not asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SliderTangents {
    /// dF/dN: the tangential force's derivative in the normal load.
    pub normal: bool,
    /// dF/dΔs: its derivative in the slip increment.
    pub slip: bool,
}

/// cbindgen:ignore
///
/// The flags as bits (the C ABI's form; its constants are
/// `ASPERITY_SLIDER_TANGENT_*`).
impl SliderTangents {
    /// Bit of [`Self::normal`] in [`Self::bits`] and
    /// [`SliderResponse::tangents`].
    pub const NORMAL: i32 = 1;
    /// Bit of [`Self::slip`].
    pub const SLIP: i32 = 2;
    /// Both tangents.
    pub const fn all() -> Self {
        Self {
            normal: true,
            slip: true,
        }
    }
    /// The set as bits ([`Self::NORMAL`] | [`Self::SLIP`]).
    pub const fn bits(self) -> i32 {
        ((self.normal as i32) * Self::NORMAL) | ((self.slip as i32) * Self::SLIP)
    }
    /// The set from bits; any other bit is an error naming `tangents`.
    pub fn from_bits(bits: i32) -> Result<Self> {
        if bits & !(Self::NORMAL | Self::SLIP) != 0 {
            return Err(Error::UnknownSelector {
                name: "tangents",
                value: bits as i64,
            });
        }
        Ok(Self {
            normal: bits & Self::NORMAL != 0,
            slip: bits & Self::SLIP != 0,
        })
    }
}

/// One time increment of a slider patch (SI); see [`Slider::step_flat`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SliderIncrement {
    /// The normal load or gap of this increment; `None`: the slider's own
    /// loading ([`SliderOptions::loading`], e.g. the scene's). A fixed load
    /// must be finite, ≥ 0 and ≤ [`Slider::capacity`] (errors name
    /// `normal_force`); a fixed-gap position finite (errors name `gap`).
    pub loading: Option<Loading>,
    /// Slip increment Δs of the patch relative to the counter-surface (m),
    /// two components in the caller's tangent basis, finite; a track uses
    /// `[Δx, 0]`.
    pub slip: [f64; 2],
    /// Time increment (s), finite and ≥ 0; validated, otherwise unused (the
    /// law is rate independent).
    pub dt: f64,
    /// Tangents wanted.
    pub tangents: SliderTangents,
}

/// The response of one [`Slider::step_flat`] (SI; the C ABI's
/// `AsperitySliderResponse`). A plain `repr(C)` value.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SliderResponse {
    /// Tangential force on the patch from the counter-surface (N), in the
    /// basis of the slip increment: F = −F_t Δs/|Δs|, opposing slip; 0 for
    /// a zero slip increment.
    pub force: [f64; 2],
    /// Its magnitude, the friction force F_t = ΔU/|Δs| (N), thesis (4-1);
    /// 0 for a zero slip increment.
    pub friction_force: f64,
    /// Normal load N carried by the rods (N): the given load, or at a fixed
    /// gap the rods' total force.
    pub normal_force: f64,
    /// Coefficient of friction in the slider's COF form; 0 when undefined
    /// (`regime` no contact) and for a zero slip increment.
    pub cof: f64,
    /// Adhesive holding force A = N_c F_adh,1 (N), 4.4.
    pub adhesion: f64,
    /// Energy dissipated in the increment ΔU (J), ≥ 0.
    pub dissipated: f64,
    /// ΔU by mechanism (J), each ≥ 0.
    pub dissipation: Dissipation,
    /// True contact area N_c·w_vdW² (m²), thesis 6.5.3.
    pub true_contact_area: f64,
    /// Fraction of the nano-asperities in contact touching only thanks to
    /// adhesion, in [0, 1].
    pub adhesion_area_share: f64,
    /// Slider position X along its track after the increment (m).
    pub position: f64,
    /// Rod-bed position b after the increment (m).
    pub rod_position: f64,
    /// Slip path length of the increment |Δs| (m): the distance the slider
    /// advanced along its track.
    pub slip_length: f64,
    /// dF/dN (dimensionless), a finite-difference secant (see
    /// [`Slider::step_flat`]); 0 unless asked for.
    pub dforce_dnormal: [f64; 2],
    /// dF_i/dΔs_j (N/m), `dforce_dslip[i][j]`; 0 unless asked for, and for
    /// a zero slip increment (rigid stick: unbounded).
    pub dforce_dslip: [[f64; 2]; 2],
    /// Nano-asperities in contact N_c.
    pub nano_contacts: u64,
    /// Of those, in contact only thanks to adhesion.
    pub adhesive_contacts: u64,
    /// Rods carrying force.
    pub rods_in_contact: u64,
    /// Rods at the yield force.
    pub yielded_rods: u64,
    /// [`FrictionRegime`] as an integer: 0 stick (zero slip increment), 1
    /// slip, 2 no contact (μ undefined: N + A ≤ 0 for Derjaguin, N ≤ 0
    /// otherwise; friction 0 unless rods leaving contact release energy).
    pub regime: i32,
    /// 1 when this call seated a fresh state first, else 0.
    pub seated: i32,
    /// The tangents computed, as bits: 1 dF/dN (`ASPERITY_SLIDER_TANGENT_NORMAL`),
    /// 2 dF/dΔs (`ASPERITY_SLIDER_TANGENT_SLIP`); [`SliderTangents::bits`].
    pub tangents: i32,
    /// Reserved, always 0.
    pub reserved: i32,
}

impl SliderResponse {
    /// The regime of the step.
    pub fn regime(&self) -> FrictionRegime {
        match self.regime {
            0 => FrictionRegime::Stick,
            1 => FrictionRegime::Slip,
            _ => FrictionRegime::NoContact,
        }
    }
}

/// The per-point states of [`Slider::step_flat_block`]: n flat states of
/// [`Slider::state_len`] values each, back to back.
#[derive(Debug)]
pub enum SliderStates<'a> {
    /// Old states read, new states written.
    Separate {
        /// States before the increment.
        old: &'a [f64],
        /// States after the increment.
        new: &'a mut [f64],
    },
    /// States stepped in place.
    InPlace(&'a mut [f64]),
}

/// Scratch states of the flat step, kept at capacity.
#[derive(Debug, Clone, PartialEq)]
struct FlatWork {
    base: SliderState,
    new: SliderState,
    trial: SliderState,
}

/// Accumulators of a flat state.
#[derive(Debug, Clone, Copy)]
struct Ledger {
    path: f64,
    dissipation: Dissipation,
}

/// cbindgen:ignore
///
/// The layout of a flat state ([`Slider::state_len`]; the C constants are
/// `ASPERITY_SLIDER_STATE_*`) and the tangent step.
impl Slider {
    /// Index of the flag of a flat state: 0 fresh, 1 stepped.
    pub const STATE_FLAG: usize = 0;
    /// Index of the slider position X along the track (m).
    pub const STATE_POSITION: usize = 1;
    /// Index of the rod-bed position b of the last equilibrium (m; NaN:
    /// none, no warm start).
    pub const STATE_ROD_POSITION: usize = 2;
    /// Index of the accumulated slip path Σ|Δs| (m).
    pub const STATE_SLIP_PATH: usize = 3;
    /// Index of the accumulated dissipation by mechanism (J): chemical, van
    /// der Waals, elastic, plastic.
    pub const STATE_DISSIPATION: usize = 4;
    /// Index of the rod heights H_i (m, n values), followed by the rods'
    /// stored elastic energies (J, n values).
    pub const STATE_HEIGHTS: usize = 8;
    /// Relative step of the finite-difference tangents.
    pub const TANGENT_STEP: f64 = 1e-2;
}

impl Slider {
    /// Number of `f64`s of a flat state: 8 + 2n for n rods. Layout:
    ///
    /// | index | content |
    /// |---|---|
    /// | 0 ([`Self::STATE_FLAG`]) | 0 fresh, 1 stepped |
    /// | 1 ([`Self::STATE_POSITION`]) | slider position X along the track (m) |
    /// | 2 ([`Self::STATE_ROD_POSITION`]) | rod-bed position b (m), NaN when none |
    /// | 3 ([`Self::STATE_SLIP_PATH`]) | accumulated slip path Σ\|Δs\| (m) |
    /// | 4..8 ([`Self::STATE_DISSIPATION`]) | accumulated dissipation: chemical, van der Waals, elastic, plastic (J) |
    /// | 8..8+n ([`Self::STATE_HEIGHTS`]) | rod heights H_i (m) |
    /// | 8+n..8+2n | rods' stored elastic energies (J) |
    ///
    /// An all-zero state is fresh. Of a fresh state (flag 0) only the
    /// position X is read: the host may set it to place patches at different
    /// points of the counter-surface; the rods start from the slider's
    /// heights with nothing stored or booked.
    pub fn state_len(&self) -> usize {
        Self::STATE_HEIGHTS + 2 * self.bed.len()
    }

    /// A [`SliderState`] from a flat state (allocates; for inspection, not
    /// the hot path). A fresh flat state gives [`Self::fresh_state`] at its
    /// position. Errors as [`Self::step_flat`] for `old_state`.
    pub fn state_from_flat(&self, flat: &[f64]) -> Result<SliderState> {
        self.check_state_len("old_state.len()", flat.len())?;
        let mut s = self.fresh_state();
        self.read_flat(flat, &mut s)?;
        Ok(s)
    }

    /// Writes `state` into the flat state `flat` (flag 1, accumulators 0).
    /// Errors: `flat.len()` ≠ [`Self::state_len`]; a state of another bed
    /// (`state.heights.len()`, `state.energy.len()`).
    pub fn state_to_flat(&self, state: &SliderState, flat: &mut [f64]) -> Result<()> {
        self.check_state_len("flat.len()", flat.len())?;
        let n = self.bed.len();
        for (name, v) in [
            ("state.heights.len()", state.rod.heights.len()),
            ("state.energy.len()", state.rod.energy.len()),
        ] {
            if v != n {
                return Err(invalid(name, v as f64, "equal to the number of rods"));
            }
        }
        let zero = Ledger {
            path: 0.0,
            dissipation: Dissipation::default(),
        };
        self.write_flat(state, &zero, flat);
        Ok(())
    }

    fn check_state_len(&self, name: &'static str, len: usize) -> Result<()> {
        if len == self.state_len() {
            Ok(())
        } else {
            Err(invalid(
                name,
                len as f64,
                "equal to Slider::state_len() (8 + 2 x the number of rods)",
            ))
        }
    }

    /// Reads a flat state (length checked) into `st` (vectors reused);
    /// returns whether it is fresh and its accumulators.
    fn read_flat(&self, flat: &[f64], st: &mut SliderState) -> Result<(bool, Ledger)> {
        let n = self.bed.len();
        let flag = flat[Self::STATE_FLAG];
        st.position = check::finite("old_state.position", flat[Self::STATE_POSITION])?;
        st.rod.heights.clear();
        st.rod.energy.clear();
        if flag == 0.0 {
            st.rod.heights.extend_from_slice(self.bed.heights());
            st.rod.energy.resize(n, 0.0);
            st.rod.position = None;
            let ledger = Ledger {
                path: 0.0,
                dissipation: Dissipation::default(),
            };
            return Ok((true, ledger));
        }
        if flag != 1.0 {
            return Err(invalid("old_state.flag", flag, "0 (fresh) or 1 (stepped)"));
        }
        let b = flat[Self::STATE_ROD_POSITION];
        st.rod.position = if b.is_nan() {
            None
        } else {
            Some(check::finite("old_state.rod_position", b)?)
        };
        let path = check::non_negative("old_state.slip_path", flat[Self::STATE_SLIP_PATH])?;
        let d = &flat[Self::STATE_DISSIPATION..Self::STATE_HEIGHTS];
        for &v in d {
            check::non_negative("old_state.dissipation", v)?;
        }
        let h = Self::STATE_HEIGHTS;
        st.rod.heights.extend_from_slice(&flat[h..h + n]);
        st.rod.energy.extend_from_slice(&flat[h + n..h + 2 * n]);
        let dissipation = Dissipation {
            chemical: d[0],
            van_der_waals: d[1],
            elastic: d[2],
            plastic: d[3],
        };
        Ok((false, Ledger { path, dissipation }))
    }

    /// Writes `st` and `ledger` into `flat` (length checked by the caller).
    fn write_flat(&self, st: &SliderState, ledger: &Ledger, flat: &mut [f64]) {
        let n = self.bed.len();
        let d = &ledger.dissipation;
        flat[Self::STATE_FLAG] = 1.0;
        flat[Self::STATE_POSITION] = st.position;
        flat[Self::STATE_ROD_POSITION] = st.rod.position.unwrap_or(f64::NAN);
        flat[Self::STATE_SLIP_PATH] = ledger.path;
        flat[Self::STATE_DISSIPATION..Self::STATE_HEIGHTS].copy_from_slice(&[
            d.chemical,
            d.van_der_waals,
            d.elastic,
            d.plastic,
        ]);
        let h = Self::STATE_HEIGHTS;
        flat[h..h + n].copy_from_slice(&st.rod.heights);
        flat[h + n..h + 2 * n].copy_from_slice(&st.rod.energy);
    }

    /// The friction step per time increment of a slider patch: a pure
    /// function of the slider, the caller's flat state `old`
    /// ([`Self::state_len`] values, layout there; all-zero = fresh) and the
    /// increment `inc`, writing the state after the increment into `new` and
    /// returning the response. `old` is only read, so an increment can be
    /// re-evaluated or cut back (the same `old` and `inc` give bit-identical
    /// results); [`Self::step_flat_in_place`] overwrites one state. No
    /// allocation once `work` ([`Self::work`]) exists; use one `work` per
    /// thread.
    ///
    /// # The increment
    ///
    /// * Loading: `inc.loading`, or the slider's own when `None`. An FE host
    ///   gives the normal force on the patch each increment
    ///   ([`Loading::FixedLoad`]; the patch is the whole slider, nominal area
    ///   [`Self::nominal_area`]).
    /// * A **fresh** state is first seated at its position X under this
    ///   loading (the rod equilibrium, nothing booked: [`Self::seat`]);
    ///   [`SliderResponse::seated`] says so. Then the step proceeds from the
    ///   seated state.
    /// * Slip: the slider advances along its track by the path length
    ///   s = |Δs| whatever the direction of Δs: the counter-surface profile is
    ///   read as a statistically isotropic sample of the counter-surface, so
    ///   a reversal meets fresh counter asperities, not the groove just
    ///   made. The increment is [`Self::step_loaded`] by s, and the
    ///   tangential force F = −F_t Δs/|Δs| opposes the slip (the sign
    ///   convention of [`super::homogenised`] and Abaqus VFRIC). Slip along a
    ///   track: `[Δx, 0]`, Δx > 0, reproduces [`Self::slide`] bit for bit.
    /// * **Zero slip** (Δs = 0) is stick: the rods re-equilibrate at X
    ///   under the increment's loading with nothing booked (a normal loading
    ///   step, as a seat), the tangential force, μ and the dissipation are 0
    ///   and [`SliderResponse::regime`] is stick (no contact when N + A = 0).
    ///   A rigid–plastic law has no force at zero slip; 0 is the lower end
    ///   of VFRIC's admissible range [0, stick force].
    ///
    /// # Tangents
    ///
    /// Asked for by `inc.tangents` (each costs two more evaluations), from
    /// the same old (seated) state, as finite-difference **secants** of a
    /// piecewise-smooth law (the count of nano-asperities in contact jumps,
    /// rods enter contact and yield): with h = [`Self::TANGENT_STEP`],
    ///
    /// * dF/dN = −u (F_t(N₊) − F_t(N₋))/(N₊ − N₋), u = Δs/|Δs|, at fixed
    ///   load N± = N ± h·max(N, h·capacity) clipped to [0, capacity] (at a
    ///   fixed gap, around the load the gap gives);
    /// * dF_i/dΔs_j = −[F_t′ u_i u_j + (F_t/s)(δ_ij − u_i u_j)], F_t′ =
    ///   (F_t(s + hs) − F_t(s − hs))/(2hs) (backward, (F_t(s) −
    ///   F_t(s − hs))/(hs), when s + hs runs past the counter profile's
    ///   end); the second term turns the force with the slip direction.
    ///
    /// Both are 0 for a zero slip increment. [`SliderWork::solution`] then
    /// holds the last tangent evaluation, not the step's.
    ///
    /// # Errors
    ///
    /// Named, with `new` untouched: `old_state.len()`, `new_state.len()`;
    /// `slip` not finite (or |Δs| overflowing); `dt` not finite and ≥ 0;
    /// `normal_force` (a fixed load not finite, negative or above the
    /// capacity), `gap` not finite; `old_state.flag` not 0 or 1;
    /// `old_state.position`, `old_state.rod_position` (finite, or NaN for
    /// none), `old_state.slip_path`, `old_state.dissipation` (finite and
    /// ≥ 0); `state.heights`, `state.energy` (see [`RodBed::solve_load`]);
    /// `position` past the counter profile with [`TrackEnd::Error`].
    pub fn step_flat(
        &self,
        old: &[f64],
        new: &mut [f64],
        inc: &SliderIncrement,
        work: &mut SliderWork,
    ) -> Result<SliderResponse> {
        self.check_state_len("new_state.len()", new.len())?;
        let (r, ledger) = self.flat_core(old, inc, work)?;
        self.write_flat(&work.flat.new, &ledger, new);
        Ok(r)
    }

    /// [`Self::step_flat`] writing the new state over the old one (what a
    /// host does once an increment is accepted). On error `state` is
    /// untouched.
    pub fn step_flat_in_place(
        &self,
        state: &mut [f64],
        inc: &SliderIncrement,
        work: &mut SliderWork,
    ) -> Result<SliderResponse> {
        let (r, ledger) = self.flat_core(state, inc, work)?;
        self.write_flat(&work.flat.new, &ledger, state);
        Ok(r)
    }

    fn flat_core(
        &self,
        old: &[f64],
        inc: &SliderIncrement,
        work: &mut SliderWork,
    ) -> Result<(SliderResponse, Ledger)> {
        self.check_state_len("old_state.len()", old.len())?;
        let sx = check::finite("slip", inc.slip[0])?;
        let sy = check::finite("slip", inc.slip[1])?;
        check::non_negative("dt", inc.dt)?;
        let loading = match inc.loading {
            None => self.options.loading,
            Some(l) => check_loading(l, self.capacity(), "normal_force", "gap")?,
        };
        let s = sx.hypot(sy);
        if !s.is_finite() {
            return Err(Error::OutOfDomain {
                name: "slip",
                value: sx.abs().max(sy.abs()),
                reason: "|slip| overflows f64",
            });
        }
        let SliderWork {
            solution,
            counter,
            flat,
        } = work;
        let FlatWork { base, new, trial } = flat;
        let (fresh, mut ledger) = self.read_flat(old, base)?;
        let x = base.position;
        let end = x + s;
        check::finite("position", end)?;
        let rec = if fresh {
            let seat = self.evaluate_in(base, new, x, None, loading, solution, counter)?;
            if s == 0.0 {
                seat
            } else {
                core::mem::swap(base, new);
                self.evaluate_in(base, new, end, Some(s), loading, solution, counter)?
            }
        } else if s == 0.0 {
            self.evaluate_in(base, new, x, None, loading, solution, counter)?
        } else {
            self.evaluate_in(base, new, end, Some(s), loading, solution, counter)?
        };
        let mut r = SliderResponse {
            friction_force: rec.friction_force,
            normal_force: rec.normal_load,
            cof: rec.cof,
            adhesion: rec.adhesion,
            dissipated: rec.dissipation.total(),
            dissipation: rec.dissipation,
            true_contact_area: rec.true_contact_area,
            adhesion_area_share: rec.adhesion_area_share,
            position: rec.position,
            rod_position: rec.rod_position,
            slip_length: s,
            nano_contacts: rec.nano_contacts as u64,
            adhesive_contacts: rec.adhesive_contacts as u64,
            rods_in_contact: rec.rods_in_contact as u64,
            yielded_rods: rec.yielded_rods as u64,
            seated: fresh as i32,
            ..SliderResponse::default()
        };
        if s == 0.0 {
            r.regime = if rec.normal_load + rec.adhesion > 0.0 {
                FrictionRegime::Stick as i32
            } else {
                FrictionRegime::NoContact as i32
            };
            return Ok((r, ledger));
        }
        r.regime = if rec.no_contact {
            FrictionRegime::NoContact as i32
        } else {
            FrictionRegime::Slip as i32
        };
        let u = [sx / s, sy / s];
        let ft = rec.friction_force;
        r.force = [-ft * u[0], -ft * u[1]];
        ledger.path += s;
        ledger.dissipation += rec.dissipation;

        let h = Self::TANGENT_STEP;
        if inc.tangents.normal {
            let cap = self.capacity();
            let n0 = rec.normal_load;
            let dn = h * n0.max(h * cap);
            let (lo, hi) = ((n0 - dn).max(0.0), (n0 + dn).min(cap));
            let mut at = |load: f64| -> Result<f64> {
                let l = Loading::FixedLoad { load };
                Ok(self
                    .evaluate_in(base, trial, end, Some(s), l, solution, counter)?
                    .friction_force)
            };
            let d = if hi > lo {
                (at(hi)? - at(lo)?) / (hi - lo)
            } else {
                0.0
            };
            r.dforce_dnormal = [-d * u[0], -d * u[1]];
            r.tangents |= SliderTangents::NORMAL;
        }
        if inc.tangents.slip {
            let ds = h * s;
            let mut at = |slip: f64| -> Result<f64> {
                Ok(self
                    .evaluate_in(
                        base,
                        trial,
                        x + slip,
                        Some(slip),
                        loading,
                        solution,
                        counter,
                    )?
                    .friction_force)
            };
            let (fp, sp) = match at(s + ds) {
                Ok(f) => (f, s + ds),
                Err(Error::OutOfDomain {
                    name: "position", ..
                }) => (ft, s),
                Err(e) => return Err(e),
            };
            let fm = at(s - ds)?;
            let dft = (fp - fm) / (sp - (s - ds));
            let turn = ft / s;
            for i in 0..2 {
                for j in 0..2 {
                    let delta = if i == j { 1.0 } else { 0.0 };
                    r.dforce_dslip[i][j] = -(dft * u[i] * u[j] + turn * (delta - u[i] * u[j]));
                }
            }
            r.tangents |= SliderTangents::SLIP;
        }
        Ok((r, ledger))
    }

    /// [`Self::step_flat`] for n patches at once, in the shape of
    /// Abaqus/Explicit's VFRIC (as
    /// [`HomogenisedFriction::step_block`]): the normal force on patch i
    /// `normal_force[i]` (N, a fixed load of this increment), its slip
    /// increment `slip[2i], [2i+1]` (m, interleaved), one `dt` (s), the
    /// states ([`SliderStates`], n·[`Self::state_len`] values), the
    /// tangential forces out in `tangential_force[2i], [2i+1]` (N,
    /// interleaved, opposing slip) and, when given, the dissipation of the
    /// increment in `dissipation[i]` (J). No tangents. n is
    /// `normal_force.len()`; the other slices must match (an error naming
    /// the slice at index 0). On an error at element i, elements before i are
    /// written and those from i on untouched. No allocation.
    #[allow(clippy::too_many_arguments)]
    pub fn step_flat_block(
        &self,
        normal_force: &[f64],
        slip: &[f64],
        dt: f64,
        states: SliderStates<'_>,
        tangential_force: &mut [f64],
        mut dissipation: Option<&mut [f64]>,
        work: &mut SliderWork,
    ) -> core::result::Result<(), BatchError> {
        let n = normal_force.len();
        let len = self.state_len();
        let check = |name: &'static str, got: usize, want: usize, bound: &'static str| {
            if got == want {
                Ok(())
            } else {
                Err(BatchError {
                    index: 0,
                    error: invalid(name, got as f64, bound),
                })
            }
        };
        const TWICE: &str = "twice the length of normal_force (x, y interleaved)";
        const STATES: &str = "the length of normal_force times Slider::state_len()";
        check("slip.len()", slip.len(), 2 * n, TWICE)?;
        check(
            "tangential_force.len()",
            tangential_force.len(),
            2 * n,
            TWICE,
        )?;
        if let Some(d) = dissipation.as_deref() {
            check(
                "dissipation.len()",
                d.len(),
                n,
                "the length of normal_force",
            )?;
        }
        let mut states = states;
        match &mut states {
            SliderStates::Separate { old, new } => {
                check("old_state.len()", old.len(), n * len, STATES)?;
                check("new_state.len()", new.len(), n * len, STATES)?;
            }
            SliderStates::InPlace(s) => check("state.len()", s.len(), n * len, STATES)?,
        }
        for i in 0..n {
            let inc = SliderIncrement {
                loading: Some(Loading::FixedLoad {
                    load: normal_force[i],
                }),
                slip: [slip[2 * i], slip[2 * i + 1]],
                dt,
                tangents: SliderTangents::default(),
            };
            let range = i * len..(i + 1) * len;
            let at = |error| BatchError { index: i, error };
            let r = match &mut states {
                SliderStates::Separate { old, new } => {
                    self.step_flat(&old[range.clone()], &mut new[range], &inc, work)
                }
                SliderStates::InPlace(s) => self.step_flat_in_place(&mut s[range], &inc, work),
            }
            .map_err(at)?;
            tangential_force[2 * i] = r.force[0];
            tangential_force[2 * i + 1] = r.force[1];
            if let Some(d) = dissipation.as_deref_mut() {
                d[i] = r.dissipated;
            }
        }
        Ok(())
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
