//! `barylab grade`: a whole class's images against barylab's renders of the course scenes.
//!
//! Each scene is loaded, rendered and made every way [`compare`] tries (its
//! [`Candidates`]) once; every submission is then compared with
//! [`compare::compare_with`] in parallel (rayon), so a verdict, its named bugs and the
//! reasons of its regions are exactly `barylab compare`'s. A submission that cannot be
//! compared (not an image, the wrong size, truncated, a FIFO, missing) is a row with the
//! reason. [`report`] writes the rows as a self-contained HTML page and as CSV.

pub mod assign;
pub mod report;
mod submissions;

use std::path::{Path, PathBuf};

use rayon::prelude::*;

pub use submissions::{Job, find_jobs};

use crate::compare::hypotheses::Candidates;
use crate::compare::{self, Comparison, Reference};
use crate::files::shown;
use crate::i18n::Lang;
use crate::raster::render::Render;
use crate::raster::{ClipMesh, RenderSettings, Texture};
use crate::scene::Scene;

/// Longest side of the difference thumbnails in the report, in pixels.
pub const THUMBNAIL: u32 = 160;

/// A scene ready for grading: loaded, rendered once, with its candidate explanations.
pub struct GradeScene {
    /// The name submissions are matched by: the file name without `.json`.
    pub name: String,
    /// The scene file.
    pub path: PathBuf,
    scene: Scene,
    mesh: ClipMesh,
    texture: Texture,
    settings: RenderSettings,
    render: Render,
    candidates: Candidates,
}

impl GradeScene {
    /// Loads the scene file at `path` and makes barylab's render and the candidates. The
    /// error names the file.
    pub fn load(path: &Path) -> Result<Self, String> {
        let failed = |e: &dyn std::fmt::Display| format!("{}: {e}", shown(path));
        let scene = Scene::load(path).map_err(|e| e.to_string())?;
        let base = path.parent().unwrap_or(Path::new("."));
        let texture = scene.load_texture(base).map_err(|e| e.to_string())?;
        let settings = scene.settings();
        let mesh = scene.to_mesh();
        let render =
            compare::render_for_comparison(&mesh, &texture, &settings).map_err(|e| failed(&e))?;
        let reference = Reference {
            scene: &scene,
            mesh: &mesh,
            texture: &texture,
            settings,
        };
        let candidates = Candidates::new(&reference, &render.frame).map_err(|e| failed(&e))?;
        let name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        Ok(Self {
            name,
            path: path.to_path_buf(),
            scene,
            mesh,
            texture,
            settings,
            render,
            candidates,
        })
    }

    /// The image size the scene renders.
    pub fn size(&self) -> (u32, u32) {
        (self.settings.width, self.settings.height)
    }

    /// barylab's image of the scene as PNG-ready pixels.
    pub fn image(&self) -> Option<image::RgbaImage> {
        compare::Rendered::of(&self.render.frame).to_image(self.settings.width)
    }

    /// The files the scene reads (the scene file, its texture or model).
    pub fn inputs(&self) -> Vec<PathBuf> {
        let mut files = self
            .scene
            .input_files(self.path.parent().unwrap_or(Path::new(".")));
        files.push(self.path.clone());
        files
    }

    /// Compares one submitted image file with the scene: the comparison and the difference
    /// thumbnail (PNG bytes), or why it could not be compared, in `lang`.
    pub fn grade(&self, file: &Path, tolerance: u8, lang: Lang) -> Result<Graded, String> {
        let size = self.size();
        let image = compare::read_image(file, lang, |w, h| {
            if (w, h) == size {
                Ok(())
            } else {
                Err(lang.tr_with(
                    "grade.wrong_size",
                    &[("w", &w), ("h", &h), ("sw", &size.0), ("sh", &size.1)],
                ))
            }
        })?;
        let by = compare::coverage_for(&image, &self.settings, None);
        let reference = Reference {
            scene: &self.scene,
            mesh: &self.mesh,
            texture: &self.texture,
            settings: self.settings,
        };
        let comparison = compare::compare_with(
            &image,
            &reference,
            &self.render,
            Some(&self.candidates),
            by,
            tolerance,
        )?;
        let diff = compare::difference_image_of(&image, &self.render.frame, by, tolerance);
        Ok(Graded {
            comparison,
            thumbnail: thumbnail_png(&diff),
        })
    }
}

/// A compared submission.
#[derive(Clone, Debug)]
pub struct Graded {
    /// `barylab compare`'s result.
    pub comparison: Comparison,
    /// The difference image, at most [`THUMBNAIL`] pixels on its longer side (small images
    /// are enlarged by whole pixels), as PNG.
    pub thumbnail: Vec<u8>,
}

/// Pass, fail, or could not be compared.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The image agrees with barylab's render.
    Pass,
    /// It differs.
    Fail,
    /// It could not be compared (the row's problem says why).
    Bad,
}

impl Verdict {
    /// The code in the CSV: `pass`, `fail`, `bad`.
    pub fn code(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "fail",
            Verdict::Bad => "bad",
        }
    }

    /// The verdict in a word, in `lang`.
    pub fn word(self, lang: Lang) -> String {
        lang.tr(&format!("grade.verdict.{}", self.code()))
    }
}

/// One submission's result: a student's image for one scene.
#[derive(Clone, Debug)]
pub struct Row {
    /// The student: the file name without extension, or the folder's name.
    pub student: String,
    /// The scene's name ([`GradeScene::name`]).
    pub scene: String,
    /// The image file (`None`: no image for this scene in the student's folder).
    pub file: Option<PathBuf>,
    /// The comparison, or the problem in words.
    pub outcome: Result<Graded, String>,
}

impl Row {
    /// Pass, fail or bad.
    pub fn verdict(&self) -> Verdict {
        match &self.outcome {
            Ok(g) if g.comparison.agrees() => Verdict::Pass,
            Ok(_) => Verdict::Fail,
            Err(_) => Verdict::Bad,
        }
    }
}

/// Grades every job in parallel; rows in the order of `jobs`.
pub fn grade_all(scenes: &[GradeScene], jobs: &[Job], tolerance: u8, lang: Lang) -> Vec<Row> {
    jobs.par_iter()
        .map(|job| {
            let outcome = match (&job.file, job.problem.as_ref(), scenes.get(job.scene)) {
                (_, Some(p), _) => Err(p.clone()),
                (Some(file), None, Some(scene)) => scene.grade(file, tolerance, lang),
                (None, None, _) => Err(lang.tr("grade.missing")),
                (_, None, None) => Err(lang.tr("grade.no_scene")),
            };
            Row {
                student: job.student.clone(),
                scene: scenes
                    .get(job.scene)
                    .map(|s| s.name.clone())
                    .unwrap_or_default(),
                file: job.file.clone(),
                outcome,
            }
        })
        .collect()
}

/// The difference image scaled to fit [`THUMBNAIL`] (nearest neighbour, so pixels stay
/// sharp), as PNG bytes (empty if encoding fails).
fn thumbnail_png(diff: &image::RgbaImage) -> Vec<u8> {
    let (w, h) = diff.dimensions();
    let longer = w.max(h).max(1);
    let (tw, th) = if longer > THUMBNAIL {
        (
            (w * THUMBNAIL / longer).max(1),
            (h * THUMBNAIL / longer).max(1),
        )
    } else {
        let k = (THUMBNAIL / longer).max(1);
        (w * k, h * k)
    };
    let small = image::imageops::resize(diff, tw, th, image::imageops::FilterType::Nearest);
    let mut png = Vec::new();
    match small.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png) {
        Ok(()) => png,
        Err(_) => Vec::new(),
    }
}
