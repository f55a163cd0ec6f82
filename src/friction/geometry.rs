//! Slider geometry from measured profiles (thesis 5.6.1 and 6.2.1).
//!
//! The slider of the multi-scale, multi-level, hierarchical model is a row of
//! flat-ended micro-rods of square cross-section (elastic–perfectly plastic in
//! the friction model), cut from a profilometer profile, whose tips carry
//! equally spaced nano-asperities described by an AFM profile. Each
//! nano-asperity is a body (the van der Waals interaction domain, width
//! w_vdW, height h_vdW) with a tip on top (the chemical interaction domain,
//! width w_chem, height h_chem); both have square cross-sections, depth equal
//! to width (thesis 6.2.1).
//!
//! ## Input profiles: mean line and form
//!
//! Every height here is measured from the profile's mean line, taken as the
//! least-squares level of the profile as given (Z_j of *Formulas*, with
//! z̄ = (1/n) Σ z_j), the convention of [`crate::surface::iso`]. Remove form
//! first so that this level is the mean line of the roughness:
//! `profile.remove_form(Form::Linear)` for a tilt, `Form::Quadratic` for a
//! bow or a stylus arc ([`Profile::remove_form`],
//! [`Form`](crate::surface::Form)), or the Gaussian filter for waviness
//! ([`crate::surface::gaussian_filter`] with the ISO cut-off λc; use its
//! `roughness` profile). Level an AFM map with
//! [`Topography::remove_form`](crate::surface::Topography::remove_form)
//! before taking a row, and remove the row's own tilt (scan-line drift).
//!
//! Each sample stands for one interval dx (as in [`crate::surface`]): the
//! length of a profile of n samples is L = n·dx, and integrals over it are
//! sums of samples times dx.
//!
//! ## Micro-rods (6-1), multi-level
//!
//! Rods of width w tile the profile from its first sample (x_k of
//! *Formulas*), k = 0..N with N = ⌊(n − 1)·dx / w⌋ (the rods cover the
//! sampled extent; the remainder shorter than one rod at the end is not
//! used). The height h_k of rod k is the mean of the profile heights at its
//! two sides, interpolated linearly between samples (thesis (6-1), 6.2.1).
//!
//! With several widths w₀ > w₁ > … each level's rods are nested inside the
//! previous level's rods: w_{ℓ−1}/w_ℓ must be an integer m_ℓ ≥ 2 (a parent
//! rod has at least two descendants, the thesis's definition of a
//! hierarchical model, 5.1), and level ℓ has N₀·m₁·…·m_ℓ rods
//! that exactly tile the N₀ rods of level 0. All levels' heights are measured
//! from the same mean line (not from the parent's tip); the model is
//! multi-level in the thesis's sense (rods of one generation at different
//! heights, 5.1).
//!
//! ## Nano-asperities (5-15, 6-2, 6-3)
//!
//! From the AFM profile, see [`nano_analysis`] for every formula and reading
//! of the text. The number of nano-asperities on one rod tip is
//! [`nano_per_rod`] of the finest rods.
//!
//! ## Statistics of 5.6.1 (5-15..5-19)
//!
//! [`asperity_statistics`] gives, for either profile, the single-level
//! model's asperity height Rq (5-15), mean width at the Rq level (5-16,
//! 5-17) and spacing λ_a (5-18, 5-19). The slider keeps them as a
//! record; they also suggest a rod width (the thesis says the width "should
//! correspond to some statistical property of the roughness profile",
//! 6.2.1).
//!
//! # Formulas
//!
//! Micro-rods (6-1) and the statistics of 5.6.1:
//!
//! $$x_k = x_0 + k\\,w, \qquad h_k = \frac{Z(x_k) + Z(x_k + w)}{2}, \qquad Z_j = z_j - \bar z, \qquad \lambda_a = \frac{2\pi R_q}{R_{\Delta q}} \ \ \text{(5-18), (5-19)} .$$
//!
//! # References
//!
//! * Thesis §5.6.1 ((5-15)–(5-19)) and §6.2.1 ((6-1)–(6-3)).
//! * ISO 4287:1997 (mean line, $R_q$, $R_{\Delta q}$); see [`crate::surface::iso`].

use crate::error::{check, Error, Result};
use crate::surface::{mean, roughness_parameters, ParameterOptions, Profile};
use serde::{Deserialize, Serialize};

/// Relative tolerance on the integer ratio of nested rod widths.
const NEST_TOLERANCE: f64 = 1e-6;
/// Relative slack when counting whole rods or nano-asperity pitches in a
/// length (so that 13.5 µm / 1.35 µm counts 10 despite rounding).
const COUNT_SLACK: f64 = 1e-9;

/// Most rods one level may have: 2²⁴ (16 777 216; 128 MiB of heights, and a
/// slider patch state of 8 + 2 × rods doubles). A larger count (a rod width
/// far below the profile's spacing, or a huge `rods` in
/// [`SliderGeometry::uniform`]) is an error naming the argument instead of an
/// allocation the process cannot survive.
pub const MAX_RODS: usize = 1 << 24;

/// Most nano-asperities one rod may carry: 2²⁴ (a 4096 × 4096 square tip).
/// A nano-asperity spacing far below the rod width (a subnormal spacing, or
/// an AFM profile sampled at 10⁻²⁰ m) would otherwise give a count that
/// overflows `usize` and a friction step that loops over ~10¹⁹ columns per
/// rod; it is an error naming the argument instead.
pub const MAX_NANO_PER_ROD: usize = 1 << 24;

/// `count` rods, or an error naming `name` when it exceeds [`MAX_RODS`].
fn check_rod_count(name: &'static str, count: f64) -> Result<usize> {
    if count > MAX_RODS as f64 {
        return Err(Error::InvalidArgument {
            name,
            value: count,
            bound: "a rod count per level <= MAX_RODS = 2^24",
        });
    }
    Ok(count as usize)
}

/// The argument names of one profile in error messages.
#[derive(Clone, Copy)]
struct Names {
    heights: &'static str,
    len: &'static str,
    dx: &'static str,
}

const PLAIN: Names = Names {
    heights: "heights",
    len: "heights.len()",
    dx: "dx",
};
const MICRO: Names = Names {
    heights: "micro_heights",
    len: "micro_heights.len()",
    dx: "micro_dx",
};
const NANO: Names = Names {
    heights: "nano_heights",
    len: "nano_heights.len()",
    dx: "nano_dx",
};

/// Rename the generic argument names of the surface module's errors to the
/// profile's own (`heights` → `nano_heights`, …).
fn rename(e: Error, names: Names) -> Error {
    let map = |n: &'static str| match n {
        "heights" => names.heights,
        "heights.len()" => names.len,
        "dx" => names.dx,
        other => other,
    };
    match e {
        Error::InvalidArgument { name, value, bound } => Error::InvalidArgument {
            name: map(name),
            value,
            bound,
        },
        Error::OutOfDomain {
            name,
            value,
            reason,
        } => Error::OutOfDomain {
            name: map(name),
            value,
            reason,
        },
        other => other,
    }
}

/// Checks a profile given as a slice: `dx` finite and > 0, at least
/// `min_len` finite heights.
fn check_profile(heights: &[f64], dx: f64, min_len: usize, names: Names) -> Result<()> {
    check::positive(names.dx, dx)?;
    if heights.len() < min_len {
        return Err(Error::InvalidArgument {
            name: names.len,
            value: heights.len() as f64,
            bound: if min_len == 2 {
                ">= 2 points"
            } else {
                ">= 8 points"
            },
        });
    }
    if let Some(&v) = heights.iter().find(|v| !v.is_finite()) {
        return Err(Error::InvalidArgument {
            name: names.heights,
            value: v,
            bound: "finite",
        });
    }
    Ok(())
}

// ------------------------------------------------------------------ 5.6.1

/// The asperity statistics of one profile used by the single-level
/// hierarchical model (thesis 5.6.1). Lengths in m, Δq
/// dimensionless.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AsperityStatistics {
    /// Asperity height Rq = √((1/n) Σ Z_i²) (m), thesis (5-15), the RMS of
    /// the heights from the mean line (computed by
    /// [`roughness_parameters`] over the whole profile).
    #[serde(with = "crate::serde_exact::lenient")]
    pub rq: f64,
    /// Asperity width d̄ = (1/n_d) Σ d_i (m), thesis (5-16, 5-17): the mean
    /// width at the Rq level of the asperities reaching it. d_i is the
    /// length of a run of the profile above Rq, its two ends interpolated
    /// linearly between samples. Runs cut by the ends of the profile have no
    /// known width and are left out; `None` when no complete run exists.
    #[serde(with = "crate::serde_exact::lenient::opt")]
    pub mean_width: Option<f64>,
    /// n_d, the number of complete asperities at the Rq level averaged in
    /// [`Self::mean_width`].
    pub asperities_at_rq: usize,
    /// Root-mean-square slope Δq (dimensionless), thesis (5-19). Computed as
    /// ISO 4287 RΔq by [`roughness_parameters`] (seven-point slopes): the
    /// thesis writes s_i = Δz/Δx with 1/(n − 1); for a sampled profile both
    /// estimate the same RMS slope, the seven-point form with an error
    /// O(dx⁶) instead of O(dx²).
    #[serde(with = "crate::serde_exact::lenient")]
    pub rdq: f64,
    /// Asperity spacing λ_a = 2π Rq / Δq (m), thesis (5-18).
    #[serde(with = "crate::serde_exact::lenient")]
    pub spacing: f64,
}

/// The 5.6.1 statistics (5-15..5-19) of the profile `heights` (m) sampled at
/// `dx` (m), heights from their mean line (see the module docs for form
/// removal).
///
/// Errors: `dx` not finite and > 0; fewer than 8 heights or a non-finite
/// one; constant heights ([`Error::OutOfDomain`]: Rq = 0 has no asperities).
pub fn asperity_statistics(heights: &[f64], dx: f64) -> Result<AsperityStatistics> {
    statistics_named(heights, dx, PLAIN)
}

fn statistics_named(heights: &[f64], dx: f64, names: Names) -> Result<AsperityStatistics> {
    check_profile(heights, dx, 8, names)?;
    let options = ParameterOptions {
        hurst: false,
        ..ParameterOptions::default()
    };
    let r = roughness_parameters(heights, dx, &options).map_err(|e| rename(e, names))?;
    if r.rdq.is_nan() || r.rdq <= 0.0 {
        return Err(Error::OutOfDomain {
            name: names.heights,
            value: r.rdq,
            reason: "RMS slope is zero: the spacing 2*pi*Rq/Dq (5-18) is undefined",
        });
    }
    let zbar = mean(heights);
    let level = r.rq;
    // Runs above Rq; `start` is None while in a run cut by the first sample.
    let (mut sum, mut count) = (0.0, 0usize);
    let mut start: Option<f64> = None;
    let mut above = heights[0] - zbar > level;
    for j in 1..heights.len() {
        let (a, b) = (heights[j - 1] - zbar, heights[j] - zbar);
        let up = b > level;
        if up != above {
            let x = (j - 1) as f64 + (level - a) / (b - a);
            if up {
                start = Some(x);
            } else if let Some(s) = start.take() {
                sum += (x - s) * dx;
                count += 1;
            }
            above = up;
        }
    }
    Ok(AsperityStatistics {
        rq: r.rq,
        mean_width: (count > 0).then(|| sum / count as f64),
        asperities_at_rq: count,
        rdq: r.rdq,
        spacing: 2.0 * core::f64::consts::PI * r.rq / r.rdq,
    })
}

// ------------------------------------------------------------- nano level

/// The nano-asperities on the micro-rod tips (SI): a body of height
/// [`Self::h_vdw`] and width [`Self::w_vdw`] (the van der Waals interaction
/// domain) with a tip of height [`Self::h_chem`] and width [`Self::w_chem`]
/// (the chemical interaction domain) on top, square cross-sections, equally
/// spaced at [`Self::spacing`] (thesis 6.2.1).
///
/// A plain value: build it from numbers (e.g. the hand calculation of thesis
/// 4.4, w_vdW = 430 nm, w_chem = 161 nm) or get it from [`nano_analysis`];
/// [`Self::validate`] checks it, and every [`SliderGeometry`] constructor
/// calls that.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct NanoAsperities {
    /// Height of the van der Waals slab h_vdW (m), > 0: the RMS of the nano
    /// profile about its mean line, thesis (5-15) as 6.2.1 applies it.
    #[serde(with = "crate::serde_exact::lenient")]
    pub h_vdw: f64,
    /// Width of the van der Waals interaction domain w_vdW (m), > 0, thesis
    /// (6-2).
    #[serde(with = "crate::serde_exact::lenient")]
    pub w_vdw: f64,
    /// Height of the chemical slab on top of the body h_chem (m), ≥ 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub h_chem: f64,
    /// Width of the chemical interaction domain w_chem (m), 0 ≤ w_chem ≤
    /// w_vdW.
    #[serde(with = "crate::serde_exact::lenient")]
    pub w_chem: f64,
    /// Distance between neighbouring nano-asperities λ (m), ≥ w_vdW, thesis
    /// (6-3).
    #[serde(with = "crate::serde_exact::lenient")]
    pub spacing: f64,
}

impl NanoAsperities {
    /// Total height of a nano-asperity, body and tip: h_vdW + h_chem (m)
    /// (8.2 nm in the thesis's Figure 6-12).
    #[inline]
    pub fn height(&self) -> f64 {
        self.h_vdw + self.h_chem
    }

    /// Checks the parameters: h_vdW and w_vdW finite and > 0; h_chem finite
    /// and ≥ 0; w_chem finite in [0, w_vdW] (the tip sits on the body);
    /// spacing finite and ≥ w_vdW (neighbours do not overlap).
    pub fn validate(&self) -> Result<()> {
        check::positive("h_vdw", self.h_vdw)?;
        check::positive("w_vdw", self.w_vdw)?;
        check::non_negative("h_chem", self.h_chem)?;
        check::in_range(
            "w_chem",
            self.w_chem,
            0.0,
            self.w_vdw,
            "finite and in [0, w_vdw]",
        )?;
        if !(self.spacing.is_finite() && self.spacing >= self.w_vdw) {
            return Err(Error::InvalidArgument {
                name: "spacing",
                value: self.spacing,
                bound: "finite and >= w_vdw",
            });
        }
        Ok(())
    }
}

/// The nano-asperities of an AFM profile and the quantities they come from
/// (SI: lengths in m, areas in m² of the profile's plane).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct NanoAnalysis {
    /// The nano-asperity parameters.
    pub asperities: NanoAsperities,
    /// The 5.6.1 statistics of the same profile (its `rq` is h_vdW).
    pub statistics: AsperityStatistics,
    /// n_mean, the number of asperities intersected by the mean line.
    pub n_mean: usize,
    /// A_vdW = dx Σ clamp(Z_i, 0, h_vdW) (m²): the material between the mean
    /// line and the h_vdW level.
    #[serde(with = "crate::serde_exact::lenient")]
    pub area_vdw: f64,
    /// A_chem = dx Σ max(Z_i − h_vdW, 0) (m²): the material above the h_vdW
    /// level.
    #[serde(with = "crate::serde_exact::lenient")]
    pub area_chem: f64,
    /// L_nano = n·dx (m), the length of the profile.
    #[serde(with = "crate::serde_exact::lenient")]
    pub length: f64,
    /// Length of the profile above the h_vdW level, dx·#{Z_i > h_vdW} (m).
    #[serde(with = "crate::serde_exact::lenient")]
    pub length_above_rms: f64,
}

/// The nano-asperities of the AFM profile `heights` (m) sampled at `dx` (m)
/// (thesis 6.2.1). With Z_i the heights from the mean line
/// (see the module docs) and each sample standing for one interval dx:
///
/// * h_vdW = Rq = √((1/n) Σ Z_i²), thesis (5-15) (6.2.1: the van der
///   Waals slab height is the RMS about the mean line).
/// * n_mean, the number of asperities intersected by the mean line, is
///   ⌈c/2⌉ with c the number of mean-line crossings (sign changes of Z > 0
///   between neighbouring samples). An asperity inside the profile is
///   crossed twice; the two asperities cut by the profile's ends count as
///   one together, so N whole periods of a periodic profile give N.
/// * w_vdW = A_vdW / (h_vdW · n_mean), thesis (6-2), with A_vdW = dx Σ
///   clamp(Z_i, 0, h_vdW): "the asperity volume bounded by the mean-line and
///   the height of the van der Waals interaction slab … equally distributed
///   to the number of asperities intersected by the mean-line" (6.2.1;
///   material only: valleys below the mean line add nothing, and
///   above h_vdW only the slab's thickness counts).
/// * λ = L_nano / n_mean with L_nano = n·dx, thesis (6-3).
/// * h_chem = (1/m) Σ_{Z_i > h_vdW} (Z_i − h_vdW), m = #{Z_i > h_vdW}: "the
///   arithmetic average of all asperity heights above the height of the van
///   der Waals interaction slab" (6.2.1), measured from the top of
///   the slab, where the tip stands. The total height h_vdW + h_chem is then
///   the mean of the heights above the slab, the quantity the thesis quotes
///   (8.2 nm against a 13.9 nm maximum, Figure 6-12) — the only reading under
///   which that comparison is made on one scale. Read as heights from the
///   mean line, the same number would be the total height, so both readings
///   give the same geometry.
/// * w_chem = A_chem / (h_chem · n_mean) with A_chem = dx Σ max(Z_i −
///   h_vdW, 0): "computed in a similar way to the width of the van der Waals
///   interaction domain. The volume of the asperities above the height of the
///   quadratic mean … is equally distributed to all nano-asperities" (6.2.1;
///   "all nano-asperities" are the n_mean of (6-2)). Since A_chem
///   = m·dx·h_chem, w_chem = m·dx/n_mean, the length above the slab shared
///   among the asperities. When no sample lies above h_vdW (a profile whose
///   RMS is set by deep valleys), h_chem = w_chem = 0: no chemical tip.
///
/// These definitions give w_chem ≤ w_vdW ≤ λ exactly: a sample above h_vdW
/// adds h_vdW·dx to A_vdW, and A_vdW ≤ h_vdW·dx·#{Z_i > 0} ≤ h_vdW·L_nano.
///
/// Errors: `dx` not finite and > 0; fewer than 8 heights or a non-finite
/// one; constant heights ([`Error::OutOfDomain`]).
pub fn nano_analysis(heights: &[f64], dx: f64) -> Result<NanoAnalysis> {
    nano_named(heights, dx, PLAIN)
}

fn nano_named(heights: &[f64], dx: f64, names: Names) -> Result<NanoAnalysis> {
    let statistics = statistics_named(heights, dx, names)?;
    let h = statistics.rq;
    let zbar = mean(heights);
    let mut crossings = 0usize;
    let mut prev_up = heights[0] - zbar > 0.0;
    let (mut clamped, mut excess, mut above) = (0.0, 0.0, 0usize);
    for &zj in heights {
        let z = zj - zbar;
        let up = z > 0.0;
        if up != prev_up {
            crossings += 1;
            prev_up = up;
        }
        clamped += z.clamp(0.0, h);
        if z > h {
            excess += z - h;
            above += 1;
        }
    }
    // Non-constant heights about their mean have samples on both sides.
    let n_mean = crossings.div_ceil(2).max(1);
    let nm = n_mean as f64;
    let area_vdw = clamped * dx;
    let area_chem = excess * dx;
    let length = heights.len() as f64 * dx;
    let h_chem = if above > 0 {
        excess / above as f64
    } else {
        0.0
    };
    let w_vdw = area_vdw / (h * nm);
    // w_chem = A_chem / (h_chem·n_mean) = m·dx/n_mean exactly (A_chem =
    // m·dx·h_chem); written in the second form, and capped at w_vdW, which
    // it equals when no sample lies in (0, h_vdW], so that rounding cannot
    // put the tip wider than the body.
    let w_chem = (above as f64 * dx / nm).min(w_vdw);
    let asperities = NanoAsperities {
        h_vdw: h,
        w_vdw,
        h_chem,
        w_chem,
        spacing: length / nm,
    };
    asperities.validate()?;
    Ok(NanoAnalysis {
        asperities,
        statistics,
        n_mean,
        area_vdw,
        area_chem,
        length,
        length_above_rms: above as f64 * dx,
    })
}

/// The number of nano-asperities on one square rod tip of width `tip_width`
/// (m) at the nano-asperity `spacing` (m): n² with n = ⌊tip_width/spacing⌋,
/// each nano-asperity owning a cell of side λ on the tip (the thesis's
/// "equally spaced rectangles on the tip", 6.2.1, with λ from (6-3); its
/// hand calculation has 100 on a 13.5 µm tip, i.e. 10 × 10 at 1.35 µm).
///
/// Errors: arguments not finite and > 0; a tip narrower than one spacing
/// ([`Error::OutOfDomain`]: it would carry no whole nano-asperity); a tip
/// so much wider than the spacing that n² > [`MAX_NANO_PER_ROD`]
/// ([`Error::OutOfDomain`], `tip_width`).
pub fn nano_per_rod(tip_width: f64, spacing: f64) -> Result<usize> {
    check::positive("tip_width", tip_width)?;
    check::positive("spacing", spacing)?;
    let n = (tip_width / spacing * (1.0 + COUNT_SLACK)).floor();
    if n < 1.0 {
        return Err(Error::OutOfDomain {
            name: "tip_width",
            value: tip_width,
            reason: "narrower than the nano-asperity spacing (6-3): a rod tip would carry no whole nano-asperity; choose wider rods",
        });
    }
    if n * n > MAX_NANO_PER_ROD as f64 {
        return Err(Error::OutOfDomain {
            name: "tip_width",
            value: tip_width,
            reason: "more than 4096 nano-asperity spacings wide: (tip_width/spacing)^2 > MAX_NANO_PER_ROD = 2^24 nano-asperities per rod (is the nano profile's spacing far too small?)",
        });
    }
    let n = n as usize;
    Ok(n * n)
}

// ------------------------------------------------------------ micro level

/// One level of micro-rods: `len()` flat-ended rods of square cross-section
/// and equal width, side by side from `origin`, rod k spanning
/// [origin + k·width, origin + (k+1)·width], with heights (m) from the mean
/// line of the profile they were cut from (thesis 6-1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "RodLevelData")]
pub struct RodLevel {
    #[serde(with = "crate::serde_exact::lenient")]
    width: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    origin: f64,
    #[serde(with = "crate::serde_exact::lenient::vec")]
    heights: Vec<f64>,
}

#[derive(Deserialize)]
struct RodLevelData {
    #[serde(with = "crate::serde_exact::lenient")]
    width: f64,
    #[serde(with = "crate::serde_exact::lenient")]
    origin: f64,
    #[serde(with = "crate::serde_exact::lenient::vec")]
    heights: Vec<f64>,
}

impl TryFrom<RodLevelData> for RodLevel {
    type Error = Error;
    fn try_from(d: RodLevelData) -> Result<Self> {
        Self::new(d.width, d.origin, d.heights)
    }
}

impl RodLevel {
    /// Rods of `width` (m) starting at `origin` (m) with `heights` (m, from
    /// the mean line; one per rod).
    ///
    /// Errors: `width` not finite and > 0; `origin` not finite; no heights;
    /// a non-finite height.
    pub fn new(width: f64, origin: f64, heights: Vec<f64>) -> Result<Self> {
        check::positive("width", width)?;
        check::finite("origin", origin)?;
        if heights.is_empty() {
            return Err(Error::InvalidArgument {
                name: "heights.len()",
                value: 0.0,
                bound: ">= 1 rod",
            });
        }
        if let Some(&v) = heights.iter().find(|v| !v.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "heights",
                value: v,
                bound: "finite",
            });
        }
        Ok(Self {
            width,
            origin,
            heights,
        })
    }

    /// Rod width (m); also the depth of the square cross-section.
    #[inline]
    pub fn width(&self) -> f64 {
        self.width
    }

    /// Position of the left side of rod 0 (m).
    #[inline]
    pub fn origin(&self) -> f64 {
        self.origin
    }

    /// Rod heights from the mean line (m).
    #[inline]
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// Number of rods.
    #[inline]
    pub fn len(&self) -> usize {
        self.heights.len()
    }

    /// Always `false`: a level has at least one rod.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.heights.is_empty()
    }

    /// Left side of rod `k` (m): origin + k·width.
    #[inline]
    pub fn left(&self, k: usize) -> f64 {
        self.origin + k as f64 * self.width
    }

    /// Centre of rod `k` (m).
    #[inline]
    pub fn center(&self, k: usize) -> f64 {
        self.origin + (k as f64 + 0.5) * self.width
    }
}

/// Z at `s` (in samples from the first) by linear interpolation; `s` in
/// [0, n − 1] up to rounding (clamped).
#[inline]
fn interpolate(z: &[f64], s: f64) -> f64 {
    let j = (s.max(0.0).floor() as usize).min(z.len() - 2);
    let t = (s - j as f64).clamp(0.0, 1.0);
    z[j] + t * (z[j + 1] - z[j])
}

/// Heights (m) of the rods of `width` (m) cut from the profile `heights` (m)
/// sampled at `dx` (m): h_k = (Z(k·w) + Z((k+1)·w))/2, thesis (6-1), Z the
/// heights from the mean line interpolated linearly, k = 0..⌊(n−1)·dx/w⌋
/// (see the module docs). The single-level form of [`rod_levels`].
///
/// Errors as [`rod_levels`].
pub fn rod_heights(heights: &[f64], dx: f64, width: f64) -> Result<Vec<f64>> {
    Ok(levels_named(heights, dx, 0.0, &[width], PLAIN)?
        .pop()
        .expect("one level")
        .heights)
}

/// Nested levels of rods cut from the profile `heights` (m) sampled at `dx`
/// (m), one level per width in `widths` (m, decreasing), rod 0 of every
/// level starting at the first sample (origin 0; [`SliderGeometry::from_profiles`]
/// uses the profile's x₀). Heights by (6-1) from the mean line; see the
/// module docs for the tiling and the nesting.
///
/// Errors: `dx` not finite and > 0; fewer than 2 heights or a non-finite
/// one; `widths` empty (`widths.len()`); a width not finite and > 0, or the
/// first wider than the sampled extent (n − 1)·dx; a width that is not the
/// previous one divided by an integer ≥ 2 (to a relative 10⁻⁶): levels that
/// do not nest (all `rod_widths`).
pub fn rod_levels(heights: &[f64], dx: f64, widths: &[f64]) -> Result<Vec<RodLevel>> {
    levels_named(heights, dx, 0.0, widths, PLAIN)
}

fn levels_named(
    heights: &[f64],
    dx: f64,
    origin: f64,
    widths: &[f64],
    names: Names,
) -> Result<Vec<RodLevel>> {
    check_profile(heights, dx, 2, names)?;
    check_widths(widths)?;
    let extent = (heights.len() - 1) as f64 * dx;
    let w0 = widths[0];
    let n0 = (extent / w0 * (1.0 + COUNT_SLACK)).floor();
    if n0 < 1.0 {
        return Err(Error::InvalidArgument {
            name: "rod_widths",
            value: w0,
            bound: "<= the profile's sampled extent (n - 1) * dx",
        });
    }
    // Every level's count is bounded before anything is allocated.
    let mut count = check_rod_count("rod_widths", n0)?;
    let mut counts = Vec::with_capacity(widths.len());
    for (l, &w) in widths.iter().enumerate() {
        if l > 0 {
            let m = nesting(widths[l - 1], w).expect("checked");
            count = check_rod_count("rod_widths", count as f64 * m as f64)?;
        }
        counts.push(count);
    }
    let zbar = mean(heights);
    let z: Vec<f64> = heights.iter().map(|h| h - zbar).collect();
    let mut levels = Vec::with_capacity(widths.len());
    for (&w, &count) in widths.iter().zip(&counts) {
        let edge = |k: usize| interpolate(&z, k as f64 * w / dx);
        let mut left = edge(0);
        let mut hs = Vec::with_capacity(count);
        for k in 0..count {
            let right = edge(k + 1);
            hs.push(0.5 * (left + right));
            left = right;
        }
        levels.push(RodLevel::new(w, origin, hs)?);
    }
    Ok(levels)
}

/// m = parent/child when it is an integer ≥ 2 (to [`NEST_TOLERANCE`]).
fn nesting(parent: f64, child: f64) -> Option<usize> {
    let r = parent / child;
    let m = r.round();
    (m >= 2.0 && (r - m).abs() <= NEST_TOLERANCE * r).then_some(m as usize)
}

fn check_widths(widths: &[f64]) -> Result<()> {
    if widths.is_empty() {
        return Err(Error::InvalidArgument {
            name: "rod_widths.len()",
            value: 0.0,
            bound: ">= 1 level",
        });
    }
    for (l, &w) in widths.iter().enumerate() {
        check::positive("rod_widths", w)?;
        if l > 0 && nesting(widths[l - 1], w).is_none() {
            return Err(Error::InvalidArgument {
                name: "rod_widths",
                value: w,
                bound: "the previous width divided by an integer >= 2 (nested levels, widths decreasing)",
            });
        }
    }
    Ok(())
}

// ---------------------------------------------------------------- slider

/// The slider of the multi-scale, multi-level hierarchical friction model
/// (thesis 6.2.1): nested levels of micro-rods (the last level's rods carry
/// the nano-asperities on their tips), the nano-asperity parameters, the
/// number of nano-asperities per rod tip, and — when built from profiles —
/// the statistics they were derived from.
///
/// Immutable after construction, `Send + Sync`; serialisable with serde
/// (deserialisation validates, so a stored geometry cannot break the
/// invariants). Numbers are written as exact decimal strings (`"1.35e-6"`)
/// so that a stored geometry reads back bit-identically; plain JSON numbers
/// are accepted when reading hand-written files. All lengths in m.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "SliderGeometryData")]
pub struct SliderGeometry {
    levels: Vec<RodLevel>,
    nano: NanoAsperities,
    nano_per_rod: usize,
    micro_statistics: Option<AsperityStatistics>,
    nano_analysis: Option<NanoAnalysis>,
}

#[derive(Deserialize)]
struct SliderGeometryData {
    levels: Vec<RodLevel>,
    nano: NanoAsperities,
    nano_per_rod: usize,
    micro_statistics: Option<AsperityStatistics>,
    nano_analysis: Option<NanoAnalysis>,
}

impl TryFrom<SliderGeometryData> for SliderGeometry {
    type Error = Error;
    fn try_from(d: SliderGeometryData) -> Result<Self> {
        let mut g = Self::new(d.levels, d.nano, d.nano_per_rod)?;
        if let Some(a) = d.nano_analysis {
            if a.asperities != g.nano {
                return Err(Error::InvalidArgument {
                    name: "nano_analysis",
                    value: a.asperities.w_vdw,
                    bound: "a record whose asperities equal `nano`",
                });
            }
        }
        g.micro_statistics = d.micro_statistics;
        g.nano_analysis = d.nano_analysis;
        Ok(g)
    }
}

impl SliderGeometry {
    /// The slider from a profilometer profile `micro` (the rods) and an AFM
    /// profile `nano` (the nano-asperities), with one level of rods per width
    /// in `rod_widths` (m, decreasing, each the previous divided by an
    /// integer ≥ 2). Rod positions start at the micro profile's x₀. See
    /// [`Self::from_slices`].
    pub fn from_profiles(micro: &Profile, rod_widths: &[f64], nano: &Profile) -> Result<Self> {
        Self::build(
            micro.heights(),
            micro.dx(),
            micro.x0(),
            rod_widths,
            nano.heights(),
            nano.dx(),
        )
    }

    /// The slice form of [`Self::from_profiles`] (rods start at x = 0):
    /// rod levels by (6-1) from `micro_heights` (m) sampled at `micro_dx`
    /// (m) ([`rod_levels`]), the nano-asperities of `nano_heights` (m)
    /// sampled at `nano_dx` (m) ([`nano_analysis`]), [`nano_per_rod`] of the
    /// finest rods, and the 5.6.1 statistics of the micro profile
    /// ([`asperity_statistics`]). Remove form from both profiles first (see
    /// the module docs).
    ///
    /// Errors, naming the argument: `micro_dx`, `nano_dx` not finite and > 0;
    /// fewer than 8 heights or non-finite ones in either profile
    /// (`micro_heights`, `nano_heights`); a constant profile
    /// ([`Error::OutOfDomain`]); the `rod_widths` errors of [`rod_levels`];
    /// finest rods narrower than the nano-asperity spacing
    /// ([`Error::OutOfDomain`], `rod_widths`).
    pub fn from_slices(
        micro_heights: &[f64],
        micro_dx: f64,
        rod_widths: &[f64],
        nano_heights: &[f64],
        nano_dx: f64,
    ) -> Result<Self> {
        Self::build(
            micro_heights,
            micro_dx,
            0.0,
            rod_widths,
            nano_heights,
            nano_dx,
        )
    }

    fn build(
        micro_heights: &[f64],
        micro_dx: f64,
        origin: f64,
        rod_widths: &[f64],
        nano_heights: &[f64],
        nano_dx: f64,
    ) -> Result<Self> {
        check_profile(micro_heights, micro_dx, 8, MICRO)?;
        let levels = levels_named(micro_heights, micro_dx, origin, rod_widths, MICRO)?;
        let micro_statistics = statistics_named(micro_heights, micro_dx, MICRO)?;
        let analysis = nano_named(nano_heights, nano_dx, NANO)?;
        let tip = *rod_widths.last().expect("checked");
        let per_rod = nano_per_rod(tip, analysis.asperities.spacing).map_err(|e| match e {
            Error::OutOfDomain { value, reason, .. } => Error::OutOfDomain {
                name: "rod_widths",
                value,
                reason,
            },
            other => other,
        })?;
        let mut g = Self::new(levels, analysis.asperities, per_rod)?;
        g.micro_statistics = Some(micro_statistics);
        g.nano_analysis = Some(analysis);
        Ok(g)
    }

    /// The slider from numbers: rod `levels` (coarsest first; see
    /// [`RodLevel::new`]), the `nano` parameters and `nano_per_rod`
    /// nano-asperities on each tip of the finest level.
    ///
    /// Errors: no levels (`levels.len()`); levels that do not nest (each
    /// width the previous divided by an integer m ≥ 2, m times as many rods,
    /// the same origin; named `levels`); invalid `nano`
    /// ([`NanoAsperities::validate`]); `nano_per_rod` = 0, above
    /// [`MAX_NANO_PER_ROD`], or more cells of side `spacing` than fit on the
    /// finest rod's square tip, nano_per_rod·λ² > w² (`nano_per_rod`).
    pub fn new(levels: Vec<RodLevel>, nano: NanoAsperities, nano_per_rod: usize) -> Result<Self> {
        if levels.is_empty() {
            return Err(Error::InvalidArgument {
                name: "levels.len()",
                value: 0.0,
                bound: ">= 1",
            });
        }
        for pair in levels.windows(2) {
            let (p, c) = (&pair[0], &pair[1]);
            let ok = nesting(p.width, c.width).is_some_and(|m| c.len() == p.len() * m)
                && (c.origin - p.origin).abs() <= NEST_TOLERANCE * p.width;
            if !ok {
                return Err(Error::InvalidArgument {
                    name: "levels",
                    value: c.width,
                    bound: "nested: each width the previous divided by an integer m >= 2, with m times as many rods and the same origin",
                });
            }
        }
        nano.validate()?;
        let tip = levels.last().expect("non-empty").width;
        let cells = nano_per_rod as f64 * nano.spacing * nano.spacing;
        if nano_per_rod == 0
            || nano_per_rod > MAX_NANO_PER_ROD
            || cells > tip * tip * (1.0 + COUNT_SLACK)
        {
            return Err(Error::InvalidArgument {
                name: "nano_per_rod",
                value: nano_per_rod as f64,
                bound: ">= 1, <= MAX_NANO_PER_ROD = 2^24 and nano_per_rod * spacing^2 <= (finest rod width)^2",
            });
        }
        Ok(Self {
            levels,
            nano,
            nano_per_rod,
            micro_statistics: None,
            nano_analysis: None,
        })
    }

    /// A single level of `rods` flat rods of `rod_width` (m) at height 0
    /// from origin 0 (the single-level slider of thesis 5.6, or the one
    /// micro-asperity of the hand calculation 4.4: 13.5 µm, 100
    /// nano-asperities). Errors as [`Self::new`] and [`RodLevel::new`]
    /// (`rods` = 0 is `heights.len()`; more than [`MAX_RODS`] is an error
    /// naming `rods`).
    pub fn uniform(
        rod_width: f64,
        rods: usize,
        nano: NanoAsperities,
        nano_per_rod: usize,
    ) -> Result<Self> {
        check_rod_count("rods", rods as f64)?;
        let level = RodLevel::new(rod_width, 0.0, vec![0.0; rods]).map_err(|e| match e {
            Error::InvalidArgument {
                name: "width",
                value,
                bound,
            } => Error::InvalidArgument {
                name: "rod_width",
                value,
                bound,
            },
            Error::InvalidArgument {
                name: "heights.len()",
                value,
                ..
            } => Error::InvalidArgument {
                name: "rods",
                value,
                bound: ">= 1",
            },
            other => other,
        })?;
        Self::new(vec![level], nano, nano_per_rod)
    }

    /// The rod levels, coarsest first.
    #[inline]
    pub fn levels(&self) -> &[RodLevel] {
        &self.levels
    }

    /// The finest level, whose rod tips carry the nano-asperities.
    #[inline]
    pub fn tips(&self) -> &RodLevel {
        self.levels.last().expect("at least one level")
    }

    /// The number of children of each rod of `level` in the next level
    /// (its width over theirs; rod k's children are k·m..(k+1)·m); `None`
    /// for the finest level or past it.
    pub fn branching(&self, level: usize) -> Option<usize> {
        let next = self.levels.get(level + 1)?;
        Some(next.len() / self.levels[level].len())
    }

    /// The nano-asperity parameters.
    #[inline]
    pub fn nano(&self) -> &NanoAsperities {
        &self.nano
    }

    /// Nano-asperities on one rod tip of the finest level.
    #[inline]
    pub fn nano_per_rod(&self) -> usize {
        self.nano_per_rod
    }

    /// Nano-asperities on the whole slider: finest rods × per tip.
    #[inline]
    pub fn nano_total(&self) -> usize {
        self.tips().len() * self.nano_per_rod
    }

    /// The 5.6.1 statistics of the micro profile (`None` when built from
    /// numbers).
    #[inline]
    pub fn micro_statistics(&self) -> Option<&AsperityStatistics> {
        self.micro_statistics.as_ref()
    }

    /// The analysis of the nano profile (`None` when built from numbers).
    #[inline]
    pub fn nano_analysis(&self) -> Option<&NanoAnalysis> {
        self.nano_analysis.as_ref()
    }

    /// JSON text of the geometry (numbers written exactly).
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a geometry always serialises")
    }

    /// A geometry from [`Self::to_json`] text, validated as by
    /// [`Self::new`]. Errors: malformed text (`json`, the value is the line)
    /// or the error of the invalid field.
    pub fn from_json(json: &str) -> Result<Self> {
        let d: SliderGeometryData = serde_json::from_str(json).map_err(|e| {
            // A level that fails `RodLevel::new` surfaces here as text.
            Error::InvalidArgument {
                name: "json",
                value: e.line() as f64,
                bound: "a serialised SliderGeometry (syntax, field or value error at this line)",
            }
        })?;
        Self::try_from(d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_is_linear_and_clamped() {
        let z = [0.0, 2.0, -2.0];
        assert_eq!(interpolate(&z, 0.0), 0.0);
        assert_eq!(interpolate(&z, 0.25), 0.5);
        assert_eq!(interpolate(&z, 1.5), 0.0);
        assert_eq!(interpolate(&z, 2.0), -2.0);
        assert_eq!(interpolate(&z, 2.0 + 1e-12), -2.0);
    }

    #[test]
    fn nesting_ratio() {
        assert_eq!(nesting(13.5e-6, 1.5e-6), Some(9));
        assert_eq!(nesting(2.0, 1.0), Some(2));
        assert_eq!(nesting(1.0, 1.0), None);
        assert_eq!(nesting(5.0, 2.0), None);
        assert_eq!(nesting(1.0, 2.0), None);
    }
}
