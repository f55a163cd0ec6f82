//! Borodich & Kryukova (1997), thesis §5.3.7: the block on a moving belt
//! with elastic rough layers. On flat profiles the closed forms of the
//! module docs (rest height, vertical frequency, the sliding response
//! x*(1 − cos ω_x t)); on sinusoidal profiles the time-averaged normal force
//! balances the weight and nothing damps the vertical motion.

use asperity::statistics::{BorodichKryukova, Sinusoid, SliderState};
use asperity::Error;
use core::f64::consts::TAU;

fn flat() -> BorodichKryukova {
    BorodichKryukova {
        half_length: 0.01,
        mass: 1.0,
        belt_speed: 0.1,
        spring_stiffness: 1e3,
        layer_stiffness: 5e8,
        friction_coefficient: 0.3,
        gravity: 9.81,
        sign_speed: 1e-4,
        slider: Sinusoid {
            amplitude: 0.0,
            wavelength: 1e-3,
        },
        belt: Sinusoid {
            amplitude: 0.0,
            wavelength: 1e-3,
        },
        nodes: 200,
    }
}

#[test]
fn flat_profiles_follow_the_closed_forms() {
    let m = flat();
    let k_layer = 2.0 * m.half_length * m.layer_stiffness;
    let y_rest = -m.mass * m.gravity / k_layer;
    assert!((m.normal_force(0.0, y_rest, 0.0) / (m.mass * m.gravity) - 1.0).abs() < 1e-12);
    // Sliding from rest at the rest height: x = x*(1 − cos ω_x t), y = y*.
    let x_star = m.friction_coefficient * m.mass * m.gravity / m.spring_stiffness;
    let wx = (m.spring_stiffness / m.mass).sqrt();
    assert!(x_star * wx < m.belt_speed, "the block must keep sliding");
    let start = SliderState {
        y: y_rest,
        ..Default::default()
    };
    let dt = 1e-5;
    let run = m.run(start, dt, 30_000, 100).unwrap();
    for s in &run {
        let want = x_star * (1.0 - (wx * s.state.time).cos());
        assert!(
            (s.state.x - want).abs() < 1e-9 * x_star.max(1.0),
            "t {}: {} vs {want}",
            s.state.time,
            s.state.x
        );
        assert!((s.state.y - y_rest).abs() < 1e-12 * y_rest.abs());
    }
    // Vertical oscillation from 1 % below rest (always in contact): period
    // 2π/√(2aε/M), no decay (nothing dissipates vertically).
    let wy = (k_layer / m.mass).sqrt();
    let start = SliderState {
        y: 1.01 * y_rest,
        ..Default::default()
    };
    let dt = 0.005 / wy;
    let steps = (5.0 * TAU / wy / dt).round() as u32;
    let run = m.run(start, dt, steps, 1).unwrap();
    for s in &run {
        let want = y_rest + 0.01 * y_rest * (wy * s.state.time).cos();
        assert!(
            (s.state.y - want).abs() < 1e-8 * y_rest.abs(),
            "t {}",
            s.state.time
        );
    }
}

#[test]
fn sinusoidal_profiles_carry_the_weight_on_average() {
    // Mean of M ÿ over a long run is (v_y(end) − v_y(0))/T → 0: the
    // time-averaged normal force equals Mg within that bound.
    let mut m = flat();
    m.slider = Sinusoid {
        amplitude: 2e-7,
        wavelength: 1e-3,
    };
    m.belt = Sinusoid {
        amplitude: 3e-7,
        wavelength: 0.7e-3,
    };
    let y0 = m.slider.amplitude + m.belt.amplitude - 2e-7;
    let start = SliderState {
        y: y0,
        ..Default::default()
    };
    let dt = 4e-6;
    let steps = 50_000;
    m.nodes = 100;
    let run = m.run(start, dt, steps, 1).unwrap();
    // Trapezoidal time average of the normal force.
    let total = dt * steps as f64;
    let mut avg = 0.0;
    for w in run.windows(2) {
        avg += 0.5 * dt * (w[0].normal_force + w[1].normal_force);
    }
    avg /= total;
    let end = run.last().unwrap().state;
    let bound = m.mass * (end.vy - 0.0).abs() / total + 1e-6 * m.mass * m.gravity;
    assert!(
        (avg - m.mass * m.gravity).abs() <= bound + 1e-3 * m.mass * m.gravity,
        "{avg} vs {}",
        m.mass * m.gravity
    );
    // The vertical motion does not die out: y keeps moving over the last
    // tenth of the run.
    let tail = &run[run.len() * 9 / 10..];
    let (lo, hi) = tail
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| {
            (a.min(s.state.y), b.max(s.state.y))
        });
    assert!(hi - lo > 1e-9, "{lo} {hi}");
    assert!(run
        .iter()
        .all(|s| s.state.x.is_finite() && s.normal_force >= 0.0));
}

#[test]
fn errors_name_the_argument() {
    let mut m = flat();
    m.mass = -1.0;
    assert!(matches!(
        m.run(SliderState::default(), 1e-5, 1, 1),
        Err(Error::InvalidArgument { name: "mass", .. })
    ));
    let mut m = flat();
    m.nodes = 0;
    assert!(matches!(
        m.validate(),
        Err(Error::InvalidArgument { name: "nodes", .. })
    ));
    let m = flat();
    assert!(matches!(
        m.run(SliderState::default(), 0.0, 1, 1),
        Err(Error::InvalidArgument { name: "dt", .. })
    ));
    assert!(matches!(
        m.run(SliderState::default(), 1e-5, 1, 0),
        Err(Error::InvalidArgument { name: "every", .. })
    ));
    let s = SliderState {
        y: f64::NAN,
        ..Default::default()
    };
    assert!(matches!(
        m.run(s, 1e-5, 1, 1),
        Err(Error::InvalidArgument {
            name: "start.y",
            ..
        })
    ));
}
