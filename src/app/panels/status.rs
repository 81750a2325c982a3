//! The status line: canvas size, mode, timings, messages.

use egui::{Color32, RichText, Ui};

use crate::app::document::state::AppState;
use crate::app::panels::canvas::CanvasState;
use crate::figure::Compare;
use crate::raster::Interpolation;

mod fit;

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
    Texture(crate::app::services::render::TextureKey),
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

/// The status line: one line, whose less important parts go (to the frame time's tooltip)
/// or get shorter when the window is narrow ([`fit`]).
pub fn status_ui(
    ui: &mut Ui,
    state: &AppState,
    canvas: &CanvasState,
    timing: FrameTiming,
    message: Option<&Message>,
) {
    let lang = crate::app::services::locale::lang(ui.ctx());
    // One line, always: the timings change every frame, and a status line that wrapped would
    // change the canvas's height, move the canvas and re-render it (a feedback loop).
    ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Truncate);
    let mode = state.options().mode;
    let (mode_text, mode_color) = match state.view.compare {
        Compare::Single => match mode {
            Interpolation::Affine => (
                lang.tr("app.status.affine"),
                Color32::from_rgb(230, 140, 60),
            ),
            Interpolation::Perspective => (
                lang.tr("app.status.perspective"),
                Color32::from_rgb(80, 170, 255),
            ),
        },
        Compare::SideBySide => (lang.tr("app.status.side_by_side"), Color32::LIGHT_GRAY),
        Compare::Wipe => (lang.tr("app.status.wipe"), Color32::LIGHT_GRAY),
        Compare::Difference => (lang.tr("app.status.difference"), Color32::LIGHT_GRAY),
    };
    let canvas_text = canvas.output.as_ref().map(|out| {
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
        let args: [(&str, &dyn std::fmt::Display); 3] =
            [("w", &out.size[0]), ("h", &out.size[1]), ("px", &px)];
        [
            lang.tr_with("app.status.canvas", &args),
            lang.tr_with("app.status.canvas_short", &args),
        ]
    });
    let t = canvas.timing;
    let frame = timing
        .frame_ms
        .map_or_else(|| "–".to_string(), |f| format!("{f:.1} ms"));
    let rasterizer = match state.view.rasterizer {
        crate::raster::render::Rasterizer::EdgeFunction => lang.tr("app.status.edge"),
        crate::raster::render::Rasterizer::Scanline => lang.tr("app.status.scanline"),
    };
    let all_timings = format!(
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
    );
    let texts = fit::StatusTexts {
        gpu: state.view.gpu.then(|| lang.tr("gpu_view.status")),
        mode: mode_text,
        canvas: canvas_text,
        timings: [
            all_timings.clone(),
            format!("{} {}", &lang.tr("app.status.frame"), frame),
        ],
        message: message.map(|m| m.text.clone()),
        help: lang.tr("app.status.help"),
    };
    let font = egui::TextStyle::Body.resolve(ui.style());
    let measure = |s: &str| {
        ui.fonts_mut(|f| {
            f.layout_no_wrap(s.to_string(), font.clone(), Color32::WHITE)
                .size()
                .x
        })
    };
    let gap = ui.spacing().item_spacing.x;
    let shown = texts.fit(ui.available_width(), gap, SEPARATOR, measure);
    ui.horizontal(|ui| {
        if let Some(g) = &texts.gpu {
            ui.label(RichText::new(g).strong().color(Color32::LIGHT_GREEN));
        }
        ui.label(RichText::new(&texts.mode).strong().color(mode_color));
        ui.separator();
        if let Some([long, short]) = &texts.canvas {
            ui.label(if shown.long_canvas { long } else { short });
            ui.separator();
        }
        let tip = if shown.all_timings {
            lang.tr("app.status.frame_tip")
        } else {
            format!("{all_timings}\n\n{}", lang.tr("app.status.frame_tip"))
        };
        ui.label(&texts.timings[usize::from(!shown.all_timings)])
            .on_hover_text(tip);
        if let Some(m) = message {
            ui.separator();
            let c = if m.error {
                Color32::from_rgb(255, 110, 110)
            } else {
                Color32::LIGHT_GREEN
            };
            ui.label(RichText::new(&m.text).color(c));
        }
        if shown.help {
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                ui.label(RichText::new(&texts.help).weak());
            });
        }
    });
}

/// Points a separator takes on the status line besides the gaps on either side of it.
const SEPARATOR: f32 = 6.0;
