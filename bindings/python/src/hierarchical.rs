//! Hierarchical roughness (thesis 5.4): Archard's spheres on spheres and
//! the contact of Cantor–Liu and Cantor–Borodich profiles.

use crate::common::{array, count, real, rs, string, vectorize, vectorize_record};
use asperity::hierarchical::{archard_exponent as exponent, Archard, ArchardModel, CantorProfile};
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

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(archard_exponent, m)?)?;
    m.add_function(wrap_pyfunction!(archard_area, m)?)?;
    m.add_function(wrap_pyfunction!(cantor_contact, m)?)?;
    m.add_function(wrap_pyfunction!(cantor_exponents, m)?)?;
    Ok(())
}
