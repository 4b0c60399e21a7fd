//! From a measured height map to the model's roughness inputs σ, R and N.
//!
//! The stage has two halves that meet in [`HeightMap`]:
//!
//! * [`read`]: the file formats (Gwyddion `.gsf`, ISO 25178-72 `.x3p`, ASCII matrix, NumPy
//!   `.npy`). A reader returns a [`read::Scan`]: the numbers as stored, with the pixel size
//!   and height unit the file gives (or `None` when it gives none); [`read::Scan::resolve`]
//!   turns it into a [`HeightMap`] in metres, taking what the file lacks from the user.
//! * the analysis, which does no I/O: [`level`] (least-squares plane or quadratic),
//!   [`filter::gaussian_cutoff`] (ISO 16610-61 areal Gaussian, edge band dropped, levelled
//!   again on the kept points), [`moments::Moments`] (m0, m2, m4 by finite differences),
//!   the McCool/Nayak [`Parameters`], the summit count [`summits::SummitCount`] and the
//!   radially averaged [`psd::Psd`].
//!
//! [`analyse`] runs the chain (level → optional cut-off → moments → parameters → summits)
//! and returns a [`Roughness`] with structured [`Warning`]s; the report stage words them.
//!
//! Missing points are NaN in a [`HeightMap`] and are left out of every sum; a difference
//! or a neighbourhood that touches one is left out too.

pub mod filter;
mod level;
pub mod moments;
pub mod psd;
pub mod read;
pub mod summits;
pub mod synthetic;

pub use level::{level, Levelling};
pub use moments::Moments;
pub use summits::SummitCount;

use serde::Serialize;

/// A regular grid of heights in metres: `h[i, j]` with `i` along x (columns) and `j` along
/// y (rows), stored row by row (`j * nx + i`, image order). NaN marks a missing point.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightMap {
    nx: usize,
    ny: usize,
    pixel_size_x: f64,
    pixel_size_y: f64,
    heights: Vec<f64>,
}

/// Why a height map cannot be analysed. These are faults of the data or of the settings
/// (exit code 2 in the CLI), never outcomes.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SurfaceError {
    /// The grid has too few points for second differences.
    #[error("the map is {nx} × {ny} points; at least 3 points along x, and 1 (a profile) or at least 3 along y, are needed for curvatures")]
    TooSmall {
        /// Points along x.
        nx: usize,
        /// Points along y.
        ny: usize,
    },
    /// The number of heights does not match the grid.
    #[error("{len} heights for a {nx} × {ny} grid")]
    WrongLength {
        /// Points along x.
        nx: usize,
        /// Points along y.
        ny: usize,
        /// Heights given.
        len: usize,
    },
    /// A pixel size that is not a positive finite length.
    #[error("pixel size {value} m along {axis}: must be a positive finite length")]
    BadPixelSize {
        /// "x" or "y".
        axis: &'static str,
        /// The value in metres.
        value: f64,
    },
    /// An infinite height (missing points are NaN, not infinite).
    #[error("height at x index {i}, y index {j} is infinite; missing points must be NaN")]
    InfiniteHeight {
        /// Column.
        i: usize,
        /// Row.
        j: usize,
    },
    /// More than half of the points are missing (SURFACES.md §1).
    #[error("only {valid} of {total} points are valid; a map with more than half its points missing is refused")]
    TooManyMissing {
        /// Valid points.
        valid: usize,
        /// All points.
        total: usize,
    },
    /// The cut-off is not a positive finite length.
    #[error("cut-off {value} m: must be a positive finite length")]
    BadCutoff {
        /// The value in metres.
        value: f64,
    },
    /// The cut-off leaves too little map once the edge band is dropped.
    #[error("cut-off {cutoff} m drops an edge band of {band_x} × {band_y} pixels, leaving {kept_nx} × {kept_ny} of a {nx} × {ny} map; use a cut-off below {largest} m")]
    CutoffTooLarge {
        /// The cut-off in metres.
        cutoff: f64,
        /// Edge band dropped along x, pixels.
        band_x: usize,
        /// Edge band dropped along y, pixels.
        band_y: usize,
        /// Points kept along x.
        kept_nx: usize,
        /// Points kept along y.
        kept_ny: usize,
        /// Points along x.
        nx: usize,
        /// Points along y.
        ny: usize,
        /// The largest cut-off that keeps at least 3 points each way (metres).
        largest: f64,
    },
    /// The levelled surface has no slope or no curvature (flat, or constant slope).
    #[error("the levelled surface has m0 = {m0} m², m2 = {m2}, m4 = {m4} m⁻²: it has no roughness to analyse")]
    Flat {
        /// Mean square height.
        m0: f64,
        /// Mean square slope moment.
        m2: f64,
        /// Mean square curvature moment.
        m4: f64,
    },
    /// The levelled heights vary by less than the stored heights can resolve: a
    /// constant map or a plane, whose "roughness" is the rounding of its levelling.
    #[error("the levelled map's rms height {rms:.3e} m is below a millionth of its heights (up to {largest:.3e} m): it is flat — a constant map or a plane — to within what its stored heights can resolve, so it has no roughness to analyse")]
    Unresolved {
        /// The levelled map's rms height (m).
        rms: f64,
        /// The largest |height| of the map as read (m).
        largest: f64,
    },
    /// α = m0 m4 / m2² below 1.5: the moments are not those of an isotropic Gaussian
    /// surface (SURFACES.md §5), so the McCool formulas do not apply.
    #[error("bandwidth α = m0 m4 / m2² = {alpha} is below 1.5, the least an isotropic Gaussian surface can have: these moments are not those of a random rough surface (a periodic or a single-wavelength pattern?), so σ, R and N cannot be derived from them")]
    InconsistentMoments {
        /// The bandwidth parameter.
        alpha: f64,
    },
}

impl HeightMap {
    /// A map of `nx × ny` heights (metres, row by row along y, NaN = missing) with pixel
    /// sizes in metres. Refuses a wrong length, a non-positive pixel size or an infinite
    /// height. A map with a single column is stored as a profile along x.
    pub fn new(
        nx: usize,
        ny: usize,
        pixel_size_x: f64,
        pixel_size_y: f64,
        heights: Vec<f64>,
    ) -> Result<Self, SurfaceError> {
        if nx.checked_mul(ny) != Some(heights.len()) {
            return Err(SurfaceError::WrongLength {
                nx,
                ny,
                len: heights.len(),
            });
        }
        for (axis, value) in [("x", pixel_size_x), ("y", pixel_size_y)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(SurfaceError::BadPixelSize { axis, value });
            }
        }
        if let Some(k) = heights.iter().position(|h| h.is_infinite()) {
            return Err(SurfaceError::InfiniteHeight {
                i: k % nx,
                j: k / nx,
            });
        }
        if nx == 1 && ny > 1 {
            // A column is a profile: store it along x.
            return Ok(HeightMap {
                nx: ny,
                ny: 1,
                pixel_size_x: pixel_size_y,
                pixel_size_y,
                heights,
            });
        }
        Ok(HeightMap {
            nx,
            ny,
            pixel_size_x,
            pixel_size_y,
            heights,
        })
    }

    /// Points along x.
    pub fn nx(&self) -> usize {
        self.nx
    }
    /// Points along y (1 for a profile).
    pub fn ny(&self) -> usize {
        self.ny
    }
    /// Δx in metres.
    pub fn pixel_size_x(&self) -> f64 {
        self.pixel_size_x
    }
    /// Δy in metres.
    pub fn pixel_size_y(&self) -> f64 {
        self.pixel_size_y
    }
    /// The heights in metres, row by row (`j * nx + i`); NaN = missing.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }
    /// Whether this is a line scan (one row).
    pub fn is_profile(&self) -> bool {
        self.ny == 1
    }
    /// `h[i, j]` (NaN when missing).
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.heights[j * self.nx + i]
    }
    /// Number of valid (non-NaN) points.
    pub fn valid_count(&self) -> usize {
        self.heights.iter().filter(|h| !h.is_nan()).count()
    }
    /// One row (fixed j).
    pub(crate) fn row(&self, j: usize) -> &[f64] {
        &self.heights[j * self.nx..(j + 1) * self.nx]
    }
    /// The same grid with other heights (crate-internal: lengths are the caller's care).
    pub(crate) fn with_heights(&self, heights: Vec<f64>) -> HeightMap {
        debug_assert_eq!(heights.len(), self.heights.len());
        HeightMap {
            nx: self.nx,
            ny: self.ny,
            pixel_size_x: self.pixel_size_x,
            pixel_size_y: self.pixel_size_y,
            heights,
        }
    }
    /// The grid size checks every analysis needs.
    fn check_analysable(&self) -> Result<(), SurfaceError> {
        if self.nx < 3 || self.ny == 2 {
            return Err(SurfaceError::TooSmall {
                nx: self.nx,
                ny: self.ny,
            });
        }
        let valid = self.valid_count();
        let total = self.heights.len();
        if 2 * valid < total || valid == 0 {
            return Err(SurfaceError::TooManyMissing { valid, total });
        }
        Ok(())
    }
}

/// What [`analyse`] does to the map before taking moments.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Settings {
    /// Form removal (SURFACES.md §2); default [`Levelling::Plane`].
    pub level: Levelling,
    /// Short-wavelength cut-off λs in metres (SURFACES.md §3); `None` for no filter.
    pub cutoff: Option<f64>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            level: Levelling::Plane,
            cutoff: None,
        }
    }
}

/// The Greenwood–Williamson parameters from the moments (McCool 1986, Nayak 1971;
/// SURFACES.md §5). All SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Parameters {
    /// Bandwidth α = m0 m4 / m2².
    pub bandwidth: f64,
    /// Summit density η = m4 / (6π√3 m2), m⁻².
    pub summit_density: f64,
    /// Mean summit radius R = 0.375 (π / m4)^½, m.
    pub summit_radius: f64,
    /// Summit height standard deviation σ_s = (1 − 0.8968/α)^½ m0^½, m.
    pub summit_sigma: f64,
    /// Mean summit height above the mean plane of the surface, z̄_s = 4 m0^½ / (π α)^½, m.
    pub mean_summit_height: f64,
}

impl Parameters {
    /// The McCool formulas. Refuses a flat surface and α < 1.5.
    pub fn from_moments(m: &Moments) -> Result<Self, SurfaceError> {
        let (m0, m2, m4) = (m.m0, m.m2, m.m4);
        if !(m0 > 0.0 && m2 > 0.0 && m4 > 0.0) {
            return Err(SurfaceError::Flat { m0, m2, m4 });
        }
        let alpha = m0 * m4 / (m2 * m2);
        if alpha.is_nan() || alpha < 1.5 || alpha.is_infinite() {
            return Err(SurfaceError::InconsistentMoments { alpha });
        }
        let pi = std::f64::consts::PI;
        Ok(Parameters {
            bandwidth: alpha,
            summit_density: m4 / (6.0 * pi * 3f64.sqrt() * m2),
            summit_radius: 0.375 * (pi / m4).sqrt(),
            summit_sigma: ((1.0 - 0.8968 / alpha) * m0).sqrt(),
            mean_summit_height: 4.0 * m0.sqrt() / (pi * alpha).sqrt(),
        })
    }

    /// η R σ_s, which the formulas make 0.0204 √α (SURFACES.md §7).
    pub fn gw_product(&self) -> f64 {
        self.summit_density * self.summit_radius * self.summit_sigma
    }
}

/// Something about the result a designer should know. Worded by the report stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Warning {
    /// The larger m2 of the two directions is more than twice the smaller: the surface is
    /// anisotropic and Nayak–McCool assume isotropy.
    Anisotropy {
        /// larger / smaller m2.
        ratio: f64,
    },
    /// Counted summits and the McCool estimates differ by more than 30 % in at least one
    /// of density, height spread or radius: roughness reaches the pixel scale.
    CountingDisagrees {
        /// counted / McCool summit density.
        density_ratio: f64,
        /// counted / McCool summit height spread (None when fewer than 2 summits).
        sigma_ratio: Option<f64>,
        /// counted mean radius / McCool radius (None when no summit).
        radius_ratio: Option<f64>,
        /// Whether a cut-off was applied already.
        cutoff_applied: bool,
    },
    /// η R σ outside the 0.03–0.05 that Greenwood–Williamson analyses assume.
    GwProductOutOfRange {
        /// η R σ_s.
        product: f64,
    },
    /// Some points were missing; they are left out of the sums.
    MissingPoints {
        /// Missing points of the map as read.
        missing: usize,
        /// All points.
        total: usize,
    },
    /// A profile: the moments are along x only and the areal formulas assume isotropy;
    /// summits cannot be counted on a line.
    Profile,
    /// One direction of the map has no valid neighbouring pair (or triple): its
    /// moments are missing, and the other direction's stand for both.
    OneDirection {
        /// The direction whose moments were used, "x" or "y".
        used: &'static str,
        /// The direction without any, "y" or "x".
        missing: &'static str,
    },
}

/// Everything [`analyse`] finds. Lengths in metres.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Roughness {
    /// Points along x of the map as given.
    pub nx: usize,
    /// Points along y of the map as given.
    pub ny: usize,
    /// Δx, m.
    pub pixel_size_x: f64,
    /// Δy, m.
    pub pixel_size_y: f64,
    /// Valid points / all points of the map as given.
    pub valid_fraction: f64,
    /// The settings used.
    pub settings: Settings,
    /// Points along x, y after the cut-off's edge band is dropped (= nx, ny without one).
    pub kept_nx: usize,
    /// See `kept_nx`.
    pub kept_ny: usize,
    /// Edge band dropped on each side, pixels along x and y (0 without a cut-off).
    pub edge_band: (usize, usize),
    /// The spectral moments of the levelled (filtered) map.
    pub moments: Moments,
    /// The McCool parameters.
    pub parameters: Parameters,
    /// The summit count (None for a profile).
    pub summits: Option<SummitCount>,
    /// What the report should point out.
    pub warnings: Vec<Warning>,
}

impl Roughness {
    /// rms height √m0, m.
    pub fn rms_height(&self) -> f64 {
        self.moments.m0.sqrt()
    }
    /// Areal rms slope √(2 m2) of an isotropic surface.
    pub fn rms_slope(&self) -> f64 {
        (2.0 * self.moments.m2).sqrt()
    }
}

/// Relative difference above which counting and moments are said to disagree.
pub const COUNTING_TOLERANCE: f64 = 0.3;
/// m2 ratio above which the surface is called anisotropic.
pub const ANISOTROPY_LIMIT: f64 = 2.0;
/// The η R σ range Greenwood–Williamson analyses assume.
pub const GW_PRODUCT_RANGE: (f64, f64) = (0.03, 0.05);

/// The map [`analyse`] takes its moments of: levelled, filtered by the optional
/// cut-off (its edge band dropped) and levelled again on the kept points.
pub fn analysed_map(map: &HeightMap, settings: &Settings) -> Result<HeightMap, SurfaceError> {
    analysed_map_with_band(map, settings).map(|(m, _)| m)
}

fn analysed_map_with_band(
    map: &HeightMap,
    settings: &Settings,
) -> Result<(HeightMap, (usize, usize)), SurfaceError> {
    map.check_analysable()?;
    let levelled = level(map, settings.level)?;
    Ok(match settings.cutoff {
        None => (levelled, (0, 0)),
        Some(cutoff) => {
            let filtered = filter::gaussian_cutoff(&levelled, cutoff)?;
            filtered.map.check_analysable()?;
            (level(&filtered.map, settings.level)?, filtered.edge_band)
        }
    })
}

/// The share of its heights' magnitude below which a levelled map's rms height is
/// taken for the rounding of its form removal ([`SurfaceError::Unresolved`]).
pub const HEIGHT_RESOLUTION: f64 = 1e-6;

/// Levels the map, applies the optional cut-off (and levels again on the kept points),
/// takes the moments, the McCool parameters and the summit count.
pub fn analyse(map: &HeightMap, settings: &Settings) -> Result<Roughness, SurfaceError> {
    let (work, band) = analysed_map_with_band(map, settings)?;
    let moments = Moments::of(&work);
    // Heights stored in single precision resolve 6e-8 of their magnitude: a
    // levelled rms within a millionth of it is the rounding of a constant or a
    // plane (a constant map read as R = 1.8e9 m), not a surface.
    let largest = map
        .heights
        .iter()
        .filter(|h| !h.is_nan())
        .fold(0.0f64, |m, h| m.max(h.abs()));
    let rms = moments.m0.sqrt();
    if largest > 0.0 && rms <= HEIGHT_RESOLUTION * largest {
        return Err(SurfaceError::Unresolved { rms, largest });
    }
    let parameters = Parameters::from_moments(&moments)?;
    let summits = (!work.is_profile()).then(|| SummitCount::of(&work));

    let mut warnings = Vec::new();
    let total = map.heights.len();
    let valid = map.valid_count();
    if valid < total {
        warnings.push(Warning::MissingPoints {
            missing: total - valid,
            total,
        });
    }
    if work.is_profile() {
        warnings.push(Warning::Profile);
    } else if let Some(used) = moments.only_along {
        let missing = if used == "x" { "y" } else { "x" };
        warnings.push(Warning::OneDirection { used, missing });
    } else {
        let ratio = moments.anisotropy_ratio();
        if ratio > ANISOTROPY_LIMIT {
            warnings.push(Warning::Anisotropy { ratio });
        }
    }
    if let Some(s) = &summits {
        let density_ratio = s.density / parameters.summit_density;
        let sigma_ratio = s.sigma.map(|x| x / parameters.summit_sigma);
        let radius_ratio = s.mean_radius.map(|x| x / parameters.summit_radius);
        let off = |r: f64| (r - 1.0).abs() > COUNTING_TOLERANCE;
        if off(density_ratio) || sigma_ratio.is_some_and(off) || radius_ratio.is_some_and(off) {
            warnings.push(Warning::CountingDisagrees {
                density_ratio,
                sigma_ratio,
                radius_ratio,
                cutoff_applied: settings.cutoff.is_some(),
            });
        }
    }
    let product = parameters.gw_product();
    if !(GW_PRODUCT_RANGE.0..=GW_PRODUCT_RANGE.1).contains(&product) {
        warnings.push(Warning::GwProductOutOfRange { product });
    }
    Ok(Roughness {
        nx: map.nx,
        ny: map.ny,
        pixel_size_x: map.pixel_size_x,
        pixel_size_y: map.pixel_size_y,
        valid_fraction: valid as f64 / total as f64,
        settings: *settings,
        kept_nx: work.nx,
        kept_ny: work.ny,
        edge_band: band,
        moments,
        parameters,
        summits,
        warnings,
    })
}
