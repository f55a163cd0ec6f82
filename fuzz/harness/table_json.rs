//! Fuzz harness `table_json`: the serde loaders of the library's stored
//! objects on arbitrary text — `TabulatedLaw::from_json` (what
//! `asperity_table_from_json` calls), `HomogenisedFriction::from_json`
//! (`asperity_homogenised_friction_from_json`), `SliderGeometry::from_json`
//! and `EquilibriumCurve::from_json` — and, when one loads, its evaluation at
//! fixed probe points inside and around its range. Any panic is a finding.
//!
//! Shared by `fuzz/fuzz_targets/table_json.rs` (libFuzzer) and
//! `tests/fuzz_corpus.rs` (corpus replay on stable).

use asperity::contact::curve::EquilibriumCurve;
use asperity::contact::TabulatedLaw;
use asperity::friction::{FrictionIncrement, FrictionLaw, HomogenisedFriction, SliderGeometry};
use asperity::{ContactState, Control, NormalContact};

const SPECIAL: [f64; 8] = [
    0.0,
    -0.0,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::MAX,
    -f64::MAX,
    5e-324,
];

fn probe_law(t: &TabulatedLaw) {
    let mut xs: Vec<f64> = SPECIAL.to_vec();
    for k in 0..t.branch_count().min(8) {
        if let Some((lo, hi)) = t.branch_range(k) {
            let span = hi - lo;
            xs.extend([
                lo,
                hi,
                0.5 * (lo + hi),
                lo - span,
                hi + span,
                lo + lo.abs() * 1e-15,
                hi - hi.abs() * 1e-15,
            ]);
        }
    }
    let mut state = ContactState::default();
    for &x in &xs {
        let _ = t.eval(x, &ContactState::default());
        if let Ok((_, s)) = t.eval(x, &state) {
            state = s;
        }
        let _ = t.eval_at_load(x);
    }
    for c in [Control::Load, Control::Displacement] {
        let _ = t.pull_off_force(c);
    }
    let _ = t.length_scale();
    let _ = t.to_json();
}

fn probe_friction(f: &HomogenisedFriction) {
    let mut ps: Vec<f64> = SPECIAL.to_vec();
    if let (Some(a), Some(b)) = (f.samples().first(), f.samples().last()) {
        ps.extend([
            a.pressure,
            b.pressure,
            0.5 * (a.pressure + b.pressure),
            2.0 * b.pressure,
        ]);
    }
    let Ok(law) = f.clone().with_stick_stiffness(1e6) else {
        panic!("a stick stiffness of 1e6 N/m refused");
    };
    let mut work = law.work();
    let mut state = vec![0.0; law.state_len()];
    let mut new = state.clone();
    for &p in &ps {
        let _ = f.sample_at(p);
        let _ = f.cof_slope(p);
        for slip in [0.0, 1e-9, -1e-6, 1.0] {
            let inc = FrictionIncrement {
                normal_force: p,
                area: 1.0,
                slip: [slip, -0.5 * slip],
                dt: 1e-3,
                tangents: 3,
                ..Default::default()
            };
            if law.step(&state, &mut new, &inc, &mut work).is_ok() {
                state.copy_from_slice(&new);
            }
            let _ = law.step_in_place(&mut state.clone(), &inc, &mut work);
        }
    }
    let _ = f.to_json();
}

pub fn run(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(t) = TabulatedLaw::from_json(text) {
        probe_law(&t);
    }
    if let Ok(f) = HomogenisedFriction::from_json(text) {
        probe_friction(&f);
    }
    if let Ok(g) = SliderGeometry::from_json(text) {
        let _ = g.nano_total();
        for l in g.levels() {
            for k in 0..l.len().min(4) {
                let _ = (l.left(k), l.center(k));
            }
        }
        let _ = g.to_json();
    }
    if let Ok(c) = EquilibriumCurve::from_json(text) {
        let _ = c.to_json();
    }
}
