//! C ABI for `crate::hierarchical`: Archard's spheres on spheres (load–area
//! law and its exponent) and the contact of Cantor–Liu and Cantor–Borodich
//! profiles (thesis 5.4.1, 5.4.2), and Schmittbuhl's renormalised friction
//! law (5.4.3, a run into caller-owned generations).

use super::surface::array;
use super::{guard, input, output, Failure};
use crate::error::Error;
use crate::hierarchical::{
    archard_exponent, Archard, ArchardModel, CantorContact, CantorProfile, Generation, Schmittbuhl,
};

/// Archard's hierarchy with Hertzian spheres of equal height at every
/// generation (A ~ W^(2/3, 8/9, 26/27, ...)).
pub const ASPERITY_ARCHARD_UNIFORM: i32 = 0;
/// Archard's hierarchy whose finest protuberances stand at heights
/// following the surface under them (A ~ W^(4/5, 14/15, 44/45, ...)).
pub const ASPERITY_ARCHARD_NON_UNIFORM: i32 = 1;

/// Write to `*out` the exponent a of Archard's A ~ W^a for `model`
/// (`ASPERITY_ARCHARD_UNIFORM` or `_NON_UNIFORM`) with `generations` sphere
/// radii (1..64, 2..64 non-uniform): 1 - 3^-n or 1 - 1/(5 3^(n-2)).
#[no_mangle]
pub unsafe extern "C" fn asperity_archard_exponent(
    model: i32,
    generations: usize,
    out: *mut f64,
) -> i32 {
    guard(|| {
        let m = ArchardModel::from_i32(model)?;
        let out = output(out, "out")?;
        *out = archard_exponent(m, generations)?;
        Ok(())
    })
}

/// Archard's real contact area `area[i]` (m^2) under `load[i]` (N, >= 0)
/// for `n` loads: `model` as `asperity_archard_exponent`, `generations`
/// sphere radii `radii` (m, decreasing), `generations - 1` densities
/// `densities` (spheres of generation k per unit area of generation k-1,
/// 1/m^2), contact modulus `contact_modulus` (Pa). `load` and `area` may be
/// the same memory; on an error at element i the elements before i are
/// written and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_archard_area_batch(
    model: i32,
    radii: *const f64,
    densities: *const f64,
    generations: usize,
    contact_modulus: f64,
    n: usize,
    load: *const f64,
    area: *mut f64,
) -> i32 {
    guard(|| {
        let m = ArchardModel::from_i32(model)?;
        let r = array(radii, generations, "radii")?;
        let d = array(densities, generations.saturating_sub(1), "densities")?;
        let a = Archard::new(m, r, d, contact_modulus)?;
        if n == 0 {
            return Ok(());
        }
        input(load, "load")?;
        output(area, "area")?;
        for i in 0..n {
            let w = *load.add(i);
            let v = a.area(w).map_err(|e| Failure::at(i, e))?;
            *area.add(i) = v;
        }
        Ok(())
    })
}

/// The contact of the Cantor profile `*profile` at `n` depths `depth[i]`
/// (m below its highest tips, >= 0) on a Winkler foundation of stiffness
/// `stiffness` (Pa/m, >= 0) and a rigid-plastic one of hardness `hardness`
/// (Pa, >= 0), written to `out[i]` (per unit length out of the plane). On
/// an error at element i the elements before i are written and the message
/// names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_cantor_contact_batch(
    profile: *const CantorProfile,
    stiffness: f64,
    hardness: f64,
    n: usize,
    depth: *const f64,
    out: *mut CantorContact,
) -> i32 {
    guard(|| {
        let p = *input(profile, "profile")?;
        p.check()?;
        if n == 0 {
            return Ok(());
        }
        input(depth, "depth")?;
        output(out, "out")?;
        for i in 0..n {
            let d = *depth.add(i);
            let c = p
                .contact(d, stiffness, hardness)
                .map_err(|e| Failure::at(i, e))?;
            *out.add(i) = c;
        }
        Ok(())
    })
}

/// The exponents of the Cantor profile `*profile`: its tips' fractal
/// dimension D = ln p/ln(1/r), beta = ln(pr)/ln q of width ~ depth^beta
/// (+infinity for Cantor-Liu, q = 1) and beta/(1 + beta) of
/// width ~ load^(beta/(1+beta)) on a Winkler foundation (1 for Cantor-Liu).
/// Any output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn asperity_cantor_exponents(
    profile: *const CantorProfile,
    fractal_dimension: *mut f64,
    width_exponent: *mut f64,
    load_area_exponent: *mut f64,
) -> i32 {
    guard(|| {
        let p = *input(profile, "profile")?;
        p.check()?;
        if !fractal_dimension.is_null() {
            *fractal_dimension = p.fractal_dimension();
        }
        if !width_exponent.is_null() {
            *width_exponent = p.width_exponent();
        }
        if !load_area_exponent.is_null() {
            *load_area_exponent = p.load_area_exponent();
        }
        Ok(())
    })
}

/// Schmittbuhl's hierarchical model (Schmittbuhl, Vilotte and Roux 1996;
/// thesis 5.4.3), by value: the friction law of a slider renormalised
/// generation by generation, each step a Burridge–Knopoff chain of `ratio`
/// blocks. `asperity_schmittbuhl_default` gives the library's defaults.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySchmittbuhl {
    /// Static coefficient μ_s⁰ of a generation-0 block (dimensionless,
    /// finite, ≥ 0).
    pub mu_static: f64,
    /// Kinetic coefficient μ_k⁰ at the onset of slip (dimensionless, in
    /// [0, μ_s⁰]).
    pub mu_kinetic: f64,
    /// Weakening velocity v_c of μ_k/(1 + v/v_c) (m/s, > 0; +infinity:
    /// constant kinetic friction).
    pub weakening_velocity: f64,
    /// Mass m₀ of a generation-0 block (kg, > 0).
    pub mass: f64,
    /// Horizontal (coupling) spring k_c,0 between generation-0 blocks (N/m,
    /// finite, ≥ 0).
    pub coupling_stiffness: f64,
    /// Vertical spring k_p,0 from a generation-0 block to its parent
    /// (N/m, > 0).
    pub pulling_stiffness: f64,
    /// Normal force n₀ on a generation-0 block (N, > 0).
    pub normal_force: f64,
    /// Plate velocity V (m/s, > 0).
    pub velocity: f64,
    /// Pre-stress disorder δ of a chain (dimensionless, in [0, 1)).
    pub disorder: f64,
    /// Ratio N of sizes between generations (blocks per chain), in [2, 64].
    pub ratio: u32,
    /// Generations G renormalised above generation 0, in [1, 12].
    pub generations: u32,
    /// Dimension d of the elastic continuum the rescaling follows, 2 or 3.
    pub dimension: u32,
    /// Reserved, 0.
    pub reserved: u32,
}

/// The friction law of one generation of Schmittbuhl's model and its blocks.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySchmittbuhlGeneration {
    /// Block size relative to generation 0, Nᵍ (dimensionless).
    pub size: f64,
    /// Block mass m_g (kg).
    pub mass: f64,
    /// Horizontal spring k_c,g (N/m).
    pub coupling_stiffness: f64,
    /// Vertical spring k_p,g (N/m).
    pub pulling_stiffness: f64,
    /// Normal force n_g on a block (N).
    pub normal_force: f64,
    /// Static coefficient μ_s^g (dimensionless).
    pub mu_static: f64,
    /// Kinetic coefficient μ_k^g at the onset of slip (dimensionless).
    pub mu_kinetic: f64,
    /// Weakening velocity v_c (m/s), the same at every generation.
    pub weakening_velocity: f64,
    /// μ_k^g / μ_s^g (dimensionless; 1 when μ_s^g = 0).
    pub kinetic_to_static: f64,
    /// The generation g (0: the imposed law).
    pub index: u32,
    /// Slip events of the chain run that gave this law (0 at g = 0).
    pub events: u32,
}

impl From<Schmittbuhl> for AsperitySchmittbuhl {
    fn from(s: Schmittbuhl) -> Self {
        Self {
            mu_static: s.mu_static,
            mu_kinetic: s.mu_kinetic,
            weakening_velocity: s.weakening_velocity,
            mass: s.mass,
            coupling_stiffness: s.coupling_stiffness,
            pulling_stiffness: s.pulling_stiffness,
            normal_force: s.normal_force,
            velocity: s.velocity,
            disorder: s.disorder,
            ratio: s.ratio as u32,
            generations: s.generations as u32,
            dimension: s.dimension,
            reserved: 0,
        }
    }
}

impl AsperitySchmittbuhl {
    /// The Rust model (checked by [`Schmittbuhl::run`]).
    pub fn to_model(&self) -> Schmittbuhl {
        Schmittbuhl {
            mu_static: self.mu_static,
            mu_kinetic: self.mu_kinetic,
            weakening_velocity: self.weakening_velocity,
            ratio: self.ratio as usize,
            generations: self.generations as usize,
            dimension: self.dimension,
            mass: self.mass,
            coupling_stiffness: self.coupling_stiffness,
            pulling_stiffness: self.pulling_stiffness,
            normal_force: self.normal_force,
            velocity: self.velocity,
            disorder: self.disorder,
        }
    }
}

impl From<Generation> for AsperitySchmittbuhlGeneration {
    fn from(g: Generation) -> Self {
        Self {
            size: g.size,
            mass: g.mass,
            coupling_stiffness: g.coupling_stiffness,
            pulling_stiffness: g.pulling_stiffness,
            normal_force: g.normal_force,
            mu_static: g.mu_static,
            mu_kinetic: g.mu_kinetic,
            weakening_velocity: g.weakening_velocity,
            kinetic_to_static: g.ratio,
            index: g.index as u32,
            events: g.events as u32,
        }
    }
}

/// The library's default Schmittbuhl model to `*out`: μ_s = 0.5, μ_k = 0.3,
/// v_c = 0.05 m/s, N = 3, G = 3, d = 3, blocks of 10 mg on 1000 N/m
/// springs (coupling and pulling), n₀ = 1 N, V = 1e-4 m/s, δ = 0.5.
#[no_mangle]
pub unsafe extern "C" fn asperity_schmittbuhl_default(out: *mut AsperitySchmittbuhl) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = Schmittbuhl::default().into();
        Ok(())
    })
}

/// The renormalised friction laws of generations 0 (the imposed one) to G
/// of `*model`: G + 1 entries written to `out`, which has room for
/// `capacity` (checked before the chains run: a smaller capacity is an
/// error naming it); the number written goes to `*written` unless it is
/// NULL. Errors: a field out of range (named), a chain integration that
/// fails (`ASPERITY_ERR_NOT_CONVERGED`).
#[no_mangle]
pub unsafe extern "C" fn asperity_schmittbuhl_run(
    model: *const AsperitySchmittbuhl,
    capacity: usize,
    out: *mut AsperitySchmittbuhlGeneration,
    written: *mut usize,
) -> i32 {
    guard(|| {
        let m = input(model, "model")?.to_model();
        m.validate()?;
        if capacity < m.generations + 1 {
            return Err(Error::InvalidArgument {
                name: "capacity",
                value: capacity as f64,
                bound: ">= generations + 1",
            }
            .into());
        }
        output(out, "out")?;
        let laws = m.run()?;
        for (i, g) in laws.iter().enumerate() {
            *out.add(i) = (*g).into();
        }
        if !written.is_null() {
            *written = laws.len();
        }
        Ok(())
    })
}
