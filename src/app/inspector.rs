//! The inspector panel: the derivation of the hovered and the pinned pixel.

use egui::{RichText, Ui};

use super::pixel::PixelReport;

/// User-facing strings of the inspector.
mod text {
    pub const TITLE: &str = "Pixel";
    pub const HOVER_HINT: &str = "Hover the canvas to inspect a pixel; click to pin it.";
    pub const HOVERED: &str = "Hovered";
    pub const PINNED: &str = "Pinned";
    pub const NOT_COVERED: &str = "not covered";
}

/// The inspector panel.
pub fn inspector_ui(ui: &mut Ui, hovered: Option<&PixelReport>, pinned: Option<&PixelReport>) {
    ui.heading(text::TITLE);
    if hovered.is_none() && pinned.is_none() {
        ui.label(text::HOVER_HINT);
    }
    for (title, r) in [(text::HOVERED, hovered), (text::PINNED, pinned)] {
        let Some(r) = r else { continue };
        ui.label(RichText::new(format!("{title} ({}, {})", r.pixel[0], r.pixel[1])).strong());
        match r.weights_screen {
            Some(w) => {
                ui.label(format!(
                    "screen weights {:.4} {:.4} {:.4}",
                    w[0], w[1], w[2]
                ));
            }
            None => {
                ui.label(text::NOT_COVERED);
            }
        }
    }
}
