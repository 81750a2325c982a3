//! The image size picker: fixed sizes for teaching (the rendered image keeps its pixels
//! through any layout change), or "fit window".

use egui::Ui;

use crate::app::document::state::{AppState, StateCommand};

/// The fixed sizes offered, smallest first.
pub const IMAGE_SIZES: [[u32; 2]; 5] = [[32, 24], [160, 120], [320, 240], [800, 600], [1280, 720]];

fn label(size: [u32; 2]) -> String {
    format!("{}×{}", size[0], size[1])
}

/// The picker; returns [`StateCommand::SetImageSize`] when another size is chosen.
pub fn image_size_ui(ui: &mut Ui, state: &AppState) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    let (w, h) = state.scene.size();
    let current = (!state.view.fit_window).then_some([w, h]);
    let shown = match current {
        None => lang.tr("app.image_size.fit_window"),
        Some(s) if IMAGE_SIZES.contains(&s) => label(s),
        Some(s) => format!("{} {}", label(s), &lang.tr("app.image_size.scene_size")),
    };
    ui.horizontal(|ui| {
        ui.label(lang.tr("app.image_size.image_size"));
        egui::ComboBox::from_id_salt("image-size")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                for s in IMAGE_SIZES {
                    if ui.selectable_label(current == Some(s), label(s)).clicked() {
                        out.push(StateCommand::SetImageSize(Some(s)));
                    }
                }
                if ui
                    .selectable_label(current.is_none(), lang.tr("app.image_size.fit_window"))
                    .clicked()
                {
                    out.push(StateCommand::SetImageSize(None));
                }
            })
            .response
            .on_hover_text(lang.tr("app.image_size.tip"));
    });
    out
}
