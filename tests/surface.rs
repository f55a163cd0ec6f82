//! Surface module against closed forms (REFERENCE.md §4, thesis 1.5), the
//! ISO 16610-21 filter transmission, generator statistics and the
//! representative pattern. Real measured data: `tests/surface_data.rs`.

use asperity::error::Error;
use asperity::surface::default_fit_band;
use asperity::surface::*;
use std::f64::consts::PI;

/// A profile of `periods` whole periods of A sin(2πx/Λ + phase), `per` samples
/// per period.
fn sine(a: f64, lambda: f64, periods: usize, per: usize, phase: f64) -> Profile {
    let dx = lambda / per as f64;
    let z = (0..periods * per)
        .map(|j| a * (2.0 * PI * j as f64 / per as f64 + phase).sin())
        .collect();
    Profile::new(dx, z).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn sine_matches_iso_closed_forms() {
    // REFERENCE §4: Ra = 2A/π, Rq = A/√2, Rsk = 0, Rku = 1.5,
    // RΔq = √2·πA/Λ, RSm = Λ; and Rp = Rv = A, Rz = Rt = Rc = 2A.
    let (a, lam) = (1.5e-6, 80e-6);
    let p = sine(a, lam, 10, 1000, 0.0);
    for sampling_length in [None, Some(2.0 * lam)] {
        let opts = ParameterOptions {
            sampling_length,
            ..Default::default()
        };
        let r = p.parameters(&opts).unwrap();
        assert!(rel(r.ra, 2.0 * a / PI) < 1e-5, "Ra {}", r.ra);
        assert!(rel(r.rq, a / 2f64.sqrt()) < 1e-12, "Rq {}", r.rq);
        assert!(r.rsk.abs() < 1e-10, "Rsk {}", r.rsk);
        assert!(rel(r.rku, 1.5) < 1e-12, "Rku {}", r.rku);
        assert!(
            rel(r.rdq, 2f64.sqrt() * PI * a / lam) < 1e-5,
            "RDq {}",
            r.rdq
        );
        assert!(rel(r.rsm.unwrap(), lam) < 1e-6, "RSm {:?}", r.rsm);
        assert!(rel(r.rc.unwrap(), 2.0 * a) < 1e-6, "Rc {:?}", r.rc);
        assert!(rel(r.rp, a) < 1e-9 && rel(r.rv, a) < 1e-9);
        assert!(rel(r.rz, 2.0 * a) < 1e-9 && rel(r.rt, 2.0 * a) < 1e-9);
        assert!(r.rz <= r.rt);
        assert_eq!(
            r.sampling_lengths,
            if sampling_length.is_some() { 5 } else { 1 }
        );
        assert!(rel(r.sampling_length, sampling_length.unwrap_or(10.0 * lam)) < 1e-12);
    }
}

#[test]
fn sine_psd_acf_and_moments() {
    // A sine on the DFT grid puts all its variance A²/2 in one line
    // (Parseval, one-sided G of thesis 1-7), so m₀ = A²/2, m₂ = q²A²/2,
    // m₄ = q⁴A²/2 and Nayak's α = m₀m₄/m₂² = 1.
    let (a, lam) = (2e-7, 50e-6);
    let p = sine(a, lam, 8, 256, 0.4);
    let g = p.psd().unwrap();
    let q = 2.0 * PI / lam;
    let k = 8;
    assert!(rel(g.q[k], q) < 1e-12);
    assert!(rel(g.c[k] * g.dq, a * a / 2.0) < 1e-12);
    let off: f64 =
        g.c.iter()
            .enumerate()
            .filter(|&(i, _)| i != k)
            .map(|(_, c)| c)
            .sum();
    assert!(off * g.dq < 1e-24 * a * a);
    let m = g.moments();
    assert!(rel(m.m0, a * a / 2.0) < 1e-12);
    assert!(rel(m.m2, q * q * a * a / 2.0) < 1e-12);
    assert!(rel(m.m4, q.powi(4) * a * a / 2.0) < 1e-12);
    assert!(rel(m.nayak_alpha(), 1.0) < 1e-12);
    // RΔq² is the slope variance m₂ (7-point slopes).
    let r = p.parameters(&ParameterOptions::default()).unwrap();
    assert!(rel(r.rdq * r.rdq, m.m2) < 1e-5);
    // ACF: R_k = (A²/2)cos(ak)(n − k)/n − (A²/2n)Σ_{j<n−k} cos(a(2j + k) + 2φ),
    // a = 2πdx/Λ; the last sum is bounded by 1/|sin a|.
    let c = p.acf().unwrap();
    assert!(rel(c.r[0], r.rq * r.rq) < 1e-12);
    let n = p.len() as f64;
    let step = 2.0 * PI / 256.0;
    let bound = a * a / (2.0 * n * step.sin());
    for k in [1usize, 64, 128, 300, 1000] {
        let main = a * a / 2.0 * (step * k as f64).cos() * (n - k as f64) / n;
        assert!((c.r[k] - main).abs() <= bound, "k = {k}");
    }
    let l = c.correlation_length(0.5).unwrap().unwrap();
    assert!(rel(l, lam / 6.0) < 0.01, "{l}"); // cos(2πδ/Λ) = 1/2 at Λ/6
}

#[test]
fn inverted_profile_same_acf_and_psd_opposite_skewness() {
    // Thesis (1-9): y = −z has the ACF and PSD of z, but Rsk changes sign
    // (and peaks become valleys: Rp and Rv swap).
    let p = SelfAffine::new(0.7, 1e-6)
        .unwrap()
        .profile(4096, 1e-7, 3)
        .unwrap();
    // Make it skewed: exponentiate.
    let z: Vec<f64> = p
        .heights()
        .iter()
        .map(|h| 1e-6 * (h / 1e-6).exp())
        .collect();
    let p = Profile::new(1e-7, z).unwrap();
    let inv = p.inverted();
    let (a, b) = (p.acf().unwrap(), inv.acf().unwrap());
    let r0 = a.r[0];
    assert!(a
        .r
        .iter()
        .zip(&b.r)
        .all(|(x, y)| (x - y).abs() <= 1e-12 * r0));
    let (ga, gb) = (p.psd().unwrap(), inv.psd().unwrap());
    assert_eq!(ga, gb);
    let o = ParameterOptions::default();
    let (ra, rb) = (p.parameters(&o).unwrap(), inv.parameters(&o).unwrap());
    assert!(ra.rsk > 0.5, "Rsk {}", ra.rsk);
    assert!((ra.rsk + rb.rsk).abs() < 1e-12);
    assert!(rel(ra.rku, rb.rku) < 1e-12);
    assert!(rel(ra.rp, rb.rv) < 1e-12 && rel(ra.rv, rb.rp) < 1e-12);
    assert!(rel(ra.rq, rb.rq) < 1e-12);
}

#[test]
fn gaussian_filter_transmission() {
    // ISO 16610-21: the mean line transmits exp(−π(αλc/λ)²), 50 % at λ = λc;
    // the roughness profile z − w the rest. Amplitudes by least-squares
    // projection on sin and cos over the retained part.
    let cutoff = 0.8e-3;
    let dx = 2e-6;
    let n = 8000; // 20 cut-offs
    for (ratio, expected) in [(1.0, 0.5), (0.5, 0.0625), (2.0, 0.840_896_4)] {
        let lam = ratio * cutoff;
        let z: Vec<f64> = (0..n)
            .map(|j| (2.0 * PI * j as f64 * dx / lam + 0.2).sin())
            .collect();
        let p = Profile::new(dx, z).unwrap();
        let f = p.gaussian_filter(cutoff, FilterEnds::Discard).unwrap();
        assert_eq!(f.first_index, 200);
        assert_eq!(f.mean_line.len(), n - 400);
        let amp = |h: &[f64]| {
            let (mut s, mut c, mut ss, mut cc) = (0.0, 0.0, 0.0, 0.0);
            for (i, v) in h.iter().enumerate() {
                let ph = 2.0 * PI * (i + 200) as f64 * dx / lam + 0.2;
                s += v * ph.sin();
                c += v * ph.cos();
                ss += ph.sin() * ph.sin();
                cc += ph.cos() * ph.cos();
            }
            ((s / ss).powi(2) + (c / cc).powi(2)).sqrt()
        };
        let t = amp(f.mean_line.heights());
        assert!((t - expected).abs() < 0.01, "λ/λc = {ratio}: {t}");
        assert!((t - gaussian_transmission(lam, cutoff)).abs() < 2e-3);
        let tr = amp(f.roughness.heights());
        assert!((tr - (1.0 - expected)).abs() < 0.01, "roughness {tr}");
        // r = z − w sample by sample.
        for i in [0usize, 100, 7599] {
            let zi = p.heights()[i + 200];
            assert_eq!(f.roughness.heights()[i], zi - f.mean_line.heights()[i]);
        }
    }
    // A straight line is its own mean line away from the ends.
    let z: Vec<f64> = (0..n).map(|j| 1e-6 + 3e-4 * j as f64 * dx).collect();
    let p = Profile::new(dx, z).unwrap();
    let f = p.gaussian_filter(cutoff, FilterEnds::Keep).unwrap();
    let m = (cutoff / dx) as usize;
    for i in m..n - m {
        assert!((f.roughness.heights()[i]).abs() < 1e-15, "{i}");
    }
    // Errors: cut-off longer than the profile, or unresolved.
    assert!(matches!(
        p.gaussian_filter(n as f64 * dx * 1.01, FilterEnds::Keep),
        Err(Error::InvalidArgument { name: "cutoff", .. })
    ));
    assert!(matches!(
        p.gaussian_filter(3.0 * dx, FilterEnds::Keep),
        Err(Error::InvalidArgument { name: "cutoff", .. })
    ));
    assert!(matches!(
        p.gaussian_filter(-1.0, FilterEnds::Keep),
        Err(Error::InvalidArgument { name: "cutoff", .. })
    ));
}

#[test]
fn material_ratio_of_a_sine() {
    // Fraction of a sine above c: 1/2 − arcsin(c/A)/π.
    let a = 1e-6;
    let p = sine(a, 1e-4, 10, 600, 0.1);
    let m = MaterialRatioCurve::new(p.heights()).unwrap();
    let n = p.len() as f64;
    for c in [-0.9, -0.5, 0.0, 0.5, 0.9] {
        let expected = 0.5 - f64::asin(c) / PI;
        assert!((m.ratio_at(c * a) - expected).abs() <= 2.0 / n, "c = {c}");
    }
    assert!(rel(m.level_at(0.0).unwrap(), a) < 1e-4);
    assert!(rel(m.level_at(1.0).unwrap(), -a) < 1e-4);
    assert!((m.level_at(1.0 / 3.0).unwrap() - 0.5 * a).abs() < 0.01 * a);
    assert!(m.level_at(1.5).is_err());
    let curve = m.curve(11);
    assert_eq!(curve.len(), 11);
    assert!(curve.windows(2).all(|w| w[1].1 <= w[0].1));
}

#[test]
fn areal_parameters_of_a_ridged_map() {
    // z = A sin(2πx/Λ), constant in y: Sq = A/√2, Sa = 2A/π, Ssk = 0,
    // Sku = 1.5, Sdq = √2πA/Λ (no slope along y).
    let (a, lam, nx, ny) = (1e-7, 1e-5, 512, 16);
    let dx = lam / 128.0;
    let h: Vec<f64> = (0..nx * ny)
        .map(|k| a * (2.0 * PI * (k % nx) as f64 / 128.0).sin())
        .collect();
    let t = Topography::new(nx, ny, dx, 2.0 * dx, h).unwrap();
    let s = t.parameters().unwrap();
    assert!(rel(s.sq, a / 2f64.sqrt()) < 1e-12);
    // Sampled mean of |sin| with N = 128 per period: (2/N)cot(π/N) exactly,
    // 2/π to O(N⁻²).
    assert!(rel(s.sa, a * 2.0 / 128.0 / (PI / 128.0).tan()) < 1e-12);
    assert!(rel(s.sa, 2.0 * a / PI) < 1e-3);
    assert!(s.ssk.abs() < 1e-10);
    assert!(rel(s.sku, 1.5) < 1e-12);
    assert!(rel(s.sdq, 2f64.sqrt() * PI * a / lam) < 1e-4);
    assert!(rel(s.sz, 2.0 * a) < 1e-9);
    let j = serde_json::to_value(s).unwrap();
    assert!(j.get("Sdq").is_some() && j.get("Sq").is_some());
}

#[test]
fn parameters_serialise_with_iso_names() {
    let p = sine(1e-6, 1e-4, 4, 100, 0.0);
    let r = p.parameters(&ParameterOptions::default()).unwrap();
    let j = serde_json::to_value(r).unwrap();
    for key in [
        "Rp",
        "Rv",
        "Rz",
        "Rc",
        "Rt",
        "Ra",
        "Rq",
        "Rsk",
        "Rku",
        "RSm",
        "RDq",
        "psd_hurst_exponent",
    ] {
        assert!(j.get(key).is_some(), "missing {key}: {j}");
    }
}

#[test]
fn peaks_of_a_sine_and_rice_density_of_a_gaussian_profile() {
    // Sine: one peak per period, curvature A(2π/Λ)² (3-point, relative
    // error (kdx)²/12).
    let (a, lam) = (1e-6, 1e-4);
    let p = sine(a, lam, 12, 400, 0.3);
    let pk = p.peaks().unwrap();
    assert_eq!(pk.len(), 12);
    let k = 2.0 * PI / lam;
    for q in &pk {
        assert!(rel(q.curvature, a * k * k) < 1e-3, "{}", q.curvature);
        assert!(rel(q.height, a) < 1e-3);
    }
    // Gaussian band-limited profile: Rice's peak density (1/2π)√(m₄/m₂).
    let dx = 1e-7;
    let g = SelfAffine::new(0.8, 1e-7)
        .unwrap()
        .with_roll_off(2000.0 * dx)
        .unwrap()
        .with_cutoff(40.0 * dx)
        .unwrap()
        .profile(1 << 17, dx, 11)
        .unwrap();
    let m = g.psd().unwrap().moments();
    let found = g.peaks().unwrap().len() as f64 / g.length();
    assert!(
        rel(found, m.peak_density()) < 0.03,
        "{found} vs {}",
        m.peak_density()
    );
    let st = PeakStatistics::of_peaks(&g.peaks().unwrap(), g.length());
    assert!(st.mean_height > 0.0 && st.mean_curvature > 0.0);
}

#[test]
fn self_affine_generator_is_reproducible_and_hits_targets() {
    let s = SelfAffine::new(0.8, 0.5e-6).unwrap();
    let a = s.profile(1 << 12, 1e-7, 42).unwrap();
    let b = s.profile(1 << 12, 1e-7, 42).unwrap();
    let c = s.profile(1 << 12, 1e-7, 43).unwrap();
    assert!(a
        .heights()
        .iter()
        .zip(b.heights())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    assert_ne!(a.heights(), c.heights());
    let r = a
        .parameters(&ParameterOptions {
            hurst: false,
            ..Default::default()
        })
        .unwrap();
    assert!(rel(r.rq, 0.5e-6) < 1e-12);
    // Map: bit-identical and Sq on target.
    let ma = s.map(64, 48, 1e-7, 2e-7, 7).unwrap();
    let mb = s.map(64, 48, 1e-7, 2e-7, 7).unwrap();
    assert!(ma
        .heights()
        .iter()
        .zip(mb.heights())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    assert!(rel(ma.parameters().unwrap().sq, 0.5e-6) < 1e-12);
    // Slice forms agree with the map forms.
    let (h, dx) = (ma.heights(), ma.dx());
    assert_eq!(summits_grid(h, 64, 48, dx, 2e-7).unwrap(), ma.summits());
    assert!(!ma.summits().is_empty());
    assert_eq!(
        areal_parameters_grid(h, 64, 48, dx, 2e-7).unwrap(),
        ma.parameters().unwrap()
    );
    assert!(summits_grid(h, 64, 47, dx, 2e-7).is_err());
    assert!(areal_parameters_grid(h, 64, 48, dx, f64::NAN).is_err());
}

#[test]
fn self_affine_hurst_exponent_is_recovered() {
    // PSD ∝ q^{−(1+2H)}: the fitted H, averaged over four generated profiles
    // of 2^16 points (one fit scatters by about ±0.025), is within ±0.05 of
    // the input.
    for h in [0.3, 0.5, 0.8, 0.95] {
        let mut sum = 0.0;
        for seed in 1..=4u64 {
            let p = SelfAffine::new(h, 1e-6)
                .unwrap()
                .profile(1 << 16, 1e-8, seed)
                .unwrap();
            let fit = hurst_fit(p.heights(), p.dx(), None).unwrap();
            assert!(fit.r_squared > 0.95, "H = {h}: r² {}", fit.r_squared);
            assert!((fit.hurst - h).abs() < 0.1, "H = {h}: {}", fit.hurst);
            let hp = psd_hurst_exponent(p.heights(), p.dx()).unwrap();
            assert_eq!(hp, Some(fit.hurst).filter(|h| (0.0..=1.0).contains(h)));
            sum += fit.hurst;
        }
        assert!((sum / 4.0 - h).abs() < 0.05, "H = {h}: mean {}", sum / 4.0);
    }
    // With a roll-off: fit above it; flat below.
    let dx = 1e-8;
    let n = 1 << 15;
    let p = SelfAffine::new(0.6, 1e-6)
        .unwrap()
        .with_roll_off(n as f64 * dx / 16.0)
        .unwrap()
        .profile(n, dx, 9)
        .unwrap();
    let g = psd_windowed(p.heights(), dx, Window::Hann).unwrap();
    let qr = 2.0 * PI / (n as f64 * dx / 16.0);
    let fit = g.power_law_fit(2.0 * qr, PI / (4.0 * dx)).unwrap();
    assert!((fit.hurst - 0.6).abs() < 0.05, "{}", fit.hurst);
    let flat = g.power_law_fit(default_fit_band(n, dx).0, qr).unwrap();
    assert!(flat.slope.abs() < 0.5, "{}", flat.slope);
}

#[test]
fn self_affine_map_has_the_areal_power_law() {
    // An isotropic map's 2-D periodogram |F(q)|² falls as q^{−2(1+H)}: fit
    // the log-binned radial average (geometric means, as the profile fit).
    use rustfft::{num_complex::Complex64, FftPlanner};
    let h = 0.7;
    let (n, dx) = (256usize, 1e-8);
    let t = SelfAffine::new(h, 1e-7)
        .unwrap()
        .map(n, n, dx, dx, 5)
        .unwrap();
    let mut a: Vec<Complex64> = t
        .heights()
        .iter()
        .map(|&z| Complex64::new(z, 0.0))
        .collect();
    let fft = FftPlanner::new().plan_fft_forward(n);
    fft.process(&mut a);
    let mut b = vec![Complex64::default(); n * n];
    for j in 0..n {
        for i in 0..n {
            b[i * n + j] = a[j * n + i];
        }
    }
    fft.process(&mut b);
    let dq = 2.0 * PI / (n as f64 * dx);
    let (q_lo, q_hi) = (4.0 * dq, n as f64 / 8.0 * dq);
    let bins = 20;
    let mut acc = vec![(0.0, 0.0, 0usize); bins];
    for i in 0..n {
        for j in 0..n {
            let (ki, kj) = (i.min(n - i) as f64, j.min(n - j) as f64);
            let q = ki.hypot(kj) * dq;
            if q < q_lo || q >= q_hi {
                continue;
            }
            let bin = ((q / q_lo).ln() / (q_hi / q_lo).ln() * bins as f64) as usize;
            let e = &mut acc[bin];
            e.0 += q.log10();
            e.1 += b[i * n + j].norm_sqr().log10();
            e.2 += 1;
        }
    }
    let pts: Vec<(f64, f64)> = acc
        .iter()
        .filter(|e| e.2 > 0)
        .map(|e| (e.0 / e.2 as f64, e.1 / e.2 as f64))
        .collect();
    let k = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / k;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / k;
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    let fitted_h = -(sxy / sxx) / 2.0 - 1.0;
    assert!((fitted_h - h).abs() < 0.05, "{fitted_h}");
}

#[test]
fn short_wavelength_cutoff_removes_power() {
    let dx = 1e-8;
    let p = SelfAffine::new(0.5, 1e-6)
        .unwrap()
        .with_cutoff(20.0 * dx)
        .unwrap()
        .profile(4096, dx, 1)
        .unwrap();
    let g = p.psd().unwrap();
    let qs = 2.0 * PI / (20.0 * dx);
    let above: f64 =
        g.q.iter()
            .zip(&g.c)
            .filter(|(q, _)| **q > qs * 1.001)
            .map(|(_, c)| c)
            .sum();
    assert!(above * g.dq < 1e-26 * g.integral() + 1e-40, "{above}");
    assert!(SelfAffine::new(1.2, 1e-6).is_err());
    assert!(SelfAffine::new(0.5, 1e-6)
        .unwrap()
        .with_roll_off(1e-6)
        .unwrap()
        .with_cutoff(2e-6)
        .is_err());
}

#[test]
fn weierstrass_mandelbrot_variance_and_spectrum() {
    // With γ = 2 every line sits on a DFT bin below Nyquist, so the sample
    // variance is exactly Σ_k (A γ^{(D−2)k})²/2 and the PSD envelope falls as
    // q^{−(5−2D)}: H = 2 − D.
    let (d, a, n) = (1.4, 1e-6, 1 << 14);
    let wm = WeierstrassMandelbrot::new(d, 2.0, a).unwrap();
    let p = wm.profile(n, 1e-8, 17).unwrap();
    let again = wm.profile(n, 1e-8, 17).unwrap();
    assert!(p
        .heights()
        .iter()
        .zip(again.heights())
        .all(|(x, y)| x.to_bits() == y.to_bits()));
    let k_terms = wm.terms(n);
    assert_eq!(k_terms, 13); // 2^12 = 4096 < 8192 = n/2
    let var: f64 = (0..k_terms)
        .map(|k| (a * 2f64.powf((d - 2.0) * k as f64)).powi(2) / 2.0)
        .sum();
    let g = p.psd().unwrap();
    assert!(rel(g.integral(), var) < 1e-10);
    // Series value at one point, evaluated independently.
    let ph = wm.phases(n, 17);
    let j = 1234;
    let direct: f64 = (0..k_terms)
        .map(|k| {
            a * 2f64.powf((d - 2.0) * k as f64)
                * (ph[k].cos()
                    - (2.0 * PI * 2f64.powi(k as i32) * j as f64 / n as f64 + ph[k]).cos())
        })
        .sum();
    assert!((p.heights()[j] - direct).abs() < 1e-12 * a);
    // Line powers: G_k Δq at k = 2^i equals (A γ^{(D−2)i})²/2.
    for i in [0usize, 5, 12] {
        let amp = a * 2f64.powf((d - 2.0) * i as f64);
        assert!(rel(g.c[1 << i] * g.dq, amp * amp / 2.0) < 1e-9);
    }
    assert!(WeierstrassMandelbrot::new(2.0, 1.5, a).is_err());
    assert!(WeierstrassMandelbrot::new(1.5, 1.0, a).is_err());
}

#[test]
fn cantor_borodich_dimension_and_structure() {
    // Thesis 1.5.3: dim = 1 + ln(2β)/ln(1/α), 0 < α < 1/2 < β < 1; three
    // descendants (Warren–Krajcinovic): 1 + ln(3β)/ln(1/α).
    let c2 = CantorBorodich::new(2, 0.25, 0.7, 1.0, 8).unwrap();
    assert!(rel(c2.fractal_dimension(), 1.0 + (1.4f64).ln() / 4f64.ln()) < 1e-15);
    let c3 = CantorBorodich::new(3, 0.2, 0.6, 1.0, 6).unwrap();
    assert!(rel(c3.fractal_dimension(), 1.0 + (1.8f64).ln() / 5f64.ln()) < 1e-15);
    // Limits: β → 1/2 flattens (D → 1); β → 1, α → 1/2 fills (D → 2).
    let lo = CantorBorodich::new(2, 0.25, 0.5 + 1e-9, 1.0, 4).unwrap();
    assert!((lo.fractal_dimension() - 1.0).abs() < 1e-8);
    let hi = CantorBorodich::new(2, 0.5 - 1e-9, 1.0 - 1e-9, 1.0, 4).unwrap();
    assert!((hi.fractal_dimension() - 2.0).abs() < 1e-6);
    // Box counting of generated profiles: square boxes, heights comparable to
    // the length (h = 0.3 L; the estimate depends on that aspect, see
    // `box_counting_dimension`), 100 000 samples, 30 generations.
    let l = 1.0;
    let c2 = CantorBorodich::new(2, 0.25, 0.7, 0.3, 30).unwrap();
    let c3 = CantorBorodich::new(3, 0.2, 0.6, 0.3, 30).unwrap();
    let p2 = c2.profile(l, 100_000).unwrap();
    let b2 = box_counting_dimension(p2.heights(), p2.dx()).unwrap();
    assert!(
        (b2.dimension - c2.fractal_dimension()).abs() < 0.05,
        "{} vs {}",
        b2.dimension,
        c2.fractal_dimension()
    );
    let p3 = c3.profile(l, 100_000).unwrap();
    let b3 = box_counting_dimension(p3.heights(), p3.dx()).unwrap();
    assert!(
        (b3.dimension - c3.fractal_dimension()).abs() < 0.05,
        "{} vs {}",
        b3.dimension,
        c3.fractal_dimension()
    );
    // Structure: the blocks of generation K cover (mα)^K of the length and
    // stand at least h(1 − β^K)/(1 − β) high (8 generations on 4^8 samples,
    // every block starting on a sample).
    let c8 = CantorBorodich::new(2, 0.25, 0.7, 1.0, 8).unwrap();
    let p8 = c8.profile(l, 1 << 16).unwrap();
    let m = MaterialRatioCurve::new(p8.heights()).unwrap();
    let zbar = p8.heights().iter().sum::<f64>() / p8.len() as f64;
    for k in 1..=8u32 {
        let top = (1.0 - 0.7f64.powi(k as i32)) / 0.3;
        assert!(
            rel(m.ratio_at(top - zbar - 1e-9), 0.5f64.powi(k as i32)) < 1e-12,
            "k = {k}"
        );
    }
    // Bounds from the thesis.
    assert!(CantorBorodich::new(2, 0.5, 0.7, 1.0, 3).is_err());
    assert!(CantorBorodich::new(2, 0.25, 0.5, 1.0, 3).is_err());
    assert!(
        CantorBorodich::new(3, 0.25, 0.5, 1.0, 3)
            .unwrap()
            .fractal_dimension()
            > 1.0
    );
    assert!(CantorBorodich::new(1, 0.25, 0.7, 1.0, 3).is_err());
}

#[test]
fn representative_pattern_of_a_periodic_profile_is_exact() {
    // A profile made of 12 copies of a 52-point section: every full period is
    // distributed exactly like the whole (D = 0), and replicating it gives the
    // profile back.
    let base: Vec<f64> = (0..52)
        .map(|j| ((j * 37 % 52) as f64 * 0.7).sin() * 1e-6)
        .collect();
    let z: Vec<f64> = base.iter().copied().cycle().take(52 * 12).collect();
    let r = representative_pattern(&z, 52).unwrap();
    assert_eq!(r.ks_statistic, 0.0);
    assert_eq!(r.start, 0);
    assert_eq!(r.replicate(z.len()).unwrap(), z);
    assert!((r.p_value() - 1.0).abs() < 1e-12);
}

#[test]
fn representative_pattern_is_the_ks_minimiser() {
    // Thesis Figs. 1-11/1-12 sizes: 52 of 668 points. Brute force: sort each
    // window and compare with the two-sample KS statistic.
    let p = SelfAffine::new(0.6, 1e-6)
        .unwrap()
        .profile(668, 1e-6, 21)
        .unwrap();
    let z = p.heights();
    let r = representative_pattern(z, 52).unwrap();
    let mut best = (f64::INFINITY, 0);
    for s in 0..=668 - 52 {
        let d = ks_two_sample(&z[s..s + 52], z).unwrap();
        if d < best.0 - 1e-15 {
            best = (d, s);
        }
    }
    assert!((r.ks_statistic - best.0).abs() < 1e-12);
    assert_eq!(r.start, best.1);
    assert_eq!(r.pattern, z[r.start..r.start + 52].to_vec());
    let eq = p.replicated(&r, 668).unwrap();
    assert_eq!(eq.len(), 668);
    assert_eq!(eq.heights()[52..104], z[r.start..r.start + 52]);
    assert!(representative_pattern(z, 0).is_err());
    assert!(representative_pattern(z, 669).is_err());
}

#[test]
fn bad_input_is_an_error_not_a_nan() {
    let o = ParameterOptions::default();
    assert!(matches!(
        roughness_parameters(&[], 1e-6, &o),
        Err(Error::InvalidArgument {
            name: "heights.len()",
            ..
        })
    ));
    assert!(matches!(
        roughness_parameters(&[1.0; 5], 1e-6, &o),
        Err(Error::InvalidArgument {
            name: "heights.len()",
            ..
        })
    ));
    assert!(matches!(
        roughness_parameters(&[1e-6; 64], 1e-6, &o),
        Err(Error::OutOfDomain {
            name: "heights",
            ..
        })
    ));
    let mut z = vec![0.0; 64];
    z[3] = 1.0;
    z[10] = f64::NAN;
    assert!(matches!(
        roughness_parameters(&z, 1e-6, &o),
        Err(Error::InvalidArgument {
            name: "heights",
            ..
        })
    ));
    z[10] = f64::INFINITY;
    assert!(psd(&z, 1e-6).is_err() && acf(&z, 1e-6).is_err() && peaks(&z, 1e-6).is_err());
    z[10] = 0.5;
    assert!(matches!(
        roughness_parameters(&z, 0.0, &o),
        Err(Error::InvalidArgument { name: "dx", .. })
    ));
    assert!(matches!(
        roughness_parameters(
            &z,
            1e-6,
            &ParameterOptions {
                sampling_length: Some(65e-6),
                ..o
            }
        ),
        Err(Error::InvalidArgument {
            name: "sampling_length",
            ..
        })
    ));
    assert!(Profile::new(1e-6, vec![1.0]).is_err());
    assert!(Profile::new(-1e-6, vec![1.0, 2.0]).is_err());
    assert!(Topography::new(2, 2, 1.0, 1.0, vec![1.0; 3]).is_err());
    let e = parse_profile("x,z\n0,1\n1,2\n5,3\n", Spacing::Tolerant).unwrap_err();
    assert!(matches!(e, Error::InvalidArgument { name: "x", .. }), "{e}");
    assert!(e.to_string().contains("uniformly spaced"));
    // Constant heights are fine where nothing divides by Rq.
    let g = psd(&[2.0; 16], 1.0).unwrap();
    assert_eq!(g.integral(), 0.0);
    assert_eq!(psd_hurst_exponent(&[2.0; 256], 1.0).unwrap(), None);
}

#[test]
fn form_removal_then_parameters() {
    // Tilt and bow on a sine: quadratic removal recovers the sine's Rq.
    let p = sine(1e-7, 1e-5, 40, 100, 0.0);
    let n = p.len();
    let z: Vec<f64> = p
        .heights()
        .iter()
        .enumerate()
        .map(|(j, h)| {
            let x = j as f64 / n as f64;
            h + 3e-6 * x + 5e-6 * (x - 0.5) * (x - 0.5)
        })
        .collect();
    let bent = Profile::new(p.dx(), z).unwrap();
    let flat = bent.remove_form(Form::Quadratic).unwrap();
    let o = ParameterOptions::default();
    let r = flat.parameters(&o).unwrap();
    assert!(rel(r.rq, 1e-7 / 2f64.sqrt()) < 1e-3, "{}", r.rq);
    let lin = bent
        .remove_form(Form::Linear)
        .unwrap()
        .parameters(&o)
        .unwrap();
    assert!(lin.rq > 2.0 * r.rq);
}

/// Fuzzing regression (fuzz/regressions/c_abi/hurst_fit_infinite_band): a
/// fit band whose ratio q_max/q_min overflows f64 (a subnormal q_min) is an
/// error naming `q_max`, not an overflowing bin count (a panic the C guard
/// turned into ASPERITY_ERR_INTERNAL). The widest finite band still works.
#[test]
fn hurst_fit_band_beyond_f64_is_an_error() {
    let z: Vec<f64> = (0..64).map(|j| (0.7 * j as f64).sin() * 1e-7).collect();
    for (lo, hi) in [
        (5e-324, 1e3),
        (1e-300, 1e300),
        (f64::MIN_POSITIVE, f64::MAX),
    ] {
        match hurst_fit(&z, 1e-6, Some((lo, hi))) {
            Err(Error::InvalidArgument { name: "q_max", .. }) => {}
            other => panic!("band ({lo:e}, {hi:e}): {other:?}"),
        }
    }
    // 1e-150 .. 1e150: 300 decades, finite; any outcome but a panic.
    let _ = hurst_fit(&z, 1e-6, Some((1e-150, 1e150)));
}

/// A profile from position and height columns is the one `parse_profile`
/// reads from the same numbers as text (the Python package's
/// `profile_parameters(x, z)` builds its profiles this way), and bad columns
/// are refused naming `x` or `z`.
#[test]
fn profile_from_positions_equals_parse_profile() {
    // Positions rounded as an instrument writes them, off the uniform grid.
    let x: Vec<f64> = (0..64)
        .map(|j| (j as f64 * 0.15625e-6 * 1e7).round() / 1e7)
        .collect();
    let z: Vec<f64> = (0..64).map(|j| (j as f64 * 0.7).sin() * 1e-7).collect();
    let text: String = x
        .iter()
        .zip(&z)
        .map(|(x, z)| format!("{x:e},{z:e}\n"))
        .collect();
    let read = parse_profile(&text, Spacing::Tolerant).unwrap();
    let built = profile_from_positions(&x, z.clone(), Spacing::Tolerant).unwrap();
    assert_eq!(read, built);
    assert!(built.spacing_deviation() > 0.1);
    let name = |e: Error| match e {
        Error::InvalidArgument { name, .. } => name,
        other => panic!("{other}"),
    };
    assert_eq!(
        name(profile_from_positions(&x, z[..63].to_vec(), Spacing::Tolerant).unwrap_err()),
        "z"
    );
    let mut back = x.clone();
    back.swap(3, 4);
    assert_eq!(
        name(profile_from_positions(&back, z.clone(), Spacing::Tolerant).unwrap_err()),
        "x"
    );
    assert_eq!(
        name(profile_from_positions(&x, z, Spacing::Strict).unwrap_err()),
        "x"
    );
}
