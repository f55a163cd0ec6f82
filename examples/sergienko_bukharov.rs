//! The Sergienko–Bukharov model (thesis §5.3.5, the library's formulation
//! from the thesis's description): a rigid body on Kragelsky's springs,
//! shaken normally by F₀ sin ωt. Prints the dynamic lift and the friction
//! ratio ⟨F_f⟩/F_s against the amplitude F₀/N for Gaussian and uniformly
//! spread spring heights, and the quasi-static closed form for the uniform
//! springs, ⟨y⟩/y_s = (1/2π)∫√(1 + a sin φ) dφ.
//!
//! `cargo run --release --example sergienko_bukharov`

use asperity::statistics::{
    Excitation, HeightDistribution, Integration, KragelskyRods, SergienkoBukharov,
};
use core::f64::consts::TAU;

fn main() -> asperity::Result<()> {
    let (k, area, load, mu, p0) = (1e4, 1e-12, 1.0, 0.2, 1e9);
    let count = 20_000;
    let span = 1e-5;
    let uniform: Vec<f64> = (0..count)
        .map(|j| (j as f64 + 0.5) * span / count as f64)
        .collect();
    let cases = [
        (
            "Gaussian heights, σ = 1 µm, N = 1e4 springs",
            KragelskyRods::new(1e4, area, k, HeightDistribution::gaussian(1e-6)?)?,
        ),
        (
            "uniform heights over 10 µm, 20000 springs",
            KragelskyRods::new(
                count as f64,
                area,
                k,
                HeightDistribution::empirical(uniform)?,
            )?,
        ),
    ];
    for (name, rods) in cases {
        let body = SergienkoBukharov::new(rods, 1e-3, load, 0.2, mu, p0)?;
        let w0 = body.natural_frequency();
        println!("\n{name}: m = 1 g, N = {load} N, ζ = 0.2, μ = {mu}, p0 = {p0:e} Pa");
        println!(
            "static: d_s = {:.4e} m, n_s = {:.1}, F_s = {:.4} N, ω₀ = {:.4e} rad/s",
            body.static_separation(),
            body.static_contacts(),
            body.static_friction(),
            w0
        );
        println!(
            "{:>6} {:>8} {:>12} {:>10} {:>10} {:>10} {:>9}",
            "ω/ω₀", "F₀/N", "lift (m)", "⟨n⟩/n_s", "⟨F⟩/F_s", "off (%)", "closed"
        );
        for ratio in [0.01, 0.3] {
            for a in [0.0, 0.2, 0.4, 0.6, 0.8, 0.95, 1.2, 1.6, 2.0] {
                let r = body.run(
                    &Excitation {
                        force_amplitude: a * load,
                        frequency: ratio * w0,
                        ..Default::default()
                    },
                    &Integration {
                        transient_periods: if ratio < 0.1 { 3 } else { 20 },
                        average_periods: 4,
                        ..Default::default()
                    },
                )?;
                // Quasi-static closed form for the uniform springs (a ≤ 1).
                let closed = if name.starts_with("uniform") && ratio < 0.1 && a <= 1.0 {
                    let n = 4096;
                    let m = (0..n)
                        .map(|i| (1.0 + a * (TAU * i as f64 / n as f64).sin()).sqrt())
                        .sum::<f64>()
                        / n as f64;
                    format!("{m:.4}")
                } else {
                    "-".into()
                };
                println!(
                    "{:>6} {:>8.2} {:>12.4e} {:>10.4} {:>10.4} {:>10.1} {:>9}",
                    ratio,
                    a,
                    r.lift,
                    r.contact_ratio,
                    r.friction_ratio,
                    100.0 * r.lift_off_fraction,
                    closed
                );
            }
        }
    }
    Ok(())
}
