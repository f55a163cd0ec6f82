//! Readers for instrument files: X3P (ISO 25178-72), Bruker/Veeco/Digital
//! Instruments Nanoscope (`.di`, `.spm`, `.001`…), Bruker Dektak CSV
//! exports, Jenoptik/Hommel `.hfm` text profiles, and the plain text of
//! [`super::read`]; [`read_measurement`] picks the reader by extension or
//! content. All heights and positions come out in metres.
//!
//! Formats (what is read; everything else in the files is ignored):
//!
//! * **X3P** (ISO 25178-72, the open format of ISO 5436-2): a zip archive
//!   with `main.xml` and the binary point data. Read: `FeatureType` (`PRF`
//!   profile or `SUR` map), the axes `CX`, `CY` (`AxisType` `I`,
//!   incremental: `Increment` is the spacing in m, `Offset` the origin) and
//!   `CZ` (`DataType` `I` int16, `L` int32, `F` float32, `D` float64; z =
//!   `Offset` + `Increment`·value, each defaulting to 0 and 1),
//!   `MatrixDimension` `SizeX`, `SizeY`, and the data as the archive member
//!   named by `PointDataLink` (little-endian, x fastest) or as inline
//!   `DataList`/`Datum` values. Missing points (NaN, or a `ValidPointsLink`
//!   mask) are refused: the analyses here need complete grids.
//! * **Nanoscope** (Digital Instruments / Veeco / Bruker AFM): a text header
//!   of `\*Section` and `\Key: value` lines ending at `\*File list end`, then
//!   the images as little-endian 16- or 32-bit integers. Of the
//!   `\*Ciao image list` sections the first whose Z scale has a length unit
//!   is read: `\Samps/line` (nx), `\Number of lines` (ny), `\Scan Size`
//!   (x and y size and unit, `~m` = µm), `\Data offset`, `\Data length`,
//!   `\Bytes/pixel`, and `\@2:Z scale: V [Quantity] (… V/LSB) H V`; the soft
//!   scale `\@Quantity: V S nm/V` of the scanner list (`\*Scanner list` or
//!   `\*Ciao scan list`). Height = value · (H/65536) · S (·1/65536 for
//!   32-bit data, which span the 16-bit range times 65536), dx = x size/nx.
//!   Lines are stored from the top of the image; row j of the map is
//!   y_j = j·dy from the bottom (the orientation of Gwyddion and
//!   SurfaceTopography, and of `afm_dimension_icon_di3_zsensor_map.csv`).
//! * **Dektak CSV** (Bruker Dektak stylus profilometers): sections of
//!   `key,value` lines; the data follow the column header
//!   `Lateral <unit>,<Raw|Normal|…> <unit>,` as `x,z,,` lines up to a blank
//!   line or the end. Units: `um`/`µm`/`Micrometer`, `nm`/`Nanometer`,
//!   `mm`/`Millimeter`, `A`/`Å`/`Angstrom`, `m`.
//! * **HFM** (Jenoptik/Hommelwerke stylus profiles, as text): a line of
//!   column names `X;Y;valid`, a line of units `[mm];[mm];[1/0]`, then
//!   `x;z;valid` lines (`;`-separated). A point flagged invalid (0) is
//!   refused.
//!
//! Positions of the text formats are placed on the least-squares uniform
//! grid and checked by [`Spacing`] as in [`super::read`].
//!
//! Errors name the line ([`Error::Parse`]) of a text file or header, or the
//! byte offset ([`Error::Binary`]) in a binary file or archive member.
//!
//! # Formulas
//!
//! No physics. Nanoscope heights: $z = v\\,\frac{H}{65536}\\,S\\,b$ with
//! $b = 1$ for 16-bit and $b = 1/65536$ for 32-bit data; X3P heights
//! $z = o_z + \Delta_z v$.
//!
//! # References
//!
//! * ISO 25178-72:2017, *Geometrical product specifications (GPS) — Surface
//!   texture: Areal — Part 72: XML file format x3p*; ISO 5436-2:2012.
//! * Digital Instruments, *Nanoscope file format* (header keys, soft and
//!   hard scales), as documented with the Nanoscope software and by
//!   S. Manne's notes (University of Arizona).
//! * The test data of ContactEngineering/SurfaceTopography (MIT): the
//!   Dektak CSV and HFM layouts of `dektak-1.csv` and `hfm-1.hfm`.

use super::read::{parse_profile, parse_topography, uniform_grid};
use super::{Profile, Spacing, Topography};
use crate::error::{Error, Result};
use std::io::Read;
use std::path::Path;

/// The file formats [`read_measurement`] knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Plain text: `x z` line scans or gridded / `x y z` maps ([`super::read`]).
    Text,
    /// X3P, ISO 25178-72.
    X3p,
    /// Bruker/Veeco/Digital Instruments Nanoscope.
    Nanoscope,
    /// Bruker Dektak CSV export.
    DektakCsv,
    /// Jenoptik/Hommel `.hfm` text.
    Hfm,
}

impl Format {
    /// Short name (`"x3p"`, `"nanoscope"`, `"dektak-csv"`, `"hfm"`, `"text"`).
    pub fn name(self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::X3p => "x3p",
            Format::Nanoscope => "nanoscope",
            Format::DektakCsv => "dektak-csv",
            Format::Hfm => "hfm",
        }
    }
}

/// A line scan or a map.
#[derive(Debug, Clone, PartialEq)]
pub enum Surface {
    /// A line scan.
    Profile(Profile),
    /// A height map.
    Map(Topography),
}

/// What [`read_measurement`] read.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    /// The format the file was read as.
    pub format: Format,
    /// The channel read, where the format has several (Nanoscope: the image
    /// data name, e.g. `ZSensor`).
    pub channel: Option<String>,
    /// The data, in metres.
    pub surface: Surface,
}

/// Metres per unit of a length unit name (case-insensitive; `~m` is the
/// Nanoscope spelling of µm, brackets are ignored).
fn metres_per(unit: &str) -> Option<f64> {
    let u = unit.trim().trim_matches(|c| c == '[' || c == ']').trim();
    let l = u.to_ascii_lowercase();
    Some(match l.as_str() {
        "m" | "meter" | "meters" | "metre" | "metres" => 1.0,
        "mm" | "millimeter" | "millimeters" | "millimetre" => 1e-3,
        "um" | "~m" | "micrometer" | "micrometers" | "micrometre" | "micron" | "microns" => 1e-6,
        "nm" | "nanometer" | "nanometers" | "nanometre" => 1e-9,
        "pm" | "picometer" | "picometers" => 1e-12,
        "a" | "angstrom" | "angstroms" => 1e-10,
        _ => match u {
            "µm" | "μm" => 1e-6,
            "Å" => 1e-10,
            _ => return None,
        },
    })
}

// ------------------------------------------------------------------- HFM

/// A profile from Hommel `.hfm` text; see the module docs.
///
/// Errors: [`Error::Parse`] with the line for a missing `X;Y` header or
/// unit line, an unknown unit, a malformed or invalid-flagged data line,
/// fewer than two points; [`Error::InvalidArgument`] `x` for non-uniform
/// positions (per `spacing`).
pub fn parse_hfm(text: &str, spacing: Spacing) -> Result<Profile> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i as u64 + 1, l));
    let (_, names) = lines.next().ok_or(Error::Parse {
        what: "empty .hfm file",
        line: 0,
    })?;
    let names: Vec<&str> = names.split(';').map(str::trim).collect();
    if names.len() < 2 || !names[0].eq_ignore_ascii_case("x") || !names[1].eq_ignore_ascii_case("y")
    {
        return Err(Error::Parse {
            what: "expected the .hfm column names `X;Y[;valid]`",
            line: 1,
        });
    }
    let has_flag = names.len() >= 3;
    let (_, units) = lines.next().ok_or(Error::Parse {
        what: "expected the .hfm unit line `[mm];[mm];[1/0]`",
        line: 2,
    })?;
    let units: Vec<&str> = units.split(';').map(str::trim).collect();
    let unknown = Error::Parse {
        what: "unknown length unit in the .hfm unit line (expected e.g. `[mm]`)",
        line: 2,
    };
    let sx = units.first().and_then(|u| metres_per(u)).ok_or(unknown)?;
    let sz = units.get(1).and_then(|u| metres_per(u)).ok_or(unknown)?;
    let (mut xs, mut zs, mut nums) = (Vec::new(), Vec::new(), Vec::new());
    for (line, l) in lines {
        let l = l.trim();
        if l.is_empty() {
            continue;
        }
        let f: Vec<&str> = l.split(';').map(str::trim).collect();
        if f.len() != names.len() {
            return Err(Error::Parse {
                what: "a .hfm data line must have as many fields as the header",
                line,
            });
        }
        let mut v = [0.0; 3];
        for (k, s) in f.iter().take(3).enumerate() {
            v[k] = s
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or(Error::Parse {
                    what: "expected finite numbers x;z;valid",
                    line,
                })?;
        }
        if has_flag && v[2] != 1.0 {
            return Err(Error::Parse {
                what: "point flagged invalid (valid != 1): profiles with gaps are not supported",
                line,
            });
        }
        xs.push(v[0] * sx);
        zs.push(v[1] * sz);
        nums.push(line);
    }
    if xs.len() < 2 {
        return Err(Error::Parse {
            what: "a profile needs at least two data lines",
            line: 0,
        });
    }
    let (x0, dx, dev) = uniform_grid(&xs, &nums, spacing)?;
    Ok(Profile::new(dx, zs)?
        .with_origin(x0)?
        .with_spacing_deviation(dev))
}

// ------------------------------------------------------------ Dektak CSV

/// A profile from a Bruker Dektak CSV export; see the module docs.
///
/// Errors: [`Error::Parse`] with the line for a missing `Lateral` column
/// header, unknown units, malformed data lines, fewer than two points;
/// [`Error::InvalidArgument`] `x` for non-uniform positions.
pub fn parse_dektak_csv(text: &str, spacing: Spacing) -> Result<Profile> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i as u64 + 1, l));
    let mut units = None;
    for (line, l) in lines.by_ref() {
        let mut f = l.split(',').map(str::trim);
        let first = f.next().unwrap_or("");
        // `get` (not indexing): a non-ASCII field must not split a character.
        if first
            .get(..7)
            .is_some_and(|h| h.eq_ignore_ascii_case("lateral"))
        {
            let bad = Error::Parse {
                what: "unknown unit in the Dektak `Lateral <unit>,<kind> <unit>` header",
                line,
            };
            let ux = metres_per(first[7..].trim()).ok_or(bad)?;
            let uz = f
                .next()
                .and_then(|s| s.split_whitespace().last())
                .and_then(metres_per)
                .ok_or(bad)?;
            units = Some((ux, uz));
            break;
        }
    }
    let (ux, uz) = units.ok_or(Error::Parse {
        what: "no `Lateral <unit>,…` column header (the Dektak CSV `Scan Data` section)",
        line: 0,
    })?;
    let (mut xs, mut zs, mut nums) = (Vec::new(), Vec::new(), Vec::new());
    for (line, l) in lines {
        if l.trim().is_empty() {
            if xs.is_empty() {
                continue;
            }
            break;
        }
        let mut f = l.split(',').map(str::trim);
        let mut num = || -> Result<f64> {
            f.next()
                .and_then(|s| s.parse::<f64>().ok())
                .filter(|v| v.is_finite())
                .ok_or(Error::Parse {
                    what: "expected a Dektak data line `x,z` of finite numbers",
                    line,
                })
        };
        let (x, z) = (num()?, num()?);
        xs.push(x * ux);
        zs.push(z * uz);
        nums.push(line);
    }
    if xs.len() < 2 {
        return Err(Error::Parse {
            what: "a profile needs at least two data lines",
            line: 0,
        });
    }
    let (x0, dx, dev) = uniform_grid(&xs, &nums, spacing)?;
    Ok(Profile::new(dx, zs)?
        .with_origin(x0)?
        .with_spacing_deviation(dev))
}

// -------------------------------------------------------------- Nanoscope

/// A Nanoscope header entry: key (lower case), value, 1-based line.
type DiEntry = (String, String, u64);

/// The header value of `key` (lower case) in a section's entries.
fn di_get<'a>(sec: &'a [DiEntry], key: &str) -> Option<(&'a str, u64)> {
    sec.iter()
        .find(|(k, _, _)| k == key)
        .map(|(_, v, l)| (v.as_str(), *l))
}

/// A height map from a Nanoscope file's bytes, with its channel name; see
/// the module docs.
///
/// Errors: [`Error::Parse`] with the header line for a missing or malformed
/// key, no height channel; [`Error::Binary`] with the byte offset when the
/// data block lies outside the file or has an unsupported pixel size.
pub fn parse_nanoscope(bytes: &[u8]) -> Result<(Topography, String)> {
    // Header: latin-1 lines up to `\*File list end`.
    let mut sections: Vec<(String, Vec<DiEntry>)> = Vec::new();
    let mut pos = 0usize;
    let mut line = 0u64;
    let mut ended = false;
    while pos < bytes.len() {
        let end = bytes[pos..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |k| pos + k);
        let raw: String = bytes[pos..end].iter().map(|&b| b as char).collect();
        pos = end + 1;
        line += 1;
        let l = raw.trim();
        if l.is_empty() {
            continue;
        }
        if l.eq_ignore_ascii_case("\\*file list end") {
            ended = true;
            break;
        }
        if let Some(name) = l.strip_prefix("\\*") {
            if sections.is_empty() && !name.eq_ignore_ascii_case("file list") {
                return Err(Error::Parse {
                    what: "a Nanoscope header starts with `\\*File list`",
                    line,
                });
            }
            sections.push((name.to_ascii_lowercase(), Vec::new()));
        } else if let Some(kv) = l.strip_prefix('\\') {
            let Some((_, sec)) = sections.last_mut() else {
                return Err(Error::Parse {
                    what: "a Nanoscope header starts with `\\*File list`",
                    line,
                });
            };
            // Keys may hold colons (`@2:Z scale`): the value follows ": ".
            let (k, v) = kv
                .split_once(": ")
                .unwrap_or((kv.strip_suffix(':').unwrap_or(kv), ""));
            sec.push((k.trim().to_ascii_lowercase(), v.trim().to_string(), line));
        } else {
            return Err(Error::Parse {
                what: "Nanoscope header lines start with a backslash",
                line,
            });
        }
    }
    if !ended {
        return Err(Error::Parse {
            what: "no `\\*File list end` line: not a Nanoscope file, or a truncated header",
            line: 0,
        });
    }
    let scanner: Vec<DiEntry> = sections
        .iter()
        .filter(|(n, _)| n == "scanner list" || n == "ciao scan list")
        .flat_map(|(_, s)| s.iter().cloned())
        .collect();
    let num = |sec: &[DiEntry], key: &str, what: &'static str| -> Result<f64> {
        let (v, l) = di_get(sec, key).ok_or(Error::Parse { what, line: 0 })?;
        v.split_whitespace()
            .next()
            .and_then(|t| t.parse::<f64>().ok())
            .filter(|x| x.is_finite())
            .ok_or(Error::Parse { what, line: l })
    };
    for (_, img) in sections.iter().filter(|(n, _)| n == "ciao image list") {
        // \@2:Z scale: V [Quantity] (0.000375 V/LSB) 24.57 V
        let Some((zs, zl)) = di_get(img, "@2:z scale") else {
            continue;
        };
        let bad_z = Error::Parse {
            what: "malformed `\\@2:Z scale: V [quantity] (… V/LSB) value unit`",
            line: zl,
        };
        let quantity = zs
            .find('[')
            .and_then(|a| zs[a + 1..].find(']').map(|b| &zs[a + 1..a + 1 + b]));
        let after = zs.rfind(')').map(|k| &zs[k + 1..]).ok_or(bad_z)?;
        let mut t = after.split_whitespace();
        let hard: f64 = t.next().and_then(|v| v.parse().ok()).ok_or(bad_z)?;
        let hard_unit = t.next().unwrap_or("V");
        let Some(q) = quantity else { continue };
        let key = format!("@{}", q.to_ascii_lowercase());
        let Some((soft, sl)) = di_get(&scanner, &key) else {
            continue;
        };
        // "V 790.3658 nm/V"
        let mut s = soft.split_whitespace().skip(1);
        let bad_s = Error::Parse {
            what: "malformed soft scale `\\@quantity: V value unit/V`",
            line: sl,
        };
        let sv: f64 = s.next().and_then(|v| v.parse().ok()).ok_or(bad_s)?;
        let Some((num_u, den_u)) = s.next().and_then(|u| u.split_once('/')) else {
            continue;
        };
        let Some(zu) = metres_per(num_u) else {
            continue; // not a height channel
        };
        if den_u != hard_unit {
            return Err(Error::Parse {
                what: "soft scale and hard scale units differ",
                line: sl,
            });
        }
        let nx = num(img, "samps/line", "missing or malformed `\\Samps/line`")?;
        let ny = num(
            img,
            "number of lines",
            "missing or malformed `\\Number of lines`",
        )?;
        let offset = num(img, "data offset", "missing or malformed `\\Data offset`")?;
        let length = num(img, "data length", "missing or malformed `\\Data length`")?;
        let bpp = match di_get(img, "bytes/pixel") {
            Some(_) => num(img, "bytes/pixel", "malformed `\\Bytes/pixel`")?,
            None => 2.0,
        };
        let (size, size_l) = di_get(img, "scan size").ok_or(Error::Parse {
            what: "missing `\\Scan Size`",
            line: 0,
        })?;
        let bad_size = Error::Parse {
            what: "malformed `\\Scan Size: x y unit`",
            line: size_l,
        };
        let tok: Vec<&str> = size.split_whitespace().collect();
        let (sx, sy, su) = match tok.as_slice() {
            [a, b, u] => (a.parse::<f64>(), b.parse::<f64>(), *u),
            [a, u] => (a.parse::<f64>(), a.parse::<f64>(), *u),
            _ => return Err(bad_size),
        };
        let (sx, sy) = match (sx, sy) {
            (Ok(a), Ok(b)) if a > 0.0 && b > 0.0 => (a, b),
            _ => return Err(bad_size),
        };
        let xu = metres_per(su).ok_or(bad_size)?;
        if nx < 2.0 || ny < 2.0 || nx.fract() != 0.0 || ny.fract() != 0.0 {
            return Err(Error::Parse {
                what: "`\\Samps/line` and `\\Number of lines` must be integers >= 2",
                line: 0,
            });
        }
        let (nx, ny) = (nx as usize, ny as usize);
        let (bpp, offset, length) = (bpp as usize, offset as usize, length as usize);
        let scale = match bpp {
            2 => 1.0,
            4 => 1.0 / 65536.0,
            _ => {
                return Err(Error::Binary {
                    what: "Nanoscope data must have 2 or 4 bytes per pixel",
                    offset: offset as u64,
                })
            }
        };
        let too_big = Error::Binary {
            what: "Samps/line x Number of lines x Bytes/pixel exceeds the file",
            offset: offset as u64,
        };
        let need = nx
            .checked_mul(ny)
            .and_then(|v| v.checked_mul(bpp))
            .filter(|&v| v <= bytes.len())
            .ok_or(too_big)?;
        if need > length {
            return Err(Error::Binary {
                what: "`\\Data length` is shorter than Samps/line x Number of lines x Bytes/pixel",
                offset: offset as u64,
            });
        }
        if offset
            .checked_add(need)
            .map_or(true, |end| end > bytes.len())
        {
            return Err(Error::Binary {
                what: "the data block runs past the end of the file",
                offset: bytes.len() as u64,
            });
        }
        let factor = hard / 65536.0 * sv * zu * scale;
        let data = &bytes[offset..offset + need];
        let value = |k: usize| -> f64 {
            let b = &data[k * bpp..(k + 1) * bpp];
            if bpp == 2 {
                i16::from_le_bytes([b[0], b[1]]) as f64
            } else {
                i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64
            }
        };
        let mut h = vec![0.0; nx * ny];
        for j in 0..ny {
            let stored = ny - 1 - j;
            for i in 0..nx {
                h[j * nx + i] = value(stored * nx + i) * factor;
            }
        }
        let name = di_get(img, "@2:image data")
            .and_then(|(v, _)| {
                v.find('[').and_then(|a| {
                    v[a + 1..]
                        .find(']')
                        .map(|b| v[a + 1..a + 1 + b].to_string())
                })
            })
            .unwrap_or_else(|| q.to_string());
        let t = Topography::new(nx, ny, sx * xu / nx as f64, sy * xu / ny as f64, h)?;
        return Ok((t, name));
    }
    Err(Error::Parse {
        what: "no image with a length-unit Z scale (a height channel) in the Nanoscope header",
        line: 0,
    })
}

// -------------------------------------------------------------------- X3P

/// The text between `<name …>` and `</name>` in `xml` (first occurrence).
fn xml_tag<'a>(xml: &'a str, name: &str) -> Option<&'a str> {
    let open = format!("<{name}");
    let mut from = 0;
    while let Some(k) = xml[from..].find(&open) {
        let a = from + k + open.len();
        let next = xml[a..].chars().next()?;
        if next == '>' || next == '/' || next.is_whitespace() {
            let body = a + xml[a..].find('>')? + 1;
            if xml[a..body].ends_with("/>") {
                return Some("");
            }
            let close = format!("</{name}>");
            let end = body + xml[body..].find(&close)?;
            return Some(&xml[body..end]);
        }
        from = a;
    }
    None
}

fn xml_num(xml: &str, name: &str) -> Option<f64> {
    xml_tag(xml, name).and_then(|v| v.trim().parse::<f64>().ok())
}

const X3P_ZIP: &str = "not a zip archive (an X3P file is a zip archive holding main.xml)";

/// A profile or map from the bytes of an X3P file; see the module docs.
///
/// Errors: [`Error::Binary`] with the byte offset for a damaged archive,
/// short point data or missing points; [`Error::Parse`] for `main.xml`
/// without the needed elements (line 0: the document as a whole).
pub fn parse_x3p(bytes: &[u8]) -> Result<Surface> {
    let mut zip = zip::ZipArchive::new(std::io::Cursor::new(bytes)).map_err(|_| Error::Binary {
        what: X3P_ZIP,
        offset: 0,
    })?;
    let mut member = |name: &str, what: &'static str| -> Result<Vec<u8>> {
        let mut f = zip
            .by_name(name)
            .map_err(|_| Error::Parse { what, line: 0 })?;
        let start = f.data_start();
        let mut v = Vec::new();
        f.read_to_end(&mut v).map_err(|_| Error::Binary {
            what: "cannot decompress the archive member (damaged or unsupported compression)",
            offset: start,
        })?;
        Ok(v)
    };
    let xml = member("main.xml", "the X3P archive has no main.xml")?;
    let xml = String::from_utf8(xml).map_err(|e| Error::Binary {
        what: "main.xml is not UTF-8 text",
        offset: e.utf8_error().valid_up_to() as u64,
    })?;
    let missing = |what: &'static str| Error::Parse { what, line: 0 };
    let axes = xml_tag(&xml, "Axes").ok_or(missing("main.xml: no <Axes>"))?;
    let cx = xml_tag(axes, "CX").ok_or(missing("main.xml: no <CX> axis"))?;
    let cy = xml_tag(axes, "CY").ok_or(missing("main.xml: no <CY> axis"))?;
    let cz = xml_tag(axes, "CZ").ok_or(missing("main.xml: no <CZ> axis"))?;
    for c in [cx, cy] {
        if xml_tag(c, "AxisType").map(str::trim) == Some("A") {
            return Err(missing(
                "main.xml: absolute x/y axes (AxisType A) are not supported, only incremental (I)",
            ));
        }
    }
    let dx = xml_num(cx, "Increment").ok_or(missing("main.xml: no <CX><Increment>"))?;
    let x0 = xml_num(cx, "Offset").unwrap_or(0.0);
    let dy = xml_num(cy, "Increment").unwrap_or(dx);
    let dz = xml_num(cz, "Increment").unwrap_or(1.0);
    let z0 = xml_num(cz, "Offset").unwrap_or(0.0);
    let dim = xml_tag(&xml, "MatrixDimension").ok_or(missing("main.xml: no <MatrixDimension>"))?;
    let size = |n: &str| xml_num(dim, n).filter(|v| *v >= 1.0 && v.fract() == 0.0);
    let nx = size("SizeX").ok_or(missing("main.xml: no valid <SizeX>"))? as usize;
    let ny = size("SizeY").ok_or(missing("main.xml: no valid <SizeY>"))? as usize;
    let nz = size("SizeZ").unwrap_or(1.0) as usize;
    if nz != 1 {
        return Err(missing(
            "main.xml: SizeZ > 1 (several layers) is not supported",
        ));
    }
    let n = nx
        .checked_mul(ny)
        .ok_or(missing("main.xml: SizeX x SizeY too large"))?;
    let mut z = Vec::new();
    if let Some(link) = xml_tag(&xml, "PointDataLink") {
        let name = link.trim().to_string();
        let data = member(
            &name,
            "the X3P archive lacks the member named by <PointDataLink>",
        )?;
        let (w, ty) = match xml_tag(cz, "DataType").map(str::trim) {
            Some("I") => (2, 'I'),
            Some("L") => (4, 'L'),
            Some("F") => (4, 'F'),
            Some("D") | None => (8, 'D'),
            Some(_) => return Err(missing("main.xml: <CZ><DataType> must be I, L, F or D")),
        };
        if n.checked_mul(w).map_or(true, |need| data.len() < need) {
            return Err(Error::Binary {
                what: "the point data are shorter than SizeX x SizeY values",
                offset: data.len() as u64,
            });
        }
        for k in 0..n {
            let b = &data[k * w..(k + 1) * w];
            let v = match ty {
                'I' => i16::from_le_bytes([b[0], b[1]]) as f64,
                'L' => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                'F' => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                _ => f64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]),
            };
            if !v.is_finite() {
                return Err(Error::Binary {
                    what: "missing point (NaN) in the X3P data: incomplete grids are not supported",
                    offset: (k * w) as u64,
                });
            }
            z.push(z0 + dz * v);
        }
        if xml_tag(&xml, "ValidPointsLink").is_some_and(|v| !v.trim().is_empty()) {
            return Err(missing(
                "main.xml: a <ValidPointsLink> mask (missing points) is not supported",
            ));
        }
    } else if let Some(list) = xml_tag(&xml, "DataList") {
        for d in list.split("<Datum>").skip(1) {
            let v = d.split("</Datum>").next().unwrap_or("").trim();
            let v: f64 = v.parse().map_err(|_| {
                missing("main.xml: a <Datum> is not a number (missing points are not supported)")
            })?;
            z.push(z0 + dz * v);
        }
        if z.len() != n {
            return Err(missing(
                "main.xml: the number of <Datum> values differs from SizeX x SizeY",
            ));
        }
    } else {
        return Err(missing("main.xml: neither <PointDataLink> nor <DataList>"));
    }
    let profile = ny == 1 || xml_tag(&xml, "FeatureType").map(str::trim) == Some("PRF");
    if profile {
        if ny != 1 {
            return Err(missing("main.xml: FeatureType PRF with SizeY > 1"));
        }
        Ok(Surface::Profile(Profile::new(dx, z)?.with_origin(x0)?))
    } else {
        Ok(Surface::Map(Topography::new(nx, ny, dx, dy, z)?))
    }
}

// -------------------------------------------------------------- dispatch

/// The format of a file, from its extension, else from its first bytes.
pub fn detect_format(path: &Path, bytes: &[u8]) -> Format {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    match ext.as_str() {
        "x3p" => return Format::X3p,
        "hfm" => return Format::Hfm,
        "di" | "spm" => return Format::Nanoscope,
        e if e.len() == 3 && e.bytes().all(|b| b.is_ascii_digit()) => return Format::Nanoscope,
        _ => {}
    }
    if bytes.starts_with(b"PK\x03\x04") {
        return Format::X3p;
    }
    let head: String = bytes.iter().take(4096).map(|&b| b as char).collect();
    let first = head
        .lines()
        .next()
        .unwrap_or("")
        .trim()
        .to_ascii_lowercase();
    if first.starts_with("\\*file list") {
        Format::Nanoscope
    } else if first.starts_with("x;y") {
        Format::Hfm
    } else if head
        .lines()
        .any(|l| l.trim_start().to_ascii_lowercase().starts_with("lateral "))
        || first == "scan parameters"
    {
        Format::DektakCsv
    } else {
        Format::Text
    }
}

fn text(bytes: &[u8]) -> Result<&str> {
    std::str::from_utf8(bytes).map_err(|e| Error::Binary {
        what: "cannot read the file as UTF-8 text (nor as a known binary format)",
        offset: e.valid_up_to() as u64,
    })
}

/// Reads a measured profile or map in any known format ([`detect_format`]):
/// the bytes of `path` go to [`parse_x3p`], [`parse_nanoscope`],
/// [`parse_dektak_csv`], [`parse_hfm`], or, for plain text, to
/// [`parse_topography`] (a map) and else [`parse_profile`]. `spacing`
/// applies to the positions of the text formats.
///
/// Errors: [`Error::Io`] when the file cannot be read, then those of the
/// reader (for plain text that is neither a map nor a profile, the profile
/// reader's).
pub fn read_measurement(path: impl AsRef<Path>, spacing: Spacing) -> Result<Measurement> {
    let path = path.as_ref();
    let bytes = std::fs::read(path).map_err(|e| Error::Io {
        what: "measurement file",
        kind: e.kind(),
    })?;
    parse_measurement(path, &bytes, spacing)
}

/// [`read_measurement`] on bytes already read; `path` only chooses the
/// format by its extension.
pub fn parse_measurement(path: &Path, bytes: &[u8], spacing: Spacing) -> Result<Measurement> {
    let format = detect_format(path, bytes);
    let (surface, channel) = match format {
        Format::X3p => (parse_x3p(bytes)?, None),
        Format::Nanoscope => {
            let (t, name) = parse_nanoscope(bytes)?;
            (Surface::Map(t), Some(name))
        }
        Format::DektakCsv => (
            Surface::Profile(parse_dektak_csv(text(bytes)?, spacing)?),
            None,
        ),
        Format::Hfm => (Surface::Profile(parse_hfm(text(bytes)?, spacing)?), None),
        Format::Text => {
            let t = text(bytes)?;
            match parse_topography(t, spacing) {
                Ok(m) => (Surface::Map(m), None),
                Err(_) => (Surface::Profile(parse_profile(t, spacing)?), None),
            }
        }
    };
    Ok(Measurement {
        format,
        channel,
        surface,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_and_tags() {
        assert_eq!(metres_per("[mm]"), Some(1e-3));
        assert_eq!(metres_per("~m"), Some(1e-6));
        assert_eq!(metres_per("µm"), Some(1e-6));
        assert_eq!(metres_per("Micrometer"), Some(1e-6));
        assert_eq!(metres_per("Å"), Some(1e-10));
        assert_eq!(metres_per("V"), None);
        let x = "<A><CX><Increment>2</Increment></CX><CXY>no</CXY><Empty/></A>";
        assert_eq!(xml_tag(x, "CX"), Some("<Increment>2</Increment>"));
        assert_eq!(xml_num(x, "Increment"), Some(2.0));
        assert_eq!(xml_tag(x, "Empty"), Some(""));
        assert_eq!(xml_tag(x, "CXY"), Some("no"));
        assert_eq!(xml_tag(x, "Missing"), None);
    }
}
