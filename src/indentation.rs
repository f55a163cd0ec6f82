//! Indentation analysis: hardness numbers, unloading stiffness (BASh), the
//! Oliver–Pharr method, and the extraction of the hardening index κ and the
//! bluntness index d from a measured load–depth curve by Borodich rescaling
//! (thesis chapter 3; [`crate::rescaling`]).
//!
//! ## The pipeline ([`analyze`])
//!
//! The formulas of the steps are under *Formulas* below.
//!
//! 1. **Segments** ([`segment`]): the labels of the file when present
//!    (`approach`, `loading`, `hold_at_peak`, `unloading`, `thermal_drift_hold`,
//!    `final_unloading`), otherwise detected from the load signal (peak, hold at
//!    ≥ 99.8 % of the peak, unloading until the load stops falling).
//! 2. **Loading branch** ([`log_log_fit`]): least-squares slope m_l of
//!    `ln P` against `ln δ` through the anchor point, by default the maximum
//!    indentation point (thesis §3.6.1; (3-20), (3-26)).
//! 3. **Unloading branch** ([`fit_unloading`], [`oliver_pharr`]): the power law
//!    of Oliver & Pharr (1992) fitted to the upper part of unloading (default
//!    25–95 % of P_max). Its exponent m is the elastic (κ = 1) rescaling
//!    slope of (3-26) with the depth measured from the residual imprint h_f,
//!    which gives d. *Note:* the thesis writes (3-26) with δ
//!    and does not say where δ is measured from on unloading; measured from the
//!    original surface, the slopes of real unloading curves are far above 2
//!    (d < 1), inconsistent with the thesis's own 1.24 for fused silica. We
//!    follow the literature (Oliver & Pharr 1992; Galanov's effective shape:
//!    unloading is the elastic contact of the indenter with its own imprint,
//!    which starts at h_f).
//! 4. **κ and d**: d from the unloading exponent and κ from the loading
//!    slope; or κ from loading with d known (a sphere: d = 2,
//!    $\kappa = 2m_l - 2$, (3-21)); or d from loading with κ known.
//!    Standard errors by first-order propagation.
//! 5. **Modulus and hardness** (Oliver & Pharr 1992, J. Mater. Res. 7:1564):
//!    the unloading stiffness S at the start of unloading, the contact depth
//!    h_c (ε = 0.75), the area A(h_c) from the area function, the reduced
//!    modulus E_r and the hardness H. β = 1.05 for pyramids (Oliver & Pharr
//!    2004), 1 for axisymmetric indenters; β = 1 is the BASh formula
//!    ((2-13), (2-14)). The sample modulus follows from E_r by (2-15);
//!    diamond `E_i = 1141 GPa`, `ν_i = 0.07` by default.
//! 6. **Validity flags** (thesis §3.6), each a code with an explanation
//!    ([`Flag`]).
//!
//! The uncertainties are statistical (from the residuals of the fits, with
//! the correlation between α, h_f and m). Systematic errors — the area
//! function, β, ε, thermal drift, frame compliance, surface detection — are not
//! in them.
//!
//! # Formulas
//!
//! Hardness numbers (2-7)–(2-12), ball diameter $D$, impression diameter (or
//! Vickers mean diagonal) $d$:
//!
//! $$\mathrm{BHN} = \frac{2P}{\pi D\bigl(D - \sqrt{D^2 - d^2}\bigr)}, \qquad H_M = \frac{4P}{\pi d^2}, \qquad \mathrm{LHN} = \frac{4P}{\sqrt2\\,\pi d^2}, \qquad \mathrm{HV} = \frac{2P\sin 68^\circ}{d^2} .$$
//!
//! Loading branch and rescaling (3-20), (3-26):
//!
//! $$\ln\frac{P}{P_1} = m_l\ln\frac{\delta}{\delta_1}, \qquad m_l = \frac{2+\kappa(d-1)}{d}, \qquad \kappa = \frac{d\\,m_l - 2}{d-1}, \qquad d = \frac{2-\kappa}{m_l - \kappa} .$$
//!
//! Unloading (Oliver & Pharr 1992), with $\varepsilon = 0.75$:
//!
//! $$P = \alpha(h - h_f)^m, \quad d = \frac{1}{m-1}, \quad S = \alpha m (h_\mathrm{max} - h_f)^{m-1}, \quad h_c = h_\mathrm{max} - \varepsilon\frac{P_\mathrm{max}}{S},$$
//!
//! $$E_r = \frac{\sqrt\pi}{2\beta}\frac{S}{\sqrt{A(h_c)}}, \qquad H = \frac{P_\mathrm{max}}{A(h_c)}, \qquad \frac{1}{E_r} = \frac{1-\nu^2}{E} + \frac{1-\nu_i^2}{E_i}, \qquad S = 2E^\ast a \ \ \text{(BASh, (2-13))}.$$
//!
//! # References
//!
//! * Thesis chapter 2 ((2-13)–(2-15)), chapter 3 ((3-20), (3-21), (3-26), §3.6).
//! * W. C. Oliver, G. M. Pharr (1992), "An improved technique for determining
//!   hardness and elastic modulus using load and displacement sensing
//!   indentation experiments", J. Mater. Res. 7, 1564–1583,
//!   [doi:10.1557/JMR.1992.1564](https://doi.org/10.1557/JMR.1992.1564).
//! * W. C. Oliver, G. M. Pharr (2004), "Measurement of hardness and elastic
//!   modulus by instrumented indentation: advances in understanding and
//!   refinements to methodology", J. Mater. Res. 19, 3–20,
//!   [doi:10.1557/jmr.2004.19.1.3](https://doi.org/10.1557/jmr.2004.19.1.3).
//! * S. I. Bulychev, V. P. Alekhin, M. Kh. Shorshorov, A. P. Ternovskii,
//!   G. D. Shnyrev (1975), the BASh relation (Zavod. Lab. 41, in Russian).
//! * F. M. Borodich (1993), Int. J. Solids Struct. 30, 1513–1526 (rescaling);
//!   B. A. Galanov (1981) (effective shape of unloading), as cited by the thesis.

// `!(x > 0.0)` is deliberate throughout: it rejects NaN as well.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::error::{check, Error, Result};
use crate::rescaling;
use serde::Serialize;
use std::fmt;
use std::path::Path;

// ---------------------------------------------------------------------------
// Hardness numbers (thesis §2.3)

/// Brinell hardness (2-7): load over the curved area of the spherical
/// impression, `BHN = 2P/(πD(D − √(D² − d²)))` (Pa) for ball diameter D and
/// impression diameter d (m), `0 < d ≤ D`. Classical tables quote kgf/mm²
/// (divide Pa by 9.80665e6).
pub fn brinell_hardness(load: f64, ball_diameter: f64, imprint_diameter: f64) -> Result<f64> {
    let p = check::non_negative("load", load)?;
    let big_d = check::positive("ball_diameter", ball_diameter)?;
    let d = check::positive("imprint_diameter", imprint_diameter)?;
    if d > big_d {
        return Err(Error::InvalidArgument {
            name: "imprint_diameter",
            value: d,
            bound: "<= ball_diameter",
        });
    }
    // D − √(D² − d²) = d²/(D + √(D² − d²)), free of cancellation for small d.
    let cap = d * d / (big_d + (big_d * big_d - d * d).sqrt());
    Ok(2.0 * p / (core::f64::consts::PI * big_d * cap))
}

/// Meyer hardness (2-8), (2-11): load over the projected area,
/// `H_M = 4P/(πd²)` (Pa), impression diameter d (m).
pub fn meyer_hardness(load: f64, imprint_diameter: f64) -> Result<f64> {
    let p = check::non_negative("load", load)?;
    let d = check::positive("imprint_diameter", imprint_diameter)?;
    Ok(4.0 * p / (core::f64::consts::PI * d * d))
}

/// Ludwik hardness (2-10) of a 90° cone: load over the conical surface,
/// `LHN = 4P/(√2 π d²)` (Pa), impression diameter d (m).
pub fn ludwik_hardness(load: f64, imprint_diameter: f64) -> Result<f64> {
    Ok(meyer_hardness(load, imprint_diameter)? / core::f64::consts::SQRT_2)
}

/// Vickers hardness (2-12): load over the surface of the pyramidal
/// impression, `HV = 2P sin(136°/2)/d² = 1.8544 P/d²` (Pa), mean diagonal d (m).
pub fn vickers_hardness(load: f64, mean_diagonal: f64) -> Result<f64> {
    let p = check::non_negative("load", load)?;
    let d = check::positive("mean_diagonal", mean_diagonal)?;
    Ok(2.0 * p * (68.0_f64).to_radians().sin() / (d * d))
}

/// Reduced modulus from the unloading stiffness and the projected contact
/// area (Pa): `E_r = (√π/2) S/(β√A)` (BASh (2-14) with Oliver–Pharr's β;
/// β = 1 is (2-14) itself). S in N/m, A in m², β > 0.
pub fn reduced_modulus_from_stiffness(stiffness: f64, area: f64, beta: f64) -> Result<f64> {
    let s = check::positive("stiffness", stiffness)?;
    let a = check::positive("area", area)?;
    let b = check::positive("beta", beta)?;
    Ok(core::f64::consts::PI.sqrt() / 2.0 * s / (b * a.sqrt()))
}

/// Sample modulus from the reduced modulus (2-15):
/// `E = (1 − ν²)/(1/E_r − (1 − ν_i²)/E_i)` (Pa). `E_i = +∞` is a rigid
/// indenter. Fails ([`Error::OutOfDomain`]) when E_r is not below the
/// indenter's own plane-strain modulus.
pub fn sample_modulus(
    reduced_modulus: f64,
    nu_sample: f64,
    e_indenter: f64,
    nu_indenter: f64,
) -> Result<f64> {
    let er = check::positive("reduced_modulus", reduced_modulus)?;
    let nu = check::poisson("nu_sample", nu_sample)?;
    let nui = check::poisson("nu_indenter", nu_indenter)?;
    if !(e_indenter > 0.0) {
        return Err(Error::InvalidArgument {
            name: "e_indenter",
            value: e_indenter,
            bound: "> 0 (+inf for a rigid indenter)",
        });
    }
    let ci = if e_indenter.is_infinite() {
        0.0
    } else {
        (1.0 - nui * nui) / e_indenter
    };
    let den = 1.0 / er - ci;
    if den <= 0.0 {
        return Err(Error::OutOfDomain {
            name: "reduced_modulus",
            value: er,
            reason: "not below the indenter's plane-strain modulus E_i/(1 - nu_i^2)",
        });
    }
    Ok((1.0 - nu * nu) / den)
}

// ---------------------------------------------------------------------------
// Indenters and area functions

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

    fn validate(&self) -> Result<()> {
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

    /// Oliver–Pharr β: 1.05 for pyramids (Oliver & Pharr 2004), 1 for
    /// axisymmetric indenters.
    pub fn beta(&self) -> f64 {
        match self {
            Indenter::Sphere { .. } | Indenter::Cone { .. } => 1.0,
            _ => 1.05,
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

    fn validate(&self) -> Result<()> {
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

// ---------------------------------------------------------------------------
// Curves and readers

/// Segment of an indentation curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Segment {
    /// Not assigned.
    Unknown,
    /// Before surface contact.
    Approach,
    /// Loading.
    Loading,
    /// Hold at peak load.
    Hold,
    /// Unloading from the peak.
    Unloading,
    /// Thermal-drift hold (usually at ~10 % of the peak, after unloading).
    DriftHold,
    /// Final withdrawal after the drift hold.
    FinalUnloading,
}

impl Segment {
    /// From the data format's label (`approach`, `loading`, `hold_at_peak`,
    /// `unloading`, `thermal_drift_hold`, `final_unloading`; `hold` and
    /// `unknown` are accepted too).
    pub fn from_label(s: &str) -> Option<Segment> {
        Some(match s.trim() {
            "approach" => Segment::Approach,
            "loading" => Segment::Loading,
            "hold_at_peak" | "hold" => Segment::Hold,
            "unloading" => Segment::Unloading,
            "thermal_drift_hold" => Segment::DriftHold,
            "final_unloading" => Segment::FinalUnloading,
            "unknown" | "" => Segment::Unknown,
            _ => return None,
        })
    }

    /// The integer code of the C ABI (0 unknown, 1 approach, 2 loading, 3 hold,
    /// 4 unloading, 5 drift hold, 6 final unloading).
    pub fn code(self) -> i32 {
        match self {
            Segment::Unknown => 0,
            Segment::Approach => 1,
            Segment::Loading => 2,
            Segment::Hold => 3,
            Segment::Unloading => 4,
            Segment::DriftHold => 5,
            Segment::FinalUnloading => 6,
        }
    }

    /// The inverse of [`Segment::code`].
    pub fn from_code(code: i32) -> Option<Segment> {
        Some(match code {
            0 => Segment::Unknown,
            1 => Segment::Approach,
            2 => Segment::Loading,
            3 => Segment::Hold,
            4 => Segment::Unloading,
            5 => Segment::DriftHold,
            6 => Segment::FinalUnloading,
            _ => return None,
        })
    }
}

/// A measured load–depth curve (SI: m, N, s).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Curve {
    /// Time (s), when the file has it.
    pub time: Option<Vec<f64>>,
    /// Depth (m), positive into the surface.
    pub depth: Vec<f64>,
    /// Load (N), positive compressive.
    pub load: Vec<f64>,
    /// Segment labels, when the file has them.
    pub segments: Option<Vec<Segment>>,
}

/// Reading a curve failed.
#[derive(Debug)]
pub enum ReadError {
    /// The file could not be read.
    Io(std::io::Error),
    /// A line could not be parsed (1-based line number).
    Parse {
        /// Line number, 1-based.
        line: usize,
        /// What was wrong.
        message: String,
    },
    /// The parsed data are invalid (unequal lengths, non-finite values, …).
    Invalid(Error),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io(e) => write!(f, "reading the curve: {e}"),
            ReadError::Parse { line, message } => write!(f, "line {line}: {message}"),
            ReadError::Invalid(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ReadError {}

impl From<Error> for ReadError {
    fn from(e: Error) -> Self {
        ReadError::Invalid(e)
    }
}

fn parse_number(s: &str, line: usize, what: &str) -> std::result::Result<f64, ReadError> {
    let v: f64 = s.trim().parse().map_err(|_| ReadError::Parse {
        line,
        message: format!("{what} `{}` is not a number", s.trim()),
    })?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(ReadError::Parse {
            line,
            message: format!("{what} `{}` is not finite", s.trim()),
        })
    }
}

impl Curve {
    /// A curve from depth (m) and load (N) arrays of equal length, all finite.
    pub fn new(depth: Vec<f64>, load: Vec<f64>) -> Result<Self> {
        if depth.len() != load.len() {
            return Err(Error::InvalidArgument {
                name: "load",
                value: load.len() as f64,
                bound: "as many values as depth",
            });
        }
        for &x in &depth {
            check::finite("depth", x)?;
        }
        for &x in &load {
            check::finite("load", x)?;
        }
        Ok(Self {
            time: None,
            depth,
            load,
            segments: None,
        })
    }

    /// Attach segment labels (one per point).
    pub fn with_segments(mut self, segments: Vec<Segment>) -> Result<Self> {
        if segments.len() != self.depth.len() {
            return Err(Error::InvalidArgument {
                name: "segments",
                value: segments.len() as f64,
                bound: "one label per point",
            });
        }
        self.segments = Some(segments);
        Ok(self)
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.depth.len()
    }

    /// No points.
    pub fn is_empty(&self) -> bool {
        self.depth.is_empty()
    }

    /// Parse the data format of `../shared/data/indentation`: `#` comment
    /// lines, then the header `time_s,depth_m,load_N,segment` (columns found
    /// by name, in any order; `time_s` and `segment` optional), then rows.
    pub fn from_csv_str(text: &str) -> std::result::Result<Self, ReadError> {
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let (hline, header) = lines.next().ok_or(ReadError::Parse {
            line: 0,
            message: "no header line".into(),
        })?;
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        let find = |n: &str| names.iter().position(|x| *x == n);
        let (Some(id), Some(il)) = (find("depth_m"), find("load_N")) else {
            return Err(ReadError::Parse {
                line: hline,
                message: format!("header `{header}` lacks depth_m and load_N"),
            });
        };
        let it = find("time_s");
        let is = find("segment");
        let mut c = Curve {
            time: it.map(|_| Vec::new()),
            segments: is.map(|_| Vec::new()),
            ..Default::default()
        };
        for (n, l) in lines {
            let f: Vec<&str> = l.split(',').collect();
            if f.len() < names.len() {
                return Err(ReadError::Parse {
                    line: n,
                    message: format!("{} fields, the header has {}", f.len(), names.len()),
                });
            }
            c.depth.push(parse_number(f[id], n, "depth")?);
            c.load.push(parse_number(f[il], n, "load")?);
            if let (Some(i), Some(t)) = (it, c.time.as_mut()) {
                t.push(parse_number(f[i], n, "time")?);
            }
            if let (Some(i), Some(s)) = (is, c.segments.as_mut()) {
                s.push(Segment::from_label(f[i]).ok_or_else(|| ReadError::Parse {
                    line: n,
                    message: format!("unknown segment label `{}`", f[i].trim()),
                })?);
            }
        }
        if c.is_empty() {
            return Err(ReadError::Parse {
                line: hline,
                message: "no data rows".into(),
            });
        }
        Ok(c)
    }

    /// Plain two-column text: `depth load` per line (m, N), separated by
    /// whitespace, a comma or a semicolon; `#` comments and a non-numeric
    /// first line (a header) are skipped.
    pub fn from_two_column_str(text: &str) -> std::result::Result<Self, ReadError> {
        let mut c = Curve::default();
        let mut first = true;
        for (i, l) in text.lines().enumerate() {
            let l = l.trim();
            if l.is_empty() || l.starts_with('#') {
                continue;
            }
            let f: Vec<&str> = l
                .split(|ch: char| ch == ',' || ch == ';' || ch.is_whitespace())
                .filter(|s| !s.is_empty())
                .collect();
            if first && f.first().is_some_and(|s| s.parse::<f64>().is_err()) {
                first = false;
                continue;
            }
            first = false;
            if f.len() < 2 {
                return Err(ReadError::Parse {
                    line: i + 1,
                    message: "expected two columns: depth load".into(),
                });
            }
            c.depth.push(parse_number(f[0], i + 1, "depth")?);
            c.load.push(parse_number(f[1], i + 1, "load")?);
        }
        if c.is_empty() {
            return Err(ReadError::Parse {
                line: 0,
                message: "no data rows".into(),
            });
        }
        Ok(c)
    }

    /// Either format: the CSV format when a header names `depth_m` and
    /// `load_N`, two columns otherwise.
    pub fn parse(text: &str) -> std::result::Result<Self, ReadError> {
        let header = text
            .lines()
            .map(str::trim)
            .find(|l| !l.is_empty() && !l.starts_with('#'));
        if header.is_some_and(|h| h.contains("depth_m") && h.contains("load_N")) {
            Self::from_csv_str(text)
        } else {
            Self::from_two_column_str(text)
        }
    }

    /// Read a file in either format ([`Curve::parse`]).
    pub fn read(path: impl AsRef<Path>) -> std::result::Result<Self, ReadError> {
        let text = std::fs::read_to_string(path).map_err(ReadError::Io)?;
        Self::parse(&text)
    }
}

// ---------------------------------------------------------------------------
// Segmentation

/// Where the segments are, as half-open index ranges into the curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Segmentation {
    /// True when the file's labels were used, false when detected.
    pub from_labels: bool,
    /// Loading `[start, end)`.
    pub loading: [usize; 2],
    /// Hold at peak `[start, end)` (may be empty).
    pub hold: [usize; 2],
    /// Unloading from the peak `[start, end)` (may be empty).
    pub unloading: [usize; 2],
}

/// Fraction of the peak load above which detected points belong to the hold.
const HOLD_FRACTION: f64 = 0.998;

fn label_range(labels: &[Segment], s: Segment) -> [usize; 2] {
    let first = labels.iter().position(|&x| x == s);
    let last = labels.iter().rposition(|&x| x == s);
    match (first, last) {
        (Some(a), Some(b)) => [a, b + 1],
        _ => [0, 0],
    }
}

/// Find the segments: from the labels when the curve has them and
/// `use_labels` is set, otherwise by detection:
///
/// * the peak is the first maximum of the load; the **hold** is the contiguous
///   run around it with load ≥ 99.8 % of the peak;
/// * **loading** is everything before the hold;
/// * **unloading** runs from the end of the hold while the load keeps falling:
///   it ends where the drop over the last 5 points is below 20 % of the mean
///   drop per 5 points so far (a drift hold or the end of the test), or where
///   the load rises again by more than 5 % of the peak (a reload).
pub fn segment(curve: &Curve, use_labels: bool) -> Result<Segmentation> {
    if curve.is_empty() {
        return Err(Error::InvalidArgument {
            name: "curve",
            value: 0.0,
            bound: "at least one point",
        });
    }
    if let (true, Some(labels)) = (use_labels, curve.segments.as_ref()) {
        return Ok(Segmentation {
            from_labels: true,
            loading: label_range(labels, Segment::Loading),
            hold: label_range(labels, Segment::Hold),
            unloading: label_range(labels, Segment::Unloading),
        });
    }
    let p = &curve.load;
    let n = p.len();
    let (ipk, pmax) =
        p.iter().enumerate().fold(
            (0, f64::NEG_INFINITY),
            |(i0, m), (i, &v)| {
                if v > m {
                    (i, v)
                } else {
                    (i0, m)
                }
            },
        );
    let thr = if pmax > 0.0 {
        HOLD_FRACTION * pmax
    } else {
        pmax
    };
    let mut h0 = ipk;
    while h0 > 0 && p[h0 - 1] >= thr {
        h0 -= 1;
    }
    let mut h1 = ipk + 1;
    while h1 < n && p[h1] >= thr {
        h1 += 1;
    }
    // Unloading from the last hold point (the peak of unloading).
    let u0 = h1 - 1;
    const W: usize = 5;
    let mut runmin = vec![p[u0]; n - u0];
    for k in 1..n - u0 {
        runmin[k] = runmin[k - 1].min(p[u0 + k]);
    }
    let mut end = n;
    for k in 1..n - u0 {
        if p[u0 + k] > runmin[k] + 0.05 * pmax.abs() {
            end = u0 + k;
            break;
        }
        if k >= 2 * W {
            let drop_w = runmin[k - W] - runmin[k];
            let mean_w = (runmin[0] - runmin[k - W]) / (k - W) as f64 * W as f64;
            if drop_w < 0.2 * mean_w {
                end = u0 + k - W + 1;
                break;
            }
        }
    }
    Ok(Segmentation {
        from_labels: false,
        loading: [0, h0],
        hold: [h0, h1],
        unloading: [h1.min(end), end.max(h1)],
    })
}

// ---------------------------------------------------------------------------
// Log–log fit

/// Where the log–log line is pinned.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Anchor {
    /// Through the maximum point of the fitted branch (thesis §3.6.1; default).
    MaxPoint,
    /// Through the given point of the curve (0-based index).
    Index {
        /// Index into the curve.
        index: usize,
    },
    /// No anchor: ordinary two-parameter regression of ln P on ln δ.
    Free,
}

/// A straight line in log–log coordinates, `ln P = ln P₁ + m ln(δ/δ₁)`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PowerLawFit {
    /// Slope m (dimensionless).
    pub slope: f64,
    /// Standard error of the slope.
    pub slope_stderr: f64,
    /// Depth δ₁ of the reference point (m): the anchor, or for a free fit the
    /// geometric mean of the depths.
    pub reference_depth: f64,
    /// Load at the reference depth on the line (N).
    pub reference_load: f64,
    /// Standard error of ln(reference_load) (0 when anchored).
    pub reference_log_load_stderr: f64,
    /// Coefficient of determination of ln P (centred total sum of squares).
    pub r_squared: f64,
    /// Residuals ln P − line, in the order of the fitted points.
    pub residuals: Vec<f64>,
    /// Points used.
    pub n_points: usize,
    /// Points of the window left out because depth or load was ≤ 0.
    pub n_excluded: usize,
    /// Whether the line was pinned to an anchor.
    pub anchored: bool,
}

/// Least-squares slope of ln P against ln δ (thesis (3-20), (3-26)); points with
/// non-positive depth or load are left out and counted. With an anchor
/// `(δ₁, P₁)` the line passes through it: `m = Σxy/Σx²` with
/// `x = ln(δ/δ₁)`, `y = ln(P/P₁)`, `se² = Σr²/((n−1)Σx²)`, at least 3 points
/// off the anchor. Without, ordinary regression, `se² = Σr²/((n−2)S_xx)`, at
/// least 3 points.
pub fn log_log_fit(depth: &[f64], load: &[f64], anchor: Option<(f64, f64)>) -> Result<PowerLawFit> {
    if depth.len() != load.len() {
        return Err(Error::InvalidArgument {
            name: "load",
            value: load.len() as f64,
            bound: "as many values as depth",
        });
    }
    let mut xs = Vec::with_capacity(depth.len());
    let mut ys = Vec::with_capacity(depth.len());
    let mut excluded = 0;
    for (&h, &p) in depth.iter().zip(load) {
        if h > 0.0 && p > 0.0 && h.is_finite() && p.is_finite() {
            xs.push(h.ln());
            ys.push(p.ln());
        } else {
            excluded += 1;
        }
    }
    let n = xs.len();
    let too_few = |need: usize| Error::OutOfDomain {
        name: "points",
        value: n as f64,
        reason: if need == 3 {
            "a log-log fit needs at least 3 points with positive depth and load"
        } else {
            "an anchored log-log fit needs at least 3 points off the anchor"
        },
    };
    let ybar = ys.iter().sum::<f64>() / n.max(1) as f64;
    let sst: f64 = ys.iter().map(|y| (y - ybar).powi(2)).sum();
    let fit = match anchor {
        Some((h1, p1)) => {
            let h1 = check::positive("anchor_depth", h1)?;
            let p1 = check::positive("anchor_load", p1)?;
            let (lx, ly) = (h1.ln(), p1.ln());
            let off = xs.iter().filter(|&&x| (x - lx).abs() > 1e-12).count();
            if off < 3 {
                return Err(too_few(4));
            }
            let sxx: f64 = xs.iter().map(|x| (x - lx).powi(2)).sum();
            let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - lx) * (y - ly)).sum();
            let m = sxy / sxx;
            let res: Vec<f64> = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| (y - ly) - m * (x - lx))
                .collect();
            let ssr: f64 = res.iter().map(|r| r * r).sum();
            let dof = (n - 1).max(1) as f64;
            PowerLawFit {
                slope: m,
                slope_stderr: (ssr / dof / sxx).sqrt(),
                reference_depth: h1,
                reference_load: p1,
                reference_log_load_stderr: 0.0,
                r_squared: if sst > 0.0 { 1.0 - ssr / sst } else { 1.0 },
                residuals: res,
                n_points: n,
                n_excluded: excluded,
                anchored: true,
            }
        }
        None => {
            if n < 3 {
                return Err(too_few(3));
            }
            let xbar = xs.iter().sum::<f64>() / n as f64;
            let sxx: f64 = xs.iter().map(|x| (x - xbar).powi(2)).sum();
            if sxx <= 0.0 {
                return Err(Error::OutOfDomain {
                    name: "depth",
                    value: depth[0],
                    reason: "all fitted depths are equal: no slope",
                });
            }
            let sxy: f64 = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| (x - xbar) * (y - ybar))
                .sum();
            let m = sxy / sxx;
            let res: Vec<f64> = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| (y - ybar) - m * (x - xbar))
                .collect();
            let ssr: f64 = res.iter().map(|r| r * r).sum();
            let s2 = ssr / (n - 2) as f64;
            PowerLawFit {
                slope: m,
                slope_stderr: (s2 / sxx).sqrt(),
                reference_depth: xbar.exp(),
                reference_load: ybar.exp(),
                reference_log_load_stderr: (s2 / n as f64).sqrt(),
                r_squared: if sst > 0.0 { 1.0 - ssr / sst } else { 1.0 },
                residuals: res,
                n_points: n,
                n_excluded: excluded,
                anchored: false,
            }
        }
    };
    if !fit.slope.is_finite() || !fit.slope_stderr.is_finite() {
        return Err(Error::OutOfDomain {
            name: "depth",
            value: depth.first().copied().unwrap_or(0.0),
            reason: "the depths do not spread around the anchor: no slope",
        });
    }
    Ok(fit)
}

// ---------------------------------------------------------------------------
// Unloading: P = α (h − h_f)^m

/// The Oliver–Pharr unloading power law `P = α(h − h_f)^m`, fitted by least
/// squares in P, with the covariance of (ln α, h_f, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UnloadingFit {
    /// Exponent m (dimensionless).
    pub exponent: f64,
    /// Standard error of m.
    pub exponent_stderr: f64,
    /// Final (residual) depth h_f (m).
    pub final_depth: f64,
    /// Standard error of h_f (m).
    pub final_depth_stderr: f64,
    /// α (N/m^m).
    pub prefactor: f64,
    /// Coefficient of determination of P.
    pub r_squared: f64,
    /// Residuals P − fit (N), in the order of the fitted points.
    pub residuals: Vec<f64>,
    /// Root-mean-square residual (N).
    pub rms_residual: f64,
    /// Points fitted.
    pub n_points: usize,
    /// Load window used, as fractions of the peak load.
    pub window: [f64; 2],
    /// Covariance of (ln α′, h_f/h_max, m) in the scaled variables of the fit.
    #[serde(skip)]
    covariance: [[f64; 3]; 3],
    /// Scales: (h_max, P_max) used to make the fit dimensionless.
    #[serde(skip)]
    scales: (f64, f64),
    /// Scaled parameters (ln α′, h_f′, m).
    #[serde(skip)]
    theta: [f64; 3],
}

fn sse_profile(h: &[f64], p: &[f64], hf: f64) -> Option<(f64, f64, f64)> {
    // Linear regression of ln p on ln(h − hf); returns (ln α, m, SSE in p).
    let n = h.len() as f64;
    let xs: Vec<f64> = h.iter().map(|&x| (x - hf).ln()).collect();
    let ys: Vec<f64> = p.iter().map(|&y| y.ln()).collect();
    let xb = xs.iter().sum::<f64>() / n;
    let yb = ys.iter().sum::<f64>() / n;
    let sxx: f64 = xs.iter().map(|x| (x - xb).powi(2)).sum();
    if !(sxx > 0.0) {
        return None;
    }
    let m = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - xb) * (y - yb))
        .sum::<f64>()
        / sxx;
    let la = yb - m * xb;
    let sse = xs
        .iter()
        .zip(p)
        .map(|(x, y)| (y - (la + m * x).exp()).powi(2))
        .sum::<f64>();
    sse.is_finite().then_some((la, m, sse))
}

fn inverse3(a: &[[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    // Adjugate inverse of a 3×3 matrix (the normal matrix of a 3-parameter
    // fit); a linear-algebra crate would add nothing at this size.
    let c = |i: usize, j: usize| {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
        a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]
    };
    let det = a[0][0] * c(0, 0) + a[0][1] * c(0, 1) + a[0][2] * c(0, 2);
    if !(det.abs() > 0.0) || !det.is_finite() {
        return None;
    }
    let mut inv = [[0.0; 3]; 3];
    for (i, row) in inv.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = c(j, i) / det;
        }
    }
    Some(inv)
}

/// Fit `P = α(h − h_f)^m` to the unloading points whose load lies in
/// `[window[0], window[1]]·P_max` (`peak_load` = P_max, N; `peak_depth` = h_max,
/// m, used only for scaling). Method: h_f is profiled (for each h_f, ln P is
/// regressed on ln(h − h_f)) over a log-spaced scan and a golden-section
/// refinement, then the three parameters are polished by damped Gauss–Newton
/// on the squared residuals in P; the covariance is `s²(JᵀJ)⁻¹`,
/// `s² = SSE/(n − 3)`. Needs ≥ 5 points in the window.
pub fn fit_unloading(
    depth: &[f64],
    load: &[f64],
    peak_depth: f64,
    peak_load: f64,
    window: [f64; 2],
) -> Result<UnloadingFit> {
    let hmax = check::positive("peak_depth", peak_depth)?;
    let pmax = check::positive("peak_load", peak_load)?;
    if !(window[0] >= 0.0 && window[1] <= 1.0 && window[0] < window[1]) {
        return Err(Error::InvalidArgument {
            name: "unloading_window",
            value: window[0],
            bound: "0 <= low < high <= 1",
        });
    }
    let mut h = Vec::new();
    let mut p = Vec::new();
    for (&x, &y) in depth.iter().zip(load) {
        if y >= window[0] * pmax && y <= window[1] * pmax && y > 0.0 && x.is_finite() {
            h.push(x / hmax);
            p.push(y / pmax);
        }
    }
    let n = h.len();
    if n < 5 {
        return Err(Error::OutOfDomain {
            name: "unloading_points",
            value: n as f64,
            reason: "the unloading fit needs at least 5 points in the load window",
        });
    }
    let hmin = h.iter().cloned().fold(f64::INFINITY, f64::min);
    let hmx = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let range = hmx - hmin;
    if !(range > 0.0) {
        return Err(Error::OutOfDomain {
            name: "unloading_points",
            value: n as f64,
            reason: "all unloading depths are equal: no slope",
        });
    }
    // Scan the gap g = hmin − h_f over 1e-4 … 1e3 ranges.
    let k = 160;
    let gap = |i: f64| range * 10f64.powf(-4.0 + 7.0 * i / k as f64);
    let mut best = (f64::INFINITY, 0usize);
    for i in 0..=k {
        if let Some((_, _, sse)) = sse_profile(&h, &p, hmin - gap(i as f64)) {
            if sse < best.0 {
                best = (sse, i);
            }
        }
    }
    if !best.0.is_finite() {
        return Err(Error::NotConverged {
            what: "unloading power-law fit (scan)",
            iterations: k as u32,
            residual: f64::INFINITY,
        });
    }
    // Golden section in the scan index around the best.
    let (mut a, mut b) = (
        (best.1 as f64 - 1.0).max(0.0),
        (best.1 as f64 + 1.0).min(k as f64),
    );
    let f = |i: f64| {
        sse_profile(&h, &p, hmin - gap(i))
            .map(|r| r.2)
            .unwrap_or(f64::INFINITY)
    };
    let gr = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..60 {
        let c = b - gr * (b - a);
        let d = a + gr * (b - a);
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let hf0 = hmin - gap(0.5 * (a + b));
    let (la0, m0, _) = sse_profile(&h, &p, hf0).ok_or(Error::NotConverged {
        what: "unloading power-law fit (profile)",
        iterations: 60,
        residual: f64::INFINITY,
    })?;
    // Damped Gauss–Newton in (ln α, h_f, m).
    let model = |t: &[f64; 3], x: f64| (t[0] + t[2] * (x - t[1]).ln()).exp();
    let sse_of = |t: &[f64; 3]| -> f64 {
        if t[1] >= hmin {
            return f64::INFINITY;
        }
        h.iter()
            .zip(&p)
            .map(|(&x, &y)| (y - model(t, x)).powi(2))
            .sum()
    };
    let jac_normal = |t: &[f64; 3]| -> ([[f64; 3]; 3], [f64; 3]) {
        let mut jtj = [[0.0; 3]; 3];
        let mut jtr = [0.0; 3];
        for (&x, &y) in h.iter().zip(&p) {
            let u = x - t[1];
            let f = model(t, x);
            let j = [f, -t[2] * f / u, f * u.ln()];
            let r = y - f;
            for a in 0..3 {
                jtr[a] += j[a] * r;
                for b in 0..3 {
                    jtj[a][b] += j[a] * j[b];
                }
            }
        }
        (jtj, jtr)
    };
    let mut t = [la0, hf0, m0];
    let mut cur = sse_of(&t);
    let mut mu = 1e-3;
    for _ in 0..100 {
        let (jtj, jtr) = jac_normal(&t);
        let mut improved = false;
        for _ in 0..30 {
            let mut a = jtj;
            for (i, row) in a.iter_mut().enumerate() {
                row[i] *= 1.0 + mu;
            }
            let Some(inv) = inverse3(&a) else {
                mu *= 10.0;
                continue;
            };
            let mut step = [0.0; 3];
            for i in 0..3 {
                step[i] = (0..3).map(|j| inv[i][j] * jtr[j]).sum();
            }
            let trial = [t[0] + step[0], t[1] + step[1], t[2] + step[2]];
            let s = sse_of(&trial);
            if s < cur {
                let rel = (cur - s) / cur.max(f64::MIN_POSITIVE);
                t = trial;
                cur = s;
                mu = (mu * 0.3).max(1e-12);
                improved = rel > 1e-14;
                break;
            }
            mu *= 10.0;
        }
        if !improved {
            break;
        }
    }
    let (jtj, _) = jac_normal(&t);
    let dof = (n - 3) as f64;
    let s2 = cur / dof;
    let inv = inverse3(&jtj).ok_or(Error::OutOfDomain {
        name: "unloading_points",
        value: n as f64,
        reason: "the unloading data do not determine alpha, h_f and m (singular normal matrix)",
    })?;
    let mut cov = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            cov[i][j] = inv[i][j] * s2;
        }
    }
    let pbar = p.iter().sum::<f64>() / n as f64;
    let sst: f64 = p.iter().map(|y| (y - pbar).powi(2)).sum();
    let residuals: Vec<f64> = h
        .iter()
        .zip(&p)
        .map(|(&x, &y)| (y - model(&t, x)) * pmax)
        .collect();
    let fit = UnloadingFit {
        exponent: t[2],
        exponent_stderr: cov[2][2].max(0.0).sqrt(),
        final_depth: t[1] * hmax,
        final_depth_stderr: cov[1][1].max(0.0).sqrt() * hmax,
        prefactor: (t[0] - t[2] * hmax.ln()).exp() * pmax,
        r_squared: if sst > 0.0 { 1.0 - cur / sst } else { 1.0 },
        rms_residual: (cur / n as f64).sqrt() * pmax,
        residuals,
        n_points: n,
        window,
        covariance: cov,
        scales: (hmax, pmax),
        theta: t,
    };
    let all_finite = [
        fit.exponent,
        fit.exponent_stderr,
        fit.final_depth,
        fit.final_depth_stderr,
        fit.prefactor,
        fit.r_squared,
    ]
    .iter()
    .all(|v| v.is_finite());
    if !all_finite {
        return Err(Error::NotConverged {
            what: "unloading power-law fit",
            iterations: 100,
            residual: cur,
        });
    }
    Ok(fit)
}

impl UnloadingFit {
    /// `dP/dh = α m (h − h_f)^{m−1}` (N/m) at depth `h` (m) on the fit.
    pub fn stiffness_at(&self, h: f64) -> f64 {
        let u = (h - self.final_depth).max(0.0);
        self.prefactor * self.exponent * u.powf(self.exponent - 1.0)
    }

    /// First-order standard error of `g(θ)` for a function of the scaled
    /// parameters θ = (ln α′, h_f′, m), by central differences.
    fn propagate(&self, g: impl Fn(&[f64; 3]) -> Option<f64>) -> Option<f64> {
        let mut grad = [0.0; 3];
        for i in 0..3 {
            let sd = self.covariance[i][i].max(0.0).sqrt();
            let step = if sd > 0.0 { 1e-3 * sd } else { 1e-9 };
            let mut tp = self.theta;
            let mut tm = self.theta;
            tp[i] += step;
            tm[i] -= step;
            grad[i] = (g(&tp)? - g(&tm)?) / (2.0 * step);
        }
        let mut var = 0.0;
        for i in 0..3 {
            for j in 0..3 {
                var += grad[i] * self.covariance[i][j] * grad[j];
            }
        }
        let se = var.max(0.0).sqrt();
        se.is_finite().then_some(se)
    }
}

/// Options of the Oliver–Pharr evaluation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OliverPharrOptions {
    /// Area function A(h_c).
    pub area: AreaFunction,
    /// ε of `h_c = h_max − ε P_max/S` (0.75 for a paraboloid of revolution,
    /// the usual choice for Berkovich tips).
    pub epsilon: f64,
    /// β of `E_r = (√π/2) S/(β√A)`.
    pub beta: f64,
    /// Load window of the unloading fit, as fractions of P_max.
    pub window: [f64; 2],
}

/// The Oliver–Pharr evaluation of one unloading branch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OliverPharr {
    /// The power-law fit of the unloading branch.
    pub fit: UnloadingFit,
    /// Peak load P_max (N) at the start of unloading.
    pub peak_load: f64,
    /// Depth h_max (m) at the start of unloading.
    pub peak_depth: f64,
    /// Unloading stiffness S = dP/dh at h_max (N/m).
    pub stiffness: f64,
    /// Standard error of S (N/m).
    pub stiffness_stderr: f64,
    /// Contact depth h_c (m).
    pub contact_depth: f64,
    /// Standard error of h_c (m).
    pub contact_depth_stderr: f64,
    /// Projected contact area A(h_c) (m²).
    pub contact_area: f64,
    /// Reduced modulus E_r = (√π/2) S/(β√A) (Pa).
    pub reduced_modulus: f64,
    /// Standard error of E_r (Pa).
    pub reduced_modulus_stderr: f64,
    /// The BASh value (β = 1), (2-14) (Pa).
    pub reduced_modulus_bash: f64,
    /// Hardness H = P_max/A (Pa).
    pub hardness: f64,
    /// Standard error of H (Pa).
    pub hardness_stderr: f64,
    /// Bluntness index of the effective (Galanov) unloading shape,
    /// d = 1/(m − 1) (κ = 1 in (3-26)).
    pub d_unloading: f64,
    /// Standard error of d_unloading, `se(m)/(m − 1)²`.
    pub d_unloading_stderr: f64,
    /// ε used.
    pub epsilon: f64,
    /// β used.
    pub beta: f64,
}

/// The Oliver & Pharr (1992) method on the unloading branch `(depth, load)`,
/// starting at `(peak_depth, peak_load)`: power-law fit ([`fit_unloading`]),
/// `S = α m (h_max − h_f)^{m−1}`, `h_c = h_max − ε P_max/S`, `A = A(h_c)`,
/// `E_r = (√π/2) S/(β√A)`, `H = P_max/A`, with statistical standard errors.
pub fn oliver_pharr(
    depth: &[f64],
    load: &[f64],
    peak_depth: f64,
    peak_load: f64,
    options: &OliverPharrOptions,
) -> Result<OliverPharr> {
    options.area.validate()?;
    let eps = check::positive("epsilon", options.epsilon)?;
    let beta = check::positive("beta", options.beta)?;
    let fit = fit_unloading(depth, load, peak_depth, peak_load, options.window)?;
    let (hmax, pmax) = fit.scales;
    let derived = |t: &[f64; 3]| -> Option<[f64; 4]> {
        let u = 1.0 - t[1];
        if !(u > 0.0) {
            return None;
        }
        // S in scaled units: α′ m u^{m−1}, times P_max/h_max.
        let s = (t[0]).exp() * t[2] * u.powf(t[2] - 1.0) * pmax / hmax;
        let hc = hmax - eps * pmax / s;
        let a = options.area.area(hc).ok()?;
        let er = core::f64::consts::PI.sqrt() / 2.0 * s / (beta * a.sqrt());
        let hard = pmax / a;
        Some([s, hc, er, hard])
    };
    let v = derived(&fit.theta).ok_or(Error::OutOfDomain {
        name: "contact_depth",
        value: hmax,
        reason: "h_c = h_max - eps P_max/S is not positive or outside the area function",
    })?;
    let se = |k: usize| fit.propagate(|t| derived(t).map(|v| v[k])).unwrap_or(0.0);
    let a = options.area.area(v[1])?;
    let m = fit.exponent;
    let d_unl = if m > 1.0 { 1.0 / (m - 1.0) } else { f64::MAX };
    let d_unl_se = if m > 1.0 {
        fit.exponent_stderr / (m - 1.0).powi(2)
    } else {
        f64::MAX
    };
    Ok(OliverPharr {
        peak_load: pmax,
        peak_depth: hmax,
        stiffness: v[0],
        stiffness_stderr: se(0),
        contact_depth: v[1],
        contact_depth_stderr: se(1),
        contact_area: a,
        reduced_modulus: v[2],
        reduced_modulus_stderr: se(2),
        reduced_modulus_bash: v[2] * beta,
        hardness: v[3],
        hardness_stderr: se(3),
        d_unloading: d_unl,
        d_unloading_stderr: d_unl_se,
        epsilon: eps,
        beta,
        fit,
    })
}

// ---------------------------------------------------------------------------
// The whole analysis

/// Options of [`analyze`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IndentationOptions {
    /// Indenter geometry (default Berkovich).
    pub indenter: Indenter,
    /// Area function; `None` uses the indenter's ideal one.
    pub area: Option<AreaFunction>,
    /// Bluntness index when known (a sphere's 2 is taken from the indenter).
    pub known_d: Option<f64>,
    /// Hardening index when known (then d comes from the loading slope).
    pub known_kappa: Option<f64>,
    /// Indenter Young's modulus (Pa), default diamond 1141 GPa.
    pub e_indenter: f64,
    /// Indenter Poisson's ratio, default diamond 0.07.
    pub nu_indenter: f64,
    /// Sample Poisson's ratio (default 0.3).
    pub nu_sample: f64,
    /// β; `None` uses the indenter's (1.05 pyramids, 1 axisymmetric).
    pub beta: Option<f64>,
    /// ε of the contact depth (0.75).
    pub epsilon: f64,
    /// Load window of the loading fit, fractions of the anchor load
    /// (default 0.1–1: the first 10 % of the load, where surface detection and
    /// noise dominate the logarithm, is left out).
    pub loading_window: [f64; 2],
    /// Load window of the unloading fit, fractions of P_max (default 0.25–0.95).
    pub unloading_window: [f64; 2],
    /// Anchor of the loading fit (default the maximum point).
    pub anchor: Anchor,
    /// Use the file's segment labels when present (default true).
    pub use_labels: bool,
}

impl Default for IndentationOptions {
    fn default() -> Self {
        Self {
            indenter: Indenter::Berkovich,
            area: None,
            known_d: None,
            known_kappa: None,
            e_indenter: 1141e9,
            nu_indenter: 0.07,
            nu_sample: 0.3,
            beta: None,
            epsilon: 0.75,
            loading_window: [0.1, 1.0],
            unloading_window: [0.25, 0.95],
            anchor: Anchor::MaxPoint,
            use_labels: true,
        }
    }
}

/// A validity diagnostic (thesis §3.6): a stable code and an explanation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Flag {
    /// Stable code (see [`FLAG_CODES`]).
    pub code: &'static str,
    /// Explanation with the numbers.
    pub message: String,
}

/// Every flag code [`analyze`] can raise, in the order of the C ABI's bit
/// mask (bit i is `FLAG_CODES[i]`).
pub static FLAG_CODES: [&str; 14] = [
    "kappa_negative",
    "kappa_above_one",
    "d_above_three",
    "d_below_one",
    "both_deformable",
    "sharp_indenter",
    "no_unloading",
    "few_points",
    "poor_loading_fit",
    "poor_unloading_fit",
    "area_function_assumed",
    "kappa_poorly_constrained",
    "d_poorly_constrained",
    "modulus_exceeds_indenter",
];

/// Where a parameter came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Source {
    /// Given by the caller.
    Given,
    /// Fixed by the indenter geometry (a sphere's d = 2).
    Indenter,
    /// From the unloading exponent (κ = 1).
    Unloading,
    /// From the loading slope.
    Loading,
}

/// The result of [`analyze`]. Serialises (serde) with the field names the
/// `asperity indent --json` command promises: `kappa`, `kappa_stderr`, `d`,
/// `d_stderr`, `reduced_modulus` (Pa), `hardness` (Pa), `flags` (codes).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IndentationResult {
    /// Hardening index κ.
    pub kappa: f64,
    /// Standard error of κ (0 when given).
    pub kappa_stderr: f64,
    /// Where κ came from.
    pub kappa_source: Source,
    /// Bluntness index d.
    pub d: f64,
    /// Standard error of d (0 when given or fixed by the indenter).
    pub d_stderr: f64,
    /// Where d came from.
    pub d_source: Source,
    /// Reduced modulus E_r (Pa), Oliver–Pharr with β; `None` without unloading.
    pub reduced_modulus: Option<f64>,
    /// Standard error of E_r (Pa).
    pub reduced_modulus_stderr: Option<f64>,
    /// Sample modulus E (Pa) from E_r and the indenter's constants.
    pub sample_modulus: Option<f64>,
    /// Standard error of E (Pa).
    pub sample_modulus_stderr: Option<f64>,
    /// Hardness H = P_max/A(h_c) (Pa).
    pub hardness: Option<f64>,
    /// Standard error of H (Pa).
    pub hardness_stderr: Option<f64>,
    /// Flag codes (see [`FLAG_CODES`]).
    pub flags: Vec<&'static str>,
    /// The flags with their explanations.
    pub flag_details: Vec<Flag>,
    /// Loading log–log fit.
    pub loading: PowerLawFit,
    /// Oliver–Pharr evaluation of the unloading branch.
    pub unloading: Option<OliverPharr>,
    /// The segments used.
    pub segmentation: Segmentation,
    /// The options used.
    pub options: IndentationOptions,
}

impl IndentationResult {
    /// One JSON object (`serde_json`).
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
    }

    /// The flags as a bit mask, bit i for `FLAG_CODES[i]`.
    pub fn flag_mask(&self) -> u32 {
        self.flags
            .iter()
            .filter_map(|c| FLAG_CODES.iter().position(|x| x == c))
            .fold(0, |m, i| m | (1 << i))
    }
}

fn in_range(seg: [usize; 2], n: usize) -> std::ops::Range<usize> {
    seg[0].min(n)..seg[1].min(n)
}

/// Analyse a measured curve: segments, loading slope, Oliver–Pharr on the
/// unloading branch, κ and d with standard errors, E_r, E, H and the validity
/// flags (module docs). Errors: too few points, no loading branch, d or κ not
/// identifiable (no unloading and neither d nor κ known; a cone, d = 1, with κ
/// unknown), invalid options.
pub fn analyze(curve: &Curve, options: &IndentationOptions) -> Result<IndentationResult> {
    let o = options;
    o.indenter.validate()?;
    if let Some(a) = &o.area {
        a.validate()?;
    }
    check::poisson("nu_sample", o.nu_sample)?;
    check::poisson("nu_indenter", o.nu_indenter)?;
    if !(o.e_indenter > 0.0) {
        return Err(Error::InvalidArgument {
            name: "e_indenter",
            value: o.e_indenter,
            bound: "> 0 (+inf for a rigid indenter)",
        });
    }
    check::positive("epsilon", o.epsilon)?;
    if let Some(b) = o.beta {
        check::positive("beta", b)?;
    }
    let w = o.loading_window;
    if !(w[0] >= 0.0 && w[1] <= 1.0 && w[0] < w[1]) {
        return Err(Error::InvalidArgument {
            name: "loading_window",
            value: w[0],
            bound: "0 <= low < high <= 1",
        });
    }
    let uw = o.unloading_window;
    if !(uw[0] >= 0.0 && uw[1] <= 1.0 && uw[0] < uw[1]) {
        return Err(Error::InvalidArgument {
            name: "unloading_window",
            value: uw[0],
            bound: "0 <= low < high <= 1",
        });
    }
    let known_d = match o.known_d {
        Some(d) => Some(check::in_range("known_d", d, 1.0, 100.0, "in [1, 100]")?),
        None => o.indenter.known_d(),
    };
    let known_kappa = match o.known_kappa {
        Some(k) => Some(check::in_range("known_kappa", k, 0.0, 10.0, "in [0, 10]")?),
        None => None,
    };
    if curve.depth.len() != curve.load.len() {
        return Err(Error::InvalidArgument {
            name: "load",
            value: curve.load.len() as f64,
            bound: "as many values as depth",
        });
    }
    for (&h, &p) in curve.depth.iter().zip(&curve.load) {
        check::finite("depth", h)?;
        check::finite("load", p)?;
    }
    let seg = segment(curve, o.use_labels)?;
    let n = curve.len();
    let lr = in_range(seg.loading, n);
    if lr.len() < 3 {
        return Err(Error::OutOfDomain {
            name: "loading_points",
            value: lr.len() as f64,
            reason: "no loading branch (fewer than 3 loading points)",
        });
    }
    let (h, p) = (&curve.depth, &curve.load);
    // Anchor: the maximum point of the loading branch, or a given point.
    let ipk = lr
        .clone()
        .max_by(|&a, &b| p[a].total_cmp(&p[b]))
        .unwrap_or(lr.start);
    let anchor = match o.anchor {
        Anchor::MaxPoint => Some((h[ipk], p[ipk])),
        Anchor::Index { index } => {
            if index >= n {
                return Err(Error::InvalidArgument {
                    name: "anchor_index",
                    value: index as f64,
                    bound: "< number of points",
                });
            }
            Some((h[index], p[index]))
        }
        Anchor::Free => None,
    };
    if let Some((ah, ap)) = anchor {
        if !(ah > 0.0 && ap > 0.0) {
            return Err(Error::OutOfDomain {
                name: "anchor",
                value: ah,
                reason: "the anchor point needs positive depth and load",
            });
        }
    }
    let pref = anchor.map(|a| a.1).unwrap_or(p[ipk]);
    let (lh, lp): (Vec<f64>, Vec<f64>) = lr
        .clone()
        .filter(|&i| p[i] >= w[0] * pref && p[i] <= w[1] * pref * (1.0 + 1e-12))
        .map(|i| (h[i], p[i]))
        .unzip();
    let loading = log_log_fit(&lh, &lp, anchor)?;

    // Unloading.
    let ur = in_range(seg.unloading, n);
    let area = o.area.clone().unwrap_or_else(|| o.indenter.ideal_area());
    let beta = o.beta.unwrap_or_else(|| o.indenter.beta());
    let mut unloading_error = None;
    let unloading = if ur.len() >= 5 {
        // Unloading starts from the point before it (the end of the hold or
        // of loading), or its own first point.
        let start = if ur.start > 0 && p[ur.start - 1] >= p[ur.start] {
            ur.start - 1
        } else {
            ur.start
        };
        let opts = OliverPharrOptions {
            area: area.clone(),
            epsilon: o.epsilon,
            beta,
            window: o.unloading_window,
        };
        match oliver_pharr(&h[ur.clone()], &p[ur.clone()], h[start], p[start], &opts) {
            Ok(r) => Some(r),
            Err(e) => {
                unloading_error = Some(e);
                None
            }
        }
    } else {
        None
    };

    // κ and d.
    let ml = loading.slope;
    let sl = loading.slope_stderr;
    let (kappa, kappa_se, ksrc, d, d_se, dsrc) = match (known_kappa, known_d) {
        (Some(k), Some(d)) => (k, 0.0, Source::Given, d, 0.0, Source::Given),
        (None, Some(d)) => {
            let k = rescaling::kappa_from_loading_slope(ml, d)?;
            let src = if o.known_d.is_some() {
                Source::Given
            } else {
                Source::Indenter
            };
            (k, sl * d / (d - 1.0).abs(), Source::Loading, d, 0.0, src)
        }
        (Some(k), None) => {
            let d = rescaling::d_from_loading_slope(ml, k)?;
            // d = (2 − κ)/(m − κ): |∂d/∂m| = |2 − κ|/(m − κ)².
            let se = sl * (2.0 - k).abs() / (ml - k).powi(2);
            (k, 0.0, Source::Given, d, se, Source::Loading)
        }
        (None, None) => {
            let Some(op) = unloading.as_ref() else {
                return Err(unloading_error.unwrap_or(Error::OutOfDomain {
                    name: "unloading_points",
                    value: ur.len() as f64,
                    reason: "no usable unloading branch: d cannot be found; give known_d or known_kappa",
                }));
            };
            let m = op.fit.exponent;
            let d = rescaling::d_from_unloading_slope(m)?;
            let d_se = op.fit.exponent_stderr / (m - 1.0).powi(2);
            let k = rescaling::kappa_from_loading_slope(ml, d)?;
            let dk_dm = d / (d - 1.0);
            let dk_dd = (2.0 - ml) / (d - 1.0).powi(2);
            let k_se = ((dk_dm * sl).powi(2) + (dk_dd * d_se).powi(2)).sqrt();
            (k, k_se, Source::Loading, d, d_se, Source::Unloading)
        }
    };
    let finite = |name: &'static str, v: f64| -> Result<f64> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(Error::OutOfDomain {
                name,
                value: v,
                reason: "not finite: the slopes do not determine it",
            })
        }
    };
    let kappa = finite("kappa", kappa)?;
    let kappa_se = finite("kappa_stderr", kappa_se)?;
    let d = finite("d", d)?;
    let d_se = finite("d_stderr", d_se)?;

    // Moduli.
    let (er, er_se, es, es_se, hard, hard_se) = match &unloading {
        Some(op) => {
            let es =
                sample_modulus(op.reduced_modulus, o.nu_sample, o.e_indenter, o.nu_indenter).ok();
            let es_se = es.map(|e| {
                // dE/dE_r = (1 − ν²)/(E_r² den²) = E²/((1 − ν²) E_r²).
                let nu2 = 1.0 - o.nu_sample * o.nu_sample;
                e * e / (nu2 * op.reduced_modulus.powi(2)) * op.reduced_modulus_stderr
            });
            (
                Some(op.reduced_modulus),
                Some(op.reduced_modulus_stderr),
                es,
                es_se,
                Some(op.hardness),
                Some(op.hardness_stderr),
            )
        }
        None => (None, None, None, None, None, None),
    };

    // Flags.
    let mut flags: Vec<Flag> = Vec::new();
    let mut flag = |code: &'static str, message: String| flags.push(Flag { code, message });
    if kappa < 0.0 {
        flag("kappa_negative", format!("kappa = {kappa:.3} < 0: the loading branch is flatter than any power-law hardening material gives (thesis 3.5, Goldsmith-Lyman); the rescaling assumptions do not hold"));
    }
    if kappa > 1.0 {
        flag("kappa_above_one", format!("kappa = {kappa:.3} > 1: only materials that densify or harden under pressure (fused silica, TiN) behave so (thesis 3.6.2); for others the indenter shape or the assumptions are at fault"));
    }
    if d > 3.0 {
        flag("d_above_three", format!("d = {d:.3} > 3: an implausibly blunt indenter (thesis 3.6.2); the effective unloading shape includes the imprint (Galanov effect)"));
    }
    if d < 1.0 {
        flag(
            "d_below_one",
            format!("d = {d:.3} < 1: sharper than a cone, outside Galin's solution"),
        );
    }
    if let Some(er) = er {
        if o.e_indenter.is_finite() {
            let share = (1.0 - o.nu_indenter.powi(2)) / o.e_indenter * er;
            if share > 0.1 && (kappa - 1.0).abs() > (2.0 * kappa_se).max(0.05) {
                flag("both_deformable", format!("the indenter carries {:.0} % of the contact compliance while the sample has kappa = {kappa:.3} != 1 (the indenter is linear elastic): the rescaling needs identical materials or a rigid indenter (thesis 3.5)", share * 100.0));
            }
        }
    }
    if o.indenter.is_sharp() {
        flag("sharp_indenter", "a pyramid or cone: a sharp indenter is outside the Hertz assumptions of the rescaling theory (thesis 3.6.2); kappa and d from its curve are not reliable without the real tip shape or the hardening index".to_string());
    }
    if unloading.is_none() {
        let why = match unloading_error {
            Some(e) => format!("no usable unloading branch ({e}): no modulus or hardness"),
            None => format!(
                "no unloading branch ({} points): no modulus or hardness",
                ur.len()
            ),
        };
        flag("no_unloading", why);
    }
    let nu_pts = unloading.as_ref().map(|u| u.fit.n_points);
    if loading.n_points < 10 || nu_pts.is_some_and(|k| k < 8) {
        flag(
            "few_points",
            format!(
                "few points in the fits (loading {}, unloading {}): the standard errors are rough",
                loading.n_points,
                nu_pts.unwrap_or(0)
            ),
        );
    }
    if loading.r_squared < 0.99 {
        flag(
            "poor_loading_fit",
            format!(
                "the loading branch is not a power law (R^2 = {:.4})",
                loading.r_squared
            ),
        );
    }
    if let Some(u) = &unloading {
        if u.fit.r_squared < 0.99 {
            flag(
                "poor_unloading_fit",
                format!(
                    "the unloading branch is not a power law (R^2 = {:.4})",
                    u.fit.r_squared
                ),
            );
        }
    }
    if o.indenter == Indenter::Unknown && o.area.is_none() {
        flag("area_function_assumed", "indenter not documented: the ideal Berkovich area 24.5 h_c^2 and beta = 1.05 were assumed".to_string());
    }
    if kappa_se > 0.25 {
        flag(
            "kappa_poorly_constrained",
            format!("se(kappa) = {kappa_se:.3}: kappa is not determined by this curve"),
        );
    }
    if d_se > 0.25 * d.abs() {
        flag(
            "d_poorly_constrained",
            format!("se(d) = {d_se:.3} for d = {d:.3}"),
        );
    }
    if unloading.is_some() && es.is_none() {
        flag("modulus_exceeds_indenter", "the reduced modulus is not below the indenter's plane-strain modulus: no sample modulus".to_string());
    }
    let codes = flags.iter().map(|f| f.code).collect();
    Ok(IndentationResult {
        kappa,
        kappa_stderr: kappa_se,
        kappa_source: ksrc,
        d,
        d_stderr: d_se,
        d_source: dsrc,
        reduced_modulus: er,
        reduced_modulus_stderr: er_se,
        sample_modulus: es,
        sample_modulus_stderr: es_se,
        hardness: hard,
        hardness_stderr: hard_se,
        flags: codes,
        flag_details: flags,
        loading,
        unloading,
        segmentation: seg,
        options: options.clone(),
    })
}
