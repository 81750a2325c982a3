//! Lessons: a guided walk through the maths, step by step (`docs/lessons.md`).
//!
//! A lesson is a JSON file: a title and steps. Each step has a title, a text, a "try this"
//! prompt, each in English and Simplified Chinese ([`Text`]), and the state it sets: a scene
//! (inline, a file relative to the lesson, or a built-in one), the interpolation mode, the
//! comparison, shading, filter, wireframe and overlays, the image and pixel size, the pinned
//! pixel, the open inspector sections and an optional [`LessonPlot`].
//!
//! Reading is strict: unknown fields, a missing language, an empty text, a scene that does
//! not load and a pin outside the image are errors naming the file, the line and the field
//! ([`LessonError`]). [`Lesson::state`] turns a step into a [`StepState`], which the app, the
//! figures and the handout ([`handout`]) all use. No egui here.

pub mod builtin;
pub mod handout;
mod parse;
pub mod plot;
pub mod quiz_sheet;
mod sheet;
pub mod slides;
pub mod text;

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::figure::{Compare, FigureOptions};
use crate::files::ReadError;
use crate::i18n::Lang;
use crate::probe::quiz::{Quantity, Question};
use crate::raster::render::Rasterizer;
use crate::raster::{Filter, Interpolation, Shading};
use crate::scene::Scene;

pub use parse::{load, parse_str};
pub use text::Text;

/// Why a lesson could not be read. Each message names the file; a parse error also the line,
/// the column and the field (a JSON path such as `steps[3].title`).
#[derive(Debug, thiserror::Error)]
pub enum LessonError {
    /// The file could not be read (missing, not a regular file, too large).
    #[error(transparent)]
    File(#[from] ReadError),
    /// The JSON is malformed, or a field is missing, unknown, of the wrong type or invalid.
    #[error("{path}:{line}:{column}: {field}{message}")]
    Parse {
        /// The lesson file as shown in messages.
        path: String,
        /// 1-based line of the problem.
        line: usize,
        /// 1-based column of the problem.
        column: usize,
        /// "field `steps[3].title`: ", or empty at the top level.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// The file is not UTF-8 text.
    #[error("{path}: {message}")]
    Invalid {
        /// The lesson file as shown in messages.
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// A plot a step shows for the pinned pixel's row (the app's plot window draws it from the
/// library's per-pixel values, never recomputed in the UI).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LessonPlot {
    /// u and v along the row, affine beside perspective-correct.
    UvRow,
    /// 1/w along the row (a straight line on the screen) and w (not one).
    WRow,
    /// Window depth z/w (straight on the screen) against view depth w (not straight).
    DepthRow,
    /// The level of detail lambda down the pinned pixel's column (up a floor it grows towards
    /// the horizon), with the mipmap level read.
    LambdaColumn,
}

/// A section of the inspector's derivation (the probe's worked example), by name: lessons
/// open the ones a step talks about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum InspectorSection {
    /// The settings the pixel is drawn with.
    Settings,
    /// The sample point at the pixel centre.
    Sample,
    /// Which triangle covers it (edge functions, fill rule).
    Coverage,
    /// The triangle's vertices in every space.
    Vertices,
    /// The clipped polygon (only when the triangle was clipped).
    Clipping,
    /// The screen-space weights r, s, t, four ways.
    ScreenWeights,
    /// The 1/w correction: W_P and a, b, c.
    Perspective,
    /// The 4x4 linear system of Umetani's notes.
    System,
    /// The point on the triangle the pixel sees (the eye ray).
    Point,
    /// Texture coordinate and colour, both ways.
    Attribute,
    /// Depth: z/w interpolated on the screen.
    Depth,
    /// The colour written.
    Color,
}

impl InspectorSection {
    /// The position of this section in the probe's derivation (0-based), which depends on
    /// whether the pixel is covered (`detail`) and its triangle was clipped; `None` when the
    /// derivation has no such section.
    ///
    /// ```
    /// use barylab::lesson::InspectorSection as S;
    /// assert_eq!(S::ScreenWeights.index(true, false), Some(4));
    /// assert_eq!(S::ScreenWeights.index(true, true), Some(5));
    /// assert_eq!(S::Color.index(false, false), Some(3));
    /// assert_eq!(S::Depth.index(false, false), None);
    /// ```
    pub fn index(self, detail: bool, clipped: bool) -> Option<usize> {
        use InspectorSection as S;
        let c = usize::from(clipped);
        match (self, detail) {
            (S::Settings, _) => Some(0),
            (S::Sample, _) => Some(1),
            (S::Coverage, _) => Some(2),
            (S::Color, false) => Some(3),
            (_, false) => None,
            (S::Vertices, true) => Some(3),
            (S::Clipping, true) => clipped.then_some(4),
            (S::ScreenWeights, true) => Some(4 + c),
            (S::Perspective, true) => Some(5 + c),
            (S::System, true) => Some(6 + c),
            (S::Point, true) => Some(7 + c),
            (S::Attribute, true) => Some(8 + c),
            (S::Depth, true) => Some(9 + c),
            (S::Color, true) => Some(10 + c),
        }
    }
}

/// The overlays drawn over the canvas (the grid and the handles default to shown, the
/// sub-triangles to hidden: a step that teaches areas shows them).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Overlays {
    /// The pixel grid (from a pixel size of 6).
    pub grid: bool,
    /// The vertex handles with their w.
    pub handles: bool,
    /// The pinned pixel's sub-triangles (its weights as areas).
    pub sub_areas: bool,
}

impl Default for Overlays {
    fn default() -> Self {
        Self {
            grid: true,
            handles: true,
            sub_areas: false,
        }
    }
}

/// Where a step's scene comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneSource {
    /// Written in the lesson file.
    Inline,
    /// A scene file (the path as resolved against the lesson's folder).
    File(PathBuf),
    /// A built-in scene ([`builtin::scene`]), by name.
    Builtin(String),
}

/// A step's scene, loaded and checked when the lesson is read.
#[derive(Clone, Debug, PartialEq)]
pub struct StepScene {
    /// Where it came from.
    pub source: SceneSource,
    /// The scene as read.
    pub scene: Scene,
    /// The folder its texture and model paths are relative to (`None`: built-in names only).
    pub dir: Option<PathBuf>,
}

/// One step of a lesson, as written (fields left out take their defaults in
/// [`Lesson::state`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The step's title.
    pub title: Text,
    /// One line for presentation mode's strip (a key formula or claim); `None`: the text's
    /// first sentence.
    pub summary: Option<Text>,
    /// The explanation: paragraphs separated by blank lines, `**bold**`, formulas in plain
    /// Unicode ([`text::blocks`]; a block indented by four spaces is a formula block).
    pub text: Text,
    /// What to try on the canvas.
    pub try_this: Text,
    /// The scene; `None`: the previous step's.
    pub scene: Option<StepScene>,
    /// Interpolation mode (default: the scene's).
    pub mode: Option<Interpolation>,
    /// How the two modes are compared (default: one view).
    pub compare: Compare,
    /// What the colour shows (default: the scene's).
    pub shading: Option<Shading>,
    /// Texture filter (default: the scene's).
    pub filter: Option<Filter>,
    /// Wireframe from the smallest weight (default: the scene's).
    pub wireframe: Option<bool>,
    /// Which rasterizer draws (default: edge functions).
    pub rasterizer: Rasterizer,
    /// The overlays.
    pub overlays: Overlays,
    /// Rendered image size `[width, height]` (default: the scene's).
    pub size: Option<[u32; 2]>,
    /// Screen pixels per rendered pixel (default 1: the image as large as the canvas allows).
    pub pixel_size: Option<u32>,
    /// The pinned pixel `[x, y]` (column from the left, row from the top).
    pub pin: Option<[u32; 2]>,
    /// The inspector sections opened (default: the inspector's own choice).
    pub inspector: Vec<InspectorSection>,
    /// A plot of the pinned pixel's row.
    pub plot: Option<LessonPlot>,
    /// The 3D view beside the canvas (default off).
    pub space_view: bool,
    /// The per-sample buffers view (default: the resolve, without the black-edge bug).
    pub samples_view: crate::figure::sample_buffers::SampleView,
    /// The texture-space or level-of-detail view beside the canvas (`"texture_view":
    /// "texture"` or `"lod"`; default off).
    pub texture_view: crate::figure::TexelView,
    /// A quiz on the pinned pixel: the class predicts these numbers before they are shown.
    pub quiz: Option<QuizSpec>,
    /// A moving figure for the step's slide (`barylab lesson --slides`), in place of the
    /// still one.
    pub animation: Option<StepAnimation>,
}

/// A step's quiz as written: `"quiz": {"ask": ["screen_weights", "weights", "inv_w", "uv"]}`,
/// with `"pixel": [x, y]` when the quiz pixel is not the step's `pin` (it is pinned instead).
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct QuizSpec {
    /// The pixel asked about (default: the step's pin).
    #[serde(default)]
    pub pixel: Option<[u32; 2]>,
    /// What the class predicts, in order, each once.
    pub ask: Vec<Quantity>,
}

/// A step's moving figure: a sweep of the step's scene with the step's figure options, as
/// `barylab animate` makes it (`"animation": {"sweep": "depth", "frames": 10, "format":
/// "apng"}`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepAnimation {
    /// What moves.
    pub sweep: crate::animate::Sweep,
    /// Frames, [`STEP_ANIMATION_FRAMES`] (few: a deck stays small).
    pub frames: u32,
    /// The corner the depth and clip sweeps move (mesh vertex index; written as its name,
    /// default C).
    pub vertex: usize,
    /// GIF (default: small, 256 colours) or APNG (lossless: smooth colour gradients).
    pub format: crate::animate::Format,
}

/// The frames a step's animation may have (default 10).
pub const STEP_ANIMATION_FRAMES: (u32, u32) = (2, 40);

/// A lesson: a title and its steps.
#[derive(Clone, Debug, PartialEq)]
pub struct Lesson {
    /// The lesson's title.
    pub title: Text,
    /// The steps, in order (at least one).
    pub steps: Vec<Step>,
    /// Where it was read from (`None`: built in).
    pub path: Option<PathBuf>,
    /// The built-in lesson's name ([`builtin::LESSONS`]); `None` for a file.
    pub builtin: Option<&'static str>,
}

/// Everything a step sets: what the app applies, and what its figure and handout show.
#[derive(Clone, Debug, PartialEq)]
pub struct StepState {
    /// The scene, at the step's size and with its mode, shading, filter and wireframe.
    pub scene: Scene,
    /// The folder the scene's texture and model paths are relative to.
    pub scene_dir: Option<PathBuf>,
    /// How the two modes are compared.
    pub compare: Compare,
    /// Which rasterizer draws.
    pub rasterizer: Rasterizer,
    /// The overlays.
    pub overlays: Overlays,
    /// Screen pixels per rendered pixel.
    pub pixel_size: u32,
    /// The pinned pixel.
    pub pin: Option<[u32; 2]>,
    /// The inspector sections opened (empty: the inspector's default).
    pub inspector: Vec<InspectorSection>,
    /// The plot to show.
    pub plot: Option<LessonPlot>,
    /// The 3D view beside the canvas.
    pub space_view: bool,
    /// The per-sample buffers view.
    pub samples_view: crate::figure::sample_buffers::SampleView,
    /// The texture-space or level-of-detail view beside the canvas.
    pub texture_view: crate::figure::TexelView,
    /// The quiz on the pinned pixel (its pixel is [`StepState::pin`]).
    pub quiz: Option<Question>,
}

impl StepState {
    /// The figure options that show this state as the canvas does (scale 1, white
    /// background for print).
    pub fn figure_options(&self) -> FigureOptions {
        FigureOptions {
            compare: self.compare,
            pixel_size: self.pixel_size,
            show_grid: self.overlays.grid,
            show_handles: self.overlays.handles,
            show_sub_areas: self.overlays.sub_areas,
            pinned: self.pin,
            background: crate::figure::Background::White,
            ..FigureOptions::default()
        }
    }
}

/// Sets a scene's interpolation mode, shading, filter and wireframe (every form stores them).
fn set_look(scene: &mut Scene, mode: Interpolation, shading: Shading, filter: Filter, wf: bool) {
    match scene {
        Scene::World(s) => (s.mode, s.shading, s.filter, s.wireframe) = (mode, shading, filter, wf),
        Scene::Clip(s) => (s.mode, s.shading, s.filter, s.wireframe) = (mode, shading, filter, wf),
        Scene::Model(s) => {
            (s.mode, s.shading, s.filter, s.wireframe) = (mode, Some(shading), filter, wf)
        }
    }
}

impl Step {
    /// The pinned pixel: the quiz's pixel when the quiz names one, else `pin`.
    pub fn quiz_pixel(&self) -> Option<[u32; 2]> {
        self.quiz.as_ref().and_then(|q| q.pixel).or(self.pin)
    }
}

impl Lesson {
    /// The built-in lesson ([`builtin::LESSON`]): barycentric weights to perspective-correct
    /// interpolation, depth and clipping.
    pub fn builtin() -> Result<Lesson, LessonError> {
        parse::parse_builtin(&builtin::LESSONS[0])
    }

    /// Reads a lesson file, or the built-in lesson a name opens ([`builtin::lesson`]:
    /// `interpolation` or `builtin`, `texture`).
    pub fn open(path: &Path) -> Result<Lesson, LessonError> {
        match path.to_str().and_then(builtin::lesson) {
            Some(b) => parse::parse_builtin(b),
            None => load(path),
        }
    }

    /// The scene step `index` (0-based) uses: its own, else the nearest earlier step's.
    pub fn scene_of(&self, index: usize) -> Option<&StepScene> {
        self.steps[..=index.min(self.steps.len().saturating_sub(1))]
            .iter()
            .rev()
            .find_map(|s| s.scene.as_ref())
    }

    /// What step `index` (0-based) sets; `None` past the last step.
    pub fn state(&self, index: usize) -> Option<StepState> {
        let step = self.steps.get(index)?;
        let from = self.scene_of(index)?;
        let mut scene = from.scene.clone();
        if let Some([w, h]) = step.size {
            scene.set_size(w, h);
        }
        let s = scene.settings();
        set_look(
            &mut scene,
            step.mode.unwrap_or(s.mode),
            step.shading.unwrap_or(s.shading),
            step.filter.unwrap_or(s.filter),
            step.wireframe.unwrap_or(s.wireframe),
        );
        Some(StepState {
            scene,
            scene_dir: from.dir.clone(),
            compare: step.compare,
            rasterizer: step.rasterizer,
            overlays: step.overlays,
            pixel_size: step.pixel_size.unwrap_or(1),
            pin: step.quiz_pixel(),
            inspector: step.inspector.clone(),
            plot: step.plot,
            space_view: step.space_view,
            samples_view: step.samples_view,
            texture_view: step.texture_view,
            quiz: step.quiz.as_ref().and_then(|q| {
                Some(Question {
                    pixel: step.quiz_pixel()?,
                    ask: q.ask.clone(),
                })
            }),
        })
    }

    /// The name shown for this lesson's file in messages (`builtin` when built in).
    pub fn shown_path(&self) -> String {
        match &self.path {
            Some(p) => crate::files::shown(p),
            None => self.builtin.unwrap_or(builtin::NAME).to_string(),
        }
    }

    /// One line per step: number, title and what it shows, for `barylab lesson --list`.
    pub fn list(&self, lang: Lang) -> String {
        let mut out = format!("{}\n", self.title.get(lang));
        for (i, step) in self.steps.iter().enumerate() {
            out.push_str(&format!("{:>2}. {}\n", i + 1, step.title.get(lang)));
        }
        out
    }
}
