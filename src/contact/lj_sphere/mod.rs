//! Numerical Lennard-Jones adhesive sphere: an elastic paraboloid against a
//! flat, interacting through the Lennard-Jones 3-9 surface law under the
//! Derjaguin approximation (Greenwood 1997, Proc. R. Soc. A 453:1277; Feng
//! 2000, Colloids Surf. A 172:175; seed 001, Lee & Chong 2015, Eqs. 1–5;
//! REFERENCE §6).
//!
//! # Formulas
//!
//! Greenwood 1997; Feng 2000; seed 001, Eqs. 1–5; REFERENCE §6. The gap
//! h(r) of the sphere at the rigid approach α (0 when the undeformed apex
//! sits at z₀), the Lennard-Jones 3-9 pressure p (attraction positive), the
//! elastic displacement u and the force P (P > 0 repulsive):
//!
//! $$h(r) = -\alpha + \frac{r^2}{2R} + z_0 + u(r), \qquad p(h) = \frac{8\Delta\gamma}{3z_0}\left(\Bigl(\frac{z_0}{h}\Bigr)^3 - \Bigl(\frac{z_0}{h}\Bigr)^9\right),$$
//!
//! $$u(r) = -\frac{4}{\pi E^\ast}\int_0^\infty p(s)\\,\frac{s}{r+s}\\,K\\!\left(\frac{2\sqrt{rs}}{r+s}\right) ds, \qquad P = -2\pi\int_0^\infty p(r)\\, r\\, dr,$$
//!
//! with $K(k)$ the complete elliptic integral of the first kind of modulus $k$
//! and the Tabor parameter $\mu = \bigl(R\\,\Delta\gamma^2/(E^{\ast 2} z_0^3)\bigr)^{1/3}$.
//! The solver works in $\bar h = h/z_0$, $\bar r = r/\sqrt{R z_0}$,
//! $\bar p = p z_0/\Delta\gamma$ and $\bar\alpha = \alpha/z_0$, where the
//! equations read
//!
//! $$\bar h(\bar r) = -\bar\alpha + \frac{\bar r^2}{2} + 1 + \bar u(\bar r), \qquad \bar p(\bar h) = \frac{8}{3}\left(\bar h^{-3} - \bar h^{-9}\right),$$
//!
//! $$\bar u(\bar r) = -\frac{4\mu^{3/2}}{\pi}\int_0^\infty \bar p(\bar s)\\,\frac{\bar s}{\bar r+\bar s}\\,K\\!\left(\frac{2\sqrt{\bar r\bar s}}{\bar r+\bar s}\right) d\bar s, \qquad \frac{P}{\pi R\\,\Delta\gamma} = -2\int_0^\infty \bar p\\,\bar r\\,d\bar r .$$
//!
//! Rigid limit ($\mu \to 0$), $h_m = 1 - \bar\alpha$:
//!
//! $$\frac{P}{\pi R\\,\Delta\gamma} = -\frac{8}{3}\left(h_m^{-2} - \frac{h_m^{-8}}{4}\right).$$
//!
//! The displacement under a uniform pressure $p$ on a disk of radius $c$
//! (Johnson 1985, §3.4; REFERENCE §6), both branches equal to $c$ at
//! $r = c$:
//!
//! $$u = \frac{4p}{\pi E^\ast}\\,D(r, c), \qquad D(r, c) = \int_0^c \frac{s}{r+s}\\,K\\!\left(\frac{2\sqrt{rs}}{r+s}\right) ds = c\\,E(r/c) \ \ (r \le c), \qquad D(r, c) = r\Bigl(E(c/r) - \bigl(1 - c^2/r^2\bigr)K(c/r)\Bigr) \ \ (r \ge c).$$
//!
//! # Discretisation
//!
//! * **Mesh.** `N` annular cells `[c_j, c_{j+1}]` over `[0, L]`, images of a
//!   uniform grid in `ξ` under the smooth map `ξ = Φ(r)/Φ(L)` with
//!   `Φ(r) = r_f ln(1 + r/r_f) + B w [tanh((r−a_e)/w) + tanh(a_e/w)]`: nearly
//!   uniform spacing up to `r_f` (the region the contact edge sweeps),
//!   geometric growth beyond (the pressure decays as `r̄⁻⁶`), and an optional
//!   concentration of cells (`B > 0`) in a band of width `w` around an
//!   expected contact edge `a_e` (used by the pull-off solver, whose edge
//!   is known in advance). For μ > 1 the curve and the pull-off follow the
//!   contact branch in the radius of its edge zone on meshes whose band
//!   moves with the edge (module `edge`). The collocation node `x_j` of cell `j` is the image
//!   of the cell's `ξ`-midpoint, so the scheme is second order on the smooth
//!   map ([`LjSolver::mesh`]).
//! * **Pressure** piecewise constant on each cell, `p̄_j = p̄(h̄(x_j))`.
//! * **Influence matrix** exact for that pressure: a uniform pressure on a
//!   disk of radius `c` gives the influence `D(r, c)` of *Formulas* (at
//!   `r = c` taken exactly), annuli are differences of disks:
//!   `A_ij = D(x_i, c_{j+1}) − D(x_i, c_j)`. The logarithmic singularity of the
//!   kernel is integrated analytically. `D` is evaluated through the
//!   arithmetic–geometric mean, vectorised over the nodes (module `disk`).
//! * **Tail** beyond `L`: there the gap is `r̄²/2 + C` to high accuracy
//!   (`C = h̄ − r̄²/2` at the last node), so the tail force is added in closed
//!   form, `−2∫_L^∞ p̄ r̄ dr̄ = −(16/3)[H_L⁻²/2 − H_L⁻⁸/8]`, `H_L = L²/2 + C`;
//!   its deformation `−(4μ^{3/2}/π)(π/2)[(64/15)L⁻⁵ + (16/21) r̄² L⁻⁷]`
//!   (leading terms of `K(r/s) ≈ (π/2)(1 + r²/(4s²))` against `p̄ ≈ (64/3)s⁻⁶`) is
//!   included as a fixed vector.
//! * **Force** `−2∫ p̄ r̄ dr̄` by 3-point Gauss–Legendre on every cell, with
//!   `h̄ = w̄(r̄) + r̄²/2` and `w̄ = h̄ − r̄²/2` (the smooth part: constant for a
//!   rigid sphere) interpolated quadratically between nodes, plus the tail.
//!   For a rigid sphere (μ = 0) this reproduces the exact Derjaguin force to
//!   ~1e-12.
//!
//! # Solver
//!
//! Unknowns are the log-gaps `y_i = ln h̄(x_i)` (positivity for free). Two
//! controls:
//!
//! * **central gap** `h̄₀ = h̄(0)` prescribed (the continuation parameter: the
//!   equilibrium is unique in `h̄₀` through the turning points of the
//!   force–approach curve). `ᾱ` is eliminated through `h̄(0) = h̄₀`:
//!   `F_i = h̄_i − h̄₀ − x_i²/2 − (ū_i − ū_0) = 0`, then `ᾱ = 1 + ū_0 − h̄₀`;
//! * **approach** `ᾱ` prescribed: `F_i = h̄_i + ᾱ − x_i²/2 − 1 − ū_i = 0`
//!   (unique only on stable branches).
//!
//! Newton's method with the dense Jacobian
//! `J_ij = δ_ij h̄_i + (4μ^{3/2}/π)(A_ij − [a₀_j]) p̄'(h̄_j) h̄_j` factored by
//! faer's partial-pivoting LU, steps capped at 0.5 in `ln h̄` and a
//! backtracking line search on `‖F‖₂`. Single solves
//! ([`LjSolver::solve_at_central_gap`], [`LjSolver::solve_at_approach`])
//! refactor every iteration (quadratic convergence); [`LjSolver::sweep`]
//! keeps the factorisation while the iteration contracts by at least 4× per
//! step and refactors otherwise (chord–Newton). The residual is the max-norm
//! of `F` in units of z₀; a solve stops below [`LjOptions::tolerance`] or
//! returns [`Error::NotConverged`](crate::error::Error::NotConverged) with its iterations and residual, never a
//! wrong number.
//!
//! # Pseudo-arclength continuation
//!
//! [`LjSolver::curve`] and [`LjSolver::pull_off_with`] follow the path in
//! the unknowns `X = (y, ᾱ)` with one extra equation, the hyperplane
//! `⟨T_k, X − X_k⟩_M = σ` normal to the unit tangent `T_k` of the last point
//! (metric `M`: weight `1/N` on each log-gap, 1 on ᾱ). The bordered
//! `(N+1)×(N+1)` system `[J 1; (M T_k)ᵀ]` is regular through the folds of
//! both ᾱ (jump-in, jump-out) and h̄₀, and is factored by faer's LU; the
//! factorisation is reused across steps and the border row of the current
//! step, which differs from the factored one, is applied by a rank-one
//! Sherman–Morrison correction (one extra dot product per solve). With a
//! stale factorisation each Newton correction is an inexact-Newton step:
//! GMRES on the true bordered Jacobian, right-preconditioned by the stored
//! LU, to a relative residual of 1e-3 (each GMRES iteration is one `O(N²)`
//! product and one triangular solve; an LU costs about 60 of them at
//! N = 256). The factorisation is refreshed when a Newton solve needed more
//! than 3 GMRES iterations, or a line search. The tangent solves
//! `[J 1; (M T_k)ᵀ] T = e_{N+1}` the same way, to 1e-4 relative for the
//! predictor and 1e-9 at special points. The predictor is the cubic Hermite
//! extrapolation through the last two points with their tangents. The step `σ` adapts to a target distance in the scaled
//! `(ᾱ, P̄, h̄₀)` plane (about [`LjOptions::target_points`] points) and to a
//! largest log-gap change of 0.1 per step. Special points — turning points
//! of ᾱ (`dᾱ/ds = 0`) and the force minimum (`dP̄/ds = 0`, the derivative by
//! central differences along the exact tangent) — are roots along the path,
//! refined by the Illinois method in the step length from the bracketing
//! sample, with exact (refined) tangents from the current factorisation.
//!
//! # The curve
//!
//! [`LjSolver::curve`] starts far from the surface (where the rigid solution
//! is an excellent guess, at prescribed h̄₀) and follows the path by
//! pseudo-arclength continuation until `P̄ ≥` [`LjOptions::max_force`] (the
//! Hertz regime). Turning points of ᾱ along the path are the jump-in (local
//! maximum of ᾱ: the approach can increase no further on the outer branch)
//! and jump-out (local minimum: on retraction the contact branch ends); both
//! and the load-controlled pull-off (minimum of `P̄`) are refined as roots of
//! `dᾱ/ds` and `dP̄/ds`. The hysteresis energy is the area of the
//! displacement-controlled loop (outer
//! branch up to the jump-in, jump at fixed ᾱ, contact branch back down to the
//! jump-out, jump back), `∮ P̄ dᾱ` in units of `πRΔγ z₀`.
//!
//! # References
//!
//! * J. A. Greenwood (1997), "Adhesion of elastic spheres", Proc. R. Soc. Lond.
//!   A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070).
//! * J. Q. Feng (2000), "Contact behavior of spherical elastic particles: a
//!   computational study of particle adhesion and deformations", Colloids
//!   Surf. A 172, 175–198.
//! * W. G. Lee, W. W. F. Chong (2015), "Adhesive contact modelling based on
//!   Lennard-Jones force law", Jurnal Teknologi 76(10) (seed 001), Eqs. 1–5.
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   §3.4, [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731)
//!   (the uniformly loaded disk).
//! * D. Tabor (1977), "Surface forces and surface interactions", J. Colloid
//!   Interface Sci. 58, 2–13 (the parameter μ).
//! * Y. Saad, M. H. Schultz (1986), "GMRES: a generalized minimal residual
//!   algorithm for solving nonsymmetric linear systems", SIAM J. Sci. Stat.
//!   Comput. 7, 856–869; E. L. Allgower, K. Georg (1990), *Numerical
//!   Continuation Methods*, Springer (pseudo-arclength continuation).

// Index loops mirror the matrix algebra; options are built by field
// assignment (documented pattern); NaN-aware `!(x < y)` is intended.
#![allow(
    clippy::needless_range_loop,
    clippy::field_reassign_with_default,
    clippy::neg_cmp_op_on_partial_ord
)]

use crate::error::{check, Result};
use core::f64::consts::PI;
use std::sync::Arc;

// The solver, one role per file: `setup` builds the discrete problem on a
// `mesh`, `newton` solves one equilibrium and `observe` reads its force and
// contact radius; `marcher` continues in h̄₀ or ᾱ; `march` drives the
// pseudo-arclength continuation of `path`, `special` refines its turning
// points and force minimum and `curve` assembles the curve; `edge` follows
// the edge zone in its marker; `pull_off` and `sample` build on these;
// `disk`, `kernels`, `lu32` and `numeric` are the numerical building blocks.
mod curve;
mod disk;
mod edge;
mod kernels;
mod lu32;
mod march;
mod marcher;
mod mesh;
mod newton;
mod numeric;
mod observe;
mod path;
mod pull_off;
mod sample;
mod setup;
mod special;
pub use disk::disk_displacement;
use mesh::Mesh;
pub use sample::LjPathSamples;

/// `(8/3)` of the Lennard-Jones 3-9 law.
const LJ_C: f64 = 8.0 / 3.0;

/// Non-dimensional Lennard-Jones pressure `p̄(h̄) = (8/3)[h̄⁻³ − h̄⁻⁹]`
/// (attraction positive) and its derivative `dp̄/dh̄`.
#[inline]
pub fn lj_pressure(h: f64) -> (f64, f64) {
    let i = 1.0 / h;
    let i3 = i * i * i;
    let i9 = i3 * i3 * i3;
    (LJ_C * (i3 - i9), LJ_C * (-3.0 * i3 + 9.0 * i9) * i)
}

/// Rigid-sphere (μ → 0) force of the Lennard-Jones 3-9 law under the
/// Derjaguin approximation, `P/(πRΔγ) = −(8/3)[h_m⁻² − h_m⁻⁸/4]` with
/// `h_m = 1 − ᾱ` the minimum gap in units of z₀ (REFERENCE §6).
pub fn rigid_force_bar(approach_bar: f64) -> f64 {
    let hm = 1.0 - approach_bar;
    -LJ_C * (hm.powi(-2) - 0.25 * hm.powi(-8))
}

/// A Lennard-Jones adhesive elastic sphere (dimensional parameters, SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LjSphere {
    /// Sphere radius R (m).
    pub radius: f64,
    /// Contact modulus E* (Pa); infinite for a rigid sphere.
    pub e_star: f64,
    /// Work of adhesion Δγ (J/m²).
    pub work_of_adhesion: f64,
    /// Equilibrium separation z₀ (m).
    pub z0: f64,
    /// Tabor parameter μ (dimensionless), cached.
    mu: f64,
}

impl LjSphere {
    /// A sphere of radius R (m), contact modulus E* (Pa), work of adhesion
    /// Δγ (J/m²) and Lennard-Jones equilibrium separation z₀ (m), all finite and
    /// positive. μ = [`crate::material::tabor_parameter`]; it must lie in
    /// `[0, 100]` (above, the edge zone of width ~μ^{-3/2}√(Rz₀) needs more
    /// cells than a dense solver should hold — use JKR).
    pub fn new(radius: f64, e_star: f64, work_of_adhesion: f64, z0: f64) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        let e = check::positive("e_star", e_star)?;
        let w = check::positive("work_of_adhesion", work_of_adhesion)?;
        let z = check::positive("z0", z0)?;
        let mu = crate::material::tabor_parameter(r, w, e, z)?;
        let mu = check::in_range("tabor_parameter", mu, 0.0, 100.0, "in [0, 100]")?;
        Ok(Self {
            radius: r,
            e_star: e,
            work_of_adhesion: w,
            z0: z,
            mu,
        })
    }

    /// The dimensionless sphere with Tabor parameter `mu` ∈ [0, 100]: unit
    /// radius, work of adhesion and z₀, `E* = μ^{-3/2}` (infinite, i.e. rigid,
    /// for μ = 0). Forces are then `π P̄`, approaches `ᾱ`.
    pub fn from_tabor(mu: f64) -> Result<Self> {
        let mu = check::in_range("mu", mu, 0.0, 100.0, "in [0, 100]")?;
        Ok(Self {
            radius: 1.0,
            e_star: if mu > 0.0 {
                mu.powf(-1.5)
            } else {
                f64::INFINITY
            },
            work_of_adhesion: 1.0,
            z0: 1.0,
            mu,
        })
    }

    /// Tabor parameter `μ = (RΔγ²/(E*²z₀³))^{1/3}`.
    #[inline]
    pub fn tabor(&self) -> f64 {
        self.mu
    }

    /// Force unit `πRΔγ` (N): `P = P̄ πRΔγ`.
    #[inline]
    pub fn force_scale(&self) -> f64 {
        PI * self.radius * self.work_of_adhesion
    }

    /// Radius unit `√(Rz₀)` (m).
    #[inline]
    pub fn radius_scale(&self) -> f64 {
        (self.radius * self.z0).sqrt()
    }

    /// Energy unit `πRΔγ z₀` (J) of [`LjCurve::hysteresis_energy`].
    #[inline]
    pub fn energy_scale(&self) -> f64 {
        self.force_scale() * self.z0
    }

    /// The grid size the library calls converged: `N = 256` for μ ≤ 3, 512 up
    /// to μ = 10, 1024 beyond. With the pull-off mesh this gives the
    /// load-controlled pull-off to about 1e-5 relative for μ ≤ 3 (see the
    /// convergence study in `examples/lj_convergence.rs` and BENCHMARKS.md:
    /// the error falls as N⁻²); the edge zone narrows as μ^{-3/2}, hence the
    /// larger grids at large μ.
    pub fn converged_default_grid(&self) -> usize {
        if self.mu <= 3.0 {
            256
        } else if self.mu <= 10.0 {
            512
        } else {
            1024
        }
    }

    /// A solver with the default options for `n_grid` cells (≥ 16; 0 means
    /// [`LjSphere::converged_default_grid`]) and the curve mesh.
    pub fn solver(&self, n_grid: usize) -> Result<LjSolver> {
        let mut o = LjOptions::default();
        o.n_grid = n_grid;
        LjSolver::new(self, o)
    }

    /// Load-controlled pull-off force (N, negative: tensile) on `n_grid` cells
    /// (0 = converged default), via [`LjSolver::pull_off_with`].
    pub fn pull_off_force(&self, n_grid: usize) -> Result<f64> {
        Ok(self.pull_off(n_grid)?.force * self.force_scale())
    }

    /// Load-controlled pull-off, dimensionless, with its solve statistics.
    pub fn pull_off(&self, n_grid: usize) -> Result<LjPullOff> {
        let mut o = LjOptions::default();
        o.n_grid = n_grid;
        LjSolver::pull_off_with(self, o)
    }
}

/// Options of the solver. Build with `LjOptions::default()` and change fields.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LjOptions {
    /// Number of radial cells N (≥ 16); 0 = [`LjSphere::converged_default_grid`].
    pub n_grid: usize,
    /// Newton tolerance on the max-norm of the gap residual (units of z₀),
    /// relative to the gap where the gap exceeds z₀: far nodes, where
    /// `h̄ ≈ r̄²/2` reaches 10⁶ on the edge continuation's scaled meshes,
    /// cannot be solved to 1e-10 z₀ in double precision, and there the
    /// pressure does not depend on the gap to that accuracy.
    pub tolerance: f64,
    /// Iteration cap of one solve.
    pub max_iterations: u32,
    /// The curve stops once `P/(πRΔγ)` reaches this compressive load.
    pub max_force: f64,
    /// Central gap `h̄₀` (units of z₀) the curve starts from; 0 = automatic
    /// (`max(6 + 4√μ, 6 + 2μ)`: the rigid solution is accurate there, and
    /// it lies beyond the jump-out approach).
    pub start_gap: f64,
    /// Target number of points of the curve (the arc-length step is chosen
    /// for it; the actual count is within a few tens of per cent).
    pub target_points: usize,
    /// Mesh: radius `r_f` (units of √(Rz₀)) of the nearly uniform region; 0 =
    /// automatic (covers the contact radius at `max_force`).
    pub uniform_radius: f64,
    /// Mesh: outer radius L (units of √(Rz₀)); 0 = automatic (`max(20, 3 r_f)`).
    pub outer_radius: f64,
    /// Mesh: expected contact-edge radius `a_e` of the concentrated band;
    /// ignored unless `edge_fraction > 0`.
    pub edge_radius: f64,
    /// Mesh: half-width `w` of the concentrated band.
    pub edge_width: f64,
    /// Mesh: fraction of the cells in the band (0 = no band, < 0.9).
    pub edge_fraction: f64,
}

impl Default for LjOptions {
    fn default() -> Self {
        Self {
            n_grid: 0,
            tolerance: 1e-10,
            max_iterations: 50,
            max_force: 10.0,
            start_gap: 0.0,
            target_points: 250,
            uniform_radius: 0.0,
            outer_radius: 0.0,
            edge_radius: 0.0,
            edge_width: 0.0,
            edge_fraction: 0.0,
        }
    }
}

/// One equilibrium, dimensionless.
#[derive(Debug, Clone, PartialEq)]
pub struct LjSolution {
    /// Central gap `h̄₀ = h(0)/z₀`.
    pub central_gap: f64,
    /// Approach `ᾱ = α/z₀`.
    pub approach: f64,
    /// Force `P/(πRΔγ)`, positive repulsive.
    pub force: f64,
    /// Contact radius `a/√(Rz₀)`: where the pressure changes sign (repulsive
    /// inside), 0 if it is attractive everywhere.
    pub contact_radius: f64,
    /// Gap `h̄` at the nodes [`LjSolver::nodes`].
    pub gap: Vec<f64>,
    /// Pressure `p̄ = p z₀/Δγ` at the nodes (attraction positive).
    pub pressure: Vec<f64>,
    /// Newton iterations spent.
    pub iterations: u32,
    /// Final residual (max-norm, units of z₀).
    pub residual: f64,
}

/// A point of the force–approach curve, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LjPoint {
    /// Central gap `h̄₀` (the continuation parameter).
    pub central_gap: f64,
    /// Approach `ᾱ`.
    pub approach: f64,
    /// Force `P/(πRΔγ)`.
    pub force: f64,
    /// Contact radius `a/√(Rz₀)` (see [`LjSolution::contact_radius`]).
    pub contact_radius: f64,
    /// `dP̄/dᾱ` along the curve (3-point finite differences in `h̄₀`; infinite
    /// magnitude at a turning point, negative on the unstable branch).
    pub stiffness: f64,
    /// `dᾱ/ds` along the continuation's unit tangent (`s` the pseudo-arclength
    /// of [`LjSolver::curve`], metric `1/N` on each log-gap and 1 on ᾱ): 0 at
    /// a turning point, negative on the unstable branch; NaN when not computed
    /// (points of [`LjSolver::sweep`]).
    pub d_approach: f64,
    /// `dP̄/ds` along the same tangent (central differences along the exact
    /// tangent); NaN when not computed.
    pub d_force: f64,
    /// `d(contact radius)/ds` along the same tangent (0 out of contact); NaN
    /// when not computed.
    pub d_radius: f64,
}

/// The force–approach curve and its characteristic points.
#[derive(Debug, Clone, PartialEq)]
pub struct LjCurve {
    /// Points by decreasing central gap (approach, then into contact).
    pub points: Vec<LjPoint>,
    /// Jump-in (local maximum of ᾱ along decreasing h̄₀), if the curve is
    /// S-shaped.
    pub jump_in: Option<LjPoint>,
    /// Jump-out (the following local minimum of ᾱ), if the curve is S-shaped.
    pub jump_out: Option<LjPoint>,
    /// Load-controlled pull-off: the point of minimum force along the
    /// path. On a grid that resolves the edge zone the force along the
    /// contact branch has one minimum. Where it does not (μ = 10 at N = 256,
    /// BENCHMARKS.md §3) the discrete branch has shallow extra minima of up
    /// to 1e-2; this reports the lowest of those the path's samples
    /// bracket, while a table of the same grid pulls off at the last one
    /// (the first met lowering the load from deep contact). The spread is
    /// the discretisation error: raise `n_grid`.
    pub pull_off_load: LjPoint,
    /// Displacement-controlled pull-off force `P/(πRΔγ)` (at the jump-out);
    /// `None` when the curve is not S-shaped (separation is then continuous).
    pub pull_off_displacement: Option<f64>,
    /// Hysteresis energy of an approach–retract cycle under displacement
    /// control, in units of `πRΔγ z₀` ([`LjSphere::energy_scale`]); 0 without
    /// S-shape.
    pub hysteresis_energy: f64,
    /// Newton iterations over all solves.
    pub iterations: u64,
    /// LU factorisations over all solves.
    pub factorizations: u64,
    /// Largest final residual of the solves (units of z₀).
    pub max_residual: f64,
    /// Grid size N.
    pub n_grid: usize,
}

/// Load-controlled pull-off, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LjPullOff {
    /// `P/(πRΔγ)` (negative).
    pub force: f64,
    /// Approach `ᾱ` at pull-off.
    pub approach: f64,
    /// Central gap `h̄₀` at pull-off.
    pub central_gap: f64,
    /// Contact radius `a/√(Rz₀)` at pull-off.
    pub contact_radius: f64,
    /// Newton iterations over all solves.
    pub iterations: u64,
    /// Largest final residual (units of z₀).
    pub max_residual: f64,
    /// Grid size N.
    pub n_grid: usize,
}

/// The discretised problem for one sphere and one mesh: the influence matrix
/// is built once ([`LjSolver::new`], `O(N²)` elliptic integrals); every solve
/// reuses it.
pub struct LjSolver {
    mu: f64,
    /// `4μ^{3/2}/π`.
    k: f64,
    opts: LjOptions,
    mesh: Mesh,
    /// Influence matrix, column-major n×n, up to the factor `scale`
    /// (shared by the solvers [`LjSolver::scaled`] from one another).
    a: Arc<[f64]>,
    /// The influence matrix rounded to `f32`, for the continuation's
    /// single-precision Jacobian products (`path` module docs).
    a32: Arc<[f32]>,
    /// The factor of `a`: the displacement `D(r, c)` of a loaded disk is
    /// homogeneous of degree 1, so the mesh scaled by `s` has the influence
    /// matrix `s·a` ([`LjSolver::scaled`]). 1 for a solver from [`LjSolver::new`].
    scale: f64,
    /// Influence row at r = 0.
    a0: Vec<f64>,
    /// Tail deformation factor at the nodes (times −k gives ū_tail).
    tail: Vec<f64>,
    /// Tail deformation factor at r = 0.
    tail0: f64,
    /// Gauss points of the force: per cell 3 points (consecutive), each
    /// with `r̄²/2`, weight·r̄, and the quadratic interpolation (node index
    /// i0, the same for the cell's 3 points, and the 3 Lagrange weights).
    quad: Vec<(f64, f64, usize, [f64; 3])>,
    /// The edge continuation's solver at the switch marker, built on first
    /// use ([`LjSolver::family`]); every edge-phase solver is it scaled.
    family: std::sync::OnceLock<Box<LjSolver>>,
}
