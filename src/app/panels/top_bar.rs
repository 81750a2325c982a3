//! The top bar: the File menu, the panel and window toggles, presentation mode, the reset
//! buttons and the text size. In a narrow window (a projector at a large text size) the
//! toggles, resets and text size go into a View menu, so the bar stays one row and the
//! canvas keeps its room.

use egui::Ui;

use crate::app::command::ExportCommand;
use crate::app::command::{self, AppCommand};
use crate::app::document::state::{AppState, StateCommand};
use crate::app::panels::{controls, file_menu, lessons};
use crate::i18n::Lang;

/// The text size slider's width in the bar, in points.
const BAR_SLIDER: f32 = 140.0;

/// Points the whole bar takes in one row, with the language switch at its end (the Chinese
/// words are shorter); below that the View menu holds most of it.
fn full_bar(lang: Lang) -> f32 {
    match lang {
        Lang::En => 1450.0,
        Lang::Zh => 1300.0,
    }
}

/// What the top bar shows besides the state.
pub struct TopBarInput<'a> {
    pub state: &'a AppState,
    pub recent: &'a crate::app::document::persist::RecentFiles,
    /// The native Open dialog is open.
    pub dialog_waiting: bool,
    pub export_open: bool,
    pub help_open: bool,
    pub bench_open: bool,
    pub presenting: bool,
    /// A font with Chinese glyphs is installed (else the switch cannot offer Chinese).
    pub cjk_font: bool,
    /// A lesson is open.
    pub lesson_open: bool,
    /// The language of the Lessons menu.
    pub lang: crate::i18n::Lang,
}

/// The top bar.
pub fn top_bar_ui(ui: &mut Ui, input: &TopBarInput<'_>) -> Vec<AppCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out: Vec<AppCommand> = Vec::new();
    let compact = ui.available_width() < full_bar(lang);
    ui.horizontal(|ui| {
        ui.label(egui::RichText::new("barylab").strong());
        ui.separator();
        out.extend(command::all(file_menu::file_menu_ui(
            ui,
            input.recent,
            input.dialog_waiting,
        )));
        ui.separator();
        if ui
            .selectable_label(input.presenting, lang.tr("app.present.button"))
            .on_hover_text(lang.tr("app.present.button_tip"))
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
            ui.menu_button(lang.tr("app.top_bar.view"), |ui| {
                toggles(ui, input, &mut out);
                ui.separator();
                out.extend(command::all(controls::reset_ui(ui, input.state)));
            })
            .response
            .on_hover_text(lang.tr("app.top_bar.view_tip"));
        } else {
            toggles(ui, input, &mut out);
            ui.separator();
            // A shorter text size slider than the panels' leaves room for the language switch.
            ui.scope(|ui| {
                ui.spacing_mut().slider_width = BAR_SLIDER;
                out.extend(command::all(controls::reset_ui(ui, input.state)));
            });
        }
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            out.extend(language_ui(ui, lang, input.cjk_font));
        });
    });
    out
}

/// The language switch, English / 中文, at the bar's right end (outside the View menu, so it
/// is always one click away). Where the bar has no room for both (a narrow window at a large
/// text size) only the other language is offered. Without a Chinese font, Chinese is offered in
/// English words and choosing it says why it cannot be shown.
fn language_ui(ui: &mut Ui, lang: Lang, cjk_font: bool) -> Option<AppCommand> {
    let name = |l: Lang| match l {
        Lang::Zh if !cjk_font => "Chinese",
        l => l.native_name(),
    };
    let font = egui::TextStyle::Button.resolve(ui.style());
    let width = |text: &str| {
        ui.painter()
            .layout_no_wrap(text.to_string(), font.clone(), egui::Color32::WHITE)
            .size()
            .x
            + 2.0 * ui.spacing().button_padding.x
            + ui.spacing().item_spacing.x
    };
    let both: f32 = Lang::ALL.into_iter().map(|l| width(name(l))).sum();
    let room = ui.available_width() >= both;
    let mut picked = None;
    // Right to left: the last language first.
    for l in Lang::ALL.into_iter().rev().filter(|&l| room || l != lang) {
        let tip = match l {
            Lang::Zh if !cjk_font => Lang::En.tr(crate::app::services::locale::NO_CJK_FONT),
            l => l.tr("app.top_bar.lang_tip"),
        };
        if ui
            .selectable_label(lang == l, name(l))
            .on_hover_text(tip)
            .clicked()
            && lang != l
        {
            picked = Some(AppCommand::SetLang(l));
        }
    }
    picked
}

/// The panel and window toggles.
fn toggles(ui: &mut Ui, input: &TopBarInput<'_>, out: &mut Vec<AppCommand>) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let view = &input.state.view;
    if ui
        .selectable_label(view.show_controls, lang.tr("app.top_bar.controls"))
        .on_hover_text(lang.tr("app.top_bar.controls_tip"))
        .clicked()
    {
        out.push(StateCommand::SetShowControls(!view.show_controls).into());
    }
    if ui
        .selectable_label(view.show_inspector, lang.tr("app.top_bar.inspector"))
        .on_hover_text(lang.tr("app.top_bar.inspector_tip"))
        .clicked()
    {
        out.push(StateCommand::SetShowInspector(!view.show_inspector).into());
    }
    if ui
        .selectable_label(input.export_open, lang.tr("app.export.button"))
        .on_hover_text(lang.tr("app.export.button_tip"))
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
        .selectable_label(input.help_open, lang.tr("app.top_bar.help"))
        .on_hover_text(lang.tr("app.top_bar.help_tip"))
        .clicked()
    {
        out.push(AppCommand::SetHelpOpen(!input.help_open));
    }
    if ui
        .selectable_label(input.bench_open, lang.tr("app.bench_panel.open"))
        .on_hover_text(lang.tr("app.bench_panel.open_tip"))
        .clicked()
    {
        out.push(crate::app::command::BenchCommand::SetOpen(!input.bench_open).into());
    }
}
