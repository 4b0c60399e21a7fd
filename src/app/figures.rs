//! `wearopt figures`: the paper's figures 1–4, the least-squares line of every
//! curve, and a verdict on each claim of its §4.

use std::path::{Path, PathBuf};

use crate::figures::{assess_claims, compute_figures, paper_figures};

use super::AppError;

pub use crate::figures::{Claim, Figure, FigureSettings, MAX_POINTS};

/// One file of the figures' output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FigureFile {
    /// `figureN.csv` of the figure at this index of [`FiguresDocument::figures`].
    Csv(usize),
    /// `figureN.svg` of the figure at this index.
    Svg(usize),
    /// `slopes.csv`: the least-squares line of every curve.
    Slopes,
}

/// What `wearopt figures` computes.
#[derive(Debug, Clone)]
pub struct FiguresDocument {
    /// The settings the figures were computed with.
    pub settings: FigureSettings,
    /// The figures.
    pub figures: Vec<Figure>,
    /// The claims of the paper's §4, judged.
    pub claims: Vec<Claim>,
    /// The files the figures make, under the folder asked for, in the order they
    /// are listed (the adapter writes each as the report renders it).
    pub files: Vec<(PathBuf, FigureFile)>,
}

impl FiguresDocument {
    /// Whether some load had no converged separation (the command line's exit 1).
    pub fn incomplete(&self) -> bool {
        self.figures
            .iter()
            .flat_map(|f| &f.curves)
            .any(|c| c.failed > 0 || c.fit.is_none())
    }
}

/// Computes the figures with `settings`, their files named under `folder`.
pub fn figures(settings: &FigureSettings, folder: &Path) -> Result<FiguresDocument, AppError> {
    settings.validate().map_err(AppError::Figures)?;
    let figures = compute_figures(&paper_figures(), settings);
    let claims = assess_claims(&figures);
    let mut files = Vec::new();
    for (i, f) in figures.iter().enumerate() {
        let n = f.spec.number;
        files.push((folder.join(format!("figure{n}.csv")), FigureFile::Csv(i)));
        files.push((folder.join(format!("figure{n}.svg")), FigureFile::Svg(i)));
    }
    files.push((folder.join("slopes.csv"), FigureFile::Slopes));
    Ok(FiguresDocument {
        settings: *settings,
        figures,
        claims,
        files,
    })
}
