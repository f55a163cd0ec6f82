//! Friction (`asperity::friction`, `asperity::scene`): the dissipation
//! mechanisms and their ledger, the material of the friction model, and
//! scenes (the hierarchical slider and the dynamic models along its track)
//! with their results as arrays per step.

use crate::common::{any_err, arg_error, count, json_value, py_to_json, real, rs, string};
use asperity::friction as fr;
use asperity::scene::Scene;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// FrictionMaterial(yield_stress, youngs_modulus, poisson_ratio, bond_diameter, chemical_bond_energy, vdw_bond_energy, work_of_adhesion)
///
/// Slider and counter-surface of one material for the energy-dissipation
/// friction model: yield stress σ_y (Pa), Young's modulus E (Pa), Poisson's
/// ratio ν, bond diameter D_chem (m), energies of one chemical and one van
/// der Waals bond (J), work of adhesion W12 (J/m²); adhesive layer 5 nm,
/// threshold strain 0.10, areal density 1/D_chem². ``FrictionMaterial.copper()``
/// is the thesis's copper; ``FrictionMaterial.from_dict(d)`` sets every field
/// (the keys of ``to_dict()``).
#[pyclass(module = "asperity", frozen)]
pub struct FrictionMaterial {
    pub inner: fr::FrictionMaterial,
}

macro_rules! material_getters {
    ($($f:ident: $doc:literal),* ; { $($rest:tt)* }) => {
        #[pymethods]
        impl FrictionMaterial {
            $(
                #[doc = $doc]
                #[getter]
                fn $f(&self) -> f64 {
                    self.inner.$f
                }
            )*
            $($rest)*
        }
    };
}
material_getters!(
    yield_stress: "Yield stress σ_y (Pa).",
    youngs_modulus: "Young's modulus E of the slider (Pa).",
    poisson_ratio: "Poisson's ratio ν of the slider.",
    counter_youngs_modulus: "Young's modulus of the counter-surface (Pa).",
    counter_poisson_ratio: "Poisson's ratio of the counter-surface.",
    bond_diameter: "Bond diameter D_chem (m).",
    chemical_bond_energy: "Energy of one chemical bond (J).",
    vdw_bond_energy: "Energy of one van der Waals bond (J).",
    work_of_adhesion: "Work of adhesion W12 (J/m²).",
    adhesive_layer: "Thickness of the adhesive layer (m).",
    threshold_strain: "Threshold strain of the nano-asperities (dimensionless).",
    areal_density: "Areal density of bonds N_A (1/m²)." ; {
    #[new]
    #[allow(clippy::too_many_arguments)]
    fn new(
        yield_stress: &Bound<'_, PyAny>,
        youngs_modulus: &Bound<'_, PyAny>,
        poisson_ratio: &Bound<'_, PyAny>,
        bond_diameter: &Bound<'_, PyAny>,
        chemical_bond_energy: &Bound<'_, PyAny>,
        vdw_bond_energy: &Bound<'_, PyAny>,
        work_of_adhesion: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Ok(Self {
            inner: fr::FrictionMaterial::new(
                real(yield_stress, "yield_stress")?,
                real(youngs_modulus, "youngs_modulus")?,
                real(poisson_ratio, "poisson_ratio")?,
                real(bond_diameter, "bond_diameter")?,
                real(chemical_bond_energy, "chemical_bond_energy")?,
                real(vdw_bond_energy, "vdw_bond_energy")?,
                real(work_of_adhesion, "work_of_adhesion")?,
            )
            .map_err(rs)?,
        })
    }
    /// copper() -> FrictionMaterial
    ///
    /// Copper on copper, the thesis's worked example (σ_y = 276 MPa, E = 120
    /// GPa, ν = 0.355, D_chem = 2.56 Å, W12 = 0.10928 J/m²).
    #[staticmethod]
    fn copper() -> Self {
        Self { inner: fr::FrictionMaterial::copper() }
    }
    /// from_dict(d) -> FrictionMaterial
    ///
    /// A material from a dict with every field of ``to_dict()`` (SI).
    #[staticmethod]
    fn from_dict(d: &Bound<'_, PyAny>) -> PyResult<Self> {
        let inner: fr::FrictionMaterial = crate::common::from_py(d, "d")?;
        inner.validate().map_err(rs)?;
        Ok(Self { inner })
    }
    /// to_dict() -> dict
    ///
    /// Every field (SI).
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        crate::common::to_py_numbers(py, &self.inner)
    }
    /// e_star() -> float
    ///
    /// Contact modulus E* of slider and counter-surface (Pa).
    fn e_star(&self) -> PyResult<f64> {
        self.inner.e_star().map_err(rs)
    }
    /// c_ns() -> float
    ///
    /// No-slip factor C_NS of the pair (dimensionless).
    fn c_ns(&self) -> PyResult<f64> {
        self.inner.c_ns().map_err(rs)
    }
    fn __repr__(&self) -> String {
        format!("FrictionMaterial({:?})", self.inner)
    }
});

/// NanoAsperities(h_vdw, w_vdw, h_chem, w_chem, spacing)
///
/// The nano-asperities on a micro-rod's tip (thesis 6.2.1): heights and
/// widths (m) of the van der Waals and chemical parts and their spacing (m).
#[pyclass(module = "asperity", frozen)]
pub struct NanoAsperities {
    pub inner: fr::NanoAsperities,
}

#[pymethods]
impl NanoAsperities {
    #[new]
    fn new(
        h_vdw: &Bound<'_, PyAny>,
        w_vdw: &Bound<'_, PyAny>,
        h_chem: &Bound<'_, PyAny>,
        w_chem: &Bound<'_, PyAny>,
        spacing: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let inner = fr::NanoAsperities {
            h_vdw: real(h_vdw, "h_vdw")?,
            w_vdw: real(w_vdw, "w_vdw")?,
            h_chem: real(h_chem, "h_chem")?,
            w_chem: real(w_chem, "w_chem")?,
            spacing: real(spacing, "spacing")?,
        };
        inner.validate().map_err(rs)?;
        Ok(Self { inner })
    }
    /// to_dict() -> dict
    ///
    /// The five lengths (m).
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        crate::common::to_py_numbers(py, &self.inner)
    }
    /// height() -> float
    ///
    /// Total height h_vdw + h_chem (m).
    fn height(&self) -> f64 {
        self.inner.height()
    }
}

crate::scalar_fn!(bond_energy_from_molar, fr::mechanisms::bond_energy_from_molar, "bond_energy_from_molar(molar_energy) -> float\n\nEnergy of one bond (J) from a molar energy (J/mol).", (molar_energy));
crate::scalar_fn!(chemical_bond_count, fr::mechanisms::chemical_bond_count, "chemical_bond_count(w_chem, bond_diameter) -> float\n\nNumber of chemical bonds across a chemical contact of width w_chem (m) for bond diameter D (m).", (w_chem, bond_diameter));
crate::scalar_fn!(vdw_bond_count, fr::mechanisms::vdw_bond_count, "vdw_bond_count(w_vdw, bond_diameter) -> float\n\nNumber of van der Waals bonds across a contact of width w_vdw (m).", (w_vdw, bond_diameter));
crate::scalar_fn!(bond_dissipation_per_slip, fr::mechanisms::bond_dissipation_per_slip, "bond_dissipation_per_slip(count, bond_energy, bond_diameter) -> float\n\nEnergy dissipated per unit slip (J/m = N) by ``count`` bonds of energy U (J) broken every bond diameter D (m).", (count, bond_energy, bond_diameter));
crate::scalar_fn!(elastic_strain_energy, fr::mechanisms::elastic_strain_energy, "elastic_strain_energy(youngs_modulus, area, length, compression) -> float\n\nElastic energy E A c²/(2L) (J) of a rod of modulus E (Pa), cross-section A (m²) and length L (m) compressed by c (m).", (youngs_modulus, area, length, compression));
crate::scalar_fn!(released_elastic_energy, fr::mechanisms::released_elastic_energy, "released_elastic_energy(youngs_modulus, area, length, before, after) -> float\n\nElastic energy released (J) when a rod's compression falls from ``before`` to ``after`` (m).", (youngs_modulus, area, length, before, after));
crate::scalar_fn!(plastic_work, fr::mechanisms::plastic_work, "plastic_work(yield_stress, plastic_strain, deformed_volume) -> float\n\nPlastic work σ_y ε_p V (J): yield stress (Pa), plastic strain, deformed volume (m³).", (yield_stress, plastic_strain, deformed_volume));

pub(crate) fn cof_form(obj: Option<&Bound<'_, PyAny>>) -> PyResult<fr::CofForm> {
    let Some(o) = obj else {
        return Ok(fr::CofForm::default());
    };
    match string(o, "form")?.as_str() {
        "amontons" => Ok(fr::CofForm::Amontons),
        "coulomb" => Ok(fr::CofForm::Coulomb),
        "derjaguin" => Ok(fr::CofForm::Derjaguin),
        "derjaguin_double_adhesion" => Ok(fr::CofForm::DerjaguinDoubleAdhesion),
        x => Err(arg_error(
            "form",
            format!("must be \"amontons\", \"coulomb\", \"derjaguin\" or \"derjaguin_double_adhesion\", got {x:?}"),
        )),
    }
}

/// coefficient_of_friction(friction_force, normal_load, adhesion=0.0, form="amontons") -> float
///
/// μ from friction force F (N), normal load N (N) and adhesive force A (N):
/// ``"amontons"`` F/N, ``"coulomb"`` (F - A)/N, ``"derjaguin"`` F/(N + A),
/// ``"derjaguin_double_adhesion"`` F/(N + 2A) (the arithmetic of thesis
/// Tables 6-1 and 6-2, not its stated form).
#[pyfunction]
#[pyo3(signature = (friction_force, normal_load, adhesion=None, form=None))]
fn coefficient_of_friction(
    friction_force: &Bound<'_, PyAny>,
    normal_load: &Bound<'_, PyAny>,
    adhesion: Option<&Bound<'_, PyAny>>,
    form: Option<&Bound<'_, PyAny>>,
) -> PyResult<f64> {
    fr::coefficient_of_friction(
        cof_form(form)?,
        real(friction_force, "friction_force")?,
        real(normal_load, "normal_load")?,
        crate::common::real_opt(adhesion, "adhesion")?.unwrap_or(0.0),
    )
    .map_err(rs)
}

fn mechanisms(obj: Option<&Bound<'_, PyAny>>) -> PyResult<fr::Mechanisms> {
    let Some(o) = obj else {
        return Ok(fr::Mechanisms::all());
    };
    let names: Vec<String> = o.extract().map_err(|_| {
        arg_error(
            "mechanisms",
            "must be a list of \"chemical\", \"van_der_waals\", \"elastic\", \"plastic\"",
        )
    })?;
    let mut m = fr::Mechanisms::none();
    for n in names {
        match n.as_str() {
            "chemical" => m.chemical = true,
            "van_der_waals" => m.van_der_waals = true,
            "elastic" => m.elastic = true,
            "plastic" => m.plastic = true,
            x => return Err(arg_error("mechanisms", format!("unknown mechanism {x:?}: must be \"chemical\", \"van_der_waals\", \"elastic\" or \"plastic\""))),
        }
    }
    Ok(m)
}

/// ledger_step(material, nano, n_contact, slip, plastic_work=0.0, released_elastic=0.0, mechanisms=None) -> dict
///
/// The energy ledger of one increment (thesis 4.1): ``n_contact``
/// nano-asperities in contact slip by ``slip`` (m), with the plastic work
/// and released elastic energy of the rods (J); ``mechanisms`` a list of
/// ``"chemical"``, ``"van_der_waals"``, ``"elastic"``, ``"plastic"`` (all by
/// default). Returns ``dissipation`` (J, by mechanism), ``friction_force``
/// F = ΔU/Δx (N) and ``adhesion`` (N).
#[pyfunction]
#[pyo3(signature = (material, nano, n_contact, slip, plastic_work=None, released_elastic=None, mechanisms=None))]
#[allow(clippy::too_many_arguments)]
fn ledger_step(
    py: Python<'_>,
    material: &FrictionMaterial,
    nano: &NanoAsperities,
    n_contact: &Bound<'_, PyAny>,
    slip: &Bound<'_, PyAny>,
    plastic_work: Option<&Bound<'_, PyAny>>,
    released_elastic: Option<&Bound<'_, PyAny>>,
    mechanisms: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let s = fr::ledger_step_for(
        &material.inner,
        &nano.inner,
        self::mechanisms(mechanisms)?,
        count(n_contact, "n_contact")?,
        real(slip, "slip")?,
        crate::common::real_opt(plastic_work, "plastic_work")?.unwrap_or(0.0),
        crate::common::real_opt(released_elastic, "released_elastic")?.unwrap_or(0.0),
    )
    .map_err(rs)?;
    crate::common::to_py_numbers(py, &s)
}

/// apparent_friction(material, nano, nano_count, external_force) -> dict
///
/// The apparent friction of ``nano_count`` nano-asperities pressed by
/// ``external_force`` (N) (thesis 4.4): bond counts, holding forces (N),
/// chemical and van der Waals forces (N), friction force (N), ``cof``, shares.
#[pyfunction]
fn apparent_friction(
    py: Python<'_>,
    material: &FrictionMaterial,
    nano: &NanoAsperities,
    nano_count: &Bound<'_, PyAny>,
    external_force: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let a = fr::apparent_friction(
        &material.inner,
        &nano.inner,
        count(nano_count, "nano_count")?,
        real(external_force, "external_force")?,
    )
    .map_err(rs)?;
    crate::common::to_py_numbers(py, &a)
}

/// single_rod(material, nano) -> dict
///
/// ``apparent_friction`` of one nano-asperity under the single-rod load of
/// the thesis (4.4).
#[pyfunction]
fn single_rod(
    py: Python<'_>,
    material: &FrictionMaterial,
    nano: &NanoAsperities,
) -> PyResult<Py<PyAny>> {
    crate::common::to_py_numbers(
        py,
        &fr::single_rod(&material.inner, &nano.inner).map_err(rs)?,
    )
}

// --------------------------------------------------------------------------
// Scenes
// --------------------------------------------------------------------------

/// The result of ``run_scene``: ``summary`` (dict, the keys of ``asperity
/// slide --json``: ``mean_cof``, ``mean_friction_force`` N, ``normal_load``
/// N, ``dissipation`` J by mechanism, ``mean_true_contact_area`` m², …,
/// ``files`` = [] and, when the scene has dynamic models,
/// ``friction_models``), ``steps`` (dict of arrays, one element per
/// increment, the columns of the CLI's CSV in SI: ``position``,
/// ``rod_position``, ``normal_load``, ``friction_force``, ``cof``,
/// ``no_contact``, ``adhesion``, ``chemical``, ``van_der_waals``,
/// ``elastic``, ``plastic``, ``true_contact_area``, ``adhesion_area_share``,
/// ``nano_contacts``, ``adhesive_contacts``, ``rods_in_contact``,
/// ``yielded_rods``) and ``models`` (list of dicts per dynamic model:
/// ``name``, ``model``, ``summary``, ``steps`` dict of arrays).
#[pyclass(module = "asperity", frozen, get_all)]
pub struct SceneRun {
    summary: Py<PyAny>,
    steps: Py<PyDict>,
    models: Py<PyList>,
}

#[pymethods]
impl SceneRun {
    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "SceneRun(<{} steps>, {} models)",
            self.steps
                .bind(py)
                .get_item("cof")
                .ok()
                .flatten()
                .map(|a| a.len().unwrap_or(0))
                .unwrap_or(0),
            self.models.bind(py).len()
        )
    }
}

pub(crate) fn load_scene(
    scene: &Bound<'_, PyAny>,
    base: Option<std::path::PathBuf>,
) -> PyResult<Scene> {
    if scene.is_instance_of::<PyDict>() {
        let text = py_to_json(scene)?;
        let base = base.unwrap_or_else(|| std::path::PathBuf::from("."));
        return Scene::from_json(&text, base).map_err(any_err);
    }
    if let Ok(p) = scene.extract::<std::path::PathBuf>() {
        return Scene::from_file(&p).map_err(any_err);
    }
    Err(arg_error(
        "scene",
        "must be a path to a JSON scene or a dict",
    ))
}

/// run_scene(scene, base=None) -> SceneRun
///
/// Run a sliding scene as ``asperity slide SCENE --json`` does: ``scene`` is
/// the path of a JSON scene (relative paths inside resolve against its
/// folder) or a dict of the same content (relative paths against ``base``,
/// default the current directory). Slides the hierarchical slider over the
/// counter-surface, then steps the scene's dynamic friction models along the
/// same track. The GIL is released during the run.
#[pyfunction]
#[pyo3(signature = (scene, base=None))]
fn run_scene(
    py: Python<'_>,
    scene: &Bound<'_, PyAny>,
    base: Option<std::path::PathBuf>,
) -> PyResult<SceneRun> {
    let scene = load_scene(scene, base)?;
    let (run, tracks) = py
        .detach(|| -> Result<_, String> {
            let slider = scene.build().map_err(|e| e.to_string())?;
            let run = slider
                .slide(scene.sliding.distance, scene.sliding.step)
                .map_err(|e| e.to_string())?;
            let tracks = scene.run_friction_models(&run).map_err(|e| e.to_string())?;
            Ok((run, tracks))
        })
        .map_err(any_err)?;
    let summary = json_value(py, &scene.summary_json(&run, &tracks).to_string())?;
    let steps = step_columns(py, &run.steps)?;
    let models = PyList::empty(py);
    for (spec, t) in scene.friction_models.iter().zip(&tracks) {
        let m = PyDict::new(py);
        m.set_item("name", &spec.name)?;
        m.set_item("model", spec.model.key())?;
        m.set_item("summary", crate::common::to_py_numbers(py, &t.summary)?)?;
        m.set_item(
            "steps",
            columns(py, &serde_json::to_value(&t.steps).map_err(any_err)?)?,
        )?;
        models.append(m)?;
    }
    Ok(SceneRun {
        summary,
        steps: steps.unbind(),
        models: models.unbind(),
    })
}

/// The records of a slide as a dict of arrays (the columns of the CLI's CSV).
pub(crate) fn step_columns<'py>(
    py: Python<'py>,
    st: &[fr::SlideStep],
) -> PyResult<Bound<'py, PyDict>> {
    let steps = PyDict::new(py);
    let col =
        |f: &dyn Fn(&fr::SlideStep) -> f64| PyArray1::from_vec(py, st.iter().map(f).collect());
    let icol =
        |f: &dyn Fn(&fr::SlideStep) -> i64| PyArray1::from_vec(py, st.iter().map(f).collect());
    steps.set_item("position", col(&|r| r.position))?;
    steps.set_item("rod_position", col(&|r| r.rod_position))?;
    steps.set_item("normal_load", col(&|r| r.normal_load))?;
    steps.set_item("friction_force", col(&|r| r.friction_force))?;
    steps.set_item("cof", col(&|r| r.cof))?;
    steps.set_item(
        "no_contact",
        PyArray1::from_vec(py, st.iter().map(|r| r.no_contact).collect()),
    )?;
    steps.set_item("adhesion", col(&|r| r.adhesion))?;
    steps.set_item("chemical", col(&|r| r.dissipation.chemical))?;
    steps.set_item("van_der_waals", col(&|r| r.dissipation.van_der_waals))?;
    steps.set_item("elastic", col(&|r| r.dissipation.elastic))?;
    steps.set_item("plastic", col(&|r| r.dissipation.plastic))?;
    steps.set_item("true_contact_area", col(&|r| r.true_contact_area))?;
    steps.set_item("adhesion_area_share", col(&|r| r.adhesion_area_share))?;
    steps.set_item("nano_contacts", icol(&|r| r.nano_contacts as i64))?;
    steps.set_item("adhesive_contacts", icol(&|r| r.adhesive_contacts as i64))?;
    steps.set_item("rods_in_contact", icol(&|r| r.rods_in_contact as i64))?;
    steps.set_item("yielded_rods", icol(&|r| r.yielded_rods as i64))?;
    Ok(steps)
}

/// A JSON array of flat objects as a dict of numpy arrays (numbers) or
/// lists (anything else), one entry per key.
fn columns<'py>(py: Python<'py>, v: &serde_json::Value) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let Some(rows) = v.as_array() else {
        return Ok(d);
    };
    let Some(first) = rows.first().and_then(|r| r.as_object()) else {
        return Ok(d);
    };
    for key in first.keys() {
        let vals: Vec<&serde_json::Value> = rows.iter().map(|r| &r[key]).collect();
        if vals.iter().all(|x| x.is_number()) {
            d.set_item(
                key,
                PyArray1::from_vec(
                    py,
                    vals.iter()
                        .map(|x| x.as_f64().unwrap_or(f64::NAN))
                        .collect(),
                ),
            )?;
        } else if vals.iter().all(|x| x.is_boolean()) {
            d.set_item(
                key,
                PyArray1::from_vec(
                    py,
                    vals.iter().map(|x| x.as_bool().unwrap_or(false)).collect(),
                ),
            )?;
        } else {
            let l = PyList::empty(py);
            for x in vals {
                l.append(json_value(py, &x.to_string())?)?;
            }
            d.set_item(key, l)?;
        }
    }
    Ok(d)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<FrictionMaterial>()?;
    m.add_class::<NanoAsperities>()?;
    m.add_class::<SceneRun>()?;
    for f in [
        wrap_pyfunction!(bond_energy_from_molar, m)?,
        wrap_pyfunction!(chemical_bond_count, m)?,
        wrap_pyfunction!(vdw_bond_count, m)?,
        wrap_pyfunction!(bond_dissipation_per_slip, m)?,
        wrap_pyfunction!(elastic_strain_energy, m)?,
        wrap_pyfunction!(released_elastic_energy, m)?,
        wrap_pyfunction!(plastic_work, m)?,
        wrap_pyfunction!(coefficient_of_friction, m)?,
        wrap_pyfunction!(ledger_step, m)?,
        wrap_pyfunction!(apparent_friction, m)?,
        wrap_pyfunction!(single_rod, m)?,
        wrap_pyfunction!(run_scene, m)?,
    ] {
        m.add_function(f)?;
    }
    Ok(())
}
