//! Private timing helpers for `benches/python/bench.py`: the Rust batch
//! (`asperity::contact::eval_batch` into preallocated buffers, as a Rust
//! host code calls it) timed inside the same process and the same build as
//! the Python calls it is compared with.

use crate::common::{arg_error, array, count};
use crate::contact::*;
use asperity::contact as c;
use asperity::NormalContact;
use pyo3::prelude::*;
use std::time::Instant;

fn time_batch<L: NormalContact + Sync>(
    law: &L,
    d: &[f64],
    old: Option<&[asperity::ContactState]>,
    repeats: usize,
    states: bool,
) -> PyResult<f64> {
    let n = d.len();
    let mut f = vec![0.0; n];
    let mut a = vec![0.0; n];
    let mut k = vec![0.0; n];
    let mut s = vec![asperity::ContactState::default(); n];
    let mut best = f64::INFINITY;
    for _ in 0..repeats.max(1) {
        let t = Instant::now();
        c::eval_batch(
            law,
            std::hint::black_box(d),
            old,
            if states { Some(&mut s[..]) } else { None },
            &mut f,
            Some(&mut a),
            Some(&mut k),
        )
        .map_err(crate::common::batch)?;
        std::hint::black_box(&f);
        best = best.min(t.elapsed().as_secs_f64());
    }
    Ok(best)
}

/// _rust_eval_batch_seconds(law, delta, repeats, states=True, state=None) -> float
///
/// Fastest of ``repeats`` calls (s) of the Rust batch `eval_batch` over the
/// overlaps ``delta`` (m) from the histories ``state`` (fresh when None)
/// into preallocated force, contact-radius, stiffness (and, with
/// ``states``, new-state) buffers: the Rust figure the Python
/// ``law.eval(array)`` is compared with in benches/python/bench.py.
#[pyfunction]
#[pyo3(signature = (law, delta, repeats, states=true, state=None))]
fn _rust_eval_batch_seconds(
    py: Python<'_>,
    law: &Bound<'_, PyAny>,
    delta: &Bound<'_, PyAny>,
    repeats: &Bound<'_, PyAny>,
    states: bool,
    state: Option<&Bound<'_, ContactState>>,
) -> PyResult<f64> {
    let d = array(delta, "delta")?;
    let d = d.as_slice()?;
    let r = count(repeats, "repeats")?;
    let old_ref = state.map(|s| s.borrow());
    if let Some(s) = &old_ref {
        if s.states.len() != d.len() {
            return Err(arg_error("state", "must have the length of delta"));
        }
    }
    let old = old_ref.as_ref().map(|s| &s.states[..]);
    macro_rules! try_law {
        ($($t:ty),*) => {$(
            if let Ok(l) = law.cast::<$t>() {
                let inner = l.get().inner.clone();
                return py.detach(|| time_batch(&inner, d, old, r, states));
            }
        )*};
    }
    try_law!(
        Hertz,
        Dmt,
        Jkr,
        MaugisDugdale,
        Kendall,
        FlatPunch,
        PowerPunch,
        JkrPowerPunch,
        Derjaguin
    );
    Err(arg_error(
        "law",
        "must be one of the closed-form law classes",
    ))
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_rust_eval_batch_seconds, m)?)?;
    Ok(())
}
