//! C ABI of `crate::statistics::borodich_kryukova`: the block on a belt (thesis
//! §5.3.7) by value, its normal force and a run into caller-owned samples.

use super::*;

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
