//! `[roughness] topography = "scans/x.gsf"`: σ, R and N from a measured height map.
//!
//! ```toml
//! [roughness]
//! topography = "scans/self-affine.gsf"   # relative to the problem file
//! cutoff = "100 nm"                      # optional ISO 16610-61 short-wavelength cut-off
//! level = "plane"                        # none | plane (default) | quadratic
//! pixel_size = "20 nm"                   # only when the file gives none (.npy, bare ASCII)
//! height_unit = "nm"                     # likewise
//! ```
//!
//! in place of `sigma`, `asperity_radius` and `asperity_density`; giving both is refused.

use std::ops::Range;
use std::path::Path;

use serde::Serialize;
use toml::Spanned;

use super::raw::{RawQuantity, RawRoughness};
use super::{Accept, Location, ProblemError, Reader};
use crate::surface::read::{self, parse_height_unit, Format, Overrides};
use crate::surface::{analyse, Levelling, Roughness, Settings};
use crate::units::Dimension;

/// Where the scene's roughness came from when the file names a scan.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScanSource {
    /// `topography` as written in the problem file.
    pub topography: String,
    /// The path read (relative to the problem file's folder).
    pub path: String,
    /// The file's format.
    pub format: Format,
    /// The whole analysis (moments, parameters, summit count, warnings).
    pub roughness: Roughness,
    /// The pixel size and height unit the problem file gave (to read the map
    /// again as it was read).
    #[serde(skip)]
    pub overrides: Overrides,
    /// How the scene takes its real area: under `bem_corrected` a request the
    /// application layer fulfils after loading (`app::load` measures the ratio and
    /// fills [`ScanSource::correction`] and the scene's `real_area_scale`).
    pub contact_model: ContactModel,
    /// The measured exact-to-statistical correction under `bem_corrected`, once the
    /// application layer has measured it; `None` before and for `statistical`.
    #[serde(skip)]
    pub correction: Option<AreaCorrection>,
    /// Where `contact_model` was written (file and line) and its value as written: what
    /// [`ScanSource::contact_model_error`] names.
    #[serde(skip)]
    contact_model_written: Option<(Location, String)>,
}

/// What `contact_model = "bem_corrected"` measured on the scan at the file's
/// operating point (both sides without adhesion); the scene's `real_area_scale` is
/// `1 / ratio`.
#[derive(Debug, Clone, PartialEq)]
pub struct AreaCorrection {
    /// The nominal pressure W / A_n the scan was solved at (Pa).
    pub pressure: f64,
    /// The statistical model's real area over the exact one (finite, > 0).
    pub ratio: f64,
    /// The exact contact it measured, kept so that a report of the same operating
    /// point does not solve the scan again.
    pub exact: ExactContact,
}

/// The exact contact on a scan at one operating point, without its fields (what
/// the application layer's solve returns and a report reads).
#[derive(Debug, Clone, PartialEq)]
pub struct ExactContact {
    /// E* the scan was solved with (Pa).
    pub modulus: f64,
    /// The hardness that capped the pixels (Pa; infinite: none).
    pub hardness: f64,
    /// The analysed map's pixels, [nx, ny].
    pub pixels: [usize; 2],
    /// The solution, its pressure and gap fields dropped.
    pub solution: crate::contact::Solution,
}

impl ScanSource {
    /// A refusal of the file's `roughness.contact_model` (at its line, with its value
    /// as written) for `reason`: how the application layer words a request it cannot
    /// fulfil.
    pub fn contact_model_error(&self, reason: impl Into<String>) -> ProblemError {
        let (at, value) = self.contact_model_written.clone().unwrap_or_else(|| {
            (
                Location {
                    origin: self.path.clone(),
                    line: None,
                },
                format!("{:?}", self.contact_model.as_str()),
            )
        });
        ProblemError::InvalidValue {
            at,
            key: "roughness.contact_model".to_string(),
            value,
            reason: reason.into(),
        }
    }
}

/// The optional keys that only make sense with `topography`.
const SCAN_KEYS: [&str; 6] = [
    "cutoff",
    "level",
    "pixel_size",
    "height_unit",
    "contact_model",
    "decimal_comma",
];

/// How a scan-based scene's real area is taken (`[roughness] contact_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactModel {
    /// The statistical model's real area as it is (the default).
    #[default]
    Statistical,
    /// The statistical real area times the exact-to-statistical ratio of real
    /// areas on the scan at the file's operating point (nominal pressure, E*, H;
    /// no adhesion on either side), held fixed as a study moves the design.
    BemCorrected,
}

impl ContactModel {
    /// The name a problem file and the JSON use.
    pub fn as_str(self) -> &'static str {
        match self {
            ContactModel::Statistical => "statistical",
            ContactModel::BemCorrected => "bem_corrected",
        }
    }
}

impl Reader<'_> {
    /// σ, R, N and the source, when `[roughness]` names a topography; `None` otherwise
    /// (after refusing scan settings without a scan).
    pub(super) fn topography(
        &mut self,
        g: &RawRoughness,
    ) -> Result<Option<(f64, f64, f64, ScanSource)>, ProblemError> {
        let Some(topo) = &g.topography else {
            let given: [(&str, Option<Range<usize>>); 6] = [
                ("contact_model", g.contact_model.as_ref().map(|v| v.span())),
                ("decimal_comma", g.decimal_comma.as_ref().map(|v| v.span())),
                ("cutoff", g.cutoff.as_ref().map(|v| v.span())),
                ("level", g.level.as_ref().map(|v| v.span())),
                ("pixel_size", g.pixel_size.as_ref().map(|v| v.span())),
                ("height_unit", g.height_unit.as_ref().map(|v| v.span())),
            ];
            if let Some((key, Some(span))) = given.into_iter().find(|(_, s)| s.is_some()) {
                return Err(self.invalid(
                    &format!("roughness.{key}"),
                    &span,
                    format!(
                        "applies only to a measured scan; add topography = \"scans/your-scan.gsf\" or remove {key} (scan settings: {})",
                        SCAN_KEYS.join(", ")
                    ),
                ));
            }
            return Ok(None);
        };
        let tspan = topo.span();
        for (key, value) in [
            ("sigma", &g.sigma),
            ("asperity_radius", &g.asperity_radius),
            ("asperity_density", &g.asperity_density),
        ] {
            if let Some(v) = value {
                return Err(self.invalid(
                    &format!("roughness.{key}"),
                    &v.span(),
                    format!(
                        "clashes with roughness.topography (line {}): the scan supplies σ, R and N; give either topography or sigma, asperity_radius and asperity_density, not both",
                        super::line_of(self.text, tspan.start)
                    ),
                ));
            }
        }
        let written = topo.get_ref().clone();
        if written.trim().is_empty() {
            return Err(self.invalid(
                "roughness.topography",
                &tspan,
                "must name a height-map file (.gsf, .x3p, .npy, or an ASCII matrix)",
            ));
        }
        let base = Path::new(self.origin)
            .parent()
            .unwrap_or_else(|| Path::new(""));
        let path = base.join(&written);
        let length = |r: &Self, key: &str, v: &Option<Spanned<RawQuantity>>| {
            r.optional_quantity(key, v, Accept::positive(Dimension::Length))
        };
        let cutoff = length(self, "roughness.cutoff", &g.cutoff)?;
        let pixel_size = length(self, "roughness.pixel_size", &g.pixel_size)?;
        let height_unit = match &g.height_unit {
            None => None,
            Some(u) => Some(parse_height_unit(u.get_ref()).ok_or_else(|| {
                self.invalid(
                    "roughness.height_unit",
                    &u.span(),
                    "not a length unit; expected e.g. \"nm\", \"um\", \"m\" or \"1e-9\"",
                )
            })?),
        };
        let level = match &g.level {
            None => Levelling::Plane,
            Some(l) => Levelling::from_name(l.get_ref()).ok_or_else(|| {
                self.invalid(
                    "roughness.level",
                    &l.span(),
                    format!(
                        "unknown levelling (one of: {})",
                        Levelling::NAMES.join(", ")
                    ),
                )
            })?,
        };
        let overrides = Overrides {
            pixel_size,
            height_unit,
            decimal_comma: g.decimal_comma.as_ref().is_some_and(|v| *v.get_ref()),
        };
        let scan_error = |r: &Self, e: String| r.invalid("roughness.topography", &tspan, e);
        let map = read::load(&path, &overrides).map_err(|e| scan_error(self, e.to_string()))?;
        let settings = Settings { level, cutoff };
        let roughness = analyse(&map, &settings)
            .map_err(|e| scan_error(self, format!("{}: {e}", path.display())))?;
        let contact_model = match &g.contact_model {
            None => ContactModel::Statistical,
            Some(m) => match m.get_ref().as_str() {
                "statistical" => ContactModel::Statistical,
                "bem_corrected" => ContactModel::BemCorrected,
                other => {
                    return Err(self.invalid(
                        "roughness.contact_model",
                        &m.span(),
                        format!(
                            "unknown contact model {other:?} (one of: statistical, bem_corrected)"
                        ),
                    ))
                }
            },
        };
        let p = roughness.parameters;
        let contact_model_written = g.contact_model.as_ref().map(|m| {
            (
                self.at(Some(&m.span())),
                super::written(self.text, &m.span()),
            )
        });
        let source = ScanSource {
            contact_model,
            correction: None,
            contact_model_written,
            topography: written,
            path: path.display().to_string(),
            format: Format::from_path(&path).unwrap_or(Format::Ascii),
            roughness,
            overrides,
        };
        Ok(Some((
            p.summit_sigma,
            p.summit_radius,
            p.summit_density,
            source,
        )))
    }
}
