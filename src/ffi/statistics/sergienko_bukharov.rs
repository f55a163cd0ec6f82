//! C ABI of `crate::statistics::sergienko_bukharov`: the body on Kragelsky's
//! springs (thesis §5.3.5), one run per call.

use super::*;

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
