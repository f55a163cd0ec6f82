//! Shared by the tests that compile native programs against the library
//! (`tests/c_examples.rs`, `tests/cpp_bindings.rs`,
//! `tests/fortran_bindings.rs`, `tests/packaging.rs`, `tests/abi_layout.rs`):
//! where the test executable's profile lives, building `libasperity.a` / the
//! shared library with that profile, finding the `cc` crate's C or C++
//! compiler, the link lines (static and shared), running a compiler or other
//! tool, running a program with a time limit, parsing its
//! `CHECK <name> <value>` lines, reporting failed checks grouped by the
//! part of the library they depend on, and the Rust side of the checks the
//! C, C++ and Fortran examples share (the FE-strip law, the slider record).
//!
//! Reached as `common::native` (`mod common;` in the test crate); each test
//! crate uses a subset.

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Native libraries a Rust staticlib needs, from
/// `cargo rustc --lib --crate-type staticlib -- --print native-static-libs`.
#[cfg(target_os = "linux")]
pub const NATIVE_STATIC_LIBS: &[&str] = &[
    "-lgcc_s",
    "-lutil",
    "-lrt",
    "-lpthread",
    "-lm",
    "-ldl",
    "-lc",
];
#[cfg(target_os = "macos")]
pub const NATIVE_STATIC_LIBS: &[&str] = &["-lSystem", "-lc", "-lm"];
#[cfg(not(any(target_os = "linux", target_os = "macos")))]
pub const NATIVE_STATIC_LIBS: &[&str] = &["-lpthread", "-lm", "-ldl", "-lc"];

#[cfg(target_os = "macos")]
pub const SHARED_LIB: &str = "libasperity.dylib";
#[cfg(not(target_os = "macos"))]
pub const SHARED_LIB: &str = "libasperity.so";

/// How a program links the library.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Linkage {
    Static,
    Shared,
}

impl Linkage {
    pub const BOTH: [Linkage; 2] = [Linkage::Static, Linkage::Shared];

    /// "static" or "shared", for file names.
    pub fn suffix(self) -> &'static str {
        match self {
            Linkage::Static => "static",
            Linkage::Shared => "shared",
        }
    }

    /// The linker arguments for the library in `lib_dir` (they follow the
    /// objects or sources on the command line).
    pub fn link_args(self, lib_dir: &Path) -> Vec<OsString> {
        match self {
            Linkage::Static => std::iter::once(lib_dir.join("libasperity.a").into())
                .chain(NATIVE_STATIC_LIBS.iter().map(OsString::from))
                .collect(),
            Linkage::Shared => {
                let mut rpath = OsString::from("-Wl,-rpath,");
                rpath.push(lib_dir);
                vec![
                    "-L".into(),
                    lib_dir.into(),
                    "-lasperity".into(),
                    rpath,
                    "-lm".into(),
                ]
            }
        }
    }
}

/// `target/<profile>` (or `target/<triple>/<profile>`) of this test executable,
/// the target directory, the cargo profile name and the cross triple, if any.
pub struct Layout {
    pub profile_dir: PathBuf,
    pub target_dir: PathBuf,
    pub profile: String,
    pub cross_target: Option<String>,
}

pub fn layout() -> Result<Layout, String> {
    let exe = std::env::current_exe().map_err(|e| format!("current_exe: {e}"))?;
    // target/<profile>/deps/<test>-<hash>
    let profile_dir = exe
        .parent()
        .and_then(Path::parent)
        .ok_or_else(|| format!("unexpected test executable path {}", exe.display()))?
        .to_path_buf();
    let dir_name = profile_dir
        .file_name()
        .and_then(|s| s.to_str())
        .ok_or("profile directory has no name")?
        .to_string();
    let profile = match dir_name.as_str() {
        "debug" => "dev".to_string(),
        other => other.to_string(),
    };
    let parent = profile_dir.parent().ok_or("no target directory")?;
    // Cargo marks its target directory with CACHEDIR.TAG; one level further up
    // means a `--target <triple>` build.
    let (target_dir, cross_target) = if parent.join("CACHEDIR.TAG").exists() {
        (parent.to_path_buf(), None)
    } else if parent
        .parent()
        .is_some_and(|p| p.join("CACHEDIR.TAG").exists())
    {
        (
            parent.parent().unwrap().to_path_buf(),
            parent
                .file_name()
                .and_then(|s| s.to_str())
                .map(String::from),
        )
    } else {
        // Fall back to the environment, then to the executable's grandparent.
        match std::env::var_os("CARGO_TARGET_DIR") {
            Some(d) => (PathBuf::from(d), None),
            None => (parent.to_path_buf(), None),
        }
    };
    Ok(Layout {
        profile_dir,
        target_dir,
        profile,
        cross_target,
    })
}

/// Build `libasperity.a` and the shared library with the test's profile
/// (integration tests do not get them in the profile directory), once per
/// test executable; later calls return the first call's result.
///
/// The build is `cargo test --no-run --test <this test>`: the unit graph of
/// the `cargo test` run that built this executable, so the library it needs
/// is the one that run has just compiled and Cargo finds it fresh (about a
/// second). `cargo build --lib` resolves the build script's `cc` without the
/// dev-dependencies: another build of the library, written over the same
/// files, so it compiled the whole library a second time (35–80 s on two
/// shared cores; most of the C examples' 276 s in issue 30 §4). Cargo leaves
/// the test graph's library in `deps/`; it is hard-linked into the profile
/// directory, where the link lines and `scripts/install.sh` look for it.
pub fn build_library(l: &Layout) -> Result<(), String> {
    static BUILT: std::sync::OnceLock<Result<(), String>> = std::sync::OnceLock::new();
    BUILT.get_or_init(|| build_library_now(l)).clone()
}

fn build_library_now(l: &Layout) -> Result<(), String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.current_dir(super::manifest());
    // The crate name of the test executable being compiled (`c_examples`, …).
    let test = option_env!("CARGO_CRATE_NAME");
    match test {
        Some(t) => cmd.args(["test", "--no-run", "--test", t]),
        None => cmd.args(["build", "--lib"]),
    };
    cmd.args(["--profile", &l.profile, "--target-dir"])
        .arg(&l.target_dir);
    if let Some(t) = &l.cross_target {
        cmd.args(["--target", t]);
    }
    if cfg!(feature = "cli") {
        cmd.args(["--features", "cli"]);
    }
    let what = if test.is_some() {
        "cargo test --no-run"
    } else {
        "cargo build --lib"
    };
    let out = cmd.output().map_err(|e| format!("running {what}: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "{what} failed ({}):\n{}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    for lib in ["libasperity.a", SHARED_LIB] {
        let built = l.profile_dir.join("deps").join(lib);
        let dest = l.profile_dir.join(lib);
        if test.is_some() {
            uplift(&built, &dest)?;
        }
        if !dest.exists() {
            return Err(format!("{what} did not produce {}", dest.display()));
        }
    }
    soname_link(&l.profile_dir)
}

/// `dest` becomes a hard link to `built` (a copy where links fail), replaced
/// in one rename so that no reader sees a missing or partial library.
fn uplift(built: &Path, dest: &Path) -> Result<(), String> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(a), Ok(b)) = (std::fs::metadata(built), std::fs::metadata(dest)) {
            if a.dev() == b.dev() && a.ino() == b.ino() {
                return Ok(());
            }
        }
    }
    let name = dest.file_name().unwrap_or_default().to_string_lossy();
    let tmp = dest.with_file_name(format!(".{name}.uplift-{}", std::process::id()));
    let _ = std::fs::remove_file(&tmp);
    if std::fs::hard_link(built, &tmp).is_err() {
        std::fs::copy(built, &tmp)
            .map_err(|e| format!("copying {} to {}: {e}", built.display(), tmp.display()))?;
    }
    std::fs::rename(&tmp, dest)
        .map_err(|e| format!("moving {} to {}: {e}", tmp.display(), dest.display()))
}

/// The shared library's soname is `libasperity.so.<ABI>` (build.rs,
/// [`super::abi_version`]): a program linked against `libasperity.so` asks
/// the loader for that name, so it must exist next to the library
/// (scripts/install.sh makes the same link).
pub fn soname_link(dir: &Path) -> Result<(), String> {
    #[cfg(target_os = "linux")]
    {
        let link = dir.join(format!("{SHARED_LIB}.{}", super::abi_version()));
        let _ = std::fs::remove_file(&link);
        match std::os::unix::fs::symlink(SHARED_LIB, &link) {
            // Another test made it between the two calls.
            Err(e) if e.kind() != std::io::ErrorKind::AlreadyExists => {
                return Err(format!("linking {} to {SHARED_LIB}: {e}", link.display()))
            }
            _ => {}
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = dir;
    Ok(())
}

fn host_triple() -> String {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    if let Ok(out) = Command::new(rustc).arg("-vV").output() {
        let text = String::from_utf8_lossy(&out.stdout);
        if let Some(h) = text.lines().find_map(|l| l.strip_prefix("host: ")) {
            return h.trim().to_string();
        }
    }
    // Good enough for the usual hosts when rustc is not on PATH.
    format!(
        "{}-{}",
        std::env::consts::ARCH,
        match std::env::consts::OS {
            "linux" => "unknown-linux-gnu",
            "macos" => "apple-darwin",
            other => other,
        }
    )
}

/// The C compiler `cc` would use for this target, without any cargo metadata.
pub fn c_compiler(l: &Layout, scratch: &Path) -> Result<cc::Tool, String> {
    compiler(l, scratch, false)
}

/// The C++ compiler `cc` would use for this target, without any cargo
/// metadata.
pub fn cpp_compiler(l: &Layout, scratch: &Path) -> Result<cc::Tool, String> {
    compiler(l, scratch, true)
}

fn compiler(l: &Layout, scratch: &Path, cpp: bool) -> Result<cc::Tool, String> {
    let host = host_triple();
    let target = l.cross_target.clone().unwrap_or_else(|| host.clone());
    cc::Build::new()
        .cpp(cpp)
        .target(&target)
        .host(&host)
        .opt_level(0)
        .debug(false)
        .out_dir(scratch)
        .cargo_metadata(false)
        .cargo_warnings(false)
        .cargo_output(false)
        .emit_rerun_if_env_changed(false)
        .try_get_compiler()
        .map_err(|e| {
            format!(
                "cc could not find a {} compiler: {e}",
                if cpp { "C++" } else { "C" }
            )
        })
}

/// Run a compiler, linker or other tool; on failure the error gives `what`,
/// the command line and the tool's output.
pub fn run_ok(cmd: &mut Command, what: &str) -> Result<(), String> {
    // The program and its arguments, without the environment `cc` sets.
    let line = std::iter::once(cmd.get_program())
        .chain(cmd.get_args())
        .map(|a| a.to_string_lossy())
        .collect::<Vec<_>>()
        .join(" ");
    let o = cmd
        .output()
        .map_err(|e| format!("{what}: running `{line}`: {e}"))?;
    if !o.status.success() {
        return Err(format!(
            "{what} failed:\n{line}\n{}{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        ));
    }
    Ok(())
}

/// One program: linkage → binary, or the compiler's or linker's complaint.
pub type ByLinkage = BTreeMap<Linkage, Result<PathBuf, String>>;

/// Built programs: name → (linkage → binary or the compiler's error).
pub type Binaries = BTreeMap<String, ByLinkage>;

/// The binary of `name` linked `linkage`; panics with the compiler's error,
/// or naming `source` when there is no such program.
pub fn binary(b: &Binaries, name: &str, linkage: Linkage, source: &str) -> PathBuf {
    match b.get(name).and_then(|m| m.get(&linkage)) {
        None => panic!("{source} not found"),
        Some(Err(e)) => panic!("{e}"),
        Some(Ok(bin)) => bin.clone(),
    }
}

/// Every build failure, one per line (empty when all built).
pub fn build_errors(b: &Binaries) -> String {
    let mut errors = String::new();
    for (name, by_linkage) in b {
        for (k, r) in by_linkage {
            if let Err(e) = r {
                let _ = writeln!(errors, "{name} ({k:?}): {e}");
            }
        }
    }
    errors
}

/// The files of `dir` (relative to the crate root) ending in `.ext`, sorted.
pub fn sources(dir: &str, ext: &str) -> Vec<PathBuf> {
    let dir = super::manifest().join(dir);
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("reading {}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == ext))
        .collect();
    v.sort();
    v
}

/// `<target>/tmp/<name>/<profile>/`, where a test keeps its programs and
/// other outputs.
pub fn out_dir(l: &Layout, name: &str) -> PathBuf {
    // `CARGO_TARGET_TMPDIR` is target/tmp of the build that compiled this test.
    let base = option_env!("CARGO_TARGET_TMPDIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| l.target_dir.join("tmp"));
    base.join(name).join(&l.profile)
}

/// `f` over `items`, one thread each, results in order.
pub fn parallel<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    std::thread::scope(|s| {
        let handles: Vec<_> = items.iter().map(|item| s.spawn(|| f(item))).collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    })
}

/// What a program printed.
pub struct Run {
    pub label: String,
    pub status: std::process::ExitStatus,
    pub stdout: String,
    pub stderr: String,
    /// `CHECK <name> <value>` lines.
    pub checks: BTreeMap<String, f64>,
}

impl Run {
    /// Rows whose first word is one of `phases`, in output order: (phase,
    /// the numbers that follow, up to the first word that is not a number).
    pub fn rows(&self, phases: &[&str]) -> Vec<(String, Vec<f64>)> {
        self.stdout
            .lines()
            .filter_map(|line| {
                let mut words = line.split_whitespace();
                let phase = words.next().filter(|w| phases.contains(w))?;
                let numbers: Vec<f64> = words.map_while(|w| w.parse().ok()).collect();
                Some((phase.to_string(), numbers))
            })
            .collect()
    }
}

/// Run `bin` with `args` (stdin closed, at most 120 s) and parse its
/// `CHECK <name> <value>` lines; `label` names the run in failure messages.
pub fn run(bin: &Path, args: &[&str], label: &str) -> Run {
    // One pair of output files per run: two tests may run the same binary
    // at once, and shared files would truncate each other.
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let stdout_path = bin.with_extension(format!("{k}.stdout"));
    let stderr_path = bin.with_extension(format!("{k}.stderr"));
    let mut child = Command::new(bin)
        .args(args)
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&stdout_path).unwrap())
        .stderr(std::fs::File::create(&stderr_path).unwrap())
        .spawn()
        .unwrap_or_else(|e| panic!("running {}: {e}", bin.display()));
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break s;
        }
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{} did not finish within 120 s", bin.display());
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let stdout = std::fs::read_to_string(&stdout_path).unwrap_or_default();
    let stderr = std::fs::read_to_string(&stderr_path).unwrap_or_default();
    let mut checks = BTreeMap::new();
    for line in stdout.lines() {
        let mut words = line.split_whitespace();
        if words.next() == Some("CHECK") {
            let (Some(k), Some(v)) = (words.next(), words.next()) else {
                panic!("{label}: malformed CHECK line `{line}`");
            };
            let v: f64 = v
                .parse()
                .unwrap_or_else(|_| panic!("{label}: CHECK {k}: `{v}` is not a number"));
            checks.insert(k.to_string(), v);
        }
    }
    Run {
        label: label.to_string(),
        status,
        stdout,
        stderr,
        checks,
    }
}

/// Collects failed checks, each tagged with the part of the library it
/// depends on, and panics with all of them at the end.
pub struct Report<'a> {
    pub run: &'a Run,
    failures: Vec<(&'static str, String)>,
    passed: usize,
}

impl<'a> Report<'a> {
    pub fn new(run: &'a Run) -> Self {
        Self {
            run,
            failures: Vec::new(),
            passed: 0,
        }
    }

    pub fn fail(&mut self, needs: &'static str, msg: String) {
        self.failures.push((needs, msg));
    }

    pub fn ok(&mut self, needs: &'static str, cond: bool, msg: impl FnOnce() -> String) {
        if cond {
            self.passed += 1;
        } else {
            self.fail(needs, msg());
        }
    }

    pub fn get(&mut self, needs: &'static str, name: &str) -> Option<f64> {
        let v = self.run.checks.get(name).copied();
        if v.is_none() {
            self.fail(needs, format!("CHECK {name} missing from the output"));
        }
        v
    }

    /// `|value − expected| ≤ tol`.
    pub fn close(&mut self, needs: &'static str, name: &str, expected: f64, tol: f64) {
        if let Some(v) = self.get(needs, name) {
            self.ok(needs, (v - expected).abs() <= tol, || {
                format!("CHECK {name} = {v:.10e}, expected {expected:.10e} ± {tol:e}")
            });
        }
    }

    /// `|value − expected| ≤ rel·|expected|`.
    pub fn rel(&mut self, needs: &'static str, name: &str, expected: f64, rel: f64) {
        self.close(needs, name, expected, rel * expected.abs());
    }

    /// `lo ≤ value ≤ hi`.
    pub fn within(&mut self, needs: &'static str, name: &str, lo: f64, hi: f64) {
        if let Some(v) = self.get(needs, name) {
            self.ok(needs, v >= lo && v <= hi, || {
                format!("CHECK {name} = {v:.10e}, expected in [{lo:e}, {hi:e}]")
            });
        }
    }

    pub fn exit_ok(&mut self, needs: &'static str) {
        let s = self.run.status;
        self.ok(needs, s.success(), || {
            format!("the program exited with {s} (a library call failed, see stderr)")
        });
    }

    pub fn finish(self) {
        if self.failures.is_empty() {
            return;
        }
        let mut by_law: BTreeMap<&str, Vec<&String>> = BTreeMap::new();
        for (needs, m) in &self.failures {
            by_law.entry(needs).or_default().push(m);
        }
        let mut msg = format!(
            "{}: {} check(s) failed, {} passed.\n",
            self.run.label,
            self.failures.len(),
            self.passed
        );
        for (law, ms) in by_law {
            let _ = writeln!(msg, "  depends on {law}:");
            for m in ms.iter().take(12) {
                let _ = writeln!(msg, "    - {m}");
            }
            if ms.len() > 12 {
                let _ = writeln!(msg, "    - … and {} more", ms.len() - 12);
            }
        }
        let _ = writeln!(msg, "--- stderr ---\n{}", self.run.stderr.trim_end());
        let tail: Vec<&str> = self.run.stdout.lines().rev().take(25).collect();
        let _ = writeln!(msg, "--- stdout (last lines) ---");
        for l in tail.into_iter().rev() {
            let _ = writeln!(msg, "{l}");
        }
        panic!("{msg}");
    }
}

/// The homogenised law of the FE-strip examples
/// (`examples/c/fe_strip_friction.c`, `examples/fortran/fe_strip_friction.f90`):
/// their table rebuilt through the Rust API.
pub fn fe_strip_law() -> asperity::friction::HomogenisedFriction {
    use asperity::friction::{CofForm, Dissipation, HomogenisedFriction, HomogenisedSample};
    // (p MPa, μ, adhesion MPa, contact fraction, chemical, vdW, elastic shares)
    let rows = [
        (10.0, 1.10, 0.90, 0.010, 0.930, 0.067, 0.002),
        (50.0, 1.02, 4.50, 0.050, 0.925, 0.066, 0.006),
        (100.0, 0.97, 9.00, 0.100, 0.920, 0.064, 0.010),
        (150.0, 0.93, 13.5, 0.150, 0.910, 0.062, 0.018),
        (200.0, 0.90, 18.0, 0.200, 0.900, 0.060, 0.025),
    ];
    let samples: Vec<HomogenisedSample> = rows
        .iter()
        .map(|&(p, mu, pa, fr, ch, v, e)| HomogenisedSample {
            pressure: p * 1e6,
            cof: mu,
            adhesion_pressure: pa * 1e6,
            contact_fraction: fr,
            shares: Dissipation {
                chemical: ch,
                van_der_waals: v,
                elastic: e,
                plastic: 1.0 - ch - v - e,
            },
        })
        .collect();
    HomogenisedFriction::from_samples(&samples, CofForm::Derjaguin).unwrap()
}

/// The steady sliding force (N) of the FE-strip examples: Σ μ(p_i)(N_i + A_i)
/// (Derjaguin form) over the 64 strip points at pressures 10 … 200 MPa on
/// 1 mm² each.
pub fn fe_strip_steady_force() -> f64 {
    let law = fe_strip_law();
    let area = 1e-6;
    (0..64)
        .map(|i| {
            let p = 10e6 + 190e6 * i as f64 / 63.0;
            let s = law.sample_at(p).unwrap();
            s.cof * (p * area + s.adhesion_pressure * area)
        })
        .sum()
}

/// The Rust side of the slider record of the `slider_patch` examples
/// (`examples/c/slider_patch.c`, `examples/cpp/slider_patch.cpp`,
/// `examples/fortran/slider_patch.f90`), their `CHECK` lines checked in `c`:
///
/// * the record of the first two blocks of a block call from fresh states
///   (`blocks` names them in the `CHECK` lines): the first seats its fresh
///   state, then the slider advances by `step` per block, to the state's
///   position; the counts nest;
/// * the record of patch 0's tangent step against the Rust step's
///   `SliderWork::record()` from the same history: `steps` increments of
///   `step` along +x at `normal_force` from a fresh state, then one with
///   both tangents;
/// * the record of a zero slip: no advance, nothing seated.
///
/// `needs` tags the slider's checks, `ffi` those of the C ABI. Returns the
/// tangent step's response and the state's position before it, for the
/// checks a program makes on its own.
pub fn check_slider_record(
    c: &mut Report,
    (needs, ffi): (&'static str, &'static str),
    blocks: [&str; 2],
    slider: &asperity::friction::Slider,
    normal_force: f64,
    (steps, step): (usize, f64),
) -> (asperity::friction::FrictionResponse, f64) {
    use asperity::friction::{
        FrictionIncrement, FrictionLaw, Slider, SliderWork, TANGENT_NORMAL, TANGENT_SLIP,
    };
    let [first, second] = blocks;
    c.close(needs, &format!("record_{first}_seated"), 1.0, 0.0);
    c.close(needs, &format!("record_{first}_position"), step, 0.0);
    c.close(needs, &format!("record_{second}_seated"), 0.0, 0.0);
    c.close(needs, &format!("record_{second}_position"), 2.0 * step, 0.0);
    c.close(needs, "record_seated_ok", 1.0, 0.0);
    c.close(ffi, "record_position_matches_state", 1.0, 0.0);
    c.within(needs, "record_max_advance_diff", 0.0, 1e-18);
    c.close(needs, "record_counts_consistent", 1.0, 0.0);
    let mut w = slider.work();
    let mut st = vec![0.0; slider.state_len()];
    let mut inc = FrictionIncrement {
        normal_force,
        slip: [step, 0.0],
        dt: 1e-5,
        ..FrictionIncrement::default()
    };
    for _ in 0..steps {
        slider.step_in_place(&mut st, &inc, &mut w).unwrap();
    }
    inc.tangents = TANGENT_NORMAL | TANGENT_SLIP;
    let mut new = vec![0.0; slider.state_len()];
    let t = slider.step(&st, &mut new, &inc, &mut w).unwrap();
    let sw = w.get::<SliderWork>().unwrap();
    let rec = sw.record();
    assert!(
        rec.nano_contacts > 0 && rec.rods_in_contact > 0,
        "the check must see a contact"
    );
    c.close(needs, "tangent_record_position", rec.position, 1e-15);
    c.close(
        needs,
        "tangent_record_rod_position",
        rec.rod_position,
        1e-10 * rec.rod_position.abs(),
    );
    c.close(
        needs,
        "tangent_record_adhesion_area_share",
        rec.adhesion_area_share,
        1e-10,
    );
    for (name, n) in [
        ("nano_contacts", rec.nano_contacts),
        ("adhesive_contacts", rec.adhesive_contacts),
        ("rods_in_contact", rec.rods_in_contact),
        ("yielded_rods", rec.yielded_rods),
    ] {
        c.close(needs, &format!("tangent_record_{name}"), n as f64, 0.0);
    }
    c.close(
        needs,
        "tangent_record_seated",
        sw.seated() as i32 as f64,
        0.0,
    );
    c.close(needs, "zero_slip_record_advance", 0.0, 0.0);
    c.close(needs, "zero_slip_record_seated", 0.0, 0.0);
    (t, st[Slider::STATE_POSITION])
}
