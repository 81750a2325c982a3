//! Paints an [`Overlay`] with egui: canvas coordinates to screen points.

use egui::epaint::{Mesh, PathStroke};
use egui::{Align2, Color32, FontId, Pos2, Rect, Shape as EShape, Stroke as EStroke, StrokeKind};
use glam::DVec2;

mod marks;
mod quad;

use marks::is_title;
pub use marks::{drop_titles, retitle, scale_marks, title};

use crate::figure::overlay::{Overlay, Rgba, Shape, Stroke};

/// Maps canvas coordinates (rendered pixels) to screen points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CanvasTransform {
    /// Screen position of canvas (0, 0).
    pub origin: Pos2,
    /// Points per rendered pixel: `pixel_size / pixels_per_point`.
    pub scale: f32,
}

impl CanvasTransform {
    pub fn to_screen(self, p: DVec2) -> Pos2 {
        Pos2::new(
            self.origin.x + p.x as f32 * self.scale,
            self.origin.y + p.y as f32 * self.scale,
        )
    }

    pub fn to_canvas(self, p: Pos2) -> DVec2 {
        DVec2::new(
            f64::from((p.x - self.origin.x) / self.scale),
            f64::from((p.y - self.origin.y) / self.scale),
        )
    }
}

pub fn color(c: Rgba) -> Color32 {
    Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3])
}

pub(super) fn stroke(s: Stroke) -> EStroke {
    EStroke::new(s.width, color(s.color))
}

use crate::figure::label_place;
use crate::figure::svg::DASH;
use crate::figure::text::{self as figure_text, LABEL_PAD, LABEL_ROUNDING};

pub(super) fn to_rect(b: figure_text::Box2) -> Rect {
    Rect::from_min_max(Pos2::new(b[0], b[1]), Pos2::new(b[2], b[3]))
}

/// A label's galley at `size` points, set smaller when wider than `clip` (with its box's
/// padding when `boxed`), and its outer size.
fn fitted(
    painter: &egui::Painter,
    text: &str,
    size: f32,
    c: Rgba,
    boxed: bool,
    clip: Rect,
) -> (std::sync::Arc<egui::Galley>, [f32; 2]) {
    let lay = |s: f32| painter.layout_no_wrap(text.to_string(), FontId::proportional(s), color(c));
    let pad = if boxed { LABEL_PAD[0] } else { 0.0 };
    let width = lay(size).size().x;
    let galley = lay(size * figure_text::fit(width, 2.0 * pad, to_box(clip)));
    let outer = figure_text::padded([galley.size().x, galley.size().y], boxed, 1.0);
    (galley, outer)
}

/// Whether a boxed label of `text` at `size` points fits `clip`'s width unshrunk (as
/// [`paint`] draws it: shrunk by [`figure_text::fit`] where it does not).
fn fits_unshrunk(painter: &egui::Painter, text: &str, size: f32, clip: Rect) -> bool {
    let width = painter
        .layout_no_wrap(text.to_string(), FontId::proportional(size), Color32::WHITE)
        .size()
        .x;
    figure_text::fit(width, 2.0 * LABEL_PAD[0], to_box(clip)) >= 1.0
}

/// The first of `titles` (longest first) that fits `clip` at full size ([`fits_unshrunk`]),
/// else the last.
pub fn first_fitting<'a>(painter: &egui::Painter, titles: &'a [String], clip: Rect) -> &'a str {
    titles
        .iter()
        .find(|t| fits_unshrunk(painter, t, crate::figure::overlay::TEXT_BADGE, clip))
        .or(titles.last())
        .map_or("", String::as_str)
}

/// Canvas position `p` as a screen point's coordinates.
pub(super) fn to_point(t: CanvasTransform, p: DVec2) -> [f32; 2] {
    let q = t.to_screen(p);
    [q.x, q.y]
}

pub(super) fn to_box(r: Rect) -> figure_text::Box2 {
    [r.left(), r.top(), r.right(), r.bottom()]
}

/// Paints the overlay: its lines and areas clipped to `image` (the image and its title
/// strip), its handles and texts to `clip` (the view's share of the canvas, so a handle at the
/// image's edge shows whole and its label has room beside it).
pub fn paint(
    painter: &egui::Painter,
    clip: Rect,
    image: Rect,
    t: CanvasTransform,
    overlay: &Overlay,
    avoid: &[Rect],
) {
    let painter = painter.with_clip_rect(clip);
    let geometry = painter.with_clip_rect(image.intersect(clip));
    // What labels keep clear of above all (handles, colour bars, what the caller shows over
    // the canvas), then the label boxes placed so far: a label goes where it covers none of
    // them if it can, and covers a label rather than a handle if it cannot.
    let keep_clear: Vec<figure_text::Box2> = overlay
        .shapes
        .iter()
        .filter_map(|shape| match shape {
            Shape::Circle { centre, radius, .. }
                if *radius >= crate::figure::svg::MIN_OBSTACLE_RADIUS =>
            {
                let c = t.to_screen(*centre);
                Some(figure_text::handle_obstacle([c.x, c.y], *radius))
            }
            Shape::ColorBar {
                at, offset, size, ..
            } => {
                let min = t.to_screen(*at) + egui::vec2(offset[0], offset[1]);
                let r = [min.x, min.y, min.x + size[0], min.y + size[1]];
                Some(crate::figure::svg::color_bar_back(r, 1.0))
            }
            Shape::QuadLabels(q) => Some(label_place::quad_box(
                to_point(t, q.min),
                to_point(t, q.max),
                q.outline,
            )),
            _ => None,
        })
        .chain(avoid.iter().map(|r| to_box(*r)))
        .collect();
    let handles = label_place::handle_centres(&overlay.shapes, |p| to_point(t, p));
    let mut placed: Vec<figure_text::Box2> = Vec::new();
    // The views' titles, drawn last so no handle near the image's top edge covers them; a
    // handle's letter that would lie on one moves below it.
    let mut titles: Vec<(Rect, std::sync::Arc<egui::Galley>, Rgba, Option<Rgba>)> = Vec::new();
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
                    geometry.add(EShape::convex_polygon(
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
                        geometry.extend(EShape::dashed_line(&closed, stroke(*s), DASH.0, DASH.1));
                    } else {
                        geometry.add(EShape::closed_line(pts, stroke(*s)));
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
                    geometry.extend(EShape::dashed_line(&pts, stroke(*s), DASH.0, DASH.1));
                } else {
                    geometry.add(EShape::line(pts, stroke(*s)));
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
                    geometry.rect_filled(r, 0.0, color(*fill));
                }
                if let Some(s) = s {
                    geometry.rect_stroke(r, 0.0, stroke(*s), StrokeKind::Outside);
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
                // Placed as the figure export places it (flipped to the other side of its
                // point if it sticks out, then pushed inside), measured with egui's galley.
                let (galley, outer) = fitted(&painter, text, *size, *c, background.is_some(), clip);
                let base = t.to_screen(*at);
                // A label with a box keeps clear of the others; a bare letter (a handle's
                // name) stays where it is.
                let (p, bounds) = ([base.x, base.y], to_box(clip));
                // A title keeps its place above the image (handles move out of its way).
                let b = if is_title(shape) {
                    figure_text::place_label(p, *offset, *anchor, outer, bounds)
                } else if background.is_some() {
                    figure_text::place_label_avoiding(
                        p,
                        *offset,
                        *anchor,
                        outer,
                        bounds,
                        &placed,
                        &keep_clear,
                    )
                } else {
                    below_titles(
                        figure_text::place_label(p, *offset, *anchor, outer, bounds),
                        &titles,
                        bounds,
                    )
                };
                if background.is_some() {
                    placed.push(b);
                }
                if is_title(shape) {
                    titles.push((to_rect(b), galley, *c, *background));
                } else {
                    draw_label(&painter, to_rect(b), galley, *c, *background);
                }
            }
            Shape::HandleLabel {
                at,
                reach,
                outward,
                text,
                size,
                color: c,
                background,
            } => {
                // Placed as the figure export places it, measured with egui's galley.
                let p = to_point(t, *at);
                let (b, scale) = label_place::place_handle_label_fitting(
                    p,
                    *reach,
                    *outward,
                    &label_place::others(&handles, p),
                    |scale| fitted(&painter, text, *size * scale, *c, true, clip).1,
                    to_box(clip),
                    &placed,
                    &keep_clear,
                );
                let galley = fitted(&painter, text, *size * scale, *c, true, clip).0;
                placed.push(b);
                draw_label(&painter, to_rect(b), galley, *c, Some(*background));
            }
            Shape::QuadLabels(q) => {
                placed.extend(quad::quad_labels(
                    &painter,
                    q,
                    t,
                    clip,
                    &placed,
                    &keep_clear,
                ));
            }
            Shape::LabelPair {
                at,
                offset_y,
                gap,
                texts,
                size,
                color: c,
                background,
            } => {
                // Placed as the figure export places them, measured with egui's galleys.
                let lay = |s: f32| {
                    texts.each_ref().map(|x| {
                        painter.layout_no_wrap(x.clone(), FontId::proportional(s), color(*c))
                    })
                };
                let has_box = background.is_some();
                let pad = if has_box { LABEL_PAD[0] } else { 0.0 };
                let widths = lay(*size).map(|g| g.size().x);
                let fit = figure_text::pair_fit(widths, pad, *gap, to_box(clip));
                let galleys = lay(size * fit);
                let outer = galleys
                    .each_ref()
                    .map(|g| figure_text::padded([g.size().x, g.size().y], has_box, 1.0));
                let base = t.to_screen(*at);
                let (boxes, _) =
                    figure_text::place_pair([base.x, base.y + offset_y], *gap, outer, to_box(clip));
                placed.extend(boxes);
                // The wipe's two titles.
                for (b, g) in boxes.into_iter().zip(galleys) {
                    titles.push((to_rect(b), g, *c, *background));
                }
            }
            Shape::PixelGrid {
                width,
                height,
                line,
                dots,
            } => paint_grid(&geometry, clip, t, *width, *height, *line, *dots),
            Shape::ColorBar {
                at,
                offset,
                size,
                colors,
                labels,
                title,
            } => {
                let min = t.to_screen(*at) + egui::vec2(offset[0], offset[1]);
                // As high as the image is shown (a shrunk image is fewer points high than
                // its pixels, and a bar sized for the pixels ran past its bottom).
                let height = size[1].min(crate::figure::overlay::color_bar_height(f64::from(
                    image.height(),
                )));
                let rect = Rect::from_min_size(min, egui::vec2(size[0], height));
                paint_color_bar(&painter, rect, colors, labels, title);
            }
        }
    }
    for (b, g, c, background) in titles {
        draw_label(&painter, b, g, c, background);
    }
}

/// A bare letter's box `b` moved down below any title it would lie on (if that stays inside
/// `bounds`).
fn below_titles(
    b: figure_text::Box2,
    titles: &[(Rect, std::sync::Arc<egui::Galley>, Rgba, Option<Rgba>)],
    bounds: figure_text::Box2,
) -> figure_text::Box2 {
    let r = to_rect(b);
    let Some(bottom) = titles
        .iter()
        .filter(|(t, ..)| t.intersects(r))
        .map(|(t, ..)| t.bottom())
        .reduce(f32::max)
    else {
        return b;
    };
    let d = bottom + 1.0 - b[1];
    if b[3] + d <= bounds[3] {
        [b[0], b[1] + d, b[2], b[3] + d]
    } else {
        b
    }
}

/// A laid-out text in its box `outer` (which includes the padding when it has a background).
pub(super) fn draw_label(
    painter: &egui::Painter,
    outer: Rect,
    galley: std::sync::Arc<egui::Galley>,
    c: Rgba,
    background: Option<Rgba>,
) {
    let pad = if background.is_some() {
        egui::vec2(LABEL_PAD[0], LABEL_PAD[1])
    } else {
        egui::Vec2::ZERO
    };
    if let Some(bg) = background {
        painter.rect_filled(outer, LABEL_ROUNDING, color(bg));
    }
    painter.galley(outer.min + pad, galley, color(c));
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
    let back = to_rect(crate::figure::svg::color_bar_back(to_box(rect), 1.0));
    painter.rect_filled(back, 6.0, color(crate::figure::overlay::LABEL_BG));
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
    let text = color(crate::figure::overlay::LABEL_TEXT);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::overlay::{Anchor, TITLE_GAP};

    /// The texts painted, in order, with their screen rectangles.
    fn painted(overlay: &Overlay, clip: Rect, t: CanvasTransform) -> Vec<(String, Rect)> {
        let ctx = egui::Context::default();
        let out = ctx.run_pass(egui::RawInput::default(), |ctx| {
            let painter = egui::Painter::new(ctx.clone(), egui::LayerId::background(), clip);
            paint(&painter, clip, clip, t, overlay, &[]);
        });
        out.shapes
            .iter()
            .filter_map(|s| match &s.shape {
                EShape::Text(text) => {
                    Some((text.galley.text().to_string(), text.visual_bounding_rect()))
                }
                _ => None,
            })
            .collect()
    }

    #[test]
    fn a_handle_at_the_top_edge_leaves_the_title_readable() {
        // A vertex just above the image's top-left corner, its handle in the title strip.
        let corner = DVec2::new(4.0, -4.0);
        let overlay = Overlay {
            shapes: vec![
                Shape::Text {
                    at: DVec2::ZERO,
                    offset: [0.0, -TITLE_GAP],
                    anchor: Anchor::LeftBottom,
                    text: "AFFINE".into(),
                    size: 24.0,
                    color: [255; 4],
                    background: Some([0, 0, 0, 200]),
                },
                Shape::Circle {
                    centre: corner,
                    radius: 11.0,
                    fill: [200, 0, 0, 255],
                    stroke: None,
                },
                Shape::Text {
                    at: corner,
                    offset: [0.0, 0.0],
                    anchor: Anchor::Center,
                    text: "D".into(),
                    size: 16.0,
                    color: [0, 0, 0, 255],
                    background: None,
                },
            ],
        };
        let t = CanvasTransform {
            origin: Pos2::new(100.0, 100.0),
            scale: 1.0,
        };
        let clip = Rect::from_min_max(Pos2::new(98.0, 40.0), Pos2::new(400.0, 400.0));
        let texts = painted(&overlay, clip, t);
        let title = texts
            .iter()
            .position(|(s, _)| s == "AFFINE")
            .expect("title");
        let letter = texts.iter().position(|(s, _)| s == "D").expect("letter");
        // The title is painted after (over) the handle, and the letter is not under it.
        assert!(title > letter, "{texts:?}");
        assert!(!texts[title].1.intersects(texts[letter].1), "{texts:?}");
        // And the title keeps its place above the image (the handle does not push it down).
        assert!(texts[title].1.bottom() <= t.origin.y, "{texts:?}");
    }
}
