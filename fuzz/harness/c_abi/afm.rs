//! AFM force curves (`src/ffi/afm.rs`): flag names and the analysis of a
//! curve from arrays, on raw arrays and on V-shaped ramps with a contact
//! part (so the fits run), at most 48 points (each analysis fits up to four
//! laws by Levenberg–Marquardt: milliseconds at this size).

use super::common::*;
use super::Op;
use arbitrary::Arbitrary;
use asperity::ffi::afm::*;
use std::ffi::CStr;

/// The most points fed to one analysis.
const MAX_POINTS: usize = 48;

/// A curve: raw arrays, or a ramp towards the sample and back whose force
/// rises past the turning point, with the given perturbations added.
#[derive(Debug, Clone, Arbitrary)]
pub struct AfmSpec {
    ramp: bool,
    position: Vec<F>,
    signal: Vec<F>,
}

impl AfmSpec {
    fn make(&self) -> (Vec<f64>, Vec<f64>) {
        if self.ramp {
            let n = (16 + self.signal.len()).min(MAX_POINTS);
            let half = n / 2;
            let mut z = Vec::with_capacity(n);
            let mut f = Vec::with_capacity(n);
            for i in 0..n {
                let t = if i < half { i } else { n - 1 - i } as f64 / half as f64;
                let dz = self.position.get(i).map_or(0.0, |v| v.0 * 1e-12);
                let df = self.signal.get(i).map_or(0.0, |v| v.0 * 1e-12);
                z.push(1e-6 * t + dz);
                f.push(
                    if t > 0.7 { 1e-7 * (t - 0.7) } else { 0.0 }
                        - if i >= half && t > 0.6 && t < 0.72 {
                            1e-8
                        } else {
                            0.0
                        }
                        + df,
                );
            }
            (z, f)
        } else {
            let n = self.position.len().min(self.signal.len()).min(MAX_POINTS);
            (
                self.position[..n].iter().map(|v| v.0).collect(),
                self.signal[..n].iter().map(|v| v.0).collect(),
            )
        }
    }
}

/// Runs one operation of this domain.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::AfmFlagName(bit) => {
            let p = asperity_afm_flag_name(*bit);
            if !p.is_null() {
                let _ = CStr::from_ptr(p);
            }
        }
        Op::AfmAnalyze {
            curve,
            input_kind,
            retract_start,
            spring_constant,
            tip_radius,
            model,
            nulls,
        } => {
            let (z, f) = curve.make();
            let mut r: AsperityAfmResult = zeroed();
            let s = asperity_afm_analyze(
                z.len(),
                bufp(&z, nulls.at(0)),
                bufp(&f, nulls.at(1)),
                input_kind.0 % 3,
                *retract_start as usize,
                spring_constant.0,
                tip_radius.0,
                model.0,
                mp(&mut r, nulls.at(2)),
            );
            if ok(s, "afm_analyze") {
                assert!(
                    r.pull_off_force.is_finite() && r.adhesion_energy.is_finite(),
                    "afm_analyze: OK with non-finite results"
                );
            }
        }
        _ => unreachable!("not an AFM operation"),
    }
}
