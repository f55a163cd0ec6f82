//! Representative elementary pattern of roughness (REPR; Pepelyshev 2015,
//! Borodich et al. 2015; thesis 1.5.4).
//!
//! Among all sections of k consecutive samples of a profile, the pattern is
//! the one whose height distribution is closest to that of the whole profile
//! in the two-sample Kolmogorov–Smirnov sense (D(s) of *Formulas*, with
//! F_{s,k} the empirical distribution of z_s..z_{s+k−1} and F_n that of all n
//! heights). Replicating the pattern gives a profile "equivalent in terms of
//! height distribution" (thesis Figs. 1-11…1-13: a 52-point pattern of a
//! 668-point profile).
//!
//! Algorithm, O(n log n): heights are ranked once (ties grouped, since both
//! distribution functions jump at the same values). For each distinct value
//! g the scaled difference V(g) of *Formulas*, with C_w(g) the number of
//! window heights ≤ g and E(g) the number of all heights ≤ g, lives in a
//! segment tree with range addition; sliding the window by one sample adds
//! ±n to a suffix of groups, and D is read at the root.
//! Integer arithmetic makes D exact and the choice among equal D
//! deterministic (the first start wins).
//!
//! # Formulas
//!
//! $$D(s) = \sup_z\bigl\lvert F_{s,k}(z) - F_n(z)\bigr\rvert = \frac{\max_g\lvert V(g)\rvert}{nk}, \qquad V(g) = n\\,C_w(g) - k\\,E(g) .$$
//!
//! # References
//!
//! * Thesis §1.5.4.
//! * A. Pepelyshev (2015) and F. M. Borodich et al. (2015): the representative
//!   elementary pattern of roughness, as cited by the thesis (§1.5.4).
//! * A. N. Kolmogorov (1933); N. V. Smirnov (1939): the (two-sample)
//!   Kolmogorov–Smirnov statistic.

use super::check_heights;
use crate::error::{Error, Result};
use serde::Serialize;

/// A representative elementary pattern.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RepresentativePattern {
    /// Index of the first sample of the pattern in the profile.
    pub start: usize,
    /// Pattern length k (samples).
    pub len: usize,
    /// Number of samples n of the whole profile.
    pub profile_len: usize,
    /// Two-sample Kolmogorov–Smirnov statistic D between the pattern's and
    /// the profile's heights (0 = identical distributions).
    pub ks_statistic: f64,
    /// The pattern's heights (m).
    pub pattern: Vec<f64>,
}

impl RepresentativePattern {
    /// The equivalent profile: the pattern repeated to `n` samples (the last
    /// copy truncated). Errors: n = 0.
    pub fn replicate(&self, n: usize) -> Result<Vec<f64>> {
        if n == 0 {
            return Err(Error::InvalidArgument {
                name: "n",
                value: 0.0,
                bound: ">= 1",
            });
        }
        Ok(self.pattern.iter().copied().cycle().take(n).collect())
    }

    /// Asymptotic p-value of D (Kolmogorov distribution with Stephens'
    /// small-sample correction, effective size n·k/(n + k)). Indicative only:
    /// the pattern is part of the profile and heights along a profile are
    /// correlated, so the samples are not independent.
    pub fn p_value(&self) -> f64 {
        let (n, k) = (self.profile_len as f64, self.len as f64);
        let ne = (n * k / (n + k)).sqrt();
        kolmogorov_q((ne + 0.12 + 0.11 / ne) * self.ks_statistic)
    }
}

/// Q_KS(λ) = 2 Σ_{j≥1} (−1)^{j−1} e^{−2j²λ²}.
fn kolmogorov_q(lambda: f64) -> f64 {
    if lambda < 0.2 {
        return 1.0;
    }
    let mut s = 0.0;
    let mut sign = 1.0;
    for j in 1..=100 {
        let t = (-2.0 * (j * j) as f64 * lambda * lambda).exp();
        s += sign * t;
        if t < 1e-16 {
            break;
        }
        sign = -sign;
    }
    (2.0 * s).clamp(0.0, 1.0)
}

/// Segment tree over groups with suffix addition and global max/min.
struct Tree {
    size: usize,
    mx: Vec<i64>,
    mn: Vec<i64>,
    add: Vec<i64>,
}

impl Tree {
    fn new(leaves: &[i64]) -> Self {
        let size = leaves.len();
        let mut t = Tree {
            size,
            mx: vec![0; 4 * size],
            mn: vec![0; 4 * size],
            add: vec![0; 4 * size],
        };
        t.build(1, 0, size, leaves);
        t
    }

    fn build(&mut self, node: usize, lo: usize, hi: usize, leaves: &[i64]) {
        if hi - lo == 1 {
            self.mx[node] = leaves[lo];
            self.mn[node] = leaves[lo];
            return;
        }
        let mid = (lo + hi) / 2;
        self.build(2 * node, lo, mid, leaves);
        self.build(2 * node + 1, mid, hi, leaves);
        self.mx[node] = self.mx[2 * node].max(self.mx[2 * node + 1]);
        self.mn[node] = self.mn[2 * node].min(self.mn[2 * node + 1]);
    }

    /// Adds `v` to every group ≥ `from`.
    fn add_suffix(&mut self, from: usize, v: i64) {
        self.update(1, 0, self.size, from, v);
    }

    fn update(&mut self, node: usize, lo: usize, hi: usize, from: usize, v: i64) {
        if hi <= from {
            return;
        }
        if from <= lo {
            self.add[node] += v;
            self.mx[node] += v;
            self.mn[node] += v;
            return;
        }
        let mid = (lo + hi) / 2;
        self.update(2 * node, lo, mid, from, v);
        self.update(2 * node + 1, mid, hi, from, v);
        self.mx[node] = self.mx[2 * node].max(self.mx[2 * node + 1]) + self.add[node];
        self.mn[node] = self.mn[2 * node].min(self.mn[2 * node + 1]) + self.add[node];
    }

    fn max_abs(&self) -> i64 {
        self.mx[1].max(-self.mn[1])
    }
}

fn check_len(n: usize, len: usize) -> Result<()> {
    if len == 0 || len > n {
        return Err(Error::InvalidArgument {
            name: "len",
            value: len as f64,
            bound: ">= 1 and <= heights.len()",
        });
    }
    Ok(())
}

/// The KS statistic D(s) of every window start s = 0..=n−k (see the module
/// docs), in O(n log n).
///
/// Errors: fewer than 2 or non-finite heights; `len` = 0 or > n.
pub fn ks_statistics(heights: &[f64], len: usize) -> Result<Vec<f64>> {
    check_heights(heights, 2, ">= 2 points")?;
    let n = heights.len();
    check_len(n, len)?;
    // Group ids by value.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_unstable_by(|&a, &b| heights[a].total_cmp(&heights[b]));
    let mut group = vec![0usize; n];
    let mut ends: Vec<i64> = Vec::new(); // E(g): heights <= value of g
    for (r, &i) in order.iter().enumerate() {
        if r > 0 && heights[i] != heights[order[r - 1]] {
            ends.push(r as i64);
        }
        group[i] = ends.len();
    }
    ends.push(n as i64);
    let (ni, ki) = (n as i64, len as i64);
    let leaves: Vec<i64> = ends.iter().map(|&e| -ki * e).collect();
    let mut tree = Tree::new(&leaves);
    for &g in &group[..len] {
        tree.add_suffix(g, ni);
    }
    let scale = 1.0 / (n as f64 * len as f64);
    let mut out = Vec::with_capacity(n - len + 1);
    out.push(tree.max_abs() as f64 * scale);
    for s in 1..=n - len {
        tree.add_suffix(group[s - 1], -ni);
        tree.add_suffix(group[s + len - 1], ni);
        out.push(tree.max_abs() as f64 * scale);
    }
    Ok(out)
}

/// The representative elementary pattern of `len` samples of `heights` (m):
/// the window with the smallest KS statistic against the whole profile (the
/// first one on ties). See the module docs.
///
/// Errors: fewer than 2 or non-finite heights; `len` = 0 or > n.
pub fn representative_pattern(heights: &[f64], len: usize) -> Result<RepresentativePattern> {
    let d = ks_statistics(heights, len)?;
    let (start, &ks) =
        d.iter().enumerate().fold(
            (0, &f64::INFINITY),
            |best, cur| if cur.1 < best.1 { cur } else { best },
        );
    Ok(RepresentativePattern {
        start,
        len,
        profile_len: heights.len(),
        ks_statistic: ks,
        pattern: heights[start..start + len].to_vec(),
    })
}

/// Two-sample Kolmogorov–Smirnov statistic D = sup |F_a − F_b| of two samples,
/// O((n + m) log(n + m)). Errors: an empty or non-finite sample.
pub fn ks_two_sample(a: &[f64], b: &[f64]) -> Result<f64> {
    check_heights(a, 1, ">= 1 point")?;
    check_heights(b, 1, ">= 1 point")?;
    let mut a = a.to_vec();
    let mut b = b.to_vec();
    a.sort_unstable_by(f64::total_cmp);
    b.sort_unstable_by(f64::total_cmp);
    let (na, nb) = (a.len() as f64, b.len() as f64);
    let (mut i, mut j, mut d) = (0usize, 0usize, 0.0f64);
    while i < a.len() && j < b.len() {
        let v = a[i].min(b[j]);
        while i < a.len() && a[i] == v {
            i += 1;
        }
        while j < b.len() && b[j] == v {
            j += 1;
        }
        d = d.max((i as f64 / na - j as f64 / nb).abs());
    }
    Ok(d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sliding_statistics_match_the_direct_two_sample_test() {
        let z: Vec<f64> = (0..200)
            .map(|j| (((j * 7919) % 37) as f64 * 0.3).sin() + ((j % 5) as f64) * 0.1)
            .collect();
        for len in [1usize, 7, 50, 200] {
            let d = ks_statistics(&z, len).unwrap();
            for s in [0usize, 1, 13, 200 - len]
                .into_iter()
                .filter(|&s| s <= 200 - len)
            {
                let direct = ks_two_sample(&z[s..s + len], &z).unwrap();
                assert!((d[s] - direct).abs() < 1e-12, "len {len}, s {s}");
            }
        }
    }

    #[test]
    fn kolmogorov_distribution_values() {
        // Q_KS(1) = 0.2699996716735..., Q_KS(1.36) ≈ 0.0494 (5 % point).
        assert!((kolmogorov_q(1.0) - 0.269_999_671_67).abs() < 1e-9);
        assert!((kolmogorov_q(1.358) - 0.05).abs() < 1e-3);
    }
}
