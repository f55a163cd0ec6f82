//! Build script: compiles the hand-written C reference kernels of the
//! benchmarks (`benches/c/kernels.c`) at -O3 and links them into the bench
//! targets only (`cargo::rustc-link-arg-benches`). The library (rlib,
//! staticlib, cdylib), tests and examples never link them: no
//! `rustc-link-lib`/`rustc-link-search` is emitted (`cargo_metadata(false)`).
//!
//! If no C compiler is available the library still builds: the script warns
//! and the benches skip the C-kernel rows (cfg `asperity_c_kernels` unset).
//!
//! On Linux it also gives the shared library its soname,
//! `libasperity.so.ABI`, where the ABI version is `MAJOR` from 1.0 on and
//! `0.MINOR` before (semver: a 0.x minor release may break).

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    // The shared library's ELF soname carries the ABI version, so host codes
    // linked against it refuse an incompatible release: MAJOR for MAJOR >= 1,
    // 0.MINOR for 0.x, where a minor release may break (semver): a host
    // linked against 0.2 asks the loader for libasperity.so.0.2, which no
    // 0.3 or 1.x library provides.
    // (scripts/install.sh installs libasperity.so.MAJOR.MINOR.PATCH with the
    // .so.ABI and .so links; tests/abi.rs guards the ABI per ABI version.)
    // Cargo hands this flag to every cdylib that depends on the crate too;
    // a dependent that is not this library (the Python extension) sets
    // ASPERITY_NO_SONAME in its .cargo/config.toml.
    println!("cargo::rerun-if-env-changed=ASPERITY_NO_SONAME");
    let own = std::env::var_os("ASPERITY_NO_SONAME").is_none();
    if own && std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        let major = std::env::var("CARGO_PKG_VERSION_MAJOR").expect("CARGO_PKG_VERSION_MAJOR");
        let minor = std::env::var("CARGO_PKG_VERSION_MINOR").expect("CARGO_PKG_VERSION_MINOR");
        let abi = if major == "0" {
            format!("0.{minor}")
        } else {
            major
        };
        println!("cargo::rustc-cdylib-link-arg=-Wl,-soname,libasperity.so.{abi}");
    }
    println!("cargo::rerun-if-changed=benches/c/kernels.c");
    println!("cargo::rerun-if-changed=benches/c/kernels.h");
    println!("cargo::rustc-check-cfg=cfg(asperity_c_kernels)");

    let objects = cc::Build::new()
        .file("benches/c/kernels.c")
        .include("benches/c")
        .opt_level(3)
        // Same codegen as an ordinary -O3 build of host code: no frame pointer
        // forced by the bench profile's debug info, no -march tuning.
        .force_frame_pointer(false)
        .warnings(true)
        .extra_warnings(true)
        .cargo_metadata(false)
        .try_compile_intermediates();

    match objects {
        Ok(objects) => {
            for object in objects {
                println!("cargo::rustc-link-arg-benches={}", object.display());
            }
            println!("cargo::rustc-cfg=asperity_c_kernels");
        }
        Err(e) => {
            println!(
                "cargo::warning=benches/c/kernels.c not compiled ({e}); \
                 the benchmarks will run without the C reference kernels"
            );
        }
    }
}
