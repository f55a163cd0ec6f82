//! Instrument file readers on small files the tests write: X3P (stored and
//! deflated, profile and map, float and integer data, inline data), Nanoscope
//! (16- and 32-bit), Dektak CSV and Hommel `.hfm`; format detection by
//! extension and by content; malformed files give errors naming the line or
//! byte offset.

use asperity::error::Error;
use asperity::surface::instrument::{detect_format, Format};
use asperity::surface::*;
use std::io::Write;
use std::path::{Path, PathBuf};

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-readers-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1e-300)
}

// ---------------------------------------------------------------- HFM

const HFM: &str = "X;Y;valid\n[mm];[mm];[1/0]\n8.672200;106.606853;1\n8.672700;106.606860;1\n8.673200;106.606835;1\n8.673700;106.606828;1\n";

#[test]
fn hfm_profile() {
    let p = parse_hfm(HFM, Spacing::Strict).unwrap();
    assert_eq!(p.len(), 4);
    assert!(close(p.dx(), 0.5e-6, 1e-9), "dx {}", p.dx());
    assert!(close(p.x0(), 8.6722e-3, 1e-12));
    assert!(close(p.heights()[0], 106.606853e-3, 1e-15));
    assert!(close(p.heights()[3], 106.606828e-3, 1e-15));
    // Errors name the line.
    let bad = HFM.replace("8.673200;106.606835;1", "8.673200;106.606835;0");
    assert!(matches!(
        parse_hfm(&bad, Spacing::Strict),
        Err(Error::Parse { line: 5, .. })
    ));
    let bad = HFM.replace("8.672700;106.606860;1", "8.672700;abc;1");
    assert!(matches!(
        parse_hfm(&bad, Spacing::Strict),
        Err(Error::Parse { line: 4, .. })
    ));
    let bad = HFM.replace("[mm];[mm]", "[furlong];[mm]");
    assert!(matches!(
        parse_hfm(&bad, Spacing::Strict),
        Err(Error::Parse { line: 2, .. })
    ));
    assert!(matches!(
        parse_hfm("A;B\n", Spacing::Strict),
        Err(Error::Parse { line: 1, .. })
    ));
    let e = parse_hfm(&bad, Spacing::Strict).unwrap_err().to_string();
    assert!(e.contains("line 2"), "{e}");
}

// --------------------------------------------------------- Dektak CSV

fn dektak(rows: &str) -> String {
    format!(
        "Scan Parameters\nScan Type,Standard Scan\nLength,1500.0 um\nResolution,0.156 um/sample\n\nAnalytical Results\nFunction,R.Cur Pos,Result\nRa,468.0 um,0.00525 um\n\nScan Data\nLateral um,Raw Micrometer,\n{rows}"
    )
}

#[test]
fn dektak_csv_profile() {
    let t =
        dektak("0.0,-0.00933,,\n0.2,-0.00760,,\n0.3,-0.00644,,\n0.5,-0.00498,,\n0.6,-0.00345,,\n");
    let p = parse_dektak_csv(&t, Spacing::Tolerant).unwrap();
    assert_eq!(p.len(), 5);
    // Rounded positions (the instrument's 0.1 µm): spacing 0.15 µm.
    assert!(close(p.dx(), 0.15e-6, 1e-9), "dx {}", p.dx());
    assert!(close(p.heights()[0], -0.00933e-6, 1e-12));
    assert!(close(p.heights()[4], -0.00345e-6, 1e-12));
    // Nanometres and Angstroms.
    let t2 = t.replace("Lateral um,Raw Micrometer,", "Lateral mm,Normal Angstrom,");
    let q = parse_dektak_csv(&t2, Spacing::Tolerant).unwrap();
    assert!(close(q.dx(), 0.15e-3, 1e-9));
    assert!(close(q.heights()[0], -0.00933e-10, 1e-12));
    // Errors name the line.
    let bad = t.replace("0.3,-0.00644,,", "0.3,x,,");
    assert!(matches!(
        parse_dektak_csv(&bad, Spacing::Tolerant),
        Err(Error::Parse { line: 14, .. })
    ));
    let bad = t.replace("Raw Micrometer", "Raw Volts");
    assert!(matches!(
        parse_dektak_csv(&bad, Spacing::Tolerant),
        Err(Error::Parse { line: 11, .. })
    ));
    assert!(matches!(
        parse_dektak_csv("Scan Parameters\n1,2\n", Spacing::Tolerant),
        Err(Error::Parse { line: 0, .. })
    ));
}

// ---------------------------------------------------------- Nanoscope

/// A Nanoscope file: header, padding to `offset`, then `nx × ny` values.
fn nanoscope(nx: usize, ny: usize, bpp: usize, values: &[i64], z_key: &str) -> Vec<u8> {
    let offset = 2048usize;
    let header = format!(
        "\\*File list\r\n\\Version: 0x09010201\r\n\\Data length: {offset}\r\n\
         \\*Ciao scan list\r\n\\Scan Size: 10 10 ~m\r\n\\@Sens. ZsensSens: V 790.3658 nm/V\r\n\
         \\@Sens. Zsens: V 20.0 nm/V\r\n\
         \\*Ciao image list\r\n\\Data offset: {offset}\r\n\\Data length: {}\r\n\\Bytes/pixel: {bpp}\r\n\
         \\Samps/line: {nx}\r\n\\Number of lines: {ny}\r\n\\Scan Size: 10 5 ~m\r\n\
         \\@2:Image Data: S [ZSensor] \"Height Sensor\"\r\n\
         \\@2:{z_key}: V [Sens. ZsensSens] (0.000375 V/LSB) 24.576 V\r\n\
         \\*File list end\r\n",
        nx * ny * bpp
    );
    let mut b = header.into_bytes();
    assert!(b.len() < offset);
    b.resize(offset, 0);
    for &v in values {
        if bpp == 2 {
            b.extend_from_slice(&(v as i16).to_le_bytes());
        } else {
            b.extend_from_slice(&(v as i32).to_le_bytes());
        }
    }
    b
}

#[test]
fn nanoscope_map() {
    // 3 × 2 image; stored lines from the top: line 0 is y = 1 (row 1).
    let vals: [i64; 6] = [1, 2, 3, -4, -5, -6];
    let per_count = 24.576 / 65536.0 * 790.3658e-9;
    for bpp in [2usize, 4] {
        let raw: Vec<i64> = vals
            .iter()
            .map(|&v| if bpp == 4 { v * 65536 } else { v })
            .collect();
        let (t, name) = parse_nanoscope(&nanoscope(3, 2, bpp, &raw, "Z scale")).unwrap();
        assert_eq!(name, "ZSensor");
        assert_eq!((t.nx(), t.ny()), (3, 2));
        assert!(close(t.dx(), 10e-6 / 3.0, 1e-12) && close(t.dy(), 5e-6 / 2.0, 1e-12));
        // Row 0 (bottom) is the last stored line.
        assert!(close(t.z(0, 0).unwrap(), -4.0 * per_count, 1e-12));
        assert!(close(t.z(2, 1).unwrap(), 3.0 * per_count, 1e-12));
    }
    // The README's scale of the AFM file: 0.296 nm per count.
    assert!(close(per_count, 0.2964e-9, 1e-3), "{per_count}");
    // Truncated data: the byte offset of the end of the file.
    let mut b = nanoscope(3, 2, 2, &vals, "Z scale");
    b.truncate(b.len() - 1);
    let e = parse_nanoscope(&b).unwrap_err();
    assert_eq!(
        e,
        Error::Binary {
            what: "the data block runs past the end of the file",
            offset: b.len() as u64
        }
    );
    assert!(e.to_string().contains(&format!("offset {}", b.len())));
    // Malformed Z scale: the header line.
    let b = nanoscope(3, 2, 2, &vals, "Z scale");
    let s =
        String::from_utf8_lossy(&b).replace("(0.000375 V/LSB) 24.576 V", "(0.000375 V/LSB) x V");
    assert!(matches!(
        parse_nanoscope(s.as_bytes()),
        Err(Error::Parse { line: 16, .. })
    ));
    // No header end, no header start.
    assert!(matches!(
        parse_nanoscope(b"\\*File list\n\\Version: 1\n"),
        Err(Error::Parse { line: 0, .. })
    ));
    assert!(matches!(
        parse_nanoscope(b"hello\n"),
        Err(Error::Parse { line: 1, .. })
    ));
}

// ---------------------------------------------------------------- X3P

fn main_xml(feature: &str, nx: usize, ny: usize, ty: &str, dz: f64, data: &str) -> String {
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>{feature}</FeatureType>\n<Axes>\n<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>2.5e-07</Increment><Offset>1e-3</Offset></CX>\n<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>5e-07</Increment><Offset>0</Offset></CY>\n<CZ><AxisType>A</AxisType><DataType>{ty}</DataType><Increment>{dz:e}</Increment><Offset>0</Offset></CZ>\n</Axes></Record1>\n<Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>\n{data}</Record3>\n</p:ISO5436_2>\n"
    )
}

fn write_x3p(path: &Path, xml: &str, bin: Option<&[u8]>, deflate: bool) {
    let f = std::fs::File::create(path).unwrap();
    let mut z = zip::ZipWriter::new(f);
    let opt = zip::write::SimpleFileOptions::default().compression_method(if deflate {
        zip::CompressionMethod::Deflated
    } else {
        zip::CompressionMethod::Stored
    });
    z.start_file("main.xml", opt).unwrap();
    z.write_all(xml.as_bytes()).unwrap();
    if let Some(b) = bin {
        z.start_file("bindata/data.bin", opt).unwrap();
        z.write_all(b).unwrap();
    }
    z.finish().unwrap();
}

const LINK: &str = "<DataLink><PointDataLink>bindata/data.bin</PointDataLink></DataLink>";

#[test]
fn x3p_map_and_profile() {
    let d = temp_dir("x3p");
    // Map 4 × 3, float64, deflated.
    let vals: Vec<f64> = (0..12).map(|k| (k as f64 - 5.0) * 1e-8).collect();
    let bin: Vec<u8> = vals.iter().flat_map(|v| v.to_le_bytes()).collect();
    let p = d.join("map.x3p");
    write_x3p(&p, &main_xml("SUR", 4, 3, "D", 1.0, LINK), Some(&bin), true);
    let m = read_measurement(&p, Spacing::Strict).unwrap();
    assert_eq!(m.format, Format::X3p);
    let Surface::Map(t) = m.surface else {
        panic!("not a map")
    };
    assert_eq!((t.nx(), t.ny()), (4, 3));
    assert!(close(t.dx(), 2.5e-7, 1e-15) && close(t.dy(), 5e-7, 1e-15));
    assert_eq!(t.z(1, 2), Some(vals[2 * 4 + 1]));
    // Profile, int16 with an increment, stored; detected by content under
    // another extension.
    let ints: Vec<i16> = vec![-3, 0, 7, 2, 5];
    let bin: Vec<u8> = ints.iter().flat_map(|v| v.to_le_bytes()).collect();
    let p = d.join("profile.bin");
    write_x3p(
        &p,
        &main_xml("PRF", 5, 1, "I", 1e-9, LINK),
        Some(&bin),
        false,
    );
    let m = read_measurement(&p, Spacing::Strict).unwrap();
    assert_eq!(m.format, Format::X3p);
    let Surface::Profile(q) = m.surface else {
        panic!("not a profile")
    };
    assert_eq!(q.len(), 5);
    assert!(close(q.x0(), 1e-3, 1e-15));
    assert!(close(q.heights()[2], 7e-9, 1e-12));
    // Inline data.
    let inline = "<DataList><Datum>1e-9</Datum><Datum>2e-9</Datum><Datum>4e-9</Datum></DataList>";
    let p = d.join("inline.x3p");
    write_x3p(&p, &main_xml("PRF", 3, 1, "D", 1.0, inline), None, true);
    let Surface::Profile(q) = read_measurement(&p, Spacing::Strict).unwrap().surface else {
        panic!()
    };
    assert_eq!(q.heights(), &[1e-9, 2e-9, 4e-9]);
    // Short data: the offset where it ends.
    let p = d.join("short.x3p");
    write_x3p(
        &p,
        &main_xml("SUR", 4, 3, "F", 1.0, LINK),
        Some(&[0u8; 40]),
        false,
    );
    assert_eq!(
        read_measurement(&p, Spacing::Strict).unwrap_err(),
        Error::Binary {
            what: "the point data are shorter than SizeX x SizeY values",
            offset: 40
        }
    );
    // A missing point (NaN) at value 2: byte offset 8 of float32 data.
    let mut f: Vec<u8> = Vec::new();
    for k in 0..12 {
        let v: f32 = if k == 2 { f32::NAN } else { k as f32 };
        f.extend_from_slice(&v.to_le_bytes());
    }
    let p = d.join("nan.x3p");
    write_x3p(&p, &main_xml("SUR", 4, 3, "F", 1.0, LINK), Some(&f), false);
    assert!(matches!(
        read_measurement(&p, Spacing::Strict),
        Err(Error::Binary { offset: 8, .. })
    ));
    // Not a zip, and a zip without main.xml.
    let p = d.join("junk.x3p");
    std::fs::write(&p, b"PK\x03\x04 not really").unwrap();
    assert!(matches!(
        read_measurement(&p, Spacing::Strict),
        Err(Error::Binary { offset: 0, .. })
    ));
    let p = d.join("empty.x3p");
    {
        let mut z = zip::ZipWriter::new(std::fs::File::create(&p).unwrap());
        z.start_file("other.txt", zip::write::SimpleFileOptions::default())
            .unwrap();
        z.finish().unwrap();
    }
    let e = read_measurement(&p, Spacing::Strict).unwrap_err();
    assert!(e.to_string().contains("main.xml"), "{e}");
    std::fs::remove_dir_all(&d).ok();
}

// ---------------------------------------------------------- dispatch

#[test]
fn detection_by_extension_and_content() {
    let d = temp_dir("detect");
    let cases: Vec<(&str, Vec<u8>, Format)> = vec![
        ("a.hfm", HFM.as_bytes().to_vec(), Format::Hfm),
        ("a.txt", HFM.as_bytes().to_vec(), Format::Hfm),
        (
            "a.csv",
            dektak("0.0,1,,\n0.2,2,,\n0.3,3,,\n").into_bytes(),
            Format::DektakCsv,
        ),
        (
            "a.di",
            nanoscope(2, 2, 2, &[1, 2, 3, 4], "Z scale"),
            Format::Nanoscope,
        ),
        (
            "a.001",
            nanoscope(2, 2, 2, &[1, 2, 3, 4], "Z scale"),
            Format::Nanoscope,
        ),
        (
            "a.data",
            nanoscope(2, 2, 2, &[1, 2, 3, 4], "Z scale"),
            Format::Nanoscope,
        ),
        (
            "a.csv",
            b"x_m,z_m\n0,1\n1e-6,2\n2e-6,0\n".to_vec(),
            Format::Text,
        ),
        (
            "m.csv",
            b"# dx_m=1e-6\n1,2,3\n4,5,6\n".to_vec(),
            Format::Text,
        ),
    ];
    for (name, bytes, format) in cases {
        let p = d.join(name);
        std::fs::write(&p, &bytes).unwrap();
        assert_eq!(detect_format(&p, &bytes), format, "{name}");
        let m = read_measurement(&p, Spacing::Tolerant).unwrap();
        assert_eq!(m.format, format, "{name}");
        let is_map = matches!(m.surface, Surface::Map(_));
        assert_eq!(
            is_map,
            matches!(name, "m.csv" | "a.di" | "a.001" | "a.data"),
            "{name}"
        );
    }
    assert_eq!(Format::DektakCsv.name(), "dektak-csv");
    assert!(matches!(
        read_measurement(d.join("missing.x3p"), Spacing::Strict),
        Err(Error::Io { .. })
    ));
    std::fs::remove_dir_all(&d).ok();
}

// ---------------------------------------------------------- robustness

#[test]
fn hostile_headers_are_errors_not_panics() {
    // Sizes that overflow or exceed the file.
    let huge = String::from_utf8_lossy(&nanoscope(3, 2, 2, &[0; 6], "Z scale"))
        .replace("Samps/line: 3", "Samps/line: 99999999999999999999")
        .into_bytes();
    assert!(matches!(parse_nanoscope(&huge), Err(Error::Binary { .. })));
    let far = String::from_utf8_lossy(&nanoscope(3, 2, 2, &[0; 6], "Z scale"))
        .replace("Data offset: 2048", "Data offset: 1e30")
        .into_bytes();
    assert!(parse_nanoscope(&far).is_err());
    // A Dektak preamble with multi-byte characters before the data header.
    let t = dektak("0.0,1,,\n0.2,2,,\n0.3,3,,\n").replace("Scan Type", "Résolution µm");
    assert_eq!(parse_dektak_csv(&t, Spacing::Tolerant).unwrap().len(), 3);
    // X3P with an absurd size: no allocation, an error.
    let d = temp_dir("hostile");
    let p = d.join("big.x3p");
    let xml = main_xml("SUR", 4, 3, "D", 1.0, LINK)
        .replace("<SizeX>4</SizeX>", "<SizeX>9000000000000000000</SizeX>");
    write_x3p(&p, &xml, Some(&[0u8; 96]), false);
    assert!(read_measurement(&p, Spacing::Strict).is_err());
    std::fs::remove_dir_all(&d).ok();
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..600)) {
        let _ = parse_nanoscope(&bytes);
        let _ = parse_x3p(&bytes);
        let text = String::from_utf8_lossy(&bytes);
        let _ = parse_hfm(&text, Spacing::Tolerant);
        let _ = parse_dektak_csv(&text, Spacing::Tolerant);
        // Mutations of valid files.
        let mut di = nanoscope(3, 2, 2, &[1, 2, 3, 4, 5, 6], "Z scale");
        for (k, b) in bytes.iter().enumerate().take(64) {
            let i = (k * 37 + *b as usize * 11) % di.len();
            di[i] = *b;
        }
        let _ = parse_nanoscope(&di);
    }
}
