//! The File menu: the native Open dialog, the typed-path window ([`crate::app::panels::path_window`]),
//! recent files. It returns [`FileCommand`]s; opening itself is [`crate::app::services::files::open`].

use egui::{RichText, Ui};

use crate::app::command::FileCommand;
use crate::app::document::persist::RecentFiles;
use crate::app::panels::path_window::PathWindow;
use crate::app::services::dialog::{DialogOutcome, NativeDialog};
use crate::scene::IMAGE_EXTENSIONS;

/// The native Open dialog and the typed-path window.
#[derive(Default)]
pub struct FilePicker {
    dialog: NativeDialog,
    save_dialog: NativeDialog,
    compare_dialog: NativeDialog,
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
            FileCommand::CompareImageDialog => self.compare_dialog(ctx),
            FileCommand::ClosePathWindow => self.path_window.open = false,
            FileCommand::EditPath(text) => self.path_window.typed.clone_from(text),
            FileCommand::PathFieldFocused => self.path_window.focus_field = false,
            FileCommand::Open(_)
            | FileCommand::ClearRecent
            | FileCommand::DismissBanner
            | FileCommand::Save
            | FileCommand::SaveTo(_)
            | FileCommand::CompareImage(_)
            | FileCommand::CloseCompareImage
            | FileCommand::ExportAnimation
            | FileCommand::SetCompareBackground(_) => {}
        }
    }

    /// Opens the native dialog (once at a time).
    fn open_dialog(&mut self, ctx: &egui::Context) {
        let lang = crate::app::services::locale::lang(ctx);
        let mut all: Vec<&str> = vec!["json", "obj"];
        all.extend(IMAGE_EXTENSIONS);
        let opened = self.dialog.open(ctx, "file dialog", move || {
            rfd::FileDialog::new()
                .set_title(lang.tr("app.file_menu.dialog_title"))
                .add_filter(lang.tr("app.file_menu.filter_all"), &all)
                .add_filter(lang.tr("app.file_menu.filter_scene"), &["json"])
                .add_filter(lang.tr("app.file_menu.filter_model"), &["obj"])
                .add_filter(lang.tr("app.file_menu.filter_image"), &IMAGE_EXTENSIONS)
                .pick_file()
        });
        if opened.is_err() {
            self.path_window.show(true);
        }
    }

    /// Opens the native Save dialog; the typed-path window (saving) when it cannot.
    fn save_dialog(&mut self, ctx: &egui::Context) {
        let lang = crate::app::services::locale::lang(ctx);
        let opened = self.save_dialog.open(ctx, "save dialog", move || {
            rfd::FileDialog::new()
                .set_title(lang.tr("app.file_menu.save_dialog_title"))
                .set_file_name(lang.tr("app.file_menu.save_name"))
                .add_filter(lang.tr("app.file_menu.filter_scene"), &["json"])
                .save_file()
        });
        if opened.is_err() {
            self.path_window.show_save(true);
        }
    }

    /// Opens the native dialog for an image to compare with the render.
    fn compare_dialog(&mut self, ctx: &egui::Context) {
        let lang = crate::app::services::locale::lang(ctx);
        let opened = self.compare_dialog.open(ctx, "compare dialog", move || {
            rfd::FileDialog::new()
                .set_title(lang.tr("compare_image.dialog_title"))
                .add_filter(lang.tr("app.file_menu.filter_image"), &IMAGE_EXTENSIONS)
                .pick_file()
        });
        if opened.is_err() {
            self.path_window.show(true);
        }
    }

    /// Whether a native dialog is open.
    pub fn waiting(&self) -> bool {
        self.dialog.is_open() || self.save_dialog.is_open() || self.compare_dialog.is_open()
    }

    /// What the dialog's closing asks for: the picked file to open, or the typed-path window
    /// when it could not open.
    pub fn poll(&mut self) -> Option<FileCommand> {
        match self.save_dialog.poll() {
            Some(DialogOutcome::Picked(path)) => return Some(FileCommand::SaveTo(path)),
            Some(DialogOutcome::Failed) => self.path_window.show_save(true),
            Some(DialogOutcome::Cancelled) | None => {}
        }
        if let Some(DialogOutcome::Picked(path)) = self.compare_dialog.poll() {
            return Some(FileCommand::CompareImage(path));
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
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    ui.menu_button(lang.tr("app.file_menu.file"), |ui| {
        if ui
            .button(lang.tr("app.file_menu.open"))
            .on_hover_text(lang.tr("app.file_menu.open_tip"))
            .clicked()
        {
            out.push(FileCommand::OpenDialog);
            ui.close();
        }
        if ui
            .button(lang.tr("app.file_menu.type_path"))
            .on_hover_text(lang.tr("app.file_menu.type_path_tip"))
            .clicked()
        {
            out.push(FileCommand::ShowPathWindow {
                dialog_failed: false,
            });
            ui.close();
        }
        ui.separator();
        for (label, tip, command) in [
            (
                &lang.tr("app.file_menu.save"),
                &lang.tr("app.file_menu.save_tip"),
                FileCommand::Save,
            ),
            (
                &lang.tr("app.file_menu.save_as"),
                &lang.tr("app.file_menu.save_as_tip"),
                FileCommand::SaveAsDialog,
            ),
        ] {
            if ui.button(label).on_hover_text(tip).clicked() {
                out.push(command);
                ui.close();
            }
        }
        if ui
            .button(lang.tr("compare_image.menu"))
            .on_hover_text(lang.tr("compare_image.menu_tip"))
            .clicked()
        {
            out.push(FileCommand::CompareImageDialog);
            ui.close();
        }
        if ui
            .button(lang.tr("animate.app.menu"))
            .on_hover_text(lang.tr("animate.app.menu_tip"))
            .clicked()
        {
            out.push(FileCommand::ExportAnimation);
            ui.close();
        }
        ui.separator();
        ui.label(RichText::new(lang.tr("app.file_menu.recent")).weak());
        if recent.0.is_empty() {
            ui.label(RichText::new(lang.tr("app.file_menu.no_recent")).weak());
        }
        for p in &recent.0 {
            let name = p
                .file_name()
                .map_or_else(|| p.display().to_string(), |n| n.to_string_lossy().into());
            let exists = p.exists();
            let label = if exists {
                name
            } else {
                format!("{name} ({})", &lang.tr("app.file_menu.missing"))
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
        if !recent.0.is_empty() && ui.button(lang.tr("app.file_menu.clear_recent")).clicked() {
            out.push(FileCommand::ClearRecent);
        }
    });
    if waiting {
        ui.label(RichText::new(lang.tr("app.file_menu.dialog_waiting")).weak());
    }
    out
}
