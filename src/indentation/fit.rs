//! Power-law fits with standard errors: the loading branch as a straight line
//! in log–log coordinates (thesis (3-20), (3-26)), and the Oliver–Pharr
//! unloading law `P = α(h − h_f)^m` with the covariance of its parameters.

use crate::error::{check, Error, Result};
use serde::Serialize;

/// Where the log–log line is pinned.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Anchor {
    /// Through the maximum point of the fitted branch (thesis §3.6.1; default).
    MaxPoint,
    /// Through the given point of the curve (0-based index).
    Index {
        /// Index into the curve.
        index: usize,
    },
    /// No anchor: ordinary two-parameter regression of ln P on ln δ.
    Free,
}

/// A straight line in log–log coordinates, `ln P = ln P₁ + m ln(δ/δ₁)`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PowerLawFit {
    /// Slope m (dimensionless).
    pub slope: f64,
    /// Standard error of the slope.
    pub slope_stderr: f64,
    /// Depth δ₁ of the reference point (m): the anchor, or for a free fit the
    /// geometric mean of the depths.
    pub reference_depth: f64,
    /// Load at the reference depth on the line (N).
    pub reference_load: f64,
    /// Standard error of ln(reference_load) (0 when anchored).
    pub reference_log_load_stderr: f64,
    /// Coefficient of determination of ln P (centred total sum of squares).
    pub r_squared: f64,
    /// Residuals ln P − line, in the order of the fitted points.
    pub residuals: Vec<f64>,
    /// Points used.
    pub n_points: usize,
    /// Points of the window left out because depth or load was ≤ 0.
    pub n_excluded: usize,
    /// Whether the line was pinned to an anchor.
    pub anchored: bool,
}

/// Least-squares slope of ln P against ln δ (thesis (3-20), (3-26)); points with
/// non-positive depth or load are left out and counted. With an anchor
/// `(δ₁, P₁)` the line passes through it: `m = Σxy/Σx²` with
/// `x = ln(δ/δ₁)`, `y = ln(P/P₁)`, `se² = Σr²/((n−1)Σx²)`, at least 3 points
/// off the anchor. Without, ordinary regression, `se² = Σr²/((n−2)S_xx)`, at
/// least 3 points.
pub fn log_log_fit(depth: &[f64], load: &[f64], anchor: Option<(f64, f64)>) -> Result<PowerLawFit> {
    if depth.len() != load.len() {
        return Err(Error::InvalidArgument {
            name: "load",
            value: load.len() as f64,
            bound: "as many values as depth",
        });
    }
    let mut xs = Vec::with_capacity(depth.len());
    let mut ys = Vec::with_capacity(depth.len());
    let mut excluded = 0;
    for (&h, &p) in depth.iter().zip(load) {
        if h > 0.0 && p > 0.0 && h.is_finite() && p.is_finite() {
            xs.push(h.ln());
            ys.push(p.ln());
        } else {
            excluded += 1;
        }
    }
    let n = xs.len();
    let too_few = |need: usize| Error::OutOfDomain {
        name: "points",
        value: n as f64,
        reason: if need == 3 {
            "a log-log fit needs at least 3 points with positive depth and load"
        } else {
            "an anchored log-log fit needs at least 3 points off the anchor"
        },
    };
    let ybar = ys.iter().sum::<f64>() / n.max(1) as f64;
    let sst: f64 = ys.iter().map(|y| (y - ybar).powi(2)).sum();
    let fit = match anchor {
        Some((h1, p1)) => {
            let h1 = check::positive("anchor_depth", h1)?;
            let p1 = check::positive("anchor_load", p1)?;
            let (lx, ly) = (h1.ln(), p1.ln());
            let off = xs.iter().filter(|&&x| (x - lx).abs() > 1e-12).count();
            if off < 3 {
                return Err(too_few(4));
            }
            let sxx: f64 = xs.iter().map(|x| (x - lx).powi(2)).sum();
            let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - lx) * (y - ly)).sum();
            let m = sxy / sxx;
            let res: Vec<f64> = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| (y - ly) - m * (x - lx))
                .collect();
            let ssr: f64 = res.iter().map(|r| r * r).sum();
            let dof = (n - 1).max(1) as f64;
            PowerLawFit {
                slope: m,
                slope_stderr: (ssr / dof / sxx).sqrt(),
                reference_depth: h1,
                reference_load: p1,
                reference_log_load_stderr: 0.0,
                r_squared: if sst > 0.0 { 1.0 - ssr / sst } else { 1.0 },
                residuals: res,
                n_points: n,
                n_excluded: excluded,
                anchored: true,
            }
        }
        None => {
            if n < 3 {
                return Err(too_few(3));
            }
            let xbar = xs.iter().sum::<f64>() / n as f64;
            let sxx: f64 = xs.iter().map(|x| (x - xbar).powi(2)).sum();
            if sxx <= 0.0 {
                return Err(Error::OutOfDomain {
                    name: "depth",
                    value: depth[0],
                    reason: "all fitted depths are equal: no slope",
                });
            }
            let sxy: f64 = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| (x - xbar) * (y - ybar))
                .sum();
            let m = sxy / sxx;
            let res: Vec<f64> = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| (y - ybar) - m * (x - xbar))
                .collect();
            let ssr: f64 = res.iter().map(|r| r * r).sum();
            let s2 = ssr / (n - 2) as f64;
            PowerLawFit {
                slope: m,
                slope_stderr: (s2 / sxx).sqrt(),
                reference_depth: xbar.exp(),
                reference_load: ybar.exp(),
                reference_log_load_stderr: (s2 / n as f64).sqrt(),
                r_squared: if sst > 0.0 { 1.0 - ssr / sst } else { 1.0 },
                residuals: res,
                n_points: n,
                n_excluded: excluded,
                anchored: false,
            }
        }
    };
    if !fit.slope.is_finite() || !fit.slope_stderr.is_finite() {
        return Err(Error::OutOfDomain {
            name: "depth",
            value: depth.first().copied().unwrap_or(0.0),
            reason: "the depths do not spread around the anchor: no slope",
        });
    }
    Ok(fit)
}

// ---------------------------------------------------------------------------
// Unloading: P = α (h − h_f)^m

/// The Oliver–Pharr unloading power law `P = α(h − h_f)^m`, fitted by least
/// squares in P, with the covariance of (ln α, h_f, m).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct UnloadingFit {
    /// Exponent m (dimensionless).
    pub exponent: f64,
    /// Standard error of m.
    pub exponent_stderr: f64,
    /// Final (residual) depth h_f (m).
    pub final_depth: f64,
    /// Standard error of h_f (m).
    pub final_depth_stderr: f64,
    /// α (N/m^m).
    pub prefactor: f64,
    /// Coefficient of determination of P.
    pub r_squared: f64,
    /// Residuals P − fit (N), in the order of the fitted points.
    pub residuals: Vec<f64>,
    /// Root-mean-square residual (N).
    pub rms_residual: f64,
    /// Points fitted.
    pub n_points: usize,
    /// Load window used, as fractions of the peak load.
    pub window: [f64; 2],
    /// Covariance of (ln α′, h_f/h_max, m) in the scaled variables of the fit.
    #[serde(skip)]
    pub(super) covariance: [[f64; 3]; 3],
    /// Scales: (h_max, P_max) used to make the fit dimensionless.
    #[serde(skip)]
    pub(super) scales: (f64, f64),
    /// Scaled parameters (ln α′, h_f′, m).
    #[serde(skip)]
    pub(super) theta: [f64; 3],
}

/// The best power law for a fixed h_f: the regression of ln P on ln(h − h_f),
/// in the scaled variables of [`fit_unloading`].
struct ProfileFit {
    /// ln α′ of the regression (α′ in scaled units).
    log_prefactor: f64,
    /// Exponent m (dimensionless).
    exponent: f64,
    /// Sum of squared residuals in the scaled load P/P_max.
    sse: f64,
}

fn sse_profile(h: &[f64], p: &[f64], hf: f64) -> Option<ProfileFit> {
    // Linear regression of ln p on ln(h − hf).
    let n = h.len() as f64;
    let xs: Vec<f64> = h.iter().map(|&x| (x - hf).ln()).collect();
    let ys: Vec<f64> = p.iter().map(|&y| y.ln()).collect();
    let xb = xs.iter().sum::<f64>() / n;
    let yb = ys.iter().sum::<f64>() / n;
    let sxx: f64 = xs.iter().map(|x| (x - xb).powi(2)).sum();
    if !(sxx > 0.0) {
        return None;
    }
    let m = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - xb) * (y - yb))
        .sum::<f64>()
        / sxx;
    let la = yb - m * xb;
    let sse = xs
        .iter()
        .zip(p)
        .map(|(x, y)| (y - (la + m * x).exp()).powi(2))
        .sum::<f64>();
    sse.is_finite().then_some(ProfileFit {
        log_prefactor: la,
        exponent: m,
        sse,
    })
}

fn inverse3(a: &[[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    // Adjugate inverse of a 3×3 matrix (the normal matrix of a 3-parameter
    // fit); a linear-algebra crate would add nothing at this size.
    let c = |i: usize, j: usize| {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
        a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]
    };
    let det = a[0][0] * c(0, 0) + a[0][1] * c(0, 1) + a[0][2] * c(0, 2);
    if !(det.abs() > 0.0) || !det.is_finite() {
        return None;
    }
    let mut inv = [[0.0; 3]; 3];
    for (i, row) in inv.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = c(j, i) / det;
        }
    }
    Some(inv)
}

/// Fit `P = α(h − h_f)^m` to the unloading points whose load lies in
/// `[window[0], window[1]]·P_max` (`peak_load` = P_max, N; `peak_depth` = h_max,
/// m, used only for scaling). Method: h_f is profiled (for each h_f, ln P is
/// regressed on ln(h − h_f)) over a log-spaced scan and a golden-section
/// refinement, then the three parameters are polished by damped Gauss–Newton
/// on the squared residuals in P; the covariance is `s²(JᵀJ)⁻¹`,
/// `s² = SSE/(n − 3)`. Needs ≥ 5 points in the window.
pub fn fit_unloading(
    depth: &[f64],
    load: &[f64],
    peak_depth: f64,
    peak_load: f64,
    window: [f64; 2],
) -> Result<UnloadingFit> {
    let hmax = check::positive("peak_depth", peak_depth)?;
    let pmax = check::positive("peak_load", peak_load)?;
    if !(window[0] >= 0.0 && window[1] <= 1.0 && window[0] < window[1]) {
        return Err(Error::InvalidArgument {
            name: "unloading_window",
            value: window[0],
            bound: "0 <= low < high <= 1",
        });
    }
    let mut h = Vec::new();
    let mut p = Vec::new();
    for (&x, &y) in depth.iter().zip(load) {
        if y >= window[0] * pmax && y <= window[1] * pmax && y > 0.0 && x.is_finite() {
            h.push(x / hmax);
            p.push(y / pmax);
        }
    }
    let n = h.len();
    if n < 5 {
        return Err(Error::OutOfDomain {
            name: "unloading_points",
            value: n as f64,
            reason: "the unloading fit needs at least 5 points in the load window",
        });
    }
    let hmin = h.iter().cloned().fold(f64::INFINITY, f64::min);
    let hmx = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let range = hmx - hmin;
    if !(range > 0.0) {
        return Err(Error::OutOfDomain {
            name: "unloading_points",
            value: n as f64,
            reason: "all unloading depths are equal: no slope",
        });
    }
    // Scan the gap g = hmin − h_f over 1e-4 … 1e3 ranges.
    let k = 160;
    let gap = |i: f64| range * 10f64.powf(-4.0 + 7.0 * i / k as f64);
    let mut best = (f64::INFINITY, 0usize);
    for i in 0..=k {
        if let Some(ProfileFit { sse, .. }) = sse_profile(&h, &p, hmin - gap(i as f64)) {
            if sse < best.0 {
                best = (sse, i);
            }
        }
    }
    if !best.0.is_finite() {
        return Err(Error::NotConverged {
            what: "unloading power-law fit (scan)",
            iterations: k as u32,
            residual: f64::INFINITY,
        });
    }
    // Golden section in the scan index around the best.
    let (mut a, mut b) = (
        (best.1 as f64 - 1.0).max(0.0),
        (best.1 as f64 + 1.0).min(k as f64),
    );
    let f = |i: f64| {
        sse_profile(&h, &p, hmin - gap(i))
            .map(|r| r.sse)
            .unwrap_or(f64::INFINITY)
    };
    let gr = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..60 {
        let c = b - gr * (b - a);
        let d = a + gr * (b - a);
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let hf0 = hmin - gap(0.5 * (a + b));
    let ProfileFit {
        log_prefactor: la0,
        exponent: m0,
        ..
    } = sse_profile(&h, &p, hf0).ok_or(Error::NotConverged {
        what: "unloading power-law fit (profile)",
        iterations: 60,
        residual: f64::INFINITY,
    })?;
    // Damped Gauss–Newton in (ln α, h_f, m).
    let model = |t: &[f64; 3], x: f64| (t[0] + t[2] * (x - t[1]).ln()).exp();
    let sse_of = |t: &[f64; 3]| -> f64 {
        if t[1] >= hmin {
            return f64::INFINITY;
        }
        h.iter()
            .zip(&p)
            .map(|(&x, &y)| (y - model(t, x)).powi(2))
            .sum()
    };
    let jac_normal = |t: &[f64; 3]| -> ([[f64; 3]; 3], [f64; 3]) {
        let mut jtj = [[0.0; 3]; 3];
        let mut jtr = [0.0; 3];
        for (&x, &y) in h.iter().zip(&p) {
            let u = x - t[1];
            let f = model(t, x);
            let j = [f, -t[2] * f / u, f * u.ln()];
            let r = y - f;
            for a in 0..3 {
                jtr[a] += j[a] * r;
                for b in 0..3 {
                    jtj[a][b] += j[a] * j[b];
                }
            }
        }
        (jtj, jtr)
    };
    let mut t = [la0, hf0, m0];
    let mut cur = sse_of(&t);
    let mut mu = 1e-3;
    for _ in 0..100 {
        let (jtj, jtr) = jac_normal(&t);
        let mut improved = false;
        for _ in 0..30 {
            let mut a = jtj;
            for (i, row) in a.iter_mut().enumerate() {
                row[i] *= 1.0 + mu;
            }
            let Some(inv) = inverse3(&a) else {
                mu *= 10.0;
                continue;
            };
            let mut step = [0.0; 3];
            for i in 0..3 {
                step[i] = (0..3).map(|j| inv[i][j] * jtr[j]).sum();
            }
            let trial = [t[0] + step[0], t[1] + step[1], t[2] + step[2]];
            let s = sse_of(&trial);
            if s < cur {
                let rel = (cur - s) / cur.max(f64::MIN_POSITIVE);
                t = trial;
                cur = s;
                mu = (mu * 0.3).max(1e-12);
                improved = rel > 1e-14;
                break;
            }
            mu *= 10.0;
        }
        if !improved {
            break;
        }
    }
    let (jtj, _) = jac_normal(&t);
    let dof = (n - 3) as f64;
    let s2 = cur / dof;
    let inv = inverse3(&jtj).ok_or(Error::OutOfDomain {
        name: "unloading_points",
        value: n as f64,
        reason: "the unloading data do not determine alpha, h_f and m (singular normal matrix)",
    })?;
    let mut cov = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            cov[i][j] = inv[i][j] * s2;
        }
    }
    let pbar = p.iter().sum::<f64>() / n as f64;
    let sst: f64 = p.iter().map(|y| (y - pbar).powi(2)).sum();
    let residuals: Vec<f64> = h
        .iter()
        .zip(&p)
        .map(|(&x, &y)| (y - model(&t, x)) * pmax)
        .collect();
    let fit = UnloadingFit {
        exponent: t[2],
        exponent_stderr: cov[2][2].max(0.0).sqrt(),
        final_depth: t[1] * hmax,
        final_depth_stderr: cov[1][1].max(0.0).sqrt() * hmax,
        prefactor: (t[0] - t[2] * hmax.ln()).exp() * pmax,
        r_squared: if sst > 0.0 { 1.0 - cur / sst } else { 1.0 },
        rms_residual: (cur / n as f64).sqrt() * pmax,
        residuals,
        n_points: n,
        window,
        covariance: cov,
        scales: (hmax, pmax),
        theta: t,
    };
    let all_finite = [
        fit.exponent,
        fit.exponent_stderr,
        fit.final_depth,
        fit.final_depth_stderr,
        fit.prefactor,
        fit.r_squared,
    ]
    .iter()
    .all(|v| v.is_finite());
    if !all_finite {
        return Err(Error::NotConverged {
            what: "unloading power-law fit",
            iterations: 100,
            residual: cur,
        });
    }
    Ok(fit)
}

impl UnloadingFit {
    /// `dP/dh = α m (h − h_f)^{m−1}` (N/m) at depth `h` (m) on the fit.
    pub fn stiffness_at(&self, h: f64) -> f64 {
        let u = (h - self.final_depth).max(0.0);
        self.prefactor * self.exponent * u.powf(self.exponent - 1.0)
    }

    /// First-order standard error of `g(θ)` for a function of the scaled
    /// parameters θ = (ln α′, h_f′, m), by central differences.
    pub(super) fn propagate(&self, g: impl Fn(&[f64; 3]) -> Option<f64>) -> Option<f64> {
        let mut grad = [0.0; 3];
        for i in 0..3 {
            let sd = self.covariance[i][i].max(0.0).sqrt();
            let step = if sd > 0.0 { 1e-3 * sd } else { 1e-9 };
            let mut tp = self.theta;
            let mut tm = self.theta;
            tp[i] += step;
            tm[i] -= step;
            grad[i] = (g(&tp)? - g(&tm)?) / (2.0 * step);
        }
        let mut var = 0.0;
        for i in 0..3 {
            for j in 0..3 {
                var += grad[i] * self.covariance[i][j] * grad[j];
            }
        }
        let se = var.max(0.0).sqrt();
        se.is_finite().then_some(se)
    }
}
