//! Recording a drag, and writing an animation in the background.
//!
//! [`Recorder`]: while on, the document's state (the scene at the canvas's render size and the
//! figure options the canvas shows) is taken at a fixed frame rate from egui's clock, not
//! grabbed from the screen: tick `k` is due at `start + k / fps`, and each frame of the UI
//! fills every tick due so far with the state as it is then (a slow UI frame repeats it). A
//! trim keeps a range of the ticks. Each kept state is drawn again at export time as a still
//! figure ([`crate::animate::render_states`]).
//!
//! [`AnimationJob`]: renders frames ([`crate::animate`], the same code as `barylab animate`)
//! and encodes them on a thread of its own, counting frames and stopping when cancelled; the
//! file is written next to the figures under a fresh name, atomically, never over a file.

use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::sync::{Arc, Mutex};

use crate::animate::{self, Animation, Control, Format, FrameState};
use crate::figure::export;
use crate::i18n::Lang;
use crate::raster::Texture;
use crate::scene::Scene;

/// The frame rate of a recording.
pub const RECORD_FPS: f64 = 25.0;

/// The most states a recording keeps: the most frames an animation has
/// ([`animate::FRAME_RANGE`]), 40 s at [`RECORD_FPS`].
pub const RECORD_MAX_FRAMES: usize = animate::FRAME_RANGE.1 as usize;

/// A recording of the document's states, one per tick of [`RECORD_FPS`].
#[derive(Debug, Default)]
pub struct Recorder {
    /// The states, one per tick; a state that did not change is shared with the tick before.
    frames: Vec<Arc<FrameState>>,
    /// egui's time when the recording started, while it is on.
    started: Option<f64>,
    /// The recording stopped at [`RECORD_MAX_FRAMES`].
    pub capped: bool,
    /// The first and last frame kept (inclusive), within the frames.
    pub trim: (usize, usize),
}

impl Recorder {
    /// Whether it is recording.
    pub fn recording(&self) -> bool {
        self.started.is_some()
    }

    /// Starts a new recording at egui time `now` (the last one is dropped).
    pub fn start(&mut self, now: f64) {
        *self = Self {
            started: Some(now),
            ..Self::default()
        };
    }

    /// Stops recording; the trim keeps every frame.
    pub fn stop(&mut self) {
        self.started = None;
        self.trim = (0, self.frames.len().saturating_sub(1));
    }

    /// Fills the ticks due at egui time `now` with `state()` (called once, only when a tick is
    /// due). Stops at [`RECORD_MAX_FRAMES`] (then [`Recorder::capped`]); returns whether it
    /// stopped now.
    pub fn capture(&mut self, now: f64, state: impl FnOnce() -> FrameState) -> bool {
        let Some(start) = self.started else {
            return false;
        };
        let due = ((now - start).max(0.0) * RECORD_FPS).floor() as usize + 1;
        let due = due.min(RECORD_MAX_FRAMES);
        if due > self.frames.len() {
            let state = state();
            let shared = match self.frames.last() {
                Some(last) if **last == state => Arc::clone(last),
                _ => Arc::new(state),
            };
            self.frames.resize(due, shared);
        }
        if self.frames.len() >= RECORD_MAX_FRAMES {
            self.capped = true;
            self.stop();
            return true;
        }
        false
    }

    /// Frames recorded.
    pub fn len(&self) -> usize {
        self.frames.len()
    }

    /// Whether nothing is recorded.
    pub fn is_empty(&self) -> bool {
        self.frames.is_empty()
    }

    /// Sets the trim to `first..=last`, kept inside the frames and in order.
    pub fn set_trim(&mut self, first: usize, last: usize) {
        let end = self.frames.len().saturating_sub(1);
        let last = last.min(end);
        self.trim = (first.min(last), last);
    }

    /// The kept frames' states (a copy each, to hand to a thread).
    pub fn trimmed(&self) -> Vec<FrameState> {
        let (a, b) = self.trim;
        self.frames
            .get(a..=b)
            .map(|s| s.iter().map(|f| (**f).clone()).collect())
            .unwrap_or_default()
    }
}

/// What an animation is made of.
pub enum AnimationSource {
    /// A sweep of a scene, as `barylab animate` makes it.
    Sweep {
        /// The scene at the canvas's render size.
        scene: Box<Scene>,
        /// The sweep, frames and figure options.
        animation: Animation,
    },
    /// Recorded states, one a frame.
    Recording(Vec<FrameState>),
}

/// A written animation.
#[derive(Clone, Debug, PartialEq)]
pub struct Written {
    /// The file.
    pub path: PathBuf,
    /// Its size in bytes.
    pub bytes: usize,
    /// Frames and their size in pixels.
    pub frames: usize,
    /// Frame width and height.
    pub size: (u32, u32),
}

/// An animation being rendered and written on its own thread.
pub struct AnimationJob {
    /// Frames drawn so far, and the cancel switch.
    pub control: Arc<Control>,
    /// Frames to draw.
    pub total: usize,
    result: Arc<Mutex<Option<Result<Written, String>>>>,
}

impl AnimationJob {
    /// Starts rendering `source` with `texture` (labels in `lang`) at `fps` as `format` into
    /// `path`; `done` is called on the thread when it has finished (to repaint the UI).
    pub fn start(
        source: AnimationSource,
        texture: Arc<Texture>,
        lang: Lang,
        (fps, format): (f64, Format),
        path: PathBuf,
        done: impl FnOnce() + Send + 'static,
    ) -> Self {
        let total = match &source {
            AnimationSource::Sweep { animation, .. } => animation.frames as usize,
            AnimationSource::Recording(states) => states.len(),
        };
        let control = Arc::new(Control::default());
        let result = Arc::new(Mutex::new(None));
        let (c, r) = (Arc::clone(&control), Arc::clone(&result));
        std::thread::spawn(move || {
            let outcome = run(&source, &texture, lang, (fps, format), &path, &c);
            if let Ok(mut slot) = r.lock() {
                *slot = Some(outcome);
            }
            done();
        });
        Self {
            control,
            total,
            result,
        }
    }

    /// The outcome, once the thread has finished (taken: `None` after).
    pub fn finished(&self) -> Option<Result<Written, String>> {
        self.result.lock().ok().and_then(|mut r| r.take())
    }

    /// Frames drawn so far.
    pub fn done(&self) -> usize {
        self.control.done.load(Ordering::Relaxed)
    }

    /// Stops the rendering (the thread ends with [`animate::AnimateError::Cancelled`]).
    pub fn cancel(&self) {
        self.control.cancel.store(true, Ordering::Relaxed);
    }
}

/// Renders, encodes and writes (the job's thread).
fn run(
    source: &AnimationSource,
    texture: &Texture,
    lang: Lang,
    (fps, format): (f64, Format),
    path: &Path,
    control: &Control,
) -> Result<Written, String> {
    let frames = match source {
        AnimationSource::Sweep { scene, animation } => {
            animate::render_frames_with(scene, texture, animation, lang, control)
        }
        AnimationSource::Recording(states) => {
            animate::render_states(states, texture, lang, control)
        }
    }
    .map_err(|e| e.to_string())?;
    if control.cancel.load(Ordering::Relaxed) {
        return Err(animate::AnimateError::Cancelled.to_string());
    }
    let bytes = animate::encode(&frames, fps, format).map_err(|e| e.to_string())?;
    export::write_new(path, &bytes).map_err(|e| e.to_string())?;
    Ok(Written {
        path: path.to_path_buf(),
        bytes: bytes.len(),
        frames: frames.len(),
        size: frames.first().map_or((0, 0), image::RgbaImage::dimensions),
    })
}

/// A fresh file `animation-NNN.EXT` in `folder` (created if missing) for `format`.
pub fn fresh_path(folder: &Path, format: Format) -> Result<PathBuf, String> {
    let ext = match format {
        Format::Gif => "gif",
        Format::Apng => "png",
        Format::WebP => "webp",
        Format::Mp4 => "mp4",
    };
    export::prepare_folder(folder).map_err(|e| e.to_string())?;
    let stem = export::fresh_stem(folder, "animation", &[ext]).map_err(|e| e.to_string())?;
    Ok(folder.join(format!("{stem}.{ext}")))
}
