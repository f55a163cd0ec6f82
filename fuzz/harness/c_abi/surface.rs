//! Surface profiles (`src/ffi/surface.rs`): roughness parameters, form
//! removal, filtering, material ratio, PSD, Hurst fit and estimate, peaks,
//! generators; maps: the areal Gaussian filter and the radial 2-D PSD (at
//! most 4096 points).

use super::common::*;
use super::Op;
use asperity::ffi::surface::*;
use std::ptr::null_mut;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::Roughness {
            h,
            dx,
            form,
            cutoff,
            sampling,
            nulls,
        } => {
            let z = h.make();
            let mut out: AsperityRoughness = zeroed();
            let s = asperity_roughness_parameters(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                form.0,
                cutoff.0,
                sampling.0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "roughness_parameters");
        }
        Op::RemoveForm {
            h,
            form,
            nulls,
            alias,
        } => {
            let mut z = h.make();
            let mut out = vec![0.0; z.len()];
            let zp = bufm(&mut z, nulls.at(0));
            let op = if *alias {
                zp
            } else {
                bufm(&mut out, nulls.at(1))
            };
            ok(
                asperity_profile_remove_form(z.len(), zp, form.0, op),
                "remove_form",
            );
        }
        Op::Filter {
            h,
            dx,
            cutoff,
            ends,
            nulls,
            alias,
        } => {
            let mut z = h.make();
            let n = z.len();
            let (mut r, mut m) = (vec![0.0; n], vec![0.0; n]);
            let (mut n_out, mut first) = (0usize, 0usize);
            let zp = bufm(&mut z, nulls.at(0));
            let rp = if *alias {
                zp
            } else {
                bufm(&mut r, nulls.at(1))
            };
            let s = asperity_profile_gaussian_filter(
                n,
                zp,
                dx.0,
                cutoff.0,
                ends.0,
                rp,
                bufm(&mut m, nulls.at(2)),
                mp(&mut n_out, nulls.at(3)),
                mp(&mut first, nulls.at(4)),
            );
            if ok(s, "gaussian_filter") && !nulls.at(3) {
                assert!(n_out <= n, "gaussian_filter wrote {n_out} of {n}");
            }
        }
        Op::MaterialRatio { h, points, nulls } => {
            let z = h.make();
            let (mut r, mut l) = (vec![0.0; points.0], vec![0.0; points.0]);
            let s = asperity_material_ratio_curve(
                z.len(),
                bufp(&z, nulls.at(0)),
                points.0,
                bufm(&mut r, nulls.at(1)),
                bufm(&mut l, nulls.at(2)),
            );
            ok(s, "material_ratio_curve");
        }
        Op::Psd {
            h,
            dx,
            window,
            n_q,
            nulls,
        } => {
            let z = h.make();
            // The documented length n/2 + 1, or another (checked) length.
            let m = n_q.map_or(z.len() / 2 + 1, |l| l.0);
            let (mut q, mut g) = (vec![0.0; m], vec![0.0; m]);
            let s = asperity_profile_psd(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                window.0,
                m,
                bufm(&mut q, nulls.at(1)),
                bufm(&mut g, nulls.at(2)),
            );
            ok(s, "profile_psd");
        }
        Op::HurstFit { h, dx, q, nulls } => {
            let z = h.make();
            let mut out: AsperityHurstFit = zeroed();
            let s = asperity_profile_hurst_fit(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                q[0].0,
                q[1].0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "hurst_fit");
            let mut e: AsperityHurstEstimate = zeroed();
            let s = asperity_profile_hurst_estimate(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                q[0].0,
                q[1].0,
                mp(&mut e, nulls.at(1)),
            );
            if ok(s, "hurst_estimate") {
                assert_eq!(e.hurst.to_bits(), out.hurst.to_bits());
                assert!(
                    e.hurst_uncertainty >= 0.0 && e.wavelength_min <= e.wavelength_max,
                    "{e:?}"
                );
            }
        }
        Op::Peaks { h, dx, nulls } => {
            let z = h.make();
            let mut out: AsperityPeakStatistics = zeroed();
            let s = asperity_profile_peak_statistics(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "peak_statistics");
        }
        Op::SelfAffine { a, seed, n, null } => {
            let [a0, a1, a2, a3, a4] = fs(*a);
            let mut h = vec![0.0; n.0];
            let s =
                asperity_generate_self_affine(a0, a1, a2, a3, a4, *seed, n.0, bufm(&mut h, *null));
            ok(s, "generate_self_affine");
        }
        Op::Weierstrass { a, seed, n, null } => {
            let [a0, a1, a2, a3] = fs(*a);
            let mut h = vec![0.0; n.0];
            let s = asperity_generate_weierstrass_mandelbrot(
                a0,
                a1,
                a2,
                a3,
                *seed,
                n.0,
                bufm(&mut h, *null),
            );
            ok(s, "generate_weierstrass_mandelbrot");
        }
        Op::Cantor {
            descendants,
            a,
            levels,
            n,
            null,
        } => {
            let [a0, a1, a2, a3] = fs(*a);
            let mut h = vec![0.0; n.0];
            let s = asperity_generate_cantor_borodich(
                *descendants,
                a0,
                a1,
                a2,
                *levels,
                a3,
                n.0,
                bufm(&mut h, *null),
            );
            ok(s, "generate_cantor_borodich");
        }
        Op::MapFilter {
            h,
            nx,
            d,
            ends,
            nulls,
        } => {
            // A map of at most 4096 points (the filter costs n·λc/dx).
            let mut z = h.make();
            z.truncate(4096);
            let nx = (*nx as usize % 70).max(1);
            let ny = z.len() / nx;
            z.truncate(nx * ny);
            let [dx, dy, cutoff] = fs(*d);
            let (mut r, mut m) = (vec![0.0; nx * ny], vec![0.0; nx * ny]);
            let (mut mx, mut my, mut fx, mut fy) = (0usize, 0usize, 0usize, 0usize);
            let s = asperity_map_gaussian_filter(
                nx,
                ny,
                dx,
                dy,
                bufp(&z, nulls.at(0)),
                cutoff,
                ends.0,
                bufm(&mut r, nulls.at(1)),
                bufm(&mut m, nulls.at(2)),
                mp(&mut mx, nulls.at(3)),
                mp(&mut my, nulls.at(4)),
                mp(&mut fx, nulls.at(5)),
                mp(&mut fy, nulls.at(6)),
            );
            if ok(s, "map_gaussian_filter") {
                assert!(mx * my <= nx * ny && mx >= 2 && my >= 2, "{mx} x {my}");
            }
        }
        Op::MapPsdRadial {
            h,
            nx,
            d,
            window,
            room,
            nulls,
        } => {
            let mut z = h.make();
            z.truncate(4096);
            let nx = (*nx as usize % 70).max(1);
            let ny = z.len() / nx;
            z.truncate(nx * ny);
            let [dx, dy] = fs(*d);
            let bound = nx.min(ny) / 2 + 1;
            let cap = match room % 4 {
                0 => bound.saturating_sub(2),
                _ => bound,
            };
            let (mut q, mut g, mut c) = (vec![0.0; cap], vec![0.0; cap], vec![0usize; cap]);
            let mut written = usize::MAX;
            let co = if nulls.at(3) {
                null_mut()
            } else {
                c.as_mut_ptr()
            };
            let s = asperity_map_psd_radial(
                nx,
                ny,
                dx,
                dy,
                bufp(&z, nulls.at(0)),
                window.0,
                cap,
                bufm(&mut q, nulls.at(1)),
                bufm(&mut g, nulls.at(2)),
                co,
                mp(&mut written, nulls.at(4)),
            );
            if ok(s, "map_psd_radial") {
                assert!(written <= cap, "{written} annuli, capacity {cap}");
            } else {
                assert_eq!(written, usize::MAX, "a failed call wrote `written`");
            }
        }
        _ => unreachable!("not a surface operation: {op:?}"),
    }
}
