//! Quick start (README): a JKR sphere from Rust, one loading step and the
//! pull-off. Run: `cargo run --example quick_start`.

use asperity::contact::Jkr;
use asperity::{ContactState, Control, NormalContact};

fn main() -> asperity::Result<()> {
    // R = 1 µm, E* = 1 GPa, w = 0.05 J/m² (SI units throughout).
    let law = Jkr::new(1e-6, 1e9, 0.05)?;
    let fresh = ContactState::default(); // all-zero: never touched
    let (r, _new_state) = law.eval(2e-9, &fresh)?;
    println!(
        "delta = 2 nm: force {:.4e} N, contact radius {:.4e} m",
        r.force, r.contact_radius
    );
    let p = law.pull_off_force(Control::Load)?;
    println!(
        "pull-off (load control) {p:.6e} N = {:.6} pi w R",
        p / (std::f64::consts::PI * 0.05e-6)
    );
    // A bad argument is refused with an error naming it.
    let e = Jkr::new(-1e-6, 1e9, 0.05).unwrap_err();
    println!("negative radius: {e}");
    Ok(())
}
