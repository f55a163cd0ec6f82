//! The speed–accuracy table of BENCHMARKS.md: for μ ∈ {0.01, 0.1, 0.3, 1, 3,
//! 10}, each adhesive-sphere model's time per evaluation and its error against
//! the converged Lennard-Jones sphere, for the pull-off force and as the
//! largest difference over a displacement-controlled approach and retraction.
//!
//! Run: `cargo run --release --example speed_accuracy` (prints Markdown).

use asperity::fidelity::{assess, Fidelity};

fn main() -> Result<(), asperity::Error> {
    // R = 1 µm, w = 0.05 J/m², z0 = 0.3 nm; E* chosen to give each μ:
    // μ³ = R w²/(E*² z0³).
    let (r, w, z0) = (1e-6, 0.05, 0.3e-9);
    let force_scale = std::f64::consts::PI * r * w;
    println!("| μ | model | time per call | pull-off error / πRw | max force error over the curve / πRw | build |");
    println!("|---|---|---|---|---|---|");
    for mu in [0.01, 0.1, 0.3, 1.0, 3.0, 10.0] {
        let e_star = (r * w * w / (mu * mu * mu * z0 * z0 * z0)).sqrt();
        let (rows, p_ref, grid) = match assess(r, e_star, w, z0) {
            Ok(x) => x,
            Err(e) => {
                println!("| {mu} | (reference not available: {e}) | | | | |");
                continue;
            }
        };
        for a in rows {
            let cost = if a.cost_per_call < 1e-6 {
                format!("{:.1} ns", a.cost_per_call * 1e9)
            } else if a.cost_per_call < 1e-3 {
                format!("{:.2} µs", a.cost_per_call * 1e6)
            } else {
                format!("{:.2} ms", a.cost_per_call * 1e3)
            };
            let build = if a.build_time > 0.0 {
                format!("{:.1} ms", a.build_time * 1e3)
            } else {
                "–".to_string()
            };
            let note = if a.law == Fidelity::LennardJones {
                format!(
                    " (reference, N = {grid}, P_c = {:.5} πRw)",
                    p_ref / force_scale
                )
            } else {
                String::new()
            };
            println!(
                "| {mu} | {}{note} | {cost} | {:.2e} | {:.2e} | {build} |",
                a.law.name(),
                a.pull_off_error / force_scale,
                a.curve_error / force_scale,
            );
        }
    }
    Ok(())
}
