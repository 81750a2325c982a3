//! The marks over the image: a traced pixel's triangle and sub-triangles, the pixel marker
//! with its crosshair, the 2x2 quad of the texture derivatives, the vertex handles with their w labels, and the note listing vertices
//! behind the camera.

use glam::DVec2;

use super::{
    Anchor, CLIP_POINT, ClipMark, HANDLE_RADIUS, HandleMark, LABEL_BG, LABEL_TEXT, NEGATIVE,
    QuadMark, Rgba, SHADOW, SUB_AREA_ALPHA, Shape, Stroke, TEXT_LABEL, TEXT_SMALL, TriangleMark,
    centre_of, text, vertex_color, vertex_name, with_alpha,
};

/// The triangle outline and, if asked (`Some(fill)`), the three sub-triangles P V_{i+1}
/// V_{i+2}, each in the colour of the vertex V_i whose weight its signed area is (dashed when
/// negative), tinted when `fill`, else outlines only.
pub(super) fn triangle_shapes(
    shapes: &mut Vec<Shape>,
    t: &TriangleMark,
    p: DVec2,
    sub_areas: Option<bool>,
) {
    if let Some(fill) = sub_areas {
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let color = t.mesh_indices[i].map_or(CLIP_POINT, vertex_color);
            let negative = t.weights[i] < 0.0;
            shapes.push(Shape::Polygon {
                points: vec![p, t.vertices[j], t.vertices[k]],
                fill: with_alpha(
                    color,
                    match (fill, negative) {
                        (false, _) => 0,
                        (true, true) => SUB_AREA_ALPHA / 2,
                        (true, false) => SUB_AREA_ALPHA,
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
        stroke: Some(Stroke::new(3.0, TRIANGLE_OUTLINE)),
        dashed: false,
    });
}

/// The clipped polygon: its outline and the fan's inner edges dashed, and each corner the
/// clipper made marked and named (K1, K2, ...), its label on the side away from the
/// polygon's centre; a corner outside the `w x h` image gets no mark (a label pushed inside
/// would name the wrong place).
pub(super) fn clip_shapes(shapes: &mut Vec<Shape>, c: &ClipMark, w: f64, h: f64) {
    let n = c.corners.len();
    if n < 3 {
        return;
    }
    let points: Vec<DVec2> = c.corners.iter().map(|(_, p, _)| *p).collect();
    for (width, color) in [(4.0, SHADOW), (2.0, CLIP_POINT)] {
        shapes.push(Shape::Polygon {
            points: points.clone(),
            fill: [0, 0, 0, 0],
            stroke: Some(Stroke::new(width, color)),
            dashed: true,
        });
    }
    // The fan from corner 0: its inner edges 0-2, 0-3, ..., 0-(n-2).
    for k in 2..n - 1 {
        shapes.push(Shape::Line {
            points: vec![points[0], points[k]],
            stroke: Stroke::new(1.5, CLIP_POINT),
            dashed: true,
        });
    }
    let centre = points.iter().sum::<DVec2>() / n as f64;
    for (name, p, made) in &c.corners {
        let inside = (0.0..=w).contains(&p.x) && (0.0..=h).contains(&p.y);
        if !made || !inside {
            continue;
        }
        shapes.push(Shape::Circle {
            centre: *p,
            radius: 6.0,
            fill: CLIP_POINT,
            stroke: Some(Stroke::new(2.0, SHADOW)),
        });
        let below = p.y >= centre.y;
        shapes.push(Shape::Text {
            at: *p,
            offset: [0.0, if below { 10.0 } else { -10.0 }],
            anchor: if below {
                Anchor::CenterTop
            } else {
                Anchor::CenterBottom
            },
            text: name.clone(),
            size: TEXT_LABEL,
            color: LABEL_TEXT,
            background: Some(LABEL_BG),
        });
    }
}

/// Colour of the marked pixel's triangle outline.
const TRIANGLE_OUTLINE: Rgba = [255, 255, 255, 230];

/// Whether `shape` is the marked pixel's triangle outline (drawn with its sub-triangles).
pub fn is_triangle_outline(shape: &Shape) -> bool {
    matches!(shape, Shape::Polygon { fill: [_, _, _, 0], stroke: Some(s), dashed: false, points }
        if s.color == TRIANGLE_OUTLINE && points.len() == 3)
}

/// The colour of the 2x2 quad's outline and labels.
const QUAD: Rgba = [255, 220, 60, 255];
/// Points: the quad's uv labels (four of them: the small labels' size, readable from the back
/// of a lecture hall where 13 points, tried first, were not).
const TEXT_QUAD: f32 = super::style::TEXT_SMALL;

/// Points between the quad and its labels' block, and between the block's labels.
const QUAD_LABEL_GAP: f32 = 8.0;
const QUAD_LABEL_SPACING: f32 = 2.0;
/// Points: the width of the quad outline's shadow, drawn outside the quad.
const QUAD_OUTLINE: f32 = 5.0;

/// The 2x2 quad a pixel's texture derivatives come from: its outline (pushed to `shapes`),
/// and, returned, the four pixels' uvs as one block of labels ([`Shape::QuadLabels`]), named
/// `uv_ij` for pixel `(x0 + i, y0 + j)` ("helper" on a pixel outside the triangle, its uv
/// extrapolated), in two rows of two as the pixels sit (`uv_00 uv_10` over `uv_01 uv_11`),
/// preferably above the quad in the lower half of the image (`size`, in pixels), else below
/// it. The caller pushes the block after the handles: it is placed clear of them and their
/// labels.
pub(super) fn quad_shapes(
    shapes: &mut Vec<Shape>,
    q: &QuadMark,
    size: DVec2,
    lang: crate::i18n::Lang,
) -> Shape {
    let o = DVec2::new(f64::from(q.origin[0]), f64::from(q.origin[1]));
    for (width, col) in [(QUAD_OUTLINE, SHADOW), (2.5, QUAD)] {
        shapes.push(Shape::Rect {
            min: o,
            max: o + DVec2::splat(2.0),
            fill: [0, 0, 0, 0],
            stroke: Some(Stroke::new(width, col)),
        });
    }
    let texts = std::array::from_fn(|k| {
        let uv = q.uvs[k]?;
        let (u, v) = (
            crate::probe::format::fmt_number(f64::from(uv[0])),
            crate::probe::format::fmt_number(f64::from(uv[1])),
        );
        let key = if q.inside[k] {
            "figure.quad.uv"
        } else {
            "figure.quad.helper"
        };
        // Named as the probe and the lessons name them (uv_ij: pixel (x0 + i, y0 + j)).
        let text = lang.tr_with(
            key,
            &[("ij", &format!("{}{}", k % 2, k / 2)), ("u", &u), ("v", &v)],
        );
        Some((text, if q.inside[k] { QUAD } else { NEGATIVE }))
    });
    Shape::QuadLabels(super::QuadLabels {
        min: o,
        max: o + DVec2::splat(2.0),
        texts,
        size: TEXT_QUAD,
        gaps: [QUAD_LABEL_SPACING, QUAD_LABEL_GAP],
        outline: QUAD_OUTLINE,
        above: o.y + 1.0 > size.y / 2.0,
        background: LABEL_BG,
        leader: Stroke::new(1.5, QUAD),
    })
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

/// Where a vertex's handle is drawn (and grabbed): at its window position `window`, or, for
/// a vertex outside the `size` image, at the nearest point of the image's edge (the view's
/// margin holds a handle there whole), so a corner far off the picture still has a handle to
/// drag and a label; an arrow beside it points the way to the corner.
///
/// ```
/// use barylab::figure::overlay::handle_position;
/// use glam::DVec2;
/// let size = DVec2::new(480.0, 300.0);
/// assert_eq!(handle_position(DVec2::new(100.0, 50.0), size), DVec2::new(100.0, 50.0));
/// assert_eq!(handle_position(DVec2::new(-2000.0, 900.0), size), DVec2::new(0.0, 300.0));
/// ```
pub fn handle_position(window: DVec2, size: DVec2) -> DVec2 {
    window.clamp(DVec2::ZERO, size.max(DVec2::ZERO))
}

/// The arrow pointing along `d` (image rows down): one of the eight compass arrows.
fn arrow(d: DVec2) -> &'static str {
    const ARROWS: [&str; 8] = ["→", "↘", "↓", "↙", "←", "↖", "↑", "↗"];
    let sector = (d.y.atan2(d.x) / std::f64::consts::FRAC_PI_4).round() as i64;
    ARROWS[sector.rem_euclid(8) as usize]
}

/// A handle and its label; the label goes on the side away from `centre` (the handles'
/// centroid), so labels of neighbouring corners do not cover each other. A vertex outside the
/// `size` image gets its handle on the edge ([`handle_position`]) with an arrow towards it.
pub(super) fn handle_shapes(shapes: &mut Vec<Shape>, h: &HandleMark, centre: DVec2, size: DVec2) {
    let color = vertex_color(h.index);
    let name = vertex_name(h.index);
    let Some(window) = h.window else {
        return;
    };
    let p = handle_position(window, size);
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
    let away = window - p;
    if away != DVec2::ZERO {
        let d = away.normalize();
        // Far enough that the arrow's box (the glyph, about 0.8 of the text size wide, and
        // its padding) clears the handle's rim and stroke: at 0.6 it lay over the disc.
        let reach = radius + 0.85 * TEXT_LABEL;
        shapes.push(Shape::Text {
            at: p,
            offset: [(d.x as f32) * reach, (d.y as f32) * reach],
            anchor: Anchor::Center,
            text: arrow(d).to_string(),
            size: TEXT_LABEL,
            color,
            background: Some(LABEL_BG),
        });
    }
    // Diagonally outward from the centroid first: neighbouring corners' labels go different
    // ways; placed beside this handle, never nearer another (`HandleLabel`).
    let outward = [
        if p.x < centre.x { -1.0 } else { 1.0 },
        if p.y < centre.y { -1.0 } else { 1.0 },
    ];
    shapes.push(Shape::HandleLabel {
        at: p,
        reach: radius,
        outward,
        text: format!("{name}  w = {}", format_w(h.w)),
        size: TEXT_LABEL,
        color,
        background: LABEL_BG,
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
    // After Chinese words the full-width colon, as the catalogue writes it.
    let colon = if behind.chars().last().is_some_and(|c| c >= '\u{2E80}') {
        "："
    } else {
        ": "
    };
    (!names.is_empty()).then(|| format!("{behind}{colon}{}", names.join(", ")))
}

/// The scanline of a marked pixel: where its row's centre line (y = row + 1/2) crosses the
/// triangle's edges, the span between the two crossings, and a dot on each crossing, for the
/// two-step (edges, then span) interpolation a scanline rasterizer does. `None` when the row
/// misses the triangle.
///
/// ```
/// use barylab::figure::overlay::{span_shapes, Shape, TriangleMark};
/// use glam::DVec2;
/// let t = TriangleMark {
///     vertices: [DVec2::new(0.0, 10.0), DVec2::new(10.0, 10.0), DVec2::new(0.0, 0.0)],
///     mesh_indices: [Some(0), Some(1), Some(2)],
///     weights: [0.3, 0.3, 0.4],
/// };
/// // Row 4: its centre line y = 4.5 crosses x = 0 (edge CA) and x = 4.5 (edge BC).
/// let shapes = span_shapes(&t, 4).expect("the row crosses the triangle");
/// let Shape::Line { points, .. } = &shapes[1] else { panic!("the span first") };
/// assert_eq!(points, &vec![DVec2::new(0.0, 4.5), DVec2::new(4.5, 4.5)]);
/// ```
pub fn span_shapes(t: &TriangleMark, row: u32) -> Option<Vec<Shape>> {
    let y = f64::from(row) + 0.5;
    let (lo, hi) = span_ends(t, row)?;
    let (l, r) = (DVec2::new(lo, y), DVec2::new(hi, y));
    let mut shapes = vec![
        Shape::Line {
            points: vec![l, r],
            stroke: Stroke::new(6.0, SHADOW),
            dashed: false,
        },
        Shape::Line {
            points: vec![l, r],
            stroke: Stroke::new(3.0, SPAN),
            dashed: false,
        },
    ];
    for p in [l, r] {
        shapes.push(Shape::Circle {
            centre: p,
            radius: 6.0,
            fill: SPAN,
            stroke: Some(Stroke::new(2.0, SHADOW)),
        });
    }
    Some(shapes)
}

/// The scanline rasterizer stepping along the pinned row's span: the pixels it has visited
/// (a trail) and the one it is at (outlined), at `step` (0 = the first pixel whose centre lies
/// in the span, `lo <= x + 0.5 < hi`; steps past the last pixel stay on it). `None` when
/// the row crosses no pixel centre inside the triangle. Returns the shapes and the span's
/// pixel count.
///
/// ```
/// use barylab::figure::overlay::{Shape, TriangleMark, span_step_shapes};
/// use glam::DVec2;
/// // Row 0's centre line y = 0.5 meets the edges C A and B C at x = 3 - 1.8 (8.5 / 9) = 1.3
/// // and x = 4.8 - 1.8 (0.5 / 9) = 4.7: the centres 1.5, 2.5, 3.5 and 4.5 lie in the span.
/// let t = TriangleMark {
///     vertices: [DVec2::new(1.2, 0.0), DVec2::new(4.8, 0.0), DVec2::new(3.0, 9.0)],
///     mesh_indices: [Some(0), Some(1), Some(2)],
///     weights: [1.0 / 3.0; 3],
/// };
/// let (shapes, count) = span_step_shapes(&t, 0, 1).expect("a span");
/// assert_eq!(count, 4);
/// // Step 1 is at the second pixel, x from 2 to 3.
/// let Shape::Polygon { points, .. } = &shapes[1] else { panic!("the outlined pixel") };
/// assert_eq!((points[0].x, points[1].x), (2.0, 3.0));
/// ```
pub fn span_step_shapes(t: &TriangleMark, row: u32, step: u32) -> Option<(Vec<Shape>, u32)> {
    let (lo, hi) = span_ends(t, row)?;
    // The first and last pixel whose centre x + 0.5 lies in [lo, hi).
    let first = (lo - 0.5).ceil();
    let last = (hi - 0.5).ceil() - 1.0;
    if !(first.is_finite() && last >= first) {
        return None;
    }
    let count = (last - first) as u32 + 1;
    let at = first + f64::from(step.min(count - 1));
    let y = f64::from(row);
    let square = |x0: f64, x1: f64| {
        vec![
            DVec2::new(x0, y),
            DVec2::new(x1, y),
            DVec2::new(x1, y + 1.0),
            DVec2::new(x0, y + 1.0),
        ]
    };
    let shapes = vec![
        Shape::Polygon {
            points: square(first, at + 1.0),
            fill: SPAN_TRAIL,
            stroke: None,
            dashed: false,
        },
        Shape::Polygon {
            points: square(at, at + 1.0),
            fill: [0, 0, 0, 0],
            stroke: Some(Stroke::new(3.0, SPAN)),
            dashed: false,
        },
    ];
    Some((shapes, count))
}

/// Where the pixel row `row`'s centre line (y = row + 0.5) enters and leaves the triangle.
fn span_ends(t: &TriangleMark, row: u32) -> Option<(f64, f64)> {
    let y = f64::from(row) + 0.5;
    let mut xs: Vec<f64> = Vec::with_capacity(3);
    for i in 0..3 {
        let (a, b) = (t.vertices[i], t.vertices[(i + 1) % 3]);
        if (a.y - y) * (b.y - y) > 0.0 || a.y == b.y {
            continue;
        }
        let k = (y - a.y) / (b.y - a.y);
        xs.push(a.x + k * (b.x - a.x));
    }
    let lo = xs.iter().copied().reduce(f64::min)?;
    let hi = xs.iter().copied().reduce(f64::max)?;
    Some((lo, hi))
}

/// The visited pixels' tint while stepping along the span.
const SPAN_TRAIL: Rgba = [255, 230, 80, 90];

/// Colour of the scanline span and its edge crossings.
const SPAN: Rgba = [255, 230, 80, 255];

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(shapes: &[Shape]) -> Vec<(DVec2, String)> {
        shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Text { at, text, .. } | Shape::HandleLabel { at, text, .. } => {
                    Some((*at, text.clone()))
                }
                _ => None,
            })
            .collect()
    }

    #[test]
    fn a_corner_off_the_image_has_its_handle_on_the_edge_with_an_arrow_towards_it() {
        let size = DVec2::new(480.0, 300.0);
        let centre = DVec2::new(240.0, 150.0);
        // (-900, 420) from the edge point (0, 300): direction (-900, 120), 172 degrees: left.
        // (-10, 400) from (0, 300): (-10, 100), 96 degrees (rows down): down.
        // (600, -100) from (480, 0): (120, -100), -40 degrees: up and right.
        for (window, edge, want) in [
            (DVec2::new(-900.0, 420.0), DVec2::new(0.0, 300.0), "←"),
            (DVec2::new(-10.0, 400.0), DVec2::new(0.0, 300.0), "↓"),
            (DVec2::new(600.0, -100.0), DVec2::new(480.0, 0.0), "↗"),
        ] {
            let h = HandleMark {
                index: 0,
                window: Some(window),
                w: 1.0,
                active: false,
            };
            let mut shapes = Vec::new();
            handle_shapes(&mut shapes, &h, centre, size);
            let circle = shapes.iter().find_map(|s| match s {
                Shape::Circle { centre, .. } => Some(*centre),
                _ => None,
            });
            assert_eq!(circle, Some(edge));
            let t = texts(&shapes);
            assert!(t.iter().all(|(at, _)| *at == edge), "{t:?}");
            assert!(t.iter().any(|(_, s)| s == want), "{window}: {t:?}");
            // The arrow's box (an arrow glyph is about 0.8 of the text size wide, plus the
            // label padding) stays off the disc and its stroke (2.5 wide, half outside).
            for s in &shapes {
                if let Shape::Text {
                    offset, size, text, ..
                } = s
                    && text == want
                {
                    let reach = offset[0].hypot(offset[1]);
                    let half = 0.4 * size + crate::figure::text::LABEL_PAD[0];
                    assert!(
                        reach - half >= HANDLE_RADIUS + 1.25,
                        "{want}: the box reaches {} from the centre",
                        reach - half
                    );
                }
            }
        }
        // A corner on the image: where it is, no arrow.
        let h = HandleMark {
            index: 1,
            window: Some(DVec2::new(100.0, 50.0)),
            w: 1.0,
            active: false,
        };
        let mut shapes = Vec::new();
        handle_shapes(&mut shapes, &h, centre, size);
        assert_eq!(texts(&shapes).len(), 2, "the name and the w label only");
    }

    /// The note of corners behind the camera: "behind the camera: A (w = -0.56)", and in
    /// Chinese with the full-width colon after the words, "在相机后方：A (w = -0.56)".
    #[test]
    fn the_behind_the_camera_note_takes_its_languages_colon() {
        let h = |index, window| HandleMark {
            index,
            window,
            w: if window.is_some() { 2.0 } else { -0.5625 },
            active: false,
        };
        let handles = [h(0, None), h(1, Some(DVec2::ZERO)), h(2, None)];
        assert_eq!(
            super::behind_note(&handles, "behind the camera").as_deref(),
            Some("behind the camera: A (w = -0.56), C (w = -0.56)")
        );
        assert_eq!(
            super::behind_note(&handles, "在相机后方").as_deref(),
            Some("在相机后方：A (w = -0.56), C (w = -0.56)")
        );
        assert_eq!(super::behind_note(&handles[1..2], "在相机后方"), None);
    }
}
