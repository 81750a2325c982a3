//! The File menu: the native Open dialog, the typed-path window ([`super::path_window`]),
//! recent files. It returns [`FileCommand`]s; opening itself is [`super::files::open`].

use egui::{RichText, Ui};

use super::dialog::{DialogOutcome, NativeDialog};
use super::files::{FileCommand, RecentFiles};
use super::path_window::PathWindow;
use crate::scene::IMAGE_EXTENSIONS;

/// User-facing strings of the File menu and the typed-path window.
pub mod text {
    pub const FILE: &str = "File";
    pub const OPEN: &str = "Open…";
    pub const OPEN_TIP: &str = "Open a scene (.json), a model (.obj) or an image \
        (PNG, JPEG, BMP, TGA, WebP: it becomes the texture). You can also drop files on the \
        window. Key: Ctrl+O";
    pub const SAVE: &str = "Save scene";
    pub const SAVE_TIP: &str = "Save the scene (corners, camera, texture, image size) as a \
        JSON file that barylab render, probe and figure read: to the file it came from, else \
        ask where.";
    pub const SAVE_AS: &str = "Save scene as…";
    pub const SAVE_AS_TIP: &str = "Save the scene to a new JSON file. Key: Ctrl+Shift+S";
    pub const SAVE_DIALOG_TITLE: &str = "Save the scene";
    pub const SAVE_NAME: &str = "scene.json";
    pub const TYPE_PATH: &str = "Type a path…";
    pub const TYPE_PATH_TIP: &str = "Open a file by typing its path.";
    pub const RECENT: &str = "Recent files";
    pub const NO_RECENT: &str = "(none yet)";
    pub const MISSING: &str = "missing";
    pub const CLEAR_RECENT: &str = "Clear the list";
    pub const DIALOG_TITLE: &str = "Open a scene, model or image";
    pub const FILTER_ALL: &str = "Scenes, models and images";
    pub const FILTER_SCENE: &str = "Scene (JSON)";
    pub const FILTER_MODEL: &str = "Model (OBJ)";
    pub const FILTER_IMAGE: &str = "Image";
    pub const DIALOG_WAITING: &str = "waiting for the file dialog…";
}

/// The native Open dialog and the typed-path window.
#[derive(Default)]
pub struct FilePicker {
    dialog: NativeDialog,
    save_dialog: NativeDialog,
    pub path_window: PathWindow,
}

impl FilePicker {
    /// Applies a command of the File menu or the typed-path window ([`FileCommand::Open`] and
    /// the others that change the app are the app's to apply).
    pub fn apply(&mut self, ctx: &egui::Context, command: &FileCommand) {
        match command {
            FileCommand::OpenDialog => self.open_dialog(ctx),
            FileCommand::ShowPathWindow { dialog_failed } => self.path_window.show(*dialog_failed),
            FileCommand::SaveAsDialog => self.save_dialog(ctx),
            FileCommand::ClosePathWindow => self.path_window.open = false,
            FileCommand::Open(_)
            | FileCommand::ClearRecent
            | FileCommand::DismissBanner
            | FileCommand::Save
            | FileCommand::SaveTo(_) => {}
        }
    }

    /// Opens the native dialog (once at a time).
    fn open_dialog(&mut self, ctx: &egui::Context) {
        let mut all: Vec<&str> = vec!["json", "obj"];
        all.extend(IMAGE_EXTENSIONS);
        let opened = self.dialog.open(ctx, "file dialog", move || {
            rfd::FileDialog::new()
                .set_title(text::DIALOG_TITLE)
                .add_filter(text::FILTER_ALL, &all)
                .add_filter(text::FILTER_SCENE, &["json"])
                .add_filter(text::FILTER_MODEL, &["obj"])
                .add_filter(text::FILTER_IMAGE, &IMAGE_EXTENSIONS)
                .pick_file()
        });
        if opened.is_err() {
            self.path_window.show(true);
        }
    }

    /// Opens the native Save dialog; the typed-path window (saving) when it cannot.
    fn save_dialog(&mut self, ctx: &egui::Context) {
        let opened = self.save_dialog.open(ctx, "save dialog", move || {
            rfd::FileDialog::new()
                .set_title(text::SAVE_DIALOG_TITLE)
                .set_file_name(text::SAVE_NAME)
                .add_filter(text::FILTER_SCENE, &["json"])
                .save_file()
        });
        if opened.is_err() {
            self.path_window.show_save(true);
        }
    }

    /// Whether a native dialog is open.
    pub fn waiting(&self) -> bool {
        self.dialog.is_open() || self.save_dialog.is_open()
    }

    /// What the dialog's closing asks for: the picked file to open, or the typed-path window
    /// when it could not open.
    pub fn poll(&mut self) -> Option<FileCommand> {
        match self.save_dialog.poll() {
            Some(DialogOutcome::Picked(path)) => return Some(FileCommand::SaveTo(path)),
            Some(DialogOutcome::Failed) => self.path_window.show_save(true),
            Some(DialogOutcome::Cancelled) | None => {}
        }
        match self.dialog.poll()? {
            DialogOutcome::Picked(path) => Some(FileCommand::Open(path)),
            DialogOutcome::Failed => Some(FileCommand::ShowPathWindow {
                dialog_failed: true,
            }),
            DialogOutcome::Cancelled => None,
        }
    }
}

/// The File menu: open (dialog), type a path, recent files. `waiting`: the native dialog is
/// open.
pub fn file_menu_ui(ui: &mut Ui, recent: &RecentFiles, waiting: bool) -> Vec<FileCommand> {
    let mut out = Vec::new();
    ui.menu_button(text::FILE, |ui| {
        if ui
            .button(text::OPEN)
            .on_hover_text(text::OPEN_TIP)
            .clicked()
        {
            out.push(FileCommand::OpenDialog);
            ui.close();
        }
        if ui
            .button(text::TYPE_PATH)
            .on_hover_text(text::TYPE_PATH_TIP)
            .clicked()
        {
            out.push(FileCommand::ShowPathWindow {
                dialog_failed: false,
            });
            ui.close();
        }
        ui.separator();
        for (label, tip, command) in [
            (text::SAVE, text::SAVE_TIP, FileCommand::Save),
            (text::SAVE_AS, text::SAVE_AS_TIP, FileCommand::SaveAsDialog),
        ] {
            if ui.button(label).on_hover_text(tip).clicked() {
                out.push(command);
                ui.close();
            }
        }
        ui.separator();
        ui.label(RichText::new(text::RECENT).weak());
        if recent.0.is_empty() {
            ui.label(RichText::new(text::NO_RECENT).weak());
        }
        for p in &recent.0 {
            let name = p
                .file_name()
                .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into());
            let exists = p.exists();
            let label = if exists {
                name
            } else {
                format!("{name} ({})", text::MISSING)
            };
            let r = ui
                .add_enabled(exists, egui::Button::new(label))
                .on_hover_text(p.display().to_string())
                .on_disabled_hover_text(p.display().to_string());
            if r.clicked() {
                out.push(FileCommand::Open(p.clone()));
                ui.close();
            }
        }
        if !recent.0.is_empty() && ui.button(text::CLEAR_RECENT).clicked() {
            out.push(FileCommand::ClearRecent);
        }
    });
    if waiting {
        ui.label(RichText::new(text::DIALOG_WAITING).weak());
    }
    out
}
