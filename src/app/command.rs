//! Everything a panel can ask of the app. Panels get the state they show and return
//! [`AppCommand`]s (or the commands of their own part, which convert into one); the app applies
//! them all in one place, in order, once per frame ([`super::BaryApp::show`]).

use super::bench_panel::BenchCommand;
use super::export::ExportCommand;
use super::files::FileCommand;
use super::lessons::LessonCommand;
use super::state::Command;

/// A change or an action asked for by a panel, a shortcut, a dialog or a dropped file.
#[derive(Clone, Debug, PartialEq)]
pub enum AppCommand {
    /// Change the scene or the view ([`super::state::AppState::apply`]).
    State(Command),
    /// The Export panel (applied by `ExportPanel::apply`).
    Export(ExportCommand),
    /// The benchmark window ([`super::bench_panel::BenchPanel::apply`]).
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
}

impl From<Command> for AppCommand {
    fn from(c: Command) -> Self {
        Self::State(c)
    }
}

impl From<ExportCommand> for AppCommand {
    fn from(c: ExportCommand) -> Self {
        Self::Export(c)
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
