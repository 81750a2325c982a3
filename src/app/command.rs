//! Everything a panel can ask of the app. Panels get the state they show and return
//! [`AppCommand`]s (or the commands of their own part, which convert into one); the app applies
//! them all in one place, in order, once per frame ([`crate::app::BaryApp::show`]).

use crate::app::document::state::StateCommand;
use std::path::PathBuf;

use crate::figure::Background;
use crate::figure::export::ExportSelection;

/// A change or an action asked for by a panel, a shortcut, a dialog or a dropped file.
#[derive(Clone, Debug, PartialEq)]
pub enum AppCommand {
    /// Change the scene or the view ([`crate::app::document::state::AppState::apply`]).
    State(StateCommand),
    /// The Export panel (applied by `ExportPanel::apply`).
    Export(ExportCommand),
    /// The benchmark window ([`crate::app::panels::bench_panel::BenchPanel::apply`]).
    Bench(BenchCommand),
    /// Opening files: the File menu, the typed-path window, the banner.
    File(FileCommand),
    /// Show or hide the help window.
    SetHelpOpen(bool),
    /// Enter or leave presentation mode.
    SetPresenting(bool),
    /// Show the app in this language (the top bar's switch).
    SetLang(crate::i18n::Lang),
    /// Undo the last scene edit.
    Undo,
    /// Redo the last undone scene edit.
    Redo,
    /// The Lessons panel, menu and keys (applied by `BaryApp::apply_lesson`).
    Lesson(LessonCommand),
    /// Start or stop stepping along the pinned row's scanline span (S).
    ToggleSpanStepping,
    /// The Export animation window and the recorder (applied by `BaryApp::apply_animation`).
    Animation(AnimationCommand),
    /// Presentation mode in a window too narrow for the 3D view beside the picture: show the
    /// 3D view in the picture's place, or the picture again (V). Any change of the scene or
    /// the lesson step brings the picture back.
    ToggleSpaceFull,
    /// The quiz on the pinned pixel ([`crate::app::panels::quiz`]).
    Quiz(QuizCommand),
}

/// What the quiz panel and the Q key ask for.
#[derive(Clone, Debug, PartialEq)]
pub enum QuizCommand {
    /// Start a quiz on the pinned pixel (every quantity), or end the one going on (Q).
    Toggle,
    /// The field of number `index` of quantity `part` now holds `text`.
    Edit {
        /// Which quantity asked (0-based, in the question's order).
        part: usize,
        /// Which of its numbers.
        index: usize,
        /// The field's text.
        text: String,
    },
    /// Show (true) or hide again (false) the answer.
    Reveal(bool),
}

impl From<QuizCommand> for AppCommand {
    fn from(c: QuizCommand) -> Self {
        AppCommand::Quiz(c)
    }
}

impl From<StateCommand> for AppCommand {
    fn from(c: StateCommand) -> Self {
        Self::State(c)
    }
}

impl From<ExportCommand> for AppCommand {
    fn from(c: ExportCommand) -> Self {
        Self::Export(c)
    }
}

impl From<AnimationCommand> for AppCommand {
    fn from(c: AnimationCommand) -> Self {
        Self::Animation(c)
    }
}

impl From<BenchCommand> for AppCommand {
    fn from(c: BenchCommand) -> Self {
        Self::Bench(c)
    }
}

impl From<FileCommand> for AppCommand {
    fn from(c: FileCommand) -> Self {
        Self::File(c)
    }
}

/// Converts a panel's own commands.
pub fn all<C: Into<AppCommand>>(commands: Vec<C>) -> impl Iterator<Item = AppCommand> {
    commands.into_iter().map(Into::into)
}

impl From<LessonCommand> for AppCommand {
    fn from(c: LessonCommand) -> Self {
        AppCommand::Lesson(c)
    }
}

/// A change or an action of the Export panel, applied once per frame.
#[derive(Clone, Debug, PartialEq)]
pub enum ExportCommand {
    /// Show the Export panel.
    Open,
    /// Hide the Export panel.
    Close,
    /// Show the native folder dialog.
    BrowseFolder,
    /// Export into this folder.
    SetFolder(PathBuf),
    /// Export at this scale: PNG pixels per figure point (1, 2 or 4).
    SetScale(u32),
    /// Use this background in the figures.
    SetBackground(Background),
    /// Write these files.
    SetSelection(ExportSelection),
    /// Add (or leave out) the figure's caption.
    SetCaption(bool),
    /// Write the selected files into the folder.
    Export,
    /// Put the figure's PNG on the clipboard.
    Copy,
    /// Save the whole window as a PNG into the folder.
    Screenshot,
}

/// What an exported animation shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AnimationKind {
    /// A sweep of the scene, as `barylab animate` makes it.
    #[default]
    Sweep,
    /// The recorded drag.
    Recording,
}

/// A change or an action of the Export animation window and the recorder.
#[derive(Clone, Debug, PartialEq)]
pub enum AnimationCommand {
    /// Show the window.
    Open,
    /// Hide the window.
    Close,
    /// Export a sweep or the recording.
    SetKind(AnimationKind),
    /// The sweep to export.
    SetSweep(crate::animate::Sweep),
    /// The corner the depth and clip sweeps move (mesh vertex index).
    SetVertex(usize),
    /// Frames of a sweep.
    SetFrames(u32),
    /// Frames per second of the file.
    SetFps(u32),
    /// The file format.
    SetFormat(crate::animate::Format),
    /// The figures' label language (`None`: the app's).
    SetLang(Option<crate::i18n::Lang>),
    /// Start recording the document's states, or stop (R).
    ToggleRecord,
    /// Keep the recorded frames `first..=last`.
    SetTrim(usize, usize),
    /// Render and write the animation in the background.
    Export,
    /// Stop the rendering going on.
    Cancel,
}

/// Which scene the benchmark draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BenchSource {
    /// The scene on the canvas, at the canvas's render size.
    #[default]
    Canvas,
    /// `assets/scenes/bench-1080p.json` (built in), 1920 x 1080.
    Reference,
}

/// A change or an action of the benchmark window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BenchCommand {
    /// Show or hide the window.
    SetOpen(bool),
    /// Measure the canvas's scene or the built-in reference scene.
    SetSource(BenchSource),
    /// Frames per configuration.
    SetFrames(u32),
    /// Start measuring the chosen scene.
    Run,
    /// Stop the run going on.
    Stop,
}

/// What the Lessons panel, the strip, the menu and the keys ask for.
#[derive(Clone, Debug, PartialEq)]
pub enum LessonCommand {
    /// Open the built-in lesson at its first step.
    OpenBuiltin,
    /// Show the native dialog to pick a lesson file.
    OpenDialog,
    /// Open a lesson file at its first step.
    OpenFile(PathBuf),
    /// Go to step `n` (0-based).
    Go(usize),
    /// The next step (stays at the last).
    Next,
    /// The previous step (stays at the first).
    Previous,
    /// Put back everything the current step sets.
    Reset,
    /// Leave the lesson: the user's own scene and settings come back.
    Leave,
    /// The inspector showed the derivation sections the step opens: forget them, so the
    /// user's own opening and closing is kept from now on.
    SectionsShown,
}

/// What the File menu, the typed-path window, the banner and drag-and-drop ask the app to do.
#[derive(Clone, Debug, PartialEq)]
pub enum FileCommand {
    /// Show the native Open dialog.
    OpenDialog,
    /// Show the typed-path window; `dialog_failed` says the native dialog could not open.
    ShowPathWindow {
        /// The native dialog could not open (the window says so).
        dialog_failed: bool,
    },
    /// Close the typed-path window.
    ClosePathWindow,
    /// The typed-path window's field now holds this text.
    EditPath(String),
    /// The typed-path window's field took the keyboard focus it was opened with.
    PathFieldFocused,
    /// Load this file and apply it ([`crate::app::services::files::open`]).
    Open(PathBuf),
    /// Empty the recent-files list.
    ClearRecent,
    /// Hide the banner.
    DismissBanner,
    /// Save the scene to the file it came from or was last saved to (else ask where).
    Save,
    /// Ask where to save the scene (the native dialog, else the typed-path window).
    SaveAsDialog,
    /// Save the scene to this file.
    SaveTo(PathBuf),
    /// Ask for an image to compare with the render (the native dialog).
    CompareImageDialog,
    /// Compare this image with the render ([`crate::app::panels::compare_image`]).
    CompareImage(PathBuf),
    /// Stop comparing with an image.
    CloseCompareImage,
    /// Show the Export animation window.
    ExportAnimation,
    /// The compared image's background colour: any other colour is covered.
    SetCompareBackground([u8; 3]),
}
