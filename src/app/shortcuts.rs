//! The keyboard shortcuts (listed in the help window, [`crate::app::panels::help`]). They read the state and
//! return commands, like the panels.

use egui::{Key, Modifiers};

use crate::app::command::AppCommand;
use crate::app::command::ExportCommand;
use crate::app::command::FileCommand;
use crate::app::command::LessonCommand;
use crate::app::command::QuizCommand;
use crate::app::document::presets::Preset;
use crate::app::document::state::{AppState, PIXEL_SIZE_RANGE, StateCommand};
use crate::figure::Compare;

/// What the shortcuts depend on besides the state.
pub struct ShortcutInput<'a> {
    pub state: &'a AppState,
    /// The canvas's render size, if anything is rendered (the pin stays inside it).
    pub canvas_size: Option<[u32; 2]>,
    pub help_open: bool,
    pub export_open: bool,
    pub presenting: bool,
    /// The preset loaded last (Page Down / Page Up step on from it).
    pub last_preset: Option<Preset>,
    /// A lesson is open: Page Down / Page Up (and the arrow keys while no pixel is pinned)
    /// step through its steps.
    pub lesson_open: bool,
}

/// The commands of the keys pressed this frame (none while a text field has the keyboard).
pub fn shortcuts(ctx: &egui::Context, input: &ShortcutInput<'_>) -> Vec<AppCommand> {
    if ctx.egui_wants_keyboard_input() {
        return Vec::new();
    }
    let none = Modifiers::NONE;
    let mut cmds: Vec<AppCommand> = Vec::new();
    let mut help = false;
    let popup_open = egui::Popup::is_any_open(ctx);
    let mut extra: Vec<AppCommand> = Vec::new();
    ctx.input_mut(|i| {
        let mut key = |k| i.consume_key(none, k);
        let mut state = |c: StateCommand| cmds.push(c.into());
        if key(Key::P) {
            state(StateCommand::ToggleMode);
        }
        for (k, c) in [
            (Key::Num1, Compare::Single),
            (Key::Num2, Compare::SideBySide),
            (Key::Num3, Compare::Wipe),
            (Key::Num4, Compare::Difference),
        ] {
            if key(k) {
                state(StateCommand::SetCompare(c));
            }
        }
        let options = input.state.options();
        let view = &input.state.view;
        if key(Key::W) {
            state(StateCommand::SetWireframe(!options.wireframe));
        }
        if key(Key::G) {
            state(StateCommand::SetShowGrid(!view.show_grid));
        }
        if key(Key::M) {
            state(StateCommand::SetShowMagnifier(!view.show_magnifier));
        }
        // C: presentation mode's card of numbers, or the picture alone at its largest.
        if input.presenting && key(Key::C) {
            state(StateCommand::SetShowCard(!view.show_card));
        }
        // R: start or stop recording the canvas (File > Export animation…).
        if key(Key::R) {
            extra.push(crate::app::command::AnimationCommand::ToggleRecord.into());
        }
        if key(Key::H) {
            state(StateCommand::SetShowHandles(!view.show_handles));
        }
        // Q: a quiz on the pinned pixel (or the end of the one going on).
        if key(Key::Q) {
            extra.push(QuizCommand::Toggle.into());
        }
        // V: the 3D view in the picture's place (in presentation mode, in windows too narrow
        // for both) and back.
        if view.space && key(Key::V) {
            extra.push(AppCommand::ToggleSpaceFull);
        }
        // S: step along the pinned row's span (the scanline rasterizer's order).
        if view.rasterizer == crate::raster::render::Rasterizer::Scanline && key(Key::S) {
            extra.push(AppCommand::ToggleSpanStepping);
        }
        // [ and ]: the pixel size when the image fits the window, else the image size.
        let (w, h) = input.state.scene.size();
        if key(Key::OpenBracket) {
            state(if view.fit_window {
                StateCommand::SetPixelSize(smaller_pixel(view.pixel_size))
            } else {
                StateCommand::SetImageSize(Some(step_size([w, h], false)))
            });
        }
        if key(Key::CloseBracket) {
            state(if view.fit_window {
                StateCommand::SetPixelSize(larger_pixel(view.pixel_size))
            } else {
                StateCommand::SetImageSize(Some(step_size([w, h], true)))
            });
        }
        // Escape closes an open menu or popup first (egui does), then the help window, then
        // leaves presentation mode, then unpins.
        if !popup_open && key(Key::Escape) {
            if input.help_open {
                help = true;
            } else if input.presenting {
                extra.push(AppCommand::SetPresenting(false));
            } else {
                state(StateCommand::Pin(None));
            }
        }
        if key(Key::F5) {
            extra.push(AppCommand::SetPresenting(!input.presenting));
        }
        for (k, forward) in [(Key::PageDown, true), (Key::PageUp, false)] {
            if key(k) {
                if input.lesson_open {
                    extra.push(lesson_step(forward));
                } else {
                    state(StateCommand::Preset(step_preset(
                        input.last_preset,
                        forward,
                    )));
                }
            }
        }
        if input.lesson_open && view.pinned.is_none() {
            for (k, forward) in [
                (Key::ArrowRight, true),
                (Key::ArrowDown, true),
                (Key::ArrowLeft, false),
                (Key::ArrowUp, false),
            ] {
                if key(k) {
                    extra.push(lesson_step(forward));
                }
            }
        }
        if key(Key::Home) {
            state(StateCommand::ResetCamera);
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
                    state(StateCommand::MovePin { dx, dy, size });
                }
            }
        }
        // Ctrl+Shift+Z before Ctrl+Z (which would also match it).
        if i.consume_key(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z)
            || i.consume_key(Modifiers::COMMAND, Key::Y)
        {
            extra.push(AppCommand::Redo);
        }
        if i.consume_key(Modifiers::COMMAND, Key::Z) {
            extra.push(AppCommand::Undo);
        }
        if i.consume_key(Modifiers::COMMAND, Key::R) {
            state(StateCommand::ResetScene);
        }
        if i.consume_key(Modifiers::COMMAND, Key::O) {
            cmds.push(FileCommand::OpenDialog.into());
        }
        // Ctrl+Shift+S before Ctrl+S (which would also match it).
        if i.consume_key(Modifiers::COMMAND | Modifiers::SHIFT, Key::S) {
            extra.push(FileCommand::SaveAsDialog.into());
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
    cmds.extend(extra);
    if help {
        cmds.push(AppCommand::SetHelpOpen(!input.help_open));
    }
    cmds
}

/// The next or previous lesson step.
fn lesson_step(forward: bool) -> AppCommand {
    if forward {
        LessonCommand::Next
    } else {
        LessonCommand::Previous
    }
    .into()
}

fn smaller_pixel(p: u32) -> u32 {
    (p / 2).max(PIXEL_SIZE_RANGE.0)
}

fn larger_pixel(p: u32) -> u32 {
    (p * 2).min(PIXEL_SIZE_RANGE.1)
}

/// The next offered image size above (`larger`) or below `size` (by pixel count); `size`
/// itself at either end.
fn step_size(size: [u32; 2], larger: bool) -> [u32; 2] {
    let count = |s: [u32; 2]| u64::from(s[0]) * u64::from(s[1]);
    let sizes = crate::app::panels::image_size::IMAGE_SIZES;
    let next = if larger {
        sizes.iter().find(|s| count(**s) > count(size))
    } else {
        sizes.iter().rev().find(|s| count(**s) < count(size))
    };
    next.copied().unwrap_or(size)
}

/// The preset after (`forward`) or before `last`; the first or the last one when none was
/// loaded yet.
fn step_preset(last: Option<Preset>, forward: bool) -> Preset {
    let all = Preset::ALL;
    let n = all.len();
    let next = match (last.and_then(|p| all.iter().position(|q| *q == p)), forward) {
        (Some(i), true) => (i + 1) % n,
        (Some(i), false) => (i + n - 1) % n,
        (None, true) => 0,
        (None, false) => n - 1,
    };
    all[next]
}
