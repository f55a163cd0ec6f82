//! Synthetic rough profiles and maps (thesis 1.5.3, 5.4.2).
//!
//! Random generators are seeded: the same parameters and seed give
//! bit-identical output on the same build and machine. Random numbers come
//! from ChaCha8 (`rand_chacha`, platform-independent stream) and
//! `rand_distr::StandardNormal`; the FFTs come from `rustfft`, which selects
//! SIMD code paths at run time, so across different CPUs the last bits may
//! differ.
//!
//! * [`SelfAffine`]: Gaussian self-affine profiles and maps by Fourier
//!   filtering of white noise (the power-law PSD of *Formulas*, with a
//!   roll-off and a short-wavelength cut-off), scaled to a target Rq.
//! * [`WeierstrassMandelbrot`]: the Weierstrass–Mandelbrot function with
//!   random phases (Berry & Lewis 1980; Ausloos & Berman 1985; thesis 1.5.3,
//!   after Roques-Carmes et al. 1988).
//! * [`CantorBorodich`]: the Cantor–Borodich profile (Borodich & Mosolov
//!   1991; Borodich & Onishchenko 1993) with two descendants, or three
//!   (Warren & Krajcinovic 1995), and its box-counting dimension (*Formulas*;
//!   thesis 1.5.3 for m = 2).
//!
//! # Formulas
//!
//! $$G(q) \propto q^{-(1+2H)} \ \ \text{(profile)}, \qquad G(q) \propto q^{-2(1+H)} \ \ \text{(map)},$$
//!
//! $$z(x) = A\sum_{k=0}^{K}\gamma^{(D-2)k}\Bigl(\cos\phi_k - \cos\Bigl(\frac{2\pi\gamma^k x}{L} + \phi_k\Bigr)\Bigr) \ \ \text{(Weierstrass–Mandelbrot)},$$
//!
//! $$z(x) = h\sum_{k=1}^{n}\beta^{k-1}\\,\mathbb{1}\bigl(x \in C_k\bigr), \qquad \dim = 1 + \frac{\ln(m\beta)}{\ln(1/\alpha)} \ \ \text{(Cantor–Borodich)}.$$
//!
//! # References
//!
//! * Thesis §1.5.3, §5.4.2.
//! * M. V. Berry, Z. V. Lewis (1980), "On the Weierstrass–Mandelbrot fractal
//!   function", Proc. R. Soc. Lond. A 370, 459–484,
//!   [doi:10.1098/rspa.1980.0044](https://doi.org/10.1098/rspa.1980.0044).
//! * M. Ausloos, D. H. Berman (1985), "A multivariate Weierstrass–Mandelbrot
//!   function", Proc. R. Soc. Lond. A 400, 331–350.
//! * F. M. Borodich, A. B. Mosolov (1991), Cantor-type fractal profiles (in
//!   Russian; as cited by the thesis); F. M. Borodich, D. A. Onishchenko (1993).
//! * T. L. Warren, D. Krajcinovic (1995), "Fractal models of elastic–perfectly
//!   plastic contact of rough surfaces based on the Cantor set", Int. J. Solids
//!   Struct. 32, 2907–2922.

use super::fft::{fft1, fft2};
use super::{Profile, Topography};
use crate::error::{check, Error, Result};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;
use rustfft::num_complex::Complex64;

const TWO_PI: f64 = 2.0 * core::f64::consts::PI;

/// A Gaussian self-affine random surface by Fourier filtering.
///
/// The PSD shape is, with q_r = 2π/λ_r (roll-off) and q_s = 2π/λ_s
/// (short-wavelength cut-off),
///
/// G(q) ∝ q_r^{−e} for q < q_r,  q^{−e} for q_r ≤ q ≤ q_s,  0 for q > q_s,
///
/// with e = 1 + 2H on a profile and e = 2(1 + H) on an isotropic map (the
/// radial PSD of a map carries one more power of q). The synthesis draws
/// independent N(0, 1) heights (ChaCha8), transforms them, multiplies by
/// √G(|q|), transforms back, removes the mean and scales to Rq exactly, so
/// the result is periodic, Gaussian and has its periodogram equal to G times
/// χ²₂/2 noise. Without a roll-off the spectrum is a power law down to the
/// lowest harmonic 2π/L; without a cut-off up to Nyquist π/dx.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SelfAffine {
    /// Hurst exponent H ∈ [0, 1] (fractal dimension 2 − H of a profile).
    pub hurst: f64,
    /// Target root-mean-square height Rq (Sq for maps) (m), matched exactly.
    pub rq: f64,
    /// Roll-off wavelength λ_r (m): the PSD is flat for longer wavelengths.
    pub roll_off_wavelength: Option<f64>,
    /// Short-wavelength cut-off λ_s (m): no power at shorter wavelengths.
    pub cutoff_wavelength: Option<f64>,
}

impl SelfAffine {
    /// A pure power law with Hurst exponent `hurst` and target `rq` (m), no
    /// roll-off or cut-off. Errors: H outside [0, 1]; rq not finite and > 0.
    pub fn new(hurst: f64, rq: f64) -> Result<Self> {
        let s = Self {
            hurst,
            rq,
            roll_off_wavelength: None,
            cutoff_wavelength: None,
        };
        s.validate()?;
        Ok(s)
    }

    /// With a roll-off wavelength (m). Errors: not finite and > 0.
    pub fn with_roll_off(mut self, wavelength: f64) -> Result<Self> {
        self.roll_off_wavelength = Some(check::positive("roll_off_wavelength", wavelength)?);
        self.validate()?;
        Ok(self)
    }

    /// With a short-wavelength cut-off (m). Errors: not finite and > 0, or
    /// not shorter than the roll-off.
    pub fn with_cutoff(mut self, wavelength: f64) -> Result<Self> {
        self.cutoff_wavelength = Some(check::positive("cutoff_wavelength", wavelength)?);
        self.validate()?;
        Ok(self)
    }

    fn validate(&self) -> Result<()> {
        check::in_range("hurst", self.hurst, 0.0, 1.0, "in [0, 1]")?;
        check::positive("rq", self.rq)?;
        if let Some(r) = self.roll_off_wavelength {
            check::positive("roll_off_wavelength", r)?;
        }
        if let Some(c) = self.cutoff_wavelength {
            check::positive("cutoff_wavelength", c)?;
            if self.roll_off_wavelength.is_some_and(|r| c >= r) {
                return Err(Error::InvalidArgument {
                    name: "cutoff_wavelength",
                    value: c,
                    bound: "< roll_off_wavelength",
                });
            }
        }
        Ok(())
    }

    /// Amplitude filter √G(q) (unnormalised) for `exponent` e.
    fn amplitude(&self, q: f64, exponent: f64) -> f64 {
        if q <= 0.0 {
            return 0.0;
        }
        if let Some(c) = self.cutoff_wavelength {
            if q > TWO_PI / c * (1.0 + 1e-12) {
                return 0.0;
            }
        }
        let qr = self.roll_off_wavelength.map_or(0.0, |r| TWO_PI / r);
        q.max(qr).powf(-0.5 * exponent)
    }

    fn scale_to_rq(&self, z: &mut [f64]) -> Result<()> {
        let m = z.iter().sum::<f64>() / z.len() as f64;
        let var = z.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / z.len() as f64;
        if var <= 0.0 || !var.is_finite() {
            return Err(Error::OutOfDomain {
                name: "cutoff_wavelength",
                value: self.cutoff_wavelength.unwrap_or(0.0),
                reason: "the cut-off leaves no Fourier mode between 2*pi/L and pi/dx",
            });
        }
        let s = self.rq / var.sqrt();
        for v in z.iter_mut() {
            *v = (*v - m) * s;
        }
        Ok(())
    }

    /// A profile of `n` samples at spacing `dx` (m) from `seed`.
    ///
    /// Errors: invalid parameters; n < 4; dx not finite and > 0; a cut-off
    /// that removes every mode.
    pub fn profile(&self, n: usize, dx: f64, seed: u64) -> Result<Profile> {
        self.validate()?;
        check::positive("dx", dx)?;
        if n < 4 {
            return Err(Error::InvalidArgument {
                name: "n",
                value: n as f64,
                bound: ">= 4 points",
            });
        }
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut a: Vec<Complex64> = (0..n)
            .map(|_| Complex64::new(rng.sample(StandardNormal), 0.0))
            .collect();
        fft1(&mut a, false);
        let e = 1.0 + 2.0 * self.hurst;
        let dq = TWO_PI / (n as f64 * dx);
        for (k, v) in a.iter_mut().enumerate() {
            let q = k.min(n - k) as f64 * dq;
            *v *= self.amplitude(q, e);
        }
        fft1(&mut a, true);
        let mut z: Vec<f64> = a.iter().map(|c| c.re).collect();
        self.scale_to_rq(&mut z)?;
        Profile::new(dx, z)
    }

    /// An isotropic map of `nx × ny` points at spacings `dx`, `dy` (m) from
    /// `seed`; Sq equals `rq`.
    ///
    /// Errors: invalid parameters; nx or ny < 2; spacings not finite and > 0;
    /// a cut-off that removes every mode.
    pub fn map(&self, nx: usize, ny: usize, dx: f64, dy: f64, seed: u64) -> Result<Topography> {
        self.validate()?;
        check::positive("dx", dx)?;
        check::positive("dy", dy)?;
        if nx < 2 || ny < 2 {
            return Err(Error::InvalidArgument {
                name: "nx",
                value: nx.min(ny) as f64,
                bound: "nx, ny >= 2",
            });
        }
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut a: Vec<Complex64> = (0..nx * ny)
            .map(|_| Complex64::new(rng.sample(StandardNormal), 0.0))
            .collect();
        fft2(&mut a, nx, ny, false);
        let e = 2.0 * (1.0 + self.hurst);
        let (dqx, dqy) = (TWO_PI / (nx as f64 * dx), TWO_PI / (ny as f64 * dy));
        for j in 0..ny {
            let qy = j.min(ny - j) as f64 * dqy;
            for i in 0..nx {
                let qx = i.min(nx - i) as f64 * dqx;
                a[j * nx + i] *= self.amplitude(qx.hypot(qy), e);
            }
        }
        fft2(&mut a, nx, ny, true);
        let mut z: Vec<f64> = a.iter().map(|c| c.re).collect();
        self.scale_to_rq(&mut z)?;
        Topography::new(nx, ny, dx, dy, z)
    }
}

/// The Weierstrass–Mandelbrot profile with random phases over a length
/// L = n·dx:
///
/// z(x) = A Σ_{k=0}^{K} γ^{(D−2)k} [cos φ_k − cos(2π γ^k x / L + φ_k)],
///
/// with φ_k uniform in [0, 2π) (ChaCha8 from the seed) and K the largest k
/// with γ^k < n/2 (wavelengths from L down to just above the Nyquist 2·dx).
/// This is the thesis's W(x; p) = Σ p^{(D−2)k} (1 − cos p^k x) (1.5.3,
/// Roques-Carmes et al. 1988) with p = γ, the length scaled by L/2π and random
/// phases
/// (Ausloos & Berman 1985); terms with wavelengths longer than L, which only
/// add a smooth form over the profile, are left out. Its spectrum is a
/// comb of lines whose envelope falls as q^{−(5−2D)}: Hurst exponent
/// H = 2 − D.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WeierstrassMandelbrot {
    /// Fractal dimension D ∈ (1, 2).
    pub fractal_dimension: f64,
    /// Frequency ratio γ > 1 between successive terms (commonly 1.5; γ = 2
    /// puts every line on a DFT bin).
    pub gamma: f64,
    /// Amplitude A of the longest-wavelength term (m).
    pub amplitude: f64,
}

impl WeierstrassMandelbrot {
    /// Errors: D outside (1, 2); γ ≤ 1 or not finite; A not finite and > 0.
    pub fn new(fractal_dimension: f64, gamma: f64, amplitude: f64) -> Result<Self> {
        let s = Self {
            fractal_dimension,
            gamma,
            amplitude,
        };
        s.validate()?;
        Ok(s)
    }

    fn validate(&self) -> Result<()> {
        let d = self.fractal_dimension;
        if !(d > 1.0 && d < 2.0) {
            return Err(Error::InvalidArgument {
                name: "fractal_dimension",
                value: d,
                bound: "in (1, 2)",
            });
        }
        if !(self.gamma.is_finite() && self.gamma > 1.0) {
            return Err(Error::InvalidArgument {
                name: "gamma",
                value: self.gamma,
                bound: "finite and > 1",
            });
        }
        check::positive("amplitude", self.amplitude)?;
        Ok(())
    }

    /// Number of terms K + 1 for n samples: K is the largest k with
    /// γ^k < n/2 (strictly below the Nyquist wavenumber, where a cosine's
    /// phase would alias).
    pub fn terms(&self, n: usize) -> usize {
        let mut k = 0usize;
        while self.gamma.powi(k as i32 + 1) < n as f64 / 2.0 {
            k += 1;
        }
        k + 1
    }

    /// The random phases φ_k (rad) drawn from `seed`, k = 0..terms.
    pub fn phases(&self, n: usize, seed: u64) -> Vec<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        (0..self.terms(n))
            .map(|_| TWO_PI * rng.random::<f64>())
            .collect()
    }

    /// A profile of `n` samples at spacing `dx` (m) from `seed`
    /// (x_j = j·dx). Errors: invalid parameters; n < 4; dx not finite and > 0.
    pub fn profile(&self, n: usize, dx: f64, seed: u64) -> Result<Profile> {
        self.validate()?;
        check::positive("dx", dx)?;
        if n < 4 {
            return Err(Error::InvalidArgument {
                name: "n",
                value: n as f64,
                bound: ">= 4 points",
            });
        }
        let phases = self.phases(n, seed);
        let mut z = vec![0.0; n];
        for (k, &phi) in phases.iter().enumerate() {
            let amp = self.amplitude * self.gamma.powf((self.fractal_dimension - 2.0) * k as f64);
            let w = TWO_PI * self.gamma.powi(k as i32) / n as f64;
            let c = phi.cos();
            for (j, v) in z.iter_mut().enumerate() {
                *v += amp * (c - (w * j as f64 + phi).cos());
            }
        }
        Profile::new(dx, z)
    }
}

/// The Cantor–Borodich profile (Borodich & Mosolov 1991; thesis 1.5.3, 5.4.2,
/// Fig. 5-13) with m descendants per generation: m = 2 is Borodich's profile,
/// m = 3 the variant of Warren & Krajcinovic (1995).
///
/// Construction on [0, L): generation 0 is the flat base z = 0. Every block
/// of generation k − 1, of width w, carries m blocks of generation k, of
/// width αw, placed at offsets i(1 − α)w/(m − 1), i = 0..m (outer ones flush
/// with the parent's edges, equal gaps between), each raised by
/// h·β^{k−1} above its parent. After `levels` generations the profile is the
/// step function
///
/// z(x) = h Σ_{k=1}^{levels} β^{k−1} 𝟙[x ∈ C_k],
///
/// C_k the union of the m^k generation-k blocks. Its box-counting dimension
/// (in the limit of infinitely many generations) is
///
/// dim = 1 + ln(mβ) / ln(1/α),
///
/// which for m = 2 is the thesis's 1 + ln(2β)/ln(1/α) with 0 < α < ½,
/// ½ < β < 1 (1.5.3): at scale ε = α^k the m^k blocks each span a height
/// range ∝ β^k, needing ∝ (mβ/α)^k boxes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CantorBorodich {
    /// Descendants per block m ≥ 2 (2: Borodich; 3: Warren–Krajcinovic).
    pub descendants: usize,
    /// Horizontal similarity ratio α ∈ (0, 1/m): width of a child / parent.
    pub alpha: f64,
    /// Vertical similarity ratio β ∈ (1/m, 1): step of generation k + 1 /
    /// step of generation k.
    pub beta: f64,
    /// Step height of the first generation h (m).
    pub height: f64,
    /// Number of generations built (1..=40).
    pub levels: u32,
}

impl CantorBorodich {
    /// Errors: m < 2; α outside (0, 1/m); β outside (1/m, 1); h not finite
    /// and > 0; levels outside 1..=40.
    pub fn new(
        descendants: usize,
        alpha: f64,
        beta: f64,
        height: f64,
        levels: u32,
    ) -> Result<Self> {
        let s = Self {
            descendants,
            alpha,
            beta,
            height,
            levels,
        };
        s.validate()?;
        Ok(s)
    }

    fn validate(&self) -> Result<()> {
        let (descendants, alpha, beta) = (self.descendants, self.alpha, self.beta);
        if descendants < 2 {
            return Err(Error::InvalidArgument {
                name: "descendants",
                value: descendants as f64,
                bound: ">= 2 (2: Cantor-Borodich, 3: Warren-Krajcinovic)",
            });
        }
        let m = descendants as f64;
        if !(alpha > 0.0 && alpha < 1.0 / m) {
            return Err(Error::InvalidArgument {
                name: "alpha",
                value: alpha,
                bound: "in (0, 1/descendants)",
            });
        }
        if !(beta > 1.0 / m && beta < 1.0) {
            return Err(Error::InvalidArgument {
                name: "beta",
                value: beta,
                bound: "in (1/descendants, 1)",
            });
        }
        check::positive("height", self.height)?;
        if !(1..=40).contains(&self.levels) {
            return Err(Error::InvalidArgument {
                name: "levels",
                value: self.levels as f64,
                bound: "in 1..=40",
            });
        }
        Ok(())
    }

    /// Box-counting dimension of the limit profile, 1 + ln(mβ)/ln(1/α)
    /// (thesis 1.5.3 for m = 2); in (1, 2).
    pub fn fractal_dimension(&self) -> f64 {
        1.0 + (self.descendants as f64 * self.beta).ln() / (1.0 / self.alpha).ln()
    }

    /// Height at relative position t = x/L ∈ [0, 1) (m); 0 outside.
    pub fn height_at(&self, t: f64) -> f64 {
        if !(0.0..1.0).contains(&t) {
            return 0.0;
        }
        let m = self.descendants;
        let step = (1.0 - self.alpha) / (m - 1) as f64;
        let mut u = t;
        let mut z = 0.0;
        let mut h = self.height;
        for _ in 0..self.levels {
            let Some(s) = (0..m)
                .map(|i| i as f64 * step)
                .find(|&s| u >= s && u < s + self.alpha)
            else {
                break;
            };
            z += h;
            h *= self.beta;
            u = (u - s) / self.alpha;
        }
        z
    }

    /// The profile sampled at x_j = j·L/n, j = 0..n, over [0, `length`) (m).
    /// Blocks are closed on the left, so a sample at a block's left edge
    /// carries all the generations stacked there: with 1/α an integer and
    /// n = (1/α)^k, every block of generation ≤ k starts on a sample and the
    /// finer generations (up to `levels`) still show in the heights.
    ///
    /// Errors: invalid parameters (as [`Self::new`]); length not finite and
    /// > 0; n < 2.
    pub fn profile(&self, length: f64, n: usize) -> Result<Profile> {
        self.validate()?;
        check::positive("length", length)?;
        if n < 2 {
            return Err(Error::InvalidArgument {
                name: "n",
                value: n as f64,
                bound: ">= 2 points",
            });
        }
        let dx = length / n as f64;
        let z = (0..n)
            .map(|j| self.height_at(j as f64 / n as f64))
            .collect();
        Profile::new(dx, z)
    }
}
