//! Multi-asperity statistics (`src/ffi/statistics/`): Greenwood–Williamson
//! (parametric and empirical surfaces), plasticity index, deformation
//! regime, Zhuravlev, Bush–Gibson–Thomas, Bora et al., Borodich–Kryukova,
//! Sergienko–Bukharov.

use super::common::*;
use super::{pick, take, Ctx, Op};
use arbitrary::Arbitrary;
use asperity::ffi::statistics::*;
use std::ffi::c_void;
use std::ptr::{null, null_mut};

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::Gw { gw, x, nulls } => {
            let g = gw.get();
            let mut out: AsperityGwResponse = zeroed();
            ok(
                asperity_gw_eval(cp(&g, nulls.at(0)), x.0, mp(&mut out, nulls.at(1))),
                "gw_eval",
            );
        }
        Op::GwBatch {
            gw,
            x,
            nulls,
            alias,
        } => {
            let g = gw.get();
            let mut xs: Vec<f64> = x.iter().take(256).map(|f| f.0).collect();
            let n = xs.len();
            let (mut l, mut a, mut c, mut k) =
                (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            let xp = bufm(&mut xs, nulls.at(1));
            let lp = if *alias {
                xp
            } else {
                bufm(&mut l, nulls.at(2))
            };
            let s = asperity_gw_eval_batch(
                cp(&g, nulls.at(0)),
                n,
                xp,
                lp,
                bufm(&mut a, nulls.at(3)),
                bufm(&mut c, nulls.at(4)),
                bufm(&mut k, nulls.at(5)),
            );
            ok(s, "gw_eval_batch");
        }
        Op::GwAtLoad { gw, load, nulls } => {
            let g = gw.get();
            let mut out: AsperitySeparation = zeroed();
            ok(
                asperity_gw_separation_at_load(
                    cp(&g, nulls.at(0)),
                    load.0,
                    mp(&mut out, nulls.at(1)),
                ),
                "gw_separation_at_load",
            );
        }
        Op::GwPlasticity {
            gw,
            hardness,
            nulls,
        } => {
            let g = gw.get();
            let mut out = 0.0;
            ok(
                asperity_gw_plasticity_index(
                    cp(&g, nulls.at(0)),
                    hardness.0,
                    mp(&mut out, nulls.at(1)),
                ),
                "gw_plasticity_index",
            );
        }
        Op::Plasticity { a, null } => {
            let [a0, a1, a2, a3] = fs(*a);
            let mut out = 0.0;
            ok(
                asperity_plasticity_index(a0, a1, a2, a3, mp(&mut out, *null)),
                "plasticity_index",
            );
        }
        Op::Regime { psi, null } => {
            let mut out = 0i32;
            ok(
                asperity_deformation_regime(psi.0, mp(&mut out, *null)),
                "deformation_regime",
            );
        }
        Op::Bgt { p, which, x, nulls } => {
            let g = AsperityBgtParams {
                m0: p[0].0,
                m2: p[1].0,
                m4: p[2].0,
                e_star: p[3].0,
                nominal_area: p[4].0,
            };
            let d = x.first().map_or(0.0, |f| f.0);
            match which % 4 {
                0 => {
                    let mut out: AsperityBgtResponse = zeroed();
                    ok(
                        asperity_bgt_eval(cp(&g, nulls.at(0)), d, mp(&mut out, nulls.at(1))),
                        "bgt_eval",
                    );
                }
                1 => {
                    let mut xs: Vec<f64> = x.iter().take(16).map(|f| f.0).collect();
                    let n = xs.len();
                    let (mut a, mut c, mut k) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
                    let xp = bufm(&mut xs, nulls.at(1));
                    let s = asperity_bgt_eval_batch(
                        cp(&g, nulls.at(0)),
                        n,
                        xp,
                        xp,
                        bufm(&mut a, nulls.at(2)),
                        bufm(&mut c, nulls.at(3)),
                        bufm(&mut k, nulls.at(4)),
                    );
                    ok(s, "bgt_eval_batch");
                }
                2 => {
                    let mut out: AsperitySeparation = zeroed();
                    ok(
                        asperity_bgt_separation_at_load(
                            cp(&g, nulls.at(0)),
                            d,
                            mp(&mut out, nulls.at(1)),
                        ),
                        "bgt_separation_at_load",
                    );
                }
                _ => {
                    let (mut dens, mut ratio) = (0.0, 0.0);
                    ok(
                        asperity_bgt_properties(
                            cp(&g, nulls.at(0)),
                            mp(&mut dens, nulls.at(1)),
                            mp(&mut ratio, nulls.at(2)),
                        ),
                        "bgt_properties",
                    );
                }
            }
        }
        Op::Bora {
            a,
            nx,
            heights,
            nulls,
        } => {
            // A small map: the solve costs (nx·ny)² per iteration.
            let mut h = heights.make();
            h.truncate(64);
            let nx = (*nx as usize % 8).max(1);
            let ny = h.len() / nx;
            h.truncate(nx * ny);
            let mut out = null_mut();
            let s = asperity_bora_new(
                nx,
                ny,
                a[0].0,
                bufp(&h, nulls.at(0)),
                a[1].0,
                a[2].0,
                mp(&mut out, nulls.at(1)),
            );
            if ok(s, "bora_new") && !out.is_null() {
                let mut r: AsperityBoraResponse = zeroed();
                let mut f = vec![0.0; nx * ny];
                ok(
                    asperity_bora_solve(
                        out,
                        a[3].0,
                        mp(&mut r, nulls.at(2)),
                        bufm(&mut f, nulls.at(3)),
                    ),
                    "bora_solve",
                );
                let mut sep: AsperitySeparation = zeroed();
                ok(
                    asperity_bora_separation_at_load(out, a[3].0, mp(&mut sep, nulls.at(4))),
                    "bora_separation_at_load",
                );
                asperity_bora_free(out);
            }
            asperity_bora_free(null_mut());
        }
        Op::BorodichKryukova {
            a,
            nodes,
            start,
            dt,
            steps,
            every,
            room,
            nulls,
        } => {
            let v = fs(*a);
            let b = AsperityBorodichKryukova {
                half_length: v[0],
                mass: v[1],
                belt_speed: v[2],
                spring_stiffness: v[3],
                layer_stiffness: v[4],
                friction_coefficient: v[5],
                gravity: v[6],
                sign_speed: v[7],
                slider_amplitude: v[8],
                slider_wavelength: v[9],
                belt_amplitude: v[10],
                belt_wavelength: v[11],
                // At most 2047 cells (0: invalid), or the invalid 100001.
                nodes: if *nodes == u16::MAX {
                    100_001
                } else {
                    u32::from(*nodes % 2048)
                },
                reserved: 0,
            };
            let [t, x, vx, y, vy] = fs(*start);
            let st = AsperityBorodichKryukovaState {
                time: t,
                x,
                vx,
                y,
                vy,
            };
            let mut f = 0.0;
            ok(
                asperity_borodich_kryukova_normal_force(
                    cp(&b, nulls.at(0)),
                    x,
                    y,
                    t,
                    mp(&mut f, nulls.at(1)),
                ),
                "borodich_kryukova_normal_force",
            );
            let steps = u32::from(*steps);
            let every = u32::from(*every % 8);
            // every = 0 is refused: room for one sample then.
            let want = steps.checked_div(every).map_or(1, |k| k as usize + 1);
            let cap = match room % 4 {
                0 => want - 1,
                1 => want + 3,
                _ => want,
            };
            let mut out = vec![AsperityBorodichKryukovaSample::default(); cap];
            let mut written = usize::MAX;
            let o = if nulls.at(3) {
                null_mut()
            } else {
                out.as_mut_ptr()
            };
            let s = asperity_borodich_kryukova_run(
                cp(&b, nulls.at(2)),
                cp(&st, nulls.at(4)),
                dt.0,
                steps,
                every,
                cap,
                o,
                mp(&mut written, nulls.at(5)),
            );
            if ok(s, "borodich_kryukova_run") {
                if !nulls.at(5) {
                    assert_eq!(written, want);
                }
                for r in &out[..want] {
                    assert!(r.state.x.is_finite() && r.normal_force >= 0.0, "{r:?}");
                }
            } else {
                assert_eq!(written, usize::MAX, "a failed run wrote `written`");
            }
        }
        Op::SergienkoBukharov {
            a,
            distribution,
            periods,
            heights,
            nulls,
        } => {
            // A bounded run: few periods, a small step budget.
            let mut h = heights.make();
            h.truncate(256);
            let p = AsperitySergienkoBukharovParams {
                distribution: distribution.0 % 3,
                transient_periods: periods[0] as u32 % 4,
                average_periods: periods[1] as u32 % 4,
                steps_per_natural_period: 8 + periods[2] as u32 % 64,
                rod_count: a[0].0,
                sigma: a[1].0,
                rod_stiffness: a[2].0,
                rod_area: a[3].0,
                mass: a[4].0,
                load: a[5].0,
                damping_ratio: a[6].0,
                friction_coefficient: a[7].0,
                attractive_pressure: a[8].0,
                force_amplitude: a[9].0,
                frequency: a[10].0,
                tangential_impulse: a[11].0,
                slope: a[12].0,
                initial_offset: a[13].0,
                max_steps: 20_000,
            };
            let mut out: AsperitySergienkoBukharovResult = zeroed();
            ok(
                asperity_sergienko_bukharov_run(
                    cp(&p, nulls.at(0)),
                    bufp(&h, nulls.at(1)),
                    h.len(),
                    mp(&mut out, nulls.at(2)),
                ),
                "sergienko_bukharov_run",
            );
        }
        Op::GwEmpiricalNew {
            a,
            heights,
            radii,
            nulls,
        } => {
            let h = heights.make();
            let n = h.len();
            let r: Option<Vec<f64>> = radii
                .as_ref()
                .map(|r| (0..n).map(|i| r.get(i).map_or(1e-6, |f| f.0)).collect());
            let mut out = null_mut();
            let s = asperity_gw_empirical_new(
                a[0].0,
                a[1].0,
                a[2].0,
                n,
                bufp(&h, nulls.at(0)),
                r.as_ref().map_or(null(), |r| r.as_ptr()),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(g) = made(s, out, !nulls.at(1), "gw_empirical_new") {
                ctx.gws.push(g);
            }
        }
        Op::GwEmpirical {
            gw,
            which,
            x,
            n,
            nulls,
        } => {
            let g = pick(&ctx.gws, *gw);
            match which % 4 {
                0 => {
                    let mut out: AsperityGwResponse = zeroed();
                    ok(
                        asperity_gw_empirical_eval(g, x.0, mp(&mut out, nulls.at(0))),
                        "gw_emp_eval",
                    );
                }
                1 => {
                    let xs: Vec<f64> = n.iter().take(256).map(|f| f.0).collect();
                    let k = xs.len();
                    let (mut l, mut a, mut c, mut st) =
                        (vec![0.0; k], vec![0.0; k], vec![0.0; k], vec![0.0; k]);
                    let s = asperity_gw_empirical_eval_batch(
                        g,
                        k,
                        bufp(&xs, nulls.at(0)),
                        bufm(&mut l, nulls.at(1)),
                        bufm(&mut a, nulls.at(2)),
                        bufm(&mut c, nulls.at(3)),
                        bufm(&mut st, nulls.at(4)),
                    );
                    ok(s, "gw_emp_eval_batch");
                }
                2 => {
                    let mut out: AsperitySeparation = zeroed();
                    ok(
                        asperity_gw_empirical_separation_at_load(g, x.0, mp(&mut out, nulls.at(0))),
                        "gw_emp_separation_at_load",
                    );
                }
                _ => {
                    let mut out = 0.0;
                    ok(
                        asperity_gw_empirical_plasticity_index(g, x.0, mp(&mut out, nulls.at(0))),
                        "gw_emp_plasticity_index",
                    );
                }
            }
        }
        Op::GwEmpiricalFree { gw } => {
            if let Some(g) = take(&mut ctx.gws, *gw) {
                asperity_gw_empirical_free(g);
            } else {
                asperity_gw_empirical_free(null_mut());
            }
        }
        Op::Zhuravlev {
            model,
            which,
            a,
            nulls,
        } => {
            let m = fs(*model);
            let z = AsperityZhuravlev {
                cap_radius: m[0],
                effective_radius: m[1],
                e_star: m[2],
                summit_count: m[3],
            };
            let zp = cp(&z, nulls.at(0));
            let [a0, a1, a2, a3] = fs(*a);
            let s = match which % 3 {
                0 => {
                    let mut out: AsperityZhuravlevResponse = zeroed();
                    asperity_zhuravlev_linear(zp, a0, a1, a2, mp(&mut out, nulls.at(1)))
                }
                1 => {
                    let mut out = 0.0;
                    asperity_zhuravlev_approach_at_load_linear(
                        zp,
                        a0,
                        a1,
                        a2,
                        mp(&mut out, nulls.at(1)),
                    )
                }
                _ => {
                    let mut out: AsperityZhuravlevFriction = zeroed();
                    asperity_zhuravlev_friction_linear(
                        zp,
                        a0,
                        a1,
                        a2,
                        a3,
                        mp(&mut out, nulls.at(1)),
                    )
                }
            };
            ok(s, "zhuravlev");
        }
        Op::ZhuravlevEval {
            model,
            approach,
            n1,
            n2,
            order,
            nulls,
        } => {
            let m = fs(*model);
            let z = AsperityZhuravlev {
                cap_radius: m[0],
                effective_radius: m[1],
                e_star: m[2],
                summit_count: m[3],
            };
            let mut d1 = n1.1 .0;
            let mut d2 = n2.1 .0;
            let mut out: AsperityZhuravlevResponse = zeroed();
            let s = asperity_zhuravlev_eval(
                cp(&z, nulls.at(0)),
                approach.0,
                density(n1.0),
                &mut d1 as *mut f64 as *mut c_void,
                density(n2.0),
                &mut d2 as *mut f64 as *mut c_void,
                order.0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "zhuravlev_eval");
        }
        _ => unreachable!("not a statistics operation: {op:?}"),
    }
}

#[derive(Debug, Clone, Arbitrary)]
pub struct GwSpec {
    distribution: Sel,
    v: [F; 4],
}

impl GwSpec {
    fn get(&self) -> AsperityGwParams {
        AsperityGwParams {
            distribution: self.distribution.0,
            reserved: 0,
            summit_count: self.v[0].0,
            radius: self.v[1].0,
            sigma: self.v[2].0,
            e_star: self.v[3].0,
        }
    }
}

pub(super) unsafe extern "C" fn density_const(_xi: f64, data: *mut c_void) -> f64 {
    *(data as *const f64)
}

pub(super) unsafe extern "C" fn density_linear(xi: f64, data: *mut c_void) -> f64 {
    *(data as *const f64) * xi
}

pub(super) unsafe extern "C" fn density_step(xi: f64, data: *mut c_void) -> f64 {
    if xi < *(data as *const f64) {
        0.0
    } else {
        1e12
    }
}

pub(super) fn density(sel: u8) -> AsperitySummitDensity {
    match sel % 4 {
        0 => None,
        1 => Some(density_const),
        2 => Some(density_linear),
        _ => Some(density_step),
    }
}
