//! Johnson–Kendall–Roberts: elastic sphere (paraboloid) with short-range
//! adhesion, the limit of large Tabor parameter.
//!
//! # Formulas
//!
//! Thesis (1-34)..(1-36); Johnson, Kendall & Roberts 1971, Proc. R. Soc. Lond.
//! A 324:301; written with the contact modulus E* (K = 4E*/3) and the work of
//! adhesion w. The equilibrium curve and its tangent stiffness
//! `dP/dδ = (dP/da)/(dδ/da)`:
//!
//! $$P(a) = \frac{4E^\ast a^3}{3R} - \sqrt{8\pi w E^\ast a^3}, \qquad \delta(a) = \frac{a^2}{R} - \sqrt{\frac{2\pi w a}{E^\ast}},$$
//!
//! $$\frac{dP}{d\delta} = 2E^\ast a\\,\frac{4a^{3/2} - 3kR}{4a^{3/2} - kR}, \qquad k = \sqrt{2\pi w/E^\ast} .$$
//!
//! The tangent stiffness is **not** the BASh value `2E*a` unless w = 0:
//! `2E*a` is `∂P/∂δ` at *fixed* contact radius (the adhesive term is a
//! flat-punch mode, `P_adh = 2E*a·δ_adh`), while along the equilibrium curve
//! the radius changes too. The tangent vanishes at the load-controlled pull-off
//! and is vertical (`dδ/da = 0`) at the displacement-controlled instability.
//!
//! Critical points (REFERENCE.md §1; Maugis 1992): the load-controlled
//! pull-off and the displacement-controlled instability,
//!
//! $$P_c = -\tfrac{3}{2}\pi w R \ \ \text{at}\ \ a = \left(\frac{9\pi w R^2}{8E^\ast}\right)^{1/3}, \qquad \delta_c = -\frac{3}{4}\left(\frac{\pi^2 w^2 R}{E^{\ast 2}}\right)^{1/3} \ \ \text{at}\ \ a = \left(\frac{\pi w R^2}{8E^\ast}\right)^{1/3}, \ \ P(\delta_c) = -\tfrac{5}{6}\pi w R .$$
//!
//! On approach the contact forms at δ = 0 with a jump to
//! $a = (2\pi w R^2/E^\ast)^{1/3}$ (force $-\tfrac{4}{3}\pi w R$); the
//! zero-load radius is $a_0 = (9\pi w R^2/(2E^\ast))^{1/3}$.
//!
//! # Hysteresis (displacement control, [`NormalContact::eval`])
//!
//! The caller-owned [`ContactState`] says whether the surfaces were in contact
//! at the end of the previous step. Out of contact (including the all-zero
//! fresh state), there is no force until δ ≥ 0, where the contact jumps in to
//! the stable branch. In contact, the contact follows the stable branch (the
//! largest root, `dδ/da > 0`) down to δ_c inclusive; below δ_c it jumps out
//! (force 0, `in_contact = 0`). `branch` is 1 in contact, 0 out.
//!
//! # Closed form for a(δ)
//!
//! With `y = √a` the equilibrium is the depressed quartic
//! `y⁴ − kR·y − δR = 0`. Scaling `y = (kR)^{1/3} η`, `δ = L Δ` with
//! `L = (kR)^{4/3}/R = (4π²w²R/E*²)^{1/3}` gives the universal quartic
//! `η⁴ − η − Δ = 0` (fold at `η³ = 1/4`, `Δ_c = −(3/4)·4^{−1/3}`). Ferrari:
//! `(η² + u)² = 2u(η + 1/(4u))²` when u solves the resolvent cubic
//! `u³ + Δu − 1/8 = 0`, i.e. `u³ + 3su − 2r = 0` with `s = Δ/3`, `r = 1/16`.
//! Its discriminant `r² + s³` is ≥ 0 exactly when `Δ ≥ Δ_c` (both vanish
//! together: the quartic has real roots iff the cubic has one real root), so
//! only Cardano's branch is ever needed on the equilibrium curve. Cardano's
//! `u = C − s/C`, `C = (r + √(r² + s³))^{1/3}`, cancels catastrophically for
//! large Δ; multiplying by `C⁴ + sC² + s²` and using `C⁶ − s³ = 2rC³` gives the
//! cancellation-free `u = 2rC²/(C⁴ + sC² + s²)` (the denominator is
//! `(C² + s/2)² + 3s²/4 > 0`). With `v = √(2u)` the stable root is
//! `η = (v + √(2/v − v²))/2`, polished by one Newton step on
//! `η⁴ − η − Δ`. Accuracy: ≤ 1e-13 relative against a bracketed reference
//! away from the fold (tests/jkr.rs); within `|Δ − Δ_c| ≲ 1e-3` the root
//! itself is ill-conditioned (`∂η/∂Δ → ∞`), as for any method.
//!
//! # References
//!
//! * Thesis (1-34)–(1-36).
//! * K. L. Johnson, K. Kendall, A. D. Roberts (1971), "Surface energy and the
//!   contact of elastic solids", Proc. R. Soc. Lond. A 324, 301–313,
//!   [doi:10.1098/rspa.1971.0141](https://doi.org/10.1098/rspa.1971.0141).
//! * D. Maugis (1992), "Adhesion of spheres: the JKR-DMT transition using a
//!   Dugdale model", J. Colloid Interface Sci. 150, 243–269 (critical points
//!   under both controls).

use super::batch::{BatchError, RawBatch};
use super::{check_delta, check_force, ContactState, Control, NormalContact, NormalResponse};
use crate::error::{check, Result};
use core::f64::consts::PI;

/// Above this reduced overlap Δ the adhesive correction (relative size
/// `Δ^{−3/4}`) is far below rounding and the Hertz value seeds the Newton step
/// (avoids overflow of `s³` in the resolvent).
pub(crate) const HERTZ_SWITCH: f64 = 1e60;

/// Inputs of a JKR sphere, as [`Jkr::from_params`] and C's
/// `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JkrParams {
    /// Sphere radius R (m, > 0).
    pub radius: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Work of adhesion w (J/m², ≥ 0).
    pub work_of_adhesion: f64,
}

/// JKR sphere. Its inputs are [`JkrParams`]; it caches the scales of the
/// reduced quartic of the module docs.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jkr {
    /// R (m).
    pub(crate) radius: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// w (J/m²).
    pub(crate) work_of_adhesion: f64,
    /// Cached `k = √(2πw/E*)` (m^{1/2}); 0 without adhesion.
    pub(crate) adhesion_coefficient: f64,
    /// Cached overlap scale `L = (4π²w²R/E*²)^{1/3}` (m) of the reduced quartic
    /// `η⁴ − η − δ/L = 0`; 0 without adhesion.
    pub(crate) delta_scale: f64,
    /// Cached `1/L` (1/m); 0 without adhesion.
    pub(crate) inv_delta_scale: f64,
    /// Cached radius scale `(kR)^{2/3} = (2πwR²/E*)^{1/3}` (m), `a = scale·η²`
    /// (the jump-in radius); 0 without adhesion.
    pub(crate) radius_scale: f64,
    /// Cached force scale `2πwR` (N), `P = scale·((4/3)η⁶ − 2η³)`.
    pub(crate) force_scale: f64,
    /// Cached displacement-controlled instability `δ_c = −(3/4)(π²w²R/E*²)^{1/3}`
    /// (m, ≤ 0).
    pub(crate) critical_delta: f64,
}

law_inputs!(
    Jkr,
    JkrParams {
        radius,
        e_star,
        work_of_adhesion
    }
);

impl Jkr {
    /// The sphere of the inputs `p`, validated as by [`Jkr::new`].
    pub fn from_params(p: &JkrParams) -> Result<Self> {
        Self::new(p.radius, p.e_star, p.work_of_adhesion)
    }

    /// The displacement-controlled instability (jump-out overlap)
    /// `δ_c = −(3/4)(π²w²R/E*²)^{1/3}` (m, ≤ 0; 0 without adhesion).
    #[inline]
    pub fn critical_delta(&self) -> f64 {
        self.critical_delta
    }

    /// The overlap scale `L = (4π²w²R/E*²)^{1/3}` (m) of the reduced quartic
    /// `η⁴ − η − δ/L = 0` (module docs); 0 without adhesion (or when w is so
    /// small that the scales underflow).
    #[inline]
    pub fn delta_scale(&self) -> f64 {
        self.delta_scale
    }

    /// A JKR sphere: radius R (m, > 0), contact modulus E* (Pa, > 0), work of
    /// adhesion w (J/m², ≥ 0). `w = 0` is Hertz. A w so small that its scales
    /// underflow `f64` behaves as `w = 0`.
    pub fn new(radius: f64, e_star: f64, work_of_adhesion: f64) -> Result<Self> {
        let radius = check::positive("radius", radius)?;
        let e_star = check::positive("e_star", e_star)?;
        let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
        let mut law = Self {
            radius,
            e_star,
            work_of_adhesion: w,
            adhesion_coefficient: 0.0,
            delta_scale: 0.0,
            inv_delta_scale: 0.0,
            radius_scale: 0.0,
            force_scale: 0.0,
            critical_delta: 0.0,
        };
        let k = (2.0 * PI * w / e_star).sqrt();
        let kr = k * radius;
        let kr13 = kr.cbrt();
        let radius_scale = kr13 * kr13;
        let delta_scale = radius_scale * radius_scale / radius;
        let force_scale = 2.0 * PI * w * radius;
        let ok = |x: f64| x.is_normal() && x > 0.0;
        if ok(k) && ok(radius_scale) && ok(delta_scale) && ok(1.0 / delta_scale) && ok(force_scale)
        {
            law.adhesion_coefficient = k;
            law.delta_scale = delta_scale;
            law.inv_delta_scale = 1.0 / delta_scale;
            law.radius_scale = radius_scale;
            law.force_scale = force_scale;
            // Δ_c = −(3/4)·4^{−1/3}.
            law.critical_delta = -0.75 * delta_scale / 4f64.cbrt();
        }
        Ok(law)
    }

    /// True when the law has adhesion (w > 0 and representable scales).
    #[inline]
    fn adhesive(&self) -> bool {
        self.delta_scale > 0.0
    }

    /// Force at contact radius `a` (m): `P = 4E*a³/(3R) − √(8πwE*a³)` (1-34).
    #[inline]
    pub fn force_at_radius(&self, a: f64) -> f64 {
        let k = self.adhesion_coefficient;
        4.0 * self.e_star * a * a * a / (3.0 * self.radius) - 2.0 * self.e_star * k * a * a.sqrt()
    }

    /// Overlap at contact radius `a` (m): `δ = a²/R − √(2πwa/E*)` (1-35).
    #[inline]
    pub fn delta_at_radius(&self, a: f64) -> f64 {
        a * a / self.radius - self.adhesion_coefficient * a.sqrt()
    }

    /// Contact radius on the stable branch (largest root) at overlap `delta`
    /// (m), by the closed form of the module docs. `None` below the
    /// displacement-controlled instability δ_c (and for δ < 0 when w = 0).
    #[inline]
    pub fn contact_radius_at_delta(&self, delta: f64) -> Option<f64> {
        if !self.adhesive() {
            return if delta >= 0.0 {
                Some((self.radius * delta).sqrt())
            } else {
                None
            };
        }
        if delta < self.critical_delta || delta.is_nan() {
            return None;
        }
        let eta = reduced_root(delta * self.inv_delta_scale);
        Some(self.radius_scale * eta * eta)
    }

    /// Load-controlled pull-off `−(3/2)πwR` (N).
    #[inline]
    fn load_pull_off(&self) -> f64 {
        if self.adhesive() {
            -0.75 * self.force_scale
        } else {
            0.0
        }
    }

    /// The response on the stable branch at overlap δ ≥ δ_c.
    #[inline]
    fn on_branch(&self, delta: f64) -> NormalResponse {
        if !self.adhesive() {
            let a = (self.radius * delta).sqrt();
            return in_contact(
                4.0 / 3.0 * self.e_star * a * delta,
                delta,
                a,
                2.0 * self.e_star * a,
            );
        }
        let (eta, gp) = reduced_root_and_slope(delta * self.inv_delta_scale);
        let e3 = eta * eta * eta;
        let a = self.radius_scale * eta * eta;
        let force = (self.force_scale * e3) * (4.0 / 3.0 * e3 - 2.0);
        // P = 2πwR((4/3)η⁶ − 2η³); dP/dδ = 2E*a(4η³ − 3)/(4η³ − 1). The
        // denominator is g'(η) from before the Newton polish (one division
        // fewer; the polish moves η by rounding only), clamped as in
        // `tangent_ratio`.
        let den = gp.max(f64::EPSILON * 4.0 * e3);
        let stiffness = self.e_star * 2.0 * a * ((4.0 * e3 - 3.0) / den);
        in_contact(force, delta, a, stiffness)
    }
}

/// `(4η³ − 3)/(4η³ − 1)`, the ratio of the tangent stiffness to `2E*a`. The
/// denominator vanishes at the fold (vertical tangent); it is kept ≥ ε·4η³ so
/// the value stays finite (about −1/ε there).
#[inline]
fn tangent_ratio(e3: f64) -> f64 {
    let den = (4.0 * e3 - 1.0).max(f64::EPSILON * 4.0 * e3);
    (4.0 * e3 - 3.0) / den
}

/// Stable (largest) root η of `η⁴ − η − Δ = 0` for `Δ ≥ Δ_c = −(3/4)4^{−1/3}`
/// (Δ slightly below Δ_c by rounding is treated as Δ_c).
#[inline]
fn reduced_root(big_delta: f64) -> f64 {
    reduced_root_and_slope(big_delta).0
}

/// [`reduced_root`] and the slope `g'(η₀) = 4η₀³ − 1` at the closed-form
/// value η₀ before the Newton polish.
#[inline]
fn reduced_root_and_slope(big_delta: f64) -> (f64, f64) {
    let mut eta = if big_delta > HERTZ_SWITCH {
        big_delta.sqrt().sqrt()
    } else {
        // Resolvent u³ + 3su − 2r = 0, r = 1/16.
        let s = big_delta * (1.0 / 3.0);
        const R: f64 = 1.0 / 16.0;
        let disc = (R * R + s * s * s).max(0.0);
        let c = cbrt_positive(R + disc.sqrt());
        let c2 = c * c;
        let u = 2.0 * R * c2 / (c2 * c2 + s * c2 + s * s);
        let v = (2.0 * u).sqrt();
        0.5 * (v + (2.0 / v - v * v).max(0.0).sqrt())
    };
    // One Newton step on g(η) = η⁴ − η − Δ, skipped at the fold.
    let e2 = eta * eta;
    let gp = 4.0 * e2 * eta - 1.0;
    if gp > 1e-8 {
        let g = e2 * e2 - eta - big_delta;
        eta -= g / gp;
    }
    (eta, gp)
}

/// Cube root of a positive normal `x` (here ≥ 1/16): exponent-bit estimate
/// (≈ 3 % off) and two Halley steps `c ← c(c³ + 2x)/(2c³ + x)` (cubic
/// convergence: 3e-2 → 1e-5 → 6e-15 relative). About 3× faster than the libm
/// `cbrt`, and the Newton polish of η absorbs what is left.
#[inline]
fn cbrt_positive(x: f64) -> f64 {
    let mut c = f64::from_bits(x.to_bits() / 3 + 0x2A9F_7893_782D_A1CE);
    let c3 = c * c * c;
    c *= (c3 + 2.0 * x) / (2.0 * c3 + x);
    let c3 = c * c * c;
    c *= (c3 + 2.0 * x) / (2.0 * c3 + x);
    c
}

#[inline]
fn in_contact(force: f64, delta: f64, a: f64, stiffness: f64) -> NormalResponse {
    NormalResponse {
        force,
        delta,
        contact_radius: a,
        stiffness,
        in_contact: 1,
        reserved: 0,
    }
}

/// The state after a step that ends in contact on the stable branch.
#[inline]
pub(crate) fn contact_state(r: &NormalResponse) -> ContactState {
    ContactState {
        contact_radius: r.contact_radius,
        cohesive_radius: 0.0,
        in_contact: 1,
        branch: 1,
    }
}

impl NormalContact for Jkr {
    /// Displacement-controlled step with jump-in at δ = 0 and jump-out below
    /// δ_c (module docs).
    #[inline]
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        if !super::stays_in_contact(old, delta, self.critical_delta) {
            return Ok(super::out_of_contact(delta));
        }
        let r = self.on_branch(delta);
        Ok((r, contact_state(&r)))
    }

    /// Four contacts at a time with AVX2 where the CPU has it (detected once),
    /// bit for bit the results of [`Jkr::eval`]; the element loop elsewhere.
    /// See `jkr_simd.rs`.
    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        // SAFETY: the pointer contract of `b` is the caller's.
        unsafe { super::jkr_simd::eval_batch(self, b) }
    }

    /// Stable branch at load P ≥ −(3/2)πwR:
    /// `a^{3/2} = (3R/4)(k + √(k² + 4P/(3RE*)))` (the larger root of the
    /// quadratic in `a^{3/2}`, sum of non-negative terms).
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        if force < self.load_pull_off() {
            return Err(super::below_pull_off(force));
        }
        let k = self.adhesion_coefficient;
        let rad = (k * k + 4.0 * force / (3.0 * self.radius * self.e_star)).max(0.0);
        let z = 0.75 * self.radius * (k + rad.sqrt()); // a^{3/2}
        let y = z.cbrt(); // √a
        let a = y * y;
        let delta = a * a / self.radius - k * y;
        // Stable under load control: dP/dδ ≥ 0 (0 at the pull-off; the clamp
        // only removes rounding there).
        let stiffness = if self.adhesive() {
            (2.0 * self.e_star * a * tangent_ratio(z / (k * self.radius))).max(0.0)
        } else {
            2.0 * self.e_star * a
        };
        Ok(in_contact(force, delta, a, stiffness))
    }

    /// Load: `−(3/2)πwR`; displacement: `−(5/6)πwR` (force at δ_c). 0 when w = 0.
    fn pull_off_force(&self, control: Control) -> Result<f64> {
        Ok(match control {
            Control::Load => self.load_pull_off(),
            Control::Displacement if self.adhesive() => -5.0 / 12.0 * self.force_scale,
            Control::Displacement => 0.0,
        })
    }

    /// `|δ_c| = (3/4)(π²w²R/E*²)^{1/3}`; the radius when w = 0.
    fn length_scale(&self) -> f64 {
        if self.adhesive() {
            -self.critical_delta
        } else {
            self.radius
        }
    }

    /// Displacement control: δ_c = `−(3/4)(π²w²R/E*²)^{1/3}`, where
    /// [`Jkr::eval`] jumps out (a contact stays down to δ_c inclusive; out of
    /// contact there is no force until δ ≥ 0).
    ///
    /// Load control: the overlap at the load-controlled pull-off
    /// `P = −(3/2)πwR`, `a = (9πwR²/(8E*))^{1/3}`,
    /// `δ = a²/R − √(2πwa/E*)`; in the reduced variables of the module
    /// (`η³ = 3/4` there) `δ = L η(η³ − 1) = −(3/4)^{1/3} L/4`,
    /// `L = (4π²w²R/E*²)^{1/3}`, i.e. `δ = −(1/4)(3π²w²R/E*²)^{1/3}`.
    /// This is where LAMMPS's `pair_style granular … jkr` releases a
    /// contact (its γ is w/2).
    ///
    /// 0 when w = 0. `rel_force` is checked, then ignored.
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        if !self.adhesive() {
            return Ok(0.0);
        }
        Ok(match control {
            Control::Displacement => self.critical_delta,
            Control::Load => -0.25 * 0.75f64.cbrt() * self.delta_scale,
        })
    }

    /// Energy of the contact on the branch `eval` ends on: 0 out of contact,
    /// otherwise elastic energy minus surface energy,
    ///
    /// `U = (8/15)E*a⁵/R² − (4/3)E*k a^{7/2}/R + πwa²`, `k = √(2πw/E*)`.
    ///
    /// Derivation (Johnson 1985 §5.5; Maugis 2000, *Contact, Adhesion and
    /// Rupture of Elastic Solids*, Springer, ch. 5): the JKR state at
    /// contact radius a is the Hertz state at a (`P₁ = 4E*a³/(3R)`,
    /// `δ₁ = a²/R`, stored energy `(8/15)E*a⁵/R²`) unloaded at fixed a as a
    /// flat punch of stiffness `2E*a` by `Δδ = δ₁ − δ = k√a`, which removes
    /// `P₁Δδ − E*aΔδ²`; the elastic energy is
    /// `U_E = (8/15)E*a⁵/R² − P₁Δδ + E*aΔδ²` (with `E*aΔδ² = 2πwa²`) and the
    /// total `U = U_E − πa²w`. Since `∂U/∂a|_δ = 0` is the JKR equilibrium
    /// (Griffith) and `∂U_E/∂δ|_a = P`, `dU/dδ = P` along the branch. In the
    /// reduced variables (`a = (kR)^{2/3}η²`)
    /// `U = 2πwR·L·[(8/15)η¹⁰ − (4/3)η⁷ + η⁴/2]`. w = 0 is Hertz's
    /// `(8/15)E*√R δ^{5/2}`.
    fn energy(&self, delta: f64, old: &ContactState) -> Result<f64> {
        let delta = check_delta(delta)?;
        if !super::stays_in_contact(old, delta, self.critical_delta) {
            return Ok(0.0);
        }
        if !self.adhesive() {
            return Ok(super::hertz_energy(self.radius, self.e_star, delta));
        }
        let eta = reduced_root(delta * self.inv_delta_scale);
        let e3 = eta * eta * eta;
        let e4 = e3 * eta;
        let u = (self.force_scale * self.delta_scale)
            * (e4 * ((8.0 / 15.0 * e3 - 4.0 / 3.0) * e3 + 0.5));
        check::finite_result(u, "delta", delta, "the energy overflows f64")
    }
}
