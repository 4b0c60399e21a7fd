//! `wearopt contact`: the exact elastic (or elastic–perfectly plastic) contact of a
//! measured height map at one or more mean pressures, beside the statistical
//! (Greenwood–Williamson) model's answer on the same map.

use std::path::Path;

use crate::contact::{Settings as SolveSettings, Solution, Solver};
use crate::surface::read::{self, Format, Overrides};
use crate::surface::{analyse, level, HeightMap, Levelling, Roughness, Settings};
use crate::units::{parse_quantity, Dimension};

use super::{AppError, OptionName};

pub use crate::contact::{Outcome, DEFAULT_TOLERANCE};
pub use crate::problem::scan_contact::{scan_contact, statistical, ScanContact, Statistical};

/// The options of `wearopt contact` (SI values).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactOptions {
    /// E*, the composite modulus of the pair (Pa).
    pub modulus: f64,
    /// The mean (nominal) pressures to solve at (Pa), each > 0.
    pub pressures: Vec<f64>,
    /// H, the cap on the contact pressure (Pa); None for a purely elastic contact.
    pub hardness: Option<f64>,
    /// Form removal before the solve (the levelled map is one period).
    pub level: Levelling,
    /// Pixel size in metres, overriding the file's.
    pub pixel_size: Option<f64>,
    /// Metres per stored height unit, overriding the file's.
    pub height_unit: Option<f64>,
    /// The residual at which each solve stops.
    pub tolerance: f64,
    /// Keep the pressure and gap fields of every solution (for `--fields` and the
    /// HTML page).
    pub fields: bool,
}

impl Default for ContactOptions {
    fn default() -> Self {
        ContactOptions {
            modulus: f64::NAN,
            pressures: Vec::new(),
            hardness: None,
            level: Levelling::Plane,
            pixel_size: None,
            height_unit: None,
            tolerance: DEFAULT_TOLERANCE,
            fields: false,
        }
    }
}

/// A positive finite quantity of `dimension` for the option `option`.
pub fn positive(option: OptionName, text: &str, dimension: Dimension) -> Result<f64, AppError> {
    let invalid = |rule: String| AppError::Invalid {
        options: vec![(option, format!("{text:?}"))],
        rule,
    };
    let x = parse_quantity(text, dimension).map_err(|e| invalid(e.to_string()))?;
    if !(x.is_finite() && x > 0.0) {
        return Err(invalid(format!(
            "must be a positive finite {}",
            dimension.name()
        )));
    }
    Ok(x)
}

/// A comma-separated list of positive pressures ("10 MPa,50 MPa,0.2 GPa").
pub fn pressures(option: OptionName, text: &str) -> Result<Vec<f64>, AppError> {
    let list: Vec<&str> = text
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect();
    if list.is_empty() {
        return Err(AppError::Invalid {
            options: vec![(option, format!("{text:?}"))],
            rule: "give one or more mean pressures, comma-separated, e.g. \"10 MPa,50 MPa\""
                .to_string(),
        });
    }
    list.into_iter()
        .map(|p| positive(option, p, Dimension::Pressure))
        .collect()
}

/// The checks the options need beyond their own ranges: a hardness above every
/// pressure and a tolerance in (0, 1).
fn check(options: &ContactOptions) -> Result<(), AppError> {
    if !(options.modulus.is_finite() && options.modulus > 0.0) {
        return Err(AppError::Invalid {
            options: vec![(OptionName("modulus"), options.modulus.to_string())],
            rule: "the composite modulus E* must be a positive finite pressure, e.g. \"150 GPa\""
                .to_string(),
        });
    }
    if options.pressures.is_empty() {
        return Err(AppError::Invalid {
            options: vec![(OptionName("pressure"), "none".to_string())],
            rule: "give one or more mean pressures".to_string(),
        });
    }
    for &p in &options.pressures {
        if !(p.is_finite() && p > 0.0) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("pressure"), p.to_string())],
                rule: "each mean pressure must be positive and finite".to_string(),
            });
        }
    }
    if let Some(h) = options.hardness {
        if h.is_nan() || h <= 0.0 {
            return Err(AppError::Invalid {
                options: vec![(OptionName("hardness"), h.to_string())],
                rule: "the hardness must be a positive pressure".to_string(),
            });
        }
        let top = options.pressures.iter().copied().fold(0.0, f64::max);
        if top >= h {
            return Err(AppError::Invalid {
                options: vec![
                    (OptionName("pressure"), top.to_string()),
                    (OptionName("hardness"), h.to_string()),
                ],
                rule: "every mean pressure must be below the hardness (at H the whole map flows)"
                    .to_string(),
            });
        }
    }
    if !(options.tolerance > 0.0 && options.tolerance < 1.0) {
        return Err(AppError::Invalid {
            options: vec![(OptionName("tolerance"), options.tolerance.to_string())],
            rule: "must be in (0, 1), e.g. 1e-10".to_string(),
        });
    }
    Ok(())
}

/// The contact at one mean pressure, both ways.
#[derive(Debug, Clone)]
pub struct ContactPoint {
    /// The boundary-element solution (its fields empty unless asked for).
    pub solution: Solution,
    /// The statistical model's answer, when the map has McCool parameters.
    pub statistical: Option<Statistical>,
}

impl ContactPoint {
    /// The statistical model's real area over the boundary-element one.
    /// None where either side has no usable answer (the statistical model out of
    /// its range, say, where its "area" may exceed the nominal one).
    pub fn area_ratio(&self) -> Option<f64> {
        let gw = self.statistical?;
        (self.solution.real_area_fraction > 0.0 && gw.status == crate::model::Status::Ok)
            .then(|| gw.real_area_fraction / self.solution.real_area_fraction)
    }
}

/// What `wearopt contact` computes for a height map.
#[derive(Debug, Clone)]
pub struct ContactDocument {
    /// The map as named by the caller.
    pub file: String,
    /// Its format.
    pub format: Format,
    /// Points along x and y.
    pub pixels: [usize; 2],
    /// Pixel size along x and y (m).
    pub pixel_size: [f64; 2],
    /// The options the solves ran with.
    pub options: ContactOptions,
    /// The rms height of the levelled map (m).
    pub rms_height: f64,
    /// The levelled map (m, row-major), for plots of the map and its contact.
    pub heights: Vec<f64>,
    /// McCool's analysis of the levelled map (the statistical model's inputs), or
    /// why there is none.
    pub roughness: Result<Roughness, String>,
    /// One point per pressure, in the order given.
    pub points: Vec<ContactPoint>,
}

/// Reads the map at `path` and solves its contact, as `wearopt contact` does.
pub fn contact(path: &Path, options: &ContactOptions) -> Result<ContactDocument, AppError> {
    check(options)?;
    let overrides = Overrides {
        pixel_size: options.pixel_size,
        height_unit: options.height_unit,
    };
    let format = Format::from_path(path).unwrap_or(Format::Ascii);
    let map = read::load(path, &overrides).map_err(AppError::Read)?;
    solved(path.display().to_string(), format, &map, options)
}

/// The contact of `heights` (row by row along y: `ny` rows of `nx`) in units of
/// `options.height_unit` metres (metres when `None`), square pixels of
/// `options.pixel_size` (required). `origin` names the map in messages.
pub fn contact_of_heights(
    origin: &str,
    nx: usize,
    ny: usize,
    heights: Vec<f64>,
    options: &ContactOptions,
) -> Result<ContactDocument, AppError> {
    check(options)?;
    let map = super::roughness::map_of_heights(
        origin,
        nx,
        ny,
        heights,
        options.pixel_size,
        options.height_unit,
    )?;
    solved(origin.to_string(), Format::Npy, &map, options)
}

fn solved(
    origin: String,
    format: Format,
    map: &HeightMap,
    options: &ContactOptions,
) -> Result<ContactDocument, AppError> {
    let contact_error = |error| AppError::Contact {
        origin: origin.clone(),
        error,
    };
    let (nx, ny) = (map.nx(), map.ny());
    let (dx, dy) = (map.pixel_size_x(), map.pixel_size_y());
    // Missing points and small maps are the solver's to refuse, before the
    // levelling (which would skip missing points) and the analysis.
    if nx < crate::contact::MIN_SIDE || ny < crate::contact::MIN_SIDE {
        return Err(contact_error(crate::contact::ContactError::TooSmall {
            nx,
            ny,
        }));
    }
    let missing = map.heights().iter().filter(|h| !h.is_finite()).count();
    if missing > 0 {
        return Err(contact_error(crate::contact::ContactError::Missing {
            missing,
            total: nx * ny,
        }));
    }
    let levelled = level(map, options.level).map_err(|error| AppError::Surface {
        origin: origin.clone(),
        error,
    })?;
    let mut solver =
        Solver::new(nx, ny, dx, dy, levelled.heights(), options.modulus).map_err(contact_error)?;
    let settings = SolveSettings {
        hardness: options.hardness.unwrap_or(f64::INFINITY),
        tolerance: options.tolerance,
        ..SolveSettings::default()
    };
    // Each pressure from the same uniform start: its numbers do not depend on
    // which other pressures were asked for.
    let mut points_solved = Vec::with_capacity(options.pressures.len());
    for &p in &options.pressures {
        let mut s = solver.solve(p, &settings, None).map_err(contact_error)?;
        if !options.fields {
            s.pressures = Vec::new();
            s.gaps = Vec::new();
        }
        points_solved.push(s);
    }
    let roughness = analyse(
        map,
        &Settings {
            level: options.level,
            cutoff: None,
        },
    )
    .map_err(|e| e.to_string());
    let area = nx as f64 * dx * ny as f64 * dy;
    let points = points_solved
        .into_iter()
        .map(|solution| {
            let statistical = roughness.as_ref().ok().map(|r| {
                let p = r.parameters;
                statistical(
                    [p.summit_sigma, p.summit_radius, p.summit_density],
                    options.modulus,
                    options.hardness.unwrap_or(f64::INFINITY),
                    solution.pressure,
                    area,
                )
            });
            ContactPoint {
                solution,
                statistical,
            }
        })
        .collect();
    let n = (nx * ny) as f64;
    let mean = levelled.heights().iter().sum::<f64>() / n;
    let rms_height = (levelled
        .heights()
        .iter()
        .map(|h| (h - mean) * (h - mean))
        .sum::<f64>()
        / n)
        .sqrt();
    Ok(ContactDocument {
        file: origin,
        format,
        pixels: [nx, ny],
        pixel_size: [dx, dy],
        options: options.clone(),
        rms_height,
        heights: levelled.heights().iter().map(|h| h - mean).collect(),
        roughness,
        points,
    })
}
