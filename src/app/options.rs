//! How the app is started: [`AppOptions`], from the command line or a test.

use std::path::PathBuf;

use crate::app::services::files;
use crate::i18n::Lang;
use crate::scene::Scene;

/// How the app is started.
#[derive(Clone, Debug, Default)]
pub struct AppOptions {
    /// A scene to open instead of the saved one, with the folder its texture paths are
    /// relative to.
    pub scene: Option<(Scene, PathBuf)>,
    /// Save a screenshot of the first fully rendered frame to this PNG and exit.
    pub screenshot: Option<PathBuf>,
    /// A file opened on the command line ([`files::open`]), applied on start as if it had
    /// been dropped on the window (an image becomes the restored scene's texture).
    pub opened: Option<files::OpenedFile>,
    /// Restore state on start and save it on exit.
    pub persist: bool,
    /// Initial window size in points.
    pub window_size: Option<[f32; 2]>,
    /// Start in presentation mode.
    pub present: bool,
    /// Start with this pixel pinned.
    pub pin: Option<[u32; 2]>,
    /// The language asked for on the command line (`--lang`): it wins over the saved one.
    pub lang: Option<Lang>,
    /// The system locale's language ([`Lang::detect`]), for a first start with nothing saved.
    pub system_lang: Lang,
    /// Behave as if no font with Chinese glyphs were installed (for tests).
    pub no_cjk_font: bool,
    /// Start at this text size (the interface zoom, as the text size slider sets it).
    pub text_size: Option<f32>,
    /// Start in a lesson, at this step (0-based).
    pub lesson: Option<(crate::lesson::Lesson, usize)>,
    /// Start in this comparison, with the GPU view on (`true`) or off (`--compare`).
    pub compare: Option<(crate::figure::Compare, bool)>,
    /// Start with the 3D view beside the canvas (`--space-view`).
    pub space_view: bool,
    /// Start with File > Export animation… open on a sweep or a recording
    /// (`--animation-window`, for screenshots).
    pub animation_window: Option<crate::app::command::AnimationKind>,
    /// Start comparing this image with the render (`--compare-image`).
    pub compare_image: Option<PathBuf>,
    /// With `compare_image`: the image's background colour (`--compare-background`).
    pub compare_background: Option<[u8; 3]>,
    /// Why a file named on the command line (a scene, model, texture or lesson) could not be
    /// opened: shown in the window as an error while the app starts on the default (or
    /// saved) scene; the command line printed it to standard error too.
    pub startup_error: Option<String>,
    /// Predictions typed into the first quiz, then revealed (`--quiz-answers`; a quiz is
    /// started on the pinned pixel if the lesson step has none).
    pub quiz_answers: Option<Vec<String>>,
}
