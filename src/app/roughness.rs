//! `wearopt roughness`: σ, R and N of a measured height map (a file, or heights in
//! memory), with its power spectral density.

use std::path::Path;

use crate::surface::psd::Psd;
use crate::surface::read::{self, Overrides};
use crate::surface::{analyse, level, HeightMap, Roughness, Settings};

use super::{AppError, OptionName};

pub use crate::surface::read::Format;
pub use crate::surface::Levelling;

/// The options of `wearopt roughness` (SI values).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughnessOptions {
    /// Short-wavelength cut-off λs in metres; `None` for no filter.
    pub cutoff: Option<f64>,
    /// Form removal before the analysis.
    pub level: Levelling,
    /// Pixel size in metres, overriding the file's (required for `.npy`, a bare
    /// ASCII matrix and heights in memory).
    pub pixel_size: Option<f64>,
    /// Metres per stored height unit, overriding the file's (required for `.npy`
    /// and a bare ASCII matrix; heights in memory default to metres).
    pub height_unit: Option<f64>,
    /// An ASCII matrix writes its decimals with commas.
    pub decimal_comma: bool,
}

impl Default for RoughnessOptions {
    fn default() -> Self {
        RoughnessOptions {
            cutoff: None,
            level: Levelling::Plane,
            pixel_size: None,
            height_unit: None,
            decimal_comma: false,
        }
    }
}

/// A positive finite length along a map written with its unit ("100 nm"; a plain
/// number is metres where plausible), for the option `option`.
pub fn length(option: OptionName, text: &str) -> Result<f64, AppError> {
    super::quantity::positive_quantity(option, text, super::quantity::OptionQuantity::ScanLength)
}

/// Metres per stored height unit from a unit ("nm") or a scale ("1e-9").
pub fn height_unit(option: OptionName, text: &str) -> Result<f64, AppError> {
    read::parse_height_unit(text).ok_or_else(|| AppError::Invalid {
        options: vec![(option, format!("{text:?}"))],
        rule: "not a length unit; expected e.g. \"nm\", \"um\", \"m\" or \"1e-9\"".to_string(),
    })
}

/// The form removal named `name` ("none", "plane", "quadratic").
pub fn levelling(option: OptionName, name: &str) -> Result<Levelling, AppError> {
    match name {
        "none" => Ok(Levelling::None),
        "plane" => Ok(Levelling::Plane),
        "quadratic" => Ok(Levelling::Quadratic),
        other => Err(AppError::Invalid {
            options: vec![(option, format!("{other:?}"))],
            rule: "expected \"none\", \"plane\" or \"quadratic\"".to_string(),
        }),
    }
}

/// What `wearopt roughness` computes for a height map.
#[derive(Debug, Clone)]
pub struct RoughnessDocument {
    /// The file as named by the caller (or what the heights in memory are).
    pub file: String,
    /// Its format (by extension; ASCII when the extension says nothing; NumPy for
    /// heights in memory).
    pub format: Format,
    /// The analysis.
    pub roughness: Roughness,
    /// The power spectral density of the levelled map (before any cut-off).
    pub psd: Psd,
}

/// Reads and analyses the height map at `path`, as `wearopt roughness` does.
pub fn roughness(path: &Path, options: &RoughnessOptions) -> Result<RoughnessDocument, AppError> {
    let overrides = Overrides {
        pixel_size: options.pixel_size,
        height_unit: options.height_unit,
        decimal_comma: options.decimal_comma,
    };
    let format = Format::from_path(path).unwrap_or(Format::Ascii);
    let map = read::load(path, &overrides).map_err(AppError::Read)?;
    analysed(path.display().to_string(), format, &map, options)
}

/// Analyses `heights` (row by row along y: `ny` rows of `nx`, NaN = missing) in
/// units of `options.height_unit` metres (metres when `None`), with square pixels
/// of `options.pixel_size` (required). `origin` names the map in messages.
pub fn roughness_of_heights(
    origin: &str,
    nx: usize,
    ny: usize,
    heights: Vec<f64>,
    options: &RoughnessOptions,
) -> Result<RoughnessDocument, AppError> {
    let map = map_of_heights(
        origin,
        nx,
        ny,
        heights,
        options.pixel_size,
        options.height_unit,
    )?;
    analysed(origin.to_string(), Format::Npy, &map, options)
}

/// Heights in memory (row by row along y, `ny` rows of `nx`, in units of
/// `height_unit` metres, metres when `None`) as a map of square pixels of
/// `pixel_size` (required: heights carry none). `origin` names them in messages.
pub(crate) fn map_of_heights(
    origin: &str,
    nx: usize,
    ny: usize,
    heights: Vec<f64>,
    pixel_size: Option<f64>,
    height_unit: Option<f64>,
) -> Result<HeightMap, AppError> {
    let Some(pixel) = pixel_size else {
        return Err(AppError::Invalid {
            options: vec![(OptionName("pixel_size"), "None".to_string())],
            rule: format!("{origin} carries no pixel size: give one, e.g. \"10 nm\""),
        });
    };
    let unit = height_unit.unwrap_or(1.0);
    let heights = heights.into_iter().map(|h| h * unit).collect();
    HeightMap::new(nx, ny, pixel, pixel, heights).map_err(|error| AppError::Surface {
        origin: origin.to_string(),
        error,
    })
}

fn analysed(
    origin: String,
    format: Format,
    map: &HeightMap,
    options: &RoughnessOptions,
) -> Result<RoughnessDocument, AppError> {
    let settings = Settings {
        level: options.level,
        cutoff: options.cutoff,
    };
    let surface_error = |error| AppError::Surface {
        origin: origin.clone(),
        error,
    };
    let roughness = analyse(map, &settings).map_err(surface_error)?;
    let levelled = level(map, options.level).map_err(surface_error)?;
    let psd = Psd::of(&levelled);
    Ok(RoughnessDocument {
        file: origin,
        format,
        roughness,
        psd,
    })
}
