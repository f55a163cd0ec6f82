//! C ABI for `crate::statistics`: Greenwood–Williamson (a plain parameter
//! struct for Gaussian and exponential summit heights, an opaque handle for a
//! measured list of summits), the plasticity index, and Zhuravlev's model
//! (linear densities in closed form, any density by quadrature through a C
//! callback), the Borodich–Kryukova block on a belt (a run into caller-owned
//! samples), the Bush–Gibson–Thomas surface (spectral moments, by value),
//! the Bora et al. interface on a measured map (opaque handle), and the
//! Sergienko–Bukharov body on Kragelsky's springs (one run per call).
//!
//! Separations d (m) are heights of the flat's reference plane above the mean
//! summit height (parametric heights) or in the frame of the listed heights
//! (empirical); approaches x (m) are measured from the first touch.

use super::surface::array;
use super::{guard, input, output, Failure};
use crate::error::{check, Error, Result};
use crate::statistics::{
    plasticity_index, BoraTopography, BorodichKryukova, BushGibsonThomas, DeformationRegime,
    EmpiricalHeights, Excitation, GreenwoodWilliamson, HeightDistribution, Integration,
    KragelskyRods, MultiAsperityResponse, SeparationSolution, SergienkoBukharov,
    SergienkoBukharovRun, Sinusoid, SliderState, Zhuravlev, ZhuravlevFriction,
};
use std::cell::Cell;
use std::ffi::c_void;

mod bora;
mod borodich_kryukova;
mod bush_gibson_thomas;
mod sergienko_bukharov;

pub use bora::*;
pub use borodich_kryukova::*;
pub use bush_gibson_thomas::*;
pub use sergienko_bukharov::*;

/// Summit heights: Gaussian of zero mean and standard deviation σ.
pub const ASPERITY_HEIGHTS_GAUSSIAN: i32 = 1;
/// Summit heights: exponential tail shifted to zero mean, standard deviation
/// (decay length) σ.
pub const ASPERITY_HEIGHTS_EXPONENTIAL: i32 = 2;

/// Deformation regime of a plasticity index ψ < 0.6: elastic.
pub const ASPERITY_REGIME_ELASTIC: i32 = 0;
/// Deformation regime 0.6 ≤ ψ ≤ 1: transitional.
pub const ASPERITY_REGIME_TRANSITIONAL: i32 = 1;
/// Deformation regime ψ > 1: plastic even at light loads.
pub const ASPERITY_REGIME_PLASTIC: i32 = 2;

/// A Greenwood–Williamson rough surface with parametric summit heights
/// (thesis (1-29), (1-30)), by value: N summits of radius R, heights of
/// standard deviation σ, against a flat with contact modulus E*. Two rough
/// surfaces reduce to one with 1/R = 1/R₁ + 1/R₂, σ² = σ₁² + σ₂².
/// An all-zero value is invalid (unknown distribution).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityGwParams {
    /// `ASPERITY_HEIGHTS_GAUSSIAN` or `ASPERITY_HEIGHTS_EXPONENTIAL`.
    pub distribution: i32,
    /// Reserved, 0.
    pub reserved: i32,
    /// Number of summits N on the nominal area (summit density η times the
    /// nominal area A_n; dimensionless, > 0).
    pub summit_count: f64,
    /// Summit radius R (m, > 0).
    pub radius: f64,
    /// Standard deviation σ of the summit heights (m, > 0).
    pub sigma: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
}

/// A Greenwood–Williamson surface over a measured or generated list of
/// summits (opaque). Create it with `asperity_gw_empirical_new`, release it
/// with `asperity_gw_empirical_free`. Immutable: safe to share between
/// threads.
pub struct AsperityGwEmpirical(GreenwoodWilliamson);

/// Response of a Greenwood–Williamson surface at one separation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityGwResponse {
    /// Total normal load P (N), ≥ 0, (1-29).
    pub load: f64,
    /// Real contact area A (m²), ≥ 0, (1-30).
    pub area: f64,
    /// Expected number of summits in contact (dimensionless).
    pub contacts: f64,
    /// Normal stiffness −dP/dd (N/m), ≥ 0.
    pub stiffness: f64,
}

/// The separation that carries a given load, with the solver's report.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySeparation {
    /// Separation d (m).
    pub separation: f64,
    /// |P(d)/P_target − 1| at `separation` (dimensionless).
    pub relative_residual: f64,
    /// Newton/bisection iterations spent after bracketing.
    pub iterations: u32,
    /// Reserved, 0.
    pub reserved: u32,
}

impl From<SeparationSolution> for AsperitySeparation {
    fn from(s: SeparationSolution) -> Self {
        Self {
            separation: s.separation,
            relative_residual: s.relative_residual,
            iterations: s.iterations,
            reserved: 0,
        }
    }
}

/// Zhuravlev's pair of rough surfaces of spherical caps (thesis (1-23),
/// (1-24)), by value. Give either `cap_radius` (Zhuravlev's setting: both
/// surfaces carry caps of radius R, a pair has R_eff = R/2) with
/// `effective_radius` = 0, or `effective_radius` (1/R_eff = 1/R₁ + 1/R₂) with
/// `cap_radius` = 0.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityZhuravlev {
    /// Cap radius R of both surfaces (m, > 0), or 0.
    pub cap_radius: f64,
    /// Effective radius of a pair of caps (m, > 0), or 0.
    pub effective_radius: f64,
    /// Contact modulus E* (Pa, > 0; E/(2(1−ν²)) for identical materials).
    pub e_star: f64,
    /// Summit count N (> 0) that normalises the meeting probability.
    pub summit_count: f64,
}

/// Load, real area and contacting pairs of Zhuravlev's model at one approach.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityZhuravlevResponse {
    /// Total normal load P (N), (1-23).
    pub load: f64,
    /// Real contact area S (m²), (1-24).
    pub area: f64,
    /// Expected number of contacting pairs (dimensionless).
    pub contacts: f64,
}

impl From<MultiAsperityResponse> for AsperityZhuravlevResponse {
    fn from(r: MultiAsperityResponse) -> Self {
        Self {
            load: r.load,
            area: r.area,
            contacts: r.contacts,
        }
    }
}

/// Friction of Zhuravlev's model at one load ((1-27), (1-28)).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityZhuravlevFriction {
    /// Approach x (m) that carries the load.
    pub approach: f64,
    /// The load P (N).
    pub load: f64,
    /// Real contact area S (m²).
    pub area: f64,
    /// Friction force F = τS (N).
    pub friction_force: f64,
    /// Coefficient of friction μ = F/P (dimensionless).
    pub coefficient: f64,
}

impl From<ZhuravlevFriction> for AsperityZhuravlevFriction {
    fn from(f: ZhuravlevFriction) -> Self {
        Self {
            approach: f.approach,
            load: f.load,
            area: f.area,
            friction_force: f.friction_force,
            coefficient: f.coefficient,
        }
    }
}

/// A summit density per unit depth n(ξ) (1/m) at depth `xi` (m, ≥ 0) below
/// the highest summit, for `asperity_zhuravlev_eval`; `user_data` is passed
/// through. It must return a finite value ≥ 0 and must not unwind.
pub type AsperitySummitDensity =
    Option<unsafe extern "C" fn(xi: f64, user_data: *mut c_void) -> f64>;

impl AsperityGwParams {
    /// The Rust model of these parameters; the distribution is validated.
    pub fn to_model(&self) -> Result<GreenwoodWilliamson> {
        let heights = match self.distribution {
            ASPERITY_HEIGHTS_GAUSSIAN => HeightDistribution::gaussian(self.sigma)?,
            ASPERITY_HEIGHTS_EXPONENTIAL => HeightDistribution::exponential(self.sigma)?,
            v => {
                return Err(Error::UnknownSelector {
                    name: "gw.distribution",
                    value: v as i64,
                })
            }
        };
        GreenwoodWilliamson::new(self.summit_count, self.radius, self.e_star, heights)
    }
}

impl AsperityZhuravlev {
    /// The Rust model of these parameters.
    pub fn to_model(&self) -> Result<Zhuravlev> {
        if self.effective_radius == 0.0 {
            Zhuravlev::new(self.cap_radius, self.e_star, self.summit_count)
        } else if self.cap_radius == 0.0 {
            Zhuravlev::with_effective_radius(self.effective_radius, self.e_star, self.summit_count)
        } else {
            Err(Error::InvalidArgument {
                name: "effective_radius",
                value: self.effective_radius,
                bound: "0 when cap_radius is given (give one of the two)",
            })
        }
    }
}

fn gw_eval(gw: &GreenwoodWilliamson, separation: f64) -> Result<AsperityGwResponse> {
    let r = gw.response(separation)?;
    Ok(AsperityGwResponse {
        load: r.load,
        area: r.area,
        contacts: r.contacts,
        stiffness: gw.stiffness(separation)?,
    })
}

/// The batch loop of the multi-asperity responses: for each separation d,
/// `eval(d, with_stiffness)` gives (load, area, contacts, stiffness), written
/// to `load` and to the outputs that are not NULL (the stiffness is asked for
/// only when its array is given). `separation` and `load` are required
/// unless n = 0; inputs and outputs may alias; an error at element i leaves
/// the elements from i on untouched and names i.
unsafe fn response_batch(
    n: usize,
    separation: *const f64,
    [load, area, contacts, stiffness]: [*mut f64; 4],
    mut eval: impl FnMut(f64, bool) -> Result<[f64; 4]>,
) -> core::result::Result<(), Failure> {
    if n == 0 {
        return Ok(());
    }
    input(separation, "separation")?;
    output(load, "load")?;
    for i in 0..n {
        // Read before any write: the input and output arrays may alias.
        let d = *separation.add(i);
        let [p, a, c, k] = eval(d, !stiffness.is_null()).map_err(|e| Failure::at(i, e))?;
        *load.add(i) = p;
        for (out, v) in [(area, a), (contacts, c), (stiffness, k)] {
            if !out.is_null() {
                *out.add(i) = v;
            }
        }
    }
    Ok(())
}

/// [`response_batch`] of a Greenwood–Williamson surface.
unsafe fn gw_batch(
    gw: &GreenwoodWilliamson,
    n: usize,
    separation: *const f64,
    outputs: [*mut f64; 4],
) -> core::result::Result<(), Failure> {
    response_batch(n, separation, outputs, |d, with_stiffness| {
        let r = gw.response(d)?;
        let k = if with_stiffness {
            gw.stiffness(d)?
        } else {
            0.0
        };
        Ok([r.load, r.area, r.contacts, k])
    })
}

/// Greenwood–Williamson load, real area, number of contacts and stiffness at
/// `separation` d (m, finite) (thesis (1-29), (1-30)).
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_eval(
    gw: *const AsperityGwParams,
    separation: f64,
    out: *mut AsperityGwResponse,
) -> i32 {
    guard(|| {
        let gw = input(gw, "gw")?.to_model()?;
        let out = output(out, "out")?;
        *out = gw_eval(&gw, separation)?;
        Ok(())
    })
}

/// `asperity_gw_eval` for `n` separations `separation[i]` (m), writing
/// `load[i]` (N) and, where the array is not NULL, `area[i]` (m²),
/// `contacts[i]` and `stiffness[i]` (N/m). `separation` and `load` are
/// required (unless n = 0); inputs and outputs may be the same memory. On an
/// error at element i, elements before i are written, those from i on are
/// untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_eval_batch(
    gw: *const AsperityGwParams,
    n: usize,
    separation: *const f64,
    load: *mut f64,
    area: *mut f64,
    contacts: *mut f64,
    stiffness: *mut f64,
) -> i32 {
    guard(|| {
        let gw = input(gw, "gw")?.to_model()?;
        gw_batch(&gw, n, separation, [load, area, contacts, stiffness])
    })
}

/// The separation (m) at which the surface carries `load` (N, finite, > 0):
/// the inverse of (1-29) by safeguarded Newton iteration.
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_separation_at_load(
    gw: *const AsperityGwParams,
    load: f64,
    out: *mut AsperitySeparation,
) -> i32 {
    guard(|| {
        let gw = input(gw, "gw")?.to_model()?;
        let out = output(out, "out")?;
        *out = gw.separation_at_load(load)?.into();
        Ok(())
    })
}

/// Plasticity index ψ = (E*/H)√(σ/R) (1-31) of the surface `gw` for the
/// hardness `hardness` H (Pa, > 0).
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_plasticity_index(
    gw: *const AsperityGwParams,
    hardness: f64,
    psi: *mut f64,
) -> i32 {
    guard(|| {
        let gw = input(gw, "gw")?.to_model()?;
        *output(psi, "psi")? = gw.plasticity_index(hardness)?;
        Ok(())
    })
}

/// Plasticity index of Greenwood & Williamson (1966), thesis (1-31):
/// ψ = (E*/H)√(σ/R) from the contact modulus `e_star` (Pa), the hardness
/// `hardness` (Pa), the standard deviation of the summit heights `sigma` (m)
/// and the summit radius `radius` (m), all finite and > 0.
#[no_mangle]
pub unsafe extern "C" fn asperity_plasticity_index(
    e_star: f64,
    hardness: f64,
    sigma: f64,
    radius: f64,
    psi: *mut f64,
) -> i32 {
    guard(|| {
        *output(psi, "psi")? = plasticity_index(e_star, hardness, sigma, radius)?;
        Ok(())
    })
}

/// The deformation regime (`ASPERITY_REGIME_*`) of a plasticity index `psi`
/// (finite, ≥ 0): elastic below 0.6, plastic above 1 (GW 1966).
#[no_mangle]
pub unsafe extern "C" fn asperity_deformation_regime(psi: f64, regime: *mut i32) -> i32 {
    guard(|| {
        let out = output(regime, "regime")?;
        *out = match DeformationRegime::of(psi)? {
            DeformationRegime::Elastic => ASPERITY_REGIME_ELASTIC,
            DeformationRegime::Transitional => ASPERITY_REGIME_TRANSITIONAL,
            DeformationRegime::Plastic => ASPERITY_REGIME_PLASTIC,
        };
        Ok(())
    })
}

/// A Greenwood–Williamson surface over `n` ≥ 1 listed summits: heights
/// `heights[i]` (m, finite, any order, in the frame of the separations) and,
/// unless `radii` is NULL, each summit's radius `radii[i]` (m, > 0; then they
/// replace `radius` in the load, area and stiffness), `summit_count` N (> 0;
/// each listed summit stands for N/n), `radius` R (m, > 0) and the contact
/// modulus `e_star` (Pa, > 0). The arrays are copied. Writes a new handle to
/// `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_empirical_new(
    summit_count: f64,
    radius: f64,
    e_star: f64,
    n: usize,
    heights: *const f64,
    radii: *const f64,
    out: *mut *mut AsperityGwEmpirical,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let h = array(heights, n, "heights")?.to_vec();
        let e = if radii.is_null() {
            EmpiricalHeights::new(h)?
        } else {
            EmpiricalHeights::with_radii(h, array(radii, n, "radii")?.to_vec())?
        };
        let gw = GreenwoodWilliamson::new(
            summit_count,
            radius,
            e_star,
            HeightDistribution::Empirical(e),
        )?;
        *out = Box::into_raw(Box::new(AsperityGwEmpirical(gw)));
        Ok(())
    })
}

/// Release an empirical Greenwood–Williamson surface; NULL is accepted.
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_empirical_free(gw: *mut AsperityGwEmpirical) {
    if !gw.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(gw));
        }));
    }
}

/// `asperity_gw_eval` for an empirical surface.
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_empirical_eval(
    gw: *const AsperityGwEmpirical,
    separation: f64,
    out: *mut AsperityGwResponse,
) -> i32 {
    guard(|| {
        let gw = &input(gw, "gw")?.0;
        let out = output(out, "out")?;
        *out = gw_eval(gw, separation)?;
        Ok(())
    })
}

/// `asperity_gw_eval_batch` for an empirical surface.
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_empirical_eval_batch(
    gw: *const AsperityGwEmpirical,
    n: usize,
    separation: *const f64,
    load: *mut f64,
    area: *mut f64,
    contacts: *mut f64,
    stiffness: *mut f64,
) -> i32 {
    guard(|| {
        let gw = &input(gw, "gw")?.0;
        gw_batch(gw, n, separation, [load, area, contacts, stiffness])
    })
}

/// `asperity_gw_separation_at_load` for an empirical surface.
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_empirical_separation_at_load(
    gw: *const AsperityGwEmpirical,
    load: f64,
    out: *mut AsperitySeparation,
) -> i32 {
    guard(|| {
        let gw = &input(gw, "gw")?.0;
        let out = output(out, "out")?;
        *out = gw.separation_at_load(load)?.into();
        Ok(())
    })
}

/// `asperity_gw_plasticity_index` for an empirical surface (σ of the listed
/// heights, the model's `radius`).
#[no_mangle]
pub unsafe extern "C" fn asperity_gw_empirical_plasticity_index(
    gw: *const AsperityGwEmpirical,
    hardness: f64,
    psi: *mut f64,
) -> i32 {
    guard(|| {
        let gw = &input(gw, "gw")?.0;
        *output(psi, "psi")? = gw.plasticity_index(hardness)?;
        Ok(())
    })
}

/// Zhuravlev's model with summit densities linear in depth, n_i(ξ) = α_i ξ
/// (`alpha1`, `alpha2` in m⁻², > 0), at the approach `approach` x (m, ≥ 0):
/// the closed forms P ∝ x^{11/2} (1-25), S ∝ x⁵ (1-26), pairs ∝ x⁴.
#[no_mangle]
pub unsafe extern "C" fn asperity_zhuravlev_linear(
    model: *const AsperityZhuravlev,
    alpha1: f64,
    alpha2: f64,
    approach: f64,
    out: *mut AsperityZhuravlevResponse,
) -> i32 {
    guard(|| {
        let z = input(model, "model")?.to_model()?;
        let out = output(out, "out")?;
        *out = z.linear(alpha1, alpha2, approach)?.into();
        Ok(())
    })
}

/// The approach x (m) that carries `load` (N, ≥ 0) with linear densities:
/// the inverse of (1-25).
#[no_mangle]
pub unsafe extern "C" fn asperity_zhuravlev_approach_at_load_linear(
    model: *const AsperityZhuravlev,
    alpha1: f64,
    alpha2: f64,
    load: f64,
    approach: *mut f64,
) -> i32 {
    guard(|| {
        let z = input(model, "model")?.to_model()?;
        *output(approach, "approach")? = z.approach_at_load_linear(alpha1, alpha2, load)?;
        Ok(())
    })
}

/// Friction of Zhuravlev's model at `load` (N, > 0) with linear densities and
/// interfacial shear strength `shear_strength` τ (Pa, ≥ 0): F = τS (1-27),
/// F ∝ P^{10/11} (1-28), μ = F/P.
#[no_mangle]
pub unsafe extern "C" fn asperity_zhuravlev_friction_linear(
    model: *const AsperityZhuravlev,
    alpha1: f64,
    alpha2: f64,
    load: f64,
    shear_strength: f64,
    out: *mut AsperityZhuravlevFriction,
) -> i32 {
    guard(|| {
        let z = input(model, "model")?.to_model()?;
        let out = output(out, "out")?;
        *out = z
            .friction_linear(alpha1, alpha2, load, shear_strength)?
            .into();
        Ok(())
    })
}

/// Zhuravlev's model for any summit densities `n1`, `n2` (1/m, callbacks
/// called with the depth ξ ≥ 0 and `n1_data` / `n2_data`) at the approach
/// `approach` (m, ≥ 0), by Gauss–Legendre quadrature of `order` (4..=64)
/// points per dimension ((1-23), (1-24)). A callback value that is not
/// finite gives `ASPERITY_ERR_INVALID_ARGUMENT` naming `n1` or `n2`; a
/// negative integral `ASPERITY_ERR_OUT_OF_DOMAIN`. The callbacks are called
/// on the calling thread only.
#[no_mangle]
pub unsafe extern "C" fn asperity_zhuravlev_eval(
    model: *const AsperityZhuravlev,
    approach: f64,
    n1: AsperitySummitDensity,
    n1_data: *mut c_void,
    n2: AsperitySummitDensity,
    n2_data: *mut c_void,
    order: usize,
    out: *mut AsperityZhuravlevResponse,
) -> i32 {
    guard(|| {
        let z = input(model, "model")?.to_model()?;
        let out = output(out, "out")?;
        let f1 = n1.ok_or(Error::NullPointer { name: "n1" })?;
        let f2 = n2.ok_or(Error::NullPointer { name: "n2" })?;
        // The first non-finite density value, reported after the quadrature.
        let bad: Cell<Option<(&'static str, f64)>> = Cell::new(None);
        let call = |name: &'static str, f: unsafe extern "C" fn(f64, *mut c_void) -> f64| {
            let bad = &bad;
            move |xi: f64, data: *mut c_void| {
                // SAFETY: the caller's callback, with the caller's data.
                let v = unsafe { f(xi, data) };
                if !v.is_finite() && bad.get().is_none() {
                    bad.set(Some((name, v)));
                }
                v
            }
        };
        let (c1, c2) = (call("n1", f1), call("n2", f2));
        let r = z.response(approach, |xi| c1(xi, n1_data), |xi| c2(xi, n2_data), order);
        if let Some((name, value)) = bad.get() {
            return Err(Error::InvalidArgument {
                name,
                value,
                bound: "a finite density at every depth",
            }
            .into());
        }
        *out = r?.into();
        Ok(())
    })
}
