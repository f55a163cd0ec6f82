//! Rigid sphere under a surface-force law: the Derjaguin approximation.
//!
//! # Formulas
//!
//! A rigid sphere of radius R faces a rigid flat. Two flats a distance z apart
//! attract each other with the pressure p(z) of a [`SurfaceLaw`] (attraction
//! positive), whose energy per unit area is e(D) = ∫_D^∞ p(z) dz, e(z_eq) = w.
//! Derjaguin (1934; thesis (1-32); Greenwood 1997, Proc. R. Soc. A 453) sums
//! the flat-flat interaction over the rings of the sphere, whose gap is
//! z = D + r²/(2R) near the apex (D the minimum gap), and gets the force F
//! (attraction positive). The library's force P is repulsive positive, and
//! its tangent follows from dD/dδ = −1, which holds for every law below:
//!
//! $$F(D) = 2\pi R\int_D^\infty p(z)\\,dz = 2\pi R\\, e(D), \qquad P = -2\pi R\\, e(D), \qquad \frac{dP}{d\delta} = -2\pi R\\, p(D) .$$
//!
//! The surface laws:
//!
//! | law | $p(z)$ | $e(D)$ | range |
//! |---|---|---|---|
//! | Lennard-Jones 3-9 (seed 001, Eq. 1) | $\frac{8w}{3z_0}\bigl((z_0/z)^3 - (z_0/z)^9\bigr)$ | $\frac{4w}{3}\bigl((z_0/D)^2 - \frac{1}{4}(z_0/D)^8\bigr)$ | $z_0$ |
//! | Dugdale step (Maugis 1992) | $\sigma_0$ for $0 \le z \le h_0$, 0 beyond | $\sigma_0 (h_0 - D)$ for $D \le h_0$, 0 beyond | $h_0 = w/\sigma_0$ |
//! | exponential | $(w/\ell)\\,e^{-z/\ell}$ | $w\\,e^{-D/\ell}$ | $\ell$ |
//!
//! The Lennard-Jones law is repulsive below z₀, attractive above, and its
//! tension peaks at $\sigma_\mathrm{th} = 16w/(9\sqrt{3}\\,z_0)$ at
//! $z = 3^{1/6} z_0$ (thesis (1-44), see
//! [`crate::material::lennard_jones_theoretical_stress`]). The Dugdale and
//! exponential laws are purely attractive: a rigid sphere under them cannot
//! carry a compressive load, nor penetrate.
//!
//! # Overlap convention
//!
//! * Lennard-Jones: `δ = z₀ − D`. δ = 0 is the equilibrium gap z₀, where the
//!   force is the pull-off force −2πRw (seed 001's rigid approach α, REFERENCE
//!   §6: `P/(πRw) = −(8/3)[h_m⁻² − h_m⁻⁸/4]`, h_m = 1 − δ/z₀); P = 0 at
//!   D = z₀/4^{1/6}. Any δ < z₀ is allowed; δ ≥ z₀ (D ≤ 0) is the singular
//!   point of the law and gives [`Error::OutOfDomain`].
//! * Dugdale and exponential: `δ = −D`. δ = 0 is touching (the force is the
//!   pull-off force −2πRw there); δ > 0 gives [`Error::OutOfDomain`].
//!
//! # Outputs
//!
//! * `contact_radius` is always 0: the sphere is rigid, so it touches the flat
//!   at most at one point (the region of repulsion of the Lennard-Jones law,
//!   D + r²/(2R) < z₀, is reported nowhere).
//! * `ContactState::cohesive_radius` is the radius of the Dugdale cohesive
//!   zone, `c = √(2R(h₀ − D))` while D < h₀; 0 for the other laws, whose range
//!   is unbounded.
//! * `in_contact` is 1 while the surfaces interact (the force is nonzero) or
//!   touch (δ ≥ 0).
//! * `stiffness` is the tangent dP/dδ of *Formulas*, analytic. For the Dugdale law it is
//!   −2πRσ₀ for 0 ≤ D ≤ h₀ and 0 beyond: at the kink D = h₀ it is the
//!   one-sided derivative on the approach side (δ → −h₀⁺), the tangent of the
//!   interacting branch, consistent with p(h₀) = σ₀.
//! * Pull-off is −2πRw under both controls (the minimum of P: at D = z₀ for
//!   Lennard-Jones, at D = 0 for the other two).
//!
//! Evaluations never allocate. Every output is finite or the call returns an
//! error; an overflow at an extreme overlap or load is
//! [`Error::OutOfDomain`].
//!
//! # References
//!
//! * Thesis (1-32), (1-44).
//! * B. V. Derjaguin (1934), "Untersuchungen über die Reibung und Adhäsion,
//!   IV", Kolloid-Z. 69, 155–164 (the approximation).
//! * J. A. Greenwood (1997), "Adhesion of elastic spheres", Proc. R. Soc. Lond.
//!   A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070).
//! * W. G. Lee, W. W. F. Chong (2015), "Adhesive contact modelling based on
//!   Lennard-Jones force law", Jurnal Teknologi 76(10) (seed 001), Eq. 1.
//! * D. Maugis (1992), J. Colloid Interface Sci. 150, 243–269,
//!   [doi:10.1016/0021-9797(92)90285-T](https://doi.org/10.1016/0021-9797(92)90285-T)
//!   (the Dugdale step).

use super::{check_delta, check_force, ContactState, Control, NormalContact, NormalResponse};
use crate::error::{check, Error, Result};
use core::f64::consts::PI;

/// `DerjaguinParams::surface_law` value of the Lennard-Jones 3-9 law (the C
/// ABI's `ASPERITY_SURFACE_LAW_LENNARD_JONES`).
pub(crate) const LENNARD_JONES: i32 = 1;
/// `DerjaguinParams::surface_law` value of the Dugdale step
/// (`ASPERITY_SURFACE_LAW_DUGDALE`).
pub(crate) const DUGDALE: i32 = 2;
/// `DerjaguinParams::surface_law` value of the exponential law
/// (`ASPERITY_SURFACE_LAW_EXPONENTIAL`).
pub(crate) const EXPONENTIAL: i32 = 3;

/// The surface-force law between two flats: pressure p(z) (Pa) at the gap z
/// (m), attraction positive, with energy per unit area
/// e(D) = ∫_D^∞ p(z) dz (J/m²). See the [module documentation](self) for the
/// formulas and sources.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SurfaceLaw {
    /// Lennard-Jones 3-9 (seed 001, Eq. 1; Greenwood 1997):
    /// `p(z) = (8w/(3z₀))[(z₀/z)³ − (z₀/z)⁹]`,
    /// `e(D) = (4w/3)[(z₀/D)² − (z₀/D)⁸/4]`, e(z₀) = w. Defined for z > 0.
    LennardJones {
        /// Work of adhesion w (J/m², > 0).
        work_of_adhesion: f64,
        /// Equilibrium separation z₀ (m, > 0): p(z₀) = 0.
        equilibrium_separation: f64,
    },
    /// Dugdale step (Maugis 1992; thesis (1-43)): `p = σ₀` for
    /// 0 ≤ z ≤ h₀ = w/σ₀, 0 beyond; `e(D) = σ₀(h₀ − D)` for 0 ≤ D ≤ h₀, 0
    /// beyond. Defined for z ≥ 0.
    Dugdale {
        /// Work of adhesion w (J/m², > 0).
        work_of_adhesion: f64,
        /// Cohesive stress σ₀ (Pa, > 0).
        cohesive_stress: f64,
    },
    /// Exponential: `p(z) = (w/ℓ) e^{−z/ℓ}`, `e(D) = w e^{−D/ℓ}`. Defined for
    /// z ≥ 0.
    Exponential {
        /// Work of adhesion w (J/m², > 0).
        work_of_adhesion: f64,
        /// Decay length ℓ (m, > 0).
        decay_length: f64,
    },
}

/// The validated parameters of a surface law in the library's internal form:
/// selector, w and the range (z₀, h₀ or ℓ).
#[derive(Debug, Clone, Copy)]
struct Parts {
    kind: i32,
    w: f64,
    range: f64,
}

impl Parts {
    /// The gap of this law, checked against its domain: finite, > 0 for
    /// Lennard-Jones, ≥ 0 otherwise.
    #[inline]
    fn check_gap(&self, gap: f64) -> Result<f64> {
        let gap = check::finite("gap", gap)?;
        if self.kind == LENNARD_JONES {
            if gap > 0.0 {
                return Ok(gap);
            }
            return Err(Error::OutOfDomain {
                name: "gap",
                value: gap,
                reason: "the Lennard-Jones law is singular at zero gap: gap must be > 0",
            });
        }
        if gap >= 0.0 {
            Ok(gap)
        } else {
            Err(Error::OutOfDomain {
                name: "gap",
                value: gap,
                reason: "the surfaces cannot interpenetrate: gap must be >= 0",
            })
        }
    }

    /// Dimensionless energy and pressure `(e/w, p·range/w)` at a gap in the
    /// domain (may overflow to ±∞ for a Lennard-Jones gap ≪ z₀, never NaN).
    #[inline]
    fn reduced(&self, gap: f64) -> (f64, f64) {
        match self.kind {
            LENNARD_JONES => {
                let s = self.range / gap; // z₀/D, in (0, ∞]
                let x = s * s;
                // 1 − s⁶ = −u(3 + 3u + u²) with u = s² − 1: exact sign at s = 1.
                let u = x - 1.0;
                let e = (4.0 / 3.0) * x * (1.0 - 0.25 * x * x * x);
                let p = -(8.0 / 3.0) * (s * x) * (u * (3.0 + u * (3.0 + u)));
                (e + 0.0, p + 0.0)
            }
            DUGDALE => {
                if gap <= self.range {
                    (1.0 - gap / self.range, 1.0)
                } else {
                    (0.0, 0.0)
                }
            }
            _ => {
                let e = (-gap / self.range).exp();
                (e, e)
            }
        }
    }
}

impl SurfaceLaw {
    /// Work of adhesion w (J/m²) = ∫ p over the law's attractive approach
    /// (e at z₀ for Lennard-Jones, at 0 for the others).
    #[inline]
    pub fn work_of_adhesion(&self) -> f64 {
        match *self {
            SurfaceLaw::LennardJones {
                work_of_adhesion, ..
            }
            | SurfaceLaw::Dugdale {
                work_of_adhesion, ..
            }
            | SurfaceLaw::Exponential {
                work_of_adhesion, ..
            } => work_of_adhesion,
        }
    }

    /// The law's length (m): z₀ (Lennard-Jones), h₀ = w/σ₀ (Dugdale) or ℓ
    /// (exponential). Not validated: see [`SurfaceLaw::validate`].
    #[inline]
    pub fn range(&self) -> f64 {
        match *self {
            SurfaceLaw::LennardJones {
                equilibrium_separation,
                ..
            } => equilibrium_separation,
            SurfaceLaw::Dugdale {
                work_of_adhesion,
                cohesive_stress,
            } => work_of_adhesion / cohesive_stress,
            SurfaceLaw::Exponential { decay_length, .. } => decay_length,
        }
    }

    /// The law itself when every parameter is valid: w > 0 and z₀, σ₀, ℓ > 0,
    /// all finite, and for Dugdale h₀ = w/σ₀ finite and > 0. The error names
    /// the offending field.
    pub fn validate(&self) -> Result<Self> {
        self.parts().map(|_| *self)
    }

    fn parts(&self) -> Result<Parts> {
        let w = check::positive("work_of_adhesion", self.work_of_adhesion())?;
        Ok(match *self {
            SurfaceLaw::LennardJones {
                equilibrium_separation,
                ..
            } => Parts {
                kind: LENNARD_JONES,
                w,
                range: check::positive("equilibrium_separation", equilibrium_separation)?,
            },
            SurfaceLaw::Dugdale {
                cohesive_stress, ..
            } => {
                let s0 = check::positive("cohesive_stress", cohesive_stress)?;
                let h0 = w / s0;
                if !(h0.is_finite() && h0 > 0.0) {
                    return Err(Error::InvalidArgument {
                        name: "cohesive_stress",
                        value: s0,
                        bound: "such that the range h0 = w/cohesive_stress is finite and > 0",
                    });
                }
                Parts {
                    kind: DUGDALE,
                    w,
                    range: h0,
                }
            }
            SurfaceLaw::Exponential { decay_length, .. } => Parts {
                kind: EXPONENTIAL,
                w,
                range: check::positive("decay_length", decay_length)?,
            },
        })
    }

    /// Pressure p(z) (Pa, attraction positive) between two flats at the gap
    /// `gap` z (m): the formulas of [`SurfaceLaw`]. The gap must be > 0 for
    /// Lennard-Jones (singular at 0) and ≥ 0 for the others
    /// ([`Error::OutOfDomain`] otherwise, also on overflow).
    pub fn pressure(&self, gap: f64) -> Result<f64> {
        let parts = self.parts()?;
        let gap = parts.check_gap(gap)?;
        let p = match *self {
            // The exact σ₀, not w/h₀.
            SurfaceLaw::Dugdale {
                cohesive_stress, ..
            } => {
                if gap <= parts.range {
                    cohesive_stress
                } else {
                    0.0
                }
            }
            _ => parts.reduced(gap).1 * (parts.w / parts.range),
        };
        finite_gap(p, gap)
    }

    /// Interaction energy per unit area e(D) = ∫_D^∞ p(z) dz (J/m²) between
    /// two flats at the gap `gap` D (m): the formulas of [`SurfaceLaw`];
    /// e = w at z₀ (Lennard-Jones) or at 0 (the others). Same domain as
    /// [`SurfaceLaw::pressure`].
    pub fn energy(&self, gap: f64) -> Result<f64> {
        let parts = self.parts()?;
        let gap = parts.check_gap(gap)?;
        finite_gap(parts.reduced(gap).0 * parts.w, gap)
    }

    /// The largest tension of the law (Pa): 16w/(9√3 z₀) at z = 3^{1/6} z₀ for
    /// Lennard-Jones (thesis (1-44)), σ₀ for Dugdale, w/ℓ (at z = 0) for the
    /// exponential law.
    pub fn peak_tension(&self) -> Result<f64> {
        let parts = self.parts()?;
        let p = match *self {
            SurfaceLaw::LennardJones { .. } => 16.0 * parts.w / (9.0 * 3f64.sqrt() * parts.range),
            SurfaceLaw::Dugdale {
                cohesive_stress, ..
            } => cohesive_stress,
            SurfaceLaw::Exponential { .. } => parts.w / parts.range,
        };
        finite_gap(p, parts.range)
    }
}

#[inline]
fn overflow(name: &'static str, value: f64) -> Error {
    Error::OutOfDomain {
        name,
        value,
        reason: "the response overflows f64",
    }
}

#[inline]
fn finite_gap(v: f64, gap: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::OutOfDomain {
            name: "gap",
            value: gap,
            reason: "the result overflows f64",
        })
    }
}

/// Inputs of a rigid sphere with a surface-force law, as
/// [`Derjaguin::from_params`] and C's `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DerjaguinParams {
    /// Sphere radius R (m, > 0).
    pub radius: f64,
    /// Work of adhesion w (J/m², > 0).
    pub work_of_adhesion: f64,
    /// The surface law's second parameter: the equilibrium separation z₀ (m)
    /// for Lennard-Jones, the cohesive stress σ₀ (Pa) for Dugdale, the decay
    /// length ℓ (m) for the exponential law (> 0).
    pub parameter: f64,
    /// Surface law selector: 1 Lennard-Jones, 2 Dugdale, 3 exponential
    /// (`ASPERITY_SURFACE_LAW_*`).
    pub surface_law: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// Rigid sphere with a surface-force law. Its inputs are
/// [`DerjaguinParams`]; it caches the law's length (z₀, h₀ = w/σ₀ or ℓ).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derjaguin {
    /// R (m).
    pub(crate) radius: f64,
    /// w (J/m²).
    pub(crate) work_of_adhesion: f64,
    /// z₀ (m), σ₀ (Pa) or ℓ (m).
    pub(crate) parameter: f64,
    /// Surface law selector.
    pub(crate) surface_law: i32,
    /// 0.
    pub(crate) reserved: i32,
    /// Cached length of the law (m): z₀, h₀ = w/σ₀ or ℓ.
    range: f64,
}

law_inputs!(
    Derjaguin,
    DerjaguinParams {
        radius,
        work_of_adhesion,
        parameter,
        surface_law,
        reserved
    }
);

impl Derjaguin {
    /// A rigid sphere of radius `radius` R (m, > 0) under the surface law
    /// `law` (every parameter validated, see [`SurfaceLaw::validate`]). The
    /// adhesive force 2πRw must be a finite, nonzero f64 (else the error names
    /// `radius`).
    pub fn new(radius: f64, law: SurfaceLaw) -> Result<Self> {
        let radius = check::positive("radius", radius)?;
        let parts = law.parts()?;
        let f = 2.0 * PI * radius * parts.w;
        if !(f.is_finite() && f > 0.0) {
            return Err(Error::InvalidArgument {
                name: "radius",
                value: radius,
                bound:
                    "such that the adhesive force 2*pi*radius*work_of_adhesion is finite and > 0",
            });
        }
        let parameter = match law {
            SurfaceLaw::LennardJones {
                equilibrium_separation,
                ..
            } => equilibrium_separation,
            SurfaceLaw::Dugdale {
                cohesive_stress, ..
            } => cohesive_stress,
            SurfaceLaw::Exponential { decay_length, .. } => decay_length,
        };
        Ok(Self {
            radius,
            work_of_adhesion: parts.w,
            parameter,
            surface_law: parts.kind,
            reserved: 0,
            range: parts.range,
        })
    }

    /// The sphere of the inputs `p`: `surface_law` is checked first
    /// ([`Error::UnknownSelector`]), then as by [`Derjaguin::new`]; an error
    /// about the law's second parameter names `parameter`.
    pub fn from_params(p: &DerjaguinParams) -> Result<Self> {
        let (w, x) = (p.work_of_adhesion, p.parameter);
        let law = match p.surface_law {
            LENNARD_JONES => SurfaceLaw::LennardJones {
                work_of_adhesion: w,
                equilibrium_separation: x,
            },
            DUGDALE => SurfaceLaw::Dugdale {
                work_of_adhesion: w,
                cohesive_stress: x,
            },
            EXPONENTIAL => SurfaceLaw::Exponential {
                work_of_adhesion: w,
                decay_length: x,
            },
            v => {
                return Err(Error::UnknownSelector {
                    name: "surface_law",
                    value: v as i64,
                })
            }
        };
        Self::new(p.radius, law).map_err(|e| {
            let e = e.renamed("equilibrium_separation", "parameter");
            let e = e.renamed("cohesive_stress", "parameter");
            e.renamed("decay_length", "parameter")
        })
    }

    /// The surface law, or [`Error::UnknownSelector`] on `surface_law` when the
    /// selector holds no law (only possible when C wrote the storage of a
    /// law directly).
    pub fn try_surface_law(&self) -> Result<SurfaceLaw> {
        let w = self.work_of_adhesion;
        match self.surface_law {
            LENNARD_JONES => Ok(SurfaceLaw::LennardJones {
                work_of_adhesion: w,
                equilibrium_separation: self.parameter,
            }),
            DUGDALE => Ok(SurfaceLaw::Dugdale {
                work_of_adhesion: w,
                cohesive_stress: self.parameter,
            }),
            EXPONENTIAL => Ok(SurfaceLaw::Exponential {
                work_of_adhesion: w,
                decay_length: self.parameter,
            }),
            v => Err(Error::UnknownSelector {
                name: "surface_law",
                value: v as i64,
            }),
        }
    }

    /// The surface law (see [`Derjaguin::try_surface_law`]). An unknown
    /// `surface_law` selector gives a Lennard-Jones law with NaN parameters,
    /// which every function that uses it rejects with
    /// [`Error::InvalidArgument`]; this never panics.
    pub fn surface_law(&self) -> SurfaceLaw {
        self.try_surface_law().unwrap_or(SurfaceLaw::LennardJones {
            work_of_adhesion: f64::NAN,
            equilibrium_separation: f64::NAN,
        })
    }

    /// The adhesive force magnitude 2πRw (N), the magnitude of the pull-off
    /// force.
    #[inline]
    pub fn adhesive_force(&self) -> f64 {
        2.0 * PI * self.radius * self.work_of_adhesion
    }

    /// The validated fields (the struct may come from C with any bits).
    #[inline]
    fn parts(&self) -> Result<(Parts, f64)> {
        let kind = match self.surface_law {
            k @ (LENNARD_JONES | DUGDALE | EXPONENTIAL) => k,
            v => {
                return Err(Error::UnknownSelector {
                    name: "surface_law",
                    value: v as i64,
                })
            }
        };
        check::positive("radius", self.radius)?;
        let w = check::positive("work_of_adhesion", self.work_of_adhesion)?;
        let range = check::positive("range", self.range)?;
        let f = self.adhesive_force();
        if !(f.is_finite() && f > 0.0) {
            return Err(Error::InvalidArgument {
                name: "radius",
                value: self.radius,
                bound:
                    "such that the adhesive force 2*pi*radius*work_of_adhesion is finite and > 0",
            });
        }
        Ok((Parts { kind, w, range }, f))
    }

    /// Force P (N, repulsive positive) at the minimum gap `gap` D (m) between
    /// sphere and flat: `P = −2πR e(D)` (Derjaguin 1934; thesis (1-32)). D > 0
    /// for Lennard-Jones, D ≥ 0 for the others; [`Error::OutOfDomain`] outside
    /// or on overflow.
    pub fn force_at_gap(&self, gap: f64) -> Result<f64> {
        let (parts, f) = self.parts()?;
        let gap = parts.check_gap(gap)?;
        finite_gap(-f * parts.reduced(gap).0 + 0.0, gap)
    }

    /// The minimum gap D (m) at the overlap δ: z₀ − δ for Lennard-Jones, −δ
    /// for the others, checked against the law's domain.
    #[inline]
    fn gap_at(&self, parts: &Parts, delta: f64) -> Result<f64> {
        if parts.kind == LENNARD_JONES {
            let gap = parts.range - delta;
            if gap > 0.0 {
                Ok(gap)
            } else {
                Err(Error::OutOfDomain {
                    name: "delta",
                    value: delta,
                    reason: "the Lennard-Jones law is singular at zero gap: delta must be < z0",
                })
            }
        } else if delta <= 0.0 {
            Ok(-delta + 0.0)
        } else {
            Err(Error::OutOfDomain {
                name: "delta",
                value: delta,
                reason: "a rigid sphere under a purely attractive law cannot penetrate: delta must be <= 0",
            })
        }
    }

    /// Response and state at the gap, with force `force` and stiffness `k`
    /// already known; checks that everything is finite.
    #[inline]
    fn respond(
        &self,
        parts: &Parts,
        gap: f64,
        delta: f64,
        force: f64,
        k: f64,
        overflow: Error,
    ) -> Result<(NormalResponse, ContactState)> {
        let in_contact = (delta >= 0.0 || force != 0.0) as i32;
        let cohesive_radius = if parts.kind == DUGDALE && gap < parts.range {
            (2.0 * self.radius).sqrt() * (parts.range - gap).sqrt()
        } else {
            0.0
        };
        if !(force.is_finite() && k.is_finite() && delta.is_finite() && cohesive_radius.is_finite())
        {
            return Err(overflow);
        }
        Ok((
            NormalResponse {
                force,
                delta,
                contact_radius: 0.0,
                stiffness: k + 0.0,
                in_contact,
                reserved: 0,
            },
            ContactState {
                contact_radius: 0.0,
                cohesive_radius,
                in_contact,
                branch: 0,
            },
        ))
    }
}

/// Solve `g(u) = (3/2)u² + u³ + u⁴/4 = b` for u ≥ 0 (b ≥ 0, finite): the
/// Lennard-Jones Derjaguin inverse `x − x⁴/4 = 3/4 − b` written in u = x − 1,
/// which keeps full precision near pull-off (b → 0, where x = 1 is a double
/// root of the original quartic). Newton from an upper bound on a convex,
/// increasing g converges monotonically; bisection guards the bracket.
fn lj_inverse(b: f64) -> Result<f64> {
    if b == 0.0 {
        return Ok(0.0);
    }
    // g(u) ≥ (3/2)u², u³ and u⁴/4: each inverse is an upper bound.
    let mut hi = (b / 1.5).sqrt().min(b.cbrt()).min((4.0 * b).sqrt().sqrt());
    let mut lo = 0.0;
    let mut u = hi;
    let g = |u: f64| u * u * (1.5 + u * (1.0 + 0.25 * u));
    let mut residual = f64::INFINITY;
    for _ in 0..200 {
        let r = g(u) - b;
        residual = (r / b).abs();
        if r == 0.0 {
            return Ok(u);
        }
        if r > 0.0 {
            hi = u;
        } else {
            lo = u;
        }
        let dg = u * (3.0 + u * (3.0 + u));
        let mut next = u - r / dg;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - u).abs() <= 4.0 * f64::EPSILON * u || hi - lo <= 4.0 * f64::EPSILON * hi {
            return Ok(next);
        }
        u = next;
    }
    Err(Error::NotConverged {
        what: "Derjaguin Lennard-Jones load inversion",
        iterations: 200,
        residual,
    })
}

impl NormalContact for Derjaguin {
    /// `P = −2πR e(D)` and `dP/dδ = −2πR p(D)` at the overlap δ (see the
    /// [module documentation](self) for the gap D(δ) and the domain). The
    /// state is not read (the law has no hysteresis).
    fn eval(&self, delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        let (parts, f) = self.parts()?;
        let gap = self.gap_at(&parts, delta)?;
        let (e, p) = if parts.kind == LENNARD_JONES {
            // u = s² − 1 = δ(z₀ + D)/D² = (δ/D)(s + 1): exact near δ = 0,
            // no overflow.
            let s = parts.range / gap;
            let x = s * s;
            let u = (delta / gap) * (s + 1.0);
            let e = (4.0 / 3.0) * x * (1.0 - 0.25 * x * x * x);
            let p = -(8.0 / 3.0) * (s * x) * (u * (3.0 + u * (3.0 + u)));
            (e, p)
        } else {
            parts.reduced(gap)
        };
        let force = -f * e + 0.0;
        let k = -(f * p) / parts.range;
        self.respond(&parts, gap, delta, force, k, overflow("delta", delta))
    }

    /// The equilibrium at the force P (N).
    ///
    /// * Lennard-Jones: the stable branch D ≤ z₀ (δ ≥ 0, dP/dδ ≥ 0), for
    ///   P ≥ −2πRw. With x = (z₀/D)², `x − x⁴/4 = −3P/(8πRw)`; solved for
    ///   u = x − 1 ≥ 0 by a bracketed Newton iteration (see the source).
    /// * Dugdale: D = h₀(1 + P/(2πRw)) for −2πRw ≤ P < 0; P = 0 gives the edge
    ///   of the interaction D = h₀ (every D ≥ h₀ carries no force).
    /// * Exponential: D = −ℓ ln(−P/(2πRw)) for −2πRw ≤ P < 0.
    ///
    /// The Dugdale and exponential branches have dP/dδ < 0, so a soft machine
    /// cannot hold them; they are returned as the unique equilibria. A
    /// compressive load on these purely attractive laws, P = 0 for the
    /// exponential law, and any P < −2πRw give [`Error::OutOfDomain`].
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        let (parts, f) = self.parts()?;
        if force < -f {
            return Err(super::below_pull_off(force));
        }
        let ratio = force / f; // ≥ −1
        let (delta, gap, k) = match parts.kind {
            LENNARD_JONES => {
                let z0 = parts.range;
                let b = 0.75 * (1.0 + ratio);
                if !(b.is_finite() && b < 1e300) {
                    return Err(overflow("force", force));
                }
                let u = lj_inverse(b)?;
                let x = 1.0 + u;
                let s = x.sqrt();
                let gap = z0 / s;
                let delta = z0 * (u / (s * (s + 1.0)));
                let k = (f / z0) * (8.0 / 3.0) * (s * x) * (u * (3.0 + u * (3.0 + u)));
                (delta, gap, k)
            }
            kind => {
                if force > 0.0 {
                    return Err(Error::OutOfDomain {
                        name: "force",
                        value: force,
                        reason: "a rigid sphere under a purely attractive law cannot carry a compressive load",
                    });
                }
                if kind == DUGDALE {
                    let gap = parts.range * (1.0 + ratio);
                    (-gap + 0.0, gap, -f / parts.range)
                } else {
                    if force == 0.0 {
                        return Err(Error::OutOfDomain {
                            name: "force",
                            value: force,
                            reason:
                                "the exponential law's force vanishes only at infinite separation",
                        });
                    }
                    let r = -ratio;
                    let ln = if r >= f64::MIN_POSITIVE {
                        r.ln()
                    } else {
                        (-force).ln() - f.ln()
                    };
                    let delta = (parts.range * ln.min(0.0)) + 0.0;
                    (delta, -delta, force / parts.range)
                }
            }
        };
        self.respond(&parts, gap, delta, force, k, overflow("force", force))
            .map(|(r, _)| r)
    }

    /// −2πRw under both controls: the minimum of P(δ), at D = z₀ for
    /// Lennard-Jones and at D = 0 for the Dugdale and exponential laws (the
    /// rigid sphere has no elastic instability).
    fn pull_off_force(&self, _control: Control) -> Result<f64> {
        let (_, f) = self.parts()?;
        Ok(-f)
    }

    /// The law's range (m): z₀, h₀ = w/σ₀ or ℓ.
    fn length_scale(&self) -> f64 {
        self.range
    }

    /// The rigid sphere has no hysteresis, so `control` does not matter:
    /// the force at δ is the same on approach and retraction. With the
    /// pull-off force `P_c = −2πRw` and `P/P_c = e(D)/w`:
    ///
    /// * Dugdale: `e(D) = 0` for `D ≥ h₀`, so the reach is `−h₀`
    ///   (`rel_force` is checked, then ignored);
    /// * exponential: `e(D)/w = e^{−D/ℓ} < rel_force` for
    ///   `D > −ℓ ln(rel_force)`, so δ_r = `ℓ ln(rel_force)`;
    /// * Lennard-Jones: with `y = (z₀/D)² < 1`,
    ///   `e(D)/w = (4/3)(y − y⁴/4)` increases with y, so
    ///   `|P| < rel_force·|P_c|` for D beyond the root of
    ///   `y − y⁴/4 = (3/4)rel_force` (a safeguarded Newton iteration), and
    ///   δ_r = `z₀ − z₀/√y`.
    fn reach(&self, _control: Control, rel_force: f64) -> Result<f64> {
        let rel = super::check_rel_force(rel_force)?;
        let (parts, f) = self.parts()?;
        let z = parts.range;
        let guess = match parts.kind {
            DUGDALE => return Ok(-z),
            EXPONENTIAL => z * rel.ln(),
            _ => {
                let y = lj_tail_inverse(0.75 * rel);
                z - z / y.sqrt()
            }
        };
        // Corrected by a few ulps against the force `eval` computes, so the
        // bound holds for every δ below in rounded arithmetic too.
        let bound = rel * f;
        Ok(super::first_staying(guess, |d| {
            self.eval(d, &ContactState::default())
                .map_or(true, |(r, _)| r.force.abs() >= bound)
        }))
    }

    /// The interaction energy `U(δ) = ∫_{−∞}^{δ} P dδ' = −2πR ∫_D^∞ e(z) dz`
    /// (J) of the rigid sphere, zero at infinite separation (from
    /// `P = −2πR e(D)` and `dD/dδ = −1`):
    ///
    /// * Lennard-Jones: `U = −2πRw·(4z₀/3)[(z₀/D) − (z₀/D)⁷/28]`, D = z₀ − δ;
    /// * Dugdale: `U = −πRσ₀(h₀ + δ)²` for `−h₀ ≤ δ ≤ 0`, 0 below;
    /// * exponential: `U = −2πRwℓ e^{δ/ℓ}`.
    fn energy(&self, delta: f64, _old: &ContactState) -> Result<f64> {
        let delta = check_delta(delta)?;
        let (parts, f) = self.parts()?;
        let gap = self.gap_at(&parts, delta)?;
        let z = parts.range;
        let u = match parts.kind {
            DUGDALE => {
                if gap >= z {
                    0.0
                } else {
                    let x = z - gap;
                    -0.5 * f / z * x * x
                }
            }
            EXPONENTIAL => -f * z * (-gap / z).exp(),
            _ => {
                let s = z / gap;
                let s7 = s * s * s * s * s * s * s;
                -f * z * (4.0 / 3.0) * (s - s7 / 28.0)
            }
        };
        check::finite_result(u, "delta", delta, "the energy overflows f64")
    }
}

/// The root y ∈ (0, 1) of `y − y⁴/4 = c` for `0 < c < 3/4` (the
/// Lennard-Jones tail `e/w = (4/3)(y − y⁴/4)`, y = (z₀/D)²): Newton from
/// the lower bound y = c on the concave, increasing left side (the iterates
/// increase monotonically to the root), bisection as a safeguard near the
/// double root at y = 1 (c → 3/4).
pub(crate) fn lj_tail_inverse(c: f64) -> f64 {
    let (mut lo, mut hi) = (c, 1.0f64);
    let mut y = c;
    for _ in 0..200 {
        let r = y - 0.25 * y * y * y * y - c;
        if r == 0.0 {
            return y;
        }
        if r < 0.0 {
            lo = y;
        } else {
            hi = y;
        }
        let dr = 1.0 - y * y * y;
        let mut next = y - r / dr;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - y).abs() <= 2.0 * f64::EPSILON * y || hi - lo <= 2.0 * f64::EPSILON * hi {
            // The last point below the root: the tail is below the bound
            // for every smaller y.
            return lo;
        }
        y = next;
    }
    lo
}
