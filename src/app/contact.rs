//! `wearopt contact`: the exact elastic (or elastic–perfectly plastic) contact of a
//! measured height map at one or more mean pressures, beside the statistical
//! (Greenwood–Williamson) model's answer on the same map.

use std::path::Path;

use crate::contact::{Settings as SolveSettings, Solution, Solver};
use crate::surface::read::{self, Format, Overrides};
use crate::surface::{analyse, level, HeightMap, Levelling, Roughness, Settings};
use crate::units::{format_quantity, Dimension};

use super::quantity::{positive_quantity, OptionQuantity};
use super::{AppError, OptionName};

pub use super::scan_contact::{fulfil, scan_contact, statistical, ScanContact, Statistical};
pub use crate::contact::adhesion::{
    Adhesion, AdhesiveSolution, PullOff, Resolution, RESOLVED_PIXELS, WELL_RESOLVED_PIXELS,
};
pub use crate::contact::{Outcome, DEFAULT_TOLERANCE};

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
    /// An ASCII matrix writes its decimals with commas.
    pub decimal_comma: bool,
    /// The residual at which each solve stops.
    pub tolerance: f64,
    /// Keep the pressure and gap fields of every solution (for `--fields` and the
    /// HTML page).
    pub fields: bool,
    /// An attraction between the surfaces, solved beside the adhesion-free contact.
    pub adhesion: Option<AdhesionOptions>,
}

/// The attraction of `wearopt contact --work-of-adhesion γ --adhesion-range ρ`:
/// the exponential law, energy `−γ e^{−g/ρ}` per unit area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesionOptions {
    /// γ, the work of adhesion (J/m²).
    pub work: f64,
    /// ρ, the range (m).
    pub range: f64,
    /// Where the map cannot resolve ρ, raise it to a well-resolved range (a
    /// process zone of [`WELL_RESOLVED_PIXELS`] pixels) instead of refusing it.
    pub coarse_grain: bool,
}

/// The adhesive side of a contact document.
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesionResult {
    /// γ (J/m²).
    pub work: f64,
    /// ρ as asked (m).
    pub range_asked: f64,
    /// ρ as solved (m): as asked, or coarse-grained up to the resolved range.
    pub range: f64,
    /// How the pixels resolve ρ as asked.
    pub resolution_asked: Resolution,
    /// How they resolve ρ as solved.
    pub resolution: Resolution,
    /// The pull-off from the contact at the largest pressure.
    pub pull_off: PullOff,
    /// Its force over the map's area (N, ≥ 0): −pull-off pressure × area.
    pub pull_off_force: f64,
    /// The map's (nominal) area (m²).
    pub area: f64,
}

impl AdhesionResult {
    /// ρ solved over ρ asked when coarse-grained, else None.
    pub fn coarse_grained(&self) -> Option<f64> {
        (self.range > self.range_asked).then(|| self.range / self.range_asked)
    }

    /// Whether the process zone, though resolved, spans fewer than
    /// [`WELL_RESOLVED_PIXELS`] pixels.
    pub fn marginal(&self) -> bool {
        self.resolution.process_zone_pixels < WELL_RESOLVED_PIXELS
    }
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
            decimal_comma: false,
            tolerance: DEFAULT_TOLERANCE,
            fields: false,
            adhesion: None,
        }
    }
}

/// A positive finite quantity for the option `option`: a number with its unit, or
/// a bare number (SI) where it is plausible ([`super::quantity::positive_quantity`]).
pub fn positive(option: OptionName, text: &str, quantity: OptionQuantity) -> Result<f64, AppError> {
    positive_quantity(option, text, quantity)
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
        .map(|p| positive(option, p, OptionQuantity::MeanPressure))
        .collect()
}

/// The stiffest composite modulus E* a solve accepts (Pa): 10 TPa, about
/// twenty times diamond on diamond (E* ≈ 0.57 TPa). A stiffer pair touches on one
/// pixel at any pressure (E* = 1e300 Pa gave 0.0015 %, "converged"), an answer
/// about the map's highest pixel, not a contact.
pub const MAX_MODULUS: f64 = 1e13;

/// The residual tolerance a solve must stay below: the residual is the mean gap
/// over the contact against the map's rms height, and a loose one takes open
/// gaps for contact. The uniform start already meets 0.8 (`--tolerance 0.999`
/// reported 100 % contact after 0 iterations where the solution has 5.7 %); on
/// the shipped self-affine scan at 50 MPa and 150 GPa (converged: 1.70 %) a
/// tolerance of 0.09 stops at 3.4 %, 0.01 at 1.82 %, 1e-3 at 1.709 %.
pub const MAX_TOLERANCE: f64 = 0.01;

/// The checks the options need beyond their own ranges: a hardness above every
/// pressure, a modulus up to [`MAX_MODULUS`] and a tolerance in (0,
/// [`MAX_TOLERANCE`]).
fn check(options: &ContactOptions) -> Result<(), AppError> {
    if !(options.modulus.is_finite() && options.modulus > 0.0) {
        return Err(AppError::Invalid {
            options: vec![(OptionName("modulus"), options.modulus.to_string())],
            rule: "the composite modulus E* must be a positive finite pressure, e.g. \"150 GPa\""
                .to_string(),
        });
    }
    if options.modulus > MAX_MODULUS {
        return Err(AppError::Invalid {
            options: vec![(OptionName("modulus"), format_quantity(options.modulus, Dimension::Pressure))],
            rule: "the composite modulus E* must be at most 10 TPa (diamond on diamond is 0.57 TPa): a stiffer pair touches on the map's highest pixel alone".to_string(),
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
    if let Some(a) = options.adhesion {
        for (name, value, example) in [
            ("work_of_adhesion", a.work, "\"50 mJ/m^2\""),
            ("adhesion_range", a.range, "\"0.5 nm\""),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(AppError::Invalid {
                    options: vec![(OptionName(name), value.to_string())],
                    rule: format!("must be positive and finite, e.g. {example}"),
                });
            }
        }
    }
    if !(options.tolerance > 0.0 && options.tolerance < MAX_TOLERANCE) {
        return Err(AppError::Invalid {
            options: vec![(OptionName("tolerance"), options.tolerance.to_string())],
            rule: format!("must be in (0, {MAX_TOLERANCE}), e.g. 1e-10: the residual is the mean gap over the contact against the map's rms height, and a looser tolerance takes open gaps for contact (at 0.01 the real area is already 7 % too large on a typical scan)"),
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
    /// The contact with adhesion at the same mean pressure, when asked for
    /// (its fields empty unless asked for).
    pub adhesive: Option<AdhesiveSolution>,
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
    /// The resolution, the range solved and the pull-off, with adhesion.
    pub adhesion: Option<AdhesionResult>,
}

impl ContactDocument {
    /// Whether a row is not a solution: a solve, with or without adhesion, that
    /// stopped at its iteration limit above the tolerance (its row is the last
    /// iterate). The command line exits with 1 then.
    pub fn failed(&self) -> bool {
        self.points.iter().any(|pt| {
            pt.solution.outcome == Outcome::IterationLimit
                || pt
                    .adhesive
                    .as_ref()
                    .is_some_and(|a| a.outcome == Outcome::IterationLimit)
        })
    }
}

/// Reads the map at `path` and solves its contact, as `wearopt contact` does.
pub fn contact(path: &Path, options: &ContactOptions) -> Result<ContactDocument, AppError> {
    contact_with(path, options, &super::Quiet)
}

/// As [`contact`], telling `progress` of each solve as it finishes: one per
/// pressure, and with adhesion the loading along the approach and the pull-off.
pub fn contact_with(
    path: &Path,
    options: &ContactOptions,
    progress: &dyn super::Progress,
) -> Result<ContactDocument, AppError> {
    check(options)?;
    let overrides = Overrides {
        pixel_size: options.pixel_size,
        height_unit: options.height_unit,
        decimal_comma: options.decimal_comma,
    };
    let format = Format::from_path(path).unwrap_or(Format::Ascii);
    let map = read::load(path, &overrides).map_err(AppError::Read)?;
    solved(path.display().to_string(), format, &map, options, progress)
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
    solved(
        origin.to_string(),
        Format::Npy,
        &map,
        options,
        &super::Quiet,
    )
}

fn solved(
    origin: String,
    format: Format,
    map: &HeightMap,
    options: &ContactOptions,
    progress: &dyn super::Progress,
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
    // A map flat to within what its heights resolve (a constant or a plane: the
    // levelling leaves only rounding) is flat: in full contact at any load. Given
    // as it is, the solver chased the rounding to its iteration limit.
    let largest = map.heights().iter().fold(0.0f64, |m, h| m.max(h.abs()));
    let n = (nx * ny) as f64;
    let mean = levelled.heights().iter().sum::<f64>() / n;
    let spread = (levelled
        .heights()
        .iter()
        .map(|h| (h - mean) * (h - mean))
        .sum::<f64>()
        / n)
        .sqrt();
    let flat = spread <= crate::surface::HEIGHT_RESOLUTION * largest;
    let zeros;
    let heights = if flat {
        zeros = vec![0.0; nx * ny];
        &zeros[..]
    } else {
        levelled.heights()
    };
    let mut solver =
        Solver::new(nx, ny, dx, dy, heights, options.modulus).map_err(contact_error)?;
    let settings = SolveSettings {
        hardness: options.hardness.unwrap_or(f64::INFINITY),
        tolerance: options.tolerance,
        ..SolveSettings::default()
    };
    // Each pressure from the same uniform start: its numbers do not depend on
    // which other pressures were asked for.
    let mut points_solved = Vec::with_capacity(options.pressures.len());
    progress.begin(options.pressures.len() + if options.adhesion.is_some() { 2 } else { 0 });
    for &p in &options.pressures {
        let mut s = solver.solve(p, &settings, None).map_err(contact_error)?;
        progress.advance();
        if !options.fields {
            s.pressures = Vec::new();
            s.gaps = Vec::new();
        }
        points_solved.push(s);
    }
    let area = nx as f64 * dx * ny as f64 * dy;
    let (mut adhesive, adhesion) = match options.adhesion {
        Some(a) => {
            let (states, result) = adhesive(&mut solver, &a, options, area, &origin, progress)?;
            (states.into_iter().map(Some).collect(), Some(result))
        }
        None => (vec![None; options.pressures.len()], None),
    };
    let roughness = analyse(
        map,
        &Settings {
            level: options.level,
            cutoff: None,
        },
    )
    .map_err(|e| e.to_string());
    let points = points_solved
        .into_iter()
        .zip(adhesive.iter_mut())
        .map(|(solution, adhesive)| {
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
                adhesive: adhesive.take(),
            }
        })
        .collect();
    Ok(ContactDocument {
        file: origin,
        format,
        pixels: [nx, ny],
        pixel_size: [dx, dy],
        options: options.clone(),
        rms_height: if flat { 0.0 } else { spread },
        heights: heights
            .iter()
            .map(|h| if flat { 0.0 } else { h - mean })
            .collect(),
        roughness,
        points,
        adhesion,
    })
}

/// The adhesive contact at every pressure (along one approach) and the pull-off
/// from the largest; ρ checked against the pixels first, and coarse-grained
/// when allowed.
fn adhesive(
    solver: &mut Solver,
    a: &AdhesionOptions,
    options: &ContactOptions,
    area: f64,
    origin: &str,
    progress: &dyn super::Progress,
) -> Result<(Vec<AdhesiveSolution>, AdhesionResult), AppError> {
    let contact_error = |error| AppError::Contact {
        origin: origin.to_string(),
        error,
    };
    let asked = Adhesion::new(a.work, a.range).map_err(contact_error)?;
    let resolution_asked = solver.resolution(&asked);
    let law = if resolution_asked.resolved() {
        asked
    } else {
        let least = Adhesion::range_for_process_zone(
            a.work,
            solver.modulus(),
            RESOLVED_PIXELS * solver.pixel(),
        );
        // Coarse-grained, the range is made well resolved, not just barely.
        let range = Adhesion::range_for_process_zone(
            a.work,
            solver.modulus(),
            WELL_RESOLVED_PIXELS * solver.pixel(),
        );
        if !a.coarse_grain {
            let len = |x: f64| format_quantity(x, Dimension::Length);
            return Err(AppError::Invalid {
                options: vec![
                    (OptionName("adhesion_range"), len(a.range)),
                    (
                        OptionName("work_of_adhesion"),
                        format_quantity(a.work, Dimension::SurfaceEnergy),
                    ),
                ],
                rule: format!(
                    "the map cannot resolve this range: the process zone π E* ρ²/(4γ) = {} spans {:.3} pixels of {}, and the solve needs at least {RESOLVED_PIXELS}; give ρ ≥ {}, a finer map, or --coarse-grain to solve at ρ = {} (×{:.3}, a process zone of {WELL_RESOLVED_PIXELS} pixels)",
                    len(resolution_asked.process_zone),
                    resolution_asked.process_zone_pixels,
                    len(solver.pixel()),
                    len(least),
                    len(range),
                    range / a.range
                ),
            });
        }
        Adhesion::new(a.work, range).map_err(contact_error)?
    };
    let settings = SolveSettings {
        tolerance: options.tolerance,
        ..SolveSettings::default()
    };
    let mut states = solver
        .adhesive_loading(&options.pressures, &law, &settings)
        .map_err(contact_error)?;
    progress.advance();
    let top = states
        .iter()
        .max_by(|x, y| x.pressure.total_cmp(&y.pressure))
        .cloned()
        .ok_or_else(|| contact_error(crate::contact::ContactError::Pressure(f64::NAN)))?;
    let pull_off = solver
        .pull_off(&top, &law, &settings)
        .map_err(contact_error)?;
    progress.advance();
    if !options.fields {
        for s in &mut states {
            s.pressures = Vec::new();
            s.gaps = Vec::new();
        }
    }
    let result = AdhesionResult {
        work: a.work,
        range_asked: a.range,
        range: law.range,
        resolution_asked,
        resolution: solver.resolution(&law),
        pull_off_force: 0.0 - pull_off.pressure * area,
        pull_off,
        area,
    };
    Ok((states, result))
}
