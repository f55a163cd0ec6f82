//! Shared by the command-line tests: where the crate is and the `asperity`
//! binary to run. (`native.rs` beside this file holds the helpers of the
//! tests that compile C and C++ programs; those include it by path, so the
//! command-line tests do not compile it.)

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The crate's root directory.
pub fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The binary: the one Cargo built for this test run when the `cli` feature
/// is on (`cargo test --features cli`); otherwise built once per run in its own
/// target directory, which keeps the library artifacts the C-example tests
/// link against untouched.
pub fn binary() -> &'static Path {
    static BIN: OnceLock<PathBuf> = OnceLock::new();
    BIN.get_or_init(|| {
        // Cargo builds the binary for this run only with its required
        // feature `cli` on. Without it Cargo still names the binary, and a
        // file there is a stale build of some earlier run: build afresh.
        if cfg!(feature = "cli") {
            if let Some(bin) = option_env!("CARGO_BIN_EXE_asperity").map(PathBuf::from) {
                return bin;
            }
        }
        let target = manifest().join("target").join("cli-test");
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let out = Command::new(cargo)
            .current_dir(manifest())
            .args([
                "build",
                "--features",
                "cli",
                "--bin",
                "asperity",
                "--target-dir",
            ])
            .arg(&target)
            .output()
            .expect("run cargo build");
        assert!(
            out.status.success(),
            "cargo build --features cli failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        target.join("debug").join("asperity")
    })
}

/// Programs in other languages (C, Fortran) built against the freshly built
/// `libasperity.a` and shared library, and run: where the libraries are, how
/// to link them, and a runner that collects `CHECK <name> <value>` lines.
/// (tests/c_examples.rs has its own copy of the layout and build steps.)
#[allow(dead_code)]
pub mod native {
    use std::collections::BTreeMap;
    use std::fmt::Write as _;
    use std::path::{Path, PathBuf};
    use std::process::{Command, ExitStatus, Stdio};
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

        pub fn name(self) -> &'static str {
            match self {
                Linkage::Static => "static",
                Linkage::Shared => "shared",
            }
        }

        /// Linker arguments for the library in `lib_dir`.
        pub fn link_args(self, lib_dir: &Path) -> Vec<String> {
            match self {
                Linkage::Static => {
                    std::iter::once(lib_dir.join("libasperity.a").display().to_string())
                        .chain(NATIVE_STATIC_LIBS.iter().map(|s| s.to_string()))
                        .collect()
                }
                Linkage::Shared => vec![
                    "-L".into(),
                    lib_dir.display().to_string(),
                    "-lasperity".into(),
                    format!("-Wl,-rpath,{}", lib_dir.display()),
                    "-lm".into(),
                ],
            }
        }
    }

    /// `target/<profile>` (or `target/<triple>/<profile>`) of this test
    /// executable, the target directory, the cargo profile name and the
    /// cross triple, if any.
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
        // Cargo marks its target directory with CACHEDIR.TAG; one level
        // further up means a `--target <triple>` build.
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
    /// (integration tests do not get them for free).
    pub fn build_library(l: &Layout) -> Result<(), String> {
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let mut cmd = Command::new(cargo);
        cmd.current_dir(super::manifest())
            .args(["build", "--lib", "--profile", &l.profile, "--target-dir"])
            .arg(&l.target_dir);
        if let Some(t) = &l.cross_target {
            cmd.args(["--target", t]);
        }
        if cfg!(feature = "cli") {
            cmd.args(["--features", "cli"]);
        }
        let out = cmd
            .output()
            .map_err(|e| format!("running cargo build --lib: {e}"))?;
        if !out.status.success() {
            return Err(format!(
                "cargo build --lib failed ({}):\n{}",
                out.status,
                String::from_utf8_lossy(&out.stderr)
            ));
        }
        for lib in ["libasperity.a", SHARED_LIB] {
            if !l.profile_dir.join(lib).exists() {
                return Err(format!(
                    "cargo build --lib did not produce {}",
                    l.profile_dir.join(lib).display()
                ));
            }
        }
        soname_link(&l.profile_dir)
    }

    /// The shared library's soname is `libasperity.so.MAJOR` (build.rs): a
    /// program linked against `libasperity.so` asks the loader for that
    /// name, so it must exist next to the library (scripts/install.sh makes
    /// the same link).
    pub fn soname_link(dir: &Path) -> Result<(), String> {
        #[cfg(target_os = "linux")]
        {
            let link = dir.join(format!("{SHARED_LIB}.{}", env!("CARGO_PKG_VERSION_MAJOR")));
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

    /// A scratch directory for this test's outputs:
    /// `target/tmp/<what>/<profile>/`.
    pub fn out_dir(l: &Layout, what: &str) -> PathBuf {
        let base = option_env!("CARGO_TARGET_TMPDIR")
            .map(PathBuf::from)
            .unwrap_or_else(|| l.target_dir.join("tmp"));
        base.join(what).join(&l.profile)
    }

    fn host_triple() -> String {
        let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
        if let Ok(out) = Command::new(rustc).arg("-vV").output() {
            let text = String::from_utf8_lossy(&out.stdout);
            if let Some(h) = text.lines().find_map(|l| l.strip_prefix("host: ")) {
                return h.trim().to_string();
            }
        }
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

    /// The C compiler `cc` would use for this target, without cargo metadata.
    pub fn c_compiler(l: &Layout, scratch: &Path) -> Result<cc::Tool, String> {
        let host = host_triple();
        let target = l.cross_target.clone().unwrap_or_else(|| host.clone());
        cc::Build::new()
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
            .map_err(|e| format!("cc could not find a C compiler: {e}"))
    }

    /// Run `cmd` and fail with its output unless it succeeds.
    pub fn run_ok(cmd: &mut Command, what: &str) -> Result<(), String> {
        let o = cmd
            .output()
            .map_err(|e| format!("{what}: running {cmd:?}: {e}"))?;
        if o.status.success() {
            Ok(())
        } else {
            Err(format!(
                "{what} failed:\n{cmd:?}\n{}{}",
                String::from_utf8_lossy(&o.stdout),
                String::from_utf8_lossy(&o.stderr)
            ))
        }
    }

    /// What a program printed.
    pub struct Run {
        pub label: String,
        pub status: ExitStatus,
        pub stdout: String,
        pub stderr: String,
        /// `CHECK <name> <value>` lines.
        pub checks: BTreeMap<String, f64>,
    }

    impl Run {
        /// The numbers after the first word of every line that starts with
        /// `word` (up to the first word that is not a number).
        pub fn rows(&self, word: &str) -> Vec<Vec<f64>> {
            self.stdout
                .lines()
                .filter_map(|l| {
                    let mut w = l.split_whitespace();
                    (w.next() == Some(word)).then(|| w.map_while(|x| x.parse().ok()).collect())
                })
                .collect()
        }
    }

    /// Run `bin` with `args` (stdin closed, 120 s at most) and parse its
    /// CHECK lines.
    pub fn run(bin: &Path, args: &[&str], label: &str) -> Run {
        // One pair of output files per run: two tests may run the same
        // binary at once.
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
                let (Some(name), Some(v)) = (words.next(), words.next()) else {
                    panic!("{label}: malformed CHECK line `{line}`");
                };
                let v: f64 = v
                    .parse()
                    .unwrap_or_else(|_| panic!("{label}: CHECK {name}: `{v}` is not a number"));
                checks.insert(name.to_string(), v);
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

    /// Collects failed checks, each tagged with what it depends on, and
    /// panics with all of them at the end.
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
            let mut by: BTreeMap<&str, Vec<&String>> = BTreeMap::new();
            for (needs, m) in &self.failures {
                by.entry(needs).or_default().push(m);
            }
            let mut msg = format!(
                "{}: {} check(s) failed, {} passed.\n",
                self.run.label,
                self.failures.len(),
                self.passed
            );
            for (needs, ms) in by {
                let _ = writeln!(msg, "  depends on {needs}:");
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
}
