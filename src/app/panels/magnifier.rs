//! The magnifier: the pinned pixel and its neighbours enlarged for the back of the room, with
//! the pixel grid, every sample point and the triangle's edges
//! ([`crate::figure::overlay::magnifier`] gives the shapes; this paints them over the canvas's
//! own texture, whose magnified pixels stay crisp squares). Presenting shows it for any pinned
//! pixel; outside presentation mode, in a column beside the canvas for a pixel of several
//! samples ([`BaryApp::magnifier_docked`](crate::app::BaryApp)).

use egui::{Color32, Rect, TextureId, Ui};

use crate::app::panels::paint::{self, CanvasTransform};
use crate::figure::overlay::{self, SampleMark, TriangleMark};
use crate::i18n::Lang;

/// The magnifier's square takes this share of the smaller side of the canvas when it lies over
/// the picture.
pub const OVER_SHARE: f32 = 0.34;
/// Points: the smallest square worth drawing (7 pixels of 16 points each).
pub const MIN_SIDE: f32 = 112.0;

/// What the magnifier shows.
pub struct MagnifierInput {
    /// The canvas's texture of the view and its size in pixels.
    pub texture: (TextureId, [u32; 2]),
    /// The pinned pixel.
    pub pixel: [u32; 2],
    /// The triangle its weights refer to.
    pub triangle: Option<TriangleMark>,
    /// Every sample of the pixels shown, when there are several per pixel.
    pub samples: Vec<SampleMark>,
    /// The language of the title.
    pub lang: Lang,
    /// The title's text size in points.
    pub text_size: f32,
}

/// The height of the title line above the square, for a title of `text_size` points.
pub fn title_height(text_size: f32) -> f32 {
    text_size * 1.4
}

/// Paints the magnifier into `ui`: a title line, then a square `side` points wide.
pub fn magnifier_ui(ui: &mut Ui, side: f32, input: &MagnifierInput) {
    let cells = (2 * radius(input) + 1) as f32;
    let k = (side / cells).floor().max(1.0);
    let side = k * cells;
    let title = rust_i18n::t!(
        "app.present.magnifier",
        locale = input.lang.code(),
        x = input.pixel[0],
        y = input.pixel[1]
    );
    ui.set_max_width(side);
    ui.label(
        egui::RichText::new(title)
            .size(input.text_size)
            .color(Color32::from_gray(225)),
    );
    let (rect, _) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
    paint_square(ui.painter(), rect, k, input);
}

/// Pixels shown on each side of the pinned one (fewer when each pixel has several samples).
fn radius(input: &MagnifierInput) -> u32 {
    overlay::magnifier_radius(!input.samples.is_empty())
}

/// The enlarged pixels and their shapes in `rect`, `k` points per pixel.
fn paint_square(painter: &egui::Painter, rect: Rect, k: f32, input: &MagnifierInput) {
    let painter = painter.with_clip_rect(rect);
    painter.rect_filled(rect, 0.0, Color32::from_gray(20));
    let (lo, _) = overlay::magnified_rect(input.pixel, radius(input));
    let t = CanvasTransform {
        origin: rect.min - egui::vec2(lo.x as f32 * k, lo.y as f32 * k),
        scale: k,
    };
    let (id, size) = input.texture;
    let image = Rect::from_min_max(
        t.to_screen(glam::DVec2::ZERO),
        t.to_screen(glam::DVec2::new(f64::from(size[0]), f64::from(size[1]))),
    );
    painter.image(
        id,
        image,
        Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0)),
        Color32::WHITE,
    );
    let shapes = overlay::magnifier(
        input.pixel,
        input.triangle.as_ref(),
        size,
        radius(input),
        &input.samples,
    );
    paint::paint(&painter, rect, rect, t, &shapes, &[]);
    painter.rect_stroke(
        rect,
        0.0,
        egui::Stroke::new(2.0, Color32::from_gray(200)),
        egui::StrokeKind::Inside,
    );
}

/// The share of the room the magnifier's column takes at most.
const COLUMN_SHARE: f32 = 0.45;
/// Points: the column's inner margin.
const COLUMN_MARGIN: f32 = 12.0;

impl crate::app::BaryApp {
    /// Outside presentation mode, a pinned pixel of several samples enlarged with its samples
    /// in a column right of the canvas, as large as the canvas's height allows: at a
    /// projector's 1024x768 with text size 1.5, the samples lesson's 120x120 picture is drawn
    /// at 2x, too small for a room to see which samples each triangle covers. Not during a
    /// quiz (its column is there), nor where the canvas would keep under
    /// [`CANVAS_BESIDE_COLUMN`](crate::app::side_panels::CANVAS_BESIDE_COLUMN).
    pub(in crate::app) fn magnifier_docked(&mut self, ui: &mut Ui) {
        self.magnifier_rect = None;
        let samples = self
            .canvas
            .output
            .as_ref()
            .is_some_and(|o| o.scene.samples().count.get() > 1);
        if !samples || self.quiz.session.is_some() {
            return;
        }
        let text = ui.text_style_height(&egui::TextStyle::Body);
        let Some(input) = self.magnifier_input(text) else {
            return;
        };
        let room = ui.available_width();
        let side = (ui.available_height() - title_height(text) - 2.0 * COLUMN_MARGIN)
            .min(COLUMN_SHARE * room - 2.0 * COLUMN_MARGIN);
        let width = side + 2.0 * COLUMN_MARGIN;
        if side < MIN_SIDE || room - width < crate::app::side_panels::CANVAS_BESIDE_COLUMN {
            return;
        }
        let shown = egui::Panel::right("magnifier-column")
            .frame(
                egui::Frame::new()
                    .fill(crate::app::panels::present::CARD_FILL)
                    .inner_margin(egui::Margin::same(COLUMN_MARGIN as i8)),
            )
            .resizable(false)
            .exact_size(width)
            .show(ui, |ui| magnifier_ui(ui, side, &input));
        self.magnifier_rect = Some(shown.response.rect);
    }
}
