//! Slider geometries (`src/ffi/friction.rs`): construction, queries,
//! freeing.

use super::common::*;
use super::{pick, take, Ctx, Op};
use asperity::ffi::friction::*;
use asperity::ffi::ASPERITY_OK;
use std::ptr::null_mut;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::GeometryNew {
            micro,
            micro_dx,
            nano,
            nano_dx,
            widths,
            nulls,
        } => {
            let m = micro.make();
            let n = nano.make();
            let w: Vec<f64> = widths.iter().take(6).map(|f| f.0).collect();
            let mut out = null_mut();
            let s = asperity_slider_geometry_new(
                bufp(&m, nulls.at(0)),
                m.len(),
                micro_dx.0,
                bufp(&n, nulls.at(1)),
                n.len(),
                nano_dx.0,
                bufp(&w, nulls.at(2)),
                w.len(),
                mp(&mut out, nulls.at(3)),
            );
            if let Some(g) = made(s, out, !nulls.at(3), "slider_geometry_new") {
                ctx.geometries.push(g);
            }
        }
        Op::GeometryUniform {
            width,
            rods,
            nano,
            per_rod,
            nulls,
        } => {
            let v = fs(*nano);
            let na = AsperityNanoAsperities {
                h_vdw: v[0],
                w_vdw: v[1],
                h_chem: v[2],
                w_chem: v[3],
                spacing: v[4],
                per_rod: per_rod.0,
            };
            let mut out = null_mut();
            let s = asperity_slider_geometry_new_uniform(
                width.0,
                rods.0,
                cp(&na, nulls.at(0)),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(g) = made(s, out, !nulls.at(1), "slider_geometry_new_uniform") {
                ctx.geometries.push(g);
            }
        }
        Op::GeometryQuery {
            geometry,
            which,
            level,
            len,
            nulls,
        } => {
            let g = pick(&ctx.geometries, *geometry);
            let null = nulls.at(0);
            let s = match which % 5 {
                0 => {
                    let mut o: AsperityNanoAsperities = zeroed();
                    asperity_slider_geometry_nano(g, mp(&mut o, null))
                }
                1 => {
                    let mut c = 0usize;
                    asperity_slider_geometry_level_count(g, mp(&mut c, null))
                }
                2 => {
                    let mut c = 0usize;
                    asperity_slider_geometry_rod_count(g, level.0, mp(&mut c, null))
                }
                3 => {
                    let (mut w, mut o) = (0.0, 0.0);
                    asperity_slider_geometry_rod_width(
                        g,
                        level.0,
                        mp(&mut w, null),
                        mp(&mut o, nulls.at(1)),
                    )
                }
                _ => {
                    // A buffer of `len` values, or of the level's rod count.
                    let mut count = 0usize;
                    let l = if nulls.at(2)
                        && asperity_slider_geometry_rod_count(g, level.0, &mut count) == ASPERITY_OK
                    {
                        count.min(1 << 20)
                    } else {
                        len.0
                    };
                    let mut h = vec![0.0; l];
                    asperity_slider_geometry_rod_heights(g, level.0, bufm(&mut h, null), l)
                }
            };
            ok(s, "slider_geometry query");
        }
        Op::GeometryFree { geometry } => {
            if let Some(g) = take(&mut ctx.geometries, *geometry) {
                asperity_slider_geometry_free(g);
            } else {
                asperity_slider_geometry_free(null_mut());
            }
        }
        _ => unreachable!("not a friction operation: {op:?}"),
    }
}

/// The rods of every level of `g`.
pub(super) unsafe fn geometry_rods(g: *const AsperitySliderGeometry) -> usize {
    let mut levels = 0usize;
    if asperity_slider_geometry_level_count(g, &mut levels) != ASPERITY_OK {
        return usize::MAX;
    }
    (0..levels)
        .map(|l| {
            let mut c = 0usize;
            if asperity_slider_geometry_rod_count(g, l, &mut c) == ASPERITY_OK {
                c
            } else {
                usize::MAX
            }
        })
        .fold(0usize, usize::saturating_add)
}
