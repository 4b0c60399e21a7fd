//! Height-map files (SURFACES.md §8): Gwyddion `.gsf`, ISO 25178-72 `.x3p`, ASCII matrix
//! (bare or with Gwyddion's header) and NumPy `.npy`.
//!
//! A reader returns a [`Scan`]: the values as stored (NaN = missing), and the pixel size and
//! height unit the file states, or `None` where it states none. [`Scan::resolve`] makes a
//! [`HeightMap`] in metres, taking what the file lacks (or what the user overrides) from
//! [`Overrides`]; it never guesses a unit.
//!
//! Every refusal is a [`ReadError`] naming the file and what is wrong with it; no input
//! makes a reader panic.

mod ascii;
mod gsf;
mod npy;
mod x3p;

use std::path::Path;

use serde::Serialize;

use super::{HeightMap, SurfaceError};
use crate::units::{parse_quantity, Dimension};

/// A file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Format {
    /// Gwyddion Simple Field.
    Gsf,
    /// ISO 25178-72 XML (a zip).
    X3p,
    /// Whitespace-separated rows, optionally with Gwyddion's `#` header.
    Ascii,
    /// NumPy array, shape (ny, nx).
    Npy,
}

impl Format {
    /// From a file extension (case-insensitive); `.txt`, `.asc`, `.dat`, `.csv` are ASCII.
    pub fn from_path(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "gsf" => Some(Format::Gsf),
            "x3p" => Some(Format::X3p),
            "npy" => Some(Format::Npy),
            "txt" | "asc" | "dat" | "csv" | "xyz" => Some(Format::Ascii),
            _ => None,
        }
    }
    /// The usual name of the format.
    pub fn name(self) -> &'static str {
        match self {
            Format::Gsf => "Gwyddion Simple Field (.gsf)",
            Format::X3p => "ISO 25178-72 XML (.x3p)",
            Format::Ascii => "ASCII matrix",
            Format::Npy => "NumPy (.npy)",
        }
    }
}

/// The numbers of a file, before units are settled.
#[derive(Debug, Clone, PartialEq)]
pub struct Scan {
    /// The format it was read as.
    pub format: Format,
    /// Points along x (columns).
    pub nx: usize,
    /// Points along y (rows).
    pub ny: usize,
    /// Values as stored, row by row (`j * nx + i`); NaN = missing.
    pub values: Vec<f64>,
    /// Metres per stored value, when the file says.
    pub height_unit: Option<f64>,
    /// Pixel sizes (Δx, Δy) in metres, when the file says.
    pub pixel_size: Option<(f64, f64)>,
}

/// What the user supplies or overrides.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// Pixel size in metres (both directions).
    pub pixel_size: Option<f64>,
    /// Metres per stored height value.
    pub height_unit: Option<f64>,
    /// An ASCII matrix writes its decimals with commas ("1,25"); its columns are
    /// then separated by whitespace or semicolons only.
    pub decimal_comma: bool,
}

/// A file that cannot be read as a height map.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ReadError {
    /// The file could not be opened or read.
    #[error("{path}: cannot read the file: {message}")]
    Io {
        /// The path as given.
        path: String,
        /// The system's reason.
        message: String,
    },
    /// The extension names no format this reader knows.
    #[error("{path}: unknown height-map format (extension {ext:?}); expected .gsf, .x3p, .npy, or an ASCII matrix (.txt, .asc, .dat, .csv)")]
    UnknownFormat {
        /// The path.
        path: String,
        /// Its extension.
        ext: String,
    },
    /// The content does not follow the format.
    #[error("{path}: not a valid {format} file: {reason}")]
    Malformed {
        /// The path.
        path: String,
        /// The format's name.
        format: &'static str,
        /// What is wrong, with the offending value.
        reason: String,
    },
    /// The file gives no pixel size and none was supplied.
    #[error("{path}: the {format} file gives no pixel size; supply it with --pixel-size (command line) or pixel_size (problem file [roughness]), e.g. \"10 nm\"")]
    NoPixelSize {
        /// The path.
        path: String,
        /// The format's name.
        format: &'static str,
    },
    /// The file gives no height unit and none was supplied.
    #[error("{path}: the {format} file gives no height unit; supply it with --height-unit (command line) or height_unit (problem file [roughness]), e.g. \"nm\"")]
    NoHeightUnit {
        /// The path.
        path: String,
        /// The format's name.
        format: &'static str,
    },
    /// A supplied pixel size or height unit that is not a positive length.
    #[error("{what} {value}: must be a positive finite length")]
    BadOverride {
        /// "pixel size" or "height unit".
        what: &'static str,
        /// The value in metres.
        value: f64,
    },
    /// The grid is not analysable (bad pixel size, infinite value, ...).
    #[error("{path}: {source}")]
    Map {
        /// The path.
        path: String,
        /// Why.
        source: SurfaceError,
    },
}

/// Reads a height-map file, its format chosen by extension.
pub fn read(path: &Path) -> Result<Scan, ReadError> {
    read_with(path, false)
}

/// [`read`], an ASCII matrix with decimal commas when `decimal_comma`.
pub fn read_with(path: &Path, decimal_comma: bool) -> Result<Scan, ReadError> {
    let origin = path.display().to_string();
    let format = Format::from_path(path).ok_or_else(|| ReadError::UnknownFormat {
        path: origin.clone(),
        ext: path
            .extension()
            .map(|e| e.to_string_lossy().into_owned())
            .unwrap_or_default(),
    })?;
    let bytes = std::fs::read(path).map_err(|e| ReadError::Io {
        path: origin.clone(),
        message: e.to_string(),
    })?;
    read_bytes_with(&bytes, format, &origin, decimal_comma)
}

/// Reads the bytes of a file of a known format; `origin` names it in messages.
pub fn read_bytes(bytes: &[u8], format: Format, origin: &str) -> Result<Scan, ReadError> {
    read_bytes_with(bytes, format, origin, false)
}

/// [`read_bytes`], an ASCII matrix with decimal commas when `decimal_comma`.
pub fn read_bytes_with(
    bytes: &[u8],
    format: Format,
    origin: &str,
    decimal_comma: bool,
) -> Result<Scan, ReadError> {
    let malformed = |reason: String| ReadError::Malformed {
        path: origin.to_string(),
        format: format.name(),
        reason,
    };
    match format {
        Format::Gsf => gsf::read(bytes),
        Format::X3p => x3p::read(bytes),
        Format::Ascii => ascii::read(bytes, decimal_comma),
        Format::Npy => npy::read(bytes),
    }
    .map_err(malformed)
}

impl Scan {
    /// The height map in metres: the file's pixel size and height unit, each replaced by
    /// the override when one is given. Refuses a scan whose pixel size or height unit is
    /// neither in the file nor supplied.
    pub fn resolve(self, overrides: &Overrides, origin: &str) -> Result<HeightMap, ReadError> {
        for (what, v) in [
            ("pixel size", overrides.pixel_size),
            ("height unit", overrides.height_unit),
        ] {
            if let Some(value) = v {
                if !(value.is_finite() && value > 0.0) {
                    return Err(ReadError::BadOverride { what, value });
                }
            }
        }
        let (dx, dy) = match (overrides.pixel_size, self.pixel_size) {
            (Some(p), _) => (p, p),
            (None, Some(p)) => p,
            (None, None) => {
                return Err(ReadError::NoPixelSize {
                    path: origin.to_string(),
                    format: self.format.name(),
                })
            }
        };
        let unit =
            overrides
                .height_unit
                .or(self.height_unit)
                .ok_or_else(|| ReadError::NoHeightUnit {
                    path: origin.to_string(),
                    format: self.format.name(),
                })?;
        let mut values = self.values;
        if unit != 1.0 {
            for v in &mut values {
                *v *= unit;
            }
        }
        HeightMap::new(self.nx, self.ny, dx, dy, values).map_err(|source| ReadError::Map {
            path: origin.to_string(),
            source,
        })
    }
}

/// Metres per unit for a length unit as files write it ("m", "um", "µm", "nm", "Å", "mm",
/// …). None for an empty or unknown unit.
pub fn length_unit(unit: &str) -> Option<f64> {
    let u = unit.trim();
    if u.is_empty() {
        return None;
    }
    let x = parse_quantity(format!("1 {u}").as_str(), Dimension::Length).ok()?;
    (x.is_finite() && x > 0.0).then_some(x)
}

/// The grid size as a checked product, refusing zero and absurd sizes (more than 2³¹
/// points) before anything is allocated.
fn grid_size(nx: usize, ny: usize) -> Result<usize, String> {
    if nx == 0 || ny == 0 {
        return Err(format!("grid of {nx} × {ny} points is empty"));
    }
    match nx.checked_mul(ny) {
        Some(n) if n <= 1 << 31 => Ok(n),
        _ => Err(format!("grid of {nx} × {ny} points is too large")),
    }
}

pub use gsf::write as write_gsf;

/// Reads a file and resolves it to a height map (see [`read`] and [`Scan::resolve`]).
pub fn load(path: &Path, overrides: &Overrides) -> Result<HeightMap, ReadError> {
    let origin = path.display().to_string();
    read_with(path, overrides.decimal_comma)?.resolve(overrides, &origin)
}

/// Reads a height unit as a user writes it: a unit name ("nm", "um", "µm", "Å", "m") or a
/// length ("1 nm", "1e-9"). Metres per stored value.
pub fn parse_height_unit(text: &str) -> Option<f64> {
    length_unit(text).or_else(|| {
        parse_quantity(text, Dimension::Length)
            .ok()
            .filter(|x| x.is_finite() && *x > 0.0)
    })
}
