//! Tabulated laws (`asperity::contact::tabulated`) and the fidelity advisor
//! (`asperity::fidelity`).

use crate::common::{any_err, count, real, real_opt, rs, string};
use crate::contact::MaugisDugdale;
use crate::lj_sphere::LjSphere;
use asperity::contact::TabulatedLaw as RsTable;
use asperity::fidelity;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

crate::normal_law!(
    /// A normal law tabulated once from Maugis–Dugdale or the Lennard-Jones
    /// solver and evaluated by lookup within a stated relative tolerance:
    /// ``TabulatedLaw.from_maugis_dugdale(md, tolerance=1e-4)``,
    /// ``TabulatedLaw.from_lj_sphere(lj, n_grid=128, tolerance=1e-4)``,
    /// ``TabulatedLaw.from_json(text)`` / ``TabulatedLaw.load(path)``. Shared
    /// between threads; ``eval`` as every law.
    TabulatedLaw, RsTable, "TabulatedLaw",
    getters {}
    {
        /// from_maugis_dugdale(md, tolerance=1e-4) -> TabulatedLaw
        ///
        /// Table of a ``MaugisDugdale`` law within ``tolerance`` (relative,
        /// dimensionless) of the closed form. The GIL is released.
        #[staticmethod]
        #[pyo3(signature = (md, tolerance=None))]
        fn from_maugis_dugdale(py: Python<'_>, md: &Bound<'_, MaugisDugdale>, tolerance: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
            let tol = real_opt(tolerance, "tolerance")?.unwrap_or(asperity::contact::tabulated::DEFAULT_TOLERANCE);
            let m = md.get().inner;
            Ok(Self { inner: py.detach(|| RsTable::from_maugis_dugdale(&m, tol)).map_err(rs)? })
        }
        /// from_lj_sphere(lj, n_grid=128, tolerance=1e-4) -> TabulatedLaw
        ///
        /// Table of the Lennard-Jones sphere solved on ``n_grid`` radial cells,
        /// within ``tolerance`` (relative) of the solver on that grid. About
        /// a second for μ ≤ 1; the GIL is released.
        #[staticmethod]
        #[pyo3(signature = (lj, n_grid=None, tolerance=None))]
        fn from_lj_sphere(py: Python<'_>, lj: &Bound<'_, LjSphere>, n_grid: Option<&Bound<'_, PyAny>>, tolerance: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
            let tol = real_opt(tolerance, "tolerance")?.unwrap_or(asperity::contact::tabulated::DEFAULT_TOLERANCE);
            let n = n_grid.map(|g| count(g, "n_grid")).transpose()?.unwrap_or(128);
            let l = lj.get().inner;
            Ok(Self { inner: py.detach(|| RsTable::from_lj_sphere(&l, n, tol)).map_err(rs)? })
        }
        /// from_json(text) -> TabulatedLaw
        ///
        /// A table from its JSON text (``to_json``), validated; evaluates
        /// bit-identically to the table written.
        #[staticmethod]
        fn from_json(text: &Bound<'_, PyAny>) -> PyResult<Self> {
            let t = string(text, "text")?;
            Ok(Self { inner: RsTable::from_json(&t).map_err(rs)? })
        }
        /// load(path) -> TabulatedLaw
        ///
        /// A table from a JSON file written by ``save``.
        #[staticmethod]
        fn load(path: std::path::PathBuf) -> PyResult<Self> {
            let t = std::fs::read_to_string(&path).map_err(|e| any_err(format!("cannot read {}: {e}", path.display())))?;
            Ok(Self { inner: RsTable::from_json(&t).map_err(rs)? })
        }
        /// to_json() -> str
        ///
        /// The table as JSON text (numbers written exactly).
        fn to_json(&self) -> String {
            self.inner.to_json()
        }
        /// save(path) -> None
        ///
        /// Write the table as JSON to ``path``.
        fn save(&self, path: std::path::PathBuf) -> PyResult<()> {
            std::fs::write(&path, self.inner.to_json()).map_err(|e| any_err(format!("cannot write {}: {e}", path.display())))
        }
        /// The stated bound of the relative error the table was built for.
        #[getter]
        fn tolerance(&self) -> f64 {
            self.inner.tolerance()
        }
        /// The largest relative error measured at construction (≤ tolerance).
        #[getter]
        fn measured_error(&self) -> f64 {
            self.inner.measured_error()
        }
        /// Where the table came from (text).
        #[getter]
        fn source(&self) -> String {
            self.inner.source().to_string()
        }
        /// Number of branches (``ContactState.branch`` runs over them).
        #[getter]
        fn branch_count(&self) -> usize {
            self.inner.branch_count()
        }
        /// branch_range(k) -> (float, float) | None
        ///
        /// Overlap range (m) of branch k: jump-out and jump-in overlaps.
        fn branch_range(&self, k: usize) -> Option<(f64, f64)> {
            self.inner.branch_range(k)
        }
        /// Number of knots over all segments.
        #[getter]
        fn knot_count(&self) -> usize {
            self.inner.knot_count()
        }
        /// Memory of the evaluation structures (bytes).
        #[getter]
        fn memory_bytes(&self) -> usize {
            self.inner.memory_bytes()
        }
        fn __repr__(&self) -> String {
            format!("TabulatedLaw(source={:?}, knots={}, tolerance={:e})", self.inner.source(), self.inner.knot_count(), self.inner.tolerance())
        }
    }
);

fn assessment<'py>(py: Python<'py>, a: &fidelity::Assessment) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("law", a.law.name())?;
    d.set_item("pull_off_error", a.pull_off_error)?;
    d.set_item("curve_error", a.curve_error)?;
    d.set_item("cost_per_call", a.cost_per_call)?;
    d.set_item("build_time", a.build_time)?;
    Ok(d)
}

/// The speed–accuracy table as a list of ``assessment`` dicts.
fn assessments<'py>(
    py: Python<'py>,
    list: &[fidelity::Assessment],
) -> PyResult<Bound<'py, PyList>> {
    let l = PyList::empty(py);
    for a in list {
        l.append(assessment(py, a)?)?;
    }
    Ok(l)
}

/// assess(radius, e_star, work_of_adhesion, z0) -> dict
///
/// The speed–accuracy table of the adhesive-sphere models (DMT, tabulated
/// Maugis–Dugdale, tabulated Lennard-Jones, JKR, Maugis–Dugdale, the full
/// Lennard-Jones solver) for a sphere of radius R (m), contact modulus E*
/// (Pa), work of adhesion w (J/m²) and Lennard-Jones z0 (m), measured
/// against the converged Lennard-Jones sphere: ``assessments`` (list of
/// dicts: ``law``, ``pull_off_error`` (N), ``curve_error`` (N),
/// ``cost_per_call`` (s), ``build_time`` (s)), ``reference_pull_off`` (N),
/// ``reference_grid``. About a second for μ ≤ 1; the GIL is released.
#[pyfunction]
fn assess<'py>(
    py: Python<'py>,
    radius: &Bound<'_, PyAny>,
    e_star: &Bound<'_, PyAny>,
    work_of_adhesion: &Bound<'_, PyAny>,
    z0: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let (r, e, w, z) = (
        real(radius, "radius")?,
        real(e_star, "e_star")?,
        real(work_of_adhesion, "work_of_adhesion")?,
        real(z0, "z0")?,
    );
    let (list, p_ref, grid) = py.detach(|| fidelity::assess(r, e, w, z)).map_err(rs)?;
    let d = PyDict::new(py);
    d.set_item("assessments", assessments(py, &list)?)?;
    d.set_item("reference_pull_off", p_ref)?;
    d.set_item("reference_grid", grid)?;
    Ok(d)
}

/// advise(radius, e_star, work_of_adhesion, z0, force_tolerance) -> dict
///
/// The cheapest adhesive-sphere model whose pull-off and curve errors are
/// both within ``force_tolerance`` (N) for this sphere (R m, E* Pa, w J/m²,
/// z0 m): ``choice`` (model name), ``chosen`` (its assessment),
/// ``assessments`` (the speed–accuracy table, see ``assess``), ``tabor``
/// (μ), ``reference_pull_off`` (N), ``reference_grid``.
#[pyfunction]
fn advise<'py>(
    py: Python<'py>,
    radius: &Bound<'_, PyAny>,
    e_star: &Bound<'_, PyAny>,
    work_of_adhesion: &Bound<'_, PyAny>,
    z0: &Bound<'_, PyAny>,
    force_tolerance: &Bound<'_, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let (r, e, w, z, t) = (
        real(radius, "radius")?,
        real(e_star, "e_star")?,
        real(work_of_adhesion, "work_of_adhesion")?,
        real(z0, "z0")?,
        real(force_tolerance, "force_tolerance")?,
    );
    let a = py.detach(|| fidelity::advise(r, e, w, z, t)).map_err(rs)?;
    let d = PyDict::new(py);
    d.set_item("choice", a.choice.name())?;
    d.set_item("chosen", assessment(py, &a.chosen)?)?;
    d.set_item("assessments", assessments(py, &a.assessments)?)?;
    d.set_item("tabor", a.tabor)?;
    d.set_item("reference_pull_off", a.reference_pull_off)?;
    d.set_item("reference_grid", a.reference_grid)?;
    Ok(d)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<TabulatedLaw>()?;
    m.add_function(wrap_pyfunction!(assess, m)?)?;
    m.add_function(wrap_pyfunction!(advise, m)?)?;
    m.add(
        "DEFAULT_TABLE_TOLERANCE",
        asperity::contact::tabulated::DEFAULT_TOLERANCE,
    )?;
    Ok(())
}
