//! Fuzz harness `scene_json`: the scene parser (`asperity::scene::Scene::
//! from_json`, validation included) on arbitrary text, and, when a scene
//! parses and is small, the slider it describes (`Scene::build`: profiles
//! read or generated, rods cut, nano-asperities placed, load resolved).
//!
//! Paths: the parser joins a scene's file paths to its base directory
//! (`base.join(path)`), so an absolute path or one with `..` reaches any
//! file the process may read. The harness builds a scene only when every
//! path is relative and made of plain names, with the base a private
//! temporary directory holding two small files (`profile.csv`, `map.csv`),
//! and only when its generated profiles have at most `MAX_POINTS` points.
//! Any panic is a finding.
//!
//! Shared by `fuzz/fuzz_targets/scene_json.rs` (libFuzzer) and
//! `tests/fuzz_corpus.rs` (corpus replay on stable).

use asperity::scene::{NanoSpec, Scene, SurfaceSpec};
use std::path::{Component, Path, PathBuf};
use std::sync::OnceLock;

/// Largest generated profile the harness builds (points).
const MAX_POINTS: usize = 4096;

/// A private directory with the files the seed scenes name.
fn base_dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("asperity-fuzz-scene-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let mut profile = String::from("x_m,z_m\n");
        for j in 0..96 {
            let x = j as f64 * 1.5e-6;
            let z = 4e-7 * (0.37 * j as f64).sin() + 1e-7 * (1.3 * j as f64).cos();
            profile.push_str(&format!("{x:e},{z:e}\n"));
        }
        std::fs::write(dir.join("profile.csv"), profile).expect("profile.csv");
        let mut map = String::from("# dx_m=1e-8\n# dy_m=1e-8\n");
        for j in 0..8 {
            let row: Vec<String> = (0..64)
                .map(|i| format!("{:e}", 2e-9 * ((0.9 * i as f64).sin() + 0.3 * j as f64)))
                .collect();
            map.push_str(&row.join(","));
            map.push('\n');
        }
        std::fs::write(dir.join("map.csv"), map).expect("map.csv");
        dir
    })
}

/// A path that stays inside the base directory: relative, plain names only.
fn contained(p: &Path) -> bool {
    p.components().all(|c| matches!(c, Component::Normal(_)))
}

fn small_and_contained(s: &Scene) -> bool {
    let surface_ok = |spec: &SurfaceSpec| match spec {
        SurfaceSpec::File { path, .. } => contained(path),
        SurfaceSpec::SelfAffine { points, .. } => *points <= MAX_POINTS,
    };
    let nano_ok = match &s.surfaces.nano {
        NanoSpec::AfmMap { path, .. } => contained(path),
        NanoSpec::Asperities(_) => true,
    };
    surface_ok(&s.surfaces.slider) && surface_ok(&s.surfaces.counter) && nano_ok
}

pub fn run(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let base = base_dir();
    let Ok(scene) = Scene::from_json(text, base) else {
        return;
    };
    if !small_and_contained(&scene) {
        return;
    }
    if let Ok(slider) = scene.build() {
        let _ = scene.sweep_loads(&slider);
        let _ = slider.capacity();
    }
}
