//! Borodich self-similar rescaling of indentation (thesis chapter 3), the
//! Galanov effective shape of the unloading branch, the extraction of the
//! hardening index κ and the bluntness index d from log–log slopes, and the
//! Zhuravlev-type integrals for power-law asperities.
//!
//! # Formulas
//!
//! ## Setting
//!
//! A punch of shape `f(r) = B r^d` (d ≥ 1) is pressed into a half-space whose
//! stress–strain curve is a power law `σ ∝ ε^κ` (κ = 1 linear elastic, κ → 0
//! perfectly plastic). The contact problem is self-similar (Borodich 1983,
//! 1989, 1993; thesis (3-10)..(3-12)): from **one** known solution
//! `(P₁, δ₁, a₁)` for the shape scale `B₁`, the solution for any load P and any
//! shape scale `B = λ B₁` follows by rescaling, (3-13), (3-14) and (3-24),
//! with $s = 2 + \kappa(d-1)$:
//!
//! $$\delta(\lambda, P) = \lambda^{(2-\kappa)/s}\Bigl(\frac{P}{P_1}\Bigr)^{d/s}\delta_1, \qquad a(\lambda, P) = \lambda^{-\kappa/s}\Bigl(\frac{P}{P_1}\Bigr)^{1/s}a_1, \qquad P(\lambda, \delta) = \lambda^{(\kappa-2)/d}\Bigl(\frac{\delta}{\delta_1}\Bigr)^{s/d}P_1 ,$$
//!
//! where λ is the ratio of the shape coefficients of the *new* and the *known*
//! punch, `λ = B/B₁`: for spheres (`B = 1/(2R)`) `λ = R₁/R` (3-15), for cones
//! (`B = cot γ`) `λ = tan γ₁/tan γ` (3-16). For a sphere (d = 2) these are
//! (3-17) `δ ∝ (R₁/R)^{(2−κ)/(2+κ)} P^{2/(2+κ)}` and (3-18)
//! `a ∝ (R/R₁)^{κ/(2+κ)} P^{1/(2+κ)}`; κ = 1, d = 2 is Hertz
//! (`δ ∝ R^{−1/3} P^{2/3}`, `a ∝ R^{1/3} P^{1/3}`) and κ = 1, any d is Galin
//! ([`crate::contact::PowerPunch`]).
//!
//! ## Extraction of κ and d (thesis §3.4–3.5, (3-20), (3-26))
//!
//! At λ = 1 the log–log slope of the loading branch m_l ([`loading_slope`])
//! and, for the elastic unloading branch (κ = 1), m_u ([`unloading_slope`])
//! give d ([`d_from_unloading_slope`]) and κ ([`kappa_from_loading_slope`];
//! for a sphere $\kappa = 2 m_l - 2$, (3-21)):
//!
//! $$m_l = \frac{2 + \kappa(d-1)}{d}, \qquad m_u = \frac{d+1}{d}, \qquad d = \frac{1}{m_u - 1}, \qquad \kappa = \frac{d\\,m_l - 2}{d - 1} .$$
//!
//! When κ is known instead, $d = (2 - \kappa)/(m_l - \kappa)$
//! ([`d_from_loading_slope`]). For a cone (d = 1) $m_l = 2$ whatever κ is:
//! κ cannot be read from the loading slope of a cone, and the functions say
//! so with [`Error::OutOfDomain`].
//!
//! ## Galanov effect (thesis §2.5, (3-22), (3-23), (2-18), (2-19))
//!
//! The elastic unloading branch of a sphere of radius R is that of a sphere
//! in its own crater of radius $R_\mathrm{medium}$, of effective radius $R_2$
//! (3-23), which follows from any Hertz solution `(P₁, δ₁)` on `R₁` and a
//! measured unloading point `(P₂, δ₂)` by rescaling with κ = 1 (3-22). The
//! cone analogue is the effective cotangent $B_\mathrm{eff}$ (2-18):
//!
//! $$R_2 = R_1\Bigl(\frac{P_2}{P_1}\Bigr)^2\Bigl(\frac{\delta_1}{\delta_2}\Bigr)^3, \qquad \frac{1}{R_2} = \frac{1}{R} - \frac{1}{R_\mathrm{medium}}, \qquad B_\mathrm{eff} = \cot\gamma_i - \cot\gamma_f .$$
//!
//! # Conventions and notes
//!
//! * (P₁, δ₁, a₁) is the known solution ([`KnownSolution`]), best taken at the
//!   maximum indentation point (thesis §3.6.1).
//! * The thesis prints κ = −0.467 for Goldsmith–Lyman where `2·0.766 − 2 =
//!   −0.468`, and d = 4.24 for Gadelrab where `1/(1.24 − 1) = 4.17` (its printed
//!   slope 1.24 is rounded; κ = 1.25 follows from either d). The functions here
//!   implement the relations, not the printed roundings.
//! * The exponent of λ in (3-13) is `(2−κ)/s`; at κ = 2 the load–depth relation
//!   does not depend on the punch scale and λ cannot be recovered from two
//!   points ([`shape_scale_from_points`] refuses κ = 2).
//!
//! # References
//!
//! * Thesis chapter 3, (3-10)–(3-28); §2.5, (2-18), (2-19).
//! * F. M. Borodich (1983), "Similarity in the problem of contact between
//!   elastic bodies", J. Appl. Math. Mech. (PMM) 47, 440–442.
//! * F. M. Borodich (1993), "The Hertz frictional contact between nonlinear
//!   elastic anisotropic bodies (the similarity approach)", Int. J. Solids
//!   Struct. 30, 1513–1526.
//! * B. A. Galanov (1981), the self-similar contact problem and the effective
//!   shape of the unloading branch (in Russian; as cited by the thesis, §2.5).
//! * L. A. Galin (1946), J. Appl. Math. Mech. (PMM) 10, 425–448 (κ = 1).
//! * H. Hertz (1882), J. reine angew. Math. 92, 156–171,
//!   [doi:10.1515/crll.1882.92.156](https://doi.org/10.1515/crll.1882.92.156)
//!   (κ = 1, d = 2).

use crate::error::{check, Error, Result};

/// Largest accepted hardening index κ. The theory has no upper bound, but
/// κ above 10 is far outside any material (and outside the validity of the
/// small-strain setting the rescaling rests on).
const KAPPA_MAX: f64 = 10.0;
/// Largest accepted bluntness index d, as for [`crate::contact::PowerPunch`].
const D_MAX: f64 = 100.0;
/// |d − 1| below which κ is declared not identifiable from the loading slope.
const D_CONE_TOLERANCE: f64 = 1e-6;

fn check_kappa(kappa: f64) -> Result<f64> {
    check::in_range("kappa", kappa, 0.0, KAPPA_MAX, "in [0, 10]")
}

fn check_d(d: f64) -> Result<f64> {
    check::in_range("d", d, 1.0, D_MAX, "in [1, 100]")
}

/// A power-law punch `B r^d` on a power-law material `σ ∝ ε^κ`: the exponents
/// of the rescaling relations (3-13), (3-14), (3-24).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Rescaling {
    /// Hardening index κ (dimensionless), `0 ≤ κ ≤ 10` (κ = 1 linear elastic,
    /// κ = 0 perfectly plastic).
    pub kappa: f64,
    /// Bluntness index d of the punch `B r^d` (dimensionless), `1 ≤ d ≤ 100`.
    pub d: f64,
}

/// One known solution of the contact problem, the seed of rescaling: load P₁
/// (N), depth δ₁ (m) and, when known, contact radius a₁ (m) for the punch of
/// shape scale B₁ (λ = 1).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct KnownSolution {
    /// Load P₁ (N), > 0.
    pub load: f64,
    /// Depth δ₁ (m), > 0.
    pub depth: f64,
    /// Contact radius a₁ (m), > 0; only [`Rescaling::radius`] needs it (pass
    /// any positive value otherwise, e.g. 1).
    pub radius: f64,
}

impl KnownSolution {
    /// A known solution `(P₁, δ₁, a₁)`; all three finite and > 0.
    pub fn new(load: f64, depth: f64, radius: f64) -> Result<Self> {
        Ok(Self {
            load: check::positive("load", load)?,
            depth: check::positive("depth", depth)?,
            radius: check::positive("radius", radius)?,
        })
    }

    fn checked(&self) -> Result<Self> {
        Self::new(self.load, self.depth, self.radius)
    }
}

impl Rescaling {
    /// The rescaling exponents for hardening index `kappa` ∈ [0, 10] and
    /// bluntness `d` ∈ [1, 100].
    pub fn new(kappa: f64, d: f64) -> Result<Self> {
        Ok(Self {
            kappa: check_kappa(kappa)?,
            d: check_d(d)?,
        })
    }

    /// Sphere (d = 2) on a material of index `kappa`.
    pub fn sphere(kappa: f64) -> Result<Self> {
        Self::new(kappa, 2.0)
    }

    /// `s = 2 + κ(d − 1)`, the common denominator of (3-13), (3-14).
    #[inline]
    pub fn s(&self) -> f64 {
        2.0 + self.kappa * (self.d - 1.0)
    }

    /// Log–log slope of load against depth at fixed λ, `s/d` ((3-20), (3-26)).
    #[inline]
    pub fn load_depth_exponent(&self) -> f64 {
        self.s() / self.d
    }

    /// Exponent of λ in (3-13): `(2 − κ)/s`.
    #[inline]
    pub fn depth_lambda_exponent(&self) -> f64 {
        (2.0 - self.kappa) / self.s()
    }

    /// Exponent of λ in (3-14): `−κ/s`.
    #[inline]
    pub fn radius_lambda_exponent(&self) -> f64 {
        -self.kappa / self.s()
    }

    /// Exponent of λ in (3-24): `(κ − 2)/d`.
    #[inline]
    pub fn load_lambda_exponent(&self) -> f64 {
        (self.kappa - 2.0) / self.d
    }

    /// Depth (m) at load `load` (N, ≥ 0) for the punch of scale `lambda = B/B₁`
    /// (> 0), (3-13): `δ = λ^{(2−κ)/s} (P/P₁)^{d/s} δ₁`.
    ///
    /// Errors with [`Error::OutOfDomain`] naming the most extreme of `lambda`,
    /// `load`, `known.load`, `known.depth` when δ is not finite (arguments
    /// near the ends of `f64`).
    pub fn depth(&self, lambda: f64, load: f64, known: &KnownSolution) -> Result<f64> {
        let k = known.checked()?;
        let lambda = check::positive("lambda", lambda)?;
        let load = check::non_negative("load", load)?;
        let s = self.s();
        check::finite_of(
            lambda.powf(self.depth_lambda_exponent()) * (load / k.load).powf(self.d / s) * k.depth,
            &[
                ("lambda", lambda),
                ("load", load),
                ("known.load", k.load),
                ("known.depth", k.depth),
            ],
            "the rescaled depth is not finite",
        )
    }

    /// Contact radius (m) at load `load` (N, ≥ 0), (3-14):
    /// `a = λ^{−κ/s} (P/P₁)^{1/s} a₁`.
    ///
    /// Errors with [`Error::OutOfDomain`] naming the most extreme of `lambda`,
    /// `load`, `known.load`, `known.radius` when a is not finite.
    pub fn radius(&self, lambda: f64, load: f64, known: &KnownSolution) -> Result<f64> {
        let k = known.checked()?;
        let lambda = check::positive("lambda", lambda)?;
        let load = check::non_negative("load", load)?;
        let s = self.s();
        check::finite_of(
            lambda.powf(self.radius_lambda_exponent()) * (load / k.load).powf(1.0 / s) * k.radius,
            &[
                ("lambda", lambda),
                ("load", load),
                ("known.load", k.load),
                ("known.radius", k.radius),
            ],
            "the rescaled contact radius is not finite",
        )
    }

    /// Load (N) at depth `depth` (m, ≥ 0), (3-24):
    /// `P = λ^{(κ−2)/d} (δ/δ₁)^{s/d} P₁`. With λ = 1 this is (3-19)/(3-25).
    ///
    /// Errors with [`Error::OutOfDomain`] naming the most extreme of `lambda`,
    /// `depth`, `known.load`, `known.depth` when P is not finite.
    pub fn load(&self, lambda: f64, depth: f64, known: &KnownSolution) -> Result<f64> {
        let k = known.checked()?;
        let lambda = check::positive("lambda", lambda)?;
        let depth = check::non_negative("depth", depth)?;
        check::finite_of(
            lambda.powf(self.load_lambda_exponent())
                * (depth / k.depth).powf(self.load_depth_exponent())
                * k.load,
            &[
                ("lambda", lambda),
                ("depth", depth),
                ("known.load", k.load),
                ("known.depth", k.depth),
            ],
            "the rescaled load is not finite",
        )
    }
}

/// λ for spheres (3-15): `λ = R₁/R`, `R₁` the radius of the known solution and
/// `R` the new one (m, both > 0). [`Error::OutOfDomain`] (naming the more
/// extreme radius) when the ratio leaves `f64` (overflows or underflows to 0).
pub fn lambda_spheres(known_radius: f64, radius: f64) -> Result<f64> {
    let r1 = check::positive("known_radius", known_radius)?;
    let r = check::positive("radius", radius)?;
    positive_result(
        r1 / r,
        &[("known_radius", r1), ("radius", r)],
        "lambda = known_radius/radius is not finite and > 0",
    )
}

/// `Ok(value)` when finite and > 0, else `OutOfDomain` naming the
/// [`check::extreme`] of `args`.
fn positive_result(value: f64, args: &[(&'static str, f64)], reason: &'static str) -> Result<f64> {
    if value > 0.0 {
        check::finite_of(value, args, reason)
    } else {
        let (name, v) = check::extreme(args);
        Err(Error::OutOfDomain {
            name,
            value: v,
            reason,
        })
    }
}

/// λ for cones (3-16): `λ = tan γ₁/tan γ`, half-angles in rad, in (0, π/2).
/// [`Error::OutOfDomain`] (naming the more extreme angle) when the ratio
/// leaves `f64` (a subnormal angle).
pub fn lambda_cones(known_half_angle: f64, half_angle: f64) -> Result<f64> {
    let g1 = check::half_angle("known_half_angle", known_half_angle)?;
    let g = check::half_angle("half_angle", half_angle)?;
    // tan of a subnormal angle is the angle: the ratio can leave f64.
    positive_result(
        g1.tan() / g.tan(),
        &[("known_half_angle", g1), ("half_angle", g)],
        "lambda = tan(known_half_angle)/tan(half_angle) is not finite and > 0",
    )
}

/// The shape scale λ = B/B₁ that carries the known point `(P₁, δ₁)` into the
/// point `(load, depth)` on the same material, inverting (3-13):
/// `λ = [(δ/δ₁)(P₁/P)^{d/s}]^{s/(2−κ)}`. With κ = 1 and d = 2 this is the
/// Galanov radius relation (3-22), `λ = R₁/R₂ = (δ/δ₁)³(P₁/P)²`. κ = 2 is
/// rejected (the relation does not depend on λ there).
pub fn shape_scale_from_points(
    rescaling: &Rescaling,
    known: &KnownSolution,
    load: f64,
    depth: f64,
) -> Result<f64> {
    let k = known.checked()?;
    let load = check::positive("load", load)?;
    let depth = check::positive("depth", depth)?;
    let two_minus_kappa = 2.0 - rescaling.kappa;
    if two_minus_kappa.abs() < 1e-12 {
        return Err(Error::OutOfDomain {
            name: "kappa",
            value: rescaling.kappa,
            reason: "at kappa = 2 the load-depth relation (3-13) does not depend on lambda",
        });
    }
    let s = rescaling.s();
    let ln = (depth / k.depth).ln() + rescaling.d / s * (k.load / load).ln();
    Ok((ln * s / two_minus_kappa).exp())
}

/// Galanov effective radius of the unloading branch (3-22), κ = 1 (Hertz):
/// `R₂ = R₁ (P₂/P₁)² (δ₁/δ₂)³`, where `(P₁, δ₁)` is a Hertz solution for the
/// sphere of radius `R₁` and `(P₂, δ₂)` the measured unloading point, δ₂
/// measured from the residual depth (the elastic recovery). All > 0; m, N.
/// [`Error::OutOfDomain`] (naming the most extreme argument) when R₂
/// overflows `f64`.
pub fn galanov_unloading_radius(
    r1: f64,
    p1: f64,
    delta1: f64,
    p2: f64,
    delta2: f64,
) -> Result<f64> {
    let r1 = check::positive("r1", r1)?;
    let p1 = check::positive("p1", p1)?;
    let delta1 = check::positive("delta1", delta1)?;
    let p2 = check::positive("p2", p2)?;
    let delta2 = check::positive("delta2", delta2)?;
    check::finite_of(
        r1 * (p2 / p1).powi(2) * (delta1 / delta2).powi(3),
        &[
            ("r1", r1),
            ("p1", p1),
            ("delta1", delta1),
            ("p2", p2),
            ("delta2", delta2),
        ],
        "the unloading radius is not finite",
    )
}

/// The same effective radius from the Hertz law directly: with
/// `δ_H(P) = (9P²/(16E*²R))^{1/3}` in (3-22), `R₂ = 9P²/(16E*²δ³)` for the
/// measured elastic recovery δ (m) at load P (N), contact modulus E* (Pa).
pub fn hertz_effective_radius(e_star: f64, load: f64, elastic_depth: f64) -> Result<f64> {
    let e = check::positive("e_star", e_star)?;
    let p = check::positive("load", load)?;
    let d = check::positive("elastic_depth", elastic_depth)?;
    Ok(9.0 * p * p / (16.0 * e * e * d.powi(3)))
}

/// Radius of the deformed medium (the crater) from (3-23),
/// `1/R₂ = 1/R − 1/R_medium` ⇒ `R_medium = R R₂/(R₂ − R)` (m). The unloading
/// radius must exceed the indenter's (`unloading_radius > radius`); an infinite
/// `unloading_radius` gives `R_medium = R` (a crater that fits the sphere).
/// [`Error::OutOfDomain`] when `R R₂` overflows `f64`.
pub fn medium_radius(radius: f64, unloading_radius: f64) -> Result<f64> {
    let r = check::positive("radius", radius)?;
    if unloading_radius.is_nan() || unloading_radius <= r {
        return Err(Error::InvalidArgument {
            name: "unloading_radius",
            value: unloading_radius,
            bound: "> radius (the effective unloading sphere is blunter than the indenter)",
        });
    }
    if unloading_radius.is_infinite() {
        return Ok(r);
    }
    check::finite_of(
        r * unloading_radius / (unloading_radius - r),
        &[("radius", r), ("unloading_radius", unloading_radius)],
        "the medium radius is not finite",
    )
}

/// The inverse of [`medium_radius`]: the effective radius of the unloading
/// branch `R₂ = 1/(1/R − 1/R_medium)` (3-23), (2-19) (m). `medium_radius > radius`;
/// `+∞` (a flat) gives `R₂ = R`.
pub fn unloading_radius(radius: f64, medium_radius: f64) -> Result<f64> {
    let r = check::positive("radius", radius)?;
    if medium_radius.is_nan() || medium_radius <= r {
        return Err(Error::InvalidArgument {
            name: "medium_radius",
            value: medium_radius,
            bound: "> radius (+inf for a flat)",
        });
    }
    if medium_radius.is_infinite() {
        return Ok(r);
    }
    Ok(r * medium_radius / (medium_radius - r))
}

/// Galanov's effective cone coefficient (2-18): `B_eff = cot γ_i − cot γ_f` for
/// an indenter of half-angle γ_i unloading from an imprint of half-angle
/// γ_f > γ_i (rad; γ_f = π/2 is a flat and gives `cot γ_i`).
pub fn galanov_cone_coefficient(indenter_half_angle: f64, imprint_half_angle: f64) -> Result<f64> {
    let gi = check::half_angle("indenter_half_angle", indenter_half_angle)?;
    if !(imprint_half_angle > gi && imprint_half_angle <= core::f64::consts::FRAC_PI_2) {
        return Err(Error::InvalidArgument {
            name: "imprint_half_angle",
            value: imprint_half_angle,
            bound: "in (indenter_half_angle, pi/2]",
        });
    }
    Ok(gi.cos() / gi.sin() - imprint_half_angle.cos() / imprint_half_angle.sin())
}

/// The imprint half-angle γ_f (rad) from an effective cone coefficient
/// `B_eff` measured on unloading (2-18): `cot γ_f = cot γ_i − B_eff`,
/// `0 < B_eff ≤ cot γ_i`.
pub fn galanov_imprint_half_angle(indenter_half_angle: f64, effective_b: f64) -> Result<f64> {
    let gi = check::half_angle("indenter_half_angle", indenter_half_angle)?;
    let cot_i = gi.cos() / gi.sin();
    let b = check::positive("effective_b", effective_b)?;
    if b > cot_i {
        return Err(Error::InvalidArgument {
            name: "effective_b",
            value: b,
            bound: "<= cot(indenter_half_angle)",
        });
    }
    Ok((1.0_f64).atan2(cot_i - b))
}

// ---------------------------------------------------------------------------
// Slopes ⇄ (κ, d)

/// Loading log–log slope `m_l = (2 + κ(d − 1))/d` ((3-20), (3-26)).
pub fn loading_slope(kappa: f64, d: f64) -> Result<f64> {
    Ok(Rescaling::new(kappa, d)?.load_depth_exponent())
}

/// Unloading log–log slope `m_u = (d + 1)/d` (κ = 1 in (3-26)).
pub fn unloading_slope(d: f64) -> Result<f64> {
    let d = check_d(d)?;
    Ok((d + 1.0) / d)
}

/// Bluntness index from the unloading slope (κ = 1): `d = 1/(m_u − 1)`.
/// `m_u` must exceed 1 (m_u → 1⁺ is the flat punch, d → ∞). A slope ≥ 2 gives
/// d ≤ 1, sharper than a cone: returned as computed, for the caller to flag.
pub fn d_from_unloading_slope(unloading_slope: f64) -> Result<f64> {
    let m = check::finite("unloading_slope", unloading_slope)?;
    if m <= 1.0 {
        return Err(Error::OutOfDomain {
            name: "unloading_slope",
            value: m,
            reason: "an elastic unloading slope must exceed 1 (d = 1/(m - 1))",
        });
    }
    Ok(1.0 / (m - 1.0))
}

/// Hardening index from the loading slope and a known bluntness index:
/// `κ = (d m_l − 2)/(d − 1)` (from (3-26)); d = 2 gives (3-21), `κ = 2m_l − 2`.
/// Not identifiable for a cone (|d − 1| < 1e-6): [`Error::OutOfDomain`].
/// The result is returned whatever its sign; the caller flags κ < 0 or κ > 1.
/// [`Error::OutOfDomain`] when κ overflows `f64`.
pub fn kappa_from_loading_slope(loading_slope: f64, d: f64) -> Result<f64> {
    let m = check::finite("loading_slope", loading_slope)?;
    let d = check::positive("d", d)?;
    if (d - 1.0).abs() < D_CONE_TOLERANCE {
        return Err(Error::OutOfDomain {
            name: "d",
            value: d,
            reason: "for a cone (d = 1) the loading slope is 2 for every kappa: kappa is not identifiable",
        });
    }
    check::finite_of(
        (d * m - 2.0) / (d - 1.0),
        &[("loading_slope", m), ("d", d)],
        "kappa overflows f64",
    )
}

/// Bluntness index from the loading slope and a known hardening index:
/// `d = (2 − κ)/(m_l − κ)` (from (3-26)). Needs `m_l ≠ κ`.
/// [`Error::OutOfDomain`] when d overflows `f64`.
pub fn d_from_loading_slope(loading_slope: f64, kappa: f64) -> Result<f64> {
    let m = check::finite("loading_slope", loading_slope)?;
    let k = check::finite("kappa", kappa)?;
    if (m - k).abs() < 1e-12 {
        return Err(Error::OutOfDomain {
            name: "loading_slope",
            value: m,
            reason: "equals kappa: d = (2 - kappa)/(m - kappa) is undefined",
        });
    }
    check::finite_of(
        (2.0 - k) / (m - k),
        &[("loading_slope", m), ("kappa", k)],
        "d overflows f64",
    )
}

// ---------------------------------------------------------------------------
// Zhuravlev-type integrals (3-27), (3-28)

/// Exponent q of the Zhuravlev-type integrand for power-law asperities:
/// `q = (2 + κ(d − 1))/d`; κ = 1 gives the linear-elastic `(d + 1)/d` of
/// (3-27), d = 2, κ = 1 the Hertzian 3/2 of Zhuravlev's original model.
pub fn zhuravlev_exponent(kappa: f64, d: f64) -> Result<f64> {
    loading_slope(kappa, d)
}

/// Prefactor of (3-27)/(3-28): the load of **one** asperity pair at
/// interference `w` is `P = λ^{(κ−2)/d} P₁ (w/δ₁)^q` (3-24), so the total load
/// is `λ^{(κ−2)/d} (P₁/δ₁^q) · I(x)` with the double integral
/// `I(x) = ∫∫_{ξ₁+ξ₂≤x} [x − (ξ₁+ξ₂)]^q n₁(ξ₁) n₂(ξ₂) dξ₁ dξ₂`
/// ([`zhuravlev_integral`]). Returns `λ^{(κ−2)/d} P₁/δ₁^q` (N·m^{−q}).
pub fn zhuravlev_prefactor(
    rescaling: &Rescaling,
    lambda: f64,
    known: &KnownSolution,
) -> Result<f64> {
    let k = known.checked()?;
    let lambda = check::positive("lambda", lambda)?;
    let q = rescaling.load_depth_exponent();
    Ok(lambda.powf(rescaling.load_lambda_exponent()) * k.load / k.depth.powf(q))
}

/// Closed form of the Zhuravlev double integral for summit densities linear in
/// depth, `n_i(ξ) = α_i ξ` (Zhuravlev 1940; REFERENCE §3):
/// `I(x) = α₁α₂ ∫₀^x (x − s)^q s³/6 ds = α₁α₂ x^{q+4} Γ(q+1)/Γ(q+5)`.
pub fn zhuravlev_integral_linear(q: f64, x: f64, alpha1: f64, alpha2: f64) -> Result<f64> {
    let q = check::non_negative("q", q)?;
    let x = check::non_negative("x", x)?;
    let a1 = check::finite("alpha1", alpha1)?;
    let a2 = check::finite("alpha2", alpha2)?;
    if x == 0.0 {
        return Ok(0.0);
    }
    let ln = (q + 4.0) * x.ln() + libm::lgamma(q + 1.0) - libm::lgamma(q + 5.0);
    Ok(a1 * a2 * ln.exp())
}

/// The Zhuravlev-type double integral (3-27), (3-28) for arbitrary summit
/// densities `n₁`, `n₂` (per unit depth, on ξ ≥ 0):
/// `I(x) = ∫∫_{ξ₁+ξ₂≤x} [x − (ξ₁+ξ₂)]^q n₁(ξ₁) n₂(ξ₂) dξ₁ dξ₂
///       = ∫₀^x (x − s)^q (n₁ ∗ n₂)(s) ds`,
/// by Gauss–Legendre quadrature of `order` points (4..=64) on both the
/// convolution and the outer integral; the outer variable is
/// `x − s = x t²`, which removes the `(x − s)^q` endpoint singularity of the
/// derivatives. Exact to rounding for polynomial densities of low degree when
/// q is an integer; relative error < 1e-9 for q = 3/2 and linear densities at
/// order 24 (see the tests). `x ≥ 0` (m).
pub fn zhuravlev_integral(
    q: f64,
    x: f64,
    n1: impl Fn(f64) -> f64,
    n2: impl Fn(f64) -> f64,
    order: usize,
) -> Result<f64> {
    let q = check::non_negative("q", q)?;
    let x = check::non_negative("x", x)?;
    if !(4..=64).contains(&order) {
        return Err(Error::InvalidArgument {
            name: "order",
            value: order as f64,
            bound: "in [4, 64]",
        });
    }
    if x == 0.0 {
        return Ok(0.0);
    }
    let (nodes, weights) = gauss_legendre(order);
    let conv = |s: f64| -> f64 {
        // ∫₀^s n1(ξ) n2(s − ξ) dξ
        let mut acc = 0.0;
        for (t, w) in nodes.iter().zip(&weights) {
            let xi = 0.5 * s * (t + 1.0);
            acc += w * n1(xi) * n2(s - xi);
        }
        0.5 * s * acc
    };
    // s = x(1 − t²), t ∈ [0, 1]: ds = 2xt dt, (x − s)^q = x^q t^{2q}.
    let mut acc = 0.0;
    for (u, w) in nodes.iter().zip(&weights) {
        let t = 0.5 * (u + 1.0);
        let s = x * (1.0 - t * t);
        acc += w * x.powf(q) * t.powf(2.0 * q) * conv(s) * 2.0 * x * t;
    }
    let value = 0.5 * acc;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::OutOfDomain {
            name: "x",
            value: x,
            reason: "the densities gave a non-finite integral",
        })
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n; Golub–Welsch
/// accuracy is not needed for n ≤ 64).
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    let nf = n as f64;
    for i in 0..n.div_ceil(2) {
        let mut z = (core::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let kf = k as f64;
                let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
                p0 = p1;
                p1 = p2;
            }
            dp = nf * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-15 {
                break;
            }
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        let wi = 2.0 / ((1.0 - z * z) * dp * dp);
        w[i] = wi;
        w[n - 1 - i] = wi;
    }
    (x, w)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials() {
        let (x, w) = gauss_legendre(7);
        let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(12)).sum();
        assert!((s - 2.0 / 13.0).abs() < 1e-14);
        let (x, w) = gauss_legendre(8);
        let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(14)).sum();
        assert!((s - 2.0 / 15.0).abs() < 1e-14);
    }
}
