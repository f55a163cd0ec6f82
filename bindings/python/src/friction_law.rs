//! The friction step (`asperity::friction::FrictionLaw`): one Python base
//! class for every friction law — the homogenised law, the hierarchical
//! slider as a patch law and the chapter-5 dynamic models — with the
//! per-increment step on numpy state arrays and its block form over n points.

use crate::common::{any_err, arg_error, array, real, real_opt, rs, to_py_numbers as to_py_value};
use asperity::friction::dynamic::DynamicModel;
use asperity::friction::{
    self as fr, BlockStates, FrictionBlock, FrictionIncrement, FrictionLaw as RsLaw, FrictionWork,
};
use asperity::scene::models::DynamicModelSpec;
use numpy::{PyArray1, PyArray2, PyArray3, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::sync::{Arc, Mutex};

/// What a subclass holds besides the law (its own methods need the concrete type).
enum Concrete {
    Homogenised(Arc<fr::HomogenisedFriction>),
    Slider(Arc<fr::Slider>),
    Dynamic(Arc<DynamicModel>),
}

/// A friction law stepped once per time increment of a host code (the Rust
/// trait ``FrictionLaw``): ``step`` (one point: old state in, response and
/// new state out), ``step_in_place`` and ``step_block`` (n points at once,
/// the shape of Abaqus/Explicit VFRIC). A state is a float64 numpy array of
/// ``state_len`` values, all zero when fresh: ``[D, S, law…]`` with the
/// accumulated dissipation D (J) and slip path S (m) first. Instances are
/// ``HomogenisedFriction``, ``Slider`` and the dynamic models (``LuGre``,
/// ``MaxwellSlip``, ``GeneralizedMaxwellSlip``, ``PrandtlTomlinson``,
/// ``BurridgeKnopoff``, ``Bristles``, or ``friction_model(spec)``). Immutable; share it between threads (the
/// GIL is released during steps).
#[pyclass(module = "asperity", frozen, subclass, name = "FrictionLaw")]
pub struct PyFrictionLaw {
    law: Arc<dyn RsLaw>,
    concrete: Concrete,
    works: Mutex<Vec<FrictionWork>>,
}

impl PyFrictionLaw {
    fn new(law: Arc<dyn RsLaw>, concrete: Concrete) -> Self {
        Self {
            law,
            concrete,
            works: Mutex::new(Vec::new()),
        }
    }

    /// A scratch work from the pool (or a new one), returned by `put`.
    fn take(&self) -> FrictionWork {
        self.works
            .lock()
            .ok()
            .and_then(|mut w| w.pop())
            .unwrap_or_else(|| self.law.work())
    }

    fn put(&self, w: FrictionWork) {
        if let Ok(mut v) = self.works.lock() {
            if v.len() < 64 {
                v.push(w);
            }
        }
    }
}

/// The response of one friction increment (SI).
///
/// ``force`` (N, 2 components, opposing slip), ``force_magnitude`` (N),
/// ``normal_force`` (N), ``cof``, ``adhesion`` (N), ``true_contact_area``
/// (m²), ``dissipated`` (J, this increment), ``dissipation`` (J by mechanism:
/// ``chemical``, ``van_der_waals``, ``elastic``, ``plastic``),
/// ``stored_energy`` (J), ``dforce_dnormal`` (2), ``dforce_dslip`` (2×2, N/m),
/// ``regime`` (0 stick, 1 partial slip, 2 slip, 3 no contact),
/// ``regime_name``, ``tangents`` (bits computed), and for a ``Slider``
/// ``record`` (the step's full record: position, rod position, contact
/// counts …; None otherwise).
#[pyclass(module = "asperity", frozen)]
pub struct FrictionResponse {
    r: fr::FrictionResponse,
    record: Option<fr::SlideStep>,
}

#[pymethods]
impl FrictionResponse {
    /// Tangential force F (N), 2 components.
    #[getter]
    fn force<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.r.force)
    }
    /// |F| (N).
    #[getter]
    fn force_magnitude(&self) -> f64 {
        self.r.force_magnitude
    }
    /// Normal force N (N).
    #[getter]
    fn normal_force(&self) -> f64 {
        self.r.normal_force
    }
    /// Coefficient of friction of the increment (0 when undefined).
    #[getter]
    fn cof(&self) -> f64 {
        self.r.cof
    }
    /// Adhesive holding force A (N).
    #[getter]
    fn adhesion(&self) -> f64 {
        self.r.adhesion
    }
    /// True contact area (m²).
    #[getter]
    fn true_contact_area(&self) -> f64 {
        self.r.true_contact_area
    }
    /// Energy dissipated in the increment (J).
    #[getter]
    fn dissipated(&self) -> f64 {
        self.r.dissipated
    }
    /// The increment's dissipation by mechanism (J).
    #[getter]
    fn dissipation(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        to_py_value(py, &self.r.dissipation)
    }
    /// Elastic energy stored in the law at the end of the increment (J).
    #[getter]
    fn stored_energy(&self) -> f64 {
        self.r.stored_energy
    }
    /// ∂F/∂N (dimensionless, 2 components), when computed.
    #[getter]
    fn dforce_dnormal<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.r.dforce_dnormal)
    }
    /// ∂F_i/∂Δs_j (N/m, 2×2), when computed.
    #[getter]
    fn dforce_dslip<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let d = self.r.dforce_dslip;
        PyArray1::from_slice(py, &[d[0][0], d[0][1], d[1][0], d[1][1]]).reshape([2, 2])
    }
    /// Regime: 0 stick, 1 partial slip, 2 slip, 3 no contact.
    #[getter]
    fn regime(&self) -> i32 {
        self.r.regime
    }
    /// ``"stick"``, ``"partial_slip"``, ``"slip"`` or ``"no_contact"``.
    #[getter]
    fn regime_name(&self) -> &'static str {
        match self.r.regime() {
            fr::FrictionRegime::Stick => "stick",
            fr::FrictionRegime::PartialSlip => "partial_slip",
            fr::FrictionRegime::Slip => "slip",
            fr::FrictionRegime::NoContact => "no_contact",
        }
    }
    /// The tangents computed (bits TANGENT_NORMAL | TANGENT_SLIP).
    #[getter]
    fn tangents(&self) -> i32 {
        self.r.tangents
    }
    /// A slider step's full record (dict), None for other laws.
    #[getter]
    fn record(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.record {
            Some(r) => to_py_value(py, r),
            None => Ok(py.None()),
        }
    }
    fn __repr__(&self) -> String {
        format!(
            "FrictionResponse(force=[{:e}, {:e}], cof={}, dissipated={:e}, regime={})",
            self.r.force[0],
            self.r.force[1],
            self.r.cof,
            self.r.dissipated,
            self.regime_name()
        )
    }
}

/// The arrays of a block step: ``tangential_force`` (n×2, N),
/// ``dissipation`` (n, J, this increment), ``state`` (n×state_len, the
/// new states; the input array itself when stepped in place), ``regime``
/// (n, int32: 0 stick, 1 partial slip, 2 slip, 3 no contact),
/// ``stored_energy`` (n, J), ``dforce_dslip`` (n×2×2, N/m,
/// ``[i, a, b]`` = ∂F_a/∂Δs_b of point i) and ``dforce_dnormal`` (n×2,
/// dimensionless); the tangents are zeros unless asked for (``tangents``).
#[pyclass(module = "asperity", frozen, get_all)]
pub struct FrictionBlockResponse {
    tangential_force: Py<PyArray2<f64>>,
    dissipation: Py<PyArray1<f64>>,
    state: Py<PyAny>,
    regime: Py<PyArray1<i32>>,
    stored_energy: Py<PyArray1<f64>>,
    dforce_dslip: Py<PyArray3<f64>>,
    dforce_dnormal: Py<PyArray2<f64>>,
}

fn slip_arg(obj: Option<&Bound<'_, PyAny>>) -> PyResult<[f64; 2]> {
    let Some(o) = obj else { return Ok([0.0, 0.0]) };
    if let Ok(v) = real(o, "slip") {
        return Ok([v, 0.0]);
    }
    let a = array(o, "slip")?;
    let s = a.as_slice()?;
    match s.len() {
        1 => Ok([s[0], 0.0]),
        2 => Ok([s[0], s[1]]),
        n => Err(arg_error(
            "slip",
            format!("must be a float or 2 components (m), got {n} values"),
        )),
    }
}

fn increment(
    normal_force: Option<&Bound<'_, PyAny>>,
    slip: Option<&Bound<'_, PyAny>>,
    dt: Option<&Bound<'_, PyAny>>,
    area: Option<&Bound<'_, PyAny>>,
    tangents: i32,
) -> PyResult<FrictionIncrement> {
    Ok(FrictionIncrement {
        normal_force: real_opt(normal_force, "normal_force")?.unwrap_or(0.0),
        area: real_opt(area, "area")?.unwrap_or(0.0),
        slip: slip_arg(slip)?,
        dt: real_opt(dt, "dt")?.unwrap_or(0.0),
        tangents,
        reserved: 0,
    })
}

/// A state argument: a 1-D float64 C-contiguous array (or None: fresh).
fn state_vec(obj: Option<&Bound<'_, PyAny>>, n: usize, name: &str) -> PyResult<Vec<f64>> {
    match obj {
        None => Ok(vec![0.0; n]),
        Some(o) if o.is_none() => Ok(vec![0.0; n]),
        Some(o) => {
            let a = array(o, name)?;
            let s = a.as_slice()?;
            if s.len() != n {
                return Err(arg_error(
                    name,
                    format!("must have state_len = {n} values, got {}", s.len()),
                ));
            }
            Ok(s.to_vec())
        }
    }
}

/// A writable C-contiguous float64 array of `len` values (any shape).
fn writable<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
    len: usize,
) -> PyResult<numpy::PyReadwriteArrayDyn<'py, f64>> {
    let a = obj
        .cast::<numpy::PyArrayDyn<f64>>()
        .map_err(|_| arg_error(name, "must be a float64 numpy array"))?;
    if !a.is_c_contiguous() {
        return Err(arg_error(
            name,
            "must be a C-contiguous array (got a strided view; use numpy.ascontiguousarray)",
        ));
    }
    if a.len() != len {
        return Err(arg_error(
            name,
            format!("must have {len} values, got {}", a.len()),
        ));
    }
    a.try_readwrite()
        .map_err(|e| arg_error(name, format!("cannot be written: {e}")))
}

fn readonly_any<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
    len: usize,
) -> PyResult<numpy::PyReadonlyArrayDyn<'py, f64>> {
    let a =
        obj.cast::<numpy::PyArrayDyn<f64>>()
            .map_err(|_| match obj.cast::<PyUntypedArray>() {
                Ok(u) => arg_error(
                    name,
                    format!("must be a float64 array, got dtype {}", u.dtype()),
                ),
                Err(_) => arg_error(name, "must be a float64 numpy array"),
            })?;
    if !a.is_c_contiguous() {
        return Err(arg_error(
            name,
            "must be a C-contiguous array (got a strided view; use numpy.ascontiguousarray)",
        ));
    }
    if a.len() != len {
        return Err(arg_error(
            name,
            format!("must have {len} values, got {}", a.len()),
        ));
    }
    a.try_readonly()
        .map_err(|e| arg_error(name, format!("cannot be read: {e}")))
}

fn batch_err(e: asperity::contact::BatchError) -> PyErr {
    crate::common::batch(e)
}

#[pymethods]
impl PyFrictionLaw {
    /// Doubles of one point's state.
    #[getter]
    fn state_len(&self) -> usize {
        self.law.state_len()
    }
    /// Whether a non-zero slip needs dt > 0.
    #[getter]
    fn rate_dependent(&self) -> bool {
        self.law.rate_dependent()
    }
    /// fresh_state(n=None) -> numpy.ndarray
    ///
    /// A fresh (all-zero) state of ``state_len`` values, or n of them as an
    /// (n, state_len) array for ``step_block``.
    #[pyo3(signature = (n=None))]
    fn fresh_state<'py>(&self, py: Python<'py>, n: Option<usize>) -> PyResult<Bound<'py, PyAny>> {
        let m = self.law.state_len();
        Ok(match n {
            None => PyArray1::<f64>::zeros(py, m, false).into_any(),
            Some(n) => PyArray2::<f64>::zeros(py, [n, m], false).into_any(),
        })
    }
    /// step(old_state=None, *, normal_force, slip=0.0, dt=0.0, area=0.0, tangents=0) -> (FrictionResponse, numpy.ndarray)
    ///
    /// One increment of one point from ``old_state`` (``state_len`` values,
    /// None = fresh; not modified): normal force N (N, ≥ 0), slip increment
    /// Δs (m; a float along x or 2 components), time increment dt (s),
    /// nominal area A_n (m², > 0 for the homogenised law), ``tangents``
    /// (0, or TANGENT_NORMAL | TANGENT_SLIP). Returns the response and the
    /// new state. The same old state and increment give bit-identical
    /// results.
    #[pyo3(signature = (old_state=None, *, normal_force=None, slip=None, dt=None, area=None, tangents=0))]
    #[allow(clippy::too_many_arguments)]
    fn step<'py>(
        &self,
        py: Python<'py>,
        old_state: Option<&Bound<'py, PyAny>>,
        normal_force: Option<&Bound<'py, PyAny>>,
        slip: Option<&Bound<'py, PyAny>>,
        dt: Option<&Bound<'py, PyAny>>,
        area: Option<&Bound<'py, PyAny>>,
        tangents: i32,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let inc = increment(normal_force, slip, dt, area, tangents)?;
        let m = self.law.state_len();
        let old = state_vec(old_state, m, "old_state")?;
        let mut new = vec![0.0; m];
        let mut w = self.take();
        let slider = matches!(self.concrete, Concrete::Slider(_));
        let res = py.detach(|| {
            self.law.step(&old, &mut new, &inc, &mut w).map(|r| {
                let rec = if slider {
                    w.get::<fr::SliderWork>().map(|s| *s.record())
                } else {
                    None
                };
                (r, rec)
            })
        });
        self.put(w);
        let (r, record) = res.map_err(|e| rs(crate::common::renamed(e, "old", "old_state")))?;
        let resp = Py::new(py, FrictionResponse { r, record })?;
        PyTuple::new(
            py,
            [
                resp.into_any(),
                PyArray1::from_vec(py, new).into_any().unbind(),
            ],
        )
    }
    /// step_in_place(state, *, normal_force, slip=0.0, dt=0.0, area=0.0, tangents=0) -> FrictionResponse
    ///
    /// ``step`` with ``state`` (a writable float64 array of ``state_len``
    /// values) updated in place; on error it is left as it was.
    #[pyo3(signature = (state, *, normal_force=None, slip=None, dt=None, area=None, tangents=0))]
    #[allow(clippy::too_many_arguments)]
    fn step_in_place(
        &self,
        py: Python<'_>,
        state: &Bound<'_, PyAny>,
        normal_force: Option<&Bound<'_, PyAny>>,
        slip: Option<&Bound<'_, PyAny>>,
        dt: Option<&Bound<'_, PyAny>>,
        area: Option<&Bound<'_, PyAny>>,
        tangents: i32,
    ) -> PyResult<FrictionResponse> {
        let inc = increment(normal_force, slip, dt, area, tangents)?;
        let m = self.law.state_len();
        let mut st = writable(state, "state", m)?;
        let s = st.as_slice_mut()?;
        let mut w = self.take();
        let slider = matches!(self.concrete, Concrete::Slider(_));
        let res = py.detach(|| {
            self.law.step_in_place(s, &inc, &mut w).map(|r| {
                let rec = if slider {
                    w.get::<fr::SliderWork>().map(|s| *s.record())
                } else {
                    None
                };
                (r, rec)
            })
        });
        self.put(w);
        let (r, record) = res.map_err(rs)?;
        Ok(FrictionResponse { r, record })
    }
    /// step_block(states, normal_force, slip, dt, area=None, in_place=False, tangents=0) -> FrictionBlockResponse
    ///
    /// n points at once (Abaqus/Explicit VFRIC's shape): ``states``
    /// (n×state_len float64, C-contiguous; rows all zero = fresh),
    /// ``normal_force`` (n, N), ``slip`` (n×2 or 2n, m), one ``dt`` (s),
    /// ``area`` (n, m², or None = 0), ``tangents`` (0, or TANGENT_NORMAL |
    /// TANGENT_SLIP, for every point). Returns the tangential forces (n×2,
    /// N), the dissipation of the increment per point (n, J), the new
    /// states (a new array, or ``states`` itself with ``in_place=True``),
    /// and per point the regime, the stored energy (J) and the tangents
    /// asked for (∂F/∂Δs n×2×2 N/m, ∂F/∂N n×2; zeros when not asked): what
    /// ``step`` gives point by point, for an implicit host's Jacobian. The
    /// GIL is released. On an error at point i the message starts with
    /// ``element i:``; without ``in_place`` nothing is returned, with it
    /// the points before i are stepped.
    #[pyo3(signature = (states, normal_force, slip, dt, area=None, in_place=false, tangents=0))]
    #[allow(clippy::too_many_arguments)]
    fn step_block(
        &self,
        py: Python<'_>,
        states: &Bound<'_, PyAny>,
        normal_force: &Bound<'_, PyAny>,
        slip: &Bound<'_, PyAny>,
        dt: &Bound<'_, PyAny>,
        area: Option<&Bound<'_, PyAny>>,
        in_place: bool,
        tangents: i32,
    ) -> PyResult<FrictionBlockResponse> {
        let nf = array(normal_force, "normal_force")?;
        let nfs = nf.as_slice()?;
        let n = nfs.len();
        let m = self.law.state_len();
        let sl = readonly_any(slip, "slip", 2 * n)?;
        let sls = sl.as_slice()?;
        let ar = match area {
            Some(a) if !a.is_none() => Some(array(a, "area")?),
            _ => None,
        };
        let ars = match &ar {
            Some(a) => {
                let s = a.as_slice()?;
                if s.len() != n {
                    return Err(arg_error(
                        "area",
                        format!(
                            "must have the length of normal_force ({n}), got {}",
                            s.len()
                        ),
                    ));
                }
                Some(s)
            }
            None => None,
        };
        let dt = real(dt, "dt")?;
        let force = PyArray2::<f64>::zeros(py, [n, 2], false);
        let diss = PyArray1::<f64>::zeros(py, n, false);
        let mut responses = vec![fr::FrictionResponse::default(); n];
        let rsp = responses.as_mut_slice();
        let mut w = self.take();
        let out_state: Py<PyAny>;
        {
            let mut fw = force.readwrite();
            let mut dw = diss.readwrite();
            let (fs, ds) = (fw.as_slice_mut()?, dw.as_slice_mut()?);
            let res = if in_place {
                let mut st = writable(states, "states", n * m)?;
                let s = st.as_slice_mut()?;
                py.detach(|| {
                    self.law.step_block(
                        FrictionBlock {
                            normal_force: nfs,
                            area: ars,
                            slip: sls,
                            dt,
                            tangents,
                            states: BlockStates::InPlace(s),
                            tangential_force: Some(fs),
                            dissipation: Some(ds),
                            responses: Some(&mut *rsp),
                        },
                        &mut w,
                    )
                })
                .map(|_| states.clone().unbind())
            } else {
                let old = readonly_any(states, "states", n * m)?;
                let os = old.as_slice()?;
                let new = PyArray2::<f64>::zeros(py, [n, m], false);
                let mut nw = new.readwrite();
                let ns = nw.as_slice_mut()?;
                let r = py.detach(|| {
                    self.law.step_block(
                        FrictionBlock {
                            normal_force: nfs,
                            area: ars,
                            slip: sls,
                            dt,
                            tangents,
                            states: BlockStates::Separate { old: os, new: ns },
                            tangential_force: Some(fs),
                            dissipation: Some(ds),
                            responses: Some(&mut *rsp),
                        },
                        &mut w,
                    )
                });
                drop(nw);
                r.map(|_| new.into_any().unbind())
            };
            self.put(w);
            out_state = res.map_err(|e| batch_err(rename_block(e)))?;
        }
        // The tangents not asked for are zeros (some laws always compute
        // them).
        let normal = tangents & fr::TANGENT_NORMAL != 0;
        let slips = tangents & fr::TANGENT_SLIP != 0;
        let regime: Vec<i32> = responses.iter().map(|r| r.regime).collect();
        let stored: Vec<f64> = responses.iter().map(|r| r.stored_energy).collect();
        let dslip: Vec<f64> = responses
            .iter()
            .flat_map(|r| r.dforce_dslip.into_iter().flatten())
            .map(|v| if slips { v } else { 0.0 })
            .collect();
        let dnormal: Vec<f64> = responses
            .iter()
            .flat_map(|r| r.dforce_dnormal)
            .map(|v| if normal { v } else { 0.0 })
            .collect();
        Ok(FrictionBlockResponse {
            tangential_force: force.unbind(),
            dissipation: diss.unbind(),
            state: out_state,
            regime: PyArray1::from_vec(py, regime).unbind(),
            stored_energy: PyArray1::from_vec(py, stored).unbind(),
            dforce_dslip: PyArray1::from_vec(py, dslip).reshape([n, 2, 2])?.unbind(),
            dforce_dnormal: PyArray1::from_vec(py, dnormal).reshape([n, 2])?.unbind(),
        })
    }
    fn __repr__(&self) -> String {
        let kind = match &self.concrete {
            Concrete::Homogenised(_) => "HomogenisedFriction".to_string(),
            Concrete::Slider(_) => "Slider".to_string(),
            Concrete::Dynamic(m) => format!("{m:?}")
                .split('(')
                .next()
                .unwrap_or("DynamicModel")
                .to_string(),
        };
        format!("<{kind} friction law, state_len={}>", self.law.state_len())
    }
}

/// Block errors name the Rust slices (`old.len()`, `states.len()`,
/// `tangential_force.len()`); the Python arguments are `states`, `slip`.
fn rename_block(mut e: asperity::contact::BatchError) -> asperity::contact::BatchError {
    use crate::common::renamed;
    e.error = renamed(
        renamed(
            renamed(e.error, "old.len()", "states"),
            "states.len()",
            "states",
        ),
        "slip.len()",
        "slip",
    );
    e.error = renamed(renamed(e.error, "old", "states"), "state", "states");
    e
}

// ---------------------------------------------------------------- laws

/// HomogenisedFriction(samples, form="derjaguin", stick_stiffness=0.0)
///
/// The homogenised friction law of an FE integration point: μ, adhesion and
/// contact fraction interpolated in the nominal pressure N/A_n from
/// ``samples`` (a list of dicts with ``pressure`` Pa, ``cof``,
/// ``adhesion_pressure`` Pa, ``contact_fraction``, ``shares`` {chemical,
/// van_der_waals, elastic, plastic}), μ read in ``form`` (``"derjaguin"``,
/// ``"amontons"``, ``"coulomb"``), stick stiffness k (N/m; 0 = rigid stick).
/// ``HomogenisedFriction.from_json(text)`` reads the Rust API's JSON. State:
/// ``[D, S, Fx, Fy, plastic slip path, chemical, van der Waals, elastic,
/// plastic]``.
#[pyclass(module = "asperity", frozen, extends = PyFrictionLaw)]
pub struct HomogenisedFriction;

fn homogenised(h: fr::HomogenisedFriction) -> PyClassInitializer<HomogenisedFriction> {
    let a = Arc::new(h);
    PyClassInitializer::from(PyFrictionLaw::new(a.clone(), Concrete::Homogenised(a)))
        .add_subclass(HomogenisedFriction)
}

fn as_homogenised(base: &PyFrictionLaw) -> &fr::HomogenisedFriction {
    match &base.concrete {
        Concrete::Homogenised(h) => h,
        _ => unreachable!("a HomogenisedFriction holds one"),
    }
}

#[pymethods]
impl HomogenisedFriction {
    #[new]
    #[pyo3(signature = (samples, form=None, stick_stiffness=None))]
    fn new(
        samples: &Bound<'_, PyAny>,
        form: Option<&Bound<'_, PyAny>>,
        stick_stiffness: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let s: Vec<fr::HomogenisedSample> = crate::common::from_py(samples, "samples")?;
        let mut h = fr::HomogenisedFriction::from_samples(&s, crate::friction::cof_form(form)?)
            .map_err(rs)?;
        if let Some(k) = real_opt(stick_stiffness, "stick_stiffness")? {
            h = h.with_stick_stiffness(k).map_err(rs)?;
        }
        Ok(homogenised(h))
    }
    /// from_json(text, stick_stiffness=0.0) -> HomogenisedFriction
    ///
    /// The law from its JSON text (``to_json``), with stick stiffness k (N/m).
    #[staticmethod]
    #[pyo3(signature = (text, stick_stiffness=None))]
    fn from_json(
        py: Python<'_>,
        text: &str,
        stick_stiffness: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<HomogenisedFriction>> {
        let mut h = fr::HomogenisedFriction::from_json(text).map_err(rs)?;
        if let Some(k) = real_opt(stick_stiffness, "stick_stiffness")? {
            h = h.with_stick_stiffness(k).map_err(rs)?;
        }
        Py::new(py, homogenised(h))
    }
    /// to_json() -> str
    ///
    /// The law's samples and form as JSON.
    fn to_json(self_: PyRef<'_, Self>) -> String {
        as_homogenised(self_.as_super()).to_json()
    }
    /// Stick stiffness k (N/m).
    #[getter]
    fn stick_stiffness(self_: PyRef<'_, Self>) -> f64 {
        as_homogenised(self_.as_super()).stick_stiffness()
    }
    /// sample_at(pressure) -> dict
    ///
    /// The interpolated sample at nominal pressure p (Pa).
    fn sample_at(
        self_: PyRef<'_, Self>,
        py: Python<'_>,
        pressure: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let s = as_homogenised(self_.as_super())
            .sample_at(real(pressure, "pressure")?)
            .map_err(rs)?;
        to_py_value(py, &s)
    }
    /// samples() -> list
    ///
    /// The samples the law was built from.
    fn samples(self_: PyRef<'_, Self>, py: Python<'_>) -> PyResult<Py<PyAny>> {
        to_py_value(py, &as_homogenised(self_.as_super()).samples())
    }
}

/// Slider — the hierarchical slider of a scene (``Slider.from_scene``): it
/// slides (``slide``) and it is the friction law of a surface patch
/// (``step``: the increment's normal force is the fixed load, ≤ its
/// capacity; the response carries the step's full ``record``). State:
/// ``[D, S, flag, X, b, chem, vdw, el, pl, heights(n), energies(n)]``.
#[pyclass(module = "asperity", frozen, extends = PyFrictionLaw)]
pub struct Slider;

fn as_slider(base: &PyFrictionLaw) -> &fr::Slider {
    match &base.concrete {
        Concrete::Slider(s) => s,
        _ => unreachable!("a Slider holds one"),
    }
}

#[pymethods]
impl Slider {
    /// from_scene(scene, base=None) -> Slider
    ///
    /// The slider a scene describes (a JSON file or a dict; see
    /// ``run_scene``). The GIL is released while it is built.
    #[staticmethod]
    #[pyo3(signature = (scene, base=None))]
    fn from_scene(
        py: Python<'_>,
        scene: &Bound<'_, PyAny>,
        base: Option<std::path::PathBuf>,
    ) -> PyResult<Py<Slider>> {
        let sc = crate::friction::load_scene(scene, base)?;
        let s = py.detach(|| sc.build()).map_err(any_err)?;
        let a = Arc::new(s);
        Py::new(
            py,
            PyClassInitializer::from(PyFrictionLaw::new(a.clone(), Concrete::Slider(a)))
                .add_subclass(Slider),
        )
    }
    /// slide(distance, step) -> dict
    ///
    /// Slide ``distance`` (m) in increments of ``step`` (m) from a fresh
    /// state, as a scene does: ``steps`` (dict of arrays per increment) and
    /// ``summary`` (dict). The GIL is released.
    fn slide(
        self_: PyRef<'_, Self>,
        py: Python<'_>,
        distance: &Bound<'_, PyAny>,
        step: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let (d, s) = (real(distance, "distance")?, real(step, "step")?);
        let sl = as_slider(self_.as_super());
        let run = py.detach(|| sl.slide(d, s)).map_err(rs)?;
        let out = PyDict::new(py);
        out.set_item("steps", crate::friction::step_columns(py, &run.steps)?)?;
        out.set_item("summary", to_py_value(py, &run.summary)?)?;
        Ok(out.into_any().unbind())
    }
    /// The nominal area of the slider n·w·D (m²).
    #[getter]
    fn nominal_area(self_: PyRef<'_, Self>) -> f64 {
        as_slider(self_.as_super()).nominal_area()
    }
    /// The load capacity of its rods n·σ_y·w·D (N); a nominal pressure
    /// above capacity/nominal_area cannot be carried.
    #[getter]
    fn capacity(self_: PyRef<'_, Self>) -> f64 {
        as_slider(self_.as_super()).capacity()
    }
    /// homogenise(pressures, distance, step, stick_stiffness=0.0) -> HomogenisedFriction
    ///
    /// The homogenised friction law of this slider for FE integration
    /// points: one fixed-load run over ``distance`` in increments of
    /// ``step`` (m) at each nominal pressure of ``pressures`` (Pa,
    /// increasing, each within capacity/nominal_area), tabulated in the
    /// slider's COF form (Rust ``Slider::homogenise``), with the stick
    /// stiffness ``stick_stiffness`` (N/m). The GIL is released.
    #[pyo3(signature = (pressures, distance, step, stick_stiffness=None))]
    fn homogenise(
        self_: PyRef<'_, Self>,
        py: Python<'_>,
        pressures: &Bound<'_, PyAny>,
        distance: &Bound<'_, PyAny>,
        step: &Bound<'_, PyAny>,
        stick_stiffness: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Py<HomogenisedFriction>> {
        let p = array(pressures, "pressures")?;
        let ps = p.as_slice()?.to_vec();
        let (d, s) = (real(distance, "distance")?, real(step, "step")?);
        let k = real_opt(stick_stiffness, "stick_stiffness")?;
        let sl = as_slider(self_.as_super());
        let mut h = py.detach(|| sl.homogenise(&ps, d, s)).map_err(rs)?;
        if let Some(k) = k {
            h = h.with_stick_stiffness(k).map_err(rs)?;
        }
        Py::new(py, homogenised(h))
    }
}

macro_rules! dynamic_class {
    ($name:ident, $key:literal, $doc:literal) => {
        #[doc = $doc]
        #[pyclass(module = "asperity", frozen, extends = PyFrictionLaw)]
        pub struct $name;

        #[pymethods]
        impl $name {
            #[new]
            #[pyo3(signature = (**kwargs))]
            fn new(
                py: Python<'_>,
                kwargs: Option<&Bound<'_, PyDict>>,
            ) -> PyResult<PyClassInitializer<Self>> {
                let py_kwargs = match kwargs {
                    Some(k) => k.clone(),
                    None => PyDict::new(py),
                };
                let m = build_dynamic($key, &py_kwargs)?;
                let a = Arc::new(m);
                Ok(
                    PyClassInitializer::from(PyFrictionLaw::new(a.clone(), Concrete::Dynamic(a)))
                        .add_subclass($name),
                )
            }
        }
    };
}

fn build_dynamic(key: &str, kwargs: &Bound<'_, PyDict>) -> PyResult<DynamicModel> {
    // The spec from the keyword arguments held as exact floats; serde names
    // a missing or unknown field ("missing field `sigma0`").
    let wrapped = PyDict::new(kwargs.py());
    wrapped.set_item(key, kwargs)?;
    let spec: DynamicModelSpec = crate::common::from_py(wrapped.as_any(), key)?;
    spec.build().map_err(rs)
}

dynamic_class!(LuGre, "lugre", "LuGre(mu_coulomb, mu_static, stribeck_velocity, sigma0, stribeck_exponent=2, sigma1=0, damping_velocity=inf, sigma2=0)\n\nThe LuGre model (Canudas de Wit et al. 1995) with Stribeck weakening, integrated exactly per increment: coefficients μ_c, μ_s, Stribeck velocity v_s (m/s), bristle stiffness σ0 and damping σ1 per unit normal force (1/m, s/m), viscous σ2 (N·s/m). Keyword arguments, named as the Rust constructor's.");
dynamic_class!(MaxwellSlip, "maxwell_slip", "MaxwellSlip(stiffness, capacity, sigma2=0)\n\nMaxwell-slip elements (pre-sliding hysteresis, Masing rules): element stiffnesses k_i per unit normal force (1/m) and break-away coefficients μ_i (lists), viscous σ2 (N·s/m). Keyword arguments.");
dynamic_class!(GeneralizedMaxwellSlip, "generalized_maxwell_slip", "GeneralizedMaxwellSlip(stiffness, weight, mu_coulomb, mu_static, stribeck_velocity, stribeck_exponent=2, attraction=inf, sigma2=0)\n\nThe generalised Maxwell-slip model (Al-Bender, Lampaert and Swevers 2005): element stiffnesses k_i per unit normal force (1/m) and weights α_i (lists), the elements' slip attracted at rate C (1/s; absent: instantaneous) to α_i s(v) on the Stribeck curve s(v) = μ_c + (μ_s − μ_c) exp(−|v/v_s|^δ), viscous σ2 (N·s/m). One-dimensional (slip[1] = 0), rate dependent. Keyword arguments.");
dynamic_class!(PrandtlTomlinson, "prandtl_tomlinson", "PrandtlTomlinson(**parameters)\n\nThe Prandtl–Tomlinson tip in a sinusoidal potential pulled through one spring (keyword arguments named as the Rust constructor's: see the scene key `prandtl_tomlinson`).");
dynamic_class!(PrandtlTomlinsonTwoSpring, "prandtl_tomlinson_two_spring", "PrandtlTomlinsonTwoSpring(**parameters)\n\nThe Prandtl–Tomlinson tip with tip and cantilever springs (scene key `prandtl_tomlinson_two_spring`; keyword arguments named as the Rust constructor's).");
dynamic_class!(BurridgeKnopoff, "burridge_knopoff", "BurridgeKnopoff(**parameters)\n\nThe Burridge–Knopoff block chain with static and velocity-weakening friction, every stick and slip located as an event (scene key `burridge_knopoff`; keyword arguments named as the Rust constructor's).");
dynamic_class!(Bristles, "bristles", "Bristles(stiffness, break_deflection, sigma2=0)\n\nThe bristle model of Haessig and Friedland: bristle stiffnesses per unit normal force (1/m) and break deflections (m), viscous σ2 (N·s/m). Keyword arguments.");

/// friction_model(spec) -> FrictionLaw
///
/// A dynamic friction model from its scene entry: ``{"lugre": {...}}`` (or
/// with a ``"name"``), the keys ``lugre``, ``maxwell_slip``,
/// ``generalized_maxwell_slip``,
/// ``prandtl_tomlinson``, ``prandtl_tomlinson_two_spring``,
/// ``burridge_knopoff``, ``bristles`` and the parameters named as the Rust
/// constructors' arguments.
#[pyfunction]
fn friction_model(py: Python<'_>, spec: &Bound<'_, PyDict>) -> PyResult<Py<PyAny>> {
    let d = spec.copy()?;
    let _ = d.del_item("name");
    if d.len() != 1 {
        return Err(arg_error(
            "spec",
            format!(
                "must hold exactly one model key (one of {:?})",
                DynamicModelSpec::KEYS
            ),
        ));
    }
    let (k, v) = d.iter().next().expect("one item");
    let key: String = k.extract()?;
    let params = v
        .cast::<PyDict>()
        .map_err(|_| arg_error("spec", "the model's parameters must be a dict"))?;
    let obj = match key.as_str() {
        "lugre" => Py::new(py, LuGre::new(py, Some(params))?)?.into_any(),
        "maxwell_slip" => Py::new(py, MaxwellSlip::new(py, Some(params))?)?.into_any(),
        "generalized_maxwell_slip" => {
            Py::new(py, GeneralizedMaxwellSlip::new(py, Some(params))?)?.into_any()
        }
        "prandtl_tomlinson" => Py::new(py, PrandtlTomlinson::new(py, Some(params))?)?.into_any(),
        "prandtl_tomlinson_two_spring" => {
            Py::new(py, PrandtlTomlinsonTwoSpring::new(py, Some(params))?)?.into_any()
        }
        "burridge_knopoff" => Py::new(py, BurridgeKnopoff::new(py, Some(params))?)?.into_any(),
        "bristles" => Py::new(py, Bristles::new(py, Some(params))?)?.into_any(),
        other => {
            return Err(arg_error(
                "spec",
                format!(
                    "unknown model {other:?}: one of {:?}",
                    DynamicModelSpec::KEYS
                ),
            ))
        }
    };
    Ok(obj)
}

/// stick_slip(forces, slips, min_drop) -> dict
///
/// Slip events of a friction-force history (N) over slip increments (m):
/// drops of at least ``min_drop`` (N); the events and the static and
/// kinetic friction (the Rust API's ``StickSlip``).
#[pyfunction]
fn stick_slip(
    py: Python<'_>,
    forces: &Bound<'_, PyAny>,
    slips: &Bound<'_, PyAny>,
    min_drop: &Bound<'_, PyAny>,
) -> PyResult<Py<PyAny>> {
    let f = array(forces, "forces")?;
    let s = array(slips, "slips")?;
    let r = fr::dynamic::stick_slip(f.as_slice()?, s.as_slice()?, real(min_drop, "min_drop")?)
        .map_err(rs)?;
    let d = PyDict::new(py);
    d.set_item("static_force", r.static_force)?;
    d.set_item("kinetic_force", r.kinetic_force)?;
    d.set_item("max_force", r.max_force)?;
    d.set_item("is_stick_slip", r.is_stick_slip())?;
    d.set_item("mean_spacing", r.mean_spacing())?;
    let events = pyo3::types::PyList::empty(py);
    for e in &r.events {
        let x = PyDict::new(py);
        x.set_item("peak_index", e.peak_index)?;
        x.set_item("trough_index", e.trough_index)?;
        x.set_item("peak_force", e.peak_force)?;
        x.set_item("drop", e.drop)?;
        x.set_item("jump", e.jump)?;
        x.set_item("slip", e.slip)?;
        x.set_item("loading", e.loading)?;
        x.set_item("position", e.position)?;
        events.append(x)?;
    }
    d.set_item("events", events)?;
    Ok(d.into_any().unbind())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyFrictionLaw>()?;
    m.add_class::<FrictionResponse>()?;
    m.add_class::<FrictionBlockResponse>()?;
    m.add_class::<HomogenisedFriction>()?;
    m.add_class::<Slider>()?;
    m.add_class::<LuGre>()?;
    m.add_class::<MaxwellSlip>()?;
    m.add_class::<GeneralizedMaxwellSlip>()?;
    m.add_class::<PrandtlTomlinson>()?;
    m.add_class::<PrandtlTomlinsonTwoSpring>()?;
    m.add_class::<BurridgeKnopoff>()?;
    m.add_class::<Bristles>()?;
    m.add_function(wrap_pyfunction!(friction_model, m)?)?;
    m.add_function(wrap_pyfunction!(stick_slip, m)?)?;
    m.add("STATE_DISSIPATION", fr::STATE_DISSIPATION)?;
    m.add("STATE_SLIP_PATH", fr::STATE_SLIP_PATH)?;
    m.add("STATE_MODEL", fr::STATE_MODEL)?;
    m.add("TANGENT_NORMAL", fr::TANGENT_NORMAL)?;
    m.add("TANGENT_SLIP", fr::TANGENT_SLIP)?;
    Ok(())
}
