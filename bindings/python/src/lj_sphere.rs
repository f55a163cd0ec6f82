//! The numerical Lennard-Jones adhesive sphere (`asperity::contact::lj_sphere`):
//! the full force–approach curve as arrays, jump points, pull-off and
//! hysteresis, in SI units and in the solver's reduced units.

use crate::common::{count, real, rs};
use asperity::contact::{LjCurve, LjPoint, LjSphere as RsLj};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// LjSphere(radius, e_star, work_of_adhesion, z0)
///
/// An elastic sphere under the Lennard-Jones 3-9 surface law (Greenwood
/// 1997; seed 001), solved numerically: radius R (m), contact modulus E*
/// (Pa), work of adhesion w (J/m²), equilibrium separation z0 (m). Reduced
/// units: force P/(πwR), approach α/z0, radius a/√(R z0), energy /(πwR z0).
#[pyclass(module = "asperity", frozen)]
pub struct LjSphere {
    pub inner: RsLj,
}

fn point<'py>(py: Python<'py>, lj: &RsLj, p: &LjPoint) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let (fs, z0, rs_) = (lj.force_scale(), lj.z0, lj.radius_scale());
    d.set_item("approach", p.approach * z0)?;
    d.set_item("force", p.force * fs)?;
    d.set_item("contact_radius", p.contact_radius * rs_)?;
    d.set_item("central_gap", p.central_gap * z0)?;
    d.set_item("stiffness", p.stiffness * fs / z0)?;
    d.set_item("approach_bar", p.approach)?;
    d.set_item("force_bar", p.force)?;
    d.set_item("contact_radius_bar", p.contact_radius)?;
    d.set_item("central_gap_bar", p.central_gap)?;
    Ok(d)
}

/// The force–approach curve of a ``LjSphere`` (``LjSphere.curve()``).
///
/// Arrays along the path (approach, then into contact), SI: ``approach``
/// α (m), ``force`` P (N), ``contact_radius`` a (m), ``central_gap`` h(0) (m),
/// ``stiffness`` dP/dα (N/m); reduced: ``approach_bar``, ``force_bar``,
/// ``contact_radius_bar``, ``central_gap_bar``. Points: ``jump_in``,
/// ``jump_out`` (dicts, None when the curve is not S-shaped),
/// ``pull_off_load`` (dict); ``pull_off_displacement`` (N or None),
/// ``hysteresis_energy`` (J), solver report ``iterations``,
/// ``factorizations``, ``max_residual`` (units of z0), ``n_grid``.
#[pyclass(module = "asperity", frozen, get_all, name = "LjCurve")]
pub struct LjCurveResult {
    approach: Py<PyArray1<f64>>,
    force: Py<PyArray1<f64>>,
    contact_radius: Py<PyArray1<f64>>,
    central_gap: Py<PyArray1<f64>>,
    stiffness: Py<PyArray1<f64>>,
    approach_bar: Py<PyArray1<f64>>,
    force_bar: Py<PyArray1<f64>>,
    contact_radius_bar: Py<PyArray1<f64>>,
    central_gap_bar: Py<PyArray1<f64>>,
    jump_in: Option<Py<PyDict>>,
    jump_out: Option<Py<PyDict>>,
    pull_off_load: Py<PyDict>,
    pull_off_displacement: Option<f64>,
    hysteresis_energy: f64,
    iterations: u64,
    factorizations: u64,
    max_residual: f64,
    n_grid: usize,
}

#[pymethods]
impl LjCurveResult {
    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "LjCurve(<{} points>, n_grid={}, pull_off_displacement={})",
            numpy::PyUntypedArrayMethods::len(self.force.bind(py)),
            self.n_grid,
            self.pull_off_displacement
                .map_or("None".to_string(), |p| format!("{p:e}"))
        )
    }
}

fn curve_result(py: Python<'_>, lj: &RsLj, c: &LjCurve) -> PyResult<LjCurveResult> {
    let (fs, z0, rsc) = (lj.force_scale(), lj.z0, lj.radius_scale());
    let col = |f: &dyn Fn(&LjPoint) -> f64| {
        PyArray1::from_vec(py, c.points.iter().map(f).collect()).unbind()
    };
    Ok(LjCurveResult {
        approach: col(&|p| p.approach * z0),
        force: col(&|p| p.force * fs),
        contact_radius: col(&|p| p.contact_radius * rsc),
        central_gap: col(&|p| p.central_gap * z0),
        stiffness: col(&|p| p.stiffness * fs / z0),
        approach_bar: col(&|p| p.approach),
        force_bar: col(&|p| p.force),
        contact_radius_bar: col(&|p| p.contact_radius),
        central_gap_bar: col(&|p| p.central_gap),
        jump_in: c
            .jump_in
            .as_ref()
            .map(|p| point(py, lj, p).map(|d| d.unbind()))
            .transpose()?,
        jump_out: c
            .jump_out
            .as_ref()
            .map(|p| point(py, lj, p).map(|d| d.unbind()))
            .transpose()?,
        pull_off_load: point(py, lj, &c.pull_off_load)?.unbind(),
        pull_off_displacement: c.pull_off_displacement.map(|p| p * fs),
        hysteresis_energy: c.hysteresis_energy * lj.energy_scale(),
        iterations: c.iterations,
        factorizations: c.factorizations,
        max_residual: c.max_residual,
        n_grid: c.n_grid,
    })
}

#[pymethods]
impl LjSphere {
    #[new]
    fn new(
        radius: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
        work_of_adhesion: &Bound<'_, PyAny>,
        z0: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: RsLj::new(
                real(radius, "radius")?,
                real(e_star, "e_star")?,
                real(work_of_adhesion, "work_of_adhesion")?,
                real(z0, "z0")?,
            )
            .map_err(rs)?,
        })
    }
    /// from_tabor(mu) -> LjSphere
    ///
    /// The reduced sphere of Tabor parameter μ (R = z0 = w = 1 units).
    #[staticmethod]
    fn from_tabor(mu: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: RsLj::from_tabor(real(mu, "mu")?).map_err(rs)?,
        })
    }
    /// Sphere radius R (m).
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius
    }
    /// Contact modulus E* (Pa).
    #[getter]
    fn e_star(&self) -> f64 {
        self.inner.e_star
    }
    /// Work of adhesion w (J/m²).
    #[getter]
    fn work_of_adhesion(&self) -> f64 {
        self.inner.work_of_adhesion
    }
    /// Equilibrium separation z0 (m).
    #[getter]
    fn z0(&self) -> f64 {
        self.inner.z0
    }
    /// tabor() -> float
    ///
    /// Tabor parameter μ = (R w²/(E*² z0³))^(1/3) (dimensionless).
    fn tabor(&self) -> f64 {
        self.inner.tabor()
    }
    /// force_scale() -> float
    ///
    /// Force unit πRw (N).
    fn force_scale(&self) -> f64 {
        self.inner.force_scale()
    }
    /// radius_scale() -> float
    ///
    /// Radius unit √(R z0) (m).
    fn radius_scale(&self) -> f64 {
        self.inner.radius_scale()
    }
    /// energy_scale() -> float
    ///
    /// Energy unit πRw z0 (J).
    fn energy_scale(&self) -> f64 {
        self.inner.energy_scale()
    }
    /// converged_default_grid() -> int
    ///
    /// The grid the library calls converged (radial cells: 256 for μ ≤ 3,
    /// 512 up to 10, 1024 beyond).
    fn converged_default_grid(&self) -> usize {
        self.inner.converged_default_grid()
    }
    /// pull_off_force(n_grid=0) -> float
    ///
    /// Load-controlled pull-off force (N, negative) on ``n_grid`` radial
    /// cells (0 = the converged default). The GIL is released.
    #[pyo3(signature = (n_grid=None))]
    fn pull_off_force(&self, py: Python<'_>, n_grid: Option<&Bound<'_, PyAny>>) -> PyResult<f64> {
        let n = n_grid.map(|g| count(g, "n_grid")).transpose()?.unwrap_or(0);
        let lj = self.inner;
        py.detach(|| lj.pull_off_force(n)).map_err(rs)
    }
    /// pull_off(n_grid=0) -> dict
    ///
    /// The load-controlled pull-off with its solve report: ``force`` (N),
    /// ``approach`` (m), ``central_gap`` (m), ``contact_radius`` (m), their
    /// reduced values (``*_bar``), ``iterations``, ``max_residual`` (units of
    /// z0), ``n_grid``.
    #[pyo3(signature = (n_grid=None))]
    fn pull_off<'py>(
        &self,
        py: Python<'py>,
        n_grid: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let n = n_grid.map(|g| count(g, "n_grid")).transpose()?.unwrap_or(0);
        let lj = self.inner;
        let p = py.detach(|| lj.pull_off(n)).map_err(rs)?;
        let d = PyDict::new(py);
        d.set_item("force", p.force * lj.force_scale())?;
        d.set_item("approach", p.approach * lj.z0)?;
        d.set_item("central_gap", p.central_gap * lj.z0)?;
        d.set_item("contact_radius", p.contact_radius * lj.radius_scale())?;
        d.set_item("force_bar", p.force)?;
        d.set_item("approach_bar", p.approach)?;
        d.set_item("central_gap_bar", p.central_gap)?;
        d.set_item("contact_radius_bar", p.contact_radius)?;
        d.set_item("iterations", p.iterations)?;
        d.set_item("max_residual", p.max_residual)?;
        d.set_item("n_grid", p.n_grid)?;
        Ok(d)
    }
    /// curve(n_grid=0) -> LjCurve
    ///
    /// The full force–approach curve by continuation through the jump points
    /// on ``n_grid`` radial cells (0 = the converged default): arrays in SI
    /// and reduced units, the jump points, pull-offs and the hysteresis
    /// energy (J). Tens of milliseconds at N = 256; the GIL is released.
    #[pyo3(signature = (n_grid=None))]
    fn curve(&self, py: Python<'_>, n_grid: Option<&Bound<'_, PyAny>>) -> PyResult<LjCurveResult> {
        let n = n_grid.map(|g| count(g, "n_grid")).transpose()?.unwrap_or(0);
        let lj = self.inner;
        let c = py
            .detach(|| lj.solver(n).and_then(|s| s.curve()))
            .map_err(rs)?;
        curve_result(py, &lj, &c)
    }
    fn __repr__(&self) -> String {
        format!(
            "LjSphere(radius={:e}, e_star={:e}, work_of_adhesion={:e}, z0={:e})",
            self.inner.radius, self.inner.e_star, self.inner.work_of_adhesion, self.inner.z0
        )
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<LjSphere>()?;
    m.add_class::<LjCurveResult>()?;
    Ok(())
}
