//! The top bar: the File menu, the panel and window toggles, presentation mode, the reset
//! buttons and the text size. In a narrow window (a projector at a large text size) the
//! toggles, resets and text size go into a View menu, so the bar stays one row and the
//! canvas keeps its room.

use egui::Ui;

use super::command::{self, AppCommand};
use super::export::ExportCommand;
use super::state::{AppState, Command};
use super::{bench_panel, controls, export, file_menu, files, lessons, present};

/// User-facing strings of the top bar.
pub mod text {
    pub const NAME: &str = "barylab";
    pub const HELP: &str = "Help";
    pub const CONTROLS: &str = "Controls";
    pub const INSPECTOR: &str = "Inspector";
    pub const VIEW: &str = "View";
    pub const CONTROLS_TIP: &str = "Show or hide the controls panel.";
    pub const INSPECTOR_TIP: &str = "Show or hide the pixel inspector.";
    pub const HELP_TIP: &str = "Mouse and keyboard shortcuts. Key: F1";
    pub const VIEW_TIP: &str = "Panels, windows, resets and the text size (the window is too \
        narrow to show them in the bar).";
}

/// Points the whole bar takes in one row; below that the View menu holds most of it.
const FULL_BAR: f32 = 1340.0;

/// What the top bar shows besides the state.
pub struct TopBarInput<'a> {
    pub state: &'a AppState,
    pub recent: &'a files::RecentFiles,
    /// The native Open dialog is open.
    pub dialog_waiting: bool,
    pub export_open: bool,
    pub help_open: bool,
    pub bench_open: bool,
    pub presenting: bool,
    /// A lesson is open.
    pub lesson_open: bool,
    /// The language of the Lessons menu.
    pub lang: crate::i18n::Lang,
}

/// The top bar.
pub fn top_bar_ui(ui: &mut Ui, input: &TopBarInput<'_>) -> Vec<AppCommand> {
    let mut out: Vec<AppCommand> = Vec::new();
    let compact = ui.available_width() < FULL_BAR;
    ui.horizontal(|ui| {
        ui.label(egui::RichText::new(text::NAME).strong());
        ui.separator();
        out.extend(command::all(file_menu::file_menu_ui(
            ui,
            input.recent,
            input.dialog_waiting,
        )));
        ui.separator();
        if ui
            .selectable_label(input.presenting, present::text::BUTTON)
            .on_hover_text(present::text::BUTTON_TIP)
            .clicked()
        {
            out.push(AppCommand::SetPresenting(!input.presenting));
        }
        out.extend(lessons::lessons_menu_ui(
            ui,
            input.lesson_open,
            input.state.view.plot,
            input.lang,
        ));
        if compact {
            ui.menu_button(text::VIEW, |ui| {
                toggles(ui, input, &mut out);
                ui.separator();
                out.extend(command::all(controls::reset_ui(ui, input.state)));
            })
            .response
            .on_hover_text(text::VIEW_TIP);
        } else {
            toggles(ui, input, &mut out);
            ui.separator();
            out.extend(command::all(controls::reset_ui(ui, input.state)));
        }
    });
    out
}

/// The panel and window toggles.
fn toggles(ui: &mut Ui, input: &TopBarInput<'_>, out: &mut Vec<AppCommand>) {
    let view = &input.state.view;
    if ui
        .selectable_label(view.show_controls, text::CONTROLS)
        .on_hover_text(text::CONTROLS_TIP)
        .clicked()
    {
        out.push(Command::SetShowControls(!view.show_controls).into());
    }
    if ui
        .selectable_label(view.show_inspector, text::INSPECTOR)
        .on_hover_text(text::INSPECTOR_TIP)
        .clicked()
    {
        out.push(Command::SetShowInspector(!view.show_inspector).into());
    }
    if ui
        .selectable_label(input.export_open, export::text::BUTTON)
        .on_hover_text(export::text::BUTTON_TIP)
        .clicked()
    {
        out.push(
            if input.export_open {
                ExportCommand::Close
            } else {
                ExportCommand::Open
            }
            .into(),
        );
    }
    if ui
        .selectable_label(input.help_open, text::HELP)
        .on_hover_text(text::HELP_TIP)
        .clicked()
    {
        out.push(AppCommand::SetHelpOpen(!input.help_open));
    }
    if ui
        .selectable_label(input.bench_open, bench_panel::text::OPEN)
        .on_hover_text(bench_panel::text::OPEN_TIP)
        .clicked()
    {
        out.push(bench_panel::BenchCommand::SetOpen(!input.bench_open).into());
    }
}
