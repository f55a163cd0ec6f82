//! Text readers for line scans and height maps.
//!
//! Accepted text, for every reader:
//! * fields separated by commas, semicolons or whitespace (any mix);
//! * `#` starts a comment that runs to the end of the line; blank lines are
//!   skipped;
//! * one header line of column names (e.g. `x_m,z_m`) is allowed before the
//!   first data line;
//! * all numbers in metres (SI); no unit conversion is done.
//!
//! Formats:
//! * **profile**: two columns `x z` per line (the line scans of
//!   `shared/data/profiles`, or any `x,z` export);
//! * **map, gridded**: `#` metadata lines `key=value` with at least `dx_m`
//!   (and `dy_m`, default `dx_m`; optional `nx`, `ny` are cross-checked),
//!   then one line per y index `j` holding `nx` heights z(x_i, y_j) — the
//!   layout of `afm_dimension_icon_di3_zsensor_map.csv`;
//! * **map, triplets**: three columns `x y z` per line, in any order, forming a
//!   complete uniform grid.
//!
//! Positions must be uniformly spaced (every analysis here assumes a uniform
//! grid). Instruments round positions, so the check has a tolerance chosen by
//! [`Spacing`].
//!
//!
//! # Formulas
//!
//! No physics: the readers fit a uniform grid $x_0 + j\\,dx$ to the positions
//! and check $\lvert x_j - (x_0 + j\\,dx)\rvert \le \tau\\,dx$, with $\tau$ chosen
//! by [`Spacing`] ($10^{-3}$ strict, $0.5$ by default).
//!
//! # References
//!
//! * No external source: the formats are those of common profilometer and AFM
//!   exports (for example `x,z` line scans and gridded height maps).

use super::{Profile, Topography};
use crate::error::{Error, Result};
use std::path::Path;

/// How strictly measured positions must follow a uniform grid. The grid is
/// the least-squares line x_j ≈ x_0 + j·dx through all positions (so the
/// rounding of the end points does not set the spacing); the check is on the
/// largest deviation of a position from that grid, max_j |x_j − x_0 − j·dx|,
/// relative to dx. Positions must also strictly increase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Spacing {
    /// Deviation ≤ 10⁻³·dx: only the decimal rounding of an exported position
    /// is accepted (the Hommel, opdx-3 and AFM files pass, with deviations
    /// below 10⁻⁵·dx).
    Strict,
    /// Deviation ≤ 0.5·dx and every step between 0.5·dx and 1.5·dx (the
    /// default): every sample stays nearer its own grid point than a
    /// neighbour's, so placing the heights on the uniform grid never reorders
    /// or merges samples. Needed for
    /// `dektak1_stylus_linescan.csv`, whose x values the instrument rounded to
    /// 0.1 µm although the true spacing is 0.15625 µm: steps alternate 0.1 and
    /// 0.2 µm and positions deviate by up to 0.32·dx from the fitted grid
    /// (whose spacing comes out at 0.15625 µm to 10⁻⁶). Treating such a file
    /// as uniform moves each height by at most 0.05 µm along x — the
    /// rounding that the file already carries.
    #[default]
    Tolerant,
}

impl Spacing {
    fn tolerance(self) -> (f64, &'static str) {
        match self {
            Spacing::Strict => (
                1e-3,
                "uniformly spaced: max |x_j - x_0 - j*dx| / dx <= 1e-3 (Spacing::Strict)",
            ),
            Spacing::Tolerant => (
                0.5,
                "uniformly spaced: max |x_j - x_0 - j*dx| / dx <= 0.5 and every step in [0.5, 1.5] dx (Spacing::Tolerant)",
            ),
        }
    }
}

fn split_fields(s: &str) -> impl Iterator<Item = &str> {
    s.split(|c: char| c == ',' || c == ';' || c.is_whitespace())
        .filter(|f| !f.is_empty())
}

/// Parses every field of `content` as a finite number into `out`; `Ok(false)`
/// if a field is not a number (a header line), `Err` for NaN/∞.
fn parse_numbers(content: &str, line: u64, out: &mut Vec<f64>) -> Result<bool> {
    out.clear();
    for f in split_fields(content) {
        match f.parse::<f64>() {
            Ok(v) if v.is_finite() => out.push(v),
            Ok(_) => {
                return Err(Error::Parse {
                    what: "non-finite number (NaN or infinity)",
                    line,
                })
            }
            Err(_) => return Ok(false),
        }
    }
    Ok(true)
}

/// Iterates over (1-based line number, content without comment) of non-blank
/// lines, and hands comment texts to `on_comment`.
fn content_lines<'a>(
    text: &'a str,
    mut on_comment: impl FnMut(&'a str) + 'a,
) -> impl Iterator<Item = (u64, &'a str)> + 'a {
    text.lines().enumerate().filter_map(move |(i, line)| {
        let (content, comment) = match line.find('#') {
            Some(p) => (&line[..p], Some(&line[p + 1..])),
            None => (line, None),
        };
        if let Some(c) = comment {
            on_comment(c.trim());
        }
        let content = content.trim();
        (!content.is_empty()).then_some((i as u64 + 1, content))
    })
}

/// Mean spacing, origin and relative deviation of `x` from the uniform grid;
/// errors per `spacing`. `lines[j]` is the line of `x[j]` for messages.
pub(crate) fn uniform_grid(x: &[f64], lines: &[u64], spacing: Spacing) -> Result<(f64, f64, f64)> {
    for j in 1..x.len() {
        if x[j] <= x[j - 1] {
            return Err(Error::Parse {
                what: "positions must strictly increase",
                line: lines[j],
            });
        }
    }
    // Least-squares line x_j ≈ x0 + j·dx (positions relative to the first,
    // so that a large absolute offset costs no precision).
    let n = x.len();
    let first = x[0];
    let tc = (n as f64 - 1.0) / 2.0;
    let (mut sxt, mut stt, mut sx) = (0.0, 0.0, 0.0);
    for (j, &v) in x.iter().enumerate() {
        let t = j as f64 - tc;
        sxt += (v - first) * t;
        stt += t * t;
        sx += v - first;
    }
    let dx = sxt / stt;
    let x0 = sx / n as f64 - dx * tc;
    let dev = x
        .iter()
        .enumerate()
        .map(|(j, &v)| (v - first - x0 - j as f64 * dx).abs())
        .fold(0.0, f64::max)
        / dx;
    let x0 = first + x0;
    let (tol, bound) = spacing.tolerance();
    if dev > tol {
        return Err(Error::InvalidArgument {
            name: "x",
            value: dev,
            bound,
        });
    }
    // With few points a least-squares grid can stay within 0.5·dx of very
    // uneven positions; the step rule catches that (strict already implies
    // steps within (1 ± 0.002)·dx).
    if let Some(w) = x
        .windows(2)
        .map(|w| (w[1] - w[0]) / dx)
        .find(|r| !(0.5..=1.5).contains(r))
    {
        return Err(Error::InvalidArgument {
            name: "x",
            value: w,
            bound,
        });
    }
    Ok((x0, dx, dev))
}

/// A [`Profile`] from measured positions `x` (m, strictly increasing) and
/// heights `z` (m), as [`parse_profile`] builds one from a file: origin and
/// spacing of the least-squares grid through `x`, the deviation from it
/// checked per `spacing` and kept in [`Profile::spacing_deviation`]. For
/// callers that hold the columns already (the Python package).
///
/// Errors: [`Error::InvalidArgument`] `z` when the lengths differ or fewer
/// than two points are given, `x` for a non-finite, non-increasing or
/// non-uniform position (the bound says which); what [`Profile::new`]
/// rejects in `z`.
pub fn profile_from_positions(x: &[f64], z: Vec<f64>, spacing: Spacing) -> Result<Profile> {
    if x.len() != z.len() {
        return Err(Error::InvalidArgument {
            name: "z",
            value: z.len() as f64,
            bound: "of the same length as x",
        });
    }
    if x.len() < 2 {
        return Err(Error::InvalidArgument {
            name: "x",
            value: x.len() as f64,
            bound: "at least 2 positions",
        });
    }
    if let Some(&v) = x.iter().find(|v| !v.is_finite()) {
        return Err(Error::InvalidArgument {
            name: "x",
            value: v,
            bound: "finite",
        });
    }
    if let Some(w) = x.windows(2).find(|w| w[1] <= w[0]) {
        return Err(Error::InvalidArgument {
            name: "x",
            value: w[1],
            bound: "strictly increasing",
        });
    }
    let lines: Vec<u64> = (1..=x.len() as u64).collect();
    let (x0, dx, dev) = uniform_grid(x, &lines, spacing)?;
    Ok(Profile::new(dx, z)?
        .with_origin(x0)?
        .with_spacing_deviation(dev))
}

/// A [`Profile`] from two-column `x z` text (m); see the module docs for the
/// accepted text. Origin and spacing are those of the least-squares grid
/// through the positions; the deviation from it is checked per `spacing` and
/// kept in [`Profile::spacing_deviation`].
///
/// Errors: [`Error::Parse`] with the line for a malformed line, a line with
/// other than two columns, non-finite numbers, decreasing x, or fewer than two
/// data lines; [`Error::InvalidArgument`] `x` for non-uniform spacing.
pub fn parse_profile(text: &str, spacing: Spacing) -> Result<Profile> {
    let mut xs = Vec::new();
    let mut zs = Vec::new();
    let mut lines = Vec::new();
    let mut header_allowed = true;
    let mut nums = Vec::with_capacity(4);
    for (line, content) in content_lines(text, |_| {}) {
        if !parse_numbers(content, line, &mut nums)? {
            if header_allowed {
                header_allowed = false;
                continue;
            }
            return Err(Error::Parse {
                what: "expected two numeric columns x, z",
                line,
            });
        }
        header_allowed = false;
        if nums.len() != 2 {
            return Err(Error::Parse {
                what: "expected exactly two columns x, z",
                line,
            });
        }
        xs.push(nums[0]);
        zs.push(nums[1]);
        lines.push(line);
    }
    if xs.len() < 2 {
        return Err(Error::Parse {
            what: "a profile needs at least two data lines",
            line: 0,
        });
    }
    let (x0, dx, dev) = uniform_grid(&xs, &lines, spacing)?;
    Ok(Profile::new(dx, zs)?
        .with_origin(x0)?
        .with_spacing_deviation(dev))
}

/// A [`Topography`] from gridded text with `dx_m` metadata, or from `x y z`
/// triplets; see the module docs. `spacing` applies to triplet positions.
///
/// Errors: [`Error::Parse`] for malformed lines, ragged rows, metadata that
/// disagrees with the grid, or triplets that do not fill a grid;
/// [`Error::InvalidArgument`] for non-uniform triplet spacing.
pub fn parse_topography(text: &str, spacing: Spacing) -> Result<Topography> {
    let mut meta_nx = None;
    let mut meta_ny = None;
    let mut meta_dx = None;
    let mut meta_dy = None;
    let mut bad_meta = None;
    let mut rows: Vec<(u64, Vec<f64>)> = Vec::new();
    let mut header_allowed = true;
    let mut nums = Vec::new();
    {
        let on_comment = |c: &str| {
            if let Some((k, v)) = c.split_once('=') {
                let (k, v) = (k.trim(), v.trim());
                let target = match k {
                    "nx" => &mut meta_nx,
                    "ny" => &mut meta_ny,
                    "dx_m" => &mut meta_dx,
                    "dy_m" => &mut meta_dy,
                    _ => return,
                };
                match v.parse::<f64>() {
                    Ok(x) if x.is_finite() && x > 0.0 => *target = Some(x),
                    _ => bad_meta = Some(k == "nx" || k == "ny"),
                }
            }
        };
        for (line, content) in content_lines(text, on_comment) {
            if !parse_numbers(content, line, &mut nums)? {
                if header_allowed {
                    header_allowed = false;
                    continue;
                }
                return Err(Error::Parse {
                    what: "expected numeric columns",
                    line,
                });
            }
            header_allowed = false;
            rows.push((line, nums.clone()));
        }
    }
    if let Some(count) = bad_meta {
        return Err(Error::Parse {
            what: if count {
                "metadata nx/ny must be positive integers"
            } else {
                "metadata dx_m/dy_m must be finite and > 0"
            },
            line: 0,
        });
    }
    if rows.is_empty() {
        return Err(Error::Parse {
            what: "no data lines",
            line: 0,
        });
    }
    if let Some(dx) = meta_dx {
        let nx = rows[0].1.len();
        for (line, r) in &rows {
            if r.len() != nx {
                return Err(Error::Parse {
                    what: "every grid row must have the same number of heights",
                    line: *line,
                });
            }
        }
        let ny = rows.len();
        if meta_nx.is_some_and(|v| v != nx as f64) {
            return Err(Error::Parse {
                what: "metadata nx differs from the number of heights per row",
                line: rows[0].0,
            });
        }
        if meta_ny.is_some_and(|v| v != ny as f64) {
            return Err(Error::Parse {
                what: "metadata ny differs from the number of rows",
                line: 0,
            });
        }
        let heights: Vec<f64> = rows.into_iter().flat_map(|(_, r)| r).collect();
        return Topography::new(nx, ny, dx, meta_dy.unwrap_or(dx), heights);
    }
    // Triplets.
    for (line, r) in &rows {
        if r.len() != 3 {
            return Err(Error::Parse {
                what: "expected three columns x, y, z (or a grid with `# dx_m=` metadata)",
                line: *line,
            });
        }
    }
    let axis = |k: usize| -> Result<(f64, f64, usize)> {
        let mut v: Vec<f64> = rows.iter().map(|(_, r)| r[k]).collect();
        v.sort_by(f64::total_cmp);
        let span = v[v.len() - 1] - v[0];
        let mut u: Vec<f64> = Vec::new();
        for x in v {
            if u.last().map_or(true, |&l| x - l > 1e-9 * span) {
                u.push(x);
            }
        }
        if u.len() < 2 {
            return Err(Error::Parse {
                what: "triplets must span at least two x and two y values",
                line: 0,
            });
        }
        let lines = vec![0; u.len()];
        let (x0, d, _) = uniform_grid(&u, &lines, spacing)?;
        Ok((x0, d, u.len()))
    };
    let (x0, dx, nx) = axis(0)?;
    let (y0, dy, ny) = axis(1)?;
    if nx * ny != rows.len() {
        return Err(Error::Parse {
            what: "x, y, z triplets do not form a complete grid",
            line: 0,
        });
    }
    let mut heights = vec![f64::NAN; nx * ny];
    for (line, r) in &rows {
        let i = ((r[0] - x0) / dx).round() as usize;
        let j = ((r[1] - y0) / dy).round() as usize;
        let k = j * nx + i;
        if i >= nx || j >= ny || !heights[k].is_nan() {
            return Err(Error::Parse {
                what: "duplicate grid point in x, y, z triplets",
                line: *line,
            });
        }
        heights[k] = r[2];
    }
    Topography::new(nx, ny, dx, dy, heights)
}

fn read_text(path: &Path, what: &'static str) -> Result<String> {
    std::fs::read_to_string(path).map_err(|e| Error::Io {
        what,
        kind: e.kind(),
    })
}

/// Reads a profile file; see [`parse_profile`]. Errors: [`Error::Io`] when
/// the file cannot be read as UTF-8 text, then those of [`parse_profile`].
pub fn read_profile(path: impl AsRef<Path>, spacing: Spacing) -> Result<Profile> {
    parse_profile(&read_text(path.as_ref(), "profile file")?, spacing)
}

/// Reads a map file; see [`parse_topography`]. Errors: [`Error::Io`] when the
/// file cannot be read as UTF-8 text, then those of [`parse_topography`].
pub fn read_topography(path: impl AsRef<Path>, spacing: Spacing) -> Result<Topography> {
    parse_topography(&read_text(path.as_ref(), "topography file")?, spacing)
}

impl Profile {
    /// Reads a profile file; see [`read_profile`].
    pub fn read(path: impl AsRef<Path>, spacing: Spacing) -> Result<Self> {
        read_profile(path, spacing)
    }
}

impl Topography {
    /// Reads a map file; see [`read_topography`].
    pub fn read(path: impl AsRef<Path>, spacing: Spacing) -> Result<Self> {
        read_topography(path, spacing)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn profile_text_variants() {
        let p = parse_profile("x_m,z_m\n0,1e-9\n1e-6,2e-9\n2e-6,3e-9\n", Spacing::Strict).unwrap();
        assert_eq!(p.len(), 3);
        assert!((p.dx() - 1e-6).abs() < 1e-18);
        let p = parse_profile(
            "# comment\n\n 0.0  1.0 # trailing\n1.0\t2.0\n2.0; 3.0\n",
            Spacing::Strict,
        )
        .unwrap();
        assert_eq!(p.heights(), &[1.0, 2.0, 3.0]);
    }

    #[test]
    fn profile_text_errors() {
        let e = parse_profile("x,z\n0,1\nfoo,2\n", Spacing::Tolerant).unwrap_err();
        assert_eq!(
            e,
            Error::Parse {
                what: "expected two numeric columns x, z",
                line: 3
            }
        );
        let e = parse_profile("0,1\n1,2,3\n", Spacing::Tolerant).unwrap_err();
        assert!(matches!(e, Error::Parse { line: 2, .. }));
        let e = parse_profile("0,1\n1,NaN\n", Spacing::Tolerant).unwrap_err();
        assert!(matches!(e, Error::Parse { line: 2, .. }));
        let e = parse_profile("0,1\n", Spacing::Tolerant).unwrap_err();
        assert!(matches!(e, Error::Parse { line: 0, .. }));
        let e = parse_profile("0,1\n2,1\n1,1\n", Spacing::Tolerant).unwrap_err();
        assert!(matches!(e, Error::Parse { line: 3, .. }));
        // Rounded positions: tolerant accepts, strict refuses.
        let t = "0,0\n0.1,1\n0.3,0\n0.4,1\n0.6,0\n";
        let p = parse_profile(t, Spacing::Tolerant).unwrap();
        assert!((p.dx() - 0.15).abs() < 1e-15);
        assert!(
            (p.spacing_deviation() - 0.2).abs() < 1e-9,
            "{}",
            p.spacing_deviation()
        );
        let e = parse_profile(t, Spacing::Strict).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument { name: "x", .. }));
        // Far from uniform: refused by both.
        let e = parse_profile("0,0\n0.1,1\n1,0\n", Spacing::Tolerant).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument { name: "x", .. }));
    }

    #[test]
    fn map_text_grid_and_triplets() {
        let g = "# nx=3\n# ny=2\n# dx_m=1e-6\n# dy_m=2e-6\n1,2,3\n4,5,6\n";
        let t = parse_topography(g, Spacing::Strict).unwrap();
        assert_eq!((t.nx(), t.ny()), (3, 2));
        assert_eq!(t.z(2, 1), Some(6.0));
        assert_eq!(t.z(3, 1), None);
        assert_eq!(t.dy(), 2e-6);
        let e = parse_topography("# dx_m=1e-6\n1,2,3\n4,5\n", Spacing::Strict).unwrap_err();
        assert!(matches!(e, Error::Parse { line: 3, .. }));
        let e =
            parse_topography("# dx_m=1e-6\n# nx=4\n1,2,3\n4,5,6\n", Spacing::Strict).unwrap_err();
        assert!(matches!(e, Error::Parse { .. }));
        let xyz = "x y z\n1 0 10\n0 0 00\n0 1 01\n1 1 11\n0 2 02\n1 2 12\n";
        let t = parse_topography(xyz, Spacing::Strict).unwrap();
        assert_eq!((t.nx(), t.ny()), (2, 3));
        assert_eq!(t.z(1, 2), Some(12.0));
        assert_eq!(t.z(0, 1), Some(1.0));
        let e = parse_topography("0 0 1\n1 0 1\n0 1 1\n", Spacing::Strict).unwrap_err();
        assert!(matches!(e, Error::Parse { .. }));
    }

    #[test]
    fn missing_file_is_an_io_error() {
        let e = read_profile("/nonexistent/asperity/profile.csv", Spacing::Strict).unwrap_err();
        assert_eq!(
            e,
            Error::Io {
                what: "profile file",
                kind: std::io::ErrorKind::NotFound
            }
        );
        assert!(e.to_string().contains("profile file"));
    }
}
