//! The real nano-topography model of Bora et al. (2013), thesis §5.3.9: the
//! measured surface as an interface layer of springs, one per point of the
//! height map, standing on an elastic half-space substrate that couples them
//! (Boussinesq), pressed by a rigid flat.
//!
//! The thesis states the model's structure: the springs are uncoupled among
//! themselves, have the heights of the measured topography (AFM), deform only
//! normally and elastically, and the substrate deforms as an elastic
//! half-space under the spring forces; no adhesion. It gives no law for the
//! spring stiffness, so it is an input here (`spring_stiffness` k, N/m, the
//! same for every spring); with no substrate ([`BoraTopography::new`] with
//! `contact_modulus = None`) the model is Kragelsky's independent springs.
//!
//! # Formulas
//!
//! Spring i of top height h_i on the grid point (x_i, y_i) carries
//! `f_i ≥ 0`; its base sinks by the substrate displacement
//! `u_i = Σ_j C_ij f_j`, C_ij the displacement at point i of the half-space
//! (contact modulus E*) under the force of spring j spread uniformly over its
//! grid cell, a square of side Δ (Love's solution,
//! [`crate::friction::square_influence`]). A flat at height d touches
//! spring i when the spring, compressed by `f_i/k` on its sunken base,
//! reaches it:
//!
//! $$g_i = d - h_i + \frac{f_i}{k} + u_i \ge 0, \qquad f_i \ge 0, \qquad f_i\\,g_i = 0,$$
//!
//! the linear complementarity problem of the symmetric positive-definite
//! matrix `M = I/k + C`, solved as the minimum of `½fᵀMf − (h − d)ᵀf` over
//! `f ≥ 0` by the constrained conjugate gradient of Polonsky & Keer (1999) to
//! `max_i |g_i| ≤ 1e-10 · max(h − d)` on the springs that carry load. The
//! load is `P = Σ f_i`, the contact count the number of loaded springs and
//! the real area that count times Δ²; the stiffness `−dP/dd = 1ᵀ M_AA⁻¹ 1`
//! over the loaded set A (a second conjugate-gradient solve).
//!
//! The influence matrix depends only on the grid offset, so it is stored as
//! one coefficient per offset (nx·ny values); a product with it costs
//! (nx·ny)² operations, which bounds the practical map to a few thousand
//! points.
//!
//! # References
//!
//! * Thesis §5.3.9 (and §1.5.4, chapter 6, which reuse the idea).
//! * C. K. Bora, M. E. Plesha, R. W. Carpick (2013), "A numerical contact
//!   model based on real surface topography", Tribol. Lett. 50, 331–347.
//! * I. A. Polonsky, L. M. Keer (1999), "A numerical method for solving rough
//!   contact problems based on the multi-level multi-summation and conjugate
//!   gradient techniques", Wear 231, 206–219.
//! * A. E. H. Love (1929), "The stress produced in a semi-infinite solid by
//!   pressure on part of the boundary", Phil. Trans. R. Soc. A 228, 377–420.

use super::{solve_separation, SeparationSolution};
use crate::error::{check, Error, Result};
use crate::friction::square_influence;

/// Largest number of grid points (the dense products cost n²).
pub const MAX_POINTS: usize = 16_384;
/// Largest number of conjugate-gradient iterations of one solve.
const MAX_ITERATIONS: u32 = 20_000;
/// Relative tolerance on the gaps of the loaded springs.
const TOLERANCE: f64 = 1e-10;

/// The Bora et al. interface on a measured height map.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BoraTopography {
    nx: usize,
    ny: usize,
    spacing: f64,
    heights: Vec<f64>,
    spring_stiffness: f64,
    contact_modulus: Option<f64>,
    /// C(|Δi|, |Δj|) (m/N), index `|Δi| + nx |Δj|`; empty without substrate.
    influence: Vec<f64>,
}

/// The equilibrium at one separation.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BoraSolution {
    /// Total load P (N), ≥ 0.
    pub load: f64,
    /// Real contact area (m²): loaded springs times Δ².
    pub area: f64,
    /// Number of loaded springs.
    pub contacts: usize,
    /// Normal stiffness −dP/dd (N/m), ≥ 0.
    pub stiffness: f64,
    /// Spring forces f_i (N), row-major like the heights.
    pub forces: Vec<f64>,
    /// Conjugate-gradient iterations spent.
    pub iterations: u32,
}

impl BoraTopography {
    /// A map of `nx` × `ny` heights (m, finite, row-major: `heights[i + nx j]`
    /// at x = iΔ, y = jΔ) with grid spacing `spacing` Δ (m, > 0), springs of
    /// stiffness `spring_stiffness` k (N/m, > 0), on a substrate of contact
    /// modulus `contact_modulus` E* (Pa, > 0) or rigid (`None`). For a
    /// profile use `ny = 1` (a row of springs, each on its Δ × Δ cell).
    /// At most [`MAX_POINTS`] points.
    pub fn new(
        nx: usize,
        ny: usize,
        spacing: f64,
        heights: Vec<f64>,
        spring_stiffness: f64,
        contact_modulus: Option<f64>,
    ) -> Result<Self> {
        let n = nx.saturating_mul(ny);
        if nx == 0 || ny == 0 || n > MAX_POINTS {
            return Err(Error::InvalidArgument {
                name: "nx",
                value: n as f64,
                bound: "nx, ny >= 1 and nx*ny <= 16384",
            });
        }
        if heights.len() != n {
            return Err(Error::InvalidArgument {
                name: "heights",
                value: heights.len() as f64,
                bound: "exactly nx*ny values",
            });
        }
        for &h in &heights {
            check::finite("heights", h)?;
        }
        let spacing = check::positive("spacing", spacing)?;
        let k = check::positive("spring_stiffness", spring_stiffness)?;
        let mut influence = Vec::new();
        if let Some(e) = contact_modulus {
            check::positive("contact_modulus", e)?;
            influence.reserve(n);
            for j in 0..ny {
                for i in 0..nx {
                    influence.push(square_influence(
                        i as f64 * spacing,
                        j as f64 * spacing,
                        spacing,
                        e,
                    )?);
                }
            }
        }
        Ok(Self {
            nx,
            ny,
            spacing,
            heights,
            spring_stiffness: k,
            contact_modulus,
            influence,
        })
    }

    /// Number of springs.
    pub fn len(&self) -> usize {
        self.heights.len()
    }
    /// Always false (a map has at least one point).
    pub fn is_empty(&self) -> bool {
        self.heights.is_empty()
    }
    /// The spring heights (m).
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }
    /// The influence coefficient C (m/N) between two springs `a`, `b`
    /// (indices into the heights); 0 without substrate.
    pub fn influence(&self, a: usize, b: usize) -> f64 {
        if self.influence.is_empty() {
            return 0.0;
        }
        let (ia, ja) = (a % self.nx, a / self.nx);
        let (ib, jb) = (b % self.nx, b / self.nx);
        self.influence[ia.abs_diff(ib) + self.nx * ja.abs_diff(jb)]
    }

    /// `out = M v = v/k + C v`.
    fn apply(&self, v: &[f64], out: &mut [f64]) {
        let inv_k = 1.0 / self.spring_stiffness;
        for (o, x) in out.iter_mut().zip(v) {
            *o = inv_k * x;
        }
        if self.influence.is_empty() {
            return;
        }
        let nx = self.nx;
        for (b, &vb) in v.iter().enumerate() {
            if vb == 0.0 {
                continue;
            }
            let (ib, jb) = (b % nx, b / nx);
            for ja in 0..self.ny {
                let row = nx * ja.abs_diff(jb);
                let base = ja * nx;
                for ia in 0..nx {
                    out[base + ia] += self.influence[ia.abs_diff(ib) + row] * vb;
                }
            }
        }
    }

    /// The equilibrium with the flat at `separation` d (m, finite; in the
    /// frame of the heights).
    pub fn solve(&self, separation: f64) -> Result<BoraSolution> {
        let d = check::finite("separation", separation)?;
        let n = self.len();
        let k = self.spring_stiffness;
        let b: Vec<f64> = self.heights.iter().map(|h| h - d).collect();
        let scale = b.iter().fold(0.0f64, |m, x| m.max(*x));
        let mut f: Vec<f64> = b.iter().map(|x| k * x.max(0.0)).collect();
        if scale <= 0.0 {
            return Ok(BoraSolution {
                load: 0.0,
                area: 0.0,
                contacts: 0,
                stiffness: 0.0,
                forces: vec![0.0; n],
                iterations: 0,
            });
        }
        let tol = TOLERANCE * scale;
        if self.influence.is_empty() {
            // Independent springs: f = k max(h − d, 0) is exact.
            return Ok(self.finish(f, 0));
        }
        // Polonsky & Keer (1999), displacement control.
        let mut g = vec![0.0; n];
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        let mut g_old = 1.0;
        let mut delta = 0.0;
        let mut iterations = 0;
        loop {
            self.apply(&f, &mut g);
            for i in 0..n {
                g[i] -= b[i];
            }
            // Converged: loaded springs touch the flat, unloaded ones clear it.
            let worst = (0..n).fold(0.0f64, |m, i| {
                if f[i] > 0.0 {
                    m.max(g[i].abs())
                } else {
                    m.max((-g[i]).max(0.0))
                }
            });
            if worst <= tol {
                break;
            }
            if iterations >= MAX_ITERATIONS {
                return Err(Error::NotConverged {
                    what: "Bora interface equilibrium",
                    iterations,
                    residual: worst / scale,
                });
            }
            iterations += 1;
            let big_g: f64 = (0..n).filter(|&i| f[i] > 0.0).map(|i| g[i] * g[i]).sum();
            for i in 0..n {
                t[i] = if f[i] > 0.0 {
                    g[i] + delta * (big_g / g_old) * t[i]
                } else {
                    0.0
                };
            }
            g_old = big_g.max(f64::MIN_POSITIVE);
            self.apply(&t, &mut r);
            let num: f64 = (0..n).filter(|&i| f[i] > 0.0).map(|i| g[i] * t[i]).sum();
            let den: f64 = (0..n).filter(|&i| f[i] > 0.0).map(|i| r[i] * t[i]).sum();
            let tau = if den > 0.0 { num / den } else { 0.0 };
            let mut overlap = false;
            for i in 0..n {
                if f[i] > 0.0 {
                    f[i] = (f[i] - tau * t[i]).max(0.0);
                } else if g[i] < 0.0 {
                    // An unloaded spring through the flat: load it.
                    let step = if tau > 0.0 {
                        tau
                    } else {
                        1.0 / (1.0 / k + self.influence[0])
                    };
                    f[i] = -step * g[i];
                    overlap = true;
                }
            }
            delta = if overlap { 0.0 } else { 1.0 };
        }
        Ok(self.finish(f, iterations))
    }

    fn finish(&self, forces: Vec<f64>, iterations: u32) -> BoraSolution {
        let contacts = forces.iter().filter(|&&x| x > 0.0).count();
        let load = forces.iter().sum();
        let stiffness = self.stiffness_of(&forces);
        BoraSolution {
            load,
            area: contacts as f64 * self.spacing * self.spacing,
            contacts,
            stiffness,
            forces,
            iterations,
        }
    }

    /// `1ᵀ M_AA⁻¹ 1` over the loaded springs by conjugate gradients.
    fn stiffness_of(&self, forces: &[f64]) -> f64 {
        let n = self.len();
        let active: Vec<bool> = forces.iter().map(|&x| x > 0.0).collect();
        let count = active.iter().filter(|&&a| a).count();
        if count == 0 {
            return 0.0;
        }
        if self.influence.is_empty() {
            return self.spring_stiffness * count as f64;
        }
        let mut s = vec![0.0; n];
        let mut res: Vec<f64> = active.iter().map(|&a| if a { 1.0 } else { 0.0 }).collect();
        let mut p = res.clone();
        let mut q = vec![0.0; n];
        let mut rr: f64 = res.iter().map(|x| x * x).sum();
        let stop = 1e-24 * rr;
        for _ in 0..(4 * count + 50) {
            self.apply(&p, &mut q);
            for i in 0..n {
                if !active[i] {
                    q[i] = 0.0;
                }
            }
            let pq: f64 = p.iter().zip(&q).map(|(a, b)| a * b).sum();
            if pq <= 0.0 {
                break;
            }
            let a = rr / pq;
            for i in 0..n {
                s[i] += a * p[i];
                res[i] -= a * q[i];
            }
            let next: f64 = res.iter().map(|x| x * x).sum();
            if next <= stop {
                break;
            }
            for i in 0..n {
                p[i] = res[i] + (next / rr) * p[i];
            }
            rr = next;
        }
        s.iter().sum()
    }

    /// The separation (m) at which the interface carries `load` (N, finite
    /// and > 0): Newton on ln P with the stiffness, safeguarded by bisection.
    pub fn separation_at_load(&self, load: f64) -> Result<SeparationSolution> {
        let target = check::positive("load", load)?;
        let top = self
            .heights
            .iter()
            .fold(f64::NEG_INFINITY, |m, &h| m.max(h));
        let lo = self.heights.iter().fold(f64::INFINITY, |m, &h| m.min(h));
        let scale = (top - lo).max(self.spacing * 1e-3);
        solve_separation(target, top, scale, Some(top), |d| {
            let s = self.solve(d)?;
            Ok((s.load, -s.stiffness))
        })
    }
}
