//! The layout of the app's window around the canvas: the side panels (each open, folded to a
//! strip, or hidden, so the canvas keeps at least half of the window: [`super::side_panels`]),
//! the canvas panel, and presentation mode's card beside or below the canvas.

use std::sync::Arc;

use super::canvas::{self, CanvasInput};
use super::command::{self, AppCommand};
use super::side_panels::{self, Fit};
use super::textures::texture_key;
use super::{BaryApp, compare_image, controls, gpu_view, inspector, present, state};
use crate::raster::Texture;

/// Presentation mode: windows wider than this many heights get the card beside the canvas
/// (taking this share of the width), others below it.
const PRESENT_SIDE_CARD_ASPECT: f32 = 1.5;
const PRESENT_SIDE_CARD_SHARE: f32 = 0.38;

impl BaryApp {
    /// The side panels, in what the canvas can spare; their commands go to `out`.
    pub(super) fn side_panels_ui(&mut self, ui: &mut egui::Ui, out: &mut Vec<AppCommand>) {
        let lang = super::locale::lang(ui.ctx());
        let ctx = ui.ctx().clone();
        // The side panels take what the canvas can spare (at least half of the window's
        // area stays the canvas's); one that does not fit is a strip that opens it.
        let row = ui.available_rect_before_wrap();
        let window = ctx.content_rect();
        let budget = side_panels::budget([window.width(), window.height()], row.height());
        let fits = side_panels::fits(
            budget,
            self.state.view.show_controls,
            self.state.view.show_inspector,
            self.panel_first,
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
                                let shown = inspector::inspector_ui(
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
                                if shown {
                                    self.lessons.open_sections = None;
                                }
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
            };
            out.extend(command::all(canvas::canvas_ui(ui, &mut self.canvas, input)));
        });
    }

    /// Presentation mode: the card (below the canvas in a window about as tall as wide, else
    /// beside it) and the canvas in all the rest.
    pub(super) fn presentation(
        &mut self,
        ui: &mut egui::Ui,
        texture: &Arc<Texture>,
        out: &mut Vec<AppCommand>,
    ) {
        let rect = ui.ctx().content_rect();
        let frame = egui::Frame::new()
            .fill(present::CARD_FILL)
            .inner_margin(egui::Margin::same(12));
        let (hover, pin) = (self.reports.hover.as_ref(), self.reports.pin.as_ref());
        let spacing = ui.spacing().item_spacing.y;
        let below = rect.width() < PRESENT_SIDE_CARD_ASPECT * rect.height();
        let size = if below {
            present::card_text_below(
                rect.width() - present::PANEL_MARGINS,
                rect.height(),
                spacing,
            )
        } else {
            present::card_text(rect.height())
        };
        let hint = self
            .lessons
            .session
            .is_some()
            .then(|| crate::i18n::tr(self.lang(), "lesson.present_hint"));
        let hint = hint.as_deref();
        if below {
            egui::Panel::bottom("present-card")
                .frame(frame)
                .resizable(false)
                .exact_size(
                    present::card_height(rect.width() - present::PANEL_MARGINS, spacing, size)
                        + present::PANEL_MARGINS,
                )
                .show(ui, |ui| present::card_ui(ui, hover, pin, size, hint));
        } else {
            egui::Panel::right("present-card")
                .frame(frame)
                .resizable(false)
                .exact_size(rect.width() * PRESENT_SIDE_CARD_SHARE)
                .show(ui, |ui| present::card_ui(ui, hover, pin, size, hint));
        }
        self.canvas_panel(ui, texture, out);
    }
}

/// A collapsed side panel: a strip with one button that opens it (and lets it have the room
/// first).
fn strip(ui: &mut egui::Ui, id: &'static str, left: bool, name: &str) -> Vec<AppCommand> {
    let lang = super::locale::lang(ui.ctx());
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
                        state::Command::SetShowControls(true)
                    } else {
                        state::Command::SetShowInspector(true)
                    }
                    .into(),
                );
            }
        });
    out
}
