//! Paints an [`Overlay`] with egui: canvas coordinates to screen points.

use egui::epaint::{Mesh, PathStroke};
use egui::{Align2, Color32, FontId, Pos2, Rect, Shape as EShape, Stroke as EStroke, StrokeKind};
use glam::DVec2;

use super::overlay::{Anchor, Overlay, Rgba, Shape, Stroke};

/// Maps canvas coordinates (rendered pixels) to screen points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CanvasTransform {
    /// Screen position of canvas (0, 0).
    pub origin: Pos2,
    /// Points per rendered pixel: `pixel_size / pixels_per_point`.
    pub scale: f32,
}

impl CanvasTransform {
    pub fn to_screen(&self, p: DVec2) -> Pos2 {
        Pos2::new(
            self.origin.x + p.x as f32 * self.scale,
            self.origin.y + p.y as f32 * self.scale,
        )
    }

    pub fn to_canvas(&self, p: Pos2) -> DVec2 {
        DVec2::new(
            f64::from((p.x - self.origin.x) / self.scale),
            f64::from((p.y - self.origin.y) / self.scale),
        )
    }
}

pub fn color(c: Rgba) -> Color32 {
    Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3])
}

fn stroke(s: Stroke) -> EStroke {
    EStroke::new(s.width, color(s.color))
}

fn align(a: Anchor) -> Align2 {
    match a {
        Anchor::LeftTop => Align2::LEFT_TOP,
        Anchor::LeftBottom => Align2::LEFT_BOTTOM,
        Anchor::RightBottom => Align2::RIGHT_BOTTOM,
        Anchor::LeftCenter => Align2::LEFT_CENTER,
        Anchor::CenterTop => Align2::CENTER_TOP,
        Anchor::CenterBottom => Align2::CENTER_BOTTOM,
        Anchor::Center => Align2::CENTER_CENTER,
        Anchor::RightTop => Align2::RIGHT_TOP,
        Anchor::RightCenter => Align2::RIGHT_CENTER,
    }
}

/// Dash and gap lengths of dashed lines, in points.
const DASH: (f32, f32) = (6.0, 4.0);
/// Padding around label text, in points.
const LABEL_PAD: egui::Vec2 = egui::vec2(6.0, 3.0);

/// Paints the overlay, clipped to `clip`.
pub fn paint(painter: &egui::Painter, clip: Rect, t: CanvasTransform, overlay: &Overlay) {
    let painter = painter.with_clip_rect(clip);
    for shape in &overlay.shapes {
        match shape {
            Shape::Polygon {
                points,
                fill,
                stroke: s,
                dashed,
            } => {
                let mut pts: Vec<Pos2> = points.iter().map(|p| t.to_screen(*p)).collect();
                if signed_area(&pts) < 0.0 {
                    pts.reverse();
                }
                if fill[3] > 0 {
                    painter.add(EShape::convex_polygon(
                        pts.clone(),
                        color(*fill),
                        PathStroke::NONE,
                    ));
                }
                if let Some(s) = s {
                    let mut closed = pts.clone();
                    if let Some(first) = pts.first() {
                        closed.push(*first);
                    }
                    if *dashed {
                        painter.extend(EShape::dashed_line(&closed, stroke(*s), DASH.0, DASH.1));
                    } else {
                        painter.add(EShape::closed_line(pts, stroke(*s)));
                    }
                }
            }
            Shape::Line {
                points,
                stroke: s,
                dashed,
            } => {
                let pts: Vec<Pos2> = points.iter().map(|p| t.to_screen(*p)).collect();
                if *dashed {
                    painter.extend(EShape::dashed_line(&pts, stroke(*s), DASH.0, DASH.1));
                } else {
                    painter.add(EShape::line(pts, stroke(*s)));
                }
            }
            Shape::Rect {
                min,
                max,
                fill,
                stroke: s,
            } => {
                let r = Rect::from_min_max(t.to_screen(*min), t.to_screen(*max));
                if fill[3] > 0 {
                    painter.rect_filled(r, 0.0, color(*fill));
                }
                if let Some(s) = s {
                    painter.rect_stroke(r, 0.0, stroke(*s), StrokeKind::Outside);
                }
            }
            Shape::Circle {
                centre,
                radius,
                fill,
                stroke: s,
            } => {
                let c = t.to_screen(*centre);
                painter.circle(
                    c,
                    *radius,
                    color(*fill),
                    s.map(stroke).unwrap_or(EStroke::NONE),
                );
            }
            Shape::Text {
                at,
                offset,
                anchor,
                text,
                size,
                color: c,
                background,
            } => {
                let base = t.to_screen(*at);
                let pos = base + egui::vec2(offset[0], offset[1]);
                let mut anchor = align(*anchor);
                let mut pos = pos;
                // A label that would stick out on one side goes to the other side of its
                // point (mirrored), before it is pushed inside.
                let galley =
                    painter.layout_no_wrap(text.clone(), FontId::proportional(*size), color(*c));
                let pad = if background.is_some() {
                    LABEL_PAD
                } else {
                    egui::Vec2::ZERO
                };
                let outer = anchor.anchor_size(pos, galley.size() + 2.0 * pad);
                let size_box = galley.size() + 2.0 * pad;
                let sticks_x = |r: Rect| r.left() < clip.left() || r.right() > clip.right();
                let sticks_y = |r: Rect| r.top() < clip.top() || r.bottom() > clip.bottom();
                if sticks_x(outer) {
                    let (a, p) = (
                        anchor.flipped_x(),
                        base + egui::vec2(-offset[0], pos.y - base.y),
                    );
                    if !sticks_x(a.anchor_size(p, size_box)) {
                        (anchor, pos) = (a, p);
                    }
                }
                if sticks_y(anchor.anchor_size(pos, size_box)) {
                    let (a, p) = (anchor.flipped_y(), Pos2::new(pos.x, base.y - offset[1]));
                    if !sticks_y(a.anchor_size(p, size_box)) {
                        (anchor, pos) = (a, p);
                    }
                }
                label_inside(&painter, clip, pos, anchor, text, *size, *c, *background);
            }
            Shape::PixelGrid {
                width,
                height,
                line,
                dots,
            } => paint_grid(&painter, clip, t, *width, *height, *line, *dots),
            Shape::ColorBar {
                at,
                offset,
                size,
                colors,
                labels,
                title,
            } => {
                let min = t.to_screen(*at) + egui::vec2(offset[0], offset[1]);
                let rect = Rect::from_min_size(min, egui::vec2(size[0], size[1]));
                paint_color_bar(&painter, rect, colors, labels, title);
            }
        }
    }
}

/// Text with an optional rounded background box; returns the box.
pub fn label(
    painter: &egui::Painter,
    pos: Pos2,
    anchor: Align2,
    text: &str,
    size: f32,
    c: Rgba,
    background: Option<Rgba>,
) -> Rect {
    label_inside(
        painter,
        Rect::EVERYTHING,
        pos,
        anchor,
        text,
        size,
        c,
        background,
    )
}

/// [`label`], moved as little as needed to lie inside `bounds` (if it fits).
#[allow(clippy::too_many_arguments)]
pub fn label_inside(
    painter: &egui::Painter,
    bounds: Rect,
    pos: Pos2,
    anchor: Align2,
    text: &str,
    size: f32,
    c: Rgba,
    background: Option<Rgba>,
) -> Rect {
    let galley = painter.layout_no_wrap(text.to_string(), FontId::proportional(size), color(c));
    let pad = if background.is_some() {
        LABEL_PAD
    } else {
        egui::Vec2::ZERO
    };
    let mut outer = anchor.anchor_size(pos, galley.size() + 2.0 * pad);
    let inner = bounds.shrink(2.0);
    if inner.is_finite() && outer.width() <= inner.width() && outer.height() <= inner.height() {
        let dx = (inner.left() - outer.left()).max(0.0) + (inner.right() - outer.right()).min(0.0);
        let dy = (inner.top() - outer.top()).max(0.0) + (inner.bottom() - outer.bottom()).min(0.0);
        outer = outer.translate(egui::vec2(dx, dy));
    }
    if let Some(bg) = background {
        painter.rect_filled(outer, 4.0, color(bg));
    }
    painter.galley(outer.min + pad, galley, color(c));
    outer
}

fn signed_area(p: &[Pos2]) -> f32 {
    let mut s = 0.0;
    for i in 0..p.len() {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        s += a.x * b.y - b.x * a.y;
    }
    s / 2.0
}

fn paint_grid(
    painter: &egui::Painter,
    clip: Rect,
    t: CanvasTransform,
    width: u32,
    height: u32,
    line: Stroke,
    dots: Option<(f32, Rgba)>,
) {
    let (w, h) = (f64::from(width), f64::from(height));
    let s = stroke(line);
    for x in 0..=width {
        let x = f64::from(x);
        painter.line_segment(
            [
                t.to_screen(DVec2::new(x, 0.0)),
                t.to_screen(DVec2::new(x, h)),
            ],
            s,
        );
    }
    for y in 0..=height {
        let y = f64::from(y);
        painter.line_segment(
            [
                t.to_screen(DVec2::new(0.0, y)),
                t.to_screen(DVec2::new(w, y)),
            ],
            s,
        );
    }
    if let Some((r, c)) = dots {
        // One mesh of small squares: thousands of dots stay cheap to tessellate.
        let mut mesh = Mesh::default();
        let c = color(c);
        for y in 0..height {
            for x in 0..width {
                let p = t.to_screen(DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
                if clip.contains(p) {
                    mesh.add_colored_rect(Rect::from_center_size(p, egui::Vec2::splat(2.0 * r)), c);
                }
            }
        }
        painter.add(EShape::mesh(mesh));
    }
}

fn paint_color_bar(
    painter: &egui::Painter,
    rect: Rect,
    colors: &[Rgba],
    labels: &[(f32, String)],
    title: &str,
) {
    // Room for the title above and the labels to the right.
    let back = Rect::from_min_max(
        rect.min - egui::vec2(12.0, 40.0),
        rect.max + egui::vec2(56.0, 12.0),
    );
    painter.rect_filled(back, 6.0, color(super::overlay::LABEL_BG));
    let n = colors.len().saturating_sub(1).max(1);
    let mut mesh = Mesh::default();
    for (i, pair) in colors.windows(2).enumerate() {
        let y_bottom = rect.bottom() - rect.height() * i as f32 / n as f32;
        let y_top = rect.bottom() - rect.height() * (i + 1) as f32 / n as f32;
        let base = mesh.vertices.len() as u32;
        mesh.colored_vertex(Pos2::new(rect.left(), y_bottom), color(pair[0]));
        mesh.colored_vertex(Pos2::new(rect.right(), y_bottom), color(pair[0]));
        mesh.colored_vertex(Pos2::new(rect.right(), y_top), color(pair[1]));
        mesh.colored_vertex(Pos2::new(rect.left(), y_top), color(pair[1]));
        mesh.add_triangle(base, base + 1, base + 2);
        mesh.add_triangle(base, base + 2, base + 3);
    }
    painter.add(EShape::mesh(mesh));
    painter.rect_stroke(
        rect,
        0.0,
        EStroke::new(1.0, Color32::WHITE),
        StrokeKind::Outside,
    );
    let text = color(super::overlay::LABEL_TEXT);
    for (t, l) in labels {
        let y = rect.bottom() - rect.height() * t;
        painter.line_segment(
            [Pos2::new(rect.right(), y), Pos2::new(rect.right() + 5.0, y)],
            EStroke::new(1.0, text),
        );
        painter.text(
            Pos2::new(rect.right() + 8.0, y),
            Align2::LEFT_CENTER,
            l,
            FontId::proportional(16.0),
            text,
        );
    }
    painter.text(
        Pos2::new(rect.center().x, rect.top() - 8.0),
        Align2::CENTER_BOTTOM,
        title,
        FontId::proportional(16.0),
        text,
    );
}
