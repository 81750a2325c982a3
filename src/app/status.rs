//! The status line: canvas size, mode, timings, messages.

use egui::{Color32, RichText, Ui};

use super::canvas::CanvasState;
use super::state::AppState;
use crate::figure::Compare;
use crate::raster::Interpolation;

/// Timings the app measures itself.
#[derive(Clone, Copy, Debug, Default)]
pub struct FrameTiming {
    /// CPU time of the last whole frame, from eframe.
    pub frame_ms: Option<f32>,
    /// This app's `ui` function in the previous frame.
    pub ui_ms: f64,
}

/// A message for the status line.
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    pub text: String,
    pub error: bool,
    /// What an error is about, so it goes when its cause does.
    pub cause: Option<Cause>,
}

/// What a red message on the status line is about.
#[derive(Clone, Debug, PartialEq)]
pub enum Cause {
    /// This texture did not load (goes when the scene names another one).
    Texture(super::render::TextureKey),
    /// The hovered or pinned pixel could not be probed (goes with the next good probe).
    Probe,
    /// A scene edit could not be done (goes with the next edit that works).
    Edit,
}

impl Message {
    pub fn note(text: String) -> Self {
        Self {
            text,
            error: false,
            cause: None,
        }
    }

    pub fn error(text: String, cause: Option<Cause>) -> Self {
        Self {
            text,
            error: true,
            cause,
        }
    }
}

/// Clears `message` if it is an error whose cause `gone` says is gone.
pub fn clear_if(message: &mut Option<Message>, gone: impl Fn(&Cause) -> bool) {
    if message
        .as_ref()
        .is_some_and(|m| m.error && m.cause.as_ref().is_some_and(&gone))
    {
        *message = None;
    }
}

/// The status line.
pub fn status_ui(
    ui: &mut Ui,
    state: &AppState,
    canvas: &CanvasState,
    timing: FrameTiming,
    message: Option<&Message>,
) {
    let lang = super::locale::lang(ui.ctx());
    // One line, always: the timings change every frame, and a status line that wrapped would
    // change the canvas's height, move the canvas and re-render it (a feedback loop).
    ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Truncate);
    ui.horizontal(|ui| {
        let mode = state.options().mode;
        let (mode_text, mode_color) = match state.view.compare {
            Compare::Single => match mode {
                Interpolation::Affine => (
                    &lang.tr("app.status.affine"),
                    Color32::from_rgb(230, 140, 60),
                ),
                Interpolation::Perspective => (
                    &lang.tr("app.status.perspective"),
                    Color32::from_rgb(80, 170, 255),
                ),
            },
            Compare::SideBySide => (&lang.tr("app.status.side_by_side"), Color32::LIGHT_GRAY),
            Compare::Wipe => (&lang.tr("app.status.wipe"), Color32::LIGHT_GRAY),
            Compare::Difference => (&lang.tr("app.status.difference"), Color32::LIGHT_GRAY),
        };
        if state.view.gpu {
            ui.label(
                RichText::new(lang.tr("gpu_view.status"))
                    .strong()
                    .color(Color32::LIGHT_GREEN),
            );
        }
        ui.label(RichText::new(mode_text).strong().color(mode_color));
        ui.separator();
        if let Some(out) = &canvas.output {
            // Screen pixels per rendered pixel: whole when magnified.
            let px = canvas
                .views
                .first()
                .map_or(1.0, |v| v.transform.scale * ui.ctx().pixels_per_point());
            let px = if (px - px.round()).abs() < 1e-3 {
                format!("{}", px.round())
            } else {
                format!("{px:.2}")
            };
            ui.label(lang.tr_with(
                "app.status.canvas",
                &[("w", &out.size[0]), ("h", &out.size[1]), ("px", &px)],
            ));
            ui.separator();
        }
        let t = canvas.timing;
        let frame = timing
            .frame_ms
            .map_or_else(|| "–".to_string(), |f| format!("{f:.1} ms"));
        let rasterizer = match state.view.rasterizer {
            crate::raster::render::Rasterizer::EdgeFunction => lang.tr("app.status.edge"),
            crate::raster::render::Rasterizer::Scanline => lang.tr("app.status.scanline"),
        };
        ui.label(format!(
            "{} ({}) {:.1} ms · {} {:.1} ms · {} {:.1} ms · {} {}",
            &lang.tr("app.status.render"),
            rasterizer,
            t.render_ms,
            &lang.tr("app.status.upload"),
            t.upload_ms,
            &lang.tr("app.status.ui"),
            timing.ui_ms,
            &lang.tr("app.status.frame"),
            frame
        ))
        .on_hover_text(lang.tr("app.status.frame_tip"));
        if let Some(m) = message {
            ui.separator();
            let c = if m.error {
                Color32::from_rgb(255, 110, 110)
            } else {
                Color32::LIGHT_GREEN
            };
            ui.label(RichText::new(&m.text).color(c));
        }
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            ui.label(RichText::new(lang.tr("app.status.help")).weak());
        });
    });
}
