//! The Lennard-Jones sphere pull-off (`src/ffi/lj_sphere.rs`), once per
//! input.

use super::common::*;
use super::{Ctx, Op};
use asperity::ffi::lj_sphere::*;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::LjPullOff { a, grid, null } => {
            if ctx.expensive > 0 {
                return;
            }
            ctx.expensive += 1;
            let [r, e, w, z0] = fs(*a);
            let mut f = 0.0;
            ok(
                asperity_lj_sphere_pull_off(r, e, w, z0, grid.0, mp(&mut f, *null)),
                "lj_pull_off",
            );
        }
        _ => unreachable!("not a lj_sphere operation: {op:?}"),
    }
}
