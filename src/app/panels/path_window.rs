//! The typed-path window: open a file by typing its path, also offered when the native dialog
//! cannot open.

use std::path::PathBuf;

use egui::{Color32, RichText};

use crate::app::command::FileCommand;

/// The typed-path window's state: whether it is shown, why, and its field.
#[derive(Default)]
pub struct PathWindow {
    pub open: bool,
    /// Shown in the window when the native dialog failed.
    pub dialog_failed: bool,
    /// The text of the path field.
    pub typed: String,
    /// Give the path field the keyboard focus (the window just opened).
    pub focus_field: bool,
    /// The typed path is where to save the scene, not a file to open.
    pub saving: bool,
}

impl PathWindow {
    /// Opens the window with an empty, focused field; `dialog_failed` says why it is offered.
    pub fn show(&mut self, dialog_failed: bool) {
        self.dialog_failed = dialog_failed;
        self.open = true;
        self.focus_field = true;
        // Start empty: typing must not append to the last path.
        self.typed.clear();
        self.saving = false;
    }

    /// Opens the window to type where to save the scene.
    pub fn show_save(&mut self, dialog_failed: bool) {
        self.show(dialog_failed);
        self.saving = true;
    }
}

/// The typed-path window (when open): what is typed comes back as [`FileCommand::EditPath`].
pub fn path_window_ui(ctx: &egui::Context, window: &PathWindow) -> Vec<FileCommand> {
    let lang = crate::app::services::locale::lang(ctx);
    let mut out = Vec::new();
    if !window.open {
        return out;
    }
    let mut window_open = true;
    let mut submit = false;
    let mut typed = window.typed.clone();
    let (title, hint, button) = if window.saving {
        (
            &lang.tr("app.path_window.save_window"),
            &lang.tr("app.path_window.save_hint"),
            &lang.tr("app.path_window.save_button"),
        )
    } else {
        (
            &lang.tr("app.path_window.path_window"),
            &lang.tr("app.path_window.path_hint"),
            &lang.tr("app.path_window.open_button"),
        )
    };
    egui::Window::new(title)
        .id(egui::Id::unique("path-window"))
        .open(&mut window_open)
        .collapsible(false)
        .default_width(560.0)
        .anchor(egui::Align2::CENTER_TOP, [0.0, 100.0])
        .show(ctx, |ui| {
            if window.dialog_failed {
                ui.label(
                    RichText::new(lang.tr("app.path_window.dialog_failed"))
                        .color(Color32::from_rgb(255, 200, 90)),
                );
            }
            let field = ui.add(
                egui::TextEdit::singleline(&mut typed)
                    .hint_text(hint)
                    .desired_width(f32::INFINITY),
            );
            if window.focus_field {
                field.request_focus();
                out.push(FileCommand::PathFieldFocused);
            }
            if field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                submit = true;
            }
            ui.horizontal(|ui| {
                if ui.button(button).clicked() {
                    submit = true;
                }
                if !window.dialog_failed && ui.button(lang.tr("app.path_window.browse")).clicked() {
                    out.push(if window.saving {
                        FileCommand::SaveAsDialog
                    } else {
                        FileCommand::OpenDialog
                    });
                }
            });
        });
    if typed != window.typed {
        out.push(FileCommand::EditPath(typed.clone()));
    }
    let typed = typed.trim();
    if submit && !typed.is_empty() {
        let path = PathBuf::from(typed);
        out.push(if window.saving {
            FileCommand::SaveTo(path)
        } else {
            FileCommand::Open(path)
        });
        window_open = false;
    }
    if !window_open {
        out.push(FileCommand::ClosePathWindow);
    }
    out
}
