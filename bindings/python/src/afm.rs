//! AFM force–distance curves (`asperity::afm`): `analyze_afm` and
//! `read_afm_curve`.

use crate::common::{any_err, arg_error, array, real_opt, rs, string};
use asperity::afm;
use pyo3::prelude::*;

/// analyze_afm(source=None, *, position=None, force=None, deflection=None, retract_start=None, spring_constant=None, tip_radius=None, model="auto", position_column=None, z0=0.3e-9, tolerance=0.1) -> dict
///
/// Analyse an AFM force–distance curve as ``asperity afm --json`` does:
/// baselines (offset N, slope N/m), contact point (m), jump-in distance (m),
/// pull-off force (N, negative, from the baseline), adhesion energy (J), the
/// fits of Hertz, DMT, JKR, Maugis–Dugdale and the numerical Lennard-Jones
/// sphere (``"lj"``: tabulated, 1–4 s; ``"auto"`` fits it only when the
/// Maugis–Dugdale fit's λ = 1.157 μ lies between 0.1 and 5, and lists it in
/// ``skipped_fits`` otherwise) to the retract curve (E* Pa and
/// w J/m² with standard errors for a given ``tip_radius`` m, else E*·√R and
/// w·R), their Tabor parameters and rms residuals (N), the recommended model
/// and the flags. The curve is a file (``source``: the CSV format of
/// ``../shared/data/afm``) or the arrays ``position`` (m) and ``force`` (N,
/// positive repulsive) or ``deflection`` (m, times ``spring_constant``),
/// approach first; ``retract_start`` splits them (None: at the turning
/// point). ``spring_constant`` (N/m) overrides the file's. ``model``:
/// ``"auto"``, ``"hertz"``, ``"dmt"``, ``"jkr"``, ``"maugis_dugdale"`` or
/// ``"lj"``.
/// Returns the dict of the CLI's JSON (keys ``pull_off_force``,
/// ``jump_in_distance``, ``adhesion_energy``, ``baseline``,
/// ``contact_point``, ``fits``, ``recommended_model``, ``flags``, …).
#[pyfunction]
#[pyo3(signature = (source=None, *, position=None, force=None, deflection=None, retract_start=None, spring_constant=None, tip_radius=None, model=None, position_column=None, z0=None, tolerance=None))]
#[allow(clippy::too_many_arguments)]
fn analyze_afm(
    py: Python<'_>,
    source: Option<std::path::PathBuf>,
    position: Option<&Bound<'_, PyAny>>,
    force: Option<&Bound<'_, PyAny>>,
    deflection: Option<&Bound<'_, PyAny>>,
    retract_start: Option<usize>,
    spring_constant: Option<&Bound<'_, PyAny>>,
    tip_radius: Option<&Bound<'_, PyAny>>,
    model: Option<&Bound<'_, PyAny>>,
    position_column: Option<String>,
    z0: Option<&Bound<'_, PyAny>>,
    tolerance: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let k = real_opt(spring_constant, "spring_constant")?;
    let curve = match (source, position, force, deflection) {
        (Some(p), None, None, None) => afm::AfmCurve::read(&p, position_column.as_deref())
            .map_err(|e| any_err(format!("{}: {e}", p.display())))?,
        (None, Some(z), f, d) if f.is_some() != d.is_some() => {
            let z = array(z, "position")?.as_slice()?.to_vec();
            let f = match (f, d) {
                (Some(f), None) => array(f, "force")?.as_slice()?.to_vec(),
                (None, Some(d)) => {
                    let k = k.ok_or_else(|| {
                        arg_error("spring_constant", "needed to turn deflection into force")
                    })?;
                    let d = array(d, "deflection")?;
                    d.as_slice()?.iter().map(|x| x * k).collect()
                }
                _ => unreachable!(),
            };
            afm::AfmCurve::new(z, f, retract_start, k).map_err(rs)?
        }
        _ => {
            return Err(arg_error(
                "source",
                "give a file path, or position= (m) with force= (N) or deflection= (m)",
            ))
        }
    };
    let defaults = afm::AfmOptions::default();
    let models = match model {
        Some(m) if !m.is_none() => match string(m, "model")?.as_str() {
            "auto" => Vec::new(),
            name => vec![afm::AfmModel::from_name(name).ok_or_else(|| {
                arg_error(
                    "model",
                    format!("unknown model `{name}`: auto | hertz | dmt | jkr | maugis_dugdale | lj"),
                )
            })?],
        },
        _ => Vec::new(),
    };
    let options = afm::AfmOptions {
        tip_radius: real_opt(tip_radius, "tip_radius")?,
        spring_constant: k,
        models,
        equilibrium_separation: real_opt(z0, "z0")?.unwrap_or(defaults.equilibrium_separation),
        tolerance: real_opt(tolerance, "tolerance")?.unwrap_or(defaults.tolerance),
    };
    let r = py.detach(|| afm::analyze(&curve, &options)).map_err(rs)?;
    crate::common::json_value(py, &r.to_json())
}

/// read_afm_curve(path, position_column=None) -> dict
///
/// A measured AFM curve as arrays: ``position`` (m), ``force`` (N, raw,
/// positive repulsive), ``retract_start`` (index), ``spring_constant`` (N/m
/// or None) and ``position_column`` (name).
#[pyfunction]
#[pyo3(signature = (path, position_column=None))]
fn read_afm_curve(
    py: Python<'_>,
    path: std::path::PathBuf,
    position_column: Option<String>,
) -> PyResult<Py<PyAny>> {
    let c = afm::AfmCurve::read(&path, position_column.as_deref())
        .map_err(|e| any_err(format!("{}: {e}", path.display())))?;
    let d = pyo3::types::PyDict::new(py);
    d.set_item("position", numpy::PyArray1::from_vec(py, c.position))?;
    d.set_item("force", numpy::PyArray1::from_vec(py, c.force))?;
    d.set_item("retract_start", c.retract_start)?;
    d.set_item("spring_constant", c.spring_constant)?;
    d.set_item("position_column", c.position_column)?;
    Ok(d.into_any().unbind())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(analyze_afm, m)?)?;
    m.add_function(wrap_pyfunction!(read_afm_curve, m)?)?;
    Ok(())
}
