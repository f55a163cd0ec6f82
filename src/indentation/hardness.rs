//! Hardness numbers (thesis §2.3) and the moduli that follow from the
//! unloading stiffness: BASh (2-14) with Oliver–Pharr's β, and the sample
//! modulus (2-15).

use crate::error::{check, Error, Result};

/// Brinell hardness (2-7): load over the curved area of the spherical
/// impression, `BHN = 2P/(πD(D − √(D² − d²)))` (Pa) for ball diameter D and
/// impression diameter d (m), `0 < d ≤ D`. Classical tables quote kgf/mm²
/// (divide Pa by 9.80665e6).
pub fn brinell_hardness(load: f64, ball_diameter: f64, imprint_diameter: f64) -> Result<f64> {
    let p = check::non_negative("load", load)?;
    let big_d = check::positive("ball_diameter", ball_diameter)?;
    let d = check::positive("imprint_diameter", imprint_diameter)?;
    if d > big_d {
        return Err(Error::InvalidArgument {
            name: "imprint_diameter",
            value: d,
            bound: "<= ball_diameter",
        });
    }
    // D − √(D² − d²) = d²/(D + √(D² − d²)), free of cancellation for small d.
    let cap = d * d / (big_d + (big_d * big_d - d * d).sqrt());
    Ok(2.0 * p / (core::f64::consts::PI * big_d * cap))
}

/// Meyer hardness (2-8), (2-11): load over the projected area,
/// `H_M = 4P/(πd²)` (Pa), impression diameter d (m).
pub fn meyer_hardness(load: f64, imprint_diameter: f64) -> Result<f64> {
    let p = check::non_negative("load", load)?;
    let d = check::positive("imprint_diameter", imprint_diameter)?;
    Ok(4.0 * p / (core::f64::consts::PI * d * d))
}

/// Ludwik hardness (2-10) of a 90° cone: load over the conical surface,
/// `LHN = 4P/(√2 π d²)` (Pa), impression diameter d (m).
pub fn ludwik_hardness(load: f64, imprint_diameter: f64) -> Result<f64> {
    Ok(meyer_hardness(load, imprint_diameter)? / core::f64::consts::SQRT_2)
}

/// Vickers hardness (2-12): load over the surface of the pyramidal
/// impression, `HV = 2P sin(136°/2)/d² = 1.8544 P/d²` (Pa), mean diagonal d (m).
pub fn vickers_hardness(load: f64, mean_diagonal: f64) -> Result<f64> {
    let p = check::non_negative("load", load)?;
    let d = check::positive("mean_diagonal", mean_diagonal)?;
    Ok(2.0 * p * (68.0_f64).to_radians().sin() / (d * d))
}

/// Reduced modulus from the unloading stiffness and the projected contact
/// area (Pa): `E_r = (√π/2) S/(β√A)` (BASh (2-14) with Oliver–Pharr's β;
/// β = 1 is (2-14) itself). S in N/m, A in m², β > 0.
pub fn reduced_modulus_from_stiffness(stiffness: f64, area: f64, beta: f64) -> Result<f64> {
    let s = check::positive("stiffness", stiffness)?;
    let a = check::positive("area", area)?;
    let b = check::positive("beta", beta)?;
    Ok(core::f64::consts::PI.sqrt() / 2.0 * s / (b * a.sqrt()))
}

/// Sample modulus from the reduced modulus (2-15):
/// `E = (1 − ν²)/(1/E_r − (1 − ν_i²)/E_i)` (Pa). `E_i = +∞` is a rigid
/// indenter. Fails ([`Error::OutOfDomain`]) when E_r is not below the
/// indenter's own plane-strain modulus.
pub fn sample_modulus(
    reduced_modulus: f64,
    nu_sample: f64,
    e_indenter: f64,
    nu_indenter: f64,
) -> Result<f64> {
    let er = check::positive("reduced_modulus", reduced_modulus)?;
    let nu = check::poisson("nu_sample", nu_sample)?;
    let nui = check::poisson("nu_indenter", nu_indenter)?;
    if !(e_indenter > 0.0) {
        return Err(Error::InvalidArgument {
            name: "e_indenter",
            value: e_indenter,
            bound: "> 0 (+inf for a rigid indenter)",
        });
    }
    let ci = if e_indenter.is_infinite() {
        0.0
    } else {
        (1.0 - nui * nui) / e_indenter
    };
    let den = 1.0 / er - ci;
    if den <= 0.0 {
        return Err(Error::OutOfDomain {
            name: "reduced_modulus",
            value: er,
            reason: "not below the indenter's plane-strain modulus E_i/(1 - nu_i^2)",
        });
    }
    Ok((1.0 - nu * nu) / den)
}
