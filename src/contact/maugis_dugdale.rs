//! Maugis–Dugdale: elastic sphere with a Dugdale (constant-stress) cohesive
//! zone, the continuous bridge between DMT (λ → 0) and JKR (λ → ∞).
//!
//! # Formulas
//!
//! Maugis, D. (1992) "Adhesion of spheres: the JKR-DMT transition using a
//! Dugdale model", J. Colloid Interface Sci. 150:243–269; thesis (1-43).
//! A uniform tension σ₀ acts between the surfaces wherever their gap is below
//! $h_0 = w/\sigma_0$ (so the work of adhesion is $\sigma_0 h_0 = w$): over
//! the annulus `a ≤ r ≤ c` around the contact of radius `a`. With
//! $K = 4E^\ast/3$ and $m = c/a$, the Maugis parameter λ
//! ([`MaugisDugdale::lambda`]) and the dimensionless radii, load (P > 0
//! repulsive) and overlap (δ > 0) are
//!
//! $$\lambda = 2\sigma_0\left(\frac{R}{\pi w K^2}\right)^{1/3}, \quad \bar A = a\left(\frac{K}{\pi w R^2}\right)^{1/3}, \quad \bar C = c\left(\frac{K}{\pi w R^2}\right)^{1/3}, \quad \bar P = \frac{P}{\pi w R}, \quad \bar\Delta = \delta\left(\frac{K^2}{\pi^2 w^2 R}\right)^{1/3} .$$
//!
//! **Contact branch** (a > 0), Maugis (1992); thesis (1-43):
//!
//! $$\frac{\lambda \bar A^2}{2}\Bigl(\sqrt{m^2-1} + (m^2-2)\arctan\sqrt{m^2-1}\Bigr) + \frac{4\lambda^2 \bar A}{3}\Bigl(\sqrt{m^2-1}\arctan\sqrt{m^2-1} - m + 1\Bigr) = 1,$$
//!
//! $$\bar P = \bar A^3 - \lambda \bar A^2\Bigl(\sqrt{m^2-1} + m^2 \arctan\sqrt{m^2-1}\Bigr), \qquad \bar\Delta = \bar A^2 - \tfrac{4}{3}\lambda \bar A\sqrt{m^2-1} .$$
//!
//! It is evaluated along the parameter `s = √(m²−1) ∈ (0, ∞)`, `m = √(1+s²)`.
//! For a given `s` the first equation is the quadratic `αĀ² + βĀ − 1 = 0` with
//! `α = (λ/2) f₁(s)`, `f₁ = s + (s²−1) atan s`, `β = (4λ²/3) f₂(s)`,
//! `f₂ = s atan s − s²/(1+m)` (that is `s atan s − (m − 1)` without
//! cancellation), whose positive root is taken as `Ā = 2/(β + √(β²+4α))`.
//! `f₁` cancels catastrophically as `s → 0` (m → 1, the JKR side), so below
//! `s <` [`SERIES_SWITCH`] its series
//! `f₁ = Σ_{k≥1} (−1)^{k+1} 4k/(4k²−1) s^{2k+1} = (4/3)s³ − (8/15)s⁵ + …`
//! is used. The derivatives along `s` are analytic (implicit
//! differentiation, `dĀ/ds = −(α'Ā² + β'Ā)/√(β²+4α)`), with the combinations
//! `2α − sα' = λ(s/(1+s²) − atan s)` (series below the switch) and
//! `β − sβ' = −(4λ²/3) s²/(m²(1+m))` written without cancellation so that
//! `d(Ās)/ds` stays accurate as `s → ∞`. `s → ∞` is `Ā → 0` (the contact
//! vanishes), `s → 0` is `Ā → ∞`.
//!
//! **Non-contact branch** (a = 0, the surfaces interact over a disk of radius
//! c but do not touch; Johnson & Greenwood 1997, "An adhesion map for the
//! contact of elastic spheres", J. Colloid Interface Sci. 192:326, from the
//! displacements of a uniformly loaded disk, Johnson 1985, *Contact Mechanics*, ch. 3):
//!
//! $$\bar P = -\frac{\lambda\pi \bar C^2}{2}, \qquad \bar\Delta = \frac{\bar C^2}{2} - \frac{8\lambda \bar C}{3\pi} - \frac{2}{\pi\lambda} .$$
//!
//! It starts at `C̄ = 0` (`δ = −h₀`, zero force) and ends at `C̄₀`, the
//! positive root of `λπC̄²/4 + (4λ²/3)(π/2 − 1)C̄ = 1`, where the central gap
//! closes and it joins the contact branch's `Ā → 0` limit (`C̄ = mĀ`).
//! For `δ < −h₀` with no cohesive zone the force is zero.
//!
//! # Stability and hysteresis
//!
//! The equilibrium curve is one continuous path: zero force → non-contact
//! (`C̄` from 0 to `C̄₀`) → contact (`Ā` from 0 to ∞). Along it `Δ̄` first
//! decreases (unstable under displacement control) to a single local minimum
//! (the jump-out point on retraction), then increases without bound. The
//! minimum lies on the non-contact branch at `C̄ = 8λ/(3π)` when `C̄₀ ≥ 8λ/(3π)`,
//! i.e. for `λ ≤ λ_c = (9π/(16(π−1)))^{1/3} = 0.9379475` ([`s_curve_onset`]):
//! contact is then made and lost continuously (`a → 0`) and the only
//! hysteresis is the small Dugdale loop of the cohesive zone between
//! `δ = −h₀` and the minimum. For `λ > λ_c` the minimum is on the contact
//! branch: the contact jumps in on approach and jumps out at finite `a` on
//! retraction (the S-shaped curve). The minimum is located once in the
//! constructor and cached.
//!
//! History ([`ContactState`]): `branch = 0` means separated (fresh or after a
//! jump-out; zero force), `branch = 1` means on the stable piece of the path
//! (beyond the minimum of `Δ̄`). A state on branch 0 stays there while
//! `δ ≤ −h₀` and jumps onto branch 1 as soon as `δ > −h₀` (so a fresh state
//! with `δ ≥ 0` jumps in); a state on branch 1 stays there down to the
//! minimum of `Δ̄` and then jumps to zero force. `ContactState::in_contact` is
//! 1 whenever the cohesive zone exists (branch 1, "interacting", as
//! [`ContactState`] documents for laws with a cohesive zone) while
//! `NormalResponse::in_contact` is 1 only when the surfaces touch (`a > 0`).
//! `cohesive_radius` is `c` (m) on branch 1.
//!
//! Under load control the stable equilibria are those beyond the minimum of
//! `P̄` along the path (largest contact radius); the minimum is the
//! load-controlled pull-off, `P̄_c` = 2 (DMT) as λ → 0, 1.5 (JKR) as λ → ∞,
//! 1.6007 at λ = 1.
//!
//! Evaluations never allocate: a bracketed, safeguarded Newton iteration in
//! `ln s` on the monotone stable piece, started from the old state's `m = c/a`
//! when there is one.
//!
//! # References
//!
//! * Thesis (1-43), (1-44).
//! * D. Maugis (1992), "Adhesion of spheres: the JKR-DMT transition using a
//!   Dugdale model", J. Colloid Interface Sci. 150, 243–269,
//!   [doi:10.1016/0021-9797(92)90285-T](https://doi.org/10.1016/0021-9797(92)90285-T).
//! * K. L. Johnson, J. A. Greenwood (1997), "An adhesion map for the contact of
//!   elastic spheres", J. Colloid Interface Sci. 192, 326–333 (the non-contact
//!   branch).
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   ch. 3, [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731)
//!   (displacements of a uniformly loaded disk).
//! * D. S. Dugdale (1960), "Yielding of steel sheets containing slits",
//!   J. Mech. Phys. Solids 8, 100–104 (the constant-stress cohesive zone).

use super::{
    check_delta, check_force, finite_response, ContactState, Control, NormalContact, NormalResponse,
};
use crate::error::{check, Error, Result};
use core::f64::consts::PI;

/// Below this value of `s = √(m²−1)` the functions `f₁(s) = s + (s²−1) atan s`
/// and `s/(1+s²) − atan s`, which cancel catastrophically as `s → 0`, are
/// evaluated from their Taylor series (14 terms: truncation below 1e-17
/// relative; the closed forms lose about `ε/s² ≈ 4e-15` at the switch).
pub const SERIES_SWITCH: f64 = 0.25;

/// Smallest `s` the solvers visit (`Ā` of order `s^{-3/2}` overflows the force
/// beyond).
const S_MIN: f64 = 1e-100;
/// Largest `s` the solvers visit: there `Ā ≈ C̄₀/s` and the contact branch
/// equals its junction with the non-contact branch to about `1/S_MAX`.
const S_MAX: f64 = 1e12;
/// Bound on the dimensionless stiffness `dP̄/dΔ̄` (it is infinite exactly at
/// the turning point).
const STIFFNESS_BAR_MAX: f64 = 1e100;

/// Onset of the S-shaped (jump-in / jump-out) contact curve of Maugis–Dugdale:
/// the λ at which the minimum of `Δ̄` along the equilibrium path passes from
/// the non-contact branch to the contact branch, i.e. where
/// `C̄₀ = 8λ/(3π)`, which gives `λ_c = (9π/(16(π−1)))^{1/3} = 0.9379475`
/// (Johnson & Greenwood 1997 quote λ > 0.938).
pub fn s_curve_onset() -> f64 {
    (9.0 * PI / (16.0 * (PI - 1.0))).cbrt()
}

/// Inputs of a Maugis–Dugdale sphere, as [`MaugisDugdale::from_params`] and
/// C's `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MaugisDugdaleParams {
    /// Sphere radius R (m, > 0).
    pub radius: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Work of adhesion w (J/m², > 0).
    pub work_of_adhesion: f64,
    /// Dugdale cohesive stress σ₀ (Pa, > 0).
    pub cohesive_stress: f64,
}

/// Maugis–Dugdale sphere. Build it with [`MaugisDugdale::new`] (or
/// [`MaugisDugdale::from_params`], [`MaugisDugdale::from_tabor`],
/// [`MaugisDugdale::from_maugis_parameter`]), which validates the inputs
/// ([`MaugisDugdaleParams`]) and caches the derived constants and the
/// turning points.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisDugdale {
    /// R (m).
    pub(crate) radius: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// w (J/m²).
    pub(crate) work_of_adhesion: f64,
    /// σ₀ (Pa).
    pub(crate) cohesive_stress: f64,
    /// Cached: Maugis parameter λ (dimensionless).
    lambda: f64,
    /// Cached: radius unit `(πwR²/K)^{1/3}` (m).
    radius_scale: f64,
    /// Cached: overlap unit `(π²w²R/K²)^{1/3}` (m).
    delta_scale: f64,
    /// Cached: `C̄₀`, where the non-contact branch closes onto the contact one.
    c0_bar: f64,
    /// Cached: jump-out point: `C̄` (turn_kind 0) or `s` (turn_kind 1).
    turn_param: f64,
    /// Cached: `Δ̄ + 2/(πλ)` at the jump-out point (≤ 0).
    turn_dh: f64,
    /// Cached: load-controlled pull-off `P̄_c` (≤ 0, dimensionless).
    pull_off_load_bar: f64,
    /// Cached: `s` at the load-controlled pull-off.
    pull_off_load_s: f64,
    /// Cached: displacement-controlled pull-off (dimensionless).
    pull_off_disp_bar: f64,
    /// Cached: 0 when the jump-out point is on the non-contact branch
    /// (λ ≤ λ_c), 1 when it is on the contact branch.
    turn_kind: i32,
    /// Reserved, 0.
    reserved: i32,
}

const _: () = assert!(core::mem::size_of::<MaugisDugdale>() <= 16 * 8);

/// A point of the Maugis–Dugdale equilibrium curve in Maugis's dimensionless
/// variables, with the derivatives along the branch parameter (`s = √(m²−1)`
/// on the contact branch, `C̄` on the non-contact branch).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// `Ā = a (K/(πwR²))^{1/3}`; 0 on the non-contact branch.
    pub a_bar: f64,
    /// `C̄ = c (K/(πwR²))^{1/3}` (outer radius of the cohesive zone).
    pub c_bar: f64,
    /// `P̄ = P/(πwR)`.
    pub p_bar: f64,
    /// `Δ̄ = δ (K²/(π²w²R))^{1/3}`.
    pub delta_bar: f64,
    /// `dP̄/dt` along the branch parameter t.
    pub dp_bar: f64,
    /// `dΔ̄/dt` along the branch parameter t.
    pub ddelta_bar: f64,
}

impl CurvePoint {
    /// Dimensionless tangent stiffness `dP̄/dΔ̄` (infinite at a turning point).
    #[inline]
    pub fn stiffness_bar(&self) -> f64 {
        self.dp_bar / self.ddelta_bar
    }
}

/// Internal point of the contact branch.
#[derive(Debug, Clone, Copy)]
struct Pt {
    m: f64,
    a: f64,
    p: f64,
    d: f64,
    dp: f64,
    dd: f64,
}

/// Coefficients 4k/(4k²−1), k = 1..14, of `f₁ = Σ (−1)^{k+1} c_k s^{2k+1}`.
const F1_SERIES: [f64; 14] = {
    let mut c = [0.0; 14];
    let mut k = 1;
    while k <= 14 {
        let kf = k as f64;
        c[k - 1] = 4.0 * kf / (4.0 * kf * kf - 1.0);
        k += 1;
    }
    c
};

/// Coefficients 2k/(2k+1), k = 1..14, of `s/(1+s²) − atan s = Σ (−1)^k c_k s^{2k+1}`.
const H1_SERIES: [f64; 14] = {
    let mut c = [0.0; 14];
    let mut k = 1;
    while k <= 14 {
        let kf = k as f64;
        c[k - 1] = 2.0 * kf / (2.0 * kf + 1.0);
        k += 1;
    }
    c
};

/// `Σ_{k=1}^{14} sign^{k+1} c_k x^{k−1}` by Horner, x = −s² (alternating).
#[inline]
fn alt_series(c: &[f64; 14], s2: f64) -> f64 {
    let x = -s2;
    let mut acc = 0.0;
    let mut i = c.len();
    while i > 0 {
        i -= 1;
        acc = acc * x + c[i];
    }
    acc
}

/// The contact branch at parameter `s > 0` for Maugis parameter `lam`.
#[inline]
fn contact_core(lam: f64, s: f64) -> Pt {
    let s2 = s * s;
    let q = 1.0 + s2; // m²
    let m = q.sqrt();
    let at = s.atan();
    // f1 = s + (s²−1) atan s; h1 = f1 − s f1'/2 = s/(1+s²) − atan s.
    let (f1, h1) = if s < SERIES_SWITCH {
        let s3 = s2 * s;
        (
            s3 * alt_series(&F1_SERIES, s2),
            -s3 * alt_series(&H1_SERIES, s2),
        )
    } else {
        (s + (s2 - 1.0) * at, s / q - at)
    };
    let f1p = 2.0 * s * at + 2.0 * s2 / q;
    let f2 = s * at - s2 / (1.0 + m);
    let f2p = at + s / q - s / m;
    let h2 = -s2 / (q * (1.0 + m)); // f2 − s f2'
    let c2 = 4.0 * lam * lam / 3.0;
    let alpha = 0.5 * lam * f1;
    let beta = c2 * f2;
    let alphap = 0.5 * lam * f1p;
    let betap = c2 * f2p;
    let disc = (beta * beta + 4.0 * alpha).sqrt(); // = 2αĀ + β
    let a = 2.0 / (beta + disc);
    let da = -(alphap * a * a + betap * a) / disc;
    // e = d(Ās)/ds = Ā + sĀ' = Ā[Ā(2α − sα') + (β − sβ')]/(2αĀ + β).
    let e = a * (lam * a * h1 + c2 * h2) / disc;
    let g = s + q * at; // √(m²−1) + m² atan √(m²−1)
    let p = a * a * (a - lam * g);
    let d = a * (a - 4.0 / 3.0 * lam * s);
    // dP̄/ds = 3Ā²Ā' − λĀ(2Ā'g + Āg'), 2Ā'g + Āg' = −2Ā atan(s)/s + (2g/s) e.
    let dp = 3.0 * a * a * da - lam * a * (2.0 * (g * e - a * at) / s);
    let dd = 2.0 * a * da - 4.0 / 3.0 * lam * e;
    Pt { m, a, p, d, dp, dd }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Target {
    Delta,
    Load,
}

impl Target {
    #[inline]
    fn value(self, p: &Pt) -> f64 {
        match self {
            Target::Delta => p.d,
            Target::Load => p.p,
        }
    }
    #[inline]
    fn slope(self, p: &Pt) -> f64 {
        match self {
            Target::Delta => p.dd,
            Target::Load => p.dp,
        }
    }
}

/// Root of `g(s) = 0` for a function negative below and positive above the
/// root (used for `dΔ̄/ds` and `dP̄/ds` at the minima), by bracketing from
/// `s = 1` and bisection in `ln s`. Returns `S_MAX` when the sign is still
/// negative there (the minimum is at the junction to double precision).
fn sign_change(lam: f64, g: impl Fn(&Pt) -> f64) -> f64 {
    let mut s = 1.0;
    let (mut lo, mut hi);
    if g(&contact_core(lam, s)) < 0.0 {
        lo = s;
        loop {
            s *= 4.0;
            if s > S_MAX {
                return S_MAX;
            }
            if g(&contact_core(lam, s)) >= 0.0 {
                hi = s;
                break;
            }
            lo = s;
        }
    } else {
        hi = s;
        loop {
            s *= 0.25;
            if s < S_MIN {
                return S_MIN;
            }
            if g(&contact_core(lam, s)) < 0.0 {
                lo = s;
                break;
            }
            hi = s;
        }
    }
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if mid <= lo || mid >= hi || hi / lo - 1.0 < 1e-14 {
            break;
        }
        if g(&contact_core(lam, mid)) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo * hi).sqrt()
}

law_inputs!(
    MaugisDugdale,
    MaugisDugdaleParams {
        radius,
        e_star,
        work_of_adhesion,
        cohesive_stress
    }
);

impl MaugisDugdale {
    /// The sphere of the inputs `p`, validated as by [`MaugisDugdale::new`].
    pub fn from_params(p: &MaugisDugdaleParams) -> Result<Self> {
        Self::new(p.radius, p.e_star, p.work_of_adhesion, p.cohesive_stress)
    }

    /// A Maugis–Dugdale sphere: radius R (m), contact modulus E* (Pa), work of
    /// adhesion w (J/m²) and Dugdale cohesive stress σ₀ (Pa), all finite and
    /// positive. Computes λ, the scales, and the turning points (jump-out and
    /// load-controlled pull-off) once.
    ///
    /// Errors: [`Error::InvalidArgument`] for a non-positive or non-finite
    /// argument, or when the combination gives λ outside `[1e-8, 1e8]` (the
    /// DMT and JKR laws are the appropriate models there).
    pub fn new(
        radius: f64,
        e_star: f64,
        work_of_adhesion: f64,
        cohesive_stress: f64,
    ) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        let e = check::positive("e_star", e_star)?;
        let w = check::positive("work_of_adhesion", work_of_adhesion)?;
        let s0 = check::positive("cohesive_stress", cohesive_stress)?;
        let k = crate::material::jkr_k(e);
        // (πw/K)^{1/3}, R^{1/3}: products of cube roots avoid overflow.
        let wk = (PI * w / k).cbrt();
        let r3 = r.cbrt();
        let radius_scale = wk * r3 * r3;
        let delta_scale = wk * wk * r3;
        let lambda = 2.0 * s0 * r3 / (wk * k);
        if !(radius_scale.is_finite()
            && radius_scale > 0.0
            && delta_scale.is_finite()
            && delta_scale > 0.0
            && (1e-8..=1e8).contains(&lambda))
        {
            return Err(Error::InvalidArgument {
                name: "cohesive_stress",
                value: s0,
                bound:
                    "such that the Maugis parameter λ lies in [1e-8, 1e8] and the scales are finite",
            });
        }
        let lam = lambda;
        // C̄₀: positive root of (πλ/4)C̄² + B C̄ − 1 = 0, B = (4λ²/3)(π/2 − 1).
        let bq = 4.0 * lam * lam / 3.0 * (0.5 * PI - 1.0);
        let c0_bar = 2.0 / (bq + (bq * bq + PI * lam).sqrt());
        let b = 8.0 * lam / (3.0 * PI);
        let (turn_kind, turn_param, turn_dh, pull_off_disp_bar) = if c0_bar >= b {
            // Minimum of Δ̄ on the non-contact branch: dΔ̄/dC̄ = C̄ − b = 0.
            (0, b, -0.5 * b * b, -0.5 * lam * PI * c0_bar * c0_bar)
        } else {
            let st = sign_change(lam, |p| p.dd);
            let p = contact_core(lam, st);
            (1, st, p.d + 2.0 / (PI * lam), p.p)
        };
        let sp = sign_change(lam, |p| p.dp);
        let pull_off_load_bar = contact_core(lam, sp).p;
        Ok(Self {
            radius: r,
            e_star: e,
            work_of_adhesion: w,
            cohesive_stress: s0,
            lambda,
            radius_scale,
            delta_scale,
            c0_bar,
            turn_param,
            turn_dh,
            pull_off_load_bar,
            pull_off_load_s: sp,
            pull_off_disp_bar,
            turn_kind,
            reserved: 0,
        })
    }

    /// The Maugis–Dugdale sphere that stands for a Lennard-Jones surface law
    /// with equilibrium separation z₀ (m): σ₀ is the Lennard-Jones theoretical
    /// stress `16w/(9√3 z₀)` ([`crate::material::lennard_jones_theoretical_stress`],
    /// thesis (1-44)), which gives `λ = 1.157 μ` (μ the Tabor parameter).
    pub fn from_tabor(
        radius: f64,
        e_star: f64,
        work_of_adhesion: f64,
        equilibrium_separation: f64,
    ) -> Result<Self> {
        let w = check::positive("work_of_adhesion", work_of_adhesion)?;
        let s0 = crate::material::lennard_jones_theoretical_stress(w, equilibrium_separation)?;
        Self::new(radius, e_star, w, s0)
    }

    /// The Maugis–Dugdale sphere with a prescribed Maugis parameter λ: the
    /// cohesive stress is `σ₀ = (λ/2)(πwK²/R)^{1/3}`, `K = 4E*/3`.
    pub fn from_maugis_parameter(
        radius: f64,
        e_star: f64,
        work_of_adhesion: f64,
        lambda: f64,
    ) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        let e = check::positive("e_star", e_star)?;
        let w = check::positive("work_of_adhesion", work_of_adhesion)?;
        let lam = check::positive("lambda", lambda)?;
        let k = crate::material::jkr_k(e);
        let s0 = 0.5 * lam * (PI * w / k).cbrt() * k / r.cbrt();
        Self::new(r, e, w, s0)
    }

    /// Maugis parameter `λ = 2σ₀ (R/(πwK²))^{1/3}`, `K = 4E*/3` (dimensionless).
    #[inline]
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// Range of the Dugdale stress `h₀ = w/σ₀` (m): the surfaces attract
    /// wherever their gap is below h₀.
    #[inline]
    pub fn range(&self) -> f64 {
        self.work_of_adhesion / self.cohesive_stress
    }

    /// Force unit `πwR` (N): `P = P̄ πwR`.
    #[inline]
    pub fn force_scale(&self) -> f64 {
        PI * self.work_of_adhesion * self.radius
    }

    /// Radius unit `(πwR²/K)^{1/3}` (m): `a = Ā·(πwR²/K)^{1/3}`.
    #[inline]
    pub fn radius_scale(&self) -> f64 {
        self.radius_scale
    }

    /// `C̄₀`, the dimensionless cohesive radius at which the non-contact
    /// branch closes onto the contact branch (positive root of
    /// `λπC̄²/4 + (4λ²/3)(π/2−1)C̄ = 1`).
    #[inline]
    pub fn closure_c_bar(&self) -> f64 {
        self.c0_bar
    }

    /// Whether the contact itself jumps in and out (λ > λ_c, the S-shaped
    /// curve): the minimum of `Δ̄` along the path, found at construction, is
    /// on the contact branch. Otherwise contact is made and lost continuously
    /// and only the cohesive zone jumps.
    #[inline]
    pub fn has_contact_jump(&self) -> bool {
        self.turn_kind == 1
    }

    /// The jump-out point on retraction under displacement control (the
    /// minimum of `Δ̄` along the equilibrium path), in dimensionless form.
    pub fn jump_out_point(&self) -> CurvePoint {
        if self.turn_kind == 0 {
            self.non_contact_unchecked(self.turn_param)
        } else {
            to_curve_point(&contact_core(self.lambda, self.turn_param))
        }
    }

    /// The load-controlled pull-off point (the minimum of `P̄` along the
    /// path, on the contact branch), in dimensionless form.
    pub fn load_pull_off_point(&self) -> CurvePoint {
        to_curve_point(&contact_core(self.lambda, self.pull_off_load_s))
    }

    /// The contact branch at `s = √(m²−1)` (finite, > 0), derivatives with
    /// respect to s. See the module documentation for the equations.
    pub fn contact_point(&self, s: f64) -> Result<CurvePoint> {
        let s = check::positive("s", s)?;
        Ok(to_curve_point(&contact_core(self.lambda, s)))
    }

    /// The non-contact branch at `C̄ ∈ [0, C̄₀]` (Johnson & Greenwood 1997):
    /// `P̄ = −λπC̄²/2`, `Δ̄ = C̄²/2 − 8λC̄/(3π) − 2/(πλ)`, derivatives with
    /// respect to `C̄`.
    pub fn non_contact_point(&self, c_bar: f64) -> Result<CurvePoint> {
        let c = check::in_range("c_bar", c_bar, 0.0, self.c0_bar, "in [0, closure_c_bar()]")?;
        Ok(self.non_contact_unchecked(c))
    }

    #[inline]
    fn non_contact_unchecked(&self, c: f64) -> CurvePoint {
        let lam = self.lambda;
        let b = 8.0 * lam / (3.0 * PI);
        CurvePoint {
            a_bar: 0.0,
            c_bar: c,
            p_bar: -0.5 * lam * PI * c * c,
            delta_bar: c * (0.5 * c - b) - 2.0 / (PI * lam),
            dp_bar: -lam * PI * c,
            ddelta_bar: c - b,
        }
    }

    /// Dimensional response from a contact-branch point.
    #[inline]
    fn contact_response(&self, p: &Pt, delta: f64, force: Option<f64>) -> NormalResponse {
        let fs = self.force_scale();
        let a = p.a * self.radius_scale;
        NormalResponse {
            force: force.unwrap_or(p.p * fs),
            delta,
            contact_radius: a,
            stiffness: clamp_stiffness(p.dp / p.dd) * fs / self.delta_scale,
            in_contact: (a > 0.0) as i32,
            reserved: 0,
        }
    }

    /// Solve `F(s) = target` on the stable piece `s ∈ (0, s_end]`, where F
    /// (Δ̄ or P̄) decreases with s: bracket from `guess` by factors of 8,
    /// then Newton in `u = ln s` safeguarded by bisection.
    fn solve_contact(&self, target: f64, which: Target, s_end: f64, guess: f64) -> Result<Pt> {
        let lam = self.lambda;
        let mut s = if guess.is_finite() && guess > 0.0 {
            guess.clamp(S_MIN, s_end)
        } else {
            1.0f64.min(s_end)
        };
        let mut p = contact_core(lam, s);
        let mut f = which.value(&p) - target;
        if f == 0.0 {
            return Ok(p);
        }
        // Bracket [lo, hi] in s with f(lo) > 0 > f(hi). The first trial is
        // the Newton point from the guess (overshot by 1 % so that it usually
        // brackets the root at once), then steps of a factor 8.
        const LN8: f64 = 2.0794415416798357;
        let slope0 = s * which.slope(&p);
        let mut du = if slope0 < 0.0 {
            (-1.01 * f / slope0).abs().min(LN8)
        } else {
            LN8
        };
        if du <= 1e-13 {
            return Ok(p);
        }
        let (mut lo, mut hi);
        if f > 0.0 {
            lo = s;
            loop {
                let s2 = (s * du.exp()).min(s_end);
                du = LN8;
                if s2 <= s {
                    // Target at (or, by rounding, just below) the piece's end.
                    return Ok(p);
                }
                let p2 = contact_core(lam, s2);
                let f2 = which.value(&p2) - target;
                s = s2;
                p = p2;
                f = f2;
                if f2 <= 0.0 {
                    hi = s2;
                    break;
                }
                lo = s2;
            }
        } else {
            hi = s;
            loop {
                let s2 = s * (-du).exp();
                du = LN8;
                if s2 < S_MIN {
                    return Err(Error::OutOfDomain {
                        name: if which == Target::Delta {
                            "delta"
                        } else {
                            "force"
                        },
                        value: target,
                        reason: "too large: the contact radius overflows",
                    });
                }
                let p2 = contact_core(lam, s2);
                let f2 = which.value(&p2) - target;
                s = s2;
                p = p2;
                f = f2;
                if f2 >= 0.0 {
                    lo = s2;
                    break;
                }
                hi = s2;
            }
        }
        if f == 0.0 {
            return Ok(p);
        }
        let (mut ulo, mut uhi) = (lo.ln(), hi.ln());
        let mut u = s.ln();
        for _ in 0..100 {
            let slope = s * which.slope(&p); // dF/du, < 0 on the stable piece
            let mut un = u - f / slope;
            let newton = slope < 0.0 && un > ulo && un < uhi;
            if !newton {
                un = 0.5 * (ulo + uhi);
            }
            let step = un - u;
            u = un;
            s = u.exp();
            p = contact_core(lam, s);
            f = which.value(&p) - target;
            // A Newton step below 1e-9 leaves an error of order step² (1e-18).
            if f == 0.0 || (newton && step.abs() <= 1e-9 * u.abs().max(1.0)) {
                return Ok(p);
            }
            if f > 0.0 {
                ulo = u;
            } else {
                uhi = u;
            }
            if uhi - ulo <= 1e-15 * u.abs().max(1.0) {
                return Ok(p);
            }
        }
        Err(Error::NotConverged {
            what: "Maugis-Dugdale contact branch",
            iterations: 100,
            residual: f,
        })
    }

    /// A first guess of `s` for a contact radius `Ā` of order `a_bar`, from
    /// the small-s forms `f₁ ≈ 4s³/3`, `f₂ ≈ s²/2` of the contact equation.
    #[inline]
    fn guess_s(&self, a_bar: f64) -> f64 {
        let lam = self.lambda;
        let a = a_bar.max(1e-30);
        let s1 = (1.5 / (lam * a * a)).cbrt();
        let s2 = (1.5 / (lam * lam * a)).sqrt();
        s1.min(s2)
    }
}

#[inline]
fn clamp_stiffness(k: f64) -> f64 {
    if k.is_nan() {
        STIFFNESS_BAR_MAX
    } else {
        k.clamp(-STIFFNESS_BAR_MAX, STIFFNESS_BAR_MAX)
    }
}

#[inline]
fn to_curve_point(p: &Pt) -> CurvePoint {
    CurvePoint {
        a_bar: p.a,
        c_bar: p.a * p.m,
        p_bar: p.p,
        delta_bar: p.d,
        dp_bar: p.dp,
        ddelta_bar: p.dd,
    }
}

impl NormalContact for MaugisDugdale {
    /// Equilibrium at overlap δ (m) under displacement control, following the
    /// history in `old` (see the module documentation: branch 0 separated,
    /// branch 1 on the stable piece). The stiffness is
    /// `dP/dδ = (dP̄/dt)/(dΔ̄/dt) · πwR/(π²w²R/K²)^{1/3}` along the branch.
    ///
    /// Errors: [`Error::InvalidArgument`] for a non-finite δ or a branch other
    /// than 0 or 1; [`Error::OutOfDomain`] when the response overflows.
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        let on_piece = match old.branch {
            0 => false,
            1 => true,
            b => {
                return Err(Error::InvalidArgument {
                    name: "old.branch",
                    value: b as f64,
                    bound: "0 (separated) or 1 (interacting)",
                })
            }
        };
        let lam = self.lambda;
        let ds = self.delta_scale;
        // δ + h₀ in units of the overlap scale: exact where Δ̄ ≈ −2/(πλ) is huge.
        let dh = (delta + self.range()) / ds;
        let stays = if on_piece {
            dh >= self.turn_dh
        } else {
            dh > 0.0
        };
        if !stays {
            return Ok(super::out_of_contact(delta));
        }
        let b = 8.0 * lam / (3.0 * PI);
        let c0 = self.c0_bar;
        if self.turn_kind == 0 && dh <= c0 * (0.5 * c0 - b) {
            // Non-contact branch, increasing piece: C̄ = b + √(b² + 2(Δ̄ + 2/(πλ))).
            let root = (b * b + 2.0 * dh).max(0.0).sqrt();
            let c = b + root;
            let fs = self.force_scale();
            let kbar = clamp_stiffness(-lam * PI * c / root);
            let r = NormalResponse {
                force: -0.5 * lam * PI * c * c * fs,
                delta,
                contact_radius: 0.0,
                stiffness: kbar * fs / ds,
                in_contact: 0,
                reserved: 0,
            };
            let st = ContactState {
                contact_radius: 0.0,
                cohesive_radius: c * self.radius_scale,
                in_contact: 1,
                branch: 1,
            };
            return finite_response((r, st));
        }
        let target = delta / ds;
        let s_end = if self.turn_kind == 1 {
            self.turn_param
        } else {
            S_MAX
        };
        let (a_old, c_old) = (old.contact_radius, old.cohesive_radius);
        let guess = if on_piece && a_old > 0.0 && c_old > a_old && c_old.is_finite() {
            ((c_old - a_old) * (c_old + a_old)).sqrt() / a_old
        } else {
            self.guess_s(target.max(1.0).sqrt())
        };
        let p = self.solve_contact(target, Target::Delta, s_end, guess)?;
        let r = self.contact_response(&p, delta, None);
        let st = ContactState {
            contact_radius: r.contact_radius,
            cohesive_radius: p.a * p.m * self.radius_scale,
            in_contact: 1,
            branch: 1,
        };
        finite_response((r, st))
    }

    /// Equilibrium at force P (N) on the load-controlled stable branch (the
    /// largest contact radius, beyond the minimum of `P̄`).
    ///
    /// Errors: [`Error::OutOfDomain`] below the load-controlled pull-off
    /// force or when the response overflows.
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        let fs = self.force_scale();
        let target = force / fs;
        if target < self.pull_off_load_bar {
            return Err(super::below_pull_off(force));
        }
        let guess = self.guess_s((target + 2.0).max(1.0).cbrt());
        let p = self.solve_contact(target, Target::Load, self.pull_off_load_s, guess)?;
        let mut r = self.contact_response(&p, p.d * self.delta_scale, Some(force));
        r.in_contact = 1;
        finite_response((r, ContactState::default())).map(|rs| rs.0)
    }

    /// Load control: the minimum of P along the equilibrium curve,
    /// `P̄_c πwR` (2πwR as λ → 0, 1.5πwR as λ → ∞). Displacement control: the
    /// force at the jump-out point (minimum of Δ̄) when it is on the contact
    /// branch (λ > λ_c; → −(5/6)πwR as λ → ∞), otherwise the force
    /// `−λπC̄₀²/2 · πwR` where contact is lost continuously (Ā → 0; → −2πwR as
    /// λ → 0). Both are cached at construction.
    fn pull_off_force(&self, control: Control) -> Result<f64> {
        let bar = match control {
            Control::Load => self.pull_off_load_bar,
            Control::Displacement => self.pull_off_disp_bar,
        };
        Ok(bar * self.force_scale())
    }

    /// The JKR/Maugis overlap unit `(π²w²R/K²)^{1/3}` (m), `K = 4E*/3`.
    fn length_scale(&self) -> f64 {
        self.delta_scale
    }

    /// The force is exactly zero outside the cohesive zone, so the reach is
    /// finite (`rel_force` is checked, then ignored):
    ///
    /// * a separated (or fresh) contact feels no force while `δ ≤ −h₀`
    ///   (`h₀ = w/σ₀`): on approach the cohesive zone forms on the
    ///   non-contact branch (Johnson & Greenwood 1997) as soon as δ > −h₀;
    /// * displacement control: a contact on the stable piece stays down to
    ///   the jump-out point, the minimum of `Δ̄` along the path,
    ///   `δ = Δ̄_min (π²w²R/K²)^{1/3}` (≤ −h₀), below which `eval` returns
    ///   zero force; the reach is that point, corrected to the double at
    ///   which `eval`'s rounded comparison switches;
    /// * load control: the overlap at the load-controlled pull-off (the
    ///   minimum of `P̄` on the contact branch), or `−h₀` where that is lower
    ///   (small λ: the cohesive zone reaches further out than the pull-off).
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        let h0 = self.range();
        let ds = self.delta_scale;
        Ok(match control {
            Control::Displacement => {
                let turn = self.turn_dh;
                let guess = (turn * ds - h0).min(-h0);
                super::first_staying(guess, |d| (d + h0) / ds >= turn)
            }
            Control::Load => {
                let p = contact_core(self.lambda, self.pull_off_load_s);
                (p.d * ds).min(-h0)
            }
        })
    }
}
