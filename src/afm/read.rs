//! Measured force–distance curves: arrays, and the CSV format of
//! `../shared/data/afm` (`#` metadata lines, one header line, columns found by
//! name).

use crate::error::{check, Error, Result};
use std::path::Path;

/// A measured AFM force–distance curve (SI: m, N): approach then retract.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AfmCurve {
    /// Piezo (or height-sensor) position (m), as the instrument writes it;
    /// the direction towards the sample is found from the approach.
    pub position: Vec<f64>,
    /// Cantilever force (N), positive when repulsive, **raw**: the baseline
    /// (offset and tilt of the free part) is still in it.
    pub force: Vec<f64>,
    /// Index of the first retract point (`1..len`): rows before it are the
    /// approach.
    pub retract_start: usize,
    /// Cantilever spring constant k (N/m) stored with the curve, if any.
    pub spring_constant: Option<f64>,
    /// Name of the position column the curve was read from (empty for
    /// arrays).
    pub position_column: String,
}

/// Position columns looked for, in order of preference: the closed-loop
/// height sensors before the piezo drive signal.
pub const POSITION_COLUMNS: [&str; 6] = [
    "z_sensor_m",
    "height_measured_m",
    "z_raw_m",
    "height_piezo_m",
    "position_m",
    "z_m",
];

impl AfmCurve {
    /// A curve from arrays of equal length (at least 8 points each side),
    /// all finite. `retract_start` splits approach and retract; `None` splits
    /// at the turning point (the position farthest from the first one).
    /// `spring_constant` (N/m) is checked when given.
    pub fn new(
        position: Vec<f64>,
        force: Vec<f64>,
        retract_start: Option<usize>,
        spring_constant: Option<f64>,
    ) -> Result<Self> {
        let c = Self {
            retract_start: retract_start.unwrap_or_else(|| turning_point(&position)),
            position,
            force,
            spring_constant,
            position_column: String::new(),
        };
        c.validate()?;
        Ok(c)
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// No points.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// Lengths, finiteness, the split and the spring constant.
    pub(crate) fn validate(&self) -> Result<()> {
        if self.force.len() != self.position.len() {
            return Err(Error::InvalidArgument {
                name: "force",
                value: self.force.len() as f64,
                bound: "as many values as position",
            });
        }
        for (&z, &f) in self.position.iter().zip(&self.force) {
            check::finite("position", z)?;
            check::finite("force", f)?;
        }
        let n = self.position.len();
        if self.retract_start < MIN_SIDE || self.retract_start + MIN_SIDE > n {
            return Err(Error::InvalidArgument {
                name: "retract_start",
                value: self.retract_start as f64,
                bound: "at least 8 approach and 8 retract points",
            });
        }
        if let Some(k) = self.spring_constant {
            check::positive("spring_constant", k)?;
        }
        Ok(())
    }

    /// Parse the CSV format of `../shared/data/afm`: `#` lines (a
    /// `# spring_constant_N_per_m=…` line gives k), one header line, rows.
    /// Position: `position_column` if given, else the first of
    /// [`POSITION_COLUMNS`] present. Force: `force_N`, else `deflection_m`
    /// times k. Split: the `segment` column (`approach`/`retract`) if
    /// present, else the turning point.
    pub fn from_csv_str(text: &str, position_column: Option<&str>) -> Result<Self> {
        let mut k = None;
        let mut header = None;
        let mut rows = Vec::new();
        for (i, l) in text.lines().enumerate() {
            let l = l.trim();
            if l.is_empty() {
                continue;
            }
            if let Some(c) = l.strip_prefix('#') {
                if let Some(v) = c.trim().strip_prefix("spring_constant_N_per_m=") {
                    k = Some(v.trim().parse::<f64>().map_err(|_| Error::Parse {
                        what: "a number after spring_constant_N_per_m=",
                        line: i as u64 + 1,
                    })?);
                }
                continue;
            }
            if header.is_none() {
                header = Some((i + 1, l));
            } else {
                rows.push((i + 1, l));
            }
        }
        let (hline, header) = header.ok_or(Error::Parse {
            what: "a header line naming the columns",
            line: 0,
        })?;
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        let find = |n: &str| names.iter().position(|x| *x == n);
        let (ip, pname) = match position_column {
            Some(c) => (find(c), c.to_string()),
            None => POSITION_COLUMNS
                .iter()
                .find_map(|c| find(c).map(|i| (Some(i), c.to_string())))
                .unwrap_or((None, String::new())),
        };
        let ip = ip.ok_or(Error::Parse {
            what: "a position column (z_sensor_m, height_measured_m, z_raw_m, height_piezo_m, position_m or z_m)",
            line: hline as u64,
        })?;
        let iforce = find("force_N");
        let idefl = find("deflection_m");
        if iforce.is_none() && (idefl.is_none() || k.is_none()) {
            return Err(Error::Parse {
                what: "a force_N column, or deflection_m with a spring_constant_N_per_m line",
                line: hline as u64,
            });
        }
        let iseg = find("segment");
        let mut position = Vec::with_capacity(rows.len());
        let mut force = Vec::with_capacity(rows.len());
        let mut first_retract = None;
        for (line, l) in rows {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            if f.len() < names.len() {
                return Err(Error::Parse {
                    what: "as many fields as the header",
                    line: line as u64,
                });
            }
            let num = |i: usize| -> Result<f64> {
                f[i].parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or(Error::Parse {
                        what: "finite numbers",
                        line: line as u64,
                    })
            };
            position.push(num(ip)?);
            force.push(match iforce {
                Some(i) => num(i)?,
                None => num(idefl.unwrap_or(0))? * k.unwrap_or(0.0),
            });
            if let Some(i) = iseg {
                match f[i] {
                    "approach" => {}
                    "retract" => {
                        if first_retract.is_none() {
                            first_retract = Some(position.len() - 1);
                        }
                    }
                    _ => {
                        return Err(Error::Parse {
                            what: "segment `approach` or `retract`",
                            line: line as u64,
                        })
                    }
                }
            }
        }
        let mut c = Self::new(position, force, first_retract, k)?;
        c.position_column = pname;
        Ok(c)
    }

    /// Read a file ([`AfmCurve::from_csv_str`]).
    pub fn read(path: impl AsRef<Path>, position_column: Option<&str>) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::Io {
            what: "AFM curve file",
            kind: e.kind(),
        })?;
        Self::from_csv_str(&text, position_column)
    }
}

/// Fewest points on each side of the split.
const MIN_SIDE: usize = 8;

/// The index after the point farthest from the first one.
fn turning_point(z: &[f64]) -> usize {
    let Some(&z0) = z.first() else { return 0 };
    let mut best = 0;
    for (i, &v) in z.iter().enumerate() {
        if (v - z0).abs() > (z[best] - z0).abs() {
            best = i;
        }
    }
    best + 1
}
