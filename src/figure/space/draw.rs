//! The space view as 2D shapes in painter's order: the planes, triangles and lines sorted
//! back to front by their mean distance from the orbit camera, then the points and labels on
//! top. The SVG figure and the app draw the same list.

use glam::DVec3;

use super::{Orbit, Projector, SpaceScene};
use crate::i18n::Lang;
use crate::probe::format::fmt_number;

use super::labels::spread_labels;
pub use super::labels::{Measure, svg_measure, text_width};
pub use super::shape::{Anchor2, Colour, INK, P_COLOUR, Q_COLOUR, RAY_COLOUR, Shape, ShapeKind};

const FRUSTUM: Colour = Colour([90, 90, 110, 255]);
const NEAR_FILL: Colour = Colour([70, 130, 230, 60]);
const FAR_FILL: Colour = Colour([120, 120, 120, 30]);
const IMAGE_FILL: Colour = Colour([250, 220, 90, 70]);
const GRID: Colour = Colour([150, 120, 30, 160]);
const TRIANGLE_FILL: Colour = Colour([120, 170, 220, 110]);
const PIXEL_TRIANGLE_FILL: Colour = Colour([245, 160, 70, 130]);
const CUT_FILL: Colour = Colour([245, 120, 40, 150]);

/// The drawing's sizes for a text size (points of the labels' font).
#[derive(Clone, Copy, Debug)]
struct Sizes {
    text: f32,
    line: f32,
    dot: f32,
}

/// The space view drawn into `rect` by `projector`, labels `text` points high in `lang`, each
/// label's size (width and row height) as the renderer draws it given by `measure`
/// (`svg_measure` in the figures; egui's rows are taller).
pub fn shapes(
    space: &SpaceScene,
    projector: &Projector,
    lang: Lang,
    text: f32,
    measure: Measure<'_>,
) -> Vec<Shape> {
    let k = text / 15.0;
    let sz = Sizes {
        text,
        line: 1.6 * k,
        dot: 4.0 * k,
    };
    let mut back = Vec::new();
    let mut front = Vec::new();
    let pr = |p: DVec3| projector.project(p);
    let poly = |pts: &[DVec3], fill: Colour, stroke: Option<(Colour, f32)>| {
        let projected: Vec<([f32; 2], f64)> = pts.iter().map(|p| pr(*p)).collect();
        let depth = projected.iter().map(|p| p.1).sum::<f64>() / projected.len().max(1) as f64;
        Shape {
            kind: ShapeKind::Polygon {
                points: projected.into_iter().map(|p| p.0).collect(),
                fill,
                stroke,
            },
            depth,
        }
    };
    let line = |a: DVec3, b: DVec3, colour: Colour, width: f32, dashed: bool| {
        let ((from, da), (to, db)) = (pr(a), pr(b));
        Shape {
            kind: ShapeKind::Line {
                from,
                to,
                colour,
                width,
                dashed,
            },
            depth: (da + db) / 2.0,
        }
    };
    let label = |p: DVec3, dx: f32, dy: f32, s: String, colour: Colour, anchor: Anchor2| {
        let (at, depth) = pr(p);
        Shape {
            kind: ShapeKind::Text {
                at: [at[0] + dx * k, at[1] + dy * k],
                text: s,
                size: sz.text,
                colour,
                anchor,
            },
            depth,
        }
    };
    let dot = |p: DVec3, radius: f32, fill: Colour, stroke: Option<(Colour, f32)>| Shape {
        kind: ShapeKind::Dot {
            centre: pr(p).0,
            radius,
            fill,
            stroke,
        },
        depth: pr(p).1,
    };
    let tr = |key: &str| lang.tr(&format!("space.{key}"));
    let eye = space.ray.as_ref().map_or(DVec3::ZERO, |r| r.origin);
    let apex = if space.lens.perspective() {
        Some(space.lens.at_depth(glam::DVec2::ZERO, 0.0))
    } else {
        None
    };

    // The frustum: the end face, the near plane, the image plane and the edges.
    let far = space.far_corners;
    back.push(poly(&far, FAR_FILL, Some((FRUSTUM, sz.line * 0.6))));
    if space.far_is_shown() {
        front.push(label(
            far[1],
            6.0,
            -6.0,
            tr("far_plane"),
            FRUSTUM,
            Anchor2::Start,
        ));
    }
    let image_is_near = space.near == Some(space.image_depth);
    if let Some(near) = space.near_corners {
        back.push(poly(&near, NEAR_FILL, Some((FRUSTUM, sz.line * 0.6))));
        if !image_is_near {
            front.push(label(
                near[0],
                -6.0,
                -6.0,
                tr("near_plane"),
                FRUSTUM,
                Anchor2::End,
            ));
        }
    }
    for i in 0..4 {
        let start = match (apex, space.near_corners) {
            (Some(a), Some(n)) => {
                back.push(line(a, n[i], FRUSTUM, sz.line * 0.5, true));
                n[i]
            }
            (Some(a), None) => a,
            (None, Some(n)) => n[i],
            (None, None) => space.image_corners[i],
        };
        back.push(line(start, far[i], FRUSTUM, sz.line * 0.7, false));
    }
    let img = space.image_corners;
    back.push(poly(&img, IMAGE_FILL, Some((GRID, sz.line * 0.6))));
    for g in &space.grid {
        back.push(line(g[0], g[1], GRID, sz.line * 0.35, false));
    }
    let image_name = if image_is_near {
        tr("image_is_near")
    } else {
        tr("image_plane")
    };
    front.push(label(img[3], 0.0, 18.0, image_name, GRID, Anchor2::Start));

    // The triangles (the kept part of a clipped one, its whole outline dashed).
    let seen = space.ray.as_ref().and_then(|r| r.seen.as_ref());
    for t in &space.triangles {
        let corners = t.corners.map(|i| space.vertices[i].point);
        let mine = seen.is_some_and(|s| s.source == t.source);
        let fill = if mine {
            PIXEL_TRIANGLE_FILL
        } else {
            TRIANGLE_FILL
        };
        match &t.kept {
            Some(kept) => {
                for i in 0..3 {
                    back.push(line(
                        corners[i],
                        corners[(i + 1) % 3],
                        INK,
                        sz.line * 0.6,
                        true,
                    ));
                }
                if kept.len() >= 3 {
                    back.push(poly(
                        kept,
                        if mine { CUT_FILL } else { fill },
                        Some((INK, sz.line)),
                    ));
                }
            }
            None => back.push(poly(&corners, fill, Some((INK, sz.line)))),
        }
    }
    // Vertex names: every drawn vertex of a small mesh, else the pixel's triangle's.
    let mut named = vec![false; space.vertices.len()];
    for t in &space.triangles {
        let mine = seen.is_some_and(|s| s.source == t.source);
        if space.triangles.len() <= crate::probe::LIST_ALL_TRIANGLES || mine {
            for i in t.corners {
                named[i] = true;
            }
        }
    }
    for (v, _) in space.vertices.iter().zip(&named).filter(|(_, n)| **n) {
        front.push(dot(v.point, sz.dot * 0.8, INK, None));
        let mut s = format!("{}  w = {}", v.name, fmt_number(v.w));
        if v.w <= 0.0 {
            s = format!("{s} ({})", tr("behind"));
        }
        front.push(label(v.point, 7.0, -7.0, s, INK, Anchor2::Start));
    }

    // The depth axis from the eye along -z, with view-depth ticks on one side and z/w ticks
    // on the other.
    if let Some(a) = apex {
        let end = DVec3::new(0.0, 0.0, -space.shown_far);
        back.push(line(a, end, INK, sz.line * 0.8, false));
        front.push(label(end, 6.0, 4.0, tr("view_depth"), INK, Anchor2::Start));
        // Ticks at least a label's height apart on the drawing (and from the eye).
        let far_enough = |placed: &mut Vec<[f32; 2]>, p: DVec3| {
            let at = pr(p).0;
            let ok = placed
                .iter()
                .all(|q| (q[0] - at[0]).hypot(q[1] - at[1]) >= 1.6 * sz.text);
            if ok {
                placed.push(at);
            }
            ok
        };
        let mut placed = vec![pr(a).0];
        let step = crate::figure::plot::tick_step(space.shown_far);
        let mut d = step;
        while d < space.shown_far {
            let p = DVec3::new(0.0, 0.0, -d);
            if far_enough(&mut placed, p) {
                front.push(dot(p, sz.dot * 0.45, INK, None));
                front.push(label(p, -5.0, 16.0, fmt_number(d), INK, Anchor2::End));
            }
            d += step;
        }
        let mut placed = vec![pr(a).0];
        for z in [0.0, 0.5, 0.9, 0.99] {
            if let Some(d) = space.lens.depth_at_z_ndc(z) {
                let p = DVec3::new(0.0, 0.0, -d);
                if d < space.shown_far && far_enough(&mut placed, p) {
                    front.push(dot(p, sz.dot * 0.55, Q_COLOUR, None));
                    front.push(label(
                        p,
                        5.0,
                        -6.0,
                        format!("z/w={z}"),
                        Q_COLOUR,
                        Anchor2::Start,
                    ));
                }
            }
        }
    }
    front.push(dot(eye, sz.dot * 1.2, INK, None));
    front.push(label(eye, -8.0, 16.0, tr("eye"), INK, Anchor2::End));

    // The pixel's ray, P and Q.
    if let Some(ray) = &space.ray {
        let pixel = lang.tr_with(
            "space.pixel",
            &[
                ("x", &ray.pixel[0].to_string()),
                ("y", &ray.pixel[1].to_string()),
            ],
        );
        back.push(line(
            ray.origin,
            ray.on_image,
            RAY_COLOUR,
            sz.line * 1.4,
            false,
        ));
        front.push(dot(ray.on_image, sz.dot * 0.8, RAY_COLOUR, None));
        front.push(label(
            ray.on_image,
            -8.0,
            -8.0,
            pixel,
            RAY_COLOUR,
            Anchor2::End,
        ));
        match seen {
            Some(s) => {
                back.push(line(ray.on_image, s.p, RAY_COLOUR, sz.line * 1.4, false));
                back.push(line(s.p, ray.end, RAY_COLOUR, sz.line * 0.8, true));
                front.push(line(s.p, s.q, Q_COLOUR, sz.line, true));
                front.push(dot(
                    s.q,
                    sz.dot * 1.3,
                    Colour([255, 255, 255, 200]),
                    Some((Q_COLOUR, sz.line * 1.4)),
                ));
                front.push(label(
                    s.q,
                    9.0,
                    16.0,
                    tr("q_short"),
                    Q_COLOUR,
                    Anchor2::Start,
                ));
                front.push(dot(s.p, sz.dot * 1.5, P_COLOUR, Some((INK, sz.line * 0.6))));
                front.push(label(
                    s.p,
                    9.0,
                    -9.0,
                    tr("p_short"),
                    P_COLOUR,
                    Anchor2::Start,
                ));
                if apex.is_some() {
                    let foot = DVec3::new(0.0, 0.0, s.p.z);
                    front.push(line(s.p, foot, P_COLOUR, sz.line * 0.7, true));
                    front.push(dot(foot, sz.dot, P_COLOUR, None));
                    front.push(label(
                        foot,
                        -8.0,
                        -8.0,
                        format!("W_P = {}", fmt_number(-s.p.z)),
                        P_COLOUR,
                        Anchor2::End,
                    ));
                }
                if let Some(cut) = &s.cut {
                    for (i, (name, p)) in cut.polygon.iter().enumerate() {
                        if i >= 2 && i + 1 < cut.polygon.len() {
                            front.push(line(cut.polygon[0].1, *p, INK, sz.line * 0.7, true));
                        }
                        if name.starts_with('K') {
                            front.push(dot(*p, sz.dot, CUT_FILL, Some((INK, sz.line * 0.6))));
                            front.push(label(*p, -7.0, 16.0, name.clone(), INK, Anchor2::End));
                        }
                    }
                }
            }
            None => back.push(line(ray.on_image, ray.end, RAY_COLOUR, sz.line, false)),
        }
    }

    back.sort_by(|a, b| b.depth.total_cmp(&a.depth));
    spread_labels(&mut front, projector.rect(), measure);
    back.extend(front);
    back
}

/// The 3D points the view frames: the eye, the image and near planes, the vertices and P
/// (the frustum beyond them may leave the picture).
pub(super) fn framed_points(space: &SpaceScene) -> Vec<DVec3> {
    let mut pts: Vec<DVec3> = space.image_corners.to_vec();
    pts.extend(space.near_corners.into_iter().flatten());
    pts.push(space.lens.at_depth(glam::DVec2::ZERO, 0.0));
    pts.extend(space.vertices.iter().map(|v| v.point));
    pts.extend(
        space
            .ray
            .iter()
            .filter_map(|r| r.seen.as_ref().map(|s| s.p)),
    );
    pts
}

impl SpaceScene {
    /// The projector of `orbit` for this scene into `rect` (`[min_x, min_y, max_x, max_y]`).
    pub fn projector(&self, orbit: Orbit, rect: [f32; 4]) -> Projector {
        Projector::new(orbit, &framed_points(self), rect)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text_at(at: [f32; 2], text: &str) -> Shape {
        Shape {
            kind: ShapeKind::Text {
                at,
                text: text.to_string(),
                size: 15.0,
                colour: INK,
                anchor: Anchor2::Start,
            },
            depth: 0.0,
        }
    }

    /// Five labels at one point: the first stays, the others move, none overlaps another; a
    /// label moved two lines or more gets a dashed line to where it was, drawn before every
    /// label, and one moved less (a line, or to the other side of the point) gets none.
    #[test]
    fn labels_moved_far_from_their_point_get_a_line_back_to_it() {
        let home = [100.0, 200.0];
        let names = ["P", "Q", "eye", "W_P = 1", "view depth"];
        let mut shapes: Vec<Shape> = names.iter().map(|n| text_at(home, n)).collect();
        spread_labels(&mut shapes, [0.0, 0.0, 400.0, 400.0], &svg_measure);
        let texts: Vec<(usize, [f32; 2], String)> = shapes
            .iter()
            .enumerate()
            .filter_map(|(i, s)| match &s.kind {
                ShapeKind::Text { at, text, .. } => Some((i, *at, text.clone())),
                _ => None,
            })
            .collect();
        let lines: Vec<(usize, [f32; 2], [f32; 2])> = shapes
            .iter()
            .enumerate()
            .filter_map(|(i, s)| match &s.kind {
                ShapeKind::Line {
                    from, to, dashed, ..
                } => {
                    assert!(dashed);
                    Some((i, *from, *to))
                }
                _ => None,
            })
            .collect();
        assert_eq!(texts.len(), names.len());
        assert_eq!(texts[0].1, home, "the first label keeps its place");
        let boxes: Vec<[f32; 4]> = texts
            .iter()
            .map(|(_, at, t)| {
                let [w, row] = svg_measure(t, 15.0);
                let bottom = at[1] + 0.25 * 15.0;
                [at[0], bottom - row, at[0] + w, bottom]
            })
            .collect();
        for (i, a) in boxes.iter().enumerate() {
            for b in &boxes[i + 1..] {
                assert_eq!(crate::figure::text::overlap_area(*a, &[*b]), 0.0);
            }
        }
        let line_height = 1.05 * 15.0 + 0.05 * 15.0;
        let far = texts
            .iter()
            .filter(|(_, at, _)| (at[1] - home[1]).abs() > 1.5 * line_height)
            .count();
        assert!(far >= 1, "five labels at one point: some move far");
        assert_eq!(lines.len(), far, "one line per label moved far");
        let first_text = texts[0].0;
        for (i, from, to) in &lines {
            assert!(*i < first_text, "the lines are drawn under the labels");
            assert!((to[1] - (home[1] + 0.25 * 15.0 - 0.5 * 1.05 * 15.0)).abs() < 1.0);
            assert!((from[1] - to[1]).abs() > line_height);
        }
    }
}
