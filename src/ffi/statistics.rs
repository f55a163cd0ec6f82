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

unsafe fn gw_batch(
    gw: &GreenwoodWilliamson,
    n: usize,
    separation: *const f64,
    load: *mut f64,
    area: *mut f64,
    contacts: *mut f64,
    stiffness: *mut f64,
) -> core::result::Result<(), Failure> {
    if n == 0 {
        return Ok(());
    }
    input(separation, "separation")?;
    output(load, "load")?;
    for i in 0..n {
        // Read before any write: the input and output arrays may alias.
        let d = *separation.add(i);
        let r = gw.response(d).map_err(|e| Failure::at(i, e))?;
        let k = if stiffness.is_null() {
            0.0
        } else {
            gw.stiffness(d).map_err(|e| Failure::at(i, e))?
        };
        *load.add(i) = r.load;
        if !area.is_null() {
            *area.add(i) = r.area;
        }
        if !contacts.is_null() {
            *contacts.add(i) = r.contacts;
        }
        if !stiffness.is_null() {
            *stiffness.add(i) = k;
        }
    }
    Ok(())
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
        gw_batch(&gw, n, separation, load, area, contacts, stiffness)
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
        gw_batch(gw, n, separation, load, area, contacts, stiffness)
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

/// The Borodich–Kryukova slider (thesis §5.3.7), by value: a rigid block
/// of length 2a and mass M on a horizontal spring k_x, on a belt moving at
/// speed U, both faces carrying a layer of linear springs (stiffness ε per
/// unit length) over sinusoidal profiles A cos(2πξ/λ). An all-zero value
/// is invalid.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBorodichKryukova {
    /// Half-length a of the block (m, > 0).
    pub half_length: f64,
    /// Mass M (kg, > 0).
    pub mass: f64,
    /// Belt speed U (m/s, finite).
    pub belt_speed: f64,
    /// Horizontal spring stiffness k_x (N/m, > 0).
    pub spring_stiffness: f64,
    /// Layer stiffness ε (N/m per m of block length, N/m², > 0).
    pub layer_stiffness: f64,
    /// Friction coefficient μ (dimensionless, finite, ≥ 0).
    pub friction_coefficient: f64,
    /// Gravity g (m/s², finite, ≥ 0).
    pub gravity: f64,
    /// Smoothing speed v_s of the friction sign, clamp((U − ẋ)/v_s, −1, 1)
    /// (m/s, > 0).
    pub sign_speed: f64,
    /// Amplitude of the block's profile f_s (m, finite, ≥ 0).
    pub slider_amplitude: f64,
    /// Wavelength of the block's profile f_s (m, > 0).
    pub slider_wavelength: f64,
    /// Amplitude of the belt's profile f_b (m, finite, ≥ 0).
    pub belt_amplitude: f64,
    /// Wavelength of the belt's profile f_b (m, > 0).
    pub belt_wavelength: f64,
    /// Midpoint cells along the block (1..=100000).
    pub nodes: u32,
    /// Reserved, 0.
    pub reserved: u32,
}

/// The state of a Borodich–Kryukova block.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBorodichKryukovaState {
    /// Time t (s).
    pub time: f64,
    /// Horizontal position x (m; the spring is unstretched at 0).
    pub x: f64,
    /// Horizontal velocity ẋ (m/s).
    pub vx: f64,
    /// Distance y between the profiles' mean lines (m; < 0: overlap).
    pub y: f64,
    /// Vertical velocity ẏ (m/s).
    pub vy: f64,
}

/// One recorded sample of a Borodich–Kryukova run.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBorodichKryukovaSample {
    /// The state.
    pub state: AsperityBorodichKryukovaState,
    /// Elastic normal force F_el,y of the layers (N).
    pub normal_force: f64,
    /// Friction force F_fr,x on the block (N).
    pub friction_force: f64,
}

impl AsperityBorodichKryukova {
    /// The Rust model (checked by its users).
    pub fn to_model(&self) -> BorodichKryukova {
        BorodichKryukova {
            half_length: self.half_length,
            mass: self.mass,
            belt_speed: self.belt_speed,
            spring_stiffness: self.spring_stiffness,
            layer_stiffness: self.layer_stiffness,
            friction_coefficient: self.friction_coefficient,
            gravity: self.gravity,
            sign_speed: self.sign_speed,
            slider: Sinusoid {
                amplitude: self.slider_amplitude,
                wavelength: self.slider_wavelength,
            },
            belt: Sinusoid {
                amplitude: self.belt_amplitude,
                wavelength: self.belt_wavelength,
            },
            nodes: self.nodes,
        }
    }
}

impl From<SliderState> for AsperityBorodichKryukovaState {
    fn from(s: SliderState) -> Self {
        Self {
            time: s.time,
            x: s.x,
            vx: s.vx,
            y: s.y,
            vy: s.vy,
        }
    }
}

/// The number of samples `asperity_borodich_kryukova_run` records for
/// `steps` steps recorded every `every`-th (≥ 1): steps/every + 1.
fn bk_samples(steps: u32, every: u32) -> Result<usize> {
    if every == 0 {
        return Err(Error::InvalidArgument {
            name: "every",
            value: 0.0,
            bound: ">= 1",
        });
    }
    Ok((steps / every) as usize + 1)
}

/// The elastic normal force F_el,y = ε ∫ max(f_s(ξ) + f_b(ξ + x − Ut) − y, 0) dξ
/// (N, midpoint rule on `nodes` cells) of the slider `bk` at position `x`
/// (m), mean-line distance `y` (m) and time `time` (s), to `*out`.
#[no_mangle]
pub unsafe extern "C" fn asperity_borodich_kryukova_normal_force(
    bk: *const AsperityBorodichKryukova,
    x: f64,
    y: f64,
    time: f64,
    out: *mut f64,
) -> i32 {
    guard(|| {
        let m = input(bk, "bk")?.to_model();
        m.validate()?;
        check::finite("x", x)?;
        check::finite("y", y)?;
        check::finite("time", time)?;
        let out = output(out, "out")?;
        *out = m.normal_force(x, y, time);
        Ok(())
    })
}

/// Integrate the slider `bk` from `*start` for `steps` steps of `dt`
/// (s, > 0) by classical Runge–Kutta 4, recording the start and every
/// `every`-th step (≥ 1): steps/every + 1 samples written to `samples`,
/// which has room for `capacity` (checked first: a smaller capacity is an
/// error naming it, and nothing is integrated). The number written goes to
/// `*written` unless it is NULL. Errors: parameters out of range (named),
/// a state that stops being finite (`ASPERITY_ERR_NOT_CONVERGED`).
#[no_mangle]
pub unsafe extern "C" fn asperity_borodich_kryukova_run(
    bk: *const AsperityBorodichKryukova,
    start: *const AsperityBorodichKryukovaState,
    dt: f64,
    steps: u32,
    every: u32,
    capacity: usize,
    samples: *mut AsperityBorodichKryukovaSample,
    written: *mut usize,
) -> i32 {
    guard(|| {
        let m = input(bk, "bk")?.to_model();
        let s = *input(start, "start")?;
        m.validate()?;
        let count = bk_samples(steps, every)?;
        if capacity < count {
            return Err(Error::InvalidArgument {
                name: "capacity",
                value: capacity as f64,
                bound: ">= steps/every + 1 (the samples recorded)",
            }
            .into());
        }
        output(samples, "samples")?;
        let start = SliderState {
            time: s.time,
            x: s.x,
            vx: s.vx,
            y: s.y,
            vy: s.vy,
        };
        let run = m.run(start, dt, steps, every)?;
        for (i, r) in run.iter().enumerate() {
            *samples.add(i) = AsperityBorodichKryukovaSample {
                state: r.state.into(),
                normal_force: r.normal_force,
                friction_force: r.friction_force,
            };
        }
        if !written.is_null() {
            *written = run.len();
        }
        Ok(())
    })
}

/// A Bush–Gibson–Thomas rough surface (thesis §5.3.3), by value: an
/// isotropic Gaussian surface of spectral moments m₀, m₂, m₄ (Nayak 1971)
/// whose summits are elliptic paraboloids in Hertz contact with a flat.
/// Nayak's α = m₀m₄/m₂² must exceed 3/2. An all-zero value is invalid.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBgtParams {
    /// Mean-square height m₀ = σ² (m², > 0).
    pub m0: f64,
    /// Mean-square profile slope m₂ (dimensionless, > 0); the mean-square
    /// gradient of the isotropic surface is 2m₂.
    pub m2: f64,
    /// Mean-square profile curvature m₄ (m⁻², > 0).
    pub m4: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Nominal contact area A₀ (m², > 0).
    pub nominal_area: f64,
}

/// Response of a Bush–Gibson–Thomas surface at one separation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBgtResponse {
    /// Total normal load P (N), ≥ 0.
    pub load: f64,
    /// Real contact area A (m²), ≥ 0.
    pub area: f64,
    /// Expected number of summits in contact (dimensionless).
    pub contacts: f64,
    /// Normal stiffness −dP/dd (N/m), ≥ 0.
    pub stiffness: f64,
}

impl AsperityBgtParams {
    /// The validated Rust model.
    pub fn to_model(&self) -> Result<BushGibsonThomas> {
        BushGibsonThomas::new(self.m0, self.m2, self.m4, self.e_star, self.nominal_area)
    }
}

fn bgt_eval(bgt: &BushGibsonThomas, separation: f64) -> Result<AsperityBgtResponse> {
    let r = bgt.evaluate(separation)?;
    Ok(AsperityBgtResponse {
        load: r.response.load,
        area: r.response.area,
        contacts: r.response.contacts,
        stiffness: r.stiffness,
    })
}

/// Bush–Gibson–Thomas load, real area, number of contacts and stiffness at
/// `separation` d (m, finite; the flat's height above the mean plane of the
/// surface).
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_eval(
    bgt: *const AsperityBgtParams,
    separation: f64,
    out: *mut AsperityBgtResponse,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        let out = output(out, "out")?;
        *out = bgt_eval(&bgt, separation)?;
        Ok(())
    })
}

/// `asperity_bgt_eval` for `n` separations `separation[i]` (m), writing
/// `load[i]` (N) and, where the array is not NULL, `area[i]` (m²),
/// `contacts[i]` and `stiffness[i]` (N/m). `separation` and `load` are
/// required (unless n = 0); inputs and outputs may be the same memory. On an
/// error at element i, elements before i are written, those from i on are
/// untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_eval_batch(
    bgt: *const AsperityBgtParams,
    n: usize,
    separation: *const f64,
    load: *mut f64,
    area: *mut f64,
    contacts: *mut f64,
    stiffness: *mut f64,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        if n == 0 {
            return Ok(());
        }
        input(separation, "separation")?;
        output(load, "load")?;
        for i in 0..n {
            // Read before any write: the input and output arrays may alias.
            let d = *separation.add(i);
            let r = bgt_eval(&bgt, d).map_err(|e| Failure::at(i, e))?;
            *load.add(i) = r.load;
            if !area.is_null() {
                *area.add(i) = r.area;
            }
            if !contacts.is_null() {
                *contacts.add(i) = r.contacts;
            }
            if !stiffness.is_null() {
                *stiffness.add(i) = r.stiffness;
            }
        }
        Ok(())
    })
}

/// The separation (m) at which the surface carries `load` (N, finite, > 0),
/// by safeguarded Newton iteration.
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_separation_at_load(
    bgt: *const AsperityBgtParams,
    load: f64,
    out: *mut AsperitySeparation,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        let out = output(out, "out")?;
        *out = bgt.separation_at_load(load)?.into();
        Ok(())
    })
}

/// Nayak's summit density D = m₄/(6π√3 m₂) (m⁻², to `*summit_density`) and
/// the small-load limit of A/P, √π/(E*√m₂) = √(2π)/(E*√(2m₂)) (m²/N, to
/// `*area_per_load`) of the surface `bgt`; either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_properties(
    bgt: *const AsperityBgtParams,
    summit_density: *mut f64,
    area_per_load: *mut f64,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        if !summit_density.is_null() {
            *summit_density = bgt.summit_density();
        }
        if !area_per_load.is_null() {
            *area_per_load = bgt.small_load_area_per_load();
        }
        Ok(())
    })
}

/// The real nano-topography interface of Bora et al. (2013, thesis §5.3.9)
/// (opaque): springs with the heights of a measured map on an elastic
/// half-space. Create it with `asperity_bora_new`, release it with
/// `asperity_bora_free`. Immutable: safe to share between threads.
pub struct AsperityBora(BoraTopography);

/// The equilibrium of a Bora interface at one separation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBoraResponse {
    /// Total load P (N), ≥ 0.
    pub load: f64,
    /// Real contact area (m²): loaded springs times the cell area Δ².
    pub area: f64,
    /// Normal stiffness −dP/dd (N/m), ≥ 0.
    pub stiffness: f64,
    /// Number of loaded springs.
    pub contacts: u64,
    /// Conjugate-gradient iterations spent.
    pub iterations: u32,
    /// Reserved, 0.
    pub reserved: u32,
}

/// A Bora interface on `nx` × `ny` heights `heights` (m, finite, row-major:
/// `heights[i + nx*j]` at x = iΔ, y = jΔ; copied) with grid spacing `spacing`
/// Δ (m, > 0), springs of stiffness `spring_stiffness` (N/m, > 0) on a
/// substrate of contact modulus `contact_modulus` E* (Pa, > 0), or a rigid
/// substrate (independent springs) when `contact_modulus` is 0. At most
/// 16384 points. Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_new(
    nx: usize,
    ny: usize,
    spacing: f64,
    heights: *const f64,
    spring_stiffness: f64,
    contact_modulus: f64,
    out: *mut *mut AsperityBora,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let n = nx.checked_mul(ny).ok_or(Error::InvalidArgument {
            name: "nx",
            value: nx as f64,
            bound: "nx, ny >= 1 and nx*ny <= 16384",
        })?;
        let h = if n == 0 {
            Vec::new()
        } else {
            array(heights, n, "heights")?.to_vec()
        };
        let substrate = if contact_modulus == 0.0 {
            None
        } else {
            Some(contact_modulus)
        };
        let m = BoraTopography::new(nx, ny, spacing, h, spring_stiffness, substrate)?;
        *out = Box::into_raw(Box::new(AsperityBora(m)));
        Ok(())
    })
}

/// Release a Bora interface; NULL is accepted.
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_free(bora: *mut AsperityBora) {
    if !bora.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(bora));
        }));
    }
}

/// The equilibrium with the flat at `separation` d (m, finite, in the frame
/// of the heights): load, area, stiffness, contacts to `*out`, and, unless
/// `forces` is NULL, the nx·ny spring forces (N) to `forces`.
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_solve(
    bora: *const AsperityBora,
    separation: f64,
    out: *mut AsperityBoraResponse,
    forces: *mut f64,
) -> i32 {
    guard(|| {
        let m = &input(bora, "bora")?.0;
        let out = output(out, "out")?;
        let s = m.solve(separation)?;
        if !forces.is_null() {
            core::ptr::copy_nonoverlapping(s.forces.as_ptr(), forces, s.forces.len());
        }
        *out = AsperityBoraResponse {
            load: s.load,
            area: s.area,
            stiffness: s.stiffness,
            contacts: s.contacts as u64,
            iterations: s.iterations,
            reserved: 0,
        };
        Ok(())
    })
}

/// The separation (m) at which the interface carries `load` (N, finite
/// and > 0).
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_separation_at_load(
    bora: *const AsperityBora,
    load: f64,
    out: *mut AsperitySeparation,
) -> i32 {
    guard(|| {
        let m = &input(bora, "bora")?.0;
        let out = output(out, "out")?;
        *out = m.separation_at_load(load)?.into();
        Ok(())
    })
}

/// Spring heights for `asperity_sergienko_bukharov_run`: the listed heights.
pub const ASPERITY_HEIGHTS_LIST: i32 = 0;

/// The Sergienko–Bukharov model (thesis §5.3.5, in the library's formulation
/// from the thesis's description; Rust module `sergienko_bukharov`), by value: a rigid body of mass m under the load N₀
/// on Kragelsky's independent springs, driven by the normal force
/// F₀ sin ωt and/or a tangential impulse J turned upwards by flanks of slope
/// tan θ; friction μ(P + p₀ A_rod n) (Derjaguin, thesis (1-3)). An all-zero
/// value is invalid.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySergienkoBukharovParams {
    /// `ASPERITY_HEIGHTS_LIST` (the `heights` array), `ASPERITY_HEIGHTS_GAUSSIAN`
    /// or `ASPERITY_HEIGHTS_EXPONENTIAL` (zero-mean, standard deviation `sigma`).
    pub distribution: i32,
    /// Periods skipped before averaging.
    pub transient_periods: u32,
    /// Periods averaged over (≥ 1).
    pub average_periods: u32,
    /// Least steps per natural period of the stiffest state reached
    /// (16..=100000; 64 is a good default).
    pub steps_per_natural_period: u32,
    /// Number of springs N (> 0); for a list, 0 means one spring per height.
    pub rod_count: f64,
    /// Standard deviation σ of parametric heights (m, > 0); ignored for a list.
    pub sigma: f64,
    /// Stiffness k of one spring (N/m, > 0).
    pub rod_stiffness: f64,
    /// Cross-section A_rod of one spring (m², > 0).
    pub rod_area: f64,
    /// Mass m of the body (kg, > 0).
    pub mass: f64,
    /// Normal load N₀ (N, > 0).
    pub load: f64,
    /// Damping ratio ζ of the motion linearised at rest (≥ 0).
    pub damping_ratio: f64,
    /// Friction coefficient μ (> 0).
    pub friction_coefficient: f64,
    /// Specific attractive force p₀ of Derjaguin's law (Pa, ≥ 0).
    pub attractive_pressure: f64,
    /// Amplitude F₀ of the normal force F₀ sin ωt (N, ≥ 0).
    pub force_amplitude: f64,
    /// Angular frequency ω (rad/s; > 0 when `force_amplitude` > 0).
    pub frequency: f64,
    /// Tangential impulse J at t = 0 (N·s, ≥ 0).
    pub tangential_impulse: f64,
    /// Flank slope tan θ turning J/m into an upward velocity (≥ 0).
    pub slope: f64,
    /// Start position relative to the static equilibrium (m, > 0 above).
    pub initial_offset: f64,
    /// Most time steps the run may take (0: 5e7); a longer run is refused.
    pub max_steps: u64,
}

/// The result of a Sergienko–Bukharov run: static reference, averages over
/// whole periods after the transient, and the integration report.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySergienkoBukharovResult {
    /// Static separation d_s (m): the springs carry N₀.
    pub static_separation: f64,
    /// Springs in contact at rest.
    pub static_contacts: f64,
    /// Static friction F_s (N).
    pub static_friction: f64,
    /// Mean separation ⟨d⟩ (m).
    pub mean_separation: f64,
    /// Dynamic lift ⟨d⟩ − d_s (m).
    pub lift: f64,
    /// Half the peak-to-peak range of d (m).
    pub separation_amplitude: f64,
    /// Mean number of contacting springs.
    pub mean_contacts: f64,
    /// Mean contacts over static contacts.
    pub contact_ratio: f64,
    /// Mean spring load (N); N₀ in a periodic steady state.
    pub mean_load: f64,
    /// Mean friction force (N).
    pub mean_friction: f64,
    /// Mean friction over static friction.
    pub friction_ratio: f64,
    /// Fraction of the averaged time spent off the springs.
    pub lift_off_fraction: f64,
    /// Damping coefficient c (N·s/m).
    pub damping: f64,
    /// Averaging period T (s).
    pub period: f64,
    /// Time step (s).
    pub time_step: f64,
    /// Steps per natural period of the stiffest state reached.
    pub resolution: f64,
    /// Steps taken.
    pub steps: u64,
}

impl AsperitySergienkoBukharovParams {
    /// The validated Rust model and the run settings, for the listed
    /// `heights` (used when `distribution` is `ASPERITY_HEIGHTS_LIST`).
    pub fn to_model(
        &self,
        heights: &[f64],
    ) -> Result<(SergienkoBukharov, Excitation, Integration)> {
        let (dist, count) = match self.distribution {
            ASPERITY_HEIGHTS_LIST => {
                let h = HeightDistribution::empirical(heights.to_vec())?;
                let count = if self.rod_count == 0.0 {
                    heights.len() as f64
                } else {
                    self.rod_count
                };
                (h, count)
            }
            ASPERITY_HEIGHTS_GAUSSIAN => {
                (HeightDistribution::gaussian(self.sigma)?, self.rod_count)
            }
            ASPERITY_HEIGHTS_EXPONENTIAL => {
                (HeightDistribution::exponential(self.sigma)?, self.rod_count)
            }
            other => {
                return Err(Error::UnknownSelector {
                    name: "distribution",
                    value: other as i64,
                })
            }
        };
        let rods = KragelskyRods::new(count, self.rod_area, self.rod_stiffness, dist)?;
        let model = SergienkoBukharov::new(
            rods,
            self.mass,
            self.load,
            self.damping_ratio,
            self.friction_coefficient,
            self.attractive_pressure,
        )?;
        let excitation = Excitation {
            force_amplitude: self.force_amplitude,
            frequency: self.frequency,
            tangential_impulse: self.tangential_impulse,
            slope: self.slope,
            initial_offset: self.initial_offset,
        };
        let integration = Integration {
            transient_periods: self.transient_periods,
            average_periods: self.average_periods,
            steps_per_natural_period: self.steps_per_natural_period,
            record_every: 0,
            max_steps: self.max_steps,
        };
        Ok((model, excitation, integration))
    }
}

impl From<&SergienkoBukharovRun> for AsperitySergienkoBukharovResult {
    fn from(r: &SergienkoBukharovRun) -> Self {
        Self {
            static_separation: r.static_separation,
            static_contacts: r.static_contacts,
            static_friction: r.static_friction,
            mean_separation: r.mean_separation,
            lift: r.lift,
            separation_amplitude: r.separation_amplitude,
            mean_contacts: r.mean_contacts,
            contact_ratio: r.contact_ratio,
            mean_load: r.mean_load,
            mean_friction: r.mean_friction,
            friction_ratio: r.friction_ratio,
            lift_off_fraction: r.lift_off_fraction,
            damping: r.damping,
            period: r.period,
            time_step: r.time_step,
            resolution: r.resolution,
            steps: r.steps,
        }
    }
}

/// Run the Sergienko–Bukharov model `params` on `n_heights` spring-top
/// heights `heights` (m, finite; read only for `ASPERITY_HEIGHTS_LIST`, may
/// be NULL otherwise) and write the averages to `*out`. A run needing more
/// than `max_steps` steps is refused (ω far below the natural frequency).
#[no_mangle]
pub unsafe extern "C" fn asperity_sergienko_bukharov_run(
    params: *const AsperitySergienkoBukharovParams,
    heights: *const f64,
    n_heights: usize,
    out: *mut AsperitySergienkoBukharovResult,
) -> i32 {
    guard(|| {
        let p = input(params, "params")?;
        let out = output(out, "out")?;
        let h: &[f64] = if p.distribution == ASPERITY_HEIGHTS_LIST && n_heights > 0 {
            array(heights, n_heights, "heights")?
        } else {
            &[]
        };
        let (model, excitation, integration) = p.to_model(h)?;
        *out = (&model.run(&excitation, &integration)?).into();
        Ok(())
    })
}
