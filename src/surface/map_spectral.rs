//! Spectra of height maps: the two-dimensional PSD and ACF (full arrays and
//! radial averages) and the isotropy of a map (thesis 1.5.2; ISO 25178-2).
//!
//! ## 2-D PSD
//!
//! Two-sided in the angular wavevector (q_x, q_y) (rad/m), normalised so that
//! its integral over the plane is the height variance Sq²: for an
//! n_x × n_y map with Z = z − z̄ (times a window w) and its 2-D DFT X_kl,
//!
//! C_kl = dx·dy / ((2π)² n_x n_y ⟨w²⟩) |X_kl|²,  Σ C_kl Δq_x Δq_y = Sq²
//!
//! exactly for the rectangular window (Parseval), Δq = 2π/(n·d). Units m⁴.
//! The array is stored centred (zero wavevector in the middle): index i
//! holds q_x = (i − ⌊n_x/2⌋)·Δq_x, the order of numpy's `fftshift`.
//! The Hann window is the product sin²(πi/n_x)·sin²(πj/n_y), ⟨w²⟩ = (3/8)².
//! The radial average C(q) is the mean of C over annuli |q| ∈ [(m − ½)Δq,
//! (m + ½)Δq), Δq = max(Δq_x, Δq_y), up to the smaller Nyquist wavenumber;
//! for an isotropic surface the profile PSD G of any line scan is
//! G(q_x) = 2∫ C(q_x, q_y) dq_y.
//!
//! ## 2-D ACF
//!
//! The biased estimator R(τ_x, τ_y) = (1/(n_x n_y)) Σ Z(x, y) Z(x + τ_x,
//! y + τ_y) over the overlapping points, by zero-padded FFT, on the full lag
//! grid (2n_x − 1) × (2n_y − 1), centred; R(0, 0) = Sq².
//!
//! ## Isotropy
//!
//! * The texture aspect ratio (ISO 25178-2 Str): the shortest over the
//!   longest distance, over directions θ (1° steps), at which the
//!   normalised ACF first falls to s = 0.2 (bilinear interpolation on the
//!   lag grid, searched up to half the map along θ). Str → 1 for an
//!   isotropic surface, → 0 for a strongly directional one; the shortest
//!   distance is the autocorrelation length Sal. When the ACF does not fall
//!   to s within half the map in some direction, Str is undefined.
//! * The gradient ratio √(λ_min/λ_max) of the slope covariance
//!   [[⟨Z_x²⟩, ⟨Z_xZ_y⟩], [⟨Z_xZ_y⟩, ⟨Z_y²⟩]] (seven-point slopes): the ratio
//!   of the smallest to the largest directional rms slope, the ratio of
//!   the directional second spectral moments m₂(θ) = ∫ (q·e_θ)² C d²q
//!   (Nayak 1973): 1 for an isotropic surface; and the direction of steepest
//!   rms slope.
//!
//! # References
//!
//! * Thesis §1.5.2 (ACF and PSD).
//! * ISO 25178-2:2012 (Str, Sal; s = 0.2 by default), ISO 25178-3:2012.
//! * P. R. Nayak (1973), "Random process model of rough surfaces in plastic
//!   contact", Wear 26, 305–333 (directional moments of anisotropic surfaces).
//! * T. D. B. Jacobs, T. Junge, L. Pastewka (2017), Surf. Topogr.: Metrol.
//!   Prop. 5, 013001 (2-D and radially averaged PSDs).

use super::fft::{fast_len, fft2};
use super::iso::slope_at;
use super::{mean, Topography, Window};
use crate::error::{Error, Result};
use rustfft::num_complex::Complex64;
use serde::Serialize;

const TWO_PI: f64 = 2.0 * core::f64::consts::PI;

/// Two-dimensional PSD C(q_x, q_y) of a map, centred (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Psd2d {
    /// Wavenumbers along x (columns).
    pub nx: usize,
    /// Wavenumbers along y (rows).
    pub ny: usize,
    /// Δq_x = 2π/(n_x dx) (rad/m).
    pub dqx: f64,
    /// Δq_y = 2π/(n_y dy) (rad/m).
    pub dqy: f64,
    /// C at (q_x(i), q_y(j)) in `c[j·nx + i]` (m⁴).
    pub c: Vec<f64>,
}

/// Radially averaged PSD or ACF.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Radial {
    /// Mean |q| (rad/m) or |τ| (m) of the annulus.
    pub r: Vec<f64>,
    /// Mean value over the annulus (PSD: m⁴; ACF: m²).
    pub value: Vec<f64>,
    /// Number of grid points in the annulus.
    pub count: Vec<usize>,
}

impl Psd2d {
    /// q_x of column `i` (rad/m).
    pub fn qx(&self, i: usize) -> f64 {
        (i as f64 - (self.nx / 2) as f64) * self.dqx
    }

    /// q_y of row `j` (rad/m).
    pub fn qy(&self, j: usize) -> f64 {
        (j as f64 - (self.ny / 2) as f64) * self.dqy
    }

    /// ∫∫ C dq_x dq_y (m²): Sq² for the rectangular window.
    pub fn integral(&self) -> f64 {
        self.c.iter().sum::<f64>() * self.dqx * self.dqy
    }

    /// The radial average over annuli of width max(Δq_x, Δq_y), centres
    /// m·Δq, up to the smaller Nyquist wavenumber (module docs).
    pub fn radial(&self) -> Radial {
        let dq = self.dqx.max(self.dqy);
        let q_max = ((self.nx / 2) as f64 * self.dqx).min((self.ny / 2) as f64 * self.dqy);
        radial_average(self.nx, self.ny, dq, q_max, |i, j| {
            (self.qx(i).hypot(self.qy(j)), self.c[j * self.nx + i])
        })
    }

    /// Directional second moments (m_xx, m_yy, m_xy) = ∫ (q_x², q_y², q_x q_y) C d²q
    /// (dimensionless): the slope covariances of the band-limited map.
    pub fn second_moments(&self) -> (f64, f64, f64) {
        let (mut xx, mut yy, mut xy) = (0.0, 0.0, 0.0);
        for j in 0..self.ny {
            let qy = self.qy(j);
            for i in 0..self.nx {
                let qx = self.qx(i);
                let c = self.c[j * self.nx + i];
                xx += qx * qx * c;
                yy += qy * qy * c;
                xy += qx * qy * c;
            }
        }
        let a = self.dqx * self.dqy;
        (xx * a, yy * a, xy * a)
    }
}

/// Averages `f(i, j) = (radius, value)` over annuli of width `dr` centred on
/// m·dr, m = 0..=r_max/dr.
fn radial_average(
    nx: usize,
    ny: usize,
    dr: f64,
    r_max: f64,
    f: impl Fn(usize, usize) -> (f64, f64),
) -> Radial {
    let nb = (r_max / dr + 0.5).floor() as usize + 1;
    let (mut sr, mut sv, mut cnt) = (vec![0.0; nb], vec![0.0; nb], vec![0usize; nb]);
    for j in 0..ny {
        for i in 0..nx {
            let (r, v) = f(i, j);
            if r > r_max * (1.0 + 1e-12) {
                continue;
            }
            let m = ((r / dr) + 0.5).floor() as usize;
            if m < nb {
                sr[m] += r;
                sv[m] += v;
                cnt[m] += 1;
            }
        }
    }
    let mut out = Radial {
        r: Vec::new(),
        value: Vec::new(),
        count: Vec::new(),
    };
    for m in 0..nb {
        if cnt[m] > 0 {
            out.r.push(sr[m] / cnt[m] as f64);
            out.value.push(sv[m] / cnt[m] as f64);
            out.count.push(cnt[m]);
        }
    }
    out
}

/// Two-dimensional PSD of `map` (mean removed) with `window`; see the module
/// docs for the normalisation and the layout.
pub fn psd_2d(map: &Topography, window: Window) -> Result<Psd2d> {
    let (nx, ny) = (map.nx(), map.ny());
    let z = map.heights();
    let zbar = mean(z);
    let hann = window == Window::Hann;
    let wx = |i: usize, n: usize| {
        if hann {
            (core::f64::consts::PI * i as f64 / n as f64).sin().powi(2)
        } else {
            1.0
        }
    };
    let mut a: Vec<Complex64> = (0..nx * ny)
        .map(|k| {
            let (i, j) = (k % nx, k / nx);
            Complex64::new((z[k] - zbar) * wx(i, nx) * wx(j, ny), 0.0)
        })
        .collect();
    fft2(&mut a, nx, ny, false);
    let w2 = if hann { 0.375 * 0.375 } else { 1.0 };
    let scale = map.dx() * map.dy() / (TWO_PI * TWO_PI * (nx * ny) as f64 * w2);
    let mut c = vec![0.0; nx * ny];
    let (hx, hy) = (nx / 2, ny / 2);
    for j in 0..ny {
        let kj = (j + ny - hy) % ny;
        for i in 0..nx {
            let ki = (i + nx - hx) % nx;
            c[j * nx + i] = a[kj * nx + ki].norm_sqr() * scale;
        }
    }
    Ok(Psd2d {
        nx,
        ny,
        dqx: TWO_PI / (nx as f64 * map.dx()),
        dqy: TWO_PI / (ny as f64 * map.dy()),
        c,
    })
}

/// Two-dimensional ACF of a map on the full lag grid, centred (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Acf2d {
    /// Lags along x: 2n_x − 1, from −(n_x − 1)dx to (n_x − 1)dx.
    pub nx: usize,
    /// Lags along y: 2n_y − 1.
    pub ny: usize,
    /// Lag step along x (m).
    pub dx: f64,
    /// Lag step along y (m).
    pub dy: f64,
    /// R at lag (τ_x(i), τ_y(j)) in `r[j·nx + i]` (m²).
    pub r: Vec<f64>,
}

impl Acf2d {
    /// τ_x of column `i` (m).
    pub fn tau_x(&self, i: usize) -> f64 {
        (i as f64 - (self.nx / 2) as f64) * self.dx
    }

    /// τ_y of row `j` (m).
    pub fn tau_y(&self, j: usize) -> f64 {
        (j as f64 - (self.ny / 2) as f64) * self.dy
    }

    /// R(0, 0) = Sq² (m²).
    pub fn r0(&self) -> f64 {
        self.r[(self.ny / 2) * self.nx + self.nx / 2]
    }

    /// The normalised ACF at lag (τ_x, τ_y) (m), bilinear between grid
    /// points; `None` outside the lag grid.
    pub fn normalized_at(&self, tx: f64, ty: f64) -> Option<f64> {
        let r0 = self.r0();
        if r0 <= 0.0 {
            return None;
        }
        let u = tx / self.dx + (self.nx / 2) as f64;
        let v = ty / self.dy + (self.ny / 2) as f64;
        if !(u >= 0.0 && v >= 0.0 && u <= (self.nx - 1) as f64 && v <= (self.ny - 1) as f64) {
            return None;
        }
        let (i, j) = (
            (u.floor() as usize).min(self.nx - 2),
            (v.floor() as usize).min(self.ny - 2),
        );
        let (fu, fv) = (u - i as f64, v - j as f64);
        let g = |i: usize, j: usize| self.r[j * self.nx + i];
        let val = g(i, j) * (1.0 - fu) * (1.0 - fv)
            + g(i + 1, j) * fu * (1.0 - fv)
            + g(i, j + 1) * (1.0 - fu) * fv
            + g(i + 1, j + 1) * fu * fv;
        Some(val / r0)
    }

    /// The radial average over annuli of width min(dx, dy), up to half the
    /// smaller map side (m²).
    pub fn radial(&self) -> Radial {
        let dr = self.dx.min(self.dy);
        let r_max = 0.5 * ((self.nx / 2) as f64 * self.dx).min((self.ny / 2) as f64 * self.dy);
        radial_average(self.nx, self.ny, dr, r_max, |i, j| {
            (self.tau_x(i).hypot(self.tau_y(j)), self.r[j * self.nx + i])
        })
    }

    /// Distance (m) along direction `theta` (rad from +x) at which the
    /// normalised ACF first falls to `s`, searched up to half the map along
    /// that direction; `None` if it does not.
    pub fn decay_length(&self, theta: f64, s: f64) -> Option<f64> {
        let (c, sn) = (theta.cos(), theta.sin());
        let half_x = 0.5 * (self.nx / 2) as f64 * self.dx;
        let half_y = 0.5 * (self.ny / 2) as f64 * self.dy;
        let reach = (half_x / c.abs().max(1e-300)).min(half_y / sn.abs().max(1e-300));
        // A quarter of the finer spacing, but at most ~8(nx + ny) steps (very
        // unequal spacings).
        let step = (0.25 * self.dx.min(self.dy)).max(reach / (8 * (self.nx + self.ny)) as f64);
        let mut prev = (0.0, 1.0);
        let mut t = step;
        while t <= reach {
            let v = self.normalized_at(t * c, t * sn)?;
            if v <= s {
                let (t0, v0) = prev;
                return Some(t0 + (v0 - s) / (v0 - v) * (t - t0));
            }
            prev = (t, v);
            t += step;
        }
        None
    }
}

/// Two-dimensional ACF of `map` (mean removed), biased estimator by
/// zero-padded FFT; see the module docs.
pub fn acf_2d(map: &Topography) -> Result<Acf2d> {
    let (nx, ny) = (map.nx(), map.ny());
    let z = map.heights();
    let zbar = mean(z);
    let (px, py) = (fast_len(2 * nx), fast_len(2 * ny));
    let mut a = vec![Complex64::default(); px * py];
    for j in 0..ny {
        for i in 0..nx {
            a[j * px + i] = Complex64::new(z[j * nx + i] - zbar, 0.0);
        }
    }
    fft2(&mut a, px, py, false);
    for v in a.iter_mut() {
        *v = Complex64::new(v.norm_sqr(), 0.0);
    }
    fft2(&mut a, px, py, true);
    let scale = 1.0 / ((px * py) as f64 * (nx * ny) as f64);
    let (lx, ly) = (2 * nx - 1, 2 * ny - 1);
    let mut r = vec![0.0; lx * ly];
    for j in 0..ly {
        let kj = (j + py - (ny - 1)) % py;
        for i in 0..lx {
            let ki = (i + px - (nx - 1)) % px;
            r[j * lx + i] = a[kj * px + ki].re * scale;
        }
    }
    Ok(Acf2d {
        nx: lx,
        ny: ly,
        dx: map.dx(),
        dy: map.dy(),
        r,
    })
}

/// Isotropy of a map (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Isotropy {
    /// Threshold s of the normalised ACF (0.2 by ISO 25178-2).
    pub s: f64,
    /// Texture aspect ratio Str = shortest / longest decay length; `None`
    /// when the ACF does not fall to s within half the map in some direction.
    pub texture_aspect_ratio: Option<f64>,
    /// Autocorrelation length Sal: the shortest decay length (m); `None` if
    /// the ACF falls to s in no direction.
    pub autocorrelation_length: Option<f64>,
    /// The longest decay length (m), `None` as for Str.
    pub longest_decay_length: Option<f64>,
    /// Direction of the longest decay (rad from +x, in [0, π)): the lay.
    pub texture_direction: f64,
    /// √(λ_min/λ_max) of the slope covariance: the smallest over the largest
    /// directional rms slope (1 isotropic).
    pub gradient_ratio: f64,
    /// Direction of the steepest rms slope (rad from +x, in [0, π)).
    pub gradient_direction: f64,
    /// Largest and smallest directional rms slopes √λ_max, √λ_min.
    pub rms_slope_max: f64,
    /// Smallest directional rms slope √λ_min.
    pub rms_slope_min: f64,
}

/// Isotropy of `map` with ACF threshold `s` (0.2 in ISO 25178-2); see the
/// module docs. Errors: `s` outside (0, 1).
pub fn isotropy(map: &Topography, s: f64) -> Result<Isotropy> {
    if !(s > 0.0 && s < 1.0) {
        return Err(Error::InvalidArgument {
            name: "s",
            value: s,
            bound: "in (0, 1)",
        });
    }
    let acf = acf_2d(map)?;
    let lens: Vec<(f64, Option<f64>)> = (0..180)
        .map(|d| {
            let th = (d as f64).to_radians();
            (th, acf.decay_length(th, s))
        })
        .collect();
    let lo = lens.iter().filter_map(|l| l.1).reduce(f64::min);
    let all = lens.iter().all(|l| l.1.is_some());
    let (str_, longest, dir) = if all {
        let (th, hi) = lens
            .iter()
            .map(|&(th, l)| (th, l.unwrap_or(0.0)))
            .fold((0.0, 0.0), |b, x| if x.1 > b.1 { x } else { b });
        (lo.map(|a| a / hi), Some(hi), th)
    } else {
        // The mean axis of the directions without decay (angles doubled).
        let (ss, cs) = lens
            .iter()
            .filter(|l| l.1.is_none())
            .fold((0.0, 0.0), |(ss, cs), l| {
                (ss + (2.0 * l.0).sin(), cs + (2.0 * l.0).cos())
            });
        let th = (0.5 * ss.atan2(cs)).rem_euclid(core::f64::consts::PI);
        (None, None, th)
    };
    // Slope covariance from seven-point slopes along rows and columns.
    let (nx, ny) = (map.nx(), map.ny());
    let z = map.heights();
    let mut gx = vec![0.0; nx * ny];
    for j in 0..ny {
        let row = &z[j * nx..(j + 1) * nx];
        for i in 0..nx {
            gx[j * nx + i] = slope_at(row, i, map.dx());
        }
    }
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    let mut col = vec![0.0; ny];
    for i in 0..nx {
        for j in 0..ny {
            col[j] = z[j * nx + i];
        }
        for j in 0..ny {
            let gy = slope_at(&col, j, map.dy());
            let g = gx[j * nx + i];
            sxx += g * g;
            syy += gy * gy;
            sxy += g * gy;
        }
    }
    let n = (nx * ny) as f64;
    let (a, b, c) = (sxx / n, syy / n, sxy / n);
    let mid = 0.5 * (a + b);
    let rad = (0.25 * (a - b) * (a - b) + c * c).sqrt();
    let (l1, l2) = (mid + rad, (mid - rad).max(0.0));
    let gdir = (0.5 * (2.0 * c).atan2(a - b)).rem_euclid(core::f64::consts::PI);
    Ok(Isotropy {
        s,
        texture_aspect_ratio: str_,
        autocorrelation_length: lo,
        longest_decay_length: longest,
        texture_direction: dir,
        gradient_ratio: if l1 > 0.0 { (l2 / l1).sqrt() } else { 1.0 },
        gradient_direction: gdir,
        rms_slope_max: l1.sqrt(),
        rms_slope_min: l2.sqrt(),
    })
}
