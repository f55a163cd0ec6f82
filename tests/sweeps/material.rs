//! The scalar functions of `src/ffi/material.rs`, swept by `scalars`.

use super::scalars::*;
use super::*;
use asperity::ffi::material::*;
use asperity::material as m;

/// The material functions, in the order they are swept.
pub(crate) fn scalars() -> Vec<Scalar> {
    vec![
        Scalar {
            name: "asperity_effective_modulus",
            args: vec![MOD_E, POISSON1, MOD_E, POISSON2],
            sel: None,
            c: |v, _, o| unsafe { asperity_effective_modulus(v[0], v[1], v[2], v[3], o) },
            rust: |v, _| m::effective_modulus(v[0], v[1], v[2], v[3]),
            combination: |v| (v[0].is_infinite() && v[2].is_infinite()).then_some(&["e2"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, 1.0)),
        },
        Scalar {
            name: "asperity_rod_effective_modulus",
            args: vec![MOD_E, MOD_E],
            sel: None,
            c: |v, _, o| unsafe { asperity_rod_effective_modulus(v[0], v[1], o) },
            rust: |v, _| m::rod_effective_modulus(v[0], v[1]),
            combination: |v| (v[0].is_infinite() && v[1].is_infinite()).then_some(&["e2"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, 1.0)),
        },
        Scalar {
            name: "asperity_no_slip_factor",
            args: vec![NU],
            sel: None,
            c: |v, _, o| unsafe { asperity_no_slip_factor(v[0], o) },
            rust: |v, _| m::no_slip_factor(v[0]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: None, // ν scaled multiplicatively would leave [0, 0.5]; see switches test
        },
        Scalar {
            name: "asperity_tabor_parameter",
            args: vec![RADIUS, W0, E_STAR, Z0_EQ],
            sel: None,
            c: |v, _, o| unsafe { asperity_tabor_parameter(v[0], v[1], v[2], v[3], o) },
            rust: |v, _| m::tabor_parameter(v[0], v[1], v[2], v[3]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, 1.0)),
        },
        Scalar {
            name: "asperity_maugis_parameter",
            args: vec![RADIUS, W, E_STAR, COHESIVE],
            sel: None,
            c: |v, _, o| unsafe { asperity_maugis_parameter(v[0], v[1], v[2], v[3], o) },
            rust: |v, _| m::maugis_parameter(v[0], v[1], v[2], v[3]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_weir_surface_energy_with",
            args: vec![
                arg(&["atomic_mass"], Dom::Pos, 1e-27, 1e-24),
                arg(&["density"], Dom::Pos, 1e2, 3e4),
                arg(&["youngs_modulus"], Dom::Pos, 1e9, 1.2e12),
                arg(&["poisson_ratio"], Dom::HalfOpen(0.0, 0.5), 0.0, 0.499),
                arg(&["m"], Dom::Gt(2.0), 2.5, 12.0),
                arg(&["n"], Dom::Gt(2.0), 6.0, 24.0),
            ],
            sel: Some((
                "prefactor",
                &[ASPERITY_WEIR_PLANE_SUM, ASPERITY_WEIR_THREE_OVER_MN],
            )),
            c: |v, s, o| unsafe {
                asperity_weir_surface_energy_with(v[0], v[1], v[2], v[3], v[4], v[5], s, o)
            },
            rust: |v, s| {
                let k = if s == ASPERITY_WEIR_PLANE_SUM {
                    m::WeirPrefactor::PlaneSum
                } else {
                    m::WeirPrefactor::ThreeOverMn
                };
                if s != ASPERITY_WEIR_PLANE_SUM && s != ASPERITY_WEIR_THREE_OVER_MN {
                    return Err(asperity::Error::UnknownSelector {
                        name: "prefactor",
                        value: s as i64,
                    });
                }
                m::weir_surface_energy(v[0], v[1], v[2], v[3], v[4], v[5], k)
            },
            combination: |v| (v[5] <= v[4]).then_some(&["n"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((2, 1.0)),
        },
        Scalar {
            name: "asperity_pair_work_of_adhesion",
            args: vec![GAMMA, GAMMA],
            sel: Some((
                "rule",
                &[
                    ASPERITY_PAIR_GEOMETRIC_MEAN,
                    ASPERITY_PAIR_SEED001_DIFFERENCE,
                ],
            )),
            c: |v, s, o| unsafe { asperity_pair_work_of_adhesion(v[0], v[1], s, o) },
            rust: |v, s| {
                let rule = match s {
                    ASPERITY_PAIR_GEOMETRIC_MEAN => m::PairRule::GeometricMean,
                    ASPERITY_PAIR_SEED001_DIFFERENCE => m::PairRule::Seed001Difference,
                    v => {
                        return Err(asperity::Error::UnknownSelector {
                            name: "rule",
                            value: v as i64,
                        })
                    }
                };
                m::pair_work_of_adhesion(v[0], v[1], rule)
            },
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: None,
        },
        Scalar {
            name: "asperity_hamaker_work_of_adhesion",
            args: vec![HAMAKER, SEPARATION],
            sel: None,
            c: |v, _, o| unsafe { asperity_hamaker_work_of_adhesion(v[0], v[1], o) },
            rust: |v, _| m::hamaker_work_of_adhesion(v[0], v[1]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, -1.0)),
        },
    ]
}
