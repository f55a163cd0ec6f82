//! Packaging: `scripts/install.sh` installs the freshly built library into a
//! temporary prefix, and host programs build against the installed copy only:
//! a C program through pkg-config (shared and static), and a CMake consumer
//! through `find_package(asperity)` (both imported targets). The installed
//! shared library carries the soname `libasperity.so.<ABI>` (the ABI version:
//! `MAJOR`, or `0.MINOR` before 1.0; `common::abi_version`), and a version
//! request of another ABI version (the next one, and the previous one) is
//! refused by the CMake package.
//!
//! Linux only (ELF sonames). pkg-config and cmake are optional: without them
//! the test skips that part (`common::skip`: a printed reason, and a failure
//! under `ASPERITY_REQUIRE_ALL=1`, which `.ci/run` sets; it installs both).

#![cfg(target_os = "linux")]

mod common;

use common::native::{self, run_ok};
use std::path::{Path, PathBuf};
use std::process::Command;

const VERSION: &str = env!("CARGO_PKG_VERSION");

/// `MAJOR.MINOR` of this crate's version.
fn major_minor() -> (u64, u64) {
    (
        env!("CARGO_PKG_VERSION_MAJOR").parse().unwrap(),
        env!("CARGO_PKG_VERSION_MINOR").parse().unwrap(),
    )
}

fn have(tool: &str) -> bool {
    Command::new(tool)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// The example every consumer builds: it prints `CHECK` lines and exits 0
/// only when the library behaves (closed forms checked inside the program).
fn example() -> PathBuf {
    common::manifest().join("examples/c/batch_and_errors.c")
}

fn run_checked(bin: &Path, label: &str) {
    let o = Command::new(bin)
        .env_remove("LD_LIBRARY_PATH")
        .output()
        .unwrap_or_else(|e| panic!("{label}: running {}: {e}", bin.display()));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{label}: {} exited with {}:\n{text}{}",
        bin.display(),
        o.status,
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(
        text.lines().filter(|l| l.starts_with("CHECK ")).count() >= 3,
        "{label}: the example printed no checks:\n{text}"
    );
}

/// The shared objects a program needs, by `ldd`, and where they resolve.
fn needs_from_prefix(bin: &Path, lib: &Path, label: &str) {
    // Cargo puts its target directory on LD_LIBRARY_PATH for tests: without
    // it, only the program's rpath can find the library.
    let o = match Command::new("ldd")
        .env_remove("LD_LIBRARY_PATH")
        .arg(bin)
        .output()
    {
        Ok(o) => o,
        Err(e) => {
            common::skip(format_args!(
                "{label}: ldd cannot be run ({e}), so where libasperity resolves is not \
                 checked (ldd comes with the C library: apt-get install libc-bin)"
            ));
            return;
        }
    };
    let text = String::from_utf8_lossy(&o.stdout);
    let line = text
        .lines()
        .find(|l| l.contains("libasperity"))
        .unwrap_or_else(|| panic!("{label}: does not need libasperity:\n{text}"));
    let abi = common::abi_version();
    let want = format!(
        "libasperity.so.{abi} => {}",
        lib.join(format!("libasperity.so.{abi}")).display()
    );
    assert!(line.contains(&want), "{label}: `{line}` is not `{want}`");
}

#[test]
fn install_then_build_consumers_against_the_prefix() {
    let l = native::layout().unwrap();
    native::build_library(&l).unwrap();
    let out = native::out_dir(&l, "packaging");
    let prefix = out.join("prefix");
    let _ = std::fs::remove_dir_all(&out);
    std::fs::create_dir_all(&out).unwrap();

    // The one install command, on the artifacts this test run built.
    run_ok(
        Command::new("bash")
            .arg(common::manifest().join("scripts/install.sh"))
            .arg("--prefix")
            .arg(&prefix)
            .args(["--profile", &l.profile, "--no-build", "--target-dir"])
            .arg(&l.target_dir),
        "scripts/install.sh",
    )
    .unwrap();
    let lib = prefix.join("lib");
    let abi = common::abi_version();
    for f in [
        "include/asperity.h".to_string(),
        format!("lib/libasperity.so.{VERSION}"),
        format!("lib/libasperity.so.{abi}"),
        "lib/libasperity.so".to_string(),
        "lib/libasperity.a".to_string(),
        "lib/pkgconfig/asperity.pc".to_string(),
        "lib/cmake/asperity/asperityConfig.cmake".to_string(),
        "lib/cmake/asperity/asperityConfigVersion.cmake".to_string(),
    ] {
        assert!(prefix.join(&f).exists(), "install.sh did not install {f}");
    }
    for (link, to) in [
        (
            format!("libasperity.so.{abi}"),
            format!("libasperity.so.{VERSION}"),
        ),
        (
            "libasperity.so".to_string(),
            format!("libasperity.so.{abi}"),
        ),
    ] {
        let t = std::fs::read_link(lib.join(&link)).unwrap_or_else(|e| panic!("{link}: {e}"));
        assert_eq!(t, PathBuf::from(&to), "{link} should point at {to}");
    }
    if let Ok(o) = Command::new("readelf")
        .arg("-d")
        .arg(lib.join(format!("libasperity.so.{VERSION}")))
        .output()
    {
        let text = String::from_utf8_lossy(&o.stdout);
        assert!(
            text.contains(&format!("Library soname: [libasperity.so.{abi}]")),
            "the installed library lacks the soname libasperity.so.{abi}:\n{text}"
        );
    }

    let cc = native::c_compiler(&l, &out).unwrap();

    // pkg-config: shared, then static.
    if have("pkg-config") {
        let pc = |args: &[&str]| -> Vec<String> {
            let o = Command::new("pkg-config")
                .env("PKG_CONFIG_PATH", lib.join("pkgconfig"))
                .args(args)
                .arg("asperity")
                .output()
                .unwrap();
            assert!(o.status.success(), "pkg-config {args:?} asperity failed");
            String::from_utf8_lossy(&o.stdout)
                .split_whitespace()
                .map(String::from)
                .collect()
        };
        assert_eq!(pc(&["--modversion"]), vec![VERSION.to_string()]);
        let shared = out.join("pc_shared");
        run_ok(
            cc.to_command()
                .args(["-std=c99", "-Wall", "-Wextra", "-Werror"])
                .args(pc(&["--cflags"]))
                .arg(example())
                .arg("-o")
                .arg(&shared)
                .args(pc(&["--libs"]))
                .arg("-lm")
                .arg(format!("-Wl,-rpath,{}", lib.display())),
            "C example through pkg-config (shared)",
        )
        .unwrap();
        needs_from_prefix(&shared, &lib, "pkg-config shared");
        run_checked(&shared, "pkg-config shared");
        // Static: the archive by path, its private dependencies from
        // `pkg-config --static`.
        let stat = out.join("pc_static");
        let private: Vec<String> = pc(&["--static", "--libs"])
            .into_iter()
            .filter(|a| a != "-lasperity" && !a.starts_with("-L"))
            .collect();
        run_ok(
            cc.to_command()
                .args(["-std=c99", "-Wall", "-Wextra", "-Werror"])
                .args(pc(&["--cflags"]))
                .arg(example())
                .arg("-o")
                .arg(&stat)
                .arg(lib.join("libasperity.a"))
                .args(private)
                .arg("-lm"),
            "C example through pkg-config (static)",
        )
        .unwrap();
        run_checked(&stat, "pkg-config static");
    } else {
        common::skip("pkg-config consumer: pkg-config not found (apt-get install pkg-config)");
    }

    // CMake: find_package of the oldest version of this ABI version with
    // both imported targets, then requests the package must refuse.
    if have("cmake") {
        let (major, minor) = major_minor();
        let oldest = if major == 0 {
            format!("0.{minor}")
        } else {
            format!("{major}.0")
        };
        let src = out.join("cmake_src");
        std::fs::create_dir_all(&src).unwrap();
        std::fs::write(
            src.join("CMakeLists.txt"),
            format!(
                "cmake_minimum_required(VERSION 3.13)\n\
                 project(asperity_consumer C)\n\
                 find_package(asperity {oldest} REQUIRED)\n\
                 add_executable(consumer_shared \"{ex}\")\n\
                 target_link_libraries(consumer_shared PRIVATE asperity::asperity m)\n\
                 add_executable(consumer_static \"{ex}\")\n\
                 target_link_libraries(consumer_static PRIVATE asperity::asperity_static m)\n",
                ex = example().display()
            ),
        )
        .unwrap();
        let build = out.join("cmake_build");
        run_ok(
            Command::new("cmake")
                .arg("-S")
                .arg(&src)
                .arg("-B")
                .arg(&build)
                .arg(format!("-DCMAKE_PREFIX_PATH={}", prefix.display()))
                .arg(format!("-DCMAKE_C_COMPILER={}", cc.path().display())),
            "cmake configure of the consumer",
        )
        .unwrap();
        run_ok(
            Command::new("cmake").arg("--build").arg(&build),
            "cmake --build",
        )
        .unwrap();
        needs_from_prefix(&build.join("consumer_shared"), &lib, "cmake shared");
        run_checked(&build.join("consumer_shared"), "cmake asperity::asperity");
        run_checked(
            &build.join("consumer_static"),
            "cmake asperity::asperity_static",
        );

        // Refused: the next ABI version, the previous one (a host built
        // against 0.1 must not take 0.2), a bare `0` (0.0; CMake's `if()`
        // reads "0" as no version at all), and a newer release of this ABI
        // version. The projects enable C: without a language
        // CMAKE_SIZEOF_VOID_P is unset and the package refuses any request
        // as not 64-bit, which would hide the version check.
        let mut refused = vec![if major == 0 {
            format!("0.{}", minor + 1)
        } else {
            format!("{}.0", major + 1)
        }];
        if major > 0 {
            refused.push(format!("{}.0", major - 1));
        } else if minor > 0 {
            refused.push(format!("0.{}", minor - 1));
        }
        if abi != "0.0" {
            refused.push("0".to_string());
        }
        refused.push(format!(
            "{major}.{minor}.{}",
            env!("CARGO_PKG_VERSION_PATCH").parse::<u64>().unwrap() + 1
        ));
        for (k, request) in refused.iter().enumerate() {
            let src2 = out.join(format!("cmake_refused_{k}"));
            std::fs::create_dir_all(&src2).unwrap();
            std::fs::write(
                src2.join("CMakeLists.txt"),
                format!(
                    "cmake_minimum_required(VERSION 3.13)\nproject(refused C)\n\
                     find_package(asperity {request} REQUIRED)\n"
                ),
            )
            .unwrap();
            let o = Command::new("cmake")
                .arg("-S")
                .arg(&src2)
                .arg("-B")
                .arg(out.join(format!("cmake_refused_{k}_build")))
                .arg(format!("-DCMAKE_PREFIX_PATH={}", prefix.display()))
                .arg(format!("-DCMAKE_C_COMPILER={}", cc.path().display()))
                .output()
                .unwrap();
            let err = String::from_utf8_lossy(&o.stderr);
            assert!(
                !o.status.success(),
                "find_package(asperity {request}) accepted version {VERSION} (ABI version {abi})"
            );
            // CMake lists the package it considered; "version: X (64-bit)"
            // would be a refusal as unsuitable, not for the version.
            let considered = format!("version: {VERSION}");
            assert!(
                err.lines().any(|l| l.trim_end().ends_with(&considered)),
                "find_package(asperity {request}) failed, but not for the version:\n{err}"
            );
        }
    } else {
        common::skip("CMake consumer: cmake not found (apt-get install cmake)");
    }
}
