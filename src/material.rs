//! Materials, effective moduli and the dimensionless groups of adhesive contact.
//!
//! Conventions (see `REFERENCE.md` §1): SI units; `w` is the work of
//! adhesion (Dupré), `w = 2γ` for identical surfaces.
//!
//! # Formulas
//!
//! The *contact modulus* E* in Johnson's convention (thesis (1-15)), the
//! `K` of JKR-era papers ([`jkr_k`]) and the rod modulus of (6-4)–(6-8); the
//! no-slip factor and ε of Borodich et al. 2014; the Tabor and Maugis
//! parameters with the Lennard-Jones theoretical stress ((1-42)–(1-44));
//! the surface energy from bulk properties (Weir 2008; seed 001, Eq. 4) and
//! the Hamaker work of adhesion (Israelachvili §13):
//!
//! $$\frac{1}{E^\ast} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}, \qquad K = \tfrac43 E^\ast, \qquad \frac{1}{E_\mathrm{rod}} = \frac{1}{E_1} + \frac{1}{E_2},$$
//!
//! $$C_\mathrm{NS} = \frac{(1-\nu)\ln(3-4\nu)}{1-2\nu}, \qquad \varepsilon = \frac{\ln(3-4\nu)}{2\pi},$$
//!
//! $$\mu = \left(\frac{R w^2}{E^{\ast 2} z_0^3}\right)^{1/3}, \qquad \lambda = 2\sigma_0\left(\frac{R}{\pi w K^2}\right)^{1/3}, \qquad \sigma_\mathrm{th} = \frac{16w}{9\sqrt3\\, z_0}, \qquad \frac{\lambda}{\mu} = \frac{32}{9\sqrt3}\left(\frac{9}{16\pi}\right)^{1/3} \approx 1.157,$$
//!
//! $$\gamma = K(m,n)\\, a\\, B, \quad a = (M/\rho)^{1/3}, \quad B = \frac{E}{3(1-2\nu)}, \quad K(m,n) = \frac{1}{(m-2)(n-2)} \ \text{or}\ \frac{3}{mn}, \qquad W_{12} = \frac{A}{12\pi D_0^2} .$$
//!
//! # References
//!
//! * Thesis (1-15), (1-42)–(1-44), §4.4, (6-4)–(6-8); REFERENCE.md §1, §6.
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   §4.2, [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731).
//! * D. Tabor (1977), "Surface forces and surface interactions", J. Colloid
//!   Interface Sci. 58, 2–13.
//! * D. Maugis (1992), "Adhesion of spheres: the JKR-DMT transition using a
//!   Dugdale model", J. Colloid Interface Sci. 150, 243–269,
//!   [doi:10.1016/0021-9797(92)90285-T](https://doi.org/10.1016/0021-9797(92)90285-T).
//! * J. A. Greenwood (1997), "Adhesion of elastic spheres", Proc. R. Soc. Lond.
//!   A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070).
//! * F. M. Borodich, B. A. Galanov, M. M. Suarez-Alvarez (2014), "The JKR-type
//!   adhesive contact problems for power-law shaped axisymmetric punches",
//!   J. Mech. Phys. Solids 68, 14–32,
//!   [doi:10.1016/j.jmps.2014.03.003](https://doi.org/10.1016/j.jmps.2014.03.003)
//!   (no-slip factor and ε).
//! * G. Weir (2008), Proc. R. Soc. A 464 (surface energy from bulk moduli);
//!   W. G. Lee, W. W. F. Chong (2015), Jurnal Teknologi 76(10) (seed 001), Eq. 4.
//! * J. N. Israelachvili, *Intermolecular and Surface Forces*, Academic Press,
//!   §13 (the Hamaker work of adhesion).

use crate::error::{check, Error, Result};

/// Contact modulus `E*` of two isotropic elastic bodies (Pa):
/// `1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂` (thesis (1-15); Johnson 1985, §4.2).
///
/// Either body may be rigid: pass `E = f64::INFINITY` and its term vanishes.
/// Both rigid is rejected (no finite contact modulus).
///
/// * `e1`, `e2`: Young's moduli (Pa), `> 0`, `+∞` allowed.
/// * `nu1`, `nu2`: Poisson's ratios, `0 ≤ ν ≤ 0.5`.
///
/// Errors with [`Error::OutOfDomain`] naming the larger modulus when `E*`
/// overflows `f64` (moduli near `f64::MAX`).
pub fn effective_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> Result<f64> {
    let c1 = compliance(check_modulus("e1", e1)?, check::poisson("nu1", nu1)?);
    let c2 = compliance(check_modulus("e2", e2)?, check::poisson("nu2", nu2)?);
    let c = c1 + c2;
    if c > 0.0 {
        let name = if e1.is_finite() && (e1 >= e2 || e2.is_infinite()) {
            ("e1", e1)
        } else {
            ("e2", e2)
        };
        check::finite_of(1.0 / c, &[name], "the contact modulus overflows f64")
    } else {
        Err(Error::InvalidArgument {
            name: "e2",
            value: e2,
            bound: "finite when e1 is infinite (two rigid bodies have no contact modulus)",
        })
    }
}

/// `(1−ν²)/E`, zero for a rigid body.
#[inline]
fn compliance(e: f64, nu: f64) -> f64 {
    if e.is_infinite() {
        0.0
    } else {
        (1.0 - nu * nu) / e
    }
}

fn check_modulus(name: &'static str, e: f64) -> Result<f64> {
    if e > 0.0 && !e.is_nan() {
        Ok(e)
    } else {
        Err(Error::InvalidArgument {
            name,
            value: e,
            bound: "> 0 (+inf for a rigid body)",
        })
    }
}

/// Effective modulus of two elastic rods of equal length and section pressed end
/// to end (thesis (6-4)..(6-8)): `1/E_eff = 1/E₁ + 1/E₂` (Pa). Used for the
/// micro- and nano-asperity rods of the hierarchical slider. A rigid rod
/// (`+∞`) contributes nothing. Errors with [`Error::OutOfDomain`] when the
/// result overflows `f64` (moduli near `f64::MAX`).
pub fn rod_effective_modulus(e1: f64, e2: f64) -> Result<f64> {
    let e1 = check_modulus("e1", e1)?;
    let e2 = check_modulus("e2", e2)?;
    let c = 1.0 / e1 + 1.0 / e2;
    if c > 0.0 {
        let name = if e1.is_finite() && (e1 >= e2 || e2.is_infinite()) {
            ("e1", e1)
        } else {
            ("e2", e2)
        };
        check::finite_of(1.0 / c, &[name], "the effective modulus overflows f64")
    } else {
        Err(Error::InvalidArgument {
            name: "e2",
            value: e2,
            bound: "finite when e1 is infinite (two rigid rods have no effective modulus)",
        })
    }
}

/// The JKR modulus `K = 4E*/3` (Pa) used by Johnson–Kendall–Roberts and Maugis.
#[inline]
pub fn jkr_k(e_star: f64) -> f64 {
    4.0 * e_star / 3.0
}

/// Below this |1/2 − ν| the no-slip factor uses its Taylor series.
pub const NO_SLIP_SERIES_SWITCH: f64 = 1e-4;

/// No-slip factor of a rigid punch bonded to an elastic half-space
/// (thesis §4.4; Borodich, Galanov, Keer & Suarez-Alvarez 2014):
///
/// `C_NS = (1−ν) ln(3−4ν) / (1−2ν)`.
///
/// The formula is 0/0 at ν = 1/2 (incompressible: no-slip and frictionless
/// coincide, `C_NS = 1`). With `ε = 1/2 − ν` it reads
/// `C_NS = (1 + 2ε) · ln(1+4ε)/(4ε)`, evaluated with `ln_1p`; for
/// `ε <` [`NO_SLIP_SERIES_SWITCH`] its Taylor series
/// `1 + (4/3)ε² − (16/3)ε³ + (96/5)ε⁴` is used instead (truncation below 1e-19
/// there), which keeps `C_NS ≥ 1` and monotone to the last bit.
/// `C_NS(0) = ln 3 = 1.0986123`, `C_NS(0.355) = 1.017376`.
pub fn no_slip_factor(nu: f64) -> Result<f64> {
    let nu = check::poisson("nu", nu)?;
    let eps = 0.5 - nu; // exact for nu in [0.25, 0.5] (Sterbenz)
    if eps < NO_SLIP_SERIES_SWITCH {
        return Ok(1.0 + eps * eps * (4.0 / 3.0 + eps * (-16.0 / 3.0 + eps * 96.0 / 5.0)));
    }
    let x = 4.0 * eps;
    Ok((1.0 + 2.0 * eps) * x.ln_1p() / x)
}

/// The oscillation index of the bonded (no-slip) punch problem,
/// `ε = ln(3−4ν)/(2π)` (Borodich, Galanov & Suarez-Alvarez 2014; REFERENCE.md §7).
/// Zero at ν = 1/2.
pub fn no_slip_epsilon(nu: f64) -> Result<f64> {
    let nu = check::poisson("nu", nu)?;
    Ok((4.0 * (0.5 - nu)).ln_1p() / (2.0 * core::f64::consts::PI))
}

/// Tabor parameter (thesis (1-42); Tabor 1977):
/// `μ = (R w² / (E*² z₀³))^{1/3}` (dimensionless).
///
/// * `radius` R (m), `work_of_adhesion` w (J/m²), `e_star` E* (Pa),
///   `equilibrium_separation` z₀ (m).
///
/// Small μ: stiff, small, weakly adhering spheres (DMT); large μ: compliant,
/// large, strongly adhering spheres (JKR).
///
/// Errors with [`Error::OutOfDomain`] naming the most extreme argument when
/// μ is not finite (arguments near the ends of `f64`).
pub fn tabor_parameter(
    radius: f64,
    work_of_adhesion: f64,
    e_star: f64,
    equilibrium_separation: f64,
) -> Result<f64> {
    let r = check::positive("radius", radius)?;
    let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
    let e = check::positive("e_star", e_star)?;
    let z0 = check::positive("equilibrium_separation", equilibrium_separation)?;
    check::finite_of(
        (r * w * w / (e * e * z0 * z0 * z0)).cbrt(),
        &[
            ("radius", r),
            ("work_of_adhesion", w),
            ("e_star", e),
            ("equilibrium_separation", z0),
        ],
        "the Tabor parameter is not finite (arguments at the ends of f64)",
    )
}

/// Maugis parameter (Maugis 1992): `λ = 2σ₀ (R / (π w K²))^{1/3}` with
/// `K = 4E*/3` and σ₀ the Dugdale cohesive stress (Pa), acting up to the
/// separation `h₀ = w/σ₀`.
///
/// Errors with [`Error::OutOfDomain`] naming the most extreme argument when
/// λ is not finite (arguments near the ends of `f64`).
pub fn maugis_parameter(
    radius: f64,
    work_of_adhesion: f64,
    e_star: f64,
    cohesive_stress: f64,
) -> Result<f64> {
    let r = check::positive("radius", radius)?;
    let w = check::positive("work_of_adhesion", work_of_adhesion)?;
    let e = check::positive("e_star", e_star)?;
    let s0 = check::positive("cohesive_stress", cohesive_stress)?;
    let k = jkr_k(e);
    check::finite_of(
        2.0 * s0 * (r / (core::f64::consts::PI * w * k * k)).cbrt(),
        &[
            ("radius", r),
            ("work_of_adhesion", w),
            ("e_star", e),
            ("cohesive_stress", s0),
        ],
        "the Maugis parameter is not finite (arguments at the ends of f64)",
    )
}

/// Peak tension of the Lennard-Jones 3-9 surface law
/// `p(h) = (8w/(3z₀))[(z₀/h)³ − (z₀/h)⁹]`, reached at `h = 3^{1/6} z₀`:
/// `σ_th = 16 w / (9√3 z₀) ≈ 1.0264 w/z₀` (thesis (1-44); Greenwood 1997). Pa.
pub fn lennard_jones_theoretical_stress(
    work_of_adhesion: f64,
    equilibrium_separation: f64,
) -> Result<f64> {
    let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
    let z0 = check::positive("equilibrium_separation", equilibrium_separation)?;
    Ok(16.0 * w / (9.0 * 3f64.sqrt() * z0))
}

/// `λ/μ` when the Dugdale stress is the Lennard-Jones theoretical stress
/// ([`lennard_jones_theoretical_stress`]): `(32/(9√3))·(9/(16π))^{1/3} = 1.157012…`.
pub fn maugis_over_tabor() -> f64 {
    32.0 / (9.0 * 3f64.sqrt()) * (9.0 / (16.0 * core::f64::consts::PI)).cbrt()
}

/// An isotropic linear-elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus E (Pa); `+∞` for a rigid body.
    pub youngs_modulus: f64,
    /// Poisson's ratio ν, 0 ≤ ν ≤ 0.5.
    pub poisson_ratio: f64,
}

impl Material {
    /// A validated material.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        Ok(Self {
            youngs_modulus: check_modulus("youngs_modulus", youngs_modulus)?,
            poisson_ratio: check::poisson("poisson_ratio", poisson_ratio)?,
        })
    }

    /// Contact modulus of this material against `other` ([`effective_modulus`]).
    pub fn contact_modulus(&self, other: &Material) -> Result<f64> {
        effective_modulus(
            self.youngs_modulus,
            self.poisson_ratio,
            other.youngs_modulus,
            other.poisson_ratio,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_slip_series_is_continuous_at_switch() {
        let nu = 0.5 - NO_SLIP_SERIES_SWITCH;
        let below = no_slip_factor(nu + 1e-12).unwrap();
        let above = no_slip_factor(nu - 1e-12).unwrap();
        assert!((below - above).abs() < 1e-14, "{below} {above}");
    }
}

// ------------------------------------------------------------------------
// Surface energy from bulk properties (seed 001, Eq. 4; Weir 2008) and the
// work of adhesion of a pair.

/// The prefactor `K(m, n)` of Weir's surface energy `γ = K · a · B`.
///
/// Seed 001's Eq. 4 lost its symbols in extraction; REFERENCE.md §6 restores
/// two readings. [`WeirPrefactor::PlaneSum`] follows from summing the m–n pair
/// potential over atomic planes and is the default; only
/// [`WeirPrefactor::ThreeOverMn`] reproduces the paper's printed pull-off
/// (8.6 nN for the WC tip on diamond (111), −1 % with the full LJ solution).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum WeirPrefactor {
    /// `K = 1/((m−2)(n−2))` (= 1/40 for the 6–12 potential). Default.
    #[default]
    PlaneSum,
    /// `K = 3/(mn)` (= 1/24 for the 6–12 potential): the reading that
    /// reproduces seed 001's 8.6 nN.
    ThreeOverMn,
}

/// Weir's surface energy (J/m²) from bulk properties (G. Weir, Proc. R. Soc. A
/// 464 (2008) 1295, doi:10.1098/rspa.2007.0360; seed 001 Eq. 4):
///
/// `γ = K(m, n) · a · B`, with the atomic spacing `a = (M/ρ)^{1/3}` and the bulk
/// modulus `B = E/(3(1−2ν))`.
///
/// * `atomic_mass` M: mass per atom (kg), `density` ρ (kg/m³),
///   `youngs_modulus` E (Pa), `poisson_ratio` ν in [0, 0.5) (B is infinite at
///   ν = 0.5), `m`, `n`: exponents of the Lennard-Jones m–n potential,
///   `2 < m < n` (6 and 12 in seed 001).
///
/// Diamond (111) (M = 1.99e-26 kg, ρ = 3500 kg/m³, E = 1164 GPa, ν = 0.079)
/// gives 2.05615 J/m² with the default prefactor.
///
/// Errors with [`Error::OutOfDomain`] naming the most extreme of
/// `atomic_mass`, `density`, `youngs_modulus` when γ overflows `f64`.
pub fn weir_surface_energy(
    atomic_mass: f64,
    density: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    m: f64,
    n: f64,
    prefactor: WeirPrefactor,
) -> Result<f64> {
    let mass = check::positive("atomic_mass", atomic_mass)?;
    let rho = check::positive("density", density)?;
    let e = check::positive("youngs_modulus", youngs_modulus)?;
    let nu = check::in_range("poisson_ratio", poisson_ratio, 0.0, 0.5, "in [0, 0.5)")?;
    if nu == 0.5 {
        return Err(Error::InvalidArgument {
            name: "poisson_ratio",
            value: nu,
            bound: "in [0, 0.5) (the bulk modulus is infinite at 0.5)",
        });
    }
    let m = check::in_range("m", m, 2.0, f64::MAX, "finite and > 2")?;
    if m == 2.0 {
        return Err(Error::InvalidArgument {
            name: "m",
            value: m,
            bound: "finite and > 2",
        });
    }
    if !(n.is_finite() && n > m) {
        return Err(Error::InvalidArgument {
            name: "n",
            value: n,
            bound: "finite and > m",
        });
    }
    let a = (mass / rho).cbrt();
    let b = e / (3.0 * (1.0 - 2.0 * nu));
    let k = match prefactor {
        WeirPrefactor::PlaneSum => 1.0 / ((m - 2.0) * (n - 2.0)),
        WeirPrefactor::ThreeOverMn => 3.0 / (m * n),
    };
    check::finite_of(
        k * a * b,
        &[
            ("atomic_mass", mass),
            ("density", rho),
            ("youngs_modulus", e),
        ],
        "the surface energy overflows f64",
    )
}

/// How the work of adhesion of two different solids is formed from their
/// surface energies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PairRule {
    /// Dupré with the Girifalco–Good (geometric-mean) interfacial energy:
    /// `w = γ₁ + γ₂ − γ₁₂ = 2√(γ₁γ₂)`. The physical default.
    #[default]
    GeometricMean,
    /// Seed 001's `Δγ = γ₁ + γ₂ − 2√(γ₁γ₂) = (√γ₁ − √γ₂)²` — the Girifalco–Good
    /// *interfacial* energy, which the paper uses as its work of adhesion; with
    /// it the paper's pull-off forces (nanonewtons) follow, while the Dupré
    /// value would give micronewtons (REFERENCE.md §6).
    Seed001Difference,
}

/// Work of adhesion (J/m²) of a pair with surface energies `gamma1`, `gamma2`
/// (J/m², ≥ 0) under `rule`. Identical surfaces give `2γ` under
/// [`PairRule::GeometricMean`] (and 0 under the seed's difference rule).
/// Errors with [`Error::OutOfDomain`] naming the larger surface energy when
/// the result overflows `f64`.
pub fn pair_work_of_adhesion(gamma1: f64, gamma2: f64, rule: PairRule) -> Result<f64> {
    let g1 = check::non_negative("gamma1", gamma1)?;
    let g2 = check::non_negative("gamma2", gamma2)?;
    let larger = if g1 >= g2 {
        ("gamma1", g1)
    } else {
        ("gamma2", g2)
    };
    let w = match rule {
        PairRule::GeometricMean => 2.0 * (g1 * g2).sqrt(),
        PairRule::Seed001Difference => {
            let d = g1.sqrt() - g2.sqrt();
            d * d
        }
    };
    check::finite_of(w, &[larger], "the work of adhesion overflows f64")
}

/// Work of adhesion (J/m²) of two flats across a gap `separation` D₀ (m) from the
/// Hamaker constant `hamaker` A (J): `W₁₂ = A/(12πD₀²)` (Israelachvili,
/// *Intermolecular and Surface Forces*, §13; thesis §4.4). A = 2.7e-19 J at
/// D₀ = 2.56 Å gives 0.10928 J/m².
///
/// Errors with [`Error::OutOfDomain`] naming `separation` (or `hamaker`,
/// whichever is more extreme) when the result overflows `f64` (e.g.
/// `separation` = 1e-200 m, where D₀² underflows to 0).
pub fn hamaker_work_of_adhesion(hamaker: f64, separation: f64) -> Result<f64> {
    let a = check::positive("hamaker", hamaker)?;
    let d0 = check::positive("separation", separation)?;
    check::finite_of(
        a / (12.0 * core::f64::consts::PI * d0 * d0),
        &[("separation", d0), ("hamaker", a)],
        "the work of adhesion A/(12 pi separation^2) overflows f64",
    )
}
