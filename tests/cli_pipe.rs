//! Every subcommand of `asperity` (feature `cli`) exits quietly when the
//! reader of its stdout goes away (issue 30 §5: `asperity lj … | head`
//! panicked on the broken pipe): status 0, no "panicked" on stderr. Each
//! runs with stdout piped, the test reads its first line (or nothing) and
//! closes the pipe; the command's later lines then meet the closed pipe.
//! The binary is found or built by `tests/common`.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

mod common;
use common::{binary, manifest};

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli-pipe")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `args` in `dir` with stdout piped; reads `lines` lines of it (0:
/// none), closes it, and checks the command ends without a panic, with
/// status 0 (or 141, the shell's status of a SIGPIPE exit).
fn closes_quietly(dir: &Path, args: &[&str], lines: usize) {
    let mut child = Command::new(binary())
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn asperity");
    let stdout = child.stdout.take().unwrap();
    let mut first = String::new();
    if lines > 0 {
        let mut r = BufReader::new(stdout);
        for _ in 0..lines {
            r.read_line(&mut first).unwrap();
        }
        drop(r);
    } else {
        drop(stdout);
    }
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !err.contains("panicked"),
        "asperity {args:?} panicked on the closed pipe:\n{err}"
    );
    assert!(
        out.status.success() || out.status.code() == Some(141),
        "asperity {args:?} after reading {first:?}: {:?}\n{err}",
        out.status
    );
    if lines > 0 {
        assert!(!first.is_empty(), "asperity {args:?} printed nothing");
    }
}

#[test]
fn every_subcommand_exits_quietly_on_a_closed_pipe() {
    let dir = scratch("all");
    // A sine line scan and a load–unload curve for `profile` and `indent`.
    let mut s = String::from("x_m,z_m\n");
    for j in 0..2000 {
        let x = j as f64 * 1e-7;
        s.push_str(&format!(
            "{x:e},{:e}\n",
            1e-6 * (x / 2e-5 * std::f64::consts::TAU).sin()
        ));
    }
    std::fs::write(dir.join("sine.csv"), s).unwrap();
    let mut s = String::new();
    for i in 0..=100 {
        let h = 1e-6 * i as f64 / 100.0;
        s.push_str(&format!("{h:e},{:e}\n", 1e-2 * (h / 1e-6).powi(2)));
    }
    for i in 1..=100 {
        let h = 1e-6 - 0.4e-6 * i as f64 / 100.0;
        s.push_str(&format!(
            "{h:e},{:e}\n",
            1e-2 * ((h - 0.6e-6) / 0.4e-6).powf(1.5)
        ));
    }
    std::fs::write(dir.join("indent.csv"), s).unwrap();
    let scene = manifest().join("examples/scenes/dynamic_models.json");
    let scene = scene.to_str().unwrap();
    let sphere = [
        "--radius",
        "1e-6",
        "--e-star",
        "1e9",
        "--work-of-adhesion",
        "0.05",
    ];
    let commands: Vec<Vec<&str>> = vec![
        [&["curve"][..], &sphere].concat(),
        [&["lj"][..], &sphere].concat(),
        vec!["indent", "indent.csv"],
        vec!["indent", "indent.csv", "--json"],
        vec!["profile", "sine.csv"],
        vec!["profile", "sine.csv", "--json"],
        vec!["slide", scene, "--out", "out"],
        vec!["slide", scene, "--json"],
        vec!["--help"],
        vec!["slide", "--help"],
    ];
    for args in &commands {
        // As `| head -1` (one line read, the rest meets the closed pipe)
        // and as `| true` (the pipe closed before the first line).
        closes_quietly(&dir, args, 1);
        closes_quietly(&dir, args, 0);
    }
}
