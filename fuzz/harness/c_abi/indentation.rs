//! Indentation (`src/ffi/indentation.rs`): flag names, default options,
//! curve fits, rescaling and hardness scalars.

use super::common::*;
use super::Op;
use arbitrary::Arbitrary;
use asperity::ffi::indentation::*;
use std::ffi::CStr;
use std::ptr::null;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::FlagName(bit) => {
            let p = asperity_indentation_flag_name(*bit);
            if !p.is_null() {
                let _ = CStr::from_ptr(p);
            }
        }
        Op::DefaultOptions { null } => {
            let mut o: AsperityIndentationOptions = zeroed();
            ok(
                asperity_indentation_default_options(mp(&mut o, *null)),
                "default_options",
            );
        }
        Op::IndentFit {
            curve,
            segments,
            options,
            nulls,
        } => {
            let (d, p) = curve.make();
            let n = d.len();
            let seg: Option<Vec<i32>> = segments
                .as_ref()
                .map(|s| (0..n).map(|i| s.get(i).map_or(2, |v| v.0)).collect());
            let mut o: AsperityIndentationOptions = zeroed();
            assert!(ok(
                asperity_indentation_default_options(&mut o),
                "default_options"
            ));
            if let Some(spec) = options {
                spec.apply(&mut o);
            }
            let mut r: AsperityIndentationResult = zeroed();
            let s = asperity_indentation_fit(
                n,
                bufp(&d, nulls.at(0)),
                bufp(&p, nulls.at(1)),
                seg.as_ref().map_or(null(), |s| s.as_ptr()),
                if options.is_none() { null() } else { &o },
                mp(&mut r, nulls.at(2)),
            );
            ok(s, "indentation_fit");
        }
        Op::IndentFitRaw { depth, load, nulls } => {
            let n = depth.len().min(load.len());
            let d: Vec<f64> = depth[..n].iter().map(|f| f.0).collect();
            let p: Vec<f64> = load[..n].iter().map(|f| f.0).collect();
            let mut r: AsperityIndentationResult = zeroed();
            let s = asperity_indentation_fit(
                n,
                bufp(&d, nulls.at(0)),
                bufp(&p, nulls.at(1)),
                null(),
                null(),
                mp(&mut r, nulls.at(2)),
            );
            ok(s, "indentation_fit");
        }
        Op::Rescaling { which, a, null } => {
            let [a0, a1, a2, a3, a4, a5] = fs(*a);
            let mut out = 0.0;
            let o = mp(&mut out, *null);
            let s = match which % 14 {
                0 => asperity_rescaling_depth(a0, a1, a2, a3, a4, a5, o),
                1 => asperity_rescaling_radius(a0, a1, a2, a3, a4, a5, o),
                2 => asperity_rescaling_load(a0, a1, a2, a3, a4, a5, o),
                3 => asperity_rescaling_lambda_spheres(a0, a1, o),
                4 => asperity_rescaling_lambda_cones(a0, a1, o),
                5 => asperity_rescaling_kappa_from_slope(a0, a1, o),
                6 => asperity_rescaling_d_from_unloading_slope(a0, o),
                7 => asperity_rescaling_d_from_loading_slope(a0, a1, o),
                8 => asperity_galanov_unloading_radius(a0, a1, a2, a3, a4, o),
                9 => asperity_galanov_medium_radius(a0, a1, o),
                10 => asperity_hardness_brinell(a0, a1, a2, o),
                11 => asperity_hardness_meyer(a0, a1, o),
                12 => asperity_hardness_ludwik(a0, a1, o),
                _ => asperity_hardness_vickers(a0, a1, o),
            };
            ok(s, "rescaling/hardness");
        }
        _ => unreachable!("not a indentation operation: {op:?}"),
    }
}

/// A loading–unloading curve P = c δ^m, then a power-law unloading, with
/// optional raw replacements.
#[derive(Debug, Clone, Arbitrary)]
pub struct CurveSpec {
    loading: u8,
    unloading: u8,
    depth: F,
    c: F,
    m: u8,
    recovery: u8,
    replace: Option<(u8, F, bool)>,
}

impl CurveSpec {
    fn make(&self) -> (Vec<f64>, Vec<f64>) {
        let nl = self.loading as usize % 60 + 1;
        let nu = self.unloading as usize % 60;
        let hmax = self.depth.0.abs();
        let m = 1.0 + self.m as f64 / 128.0;
        let c = self.c.0.abs();
        let hf = hmax * self.recovery as f64 / 300.0;
        let mut d = Vec::new();
        let mut p = Vec::new();
        for i in 1..=nl {
            let h = hmax * i as f64 / nl as f64;
            d.push(h);
            p.push(c * h.powf(m));
        }
        let pmax = c * hmax.powf(m);
        for i in 1..=nu {
            let h = hmax - (hmax - hf) * i as f64 / nu as f64;
            d.push(h);
            p.push(pmax * ((h - hf) / (hmax - hf)).max(0.0).powf(1.5));
        }
        if let Some((k, f, depth)) = self.replace {
            let i = k as usize % d.len();
            if depth {
                d[i] = f.0;
            } else {
                p[i] = f.0;
            }
        }
        (d, p)
    }
}

#[derive(Debug, Clone, Arbitrary)]
pub struct OptionsSpec {
    indenter: Sel,
    anchor: Sel,
    use_labels: Sel,
    n_area: Sel,
    area: [F; 8],
    radius: F,
    angle: F,
    known: (Sel, Sel, F, F),
    anchor_index: Big,
    moduli: [F; 3],
    beta: F,
    epsilon: F,
    windows: [F; 4],
    which: u16,
}

impl OptionsSpec {
    /// The defaults with the fields selected by `which` replaced.
    fn apply(&self, o: &mut AsperityIndentationOptions) {
        let w = |i: u32| self.which >> i & 1 == 1;
        if w(0) {
            o.indenter = self.indenter.0;
        }
        if w(1) {
            o.anchor = self.anchor.0;
        }
        if w(2) {
            o.use_labels = self.use_labels.0;
        }
        if w(3) {
            o.n_area_coefficients = self.n_area.0;
            o.area_coefficients = fs(self.area);
        }
        if w(4) {
            o.sphere_radius = self.radius.0;
            o.cone_half_angle = self.angle.0;
        }
        if w(5) {
            o.has_known_d = self.known.0 .0;
            o.has_known_kappa = self.known.1 .0;
            o.known_d = self.known.2 .0;
            o.known_kappa = self.known.3 .0;
        }
        if w(6) {
            o.anchor_index = self.anchor_index.0;
        }
        if w(7) {
            o.e_indenter = self.moduli[0].0;
            o.nu_indenter = self.moduli[1].0;
            o.nu_sample = self.moduli[2].0;
        }
        if w(8) {
            o.beta = self.beta.0;
            o.epsilon = self.epsilon.0;
        }
        if w(9) {
            let v = fs(self.windows);
            o.loading_window = [v[0], v[1]];
            o.unloading_window = [v[2], v[3]];
        }
    }
}
