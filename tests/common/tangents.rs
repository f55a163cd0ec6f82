//! The consistent tangents of a friction law against central finite
//! differences of its own step from the same old state (issue 32: an
//! implicit host builds its Jacobian from them). Included with
//! `#[path = "common/tangents.rs"] mod tangents;` by the friction tests
//! that use it.
//!
//! [`fd_check`] steps the increment with both tangents asked, then the
//! increment with N ± h_N and with each slip component ± h_s, and compares
//! ∂F/∂N and ∂F_a/∂Δs_b with the central differences
//! (F(x + h) − F(x − h))/2h, to [`TOL`] of the tangent's size. A kink
//! within the step (a stick–slip switch, an element that starts or stops
//! slipping, the end of a table) makes the difference meaningless there:
//! it is recognised, and that derivative skipped, when the regime at x ± h
//! differs from the one at x, or when the one-sided differences
//! (F(x + h) − F(x))/h and (F(x) − F(x − h))/h disagree by more than
//! [`TOL`] of the largest of them (a smooth F makes them differ by h|F''|,
//! far less with the step sizes the tests choose: 1e-7 of the length over
//! which the force turns). Below N = 2h_N, the derivative in N is the
//! second-order forward difference (−3F(N) + 4F(N + h) − F(N + 2h))/2h
//! (N ≥ 0), a kink recognised when it disagrees with the first-order one.

#![allow(dead_code)]

use asperity::friction::{
    FrictionIncrement, FrictionLaw, FrictionResponse, TANGENT_NORMAL, TANGENT_SLIP,
};

/// Relative agreement asked of a tangent and its finite difference.
pub const TOL: f64 = 1e-6;

/// What [`fd_check`] compared: the largest relative error of ∂F/∂Δs and of
/// ∂F/∂N, or None when a kink within the step made the difference
/// meaningless.
#[derive(Debug, Clone, Copy)]
pub struct Fd {
    pub slip: Option<f64>,
    pub normal: Option<f64>,
    /// The response of the increment itself (both tangents asked).
    pub response: FrictionResponse,
}

impl Fd {
    /// Both derivatives were compared.
    pub fn both(&self) -> bool {
        self.slip.is_some() && self.normal.is_some()
    }
}

/// The force and regime of `inc` stepped from `old`.
fn force(law: &dyn FrictionLaw, old: &[f64], inc: &FrictionIncrement) -> ([f64; 2], i32) {
    let mut new = vec![0.0; law.state_len()];
    let r = law
        .step(old, &mut new, inc, &mut law.work())
        .unwrap_or_else(|e| panic!("{e}: {inc:?}"));
    (r.force, r.regime)
}

fn max_abs(v: impl IntoIterator<Item = f64>) -> f64 {
    v.into_iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// Compares the tangents `law` returns for `inc` from `old` with central
/// differences of steps `h_normal` (N) and `h_slip` (m), asserting
/// agreement to [`TOL`] of the larger of the tangent and its difference
/// (the matrix's largest entry for ∂F/∂Δs, |F|/N at least for ∂F/∂N)
/// wherever no kink lies within the step. `what` names the point in the
/// messages.
#[track_caller]
pub fn fd_check(
    law: &dyn FrictionLaw,
    old: &[f64],
    inc: &FrictionIncrement,
    h_normal: f64,
    h_slip: f64,
    what: &str,
) -> Fd {
    fd_check_columns(law, old, inc, h_normal, h_slip, what, 2)
}

/// [`fd_check`] for a one-dimensional law (one that refuses `slip[1]` ≠ 0):
/// ∂F/∂Δs_x only (the column along the track).
#[track_caller]
pub fn fd_check_track(
    law: &dyn FrictionLaw,
    old: &[f64],
    inc: &FrictionIncrement,
    h_normal: f64,
    h_slip: f64,
    what: &str,
) -> Fd {
    fd_check_columns(law, old, inc, h_normal, h_slip, what, 1)
}

#[track_caller]
fn fd_check_columns(
    law: &dyn FrictionLaw,
    old: &[f64],
    inc: &FrictionIncrement,
    h_normal: f64,
    h_slip: f64,
    what: &str,
    columns: usize,
) -> Fd {
    let asked = FrictionIncrement {
        tangents: TANGENT_NORMAL | TANGENT_SLIP,
        ..*inc
    };
    let mut new = vec![0.0; law.state_len()];
    let r = law.step(old, &mut new, &asked, &mut law.work()).unwrap();
    assert_eq!(
        r.tangents & (TANGENT_NORMAL | TANGENT_SLIP),
        TANGENT_NORMAL | TANGENT_SLIP,
        "{what}: tangents asked, not computed: {r:?}"
    );
    let f0 = r.force;
    let at = |dn: f64, ds: [f64; 2]| {
        let i = FrictionIncrement {
            normal_force: inc.normal_force + dn,
            slip: [inc.slip[0] + ds[0], inc.slip[1] + ds[1]],
            ..*inc
        };
        force(law, old, &i)
    };
    // ∂F/∂Δs, column b; one-sided differences for the kink test.
    let mut fd = [[0.0; 2]; 2];
    let (mut fwd, mut bwd) = ([[0.0; 2]; 2], [[0.0; 2]; 2]);
    let mut smooth = true;
    for b in 0..columns {
        let mut e = [0.0; 2];
        e[b] = h_slip;
        let (fp, rp) = at(0.0, e);
        let (fm, rm) = at(0.0, [-e[0], -e[1]]);
        smooth &= rp == r.regime && rm == r.regime;
        for a in 0..2 {
            fd[a][b] = (fp[a] - fm[a]) / (2.0 * h_slip);
            fwd[a][b] = (fp[a] - f0[a]) / h_slip;
            bwd[a][b] = (f0[a] - fm[a]) / h_slip;
        }
    }
    let scale = max_abs(fwd.iter().chain(&bwd).flatten().copied()).max(1e-300);
    let kink = max_abs((0..4).map(|k| fwd[k / 2][k % 2] - bwd[k / 2][k % 2]));
    smooth &= kink <= TOL * scale;
    let slip = smooth.then(|| {
        let mut t = r.dforce_dslip;
        if columns == 1 {
            t[0][1] = 0.0;
            t[1][1] = 0.0;
        }
        let scale = max_abs(t.iter().chain(&fd).flatten().copied()).max(1e-300);
        let err = max_abs((0..4).map(|k| t[k / 2][k % 2] - fd[k / 2][k % 2])) / scale;
        assert!(
            err <= TOL,
            "{what}: dF/dslip = {t:?}, central differences {fd:?} (relative error {err:e}, {:?}, h = {h_slip:e} m)",
            r.regime()
        );
        err
    });
    // ∂F/∂N.
    let n = inc.normal_force;
    let (dn, smooth) = if n >= 2.0 * h_normal {
        let ((fp, rp), (fm, rm)) = (at(h_normal, [0.0; 2]), at(-h_normal, [0.0; 2]));
        let d = [0, 1].map(|a| (fp[a] - fm[a]) / (2.0 * h_normal));
        let fwd = [0, 1].map(|a| (fp[a] - f0[a]) / h_normal);
        let bwd = [0, 1].map(|a| (f0[a] - fm[a]) / h_normal);
        let scale = max_abs(fwd.into_iter().chain(bwd)).max(1e-300);
        let kink = max_abs([fwd[0] - bwd[0], fwd[1] - bwd[1]]);
        (d, rp == r.regime && rm == r.regime && kink <= TOL * scale)
    } else {
        // One-sided: N ≥ 0.
        let ((f1, r1), (f2, r2)) = (at(h_normal, [0.0; 2]), at(2.0 * h_normal, [0.0; 2]));
        let d = [0, 1].map(|a| (-3.0 * f0[a] + 4.0 * f1[a] - f2[a]) / (2.0 * h_normal));
        let first = [0, 1].map(|a| (f1[a] - f0[a]) / h_normal);
        let scale = max_abs(first.into_iter().chain(d)).max(1e-300);
        let kink = max_abs([first[0] - d[0], first[1] - d[1]]);
        (d, r1 == r2 && kink <= TOL * scale)
    };
    let normal = smooth.then(|| {
        let t = r.dforce_dnormal;
        let floor = if n > 0.0 { max_abs(f0) / n } else { 0.0 };
        let scale = max_abs(t.into_iter().chain(dn)).max(floor).max(1e-300);
        let err = max_abs([t[0] - dn[0], t[1] - dn[1]]) / scale;
        assert!(
            err <= TOL,
            "{what}: dF/dN = {t:?}, finite differences {dn:?} (relative error {err:e}, {:?}, h = {h_normal:e} N)",
            r.regime()
        );
        err
    });
    Fd {
        slip,
        normal,
        response: r,
    }
}
