//! The keyboard shortcuts (listed in the help window, [`super::help`]). They read the state and
//! return commands, like the panels.

use egui::{Key, Modifiers};

use super::command::AppCommand;
use super::export::ExportCommand;
use super::files::FileCommand;
use super::state::{AppState, Command, PIXEL_SIZE_RANGE};
use crate::figure::Compare;

/// What the shortcuts depend on besides the state.
pub struct ShortcutInput<'a> {
    pub state: &'a AppState,
    /// The canvas's render size, if anything is rendered (the pin stays inside it).
    pub canvas_size: Option<[u32; 2]>,
    pub help_open: bool,
    pub export_open: bool,
}

/// The commands of the keys pressed this frame (none while a text field has the keyboard).
pub fn shortcuts(ctx: &egui::Context, input: &ShortcutInput<'_>) -> Vec<AppCommand> {
    if ctx.egui_wants_keyboard_input() {
        return Vec::new();
    }
    let none = Modifiers::NONE;
    let mut cmds: Vec<AppCommand> = Vec::new();
    let mut help = false;
    ctx.input_mut(|i| {
        let mut key = |k| i.consume_key(none, k);
        let mut state = |c: Command| cmds.push(c.into());
        if key(Key::P) {
            state(Command::ToggleMode);
        }
        for (k, c) in [
            (Key::Num1, Compare::Single),
            (Key::Num2, Compare::SideBySide),
            (Key::Num3, Compare::Wipe),
            (Key::Num4, Compare::Difference),
        ] {
            if key(k) {
                state(Command::SetCompare(c));
            }
        }
        let options = input.state.options();
        let view = &input.state.view;
        if key(Key::W) {
            state(Command::SetWireframe(!options.wireframe));
        }
        if key(Key::G) {
            state(Command::SetShowGrid(!view.show_grid));
        }
        if key(Key::H) {
            state(Command::SetShowHandles(!view.show_handles));
        }
        if key(Key::OpenBracket) {
            state(Command::SetPixelSize(smaller_pixel(view.pixel_size)));
        }
        if key(Key::CloseBracket) {
            state(Command::SetPixelSize(larger_pixel(view.pixel_size)));
        }
        if key(Key::Escape) {
            if input.help_open {
                help = true;
            } else {
                state(Command::Pin(None));
            }
        }
        if key(Key::Home) {
            state(Command::ResetCamera);
        }
        if key(Key::F1) {
            help = true;
        }
        if let Some(size) = input.canvas_size
            && view.pinned.is_some()
        {
            for (k, dx, dy) in [
                (Key::ArrowLeft, -1, 0),
                (Key::ArrowRight, 1, 0),
                (Key::ArrowUp, 0, -1),
                (Key::ArrowDown, 0, 1),
            ] {
                if key(k) {
                    state(Command::MovePin { dx, dy, size });
                }
            }
        }
        if i.consume_key(Modifiers::COMMAND, Key::R) {
            state(Command::ResetScene);
        }
        if i.consume_key(Modifiers::COMMAND, Key::O) {
            cmds.push(FileCommand::OpenDialog.into());
        }
        if i.consume_key(Modifiers::COMMAND, Key::S) {
            // The first Ctrl+S opens the Export window, the next one exports.
            cmds.push(
                if input.export_open {
                    ExportCommand::Export
                } else {
                    ExportCommand::Open
                }
                .into(),
            );
        }
    });
    if help {
        cmds.push(AppCommand::SetHelpOpen(!input.help_open));
    }
    cmds
}

fn smaller_pixel(p: u32) -> u32 {
    (p / 2).max(PIXEL_SIZE_RANGE.0)
}

fn larger_pixel(p: u32) -> u32 {
    (p * 2).min(PIXEL_SIZE_RANGE.1)
}
