//! Writes the two small files the README's commands read
//! (`examples/data/`), so they run from a fresh clone:
//!
//! - `synthetic_berkovich.csv`: a Berkovich indentation curve of a
//!   fused-silica-like sample (E_r = 69.6 GPa, H = 9 GPa), made to be read
//!   back by Oliver–Pharr: loading P = P_max (h/h_max)², a hold, and
//!   unloading P = P_max ((h − h_f)/(h_max − h_f))^m with m = 1.5, whose
//!   stiffness at h_max is S = 2β E_r √(A(h_c)/π) with the library's ideal
//!   Berkovich area and β, and h_c = h_max − ε P_max/S (ε = 0.75).
//! - `synthetic_profile.csv`: a self-affine line scan (H = 0.8, Rq = 0.5 µm,
//!   2048 points 1 µm apart) from the library's Fourier generator.
//!
//! Run: `cargo run --example example_data` (rewrites both files).

use asperity::indentation::Indenter;
use asperity::surface::SelfAffine;
use std::fmt::Write as _;

const E_R: f64 = 69.6e9; // Pa
const HARDNESS: f64 = 9e9; // Pa
const P_MAX: f64 = 0.1; // N
const M: f64 = 1.5; // unloading exponent
const EPSILON: f64 = 0.75; // Oliver–Pharr ε of a paraboloid of revolution

fn main() -> asperity::Result<()> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/data");

    // Indentation: contact area from the hardness, contact depth from the
    // ideal area function (bisection), stiffness from E_r.
    let tip = Indenter::Berkovich;
    let area_fn = tip.ideal_area();
    let a_c = P_MAX / HARDNESS;
    let (mut lo, mut hi) = (0.0_f64, 1e-3_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if area_fn.area(mid)? < a_c {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let h_c = 0.5 * (lo + hi);
    let s = 2.0 * tip.beta() * E_R * (a_c / std::f64::consts::PI).sqrt();
    let h_max = h_c + EPSILON * P_MAX / s;
    let h_f = h_max - M * P_MAX / s;

    let mut csv = String::from(
        "# synthetic Berkovich curve written by `cargo run --example example_data`\n\
         # sample: fused-silica-like, E_r = 69.6 GPa against diamond, H = 9 GPa\n\
         time_s,depth_m,load_N,segment\n",
    );
    let n = 200;
    let mut t = 0.0;
    for i in 0..=n {
        let h = h_max * i as f64 / n as f64;
        let _ = writeln!(
            csv,
            "{t:.3},{h:.6e},{:.6e},loading",
            P_MAX * (h / h_max).powi(2)
        );
        t += 0.1;
    }
    for _ in 0..20 {
        let _ = writeln!(csv, "{t:.3},{h_max:.6e},{P_MAX:.6e},hold");
        t += 0.1;
    }
    for i in 1..=n {
        let h = h_max - (h_max - h_f) * i as f64 / n as f64;
        let p = P_MAX * ((h - h_f) / (h_max - h_f)).max(0.0).powf(M);
        let _ = writeln!(csv, "{t:.3},{h:.6e},{p:.6e},unloading");
        t += 0.1;
    }
    std::fs::write(dir.join("synthetic_berkovich.csv"), csv).expect("write the curve");

    // Profile.
    let profile = SelfAffine::new(0.8, 0.5e-6)?.profile(2048, 1e-6, 2026)?;
    let mut csv = String::from(
        "# synthetic self-affine line scan written by `cargo run --example example_data`\n\
         # H = 0.8, Rq = 0.5 um, 2048 points, dx = 1 um\n\
         x_m,z_m\n",
    );
    for (j, z) in profile.heights().iter().enumerate() {
        let _ = writeln!(csv, "{:.6e},{z:.6e}", profile.x(j));
    }
    std::fs::write(dir.join("synthetic_profile.csv"), csv).expect("write the profile");
    println!(
        "wrote {}: h_max = {h_max:.4e} m, h_c = {h_c:.4e} m, S = {s:.4e} N/m",
        dir.display()
    );
    Ok(())
}
