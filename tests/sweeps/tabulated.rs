//! Tabulated Maugis–Dugdale tables through `src/ffi/tabulated.rs`
//! (`tabulated_*`): within tolerance of the closed form.

use super::contact::{bits, finite_response, finite_state, sample_delta};
use super::*;
use asperity::contact::{
    ContactState, Control, MaugisDugdale, NormalContact, NormalResponse, TabulatedLaw,
};
use asperity::ffi::tabulated::*;

/// Tables of Maugis–Dugdale spheres (R = 1 µm, E* = 100 GPa, w = 0.5 J/m²)
/// at Maugis parameters 0.05 (DMT-like) … 10 (JKR-like), built once through
/// the C ABI and once through Rust, swept over overlaps (with the history
/// carried from point to point, and fresh), loads and batches.
fn sweep_tabulated(n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let tol = 1e-4;
    let tables: Vec<(MaugisDugdale, TabulatedLaw, usize)> = [0.05, 0.5, 2.0, 10.0]
        .iter()
        .map(|&lam| {
            let md = MaugisDugdale::from_maugis_parameter(1e-6, 1e11, 0.5, lam).unwrap();
            let mut h = null_mut();
            let st = unsafe {
                asperity_table_new_maugis_dugdale(
                    md.params().radius,
                    md.params().e_star,
                    md.params().work_of_adhesion,
                    md.params().cohesive_stress,
                    tol,
                    &mut h,
                )
            };
            assert_eq!(st, ASPERITY_OK, "{}", last_message());
            let rust = TabulatedLaw::from_maugis_dugdale(&md, tol).unwrap();
            (md, rust, h as usize)
        })
        .collect();
    let mut states = vec![ContactState::default(); tables.len()];
    for _ in 0..n {
        t.points += 1;
        let k = (rng.u64() % tables.len() as u64) as usize;
        let (md, law, hc) = &tables[k];
        let h = *hc as *const AsperityTable;
        let l = law.length_scale();
        let fresh = rng.f() < 0.3;
        let old = if fresh {
            ContactState::default()
        } else {
            states[k]
        };
        // Mostly within a few length scales (crossing the jumps with the
        // history carried over); sometimes anywhere.
        let delta = if !fresh && rng.f() < 0.7 {
            l * rng.uniform(-3.0, 5.0)
        } else {
            sample_delta(&mut rng, l)
        };
        let mut r = NormalResponse::default();
        let mut s = ContactState::default();
        let st = unsafe { asperity_table_eval(h, delta, &old, &mut s, &mut r) };
        let rust = law.eval(delta, &old);
        if st == ASPERITY_OK {
            t.ok += 1;
            let (rr, rs) = rust.unwrap();
            assert_eq!(bits(&r), bits(&rr));
            assert_eq!(s, rs);
            assert!(
                finite_response(&r) && finite_state(&s),
                "λ#{k} δ={delta:e}: {r:?}"
            );
            // Against the closed-form law from the same history: the
            // documented error measure, within the tolerance (×2 for the
            // rounding of the measure itself), where both are on the same
            // branch and inside 10³ length scales.
            if let Ok((ex, _)) = md.eval(delta, &old) {
                if ex.in_contact == r.in_contact && delta.abs() <= 1e3 * l {
                    let e = law.relative_error(&ex, &r);
                    assert!(
                        e <= 2.0 * tol,
                        "λ#{k} δ={delta:e} (L = {l:e}) {old:?}: table error {e:e}: {r:?} vs {ex:?}"
                    );
                }
            }
            // Monotone on the branch: a larger overlap from the new state,
            // same branch, compressive ⇒ larger force.
            let d2 = delta + l * rng.log_uniform(1e-6, 1.0);
            if let Ok((r2, s2)) = law.eval(d2, &s) {
                if s2.branch == s.branch && r.force >= 0.0 && delta.abs() <= 1e3 * l {
                    assert!(
                        r2.force >= r.force * (1.0 - 1e-12),
                        "λ#{k}: F({d2:e}) = {:e} < F({delta:e}) = {:e}",
                        r2.force,
                        r.force
                    );
                }
            }
            states[k] = s;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            assert!(m.contains("`delta`"), "{m}");
            assert!(
                !delta.is_finite() || delta.abs() > 1e6 * l,
                "λ#{k} δ={delta:e} (L = {l:e}) refused: {m}"
            );
            states[k] = ContactState::default();
        }

        // Load control.
        let po = law.pull_off_force(Control::Load).unwrap();
        let p = match rng.f() {
            u if u < 0.01 => f64::NAN,
            u if u < 0.03 => po * (1.0 + rng.uniform(-1e-6, 1e-6)),
            u if u < 0.05 => rng.log_uniform(1e-300, 1e300) * rng.pick(&[-1.0, 1.0]),
            _ => -po * rng.log_uniform(1e-6, 1e6) * rng.pick(&[-1.0, 1.0, 1.0]),
        };
        let mut ra = NormalResponse::default();
        let st = unsafe { asperity_table_eval_at_load(h, p, &mut ra) };
        if st == ASPERITY_OK {
            assert!(
                finite_response(&ra) && p >= po * (1.0 + 1e-9),
                "P={p:e}: {ra:?}"
            );
            assert_eq!(bits(&ra), bits(&law.eval_at_load(p).unwrap()));
        } else {
            let m = last_message();
            t.error(&m);
            assert!(m.contains("`force`"), "P={p:e}: {m}");
            assert!(
                !p.is_finite() || p < po * (1.0 - 1e-7) || p.abs() > -po * 1e6,
                "P={p:e} (pull-off {po:e}) refused: {m}"
            );
        }

        // Batch with a bad element j.
        if rng.f() < 0.01 {
            let nb = 8;
            let j = (rng.u64() % nb as u64) as usize;
            let mut d: Vec<f64> = (0..nb).map(|_| l * rng.uniform(-3.0, 5.0)).collect();
            d[j] = rng.pick(&[f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
            let sentinel = -9.75;
            let mut f = vec![sentinel; nb];
            let mut a = vec![sentinel; nb];
            let mut ns = vec![
                ContactState {
                    contact_radius: sentinel,
                    ..ContactState::default()
                };
                nb
            ];
            let st = unsafe {
                asperity_table_eval_batch(
                    h,
                    nb,
                    d.as_ptr(),
                    core::ptr::null(),
                    ns.as_mut_ptr(),
                    f.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                )
            };
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
            let m = last_message();
            assert!(
                m.starts_with(&format!("element {j}: ")) && m.contains("`delta`"),
                "{m}"
            );
            for i in 0..nb {
                if i < j {
                    let (w, ws) = law.eval(d[i], &ContactState::default()).unwrap();
                    assert_eq!((f[i], a[i], ns[i]), (w.force, w.contact_radius, ws));
                } else {
                    assert_eq!(
                        (f[i], a[i], ns[i].contact_radius),
                        (sentinel, sentinel, sentinel)
                    );
                }
            }
        }
    }
    for (_, _, h) in tables {
        unsafe { asperity_table_free(h as *mut AsperityTable) };
    }
    t
}

#[test]
fn tabulated_quick() {
    sweep_tabulated(QUICK, 0x5EED_0006).print("tabulated Maugis–Dugdale");
}

#[test]
#[ignore = "10⁶ points: run in release (.ci/run)"]
fn tabulated_full() {
    sweep_tabulated(FULL, 0x5EED_0006).print("tabulated Maugis–Dugdale");
}
