//! Building the discrete problem: the options checked and their automatic
//! values filled in, the mesh, the influence matrix and the matrix-free parts
//! (centre row, tail, force quadrature); the solver's accessors.

use super::mesh::Mesh;
use super::{disk, kernels, LjOptions, LjSolver, LjSphere};
use crate::error::{check, Error, Result};
use core::f64::consts::PI;
use std::sync::Arc;

/// Estimate of the JKR contact radius `a/√(Rz₀)` at load `P̄` (an upper bound
/// of the LJ contact radius, used only to size meshes).
pub(super) fn jkr_radius_estimate(mu: f64, force_bar: f64) -> f64 {
    let f = force_bar.max(-1.5);
    let s = f + 3.0 + (6.0 * f + 9.0).max(0.0).sqrt();
    (0.75 * PI * mu.powf(1.5) * s).cbrt()
}

impl LjSolver {
    /// Build the solver: mesh and influence matrix. Errors on invalid options
    /// (`n_grid` in `1..16`, non-positive tolerance, zero iterations, mesh
    /// parameters out of range).
    pub fn new(sphere: &LjSphere, options: LjOptions) -> Result<Self> {
        let mu = sphere.mu;
        let mut o = options;
        if o.n_grid == 0 {
            o.n_grid = sphere.converged_default_grid();
        }
        if o.n_grid < 16 || o.n_grid > 16384 {
            return Err(Error::InvalidArgument {
                name: "n_grid",
                value: o.n_grid as f64,
                bound: "0 (default) or in [16, 16384]",
            });
        }
        check::positive("tolerance", o.tolerance)?;
        if o.max_iterations == 0 {
            return Err(Error::InvalidArgument {
                name: "max_iterations",
                value: 0.0,
                bound: ">= 1",
            });
        }
        check::finite("max_force", o.max_force)?;
        check::non_negative("start_gap", o.start_gap)?;
        if o.start_gap > 0.0 && o.start_gap < 1.5 {
            return Err(Error::InvalidArgument {
                name: "start_gap",
                value: o.start_gap,
                bound: "0 (automatic) or >= 1.5",
            });
        }
        check::non_negative("uniform_radius", o.uniform_radius)?;
        check::non_negative("outer_radius", o.outer_radius)?;
        check::in_range("edge_fraction", o.edge_fraction, 0.0, 0.9, "in [0, 0.9]")?;
        if o.uniform_radius == 0.0 {
            o.uniform_radius = 1.0 + 1.2 * jkr_radius_estimate(mu, o.max_force.max(0.0));
        }
        if o.outer_radius == 0.0 {
            o.outer_radius = (3.0 * o.uniform_radius).max(20.0);
        }
        if o.outer_radius <= o.uniform_radius.min(1.0) || o.outer_radius > 1e4 {
            return Err(Error::InvalidArgument {
                name: "outer_radius",
                value: o.outer_radius,
                bound: "in (min(1, uniform_radius), 1e4]",
            });
        }
        if o.edge_fraction > 0.0 {
            check::non_negative("edge_radius", o.edge_radius)?;
            check::positive("edge_width", o.edge_width)?;
        }
        if o.start_gap == 0.0 {
            // Far enough that the rigid solution is accurate, and (μ > 1)
            // beyond the jump-out approach ≈ −(3/4)π^{2/3}μ (JKR), so that
            // the outer branch spans the hysteresis loop.
            o.start_gap = (6.0 + 4.0 * mu.sqrt()).max(6.0 + 2.0 * mu);
        }
        let n = o.n_grid;
        let mesh = Mesh::new(
            n,
            o.uniform_radius,
            o.outer_radius,
            o.edge_radius,
            o.edge_width,
            o.edge_fraction,
        );
        Self::with_mesh(mu, o, mesh)
    }

    /// The solver on `mesh` (options filled in and checked): its influence
    /// matrix and the rest ([`LjSolver::on_mesh`]).
    pub(super) fn with_mesh(mu: f64, o: LjOptions, mesh: Mesh) -> Result<Self> {
        // Influence matrix, column-major: a[j*n + i] = D(x_i, c_{j+1}) − D(x_i, c_j).
        let a = disk::influence_matrix(&mesh.x, &mesh.c);
        if a.iter().any(|v| !v.is_finite()) {
            return Err(Error::NotConverged {
                what: "LJ sphere influence matrix (elliptic integrals)",
                iterations: 0,
                residual: f64::NAN,
            });
        }
        let a32: Arc<[f32]> = a.iter().map(|&v| v as f32).collect();
        Ok(Self::on_mesh(mu, o, mesh, a.into(), a32, 1.0))
    }

    /// The solver on `mesh` with the influence matrix `scale·a`: the
    /// matrix-free parts (centre row, tail, force quadrature) from the mesh.
    fn on_mesh(
        mu: f64,
        o: LjOptions,
        mesh: Mesh,
        a: Arc<[f64]>,
        a32: Arc<[f32]>,
        scale: f64,
    ) -> Self {
        let n = mesh.x.len();
        let a0: Vec<f64> = (0..n)
            .map(|j| 0.5 * PI * (mesh.c[j + 1] - mesh.c[j]))
            .collect();
        let l = o.outer_radius;
        let t5 = 64.0 / 15.0 / l.powi(5);
        let t7 = 16.0 / 21.0 / l.powi(7);
        let tail = mesh
            .x
            .iter()
            .map(|&x| 0.5 * PI * (t5 + t7 * x * x))
            .collect();
        let tail0 = 0.5 * PI * t5;
        // Force quadrature.
        let g = [
            (-(0.6f64).sqrt(), 5.0 / 9.0),
            (0.0, 8.0 / 9.0),
            ((0.6f64).sqrt(), 5.0 / 9.0),
        ];
        let mut quad = Vec::with_capacity(3 * n);
        for j in 0..n {
            let (lo, hi) = (mesh.c[j], mesh.c[j + 1]);
            let i0 = j.clamp(1, n - 2) - 1;
            let (x0, x1, x2) = (mesh.x[i0], mesh.x[i0 + 1], mesh.x[i0 + 2]);
            for &(t, wt) in &g {
                let r = 0.5 * (lo + hi) + 0.5 * (hi - lo) * t;
                let l0 = (r - x1) * (r - x2) / ((x0 - x1) * (x0 - x2));
                let l1 = (r - x0) * (r - x2) / ((x1 - x0) * (x1 - x2));
                let l2 = (r - x0) * (r - x1) / ((x2 - x0) * (x2 - x1));
                quad.push((0.5 * r * r, 0.5 * (hi - lo) * wt * r, i0, [l0, l1, l2]));
            }
        }
        Self {
            mu,
            k: 4.0 * mu.powf(1.5) / PI,
            opts: o,
            mesh,
            a,
            a32,
            scale,
            a0,
            tail,
            tail0,
            quad,
            family: std::sync::OnceLock::new(),
        }
    }

    /// This solver on its mesh scaled by `s > 0` (nodes, cell edges, the
    /// uniform, outer and band radii and the band width), without new
    /// elliptic integrals: the influence matrix is `s` times this one
    /// (`scale`). `O(N)`.
    pub(super) fn scaled(&self, s: f64) -> LjSolver {
        let mut o = self.opts;
        o.uniform_radius *= s;
        o.outer_radius *= s;
        o.edge_radius *= s;
        o.edge_width *= s;
        let mesh = Mesh {
            x: self.mesh.x.iter().map(|v| v * s).collect(),
            c: self.mesh.c.iter().map(|v| v * s).collect(),
        };
        Self::on_mesh(
            self.mu,
            o,
            mesh,
            self.a.clone(),
            self.a32.clone(),
            self.scale * s,
        )
    }

    /// The options in effect (automatic values filled in).
    pub fn options(&self) -> &LjOptions {
        &self.opts
    }

    /// Tabor parameter μ.
    pub fn tabor(&self) -> f64 {
        self.mu
    }

    /// Collocation nodes `x_j` (units of √(Rz₀)), one per cell.
    pub fn nodes(&self) -> &[f64] {
        &self.mesh.x
    }

    /// Cell edges `c_0 = 0 < … < c_N = L` (units of √(Rz₀)).
    pub fn mesh(&self) -> &[f64] {
        &self.mesh.c
    }

    /// `Σ_j A_ij q_j`: the discrete `∫₀^L q(s) s/(r+s) K(2√(rs)/(r+s)) ds` at
    /// the nodes for the piecewise-constant `q` with values `q_j` on the cells
    /// (the influence matrix applied to `q`; `q.len()` must be N).
    pub fn apply_influence(&self, q: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.n()];
        self.matvec(q, &mut out);
        out
    }

    pub(super) fn n(&self) -> usize {
        self.mesh.x.len()
    }

    /// `out = scale·A q` ([`kernels::matvec`]).
    pub(super) fn matvec(&self, q: &[f64], out: &mut [f64]) {
        kernels::matvec(&self.a, q, self.scale, out);
    }
}
