//! Materials and dimensionless groups (`asperity::material`).

use crate::common::{arg_error, real, rs, string};
use asperity::material as m;
use pyo3::prelude::*;

/// effective_modulus(e1, nu1, e2, nu2) -> float
///
/// Contact modulus E* (Pa) of two elastic solids:
/// 1/E* = (1 - nu1²)/e1 + (1 - nu2²)/e2. Young's moduli e1, e2 in Pa
/// (> 0, ``math.inf`` for a rigid body), Poisson's ratios nu1, nu2 in [0, 0.5].
#[pyfunction]
#[pyo3(signature = (e1, nu1, e2, nu2))]
fn effective_modulus(
    e1: &Bound<'_, PyAny>,
    nu1: &Bound<'_, PyAny>,
    e2: &Bound<'_, PyAny>,
    nu2: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    m::effective_modulus(
        real(e1, "e1")?,
        real(nu1, "nu1")?,
        real(e2, "e2")?,
        real(nu2, "nu2")?,
    )
    .map_err(rs)
}

/// rod_effective_modulus(e1, e2) -> float
///
/// Effective modulus (Pa) of two rods in series (thesis 6.2, uniaxial):
/// 1/E = 1/e1 + 1/e2, moduli in Pa (> 0, ``math.inf`` for a rigid rod).
#[pyfunction]
fn rod_effective_modulus(e1: &Bound<'_, PyAny>, e2: &Bound<'_, PyAny>) -> PyResult<f64> {
    m::rod_effective_modulus(real(e1, "e1")?, real(e2, "e2")?).map_err(rs)
}

/// no_slip_factor(nu) -> float
///
/// The no-slip (bonded) correction factor C_NS(nu) of a flat punch
/// (dimensionless, 1 at nu = 0.5), for Poisson's ratio nu in [0, 0.5].
#[pyfunction]
fn no_slip_factor(nu: &Bound<'_, PyAny>) -> PyResult<f64> {
    m::no_slip_factor(real(nu, "nu")?).map_err(rs)
}

/// no_slip_epsilon(nu) -> float
///
/// The oscillation index ε = ln(3 - 4nu)/(2π) of a bonded contact
/// (dimensionless), for Poisson's ratio nu in [0, 0.5].
#[pyfunction]
fn no_slip_epsilon(nu: &Bound<'_, PyAny>) -> PyResult<f64> {
    m::no_slip_epsilon(real(nu, "nu")?).map_err(rs)
}

/// tabor_parameter(radius, work_of_adhesion, e_star, equilibrium_separation) -> float
///
/// Tabor's parameter μ = (R w² / (E*² z0³))^(1/3) (dimensionless): radius R (m),
/// work of adhesion w (J/m²), contact modulus E* (Pa), equilibrium
/// separation z0 (m).
#[pyfunction]
fn tabor_parameter(
    radius: &Bound<'_, PyAny>,
    work_of_adhesion: &Bound<'_, PyAny>,
    e_star: &Bound<'_, PyAny>,
    equilibrium_separation: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    m::tabor_parameter(
        real(radius, "radius")?,
        real(work_of_adhesion, "work_of_adhesion")?,
        real(e_star, "e_star")?,
        real(equilibrium_separation, "equilibrium_separation")?,
    )
    .map_err(rs)
}

/// maugis_parameter(radius, work_of_adhesion, e_star, cohesive_stress) -> float
///
/// Maugis' parameter λ = 2σ0 (R/(π w K²))^(1/3), K = 4E*/3 (dimensionless):
/// radius R (m), work of adhesion w (J/m²), contact modulus E* (Pa),
/// Dugdale cohesive stress σ0 (Pa).
#[pyfunction]
fn maugis_parameter(
    radius: &Bound<'_, PyAny>,
    work_of_adhesion: &Bound<'_, PyAny>,
    e_star: &Bound<'_, PyAny>,
    cohesive_stress: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    m::maugis_parameter(
        real(radius, "radius")?,
        real(work_of_adhesion, "work_of_adhesion")?,
        real(e_star, "e_star")?,
        real(cohesive_stress, "cohesive_stress")?,
    )
    .map_err(rs)
}

/// lennard_jones_theoretical_stress(work_of_adhesion, equilibrium_separation) -> float
///
/// The Lennard-Jones 3-9 theoretical stress σ_th = 16w/(9√3 z0) (Pa), the
/// Dugdale stress that stands for it (thesis (1-44)): work of adhesion w
/// (J/m²), equilibrium separation z0 (m).
#[pyfunction]
fn lennard_jones_theoretical_stress(
    work_of_adhesion: &Bound<'_, PyAny>,
    equilibrium_separation: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    m::lennard_jones_theoretical_stress(
        real(work_of_adhesion, "work_of_adhesion")?,
        real(equilibrium_separation, "equilibrium_separation")?,
    )
    .map_err(rs)
}

/// maugis_over_tabor() -> float
///
/// λ/μ = 1.1570… (dimensionless) when σ0 is the Lennard-Jones theoretical stress.
#[pyfunction]
fn maugis_over_tabor() -> f64 {
    m::maugis_over_tabor()
}

/// jkr_k(e_star) -> float
///
/// K = 4E*/3 (Pa) of the JKR literature, for a contact modulus E* (Pa).
#[pyfunction]
fn jkr_k(e_star: &Bound<'_, PyAny>) -> PyResult<f64> {
    Ok(m::jkr_k(real(e_star, "e_star")?))
}

/// weir_surface_energy(atomic_mass, density, youngs_modulus, poisson_ratio, m=6.0, n=12.0, prefactor="plane_sum") -> float
///
/// Weir's surface energy γ (J/m²) from bulk properties: γ = K(m, n)·a·B with
/// a = (M/ρ)^(1/3) and B = E/(3(1 - 2ν)). atomic_mass M (kg per atom),
/// density ρ (kg/m³), youngs_modulus E (Pa), poisson_ratio ν in [0, 0.5),
/// exponents 2 < m < n of the Lennard-Jones m-n potential; prefactor
/// ``"plane_sum"`` (K = 1/((m-2)(n-2)), default) or ``"three_over_mn"``
/// (K = 3/(mn), the reading that reproduces seed 001's 8.6 nN).
#[pyfunction]
#[pyo3(signature = (atomic_mass, density, youngs_modulus, poisson_ratio, m=None, n=None, prefactor=None))]
fn weir_surface_energy(
    atomic_mass: &Bound<'_, PyAny>,
    density: &Bound<'_, PyAny>,
    youngs_modulus: &Bound<'_, PyAny>,
    poisson_ratio: &Bound<'_, PyAny>,
    m: Option<&Bound<'_, PyAny>>,
    n: Option<&Bound<'_, PyAny>>,
    prefactor: Option<&Bound<'_, PyAny>>,
) -> PyResult<f64> {
    let p = match prefactor {
        None => m::WeirPrefactor::PlaneSum,
        Some(p) => match string(p, "prefactor")?.as_str() {
            "plane_sum" => m::WeirPrefactor::PlaneSum,
            "three_over_mn" => m::WeirPrefactor::ThreeOverMn,
            s => {
                return Err(arg_error(
                    "prefactor",
                    format!("must be \"plane_sum\" or \"three_over_mn\", got {s:?}"),
                ))
            }
        },
    };
    let mm = match m {
        Some(v) => real(v, "m")?,
        None => 6.0,
    };
    let nn = match n {
        Some(v) => real(v, "n")?,
        None => 12.0,
    };
    m::weir_surface_energy(
        real(atomic_mass, "atomic_mass")?,
        real(density, "density")?,
        real(youngs_modulus, "youngs_modulus")?,
        real(poisson_ratio, "poisson_ratio")?,
        mm,
        nn,
        p,
    )
    .map_err(rs)
}

/// pair_work_of_adhesion(gamma1, gamma2, rule="geometric_mean") -> float
///
/// Work of adhesion w (J/m²) of two solids with surface energies gamma1,
/// gamma2 (J/m², ≥ 0): ``"geometric_mean"`` (Dupré with Girifalco–Good,
/// w = 2√(γ1γ2), default) or ``"seed001_difference"`` ((√γ1 - √γ2)², seed 001).
#[pyfunction]
#[pyo3(signature = (gamma1, gamma2, rule=None))]
fn pair_work_of_adhesion(
    gamma1: &Bound<'_, PyAny>,
    gamma2: &Bound<'_, PyAny>,
    rule: Option<&Bound<'_, PyAny>>,
) -> PyResult<f64> {
    let r = match rule {
        None => m::PairRule::GeometricMean,
        Some(r) => match string(r, "rule")?.as_str() {
            "geometric_mean" => m::PairRule::GeometricMean,
            "seed001_difference" => m::PairRule::Seed001Difference,
            s => {
                return Err(arg_error(
                    "rule",
                    format!("must be \"geometric_mean\" or \"seed001_difference\", got {s:?}"),
                ))
            }
        },
    };
    m::pair_work_of_adhesion(real(gamma1, "gamma1")?, real(gamma2, "gamma2")?, r).map_err(rs)
}

/// hamaker_work_of_adhesion(hamaker, separation) -> float
///
/// Work of adhesion W = A/(12π D0²) (J/m²) of two flats from the Hamaker
/// constant A (J) and the gap D0 (m).
#[pyfunction]
fn hamaker_work_of_adhesion(
    hamaker: &Bound<'_, PyAny>,
    separation: &Bound<'_, PyAny>,
) -> PyResult<f64> {
    m::hamaker_work_of_adhesion(real(hamaker, "hamaker")?, real(separation, "separation")?)
        .map_err(rs)
}

/// An isotropic elastic solid: Young's modulus (Pa, > 0 or ``math.inf`` for
/// a rigid body) and Poisson's ratio (in [0, 0.5]).
#[pyclass(module = "asperity", frozen)]
pub struct Material {
    pub inner: m::Material,
}

#[pymethods]
impl Material {
    #[new]
    fn new(youngs_modulus: &Bound<'_, PyAny>, poisson_ratio: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self {
            inner: m::Material::new(
                real(youngs_modulus, "youngs_modulus")?,
                real(poisson_ratio, "poisson_ratio")?,
            )
            .map_err(rs)?,
        })
    }
    /// Young's modulus E (Pa).
    #[getter]
    fn youngs_modulus(&self) -> f64 {
        self.inner.youngs_modulus
    }
    /// Poisson's ratio ν (dimensionless).
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.inner.poisson_ratio
    }
    /// contact_modulus(other) -> float
    ///
    /// The contact modulus E* (Pa) of this solid against ``other``.
    fn contact_modulus(&self, other: &Material) -> PyResult<f64> {
        self.inner.contact_modulus(&other.inner).map_err(rs)
    }
    fn __repr__(&self) -> String {
        format!(
            "Material(youngs_modulus={:e}, poisson_ratio={})",
            self.inner.youngs_modulus, self.inner.poisson_ratio
        )
    }
}

pub fn register(mdl: &Bound<'_, PyModule>) -> PyResult<()> {
    mdl.add_function(wrap_pyfunction!(effective_modulus, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(rod_effective_modulus, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(no_slip_factor, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(no_slip_epsilon, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(tabor_parameter, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(maugis_parameter, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(lennard_jones_theoretical_stress, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(maugis_over_tabor, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(jkr_k, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(weir_surface_energy, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(pair_work_of_adhesion, mdl)?)?;
    mdl.add_function(wrap_pyfunction!(hamaker_work_of_adhesion, mdl)?)?;
    mdl.add_class::<Material>()?;
    Ok(())
}
