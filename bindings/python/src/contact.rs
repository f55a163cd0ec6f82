//! Single-asperity normal laws (`asperity::contact`): one Python class per
//! law with the shared methods of the trait `NormalContact` (`eval` on a
//! float or an array, `eval_at_load`, `pull_off_force`, `reach`, `energy`,
//! `length_scale`), the per-contact `ContactState` and the `NormalResponse`.

use crate::common::{arg_error, array, batch, real, real_or_array, rs, RealOrArray};
use asperity::contact as c;
use asperity::NormalContact;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

// --------------------------------------------------------------------------
// Per-contact state
// --------------------------------------------------------------------------

/// Per-contact history of a normal law, owned by the caller: one state (from
/// a scalar ``eval``) or n states (from an array ``eval``). All-zero means
/// "never touched". Pass it back as ``state=`` to the next ``eval``; it is
/// immutable, every ``eval`` returns a new one.
///
/// Attributes (floats for one state, numpy arrays for n): ``contact_radius``
/// a (m), ``cohesive_radius`` c (m, 0 when the law has no cohesive zone),
/// ``in_contact`` (1/0), ``branch`` (law-specific branch index).
#[pyclass(module = "asperity", sequence)]
pub struct ContactState {
    pub states: Vec<asperity::ContactState>,
    pub scalar: bool,
}

impl ContactState {
    fn field<'py, T: numpy::Element + Copy + IntoPyObjectExt<'py>>(
        &self,
        py: Python<'py>,
        f: impl Fn(&asperity::ContactState) -> T,
    ) -> PyResult<Py<PyAny>> {
        if self.scalar {
            f(&self.states[0]).into_py_any(py)
        } else {
            let v: Vec<T> = self.states.iter().map(f).collect();
            Ok(PyArray1::from_vec(py, v).into_any().unbind())
        }
    }
}

use pyo3::IntoPyObjectExt;

#[pymethods]
impl ContactState {
    /// ContactState(contact_radius=0.0, cohesive_radius=0.0, in_contact=0, branch=0)
    ///
    /// One state from its fields: contact radius (m), cohesive-zone radius
    /// (m), in-contact flag and branch index. ``ContactState()`` is a fresh
    /// (never touched) contact; ``ContactState.fresh(n)`` gives n of them and
    /// ``ContactState.from_arrays(...)`` n states from arrays.
    #[new]
    #[pyo3(signature = (contact_radius=None, cohesive_radius=None, in_contact=0, branch=0))]
    fn new(
        contact_radius: Option<&Bound<'_, PyAny>>,
        cohesive_radius: Option<&Bound<'_, PyAny>>,
        in_contact: i32,
        branch: i32,
    ) -> PyResult<Self> {
        let a = crate::common::real_opt(contact_radius, "contact_radius")?.unwrap_or(0.0);
        let cz = crate::common::real_opt(cohesive_radius, "cohesive_radius")?.unwrap_or(0.0);
        Ok(Self {
            states: vec![asperity::ContactState {
                contact_radius: a,
                cohesive_radius: cz,
                in_contact,
                branch,
            }],
            scalar: true,
        })
    }

    /// fresh(n) -> ContactState
    ///
    /// n fresh (all-zero, never touched) states for an array ``eval``.
    #[staticmethod]
    fn fresh(n: &Bound<'_, PyAny>) -> PyResult<Self> {
        let n = crate::common::count(n, "n")?;
        Ok(Self {
            states: vec![asperity::ContactState::default(); n],
            scalar: false,
        })
    }

    /// from_arrays(contact_radius, cohesive_radius, in_contact, branch) -> ContactState
    ///
    /// n states from arrays of equal length: contact radii (m), cohesive
    /// radii (m), in-contact flags and branch indices (integers).
    #[staticmethod]
    fn from_arrays(
        contact_radius: &Bound<'_, PyAny>,
        cohesive_radius: &Bound<'_, PyAny>,
        in_contact: Vec<i32>,
        branch: Vec<i32>,
    ) -> PyResult<Self> {
        let a = array(contact_radius, "contact_radius")?;
        let cz = array(cohesive_radius, "cohesive_radius")?;
        let (a, cz) = (a.as_slice()?, cz.as_slice()?);
        let n = a.len();
        for (name, len) in [
            ("cohesive_radius", cz.len()),
            ("in_contact", in_contact.len()),
            ("branch", branch.len()),
        ] {
            if len != n {
                return Err(arg_error(
                    name,
                    format!("must have the length of contact_radius ({n}), got {len}"),
                ));
            }
        }
        Ok(Self {
            states: (0..n)
                .map(|i| asperity::ContactState {
                    contact_radius: a[i],
                    cohesive_radius: cz[i],
                    in_contact: in_contact[i],
                    branch: branch[i],
                })
                .collect(),
            scalar: false,
        })
    }

    /// Contact radius a at the end of the step (m).
    #[getter]
    fn contact_radius(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.field(py, |s| s.contact_radius)
    }
    /// Outer radius c of the cohesive zone (m); 0 when the law has none.
    #[getter]
    fn cohesive_radius(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.field(py, |s| s.cohesive_radius)
    }
    /// 1 in contact (or interacting), 0 otherwise.
    #[getter]
    fn in_contact(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.field(py, |s| s.in_contact)
    }
    /// Law-specific index of the equilibrium branch; 0 when fresh.
    #[getter]
    fn branch(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        self.field(py, |s| s.branch)
    }
    /// True for one state (from a scalar ``eval``), False for an array of states.
    #[getter]
    fn is_scalar(&self) -> bool {
        self.scalar
    }
    fn __len__(&self) -> PyResult<usize> {
        if self.scalar {
            Err(pyo3::exceptions::PyTypeError::new_err(
                "a single ContactState has no len()",
            ))
        } else {
            Ok(self.states.len())
        }
    }
    fn __getitem__(&self, i: isize) -> PyResult<ContactState> {
        let n = self.states.len() as isize;
        let j = if i < 0 { i + n } else { i };
        if self.scalar || j < 0 || j >= n {
            return Err(pyo3::exceptions::PyIndexError::new_err(
                "state index out of range",
            ));
        }
        Ok(ContactState {
            states: vec![self.states[j as usize]],
            scalar: true,
        })
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        match other.cast::<ContactState>() {
            Ok(o) => {
                let Ok(o) = o.try_borrow() else { return false };
                o.scalar == self.scalar && o.states == self.states
            }
            Err(_) => false,
        }
    }
    fn __repr__(&self) -> String {
        if self.scalar {
            let s = &self.states[0];
            format!(
                "ContactState(contact_radius={:e}, cohesive_radius={:e}, in_contact={}, branch={})",
                s.contact_radius, s.cohesive_radius, s.in_contact, s.branch
            )
        } else {
            format!("ContactState(<{} states>)", self.states.len())
        }
    }
}

// --------------------------------------------------------------------------
// Response
// --------------------------------------------------------------------------

enum Resp {
    Scalar {
        r: asperity::NormalResponse,
        s: Option<asperity::ContactState>,
    },
    Array {
        force: Py<PyArray1<f64>>,
        delta: Py<PyAny>,
        contact_radius: Py<PyArray1<f64>>,
        stiffness: Py<PyArray1<f64>>,
        in_contact: Option<Py<PyArray1<i32>>>,
        state: Option<Py<ContactState>>,
    },
}

/// The result of ``eval`` / ``eval_at_load``: floats for a scalar call,
/// numpy arrays (one element per contact) for an array call.
///
/// Attributes: ``force`` P (N, positive when repulsive), ``delta`` δ (m),
/// ``contact_radius`` a (m), ``stiffness`` dP/dδ (N/m), ``in_contact`` (1/0),
/// ``state`` (the new ``ContactState``; None from ``eval_at_load``).
#[pyclass(module = "asperity", frozen)]
pub struct NormalResponse {
    inner: Resp,
}

#[pymethods]
impl NormalResponse {
    /// Normal force P (N), positive when repulsive.
    #[getter]
    fn force(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.inner {
            Resp::Scalar { r, .. } => r.force.into_py_any(py),
            Resp::Array { force, .. } => Ok(force.clone_ref(py).into_any()),
        }
    }
    /// Overlap δ (m) of the equilibrium (the input under displacement control).
    #[getter]
    fn delta(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.inner {
            Resp::Scalar { r, .. } => r.delta.into_py_any(py),
            Resp::Array { delta, .. } => Ok(delta.clone_ref(py)),
        }
    }
    /// Contact radius a (m); 0 out of contact.
    #[getter]
    fn contact_radius(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.inner {
            Resp::Scalar { r, .. } => r.contact_radius.into_py_any(py),
            Resp::Array { contact_radius, .. } => Ok(contact_radius.clone_ref(py).into_any()),
        }
    }
    /// Tangent stiffness dP/dδ (N/m) along the branch the contact is on.
    #[getter]
    fn stiffness(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.inner {
            Resp::Scalar { r, .. } => r.stiffness.into_py_any(py),
            Resp::Array { stiffness, .. } => Ok(stiffness.clone_ref(py).into_any()),
        }
    }
    /// 1 in contact, 0 otherwise.
    #[getter]
    fn in_contact(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.inner {
            Resp::Scalar { r, .. } => r.in_contact.into_py_any(py),
            Resp::Array {
                in_contact: Some(a),
                ..
            } => Ok(a.clone_ref(py).into_any()),
            Resp::Array { state: Some(s), .. } => s.borrow(py).in_contact(py),
            Resp::Array { .. } => Ok(py.None()),
        }
    }
    /// The new per-contact state (``ContactState``), to pass to the next
    /// ``eval``; None from ``eval_at_load``.
    #[getter]
    fn state(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        match &self.inner {
            Resp::Scalar { s: Some(s), .. } => ContactState {
                states: vec![*s],
                scalar: true,
            }
            .into_py_any(py),
            Resp::Scalar { s: None, .. } => Ok(py.None()),
            Resp::Array { state: Some(s), .. } => Ok(s.clone_ref(py).into_any()),
            Resp::Array { state: None, .. } => Ok(py.None()),
        }
    }
    fn __repr__(&self, py: Python<'_>) -> String {
        match &self.inner {
            Resp::Scalar { r, .. } => format!(
                "NormalResponse(force={:e}, delta={:e}, contact_radius={:e}, stiffness={:e}, in_contact={})",
                r.force, r.delta, r.contact_radius, r.stiffness, r.in_contact
            ),
            Resp::Array { force, .. } => {
                format!("NormalResponse(<{} contacts>)", numpy::PyUntypedArrayMethods::len(force.bind(py)))
            }
        }
    }
}

fn overflow(delta: f64) -> asperity::Error {
    asperity::Error::OutOfDomain {
        name: "delta",
        value: delta,
        reason: "the response overflows f64",
    }
}

fn finite(r: &asperity::NormalResponse) -> bool {
    r.force.is_finite()
        && r.delta.is_finite()
        && r.contact_radius.is_finite()
        && r.stiffness.is_finite()
}

/// Borrow the old states for an array call of `n` contacts.
fn old_states<'py>(
    state: Option<&Bound<'py, ContactState>>,
    n: usize,
) -> PyResult<Option<PyRef<'py, ContactState>>> {
    match state {
        None => Ok(None),
        Some(s) => {
            let s = s
                .try_borrow()
                .map_err(|_| arg_error("state", "is being written by another call"))?;
            if s.scalar {
                return Err(arg_error(
                    "state",
                    format!("must hold one state per contact ({n}), got a single state (from a scalar eval)"),
                ));
            }
            if s.states.len() != n {
                return Err(arg_error(
                    "state",
                    format!(
                        "must have the length of delta ({n}), got {} states",
                        s.states.len()
                    ),
                ));
            }
            Ok(Some(s))
        }
    }
}

fn scalar_state(state: Option<&Bound<'_, ContactState>>) -> PyResult<asperity::ContactState> {
    match state {
        None => Ok(asperity::ContactState::default()),
        Some(s) => {
            let s = s
                .try_borrow()
                .map_err(|_| arg_error("state", "is being written by another call"))?;
            if !s.scalar {
                return Err(arg_error(
                    "state",
                    format!(
                        "must be a single state for a scalar delta, got {} states",
                        s.states.len()
                    ),
                ));
            }
            Ok(s.states[0])
        }
    }
}

/// Allocate an uninitialised 1-D float64 array of n elements.
pub fn empty(py: Python<'_>, n: usize) -> Bound<'_, PyArray1<f64>> {
    // SAFETY: every element is written before the array is handed to Python
    // (on failure the array is dropped unseen).
    unsafe { PyArray1::<f64>::new(py, n, false) }
}

/// `law.eval(delta, state)` on a float or an array, the GIL released for arrays.
pub fn eval_any<L: NormalContact + Sync>(
    law: &L,
    py: Python<'_>,
    delta: &Bound<'_, PyAny>,
    state: Option<&Bound<'_, ContactState>>,
    out: Option<&Bound<'_, NormalResponse>>,
) -> PyResult<NormalResponse> {
    match real_or_array(delta, "delta")? {
        RealOrArray::Scalar(d) => {
            let old = scalar_state(state)?;
            let (r, s) = law.eval(d, &old).map_err(rs)?;
            if !finite(&r) {
                return Err(rs(overflow(d)));
            }
            Ok(NormalResponse {
                inner: Resp::Scalar { r, s: Some(s) },
            })
        }
        RealOrArray::Array(a) => {
            let d = a.as_slice()?;
            let n = d.len();
            if let Some(out) = out {
                return eval_into(law, py, delta, d, state, out);
            }
            let old_ref = old_states(state, n)?;
            let old = old_ref.as_ref().map(|s| &s.states[..]);
            let mut new = uninit_states(n);
            let f = empty(py, n);
            let ar = empty(py, n);
            let k = empty(py, n);
            {
                // SAFETY: fresh arrays, not shared with anyone yet.
                let (fs, as_, ks) = unsafe {
                    (
                        f.as_slice_mut().expect("contiguous"),
                        ar.as_slice_mut().expect("contiguous"),
                        k.as_slice_mut().expect("contiguous"),
                    )
                };
                let ns = &mut new[..];
                py.detach(|| c::eval_batch(law, d, old, Some(ns), fs, Some(as_), Some(ks)))
                    .map_err(batch)?;
            }
            drop(old_ref);
            let state = Py::new(
                py,
                ContactState {
                    states: new,
                    scalar: false,
                },
            )?;
            Ok(NormalResponse {
                inner: Resp::Array {
                    force: f.unbind(),
                    delta: delta.clone().unbind(),
                    contact_radius: ar.unbind(),
                    stiffness: k.unbind(),
                    in_contact: None,
                    state: Some(state),
                },
            })
        }
    }
}

/// n all-zero (fresh) states from zeroed memory (`calloc`: large blocks come
/// zeroed from the OS, with no second pass over them).
fn uninit_states(n: usize) -> Vec<asperity::ContactState> {
    if n == 0 {
        return Vec::new();
    }
    let layout = std::alloc::Layout::array::<asperity::ContactState>(n).expect("state array size");
    // SAFETY: the all-zero bit pattern is a valid ContactState (the fresh
    // state: two 0.0 and two 0), the layout is the Vec's for n elements and
    // the allocation is checked for NULL.
    unsafe {
        let p = std::alloc::alloc_zeroed(layout) as *mut asperity::ContactState;
        if p.is_null() {
            std::alloc::handle_alloc_error(layout);
        }
        Vec::from_raw_parts(p, n, n)
    }
}

/// `eval` into the arrays of a previous array response `out` (same length):
/// no allocation, the new states overwrite `out.state`. `state` may be
/// `out.state` itself (the old states are then copied first).
fn eval_into<L: NormalContact + Sync>(
    law: &L,
    py: Python<'_>,
    delta: &Bound<'_, PyAny>,
    d: &[f64],
    state: Option<&Bound<'_, ContactState>>,
    out: &Bound<'_, NormalResponse>,
) -> PyResult<NormalResponse> {
    let n = d.len();
    let Resp::Array {
        force,
        contact_radius,
        stiffness,
        state: Some(out_state),
        ..
    } = &out.get().inner
    else {
        return Err(arg_error(
            "out",
            "must be the response of an array eval (it holds the arrays to overwrite)",
        ));
    };
    let arrays = [force.bind(py), contact_radius.bind(py), stiffness.bind(py)];
    for a in arrays {
        if numpy::PyUntypedArrayMethods::len(a) != n {
            return Err(arg_error(
                "out",
                format!(
                    "must have the length of delta ({n}), got {}",
                    numpy::PyUntypedArrayMethods::len(a)
                ),
            ));
        }
    }
    let busy = |_| arg_error("out", "its arrays are borrowed elsewhere");
    let mut fw = force.bind(py).try_readwrite().map_err(busy)?;
    let mut aw = contact_radius.bind(py).try_readwrite().map_err(busy)?;
    let mut kw = stiffness.bind(py).try_readwrite().map_err(busy)?;
    let out_state_b = out_state.bind(py);
    let aliased = state.is_some_and(|s| s.is(out_state_b));
    let copied: Option<Vec<asperity::ContactState>>;
    let old_ref;
    let old: Option<&[asperity::ContactState]> = if aliased {
        let s = out_state_b.borrow();
        if s.states.len() != n {
            return Err(arg_error(
                "state",
                format!(
                    "must have the length of delta ({n}), got {} states",
                    s.states.len()
                ),
            ));
        }
        copied = Some(s.states.clone());
        copied.as_deref()
    } else {
        old_ref = old_states(state, n)?;
        old_ref.as_ref().map(|s| &s.states[..])
    };
    let mut ns = out_state_b
        .try_borrow_mut()
        .map_err(|_| arg_error("out", "its state is in use by another call"))?;
    if ns.states.len() != n {
        return Err(arg_error(
            "out",
            format!("must have the length of delta ({n})"),
        ));
    }
    {
        let (fs, as_, ks) = (fw.as_slice_mut()?, aw.as_slice_mut()?, kw.as_slice_mut()?);
        let nss = &mut ns.states[..];
        py.detach(|| c::eval_batch(law, d, old, Some(nss), fs, Some(as_), Some(ks)))
            .map_err(batch)?;
    }
    drop(ns);
    Ok(NormalResponse {
        inner: Resp::Array {
            force: force.clone_ref(py),
            delta: delta.clone().unbind(),
            contact_radius: contact_radius.clone_ref(py),
            stiffness: stiffness.clone_ref(py),
            in_contact: None,
            state: Some(out_state.clone_ref(py)),
        },
    })
}

/// Equilibria along a displacement-controlled path: element i starts from
/// the state element i - 1 ended in.
pub fn eval_path_any<L: NormalContact + Sync>(
    law: &L,
    py: Python<'_>,
    delta: &Bound<'_, PyAny>,
    state: Option<&Bound<'_, ContactState>>,
) -> PyResult<NormalResponse> {
    let a = array(delta, "delta")?;
    let d = a.as_slice()?;
    let n = d.len();
    let mut s = scalar_state(state)?;
    let f = empty(py, n);
    let ar = empty(py, n);
    let k = empty(py, n);
    let mut inc = vec![0i32; n];
    {
        let (fs, as_, ks) = unsafe {
            (
                f.as_slice_mut().expect("contiguous"),
                ar.as_slice_mut().expect("contiguous"),
                k.as_slice_mut().expect("contiguous"),
            )
        };
        let incs = &mut inc[..];
        let sp = &mut s;
        py.detach(|| -> Result<(), PyErr> {
            for i in 0..n {
                let (r, ns) = law
                    .eval(d[i], sp)
                    .map_err(|e| crate::common::any_err(format!("element {i}: {e}")))?;
                if !finite(&r) {
                    return Err(crate::common::any_err(format!(
                        "element {i}: {}",
                        overflow(d[i])
                    )));
                }
                *sp = ns;
                fs[i] = r.force;
                as_[i] = r.contact_radius;
                ks[i] = r.stiffness;
                incs[i] = r.in_contact;
            }
            Ok(())
        })?;
    }
    let state = Py::new(
        py,
        ContactState {
            states: vec![s],
            scalar: true,
        },
    )?;
    Ok(NormalResponse {
        inner: Resp::Array {
            force: f.unbind(),
            delta: a
                .as_array()
                .to_owned()
                .to_pyarray_bound(py)
                .into_any()
                .unbind(),
            contact_radius: ar.unbind(),
            stiffness: k.unbind(),
            in_contact: Some(PyArray1::from_vec(py, inc).unbind()),
            state: Some(state),
        },
    })
}

use numpy::ToPyArray;
trait ToPyArrayBound {
    fn to_pyarray_bound<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>>;
}
impl ToPyArrayBound for numpy::ndarray::Array1<f64> {
    fn to_pyarray_bound<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        self.to_pyarray(py)
    }
}

/// `law.eval_at_load(force)` on a float or an array.
pub fn eval_at_load_any<L: NormalContact + Sync>(
    law: &L,
    py: Python<'_>,
    force: &Bound<'_, PyAny>,
) -> PyResult<NormalResponse> {
    match real_or_array(force, "force")? {
        RealOrArray::Scalar(p) => {
            let r = law.eval_at_load(p).map_err(rs)?;
            if !finite(&r) {
                return Err(rs(asperity::Error::OutOfDomain {
                    name: "force",
                    value: p,
                    reason: "the response overflows f64",
                }));
            }
            Ok(NormalResponse {
                inner: Resp::Scalar { r, s: None },
            })
        }
        RealOrArray::Array(a) => {
            let p = a.as_slice()?;
            let n = p.len();
            let mut out = vec![asperity::NormalResponse::default(); n];
            {
                let o = &mut out[..];
                py.detach(|| -> Result<(), PyErr> {
                    for i in 0..n {
                        let r = law
                            .eval_at_load(p[i])
                            .map_err(|e| crate::common::any_err(format!("element {i}: {e}")))?;
                        o[i] = r;
                    }
                    Ok(())
                })?;
            }
            let col = |f: fn(&asperity::NormalResponse) -> f64| {
                PyArray1::from_vec(py, out.iter().map(f).collect()).unbind()
            };
            Ok(NormalResponse {
                inner: Resp::Array {
                    force: col(|r| r.force),
                    delta: col(|r| r.delta).into_any(),
                    contact_radius: col(|r| r.contact_radius),
                    stiffness: col(|r| r.stiffness),
                    in_contact: Some(
                        PyArray1::from_vec(py, out.iter().map(|r| r.in_contact).collect()).unbind(),
                    ),
                    state: None,
                },
            })
        }
    }
}

/// `law.energy(delta, state)` on a float or an array.
pub fn energy_any<L: NormalContact + Sync>(
    law: &L,
    py: Python<'_>,
    delta: &Bound<'_, PyAny>,
    state: Option<&Bound<'_, ContactState>>,
) -> PyResult<Py<PyAny>> {
    match real_or_array(delta, "delta")? {
        RealOrArray::Scalar(d) => {
            let old = scalar_state(state)?;
            law.energy(d, &old).map_err(rs)?.into_py_any(py)
        }
        RealOrArray::Array(a) => {
            let d = a.as_slice()?;
            let n = d.len();
            let old_ref = old_states(state, n)?;
            let old = old_ref.as_ref().map(|s| &s.states[..]);
            let mut out = vec![0.0; n];
            {
                let o = &mut out[..];
                py.detach(|| -> Result<(), PyErr> {
                    for i in 0..n {
                        let s = old.map_or(asperity::ContactState::default(), |s| s[i]);
                        o[i] = law
                            .energy(d[i], &s)
                            .map_err(|e| crate::common::any_err(format!("element {i}: {e}")))?;
                    }
                    Ok(())
                })?;
            }
            Ok(PyArray1::from_vec(py, out).into_any().unbind())
        }
    }
}

/// The default `rel_force` of `reach` when not given.
pub const DEFAULT_REL_FORCE: f64 = 1e-3;

/// Generates a law class: the wrapper struct and one `#[pymethods]` block
/// with the shared `NormalContact` methods, getters for the listed public
/// fields, and the law's own items.
#[macro_export]
macro_rules! normal_law {
    (
        $(#[$meta:meta])*
        $py:ident, $rust:ty, $pyname:literal,
        getters { $( $(#[$gm:meta])* $g:ident ),* $(,)? }
        { $($extra:tt)* }
    ) => {
        $(#[$meta])*
        #[pyclass(module = "asperity", frozen, name = $pyname)]
        #[derive(Clone)]
        pub struct $py {
            pub inner: $rust,
        }

        #[pymethods]
        impl $py {
            /// eval(delta, state=None, out=None) -> NormalResponse
            ///
            /// Equilibrium at the prescribed overlap ``delta`` δ (m; > 0 is
            /// penetration): a float, or a 1-D float64 array of independent
            /// contacts (the GIL is released). ``state`` is the history
            /// (``ContactState``; a single one for a float, one per contact
            /// for an array; None = fresh). Returns force (N), contact
            /// radius (m), stiffness (N/m) and the new state. ``out``: a
            /// previous array response of the same length whose arrays and
            /// state are overwritten instead of allocating new ones (it may
            /// hold ``state`` itself).
            #[pyo3(signature = (delta, state=None, out=None))]
            fn eval(
                &self,
                py: Python<'_>,
                delta: &Bound<'_, PyAny>,
                state: Option<&Bound<'_, $crate::contact::ContactState>>,
                out: Option<&Bound<'_, $crate::contact::NormalResponse>>,
            ) -> PyResult<$crate::contact::NormalResponse> {
                $crate::contact::eval_any(&self.inner, py, delta, state, out)
            }

            /// eval_path(delta, state=None) -> NormalResponse
            ///
            /// Equilibria along a displacement-controlled path of overlaps
            /// ``delta`` (m, 1-D array): each point starts from the state the
            /// previous one ended in (an approach–retraction cycle). Returns
            /// arrays of force (N), contact radius (m), stiffness (N/m),
            /// in-contact flags and the final state.
            #[pyo3(signature = (delta, state=None))]
            fn eval_path(
                &self,
                py: Python<'_>,
                delta: &Bound<'_, PyAny>,
                state: Option<&Bound<'_, $crate::contact::ContactState>>,
            ) -> PyResult<$crate::contact::NormalResponse> {
                $crate::contact::eval_path_any(&self.inner, py, delta, state)
            }

            /// eval_at_load(force) -> NormalResponse
            ///
            /// Equilibrium at the prescribed force P (N; a float or a 1-D
            /// array) on the stable branch (largest contact radius). Below the
            /// load-controlled pull-off force: asperity.Error.
            fn eval_at_load(
                &self,
                py: Python<'_>,
                force: &Bound<'_, PyAny>,
            ) -> PyResult<$crate::contact::NormalResponse> {
                $crate::contact::eval_at_load_any(&self.inner, py, force)
            }

            /// pull_off_force(control="load") -> float
            ///
            /// The force (N, ≤ 0 for adhesive laws) at which the contact
            /// separates, under ``"load"`` or ``"displacement"`` control.
            #[pyo3(signature = (control=None))]
            fn pull_off_force(&self, control: Option<&Bound<'_, PyAny>>) -> PyResult<f64> {
                let c = match control {
                    Some(c) => $crate::common::control(c)?,
                    None => asperity::Control::Load,
                };
                let f = asperity::NormalContact::pull_off_force(&self.inner, c)
                    .map_err($crate::common::rs)?;
                if f.is_finite() {
                    Ok(f)
                } else {
                    Err($crate::common::rs(asperity::Error::OutOfDomain {
                        name: "law",
                        value: f,
                        reason: "its pull-off force overflows f64",
                    }))
                }
            }

            /// length_scale() -> float
            ///
            /// A characteristic overlap of the law (m), used to
            /// non-dimensionalise.
            fn length_scale(&self) -> f64 {
                asperity::NormalContact::length_scale(&self.inner)
            }

            /// reach(control="displacement", rel_force=1e-3) -> float
            ///
            /// The overlap δ_r (m, ≤ 0) below which the force is zero from any
            /// history when the contact separates under ``control``; for laws
            /// with an infinite tail, where |P| < rel_force·|P_c|.
            #[pyo3(signature = (control=None, rel_force=None))]
            fn reach(
                &self,
                control: Option<&Bound<'_, PyAny>>,
                rel_force: Option<&Bound<'_, PyAny>>,
            ) -> PyResult<f64> {
                let c = match control {
                    Some(c) => $crate::common::control(c)?,
                    None => asperity::Control::Displacement,
                };
                let r = $crate::common::real_opt(rel_force, "rel_force")?
                    .unwrap_or($crate::contact::DEFAULT_REL_FORCE);
                asperity::NormalContact::reach(&self.inner, c, r).map_err($crate::common::rs)
            }

            /// energy(delta, state=None) -> float | numpy.ndarray
            ///
            /// Energy U (J) of the equilibrium at overlap ``delta`` (m) from
            /// ``state``: elastic energy minus the surface energy of the
            /// contact, dU/dδ = P. asperity.Error for a law without a closed
            /// form.
            #[pyo3(signature = (delta, state=None))]
            fn energy(
                &self,
                py: Python<'_>,
                delta: &Bound<'_, PyAny>,
                state: Option<&Bound<'_, $crate::contact::ContactState>>,
            ) -> PyResult<Py<PyAny>> {
                $crate::contact::energy_any(&self.inner, py, delta, state)
            }

            $(
                $(#[$gm])*
                #[getter]
                fn $g(&self) -> f64 {
                    self.inner.params().$g
                }
            )*

            $($extra)*
        }
    };
}

fn point_dict<'py>(
    py: Python<'py>,
    md: &c::MaugisDugdale,
    p: c::maugis_dugdale::CurvePoint,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (k, v) in point_values(md, &p).iter().zip(POINT_KEYS) {
        d.set_item(v, *k)?;
    }
    Ok(d)
}

/// Keys of a Maugis–Dugdale curve point: SI, then reduced.
const POINT_KEYS: [&str; 12] = [
    "contact_radius",
    "cohesive_radius",
    "force",
    "delta",
    "stiffness",
    "a_bar",
    "c_bar",
    "p_bar",
    "delta_bar",
    "dp_bar",
    "ddelta_bar",
    "stiffness_bar",
];

fn point_values(md: &c::MaugisDugdale, p: &c::maugis_dugdale::CurvePoint) -> [f64; 12] {
    let (rs_, fs, ds) = (
        md.radius_scale(),
        md.force_scale(),
        asperity::NormalContact::length_scale(md),
    );
    [
        p.a_bar * rs_,
        p.c_bar * rs_,
        p.p_bar * fs,
        p.delta_bar * ds,
        p.stiffness_bar() * fs / ds,
        p.a_bar,
        p.c_bar,
        p.p_bar,
        p.delta_bar,
        p.dp_bar,
        p.ddelta_bar,
        p.stiffness_bar(),
    ]
}

/// A Maugis–Dugdale curve point per parameter, on a float (dict of floats)
/// or an array (dict of arrays, the GIL released).
fn points_any(
    py: Python<'_>,
    md: &c::MaugisDugdale,
    x: &Bound<'_, PyAny>,
    name: &str,
    f: impl Fn(f64) -> asperity::Result<c::maugis_dugdale::CurvePoint> + Send + Sync,
) -> PyResult<Py<PyAny>> {
    crate::common::vectorize_record(py, x, name, POINT_KEYS, |v| {
        f(v).map(|p| point_values(md, &p))
    })
}

normal_law!(
    /// Hertz(radius, e_star)
    ///
    /// Hertz's elastic sphere: P = (4/3) E* R^½ δ^(3/2). radius R (m), contact
    /// modulus e_star E* (Pa).
    Hertz, c::Hertz, "Hertz",
    getters {
        /// Sphere radius R (m).
        radius,
        /// Contact modulus E* (Pa).
        e_star,
    }
    {
        #[new]
        fn new(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::Hertz::new(real(radius, "radius")?, real(e_star, "e_star")?).map_err(rs)? })
        }
        /// sphere_in_crater(radius, medium_radius, e_star) -> Hertz
        ///
        /// A sphere of radius R (m) in a spherical crater of radius
        /// medium_radius (m, > R): the effective radius of the pair.
        #[staticmethod]
        fn sphere_in_crater(radius: &Bound<'_, PyAny>, medium_radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::Hertz::sphere_in_crater(real(radius, "radius")?, real(medium_radius, "medium_radius")?, real(e_star, "e_star")?).map_err(rs)? })
        }
        /// contact_radius_at_load(force) -> float
        ///
        /// Contact radius a = (3PR/(4E*))^(1/3) (m) at force P (N, ≥ 0).
        fn contact_radius_at_load(&self, force: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.contact_radius_at_load(real(force, "force")?))
        }
        /// peak_pressure(force) -> float
        ///
        /// Peak contact pressure p0 = 3P/(2πa²) (Pa) at force P (N).
        fn peak_pressure(&self, force: &Bound<'_, PyAny>) -> PyResult<f64> {
            self.inner.peak_pressure(real(force, "force")?).map_err(rs)
        }
        fn __repr__(&self) -> String {
            format!("Hertz(radius={:e}, e_star={:e})", self.inner.params().radius, self.inner.params().e_star)
        }
    }
);

normal_law!(
    /// Dmt(radius, e_star, work_of_adhesion)
    ///
    /// Derjaguin–Muller–Toporov sphere: Hertz plus a constant adhesive force
    /// -2πwR. radius R (m), e_star E* (Pa), work_of_adhesion w (J/m²).
    Dmt, c::Dmt, "Dmt",
    getters {
        /// Sphere radius R (m).
        radius,
        /// Contact modulus E* (Pa).
        e_star,
        /// Work of adhesion w (J/m²).
        work_of_adhesion,
    }
    {
        #[new]
        fn new(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::Dmt::new(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?).map_err(rs)? })
        }
        /// adhesive_force() -> float
        ///
        /// The DMT adhesive force 2πwR (N, positive).
        fn adhesive_force(&self) -> f64 {
            self.inner.adhesive_force()
        }
        fn __repr__(&self) -> String {
            format!("Dmt(radius={:e}, e_star={:e}, work_of_adhesion={:e})", self.inner.params().radius, self.inner.params().e_star, self.inner.params().work_of_adhesion)
        }
    }
);

normal_law!(
    /// Jkr(radius, e_star, work_of_adhesion)
    ///
    /// Johnson–Kendall–Roberts sphere with jump-in at δ = 0 and jump-out at
    /// the critical overlap (hysteresis in the state). radius R (m), e_star E*
    /// (Pa), work_of_adhesion w (J/m²). Pull-off -1.5πwR under load control.
    Jkr, c::Jkr, "Jkr",
    getters {
        /// Sphere radius R (m).
        radius,
        /// Contact modulus E* (Pa).
        e_star,
        /// Work of adhesion w (J/m²).
        work_of_adhesion,
    }
    {
        /// The critical (jump-out) overlap δ_c (m, < 0) under displacement control.
        #[getter]
        fn critical_delta(&self) -> f64 {
            self.inner.critical_delta()
        }
        /// Overlap scale (π²w²R/E*²)^(1/3) (m).
        #[getter]
        fn delta_scale(&self) -> f64 {
            self.inner.delta_scale()
        }
        #[new]
        fn new(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::Jkr::new(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?).map_err(rs)? })
        }
        /// force_at_radius(a) -> float
        ///
        /// JKR force P (N) at contact radius a (m).
        fn force_at_radius(&self, a: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.force_at_radius(real(a, "a")?))
        }
        /// delta_at_radius(a) -> float
        ///
        /// JKR overlap δ (m) at contact radius a (m).
        fn delta_at_radius(&self, a: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.delta_at_radius(real(a, "a")?))
        }
        /// contact_radius_at_delta(delta) -> float | None
        ///
        /// Contact radius a (m) on the stable branch at overlap δ (m); None
        /// below the critical overlap.
        fn contact_radius_at_delta(&self, delta: &Bound<'_, PyAny>) -> PyResult<Option<f64>> {
            Ok(self.inner.contact_radius_at_delta(real(delta, "delta")?))
        }
        fn __repr__(&self) -> String {
            format!("Jkr(radius={:e}, e_star={:e}, work_of_adhesion={:e})", self.inner.params().radius, self.inner.params().e_star, self.inner.params().work_of_adhesion)
        }
    }
);

normal_law!(
    /// MaugisDugdale(radius, e_star, work_of_adhesion, sigma0)
    ///
    /// Maugis–Dugdale sphere (Maugis 1992): a Dugdale cohesive stress σ0 over
    /// a range h0 = w/σ0 outside the contact, bridging DMT (λ → 0) and JKR
    /// (λ → ∞). radius R (m), e_star E* (Pa), work_of_adhesion w (J/m²),
    /// sigma0 (the Rust API's ``cohesive_stress``) σ0 (Pa). Also
    /// ``MaugisDugdale.from_tabor`` and ``MaugisDugdale.from_maugis_parameter``.
    MaugisDugdale, c::MaugisDugdale, "MaugisDugdale",
    getters {
        /// Sphere radius R (m).
        radius,
        /// Contact modulus E* (Pa).
        e_star,
        /// Work of adhesion w (J/m²).
        work_of_adhesion,
        /// Dugdale cohesive stress σ0 (Pa).
        cohesive_stress,
    }
    {
        #[new]
        #[pyo3(signature = (radius, e_star, work_of_adhesion, sigma0=None, *, cohesive_stress=None))]
        fn new(
            radius: &Bound<'_, PyAny>,
            e_star: &Bound<'_, PyAny>,
            work_of_adhesion: &Bound<'_, PyAny>,
            sigma0: Option<&Bound<'_, PyAny>>,
            cohesive_stress: Option<&Bound<'_, PyAny>>,
        ) -> PyResult<Self> {
            let (s, name) = match (sigma0, cohesive_stress) {
                (Some(s), None) => (real(s, "sigma0")?, "sigma0"),
                (None, Some(s)) => (real(s, "cohesive_stress")?, "cohesive_stress"),
                _ => return Err(arg_error("sigma0", "give exactly one of sigma0 and cohesive_stress (Pa)")),
            };
            let inner = c::MaugisDugdale::new(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?, s)
                .map_err(|e| crate::common::rs(crate::common::renamed(e, "cohesive_stress", name)))?;
            Ok(Self { inner })
        }
        /// from_tabor(radius, e_star, work_of_adhesion, equilibrium_separation) -> MaugisDugdale
        ///
        /// The Maugis–Dugdale sphere that stands for a Lennard-Jones surface
        /// law of equilibrium separation z0 (m): σ0 = 16w/(9√3 z0), λ = 1.157μ.
        #[staticmethod]
        fn from_tabor(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>, equilibrium_separation: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::MaugisDugdale::from_tabor(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?, real(equilibrium_separation, "equilibrium_separation")?).map_err(rs)? })
        }
        /// from_maugis_parameter(radius, e_star, work_of_adhesion, lambda_) -> MaugisDugdale
        ///
        /// The Maugis–Dugdale sphere with Maugis parameter λ (dimensionless):
        /// σ0 = (λ/2)(πwK²/R)^(1/3), K = 4E*/3.
        #[staticmethod]
        fn from_maugis_parameter(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>, lambda_: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::MaugisDugdale::from_maugis_parameter(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?, real(lambda_, "lambda")?).map_err(rs)? })
        }
        /// Maugis parameter λ (dimensionless).
        #[getter]
        fn lambda_(&self) -> f64 {
            self.inner.lambda()
        }
        /// range() -> float
        ///
        /// Range of the Dugdale stress h0 = w/σ0 (m).
        fn range(&self) -> f64 {
            self.inner.range()
        }
        /// force_scale() -> float
        ///
        /// Force scale πwR (N) of the reduced variables.
        fn force_scale(&self) -> f64 {
            self.inner.force_scale()
        }
        /// radius_scale() -> float
        ///
        /// Radius scale (πwR²/K)^(1/3) (m) of the reduced variables.
        fn radius_scale(&self) -> f64 {
            self.inner.radius_scale()
        }
        /// has_contact_jump() -> bool
        ///
        /// Whether the displacement-controlled curve jumps (λ above the
        /// S-curve onset).
        fn has_contact_jump(&self) -> bool {
            self.inner.has_contact_jump()
        }
        /// jump_out_point() -> dict
        ///
        /// The displacement-controlled separation point, keys as
        /// ``contact_point`` (SI and reduced).
        fn jump_out_point<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
            point_dict(py, &self.inner, self.inner.jump_out_point())
        }
        /// load_pull_off_point() -> dict
        ///
        /// The load-controlled pull-off point, keys as ``contact_point``.
        fn load_pull_off_point<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
            point_dict(py, &self.inner, self.inner.load_pull_off_point())
        }
        /// contact_point(s) -> dict
        ///
        /// The point of the contact branch at parameter s = √(m² - 1) > 0
        /// (m = c/a), in closed form (Maugis' equation is quadratic in Ā for
        /// a given m): a float, or an array of them for a whole
        /// load–approach curve (arrays out, the GIL released). Keys, SI:
        /// ``contact_radius`` a (m), ``cohesive_radius`` c (m), ``force`` P
        /// (N), ``delta`` δ (m), ``stiffness`` dP/dδ (N/m); reduced: ``a_bar``,
        /// ``c_bar``, ``p_bar``, ``delta_bar``, ``dp_bar``, ``ddelta_bar``
        /// (derivatives with respect to s), ``stiffness_bar``.
        fn contact_point(&self, py: Python<'_>, s: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
            let md = self.inner;
            points_any(py, &md, s, "s", |v| md.contact_point(v))
        }
        /// non_contact_point(c_bar) -> dict
        ///
        /// The point of the non-contact branch with reduced cohesive radius
        /// c_bar in [0, C̄0] (a float or an array); keys as ``contact_point``.
        fn non_contact_point(&self, py: Python<'_>, c_bar: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
            let md = self.inner;
            points_any(py, &md, c_bar, "c_bar", |v| md.non_contact_point(v))
        }
        fn __repr__(&self) -> String {
            format!("MaugisDugdale(radius={:e}, e_star={:e}, work_of_adhesion={:e}, sigma0={:e})", self.inner.params().radius, self.inner.params().e_star, self.inner.params().work_of_adhesion, self.inner.params().cohesive_stress)
        }
    }
);

normal_law!(
    /// Kendall(radius, e_star, work_of_adhesion)
    ///
    /// Kendall's adhesive flat punch of radius a (m): P = 2E* C_NS a δ,
    /// pull-off -√(8πwE* C_NS a³). ``Kendall.no_slip(radius, e_star,
    /// work_of_adhesion, nu)`` for a bonded punch.
    Kendall, c::Kendall, "Kendall",
    getters {
        /// Punch radius a (m).
        radius,
        /// Contact modulus E* (Pa).
        e_star,
        /// Work of adhesion w (J/m²).
        work_of_adhesion,
        /// Poisson's ratio ν of the bonded punch (0 when frictionless).
        nu,
    }
    {
        /// Stiffness 2E* C_NS a (N/m).
        #[getter]
        fn stiffness(&self) -> f64 {
            self.inner.stiffness()
        }
        /// Critical (jump-out) overlap (m, < 0).
        #[getter]
        fn critical_delta(&self) -> f64 {
            self.inner.critical_delta()
        }
        /// Whether the punch is bonded (no slip).
        #[getter]
        fn bonded(&self) -> bool {
            self.inner.params().no_slip != 0
        }
        #[new]
        fn new(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::Kendall::new(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?).map_err(rs)? })
        }
        /// no_slip(radius, e_star, work_of_adhesion, nu) -> Kendall
        ///
        /// The bonded (no-slip) punch for Poisson's ratio nu in [0, 0.5].
        #[staticmethod]
        fn no_slip(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>, nu: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::Kendall::no_slip(real(radius, "radius")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?, real(nu, "nu")?).map_err(rs)? })
        }
        fn __repr__(&self) -> String {
            format!("Kendall(radius={:e}, e_star={:e}, work_of_adhesion={:e})", self.inner.params().radius, self.inner.params().e_star, self.inner.params().work_of_adhesion)
        }
    }
);

normal_law!(
    /// FlatPunch(radius, e_star)
    ///
    /// Boussinesq's rigid flat punch: P = 2E* a δ. radius a (m), e_star E*
    /// (Pa). ``FlatPunch.no_slip(radius, e_star, nu)`` for a bonded punch.
    FlatPunch, c::FlatPunch, "FlatPunch",
    getters {
        /// Punch radius a (m).
        radius,
        /// Contact modulus E* (Pa).
        e_star,
        /// Poisson's ratio ν of the bonded punch (0 when frictionless).
        nu,
    }
    {
        /// Stiffness 2E* a (N/m), times C_NS when bonded.
        #[getter]
        fn stiffness(&self) -> f64 {
            self.inner.stiffness()
        }
        /// Whether the punch is bonded (no slip).
        #[getter]
        fn bonded(&self) -> bool {
            self.inner.params().no_slip != 0
        }
        #[new]
        fn new(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::FlatPunch::new(real(radius, "radius")?, real(e_star, "e_star")?).map_err(rs)? })
        }
        /// no_slip(radius, e_star, nu) -> FlatPunch
        ///
        /// The bonded (no-slip) punch for Poisson's ratio nu in [0, 0.5].
        #[staticmethod]
        fn no_slip(radius: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, nu: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::FlatPunch::no_slip(real(radius, "radius")?, real(e_star, "e_star")?, real(nu, "nu")?).map_err(rs)? })
        }
        fn __repr__(&self) -> String {
            format!("FlatPunch(radius={:e}, e_star={:e})", self.inner.params().radius, self.inner.params().e_star)
        }
    }
);

normal_law!(
    /// PowerPunch(b, d, e_star)
    ///
    /// Galin's power-law punch f(r) = B r^d: P = C(d) B E* a^(d+1),
    /// δ = D(d) B a^d. b B (m^(1-d)), d (> 0), e_star E* (Pa). Cones:
    /// ``PowerPunch.cone(half_angle, e_star)``.
    PowerPunch, c::PowerPunch, "PowerPunch",
    getters {
        /// Shape coefficient B (m^(1-d)).
        b,
        /// Shape exponent d (dimensionless).
        d,
        /// Contact modulus E* (Pa).
        e_star,
    }
    {
        #[new]
        fn new(b: &Bound<'_, PyAny>, d: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::PowerPunch::new(real(b, "b")?, real(d, "d")?, real(e_star, "e_star")?).map_err(rs)? })
        }
        /// cone(half_angle, e_star) -> PowerPunch
        ///
        /// A cone of half-angle (rad, in (0, π/2)): B = cot(half_angle), d = 1.
        #[staticmethod]
        fn cone(half_angle: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::PowerPunch::cone(real(half_angle, "half_angle")?, real(e_star, "e_star")?).map_err(rs)? })
        }
        /// cone_in_imprint(indenter_half_angle, imprint_half_angle, e_star) -> PowerPunch
        ///
        /// Galanov's effective cone of a cone unloading from a conical imprint
        /// (half-angles in rad).
        #[staticmethod]
        fn cone_in_imprint(indenter_half_angle: &Bound<'_, PyAny>, imprint_half_angle: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::PowerPunch::cone_in_imprint(real(indenter_half_angle, "indenter_half_angle")?, real(imprint_half_angle, "imprint_half_angle")?, real(e_star, "e_star")?).map_err(rs)? })
        }
        /// delta_at_radius(a) -> float
        ///
        /// Overlap δ (m) at contact radius a (m).
        fn delta_at_radius(&self, a: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.delta_at_radius(real(a, "a")?))
        }
        /// force_at_radius(a) -> float
        ///
        /// Force P (N) at contact radius a (m).
        fn force_at_radius(&self, a: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.force_at_radius(real(a, "a")?))
        }
        /// radius_at_delta(delta) -> float
        ///
        /// Contact radius a (m) at overlap δ (m).
        fn radius_at_delta(&self, delta: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.radius_at_delta(real(delta, "delta")?))
        }
        fn __repr__(&self) -> String {
            format!("PowerPunch(b={:e}, d={}, e_star={:e})", self.inner.params().b, self.inner.params().d, self.inner.params().e_star)
        }
    }
);

normal_law!(
    /// JkrPowerPunch(b, d, e_star, work_of_adhesion)
    ///
    /// JKR adhesion on Galin's power-law punch f(r) = B r^d (Borodich):
    /// b B (m^(1-d)), d, e_star E* (Pa), work_of_adhesion w (J/m²).
    /// ``JkrPowerPunch.no_slip(b, d, e_star, work_of_adhesion, nu)`` for the
    /// bonded punch.
    JkrPowerPunch, c::JkrPowerPunch, "JkrPowerPunch",
    getters {
        /// Shape coefficient B (m^(1-d)).
        b,
        /// Shape exponent d.
        d,
        /// Contact modulus E* (Pa).
        e_star,
        /// Work of adhesion w (J/m²).
        work_of_adhesion,
        /// Poisson's ratio ν of the bonded punch (0 when frictionless).
        nu,
    }
    {
        /// Critical (jump-out) overlap (m).
        #[getter]
        fn critical_delta(&self) -> f64 {
            self.inner.critical_delta()
        }
        /// Borodich's no-slip shape factor k*(d, ν) (1 frictionless).
        #[getter]
        fn k_star(&self) -> f64 {
            self.inner.k_star()
        }
        #[new]
        fn new(b: &Bound<'_, PyAny>, d: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::JkrPowerPunch::new(real(b, "b")?, real(d, "d")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?).map_err(rs)? })
        }
        /// no_slip(b, d, e_star, work_of_adhesion, nu) -> JkrPowerPunch
        ///
        /// The bonded punch for Poisson's ratio nu in [0, 0.5].
        #[staticmethod]
        fn no_slip(b: &Bound<'_, PyAny>, d: &Bound<'_, PyAny>, e_star: &Bound<'_, PyAny>, work_of_adhesion: &Bound<'_, PyAny>, nu: &Bound<'_, PyAny>) -> PyResult<Self> {
            Ok(Self { inner: c::JkrPowerPunch::no_slip(real(b, "b")?, real(d, "d")?, real(e_star, "e_star")?, real(work_of_adhesion, "work_of_adhesion")?, real(nu, "nu")?).map_err(rs)? })
        }
        /// force_at_radius(a) -> float
        ///
        /// Force P (N) at contact radius a (m).
        fn force_at_radius(&self, a: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.force_at_radius(real(a, "a")?))
        }
        /// delta_at_radius(a) -> float
        ///
        /// Overlap δ (m) at contact radius a (m).
        fn delta_at_radius(&self, a: &Bound<'_, PyAny>) -> PyResult<f64> {
            Ok(self.inner.delta_at_radius(real(a, "a")?))
        }
        fn __repr__(&self) -> String {
            format!("JkrPowerPunch(b={:e}, d={}, e_star={:e}, work_of_adhesion={:e})", self.inner.params().b, self.inner.params().d, self.inner.params().e_star, self.inner.params().work_of_adhesion)
        }
    }
);

/// A surface-force law p(z) between flats (attraction positive), for
/// ``Derjaguin``: ``SurfaceLaw.lennard_jones(work_of_adhesion,
/// equilibrium_separation)``, ``SurfaceLaw.dugdale(work_of_adhesion,
/// cohesive_stress)`` or ``SurfaceLaw.exponential(work_of_adhesion,
/// decay_length)``; w in J/m², lengths in m, stress in Pa.
#[pyclass(module = "asperity", frozen)]
#[derive(Clone)]
pub struct SurfaceLaw {
    pub inner: c::SurfaceLaw,
}

impl SurfaceLaw {
    fn validated(l: c::SurfaceLaw) -> PyResult<Self> {
        Ok(Self {
            inner: l.validate().map_err(rs)?,
        })
    }
}

#[pymethods]
impl SurfaceLaw {
    /// lennard_jones(work_of_adhesion, equilibrium_separation) -> SurfaceLaw
    ///
    /// Lennard-Jones 3-9: p(z) = (8w/(3z0))[(z0/z)³ - (z0/z)⁹].
    #[staticmethod]
    fn lennard_jones(
        work_of_adhesion: &Bound<'_, PyAny>,
        equilibrium_separation: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let l = c::SurfaceLaw::LennardJones {
            work_of_adhesion: real(work_of_adhesion, "work_of_adhesion")?,
            equilibrium_separation: real(equilibrium_separation, "equilibrium_separation")?,
        };
        Self::validated(l)
    }
    /// dugdale(work_of_adhesion, cohesive_stress) -> SurfaceLaw
    ///
    /// Dugdale step: p = σ0 for 0 ≤ z ≤ w/σ0.
    #[staticmethod]
    fn dugdale(
        work_of_adhesion: &Bound<'_, PyAny>,
        cohesive_stress: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let l = c::SurfaceLaw::Dugdale {
            work_of_adhesion: real(work_of_adhesion, "work_of_adhesion")?,
            cohesive_stress: real(cohesive_stress, "cohesive_stress")?,
        };
        Self::validated(l)
    }
    /// exponential(work_of_adhesion, decay_length) -> SurfaceLaw
    ///
    /// Exponential: p(z) = (w/ℓ) exp(-z/ℓ).
    #[staticmethod]
    fn exponential(
        work_of_adhesion: &Bound<'_, PyAny>,
        decay_length: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let l = c::SurfaceLaw::Exponential {
            work_of_adhesion: real(work_of_adhesion, "work_of_adhesion")?,
            decay_length: real(decay_length, "decay_length")?,
        };
        Self::validated(l)
    }
    /// work_of_adhesion() -> float
    ///
    /// Work of adhesion w = ∫ p dz (J/m²).
    fn work_of_adhesion(&self) -> f64 {
        self.inner.work_of_adhesion()
    }
    /// range() -> float
    ///
    /// The law's length (m): z0, h0 or ℓ.
    fn range(&self) -> f64 {
        self.inner.range()
    }
    /// pressure(gap) -> float
    ///
    /// Surface pressure p (Pa, attraction positive) at gap z (m).
    fn pressure(&self, gap: &Bound<'_, PyAny>) -> PyResult<f64> {
        self.inner.pressure(real(gap, "gap")?).map_err(rs)
    }
    /// energy(gap) -> float
    ///
    /// Interaction energy per unit area e(D) = ∫_D^∞ p dz (J/m²) at gap D (m).
    fn energy(&self, gap: &Bound<'_, PyAny>) -> PyResult<f64> {
        self.inner.energy(real(gap, "gap")?).map_err(rs)
    }
    /// peak_tension() -> float
    ///
    /// The largest attraction (Pa).
    fn peak_tension(&self) -> PyResult<f64> {
        self.inner.peak_tension().map_err(rs)
    }
    fn __repr__(&self) -> String {
        format!("SurfaceLaw({:?})", self.inner)
    }
}

normal_law!(
    /// Derjaguin(radius, surface_law)
    ///
    /// A rigid sphere of radius R (m) under a surface-force law (Derjaguin's
    /// approximation): P = -2πR ∫_D^∞ p(z) dz. Overlap δ = z0 - D for
    /// Lennard-Jones, δ = -D for Dugdale and exponential laws.
    Derjaguin, c::Derjaguin, "Derjaguin",
    getters {
        /// Sphere radius R (m).
        radius,
        /// Work of adhesion w (J/m²).
        work_of_adhesion,
    }
    {
        /// The surface law's range (m): z0, h0 or ℓ.
        #[getter]
        fn range(&self) -> f64 {
            self.inner.surface_law().range()
        }
        #[new]
        fn new(radius: &Bound<'_, PyAny>, surface_law: &Bound<'_, SurfaceLaw>) -> PyResult<Self> {
            Ok(Self { inner: c::Derjaguin::new(real(radius, "radius")?, surface_law.get().inner).map_err(rs)? })
        }
        /// The surface law (``SurfaceLaw``).
        #[getter]
        fn surface_law(&self) -> SurfaceLaw {
            SurfaceLaw { inner: self.inner.surface_law() }
        }
        /// adhesive_force() -> float
        ///
        /// 2πwR (N).
        fn adhesive_force(&self) -> f64 {
            self.inner.adhesive_force()
        }
        /// force_at_gap(gap) -> float
        ///
        /// Force P (N, positive repulsive) at gap D (m).
        fn force_at_gap(&self, gap: &Bound<'_, PyAny>) -> PyResult<f64> {
            self.inner.force_at_gap(real(gap, "gap")?).map_err(rs)
        }
        fn __repr__(&self) -> String {
            format!("Derjaguin(radius={:e}, surface_law={:?})", self.inner.params().radius, self.inner.surface_law())
        }
    }
);

/// galin_c(d) -> float
///
/// Galin's force coefficient C(d) of a power-law punch (dimensionless).
#[pyfunction]
fn galin_c(d: &Bound<'_, PyAny>) -> PyResult<f64> {
    Ok(c::power_punch::galin_c(real(d, "d")?))
}

/// galin_d(d) -> float
///
/// Galin's depth coefficient D(d) of a power-law punch (dimensionless).
#[pyfunction]
fn galin_d(d: &Bound<'_, PyAny>) -> PyResult<f64> {
    Ok(c::power_punch::galin_d(real(d, "d")?))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<ContactState>()?;
    m.add_class::<NormalResponse>()?;
    m.add_class::<Hertz>()?;
    m.add_class::<Dmt>()?;
    m.add_class::<Jkr>()?;
    m.add_class::<MaugisDugdale>()?;
    m.add_class::<Kendall>()?;
    m.add_class::<FlatPunch>()?;
    m.add_class::<PowerPunch>()?;
    m.add_class::<JkrPowerPunch>()?;
    m.add_class::<SurfaceLaw>()?;
    m.add_class::<Derjaguin>()?;
    m.add_function(wrap_pyfunction!(galin_c, m)?)?;
    m.add_function(wrap_pyfunction!(galin_d, m)?)?;
    m.add(
        "BERKOVICH_EQUIVALENT_HALF_ANGLE",
        c::power_punch::BERKOVICH_EQUIVALENT_HALF_ANGLE,
    )?;
    m.add(
        "VICKERS_EQUIVALENT_HALF_ANGLE",
        c::power_punch::VICKERS_EQUIVALENT_HALF_ANGLE,
    )?;
    m.add(
        "CUBE_CORNER_EQUIVALENT_HALF_ANGLE",
        c::power_punch::CUBE_CORNER_EQUIVALENT_HALF_ANGLE,
    )?;
    Ok(())
}
