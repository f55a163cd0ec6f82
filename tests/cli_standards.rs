//! `asperity profile` with the profile conventions and instrument files:
//! `--convention` named in the output and changing what the issue says it
//! changes, the ISO 13565-2 / 25178-2 functional keys, and an `.hfm` and a
//! Nanoscope file read by extension, with their format in the JSON.

use std::process::Command;

#[allow(dead_code)]
mod common;
use common::binary;

fn json(args: &[&str]) -> serde_json::Value {
    let out = Command::new(binary()).args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn num(v: &serde_json::Value, k: &str) -> f64 {
    v[k].as_f64().unwrap_or_else(|| panic!("{k}: {}", v[k]))
}

#[test]
fn conventions_and_instrument_files() {
    let dir = std::env::temp_dir().join(format!("asperity-cli-standards-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A line scan whose five sections differ in amplitude, as .hfm (mm).
    let per = 100usize;
    let dx_mm = 1e-3;
    let mut hfm = String::from("X;Y;valid\n[mm];[mm];[1/0]\n");
    for j in 0..5 * 4 * per {
        let amp = 1.0 + (j / (4 * per)) as f64;
        let z = amp * 1e-3 * (2.0 * std::f64::consts::PI * j as f64 / per as f64).sin();
        hfm.push_str(&format!("{:.6};{:.9};1\n", j as f64 * dx_mm, z));
    }
    let f = dir.join("scan.hfm");
    std::fs::write(&f, hfm).unwrap();
    let f = f.to_str().unwrap();
    let new = json(&["profile", f, "--json", "--detrend", "none"]);
    let old = json(&[
        "profile",
        f,
        "--json",
        "--detrend",
        "none",
        "--convention",
        "iso4287",
    ]);
    assert_eq!(new["convention"], "ISO 21920-2:2021");
    assert_eq!(old["convention"], "ISO 4287:1997");
    assert_eq!(new["format"], "hfm");
    // One section without a cut-off: both conventions agree.
    assert_eq!(num(&new, "Rq"), num(&old, "Rq"));
    for k in ["Rk", "Rpk", "Rvk", "Mr1", "Mr2"] {
        assert!(num(&new, k).is_finite(), "{k}");
    }
    // Table: the convention and the format are named.
    let out = Command::new(binary())
        .args(["profile", f, "--detrend", "none"])
        .output()
        .unwrap();
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(
        table.contains("ISO 21920-2:2021 rules, hfm file"),
        "{table}"
    );
    assert!(table.contains("Rk "), "{table}");
    // A Nanoscope map by extension: 4 × 3, 16-bit (3 × 3 is the smallest
    // map the scale-dependent slope takes).
    let offset = 1024usize;
    let header = format!(
        "\\*File list\r\n\\*Scanner list\r\n\\@Sens. Zsens: V 100 nm/V\r\n\
         \\*Ciao image list\r\n\\Data offset: {offset}\r\n\\Data length: 24\r\n\\Bytes/pixel: 2\r\n\
         \\Samps/line: 4\r\n\\Number of lines: 3\r\n\\Scan Size: 4 3 ~m\r\n\
         \\@2:Image Data: S [Height] \"Height\"\r\n\
         \\@2:Z scale: V [Sens. Zsens] (0.0003 V/LSB) 65.536 V\r\n\\*File list end\r\n"
    );
    let mut b = header.into_bytes();
    b.resize(offset, 0);
    for v in [1i16, -2, 3, -4, 5, -6, 7, -8, 9, -10, 11, -12] {
        b.extend_from_slice(&v.to_le_bytes());
    }
    let m = dir.join("map.001");
    std::fs::write(&m, b).unwrap();
    let v = json(&[
        "profile",
        m.to_str().unwrap(),
        "--json",
        "--detrend",
        "none",
    ]);
    assert_eq!(v["kind"], "map");
    assert_eq!(v["format"], "nanoscope");
    assert_eq!(v["channel"], "Height");
    assert_eq!((v["nx"].as_u64(), v["ny"].as_u64()), (Some(4), Some(3)));
    assert!((num(&v, "dx") - 1e-6).abs() < 1e-18);
    // 1 count = 65.536/65536 V × 100 nm/V = 0.1 nm: heights ±0.1…1.2 nm,
    // mean −0.05 nm, so Sz = 1.1 + 1.2 nm.
    assert!((num(&v, "Sz") - 2.3e-9).abs() < 1e-15, "{}", v["Sz"]);
    for k in [
        "Sk", "Spk", "Svk", "Smr1", "Smr2", "Vmp", "Vmc", "Vvc", "Vvv",
    ] {
        assert!(num(&v, k).is_finite(), "{k}");
    }
    // A malformed file: the error names the line.
    let bad = dir.join("bad.hfm");
    std::fs::write(&bad, "X;Y;valid\n[mm];[mm];[1/0]\n0;1;1\n0.001;x;1\n").unwrap();
    let out = Command::new(binary())
        .args(["profile", bad.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 4"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}
