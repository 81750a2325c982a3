//! Over the canvas: the progress bar and Cancel button of a render that takes longer than a
//! frame, the note that one was cancelled, and a render's failure in the picture's place.

use std::time::Duration;

use egui::{Align2, Color32, Rect, Ui};

use crate::app::services::render::{RenderFailure, Underway};
use crate::i18n::Lang;

/// How often the progress bar is redrawn while a render runs.
const PROGRESS_REPAINT: Duration = Duration::from_millis(50);

/// Points between the canvas's top edge and the progress box.
const MARGIN: f32 = 8.0;

/// `width`x`height`, as the image size picker writes it.
fn size_text(size: [u32; 2]) -> String {
    format!("{}×{}", size[0], size[1])
}

/// The progress bar and Cancel button of the render `underway`, else the note that the render
/// of size `cancelled` was cancelled, at the top of the canvas `area`. Returns whether Cancel
/// was pressed.
pub(crate) fn underway_ui(
    ui: &Ui,
    area: Rect,
    underway: Option<Underway>,
    cancelled: Option<[u32; 2]>,
    lang: Lang,
) -> bool {
    if underway.is_none() && cancelled.is_none() {
        return false;
    }
    let mut cancel = false;
    egui::Area::new(egui::Id::unique("canvas-render-progress"))
        .order(egui::Order::Foreground)
        .pivot(Align2::CENTER_TOP)
        .fixed_pos(area.center_top() + egui::vec2(0.0, MARGIN))
        .show(ui.ctx(), |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| match underway {
                Some(u) => {
                    ui.ctx().request_repaint_after(PROGRESS_REPAINT);
                    ui.label(lang.tr_with(
                        "app.canvas.rendering",
                        &[
                            ("size", &size_text(u.size)),
                            ("seconds", &format!("{:.1}", u.seconds)),
                        ],
                    ));
                    ui.horizontal(|ui| {
                        ui.add(
                            egui::ProgressBar::new(u.fraction as f32)
                                .desired_width(240.0)
                                .show_percentage(),
                        );
                        cancel = ui.button(lang.tr("app.canvas.cancel")).clicked();
                    });
                }
                None => {
                    let size = cancelled.map(size_text).unwrap_or_default();
                    ui.label(lang.tr_with("app.canvas.cancelled", &[("size", &size)]));
                }
            });
        });
    cancel
}

/// A render's failure, in the picture's place: over the memory budget, what to do about it.
pub(crate) fn failure_ui(ui: &mut Ui, failure: &RenderFailure, lang: Lang) {
    let key = if failure.memory {
        "app.canvas.over_budget"
    } else {
        "app.canvas.render_failed"
    };
    ui.colored_label(
        Color32::LIGHT_RED,
        lang.tr_with(key, &[("error", &failure.text)]),
    );
}
