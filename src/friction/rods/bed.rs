//! The bed of independent elastic–perfectly plastic rods, [`RodBed`]
//! (thesis 4.3.1, 6.2.2–6.4; formulas in the module docs): construction and
//! input checks, the fixed-gap and fixed-load solves (the position itself
//! comes from `equilibrium.rs`), the plastic shortening and the
//! volume-conserving pile-up of 6.2.3, and the energies (4-15), (4-16).

// Rod arrays (heights, stiffnesses, onsets, forces) are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

use super::equilibrium::{rod_force, Balance, Problem};
use super::{
    Loading, PlasticUpdate, RodOptions, RodReport, RodSolution, RodSolver, RodState,
    WARM_WALK_LIMIT,
};
use crate::error::{check, Error, Result};
use crate::friction::geometry::{RodLevel, SliderGeometry};

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
    /// Errors as [`Self::solve`].
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

    /// The rod equilibrium under `loading`: a reading of `old`, per-rod
    /// results into `out`, the updated heights and energies into `new`
    /// (which may be a copy of `old`).
    ///
    /// * [`Loading::FixedGap`], thesis (6-9)..(6-12): the slider's mean line
    ///   prescribed at `position` b₀ (m) for an undeformed bulk (b = b₀ +
    ///   δ_B, δ_B = F/k_B; b = b₀ for a rigid bulk).
    /// * [`Loading::FixedLoad`], thesis (6-13)..(6-16): the position b at
    ///   which the rods carry `load` P (N). See the module docs for P = 0,
    ///   P = capacity and the warm start.
    ///
    /// Errors (named): `position` not finite; `load` not finite and ≥ 0;
    /// `load` above [`Self::capacity`] ([`Error::OutOfDomain`]);
    /// `counter.len()`, `state.heights.len()`, `state.energy.len()` ≠ n; a
    /// non-finite `counter`; a state height non-finite or with H_i + d ≤ 0
    /// (`state.heights`); a negative or non-finite `state.energy`; a
    /// non-finite `state.position`; `solution.len()` ≠ n; a Gaussian
    /// `width` not finite and > 0; a dense solve that does not converge
    /// ([`Error::NotConverged`]).
    pub fn solve(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        loading: Loading,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        check_loading(loading)?;
        self.solve_checked(old, new, counter, loading, options, out)
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

    /// Every input check of a solve (the errors listed at
    /// [`Self::solve`]).
    pub(super) fn check_all(
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
    pub(super) fn prepare(&self, old: &RodState, counter: &[f64], out: &mut RodSolution) {
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

    /// A fixed load above [`Self::capacity`] has no equilibrium: every rod
    /// yields and the bed would flow without bound.
    pub(super) fn check_capacity(&self, loading: Loading) -> Result<()> {
        match loading {
            Loading::FixedLoad { load } if load > self.capacity() => Err(Error::OutOfDomain {
                name: "load",
                value: load,
                reason: "exceeds the capacity n*sigma_y*A: every rod yields, no equilibrium",
            }),
            _ => Ok(()),
        }
    }

    fn solve_checked(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        loading: Loading,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        self.check_all(old, counter, options, out)?;
        self.check_capacity(loading)?;
        let fy = self.yield_force();
        self.prepare(old, counter, out);
        let problem = Problem {
            a: &out.contact_at,
            y: &out.yield_at,
            k: &out.stiffness,
            fy,
            eq: Balance::new(loading, self.bulk_stiffness),
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
        self.balance_report(loading, &mut report);
        self.check_crush(out, old, loading)?;
        self.commit(old, new, options, out, &mut report);
        new.position = Some(b);
        Ok(report)
    }

    /// Sets the bulk compression δ_B and the equilibrium residual of
    /// `report` from its position b and total force Σ f: fixed gap
    /// δ_B = b − b₀ and |Σ f − k_B·δ_B| (both 0 for a rigid bulk), thesis
    /// (6-9), (6-10); fixed load δ_B = P/k_B and |Σ f − P|, (6-13), (6-14).
    pub(super) fn balance_report(&self, loading: Loading, report: &mut RodReport) {
        let (b, total) = (report.position, report.total_force);
        let c = self.bulk_stiffness;
        match loading {
            Loading::FixedGap { position: b0 } => {
                let db = if c.is_finite() { b - b0 } else { 0.0 };
                report.bulk_compression = db;
                report.residual = if c.is_finite() {
                    (total - c * db).abs()
                } else {
                    0.0
                };
            }
            Loading::FixedLoad { load } => {
                report.bulk_compression = if c.is_finite() { load / c } else { 0.0 };
                report.residual = (total - load).abs();
            }
        }
    }

    /// A yielded rod whose overlap reaches its length would be crushed to
    /// its root by the plastic update: no meaningful state. The error names
    /// the prescribed `position` or `load`.
    pub(super) fn check_crush(
        &self,
        out: &RodSolution,
        old: &RodState,
        loading: Loading,
    ) -> Result<()> {
        let (name, value) = match loading {
            Loading::FixedGap { position } => ("position", position),
            Loading::FixedLoad { load } => ("load", load),
        };
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
    pub(super) fn commit(
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

/// The value checks of a loading: a finite position, a finite load ≥ 0.
pub(super) fn check_loading(loading: Loading) -> Result<()> {
    match loading {
        Loading::FixedGap { position } => check::finite("position", position).map(|_| ()),
        Loading::FixedLoad { load } => check::non_negative("load", load).map(|_| ()),
    }
}

#[cfg(test)]
mod tests {
    use super::redistribute;
    use crate::friction::rods::PlasticUpdate;

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
