//! The dissipation mechanisms of the energy friction model (thesis chapter 4):
//! the material constants they need, chemical and van der Waals bonds of a
//! nano-asperity (4.1, 4.2), its adhesive holding force (Kendall no-slip
//! pull-off, 4.4), its Lennard-Jones stiffness (4.3.2) and the mechanical
//! energies of an elastic–perfectly plastic micro-rod (4.3.1, 4.3.3).
//!
//! Where each formula of the thesis lives (the formulas themselves are under
//! *Formulas*):
//!
//! | thesis | here |
//! |---|---|
//! | (4-6) number of chemical bonds n_chem | [`chemical_bond_count`] |
//! | (4-7) chemical bond energy of a nano-asperity | [`bond_dissipation_per_slip`], [`NanoAsperityBonds`] |
//! | (4-8) number of van der Waals bonds n_vdW | [`vdw_bond_count`] |
//! | (4-9) van der Waals bond energy of a nano-asperity | [`bond_dissipation_per_slip`], [`NanoAsperityBonds`] |
//! | (4-10) elastic shortening δ of a rod | [`ElasticPlasticRod`] |
//! | (4-11), (4-12) 12-6 Lennard-Jones potential and force | [`LjNanoAsperity::potential`], [`LjNanoAsperity::pair_force`] |
//! | (4-13) Lennard-Jones σ from the bond spacing D_chem | [`LjNanoAsperity::sigma`] |
//! | (4-14) Lennard-Jones stress Σ and modulus E | [`LjNanoAsperity::stress`], [`LjNanoAsperity::epsilon`] |
//! | (4-15) elastic strain energy ΔU_e | [`elastic_strain_energy`] |
//! | (4-16) plastic work ΔU_p | [`plastic_work`] |
//! | 4.4 holding force F_adh,1 (Kendall no-slip pull-off) | [`nano_holding_force`] |
//! | 4.4 Hamaker work of adhesion W₁₂ | [`crate::material::hamaker_work_of_adhesion`] |
//!
//! All quantities SI: m, N, Pa, J, J/m², J/m (energy per unit slip = N).
//!
//! # Formulas
//!
//! Bonds of one nano-asperity (4-6)–(4-9) and their dissipation per unit slip:
//!
//! $$n_\mathrm{chem} = \Bigl(\frac{w_\mathrm{chem}}{D_\mathrm{chem}}\Bigr)^2, \qquad n_\mathrm{vdW} = \Bigl(\frac{w_\mathrm{vdW}}{D_\mathrm{chem}}\Bigr)^2, \qquad U_\mathrm{chem,nano} = n_\mathrm{chem}U_\mathrm{chem,1}, \qquad U_\mathrm{vdW,nano} = n_\mathrm{vdW}U_\mathrm{vdW,1}, \qquad \frac{dU}{dx} = \frac{n_\mathrm{chem}U_\mathrm{chem} + n_\mathrm{vdW}U_\mathrm{vdW}}{D_\mathrm{chem}} .$$
//!
//! Lennard-Jones nano-asperity (4-11)–(4-14), $\rho = 2^{1/6}\sigma = D_\mathrm{chem}$:
//!
//! $$U(r) = 4\epsilon\Bigl(\Bigl(\frac{\sigma}{r}\Bigr)^{12} - \Bigl(\frac{\sigma}{r}\Bigr)^{6}\Bigr), \qquad F(r) = 24\epsilon\Bigl(\frac{2\sigma^{12}}{r^{13}} - \frac{\sigma^6}{r^7}\Bigr), \qquad \Sigma(\varepsilon_s) = F_\mathrm{LJ} N_A = \frac{E}{6}\bigl((1-\varepsilon_s)^{-13} - (1-\varepsilon_s)^{-7}\bigr), \qquad E = \frac{72\\,\epsilon N_A}{\rho} .$$
//!
//! Micro-rod energies (4-10), (4-15), (4-16) and the holding force (4.4):
//!
//! $$\delta = \frac{PL}{EA}, \qquad \Delta U_e = \frac{E A_c\\,\delta_e^2}{2L}, \qquad \Delta U_p = \sigma_y\\,\varepsilon_p V_d, \qquad F_\mathrm{adh,1} = \sqrt{8\pi W_{12} E^\ast C_\mathrm{NS}\\, a_1^3}, \quad a_1 = \frac{w_\mathrm{vdW}}{2}, \quad W_{12} = \frac{A}{12\pi D_0^2} .$$
//!
//! # References
//!
//! * Thesis chapter 4: (4-6)–(4-16), §4.3.1–4.3.3, §4.4; REFERENCE.md §5.
//! * K. Kendall (1971), "The adhesion and surface energy of elastic solids",
//!   J. Phys. D: Appl. Phys. 4, 1186–1195,
//!   [doi:10.1088/0022-3727/4/8/320](https://doi.org/10.1088/0022-3727/4/8/320).
//! * F. M. Borodich, B. A. Galanov, M. M. Suarez-Alvarez (2014), J. Mech. Phys.
//!   Solids 68, 14–32,
//!   [doi:10.1016/j.jmps.2014.03.003](https://doi.org/10.1016/j.jmps.2014.03.003)
//!   (no-slip factor).
//! * J. E. Lennard-Jones (1924), "On the determination of molecular fields",
//!   Proc. R. Soc. Lond. A 106, 463–477 (the 12-6 potential).
//! * J. N. Israelachvili, *Intermolecular and Surface Forces*, Academic Press,
//!   §13 (Hamaker work of adhesion).

use super::geometry::NanoAsperities;
use crate::contact::kendall::Kendall;
use crate::error::{check, Error, Result};
use crate::material::{effective_modulus, no_slip_factor};
use serde::{Deserialize, Serialize};

/// Avogadro's number N_Av (mol⁻¹, exact since the 2019 SI). The thesis uses
/// 6.0221413e23; the difference is 1e-8 relative.
const AVOGADRO: f64 = 6.022_140_76e23;

/// Default adhesive layer thickness (m): 5 nm (thesis 4.2).
const DEFAULT_ADHESIVE_LAYER: f64 = 5e-9;

/// Default threshold strain of the bilinear nano-asperity law: 10 % (thesis
/// 4.3.2, Figure 4-6).
const DEFAULT_THRESHOLD_STRAIN: f64 = 0.10;

// ---------------------------------------------------------------- material

/// The material constants of the friction model (thesis chapter 4), SI.
///
/// The slider (`youngs_modulus`, `poisson_ratio`) and the counter-surface
/// (`counter_youngs_modulus`, `counter_poisson_ratio`) are given separately;
/// the contact modulus is `1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂` ([`Self::e_star`]),
/// which for identical bodies is the thesis's `E* = E/(2(1−ν²))` (4.4). The
/// no-slip factor C_NS of the adhesive flat punch ([`Self::c_ns`]) is taken
/// with the counter-surface's ν (the nano-asperity is the punch, the
/// counter-surface the half-space; for identical bodies, as in the thesis, the
/// choice does not matter).
///
/// A plain value: fields are public, [`Self::validate`] checks them and every
/// function of the friction model that takes a material calls it.
/// Deserialisation validates; `adhesive_layer` and `threshold_strain` default
/// to 5 nm and 0.10, `areal_density` to 1/D_chem². Numbers are written as
/// exact decimal strings; plain JSON numbers are read too.
///
/// In C this is `AsperityFrictionMaterial` (same fields, same order);
/// `asperity_friction_material_copper` fills it with [`Self::copper`].
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "FrictionMaterialData")]
pub struct FrictionMaterial {
    /// Yield stress σ_y of the micro-rods (Pa), > 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub yield_stress: f64,
    /// Young's modulus E of the slider (Pa), finite and > 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub youngs_modulus: f64,
    /// Poisson's ratio ν of the slider, in [0, 0.5].
    #[serde(with = "crate::serde_exact::lenient")]
    pub poisson_ratio: f64,
    /// Young's modulus of the counter-surface (Pa), finite and > 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub counter_youngs_modulus: f64,
    /// Poisson's ratio of the counter-surface, in [0, 0.5].
    #[serde(with = "crate::serde_exact::lenient")]
    pub counter_poisson_ratio: f64,
    /// Diameter of the metallic bond D_chem (m), > 0: the bond length of the
    /// bond counts (4-6), (4-8), the slip per broken bond, the LJ equilibrium
    /// separation ρ (4.3.2) and the Hamaker cut-off D₀ of the hand calculation.
    #[serde(with = "crate::serde_exact::lenient")]
    pub bond_diameter: f64,
    /// Energy dissipated by breaking one chemical bond U_chem,1 (J), ≥ 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub chemical_bond_energy: f64,
    /// Energy dissipated by breaking one van der Waals "bond" U_vdW,1 (J), ≥ 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub vdw_bond_energy: f64,
    /// Work of adhesion W₁₂ between slider and counter-surface (J/m²), ≥ 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub work_of_adhesion: f64,
    /// Thickness of the adhesive layer (m), > 0; default 5 nm (thesis 4.2).
    #[serde(with = "crate::serde_exact::lenient")]
    pub adhesive_layer: f64,
    /// Threshold strain of the bilinear elastic–rigid nano-asperity law, in
    /// (0, 1); default 0.10 (thesis 4.3.2).
    #[serde(with = "crate::serde_exact::lenient")]
    pub threshold_strain: f64,
    /// Areal density of surface atoms N_A (m⁻²), > 0, of the Lennard-Jones
    /// stiffness (4-14). The thesis uses 1.53e19 m⁻² for copper, which is
    /// 1/D_chem² = 1.526e19 m⁻² rounded (the bond counts (4-6), (4-8) assume
    /// the same density); [`Self::new`] sets 1/D_chem².
    #[serde(with = "crate::serde_exact::lenient")]
    pub areal_density: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrictionMaterialData {
    #[serde(with = "crate::serde_exact::lenient")]
    yield_stress: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    youngs_modulus: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    poisson_ratio: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    counter_youngs_modulus: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    counter_poisson_ratio: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    bond_diameter: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    chemical_bond_energy: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    vdw_bond_energy: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    work_of_adhesion: f64,
    #[serde(default, with = "crate::serde_exact::lenient::opt")]
    adhesive_layer: Option<f64>,
    #[serde(default, with = "crate::serde_exact::lenient::opt")]
    threshold_strain: Option<f64>,
    #[serde(default, with = "crate::serde_exact::lenient::opt")]
    areal_density: Option<f64>,
}

impl TryFrom<FrictionMaterialData> for FrictionMaterial {
    type Error = Error;
    fn try_from(d: FrictionMaterialData) -> Result<Self> {
        let m = Self {
            yield_stress: d.yield_stress,
            youngs_modulus: d.youngs_modulus,
            poisson_ratio: d.poisson_ratio,
            counter_youngs_modulus: d.counter_youngs_modulus,
            counter_poisson_ratio: d.counter_poisson_ratio,
            bond_diameter: d.bond_diameter,
            chemical_bond_energy: d.chemical_bond_energy,
            vdw_bond_energy: d.vdw_bond_energy,
            work_of_adhesion: d.work_of_adhesion,
            adhesive_layer: d.adhesive_layer.unwrap_or(DEFAULT_ADHESIVE_LAYER),
            threshold_strain: d.threshold_strain.unwrap_or(DEFAULT_THRESHOLD_STRAIN),
            areal_density: d
                .areal_density
                .unwrap_or(1.0 / (d.bond_diameter * d.bond_diameter)),
        };
        m.validate()?;
        Ok(m)
    }
}

impl FrictionMaterial {
    /// A slider and counter-surface of the same material: yield stress σ_y
    /// (Pa), Young's modulus E (Pa), Poisson's ratio ν, bond diameter D_chem
    /// (m), energies of one chemical and one van der Waals bond (J), work of
    /// adhesion W₁₂ (J/m²). Adhesive layer 5 nm, threshold strain 0.10,
    /// areal density 1/D_chem². Errors as [`Self::validate`].
    pub fn new(
        yield_stress: f64,
        youngs_modulus: f64,
        poisson_ratio: f64,
        bond_diameter: f64,
        chemical_bond_energy: f64,
        vdw_bond_energy: f64,
        work_of_adhesion: f64,
    ) -> Result<Self> {
        let m = Self {
            yield_stress,
            youngs_modulus,
            poisson_ratio,
            counter_youngs_modulus: youngs_modulus,
            counter_poisson_ratio: poisson_ratio,
            bond_diameter,
            chemical_bond_energy,
            vdw_bond_energy,
            work_of_adhesion,
            adhesive_layer: DEFAULT_ADHESIVE_LAYER,
            threshold_strain: DEFAULT_THRESHOLD_STRAIN,
            areal_density: 1.0 / (bond_diameter * bond_diameter),
        };
        m.validate()?;
        Ok(m)
    }

    /// Copper on copper, the thesis's worked example (4.3.2, 4.4, 5.2;
    /// REFERENCE.md §5): σ_y = 276 MPa; E = 120 GPa, ν = 0.355 for both
    /// bodies (E* = E/(2(1−ν²)) = 68.65 GPa, C_NS = 1.017376);
    /// D_chem = 2.56 Å (twice the metallic radius 1.28 Å, Wells 1984);
    /// U_chem = 202 kJ/mol / N_Av = 3.35429e-19 J (Darwent 1970);
    /// U_vdW = U_chem/100; W₁₂ = A/(12πD₀²) with A = 2.7e-19 J, D₀ = 2.56 Å:
    /// 0.10928 J/m² (the thesis prints 0.502 J/m², a misprint: only 0.109
    /// reproduces its own F_adh and μ); adhesive layer 5 nm; threshold strain
    /// 0.10; N_A = 1.53e19 m⁻² (4.3.2).
    pub fn copper() -> Self {
        let d_chem = 2.56e-10;
        let u_chem = 202e3 / AVOGADRO;
        let hamaker = 2.7e-19;
        Self {
            yield_stress: 276e6,
            youngs_modulus: 120e9,
            poisson_ratio: 0.355,
            counter_youngs_modulus: 120e9,
            counter_poisson_ratio: 0.355,
            bond_diameter: d_chem,
            chemical_bond_energy: u_chem,
            vdw_bond_energy: u_chem / 100.0,
            // = material::hamaker_work_of_adhesion(hamaker, d_chem) (tested).
            work_of_adhesion: hamaker / (12.0 * core::f64::consts::PI * d_chem * d_chem),
            adhesive_layer: DEFAULT_ADHESIVE_LAYER,
            threshold_strain: DEFAULT_THRESHOLD_STRAIN,
            areal_density: 1.53e19,
        }
    }

    /// Checks every field; the error names the field and its bound:
    /// `yield_stress`, `youngs_modulus`, `counter_youngs_modulus`,
    /// `bond_diameter`, `adhesive_layer`, `areal_density` finite and > 0;
    /// `poisson_ratio`, `counter_poisson_ratio` in [0, 0.5];
    /// `chemical_bond_energy`, `vdw_bond_energy`, `work_of_adhesion` finite
    /// and ≥ 0; `threshold_strain` in (0, 1).
    pub fn validate(&self) -> Result<()> {
        check::positive("yield_stress", self.yield_stress)?;
        check::positive("youngs_modulus", self.youngs_modulus)?;
        check::poisson("poisson_ratio", self.poisson_ratio)?;
        check::positive("counter_youngs_modulus", self.counter_youngs_modulus)?;
        check::poisson("counter_poisson_ratio", self.counter_poisson_ratio)?;
        check::positive("bond_diameter", self.bond_diameter)?;
        check::non_negative("chemical_bond_energy", self.chemical_bond_energy)?;
        check::non_negative("vdw_bond_energy", self.vdw_bond_energy)?;
        check::non_negative("work_of_adhesion", self.work_of_adhesion)?;
        check::positive("adhesive_layer", self.adhesive_layer)?;
        check_threshold_strain(self.threshold_strain)?;
        check::positive("areal_density", self.areal_density)?;
        Ok(())
    }

    /// Contact modulus E* (Pa): `1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂` (thesis
    /// (1-15)); `E/(2(1−ν²))` for identical bodies (4.4). Errors as
    /// [`Self::validate`].
    pub fn e_star(&self) -> Result<f64> {
        self.validate()?;
        effective_modulus(
            self.youngs_modulus,
            self.poisson_ratio,
            self.counter_youngs_modulus,
            self.counter_poisson_ratio,
        )
    }

    /// No-slip factor C_NS = (1−ν) ln(3−4ν)/(1−2ν) of the counter-surface's ν
    /// (4.4; Borodich et al. 2014; [`crate::material::no_slip_factor`]):
    /// 1.017376 for copper. Errors as [`Self::validate`].
    pub fn c_ns(&self) -> Result<f64> {
        self.validate()?;
        no_slip_factor(self.counter_poisson_ratio)
    }

    /// The Lennard-Jones nano-asperity of this material (4.3.2): the slider's
    /// Young's modulus, ρ = D_chem, its areal density and threshold strain.
    pub fn lj_nano_asperity(&self) -> Result<LjNanoAsperity> {
        self.validate()?;
        LjNanoAsperity::new(
            self.youngs_modulus,
            self.bond_diameter,
            self.areal_density,
            self.threshold_strain,
        )
    }
}

fn check_threshold_strain(value: f64) -> Result<f64> {
    if value > 0.0 && value < 1.0 {
        Ok(value)
    } else {
        Err(Error::InvalidArgument {
            name: "threshold_strain",
            value,
            bound: "in (0, 1)",
        })
    }
}

/// Energy of one bond (J) from a molar energy (J/mol): `U₁ = U_mol/N_Av`
/// (thesis 4.4: 202 kJ/mol → 3.3543e-19 J for Cu–Cu). Error: `molar_energy`
/// not finite and ≥ 0.
pub fn bond_energy_from_molar(molar_energy: f64) -> Result<f64> {
    Ok(check::non_negative("molar_energy", molar_energy)? / AVOGADRO)
}

// ------------------------------------------------------------------ bonds

/// Number of chemical bonds of one nano-asperity tip, thesis (4-6):
/// `n_chem = (w_chem/D_chem)²` — one bond per D_chem × D_chem cell of the
/// square tip of width `w_chem` (m). Kept real-valued: the thesis does not
/// floor it (it prints 395.523 for (161 nm/2.56 Å)² = 395 522.9).
///
/// Errors: `w_chem` not finite and ≥ 0; `bond_diameter` not finite and > 0.
pub fn chemical_bond_count(w_chem: f64, bond_diameter: f64) -> Result<f64> {
    let w = check::non_negative("w_chem", w_chem)?;
    let d = check::positive("bond_diameter", bond_diameter)?;
    Ok((w / d) * (w / d))
}

/// Number of van der Waals "bonds" of one nano-asperity, thesis (4-8):
/// `n_vdW = (w_vdW/D_chem)²` (same atom density as the metallic bonds).
/// Real-valued (the thesis prints 2 819 906 for 430 nm, a misprint of
/// 2 821 350).
///
/// Errors: `w_vdw` not finite and ≥ 0; `bond_diameter` not finite and > 0.
pub fn vdw_bond_count(w_vdw: f64, bond_diameter: f64) -> Result<f64> {
    let w = check::non_negative("w_vdw", w_vdw)?;
    let d = check::positive("bond_diameter", bond_diameter)?;
    Ok((w / d) * (w / d))
}

/// Energy dissipated per unit slip by one nano-asperity in contact (J/m,
/// i.e. its friction force in N): all `count` bonds of energy `bond_energy`
/// (J) break once per `bond_diameter` D_chem (m) of sliding, thesis (4-7) and
/// (4-9) divided by D_chem (4.4): `n U₁ / D_chem`.
///
/// Errors: `count`, `bond_energy` not finite and ≥ 0; `bond_diameter` not
/// finite and > 0.
pub fn bond_dissipation_per_slip(count: f64, bond_energy: f64, bond_diameter: f64) -> Result<f64> {
    let n = check::non_negative("count", count)?;
    let u = check::non_negative("bond_energy", bond_energy)?;
    let d = check::positive("bond_diameter", bond_diameter)?;
    Ok(n * u / d)
}

/// Adhesive holding force of one nano-asperity (N, ≥ 0): the no-slip
/// Boussinesq–Kendall pull-off of a flat punch of radius `a₁ = w_vdW/2`,
/// `F_adh,1 = √(8π W₁₂ E* C_NS a₁³)` (thesis 4.4; [`Kendall::no_slip`]).
/// 4.366e-5 N for the copper nano-asperity of 4.4 (w_vdW = 430 nm).
///
/// The force is constant while the nano-asperity's tip is within the
/// adhesive layer (thesis 4.2). Errors as [`FrictionMaterial::validate`] and
/// [`NanoAsperities::validate`].
pub fn nano_holding_force(material: &FrictionMaterial, nano: &NanoAsperities) -> Result<f64> {
    nano.validate()?;
    let e_star = material.e_star()?;
    // The punch radius is w_vdW/2: a subnormal w_vdW underflows to 0 there,
    // and the error must name the argument the caller passed.
    let punch = Kendall::no_slip(
        0.5 * nano.w_vdw,
        e_star,
        material.work_of_adhesion,
        material.counter_poisson_ratio,
    )
    .map_err(|e| e.renamed("radius", "w_vdw"))?;
    Ok(-punch.pull_off)
}

/// Everything the sliding models need about one nano-asperity in contact,
/// computed once from a material and the nano-asperity geometry (then
/// immutable; the per-increment ledger [`super::ledger::ledger_step`] only
/// reads it).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NanoAsperityBonds {
    n_chem: f64,
    n_vdw: f64,
    chemical: f64,
    van_der_waals: f64,
    contact_radius: f64,
    holding_force: f64,
}

impl NanoAsperityBonds {
    /// Bond counts (4-6), (4-8), dissipation per unit slip (4-7), (4-9) and
    /// the adhesive holding force (4.4) of one nano-asperity. Errors as
    /// [`FrictionMaterial::validate`] and [`NanoAsperities::validate`].
    pub fn new(material: &FrictionMaterial, nano: &NanoAsperities) -> Result<Self> {
        material.validate()?;
        nano.validate()?;
        let d = material.bond_diameter;
        let n_chem = chemical_bond_count(nano.w_chem, d)?;
        let n_vdw = vdw_bond_count(nano.w_vdw, d)?;
        Ok(Self {
            n_chem,
            n_vdw,
            chemical: bond_dissipation_per_slip(n_chem, material.chemical_bond_energy, d)?,
            van_der_waals: bond_dissipation_per_slip(n_vdw, material.vdw_bond_energy, d)?,
            contact_radius: 0.5 * nano.w_vdw,
            holding_force: nano_holding_force(material, nano)?,
        })
    }

    /// Chemical bonds per nano-asperity n_chem, (4-6).
    #[inline]
    pub fn n_chem(&self) -> f64 {
        self.n_chem
    }

    /// Van der Waals bonds per nano-asperity n_vdW, (4-8).
    #[inline]
    pub fn n_vdw(&self) -> f64 {
        self.n_vdw
    }

    /// Chemical dissipation per unit slip of one nano-asperity,
    /// `n_chem U_chem/D_chem` (J/m = N), (4-7).
    #[inline]
    pub fn chemical(&self) -> f64 {
        self.chemical
    }

    /// Van der Waals dissipation per unit slip of one nano-asperity,
    /// `n_vdW U_vdW/D_chem` (J/m = N), (4-9).
    #[inline]
    pub fn van_der_waals(&self) -> f64 {
        self.van_der_waals
    }

    /// Radius of the adhesive punch a₁ = w_vdW/2 (m), 4.4.
    #[inline]
    pub fn contact_radius(&self) -> f64 {
        self.contact_radius
    }

    /// Adhesive holding force of one nano-asperity F_adh,1 (N, ≥ 0), see
    /// [`nano_holding_force`].
    #[inline]
    pub fn holding_force(&self) -> f64 {
        self.holding_force
    }
}

// ----------------------------------------------------- Lennard-Jones nano

/// The Lennard-Jones stiffness of a nano-asperity (thesis 4.3.2): two
/// half-spaces of atoms at areal density N_A interacting pairwise by the 12-6
/// potential (4-11) whose equilibrium separation ρ is the bond diameter
/// D_chem, so `σ = ρ/2^{1/6}` (4-13), and whose depth ε makes the slope of
/// the stress–strain curve at ρ equal to Young's modulus,
/// `E = 72 ε N_A/ρ`, `ε = Eρ/(72 N_A)` (4-14 and the lines after it).
///
/// With the compressive strain `ε_s = −(z − ρ)/ρ` (z the current
/// separation), the stress (4-14), compression positive, is
/// `Σ(ε_s) = N_A F_LJ(ρ(1−ε_s)) = (E/6)[(1−ε_s)^{−13} − (1−ε_s)^{−7}]`.
/// Copper (E = 120 GPa, ρ = 2.56 Å, N_A = 1.53e19 m⁻²): σ = 2.2807 Å,
/// ε = 2.78867e-20 J, tensile peak −4.4832 GPa at ε_s = −0.10868
/// (REFERENCE.md §8).
///
/// The sliding models use the bilinear elastic–perfectly rigid
/// approximation (Figure 4-6): Hooke's law `Σ = E ε_s` up to the threshold
/// strain (10 % for copper), beyond which the nano-asperity is rigid and the
/// load passes to its micro-rod; it never deforms plastically
/// (Polonsky–Keer, 4.3.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LjNanoAsperity {
    youngs_modulus: f64,
    rho: f64,
    areal_density: f64,
    threshold_strain: f64,
    sigma: f64,
    epsilon: f64,
}

impl LjNanoAsperity {
    /// From Young's modulus E (Pa), the equilibrium separation ρ = D_chem
    /// (`bond_diameter`, m), the areal atom density N_A (m⁻²) and the
    /// threshold strain of the bilinear law (in (0, 1)). Errors name the
    /// argument: `youngs_modulus`, `bond_diameter`, `areal_density` not
    /// finite and > 0; `threshold_strain` outside (0, 1).
    pub fn new(
        youngs_modulus: f64,
        bond_diameter: f64,
        areal_density: f64,
        threshold_strain: f64,
    ) -> Result<Self> {
        let e = check::positive("youngs_modulus", youngs_modulus)?;
        let rho = check::positive("bond_diameter", bond_diameter)?;
        let n_a = check::positive("areal_density", areal_density)?;
        let th = check_threshold_strain(threshold_strain)?;
        let epsilon = e * rho / (72.0 * n_a);
        if !(epsilon.is_finite() && epsilon > 0.0) {
            return Err(Error::InvalidArgument {
                name: "youngs_modulus",
                value: e,
                bound: "such that the well depth E rho/(72 N_A) is finite and > 0",
            });
        }
        Ok(Self {
            youngs_modulus: e,
            rho,
            areal_density: n_a,
            threshold_strain: th,
            sigma: rho / 2f64.powf(1.0 / 6.0),
            epsilon,
        })
    }

    /// Young's modulus E (Pa), the slope of Σ(ε_s) at ε_s = 0.
    #[inline]
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Equilibrium separation ρ = D_chem (m).
    #[inline]
    pub fn equilibrium_separation(&self) -> f64 {
        self.rho
    }

    /// Areal atom density N_A (m⁻²).
    #[inline]
    pub fn areal_density(&self) -> f64 {
        self.areal_density
    }

    /// Threshold strain of the bilinear law.
    #[inline]
    pub fn threshold_strain(&self) -> f64 {
        self.threshold_strain
    }

    /// The LJ length σ = ρ/2^{1/6} (m), (4-13): 2.2807 Å for copper.
    #[inline]
    pub fn sigma(&self) -> f64 {
        self.sigma
    }

    /// The LJ well depth ε = Eρ/(72 N_A) (J): 2.78867e-20 J for copper.
    #[inline]
    pub fn epsilon(&self) -> f64 {
        self.epsilon
    }

    /// Pair potential (4-11), `U(r) = 4ε[(σ/r)¹² − (σ/r)⁶]` (J) at
    /// separation `r` (m, finite and > 0); `−ε` at r = ρ.
    pub fn potential(&self, r: f64) -> Result<f64> {
        let r = check::positive("r", r)?;
        let s6 = (self.sigma / r).powi(6);
        finite_or_out("r", r, 4.0 * self.epsilon * s6 * (s6 - 1.0))
    }

    /// Pair force (4-12), `F(r) = 24ε[2σ¹²/r¹³ − σ⁶/r⁷]` (N, > 0
    /// repulsive) at separation `r` (m, finite and > 0); zero at r = ρ.
    pub fn pair_force(&self, r: f64) -> Result<f64> {
        let r = check::positive("r", r)?;
        let s6 = (self.sigma / r).powi(6);
        finite_or_out("r", r, 24.0 * self.epsilon * s6 * (2.0 * s6 - 1.0) / r)
    }

    /// Stress (4-14) at compressive strain ε_s (finite and < 1; negative is
    /// tension): `Σ = (E/6)[(1−ε_s)^{−13} − (1−ε_s)^{−7}]` (Pa, > 0
    /// compressive). Equal to `N_A · pair_force(ρ(1−ε_s))`.
    pub fn stress(&self, strain: f64) -> Result<f64> {
        let s = check::finite("strain", strain)?;
        if s >= 1.0 {
            return Err(Error::InvalidArgument {
                name: "strain",
                value: s,
                bound: "finite and < 1 (the atoms cannot pass through each other)",
            });
        }
        let x = 1.0 - s;
        let x7 = x.powi(-7);
        finite_or_out(
            "strain",
            s,
            self.youngs_modulus / 6.0 * x7 * (x.powi(-6) - 1.0),
        )
    }

    /// The tensile peak of Σ(ε_s): `(ε_s, Σ)` at `1 − ε_s = (13/7)^{1/6}`,
    /// i.e. ε_s = −0.10868 and Σ = −0.037360 E (−4.4832 GPa for copper).
    pub fn tensile_peak(&self) -> (f64, f64) {
        let x = (13.0f64 / 7.0).powf(1.0 / 6.0);
        let stress = self.youngs_modulus / 6.0 * (x.powi(-13) - x.powi(-7));
        (1.0 - x, stress)
    }

    /// The bilinear approximation on its elastic branch: `Σ = E ε_s` (Pa)
    /// for `0 ≤ ε_s ≤` threshold. Beyond the threshold the nano-asperity is
    /// rigid (the stress is whatever its micro-rod carries) and a strain
    /// there is rejected, as is tension (the nano-asperity's attraction is
    /// the adhesive holding force, not this law). Error: `strain` outside
    /// [0, threshold_strain].
    pub fn bilinear_stress(&self, strain: f64) -> Result<f64> {
        let s = check::in_range(
            "strain",
            strain,
            0.0,
            self.threshold_strain,
            "in [0, threshold_strain] (elastic branch of the bilinear law)",
        )?;
        Ok(self.youngs_modulus * s)
    }

    /// Largest stress of the elastic branch, `E ε_th` (Pa): 12 GPa for copper.
    #[inline]
    pub fn elastic_limit_stress(&self) -> f64 {
        self.youngs_modulus * self.threshold_strain
    }

    /// Compression at which a nano-asperity of height `height` (m, finite
    /// and ≥ 0) becomes rigid: `ε_th · height` (m).
    pub fn threshold_compression(&self, height: f64) -> Result<f64> {
        Ok(self.threshold_strain * check::non_negative("height", height)?)
    }
}

fn finite_or_out(name: &'static str, value: f64, result: f64) -> Result<f64> {
    if result.is_finite() {
        Ok(result)
    } else {
        Err(Error::OutOfDomain {
            name,
            value,
            reason: "the result overflows f64",
        })
    }
}

// ------------------------------------------------------------ micro-rods

/// Elastic strain energy of a rod (thesis (4-15)):
/// `U_e = E A_c δ²/(2L)` (J) for a rod of modulus `youngs_modulus` E (Pa),
/// cross-section `area` A_c (m²) and length `length` L (m), compressed
/// elastically by `compression` δ (m) — the work of the Hooke force
/// `P = EA_cδ/L` (4-10).
///
/// The thesis writes (4-15) with δ_e "the change in the state of
/// deformation" between two slider positions; the energy released by a rod
/// unloading from δ_A to δ_B is `U_e(δ_A) − U_e(δ_B)`
/// ([`released_elastic_energy`]), which is what the ledger uses.
///
/// Errors: `youngs_modulus`, `area`, `length` not finite and > 0;
/// `compression` not finite and ≥ 0; OutOfDomain if the energy overflows.
pub fn elastic_strain_energy(
    youngs_modulus: f64,
    area: f64,
    length: f64,
    compression: f64,
) -> Result<f64> {
    let e = check::positive("youngs_modulus", youngs_modulus)?;
    let a = check::positive("area", area)?;
    let l = check::positive("length", length)?;
    let d = check::non_negative("compression", compression)?;
    finite_or_out("compression", d, 0.5 * (e * a / l) * d * d)
}

/// Elastic strain energy released (J, ≥ 0) when a rod's elastic compression
/// goes from `before` to `after` (m, finite and ≥ 0):
/// `max(0, U_e(before) − U_e(after))` with U_e of (4-15). Energy stored on
/// loading is not dissipated, so a rod that is loaded releases nothing.
/// Errors as [`elastic_strain_energy`] (`before`, `after` named).
pub fn released_elastic_energy(
    youngs_modulus: f64,
    area: f64,
    length: f64,
    before: f64,
    after: f64,
) -> Result<f64> {
    let b = check::non_negative("before", before)?;
    let a = check::non_negative("after", after)?;
    let ub = elastic_strain_energy(youngs_modulus, area, length, b)?;
    let ua = elastic_strain_energy(youngs_modulus, area, length, a)?;
    Ok((ub - ua).max(0.0))
}

/// Plastic work of a rod (thesis (4-16)): `U_p = σ_y ε_p V_d` (J), the
/// yield stress `yield_stress` σ_y (Pa) times the plastic strain increment
/// `plastic_strain` ε_p times the deformed volume `deformed_volume` V_d
/// (m³). For a rod of section A and length L yielding by Δδ_p,
/// ε_p = Δδ_p/L and V_d = AL, so U_p = σ_y A Δδ_p.
///
/// Errors: `yield_stress` not finite and > 0; `plastic_strain`,
/// `deformed_volume` not finite and ≥ 0; OutOfDomain on overflow.
pub fn plastic_work(yield_stress: f64, plastic_strain: f64, deformed_volume: f64) -> Result<f64> {
    let s = check::positive("yield_stress", yield_stress)?;
    let e = check::non_negative("plastic_strain", plastic_strain)?;
    let v = check::non_negative("deformed_volume", deformed_volume)?;
    finite_or_out("plastic_strain", e, s * e * v)
}

/// An elastic–perfectly plastic micro-rod in compression (thesis 4.3.1,
/// Figure 4-3): Hooke's law `P = EAδ_e/L` (4-10) up to the yield force
/// `σ_y A`, then constant force; plastic compression is permanent. All SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ElasticPlasticRod {
    /// Young's modulus E (Pa), finite and > 0.
    pub youngs_modulus: f64,
    /// Yield stress σ_y (Pa), finite and > 0.
    pub yield_stress: f64,
    /// Cross-section A (m²), finite and > 0.
    pub area: f64,
    /// Length L (m), finite and > 0.
    pub length: f64,
}

/// What one rod does over one increment (see [`ElasticPlasticRod::increment`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct RodIncrement {
    /// Elastic strain energy released (J, ≥ 0), from (4-15).
    pub released_elastic: f64,
    /// Plastic work (J, ≥ 0), (4-16).
    pub plastic_work: f64,
    /// Permanent (plastic) compression after the increment (m, ≥ 0).
    pub plastic_compression: f64,
    /// Axial force after the increment (N, ≥ 0, compressive).
    pub force: f64,
}

impl ElasticPlasticRod {
    /// Checks the fields (errors name them).
    pub fn validate(&self) -> Result<()> {
        check::positive("youngs_modulus", self.youngs_modulus)?;
        check::positive("yield_stress", self.yield_stress)?;
        check::positive("area", self.area)?;
        check::positive("length", self.length)?;
        Ok(())
    }

    /// Elastic compression at first yield, `δ_y = σ_y L/E` (m).
    pub fn yield_compression(&self) -> Result<f64> {
        self.validate()?;
        Ok(self.yield_stress * self.length / self.youngs_modulus)
    }

    /// The rod goes from total compression `before` (m) with permanent part
    /// `plastic_before` (m) to total compression `after` (m). The elastic
    /// compression is `δ − δ_p` clamped to [0, δ_y] (below 0 the rod has lost
    /// contact); when it would exceed δ_y the rod yields and δ_p grows by the
    /// excess. Returns the released elastic energy (4-15), the plastic work
    /// σ_y A Δδ_p (4-16), the new δ_p and the force. Compressions finite and
    /// ≥ 0 (`before`, `plastic_before`, `after` named in errors).
    pub fn increment(&self, before: f64, plastic_before: f64, after: f64) -> Result<RodIncrement> {
        let dy = self.yield_compression()?;
        let before = check::non_negative("before", before)?;
        let dp0 = check::non_negative("plastic_before", plastic_before)?;
        let after = check::non_negative("after", after)?;
        let e0 = (before - dp0).clamp(0.0, dy);
        let dp1 = dp0.max(after - dy);
        let e1 = (after - dp1).clamp(0.0, dy);
        let released =
            released_elastic_energy(self.youngs_modulus, self.area, self.length, e0, e1)?;
        let plastic = plastic_work(
            self.yield_stress,
            (dp1 - dp0) / self.length,
            self.area * self.length,
        )?;
        Ok(RodIncrement {
            released_elastic: released,
            plastic_work: plastic,
            plastic_compression: dp1,
            force: self.youngs_modulus * self.area * e1 / self.length,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::hamaker_work_of_adhesion;

    #[test]
    fn copper_work_of_adhesion_is_the_hamaker_function() {
        let m = FrictionMaterial::copper();
        let w = hamaker_work_of_adhesion(2.7e-19, 2.56e-10).unwrap();
        assert!((m.work_of_adhesion - w).abs() <= 1e-15 * w);
        assert!(m.validate().is_ok());
    }

    #[test]
    fn stress_is_areal_density_times_pair_force() {
        let lj = FrictionMaterial::copper().lj_nano_asperity().unwrap();
        for s in [-0.5, -0.1, 0.0, 0.05, 0.1, 0.3] {
            let direct = lj.stress(s).unwrap();
            let r = lj.equilibrium_separation() * (1.0 - s);
            let pair = lj.areal_density() * lj.pair_force(r).unwrap();
            assert!((direct - pair).abs() <= 1e-9 * lj.youngs_modulus(), "{s}");
        }
        assert!(lj.pair_force(lj.equilibrium_separation()).unwrap().abs() < 1e-20);
        let u = lj.potential(lj.equilibrium_separation()).unwrap();
        assert!((u + lj.epsilon()).abs() < 1e-12 * lj.epsilon());
        // slope at zero strain is E
        let h = 1e-6;
        let slope = (lj.stress(h).unwrap() - lj.stress(-h).unwrap()) / (2.0 * h);
        assert!((slope / lj.youngs_modulus() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn rod_increment_loads_yields_and_unloads() {
        let rod = ElasticPlasticRod {
            youngs_modulus: 100e9,
            yield_stress: 100e6,
            area: 1e-10,
            length: 1e-5,
        };
        let dy = rod.yield_compression().unwrap(); // 1e-8 m
        assert!((dy - 1e-8).abs() < 1e-22);
        // loading elastically: nothing dissipated
        let r = rod.increment(0.0, 0.0, 0.5 * dy).unwrap();
        assert_eq!(r.released_elastic, 0.0);
        assert_eq!(r.plastic_work, 0.0);
        // yielding by dy: plastic work sigma_y A dy
        let r = rod.increment(dy, 0.0, 2.0 * dy).unwrap();
        assert!((r.plastic_work - 100e6 * 1e-10 * dy).abs() < 1e-12 * r.plastic_work);
        assert!((r.plastic_compression - dy).abs() < 1e-22);
        assert!((r.force - 100e6 * 1e-10).abs() < 1e-9 * r.force);
        // full unloading releases E A dy^2/(2L)
        let r = rod.increment(2.0 * dy, dy, 0.0).unwrap();
        let expect = 0.5 * 100e9 * 1e-10 * dy * dy / 1e-5;
        assert!((r.released_elastic - expect).abs() < 1e-12 * expect);
        assert_eq!(r.plastic_work, 0.0);
        assert_eq!(r.force, 0.0);
    }
}
