//! The layout of the app's window around the canvas: the side panels (each open, folded to a
//! strip, or hidden, so the canvas keeps at least half of the window: [`crate::app::side_panels`]),
//! the canvas panel, and presentation mode's card beside or below the canvas ([`presenting`]).

use std::sync::Arc;

use crate::app::BaryApp;
use crate::app::command::{self, AppCommand};
use crate::app::document::state;
use crate::app::panels::canvas::{self, CanvasInput};
use crate::app::panels::canvas_layout::Framing;
use crate::app::panels::{compare_image, controls, gpu_view, inspector};
use crate::app::services::textures::texture_key;
use crate::app::side_panels::{self, Fit};
use crate::raster::Texture;

mod presenting;

/// Presentation mode draws the canvas's marks (handles, labels, markers) this much larger.
const PRESENT_MARK_SCALE: f32 = 1.35;

impl BaryApp {
    /// The side panels, in what the canvas can spare; their commands go to `out`.
    pub(super) fn side_panels_ui(&mut self, ui: &mut egui::Ui, out: &mut Vec<AppCommand>) {
        let lang = crate::app::services::locale::lang(ui.ctx());
        let ctx = ui.ctx().clone();
        // The side panels take what the canvas can spare (at least half of the window's
        // area stays the canvas's); one that does not fit is a strip that opens it.
        let row = ui.available_rect_before_wrap();
        let window = ctx.content_rect();
        let budget = side_panels::budget([window.width(), window.height()], row.height());
        let fits = side_panels::fits_forced(
            budget,
            side_panels::room(window.width()),
            self.state.view.show_controls,
            self.state.view.show_inspector,
            self.panel_first,
            self.panel_forced,
        );
        let mut controls_width = 0.0;
        match fits.controls {
            Fit::Hidden => {}
            Fit::Strip => {
                controls_width = side_panels::STRIP;
                out.extend(strip(
                    ui,
                    "controls-strip",
                    true,
                    &lang.tr("app.top_bar.controls"),
                ));
            }
            Fit::Open { max } => {
                let r = egui::Panel::left("controls")
                    .resizable(true)
                    .default_size(side_panels::CONTROLS_DEFAULT)
                    .size_range(side_panels::PANEL_MIN..=max)
                    .show(ui, |ui| {
                        out.extend(fold_row(ui, true, &lang.tr("app.top_bar.controls")));
                        // Content never widens the panel (see the inspector below).
                        let width = ui.available_width();
                        egui::ScrollArea::both()
                            .auto_shrink([false, false])
                            .show(ui, |ui| {
                                ui.set_max_width(width);
                                out.extend(command::all(controls::controls_ui(ui, &self.state)));
                            });
                    });
                controls_width = r.response.rect.width();
            }
        }
        match fits.inspector {
            Fit::Hidden => {}
            Fit::Strip => {
                out.extend(strip(
                    ui,
                    "inspector-strip",
                    false,
                    &lang.tr("app.top_bar.inspector"),
                ));
            }
            Fit::Open { max } => {
                let max = max.min(budget - controls_width).max(side_panels::PANEL_MIN);
                egui::Panel::right("inspector")
                    .resizable(true)
                    .default_size(side_panels::INSPECTOR_DEFAULT)
                    .size_range(side_panels::PANEL_MIN..=max)
                    .show(ui, |ui| {
                        // Content never widens the panel: lines wrap at its width, and
                        // anything wider still scrolls. (A panel that grew with the hovered
                        // pixel's text would move the canvas under the pointer, change the
                        // hovered pixel, and so on.)
                        let width = ui.available_width();
                        egui::ScrollArea::both()
                            .auto_shrink([false, false])
                            .show(ui, |ui| {
                                ui.set_max_width(width);
                                let asked = inspector::inspector_ui(
                                    ui,
                                    self.reports.hover.as_ref(),
                                    self.reports.pin.as_ref(),
                                    self.lessons.open_sections.as_deref(),
                                    compare_image::other_view(
                                        self.compare_image.as_ref(),
                                        self.state.view.gpu,
                                        &self.gpu_view,
                                    ),
                                );
                                out.extend(crate::app::command::all(asked));
                            });
                    });
            }
        }
    }

    /// The canvas in the rest of the window.
    pub(super) fn canvas_panel(
        &mut self,
        ui: &mut egui::Ui,
        texture: &Arc<Texture>,
        framing: Framing,
        out: &mut Vec<AppCommand>,
    ) {
        egui::CentralPanel::default().show(ui, |ui| {
            let gpu = compare_image::other_view(
                self.compare_image.as_ref(),
                self.state.view.gpu,
                &self.gpu_view,
            );
            if let Some(ic) = self.compare_image.as_ref().filter(|_| !self.presenting) {
                out.extend(compare_image::strip_ui(ui, ic, self.state.view.compare));
                ui.separator();
            } else if let Some(g) = gpu.filter(|_| !self.presenting) {
                let compare = self.state.view.compare;
                out.extend(command::all(gpu_view::strip_ui(ui, g, compare)));
                ui.separator();
            }
            let input = CanvasInput {
                state: &self.state,
                texture,
                texture_key: texture_key(&self.state.scene, self.state.scene_dir.as_deref()),
                hover_report: self.reports.hover.as_ref(),
                pin_report: self.reports.pin.as_ref(),
                gpu,
                framing,
                // Two images side by side are each too small for the larger marks.
                mark_scale: if self.presenting
                    && self.state.view.compare != crate::figure::Compare::SideBySide
                {
                    PRESENT_MARK_SCALE
                } else {
                    1.0
                },
            };
            out.extend(command::all(canvas::canvas_ui(ui, &mut self.canvas, input)));
        });
    }
}

/// An open side panel's first row: its name and a button that folds it to a strip (so a panel
/// opened on a small window, where the canvas gave way, is as easily put away).
fn fold_row(ui: &mut egui::Ui, left: bool, name: &str) -> Vec<AppCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut folded = false;
    ui.horizontal(|ui| {
        ui.label(egui::RichText::new(name).strong());
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let icon = if left { "«" } else { "»" };
            folded = ui
                .button(icon)
                .on_hover_text(lang.tr_with("app.layout.fold_tip", &[("panel", &name)]))
                .clicked();
        });
    });
    if !folded {
        return Vec::new();
    }
    vec![
        if left {
            state::StateCommand::SetShowControls(false)
        } else {
            state::StateCommand::SetShowInspector(false)
        }
        .into(),
    ]
}

/// A collapsed side panel: a strip with one button that opens it (and lets it have the room
/// first).
fn strip(ui: &mut egui::Ui, id: &'static str, left: bool, name: &str) -> Vec<AppCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    let panel = if left {
        egui::Panel::left(id)
    } else {
        egui::Panel::right(id)
    };
    panel
        .resizable(false)
        .exact_size(side_panels::STRIP)
        .show(ui, |ui| {
            let icon = if left { "»" } else { "«" };
            if ui
                .button(icon)
                .on_hover_text(lang.tr_with("app.layout.strip_tip", &[("panel", &name)]))
                .clicked()
            {
                out.push(
                    if left {
                        state::StateCommand::SetShowControls(true)
                    } else {
                        state::StateCommand::SetShowInspector(true)
                    }
                    .into(),
                );
            }
        });
    out
}
