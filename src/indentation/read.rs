//! Measured load–depth curves: the CSV format of the data sets (with segment
//! labels), plain two-column text, and arrays.

use super::segment::Segment;
use crate::error::{check, Error, Result};
use std::fmt;
use std::path::Path;

/// A measured load–depth curve (SI: m, N, s).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Curve {
    /// Time (s), when the file has it.
    pub time: Option<Vec<f64>>,
    /// Depth (m), positive into the surface.
    pub depth: Vec<f64>,
    /// Load (N), positive compressive.
    pub load: Vec<f64>,
    /// Segment labels, when the file has them.
    pub segments: Option<Vec<Segment>>,
}

/// Reading a curve failed.
#[derive(Debug)]
pub enum ReadError {
    /// The file could not be read.
    Io(std::io::Error),
    /// A line could not be parsed (1-based line number).
    Parse {
        /// Line number, 1-based.
        line: usize,
        /// What was wrong.
        message: String,
    },
    /// The parsed data are invalid (unequal lengths, non-finite values, …).
    Invalid(Error),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io(e) => write!(f, "reading the curve: {e}"),
            ReadError::Parse { line, message } => write!(f, "line {line}: {message}"),
            ReadError::Invalid(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ReadError {}

impl From<Error> for ReadError {
    fn from(e: Error) -> Self {
        ReadError::Invalid(e)
    }
}

fn parse_number(s: &str, line: usize, what: &str) -> std::result::Result<f64, ReadError> {
    let v: f64 = s.trim().parse().map_err(|_| ReadError::Parse {
        line,
        message: format!("{what} `{}` is not a number", s.trim()),
    })?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(ReadError::Parse {
            line,
            message: format!("{what} `{}` is not finite", s.trim()),
        })
    }
}

impl Curve {
    /// A curve from depth (m) and load (N) arrays of equal length, all finite.
    pub fn new(depth: Vec<f64>, load: Vec<f64>) -> Result<Self> {
        if depth.len() != load.len() {
            return Err(Error::InvalidArgument {
                name: "load",
                value: load.len() as f64,
                bound: "as many values as depth",
            });
        }
        for &x in &depth {
            check::finite("depth", x)?;
        }
        for &x in &load {
            check::finite("load", x)?;
        }
        Ok(Self {
            time: None,
            depth,
            load,
            segments: None,
        })
    }

    /// Attach segment labels (one per point).
    pub fn with_segments(mut self, segments: Vec<Segment>) -> Result<Self> {
        if segments.len() != self.depth.len() {
            return Err(Error::InvalidArgument {
                name: "segments",
                value: segments.len() as f64,
                bound: "one label per point",
            });
        }
        self.segments = Some(segments);
        Ok(self)
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.depth.len()
    }

    /// No points.
    pub fn is_empty(&self) -> bool {
        self.depth.is_empty()
    }

    /// Parse the data format of `../shared/data/indentation`: `#` comment
    /// lines, then the header `time_s,depth_m,load_N,segment` (columns found
    /// by name, in any order; `time_s` and `segment` optional), then rows.
    pub fn from_csv_str(text: &str) -> std::result::Result<Self, ReadError> {
        let mut lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
        let (hline, header) = lines.next().ok_or(ReadError::Parse {
            line: 0,
            message: "no header line".into(),
        })?;
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        let find = |n: &str| names.iter().position(|x| *x == n);
        let (Some(id), Some(il)) = (find("depth_m"), find("load_N")) else {
            return Err(ReadError::Parse {
                line: hline,
                message: format!("header `{header}` lacks depth_m and load_N"),
            });
        };
        let it = find("time_s");
        let is = find("segment");
        let mut c = Curve {
            time: it.map(|_| Vec::new()),
            segments: is.map(|_| Vec::new()),
            ..Default::default()
        };
        for (n, l) in lines {
            let f: Vec<&str> = l.split(',').collect();
            if f.len() < names.len() {
                return Err(ReadError::Parse {
                    line: n,
                    message: format!("{} fields, the header has {}", f.len(), names.len()),
                });
            }
            c.depth.push(parse_number(f[id], n, "depth")?);
            c.load.push(parse_number(f[il], n, "load")?);
            if let (Some(i), Some(t)) = (it, c.time.as_mut()) {
                t.push(parse_number(f[i], n, "time")?);
            }
            if let (Some(i), Some(s)) = (is, c.segments.as_mut()) {
                s.push(Segment::from_label(f[i]).ok_or_else(|| ReadError::Parse {
                    line: n,
                    message: format!("unknown segment label `{}`", f[i].trim()),
                })?);
            }
        }
        if c.is_empty() {
            return Err(ReadError::Parse {
                line: hline,
                message: "no data rows".into(),
            });
        }
        Ok(c)
    }

    /// Plain two-column text: `depth load` per line (m, N), separated by
    /// whitespace, a comma or a semicolon; `#` comments and a non-numeric
    /// first line (a header) are skipped.
    pub fn from_two_column_str(text: &str) -> std::result::Result<Self, ReadError> {
        let mut c = Curve::default();
        let mut first = true;
        for (i, l) in text.lines().enumerate() {
            let l = l.trim();
            if l.is_empty() || l.starts_with('#') {
                continue;
            }
            let f: Vec<&str> = l
                .split(|ch: char| ch == ',' || ch == ';' || ch.is_whitespace())
                .filter(|s| !s.is_empty())
                .collect();
            if first && f.first().is_some_and(|s| s.parse::<f64>().is_err()) {
                first = false;
                continue;
            }
            first = false;
            if f.len() < 2 {
                return Err(ReadError::Parse {
                    line: i + 1,
                    message: "expected two columns: depth load".into(),
                });
            }
            c.depth.push(parse_number(f[0], i + 1, "depth")?);
            c.load.push(parse_number(f[1], i + 1, "load")?);
        }
        if c.is_empty() {
            return Err(ReadError::Parse {
                line: 0,
                message: "no data rows".into(),
            });
        }
        Ok(c)
    }

    /// Either format: the CSV format when a header names `depth_m` and
    /// `load_N`, two columns otherwise.
    pub fn parse(text: &str) -> std::result::Result<Self, ReadError> {
        let header = text
            .lines()
            .map(str::trim)
            .find(|l| !l.is_empty() && !l.starts_with('#'));
        if header.is_some_and(|h| h.contains("depth_m") && h.contains("load_N")) {
            Self::from_csv_str(text)
        } else {
            Self::from_two_column_str(text)
        }
    }

    /// Read a file in either format ([`Curve::parse`]).
    pub fn read(path: impl AsRef<Path>) -> std::result::Result<Self, ReadError> {
        let text = std::fs::read_to_string(path).map_err(ReadError::Io)?;
        Self::parse(&text)
    }
}

impl Curve {
    /// Equal lengths and finite values, which [`Curve::new`] ensures but a
    /// curve built field by field may lack.
    pub(super) fn validate(&self) -> Result<()> {
        if self.depth.len() != self.load.len() {
            return Err(Error::InvalidArgument {
                name: "load",
                value: self.load.len() as f64,
                bound: "as many values as depth",
            });
        }
        for (&h, &p) in self.depth.iter().zip(&self.load) {
            check::finite("depth", h)?;
            check::finite("load", p)?;
        }
        Ok(())
    }
}
