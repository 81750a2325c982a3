//! The 3D view beside the canvas: the space view of `figure::space` (the eye, the frustum,
//! the image plane, the triangles and the hovered, else pinned, pixel's ray meeting its
//! triangle at P beside the affine guess Q), painted with egui from the same shapes the
//! figure writes as SVG. Its own orbit camera: drag to orbit, scroll to zoom, a reset button.
//! The scene follows the canvas's render (a dragged corner moves it live).

use egui::epaint::PathStroke;
use egui::{Align2, Color32, FontId, Pos2, RichText, Sense, Shape as EShape, Stroke, Ui};

use crate::app::command::AppCommand;
use crate::app::document::state::StateCommand;
use crate::app::services::pixel::PixelReport;
use crate::app::services::render::CanvasOutput;
use crate::figure::space::{
    Anchor2, Colour, INK, Orbit, Shape, ShapeKind, SpaceScene, TetraFigure, is_tetrahedron,
    panel_lines, shapes,
};

/// The labels' size in the 3D view, points (egui's zoom scales it).
const LABEL_SIZE: f32 = 12.0;
/// Points: the labels in the 3D picture in presentation mode (read from the back of a room).
const PRESENT_LABEL_SIZE: f32 = 17.0;

/// Degrees the orbit turns per point dragged.
const TURN_PER_POINT: f64 = 0.4;

/// What the cached scene was built for: the render's generation, and the traced pixel with
/// its report's generation.
type SceneKey = (u64, Option<([u32; 2], u64)>);

/// The 3D view's widget state: its orbit and the scene built for the last render and pixel.
#[derive(Default)]
pub struct SpaceView {
    /// The orbit camera.
    pub orbit: Orbit,
    cached: Option<(SceneKey, SpaceScene)>,
    /// Where its panel was laid out last (beside the canvas, or in its place when enlarged;
    /// not presenting).
    pub(in crate::app) panel_rect: Option<egui::Rect>,
    /// Where the drawing was laid out last (for tests: `BaryApp::space_drawing_rect`).
    pub(in crate::app) drawing_rect: Option<egui::Rect>,
}

/// The Controls panel's toggle of the 3D view (beside the comparison choices).
pub fn toggle_ui(ui: &mut Ui, on: bool) -> Vec<StateCommand> {
    let lang = crate::app::services::locale::lang(ui.ctx());
    let mut out = Vec::new();
    if ui
        .selectable_label(on, lang.tr("space.view_name"))
        .on_hover_text(lang.tr("space.toggle_tip"))
        .clicked()
    {
        out.push(StateCommand::SetSpaceView(!on));
    }
    out
}

fn colour(c: Colour) -> Color32 {
    let [r, g, b, a] = c.0;
    Color32::from_rgba_unmultiplied(r, g, b, a)
}

impl SpaceView {
    /// The scene in 3D for `output` and the pixel `report` traced (built again only when the
    /// render or the pixel changed).
    fn scene(
        &mut self,
        output: &CanvasOutput,
        report: Option<&PixelReport>,
    ) -> Option<&SpaceScene> {
        let key = (output.generation, report.map(|r| (r.pixel, r.generation)));
        if self.cached.as_ref().is_none_or(|(k, _)| *k != key) {
            let settings = output.scene.settings();
            let space =
                SpaceScene::build(&output.scene, &settings, report.map(|r| &r.trace)).ok()?;
            self.cached = Some((key, space));
        }
        self.cached.as_ref().map(|(_, s)| s)
    }

    /// The view: a reset button and hint, the drawing (dragged to orbit, scrolled to zoom),
    /// and the pixel's numbers under it; the drawing's labels `label_size` points. `enlarged`:
    /// `Some(false)` beside the canvas, with a button that puts it in the canvas's place;
    /// `Some(true)` in that place, with a button back to the picture; `None` (presentation
    /// mode, whose card names the key) neither. Returns whether that button was clicked.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        output: Option<&CanvasOutput>,
        report: Option<&PixelReport>,
        label_size: f32,
        enlarged: Option<bool>,
    ) -> bool {
        let mut toggle = false;
        let lang = crate::app::services::locale::lang(ui.ctx());
        // A tetrahedron scene shows its volume weights (the lesson's last step).
        let tetra = output
            .and_then(|o| self.scene(o, report))
            .is_some_and(is_tetrahedron);
        let title = if tetra {
            "space.tetra.title"
        } else {
            "space.title"
        };
        // Beside the canvas, the title on a line of its own, the buttons under it: in one
        // wrapped row with them, the row asked the panel for more width than a projector's
        // window gives it, and the panel took it from the canvas. In the canvas's place, one
        // row: the buttons first, then the title (cut short, with its whole text as tooltip,
        // where the row is too narrow).
        let one_row = enlarged == Some(true);
        let title = RichText::new(lang.tr(title)).strong();
        if !one_row {
            ui.label(title.clone());
        }
        let row = |ui: &mut Ui| {
            if let Some(on) = enlarged {
                let (text, tip) = if on {
                    ("space.shrink", "space.shrink_tip")
                } else {
                    ("space.enlarge", "space.enlarge_tip")
                };
                toggle = ui
                    .button(lang.tr(text))
                    .on_hover_text(lang.tr(tip))
                    .clicked();
            }
            if ui.button(lang.tr("space.reset")).clicked() {
                self.orbit = Orbit::default();
            }
            if one_row {
                ui.add(egui::Label::new(title).truncate());
            }
        };
        if one_row {
            ui.horizontal(row);
        } else {
            ui.horizontal_wrapped(row);
        }
        let body = ui.text_style_height(&egui::TextStyle::Body);
        let lines = 2.0 * body + ui.spacing().item_spacing.y;
        // The hint under the title where the drawing keeps its smallest height below it (the
        // hint takes two lines in a narrow panel), else on the drawing as a tooltip.
        let hint_shown = ui.available_height() >= 2.0 * lines + MIN_DRAWING;
        if hint_shown {
            ui.label(RichText::new(lang.tr("space.hint")).weak());
        }
        let Some(output) = output else {
            return toggle;
        };
        // The drawing takes about two thirds of the height, at least `MIN_DRAWING`, and leaves
        // room for two lines of the numbers, which scroll under it: nothing overflows the
        // panel (an overflow grew the panel past the lesson panel's top, its edge drawn
        // across the lesson's buttons).
        // Where that leaves the drawing under `MIN_DRAWING` (a 1024x768 projector with a plot
        // in the Lessons panel), the drawing takes the whole room and the numbers go into its
        // tooltip: two cut lines of numbers helped less than a drawing half as tall again.
        // Enlarged in a wide, low place (the canvas's, above a lesson's text), the numbers
        // are a column beside the drawing, which keeps the whole height.
        let room = ui.available_height();
        let beside = enlarged == Some(true) && ui.available_width() >= BESIDE_ASPECT * room;
        let numbers_under = !beside && room - lines >= MIN_DRAWING;
        let height = if numbers_under {
            (0.68 * room).max(MIN_DRAWING).min(room - lines)
        } else {
            room
        }
        .max(0.0);
        let whole = ui.available_rect_before_wrap();
        let width = if beside {
            (BESIDE_SHARE * whole.width()).round()
        } else {
            whole.width()
        };
        let numbers_rect = beside.then(|| {
            let gap = ui.spacing().item_spacing.x * 2.0;
            egui::Rect::from_min_max(
                egui::pos2(whole.min.x + width + gap, whole.min.y),
                whole.max,
            )
        });
        let size = egui::vec2(width, height);
        let (response, painter) = ui.allocate_painter(size, Sense::click_and_drag());
        self.drawing_rect = Some(response.rect);
        let mut tip = Vec::new();
        if !hint_shown {
            tip.push(lang.tr("space.hint"));
        }
        if response.dragged() {
            let d = response.drag_delta();
            self.orbit = self.orbit.turned(
                -f64::from(d.x) * TURN_PER_POINT,
                f64::from(d.y) * TURN_PER_POINT,
            );
        }
        if response.hovered() {
            let scroll = ui.input(|i| i.smooth_scroll_delta.y);
            if scroll != 0.0 {
                self.orbit = self.orbit.zoomed((f64::from(scroll) * 0.002).exp());
            }
        }
        let orbit = self.orbit;
        let Some(space) = self.scene(output, report) else {
            return toggle;
        };
        let r = response.rect;
        painter.rect_filled(r, 0.0, Color32::WHITE);
        let rect = [r.min.x, r.min.y, r.max.x, r.max.y];
        let painter = painter.with_clip_rect(r);
        // egui's labels are wider and their rows taller than the SVG's estimate: they are
        // spread by the size they are drawn at.
        let measure = |text: &str, size: f32| {
            let g =
                painter.layout_no_wrap(text.to_owned(), FontId::proportional(size), Color32::BLACK);
            [g.size().x, g.size().y]
        };
        let (drawn, lines) = match tetra.then(|| TetraFigure::new(space, orbit, lang).ok()) {
            Some(Some(fig)) => (fig.shapes(rect, label_size, &measure), fig.panel_lines()),
            _ => (
                shapes(
                    space,
                    &space.projector(orbit, rect),
                    lang,
                    label_size,
                    &measure,
                ),
                panel_lines(space, lang),
            ),
        };
        for s in &drawn {
            paint(&painter, s);
        }
        if !numbers_under && !beside {
            tip.extend(lines.into_iter().map(|(line, _)| line));
            response.on_hover_text(tip.join("\n"));
            return toggle;
        }
        if !tip.is_empty() {
            response.on_hover_text(tip.join("\n"));
        }
        let numbers = |ui: &mut Ui| {
            egui::ScrollArea::vertical()
                .id_salt("space-numbers")
                .min_scrolled_height(0.0)
                .max_height(ui.available_height())
                .show(ui, |ui| {
                    let ink = ui.visuals().text_color();
                    for (line, c) in lines {
                        let c = if c == INK { ink } else { colour(c) };
                        ui.label(RichText::new(line).color(c));
                    }
                });
        };
        match numbers_rect {
            Some(r) => {
                ui.scope_builder(egui::UiBuilder::new().max_rect(r), numbers);
            }
            None => numbers(ui),
        }
        toggle
    }
}

/// Paints one shape of the space view.
fn paint(painter: &egui::Painter, s: &Shape) {
    let p = |q: [f32; 2]| Pos2::new(q[0], q[1]);
    match &s.kind {
        ShapeKind::Polygon {
            points,
            fill,
            stroke,
        } => {
            let mut pts: Vec<Pos2> = points.iter().map(|q| p(*q)).collect();
            let area: f32 = (0..pts.len())
                .map(|i| {
                    let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
                    a.x * b.y - b.x * a.y
                })
                .sum();
            if area < 0.0 {
                pts.reverse();
            }
            let stroke = stroke.map_or(PathStroke::NONE, |(c, w)| PathStroke::new(w, colour(c)));
            painter.add(EShape::convex_polygon(pts, colour(*fill), stroke));
        }
        ShapeKind::Line {
            from,
            to,
            colour: c,
            width,
            dashed,
        } => {
            let stroke = Stroke::new(*width, colour(*c));
            if *dashed {
                painter.extend(EShape::dashed_line(
                    &[p(*from), p(*to)],
                    stroke,
                    3.0 * width,
                    3.0 * width,
                ));
            } else {
                painter.line_segment([p(*from), p(*to)], stroke);
            }
        }
        ShapeKind::Dot {
            centre,
            radius,
            fill,
            stroke,
        } => {
            painter.circle_filled(p(*centre), *radius, colour(*fill));
            if let Some((c, w)) = stroke {
                painter.circle_stroke(p(*centre), *radius, Stroke::new(*w, colour(*c)));
            }
        }
        ShapeKind::Text {
            at,
            text,
            size,
            colour: c,
            anchor,
        } => {
            let align = match anchor {
                Anchor2::Start => Align2::LEFT_BOTTOM,
                Anchor2::Middle => Align2::CENTER_BOTTOM,
                Anchor2::End => Align2::RIGHT_BOTTOM,
            };
            let galley =
                painter.layout_no_wrap(text.clone(), FontId::proportional(*size), colour(*c));
            // The baseline at `at`: the galley's bottom a little below it.
            let rect = align.anchor_size(p(*at) + egui::vec2(0.0, 0.25 * size), galley.size());
            painter.rect_filled(
                rect.expand(1.0),
                2.0,
                Color32::from_rgba_unmultiplied(255, 255, 255, 190),
            );
            painter.galley(rect.min, galley, colour(*c));
        }
    }
}

/// Presentation mode shows the 3D view (right of the picture) only in windows at least this
/// many times as wide as high: on a 16:9 or 16:10 screen it takes width the picture cannot use,
/// while on a 4:3 projector it would take what the picture needs.
pub const PRESENT_MIN_ASPECT: f32 = 1.5;

/// The 3D view's share of the window's width in presentation mode.
pub const PRESENT_SHARE: f32 = 0.36;
/// The 3D drawing's smallest height in points, where the panel has room for it.
const MIN_DRAWING: f32 = 160.0;
/// The enlarged view puts its numbers beside the drawing where its place is at least this
/// many times as wide as high: under it, they would leave a wide, low strip of a drawing.
const BESIDE_ASPECT: f32 = 1.8;
/// The drawing's share of the width when the numbers are beside it.
const BESIDE_SHARE: f32 = 0.6;

impl crate::app::BaryApp {
    /// Presentation mode, when the 3D view is on: in a column right of the picture when the
    /// window is wide ([`PRESENT_MIN_ASPECT`]); in a narrower window, in the picture's place
    /// while V has asked for it (returns true: nothing else is to be laid out).
    pub(in crate::app) fn space_panel_presenting(&mut self, ui: &mut Ui) -> bool {
        let window = ui.ctx().content_rect();
        let wide = window.width() >= PRESENT_MIN_ASPECT * window.height();
        self.space_toggle_offered = self.state.view.space && !wide;
        if !self.state.view.space || (!wide && !self.space_full) {
            return false;
        }
        if !wide {
            // The canvas is not drawn: nothing on it is hovered (else the view would trace the
            // pixel the pointer was on when V was pressed, not the pinned one).
            self.canvas.hover = None;
        }
        let report = self.reports.hover.as_ref().or(self.reports.pin.as_ref());
        let output = self.canvas.output.as_ref();
        let view = &mut self.space_view;
        let frame = egui::Frame::new()
            .fill(crate::app::panels::present::CARD_FILL)
            .inner_margin(egui::Margin::same(12));
        if !wide {
            let back = crate::app::services::locale::lang(ui.ctx()).tr("space.present_back");
            egui::CentralPanel::default().frame(frame).show(ui, |ui| {
                ui.label(RichText::new(back).color(crate::app::panels::present::DIM));
                view.ui(ui, output, report, PRESENT_LABEL_SIZE, None);
            });
            return true;
        }
        egui::Panel::right("space-view-present")
            .frame(
                egui::Frame::new()
                    .fill(crate::app::panels::present::CARD_FILL)
                    .inner_margin(egui::Margin::same(12)),
            )
            .resizable(false)
            .exact_size((PRESENT_SHARE * window.width()).round())
            .show(ui, |ui| {
                view.ui(ui, output, report, PRESENT_LABEL_SIZE, None);
            });
        false
    }

    /// The 3D view as a resizable panel right of the canvas (when it is on), drawn from the
    /// canvas's render and the hovered, else pinned, pixel's trace; its button (or V) asks
    /// for it in the canvas's place ([`Self::space_enlarged`]).
    pub(in crate::app) fn space_panel(&mut self, ui: &mut Ui, out: &mut Vec<AppCommand>) {
        self.space_view.panel_rect = None;
        if !self.state.view.space {
            return;
        }
        let width = ui.available_width();
        let report = self.reports.hover.as_ref().or(self.reports.pin.as_ref());
        let output = self.canvas.output.as_ref();
        let view = &mut self.space_view;
        let shown = egui::Panel::right("space-view")
            .resizable(true)
            .default_size(0.45 * width)
            .size_range((0.25 * width)..=(0.7 * width))
            .show(ui, |ui| {
                view.ui(ui, output, report, LABEL_SIZE, Some(false))
            });
        if shown.inner {
            out.push(AppCommand::ToggleSpaceFull);
        }
        view.panel_rect = Some(shown.response.rect);
    }

    /// The 3D view in the canvas's place, its labels as large as presentation mode's, when
    /// its Enlarge button or V asked for it (a projector's panel beside the canvas is too small
    /// to read from the back of a room). Returns false, drawing nothing, when it is not
    /// asked for: the canvas is laid out as usual.
    pub(in crate::app) fn space_enlarged(
        &mut self,
        ui: &mut Ui,
        out: &mut Vec<AppCommand>,
    ) -> bool {
        if !(self.space_full && self.state.view.space) {
            return false;
        }
        // The canvas is not drawn: nothing on it is hovered (as in presentation mode).
        self.canvas.hover = None;
        let report = self.reports.hover.as_ref().or(self.reports.pin.as_ref());
        let output = self.canvas.output.as_ref();
        let view = &mut self.space_view;
        let shown = egui::CentralPanel::default().show(ui, |ui| {
            view.ui(ui, output, report, PRESENT_LABEL_SIZE, Some(true))
        });
        if shown.inner {
            out.push(AppCommand::ToggleSpaceFull);
        }
        view.panel_rect = Some(shown.response.rect);
        true
    }
}
