//! The overlay's shapes as SVG elements: polygons, lines, rectangles, circles, labels (kept
//! clear of each other), the label pair of the wipe line, the pixel grid and the colour bar.

use std::fmt::Write;

use glam::DVec2;

use super::MIN_OBSTACLE_RADIUS;
use super::labels::{Glyphs, Label, label};
use super::markup::{Transform, fill, hex, n, points, rect, stroke};
use crate::figure::label_place;
use crate::figure::overlay::{self, Anchor, LABEL_BG, LABEL_TEXT, Overlay, Rgba, Shape, Stroke};
use crate::figure::text::{self, Box2, LABEL_PAD};

/// Points: corner radius of the colour bar's background.
const COLOR_BAR_ROUNDING: f32 = 6.0;
/// Points: the colour bar's background reaches this far left/above and right/below the bar
/// (room for its title above and its labels to the right).
const COLOR_BAR_BACK_MIN: [f32; 2] = [12.0, 40.0];
const COLOR_BAR_BACK_MAX: [f32; 2] = [56.0, 12.0];
/// Points: the colour bar's text size.
const COLOR_BAR_TEXT: f32 = 16.0;
/// Points: length of a tick of the colour bar, and the gap between the bar and its labels.
const COLOR_BAR_TICK: f32 = 5.0;
const COLOR_BAR_LABEL_GAP: f32 = 8.0;

/// The overlay's shapes as SVG elements.
/// The overlay's shapes (sizes already scaled) as SVG elements; `k` scales the fixed sizes
/// of the drawing itself (label padding, dashes, the colour bar's frame and text).
pub(super) fn overlay(
    s: &mut String,
    glyphs: &mut Glyphs,
    overlay: &Overlay,
    t: Transform,
    clip: Box2,
    image_clip: &str,
    k: f32,
) {
    // Lines and areas stay on the image (a clipped triangle's outline can reach far off it);
    // handles and labels may use the margin around it. Consecutive shapes on the image share
    // one clipped group, so the painting order is kept.
    let mut in_image_group = false;
    // What labels keep clear of above all (handles, colour bars, what the caller shows over
    // the canvas), then the label boxes placed so far: a label goes where it covers none of
    // them if it can, and covers a label rather than a handle if it cannot.
    let keep_clear: Vec<Box2> = overlay
        .shapes
        .iter()
        .filter_map(|shape| match shape {
            Shape::Circle { centre, radius, .. } if *radius >= MIN_OBSTACLE_RADIUS * k => {
                Some(text::handle_obstacle(t.point(*centre), *radius))
            }
            Shape::ColorBar {
                at, offset, size, ..
            } => {
                let p = t.point(*at);
                let min = [p[0] + offset[0], p[1] + offset[1]];
                Some(color_bar_back(
                    [min[0], min[1], min[0] + size[0], min[1] + size[1]],
                    k,
                ))
            }
            Shape::QuadLabels(q) => Some(label_place::quad_box(
                t.point(q.min),
                t.point(q.max),
                q.outline,
            )),
            _ => None,
        })
        .collect();
    let handles = label_place::handle_centres(&overlay.shapes, |p| t.point(p));
    let mut placed: Vec<Box2> = Vec::new();
    for shape in &overlay.shapes {
        let on_image = matches!(
            shape,
            Shape::Polygon { .. }
                | Shape::Line { .. }
                | Shape::Rect { .. }
                | Shape::PixelGrid { .. }
        );
        if on_image != in_image_group {
            if on_image {
                let _ = writeln!(s, r#"<g clip-path="url(#{image_clip})">"#);
            } else {
                s.push_str("</g>\n");
            }
            in_image_group = on_image;
        }
        match shape {
            Shape::Polygon {
                points: pts,
                fill: f,
                stroke: st,
                dashed,
            } => {
                let p: Vec<[f32; 2]> = pts.iter().map(|p| t.point(*p)).collect();
                let _ = writeln!(
                    s,
                    r#"<polygon points="{}" {}{}/>"#,
                    points(&p),
                    fill(*f),
                    stroke(*st, *dashed, k)
                );
            }
            Shape::Line {
                points: pts,
                stroke: st,
                dashed,
            } => {
                let p: Vec<[f32; 2]> = pts.iter().map(|p| t.point(*p)).collect();
                let _ = writeln!(
                    s,
                    r#"<polyline points="{}" fill="none"{}/>"#,
                    points(&p),
                    stroke(Some(*st), *dashed, k)
                );
            }
            Shape::Rect {
                min,
                max,
                fill: f,
                stroke: st,
            } => {
                let (a, b) = (t.point(*min), t.point(*max));
                if f[3] > 0 {
                    rect(s, [a[0], a[1], b[0], b[1]], 0.0, &fill(*f));
                }
                if let Some(st) = st {
                    // The stroke lies outside the rectangle, as on screen.
                    let e = st.width / 2.0;
                    rect(
                        s,
                        [a[0] - e, a[1] - e, b[0] + e, b[1] + e],
                        0.0,
                        &format!(r#"fill="none"{}"#, stroke(Some(*st), false, k)),
                    );
                }
            }
            Shape::Circle {
                centre,
                radius,
                fill: f,
                stroke: st,
            } => {
                let c = t.point(*centre);
                let _ = writeln!(
                    s,
                    r#"<circle cx="{}" cy="{}" r="{}" {}{}/>"#,
                    n(c[0]),
                    n(c[1]),
                    n(*radius),
                    fill(*f),
                    stroke(*st, false, k)
                );
            }
            Shape::Text {
                at,
                offset,
                anchor,
                text: txt,
                size,
                color,
                background,
            } => {
                // A label wider than its view shrinks to fit it.
                let pad = if background.is_some() {
                    LABEL_PAD[0] * k
                } else {
                    0.0
                };
                let width = text::measure(txt, *size).0[0];
                let mut fits = text::fit(width, 2.0 * pad, clip);
                // A mode's title too wide for its view (side by side, a narrow figure) in its
                // short form at full size, as the app shows it: shrunk, it was smaller than
                // its neighbour's title.
                let short = (fits < 1.0 && overlay::is_title(shape))
                    .then(|| overlay::short_title(txt))
                    .flatten();
                let txt = short.as_deref().unwrap_or(txt);
                if short.is_some() {
                    fits = text::fit(text::measure(txt, *size).0[0], 2.0 * pad, clip);
                }
                let size = &(size * fits);
                let (text_size, _) = text::measure(txt, *size);
                let outer = text::padded(text_size, background.is_some(), k);
                // A label with a box keeps clear of the others; a bare letter (a handle's
                // name) stays where it is.
                let b = if background.is_some() {
                    text::place_label_avoiding(
                        t.point(*at),
                        *offset,
                        *anchor,
                        outer,
                        clip,
                        &placed,
                        &keep_clear,
                    )
                } else {
                    text::place_label(t.point(*at), *offset, *anchor, outer, clip)
                };
                if background.is_some() {
                    placed.push(b);
                }
                label(s, glyphs, b, Label::new(txt, *size, *color, *background), k);
            }
            Shape::HandleLabel {
                at,
                reach,
                outward,
                text: txt,
                size,
                color,
                background,
            } => {
                let p = t.point(*at);
                let width = text::measure(txt, *size).0[0];
                let size = size * text::fit(width, 2.0 * LABEL_PAD[0] * k, clip);
                let others = label_place::others(&handles, p);
                let (b, scale) = label_place::place_handle_label_fitting(
                    p,
                    *reach,
                    *outward,
                    &others,
                    |scale| text::padded(text::measure(txt, size * scale).0, true, k),
                    clip,
                    &placed,
                    &keep_clear,
                );
                let size = size * scale;
                placed.push(b);
                label(
                    s,
                    glyphs,
                    b,
                    Label::new(txt, size, *color, Some(*background)),
                    k,
                );
            }
            Shape::QuadLabels(quad_labels) => {
                let (texts, gaps) = (&quad_labels.texts, quad_labels.gaps);
                // A block wider than its view shrinks to fit it.
                let widths = texts.each_ref().map(|x| {
                    x.as_ref()
                        .map(|(x, _)| text::measure(x, quad_labels.size).0[0])
                });
                let size = quad_labels.size
                    * label_place::block_fit(widths, LABEL_PAD[0] * k, gaps[0], clip);
                let sizes_at = |scale: f32| {
                    texts.each_ref().map(|x| {
                        x.as_ref()
                            .map(|(x, _)| text::padded(text::measure(x, size * scale).0, true, k))
                    })
                };
                let quad = label_place::quad_box(
                    t.point(quad_labels.min),
                    t.point(quad_labels.max),
                    quad_labels.outline,
                );
                let (q, scale) = label_place::place_quad_block_fitting(
                    quad,
                    sizes_at,
                    gaps[0],
                    gaps[1],
                    quad_labels.above,
                    clip,
                    &placed,
                    &keep_clear,
                );
                let size = size * scale;
                if let Some([a, b]) = q.leader {
                    let _ = writeln!(
                        s,
                        r#"<polyline points="{}" fill="none"{}/>"#,
                        points(&[a, b]),
                        stroke(Some(quad_labels.leader), false, k)
                    );
                }
                for (b, x) in q.boxes.iter().zip(texts) {
                    if let (Some(b), Some((txt, color))) = (b, x) {
                        label(
                            s,
                            glyphs,
                            *b,
                            Label::new(txt, size, *color, Some(quad_labels.background)),
                            k,
                        );
                        placed.push(*b);
                    }
                }
            }
            Shape::LabelPair {
                at,
                offset_y,
                gap,
                texts,
                size,
                color,
                background,
            } => {
                let p = t.point(*at);
                let has_box = background.is_some();
                let widths = texts.each_ref().map(|x| text::measure(x, *size).0[0]);
                let pad = if has_box { LABEL_PAD[0] * k } else { 0.0 };
                let size = size * text::pair_fit(widths, pad, *gap, clip);
                let outer = texts
                    .each_ref()
                    .map(|x| text::padded(text::measure(x, size).0, has_box, k));
                let (boxes, _) = text::place_pair([p[0], p[1] + offset_y], *gap, outer, clip);
                for (b, txt) in boxes.iter().zip(texts) {
                    label(s, glyphs, *b, Label::new(txt, size, *color, *background), k);
                }
                placed.extend(boxes);
            }
            Shape::PixelGrid {
                width,
                height,
                line,
                dots,
            } => grid(s, t, clip, [*width, *height], *line, *dots),
            Shape::ColorBar {
                at,
                offset,
                size,
                colors,
                labels,
                title,
            } => {
                let p = t.point(*at);
                let min = [p[0] + offset[0], p[1] + offset[1]];
                color_bar(
                    s,
                    glyphs,
                    [min[0], min[1], min[0] + size[0], min[1] + size[1]],
                    colors,
                    labels,
                    title,
                    k,
                );
            }
        }
    }
    if in_image_group {
        s.push_str("</g>\n");
    }
}

fn grid(
    s: &mut String,
    t: Transform,
    clip: Box2,
    [width, height]: [u32; 2],
    line: Stroke,
    dots: Option<(f32, Rgba)>,
) {
    let (w, h) = (f64::from(width), f64::from(height));
    let mut d = String::new();
    for x in 0..=width {
        let a = t.point(DVec2::new(f64::from(x), 0.0));
        let b = t.point(DVec2::new(f64::from(x), h));
        let _ = write!(d, "M{} {}V{}", n(a[0]), n(a[1]), n(b[1]));
    }
    for y in 0..=height {
        let a = t.point(DVec2::new(0.0, f64::from(y)));
        let b = t.point(DVec2::new(w, f64::from(y)));
        let _ = write!(d, "M{} {}H{}", n(a[0]), n(a[1]), n(b[0]));
    }
    let _ = writeln!(
        s,
        r#"<path d="{d}" fill="none"{}/>"#,
        stroke(Some(line), false, 1.0).replace(r#" stroke-linejoin="round""#, "")
    );
    if let Some((r, c)) = dots {
        let mut d = String::new();
        for y in 0..height {
            for x in 0..width {
                let p = t.point(DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
                if p[0] >= clip[0] && p[0] <= clip[2] && p[1] >= clip[1] && p[1] <= clip[3] {
                    let _ = write!(
                        d,
                        "M{} {}h{}v{}h-{}z",
                        n(p[0] - r),
                        n(p[1] - r),
                        n(2.0 * r),
                        n(2.0 * r),
                        n(2.0 * r)
                    );
                }
            }
        }
        let _ = writeln!(s, r#"<path d="{d}" {}/>"#, fill(c));
    }
}

/// The colour bar's background box for the bar `r` (its title above, its labels right).
pub fn color_bar_back(r: Box2, k: f32) -> Box2 {
    [
        r[0] - COLOR_BAR_BACK_MIN[0] * k,
        r[1] - COLOR_BAR_BACK_MIN[1] * k,
        r[2] + COLOR_BAR_BACK_MAX[0] * k,
        r[3] + COLOR_BAR_BACK_MAX[1] * k,
    ]
}

/// The colour bar as the screen draws it: a rounded background, the gradient from the first
/// colour at the bottom to the last at the top, a white frame, ticks with labels, a title.
fn color_bar(
    s: &mut String,
    glyphs: &mut Glyphs,
    r: Box2,
    colors: &[Rgba],
    labels: &[(f32, String)],
    title: &str,
    k: f32,
) {
    let back = color_bar_back(r, k);
    rect(s, back, COLOR_BAR_ROUNDING * k, &fill(LABEL_BG));
    // One gradient through all the colours, evenly spaced from bottom to top (the screen
    // draws the same as one band per pair of neighbouring colours).
    let last = colors.len().saturating_sub(1).max(1);
    let height = r[3] - r[1];
    let id = format!("bar-{}-{}", r[0].round(), r[1].round());
    let _ = write!(
        s,
        r#"<linearGradient id="{id}" x1="0" y1="1" x2="0" y2="0">"#
    );
    for (i, c) in colors.iter().enumerate() {
        let _ = write!(
            s,
            r#"<stop offset="{}" stop-color="{}"/>"#,
            n(i as f32 / last as f32),
            hex(*c)
        );
    }
    s.push_str("</linearGradient>\n");
    rect(s, r, 0.0, &format!(r#"fill="url(#{id})""#));
    // A white frame of one point, outside the bar.
    let e = k / 2.0;
    rect(
        s,
        [r[0] - e, r[1] - e, r[2] + e, r[3] + e],
        0.0,
        &format!(r##"fill="none" stroke="#ffffff" stroke-width="{}""##, n(k)),
    );
    let size = COLOR_BAR_TEXT * k;
    for (f, l) in labels {
        let y = r[3] - height * f;
        let _ = writeln!(
            s,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}"{}/>"#,
            n(r[2]),
            n(y),
            n(r[2] + COLOR_BAR_TICK * k),
            n(y),
            stroke(Some(Stroke::new(k, LABEL_TEXT)), false, k)
        );
        let (extent, _) = text::measure(l, size);
        let b = Anchor::LeftCenter.box_at([r[2] + COLOR_BAR_LABEL_GAP * k, y], extent);
        label(s, glyphs, b, Label::new(l, size, LABEL_TEXT, None), k);
    }
    let (extent, _) = text::measure(title, size);
    let b = Anchor::CenterBottom.box_at(
        [(r[0] + r[2]) / 2.0, r[1] - COLOR_BAR_LABEL_GAP * k],
        extent,
    );
    label(s, glyphs, b, Label::new(title, size, LABEL_TEXT, None), k);
}
