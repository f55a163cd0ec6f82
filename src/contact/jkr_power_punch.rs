//! JKR theory for axisymmetric power-law punches `f(r) = B r^d`, frictionless
//! or bonded (no slip): Borodich, Galanov & Suarez-Alvarez 2014, J. Mech. Phys.
//! Solids 68:14 ("The JKR-type adhesive contact problems for power-law shaped
//! axisymmetric punches"); thesis (1-37)..(1-40); REFERENCE.md §1, §7.
//!
//! # Formulas
//!
//! Frictionless (1-37), (1-38), with Galin's $C(d)$ = [`galin_c`] and
//! $D(d)$ = [`galin_d`]:
//!
//! $$P(a) = C(d)\\,B\\,E^\ast a^{d+1} - \sqrt{8\pi w E^\ast a^3}, \qquad \delta(a) = D(d)\\,B\\,a^d - \sqrt{\frac{2\pi w a}{E^\ast}} .$$
//!
//! No slip (1-39), (1-40), for a punch bonded to a half-space of Poisson's
//! ratio ν, with $C_\mathrm{NS}$ = [`no_slip_factor`], $\varepsilon$ =
//! [`no_slip_epsilon`] and $k^\ast(d)$ = [`k_star`]:
//!
//! $$P(a) = \frac{C_\mathrm{NS}\\, C(d)\\,B\\,E^\ast a^{d+1}}{k^\ast(d)} - \sqrt{8\pi w E^\ast C_\mathrm{NS}\\, a^3}, \qquad \delta(a) = \frac{D(d)\\,B\\,a^d}{k^\ast(d)} - \sqrt{\frac{2\pi w a}{E^\ast C_\mathrm{NS}}},$$
//!
//! $$k^\ast(d) = d\int_0^1 x^{d-1} \cos\Bigl(\varepsilon \ln\frac{1-x}{1+x}\Bigr)\\,dx, \qquad \varepsilon = \frac{\ln(3-4\nu)}{2\pi} .$$
//!
//! Both reduce to the frictionless law as ν → 1/2 (ε → 0, k* → 1, C_NS → 1)
//! and to Galin's punch ([`super::PowerPunch`]) when w = 0; d = 2,
//! B = 1/(2R) is the JKR sphere ([`super::Jkr`]).
//!
//! Load-controlled pull-off (REFERENCE.md §7), with $A = C(d)BE^\ast$ (no slip: $C_\mathrm{NS}C(d)BE^\ast/k^\ast$) and $b = \sqrt{8\pi w E^\ast}$ (no slip: $\sqrt{8\pi w E^\ast C_\mathrm{NS}}$):
//!
//! $$a_c^{d-1/2} = \frac{3b}{2(d+1)A}, \qquad P_c = -\frac{b(2d-1)}{2(d+1)}\left(\frac{3b}{2(d+1)A}\right)^{3/(2d-1)} .$$
//!
//! d = 2 gives `−(3/2)πwR`; the cone (d = 1, B = cot γ, frictionless) gives
//! `−(54/π) w² tan³γ/E*`.
//!
//! # Reduced form
//!
//! Write the law as `P = α a^{d+1} − β a^{3/2}`, `δ = γ a^d − κ a^{1/2}`. With
//! `a = A₀ t²`, `A₀ = (κ/γ)^{1/(d−1/2)}`, `δ = L Δ`, `L = κ A₀^{1/2}`,
//! `P = F Π`, `F = β A₀^{3/2}`, every case (any B, E*, w, ν) becomes
//!
//! * `Δ = t^{2d} − t`, `Π = (d/(d+1)) t^{2d+2} − t³`,
//!
//! because `αγ⁻¹κβ⁻¹ = C/(2D) = d/(d+1)` for both friction conditions, and
//! `F/L = 2E* C_NS A₀`. On the equilibrium curve `Π = t²(dΔ − t)/(d+1)` and
//! the tangent stiffness is
//! `dP/dδ = (dP/da)/(dδ/da) = 2E* C_NS a·(dΔ + (d−3/2)t)/(dΔ + (d−1/2)t)`
//! (not `2E*a`: that is `∂P/∂δ` at fixed a, see [`super::jkr`]).
//!
//! * Displacement-controlled instability (minimum of δ(a), `dδ/da = 0`):
//!   `t^{2d−1} = 1/(2d)`, `Δ_c = t(1/(2d) − 1)`, force
//!   `Π = −t³(2d+1)/(2(d+1))`.
//! * Load-controlled pull-off (minimum of P(a)): `t^{2d−1} = 3/(2d)`,
//!   `Π_c = −t³(2d−1)/(2(d+1))`; in dimensional form, with `A = α`, `b = β`,
//!   the pull-off of *Formulas*.
//!
//! # Solving for the contact radius
//!
//! The stable branch (`dδ/da > 0` under displacement control, `dP/da > 0` under
//! load control) is the root `t` beyond the fold of `c t^m − t^p = X`
//! (`m = 2d, p = 1, c = 1` for δ; `m = 2d+2, p = 3, c = d/(d+1)` for P). The
//! function is convex with a positive third derivative beyond the fold, so:
//! for `X < 0` Newton in t starts from the smaller of two upper bounds (the
//! root at X = 0, and the root of the quadratic model at the fold, which lies
//! below the function) and decreases monotonically to the root; for `X ≥ 0`
//! Newton on `G(s) = ln c + ms − ln(e^{ps} + X)`, `s = ln t` (increasing,
//! concave, `G' ∈ [m−p, m]`) starts from a lower bound and increases
//! monotonically. A step that leaves the bracket is replaced by bisection;
//! iterations are capped ([`MAX_ITERATIONS`], then
//! [`Error::NotConverged`]). Relative accuracy a few ulp away
//! from the fold (tests/jkr.rs checks the equilibrium equations to 1e-11).
//!
//! Hysteresis under displacement control is that of [`super::Jkr`]: jump-in at
//! δ = 0 to the stable branch, jump-out below the minimum δ_c of δ(a).
//!
//! # References
//!
//! * Thesis (1-37)–(1-40); REFERENCE.md §1, §7.
//! * F. M. Borodich, B. A. Galanov, M. M. Suarez-Alvarez (2014), "The JKR-type
//!   adhesive contact problems for power-law shaped axisymmetric punches",
//!   J. Mech. Phys. Solids 68, 14–32,
//!   [doi:10.1016/j.jmps.2014.03.003](https://doi.org/10.1016/j.jmps.2014.03.003).
//! * K. L. Johnson, K. Kendall, A. D. Roberts (1971), Proc. R. Soc. Lond. A 324,
//!   301–313, [doi:10.1098/rspa.1971.0141](https://doi.org/10.1098/rspa.1971.0141)
//!   (d = 2).
//! * L. A. Galin (1946), J. Appl. Math. Mech. (PMM) 10, 425–448 (the shape
//!   terms $C(d)$, $D(d)$).

use super::jkr::contact_state;
use super::out_of_contact;
use super::power_punch::{check_shape, galin_c, galin_d};
use super::{check_delta, check_force, ContactState, Control, NormalContact, NormalResponse};
use crate::error::{check, Error, Result};
use crate::material::{no_slip_epsilon, no_slip_factor};
use core::f64::consts::PI;

/// Cap on the Newton iterations of the contact-radius solve.
pub const MAX_ITERATIONS: u32 = 100;

/// Inputs of a JKR power-law punch, as [`JkrPowerPunch::from_params`] and
/// C's `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JkrPowerPunchParams {
    /// Shape coefficient B (m^{1−d}, > 0) of the profile `f(r) = B r^d`.
    pub b: f64,
    /// Shape exponent d (1 ≤ d ≤ 100).
    pub d: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Work of adhesion w (J/m², ≥ 0).
    pub work_of_adhesion: f64,
    /// Poisson's ratio ν of the half-space (0 ≤ ν ≤ 0.5): gives C_NS and
    /// k*(d) when `no_slip` = 1; range-checked only when 0.
    pub nu: f64,
    /// 1 for a punch bonded to the half-space (no slip), 0 frictionless.
    pub no_slip: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// JKR power-law punch, frictionless or no-slip. Its inputs are
/// [`JkrPowerPunchParams`]; it caches the factors and scales of the module
/// docs.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrPowerPunch {
    /// B (m^{1−d}).
    pub(crate) b: f64,
    /// d.
    pub(crate) d: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// w (J/m²).
    pub(crate) work_of_adhesion: f64,
    /// ν.
    pub(crate) nu: f64,
    /// 1 bonded, 0 frictionless.
    pub(crate) no_slip: i32,
    /// 0.
    pub(crate) reserved: i32,
    /// Cached no-slip factor C_NS (1 when frictionless).
    no_slip_factor: f64,
    /// Cached shape factor k*(d) of the bonded punch (1 when frictionless).
    k_star: f64,
    /// Cached `α = C_NS C(d) B E*/k*` (Pa·m^{1−d}), `P_shape = α a^{d+1}`.
    force_coefficient: f64,
    /// Cached `γ = D(d) B/k*` (m^{1−d}), `δ_shape = γ a^d`.
    depth_coefficient: f64,
    /// Cached radius scale `A₀ = (κ/γ)^{1/(d−1/2)}` (m), `κ = √(2πw/(E*C_NS))`;
    /// 0 without adhesion.
    radius_scale: f64,
    /// Cached overlap scale `L = κ A₀^{1/2}` (m); 0 without adhesion.
    delta_scale: f64,
    /// Cached force scale `F = √(8πwE*C_NS) A₀^{3/2}` (N); 0 without adhesion.
    force_scale: f64,
    /// Cached displacement-controlled instability δ_c (m, ≤ 0), the minimum of
    /// δ(a).
    critical_delta: f64,
    /// Cached reduced radius `t_c = (2d)^{−1/(2d−1)}` at δ_c.
    critical_t: f64,
}

law_inputs!(
    JkrPowerPunch,
    JkrPowerPunchParams {
        b,
        d,
        e_star,
        work_of_adhesion,
        nu,
        no_slip,
        reserved
    }
);

impl JkrPowerPunch {
    /// Frictionless adhesive punch `f(r) = b r^d` (b in m^{1−d}, 1 ≤ d ≤ 100),
    /// contact modulus `e_star` (Pa), work of adhesion (J/m², ≥ 0).
    pub fn new(b: f64, d: f64, e_star: f64, work_of_adhesion: f64) -> Result<Self> {
        let (b, d) = check_shape(b, d)?;
        let e_star = check::positive("e_star", e_star)?;
        let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
        Ok(Self::build(b, d, e_star, w, (0.0, 0), 1.0, 1.0))
    }

    /// Punch bonded (no slip) to a half-space of Poisson's ratio `nu`
    /// (0 ≤ ν ≤ 0.5), thesis (1-39), (1-40). Computes k*(d) by quadrature
    /// ([`k_star`]) once.
    pub fn no_slip(b: f64, d: f64, e_star: f64, work_of_adhesion: f64, nu: f64) -> Result<Self> {
        let (b, d) = check_shape(b, d)?;
        let e_star = check::positive("e_star", e_star)?;
        let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
        let c_ns = no_slip_factor(nu)?;
        let ks = k_star(d, nu)?;
        Ok(Self::build(b, d, e_star, w, (nu, 1), c_ns, ks))
    }

    /// The punch of the inputs `p`: `no_slip` is checked first (0 or 1),
    /// then, when frictionless, `nu` (range only), then as by
    /// [`JkrPowerPunch::new`] or [`JkrPowerPunch::no_slip`].
    pub fn from_params(p: &JkrPowerPunchParams) -> Result<Self> {
        if super::no_slip_flag(p.no_slip)? {
            Self::no_slip(p.b, p.d, p.e_star, p.work_of_adhesion, p.nu)
        } else {
            let nu = check::poisson("nu", p.nu)?;
            Ok(Self {
                nu,
                ..Self::new(p.b, p.d, p.e_star, p.work_of_adhesion)?
            })
        }
    }

    /// The no-slip factor `C_NS(ν)` (1 when frictionless).
    #[inline]
    pub fn no_slip_factor(&self) -> f64 {
        self.no_slip_factor
    }

    /// The shape factor k*(d) of the bonded punch (1 when frictionless).
    #[inline]
    pub fn k_star(&self) -> f64 {
        self.k_star
    }

    /// The displacement-controlled instability δ_c (m, ≤ 0), the minimum of
    /// δ(a); 0 without adhesion.
    #[inline]
    pub fn critical_delta(&self) -> f64 {
        self.critical_delta
    }

    fn build(
        b: f64,
        d: f64,
        e_star: f64,
        w: f64,
        (nu, no_slip): (f64, i32),
        c_ns: f64,
        ks: f64,
    ) -> Self {
        let alpha = c_ns * galin_c(d) * b * e_star / ks;
        let gamma = galin_d(d) * b / ks;
        let kappa = (2.0 * PI * w / (e_star * c_ns)).sqrt();
        let beta = (8.0 * PI * w * e_star * c_ns).sqrt();
        let a0 = (kappa / gamma).powf(1.0 / (d - 0.5));
        let l = kappa * a0.sqrt();
        let f = beta * a0 * a0.sqrt();
        let tc = (2.0 * d).powf(-1.0 / (2.0 * d - 1.0));
        let ok = |x: f64| x.is_normal() && x > 0.0;
        let adhesive = ok(kappa) && ok(a0) && ok(l) && ok(1.0 / l) && ok(f);
        Self {
            b,
            d,
            e_star,
            work_of_adhesion: w,
            nu,
            no_slip,
            reserved: 0,
            no_slip_factor: c_ns,
            k_star: ks,
            force_coefficient: alpha,
            depth_coefficient: gamma,
            radius_scale: if adhesive { a0 } else { 0.0 },
            delta_scale: if adhesive { l } else { 0.0 },
            force_scale: if adhesive { f } else { 0.0 },
            critical_delta: if adhesive {
                l * tc * (0.5 / d - 1.0)
            } else {
                0.0
            },
            critical_t: tc,
        }
    }

    #[inline]
    fn adhesive(&self) -> bool {
        self.delta_scale > 0.0
    }

    /// `√(2πw/(E* C_NS))` (m^{1/2}).
    #[inline]
    fn kappa(&self) -> f64 {
        (2.0 * PI * self.work_of_adhesion / (self.e_star * self.no_slip_factor)).sqrt()
    }

    /// `√(8πwE* C_NS)` (N/m^{3/2}).
    #[inline]
    fn beta(&self) -> f64 {
        (8.0 * PI * self.work_of_adhesion * self.e_star * self.no_slip_factor).sqrt()
    }

    /// Force at contact radius `a` (m): `P = α a^{d+1} − β a^{3/2}` ((1-37) or
    /// (1-39)).
    pub fn force_at_radius(&self, a: f64) -> f64 {
        self.force_coefficient * a.powf(self.d + 1.0) - self.beta() * a * a.sqrt()
    }

    /// Overlap at contact radius `a` (m): `δ = γ a^d − κ a^{1/2}` ((1-38) or
    /// (1-40)).
    pub fn delta_at_radius(&self, a: f64) -> f64 {
        self.depth_coefficient * a.powf(self.d) - self.kappa() * a.sqrt()
    }

    /// Contact radius (m) on the stable branch at overlap `delta` (m); `None`
    /// below δ_c. Errors only if the solver fails to converge.
    pub fn contact_radius_at_delta(&self, delta: f64) -> Result<Option<f64>> {
        if delta.is_nan() || delta < self.critical_delta || (!self.adhesive() && delta < 0.0) {
            return Ok(None);
        }
        Ok(Some(self.on_branch(delta)?.contact_radius))
    }

    /// The reduced displacement equation `t^{2d} − t = Δ`.
    #[inline]
    fn displacement_eq(&self) -> Reduced {
        let m = 2.0 * self.d;
        let tf = self.critical_t;
        Reduced {
            c: 1.0,
            m,
            p: 1.0,
            t_fold: tf,
            x_fold: tf * (0.5 / self.d - 1.0),
            curv_fold: (m - 1.0) / tf,
            t_zero: 1.0,
        }
    }

    /// The reduced load equation `(d/(d+1)) t^{2d+2} − t³ = Π`.
    fn load_eq(&self) -> Reduced {
        let d = self.d;
        let c = d / (d + 1.0);
        let m = 2.0 * d + 2.0;
        let tf = (1.5 / d).powf(1.0 / (2.0 * d - 1.0));
        Reduced {
            c,
            m,
            p: 3.0,
            t_fold: tf,
            x_fold: -tf * tf * tf * (2.0 * d - 1.0) / (2.0 * (d + 1.0)),
            curv_fold: 3.0 * (m - 3.0) * tf,
            t_zero: c.powf(-1.0 / (m - 3.0)),
        }
    }

    /// Response on the stable branch at δ ≥ δ_c.
    fn on_branch(&self, delta: f64) -> Result<NormalResponse> {
        if !self.adhesive() {
            return Ok(self.galin(delta, self.radius_at_shape_delta(delta)));
        }
        let big = delta / self.delta_scale;
        if !big.is_finite() {
            return Ok(self.galin(delta, self.radius_at_shape_delta(delta)));
        }
        let t = self.displacement_eq().stable_root(big)?;
        let d = self.d;
        let a = self.radius_scale * t * t;
        let force = self.force_scale * t * t * (d * big - t) / (d + 1.0);
        let stiffness = self.tangent(a, t, big);
        Ok(respond(force, delta, a, stiffness))
    }

    /// `2E*C_NS a (dΔ + (d−3/2)t)/(dΔ + (d−1/2)t)`, denominator kept
    /// ≥ ε·d(|Δ| + t) (vertical tangent at the fold: about −1/ε times `2E*a`,
    /// finite).
    #[inline]
    fn tangent(&self, a: f64, t: f64, big: f64) -> f64 {
        let d = self.d;
        let den = (d * big + (d - 0.5) * t).max(f64::EPSILON * d * (big.abs() + t));
        2.0 * self.e_star * self.no_slip_factor * a * (d * big + (d - 1.5) * t) / den
    }

    #[inline]
    fn radius_at_shape_delta(&self, delta: f64) -> f64 {
        (delta / self.depth_coefficient).powf(1.0 / self.d)
    }

    /// Non-adhesive (Galin, with the no-slip factors) response at radius a.
    #[inline]
    fn galin(&self, delta: f64, a: f64) -> NormalResponse {
        let force = self.force_coefficient * a.powf(self.d + 1.0);
        respond(force, delta, a, 2.0 * self.e_star * self.no_slip_factor * a)
    }

    fn load_pull_off(&self) -> f64 {
        if self.adhesive() {
            self.force_scale * self.load_eq().x_fold
        } else {
            0.0
        }
    }
}

#[inline]
fn respond(force: f64, delta: f64, a: f64, stiffness: f64) -> NormalResponse {
    NormalResponse {
        force,
        delta,
        contact_radius: a,
        stiffness,
        in_contact: 1,
        reserved: 0,
    }
}

/// `c t^m − t^p = X` on the branch beyond its fold (module docs).
struct Reduced {
    c: f64,
    m: f64,
    p: f64,
    /// Fold abscissa, where `c m t^{m−1} = p t^{p−1}`.
    t_fold: f64,
    /// Value `c t^m − t^p` at the fold (the minimum, < 0).
    x_fold: f64,
    /// Second derivative at the fold, `p(m−p)t^{p−2}`.
    curv_fold: f64,
    /// Root at X = 0, `c^{−1/(m−p)}`.
    t_zero: f64,
}

impl Reduced {
    /// The stable root t ≥ t_fold for X ≥ x_fold (X below x_fold by rounding is
    /// treated as x_fold).
    fn stable_root(&self, x: f64) -> Result<f64> {
        let (c, m, p) = (self.c, self.m, self.p);
        let tol = 4.0 * f64::EPSILON;
        if x < 0.0 {
            // Newton in t from above on q(t) = c t^m − t^p − X: convex,
            // increasing, q''' > 0 beyond the fold.
            let quad = self.t_fold + (2.0 * (x - self.x_fold).max(0.0) / self.curv_fold).sqrt();
            // Bracket: q(lo) ≤ 0 ≤ q(hi).
            let mut lo = self.t_fold;
            let mut hi = self.t_zero.min(quad).max(lo);
            let mut t = hi;
            for _ in 0..MAX_ITERATIONS {
                let tp = t.powf(p);
                let tm = t.powf(m);
                let q = c * tm - tp - x;
                if q == 0.0 {
                    return Ok(t);
                }
                if q > 0.0 {
                    hi = t;
                } else {
                    lo = t;
                }
                let qp = (c * m * tm - p * tp) / t;
                let mut next = t - q / qp;
                if !(next > lo && next < hi) {
                    next = 0.5 * (lo + hi);
                }
                if hi - lo <= tol * hi || (next - t).abs() <= tol * t {
                    return Ok(next);
                }
                t = next;
            }
            Err(Error::NotConverged {
                what: "JKR power-law punch contact radius (Newton, t)",
                iterations: MAX_ITERATIONS,
                residual: c * t.powf(m) - t.powf(p) - x,
            })
        } else {
            // Newton on G(s) = ln c + m s − ln(e^{ps} + X), s = ln t, from below.
            let lnc = c.ln();
            let mut s = self
                .t_zero
                .ln()
                .max(if x > 0.0 { (x / c).ln() / m } else { f64::MIN });
            for _ in 0..MAX_ITERATIONS {
                let eps = (p * s).exp();
                let den = eps + x;
                let g = lnc + m * s - den.ln();
                let gp = m - p * eps / den;
                let step = g / gp;
                let next = s - step;
                if step.abs() <= tol * (1.0 + s.abs()) || step >= 0.0 || step.is_nan() {
                    return Ok(next.exp());
                }
                s = next;
            }
            Err(Error::NotConverged {
                what: "JKR power-law punch contact radius (Newton, ln t)",
                iterations: MAX_ITERATIONS,
                residual: lnc + m * s - ((p * s).exp() + x).ln(),
            })
        }
    }
}

impl NormalContact for JkrPowerPunch {
    /// Displacement-controlled step: jump-in at δ = 0, jump-out below δ_c.
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        if !super::stays_in_contact(old, delta, self.critical_delta) {
            return Ok(out_of_contact(delta));
        }
        let r = self.on_branch(delta)?;
        Ok((r, contact_state(&r)))
    }

    /// Stable branch (`dP/da ≥ 0`) at load `force` ≥ the load-controlled
    /// pull-off.
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        if force < self.load_pull_off() {
            return Err(super::below_pull_off(force));
        }
        let pi = force / self.force_scale;
        if !self.adhesive() || !pi.is_finite() {
            let a = (force / self.force_coefficient).powf(1.0 / (self.d + 1.0));
            let delta = self.depth_coefficient * a.powf(self.d);
            return Ok(respond(
                force,
                delta,
                a,
                2.0 * self.e_star * self.no_slip_factor * a,
            ));
        }
        let t = self.load_eq().stable_root(pi)?;
        let big = t.powf(2.0 * self.d) - t;
        let a = self.radius_scale * t * t;
        // Stable under load control: dP/dδ ≥ 0 (0 at the pull-off; the clamp
        // only removes rounding there).
        let stiffness = self.tangent(a, t, big).max(0.0);
        Ok(respond(force, self.delta_scale * big, a, stiffness))
    }

    /// Load: `P_c` of the module docs; displacement: the force at δ_c,
    /// `−F t_c³(2d+1)/(2(d+1))`. 0 when w = 0.
    fn pull_off_force(&self, control: Control) -> Result<f64> {
        if !self.adhesive() {
            return Ok(0.0);
        }
        Ok(match control {
            Control::Load => self.load_pull_off(),
            Control::Displacement => {
                let d = self.d;
                let t = self.critical_t;
                -self.force_scale * t * t * t * (2.0 * d + 1.0) / (2.0 * (d + 1.0))
            }
        })
    }

    /// `|δ_c|` with adhesion; without, the radius at which the punch depth
    /// equals the radius, `γ^{−1/(d−1)}` (d > 1), or 1 m for the cone (and,
    /// as for [`super::PowerPunch`], when that power under- or overflows).
    fn length_scale(&self) -> f64 {
        let l = if self.adhesive() {
            -self.critical_delta
        } else if self.d > 1.0 {
            self.depth_coefficient.powf(-1.0 / (self.d - 1.0))
        } else {
            1.0
        };
        if l.is_normal() && l > 0.0 {
            l
        } else {
            1.0
        }
    }

    /// Displacement control: δ_c, the minimum of δ(a) where `eval` jumps
    /// out (`δ_c = L t_c(1/(2d) − 1)`, `t_c = (2d)^{−1/(2d−1)}`). Load
    /// control: the overlap at the load-controlled pull-off, the fold
    /// `t_f = (3/(2d))^{1/(2d−1)}` of the load equation, where
    /// `Δ = t_f^{2d} − t_f = t_f(3/(2d) − 1)`, so `δ = L t_f(3/(2d) − 1)`
    /// (d = 2: the JKR sphere's `−(3/4)^{1/3}L/4`). Out of contact the punch
    /// touches only at δ ≥ 0, so a fresh contact has a force from δ = 0 on:
    /// the load-control reach is `min(δ, 0)` (for d < 3/2 the load pull-off
    /// lies at δ > 0). 0 when w = 0; `rel_force` is checked, then ignored.
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        if !self.adhesive() {
            return Ok(0.0);
        }
        Ok(match control {
            Control::Displacement => self.critical_delta,
            Control::Load => {
                let t = self.load_eq().t_fold;
                (self.delta_scale * t * (1.5 / self.d - 1.0)).min(0.0)
            }
        })
    }
}

/// Step of the tanh-sinh rule used by [`k_star`] (finest level).
const K_STAR_STEP: f64 = 1.0 / 64.0;
/// Half-width of the tanh-sinh abscissa range; beyond it the weights are
/// below 1e-35.
const K_STAR_RANGE: f64 = 4.0;

/// Shape factor of a power-law punch bonded to a half-space (Borodich, Galanov
/// & Suarez-Alvarez 2014; REFERENCE.md §7):
/// `k*(d) = d ∫₀¹ x^{d−1} cos[ε ln((1−x)/(1+x))] dx`, `ε = ln(3−4ν)/(2π)`.
///
/// `k*(1) = πε/sinh(πε)`; k* = 1 at ν = 1/2. See [`k_star_with_error`] for the
/// method; accuracy better than 1e-13.
pub fn k_star(d: f64, nu: f64) -> Result<f64> {
    k_star_with_error(d, nu).map(|(k, _)| k)
}

/// [`k_star`] with an error estimate: returns `(k*, |difference to the rule
/// with twice the step|)`.
///
/// Method: tanh-sinh quadrature, `x = 1/(1 + e^{−π sinh u})`,
/// `1 − x = 1/(1 + e^{π sinh u})` (both computed directly, so neither end
/// loses digits), trapezoidal in u with step 1/64 over |u| ≤ 4 (513 nodes).
/// The integrand is bounded but has two end-point features: `x^{d−1}` is not
/// smooth at x = 0 for non-integer d, and `cos[ε ln(1−x)]` oscillates
/// log-periodically as x → 1 (ε ≤ ln3/(2π) ≈ 0.175, so at most a few periods
/// before the weights vanish doubly exponentially). Both are end-point
/// singularities of the kind the double-exponential rule integrates at
/// geometric speed (Takahashi & Mori 1974); the half-step comparison is below 1e-13
/// (tests/jkr.rs).
pub fn k_star_with_error(d: f64, nu: f64) -> Result<(f64, f64)> {
    let d = check::in_range("d", d, 1.0, super::power_punch::MAX_EXPONENT, "in [1, 100]")?;
    let eps = no_slip_epsilon(nu)?;
    let n = (K_STAR_RANGE / K_STAR_STEP) as i32;
    let (mut fine, mut coarse) = (0.0, 0.0);
    for i in -n..=n {
        let u = i as f64 * K_STAR_STEP;
        let z = PI * u.sinh();
        // ln x = −softplus(−z), ln(1−x) = −softplus(z).
        let ln_x = -softplus(-z);
        let ln_1mx = -softplus(z);
        let one_m_x = ln_1mx.exp();
        let ln_1px = (-0.5 * one_m_x).ln_1p() + core::f64::consts::LN_2; // ln(2 − (1−x))
                                                                         // dx/du = π cosh u · x(1−x)
        let w = PI * u.cosh() * (ln_x + ln_1mx).exp();
        let f = d * ((d - 1.0) * ln_x).exp() * (eps * (ln_1mx - ln_1px)).cos() * w;
        fine += f;
        if i % 2 == 0 {
            coarse += f;
        }
    }
    let fine = fine * K_STAR_STEP;
    let coarse = coarse * 2.0 * K_STAR_STEP;
    Ok((fine, (fine - coarse).abs()))
}

/// `ln(1 + e^z)` without overflow or loss.
#[inline]
fn softplus(z: f64) -> f64 {
    z.max(0.0) + (-z.abs()).exp().ln_1p()
}
