//! Statistical multi-asperity models (`asperity::statistics`): height
//! distributions, Greenwood–Williamson, Bush–Gibson–Thomas, Bora et al.,
//! Borodich–Kryukova's block on a belt,
//! Kragelsky rods and bearing curve, Sergienko–Bukharov's body on the rods,
//! Zhuravlev, power-law asperities; every response on a float or an array of
//! separations.

use crate::common::{array, count, real, real_opt, rs, vectorize, vectorize_record};
use crate::rescaling::{KnownSolution, Rescaling};
use asperity::statistics as st;
use pyo3::prelude::*;
use pyo3::types::PyDict;

const RESPONSE: [&str; 4] = ["load", "area", "contacts", "mean_pressure"];

fn record(r: st::MultiAsperityResponse) -> [f64; 4] {
    [r.load, r.area, r.contacts, r.mean_pressure()]
}

fn separation<'py>(py: Python<'py>, s: st::SeparationSolution) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("separation", s.separation)?;
    d.set_item("iterations", s.iterations)?;
    d.set_item("relative_residual", s.relative_residual)?;
    Ok(d)
}

/// `f`'s response as the dict ``load``, ``area``, ``contacts``,
/// ``mean_pressure`` at `x` (named `name`): floats, or arrays for an array.
fn responses<F>(py: Python<'_>, x: &Bound<'_, PyAny>, name: &str, f: F) -> PyResult<Py<PyAny>>
where
    F: Fn(f64) -> asperity::Result<st::MultiAsperityResponse> + Send + Sync,
{
    vectorize_record(py, x, name, RESPONSE, |v| f(v).map(record))
}

/// The separation dict of `f` at the float argument `load`.
fn separation_at<'py, F>(
    py: Python<'py>,
    load: &Bound<'_, PyAny>,
    f: F,
) -> PyResult<Bound<'py, PyDict>>
where
    F: FnOnce(f64) -> asperity::Result<st::SeparationSolution>,
{
    separation(py, f(real(load, "load")?).map_err(rs)?)
}

/// The summit-height distribution of a statistical model:
/// ``HeightDistribution.gaussian(sigma)``, ``.exponential(sigma)`` (σ in m)
/// or ``.empirical(heights, radii=None)`` (a measured list, m).
#[pyclass(module = "asperity", frozen)]
pub struct HeightDistribution {
    pub inner: st::HeightDistribution,
}

#[pymethods]
impl HeightDistribution {
    /// gaussian(sigma) -> HeightDistribution
    ///
    /// Zero-mean normal heights of standard deviation σ (m).
    #[staticmethod]
    fn gaussian(sigma: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: st::HeightDistribution::gaussian(real(sigma, "sigma")?).map_err(rs)?,
        })
    }
    /// exponential(sigma) -> HeightDistribution
    ///
    /// Zero-mean exponential heights of standard deviation σ (m).
    #[staticmethod]
    fn exponential(sigma: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: st::HeightDistribution::exponential(real(sigma, "sigma")?).map_err(rs)?,
        })
    }
    /// empirical(heights, radii=None) -> HeightDistribution
    ///
    /// A measured list of summit heights (m), with per-summit radii (m) if given.
    #[staticmethod]
    #[pyo3(signature = (heights, radii=None))]
    fn empirical(heights: &Bound<'_, PyAny>, radii: Option<&Bound<'_, PyAny>>) -> PyResult<Self> {
        let h: Vec<f64> = array(heights, "heights")?
            .as_array()
            .iter()
            .copied()
            .collect();
        let inner = match radii {
            None => st::HeightDistribution::empirical(h).map_err(rs)?,
            Some(r) => st::HeightDistribution::Empirical(
                st::EmpiricalHeights::with_radii(h, array(r, "radii")?.as_slice()?.to_vec())
                    .map_err(rs)?,
            ),
        };
        Ok(Self { inner })
    }
    /// std_dev() -> float
    ///
    /// Standard deviation of the heights (m).
    fn std_dev(&self) -> f64 {
        self.inner.std_dev()
    }
    /// exceedance(d) -> float | numpy.ndarray
    ///
    /// Probability that a height exceeds d (m).
    fn exceedance(&self, py: Python<'_>, d: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let h = &self.inner;
        vectorize(py, d, "d", |x| h.exceedance(x))
    }
    /// tail_moment(q, d) -> float | numpy.ndarray
    ///
    /// ∫_d^∞ (z - d)^q φ(z) dz (m^q) at separation d (m).
    fn tail_moment(
        &self,
        py: Python<'_>,
        q: &Bound<'_, PyAny>,
        d: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let q = real(q, "q")?;
        let h = &self.inner;
        vectorize(py, d, "d", |x| h.tail_moment(q, x))
    }
    fn __repr__(&self) -> String {
        match &self.inner {
            st::HeightDistribution::Gaussian { sigma } => {
                format!("HeightDistribution.gaussian({sigma:e})")
            }
            st::HeightDistribution::Exponential { sigma } => {
                format!("HeightDistribution.exponential({sigma:e})")
            }
            st::HeightDistribution::Empirical(e) => {
                format!("HeightDistribution.empirical(<{} heights>)", e.len())
            }
        }
    }
}

/// GreenwoodWilliamson(summit_count, radius, e_star, heights)
///
/// Greenwood & Williamson (1966): N (summit_count) Hertzian summits of radius
/// R (m) on contact modulus E* (Pa) with heights from a
/// ``HeightDistribution``; responses at the separation d (m) of the mean
/// planes, on a float or an array.
#[pyclass(module = "asperity", frozen)]
pub struct GreenwoodWilliamson {
    pub inner: st::GreenwoodWilliamson,
}

#[pymethods]
impl GreenwoodWilliamson {
    #[new]
    fn new(
        summit_count: &Bound<'_, PyAny>,
        radius: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
        heights: &HeightDistribution,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::GreenwoodWilliamson::new(
                real(summit_count, "summit_count")?,
                real(radius, "radius")?,
                real(e_star, "e_star")?,
                heights.inner.clone(),
            )
            .map_err(rs)?,
        })
    }
    /// load(separation) -> float | numpy.ndarray
    ///
    /// Total load P (N) at separation d (m).
    fn load(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.load(d))
    }
    /// area(separation) -> float | numpy.ndarray
    ///
    /// Real contact area A (m²) at separation d (m).
    fn area(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.area(d))
    }
    /// contacts(separation) -> float | numpy.ndarray
    ///
    /// Expected number of summits in contact at separation d (m).
    fn contacts(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.contacts(d))
    }
    /// stiffness(separation) -> float | numpy.ndarray
    ///
    /// Normal contact stiffness -dP/dd (N/m) at separation d (m).
    fn stiffness(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.stiffness(d))
    }
    /// mean_pressure(separation) -> float | numpy.ndarray
    ///
    /// Mean real contact pressure P/A (Pa) at separation d (m).
    fn mean_pressure(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.mean_pressure(d))
    }
    /// response(separation) -> dict
    ///
    /// ``load`` (N), ``area`` (m²), ``contacts``, ``mean_pressure`` (Pa) at
    /// separation d (m): floats, or arrays for an array of separations.
    fn response(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        responses(py, separation, "separation", |d| g.response(d))
    }
    /// separation_at_load(load) -> dict
    ///
    /// The separation (m) that carries ``load`` (N), with ``iterations`` and
    /// ``relative_residual``.
    fn separation_at_load<'py>(
        &self,
        py: Python<'py>,
        load: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        separation_at(py, load, |p| self.inner.separation_at_load(p))
    }
    /// plasticity_index(hardness) -> float
    ///
    /// ψ = (E*/H)√(σ/R) for hardness H (Pa).
    fn plasticity_index(&self, hardness: &Bound<'_, PyAny>) -> PyResult<f64> {
        self.inner
            .plasticity_index(real(hardness, "hardness")?)
            .map_err(rs)
    }
}

/// BushGibsonThomas(m0, m2, m4, e_star, nominal_area)
///
/// Bush, Gibson & Thomas (1975): an isotropic Gaussian surface of spectral
/// moments m0 (m², σ²), m2 (mean-square profile slope) and m4 (m⁻²,
/// mean-square profile curvature), Nayak's α = m0 m4/m2² > 1.5, whose
/// summits are elliptic paraboloids in Hertz contact with a flat of contact
/// modulus E* (Pa), over the nominal area A0 (m²). Responses at the
/// separation d (m) of the flat above the surface's mean plane, on a float
/// or an array. ``BushGibsonThomas.from_alpha(sigma, rms_slope, alpha,
/// e_star, nominal_area)`` builds it from σ (m), √m2 and α.
#[pyclass(module = "asperity", frozen)]
pub struct BushGibsonThomas {
    pub inner: st::BushGibsonThomas,
}

#[pymethods]
impl BushGibsonThomas {
    #[new]
    fn new(
        m0: &Bound<'_, PyAny>,
        m2: &Bound<'_, PyAny>,
        m4: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
        nominal_area: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::BushGibsonThomas::new(
                real(m0, "m0")?,
                real(m2, "m2")?,
                real(m4, "m4")?,
                real(e_star, "e_star")?,
                real(nominal_area, "nominal_area")?,
            )
            .map_err(rs)?,
        })
    }
    /// from_alpha(sigma, rms_slope, alpha, e_star, nominal_area) -> BushGibsonThomas
    ///
    /// m0 = σ², m2 = rms_slope², m4 = α m2²/m0.
    #[staticmethod]
    fn from_alpha(
        sigma: &Bound<'_, PyAny>,
        rms_slope: &Bound<'_, PyAny>,
        alpha: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
        nominal_area: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::BushGibsonThomas::from_alpha(
                real(sigma, "sigma")?,
                real(rms_slope, "rms_slope")?,
                real(alpha, "alpha")?,
                real(e_star, "e_star")?,
                real(nominal_area, "nominal_area")?,
            )
            .map_err(rs)?,
        })
    }
    /// Nayak's α = m0 m4/m2².
    #[getter]
    fn alpha(&self) -> f64 {
        self.inner.alpha()
    }
    /// Nayak's summit density m4/(6π√3 m2) (m⁻²).
    #[getter]
    fn summit_density(&self) -> f64 {
        self.inner.summit_density()
    }
    /// Small-load limit of A/P, √(2π)/(E*√(2 m2)) (m²/N).
    #[getter]
    fn small_load_area_per_load(&self) -> f64 {
        self.inner.small_load_area_per_load()
    }
    /// load(separation) -> float | numpy.ndarray
    ///
    /// Total load P (N) at separation d (m).
    fn load(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.load(d))
    }
    /// area(separation) -> float | numpy.ndarray
    ///
    /// Real contact area A (m²) at separation d (m).
    fn area(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.area(d))
    }
    /// contacts(separation) -> float | numpy.ndarray
    ///
    /// Expected number of summits in contact at separation d (m).
    fn contacts(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.contacts(d))
    }
    /// stiffness(separation) -> float | numpy.ndarray
    ///
    /// Normal contact stiffness -dP/dd (N/m) at separation d (m).
    fn stiffness(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.stiffness(d))
    }
    /// response(separation) -> dict
    ///
    /// ``load`` (N), ``area`` (m²), ``contacts``, ``mean_pressure`` (Pa) at
    /// separation d (m): floats, or arrays for an array of separations.
    fn response(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        responses(py, separation, "separation", |d| g.response(d))
    }
    /// separation_at_load(load) -> dict
    ///
    /// The separation (m) that carries ``load`` (N), with ``iterations`` and
    /// ``relative_residual``.
    fn separation_at_load<'py>(
        &self,
        py: Python<'py>,
        load: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        separation_at(py, load, |p| self.inner.separation_at_load(p))
    }
}

/// BoraTopography(heights, spacing, spring_stiffness, contact_modulus=None, nx=None)
///
/// Bora et al. (2013), thesis §5.3.9: one spring of stiffness k (N/m) per
/// point of a measured height map (m; a 1-D array, row-major
/// ``heights[i + nx*j]``, ``nx`` its row length, default the whole array, a
/// profile) with grid spacing Δ (m), on an elastic half-space of contact
/// modulus E* (Pa) or a rigid one (``None``: independent springs), pressed
/// by a flat at separation d (m, in the frame of the heights).
#[pyclass(module = "asperity", frozen)]
pub struct BoraTopography {
    pub inner: st::BoraTopography,
}

#[pymethods]
impl BoraTopography {
    #[new]
    #[pyo3(signature = (heights, spacing, spring_stiffness, contact_modulus=None, nx=None))]
    fn new(
        heights: &Bound<'_, PyAny>,
        spacing: &Bound<'_, PyAny>,
        spring_stiffness: &Bound<'_, PyAny>,
        contact_modulus: Option<&Bound<'_, PyAny>>,
        nx: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let h: Vec<f64> = array(heights, "heights")?
            .as_array()
            .iter()
            .copied()
            .collect();
        let nx = match nx {
            Some(v) => crate::common::count(v, "nx")?,
            None => h.len(),
        };
        let ny = h.len().checked_div(nx).unwrap_or(0);
        Ok(Self {
            inner: st::BoraTopography::new(
                nx,
                ny.max(1),
                real(spacing, "spacing")?,
                h,
                real(spring_stiffness, "spring_stiffness")?,
                real_opt(contact_modulus, "contact_modulus")?,
            )
            .map_err(rs)?,
        })
    }
    /// solve(separation) -> dict
    ///
    /// ``load`` (N), ``area`` (m²), ``contacts`` (loaded springs),
    /// ``stiffness`` (N/m), ``iterations`` and ``forces`` (N, an array like
    /// the heights) with the flat at separation d (m).
    fn solve<'py>(
        &self,
        py: Python<'py>,
        separation: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let s = self
            .inner
            .solve(real(separation, "separation")?)
            .map_err(rs)?;
        let d = PyDict::new(py);
        d.set_item("load", s.load)?;
        d.set_item("area", s.area)?;
        d.set_item("contacts", s.contacts)?;
        d.set_item("stiffness", s.stiffness)?;
        d.set_item("iterations", s.iterations)?;
        d.set_item("forces", numpy::PyArray1::from_vec(py, s.forces))?;
        Ok(d)
    }
    /// load(separation) -> float | numpy.ndarray
    ///
    /// Total load P (N) at separation d (m).
    fn load(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.solve(d).map(|s| s.load))
    }
    /// separation_at_load(load) -> dict
    ///
    /// The separation (m) that carries ``load`` (N), with ``iterations`` and
    /// ``relative_residual``.
    fn separation_at_load<'py>(
        &self,
        py: Python<'py>,
        load: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        separation_at(py, load, |p| self.inner.separation_at_load(p))
    }
}

/// KragelskyRods(rod_count, rod_area, rod_stiffness, heights)
///
/// Kragelsky's elastic rods: N rods of cross-section A (m²) and axial
/// stiffness k (N/m) with top heights from a ``HeightDistribution``;
/// ``KragelskyRods.from_material(rod_count, rod_area, rod_length,
/// youngs_modulus, heights)`` with k = E A/L.
#[pyclass(module = "asperity", frozen)]
pub struct KragelskyRods {
    pub inner: st::KragelskyRods,
}

#[pymethods]
impl KragelskyRods {
    #[new]
    fn new(
        rod_count: &Bound<'_, PyAny>,
        rod_area: &Bound<'_, PyAny>,
        rod_stiffness: &Bound<'_, PyAny>,
        heights: &HeightDistribution,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::KragelskyRods::new(
                real(rod_count, "rod_count")?,
                real(rod_area, "rod_area")?,
                real(rod_stiffness, "rod_stiffness")?,
                heights.inner.clone(),
            )
            .map_err(rs)?,
        })
    }
    /// from_material(rod_count, rod_area, rod_length, youngs_modulus, heights) -> KragelskyRods
    ///
    /// Rods of Young's modulus E (Pa) and length L (m): k = E A/L.
    #[staticmethod]
    fn from_material(
        rod_count: &Bound<'_, PyAny>,
        rod_area: &Bound<'_, PyAny>,
        rod_length: &Bound<'_, PyAny>,
        youngs_modulus: &Bound<'_, PyAny>,
        heights: &HeightDistribution,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::KragelskyRods::from_material(
                real(rod_count, "rod_count")?,
                real(rod_area, "rod_area")?,
                real(rod_length, "rod_length")?,
                real(youngs_modulus, "youngs_modulus")?,
                heights.inner.clone(),
            )
            .map_err(rs)?,
        })
    }
    /// Axial stiffness k of one rod (N/m).
    #[getter]
    fn rod_stiffness(&self) -> f64 {
        self.inner.rod_stiffness()
    }
    /// load(separation) -> float | numpy.ndarray
    ///
    /// Total load (N) at separation d (m).
    fn load(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, separation, "separation", |d| g.load(d))
    }
    /// response(separation) -> dict
    ///
    /// ``load`` (N), ``area`` (m²), ``contacts``, ``mean_pressure`` (Pa).
    fn response(&self, py: Python<'_>, separation: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        responses(py, separation, "separation", |d| g.response(d))
    }
    /// separation_at_load(load) -> dict
    ///
    /// The separation (m) that carries ``load`` (N).
    fn separation_at_load<'py>(
        &self,
        py: Python<'py>,
        load: &Bound<'_, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        separation_at(py, load, |p| self.inner.separation_at_load(p))
    }
}

/// SergienkoBukharov(rods, mass, load, friction_coefficient, damping_ratio=0.1, attractive_pressure=0.0)
///
/// Sergienko & Bukharov (2015), thesis §5.3.5, in the library's formulation
/// from the thesis's description (the book's equations were not available):
/// a rigid body of mass m (kg) under the load N0 (N) on Kragelsky's
/// independent springs ``rods`` (``KragelskyRods``), viscous damping of ratio
/// ζ about the static equilibrium, friction μ(P + p0 A_rod n) (Derjaguin).
/// ``run(...)`` drives it with F0 sin ωt and/or a tangential impulse and
/// returns the time averages: the dynamic lift and the friction ratio.
#[pyclass(module = "asperity", frozen)]
pub struct SergienkoBukharov {
    pub inner: st::SergienkoBukharov,
}

#[pymethods]
impl SergienkoBukharov {
    #[new]
    #[pyo3(signature = (rods, mass, load, friction_coefficient, damping_ratio=None, attractive_pressure=None))]
    fn new(
        rods: &KragelskyRods,
        mass: &Bound<'_, PyAny>,
        load: &Bound<'_, PyAny>,
        friction_coefficient: &Bound<'_, PyAny>,
        damping_ratio: Option<&Bound<'_, PyAny>>,
        attractive_pressure: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::SergienkoBukharov::new(
                rods.inner.clone(),
                real(mass, "mass")?,
                real(load, "load")?,
                real_opt(damping_ratio, "damping_ratio")?.unwrap_or(0.1),
                real(friction_coefficient, "friction_coefficient")?,
                real_opt(attractive_pressure, "attractive_pressure")?.unwrap_or(0.0),
            )
            .map_err(rs)?,
        })
    }
    /// Static separation d_s (m): the springs carry the load.
    #[getter]
    fn static_separation(&self) -> f64 {
        self.inner.static_separation()
    }
    /// Springs in contact at rest.
    #[getter]
    fn static_contacts(&self) -> f64 {
        self.inner.static_contacts()
    }
    /// Static friction μ(N0 + p0 A_rod n_s) (N).
    #[getter]
    fn static_friction(&self) -> f64 {
        self.inner.static_friction()
    }
    /// Natural angular frequency √(k n_s/m) (rad/s) about the rest state.
    #[getter]
    fn natural_frequency(&self) -> f64 {
        self.inner.natural_frequency()
    }
    /// Damping coefficient c = 2ζ√(m k n_s) (N·s/m).
    #[getter]
    fn damping(&self) -> f64 {
        self.inner.damping()
    }
    /// run(force_amplitude=0.0, frequency=0.0, tangential_impulse=0.0, slope=0.0, initial_offset=0.0, transient_periods=20, average_periods=10, steps_per_natural_period=64, record_every=0, max_steps=0) -> dict
    ///
    /// Integrate under F0 sin ωt (N, rad/s), a tangential impulse J (N·s)
    /// turned upwards by flanks of slope tan θ, from d_s + initial_offset
    /// (m); average over whole periods after the transient. The dict holds
    /// ``static_separation``, ``static_contacts``, ``static_friction``,
    /// ``mean_separation``, ``lift``, ``separation_amplitude``,
    /// ``mean_contacts``, ``contact_ratio``, ``mean_load``,
    /// ``mean_friction``, ``friction_ratio``, ``lift_off_fraction``,
    /// ``damping``, ``period``, ``time_step``, ``steps``, ``resolution``
    /// and, when ``record_every`` > 0, ``samples``: a dict of arrays
    /// ``time``, ``separation``, ``velocity``, ``load``, ``contacts``,
    /// ``friction``.
    #[pyo3(signature = (force_amplitude=None, frequency=None, tangential_impulse=None, slope=None, initial_offset=None, transient_periods=None, average_periods=None, steps_per_natural_period=None, record_every=None, max_steps=None))]
    #[allow(clippy::too_many_arguments)]
    fn run<'py>(
        &self,
        py: Python<'py>,
        force_amplitude: Option<&Bound<'_, PyAny>>,
        frequency: Option<&Bound<'_, PyAny>>,
        tangential_impulse: Option<&Bound<'_, PyAny>>,
        slope: Option<&Bound<'_, PyAny>>,
        initial_offset: Option<&Bound<'_, PyAny>>,
        transient_periods: Option<&Bound<'_, PyAny>>,
        average_periods: Option<&Bound<'_, PyAny>>,
        steps_per_natural_period: Option<&Bound<'_, PyAny>>,
        record_every: Option<&Bound<'_, PyAny>>,
        max_steps: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let or0 = |o: Option<&Bound<'_, PyAny>>, name: &str| -> PyResult<f64> {
            Ok(real_opt(o, name)?.unwrap_or(0.0))
        };
        let int = |o: Option<&Bound<'_, PyAny>>, name: &str, default: u32| -> PyResult<u32> {
            match o {
                None => Ok(default),
                Some(v) if v.is_none() => Ok(default),
                Some(v) => u32::try_from(count(v, name)?)
                    .map_err(|_| crate::common::arg_error(name, "must be an integer below 2**32")),
            }
        };
        let excitation = st::Excitation {
            force_amplitude: or0(force_amplitude, "force_amplitude")?,
            frequency: or0(frequency, "frequency")?,
            tangential_impulse: or0(tangential_impulse, "tangential_impulse")?,
            slope: or0(slope, "slope")?,
            initial_offset: or0(initial_offset, "initial_offset")?,
        };
        let default = st::Integration::default();
        let integration = st::Integration {
            transient_periods: int(
                transient_periods,
                "transient_periods",
                default.transient_periods,
            )?,
            average_periods: int(average_periods, "average_periods", default.average_periods)?,
            steps_per_natural_period: int(
                steps_per_natural_period,
                "steps_per_natural_period",
                default.steps_per_natural_period,
            )?,
            record_every: int(record_every, "record_every", 0)?,
            max_steps: match max_steps {
                None => 0,
                Some(v) if v.is_none() => 0,
                Some(v) => count(v, "max_steps")? as u64,
            },
        };
        let model = &self.inner;
        let r = py
            .detach(|| model.run(&excitation, &integration))
            .map_err(rs)?;
        let d = PyDict::new(py);
        for (k, v) in [
            ("static_separation", r.static_separation),
            ("static_contacts", r.static_contacts),
            ("static_friction", r.static_friction),
            ("mean_separation", r.mean_separation),
            ("lift", r.lift),
            ("separation_amplitude", r.separation_amplitude),
            ("mean_contacts", r.mean_contacts),
            ("contact_ratio", r.contact_ratio),
            ("mean_load", r.mean_load),
            ("mean_friction", r.mean_friction),
            ("friction_ratio", r.friction_ratio),
            ("lift_off_fraction", r.lift_off_fraction),
            ("damping", r.damping),
            ("period", r.period),
            ("time_step", r.time_step),
            ("resolution", r.resolution),
        ] {
            d.set_item(k, v)?;
        }
        d.set_item("steps", r.steps)?;
        if integration.record_every > 0 {
            let s = PyDict::new(py);
            let col = |f: fn(&st::SergienkoBukharovSample) -> f64| -> Vec<f64> {
                r.samples.iter().map(f).collect()
            };
            s.set_item("time", numpy::PyArray1::from_vec(py, col(|x| x.time)))?;
            s.set_item(
                "separation",
                numpy::PyArray1::from_vec(py, col(|x| x.separation)),
            )?;
            s.set_item(
                "velocity",
                numpy::PyArray1::from_vec(py, col(|x| x.velocity)),
            )?;
            s.set_item("load", numpy::PyArray1::from_vec(py, col(|x| x.load)))?;
            s.set_item(
                "contacts",
                numpy::PyArray1::from_vec(py, col(|x| x.contacts)),
            )?;
            s.set_item(
                "friction",
                numpy::PyArray1::from_vec(py, col(|x| x.friction)),
            )?;
            d.set_item("samples", s)?;
        }
        Ok(d)
    }
}

/// BearingCurveRods(contour_area, stiffness_per_area, b, nu, max_height, rod_area)
///
/// Kragelsky's rods under a bearing curve η = b (x/max_height)^ν: contour
/// area (m²), stiffness per unit area (N/m³), b, ν (dimensionless), maximum
/// height (m), rod cross-section (m²); responses at the approach x (m).
#[pyclass(module = "asperity", frozen)]
pub struct BearingCurveRods {
    pub inner: st::BearingCurveRods,
}

#[pymethods]
impl BearingCurveRods {
    #[new]
    fn new(
        contour_area: &Bound<'_, PyAny>,
        stiffness_per_area: &Bound<'_, PyAny>,
        b: &Bound<'_, PyAny>,
        nu: &Bound<'_, PyAny>,
        max_height: &Bound<'_, PyAny>,
        rod_area: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::BearingCurveRods::new(
                real(contour_area, "contour_area")?,
                real(stiffness_per_area, "stiffness_per_area")?,
                real(b, "b")?,
                real(nu, "nu")?,
                real(max_height, "max_height")?,
                real(rod_area, "rod_area")?,
            )
            .map_err(rs)?,
        })
    }
    /// response(approach) -> dict
    ///
    /// ``load`` (N), ``area`` (m²), ``contacts``, ``mean_pressure`` (Pa) at
    /// approach x (m).
    fn response(&self, py: Python<'_>, approach: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        responses(py, approach, "approach", |d| g.response(d))
    }
    /// approach_at_load(load) -> float | numpy.ndarray
    ///
    /// The approach x (m) that carries ``load`` (N).
    fn approach_at_load(&self, py: Python<'_>, load: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, load, "load", |p| g.approach_at_load(p))
    }
}

/// Zhuravlev(cap_radius, e_star, summit_count)
///
/// Zhuravlev's model (1940): both surfaces carry spherical caps of radius R
/// (m), so a pair has R_eff = R/2; contact modulus E* (Pa), N summits.
/// ``Zhuravlev.with_effective_radius(effective_radius, e_star,
/// summit_count)`` gives R_eff directly.
#[pyclass(module = "asperity", frozen)]
pub struct Zhuravlev {
    pub inner: st::Zhuravlev,
}

#[pymethods]
impl Zhuravlev {
    #[new]
    fn new(
        cap_radius: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
        summit_count: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::Zhuravlev::new(
                real(cap_radius, "cap_radius")?,
                real(e_star, "e_star")?,
                real(summit_count, "summit_count")?,
            )
            .map_err(rs)?,
        })
    }
    /// with_effective_radius(effective_radius, e_star, summit_count) -> Zhuravlev
    ///
    /// The model with the pair's effective radius (m) given directly.
    #[staticmethod]
    fn with_effective_radius(
        effective_radius: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
        summit_count: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::Zhuravlev::with_effective_radius(
                real(effective_radius, "effective_radius")?,
                real(e_star, "e_star")?,
                real(summit_count, "summit_count")?,
            )
            .map_err(rs)?,
        })
    }
    /// Effective radius of a pair of caps (m).
    #[getter]
    fn effective_radius(&self) -> f64 {
        self.inner.effective_radius()
    }
    /// linear(alpha1, alpha2, approach) -> dict
    ///
    /// The response (``load`` N, ``area`` m², ``contacts``,
    /// ``mean_pressure`` Pa) for linear summit densities α1 ξ, α2 ξ (1/m²)
    /// at approach x (m; float or array).
    fn linear(
        &self,
        py: Python<'_>,
        alpha1: &Bound<'_, PyAny>,
        alpha2: &Bound<'_, PyAny>,
        approach: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let (a1, a2) = (real(alpha1, "alpha1")?, real(alpha2, "alpha2")?);
        let g = &self.inner;
        responses(py, approach, "approach", |x| g.linear(a1, a2, x))
    }
    /// approach_at_load_linear(alpha1, alpha2, load) -> float
    ///
    /// The approach x (m) that carries ``load`` (N) with linear densities.
    fn approach_at_load_linear(
        &self,
        alpha1: &Bound<'_, PyAny>,
        alpha2: &Bound<'_, PyAny>,
        load: &Bound<'_, PyAny>,
    ) -> PyResult<f64> {
        self.inner
            .approach_at_load_linear(
                real(alpha1, "alpha1")?,
                real(alpha2, "alpha2")?,
                real(load, "load")?,
            )
            .map_err(rs)
    }
    /// friction_linear(alpha1, alpha2, load, shear_strength) -> dict
    ///
    /// Zhuravlev's friction F = τ S at ``load`` (N) with shear strength τ
    /// (Pa): the dict of ``ZhuravlevFriction`` (friction force N, area m²,
    /// coefficient of friction, …).
    fn friction_linear(
        &self,
        py: Python<'_>,
        alpha1: &Bound<'_, PyAny>,
        alpha2: &Bound<'_, PyAny>,
        load: &Bound<'_, PyAny>,
        shear_strength: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let f = self
            .inner
            .friction_linear(
                real(alpha1, "alpha1")?,
                real(alpha2, "alpha2")?,
                real(load, "load")?,
                real(shear_strength, "shear_strength")?,
            )
            .map_err(rs)?;
        crate::common::to_py_value(py, &f)
    }
}

/// PowerLawAsperities(rescaling, lambda_, known)
///
/// Asperities of shape B r^d on a material of hardening index κ through
/// Borodich's rescaling (``Rescaling``, shape scale λ, a ``KnownSolution``);
/// ``PowerLawAsperities.elastic(b, d, e_star)`` and
/// ``PowerLawAsperities.sphere(radius, e_star)`` for elastic ones.
#[pyclass(module = "asperity", frozen)]
pub struct PowerLawAsperities {
    pub inner: st::PowerLawAsperities,
}

#[pymethods]
impl PowerLawAsperities {
    #[new]
    fn new(
        rescaling: &Rescaling,
        lambda_: &Bound<'_, PyAny>,
        known: &KnownSolution,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::PowerLawAsperities::new(
                rescaling.inner,
                real(lambda_, "lambda")?,
                known.inner,
            )
            .map_err(rs)?,
        })
    }
    /// elastic(b, d, e_star) -> PowerLawAsperities
    ///
    /// Elastic Galin punches B r^d (B in m^(1-d)) on contact modulus E* (Pa).
    #[staticmethod]
    fn elastic(
        b: &Bound<'_, PyAny>,
        d: &Bound<'_, PyAny>,
        e_star: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: st::PowerLawAsperities::elastic(
                real(b, "b")?,
                real(d, "d")?,
                real(e_star, "e_star")?,
            )
            .map_err(rs)?,
        })
    }
    /// sphere(radius, e_star) -> PowerLawAsperities
    ///
    /// Hertzian spheres of radius R (m) on contact modulus E* (Pa).
    #[staticmethod]
    fn sphere(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: st::PowerLawAsperities::sphere(real(radius, "radius")?, real(e_star, "e_star")?)
                .map_err(rs)?,
        })
    }
    /// exponent() -> float
    ///
    /// Load-depth exponent q of one asperity.
    fn exponent(&self) -> f64 {
        self.inner.exponent()
    }
    /// area_exponent() -> float
    ///
    /// Area-depth exponent of one asperity.
    fn area_exponent(&self) -> f64 {
        self.inner.area_exponent()
    }
    /// asperity_load(depth) -> float | numpy.ndarray
    ///
    /// Load (N) of one asperity at depth (m).
    fn asperity_load(&self, py: Python<'_>, depth: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, depth, "depth", |x| g.asperity_load(x))
    }
    /// asperity_contact_radius(depth) -> float | numpy.ndarray
    ///
    /// Contact radius (m) of one asperity at depth (m).
    fn asperity_contact_radius(
        &self,
        py: Python<'_>,
        depth: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let g = &self.inner;
        vectorize(py, depth, "depth", |x| g.asperity_contact_radius(x))
    }
    /// greenwood_williamson(summit_count, heights, separation) -> dict
    ///
    /// The GW sum of these asperities: response at separation d (m).
    fn greenwood_williamson(
        &self,
        py: Python<'_>,
        summit_count: &Bound<'_, PyAny>,
        heights: &HeightDistribution,
        separation: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let n = real(summit_count, "summit_count")?;
        let (g, h) = (&self.inner, &heights.inner);
        responses(py, separation, "separation", |d| {
            g.greenwood_williamson(n, h, d)
        })
    }
    /// zhuravlev_linear(summit_count, alpha1, alpha2, approach) -> dict
    ///
    /// The Zhuravlev sum with linear densities (1/m²) at approach x (m).
    fn zhuravlev_linear(
        &self,
        py: Python<'_>,
        summit_count: &Bound<'_, PyAny>,
        alpha1: &Bound<'_, PyAny>,
        alpha2: &Bound<'_, PyAny>,
        approach: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let (n, a1, a2) = (
            real(summit_count, "summit_count")?,
            real(alpha1, "alpha1")?,
            real(alpha2, "alpha2")?,
        );
        let g = &self.inner;
        responses(py, approach, "approach", |x| {
            g.zhuravlev_linear(n, a1, a2, x)
        })
    }
}

/// plasticity_index(e_star, hardness, sigma, radius) -> float
///
/// Greenwood–Williamson plasticity index ψ = (E*/H)√(σ/R): contact modulus
/// E* (Pa), hardness H (Pa), summit-height deviation σ (m), summit radius R (m).
#[pyfunction]
fn plasticity_index(
    e_star: &Bound<'_, PyAny>,
    hardness: &Bound<'_, PyAny>,
    sigma: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    st::plasticity_index(
        real(e_star, "e_star")?,
        real(hardness, "hardness")?,
        real(sigma, "sigma")?,
        real(radius, "radius")?,
    )
    .map_err(rs)
}

/// deformation_regime(plasticity_index) -> str
///
/// ``"elastic"`` (ψ < 0.6), ``"transitional"`` or ``"plastic"`` (ψ > 1).
#[pyfunction]
fn deformation_regime(plasticity_index: &Bound<'_, PyAny>) -> PyResult<&'static str> {
    Ok(
        match st::DeformationRegime::of(real(plasticity_index, "plasticity_index")?).map_err(rs)? {
            st::DeformationRegime::Elastic => "elastic",
            st::DeformationRegime::Transitional => "transitional",
            st::DeformationRegime::Plastic => "plastic",
        },
    )
}

/// gaussian_tail_moment(q, h) -> float | numpy.ndarray
///
/// F_q(h) = ∫_h^∞ (s - h)^q φ(s) ds of the standard normal density
/// (dimensionless; GW's F_0, F_1, F_3/2 …), h a float or an array.
#[pyfunction]
fn gaussian_tail_moment(
    py: Python<'_>,
    q: &Bound<'_, PyAny>,
    h: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let q = real(q, "q")?;
    vectorize(py, h, "h", |x| st::gaussian::tail_moment(q, x))
}

/// BorodichKryukova(half_length, mass, belt_speed, spring_stiffness, layer_stiffness, friction_coefficient, sign_speed, slider_amplitude=0, slider_wavelength=1, belt_amplitude=0, belt_wavelength=1, gravity=9.81, nodes=200)
///
/// Borodich & Kryukova (1997, thesis §5.3.7): a rigid block of half-length
/// a (m) and mass M (kg) on a horizontal spring k_x (N/m), on a belt moving
/// at speed U (m/s); both faces carry a layer of linear springs of stiffness
/// ε (N/m²) over the profiles A cos(2πξ/λ) (amplitudes and wavelengths in
/// m); friction μ F_el,y with the sign smoothed as clamp((U − ẋ)/v_s, −1, 1)
/// (``sign_speed`` v_s, m/s); gravity g (m/s²); ``nodes`` midpoint cells
/// along the block.
#[pyclass(module = "asperity", frozen)]
pub struct BorodichKryukova {
    pub inner: st::BorodichKryukova,
}

#[pymethods]
impl BorodichKryukova {
    #[new]
    #[pyo3(signature = (half_length, mass, belt_speed, spring_stiffness, layer_stiffness, friction_coefficient, sign_speed, slider_amplitude=None, slider_wavelength=None, belt_amplitude=None, belt_wavelength=None, gravity=None, nodes=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        half_length: &Bound<'_, PyAny>,
        mass: &Bound<'_, PyAny>,
        belt_speed: &Bound<'_, PyAny>,
        spring_stiffness: &Bound<'_, PyAny>,
        layer_stiffness: &Bound<'_, PyAny>,
        friction_coefficient: &Bound<'_, PyAny>,
        sign_speed: &Bound<'_, PyAny>,
        slider_amplitude: Option<&Bound<'_, PyAny>>,
        slider_wavelength: Option<&Bound<'_, PyAny>>,
        belt_amplitude: Option<&Bound<'_, PyAny>>,
        belt_wavelength: Option<&Bound<'_, PyAny>>,
        gravity: Option<&Bound<'_, PyAny>>,
        nodes: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let or = |v: Option<&Bound<'_, PyAny>>, name: &str, d: f64| -> PyResult<f64> {
            Ok(real_opt(v, name)?.unwrap_or(d))
        };
        let nodes = match nodes {
            Some(n) if !n.is_none() => u32::try_from(count(n, "nodes")?)
                .map_err(|_| crate::common::arg_error("nodes", "in 1..=100000"))?,
            _ => 200,
        };
        let inner = st::BorodichKryukova {
            half_length: real(half_length, "half_length")?,
            mass: real(mass, "mass")?,
            belt_speed: real(belt_speed, "belt_speed")?,
            spring_stiffness: real(spring_stiffness, "spring_stiffness")?,
            layer_stiffness: real(layer_stiffness, "layer_stiffness")?,
            friction_coefficient: real(friction_coefficient, "friction_coefficient")?,
            gravity: or(gravity, "gravity", 9.81)?,
            sign_speed: real(sign_speed, "sign_speed")?,
            slider: st::Sinusoid {
                amplitude: or(slider_amplitude, "slider_amplitude", 0.0)?,
                wavelength: or(slider_wavelength, "slider_wavelength", 1.0)?,
            },
            belt: st::Sinusoid {
                amplitude: or(belt_amplitude, "belt_amplitude", 0.0)?,
                wavelength: or(belt_wavelength, "belt_wavelength", 1.0)?,
            },
            nodes,
        };
        inner.validate().map_err(rs)?;
        Ok(Self { inner })
    }

    /// normal_force(x, y, time=0) -> float
    ///
    /// The layers' elastic normal force F_el,y (N) with the block at x (m),
    /// the profiles' mean lines at distance y (m; < 0: overlap), at time t
    /// (s).
    #[pyo3(signature = (x, y, time=None))]
    fn normal_force(
        &self,
        x: &Bound<'_, PyAny>,
        y: &Bound<'_, PyAny>,
        time: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<f64> {
        let x = asperity::error::check::finite("x", real(x, "x")?).map_err(rs)?;
        let y = asperity::error::check::finite("y", real(y, "y")?).map_err(rs)?;
        let t = real_opt(time, "time")?.unwrap_or(0.0);
        let t = asperity::error::check::finite("time", t).map_err(rs)?;
        Ok(self.inner.normal_force(x, y, t))
    }

    /// run(dt, steps, every=1, time=0, x=0, vx=0, y=0, vy=0) -> dict
    ///
    /// Runge–Kutta 4 from the state (t, x, ẋ, y, ẏ) for ``steps`` steps of
    /// ``dt`` (s), recording the start and every ``every``-th step: a dict
    /// of arrays ``time`` (s), ``x`` (m), ``vx`` (m/s), ``y`` (m), ``vy``
    /// (m/s), ``normal_force`` and ``friction_force`` (N).
    #[pyo3(signature = (dt, steps, every=None, time=None, x=None, vx=None, y=None, vy=None))]
    #[allow(clippy::too_many_arguments)]
    fn run(
        &self,
        py: Python<'_>,
        dt: &Bound<'_, PyAny>,
        steps: &Bound<'_, PyAny>,
        every: Option<&Bound<'_, PyAny>>,
        time: Option<&Bound<'_, PyAny>>,
        x: Option<&Bound<'_, PyAny>>,
        vx: Option<&Bound<'_, PyAny>>,
        y: Option<&Bound<'_, PyAny>>,
        vy: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        let small = |o: &Bound<'_, PyAny>, name: &str| -> PyResult<u32> {
            u32::try_from(count(o, name)?)
                .map_err(|_| crate::common::arg_error(name, "at most 4294967295"))
        };
        let steps = small(steps, "steps")?;
        let every = match every {
            Some(e) if !e.is_none() => small(e, "every")?,
            _ => 1,
        };
        let zero = |v: Option<&Bound<'_, PyAny>>, name: &str| -> PyResult<f64> {
            Ok(real_opt(v, name)?.unwrap_or(0.0))
        };
        let start = st::SliderState {
            time: zero(time, "time")?,
            x: zero(x, "x")?,
            vx: zero(vx, "vx")?,
            y: zero(y, "y")?,
            vy: zero(vy, "vy")?,
        };
        let dt = real(dt, "dt")?;
        let m = self.inner;
        let run = py.detach(|| m.run(start, dt, steps, every)).map_err(rs)?;
        let d = PyDict::new(py);
        let col = |f: fn(&st::SliderSample) -> f64| -> Vec<f64> { run.iter().map(f).collect() };
        d.set_item("time", numpy::PyArray1::from_vec(py, col(|s| s.state.time)))?;
        d.set_item("x", numpy::PyArray1::from_vec(py, col(|s| s.state.x)))?;
        d.set_item("vx", numpy::PyArray1::from_vec(py, col(|s| s.state.vx)))?;
        d.set_item("y", numpy::PyArray1::from_vec(py, col(|s| s.state.y)))?;
        d.set_item("vy", numpy::PyArray1::from_vec(py, col(|s| s.state.vy)))?;
        d.set_item(
            "normal_force",
            numpy::PyArray1::from_vec(py, col(|s| s.normal_force)),
        )?;
        d.set_item(
            "friction_force",
            numpy::PyArray1::from_vec(py, col(|s| s.friction_force)),
        )?;
        Ok(d.into_any().unbind())
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<HeightDistribution>()?;
    m.add_class::<GreenwoodWilliamson>()?;
    m.add_class::<BushGibsonThomas>()?;
    m.add_class::<BoraTopography>()?;
    m.add_class::<BorodichKryukova>()?;
    m.add_class::<KragelskyRods>()?;
    m.add_class::<BearingCurveRods>()?;
    m.add_class::<SergienkoBukharov>()?;
    m.add_class::<Zhuravlev>()?;
    m.add_class::<PowerLawAsperities>()?;
    m.add_function(wrap_pyfunction!(plasticity_index, m)?)?;
    m.add_function(wrap_pyfunction!(deformation_regime, m)?)?;
    m.add_function(wrap_pyfunction!(gaussian_tail_moment, m)?)?;
    Ok(())
}
