//! Indenter geometries and the area functions A(h_c) of their contact.

use crate::error::{check, Error, Result};
use serde::Serialize;

/// Projected contact area as a function of the contact depth h_c.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum AreaFunction {
    /// NanoSuite / Oliver–Pharr series with h_c in **nm** and A in **nm²**:
    /// `A = C0 h_c² + C1 h_c + C2 h_c^{1/2} + C3 h_c^{1/4} + …` (the
    /// convention of the data README; up to 8 coefficients).
    NanoSuite {
        /// C0 (dimensionless), C1 (nm), C2 (nm^{3/2}), C3 (nm^{7/4}), …
        coefficients: Vec<f64>,
    },
    /// `A = c0 h_c²` (SI): ideal Berkovich/Vickers 24.5, cube corner 2.598,
    /// cone `π tan²γ`.
    Quadratic {
        /// The coefficient (dimensionless).
        c0: f64,
    },
    /// Sphere of radius R (m): `A = π(2R h_c − h_c²)` for h_c ≤ R, `πR²` beyond.
    Sphere {
        /// Radius (m).
        radius: f64,
    },
}

impl AreaFunction {
    /// Projected area (m²) at contact depth `hc` (m). Non-positive depths and
    /// series that evaluate to a non-positive area give an error.
    pub fn area(&self, hc: f64) -> Result<f64> {
        let hc = check::positive("contact_depth", hc)?;
        let a = match self {
            AreaFunction::NanoSuite { coefficients } => {
                let h = hc * 1e9;
                let mut e = 2.0;
                let mut a = 0.0;
                for c in coefficients {
                    a += c * h.powf(e);
                    e *= 0.5;
                }
                a * 1e-18
            }
            AreaFunction::Quadratic { c0 } => c0 * hc * hc,
            AreaFunction::Sphere { radius } => {
                let h = hc.min(*radius);
                core::f64::consts::PI * (2.0 * radius * h - h * h)
            }
        };
        if a.is_finite() && a > 0.0 {
            Ok(a)
        } else {
            Err(Error::OutOfDomain {
                name: "contact_depth",
                value: hc,
                reason: "the area function gives a non-positive area there",
            })
        }
    }

    pub(super) fn validate(&self) -> Result<()> {
        match self {
            AreaFunction::NanoSuite { coefficients } => {
                if coefficients.is_empty() || coefficients.len() > 8 {
                    return Err(Error::InvalidArgument {
                        name: "area_coefficients",
                        value: coefficients.len() as f64,
                        bound: "between 1 and 8 coefficients",
                    });
                }
                for &c in coefficients {
                    check::finite("area_coefficient", c)?;
                }
                Ok(())
            }
            AreaFunction::Quadratic { c0 } => check::positive("area_c0", *c0).map(|_| ()),
            AreaFunction::Sphere { radius } => check::positive("radius", *radius).map(|_| ()),
        }
    }
}

/// The indenter's geometry.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Indenter {
    /// Berkovich pyramid (ideal area 24.5 h_c², equivalent cone 70.3°).
    Berkovich,
    /// Vickers pyramid (ideal area 24.5 h_c², equivalent cone 70.3°).
    Vickers,
    /// Cube-corner pyramid (ideal area 2.598 h_c², equivalent cone 42.3°).
    CubeCorner,
    /// Cone of the given half-angle (rad).
    Cone {
        /// Half-angle (rad), in (0, π/2).
        half_angle: f64,
    },
    /// Sphere of the given radius (m): d = 2 is known.
    Sphere {
        /// Radius (m).
        radius: f64,
    },
    /// Not documented (as for the Hysitron file): treated as a Berkovich for
    /// the area function and β, and flagged.
    Unknown,
}

impl Indenter {
    /// Parse `berkovich`, `vickers`, `cube_corner` (or `cube-corner`),
    /// `unknown`, `sphere:<radius m>`, `cone:<half-angle deg>`.
    pub fn parse(s: &str) -> Option<Indenter> {
        let s = s.trim().to_ascii_lowercase();
        match s.as_str() {
            "berkovich" => Some(Indenter::Berkovich),
            "vickers" => Some(Indenter::Vickers),
            "cube_corner" | "cube-corner" | "cubecorner" => Some(Indenter::CubeCorner),
            "unknown" => Some(Indenter::Unknown),
            _ => {
                let (k, v) = s.split_once(':')?;
                let v: f64 = v.trim().parse().ok()?;
                match k {
                    "sphere" if v > 0.0 && v.is_finite() => Some(Indenter::Sphere { radius: v }),
                    "cone" if v > 0.0 && v < 90.0 => Some(Indenter::Cone {
                        half_angle: v.to_radians(),
                    }),
                    _ => None,
                }
            }
        }
    }

    /// Pyramids and cones: outside the Hertz assumptions (thesis §3.6.2).
    pub fn is_sharp(&self) -> bool {
        !matches!(self, Indenter::Sphere { .. })
    }

    /// The ideal area function of the geometry.
    pub fn ideal_area(&self) -> AreaFunction {
        match *self {
            Indenter::Berkovich | Indenter::Vickers | Indenter::Unknown => {
                AreaFunction::Quadratic { c0: 24.5 }
            }
            Indenter::CubeCorner => AreaFunction::Quadratic { c0: 2.598 },
            Indenter::Cone { half_angle } => AreaFunction::Quadratic {
                c0: core::f64::consts::PI * half_angle.tan().powi(2),
            },
            Indenter::Sphere { radius } => AreaFunction::Sphere { radius },
        }
    }

    /// Oliver–Pharr β of `E_r = √π S/(2β√A)`, the correction of the
    /// axisymmetric stiffness for the pyramid's cross-section: King (1987,
    /// Int. J. Solids Struct. 23, 1657–1664, finite-element flat punches)
    /// 1.034 for a triangular punch (Berkovich, cube corner) and 1.012 for a
    /// square one (Vickers), the values Oliver & Pharr (2004, J. Mater. Res.
    /// 19:3, §III.A) recommend among the published 1.0226–1.085; 1 for
    /// axisymmetric indenters (Sneddon). Oliver & Pharr (1992) used 1; an
    /// undocumented indenter is treated as a Berkovich.
    pub fn beta(&self) -> f64 {
        match self {
            Indenter::Sphere { .. } | Indenter::Cone { .. } => 1.0,
            Indenter::Vickers => 1.012,
            Indenter::Berkovich | Indenter::CubeCorner | Indenter::Unknown => 1.034,
        }
    }

    /// d fixed by the geometry: 2 for a sphere; none for sharp indenters (their
    /// real tips are rounded, so d is fitted).
    pub fn known_d(&self) -> Option<f64> {
        match self {
            Indenter::Sphere { .. } => Some(2.0),
            _ => None,
        }
    }

    pub(super) fn validate(&self) -> Result<()> {
        match *self {
            Indenter::Sphere { radius } => check::positive("sphere_radius", radius).map(|_| ()),
            Indenter::Cone { half_angle } => check::in_range(
                "cone_half_angle",
                half_angle,
                1e-9,
                core::f64::consts::FRAC_PI_2 - 1e-9,
                "in (0, pi/2) rad",
            )
            .map(|_| ()),
            _ => Ok(()),
        }
    }
}
