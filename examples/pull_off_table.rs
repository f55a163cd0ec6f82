//! Pull-off force against the Maugis parameter λ for DMT, Maugis–Dugdale and
//! JKR, and one Maugis–Dugdale force–approach cycle.
//!
//! Run: `cargo run --release --example pull_off_table`
//!
//! The sphere: R = 1 µm, E* = 1 GPa, w = 0.05 J/m². λ is set through the
//! Dugdale stress σ₀ = (λ/2)(πwK²/R)^{1/3}, K = 4E*/3 (Maugis 1992).

use asperity::contact::{Dmt, Jkr, MaugisDugdale};
use asperity::material::{jkr_k, maugis_parameter};
use asperity::{ContactState, Control, NormalContact};
use std::f64::consts::PI;

fn main() -> Result<(), asperity::Error> {
    let (r, e, w) = (1e-6, 1e9, 0.05);
    let scale = PI * w * r;
    let k = jkr_k(e);
    let sigma_for = |lambda: f64| 0.5 * lambda * (PI * w * k * k / r).cbrt();

    let dmt = Dmt::new(r, e, w)?;
    let jkr = Jkr::new(r, e, w)?;
    println!("Pull-off force / (pi w R) against the Maugis parameter (R = 1 um, E* = 1 GPa, w = 0.05 J/m^2)");
    println!(
        "{:>10} {:>10} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "lambda",
        "sigma0/Pa",
        "DMT load",
        "MD load",
        "JKR load",
        "DMT displ",
        "MD displ",
        "JKR displ"
    );
    for i in 0..=16 {
        let lambda = 10f64.powf(-2.0 + 0.25 * i as f64);
        let md = MaugisDugdale::new(r, e, w, sigma_for(lambda))?;
        debug_assert!((maugis_parameter(r, w, e, sigma_for(lambda))? / lambda - 1.0).abs() < 1e-12);
        let row = |c| -> Result<[f64; 3], asperity::Error> {
            Ok([
                dmt.pull_off_force(c)? / scale,
                md.pull_off_force(c)? / scale,
                jkr.pull_off_force(c)? / scale,
            ])
        };
        let l = row(Control::Load)?;
        let d = row(Control::Displacement)?;
        println!(
            "{:>10.4} {:>10.3e} {:>12.5} {:>12.5} {:>12.5} {:>12.5} {:>12.5} {:>12.5}",
            lambda,
            sigma_for(lambda),
            l[0],
            l[1],
            l[2],
            d[0],
            d[1],
            d[2]
        );
    }

    // One force–approach cycle under displacement control at λ = 2 (S-shaped:
    // jump-in on approach, jump-out on retraction).
    let md = MaugisDugdale::new(r, e, w, sigma_for(2.0))?;
    let len = md.length_scale();
    println!();
    println!("Maugis-Dugdale force-approach cycle, lambda = 2 (delta in units of (pi^2 w^2 R/K^2)^(1/3) = {len:.4e} m)");
    println!(
        "{:>6} {:>10} {:>14} {:>14} {:>4}",
        "step", "delta", "force/(pi w R)", "a/m", "on"
    );
    let mut state = ContactState::default();
    let n = 40;
    let path = (0..=n)
        .map(|i| -3.0 + 5.0 * i as f64 / n as f64)
        .chain((0..=n).map(|i| 2.0 - 5.0 * i as f64 / n as f64));
    for (step, x) in path.enumerate() {
        let (resp, next) = md.eval(x * len, &state)?;
        state = next;
        println!(
            "{:>6} {:>10.4} {:>14.6} {:>14.6e} {:>4}",
            step,
            x,
            resp.force / scale,
            resp.contact_radius,
            resp.in_contact
        );
    }
    Ok(())
}
