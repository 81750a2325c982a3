//! The marks over the image: a traced pixel's triangle and sub-triangles, the pixel marker
//! with its crosshair, the vertex handles with their w labels, and the note listing vertices
//! behind the camera.

use glam::DVec2;

use super::{
    Anchor, CLIP_POINT, HANDLE_RADIUS, HandleMark, LABEL_BG, NEGATIVE, Rgba, SHADOW,
    SUB_AREA_ALPHA, Shape, Stroke, TEXT_LABEL, TEXT_SMALL, TriangleMark, centre_of, text,
    vertex_color, vertex_name, with_alpha,
};

/// The triangle outline and, if asked, the three sub-triangles P V_{i+1} V_{i+2}, each in
/// the colour of the vertex V_i whose weight its signed area is (dashed when negative).
pub(super) fn triangle_shapes(
    shapes: &mut Vec<Shape>,
    t: &TriangleMark,
    p: DVec2,
    sub_areas: bool,
) {
    if sub_areas {
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let color = t.mesh_indices[i].map_or(CLIP_POINT, vertex_color);
            let negative = t.weights[i] < 0.0;
            shapes.push(Shape::Polygon {
                points: vec![p, t.vertices[j], t.vertices[k]],
                fill: with_alpha(
                    color,
                    if negative {
                        SUB_AREA_ALPHA / 2
                    } else {
                        SUB_AREA_ALPHA
                    },
                ),
                stroke: Some(Stroke::new(
                    if negative { 2.5 } else { 1.5 },
                    if negative { NEGATIVE } else { color },
                )),
                dashed: negative,
            });
        }
    }
    shapes.push(Shape::Polygon {
        points: t.vertices.to_vec(),
        fill: [0, 0, 0, 0],
        stroke: Some(Stroke::new(3.0, [255, 255, 255, 230])),
        dashed: false,
    });
}

/// A square around the pixel and a crosshair through its centre.
pub(super) fn pixel_marker(
    shapes: &mut Vec<Shape>,
    pixel: [u32; 2],
    color: Rgba,
    w: f64,
    h: f64,
    cross: bool,
) {
    let (x, y) = (f64::from(pixel[0]), f64::from(pixel[1]));
    let c = centre_of(pixel);
    if cross {
        for points in [
            vec![DVec2::new(0.0, c.y), DVec2::new(x, c.y)],
            vec![DVec2::new(x + 1.0, c.y), DVec2::new(w, c.y)],
            vec![DVec2::new(c.x, 0.0), DVec2::new(c.x, y)],
            vec![DVec2::new(c.x, y + 1.0), DVec2::new(c.x, h)],
        ] {
            shapes.push(Shape::Line {
                points,
                stroke: Stroke::new(1.0, with_alpha(color, 150)),
                dashed: true,
            });
        }
    }
    for (width, col) in [(4.0, SHADOW), (2.0, color)] {
        shapes.push(Shape::Rect {
            min: DVec2::new(x, y),
            max: DVec2::new(x + 1.0, y + 1.0),
            fill: [0, 0, 0, 0],
            stroke: Some(Stroke::new(width, col)),
        });
    }
    shapes.push(Shape::Circle {
        centre: c,
        radius: 2.5,
        fill: color,
        stroke: Some(Stroke::new(1.0, SHADOW)),
    });
}

/// A handle and its label; the label goes on the side away from `centre` (the handles'
/// centroid), so labels of neighbouring corners do not cover each other.
pub(super) fn handle_shapes(shapes: &mut Vec<Shape>, h: &HandleMark, centre: DVec2) {
    let color = vertex_color(h.index);
    let name = vertex_name(h.index);
    let Some(p) = h.window else {
        return;
    };
    let radius = if h.active {
        HANDLE_RADIUS + 3.0
    } else {
        HANDLE_RADIUS
    };
    shapes.push(Shape::Circle {
        centre: p,
        radius,
        fill: with_alpha(color, 200),
        stroke: Some(Stroke::new(
            if h.active { 3.5 } else { 2.5 },
            [255, 255, 255, 255],
        )),
    });
    shapes.push(Shape::Text {
        at: p,
        offset: [0.0, 0.0],
        anchor: Anchor::Center,
        text: name.clone(),
        size: TEXT_SMALL,
        color: [0, 0, 0, 255],
        background: None,
    });
    // Diagonally outward from the centroid: neighbouring corners' labels go different ways.
    let (left, up) = (p.x < centre.x, p.y < centre.y);
    // (The handle's own radius: an active, larger handle's label stays beside it too.)
    let d = radius * 0.75;
    shapes.push(Shape::Text {
        at: p,
        offset: [if left { -d } else { d }, if up { -d } else { d }],
        anchor: match (left, up) {
            (true, true) => Anchor::RightBottom,
            (true, false) => Anchor::RightTop,
            (false, true) => Anchor::LeftBottom,
            (false, false) => Anchor::LeftTop,
        },
        text: format!("{name}  w = {}", format_w(h.w)),
        size: TEXT_LABEL,
        color,
        background: Some(LABEL_BG),
    });
}

/// Magnitude of w from which labels use scientific notation: up to it, a label is at most
/// six digits.
pub const SCIENTIFIC_W: f64 = 1e6;

/// A w value for labels: three significant digits; scientific notation from
/// [`SCIENTIFIC_W`] on (a vertex near the eye plane has a w like 3.5e38).
pub fn format_w(w: f64) -> String {
    if w.abs() >= SCIENTIFIC_W {
        format!("{w:.2e}")
    } else if w.abs() >= 100.0 {
        format!("{w:.0}")
    } else if w.abs() >= 10.0 {
        format!("{w:.1}")
    } else {
        format!("{w:.2}")
    }
}

/// Labels for vertices behind the camera, listed in a corner of the view.
pub fn behind_camera_note(handles: &[HandleMark]) -> Option<String> {
    behind_note(handles, text::BEHIND)
}

pub(super) fn behind_note(handles: &[HandleMark], behind: &str) -> Option<String> {
    let names: Vec<String> = handles
        .iter()
        .filter(|h| h.window.is_none())
        .map(|h| format!("{} (w = {})", vertex_name(h.index), format_w(h.w)))
        .collect();
    (!names.is_empty()).then(|| format!("{behind}: {}", names.join(", ")))
}
