//! Derjaguin approximation: rigid sphere under Lennard-Jones, Dugdale and
//! exponential surface laws (REFERENCE §1, §6).

use approx::assert_relative_eq;
use asperity::contact::{Derjaguin, DerjaguinParams, SurfaceLaw};
use asperity::ffi::contact::AsperityNormalLaw;
use asperity::{ContactState, Control, Error, NormalContact, NormalLaw};
use core::f64::consts::PI;

const R: f64 = 1e-6;
const W: f64 = 0.05;
const Z0: f64 = 1.65e-10;
const SIGMA0: f64 = 1e8; // h₀ = w/σ₀ = 5e-10
const ELL: f64 = 2e-10;

fn lj(w: f64, z0: f64) -> SurfaceLaw {
    SurfaceLaw::LennardJones {
        work_of_adhesion: w,
        equilibrium_separation: z0,
    }
}
fn dugdale(w: f64, s0: f64) -> SurfaceLaw {
    SurfaceLaw::Dugdale {
        work_of_adhesion: w,
        cohesive_stress: s0,
    }
}
fn expo(w: f64, l: f64) -> SurfaceLaw {
    SurfaceLaw::Exponential {
        work_of_adhesion: w,
        decay_length: l,
    }
}
fn laws() -> [SurfaceLaw; 3] {
    [lj(W, Z0), dugdale(W, SIGMA0), expo(W, ELL)]
}
fn fresh() -> ContactState {
    ContactState::default()
}
fn force(d: &Derjaguin, delta: f64) -> f64 {
    d.eval(delta, &fresh()).unwrap().0.force
}

/// Adaptive Simpson on [a, b].
fn simpson(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    #[allow(clippy::too_many_arguments)]
    fn rec(
        f: &dyn Fn(f64) -> f64,
        a: f64,
        b: f64,
        fa: f64,
        fm: f64,
        fb: f64,
        whole: f64,
        tol: f64,
        depth: u32,
    ) -> f64 {
        let m = 0.5 * (a + b);
        let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
        let (flm, frm) = (f(lm), f(rm));
        let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
        let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
        let delta = left + right - whole;
        // Stop at the tolerance, at the depth limit, or at round-off.
        let roundoff = 1e-15 * (left.abs() + right.abs());
        if depth == 0 || delta.abs() <= 15.0 * tol.max(roundoff) {
            return left + right + delta / 15.0;
        }
        rec(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1)
            + rec(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1)
    }
    let (fa, fb, fm) = (f(a), f(b), f(0.5 * (a + b)));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    rec(f, a, b, fa, fm, fb, whole, tol, 40)
}

/// ∫_D^∞ p(z) dz by quadrature: z = D/t on t ∈ (0, 1] for Lennard-Jones, a
/// finite interval covering the range otherwise.
fn energy_by_quadrature(law: &SurfaceLaw, gap: f64) -> f64 {
    let w = law.work_of_adhesion();
    let tol = 1e-13 * w;
    match law {
        SurfaceLaw::LennardJones { .. } => {
            let f = |t: f64| {
                if t == 0.0 {
                    0.0
                } else {
                    law.pressure(gap / t).unwrap() * gap / (t * t)
                }
            };
            simpson(&f, 0.0, 1.0, tol)
        }
        SurfaceLaw::Dugdale { .. } => {
            // Split at the step z = h₀.
            let f = |z: f64| law.pressure(z).unwrap();
            let h0 = law.range();
            if gap < h0 {
                simpson(&f, gap, h0, tol) + simpson(&f, h0, 2.0 * h0, tol)
            } else {
                simpson(&f, gap, gap + h0, tol)
            }
        }
        SurfaceLaw::Exponential { .. } => {
            let f = |z: f64| law.pressure(z).unwrap();
            simpson(&f, gap, gap + 80.0 * law.range(), tol)
        }
    }
}

#[test]
fn pull_off_is_two_pi_r_w_for_every_law() {
    for law in laws() {
        let d = Derjaguin::new(R, law).unwrap();
        for c in [Control::Load, Control::Displacement] {
            let p = d.pull_off_force(c).unwrap();
            assert_relative_eq!(p, -2.0 * PI * R * W, max_relative = 1e-14);
            assert_relative_eq!(p, -3.14159265e-7, max_relative = 1e-8);
        }
        // The force at δ = 0 is the pull-off force and is the minimum of P.
        let r = d.eval(0.0, &fresh()).unwrap().0;
        assert_relative_eq!(r.force, -2.0 * PI * R * W, max_relative = 1e-14);
        assert_eq!(r.in_contact, 1);
        let l = d.length_scale();
        for k in 1..200 {
            let delta = -5.0 * l + k as f64 * (5.0 * l / 200.0);
            assert!(force(&d, delta) >= r.force * (1.0 + 1e-14));
        }
        let at_load = d.eval_at_load(r.force).unwrap();
        assert!(at_load.delta.abs() <= 1e-12 * l, "{at_load:?}");
        // Through the dispatching enum.
        let law = NormalLaw::Derjaguin(d);
        assert_relative_eq!(
            law.pull_off_force(Control::Load).unwrap(),
            -2.0 * PI * R * W,
            max_relative = 1e-14
        );
    }
}

#[test]
fn lennard_jones_rigid_limit_of_reference_section_6() {
    let d = Derjaguin::new(R, lj(W, Z0)).unwrap();
    let prw = PI * R * W;
    // h_m = 1 − δ/z₀.
    assert!((force(&d, 0.0) / prw - -2.0).abs() <= 1e-9);
    let exact = (8.0 / 3.0) * (0.25 - 1.0 / 1024.0);
    assert_eq!(exact, 0.6640625);
    assert!((force(&d, -Z0) / prw - -0.6640625).abs() <= 1e-9);
    for hm in [0.7, 0.9, 4f64.powf(-1.0 / 6.0), 1.3, 3.0, 10.0] {
        let expect = -(8.0 / 3.0) * (hm.powi(-2) - hm.powi(-8) / 4.0);
        let got = force(&d, Z0 * (1.0 - hm)) / prw;
        assert!((got - expect).abs() <= 1e-9 * expect.abs().max(1.0), "{hm}");
    }
    // Zero force at D = z₀/4^{1/6}.
    let p0 = force(&d, Z0 * (1.0 - 4f64.powf(-1.0 / 6.0)));
    assert!(p0.abs() <= 1e-12 * prw);
    // force_at_gap agrees with eval at D = z₀ − δ.
    for hm in [0.8, 1.0, 2.0] {
        assert_relative_eq!(
            d.force_at_gap(hm * Z0).unwrap(),
            force(&d, Z0 * (1.0 - hm)),
            max_relative = 1e-14
        );
    }
}

#[test]
fn energy_matches_quadrature_of_pressure() {
    for law in laws() {
        let h = law.range();
        for g in [0.0, 0.3, 0.8, 1.0, 1.5, 3.0] {
            let gap = if matches!(law, SurfaceLaw::LennardJones { .. }) && g == 0.0 {
                0.6 * h
            } else {
                g * h
            };
            let e = law.energy(gap).unwrap();
            let q = energy_by_quadrature(&law, gap);
            assert!((e - q).abs() <= 1e-9 * W, "{law:?} gap {gap}: {e} vs {q}");
        }
    }
    // ∫_{z₀}^∞ p = w for Lennard-Jones, ∫_0^∞ p = w for the others.
    assert_relative_eq!(
        energy_by_quadrature(&lj(W, Z0), Z0),
        W,
        max_relative = 1e-10
    );
    assert_relative_eq!(lj(W, Z0).energy(Z0).unwrap(), W, max_relative = 1e-15);
    for law in [dugdale(W, SIGMA0), expo(W, ELL)] {
        assert_relative_eq!(energy_by_quadrature(&law, 0.0), W, max_relative = 1e-10);
        assert_relative_eq!(law.energy(0.0).unwrap(), W, max_relative = 1e-15);
    }
}

#[test]
fn lennard_jones_peak_tension() {
    let law = lj(W, Z0);
    let peak = asperity::material::lennard_jones_theoretical_stress(W, Z0).unwrap();
    assert_relative_eq!(
        peak,
        16.0 * W / (9.0 * 3f64.sqrt() * Z0),
        max_relative = 1e-15
    );
    let hp = 3f64.powf(1.0 / 6.0) * Z0;
    assert_relative_eq!(law.pressure(hp).unwrap(), peak, max_relative = 1e-14);
    assert_relative_eq!(law.peak_tension().unwrap(), peak, max_relative = 1e-15);
    // It is the maximum: a scan over the gap never exceeds it.
    for k in 1..2000 {
        let z = Z0 * (0.9 + k as f64 * 0.002);
        assert!(law.pressure(z).unwrap() <= peak * (1.0 + 1e-14));
    }
    // Repulsive below z₀, zero at z₀.
    assert_eq!(law.pressure(Z0).unwrap(), 0.0);
    assert!(law.pressure(0.9 * Z0).unwrap() < 0.0);
    assert_relative_eq!(
        dugdale(W, SIGMA0).pressure(0.5 * W / SIGMA0).unwrap(),
        SIGMA0
    );
    assert_eq!(dugdale(W, SIGMA0).pressure(1.01 * W / SIGMA0).unwrap(), 0.0);
    assert_relative_eq!(expo(W, ELL).peak_tension().unwrap(), W / ELL);
}

#[test]
fn stiffness_is_the_derivative_of_force() {
    for law in laws() {
        let d = Derjaguin::new(R, law).unwrap();
        let l = d.length_scale();
        let deltas: &[f64] = match law {
            SurfaceLaw::LennardJones { .. } => &[-3.0, -1.0, -0.3, -0.1, 0.0, 0.1, 0.3, 0.6],
            _ => &[-3.0, -1.5, -0.9, -0.5, -0.1, -0.01],
        };
        for &x in deltas {
            let delta = x * l;
            let h = 1e-5 * l;
            let k = d.eval(delta, &fresh()).unwrap().0.stiffness;
            let fd = (force(&d, delta + h) - force(&d, delta - h)) / (2.0 * h);
            let scale = d.adhesive_force() / l;
            assert!(
                (k - fd).abs() <= 1e-6 * scale.max(k.abs()),
                "{law:?} delta/l = {x}: {k} vs {fd}"
            );
        }
    }
    // LJ: zero stiffness at the pull-off point, positive (stable) above it.
    let d = Derjaguin::new(R, lj(W, Z0)).unwrap();
    assert_eq!(d.eval(0.0, &fresh()).unwrap().0.stiffness, 0.0);
    assert!(d.eval(0.1 * Z0, &fresh()).unwrap().0.stiffness > 0.0);
    assert!(d.eval(-0.1 * Z0, &fresh()).unwrap().0.stiffness < 0.0);
    // Dugdale kink: the approach-side tangent at D = h₀, zero beyond.
    let d = Derjaguin::new(R, dugdale(W, SIGMA0)).unwrap();
    let h0 = W / SIGMA0;
    assert_relative_eq!(h0, d.length_scale(), max_relative = 1e-15);
    let at = d.eval(-h0, &fresh()).unwrap();
    assert_eq!(at.0.force, 0.0);
    assert_eq!(at.0.in_contact, 0);
    assert_relative_eq!(at.0.stiffness, -2.0 * PI * R * SIGMA0, max_relative = 1e-14);
    let beyond = d.eval(-1.0001 * h0, &fresh()).unwrap().0;
    assert_eq!(
        (beyond.force, beyond.stiffness, beyond.in_contact),
        (0.0, 0.0, 0)
    );
    let inside = d.eval(-0.5 * h0, &fresh()).unwrap();
    assert_eq!(inside.0.in_contact, 1);
    assert_eq!(inside.0.contact_radius, 0.0);
    assert_relative_eq!(
        inside.1.cohesive_radius,
        (2.0 * R * 0.5 * h0).sqrt(),
        max_relative = 1e-14
    );
}

#[test]
fn eval_at_load_inverts_eval() {
    for law in laws() {
        let d = Derjaguin::new(R, law).unwrap();
        let l = d.length_scale();
        let deltas: Vec<f64> = match law {
            SurfaceLaw::LennardJones { .. } => (0..=40)
                .map(|k| l * (1.0 - 10f64.powf(-(k as f64) * 0.35)))
                .collect(),
            _ => (0..=40).map(|k| -(k as f64) * 0.1 * l).collect(),
        };
        for delta in deltas {
            let r = d.eval(delta, &fresh()).unwrap().0;
            if !matches!(law, SurfaceLaw::LennardJones { .. }) && r.force == 0.0 {
                continue;
            }
            let back = d.eval_at_load(r.force).unwrap();
            assert_eq!(back.force, r.force);
            let tol = match law {
                // Near pull-off dP/dδ → 0: δ is determined only to √ε.
                SurfaceLaw::LennardJones { .. } => 1e-7 * l + 1e-10 * delta.abs(),
                _ => 1e-12 * l,
            };
            assert!(
                (back.delta - delta).abs() <= tol,
                "{law:?}: {delta} -> {} -> {}",
                r.force,
                back.delta
            );
            assert_relative_eq!(
                back.stiffness,
                r.stiffness,
                max_relative = 1e-6,
                epsilon = 1e-6 * d.adhesive_force() / l
            );
        }
    }
    // LJ: the stable branch D ≤ z₀, zero load at D = z₀/4^{1/6}.
    let d = Derjaguin::new(R, lj(W, Z0)).unwrap();
    let r = d.eval_at_load(0.0).unwrap();
    assert_relative_eq!(
        r.delta,
        Z0 * (1.0 - 4f64.powf(-1.0 / 6.0)),
        max_relative = 1e-14
    );
    for p in [-1.0, -0.999999, -0.5, 0.0, 1.0, 1e3, 1e9] {
        let r = d.eval_at_load(p * d.adhesive_force()).unwrap();
        assert!(
            r.delta >= 0.0 && r.delta < Z0 && r.stiffness >= 0.0,
            "{p}: {r:?}"
        );
    }
    // Dugdale at zero load: the edge of the interaction.
    let d = Derjaguin::new(R, dugdale(W, SIGMA0)).unwrap();
    assert_relative_eq!(d.eval_at_load(0.0).unwrap().delta, -W / SIGMA0);
}

#[test]
fn extreme_sweeps_are_finite_or_clean_errors() {
    let mut ok = 0usize;
    for law_i in 0..3 {
        for &r in &[1e-12, 1e-6, 1.0, 1e6] {
            for &w in &[1e-9, 1e-3, 1.0, 1e4] {
                for &range in &[1e-14, 1e-10, 1e-6] {
                    let law = match law_i {
                        0 => lj(w, range),
                        1 => dugdale(w, w / range),
                        _ => expo(w, range),
                    };
                    let d = Derjaguin::new(r, law).unwrap();
                    let f = d.adhesive_force();
                    let l = d.length_scale();
                    let mut deltas: Vec<f64> = (0..=60)
                        .map(|k| -l * 10f64.powf(6.0 - 0.2 * k as f64))
                        .collect();
                    deltas.push(0.0);
                    if law_i == 0 {
                        for k in 1..=16 {
                            deltas.push(l * (1.0 - 10f64.powi(-k)));
                        }
                        deltas.push(l - l * f64::EPSILON);
                    }
                    for delta in deltas {
                        match d.eval(delta, &fresh()) {
                            Ok((resp, st)) => {
                                ok += 1;
                                for v in [
                                    resp.force,
                                    resp.stiffness,
                                    resp.delta,
                                    resp.contact_radius,
                                    st.cohesive_radius,
                                ] {
                                    assert!(v.is_finite(), "{law:?} r {r} delta {delta}");
                                }
                                assert!(resp.force >= -f * (1.0 + 1e-12));
                            }
                            Err(Error::OutOfDomain { name: "delta", .. }) => {}
                            Err(e) => panic!("{law:?} r {r} delta {delta}: {e}"),
                        }
                    }
                    for p in (0..=40)
                        .map(|k| -f * (1.0 - 10f64.powf(-0.4 * k as f64)))
                        .chain((0..=30).map(|k| f * 10f64.powi(k - 10)))
                    {
                        match d.eval_at_load(p) {
                            Ok(resp) => {
                                ok += 1;
                                assert!(resp.delta.is_finite() && resp.stiffness.is_finite());
                            }
                            Err(Error::OutOfDomain { name: "force", .. }) => {}
                            Err(e) => panic!("{law:?} r {r} P {p}: {e}"),
                        }
                    }
                }
            }
        }
    }
    assert!(ok > 10_000);
    // Far away the force vanishes smoothly.
    let d = Derjaguin::new(R, lj(W, Z0)).unwrap();
    let far = d.eval(-1e6 * Z0, &fresh()).unwrap().0;
    assert!(far.force < 0.0 && far.force > -1e-18);
    // At the most extreme overlaps: huge numbers give an error, not inf/NaN.
    let big = Derjaguin::new(1e300, lj(1e5, 1e-300)).unwrap();
    assert!(matches!(
        big.eval(1e-300 * (1.0 - 1e-15), &fresh()),
        Err(Error::OutOfDomain { name: "delta", .. })
    ));
    assert!(big.eval(-1e308, &fresh()).unwrap().0.force.is_finite());
}

#[test]
fn bad_inputs_name_the_argument() {
    fn name(e: Error) -> &'static str {
        match e {
            Error::InvalidArgument { name, .. } => name,
            Error::OutOfDomain { name, .. } => name,
            Error::UnknownSelector { name, .. } => name,
            e => panic!("{e}"),
        }
    }
    for bad in [-1.0, 0.0, f64::NAN, f64::INFINITY] {
        assert_eq!(name(Derjaguin::new(bad, lj(W, Z0)).unwrap_err()), "radius");
        assert_eq!(
            name(Derjaguin::new(R, lj(bad, Z0)).unwrap_err()),
            "work_of_adhesion"
        );
        assert_eq!(
            name(Derjaguin::new(R, lj(W, bad)).unwrap_err()),
            "equilibrium_separation"
        );
        assert_eq!(
            name(Derjaguin::new(R, dugdale(W, bad)).unwrap_err()),
            "cohesive_stress"
        );
        assert_eq!(
            name(Derjaguin::new(R, expo(W, bad)).unwrap_err()),
            "decay_length"
        );
        assert_eq!(
            name(lj(W, bad).pressure(Z0).unwrap_err()),
            "equilibrium_separation"
        );
    }
    // h₀ = w/σ₀ overflows; 2πRw overflows.
    assert_eq!(
        name(Derjaguin::new(R, dugdale(1e300, 1e-300)).unwrap_err()),
        "cohesive_stress"
    );
    assert_eq!(
        name(Derjaguin::new(1e300, lj(1e300, Z0)).unwrap_err()),
        "radius"
    );

    let [l, dg, ex] = laws().map(|law| Derjaguin::new(R, law).unwrap());
    for d in [l, dg, ex] {
        assert!(matches!(
            d.eval(f64::NAN, &fresh()),
            Err(Error::InvalidArgument { name: "delta", .. })
        ));
        assert!(matches!(
            d.eval_at_load(f64::INFINITY),
            Err(Error::InvalidArgument { name: "force", .. })
        ));
        assert!(matches!(
            d.eval_at_load(-1.0001 * d.adhesive_force()),
            Err(Error::OutOfDomain { name: "force", .. })
        ));
    }
    for delta in [Z0, 2.0 * Z0, 1e300] {
        assert!(matches!(
            l.eval(delta, &fresh()),
            Err(Error::OutOfDomain { name: "delta", .. })
        ));
    }
    for d in [dg, ex] {
        assert!(matches!(
            d.eval(1e-15, &fresh()),
            Err(Error::OutOfDomain { name: "delta", .. })
        ));
        assert!(matches!(
            d.eval_at_load(1e-12),
            Err(Error::OutOfDomain { name: "force", .. })
        ));
        assert!(matches!(
            d.force_at_gap(-1e-12),
            Err(Error::OutOfDomain { name: "gap", .. })
        ));
    }
    assert!(matches!(
        ex.eval_at_load(0.0),
        Err(Error::OutOfDomain { name: "force", .. })
    ));
    assert!(matches!(
        l.force_at_gap(0.0),
        Err(Error::OutOfDomain { name: "gap", .. })
    ));
    assert!(matches!(
        lj(W, Z0).pressure(-1.0),
        Err(Error::OutOfDomain { name: "gap", .. })
    ));
    assert!(matches!(
        expo(W, ELL).energy(f64::NAN),
        Err(Error::InvalidArgument { name: "gap", .. })
    ));

    // A selector written directly (as C may) is validated, never trusted.
    for bad in [0, 4, -1, i32::MAX] {
        let d = written_from_c(l, |p| p.surface_law = bad);
        let sel = |e: Error| matches!(e, Error::UnknownSelector { name: "surface_law", value } if value == bad as i64);
        assert!(sel(d.eval(0.0, &fresh()).unwrap_err()));
        assert!(sel(d.eval_at_load(0.0).unwrap_err()));
        assert!(sel(d.pull_off_force(Control::Load).unwrap_err()));
        assert!(sel(d.force_at_gap(Z0).unwrap_err()));
        assert!(sel(d.try_surface_law().unwrap_err()));
        assert!(d.surface_law().validate().is_err());
    }
    let d = written_from_c(l, |p| p.radius = -1.0);
    assert_eq!(name(d.eval(0.0, &fresh()).unwrap_err()), "radius");
}

/// `d` after C wrote its inputs in place: the member of the storage of an
/// `AsperityNormalLaw`, changed by `write`, read back as the Rust law.
fn written_from_c(d: Derjaguin, write: impl FnOnce(&mut DerjaguinParams)) -> Derjaguin {
    let mut c = AsperityNormalLaw::from(NormalLaw::Derjaguin(d));
    // SAFETY: the member of the kind the value holds.
    write(unsafe { &mut c.params.derjaguin });
    match c.to_law().unwrap() {
        NormalLaw::Derjaguin(d) => d,
        other => panic!("{other:?}"),
    }
}

#[test]
fn layout_and_law_round_trip() {
    assert!(core::mem::size_of::<Derjaguin>() <= 16 * 8);
    for (law, sel) in laws().into_iter().zip([1, 2, 3]) {
        let d = Derjaguin::new(R, law).unwrap();
        assert_eq!(d.params().surface_law, sel);
        assert_eq!(d.params().reserved, 0);
        let back = d.surface_law();
        assert_eq!(back.work_of_adhesion(), W);
        assert_relative_eq!(back.range(), law.range(), max_relative = 1e-15);
        if let SurfaceLaw::Dugdale {
            cohesive_stress, ..
        } = back
        {
            assert_relative_eq!(cohesive_stress, SIGMA0, max_relative = 1e-15);
        }
        assert_eq!(Derjaguin::new(R, back).unwrap(), d);
    }
    // The C constructor passes σ₀ for Dugdale; the law keeps it as its input
    // and h₀ = w/σ₀ as its length.
    let mut out = core::mem::MaybeUninit::<asperity::ffi::contact::AsperityNormalLaw>::uninit();
    let st = unsafe {
        asperity::ffi::contact::asperity_law_derjaguin(
            R,
            W,
            asperity::ffi::contact::ASPERITY_SURFACE_LAW_DUGDALE,
            SIGMA0,
            out.as_mut_ptr(),
        )
    };
    assert_eq!(st, 0);
    let law = unsafe { out.assume_init() }.to_law().unwrap();
    match law {
        NormalLaw::Derjaguin(d) => {
            assert_eq!(
                d.params().surface_law,
                asperity::ffi::contact::ASPERITY_SURFACE_LAW_DUGDALE
            );
            assert_eq!(d.params().parameter, SIGMA0);
            assert_relative_eq!(d.length_scale(), W / SIGMA0, max_relative = 1e-15);
        }
        other => panic!("{other:?}"),
    }
}
