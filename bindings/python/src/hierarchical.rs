//! Hierarchical roughness (thesis 5.4): Archard's spheres on spheres and
//! the contact of Cantor–Liu and Cantor–Borodich profiles, Schmittbuhl's
//! renormalised friction law.

use crate::common::{array, count, real, real_opt, rs, string, vectorize, vectorize_record};
use asperity::hierarchical::{
    archard_exponent as exponent, Archard, ArchardModel, CantorProfile, Schmittbuhl,
};
use pyo3::prelude::*;

fn parse_model(name: &str) -> PyResult<ArchardModel> {
    match name {
        "uniform" => Ok(ArchardModel::Uniform),
        "non_uniform" => Ok(ArchardModel::NonUniform),
        other => Err(crate::common::arg_error(
            "model",
            format!("{other:?}: \"uniform\" or \"non_uniform\""),
        )),
    }
}

/// archard_exponent(model, generations) -> float
///
/// The exponent a of Archard's A ∝ W^a (1957) for ``model`` ``"uniform"``
/// (Hertzian spheres of equal height: 2/3, 8/9, 26/27, …) or
/// ``"non_uniform"`` (the finest protuberances at distributed heights:
/// 4/5, 14/15, 44/45, …) with ``generations`` sphere radii.
#[pyfunction]
fn archard_exponent(model: &Bound<'_, PyAny>, generations: &Bound<'_, PyAny>) -> PyResult<f64> {
    let m = parse_model(&string(model, "model")?)?;
    exponent(m, count(generations, "generations")?).map_err(rs)
}

/// archard_area(model, radii, densities, contact_modulus, load) -> float | numpy.ndarray
///
/// Archard's real contact area A (m²) under the load W (N; a float or an
/// array): sphere radii R₁ > R₂ > … (m), densities η₂, η₃, … of each
/// generation on the last (1/m², one fewer), contact modulus E* (Pa).
#[pyfunction]
#[pyo3(signature = (model, radii, densities, contact_modulus, load))]
fn archard_area(
    py: Python<'_>,
    model: &Bound<'_, PyAny>,
    radii: &Bound<'_, PyAny>,
    densities: &Bound<'_, PyAny>,
    contact_modulus: &Bound<'_, PyAny>,
    load: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let m = parse_model(&string(model, "model")?)?;
    let r = array(radii, "radii")?;
    let d = array(densities, "densities")?;
    let a = Archard::new(m, r.as_slice()?, d.as_slice()?, real(contact_modulus, "contact_modulus")?)
        .map_err(rs)?;
    vectorize(py, load, "load", |w| a.area(w))
}

/// cantor_contact(descendants, width_ratio, height_ratio, base_width, base_height, generations, depth, stiffness=0, hardness=0) -> dict
///
/// A Cantor profile (p descendants r times as wide and q times as high per
/// generation; q = 1 Cantor–Liu, q < 1 Cantor–Borodich) pressed to the
/// depth δ (m below its highest tips; a float or an array) into a Winkler
/// foundation of stiffness κ (Pa/m) and a rigid-plastic one of hardness H
/// (Pa): ``width`` (m), ``winkler_load`` and ``plastic_load`` (N/m), per
/// unit length out of the plane.
#[pyfunction]
#[pyo3(signature = (descendants, width_ratio, height_ratio, base_width, base_height, generations, depth, stiffness=None, hardness=None))]
#[allow(clippy::too_many_arguments)]
fn cantor_contact(
    py: Python<'_>,
    descendants: &Bound<'_, PyAny>,
    width_ratio: &Bound<'_, PyAny>,
    height_ratio: &Bound<'_, PyAny>,
    base_width: &Bound<'_, PyAny>,
    base_height: &Bound<'_, PyAny>,
    generations: &Bound<'_, PyAny>,
    depth: &Bound<'_, PyAny>,
    stiffness: Option<&Bound<'_, PyAny>>,
    hardness: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let p = profile(
        descendants,
        width_ratio,
        height_ratio,
        base_width,
        base_height,
        generations,
    )?;
    let k = stiffness.map(|s| real(s, "stiffness")).transpose()?.unwrap_or(0.0);
    let h = hardness.map(|s| real(s, "hardness")).transpose()?.unwrap_or(0.0);
    vectorize_record(
        py,
        depth,
        "depth",
        ["width", "winkler_load", "plastic_load"],
        |d| {
            let c = p.contact(d, k, h)?;
            Ok([c.width, c.winkler_load, c.plastic_load])
        },
    )
}

/// cantor_exponents(descendants, width_ratio, height_ratio, base_width, base_height, generations) -> dict
///
/// ``fractal_dimension`` ln p/ln(1/r), ``width_exponent`` β = ln(pr)/ln q
/// (width ∝ depth^β; inf for Cantor–Liu) and ``load_area_exponent``
/// β/(1 + β) (width ∝ load^(β/(1+β)) on a Winkler foundation; 1 for
/// Cantor–Liu).
#[pyfunction]
fn cantor_exponents(
    py: Python<'_>,
    descendants: &Bound<'_, PyAny>,
    width_ratio: &Bound<'_, PyAny>,
    height_ratio: &Bound<'_, PyAny>,
    base_width: &Bound<'_, PyAny>,
    base_height: &Bound<'_, PyAny>,
    generations: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let p = profile(
        descendants,
        width_ratio,
        height_ratio,
        base_width,
        base_height,
        generations,
    )?;
    let d = pyo3::types::PyDict::new(py);
    d.set_item("fractal_dimension", p.fractal_dimension())?;
    d.set_item("width_exponent", p.width_exponent())?;
    d.set_item("load_area_exponent", p.load_area_exponent())?;
    Ok(d.into_any().unbind())
}

fn profile(
    descendants: &Bound<'_, PyAny>,
    width_ratio: &Bound<'_, PyAny>,
    height_ratio: &Bound<'_, PyAny>,
    base_width: &Bound<'_, PyAny>,
    base_height: &Bound<'_, PyAny>,
    generations: &Bound<'_, PyAny>,
) -> PyResult<CantorProfile> {
    let small = |n: usize, name: &str| {
        u32::try_from(n).map_err(|_| crate::common::arg_error(name, "too large"))
    };
    let p = CantorProfile {
        descendants: small(count(descendants, "descendants")?, "descendants")?,
        generations: small(count(generations, "generations")?, "generations")?,
        width_ratio: real(width_ratio, "width_ratio")?,
        height_ratio: real(height_ratio, "height_ratio")?,
        base_width: real(base_width, "base_width")?,
        base_height: real(base_height, "base_height")?,
    };
    p.check().map_err(rs)?;
    Ok(p)
}

/// schmittbuhl_run(mu_static=0.5, mu_kinetic=0.3, weakening_velocity=0.05, ratio=3, generations=3, dimension=3, mass=1e-5, coupling_stiffness=1e3, pulling_stiffness=1e3, normal_force=1.0, velocity=1e-4, disorder=0.5) -> list[dict]
///
/// Schmittbuhl, Vilotte and Roux's hierarchical model (1996, thesis 5.4.3):
/// the friction law of generation-0 blocks (static μ_s, kinetic μ_k at the
/// onset of slip, weakening μ_k/(1 + v/v_c), v_c in m/s, ``inf`` for none)
/// renormalised over ``generations`` generations, each a Burridge–Knopoff
/// chain of ``ratio`` blocks of the generation below, rescaled as an
/// elastic continuum of ``dimension`` 2 or 3 (block mass m₀ in kg, springs
/// k_c,0 and k_p,0 in N/m, normal force n₀ in N, plate velocity V in m/s,
/// pre-stress disorder δ in [0, 1)). One dict per generation 0…G:
/// ``index``, ``size`` (Nᵍ), ``mass`` (kg), ``coupling_stiffness`` and
/// ``pulling_stiffness`` (N/m), ``normal_force`` (N), ``mu_static``,
/// ``mu_kinetic``, ``weakening_velocity`` (m/s), ``kinetic_to_static``,
/// ``events`` (slip events of the chain run).
#[pyfunction]
#[pyo3(signature = (mu_static=None, mu_kinetic=None, weakening_velocity=None, ratio=None, generations=None, dimension=None, mass=None, coupling_stiffness=None, pulling_stiffness=None, normal_force=None, velocity=None, disorder=None))]
#[allow(clippy::too_many_arguments)]
fn schmittbuhl_run(
    py: Python<'_>,
    mu_static: Option<&Bound<'_, PyAny>>,
    mu_kinetic: Option<&Bound<'_, PyAny>>,
    weakening_velocity: Option<&Bound<'_, PyAny>>,
    ratio: Option<&Bound<'_, PyAny>>,
    generations: Option<&Bound<'_, PyAny>>,
    dimension: Option<&Bound<'_, PyAny>>,
    mass: Option<&Bound<'_, PyAny>>,
    coupling_stiffness: Option<&Bound<'_, PyAny>>,
    pulling_stiffness: Option<&Bound<'_, PyAny>>,
    normal_force: Option<&Bound<'_, PyAny>>,
    velocity: Option<&Bound<'_, PyAny>>,
    disorder: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let d = Schmittbuhl::default();
    let or = |v: Option<&Bound<'_, PyAny>>, name: &str, def: f64| -> PyResult<f64> {
        Ok(real_opt(v, name)?.unwrap_or(def))
    };
    let int = |v: Option<&Bound<'_, PyAny>>, name: &str, def: usize| -> PyResult<usize> {
        match v {
            Some(o) if !o.is_none() => count(o, name),
            _ => Ok(def),
        }
    };
    let model = Schmittbuhl {
        mu_static: or(mu_static, "mu_static", d.mu_static)?,
        mu_kinetic: or(mu_kinetic, "mu_kinetic", d.mu_kinetic)?,
        weakening_velocity: or(
            weakening_velocity,
            "weakening_velocity",
            d.weakening_velocity,
        )?,
        ratio: int(ratio, "ratio", d.ratio)?,
        generations: int(generations, "generations", d.generations)?,
        dimension: u32::try_from(int(dimension, "dimension", d.dimension as usize)?)
            .map_err(|_| crate::common::arg_error("dimension", "2 or 3"))?,
        mass: or(mass, "mass", d.mass)?,
        coupling_stiffness: or(
            coupling_stiffness,
            "coupling_stiffness",
            d.coupling_stiffness,
        )?,
        pulling_stiffness: or(pulling_stiffness, "pulling_stiffness", d.pulling_stiffness)?,
        normal_force: or(normal_force, "normal_force", d.normal_force)?,
        velocity: or(velocity, "velocity", d.velocity)?,
        disorder: or(disorder, "disorder", d.disorder)?,
    };
    let laws = py.detach(|| model.run()).map_err(rs)?;
    let out = pyo3::types::PyList::empty(py);
    for g in laws {
        let d = pyo3::types::PyDict::new(py);
        d.set_item("index", g.index)?;
        d.set_item("size", g.size)?;
        d.set_item("mass", g.mass)?;
        d.set_item("coupling_stiffness", g.coupling_stiffness)?;
        d.set_item("pulling_stiffness", g.pulling_stiffness)?;
        d.set_item("normal_force", g.normal_force)?;
        d.set_item("mu_static", g.mu_static)?;
        d.set_item("mu_kinetic", g.mu_kinetic)?;
        d.set_item("weakening_velocity", g.weakening_velocity)?;
        d.set_item("kinetic_to_static", g.ratio)?;
        d.set_item("events", g.events)?;
        out.append(d)?;
    }
    Ok(out.into_any().unbind())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(archard_exponent, m)?)?;
    m.add_function(wrap_pyfunction!(archard_area, m)?)?;
    m.add_function(wrap_pyfunction!(cantor_contact, m)?)?;
    m.add_function(wrap_pyfunction!(cantor_exponents, m)?)?;
    m.add_function(wrap_pyfunction!(schmittbuhl_run, m)?)?;
    Ok(())
}
