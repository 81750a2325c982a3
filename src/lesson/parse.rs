//! Reading a lesson: strict JSON through serde, scenes loaded and checked as they are read,
//! so every error has the lesson file's line and the field's path.

use std::cell::RefCell;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::animate::{Format, Sweep};

use super::{
    Compare, InspectorSection, Lesson, LessonError, LessonPlot, Overlays, QuizSpec,
    STEP_ANIMATION_FRAMES, SceneSource, Step, StepAnimation, StepScene, Text, builtin,
};
use crate::files::{self, FileKind, shown};
use crate::probe::quiz::Quantity;
use crate::raster::project::MAX_IMAGE_SIZE;
use crate::raster::render::Rasterizer;
use crate::raster::{Filter, Interpolation, Shading};
use crate::scene::{Scene, SceneError};

/// Where the lesson being read resolves its scene references: its folder, or the built-in
/// table. Set for the time of one parse (serde gives a `Deserialize` no context).
#[derive(Clone, Debug)]
enum Origin {
    Folder(PathBuf),
    Builtin,
}

thread_local! {
    static ORIGIN: RefCell<Option<Origin>> = const { RefCell::new(None) };
}

/// Sets [`ORIGIN`] for as long as it lives.
struct OriginGuard;

impl OriginGuard {
    fn set(origin: Origin) -> Self {
        ORIGIN.with(|o| *o.borrow_mut() = Some(origin));
        OriginGuard
    }
}

impl Drop for OriginGuard {
    fn drop(&mut self) {
        ORIGIN.with(|o| *o.borrow_mut() = None);
    }
}

/// A lesson as written.
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a lesson: a JSON object with `title` and `steps`"
)]
struct RawLesson {
    title: Text,
    steps: Vec<Step>,
}

/// A step as written, checked into a [`Step`].
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a step: a JSON object with `title`, `text` and `try`"
)]
struct RawStep {
    title: Text,
    #[serde(default)]
    summary: Option<Text>,
    text: Text,
    #[serde(rename = "try")]
    try_this: Text,
    #[serde(default)]
    scene: Option<StepScene>,
    #[serde(default)]
    mode: Option<Interpolation>,
    #[serde(default)]
    compare: Compare,
    #[serde(default)]
    shading: Option<Shading>,
    #[serde(default)]
    filter: Option<Filter>,
    #[serde(default)]
    wireframe: Option<bool>,
    #[serde(default)]
    rasterizer: Rasterizer,
    #[serde(default)]
    overlays: Overlays,
    #[serde(default)]
    size: Option<[u32; 2]>,
    #[serde(default)]
    pixel_size: Option<u32>,
    #[serde(default)]
    pin: Option<[u32; 2]>,
    #[serde(default)]
    inspector: Vec<InspectorSection>,
    #[serde(default)]
    plot: Option<LessonPlot>,
    #[serde(default)]
    space_view: bool,
    #[serde(default)]
    samples_view: crate::figure::sample_buffers::SampleView,
    #[serde(default)]
    texture_view: crate::figure::TexelView,
    #[serde(default)]
    quiz: Option<QuizSpec>,
    animation: Option<StepAnimation>,
}

/// A step's animation as written.
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "an animation: a JSON object with `sweep` and optionally `frames`, `vertex` and `format`"
)]
struct RawAnimation {
    sweep: String,
    #[serde(default = "default_animation_frames")]
    frames: u32,
    #[serde(default = "default_animation_vertex")]
    vertex: String,
    #[serde(default)]
    format: Option<String>,
}

fn default_animation_frames() -> u32 {
    10
}

fn default_animation_vertex() -> String {
    "C".into()
}

impl<'de> Deserialize<'de> for StepAnimation {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let r = RawAnimation::deserialize(d)?;
        let sweep = Sweep::from_name(&r.sweep).ok_or_else(|| {
            let names: Vec<&str> = Sweep::ALL.iter().map(|s| s.name()).collect();
            D::Error::custom(format!(
                "`sweep` `{}` is not a sweep: one of {}",
                r.sweep,
                names.join(", ")
            ))
        })?;
        let (lo, hi) = STEP_ANIMATION_FRAMES;
        if !(lo..=hi).contains(&r.frames) {
            return Err(D::Error::custom(format!(
                "`frames` {} is outside {lo}..={hi}",
                r.frames
            )));
        }
        let vertex = crate::animate::vertex_by_name(&r.vertex).ok_or_else(|| {
            D::Error::custom(format!(
                "`vertex` `{}` is not a corner's name (A, B, C, ...)",
                r.vertex
            ))
        })?;
        let format = match r.format.as_deref() {
            None | Some("gif") => Format::Gif,
            Some("apng") => Format::Apng,
            Some(f) => {
                return Err(D::Error::custom(format!(
                    "`format` `{f}` is not an animation format for slides: gif or apng"
                )));
            }
        };
        Ok(StepAnimation {
            sweep,
            frames: r.frames,
            vertex,
            format,
        })
    }
}

impl<'de> Deserialize<'de> for Step {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let r = RawStep::deserialize(d)?;
        if let Some([w, h]) = r.size
            && (w == 0 || h == 0 || w > MAX_IMAGE_SIZE || h > MAX_IMAGE_SIZE)
        {
            return Err(D::Error::custom(format!(
                "`size` {w}x{h} is outside 1..={MAX_IMAGE_SIZE} pixels per side"
            )));
        }
        if let Some(p) = r.pixel_size
            && !(1..=32).contains(&p)
        {
            return Err(D::Error::custom(format!(
                "`pixel_size` {p} is outside 1..=32"
            )));
        }
        // The pin is checked against the size here when the step says it; else once the
        // lesson is read (the scene may be an earlier step's).
        let size = r.size.or(r.scene.as_ref().map(|s| {
            let (w, h) = s.scene.size();
            [w, h]
        }));
        if let Some(q) = &r.quiz {
            check_quiz(q, r.pin).map_err(D::Error::custom)?;
        }
        let pin = r.quiz.as_ref().and_then(|q| q.pixel).or(r.pin);
        if let (Some([x, y]), Some([w, h])) = (pin, size) {
            check_pin([x, y], [w, h]).map_err(D::Error::custom)?;
        }
        Ok(Step {
            title: r.title,
            summary: r.summary,
            text: r.text,
            try_this: r.try_this,
            scene: r.scene,
            mode: r.mode,
            compare: r.compare,
            shading: r.shading,
            filter: r.filter,
            wireframe: r.wireframe,
            rasterizer: r.rasterizer,
            overlays: r.overlays,
            size: r.size,
            pixel_size: r.pixel_size,
            pin: r.pin,
            inspector: r.inspector,
            plot: r.plot,
            space_view: r.space_view,
            samples_view: r.samples_view,
            texture_view: r.texture_view,
            quiz: r.quiz,
            animation: r.animation,
        })
    }
}

/// A quiz asks something, each thing once, about one pixel: its own (pinned instead of the
/// step's `pin`) or the step's pin.
fn check_quiz(q: &QuizSpec, pin: Option<[u32; 2]>) -> Result<(), String> {
    let codes = || {
        Quantity::ALL
            .iter()
            .map(|q| q.code())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if q.ask.is_empty() {
        return Err(format!(
            "`quiz.ask` is empty: name one or more of {}",
            codes()
        ));
    }
    if let Some(dup) = q
        .ask
        .iter()
        .enumerate()
        .find_map(|(i, a)| q.ask[..i].contains(a).then_some(a))
    {
        return Err(format!("`quiz.ask` names `{}` twice", dup.code()));
    }
    if q.pixel.is_none() && pin.is_none() {
        return Err("`quiz` needs a pixel: give `quiz.pixel` or the step's `pin`".into());
    }
    Ok(())
}

/// A pin must lie in the image.
fn check_pin([x, y]: [u32; 2], [w, h]: [u32; 2]) -> Result<(), String> {
    if x >= w || y >= h {
        return Err(format!(
            "`pin` {x},{y} is outside the {w}x{h} image (x 0..={}, y 0..={})",
            w.saturating_sub(1),
            h.saturating_sub(1)
        ));
    }
    Ok(())
}

/// A scene reference as written: a path or `builtin:NAME`, or a scene object.
#[derive(Deserialize)]
#[serde(
    untagged,
    expecting = "a scene: a file path, \"builtin:NAME\", or a scene object"
)]
enum RawScene {
    Reference(String),
    Inline(serde_json::Value),
}

impl<'de> Deserialize<'de> for StepScene {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let raw = RawScene::deserialize(d)?;
        let origin = ORIGIN.with(|o| o.borrow().clone());
        resolve_scene(raw, origin).map_err(D::Error::custom)
    }
}

/// Loads a step's scene: a built-in one by name, a file relative to the lesson (a built-in
/// lesson's relative paths name built-in scenes), or an inline object.
fn resolve_scene(raw: RawScene, origin: Option<Origin>) -> Result<StepScene, String> {
    let folder = match &origin {
        Some(Origin::Folder(f)) => Some(f.clone()),
        _ => None,
    };
    match raw {
        RawScene::Reference(name) => {
            let builtin_name = match (&origin, name.strip_prefix(builtin::SCENE_PREFIX)) {
                (_, Some(n)) => Some(n.to_string()),
                (Some(Origin::Builtin), None) => Some(builtin::scene_name_of(&name)),
                _ => None,
            };
            if let Some(n) = builtin_name {
                let text = builtin::scene(&n).ok_or_else(|| {
                    format!(
                        "no built-in scene `{n}` (there are: {})",
                        builtin::scene_names().join(", ")
                    )
                })?;
                let scene =
                    Scene::from_json(text, &format!("builtin:{n}")).map_err(|e| e.to_string())?;
                return Ok(StepScene {
                    source: SceneSource::Builtin(n),
                    scene,
                    dir: None,
                });
            }
            let path = folder.unwrap_or_default().join(&name);
            let scene = Scene::load(&path).map_err(|e| e.to_string())?;
            Ok(StepScene {
                source: SceneSource::File(path.clone()),
                scene,
                dir: path.parent().map(Path::to_path_buf),
            })
        }
        RawScene::Inline(value) => {
            // Named after the lesson's folder so a model path resolves against it.
            let dir = folder.unwrap_or_default();
            let text = serde_json::to_string_pretty(&value).map_err(|e| e.to_string())?;
            let scene = Scene::from_json(&text, &dir.join("inline scene").to_string_lossy())
                .map_err(|e| match e {
                    SceneError::Parse { field, message, .. } => {
                        format!("inline scene: {field}{message}")
                    }
                    e => e.to_string(),
                })?;
            Ok(StepScene {
                source: SceneSource::Inline,
                scene,
                dir: Some(dir),
            })
        }
    }
}

/// Parses lesson JSON; `path` names it in errors, `origin` resolves its scenes.
fn parse(
    text: &str,
    path: &str,
    origin: Origin,
    file: Option<PathBuf>,
) -> Result<Lesson, LessonError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let _guard = OriginGuard::set(origin);
    let raw: RawLesson = crate::scene::json::strict(text, path).map_err(|e| match e {
        SceneError::Parse {
            path,
            line,
            column,
            field,
            message,
        } => LessonError::Parse {
            path,
            line,
            column,
            field,
            message,
        },
        e => LessonError::Invalid {
            path: path.to_string(),
            message: e.to_string(),
        },
    })?;
    let lesson = Lesson {
        title: raw.title,
        steps: raw.steps,
        path: file,
        builtin: None,
    };
    check(&lesson, text, path)?;
    Ok(lesson)
}

/// What can only be checked on the whole lesson: steps exist, the first has a scene, and
/// each pin lies in the image of the scene it inherits.
fn check(lesson: &Lesson, text: &str, path: &str) -> Result<(), LessonError> {
    // These errors point at the end of the document (the lesson as a whole).
    let end_line = text.lines().count().max(1);
    let at = |field: String, message: String| LessonError::Parse {
        path: path.to_string(),
        line: end_line,
        column: 1,
        field: format!("field `{field}`: "),
        message,
    };
    if lesson.steps.is_empty() {
        return Err(at(
            "steps".into(),
            "a lesson needs at least one step".into(),
        ));
    }
    if lesson.steps[0].scene.is_none() {
        return Err(at(
            "steps[0].scene".into(),
            "the first step needs a scene (later steps keep the previous one)".into(),
        ));
    }
    for (i, step) in lesson.steps.iter().enumerate() {
        if let (Some(pin), Some(state)) = (step.quiz_pixel(), lesson.state(i)) {
            let (w, h) = state.scene.size();
            check_pin(pin, [w, h]).map_err(|m| at(format!("steps[{i}].pin"), m))?;
        }
    }
    Ok(())
}

/// Parses lesson JSON text; scene files are relative to `dir`; `path` names it in errors.
pub fn parse_str(text: &str, path: &str, dir: &Path) -> Result<Lesson, LessonError> {
    parse(text, path, Origin::Folder(dir.to_path_buf()), None)
}

/// Reads and parses a lesson file (only a regular file, at most
/// [`files::MAX_LESSON_BYTES`]).
pub fn load(path: &Path) -> Result<Lesson, LessonError> {
    let bytes = files::read_regular(path, FileKind::Lesson)?;
    let name = shown(path);
    let text = std::str::from_utf8(&bytes).map_err(|e| LessonError::Invalid {
        path: name.clone(),
        message: format!("is not UTF-8 text (bad byte at offset {})", e.valid_up_to()),
    })?;
    let dir = path.parent().unwrap_or(Path::new("")).to_path_buf();
    parse(text, &name, Origin::Folder(dir), Some(path.to_path_buf()))
}

/// Parses a built-in lesson.
pub(super) fn parse_builtin(lesson: &builtin::BuiltinLesson) -> Result<Lesson, LessonError> {
    let mut l = parse(lesson.text, lesson.name, Origin::Builtin, None)?;
    l.builtin = Some(lesson.name);
    Ok(l)
}
