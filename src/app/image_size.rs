//! The image size picker: fixed sizes for teaching (the rendered image keeps its pixels
//! through any layout change), or "fit window".

use egui::Ui;

use super::state::{AppState, Command};

/// User-facing strings of the image size picker.
pub mod text {
    pub const IMAGE_SIZE: &str = "Image size";
    pub const FIT_WINDOW: &str = "Fit window";
    pub const SCENE_SIZE: &str = "(scene)";
    pub const TIP: &str = "How many pixels the image has. A fixed size keeps every pixel (and a \
        pinned pixel) where it is when the window, the panels, the comparison or the text size \
        change; the image is drawn as large as the canvas allows, each pixel a square. \
        \"Fit window\" renders as many pixels as the canvas holds at the pixel size below.";
}

/// The fixed sizes offered, smallest first.
pub const IMAGE_SIZES: [[u32; 2]; 5] = [[32, 24], [160, 120], [320, 240], [800, 600], [1280, 720]];

fn label(size: [u32; 2]) -> String {
    format!("{}×{}", size[0], size[1])
}

/// The picker; returns [`Command::SetImageSize`] when another size is chosen.
pub fn image_size_ui(ui: &mut Ui, state: &AppState) -> Vec<Command> {
    let mut out = Vec::new();
    let (w, h) = state.scene.size();
    let current = (!state.view.fit_window).then_some([w, h]);
    let shown = match current {
        None => text::FIT_WINDOW.to_string(),
        Some(s) if IMAGE_SIZES.contains(&s) => label(s),
        Some(s) => format!("{} {}", label(s), text::SCENE_SIZE),
    };
    ui.horizontal(|ui| {
        ui.label(text::IMAGE_SIZE);
        egui::ComboBox::from_id_salt("image-size")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                for s in IMAGE_SIZES {
                    if ui.selectable_label(current == Some(s), label(s)).clicked() {
                        out.push(Command::SetImageSize(Some(s)));
                    }
                }
                if ui
                    .selectable_label(current.is_none(), text::FIT_WINDOW)
                    .clicked()
                {
                    out.push(Command::SetImageSize(None));
                }
            })
            .response
            .on_hover_text(text::TIP);
    });
    out
}
