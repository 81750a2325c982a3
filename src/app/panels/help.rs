//! The help window: what the app shows and its keyboard shortcuts.

use egui::{RichText, Ui};

/// The mouse rows: catalogue keys of what to do and what it does.
const MOUSE_ROWS: &[(&str, &str)] = &[
    (
        "app.help.mouse_rows.m01.key",
        "app.help.mouse_rows.m01.what",
    ),
    (
        "app.help.mouse_rows.m02.key",
        "app.help.mouse_rows.m02.what",
    ),
    (
        "app.help.mouse_rows.m03.key",
        "app.help.mouse_rows.m03.what",
    ),
    (
        "app.help.mouse_rows.m04.key",
        "app.help.mouse_rows.m04.what",
    ),
    (
        "app.help.mouse_rows.m05.key",
        "app.help.mouse_rows.m05.what",
    ),
    (
        "app.help.mouse_rows.m06.key",
        "app.help.mouse_rows.m06.what",
    ),
    (
        "app.help.mouse_rows.m07.key",
        "app.help.mouse_rows.m07.what",
    ),
    (
        "app.help.mouse_rows.m08.key",
        "app.help.mouse_rows.m08.what",
    ),
    (
        "app.help.mouse_rows.m09.key",
        "app.help.mouse_rows.m09.what",
    ),
    (
        "app.help.mouse_rows.m10.key",
        "app.help.mouse_rows.m10.what",
    ),
];

/// The keyboard rows: catalogue keys of what to do and what it does.
const KEY_ROWS: &[(&str, &str)] = &[
    ("app.help.key_rows.k01.key", "app.help.key_rows.k01.what"),
    ("app.help.key_rows.k02.key", "app.help.key_rows.k02.what"),
    ("app.help.key_rows.k03.key", "app.help.key_rows.k03.what"),
    ("app.help.key_rows.k04.key", "app.help.key_rows.k04.what"),
    ("app.help.key_rows.k05.key", "app.help.key_rows.k05.what"),
    ("app.help.key_rows.k06.key", "app.help.key_rows.k06.what"),
    ("app.help.key_rows.k20.key", "app.help.key_rows.k20.what"),
    ("app.help.key_rows.k21.key", "app.help.key_rows.k21.what"),
    ("app.help.key_rows.k22.key", "app.help.key_rows.k22.what"),
    ("app.help.key_rows.k23.key", "app.help.key_rows.k23.what"),
    ("app.help.key_rows.k24.key", "app.help.key_rows.k24.what"),
    ("app.help.key_rows.k07.key", "app.help.key_rows.k07.what"),
    ("app.help.key_rows.k08.key", "app.help.key_rows.k08.what"),
    ("app.help.key_rows.k09.key", "app.help.key_rows.k09.what"),
    ("app.help.key_rows.k10.key", "app.help.key_rows.k10.what"),
    ("app.help.key_rows.k11.key", "app.help.key_rows.k11.what"),
    ("app.help.key_rows.k12.key", "app.help.key_rows.k12.what"),
    ("app.help.key_rows.k13.key", "app.help.key_rows.k13.what"),
    ("app.help.key_rows.k14.key", "app.help.key_rows.k14.what"),
    ("app.help.key_rows.k15.key", "app.help.key_rows.k15.what"),
    ("app.help.key_rows.k16.key", "app.help.key_rows.k16.what"),
    ("app.help.key_rows.k17.key", "app.help.key_rows.k17.what"),
    ("app.help.key_rows.k18.key", "app.help.key_rows.k18.what"),
    ("app.help.key_rows.k19.key", "app.help.key_rows.k19.what"),
    ("quiz.help_key", "quiz.help_what"),
];

/// The help window's contents (they scroll when the window is shorter than they are).
pub fn help_ui(ui: &mut Ui) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    egui::ScrollArea::vertical().show(ui, |ui| {
        ui.label(lang.tr("app.help.intro"));
        ui.add_space(8.0);
        for (id, title, rows) in [
            ("help-mouse", "app.help.mouse", MOUSE_ROWS),
            ("help-keys", "app.help.keys", KEY_ROWS),
        ] {
            ui.label(RichText::new(lang.tr(title)).strong());
            egui::Grid::new(id)
                .num_columns(2)
                .striped(true)
                .spacing([16.0, 4.0])
                .show(ui, |ui| {
                    for (k, what) in rows {
                        ui.label(RichText::new(lang.tr(k)).monospace().strong());
                        ui.label(lang.tr(what));
                        ui.end_row();
                    }
                });
            ui.add_space(8.0);
        }
    });
}
