//! The exact contact on a scene's own scan at its operating point, and the
//! statistical model on the same terms: what `wearopt eval` reports for a
//! scan-based scene and what `[roughness] contact_model = "bem_corrected"` scales
//! the statistical real area by. The problem file keeps the request; [`fulfil`]
//! (run by [`super::load`] and [`super::parse`]) solves the scan and sets the scale.

use std::path::Path;

use crate::contact::{Settings as SolveSettings, Solution, Solver};
use crate::model::{evaluate, AdhesionModel, EvaluationOptions, Scene, Status, WearArea};
use crate::surface::analysed_map;
use crate::surface::read;

use crate::problem::{
    AreaCorrection, ContactModel, ExactContact, Problem, ProblemError, ScanSource,
};

/// The statistical model on the same map at the same mean pressure: McCool's σ,
/// R and N of the levelled map, no adhesion, H as given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statistical {
    /// Real area / nominal area.
    pub real_area_fraction: f64,
    /// Plastic real area / nominal area.
    pub plastic_area_fraction: f64,
    /// Asperities in contact over the map.
    pub contact_count: f64,
    /// The model's separation over σ (from the mean of summit heights).
    pub separation: Option<f64>,
    /// The evaluation's status.
    pub status: Status,
}

/// The statistical model's contact without adhesion at mean pressure `pressure`
/// over a nominal area `area`: summit σ, R and density `gw`, composite modulus
/// `modulus`, hardness `hardness` (infinite: elastic).
pub fn statistical(
    gw: [f64; 3],
    modulus: f64,
    hardness: f64,
    pressure: f64,
    area: f64,
) -> Statistical {
    let [sigma, asperity_radius, asperity_density] = gw;
    let scene = Scene {
        // E* itself: ν = 0 on a rigid counterface.
        youngs_modulus_a: modulus,
        poisson_ratio_a: 0.0,
        youngs_modulus_b: f64::INFINITY,
        poisson_ratio_b: 0.0,
        hardness,
        work_of_adhesion: 0.0,
        // Without adhesion Z0 enters nothing.
        interatomic_distance: 0.3e-9,
        sigma,
        asperity_radius,
        asperity_density,
        load: pressure * area,
        nominal_area: area,
        sliding_distance: 0.0,
        wear_coefficient: 0.0,
        wear_area: WearArea::Total,
        wear_law: Default::default(),
        temperature: 298.15,
        activation: None,
        real_area_scale: 1.0,
        requirements: Default::default(),
        adhesion_model: AdhesionModel::Jkr,
        attraction: Default::default(),
        environment: None,
    };
    let ev = evaluate(
        &scene,
        &EvaluationOptions {
            pull_off: false,
            work_of_adhesion: false,
            ..EvaluationOptions::default()
        },
    );
    Statistical {
        real_area_fraction: ev.real_area_fraction,
        plastic_area_fraction: ev.plastic_area_fraction,
        contact_count: ev.contact_count,
        separation: ev.nondimensional_separation,
        status: ev.status,
    }
}

/// The exact contact on a scene's own scan at its operating point (what
/// `wearopt eval` adds for a scan-based scene).
#[derive(Debug, Clone, PartialEq)]
pub struct ScanContact {
    /// The nominal pressure W / A_n (Pa).
    pub pressure: f64,
    /// The scene's composite modulus E* (Pa).
    pub modulus: f64,
    /// The scene's hardness (Pa; infinite: elastic).
    pub hardness: f64,
    /// Points along x and y of the map solved (after any cut-off's edge band).
    pub pixels: [usize; 2],
    /// The boundary-element solution on the scan (no fields).
    pub solution: Solution,
    /// The statistical model without adhesion, the scene's σ, R, N, E* and H, at
    /// the same pressure: the like-for-like comparison.
    pub statistical: Statistical,
}

impl ScanContact {
    /// The statistical model's real area over the exact one (both without adhesion).
    /// None where the statistical model has no usable answer (out of its range).
    pub fn area_ratio(&self) -> Option<f64> {
        (self.solution.real_area_fraction > 0.0 && self.statistical.status == Status::Ok)
            .then(|| self.statistical.real_area_fraction / self.solution.real_area_fraction)
    }
}

/// The exact contact of the scene's scan at its nominal pressure, or why there
/// is none (a tensile load, a pressure at or above H, a map the solver cannot
/// take): words for the report, not an error of the scene.
pub fn scan_contact(scan: &ScanSource, scene: &Scene, modulus: f64) -> Result<ScanContact, String> {
    let pressure = scene.load / scene.nominal_area;
    // The solve `contact_model = "bem_corrected"` made at load, where it was at
    // this operating point (the statistical side is cheap: taken again).
    let kept = scan.correction.as_ref().map(|c| &c.exact).filter(|e| {
        e.solution.pressure == pressure && e.modulus == modulus && e.hardness == scene.hardness
    });
    let exact = match kept {
        Some(e) => e.clone(),
        None => exact_contact(scan, scene, modulus)?,
    };
    let statistical = statistical(
        [scene.sigma, scene.asperity_radius, scene.asperity_density],
        modulus,
        scene.hardness,
        pressure,
        scene.nominal_area,
    );
    Ok(ScanContact {
        pressure,
        modulus,
        hardness: scene.hardness,
        pixels: exact.pixels,
        solution: exact.solution,
        statistical,
    })
}

/// The exact contact of the scene's scan at its nominal pressure (the solve
/// [`scan_contact`] reports), or why there is none.
fn exact_contact(scan: &ScanSource, scene: &Scene, modulus: f64) -> Result<ExactContact, String> {
    let pressure = scene.load / scene.nominal_area;
    if pressure <= 0.0 {
        return Err(format!(
            "the load is {} N: the contact solver takes a compressive load",
            scene.load
        ));
    }
    if pressure >= scene.hardness {
        return Err("the nominal pressure is not below the hardness".to_string());
    }
    let map = read::load(Path::new(&scan.path), &scan.overrides).map_err(|e| e.to_string())?;
    if map.heights().iter().any(|h| !h.is_finite()) {
        let missing = map.heights().iter().filter(|h| !h.is_finite()).count();
        return Err(format!(
            "{missing} of {} points of the scan are missing; the contact solver needs a complete map",
            map.heights().len()
        ));
    }
    let work = analysed_map(&map, &scan.roughness.settings).map_err(|e| e.to_string())?;
    let (nx, ny) = (work.nx(), work.ny());
    let mut solver = Solver::new(
        nx,
        ny,
        work.pixel_size_x(),
        work.pixel_size_y(),
        work.heights(),
        modulus,
    )
    .map_err(|e| e.to_string())?;
    let settings = SolveSettings {
        hardness: scene.hardness,
        ..SolveSettings::default()
    };
    let mut solution = solver
        .solve(pressure, &settings, None)
        .map_err(|e| e.to_string())?;
    solution.pressures = Vec::new();
    solution.gaps = Vec::new();
    Ok(ExactContact {
        modulus,
        hardness: scene.hardness,
        pixels: [nx, ny],
        solution,
    })
}

/// Fulfils what a loaded problem asks of the contact solver: under
/// `contact_model = "bem_corrected"`, the exact contact on the scan at the scene's
/// operating point ([`scan_contact`]), and the scene's real-area scale set to the
/// exact-to-statistical ratio of real areas (both without adhesion; held fixed as a
/// study moves the design). Other problems pass unchanged. A ratio that cannot be
/// measured is an error of the file's `roughness.contact_model`, naming why
/// (`tests/all/contact.rs` holds both).
pub fn fulfil(mut problem: Problem) -> Result<Problem, ProblemError> {
    let Some(scan) = problem
        .scan
        .as_mut()
        .filter(|s| s.contact_model == ContactModel::BemCorrected)
    else {
        return Ok(problem);
    };
    let modulus = crate::model::wear::equivalent_modulus(&problem.scene);
    let exact = scan_contact(scan, &problem.scene, modulus).map_err(|why| {
        scan.contact_model_error(format!(
            "\"bem_corrected\" needs the exact contact on the scan at the operating point, which cannot be had: {why}"
        ))
    })?;
    let Some(ratio) = exact.area_ratio().filter(|r| r.is_finite() && *r > 0.0) else {
        return Err(scan.contact_model_error(
            "\"bem_corrected\": the exact contact on the scan has no real area to compare with at the operating point",
        ));
    };
    problem.scene.real_area_scale = 1.0 / ratio;
    scan.correction = Some(AreaCorrection {
        pressure: exact.pressure,
        ratio,
        exact: ExactContact {
            modulus: exact.modulus,
            hardness: exact.hardness,
            pixels: exact.pixels,
            solution: exact.solution,
        },
    });
    Ok(problem)
}
