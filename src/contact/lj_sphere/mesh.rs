//! The radial mesh of the solver: annular cells and their collocation
//! nodes, from the smooth map of the module docs (*Discretisation*) or, for
//! the edge continuation's scaled family, graded towards a marker node.

/// Radial mesh: `n` cells with edges `c` (n + 1) and nodes `x` (n).
#[derive(Debug, Clone)]
pub(super) struct Mesh {
    pub(super) x: Vec<f64>,
    pub(super) c: Vec<f64>,
}

impl Mesh {
    pub(super) fn new(n: usize, rf: f64, l: f64, a_e: f64, w: f64, frac: f64) -> Mesh {
        // φ(r) = rf ln(1 + r/rf) + b w [tanh((r − a_e)/w) + tanh(a_e/w)],
        // with b giving the band the fraction `frac` of φ(l); φ and φ'
        // together (one log1p, one tanh).
        let ta = if frac > 0.0 { (a_e / w).tanh() } else { 0.0 };
        let base_l = rf * (l / rf).ln_1p();
        let b = if frac > 0.0 {
            frac / (1.0 - frac) * base_l / (w * (((l - a_e) / w).tanh() + ta))
        } else {
            0.0
        };
        let phi_dphi = |r: f64| {
            let base = rf * (r / rf).ln_1p();
            let d_base = 1.0 / (1.0 + r / rf);
            if frac > 0.0 {
                let t = ((r - a_e) / w).tanh();
                (base + b * w * (t + ta), d_base + b * (1.0 - t * t))
            } else {
                (base, d_base)
            }
        };
        let total = phi_dphi(l).0;
        // phi(r) = target for increasing targets: each root brackets the
        // next from below and starts its Newton iteration (a few steps each).
        let inv = |target: f64, from: f64| -> f64 {
            // Newton safeguarded by bisection: a Newton step must land in
            // the bracket and must have halved |φ − target| since the last
            // step (Newton can cycle around the inflections of the tanh
            // band). The bracket's upper end is L, far away: a rule that
            // asks the bracket itself to halve bisects towards L although
            // Newton converges from below, at 5× the evaluations.
            let (mut lo, mut hi) = (from, l);
            let (p0, d0) = phi_dphi(from);
            let mut r = from + (target - p0) / d0;
            if !(r > lo && r < hi) {
                r = 0.5 * (lo + hi);
            }
            let mut f_last = f64::INFINITY;
            for _ in 0..400 {
                let (p, dp) = phi_dphi(r);
                let f = p - target;
                if f > 0.0 {
                    hi = r;
                } else {
                    lo = r;
                }
                if f == 0.0 || hi - lo <= 1e-15 * (1.0 + r) {
                    return r;
                }
                let mut rn = r - f / dp;
                if (rn - r).abs() <= 1e-16 * (1.0 + r) {
                    return rn;
                }
                if !(rn > lo && rn < hi) || f.abs() > 0.5 * f_last {
                    rn = 0.5 * (lo + hi);
                }
                f_last = f.abs();
                r = rn;
            }
            0.5 * (lo + hi)
        };
        // Cell edges at the targets total·j/n, nodes half-way (in phi)
        // between them: 2n + 1 increasing targets.
        let nf = n as f64;
        let mut c = Vec::with_capacity(n + 1);
        let mut x = Vec::with_capacity(n);
        let mut prev = 0.0f64;
        c.push(0.0);
        for k in 1..2 * n {
            let r = inv(total * k as f64 / (2.0 * nf), prev);
            if k % 2 == 1 {
                x.push(r);
            } else {
                c.push(r);
            }
            prev = r;
        }
        c.push(l);
        Mesh { x, c }
    }
}

impl Mesh {
    /// The mesh of the edge continuation's scaled family (`edge` module
    /// docs): `n` cells on `[0, l]` with node `j` exactly at the marker `a`
    /// (returned with the mesh). Target cell size `h(r)`: `h_in` near the
    /// centre, falling geometrically to `h_a` at `a`
    /// (`h = h_a + g|a − r|`, capped at `h_in` inside) and growing
    /// geometrically outside; `g` is chosen so that the cells number `n`.
    /// The family scales this mesh by `m/a`, so `h_a·m/a` is the cell size at
    /// the marker `m`, and `h_in` the resolution of the neck inside `a`.
    pub(super) fn marker(n: usize, a: f64, h_in: f64, h_a: f64, l: f64) -> (Mesh, usize) {
        let h_a = h_a.min(h_in);
        // φ(r) = ∫₀ʳ ds/h(s) and its inverse, for the grading g.
        // The core's end r1 (where h_a + g(a − r) reaches h_in), φ(r1)
        // and φ(a), for the grading g.
        let breaks = |g: f64| -> (f64, f64, f64) {
            let r1 = (a - (h_in - h_a) / g).max(0.0);
            let p1 = r1 / h_in;
            (r1, p1, p1 + ((h_a + g * (a - r1)) / h_a).ln() / g)
        };
        let phi = |g: f64, r: f64| -> f64 {
            let (r1, p1, pa) = breaks(g);
            if r <= r1 {
                r / h_in
            } else if r <= a {
                p1 + ((h_a + g * (a - r1)) / (h_a + g * (a - r))).ln() / g
            } else {
                pa + (g * (r - a) / h_a).ln_1p() / g
            }
        };
        let inv = |g: f64, v: f64| -> f64 {
            let (r1, p1, pa) = breaks(g);
            if v <= p1 {
                v * h_in
            } else if v <= pa {
                a - ((h_a + g * (a - r1)) * (-(g * (v - p1))).exp() - h_a) / g
            } else {
                a + h_a * (g * (v - pa)).exp_m1() / g
            }
        };
        // φ(l) = n: φ(l) falls as g grows (bisection in log g).
        let (mut lo, mut hi) = (1e-6f64, 10.0f64);
        for _ in 0..200 {
            let g = (lo * hi).sqrt();
            if phi(g, l) > n as f64 {
                lo = g;
            } else {
                hi = g;
            }
            if hi / lo < 1.0 + 1e-12 {
                break;
            }
        }
        let g = hi;
        let (pa, pl) = (phi(g, a), phi(g, l));
        // Node j at a: φ mapped linearly onto the cell index on either side.
        let j = (pa.floor() as usize).clamp(1, n - 2);
        let tj = j as f64 + 0.5;
        let nf = n as f64;
        let at = |t: f64| -> f64 {
            let v = if t <= tj {
                t * pa / tj
            } else {
                pa + (t - tj) * (pl - pa) / (nf - tj)
            };
            inv(g, v)
        };
        let mut c = Vec::with_capacity(n + 1);
        let mut x = Vec::with_capacity(n);
        c.push(0.0);
        for k in 0..n {
            x.push(if k == j { a } else { at(k as f64 + 0.5) });
            c.push(if k + 1 == n { l } else { at(k as f64 + 1.0) });
        }
        (Mesh { x, c }, j)
    }
}
