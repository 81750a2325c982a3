//! The per-sample buffers control (under the samples control): which buffer the canvas shows
//! (the resolve, the coverage count, or a sample's colour or depth), the sample index, and
//! the black-edge toggle (GAMES101 A2's bug: colour kept per pixel while coverage is per
//! sample), with the coverage count's legend. The images: `services::sample_images`.

use egui::{Color32, RichText, Ui};

use crate::app::document::state::StateCommand;
use crate::figure::sample_buffers::{CLEARED_DEPTH, SampleBufferKind, SampleView, coverage_colour};

/// A small colour square followed by `label`.
fn swatch(ui: &mut Ui, c: [u8; 4], label: &str) {
    ui.horizontal(|ui| {
        let size = egui::vec2(14.0, 14.0) * (ui.text_style_height(&egui::TextStyle::Body) / 14.0);
        let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
        ui.painter()
            .rect_filled(rect, 2.0, Color32::from_rgb(c[0], c[1], c[2]));
        ui.painter().rect_stroke(
            rect,
            2.0,
            egui::Stroke::new(1.0, Color32::GRAY),
            egui::StrokeKind::Inside,
        );
        ui.label(label);
    });
}

/// The control for a scene with `n` samples per pixel; returns the changed view as a command.
pub fn buffers_ui(ui: &mut Ui, view: SampleView, n: usize) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    if n < 2 {
        ui.label(RichText::new(lang.tr("app.samples.buffers_need")).weak());
        return Vec::new();
    }
    let mut next = view;
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("app.samples.buffers"))
            .on_hover_text(lang.tr("app.samples.buffers_tip"));
        for kind in SampleBufferKind::ALL {
            let name = lang.tr(kind_key(kind));
            if ui
                .add(egui::Button::selectable(view.kind == kind, name))
                .clicked()
            {
                next.kind = kind;
            }
        }
    });
    let index = (view.index as usize).min(n - 1);
    let per_sample = matches!(view.kind, SampleBufferKind::Color | SampleBufferKind::Depth);
    ui.horizontal_wrapped(|ui| {
        ui.label(lang.tr("app.samples.index"))
            .on_hover_text(lang.tr("app.samples.index_tip"));
        for k in 0..n {
            let b = egui::Button::selectable(index == k, k.to_string());
            if ui.add_enabled(per_sample, b).clicked() {
                next.index = k as u32;
            }
        }
    });
    ui.checkbox(&mut next.black_edges, lang.tr("app.samples.black_edges"))
        .on_hover_text(lang.tr("app.samples.black_edges_tip"));
    match view.kind {
        SampleBufferKind::Coverage => {
            ui.horizontal_wrapped(|ui| {
                for c in 0..=n as u8 {
                    let label = lang.tr_with("figure.samples.count", &[("count", &c)]);
                    swatch(ui, coverage_colour(c, n), &label);
                }
            });
        }
        SampleBufferKind::Depth => {
            ui.horizontal_wrapped(|ui| {
                swatch(ui, [0, 0, 0, 255], &lang.tr("app.samples.near"));
                swatch(ui, [255, 255, 255, 255], &lang.tr("app.samples.far"));
                swatch(ui, CLEARED_DEPTH, &lang.tr("figure.samples.cleared"));
            });
        }
        _ => {}
    }
    if next == view {
        Vec::new()
    } else {
        vec![StateCommand::SetSamplesView(next)]
    }
}

/// The catalogue key of `kind`'s button.
fn kind_key(kind: SampleBufferKind) -> &'static str {
    match kind {
        SampleBufferKind::Resolve => "app.samples.buffer_resolve",
        SampleBufferKind::Coverage => "app.samples.buffer_coverage",
        SampleBufferKind::Color => "app.samples.buffer_color",
        SampleBufferKind::Depth => "app.samples.buffer_depth",
    }
}
