//! Hierarchical roughness (`src/ffi/hierarchical.rs`): Archard's exponent
//! and load–area batch, the Cantor profile's contact batch and exponents,
//! with NULL pointers and out-of-range values; every `Ok` output finite.

use super::common::*;
use super::Op;
use asperity::ffi::hierarchical::*;
use asperity::hierarchical::{CantorContact, CantorProfile};
use std::ptr::null_mut;

/// Runs one operation of this domain.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::Archard {
            model,
            radii,
            densities,
            modulus,
            loads,
            generations,
            nulls,
        } => {
            let mut a = 0.0;
            let s =
                asperity_archard_exponent(model.0, *generations as usize, mp(&mut a, nulls.at(0)));
            if ok(s, "archard_exponent") {
                assert!(a.is_finite() && a > 0.0 && a <= 1.0, "exponent {a}");
            }
            let r: Vec<f64> = radii.iter().take(8).map(|f| f.0).collect();
            let d: Vec<f64> = densities.iter().take(8).map(|f| f.0).collect();
            let w: Vec<f64> = loads.iter().map(|f| f.0).collect();
            let mut out = vec![0.0; w.len()];
            // The densities need radii.len() - 1 readable values.
            let g = r.len().min(d.len() + 1);
            let s = asperity_archard_area_batch(
                model.0,
                bufp(&r, nulls.at(1)),
                bufp(&d, nulls.at(2)),
                g,
                modulus.0,
                w.len(),
                bufp(&w, nulls.at(3)),
                bufm(&mut out, nulls.at(4)),
            );
            if ok(s, "archard_area_batch") {
                assert!(out.iter().all(|x| x.is_finite() && *x >= 0.0), "{out:?}");
            }
        }
        Op::CantorContact {
            descendants,
            generations,
            a,
            depths,
            nulls,
        } => {
            let [r, q, w0, h0, k, h] = fs(*a);
            let p = CantorProfile {
                descendants: *descendants,
                generations: *generations,
                width_ratio: r,
                height_ratio: q,
                base_width: w0,
                base_height: h0,
            };
            let d: Vec<f64> = depths.iter().map(|f| f.0).collect();
            let mut out = vec![CantorContact::default(); d.len()];
            let o = if nulls.at(2) {
                null_mut()
            } else {
                out.as_mut_ptr()
            };
            let s = asperity_cantor_contact_batch(
                cp(&p, nulls.at(0)),
                k,
                h,
                d.len(),
                bufp(&d, nulls.at(1)),
                o,
            );
            if ok(s, "cantor_contact_batch") {
                for c in &out {
                    assert!(c.width.is_finite() && c.plastic_load.is_finite(), "{c:?}");
                }
            }
            let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
            let s = asperity_cantor_exponents(
                cp(&p, nulls.at(3)),
                mp(&mut x, nulls.at(4)),
                mp(&mut y, nulls.at(5)),
                mp(&mut z, nulls.at(6)),
            );
            if ok(s, "cantor_exponents") {
                assert!(x.is_finite() && z.is_finite(), "{x} {z}");
            }
        }
        _ => unreachable!("not a hierarchical operation"),
    }
}
