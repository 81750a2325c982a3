//! Writing a figure's files into a folder: the PNG, the SVG, the marked pixel's derivation as
//! Markdown and LaTeX, and the scene file that reproduces the figure. Names are fresh
//! (`figure-001.png`, `figure-002.png`, ...): nothing is ever overwritten.

use std::path::{Path, PathBuf};

use super::{Figure, FigureError, png, svg};
use crate::probe::format::{self, Format};
use crate::scene::Scene;

/// Which files an export writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct ExportSelection {
    /// The annotated figure as PNG (`.png`).
    pub png: bool,
    /// The figure as SVG (`.svg`).
    pub svg: bool,
    /// The pinned (else the hovered) pixel's derivation, as `.md` and `.tex`.
    pub derivation: bool,
    /// The scene as JSON (`.json`), sized as rendered, texture and model paths absolute.
    pub scene: bool,
}

impl Default for ExportSelection {
    fn default() -> Self {
        Self {
            png: true,
            svg: true,
            derivation: true,
            scene: true,
        }
    }
}

/// Why an export failed. Nothing of the scene is changed by a failed export.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error("cannot use folder {path}: {cause}")]
    /// The folder cannot be made or used.
    Folder {
        /// The folder, as shown to the user.
        path: String,
        /// Why.
        cause: std::io::Error,
    },
    /// A file could not be written.
    #[error(transparent)]
    Write(#[from] crate::files::WriteError),
    #[error("no free file name {stem}-001 ... {stem}-{last} in {folder}", last = MAX_NUMBER)]
    /// Every name from 001 to [`MAX_NUMBER`] is taken.
    NoFreeName {
        /// The names' stem (`figure`).
        stem: String,
        /// The folder, as shown to the user.
        folder: String,
    },
    /// The figure could not be made.
    #[error(transparent)]
    Figure(#[from] FigureError),
}

/// The highest number tried for a fresh name.
pub const MAX_NUMBER: u32 = 9999;

/// The file extensions an export may write (a name is fresh only if none of them exists).
pub const EXTENSIONS: [&str; 5] = ["png", "svg", "md", "tex", "json"];

/// The first `STEM-NNN` (from 001) for which no `STEM-NNN.EXT` exists in `folder` for any of
/// `extensions`.
pub fn fresh_stem(folder: &Path, stem: &str, extensions: &[&str]) -> Result<String, ExportError> {
    (1..=MAX_NUMBER)
        .map(|k| format!("{stem}-{k:03}"))
        .find(|name| {
            extensions
                .iter()
                .all(|ext| !folder.join(format!("{name}.{ext}")).exists())
        })
        .ok_or_else(|| ExportError::NoFreeName {
            stem: stem.to_string(),
            folder: crate::files::shown(folder),
        })
}

/// Creates `folder` (and its parents) if needed; the error names it.
pub fn prepare_folder(folder: &Path) -> Result<(), ExportError> {
    std::fs::create_dir_all(folder).map_err(|cause| ExportError::Folder {
        path: crate::files::shown(folder),
        cause,
    })
}

/// Writes `bytes` to a new file, atomically (a temporary file renamed into place); fails
/// (never overwrites) if it exists.
pub fn write_new(path: &Path, bytes: &[u8]) -> Result<(), ExportError> {
    Ok(crate::files::write_new(path, bytes)?)
}

/// The scene file of a figure: `scene` (sized as rendered) with its texture and model paths
/// made absolute against `scene_dir`, so it loads from wherever it is saved.
pub fn scene_json(scene: &Scene, scene_dir: Option<&Path>) -> String {
    let dir = scene_dir.unwrap_or(Path::new(""));
    scene.with_absolute_paths(dir).to_json()
}

/// Everything one export writes.
pub struct ExportRequest<'a> {
    /// The folder to write into (made if needed).
    pub folder: &'a Path,
    /// File names start with this (`figure` gives `figure-001.png`, ...).
    pub stem: &'a str,
    /// The figure to write.
    pub figure: &'a Figure,
    /// The scene the figure shows (sized as rendered).
    pub scene: &'a Scene,
    /// The folder the scene's relative paths are relative to.
    pub scene_dir: Option<&'a Path>,
    /// Which files to write.
    pub selection: ExportSelection,
}

/// Writes the selected files under one fresh name; returns the files written. The derivation
/// is skipped when no pixel is marked.
pub fn export(request: &ExportRequest<'_>) -> Result<Vec<PathBuf>, ExportError> {
    let r = request;
    let sel = r.selection;
    // Everything is made before anything is written: a failure leaves no half export.
    let mut files: Vec<(&str, Vec<u8>)> = Vec::new();
    if sel.png {
        files.push(("png", png::to_png(r.figure)?));
    }
    if sel.svg {
        files.push(("svg", svg::to_svg(r.figure)?.into_bytes()));
    }
    if sel.derivation
        && let Some(trace) = r.figure.pinned.as_ref().or(r.figure.hovered.as_ref())
    {
        // The derivation in the figure's language (LaTeX stays English: see docs/probe.md).
        let lang = r.figure.lang;
        let md = format::write_in(trace, Format::Markdown, lang);
        files.push(("md", md.into_bytes()));
        files.push((
            "tex",
            format::write_in(trace, Format::Latex, lang).into_bytes(),
        ));
    }
    if sel.scene {
        files.push(("json", scene_json(r.scene, r.scene_dir).into_bytes()));
    }
    prepare_folder(r.folder)?;
    let stem = fresh_stem(r.folder, r.stem, &EXTENSIONS)?;
    let mut written = Vec::new();
    for (ext, bytes) in files {
        let path = r.folder.join(format!("{stem}.{ext}"));
        write_new(&path, &bytes)?;
        written.push(path);
    }
    Ok(written)
}
