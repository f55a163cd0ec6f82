//! Profile parameters in the two conventions users meet (ISO 21920-2:2021,
//! the default, and ISO 4287:1997 with ISO 4288:1996; thesis 1.5.1), the
//! material-ratio (Abbott–Firestone) curve, and areal parameters of maps
//! (ISO 25178-2). The ISO 13565-2 and ISO 25178-2 functional parameters of
//! the material-ratio curve (Rk, Sk, Vmp, …) are in [`super::material_ratio`].
//!
//! Conventions, for a profile z_j, j = 0..n, spacing dx:
//!
//! * Heights are measured from the mean line. The profile is taken as given
//!   (filter or form-remove it first: [`super::gaussian_filter`],
//!   [`super::remove_form`]); the mean line is its least-squares level over
//!   the evaluation length, z̄ = mean(z), and Z(x) = z − z̄.
//! * Sections (ISO 21920-2 "sections", ISO 4287 "sampling lengths"): with
//!   [`ParameterOptions::sampling_length`] = l, the evaluation length is the
//!   first ⌊n·dx / l⌋ whole sections of m = round(l/dx) samples (a remainder
//!   at the end is ignored). Without a sampling length the whole profile is
//!   one section. ISO 4288 and ISO 21920-3 tie l to the cut-off: l = λc,
//!   five sections.
//! * Which parameters are averaged over the sections ([`Convention`]):
//!
//!   | parameter | [`Convention::Iso21920`] (default) | [`Convention::Iso4287`] |
//!   |---|---|---|
//!   | Rp, Rv, Rz | mean of the section values | mean of the section values |
//!   | Rt | evaluation length | evaluation length |
//!   | Ra, Rq, Rsk, Rku, RΔq | evaluation length | mean of the section values |
//!   | Rc, RSm | evaluation length | mean of the section values |
//!
//!   ISO 21920-2 evaluates the field parameters over the evaluation length
//!   and keeps section means only for the peak/valley heights Rp, Rv, Rz
//!   (whose evaluation-length forms are Rpt, Rvt, Rt). ISO 4287 defines
//!   nearly every parameter on a sampling length, and ISO 4288 §4.1 averages
//!   over the sampling lengths. On a skewed profile the two differ: for the
//!   Hommel scan of `shared/data/profiles` (quadratic form removed, λc =
//!   0.8 mm, five sections) Rq is 22.60 nm over the evaluation length and
//!   19.57 nm as the mean of the section values (the mean of square roots
//!   is below the square root of the mean); Rsk 5.974 against 4.027, Rku
//!   62.62 against 45.30. surfalize (Profile.Rq, Rsk, Rku; Rp, Rv, Rz with
//!   `n_sections = 5`) follows the ISO 21920-2 column: 22.7 nm, 5.97, 62.1
//!   (`tests/surface_standards.rs` holds both within 1 %).
//! * Integrals are sample means (each sample stands for one interval dx),
//!   e.g. Rq for (1-5) (*Formulas*).
//! * Profile elements (Rc, RSm): runs of the profile between mean-line
//!   crossings (interpolated linearly) are peaks (Z > 0) or valleys. The runs
//!   cut by the ends of the section or evaluation length count as a peak or
//!   valley too (ISO 4287 §3.2.3, note), from or to the end of the last
//!   sample's interval. A run lower than the height discrimination or
//!   narrower than the width discrimination (default 1 % of the section
//!   length) is counted as part of the preceding peak or valley
//!   (ISO 4287 §3.2.8–3.2.9).
//!   * ISO 4287: the height discrimination is 10 % of Rz of the sampling
//!     length, for peaks and valleys alike; an element is a peak with the
//!     valley that follows it; Rc and RSm are averaged over the sampling
//!     lengths that hold an element.
//!   * ISO 21920-2: the height discriminations are 10 % of Rp for peaks and
//!     10 % of Rv for valleys; an element is a peak with the adjacent valley
//!     in either order (evaluated in both directions), over the evaluation
//!     length (as documented for ISO 21920-2 by Mahr's MarSurf manual; the
//!     standard's text was not available here). Pairs with a part cut by an
//!     end of the evaluation length are left out (counted in both directions
//!     they would bias RSm low by about Λ/(2N) on N periods).
//!
//!   Why the ISO 4287 rule finds no element on strongly skewed scans: on the
//!   Hommel roughness profile Rv ≈ 29 nm against Rz ≈ 229 nm, so almost no
//!   valley reaches 10 % of Rz and no peak is followed by a significant
//!   valley — Rc and RSm are `None` by the standard's own rule. Scaling the
//!   valley threshold with Rv (ISO 21920-2) finds them.
//! * Local slopes dZ/dX for RΔq use the seven-point formula of *Formulas*,
//!   with the 5- and 3-point central formulas within
//!   three samples of the ends and one-sided differences at the end points.
//!
//! # Formulas
//!
//! Over a section (ISO 4287) or the evaluation length (ISO 21920-2) of $m$
//! samples, $Z_j = z_j - \bar z$:
//!
//! $$R_a = \frac1m\sum_j \lvert Z_j\rvert, \qquad R_q = \sqrt{\frac1m\sum_j Z_j^2}, \qquad R_{sk} = \frac{1}{R_q^3}\\,\frac1m\sum_j Z_j^3, \qquad R_{ku} = \frac{1}{R_q^4}\\,\frac1m\sum_j Z_j^4,$$
//!
//! $$R_{\Delta q} = \sqrt{\frac1m\sum_j\Bigl(\frac{dZ}{dX}\Bigr)\_j^2}, \qquad \Bigl(\frac{dZ}{dX}\Bigr)\_j = \frac{Z_{j+3} - 9Z_{j+2} + 45Z_{j+1} - 45Z_{j-1} + 9Z_{j-2} - Z_{j-3}}{60\\,dx} .$$
//!
//! For $z = A\sin(2\pi x/\Lambda)$ over whole periods: $R_a = 2A/\pi$,
//! $R_q = A/\sqrt2$, $R_{sk} = 0$, $R_{ku} = 1.5$, $R_{\Delta q} = \sqrt2\\,\pi A/\Lambda$,
//! $R_{Sm} = \Lambda$, in both conventions.
//!
//! # References
//!
//! * ISO 21920-2:2021, *Geometrical product specifications (GPS) — Surface
//!   texture: Profile — Part 2: Terms, definitions and surface texture
//!   parameters*; ISO 21920-3:2021 (specification operators, section length
//!   and number of sections).
//! * ISO 4287:1997, *Geometrical Product Specifications (GPS) — Surface texture:
//!   Profile method — Terms, definitions and surface texture parameters*.
//! * ISO 4288:1996 (sampling lengths); ISO 25178-2:2012 (areal parameters).
//! * Mahr, MarSurf software documentation (ISO 21920-2 parameters: Rp, Rv as
//!   section means, Rpt, Rvt over the evaluation length, profile elements in
//!   both directions with 10 % Rp / 10 % Rv thresholds).
//! * surfalize (Python package, github.com/fredericjs/surfalize), `Profile`
//!   parameters: the Hommel comparison above.
//! * Thesis §1.5.1, (1-5).

use super::{check_heights, mean, Topography};
use crate::error::{check, Error, Result};
use serde::{Deserialize, Serialize};

/// Which standard's evaluation rules [`roughness_parameters`] follows (see
/// the module docs for the table of what each averages over sections).
/// Serialised as the standard's name, `"ISO 21920-2:2021"` or
/// `"ISO 4287:1997"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Convention {
    /// ISO 21920-2:2021 (the default): Ra, Rq, Rsk, Rku, RΔq, Rc, RSm over the
    /// evaluation length; Rp, Rv, Rz section means; profile elements with
    /// 10 % Rp / 10 % Rv height discrimination, in both directions.
    #[default]
    #[serde(rename = "ISO 21920-2:2021")]
    Iso21920,
    /// ISO 4287:1997 with ISO 4288:1996: every parameter but Rt on a
    /// sampling length, averaged over the sampling lengths; profile elements
    /// with 10 % Rz height discrimination, a peak and the following valley.
    #[serde(rename = "ISO 4287:1997")]
    Iso4287,
}

impl Convention {
    /// The standard's name, as serialised (`"ISO 21920-2:2021"`).
    pub fn name(self) -> &'static str {
        match self {
            Convention::Iso21920 => "ISO 21920-2:2021",
            Convention::Iso4287 => "ISO 4287:1997",
        }
    }
}

/// Profile parameters (all lengths in m, slopes and shape factors
/// dimensionless) in the [`Convention`] named by [`Self::convention`].
/// Serialised with the ISO symbols as names (`Rp`, `Rv`, …, `RDq` for RΔq)
/// and `convention`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RoughnessParameters {
    /// Maximum profile peak height Rp = max Z within a sampling length (m).
    #[serde(rename = "Rp")]
    pub rp: f64,
    /// Maximum profile valley depth Rv = −min Z within a sampling length (m).
    #[serde(rename = "Rv")]
    pub rv: f64,
    /// Maximum height Rz = Rp + Rv within a sampling length (m).
    #[serde(rename = "Rz")]
    pub rz: f64,
    /// Mean height of profile elements Rc = (1/m) Σ Zt_i (m); `None` when no
    /// complete element (a peak and the adjacent valley, both above the
    /// height and width discriminations) lies in any sampling length.
    #[serde(rename = "Rc")]
    pub rc: Option<f64>,
    /// Total height Rt = max Z − min Z over the evaluation length (m); Rt ≥ Rz.
    #[serde(rename = "Rt")]
    pub rt: f64,
    /// Arithmetic mean deviation Ra = (1/l) ∫ |Z| dx (m).
    #[serde(rename = "Ra")]
    pub ra: f64,
    /// Root-mean-square deviation Rq = √((1/l) ∫ Z² dx) (m), thesis (1-5).
    #[serde(rename = "Rq")]
    pub rq: f64,
    /// Skewness Rsk = (1/Rq³)(1/l) ∫ Z³ dx.
    #[serde(rename = "Rsk")]
    pub rsk: f64,
    /// Kurtosis Rku = (1/Rq⁴)(1/l) ∫ Z⁴ dx (3 for a Gaussian, 1.5 for a sine).
    #[serde(rename = "Rku")]
    pub rku: f64,
    /// Mean width of profile elements RSm = (1/m) Σ Xs_i (m); `None` as for
    /// [`Self::rc`].
    #[serde(rename = "RSm")]
    pub rsm: Option<f64>,
    /// Root-mean-square slope RΔq = √((1/l) ∫ (dZ/dX)² dx) (dimensionless).
    #[serde(rename = "RDq")]
    pub rdq: f64,
    /// Hurst exponent H of a power-law fit PSD ∝ q^{−(1+2H)} (see
    /// [`super::psd_hurst_exponent`]); `None` when not requested, the profile
    /// is too short, or the spectrum is not a power law over the fit band.
    pub psd_hurst_exponent: Option<f64>,
    /// Sampling (section) length used (m).
    pub sampling_length: f64,
    /// Number of sampling lengths (sections) in the evaluation length.
    pub sampling_lengths: usize,
    /// The standard whose rules gave these values.
    pub convention: Convention,
}

impl RoughnessParameters {
    /// Why Rc and RSm are `None`, or `None` when they are given: no profile
    /// element passes the height (10 % by default) and width (1 % of the
    /// sampling length) discriminations (ISO 4287 §3.2.8–3.2.9), which
    /// happens to a form-dominated profile without a cut-off and to tall
    /// peaks narrower than the width discrimination.
    pub fn profile_elements_reason(&self) -> Option<&'static str> {
        self.rc.is_none().then_some(
            "no profile element passes the convention's height (10 %) and width (1 % of the \
             sampling length) discriminations: a form-dominated profile (give a cut-off λc) or \
             tall peaks narrower than the width discrimination",
        )
    }
}

/// Options of [`roughness_parameters`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParameterOptions {
    /// Sampling length l (m); `None` = the whole profile is one sampling
    /// length. ISO 4288 ties l to the cut-off: l = λc, 5 sampling lengths.
    pub sampling_length: Option<f64>,
    /// Height discrimination for profile elements (Rc, RSm), as a fraction:
    /// of Rz of the sampling length for ISO 4287, of Rp (peaks) and Rv
    /// (valleys) for ISO 21920-2; default 0.1 in both.
    pub height_discrimination: f64,
    /// Width discrimination for profile elements, as a fraction of the
    /// sampling length: ISO 4287 default 0.01.
    pub width_discrimination: f64,
    /// Fit the Hurst exponent (one extra FFT); default `true`.
    pub hurst: bool,
    /// Evaluation rules; default [`Convention::Iso21920`].
    pub convention: Convention,
}

impl Default for ParameterOptions {
    fn default() -> Self {
        Self {
            sampling_length: None,
            height_discrimination: 0.1,
            width_discrimination: 0.01,
            hurst: true,
            convention: Convention::Iso21920,
        }
    }
}

/// Local slope dZ/dX at sample `i` of `z` (len `n`, spacing `dx`): 7-point
/// formula, 5- and 3-point near the ends, one-sided at the end points.
#[inline]
pub(crate) fn slope_at(z: &[f64], i: usize, dx: f64) -> f64 {
    let n = z.len();
    if i >= 3 && i + 3 < n {
        (z[i + 3] - 9.0 * z[i + 2] + 45.0 * z[i + 1] - 45.0 * z[i - 1] + 9.0 * z[i - 2] - z[i - 3])
            / (60.0 * dx)
    } else if i >= 2 && i + 2 < n {
        (-z[i + 2] + 8.0 * z[i + 1] - 8.0 * z[i - 1] + z[i - 2]) / (12.0 * dx)
    } else if i >= 1 && i + 1 < n {
        (z[i + 1] - z[i - 1]) / (2.0 * dx)
    } else if i == 0 {
        (z[1] - z[0]) / dx
    } else {
        (z[n - 1] - z[n - 2]) / dx
    }
}

/// Height and width thresholds of profile elements, and which pairs form
/// an element.
#[derive(Clone, Copy)]
struct Discrimination {
    /// Minimum height of a peak (m).
    peak: f64,
    /// Minimum depth of a valley (m).
    valley: f64,
    /// Minimum width of a peak or valley (samples).
    width: f64,
    /// Valley–peak pairs count too (ISO 21920-2), not only peak–valley.
    both_directions: bool,
}

/// Profile elements of `seg` (heights `seg − zbar` from the mean line): mean
/// width Xs (in samples) and mean height Zt, or `None` without an element.
///
/// Runs between mean-line crossings (crossings interpolated linearly) are
/// peaks (Z > 0) or valleys; the runs cut by the ends count too (ISO 4287
/// §3.2.3, note), the first from 0 and the last to `seg.len()` (each sample
/// stands for one interval). A run lower than its height threshold or
/// narrower than the width threshold is counted as part of the preceding
/// peak or valley (ISO 4287 §3.2.8–3.2.9); a leading insignificant run is
/// dropped. An element is a significant peak with the following significant
/// valley (ISO 4287), or, with `both_directions`, any two adjacent
/// significant parts neither of which touches an end (a pair cut by an end
/// is shorter than a whole element, and counting pairs in both directions
/// would weigh the cut ones twice).
fn elements(seg: &[f64], zbar: f64, d: Discrimination) -> Option<(f64, f64)> {
    #[derive(Clone, Copy)]
    struct Part {
        up: bool,
        start: f64,
        end: f64,
        ext: f64,
        /// Touches an end of `seg` (itself or a run merged into it).
        cut: bool,
    }
    let mut parts: Vec<Part> = Vec::new();
    let close = |run: Part, parts: &mut Vec<Part>| {
        let h = if run.up { d.peak } else { d.valley };
        if run.ext >= h && run.ext > 0.0 && run.end - run.start >= d.width {
            match parts.last_mut() {
                Some(p) if p.up == run.up => {
                    p.end = run.end;
                    p.ext = p.ext.max(run.ext);
                    p.cut |= run.cut;
                }
                _ => parts.push(run),
            }
        } else if let Some(p) = parts.last_mut() {
            p.end = run.end;
            p.cut |= run.cut;
        }
    };
    let mut prev = seg[0] - zbar;
    let mut up = prev > 0.0;
    let mut start = 0.0;
    let mut ext = prev.abs();
    for (j, &z) in seg.iter().enumerate().skip(1) {
        let dj = z - zbar;
        let u = dj > 0.0;
        if u != up {
            let x = (j - 1) as f64 + prev / (prev - dj);
            close(
                Part {
                    up,
                    start,
                    end: x,
                    ext,
                    cut: start == 0.0,
                },
                &mut parts,
            );
            start = x;
            up = u;
            ext = 0.0;
        }
        ext = ext.max(dj.abs());
        prev = dj;
    }
    close(
        Part {
            up,
            start,
            end: seg.len() as f64,
            ext,
            cut: true,
        },
        &mut parts,
    );
    let (mut sx, mut sz, mut count) = (0.0, 0.0, 0usize);
    for w in parts.windows(2) {
        // Pairs of complete parts only: a part cut by an end would bias Xs
        // low.
        let counted = !w[0].cut && !w[1].cut && (d.both_directions || (w[0].up && !w[1].up));
        if counted {
            sx += w[1].end - w[0].start;
            sz += w[0].ext + w[1].ext;
            count += 1;
        }
    }
    (count > 0).then(|| (sx / count as f64, sz / count as f64))
}

/// Profile parameters of `heights` (m) sampled at `dx` (m) in
/// `options.convention` (ISO 21920-2 by default); see the module docs for the
/// mean line, sections, what each convention averages, and discretisation.
/// With `options.hurst`, also [`super::psd_hurst_exponent`] of the whole
/// profile.
///
/// Errors: `dx` not finite and > 0; fewer than 8 heights or non-finite ones;
/// a sampling length shorter than 8·dx or longer than the profile;
/// discrimination fractions outside [0, 1); heights constant within a
/// sampling length ([`Error::OutOfDomain`]: Rsk and Rku divide by Rq).
pub fn roughness_parameters(
    heights: &[f64],
    dx: f64,
    options: &ParameterOptions,
) -> Result<RoughnessParameters> {
    check::positive("dx", dx)?;
    check_heights(heights, 8, ">= 8 points")?;
    check::in_range(
        "height_discrimination",
        options.height_discrimination,
        0.0,
        0.999_999,
        "in [0, 1)",
    )?;
    check::in_range(
        "width_discrimination",
        options.width_discrimination,
        0.0,
        0.999_999,
        "in [0, 1)",
    )?;
    let n = heights.len();
    let (m, count) = match options.sampling_length {
        None => (n, 1),
        Some(l) => {
            check::positive("sampling_length", l)?;
            let m = (l / dx).round();
            if m < 8.0 {
                return Err(Error::InvalidArgument {
                    name: "sampling_length",
                    value: l,
                    bound: ">= 8 * dx",
                });
            }
            let m = m as usize;
            if m > n {
                return Err(Error::InvalidArgument {
                    name: "sampling_length",
                    value: l,
                    bound: "<= profile length n*dx",
                });
            }
            (m, n / m)
        }
    };
    let ev = &heights[..m * count];
    let zbar = mean(ev);
    let iso4287 = options.convention == Convention::Iso4287;
    let mf = m as f64;
    // Section means (ISO 4287: all; ISO 21920-2: Rp, Rv, Rz).
    let (mut rp, mut rv, mut rz, mut ra, mut rq, mut rsk, mut rku, mut rdq) =
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    // Evaluation-length sums (ISO 21920-2).
    let (mut t1, mut t2, mut t3, mut t4, mut tg) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let (mut rc_sum, mut rsm_sum, mut n_elem) = (0.0, 0.0, 0usize);
    let (mut zmax, mut zmin) = (f64::NEG_INFINITY, f64::INFINITY);
    let ne = ev.len();
    for s in 0..count {
        let (first, last) = (s * m, (s + 1) * m);
        let seg = &ev[first..last];
        let (mut s1, mut s2, mut s3, mut s4) = (0.0, 0.0, 0.0, 0.0);
        let (mut hi, mut lo) = (f64::NEG_INFINITY, f64::INFINITY);
        for &z in seg {
            let v = z - zbar;
            let v2 = v * v;
            s1 += v.abs();
            s2 += v2;
            s3 += v2 * v;
            s4 += v2 * v2;
            hi = hi.max(v);
            lo = lo.min(v);
        }
        let q = (s2 / mf).sqrt();
        if hi == lo {
            return Err(Error::OutOfDomain {
                name: "heights",
                value: seg[0],
                reason: "constant heights (Rq = 0): Rsk and Rku divide by Rq",
            });
        }
        zmax = zmax.max(hi);
        zmin = zmin.min(lo);
        rp += hi;
        rv += -lo;
        rz += hi - lo;
        ra += s1 / mf;
        rq += q;
        rsk += s3 / mf / (q * q * q);
        rku += s4 / mf / (q * q * q * q);
        (t1, t2, t3, t4) = (t1 + s1, t2 + s2, t3 + s3, t4 + s4);
        // Slopes: the evaluation length supplies neighbours across sampling
        // lengths; the lower-order stencils apply only at its two ends.
        let a = first.max(3).min(last);
        let b = last.min(ne.saturating_sub(3)).max(a);
        let mut sd = 0.0;
        for i in (first..a).chain(b..last) {
            let g = slope_at(ev, i, dx);
            sd += g * g;
        }
        if b > a {
            let mut si = 0.0;
            for w in ev[a - 3..b + 3].windows(7) {
                let g = w[6] - 9.0 * w[5] + 45.0 * (w[4] - w[2]) + 9.0 * w[1] - w[0];
                si += g * g;
            }
            sd += si / (60.0 * dx * 60.0 * dx);
        }
        rdq += (sd / mf).sqrt();
        tg += sd;
        if iso4287 {
            let hd = options.height_discrimination * (hi - lo);
            let d = Discrimination {
                peak: hd,
                valley: hd,
                width: options.width_discrimination * mf,
                both_directions: false,
            };
            if let Some((xs, zt)) = elements(seg, zbar, d) {
                rsm_sum += xs * dx;
                rc_sum += zt;
                n_elem += 1;
            }
        }
    }
    let c = count as f64;
    let (rp, rv, rz) = (rp / c, rv / c, rz / c);
    let (ra, rq, rsk, rku, rdq) = if iso4287 {
        (ra / c, rq / c, rsk / c, rku / c, rdq / c)
    } else {
        let nf = ne as f64;
        let q = (t2 / nf).sqrt();
        (
            t1 / nf,
            q,
            t3 / nf / (q * q * q),
            t4 / nf / (q * q * q * q),
            (tg / nf).sqrt(),
        )
    };
    let (rc, rsm) = if iso4287 {
        (
            (n_elem > 0).then(|| rc_sum / n_elem as f64),
            (n_elem > 0).then(|| rsm_sum / n_elem as f64),
        )
    } else {
        let d = Discrimination {
            peak: options.height_discrimination * rp,
            valley: options.height_discrimination * rv,
            width: options.width_discrimination * mf,
            both_directions: true,
        };
        match elements(ev, zbar, d) {
            Some((xs, zt)) => (Some(zt), Some(xs * dx)),
            None => (None, None),
        }
    };
    let psd_hurst_exponent = if options.hurst {
        super::psd_hurst_exponent(heights, dx)?
    } else {
        None
    };
    Ok(RoughnessParameters {
        rp,
        rv,
        rz,
        rc,
        rt: zmax - zmin,
        ra,
        rq,
        rsk,
        rku,
        rsm,
        rdq,
        psd_hurst_exponent,
        sampling_length: m as f64 * dx,
        sampling_lengths: count,
        convention: options.convention,
    })
}

/// The material-ratio (Abbott–Firestone) curve of a profile or map (ISO 4287
/// §3.2.17–3.2.20, thesis Fig. 1-5): Rmr(c), the fraction of the evaluation
/// length where the profile is at or above level c (measured from the mean
/// line), and its inverse c(Rmr). Each sample stands for an equal length.
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialRatioCurve {
    /// Heights from the mean line, sorted in decreasing order (m).
    sorted: Vec<f64>,
}

impl MaterialRatioCurve {
    /// The curve of `heights` (m). Errors: empty or non-finite heights.
    pub fn new(heights: &[f64]) -> Result<Self> {
        check_heights(heights, 1, ">= 1 point")?;
        let zbar = mean(heights);
        let mut sorted: Vec<f64> = heights.iter().map(|z| z - zbar).collect();
        sorted.sort_unstable_by(|a, b| b.total_cmp(a));
        Ok(Self { sorted })
    }

    /// Rmr(c) ∈ [0, 1]: fraction of samples with Z ≥ `level` (m, from the
    /// mean line).
    pub fn ratio_at(&self, level: f64) -> f64 {
        let k = self.sorted.partition_point(|&z| z >= level);
        k as f64 / self.sorted.len() as f64
    }

    /// c(Rmr) (m, from the mean line): the highest level whose material ratio
    /// reaches `ratio` ∈ [0, 1] (the highest peak for 0, the deepest valley
    /// for 1). Errors: `ratio` outside [0, 1].
    pub fn level_at(&self, ratio: f64) -> Result<f64> {
        check::in_range("ratio", ratio, 0.0, 1.0, "in [0, 1]")?;
        let n = self.sorted.len();
        let k = ((ratio * n as f64).ceil() as usize).clamp(1, n);
        Ok(self.sorted[k - 1])
    }

    /// Profile section height difference Rδc = c(Rmr1) − c(Rmr2) (m), ISO 4287
    /// §4.5.3. Errors: ratios outside [0, 1].
    pub fn section_height(&self, rmr1: f64, rmr2: f64) -> Result<f64> {
        Ok(self.level_at(rmr1)? - self.level_at(rmr2)?)
    }

    /// `points` (≥ 2) samples of the curve as (Rmr, c) pairs, Rmr from 0 to 1
    /// in equal steps.
    pub fn curve(&self, points: usize) -> Vec<(f64, f64)> {
        let p = points.max(2);
        (0..p)
            .map(|i| {
                let r = i as f64 / (p - 1) as f64;
                (r, self.level_at(r).unwrap_or(0.0))
            })
            .collect()
    }
}

/// Areal (ISO 25178-2) height parameters of a map, heights from the mean
/// plane z̄ (remove a plane or quadric first with
/// [`Topography::remove_form`]). Serialised with the ISO symbols (`Sdq`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ArealParameters {
    /// Arithmetic mean height Sa = mean |Z| (m).
    #[serde(rename = "Sa")]
    pub sa: f64,
    /// Root-mean-square height Sq = √(mean Z²) (m).
    #[serde(rename = "Sq")]
    pub sq: f64,
    /// Skewness Ssk = mean Z³ / Sq³.
    #[serde(rename = "Ssk")]
    pub ssk: f64,
    /// Kurtosis Sku = mean Z⁴ / Sq⁴.
    #[serde(rename = "Sku")]
    pub sku: f64,
    /// Maximum peak height Sp = max Z (m).
    #[serde(rename = "Sp")]
    pub sp: f64,
    /// Maximum pit depth Sv = −min Z (m).
    #[serde(rename = "Sv")]
    pub sv: f64,
    /// Maximum height Sz = Sp + Sv (m).
    #[serde(rename = "Sz")]
    pub sz: f64,
    /// Root-mean-square gradient Sdq = √(mean((∂Z/∂x)² + (∂Z/∂y)²)), slopes
    /// by the seven-point formula along rows and columns (as for RΔq).
    #[serde(rename = "Sdq")]
    pub sdq: f64,
}

/// Areal parameters of a map; see [`ArealParameters`] and
/// [`areal_parameters_grid`]. Errors: constant heights (Ssk, Sku divide by Sq).
pub fn areal_parameters(t: &Topography) -> Result<ArealParameters> {
    areal_parameters_grid(t.heights(), t.nx(), t.ny(), t.dx(), t.dy())
}

/// Areal parameters of a row-major `nx × ny` grid `heights` (m),
/// `heights[j*nx + i] = z(x_i, y_j)`, spacings `dx`, `dy` (m) — the slice form
/// of [`areal_parameters`].
///
/// Errors: `dx`, `dy` not finite and > 0; nx or ny < 2; `heights.len() !=
/// nx*ny`; non-finite heights; constant heights ([`Error::OutOfDomain`]).
pub fn areal_parameters_grid(
    heights: &[f64],
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
) -> Result<ArealParameters> {
    check::positive("dx", dx)?;
    check::positive("dy", dy)?;
    if nx < 2 || ny < 2 || heights.len() != nx * ny {
        return Err(Error::InvalidArgument {
            name: "heights.len()",
            value: heights.len() as f64,
            bound: "== nx * ny with nx, ny >= 2",
        });
    }
    check_heights(heights, 4, ">= 4 points")?;
    let zbar = mean(heights);
    let (mut s1, mut s2, mut s3, mut s4) = (0.0, 0.0, 0.0, 0.0);
    let (mut hi, mut lo) = (f64::NEG_INFINITY, f64::INFINITY);
    for &z in heights {
        let v = z - zbar;
        let v2 = v * v;
        s1 += v.abs();
        s2 += v2;
        s3 += v2 * v;
        s4 += v2 * v2;
        hi = hi.max(v);
        lo = lo.min(v);
    }
    let nf = heights.len() as f64;
    let sq = (s2 / nf).sqrt();
    if hi == lo {
        return Err(Error::OutOfDomain {
            name: "heights",
            value: heights[0],
            reason: "constant heights (Sq = 0): Ssk and Sku divide by Sq",
        });
    }
    let mut g2 = 0.0;
    for j in 0..ny {
        let row = &heights[j * nx..(j + 1) * nx];
        for i in 0..nx {
            let g = slope_at(row, i, dx);
            g2 += g * g;
        }
    }
    let mut col = vec![0.0; ny];
    for i in 0..nx {
        for (j, c) in col.iter_mut().enumerate() {
            *c = heights[j * nx + i];
        }
        for j in 0..ny {
            let g = slope_at(&col, j, dy);
            g2 += g * g;
        }
    }
    Ok(ArealParameters {
        sa: s1 / nf,
        sq,
        ssk: s3 / nf / (sq * sq * sq),
        sku: s4 / nf / (sq * sq * sq * sq),
        sp: hi,
        sv: -lo,
        sz: hi - lo,
        sdq: (g2 / nf).sqrt(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const D4287: Discrimination = Discrimination {
        peak: 0.2,
        valley: 0.2,
        width: 10.0,
        both_directions: false,
    };

    #[test]
    fn elements_of_a_sine() {
        // 10 periods of 100 samples: the elements, the cut ones at the ends
        // included, tile the 1000 samples, so Xs = 100 in both conventions.
        let d: Vec<f64> = (0..1000)
            .map(|j| (2.0 * core::f64::consts::PI * j as f64 / 100.0 + 0.3).sin())
            .collect();
        for both_directions in [false, true] {
            let disc = Discrimination {
                both_directions,
                ..D4287
            };
            let (xs, zt) = elements(&d, 0.0, disc).unwrap();
            assert!((xs - 100.0).abs() < 1e-3, "{xs}");
            assert!((zt - 2.0).abs() < 0.02, "{zt}");
        }
    }

    #[test]
    fn spikes_narrower_than_the_width_discrimination_are_no_elements() {
        // A flat base just below the mean line with a tall spike every 100
        // samples (the shape of the Hommel scan at λc = 0.8 mm: 38 of its 39
        // peaks above 10 % of Rp are narrower than 1 % of λc). Spikes of 3
        // samples under a width discrimination of 10 merge into the base:
        // one valley, no element (ISO 4287 §3.2.8–3.2.9). Spikes of 20
        // samples are elements of width 100.
        let spiky = |width: usize| -> Vec<f64> {
            (0..1000)
                .map(|j| if j % 100 < width { 1.0 } else { -0.05 })
                .collect()
        };
        let disc = Discrimination {
            peak: 0.1,
            valley: 0.01,
            both_directions: true,
            ..D4287
        };
        assert!(elements(&spiky(3), 0.0, disc).is_none());
        let (xs, zt) = elements(&spiky(20), 0.0, disc).unwrap();
        assert!((xs - 100.0).abs() < 1e-9, "{xs}");
        assert!((zt - 1.05).abs() < 1e-12, "{zt}");
    }

    #[test]
    fn small_wiggles_merge_into_the_preceding_part() {
        // Peak, tiny dip below the line, peak, valley, peak: one complete
        // peak-valley element.
        let d = [
            -1.0, 1.0, 2.0, 1.0, -0.01, 1.0, 2.0, 1.0, -1.0, -2.0, -1.0, 1.0, 2.0, -1.0,
        ];
        let disc = Discrimination {
            width: 0.0,
            ..D4287
        };
        let (xs, zt) = elements(&d, 0.0, disc).unwrap();
        // Leading valley (from 0 to the crossing at 0.5, cut by the start),
        // peak to 7.5 (the dip merged), valley to 10.5, peak to 12.667, last
        // valley to 14 (cut by the end): the one complete peak-valley pair is
        // 0.5..10.5.
        assert!((zt - 4.0).abs() < 1e-12, "{zt}");
        assert!((xs - 10.0).abs() < 1e-12, "{xs}");
        // Thresholds per sign: valleys need 1.5, so only the valley of depth
        // 2 counts; the peaks merge around it.
        let disc = Discrimination {
            valley: 1.5,
            both_directions: true,
            ..disc
        };
        let (xs, zt) = elements(&d, 0.0, disc).unwrap();
        // Peak 0.5..7.5 (the dip merged), valley 7.5..10.5, peak 10.5..14
        // (the shallow last valley merged, so cut by the end): one complete
        // pair, 0.5..10.5.
        assert!((zt - 4.0).abs() < 1e-12, "{zt}");
        assert!((xs - 10.0).abs() < 1e-12, "{xs}");
    }
}
