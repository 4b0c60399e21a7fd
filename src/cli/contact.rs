//! `wearopt contact`: a height map in, its exact contact at each mean pressure out,
//! beside the statistical model's.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::Args;

use wearopt::app::contact::{self as ct, ContactOptions};
use wearopt::app::quantity::OptionQuantity as Q;
use wearopt::app::roughness as rough;
use wearopt::app::{AppError, OptionName};
use wearopt::report::{self, Format};

use super::format::formats;
use super::roughness::LevelArg;
use super::write_output;

#[derive(Debug, Args)]
pub(crate) struct ContactArgs {
    /// The height map: .gsf, .x3p, .npy (shape (ny, nx)) or an ASCII matrix; taken as one
    /// period of a periodic surface, complete (no missing points), at least 8 × 8.
    scan: PathBuf,
    /// Pixel size (both directions), e.g. "20 nm"; required for .npy and a bare ASCII
    /// matrix, overrides the file's otherwise.
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pixel_size: Option<String>,
    /// The unit of the stored heights, e.g. "nm" or "1e-9"; required for .npy and a bare
    /// ASCII matrix, overrides the file's otherwise.
    #[arg(long, value_name = "UNIT")]
    height_unit: Option<String>,
    /// The ASCII matrix writes its decimals with commas ("1,25"; columns then separated by
    /// whitespace or semicolons). Such a file is refused without it.
    #[arg(long)]
    decimal_comma: bool,
    /// The composite modulus E* of the pair, 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2, e.g. "150 GPa".
    #[arg(long, value_name = "E_STAR", allow_hyphen_values = true)]
    modulus: String,
    /// The mean (nominal) pressure, or several comma-separated, e.g. "50 MPa,100 MPa,200 MPa".
    #[arg(long, value_name = "P1[,P2,…]", allow_hyphen_values = true)]
    pressure: String,
    /// Cap every pixel's pressure at the hardness H (elastic–perfectly plastic), e.g. "10 GPa".
    #[arg(long, value_name = "H", allow_hyphen_values = true)]
    hardness: Option<String>,
    /// Form removal before the solve.
    #[arg(long, value_enum, default_value_t = LevelArg::Plane)]
    level: LevelArg,
    /// The residual at which each solve stops (see docs/contact.md).
    #[arg(long, value_name = "TOL", default_value_t = ct::DEFAULT_TOLERANCE, allow_hyphen_values = true)]
    tolerance: f64,
    /// Add an attraction between the surfaces, the exponential law −γ e^{−g/ρ}: its work of
    /// adhesion γ, e.g. "50 mJ/m^2" (with --adhesion-range). Solved beside the adhesion-free
    /// contact, elastic, along the approach; the pull-off of the map is reported.
    #[arg(
        long,
        value_name = "GAMMA",
        allow_hyphen_values = true,
        requires = "adhesion_range"
    )]
    work_of_adhesion: Option<String>,
    /// The range ρ of the attraction, e.g. "1 nm" (with --work-of-adhesion). The map must
    /// resolve it: the process zone π E* ρ²/(4γ) must span 3 pixels or more.
    #[arg(
        long,
        value_name = "RHO",
        allow_hyphen_values = true,
        requires = "work_of_adhesion"
    )]
    adhesion_range: Option<String>,
    /// Where the map cannot resolve ρ, raise it to a well-resolved range (a process zone of
    /// 6 pixels; the report says by how much) instead of refusing.
    #[arg(long, requires = "work_of_adhesion")]
    coarse_grain: bool,
    /// Output format.
    #[arg(long, value_parser = formats("contact", report::contact::FORMATS), default_value = "text")]
    format: Format,
    /// Write the plot of real area against pressure, both models, as SVG ("-": stdout).
    #[arg(long, value_name = "AREA.svg")]
    plot: Option<PathBuf>,
    /// Write each pressure's pressure and gap fields as .npy into this folder (made if absent)
    /// (pressure_1.npy, gap_1.npy, … in the order of --pressure; Pa and m, shape (ny, nx));
    /// with adhesion also adhesive_pressure_1.npy, adhesive_gap_1.npy, ….
    #[arg(long, value_name = "DIR")]
    fields: Option<PathBuf>,
}

/// The fields `--fields` writes: (name, 1-based pressure number), in order.
fn field_names(pressures: usize, adhesion: bool) -> Vec<(&'static str, usize)> {
    let names: &[&'static str] = if adhesion {
        &["pressure", "gap", "adhesive_pressure", "adhesive_gap"]
    } else {
        &["pressure", "gap"]
    };
    (1..=pressures)
        .flat_map(|i| names.iter().map(move |&n| (n, i)))
        .collect()
}

pub(crate) fn run(args: ContactArgs) -> Result<ExitCode> {
    let pixel_size = args
        .pixel_size
        .as_deref()
        .map(|t| rough::length(OptionName("pixel_size"), t))
        .transpose()?;
    let height_unit = args
        .height_unit
        .as_deref()
        .map(|t| rough::height_unit(OptionName("height_unit"), t))
        .transpose()?;
    let modulus = ct::positive(OptionName("modulus"), &args.modulus, Q::Modulus)?;
    let pressures = ct::pressures(OptionName("pressure"), &args.pressure)?;
    let hardness = args
        .hardness
        .as_deref()
        .map(|t| ct::positive(OptionName("hardness"), t, Q::Hardness))
        .transpose()?;
    let adhesion = match (&args.work_of_adhesion, &args.adhesion_range) {
        (Some(w), Some(r)) => Some(ct::AdhesionOptions {
            work: ct::positive(OptionName("work_of_adhesion"), w, Q::WorkOfAdhesion)?,
            range: ct::positive(OptionName("adhesion_range"), r, Q::AttractionRange)?,
            coarse_grain: args.coarse_grain,
        }),
        _ => None,
    };
    // The outputs are checked before the solves, which take seconds to minutes.
    if let Some(path) = &args.plot {
        if path.as_os_str() == "-" && args.format != Format::Text {
            return Err(super::usage(format!(
                "--plot - would write the SVG to stdout, where the {} report goes: give --plot a file name (--plot area.svg), or use --format text",
                args.format.as_str()
            )));
        }
        super::check_output(path, "the area plot", &[&args.scan])?;
    }
    // The folder is made as `figures --out` makes its own, before the solves, and
    // each field's file is checked there: writable, not the scan, not a link
    // (which the write would follow to overwrite its target).
    if let Some(dir) = &args.fields {
        std::fs::create_dir_all(dir).map_err(|e| AppError::Output {
            option: OptionName("fields"),
            path: dir.display().to_string(),
            reason: e.to_string(),
        })?;
        for (name, i) in field_names(pressures.len(), adhesion.is_some()) {
            let path = dir.join(format!("{name}_{i}.npy"));
            if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink()) {
                return Err(super::usage(format!(
                    "--fields {}: {} is a symbolic link, and writing the field would overwrite what it points to: remove it or choose another folder",
                    dir.display(),
                    path.display()
                )));
            }
            super::check_output(&path, "a field", &[&args.scan])?;
        }
    }
    let options = ContactOptions {
        modulus,
        pressures,
        hardness,
        level: args.level.into(),
        pixel_size,
        height_unit,
        decimal_comma: args.decimal_comma,
        tolerance: args.tolerance,
        fields: args.fields.is_some() || args.format == Format::Html,
        adhesion,
    };
    let bar = super::progress::Bar(super::progress::bar(Some(0), "solves"));
    let doc = ct::contact_with(&args.scan, &options, &bar)?;
    drop(bar);
    if let Some(path) = &args.plot {
        write_output(path, &report::contact::area_plot(&doc), "the area plot")?;
    }
    if let Some(dir) = &args.fields {
        let [nx, ny] = doc.pixels;
        for (i, pt) in doc.points.iter().enumerate() {
            let mut fields = vec![
                ("pressure", &pt.solution.pressures),
                ("gap", &pt.solution.gaps),
            ];
            if let Some(a) = &pt.adhesive {
                fields.push(("adhesive_pressure", &a.pressures));
                fields.push(("adhesive_gap", &a.gaps));
            }
            for (name, field) in fields {
                let path = dir.join(format!("{name}_{}.npy", i + 1));
                std::fs::write(&path, report::contact::npy(nx, ny, field))
                    .map_err(|e| super::unwritable(&path, "a field", &e))?;
            }
        }
    }
    super::print_out(&report::contact::render(&doc, args.format)?)?;
    // A row that is not a solution is no usable result (the report says which).
    Ok(if doc.failed() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
