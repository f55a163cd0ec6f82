//! Greenwood–Williamson surfaces through `src/ffi/statistics/`
//! (`statistics_*`): parametric and empirical, monotone in the separation,
//! the inverse reproducing the load, batches.

use super::*;
use asperity::ffi::statistics::*;

const SUMMITS: Arg = arg(&["summit_count"], Dom::Pos, 1.0, 1e9);
const SUMMIT_RADIUS: Arg = arg(&["radius"], Dom::Pos, 1e-7, 1e-3);
const SIGMA: Arg = arg(&["sigma"], Dom::Pos, 1e-9, 1e-5);

/// A separation around the height scale `s`: ±s·U(0, 8) mostly, 0, huge,
/// tiny, NaN and ±∞ at small rates.
fn sample_separation(rng: &mut Rng, s: f64) -> f64 {
    match rng.f() {
        u if u < 0.004 => f64::NAN,
        u if u < 0.008 => f64::INFINITY,
        u if u < 0.012 => f64::NEG_INFINITY,
        u if u < 0.02 => 0.0,
        u if u < 0.05 => rng.log_uniform(1e-300, 1e300) * rng.pick(&[-1.0, 1.0]),
        u if u < 0.1 => s * rng.log_uniform(1e-6, 1e6) * rng.pick(&[-1.0, 1.0]),
        _ => s * rng.uniform(-8.0, 8.0),
    }
}

fn gw_bits(r: &AsperityGwResponse) -> [u64; 4] {
    [
        r.load.to_bits(),
        r.area.to_bits(),
        r.contacts.to_bits(),
        r.stiffness.to_bits(),
    ]
}

fn gw_finite(r: &AsperityGwResponse) -> bool {
    [r.load, r.area, r.contacts, r.stiffness]
        .iter()
        .all(|x| x.is_finite() && *x >= 0.0)
}

/// One Greenwood–Williamson surface (C evaluation closure, Rust model,
/// whether its parameters are typical) swept over separations: OK ⇒ every
/// output finite and ≥ 0, equal to the Rust API's; load, area, contacts and
/// stiffness non-increasing in the separation; the separation at a load
/// reproduces the load; a batch with a bad element at j writes the elements
/// before j, leaves those from j on untouched and names j.
/// A batch call: separations in, loads and areas out, the status.
type GwBatch<'a> = dyn Fn(&[f64], &mut [f64], &mut [f64]) -> i32 + 'a;

#[allow(clippy::too_many_arguments)]
fn gw_check(
    eval: &dyn Fn(f64, &mut AsperityGwResponse) -> i32,
    at_load: &dyn Fn(f64, &mut AsperitySeparation) -> i32,
    batch: &GwBatch<'_>,
    model: &asperity::statistics::GreenwoodWilliamson,
    scale: f64,
    typical: bool,
    rng: &mut Rng,
    t: &mut Tally,
) {
    let d1 = sample_separation(rng, scale);
    let d2 = d1 + scale * rng.log_uniform(1e-6, 1.0);
    let mut r = [AsperityGwResponse::default(); 2];
    let mut ok = [false; 2];
    for (k, d) in [d1, d2].into_iter().enumerate() {
        let st = eval(d, &mut r[k]);
        let rust = model.response(d).and_then(|x| Ok((x, model.stiffness(d)?)));
        if st == ASPERITY_OK {
            assert!(gw_finite(&r[k]), "{model:?} d={d:e}: {:?}", r[k]);
            let (x, s) = rust.unwrap();
            assert_eq!(
                gw_bits(&r[k]),
                gw_bits(&AsperityGwResponse {
                    load: x.load,
                    area: x.area,
                    contacts: x.contacts,
                    stiffness: s
                })
            );
            ok[k] = true;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            assert!(m.contains("`separation`"), "{model:?} d={d:e}: {m}");
            assert!(
                !d.is_finite() || !typical || d.abs() > 1e6 * scale,
                "{model:?}: typical separation {d:e} refused: {m}"
            );
        }
    }
    if ok[0] && ok[1] && d2 > d1 {
        let (a, b) = (&r[0], &r[1]);
        for (x, y, what) in [
            (a.load, b.load, "load"),
            (a.area, b.area, "area"),
            (a.contacts, b.contacts, "contacts"),
            (a.stiffness, b.stiffness, "stiffness"),
        ] {
            assert!(
                y <= x * (1.0 + 1e-12),
                "{model:?}: {what} grows with the separation: {x:e} at {d1:e}, {y:e} at {d2:e}"
            );
        }
    }
    // Inverse: the separation that carries the load at d1.
    if ok[0] && typical && r[0].load > 1e-300 * scale {
        let mut s = AsperitySeparation::default();
        let st = at_load(r[0].load, &mut s);
        if st == ASPERITY_OK {
            assert!(
                s.separation.is_finite() && s.relative_residual <= 1e-9,
                "{s:?}"
            );
            let p = model.load(s.separation).unwrap();
            assert!(
                (p / r[0].load - 1.0).abs() <= 1e-9,
                "{model:?}: P({:e}) = {p:e}, wanted {:e}",
                s.separation,
                r[0].load
            );
        } else {
            let m = last_message();
            t.error(&m);
            assert!(m.contains("`load`"), "{m}");
            assert!(
                d1.abs() > 100.0 * scale,
                "separation at load {:e} (d = {d1:e}) refused: {m}",
                r[0].load
            );
        }
    }
    // Batch with one bad element.
    if typical && rng.f() < 0.02 {
        let n = 8;
        let j = (rng.u64() % n as u64) as usize;
        let mut sep: Vec<f64> = (0..n).map(|_| scale * rng.uniform(-4.0, 4.0)).collect();
        sep[j] = rng.pick(&[f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
        let sentinel = -7.25;
        let mut load = vec![sentinel; n];
        let mut area = vec![sentinel; n];
        let st = batch(&sep, &mut load, &mut area);
        assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
        let m = last_message();
        assert!(
            m.starts_with(&format!("element {j}: ")) && m.contains("`separation`"),
            "{m}"
        );
        for i in 0..n {
            if i < j {
                let x = model.response(sep[i]).unwrap();
                assert_eq!((load[i], area[i]), (x.load, x.area), "element {i} < {j}");
            } else {
                assert_eq!(
                    (load[i], area[i]),
                    (sentinel, sentinel),
                    "element {i} ≥ {j}"
                );
            }
        }
    }
}

fn sweep_gw(n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let args = [SUMMITS, SUMMIT_RADIUS, SIGMA, E_STAR];
    for _ in 0..n {
        t.points += 1;
        let dist = if rng.f() < 0.01 {
            rng.pick(&[0, 3, -1])
        } else {
            rng.pick(&[ASPERITY_HEIGHTS_GAUSSIAN, ASPERITY_HEIGHTS_EXPONENTIAL])
        };
        let v: Vec<f64> = args.iter().map(|a| sample(&mut rng, a)).collect();
        let gw = AsperityGwParams {
            distribution: dist,
            reserved: 0,
            summit_count: v[0],
            radius: v[1],
            sigma: v[2],
            e_star: v[3],
        };
        let bad: Vec<&Arg> = args
            .iter()
            .zip(&v)
            .filter(|(a, x)| !a.dom.contains(**x))
            .map(|(a, _)| a)
            .collect();
        let typical = args.iter().zip(&v).all(|(a, x)| typical(a, *x));
        let model = match gw.to_model() {
            Ok(m) => m,
            Err(e) => {
                // Every C call refuses the parameters with the same message.
                let mut r = AsperityGwResponse::default();
                let st = unsafe { asperity_gw_eval(&gw, 0.0, &mut r) };
                assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
                let m = last_message();
                assert_eq!(m, e.to_string());
                t.error(&m);
                assert!(
                    names_one_of(&m, &bad) || m.contains("`gw.distribution`"),
                    "{gw:?}: {m}"
                );
                continue;
            }
        };
        assert!(bad.is_empty(), "{gw:?} accepted");
        t.ok += 1;
        gw_check(
            &|d, r| unsafe { asperity_gw_eval(&gw, d, r) },
            &|p, s| unsafe { asperity_gw_separation_at_load(&gw, p, s) },
            &|s, l, a| unsafe {
                asperity_gw_eval_batch(
                    &gw,
                    s.len(),
                    s.as_ptr(),
                    l.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                    null_mut(),
                )
            },
            &model,
            v[2],
            typical,
            &mut rng,
            &mut t,
        );
    }
    t
}

/// An empirical surface (300 summits, heights Gaussian-ish, radii
/// log-uniform) built once, swept over separations.
fn sweep_gw_empirical(n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let heights: Vec<f64> = (0..300)
        .map(|_| 1e-7 * (rng.f() + rng.f() + rng.f() - 1.5))
        .collect();
    let radii: Vec<f64> = (0..300).map(|_| rng.log_uniform(1e-6, 1e-4)).collect();
    let mut h = null_mut();
    assert_eq!(
        unsafe {
            asperity_gw_empirical_new(
                1e6,
                1e-5,
                1e11,
                300,
                heights.as_ptr(),
                radii.as_ptr(),
                &mut h,
            )
        },
        ASPERITY_OK
    );
    let model = asperity::statistics::GreenwoodWilliamson::new(
        1e6,
        1e-5,
        1e11,
        asperity::statistics::HeightDistribution::Empirical(
            asperity::statistics::EmpiricalHeights::with_radii(heights, radii).unwrap(),
        ),
    )
    .unwrap();
    let hc = h as usize;
    for _ in 0..n {
        t.points += 1;
        t.ok += 1;
        let h = hc as *const AsperityGwEmpirical;
        gw_check(
            &|d, r| unsafe { asperity_gw_empirical_eval(h, d, r) },
            &|p, s| unsafe { asperity_gw_empirical_separation_at_load(h, p, s) },
            &|s, l, a| unsafe {
                asperity_gw_empirical_eval_batch(
                    h,
                    s.len(),
                    s.as_ptr(),
                    l.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                    null_mut(),
                )
            },
            &model,
            5e-8,
            true,
            &mut rng,
            &mut t,
        );
    }
    unsafe { asperity_gw_empirical_free(h) };
    t
}

fn sweep_statistics(n: usize) {
    let (a, b) = std::thread::scope(|s| {
        let a = s.spawn(|| sweep_gw(n, 0x5EED_0003));
        let b = s.spawn(|| sweep_gw_empirical(n / 10, 0x5EED_0004));
        (a.join().unwrap(), b.join().unwrap())
    });
    a.print("Greenwood–Williamson (Gaussian, exponential)");
    b.print("Greenwood–Williamson (300 listed summits)");
}

#[test]
fn statistics_quick() {
    sweep_statistics(QUICK);
}

#[test]
#[ignore = "10⁶ points: run in release (.ci/run)"]
fn statistics_full() {
    sweep_statistics(FULL);
}
