//! What every domain module shares: the `asperity.Error` exception and the
//! mapping of the Rust error to it, argument extraction that names the
//! argument on a bad type, numpy array checks (1-D, float64, C-contiguous)
//! and the control-mode selector.

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyFloat, PyList, PyTuple};

pyo3::create_exception!(
    asperity,
    Error,
    PyValueError,
    "An argument outside its documented domain, a state that does not exist, a solver that \
did not converge, an unreadable file: the message names the argument and its bound, as the \
Rust and C errors do. A subclass of ValueError."
);

/// The Rust error as `asperity.Error` (its message names the argument and
/// the bound).
pub fn rs(e: asperity::Error) -> PyErr {
    Error::new_err(e.to_string())
}

/// A failed batch as `asperity.Error`: `element i: <error>`, as the C ABI
/// reports it.
pub fn batch(e: asperity::contact::BatchError) -> PyErr {
    if e.index == 0
        && matches!(e.error, asperity::Error::InvalidArgument { name, .. } if name != "delta")
    {
        Error::new_err(e.error.to_string())
    } else {
        Error::new_err(e.to_string())
    }
}

/// `asperity.Error` with a message about argument `name`.
pub fn arg_error(name: &str, message: impl std::fmt::Display) -> PyErr {
    Error::new_err(format!("invalid argument `{name}`: {message}"))
}

/// Map any Rust error with a `Display` (scene errors, read errors) to
/// `asperity.Error`.
pub fn any_err(e: impl std::fmt::Display) -> PyErr {
    Error::new_err(e.to_string())
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".into())
}

/// A real number (float, int, numpy scalar) for argument `name`; anything
/// else is `asperity.Error` naming the argument. Range checks are the Rust
/// API's (which names the argument and the bound).
#[inline]
pub fn real(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    if let Ok(f) = obj.cast::<PyFloat>() {
        return Ok(f.value());
    }
    if obj.is_instance_of::<pyo3::types::PyString>() || obj.is_none() {
        return Err(arg_error(
            name,
            format!("must be a real number (float), got {}", type_name(obj)),
        ));
    }
    obj.extract::<f64>().map_err(|_| {
        arg_error(
            name,
            format!("must be a real number (float), got {}", type_name(obj)),
        )
    })
}

/// An optional real number.
pub fn real_opt(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<f64>> {
    match obj {
        None => Ok(None),
        Some(o) if o.is_none() => Ok(None),
        Some(o) => real(o, name).map(Some),
    }
}

/// A non-negative integer for argument `name`.
pub fn count(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<usize> {
    if obj.is_instance_of::<pyo3::types::PyFloat>() {
        return Err(arg_error(name, "must be a non-negative integer, got float"));
    }
    obj.extract::<usize>().map_err(|_| {
        arg_error(
            name,
            format!("must be a non-negative integer, got {}", type_name(obj)),
        )
    })
}

/// An integer seed (any u64).
pub fn seed(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<u64> {
    obj.extract::<u64>().map_err(|_| {
        arg_error(
            name,
            format!("must be an integer in [0, 2**64), got {}", type_name(obj)),
        )
    })
}

/// A string for argument `name`.
pub fn string(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<String> {
    obj.extract::<String>()
        .map_err(|_| arg_error(name, format!("must be a string, got {}", type_name(obj))))
}

/// A float or a 1-D array argument.
pub enum RealOrArray<'py> {
    /// A Python float (or int, numpy scalar).
    Scalar(f64),
    /// A 1-D C-contiguous float64 array (lists and tuples are converted).
    Array(PyReadonlyArray1<'py, f64>),
}

/// A 1-D, C-contiguous float64 numpy array for argument `name`; a list or
/// tuple of numbers is converted. Arrays of another dtype or shape, or
/// non-contiguous views, are `asperity.Error` naming the argument and what
/// it must be (no silent copy).
pub fn array<'py>(obj: &Bound<'py, PyAny>, name: &str) -> PyResult<PyReadonlyArray1<'py, f64>> {
    if let Ok(a) = obj.cast::<PyArray1<f64>>() {
        if !a.is_c_contiguous() {
            return Err(arg_error(
                name,
                "must be a C-contiguous array (got a strided view; use numpy.ascontiguousarray)",
            ));
        }
        return a
            .try_readonly()
            .map_err(|e| arg_error(name, format!("cannot be borrowed: {e}")));
    }
    if let Ok(u) = obj.cast::<PyUntypedArray>() {
        let dtype = u.dtype().str().map(|s| s.to_string()).unwrap_or_default();
        return Err(arg_error(
            name,
            format!(
                "must be a 1-D float64 array (got dtype {dtype} with {} dimension{}; use numpy.asarray(x, dtype=float).ravel())",
                u.ndim(),
                if u.ndim() == 1 { "" } else { "s" }
            ),
        ));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        let v: Vec<f64> = obj
            .extract()
            .map_err(|_| arg_error(name, "must be a sequence of real numbers (float)"))?;
        let py = obj.py();
        return Ok(PyArray1::from_vec(py, v).readonly());
    }
    Err(arg_error(
        name,
        format!(
            "must be a 1-D float64 numpy array or a sequence of floats, got {}",
            type_name(obj)
        ),
    ))
}

/// A float or a 1-D array (see [`array`]).
pub fn real_or_array<'py>(obj: &Bound<'py, PyAny>, name: &str) -> PyResult<RealOrArray<'py>> {
    if let Ok(f) = obj.cast::<PyFloat>() {
        return Ok(RealOrArray::Scalar(f.value()));
    }
    if obj.cast::<PyUntypedArray>().is_ok()
        || obj.is_instance_of::<PyList>()
        || obj.is_instance_of::<PyTuple>()
    {
        return array(obj, name).map(RealOrArray::Array);
    }
    real(obj, name).map(RealOrArray::Scalar).map_err(|_| {
        arg_error(
            name,
            format!(
                "must be a float or a 1-D float64 array, got {}",
                type_name(obj)
            ),
        )
    })
}

/// The control mode: `"load"` or `"displacement"`.
pub fn control(obj: &Bound<'_, PyAny>) -> PyResult<asperity::Control> {
    let s = string(obj, "control")?;
    match s.as_str() {
        "load" => Ok(asperity::Control::Load),
        "displacement" => Ok(asperity::Control::Displacement),
        _ => Err(arg_error(
            "control",
            format!("must be \"load\" or \"displacement\", got {s:?}"),
        )),
    }
}

/// A JSON text (from the Rust API's serde output) as Python objects
/// (dicts, lists, floats; `null` as None).
pub fn json_value(py: Python<'_>, text: &str) -> PyResult<Py<PyAny>> {
    let json = py.import("json")?;
    Ok(json.call_method1("loads", (text,))?.unbind())
}

/// A serde-serialisable Rust value as Python objects, via JSON.
pub fn to_py_value<T: serde::Serialize>(py: Python<'_>, v: &T) -> PyResult<Py<PyAny>> {
    let text = serde_json::to_string(v).map_err(any_err)?;
    json_value(py, &text)
}

/// A Python object (dict, list, …) as JSON text, via the `json` module.
pub fn py_to_json(obj: &Bound<'_, PyAny>) -> PyResult<String> {
    let json = obj.py().import("json")?;
    json.call_method1("dumps", (obj,))?.extract()
}

/// The Rust error with the argument name `from` replaced by `to` (the name
/// the Python caller used).
pub fn renamed(e: asperity::Error, from: &'static str, to: &'static str) -> asperity::Error {
    use asperity::Error as E;
    match e {
        E::InvalidArgument { name, value, bound } if name == from => E::InvalidArgument {
            name: to,
            value,
            bound,
        },
        E::OutOfDomain {
            name,
            value,
            reason,
        } if name == from => E::OutOfDomain {
            name: to,
            value,
            reason,
        },
        other => other,
    }
}

/// A Python function over a fallible Rust function of real arguments:
/// `scalar_fn!(name, rust::path, "doc", (a, b, c))` defines
/// `name(a, b, c) -> float`, each argument checked as a real number named
/// as in the Rust API.
#[macro_export]
macro_rules! scalar_fn {
    ($name:ident, $path:path, $doc:literal, ($($arg:ident),*)) => {
        #[doc = $doc]
        #[pyfunction]
        fn $name($($arg: &Bound<'_, PyAny>),*) -> PyResult<f64> {
            $path($($crate::common::real($arg, stringify!($arg))?),*).map_err($crate::common::rs)
        }
    };
}

/// `f` element by element on `xs` with the GIL released; a failing
/// element's error starts with `element i:`.
fn elementwise<T, F>(py: Python<'_>, xs: &[f64], f: F) -> PyResult<Vec<T>>
where
    T: Send,
    F: Fn(f64) -> asperity::Result<T> + Send + Sync,
{
    py.detach(|| {
        xs.iter()
            .enumerate()
            .map(|(i, &v)| f(v).map_err(|e| (i, e)))
            .collect::<Result<Vec<T>, _>>()
    })
    .map_err(|(i, e)| Error::new_err(format!("element {i}: {e}")))
}

/// `f` on a float (-> float) or element by element on a 1-D array
/// (-> array; the GIL released; a failing element's error starts with
/// `element i:`).
pub fn vectorize<F>(py: Python<'_>, x: &Bound<'_, PyAny>, name: &str, f: F) -> PyResult<Py<PyAny>>
where
    F: Fn(f64) -> asperity::Result<f64> + Send + Sync,
{
    use pyo3::IntoPyObjectExt;
    match real_or_array(x, name)? {
        RealOrArray::Scalar(v) => f(v).map_err(rs)?.into_py_any(py),
        RealOrArray::Array(a) => {
            let out = elementwise(py, a.as_slice()?, f)?;
            Ok(PyArray1::from_vec(py, out).into_any().unbind())
        }
    }
}

/// `f` returning several named numbers, on a float (-> dict of floats) or
/// an array (-> dict of arrays).
pub fn vectorize_record<F, const K: usize>(
    py: Python<'_>,
    x: &Bound<'_, PyAny>,
    name: &str,
    keys: [&str; K],
    f: F,
) -> PyResult<Py<PyAny>>
where
    F: Fn(f64) -> asperity::Result<[f64; K]> + Send + Sync,
{
    let d = pyo3::types::PyDict::new(py);
    match real_or_array(x, name)? {
        RealOrArray::Scalar(v) => {
            let r = f(v).map_err(rs)?;
            for (k, v) in keys.iter().zip(r) {
                d.set_item(k, v)?;
            }
        }
        RealOrArray::Array(a) => {
            let rows = elementwise(py, a.as_slice()?, f)?;
            for (j, k) in keys.iter().enumerate() {
                d.set_item(
                    k,
                    PyArray1::from_vec(py, rows.iter().map(|r| r[j]).collect()),
                )?;
            }
        }
    }
    Ok(d.into_any().unbind())
}

/// A serde-serialisable Rust value as Python objects, with the exact-float
/// strings of the library's serde form (`"2.5e-7"`, used by `Dissipation`
/// and the tables so that JSON round trips are exact) turned back into
/// floats. For values whose string fields are never numbers.
pub fn to_py_numbers<T: serde::Serialize>(py: Python<'_>, v: &T) -> PyResult<Py<PyAny>> {
    fn fix(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::String(s) => {
                if let Ok(x) = s.parse::<f64>() {
                    if let Some(n) = serde_json::Number::from_f64(x) {
                        *v = serde_json::Value::Number(n);
                    }
                }
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(fix),
            serde_json::Value::Object(o) => o.values_mut().for_each(fix),
            _ => {}
        }
    }
    let mut j = serde_json::to_value(v).map_err(any_err)?;
    fix(&mut j);
    json_value(py, &j.to_string())
}

/// A Python object (dict, list, tuple, float, int, str, bool, None, numpy
/// scalars and 1-D arrays) as a `serde_json::Value` built in memory: floats
/// go in as their exact f64 (a JSON text would be re-parsed by serde_json's
/// fast float parser, which can land one ulp away).
pub fn py_to_value(obj: &Bound<'_, PyAny>) -> PyResult<serde_json::Value> {
    use pyo3::types::{PyBool, PyDict, PyInt, PyString};
    use serde_json::Value;
    if obj.is_none() {
        return Ok(Value::Null);
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Value::Bool(b.is_true()));
    }
    if obj.is_instance_of::<PyInt>() {
        if let Ok(i) = obj.extract::<i64>() {
            return Ok(Value::from(i));
        }
        if let Ok(u) = obj.extract::<u64>() {
            return Ok(Value::from(u));
        }
    }
    if let Ok(f) = obj.cast::<PyFloat>() {
        return serde_json::Number::from_f64(f.value())
            .map(Value::Number)
            .ok_or_else(|| {
                Error::new_err(format!(
                    "a non-finite number ({}) cannot be a parameter",
                    f.value()
                ))
            });
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Value::String(s.to_string_lossy().into_owned()));
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        let mut m = serde_json::Map::new();
        for (k, v) in d.iter() {
            let key: String = k
                .extract()
                .map_err(|_| Error::new_err("dict keys must be strings"))?;
            m.insert(key, py_to_value(&v)?);
        }
        return Ok(Value::Object(m));
    }
    if obj.is_instance_of::<PyList>()
        || obj.is_instance_of::<PyTuple>()
        || obj.cast::<PyUntypedArray>().is_ok()
    {
        let mut v = Vec::new();
        for x in obj.try_iter()? {
            v.push(py_to_value(&x?)?);
        }
        return Ok(Value::Array(v));
    }
    if let Ok(f) = obj.extract::<f64>() {
        return serde_json::Number::from_f64(f)
            .map(Value::Number)
            .ok_or_else(|| {
                Error::new_err(format!("a non-finite number ({f}) cannot be a parameter"))
            });
    }
    Err(Error::new_err(format!(
        "cannot use a {} as a parameter",
        type_name(obj)
    )))
}

/// A Rust value deserialised from a Python object through [`py_to_value`];
/// serde's messages name the field (`missing field \`x\``), and the error
/// names it as the argument (or `what` when serde names none).
pub fn from_py<T: serde::de::DeserializeOwned>(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<T> {
    let v = py_to_value(obj)?;
    serde_json::from_value(v).map_err(|e| {
        let m = e.to_string();
        let name = m.split('`').nth(1).unwrap_or(what).to_string();
        arg_error(&name, m)
    })
}
