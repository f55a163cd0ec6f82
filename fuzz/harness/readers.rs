//! Fuzz harness `readers`: the profile and height-map readers
//! (`asperity::surface::parse_profile`, `parse_topography`, both spacing
//! rules) and the indentation-curve reader (`indentation::Curve::parse`) on
//! arbitrary bytes (UTF-8, or lossily converted), then the analyses a reader's
//! result feeds (ISO parameters, PSD, peaks, areal parameters, segmentation
//! and the indentation fit) when it loads. Any panic is a finding; errors are
//! the expected outcome for most inputs.
//!
//! Shared by `fuzz/fuzz_targets/readers.rs` (libFuzzer) and
//! `tests/fuzz_corpus.rs` (corpus replay on stable).

use asperity::indentation::{analyze, segment, Curve, IndentationOptions};
use asperity::surface::{parse_profile, parse_topography, ParameterOptions, Spacing};

/// Larger inputs are cut: the readers are linear, and the analyses behind
/// them would only make the fuzzer slow.
const MAX_LEN: usize = 64 * 1024;

pub fn run(data: &[u8]) {
    let data = &data[..data.len().min(MAX_LEN)];
    let text = String::from_utf8_lossy(data);
    for spacing in [Spacing::Strict, Spacing::Tolerant] {
        if let Ok(p) = parse_profile(&text, spacing) {
            assert!(p.len() >= 2, "a profile of {} points loaded", p.len());
            assert!(p.dx().is_finite() && p.dx() > 0.0, "dx = {}", p.dx());
            assert!(p.heights().iter().all(|z| z.is_finite()));
            let _ = p.parameters(&ParameterOptions::default());
            let _ = p.psd();
            let _ = p.peaks();
        }
        if let Ok(t) = parse_topography(&text, spacing) {
            assert_eq!(t.heights().len(), t.nx() * t.ny());
            assert!(t.heights().iter().all(|z| z.is_finite()));
            let _ = t.parameters();
            let _ = t.summits();
            let _ = t.row(0);
        }
    }
    if let Ok(c) = Curve::parse(&text) {
        for use_labels in [true, false] {
            let _ = segment(&c, use_labels);
        }
        let _ = analyze(&c, &IndentationOptions::default());
    }
}
