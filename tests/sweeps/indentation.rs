//! The rescaling and hardness functions of `src/ffi/indentation.rs`, swept
//! by `scalars`.

use super::scalars::*;
use super::*;
use asperity::ffi::indentation::*;
use asperity::rescaling as rs;

/// The rescaling and hardness functions, in the order they are swept.
pub(crate) fn scalars() -> Vec<Scalar> {
    vec![
        Scalar {
            name: "asperity_rescaling_depth",
            args: vec![KAPPA, D, LAMBDA, LOAD, KNOWN_LOAD, KNOWN_DEPTH],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_depth(v[0], v[1], v[2], v[3], v[4], v[5], o) },
            rust: |v, _| {
                let k = rs::KnownSolution::new(v[4], v[5], 1.0)?;
                rs::Rescaling::new(v[0], v[1])?.depth(v[2], v[3], &k)
            },
            combination: no_combination,
            overflow_ok: true,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_radius",
            args: vec![KAPPA, D, LAMBDA, LOAD, KNOWN_LOAD, KNOWN_RADIUS],
            sel: None,
            c: |v, _, o| unsafe {
                asperity_rescaling_radius(v[0], v[1], v[2], v[3], v[4], v[5], o)
            },
            rust: |v, _| {
                let k = rs::KnownSolution::new(v[4], 1.0, v[5])?;
                rs::Rescaling::new(v[0], v[1])?.radius(v[2], v[3], &k)
            },
            combination: no_combination,
            overflow_ok: true,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_load",
            args: vec![KAPPA, D, LAMBDA, DEPTH, KNOWN_LOAD, KNOWN_DEPTH],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_load(v[0], v[1], v[2], v[3], v[4], v[5], o) },
            rust: |v, _| {
                let k = rs::KnownSolution::new(v[4], v[5], 1.0)?;
                rs::Rescaling::new(v[0], v[1])?.load(v[2], v[3], &k)
            },
            combination: no_combination,
            overflow_ok: true,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_lambda_spheres",
            args: vec![KNOWN_RADIUS, arg(&["radius"], Dom::Pos, 1e-9, 1e-3)],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_lambda_spheres(v[0], v[1], o) },
            rust: |v, _| rs::lambda_spheres(v[0], v[1]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, -1.0)),
        },
        Scalar {
            name: "asperity_rescaling_lambda_cones",
            args: vec![ANGLE, ANGLE],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_lambda_cones(v[0], v[1], o) },
            rust: |v, _| rs::lambda_cones(v[0], v[1]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_kappa_from_slope",
            args: vec![SLOPE, arg(&["d"], Dom::Pos, 1.0, 100.0)],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_kappa_from_slope(v[0], v[1], o) },
            rust: |v, _| rs::kappa_from_loading_slope(v[0], v[1]),
            combination: |v| ((v[1] - 1.0).abs() < 1e-6).then_some(&["d"][..]),
            overflow_ok: false,
            nonneg: false,
            mono: None,
        },
        Scalar {
            name: "asperity_rescaling_d_from_unloading_slope",
            args: vec![SLOPE],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_d_from_unloading_slope(v[0], o) },
            rust: |v, _| rs::d_from_unloading_slope(v[0]),
            combination: |v| (v[0] <= 1.0).then_some(&["unloading_slope"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, -1.0)),
        },
        Scalar {
            name: "asperity_rescaling_d_from_loading_slope",
            args: vec![SLOPE, arg(&["kappa"], Dom::Finite, 0.1, 10.0)],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_d_from_loading_slope(v[0], v[1], o) },
            rust: |v, _| rs::d_from_loading_slope(v[0], v[1]),
            combination: |v| ((v[0] - v[1]).abs() < 1e-12).then_some(&["loading_slope"][..]),
            // (2 − κ)/(m − κ) with m − κ ≥ 1e-12 can exceed f64 for κ ~ 1e300.
            overflow_ok: false,
            nonneg: false,
            mono: None,
        },
        Scalar {
            name: "asperity_galanov_unloading_radius",
            args: vec![
                arg(&["r1"], Dom::Pos, 1e-9, 1e-3),
                arg(&["p1"], Dom::Pos, 1e-6, 1e2),
                arg(&["delta1"], Dom::Pos, 1e-9, 1e-3),
                arg(&["p2"], Dom::Pos, 1e-6, 1e2),
                arg(&["delta2"], Dom::Pos, 1e-9, 1e-3),
            ],
            sel: None,
            c: |v, _, o| unsafe {
                asperity_galanov_unloading_radius(v[0], v[1], v[2], v[3], v[4], o)
            },
            rust: |v, _| rs::galanov_unloading_radius(v[0], v[1], v[2], v[3], v[4]),
            combination: no_combination,
            // (P₂/P₁)²(δ₁/δ₂)³ spans 10^±(2·10 + 3·8) over the typical ranges.
            overflow_ok: false,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_galanov_medium_radius",
            args: vec![
                arg(&["radius"], Dom::Pos, 1e-9, 1e-3),
                arg(&["unloading_radius"], Dom::PosInf, 1e-9, 1e-3),
            ],
            sel: None,
            c: |v, _, o| unsafe { asperity_galanov_medium_radius(v[0], v[1], o) },
            rust: |v, _| rs::medium_radius(v[0], v[1]),
            combination: |v| (v[1] <= v[0]).then_some(&["unloading_radius"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, -1.0)),
        },
    ]
}
