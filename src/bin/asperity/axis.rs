//! Units and tick labels of the command's plots: plotters'
//! default labels of an `f64` axis carry a fixed handful of decimals, so an
//! axis of energies near 1e-7 J read "0.0" at every tick. Every chart of the
//! command scales its dimensional quantities to an SI prefix ([`si_prefix`],
//! [`si_prefix_squared`]) and labels both axes with [`ticks`], whose labels
//! are distinct whatever the magnitude and span of the axis.

/// Divisor and SI prefix that show values up to `magnitude` (in absolute
/// value) with one to three integer digits, e.g. `(1e-9, "n")` for 1.2e-7.
/// Non-finite or zero magnitudes keep the base unit.
pub fn si_prefix(magnitude: f64) -> (f64, &'static str) {
    let m = magnitude.abs();
    if !(m.is_finite() && m > 0.0) {
        return (1.0, "");
    }
    PREFIXES
        .iter()
        // The tolerance keeps 999.9999999e-9 (a rounded 1e-6) in µ.
        .find(|&&(s, _)| m >= s * (1.0 - 1e-9))
        .copied()
        .unwrap_or(PREFIXES[PREFIXES.len() - 1])
}

/// Divisor (the square of a length prefix) and prefix that show an area (or
/// any squared unit) of up to `magnitude` with values from 0.1 up: e.g.
/// `(1e-12, "µ")` (µm²) for 5e-13 m², read as 0.5 µm².
pub fn si_prefix_squared(magnitude: f64) -> (f64, &'static str) {
    let m = magnitude.abs();
    if !(m.is_finite() && m > 0.0) {
        return (1.0, "");
    }
    PREFIXES
        .iter()
        .map(|&(s, p)| (s * s, p))
        .find(|&(s2, _)| m >= 0.1 * s2 * (1.0 - 1e-9))
        .unwrap_or_else(|| {
            let (s, p) = PREFIXES[PREFIXES.len() - 1];
            (s * s, p)
        })
}

const PREFIXES: [(f64, &str); 11] = [
    (1e12, "T"),
    (1e9, "G"),
    (1e6, "M"),
    (1e3, "k"),
    (1.0, ""),
    (1e-3, "m"),
    (1e-6, "µ"),
    (1e-9, "n"),
    (1e-12, "p"),
    (1e-15, "f"),
    (1e-18, "a"),
];

/// The largest absolute value of `values` (0 when empty or all non-finite).
pub fn magnitude(values: impl IntoIterator<Item = f64>) -> f64 {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(0.0, |m, v| m.max(v.abs()))
}

/// A tick-label formatter for plotters' `x_label_formatter` /
/// `y_label_formatter`.
pub type Formatter = Box<dyn Fn(&f64) -> String>;

/// Labels of an axis over `lo..hi`: plotters puts at most ten labelled ticks
/// on an axis (its default), so they are at least (hi − lo)/10 apart; the
/// labels carry one decimal more than that spacing needs, so they read
/// distinct, with trailing zeros dropped ("0.25", "0.5", "1"). Scientific
/// notation ("1.5e-7") when the axis reaches 1e5 or stays below 1e-3 in
/// magnitude (charts scale their values to an SI prefix first, so this is
/// the fallback of dimensionless axes).
pub fn ticks(lo: f64, hi: f64) -> Formatter {
    let mag = lo.abs().max(hi.abs());
    let span = if (hi - lo).is_finite() && hi > lo {
        hi - lo
    } else if mag.is_finite() && mag > 0.0 {
        mag
    } else {
        1.0
    };
    let e_step = (span / 10.0).log10().floor() as i32;
    // Below this a tick is zero up to rounding (0.1 + 0.2 − 0.3).
    let zero = span * 1e-9;
    let sci = mag.is_finite() && mag > 0.0 && !(1e-3..1e5).contains(&mag);
    if sci {
        let e_mag = mag.log10().floor() as i32;
        let digits = (e_mag - e_step + 1).clamp(1, 15) as usize;
        Box::new(move |v: &f64| {
            if v.abs() < zero {
                return "0".into();
            }
            let s = format!("{v:.digits$e}");
            match s.split_once('e') {
                Some((m, e)) => format!("{}e{e}", trim(m)),
                None => s,
            }
        })
    } else {
        let decimals = (1 - e_step).clamp(0, 15) as usize;
        Box::new(move |v: &f64| {
            if v.abs() < zero {
                return "0".into();
            }
            let s = trim(&format!("{v:.decimals$}"));
            if s == "-0" {
                "0".into()
            } else {
                s
            }
        })
    }
}

/// `s` without the trailing zeros of its decimals (and without a bare
/// trailing point).
fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(lo: f64, hi: f64, n: usize) -> Vec<String> {
        let f = ticks(lo, hi);
        (0..=n)
            .map(|i| f(&(lo + (hi - lo) * i as f64 / n as f64)))
            .collect()
    }

    #[test]
    fn tiny_axes_read_distinct() {
        for (lo, hi) in [
            (0.0, 1.2e-7),
            (1e-9, 1.0000001e-9),
            (0.25, 0.2501),
            (-3e8, 7e8),
        ] {
            let l = labels(lo, hi, 10);
            let mut d = l.clone();
            d.dedup();
            assert_eq!(d.len(), l.len(), "{lo}..{hi}: {l:?}");
        }
        assert_eq!(labels(0.0, 1.0, 4), ["0", "0.25", "0.5", "0.75", "1"]);
        assert_eq!(ticks(0.0, 1.2e-7)(&6e-8), "6e-8");
    }

    #[test]
    fn prefixes() {
        assert_eq!(si_prefix(1.2e-7), (1e-9, "n"));
        assert_eq!(si_prefix(0.18), (1e-3, "m"));
        assert_eq!(si_prefix(0.0), (1.0, ""));
        assert_eq!(si_prefix_squared(5e-13), (1e-12, "µ"));
        assert_eq!(si_prefix_squared(1e-15).1, "n");
    }
}
