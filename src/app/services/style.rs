//! The look of the app: text sizes for a projector, spacing, the dark theme, and the UI zoom
//! kept in the view settings.

/// Text sizes in points, large enough for a projector at zoom 1.
pub fn apply_style(ctx: &egui::Context) {
    use egui::{FontFamily, FontId, TextStyle};
    ctx.all_styles_mut(|style| {
        style.text_styles = [
            (
                TextStyle::Heading,
                FontId::new(26.0, FontFamily::Proportional),
            ),
            (TextStyle::Body, FontId::new(18.0, FontFamily::Proportional)),
            (
                TextStyle::Button,
                FontId::new(18.0, FontFamily::Proportional),
            ),
            (
                TextStyle::Monospace,
                FontId::new(17.0, FontFamily::Monospace),
            ),
            (
                TextStyle::Small,
                FontId::new(14.0, FontFamily::Proportional),
            ),
        ]
        .into();
        style.spacing.item_spacing = egui::vec2(8.0, 6.0);
        style.spacing.button_padding = egui::vec2(8.0, 4.0);
        style.spacing.interact_size.y = 26.0;
        style.spacing.slider_width = 180.0;
    });
    ctx.set_visuals(egui::Visuals::dark());
}

/// Keeps egui's zoom and the saved `ui_scale` together: a zoom changed with Ctrl +/- since
/// the last frame (`applied` is what was set then) becomes the `ui_scale`, and a `ui_scale`
/// changed by a command is applied.
pub fn sync_zoom(ctx: &egui::Context, applied: &mut Option<f32>, ui_scale: &mut f32) {
    let z = ctx.zoom_factor();
    if let Some(applied) = *applied
        && (z - applied).abs() > f32::EPSILON
    {
        // Changed with Ctrl +/-: keep it.
        *ui_scale = z;
    }
    if (*ui_scale - z).abs() > f32::EPSILON {
        ctx.set_zoom_factor(*ui_scale);
    }
    *applied = Some(*ui_scale);
}

/// A small square of colour `c`.
pub(in crate::app) fn swatch(ui: &mut egui::Ui, c: [u8; 4]) {
    let h = ui.text_style_height(&egui::TextStyle::Body) * 0.8;
    let (rect, _) = ui.allocate_exact_size(egui::vec2(h, h), egui::Sense::hover());
    ui.painter()
        .rect_filled(rect, 2.0, egui::Color32::from_rgb(c[0], c[1], c[2]));
    ui.painter().rect_stroke(
        rect,
        2.0,
        egui::Stroke::new(1.0, egui::Color32::GRAY),
        egui::StrokeKind::Inside,
    );
}
