//! The slider as the friction law of a surface patch: the flat state's
//! layout and the [`FrictionLaw`] implementation (formulas and rules in the
//! documentation of `impl FrictionLaw for Slider`).

use super::{check_loading, invalid, Loading, Slider, SliderState, SliderWork};
use crate::error::{check, Error, Result};
use crate::friction::law::{
    FrictionIncrement, FrictionLaw, FrictionRegime, FrictionResponse, FrictionWork,
    STATE_DISSIPATION, STATE_MODEL, STATE_SLIP_PATH, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::friction::ledger::Dissipation;

/// Accumulators of a flat state.
#[derive(Debug, Clone, Copy)]
struct Ledger {
    total: f64,
    path: f64,
    dissipation: Dissipation,
}

/// The names of a state's fields in errors, for `old` or `state`.
fn state_names(what: &'static str) -> [&'static str; 5] {
    if what == "old" {
        [
            "old.flag",
            "old.position",
            "old.rod_position",
            "old.mechanisms",
            "old.len()",
        ]
    } else {
        [
            "state.flag",
            "state.position",
            "state.rod_position",
            "state.mechanisms",
            "state.len()",
        ]
    }
}

/// cbindgen:ignore
///
/// The layout of a state ([`Slider::state_len`]) and the tangent step.
impl Slider {
    /// Index of the flag: 0 fresh, 1 stepped.
    pub const STATE_FLAG: usize = STATE_MODEL;
    /// Index of the slider position X along the track (m).
    pub const STATE_POSITION: usize = STATE_MODEL + 1;
    /// Index of the rod-bed position b of the last equilibrium (m; NaN:
    /// none, no warm start).
    pub const STATE_ROD_POSITION: usize = STATE_MODEL + 2;
    /// Index of the accumulated dissipation by mechanism (J): chemical, van
    /// der Waals, elastic, plastic.
    pub const STATE_MECHANISMS: usize = STATE_MODEL + 3;
    /// Index of the rod heights H_i (m, n values), followed by the rods'
    /// stored elastic energies (J, n values).
    pub const STATE_HEIGHTS: usize = STATE_MODEL + 7;
    /// Relative step of the finite-difference tangents.
    pub const TANGENT_STEP: f64 = 1e-2;
}

impl Slider {
    /// Reads a state (length checked by the caller) into `st` (vectors
    /// reused); returns whether it is fresh and its accumulators.
    fn read_flat(
        &self,
        flat: &[f64],
        st: &mut SliderState,
        what: &'static str,
    ) -> Result<(bool, Ledger)> {
        let [n_flag, n_pos, n_rod, n_mech, _] = state_names(what);
        let n = self.bed.len();
        let flag = flat[Self::STATE_FLAG];
        st.position = check::finite(n_pos, flat[Self::STATE_POSITION])?;
        let d = &flat[Self::STATE_MECHANISMS..Self::STATE_HEIGHTS];
        for &v in d {
            check::non_negative(n_mech, v)?;
        }
        let ledger = Ledger {
            total: flat[STATE_DISSIPATION],
            path: flat[STATE_SLIP_PATH],
            dissipation: Dissipation {
                chemical: d[0],
                van_der_waals: d[1],
                elastic: d[2],
                plastic: d[3],
            },
        };
        st.rod.heights.clear();
        st.rod.energy.clear();
        if flag == 0.0 {
            st.rod.heights.extend_from_slice(self.bed.heights());
            st.rod.energy.resize(n, 0.0);
            st.rod.position = None;
            return Ok((true, ledger));
        }
        if flag != 1.0 {
            return Err(invalid(n_flag, flag, "0 (fresh) or 1 (stepped)"));
        }
        let b = flat[Self::STATE_ROD_POSITION];
        st.rod.position = if b.is_nan() {
            None
        } else {
            Some(check::finite(n_rod, b)?)
        };
        let h = Self::STATE_HEIGHTS;
        st.rod.heights.extend_from_slice(&flat[h..h + n]);
        st.rod.energy.extend_from_slice(&flat[h + n..h + 2 * n]);
        Ok((false, ledger))
    }

    /// Writes `st` and `ledger` into `flat` (length checked by the caller).
    fn write_flat(&self, st: &SliderState, ledger: &Ledger, flat: &mut [f64]) {
        let n = self.bed.len();
        let d = &ledger.dissipation;
        flat[STATE_DISSIPATION] = ledger.total;
        flat[STATE_SLIP_PATH] = ledger.path;
        flat[Self::STATE_FLAG] = 1.0;
        flat[Self::STATE_POSITION] = st.position;
        flat[Self::STATE_ROD_POSITION] = st.rod.position.unwrap_or(f64::NAN);
        flat[Self::STATE_MECHANISMS..Self::STATE_HEIGHTS].copy_from_slice(&[
            d.chemical,
            d.van_der_waals,
            d.elastic,
            d.plastic,
        ]);
        let h = Self::STATE_HEIGHTS;
        flat[h..h + n].copy_from_slice(&st.rod.heights);
        flat[h + n..h + 2 * n].copy_from_slice(&st.rod.energy);
    }

    /// One increment from `old` (`None`: `new` itself) into `new` under
    /// `loading` (checked), slip `slip` (finite), tangents `tangents`
    /// (known bits); see [`FrictionLaw for Slider`](Slider#impl-FrictionLaw-for-Slider).
    /// `new` is written only on success.
    pub(super) fn flat_step(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        slip: [f64; 2],
        loading: Loading,
        tangents: i32,
        work: &mut SliderWork,
    ) -> Result<FrictionResponse> {
        let what = if old.is_some() { "old" } else { "state" };
        let [sx, sy] = slip;
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
            base,
            new: next,
            trial,
            record,
            seated,
        } = work;
        let (fresh, mut ledger) = self.read_flat(old.unwrap_or(&*new), base, what)?;
        let x = base.position;
        let end = x + s;
        check::finite("position", end)?;
        let rec = if fresh {
            let seat = self.evaluate_in(base, next, x, None, loading, solution, counter)?;
            if s == 0.0 {
                seat
            } else {
                core::mem::swap(base, next);
                self.evaluate_in(base, next, end, Some(s), loading, solution, counter)?
            }
        } else if s == 0.0 {
            self.evaluate_in(base, next, x, None, loading, solution, counter)?
        } else {
            self.evaluate_in(base, next, end, Some(s), loading, solution, counter)?
        };
        let mut r = FrictionResponse {
            force_magnitude: rec.friction_force,
            normal_force: rec.normal_load,
            cof: rec.cof,
            adhesion: rec.adhesion,
            true_contact_area: rec.true_contact_area,
            dissipated: rec.dissipation.total(),
            dissipation: rec.dissipation,
            stored_energy: next.rod.energy.iter().sum(),
            ..FrictionResponse::default()
        };
        if s == 0.0 {
            r.regime = if rec.normal_load + rec.adhesion > 0.0 {
                FrictionRegime::Stick as i32
            } else {
                FrictionRegime::NoContact as i32
            };
        } else {
            r.regime = if rec.no_contact {
                FrictionRegime::NoContact as i32
            } else {
                FrictionRegime::Slip as i32
            };
            let u = [sx / s, sy / s];
            let ft = rec.friction_force;
            r.force = [-ft * u[0], -ft * u[1]];
            ledger.path += s;
            ledger.total += r.dissipated;
            ledger.dissipation += rec.dissipation;

            let h = Self::TANGENT_STEP;
            if tangents & TANGENT_NORMAL != 0 {
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
                r.tangents |= TANGENT_NORMAL;
            }
            if tangents & TANGENT_SLIP != 0 {
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
                r.tangents |= TANGENT_SLIP;
            }
        }
        *record = rec;
        *seated = fresh;
        self.write_flat(next, &ledger, new);
        Ok(r)
    }
}

/// The slider as the friction law of a patch (an FE contact facet, the
/// whole slider of nominal area [`Slider::nominal_area`]), per time
/// increment.
///
/// # State
///
/// [`Slider::state_len`] = 9 + 2n doubles for n rods:
///
/// | index | content |
/// |---|---|
/// | 0, 1 | the common accumulators: dissipation (J), slip path Σ\|Δs\| (m) |
/// | 2 ([`Slider::STATE_FLAG`]) | 0 fresh, 1 stepped |
/// | 3 ([`Slider::STATE_POSITION`]) | slider position X along the track (m) |
/// | 4 ([`Slider::STATE_ROD_POSITION`]) | rod-bed position b (m), NaN when none |
/// | 5..9 ([`Slider::STATE_MECHANISMS`]) | dissipation by mechanism: chemical, van der Waals, elastic, plastic (J) |
/// | 9..9+n ([`Slider::STATE_HEIGHTS`]) | rod heights H_i (m) |
/// | 9+n..9+2n | rods' stored elastic energies (J) |
///
/// An all-zero state is fresh; of a fresh state only the position X is
/// read (a host may set it to place patches at different points of the
/// counter-surface) and the accumulators (indices 0, 1, 5..9) are carried.
///
/// # The increment
///
/// * Loading: the fixed normal load N of the increment
///   ([`Loading::FixedLoad`], at most [`Slider::capacity`]; `area` is
///   unused, the patch is the slider).
/// * A **fresh** state is first seated at its position under this load
///   (the rod equilibrium, nothing booked); [`SliderWork::seated`] says so.
/// * Slip: the slider advances along its track by the path length
///   s = |Δs| whatever the direction of Δs: the counter-surface profile is
///   read as a statistically isotropic sample of the counter-surface, so a
///   reversal meets fresh counter asperities, not the groove just made. The
///   tangential force F = −F_t Δs/|Δs|, F_t = ΔU/s (thesis (4-1)), opposes
///   the slip. Slip along a track, `[Δx, 0]` with Δx > 0, under the
///   slider's own fixed load, reproduces [`Slider::slide`] bit for bit.
/// * **Zero slip** is stick: the rods re-equilibrate at X under the load
///   with nothing booked, force and dissipation 0 (no contact when
///   N + A = 0). 0 is the lower end of VFRIC's admissible range.
/// * The stored energy is the rods' elastic energy; the response's
///   adhesion A = N_c F_adh,1 and true contact area N_c w_vdW² (6.5.3);
///   the rest of the record (positions, counts) is [`SliderWork::record`].
///
/// # Tangents
///
/// Finite-difference **secants** of a piecewise-smooth law (the count of
/// nano-asperities in contact jumps, rods enter contact and yield), each
/// two more evaluations from the same old (seated) state, h =
/// [`Slider::TANGENT_STEP`]:
///
/// * ∂F/∂N = −u (F_t(N₊) − F_t(N₋))/(N₊ − N₋), u = Δs/|Δs|, N± = N ±
///   h·max(N, h·capacity) clipped to [0, capacity];
/// * ∂F_i/∂Δs_j = −[F_t′ u_i u_j + (F_t/s)(δ_ij − u_i u_j)], F_t′ =
///   (F_t(s + hs) − F_t(s − hs))/(2hs) (backward when s + hs runs past the
///   counter profile's end); the second term turns the force with the slip.
///
/// Both are 0 for a zero slip increment.
///
/// # Errors
///
/// Beyond the common ones: `normal_force` above the capacity; `old.flag`
/// not 0 or 1; `old.position`, `old.rod_position` (finite, or NaN for
/// none), `old.mechanisms` (≥ 0) (`state.…` in place); rod heights and
/// energies ([`RodBed::solve`](crate::friction::RodBed::solve)); `position` past the counter profile
/// with [`TrackEnd::Error`](super::TrackEnd::Error).
impl FrictionLaw for Slider {
    fn state_len(&self) -> usize {
        Self::STATE_HEIGHTS + 2 * self.bed.len()
    }

    fn work(&self) -> FrictionWork {
        FrictionWork::new(self.buffers())
    }

    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        let load = increment.normal_force;
        check_loading(
            Loading::FixedLoad { load },
            self.capacity(),
            "normal_force",
            "gap",
        )?;
        Ok(())
    }

    fn check_state(&self, _state: &[f64], _what: &'static str) -> Result<()> {
        // Checked as the state is read (the rod position may be NaN).
        Ok(())
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        inc: &FrictionIncrement,
        work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let n = self.bed.len();
        let work = work.get_or_make(
            |w: &SliderWork| w.counter.len() == n && w.solution.len() == n,
            || self.buffers(),
        );
        let loading = Loading::FixedLoad {
            load: inc.normal_force,
        };
        self.flat_step(old, new, inc.slip, loading, inc.tangents, work)
    }
}
