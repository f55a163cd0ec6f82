//! Contact of the Cantor–Liu and Cantor–Borodich profiles (thesis 5.4.2):
//! a rigid multilevel profile pressed into an elastic Winkler–Fuss
//! foundation (Borodich and Onishchenko) or a rigid-perfectly plastic one
//! (Warren and Krajcinovic 1995), and the normal compliance of the profile's
//! layers as springs in series (Plesha and Ni 2001, (5-13)).
//!
//! # Profile
//!
//! Generation 0 is a block of width w₀ and height h₀. On top of every block
//! of generation k stand p blocks of generation k+1 (p ≥ 2 descendants:
//! Borodich's 2, Warren and Krajcinovic's 3), each r times as wide
//! (p r < 1) and q times as high (0 < q ≤ 1), up to generation n. Cantor–Liu
//! is q = 1 (the same height at every generation: unbounded as n → ∞);
//! Cantor–Borodich is q < 1 (bounded, height h₀/(1 − q)). The tips of the
//! profile form a Cantor set of dimension D = ln p / ln(1/r).
//!
//! # Contact
//!
//! Pressed to the depth δ below its highest tips, the profile touches with
//! every block top lying less than δ deep. The tops of generation k lie at
//! d_k = Σ_{j=k+1}^{n} h₀qʲ below the highest; the contact width (per unit
//! length out of the plane) is A(δ) = (p r)^k w₀ for d_k ≤ δ < d_{k−1}, and
//! on a Winkler foundation of stiffness κ (Pa/m: pressure per unit
//! deflection) the load is
//!
//! $$P(\delta) = \kappa \sum_{k=0}^{n} E_k\,(\delta - d_k)^+,\qquad
//!   E_k = (pr)^k w_0 - (pr)^{k+1} w_0\ (k < n),\quad E_n = (pr)^n w_0,$$
//!
//! the exposed width of the tops of generation k. On a rigid-perfectly
//! plastic foundation of hardness H, P = H A(δ).
//!
//! **Power laws.** For Cantor–Borodich with many generations, d_{k+1} = q d_k
//! and E_{k+1} = p r E_k make the contact self-similar: P(qδ) = p r q P(δ)
//! and A(qδ) = p r A(δ). So, up to log-periodic oscillations,
//!
//! $$A \propto \delta^{\beta},\quad P \propto \delta^{1+\beta},\quad
//!   A \propto P^{\beta/(1+\beta)},\qquad \beta = \frac{\ln(pr)}{\ln q},$$
//!
//! (plastic: P ∝ δ^β, A ∝ P). The exponents depend on the height ratio q
//! as well as on r and p: two profiles of the same fractal dimension contact
//! differently, Borodich and Onishchenko's conclusion that the fractal
//! dimension alone cannot describe the contact. For Cantor–Liu (q = 1)
//! A(δ) grows by 1/(pr) per h₀ of depth and P/A → κ h₀ p r/(1 − p r): the
//! load–area law tends to proportionality.
//!
//! **Series springs (5-13).** With every tip in contact (a flat on Cantor–
//! Liu's equal tips, the layers as columns of modulus E), the layers deflect
//! in series: Δ = P Σ_k h_k/(E A_k), A_k = (pr)^k w₀ per unit length.
//!
//! # References
//!
//! * S. Liu, et al., "Fractal model for contact of rough surfaces" (1986),
//!   as cited by the thesis; F. M. Borodich, A. B. Mosolov, "Fractal
//!   contact of solids", Sov. Phys. Tech. Phys. 36 (1991) 1043–1046.
//! * F. M. Borodich, D. A. Onishchenko, "Similarity and fractality in the
//!   modelling of roughness by a multilevel profile with hierarchical
//!   structure", Int. J. Solids Struct. 36 (1999) 2585–2612.
//! * T. L. Warren, D. Krajcinovic, "Fractal models of elastic-perfectly
//!   plastic contact of rough surfaces based on the Cantor set", Int. J.
//!   Solids Struct. 32 (1995) 2907–2922.
//! * M. E. Plesha, D. Ni, Int. J. Numer. Anal. Meth. Geomech. 25 (2001)
//!   741–756.

use crate::error::{check, Error, Result};

/// The most generations of a profile.
const MAX_GENERATIONS: usize = 200;

/// A Cantor profile (the C ABI's `AsperityCantorProfile`). SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CantorProfile {
    /// Descendants p of every block, in [2, 64].
    pub descendants: u32,
    /// Generations n above the base, in [1, 200].
    pub generations: u32,
    /// Width ratio r of a descendant to its parent, > 0 with p r < 1.
    pub width_ratio: f64,
    /// Height ratio q of a descendant's step to its parent's, in (0, 1]
    /// (1: Cantor–Liu; < 1: Cantor–Borodich).
    pub height_ratio: f64,
    /// Width w₀ of the base block (m), finite and > 0.
    pub base_width: f64,
    /// Height h₀ of the base block's step (m), finite and > 0.
    pub base_height: f64,
}

/// The contact of a profile at one depth (the C ABI's
/// `AsperityCantorContact`). Per unit length out of the plane.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CantorContact {
    /// Depth δ below the highest tips (m).
    pub depth: f64,
    /// Contact width A (m).
    pub width: f64,
    /// Load on a Winkler foundation (N/m), κ Σ E_k (δ − d_k)⁺.
    pub winkler_load: f64,
    /// Load on a rigid-perfectly plastic foundation (N/m), H A.
    pub plastic_load: f64,
}

impl CantorProfile {
    /// Checks the profile; errors name the field.
    pub fn check(&self) -> Result<()> {
        if !(2..=64).contains(&self.descendants) {
            return Err(Error::InvalidArgument {
                name: "descendants",
                value: self.descendants as f64,
                bound: "in [2, 64]",
            });
        }
        if self.generations < 1 || self.generations as usize > MAX_GENERATIONS {
            return Err(Error::InvalidArgument {
                name: "generations",
                value: self.generations as f64,
                bound: "in [1, 200]",
            });
        }
        let r = check::positive("width_ratio", self.width_ratio)?;
        if self.descendants as f64 * r >= 1.0 {
            return Err(Error::InvalidArgument {
                name: "width_ratio",
                value: r,
                bound: "< 1/descendants (the descendants fit side by side)",
            });
        }
        let q = check::positive("height_ratio", self.height_ratio)?;
        if q > 1.0 {
            return Err(Error::InvalidArgument {
                name: "height_ratio",
                value: q,
                bound: "in (0, 1]",
            });
        }
        check::positive("base_width", self.base_width)?;
        check::positive("base_height", self.base_height)?;
        Ok(())
    }

    /// p r: the contact width's ratio from one generation to the next.
    fn pr(&self) -> f64 {
        self.descendants as f64 * self.width_ratio
    }

    /// The fractal dimension D = ln p / ln(1/r) of the profile's tips.
    pub fn fractal_dimension(&self) -> f64 {
        (self.descendants as f64).ln() / (1.0 / self.width_ratio).ln()
    }

    /// β = ln(pr)/ln q of A ∝ δ^β (Cantor–Borodich, q < 1); +∞ for
    /// Cantor–Liu.
    pub fn width_exponent(&self) -> f64 {
        if self.height_ratio == 1.0 {
            f64::INFINITY
        } else {
            self.pr().ln() / self.height_ratio.ln()
        }
    }

    /// The exponent β/(1 + β) of A ∝ P^{β/(1+β)} on a Winkler foundation
    /// (Cantor–Borodich; 1 for Cantor–Liu).
    pub fn load_area_exponent(&self) -> f64 {
        let b = self.width_exponent();
        if b.is_infinite() {
            1.0
        } else {
            b / (1.0 + b)
        }
    }

    /// The depth d_k (m) of the tops of generation k below the highest tips.
    fn top_depth(&self, k: usize) -> f64 {
        let n = self.generations as usize;
        let q = self.height_ratio;
        let h0 = self.base_height;
        // Σ_{j=k+1}^{n} h₀ qʲ = h₀ q^{k+1} (1 − q^{n−k})/(1 − q).
        if q == 1.0 {
            (n - k) as f64 * h0
        } else {
            let m = (n - k) as f64;
            h0 * q.powi(k as i32 + 1) * (-(m * q.ln()).exp_m1()) / (1.0 - q)
        }
    }

    /// The contact at depth `depth` δ (m, finite, ≥ 0) on a Winkler
    /// foundation of stiffness `stiffness` κ (Pa/m, finite, ≥ 0) and a
    /// plastic one of hardness `hardness` H (Pa, finite, ≥ 0). Errors name
    /// the argument (or the profile's field).
    pub fn contact(&self, depth: f64, stiffness: f64, hardness: f64) -> Result<CantorContact> {
        self.check()?;
        let d = check::non_negative("depth", depth)?;
        let kappa = check::non_negative("stiffness", stiffness)?;
        let h = check::non_negative("hardness", hardness)?;
        let n = self.generations as usize;
        let pr = self.pr();
        let (mut width, mut load) = (0.0, 0.0);
        let mut wk = self.base_width * pr.powi(n as i32);
        for k in (0..=n).rev() {
            let dk = self.top_depth(k);
            if dk > d {
                break;
            }
            // Exposed top width of generation k.
            let exposed = if k == n { wk } else { wk * (1.0 - pr) };
            width = wk;
            load += exposed * (d - dk);
            wk /= pr;
        }
        let c = CantorContact {
            depth: d,
            width,
            winkler_load: kappa * load,
            plastic_load: h * width,
        };
        if c.winkler_load.is_finite() && c.plastic_load.is_finite() {
            Ok(c)
        } else {
            Err(Error::OutOfDomain {
                name: "depth",
                value: d,
                reason: "the load overflows",
            })
        }
    }

    /// The Plesha–Ni series compliance Δ/P (m per N/m) of the layers as
    /// columns of modulus `modulus` E (Pa, finite, > 0) with every tip
    /// loaded (5-13): Σ_k h_k/(E A_k), A_k = (pr)^k w₀.
    pub fn series_compliance(&self, modulus: f64) -> Result<f64> {
        self.check()?;
        let e = check::positive("modulus", modulus)?;
        let n = self.generations as usize;
        let ratio = self.height_ratio / self.pr();
        let mut s = 0.0;
        let mut term = self.base_height / (e * self.base_width);
        for _ in 0..=n {
            s += term;
            term *= ratio;
        }
        if s.is_finite() {
            Ok(s)
        } else {
            Err(Error::OutOfDomain {
                name: "generations",
                value: n as f64,
                reason: "the compliance of the finest layers overflows",
            })
        }
    }
}
