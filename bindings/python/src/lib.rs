//! The native part of the `asperity` Python package: PyO3 classes and
//! functions over the Rust API of the `asperity` crate (not the C ABI), one
//! file per domain. `python/asperity/__init__.py` re-exports everything.

use pyo3::prelude::*;

mod afm;
mod bench;
mod common;
mod contact;
mod friction;
mod friction_law;
mod hierarchical;
mod lj_sphere;
mod materials;
mod rescaling;
mod statistics;
mod surface;
mod tabulated;

#[pymodule]
fn _asperity(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("Error", m.py().get_type::<common::Error>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    materials::register(m)?;
    contact::register(m)?;
    bench::register(m)?;
    lj_sphere::register(m)?;
    tabulated::register(m)?;
    rescaling::register(m)?;
    afm::register(m)?;
    surface::register(m)?;
    statistics::register(m)?;
    friction::register(m)?;
    friction_law::register(m)?;
    hierarchical::register(m)?;
    Ok(())
}
