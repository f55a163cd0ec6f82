//! Choosing the fidelity a scene needs.
//!
//! Six models describe an elastic sphere with short-range adhesion, from the
//! cheapest to the most faithful: [`Dmt`], [`Jkr`], [`MaugisDugdale`] (Dugdale
//! stress = the Lennard-Jones theoretical stress), a
//! [`TabulatedLaw`] of Maugis–Dugdale, a [`TabulatedLaw`] of the numerical
//! Lennard-Jones sphere, and the numerical [`LjSphere`] itself (Greenwood
//! 1997; seed 001). [`assess`] measures, for one sphere, each model's error
//! against the converged Lennard-Jones solution and its cost per call;
//! [`advise`] returns the cheapest one whose error is within a force
//! tolerance.
//!
//! **Errors** are absolute forces (N), as in *Formulas*:
//! * `pull_off_error`: the difference of the load-controlled pull-offs;
//! * `curve_error`: the largest force difference over a displacement-controlled
//!   approach from far away (−50 z₀) to deep contact (P ≈ 10 πRw) and back,
//!   each model keeping its own hysteresis state. Near a jump the models'
//!   jumps fall at different approaches, and the difference there is part of
//!   the error, as it is for a host code that uses the model.
//!
//! The pull-off reference is the solver's load-controlled pull-off on the
//! library's converged grid ([`LjSphere::converged_default_grid`]: N = 256
//! for μ ≤ 3, 512 up to μ = 10). The curve reference is the Lennard-Jones
//! curve on N = 128 radial cells for μ ≤ 1 and 256 above (above μ = 1 the
//! edge continuation on meshes that move with the contact edge), evaluated
//! through its table (within 1e-4 relative of the solver on that grid; on
//! N = 128 at μ = 1 the grid itself is 4e-4 πRw from the converged
//! pull-off, BENCHMARKS.md §4), so
//! curve errors below about 1e-4·πRw are not resolved; at μ = 10 and 30
//! the pull-off itself is known to about 2e-4 πRw (BENCHMARKS.md §3). The tabulated Lennard-Jones model is that
//! table, so its pull-off error is its grid's. The full Lennard-Jones model
//! is the solver on the converged grid. **Cost** is measured on this machine when [`assess`] runs (time
//! per `eval`, median of repeated passes over the path); the choice itself
//! uses the fixed cost order of [`Fidelity::ALL`], so it does not depend on
//! timing noise.
//!
//! # Formulas
//!
//! $$e_\mathrm{pull\text{-}off} = \bigl\lvert P_c^\mathrm{model} - P_c^\mathrm{LJ}\bigr\rvert, \qquad e_\mathrm{curve} = \max_{\delta\ \text{on the path}}\bigl\lvert P^\mathrm{model}(\delta) - P^\mathrm{LJ}(\delta)\bigr\rvert,$$
//!
//! with the Maugis–Dugdale stress $\sigma_0 = 16w/(9\sqrt3\\, z_0)$, so that
//! $\lambda = 1.157\\,\mu$, $\mu = (Rw^2/(E^{\ast 2}z_0^3))^{1/3}$.
//!
//! # References
//!
//! * B. V. Derjaguin, V. M. Muller, Yu. P. Toporov (1975), J. Colloid Interface
//!   Sci. 53, 314–326,
//!   [doi:10.1016/0021-9797(75)90018-1](https://doi.org/10.1016/0021-9797(75)90018-1).
//! * K. L. Johnson, K. Kendall, A. D. Roberts (1971), Proc. R. Soc. Lond. A 324,
//!   301–313, [doi:10.1098/rspa.1971.0141](https://doi.org/10.1098/rspa.1971.0141).
//! * D. Maugis (1992), J. Colloid Interface Sci. 150, 243–269,
//!   [doi:10.1016/0021-9797(92)90285-T](https://doi.org/10.1016/0021-9797(92)90285-T).
//! * J. A. Greenwood (1997), Proc. R. Soc. Lond. A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070).
//! * W. G. Lee, W. W. F. Chong (2015), Jurnal Teknologi 76(10) (seed 001).
//! * Thesis (1-41)–(1-44).

use crate::contact::{
    ContactState, Control, Dmt, Jkr, LjSphere, MaugisDugdale, NormalContact, TabulatedLaw,
};
use crate::error::{check, Error, Result};
use std::time::Instant;

/// The models the advisor weighs, in order of cost per call.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Fidelity {
    /// [`Dmt`]: Hertz plus a constant adhesive force, a few arithmetic
    /// operations per call.
    Dmt,
    /// [`TabulatedLaw`] of Maugis–Dugdale: an interpolation per call in a
    /// table built once.
    TabulatedMaugisDugdale,
    /// [`TabulatedLaw`] of the Lennard-Jones sphere: an interpolation per
    /// call in a table built once.
    TabulatedLennardJones,
    /// [`Jkr`]: closed form, the root of a quartic per call.
    Jkr,
    /// [`MaugisDugdale`]: root finding per call.
    MaugisDugdale,
    /// The numerical [`LjSphere`]: a Newton solve of the discretised
    /// surface per call, orders of magnitude dearer than the others.
    LennardJones,
}

impl Fidelity {
    /// Every model, cheapest per call first.
    pub const ALL: [Fidelity; 6] = [
        Fidelity::Dmt,
        Fidelity::TabulatedMaugisDugdale,
        Fidelity::TabulatedLennardJones,
        Fidelity::Jkr,
        Fidelity::MaugisDugdale,
        Fidelity::LennardJones,
    ];

    /// A short name.
    pub fn name(self) -> &'static str {
        match self {
            Fidelity::Dmt => "DMT",
            Fidelity::TabulatedMaugisDugdale => "tabulated Maugis-Dugdale",
            Fidelity::TabulatedLennardJones => "tabulated Lennard-Jones",
            Fidelity::Jkr => "JKR",
            Fidelity::MaugisDugdale => "Maugis-Dugdale",
            Fidelity::LennardJones => "Lennard-Jones (full)",
        }
    }
}

/// One model measured against the converged Lennard-Jones sphere.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Assessment {
    /// The model.
    pub law: Fidelity,
    /// |P_c,model − P_c,LJ| (N), load-controlled pull-off.
    pub pull_off_error: f64,
    /// Largest force difference over the approach–retraction path (N).
    pub curve_error: f64,
    /// Time per evaluation on this machine (s).
    pub cost_per_call: f64,
    /// One-time construction time (s): building a table, or 0.
    pub build_time: f64,
}

/// The advisor's answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Advice {
    /// The cheapest model within the tolerance (the full Lennard-Jones sphere
    /// when nothing cheaper is).
    pub choice: Fidelity,
    /// The chosen model's measurements.
    pub chosen: Assessment,
    /// Every model's measurements, in the order of [`Fidelity::ALL`].
    pub assessments: Vec<Assessment>,
    /// Tabor parameter μ of the sphere.
    pub tabor: f64,
    /// Load-controlled pull-off of the converged solver (N), the yardstick
    /// of the pull-off errors.
    pub reference_pull_off: f64,
    /// Grid of that solver ([`LjSphere::converged_default_grid`]).
    pub reference_grid: usize,
}

/// Tolerance of the Lennard-Jones table used as the yardstick (its stated
/// maximum relative error against the solver); also the tabulated
/// Lennard-Jones model's, so that table is the reference itself.
const REFERENCE_TOLERANCE: f64 = crate::contact::tabulated::DEFAULT_TOLERANCE;

/// Grid of the curve reference (the table): N = 128 resolves the curve to
/// ~1e-4 relative for μ ≤ 1 (the convergence study in BENCHMARKS.md);
/// above, the moving edge band needs N = 256.
fn table_grid(mu: f64) -> usize {
    if mu <= 1.0 {
        128
    } else {
        256
    }
}

/// Measure every model for a sphere of radius R (m), contact modulus E* (Pa),
/// work of adhesion w (J/m²) and Lennard-Jones equilibrium separation z₀ (m)
/// (Tabor parameter in the Lennard-Jones solver's range, [0, 100]). Returns
/// the assessments in the order of [`Fidelity::ALL`], the reference pull-off
/// (N) and its grid (the converged one). Builds the Lennard-Jones reference
/// table: about a second for μ ≤ 1, up to a minute above (N = 256 on moving
/// meshes, see [`crate::contact::lj_sphere::LjSolver::path_samples`]); above
/// μ = 10 the converged pull-off (N = 1024) adds a minute or more.
pub fn assess(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    z0: f64,
) -> Result<(Vec<Assessment>, f64, usize)> {
    let lj = LjSphere::new(radius, e_star, work_of_adhesion, z0)?;
    let grid = table_grid(lj.tabor());
    let t = Instant::now();
    let reference = TabulatedLaw::from_lj_sphere(&lj, grid, REFERENCE_TOLERANCE)?;
    let reference_build = t.elapsed().as_secs_f64();
    // The pull-off yardstick is the solver on the library's converged grid
    // (finer than the table's: N = 256 against 128 for μ ≤ 1, 512 against
    // 256 for 3 < μ ≤ 10, where the table's grid leaves wiggles of up to
    // 1e-2 πRw in the force along the contact branch).
    let converged = lj.converged_default_grid();
    let p_ref = lj.pull_off_force(converged)?;
    let path = sweep_path(&reference, z0)?;
    let f_ref = forces_along(&reference, &path)?;

    let mut out = Vec::with_capacity(Fidelity::ALL.len());
    for law in Fidelity::ALL {
        let a = match law {
            Fidelity::Dmt => measure(
                law,
                &Dmt::new(radius, e_star, work_of_adhesion)?,
                0.0,
                &path,
                &f_ref,
                p_ref,
            )?,
            Fidelity::Jkr => measure(
                law,
                &Jkr::new(radius, e_star, work_of_adhesion)?,
                0.0,
                &path,
                &f_ref,
                p_ref,
            )?,
            Fidelity::MaugisDugdale => {
                let md = MaugisDugdale::from_tabor(radius, e_star, work_of_adhesion, z0)?;
                measure(law, &md, 0.0, &path, &f_ref, p_ref)?
            }
            Fidelity::TabulatedMaugisDugdale => {
                let t = Instant::now();
                let md = MaugisDugdale::from_tabor(radius, e_star, work_of_adhesion, z0)?;
                let table = TabulatedLaw::from_maugis_dugdale(
                    &md,
                    crate::contact::tabulated::DEFAULT_TOLERANCE,
                )?;
                measure(law, &table, t.elapsed().as_secs_f64(), &path, &f_ref, p_ref)?
            }
            // The reference table itself (the same grid and tolerance):
            // building it again would double the longest step.
            Fidelity::TabulatedLennardJones => {
                measure(law, &reference, reference_build, &path, &f_ref, p_ref)?
            }
            Fidelity::LennardJones => {
                // The converged solver; its cost is one Newton solve from a
                // neighbouring solution, at ᾱ = 0 (in contact). Where the
                // fixed mesh cannot reach it (μ = 10: the continuation in
                // the nodal unknowns needs O(μ²) steps, see the `edge`
                // module of the solver), at the far start gap instead.
                let solver = lj.solver(converged)?;
                let mid = match solver.solve_at_approach(0.0, None) {
                    Ok(s) => s,
                    Err(_) => solver.solve_at_central_gap(6.0 + 4.0 * lj.tabor().sqrt(), None)?,
                };
                let t = Instant::now();
                let mut calls = 0u32;
                while calls < 3 || t.elapsed().as_secs_f64() < 0.02 {
                    let al = mid.approach + 1e-3 * (calls as f64 + 1.0);
                    let _ = solver.solve_at_approach(al, Some(&mid))?;
                    calls += 1;
                }
                Assessment {
                    law,
                    pull_off_error: 0.0,
                    curve_error: 0.0,
                    cost_per_call: t.elapsed().as_secs_f64() / calls as f64,
                    build_time: reference_build,
                }
            }
        };
        out.push(a);
    }
    Ok((out, p_ref, converged))
}

/// The cheapest model whose pull-off and curve errors are both within
/// `force_tolerance` (N, > 0) for this sphere (see [`assess`]).
pub fn advise(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    z0: f64,
    force_tolerance: f64,
) -> Result<Advice> {
    let tol = check::positive("force_tolerance", force_tolerance)?;
    let (assessments, reference_pull_off, reference_grid) =
        assess(radius, e_star, work_of_adhesion, z0)?;
    let chosen = *assessments
        .iter()
        .find(|a| a.pull_off_error <= tol && a.curve_error <= tol)
        .unwrap_or_else(|| assessments.last().expect("six assessments"));
    Ok(Advice {
        choice: chosen.law,
        chosen,
        tabor: crate::material::tabor_parameter(radius, work_of_adhesion, e_star, z0)?,
        assessments,
        reference_pull_off,
        reference_grid,
    })
}

/// Approach path (m): from −50 z₀ to the deepest point of the reference's
/// table range where the force reaches ~10 πRw, and back. Log-spaced far
/// away, uniform within 5 z₀ of contact.
fn sweep_path(reference: &TabulatedLaw, z0: f64) -> Result<Vec<f64>> {
    // Deep end: where the reference force reaches 10 πRw, found by doubling.
    let force_scale = -reference.pull_off_force(Control::Load)? / 1.5; // ≈ πRw
    let mut deep = z0;
    let mut state = ContactState::default();
    for _ in 0..200 {
        let (r, s) = reference.eval(deep, &state)?;
        state = s;
        if r.force >= 10.0 * force_scale {
            break;
        }
        deep *= 1.5;
    }
    let n_far = 200;
    let n_near = 1800;
    let mut up = Vec::with_capacity(n_far + n_near);
    for i in 0..n_far {
        // −50 z₀ … −5 z₀, log-spaced in the gap.
        let g = 50.0 * (0.1f64).powf(i as f64 / n_far as f64);
        up.push(-g * z0);
    }
    for i in 0..=n_near {
        up.push(-5.0 * z0 + (deep + 5.0 * z0) * i as f64 / n_near as f64);
    }
    let mut path = up.clone();
    path.extend(up.iter().rev().skip(1));
    Ok(path)
}

fn forces_along<L: NormalContact>(law: &L, path: &[f64]) -> Result<Vec<f64>> {
    let mut state = ContactState::default();
    path.iter()
        .map(|&d| {
            let (r, s) = law.eval(d, &state)?;
            state = s;
            Ok(r.force)
        })
        .collect()
}

fn measure<L: NormalContact>(
    law: Fidelity,
    model: &L,
    build_time: f64,
    path: &[f64],
    f_ref: &[f64],
    p_ref: f64,
) -> Result<Assessment> {
    let f = forces_along(model, path)?;
    let curve_error = f
        .iter()
        .zip(f_ref)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    let pull_off_error = (model.pull_off_force(Control::Load)? - p_ref).abs();
    // Cost: median of 5 passes over the path.
    let mut times = [0.0; 5];
    for t in times.iter_mut() {
        let start = Instant::now();
        let mut state = ContactState::default();
        for &d in path {
            let (r, s) = model.eval(std::hint::black_box(d), &state)?;
            state = s;
            std::hint::black_box(r.force);
        }
        *t = start.elapsed().as_secs_f64() / path.len() as f64;
    }
    times.sort_by(f64::total_cmp);
    if !(curve_error.is_finite() && pull_off_error.is_finite()) {
        return Err(Error::OutOfDomain {
            name: "law",
            value: 0.0,
            reason: "a model gave a non-finite force on the assessment path",
        });
    }
    Ok(Assessment {
        law,
        pull_off_error,
        curve_error,
        cost_per_call: times[2],
        build_time,
    })
}
