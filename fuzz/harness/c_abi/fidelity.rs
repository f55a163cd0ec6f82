//! `asperity_fidelity_advise` (`src/ffi/fidelity.rs`), fed only argument
//! sets its validation rejects.

use super::common::*;
use super::Op;
use asperity::ffi::fidelity::*;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::Fidelity { a, null } => {
            let v = fs(*a);
            // A valid set runs the Lennard-Jones reference (seconds to
            // minutes): only sets that validation rejects are fed.
            if !*null && v.iter().all(|x| x.is_finite() && *x > 0.0) {
                return;
            }
            let mut out: AsperityFidelityAdvice = zeroed();
            ok(
                asperity_fidelity_advise(v[0], v[1], v[2], v[3], v[4], mp(&mut out, *null)),
                "fidelity_advise",
            );
        }
        _ => unreachable!("not a fidelity operation: {op:?}"),
    }
}
