//! Uniformly sampled line scans ([`Profile`]) and height maps
//! ([`Topography`]), and least-squares form removal ([`Form`], [`MapForm`]).
//!
//! # Formulas
//!
//! Form removal fits, by least squares over the samples $(x_j, z_j)$, a
//! polynomial of degree 0, 1 or 2 (a plane or a quadric for maps) and removes
//! it:
//!
//! $$Z_j = z_j - \sum_{i=0}^{p} c_i x_j^i, \qquad c = \arg\min_c \sum_j \Bigl(z_j - \sum_{i=0}^{p} c_i x_j^i\Bigr)^2 .$$
//!
//! # References
//!
//! * ISO 4287:1997 §3.1 (form removal and the mean line); thesis §1.5.1.

use super::{check_heights, mean};
use crate::error::{check, Error, Result};

/// A line scan sampled at a uniform spacing: heights `z_j` (m) at positions
/// `x_j = x0 + j·dx` (m), `j = 0..n`.
///
/// Invariants (checked by every constructor): `dx` finite and > 0, at least
/// two heights, all finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    dx: f64,
    x0: f64,
    heights: Vec<f64>,
    spacing_deviation: f64,
}

impl Profile {
    /// A profile with spacing `dx` (m) and `heights` (m), starting at x = 0.
    ///
    /// Errors: `dx` not finite and > 0; fewer than 2 heights; a non-finite
    /// height.
    pub fn new(dx: f64, heights: Vec<f64>) -> Result<Self> {
        check::positive("dx", dx)?;
        check_heights(&heights, 2, ">= 2 points")?;
        Ok(Self {
            dx,
            x0: 0.0,
            heights,
            spacing_deviation: 0.0,
        })
    }

    /// The same profile starting at `x0` (m) instead of 0.
    pub fn with_origin(mut self, x0: f64) -> Result<Self> {
        self.x0 = check::finite("x0", x0)?;
        Ok(self)
    }

    /// Records how far the measured positions were from the uniform grid
    /// (readers only): max |x_j − x0 − j·dx| / dx.
    pub(crate) fn with_spacing_deviation(mut self, d: f64) -> Self {
        self.spacing_deviation = d;
        self
    }

    /// Sampling interval dx (m).
    #[inline]
    pub fn dx(&self) -> f64 {
        self.dx
    }

    /// Position of the first sample x0 (m).
    #[inline]
    pub fn x0(&self) -> f64 {
        self.x0
    }

    /// Position of sample `j`: x0 + j·dx (m).
    #[inline]
    pub fn x(&self, j: usize) -> f64 {
        self.x0 + j as f64 * self.dx
    }

    /// Heights (m).
    #[inline]
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// Consumes the profile, returning its heights (m).
    pub fn into_heights(self) -> Vec<f64> {
        self.heights
    }

    /// Number of samples n.
    #[inline]
    pub fn len(&self) -> usize {
        self.heights.len()
    }

    /// Always `false`: a profile has at least two samples.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.heights.is_empty()
    }

    /// Evaluation length L = n·dx (m): each sample stands for one interval dx,
    /// so a profile of whole periods of a sine has L equal to those periods.
    #[inline]
    pub fn length(&self) -> f64 {
        self.len() as f64 * self.dx
    }

    /// For profiles from a reader: the largest deviation of a measured position
    /// from the uniform grid, max_j |x_j − x0 − j·dx| / dx (dimensionless; 0
    /// for profiles built in memory). See [`super::Spacing`].
    #[inline]
    pub fn spacing_deviation(&self) -> f64 {
        self.spacing_deviation
    }

    /// The profile with `form` removed by least squares (see [`remove_form`]).
    pub fn remove_form(&self, form: Form) -> Result<Self> {
        let heights = remove_form(&self.heights, form)?;
        Ok(Self {
            heights,
            ..self.clone()
        })
    }

    /// The inverted profile y(x) = −z(x) (thesis 1-9: same autocorrelation and
    /// spectrum, opposite skewness).
    pub fn inverted(&self) -> Self {
        Self {
            heights: self.heights.iter().map(|z| -z).collect(),
            ..self.clone()
        }
    }

    /// The sub-profile of samples `start..end` (its origin moves with it).
    ///
    /// Errors: fewer than 2 samples in the range, or a range outside the
    /// profile.
    pub fn slice(&self, start: usize, end: usize) -> Result<Self> {
        if end > self.len() || end < start + 2 {
            return Err(Error::InvalidArgument {
                name: "end",
                value: end as f64,
                bound: ">= start + 2 and <= profile length in samples",
            });
        }
        Ok(Self {
            dx: self.dx,
            x0: self.x(start),
            heights: self.heights[start..end].to_vec(),
            spacing_deviation: self.spacing_deviation,
        })
    }

    /// ISO 4287 parameters; see [`super::roughness_parameters`].
    pub fn parameters(
        &self,
        options: &super::ParameterOptions,
    ) -> Result<super::RoughnessParameters> {
        super::roughness_parameters(&self.heights, self.dx, options)
    }

    /// One-sided PSD, rectangular window; see [`super::psd`].
    pub fn psd(&self) -> Result<super::Psd> {
        super::psd(&self.heights, self.dx)
    }

    /// Autocorrelation function; see [`super::acf`].
    pub fn acf(&self) -> Result<super::Acf> {
        super::acf(&self.heights, self.dx)
    }

    /// Peaks (3-point maxima); see [`super::peaks()`](fn@super::peaks).
    pub fn peaks(&self) -> Result<Vec<super::Peak>> {
        super::peaks(&self.heights, self.dx)
    }

    /// Gaussian mean-line filter; see [`super::gaussian_filter`].
    pub fn gaussian_filter(
        &self,
        cutoff: f64,
        ends: super::FilterEnds,
    ) -> Result<super::FilteredProfile> {
        super::gaussian_filter(self, cutoff, ends)
    }

    /// The profile of `n` samples built by replicating `pattern` (same spacing
    /// and origin as `self`): the "equivalent profile" of thesis 1.5.4.
    pub fn replicated(&self, pattern: &super::RepresentativePattern, n: usize) -> Result<Self> {
        let heights = pattern.replicate(n)?;
        Ok(Self {
            heights,
            spacing_deviation: 0.0,
            ..self.clone()
        })
    }
}

/// Form removed from a profile by least squares over the sample index
/// (uniform spacing, so fitting in x or in j is the same).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Form {
    /// The mean height.
    Mean,
    /// A straight line (tilt): z ≈ a + b x.
    Linear,
    /// A parabola (tilt and curvature, e.g. a stylus arc or a bow):
    /// z ≈ a + b x + c x².
    Quadratic,
}

/// `heights` minus its least-squares `form` (m).
///
/// The fit uses polynomials orthogonal on the uniform grid,
/// p₀ = 1, p₁ = t, p₂ = t² − (n² − 1)/12 with t = j − (n − 1)/2, so each
/// coefficient is an independent projection ⟨z, p⟩/⟨p, p⟩ — exact least
/// squares, well conditioned for any n, one pass per term.
///
/// Errors: fewer points than the form needs (1, 2, 3) or non-finite heights.
pub fn remove_form(heights: &[f64], form: Form) -> Result<Vec<f64>> {
    let (min, bound) = match form {
        Form::Mean => (1, ">= 1 point"),
        Form::Linear => (2, ">= 2 points for a linear fit"),
        Form::Quadratic => (3, ">= 3 points for a quadratic fit"),
    };
    check_heights(heights, min, bound)?;
    let n = heights.len();
    let nf = n as f64;
    let tc = (nf - 1.0) / 2.0;
    let c2 = (nf * nf - 1.0) / 12.0;
    let m = mean(heights);
    let (mut b1, mut b2) = (0.0, 0.0);
    if form != Form::Mean {
        let (mut s1, mut s11, mut s2, mut s22) = (0.0, 0.0, 0.0, 0.0);
        for (j, &z) in heights.iter().enumerate() {
            let t = j as f64 - tc;
            let p2 = t * t - c2;
            s1 += z * t;
            s11 += t * t;
            s2 += z * p2;
            s22 += p2 * p2;
        }
        b1 = s1 / s11;
        if form == Form::Quadratic {
            b2 = s2 / s22;
        }
    }
    Ok(heights
        .iter()
        .enumerate()
        .map(|(j, &z)| {
            let t = j as f64 - tc;
            z - m - b1 * t - b2 * (t * t - c2)
        })
        .collect())
}

/// A height map on a uniform grid: `heights[j·nx + i] = z(x_i, y_j)` (m) with
/// x_i = i·dx, y_j = j·dy (row-major, x the fast axis).
///
/// Invariants: nx, ny ≥ 2; dx, dy finite and > 0; all heights finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    heights: Vec<f64>,
}

impl Topography {
    /// A map of `nx × ny` points with spacings `dx`, `dy` (m) and row-major
    /// `heights` (m), `heights.len() == nx·ny`.
    pub fn new(nx: usize, ny: usize, dx: f64, dy: f64, heights: Vec<f64>) -> Result<Self> {
        check::positive("dx", dx)?;
        check::positive("dy", dy)?;
        if nx < 2 {
            return Err(Error::InvalidArgument {
                name: "nx",
                value: nx as f64,
                bound: ">= 2",
            });
        }
        if ny < 2 {
            return Err(Error::InvalidArgument {
                name: "ny",
                value: ny as f64,
                bound: ">= 2",
            });
        }
        if heights.len() != nx * ny {
            return Err(Error::InvalidArgument {
                name: "heights.len()",
                value: heights.len() as f64,
                bound: "== nx * ny",
            });
        }
        check_heights(&heights, 4, ">= 4 points")?;
        Ok(Self {
            nx,
            ny,
            dx,
            dy,
            heights,
        })
    }

    /// Points along x.
    #[inline]
    pub fn nx(&self) -> usize {
        self.nx
    }

    /// Points along y.
    #[inline]
    pub fn ny(&self) -> usize {
        self.ny
    }

    /// Spacing along x (m).
    #[inline]
    pub fn dx(&self) -> f64 {
        self.dx
    }

    /// Spacing along y (m).
    #[inline]
    pub fn dy(&self) -> f64 {
        self.dy
    }

    /// Row-major heights (m), `heights()[j*nx + i] = z(x_i, y_j)`.
    #[inline]
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// z(x_i, y_j) (m); `None` outside the grid.
    #[inline]
    pub fn z(&self, i: usize, j: usize) -> Option<f64> {
        (i < self.nx && j < self.ny).then(|| self.heights[j * self.nx + i])
    }

    /// Row `j` (constant y) as a [`Profile`] along x.
    pub fn row(&self, j: usize) -> Result<Profile> {
        if j >= self.ny {
            return Err(Error::InvalidArgument {
                name: "j",
                value: j as f64,
                bound: "< ny",
            });
        }
        Profile::new(
            self.dx,
            self.heights[j * self.nx..(j + 1) * self.nx].to_vec(),
        )
    }

    /// The map with `form` removed by least squares (see [`MapForm`]).
    pub fn remove_form(&self, form: MapForm) -> Result<Self> {
        let (nx, ny) = (self.nx, self.ny);
        let (tcx, tcy) = ((nx as f64 - 1.0) / 2.0, (ny as f64 - 1.0) / 2.0);
        let (cx, cy) = (
            ((nx * nx) as f64 - 1.0) / 12.0,
            ((ny * ny) as f64 - 1.0) / 12.0,
        );
        // Orthogonal basis on the full rectangular grid: 1, tx, ty, tx²−cx,
        // ty²−cy, tx·ty (every pair has zero inner product by symmetry and
        // separability), so each coefficient is an independent projection.
        let basis = |i: usize, j: usize| -> [f64; 5] {
            let tx = i as f64 - tcx;
            let ty = j as f64 - tcy;
            [tx, ty, tx * tx - cx, ty * ty - cy, tx * ty]
        };
        let terms = match form {
            MapForm::Mean => 0,
            MapForm::Plane => 2,
            MapForm::Quadratic => 5,
        };
        let m = mean(&self.heights);
        let mut num = [0.0; 5];
        let mut den = [0.0; 5];
        if terms > 0 {
            for j in 0..ny {
                for i in 0..nx {
                    let z = self.heights[j * nx + i];
                    let b = basis(i, j);
                    for t in 0..terms {
                        num[t] += z * b[t];
                        den[t] += b[t] * b[t];
                    }
                }
            }
        }
        let mut coef = [0.0; 5];
        for t in 0..terms {
            coef[t] = num[t] / den[t];
        }
        let mut heights = self.heights.clone();
        for j in 0..ny {
            for i in 0..nx {
                let b = basis(i, j);
                let f: f64 = (0..terms).map(|t| coef[t] * b[t]).sum();
                heights[j * nx + i] -= m + f;
            }
        }
        Ok(Self {
            heights,
            ..self.clone()
        })
    }

    /// The inverted map −z.
    pub fn inverted(&self) -> Self {
        Self {
            heights: self.heights.iter().map(|z| -z).collect(),
            ..self.clone()
        }
    }

    /// Areal parameters; see [`super::areal_parameters`].
    pub fn parameters(&self) -> Result<super::ArealParameters> {
        super::areal_parameters(self)
    }

    /// Summits (8-neighbour maxima); see [`super::summits`].
    pub fn summits(&self) -> Vec<super::Summit> {
        super::summits(self)
    }
}

/// Form removed from a map by least squares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapForm {
    /// The mean height.
    Mean,
    /// A plane (tilt in x and y): z ≈ a + b x + c y (levelling).
    Plane,
    /// A quadric: z ≈ a + b x + c y + d x² + e y² + f xy.
    Quadratic,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn form_removal_is_exact_on_polynomials() {
        let n = 101;
        let line: Vec<f64> = (0..n).map(|j| 3.0 + 0.25 * j as f64).collect();
        let r = remove_form(&line, Form::Linear).unwrap();
        assert!(r.iter().all(|v| v.abs() < 1e-12));
        let quad: Vec<f64> = (0..n)
            .map(|j| {
                let x = j as f64;
                1.0 - 0.5 * x + 0.01 * x * x
            })
            .collect();
        let r = remove_form(&quad, Form::Quadratic).unwrap();
        assert!(r.iter().all(|v| v.abs() < 1e-11));
        // A linear fit leaves the parabola's curvature.
        let r = remove_form(&quad, Form::Linear).unwrap();
        assert!(r.iter().any(|v| v.abs() > 1.0));
    }

    #[test]
    fn map_plane_and_quadric_removal() {
        let (nx, ny) = (17, 12);
        let mut h = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                let (x, y) = (i as f64, j as f64);
                h.push(2.0 + 0.1 * x - 0.3 * y + 0.02 * x * x + 0.01 * x * y - 0.03 * y * y);
            }
        }
        let t = Topography::new(nx, ny, 1e-6, 2e-6, h).unwrap();
        let q = t.remove_form(MapForm::Quadratic).unwrap();
        assert!(q.heights().iter().all(|v| v.abs() < 1e-11));
        let p = t.remove_form(MapForm::Plane).unwrap();
        assert!(p.heights().iter().any(|v| v.abs() > 0.1));
        assert!(p.heights().iter().sum::<f64>().abs() < 1e-9);
    }
}
