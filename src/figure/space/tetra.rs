//! Tetrahedron (volume) coordinates: a point X inside a tetrahedron ABCD is
//! `X = λ_A A + λ_B B + λ_C C + λ_D D` with `λ_A + λ_B + λ_C + λ_D = 1`, each weight the ratio
//! of a sub-tetrahedron's signed volume to the whole one's: `λ_A = V(X, B, C, D) / V(A, B, C,
//! D)`, ..., `V(P0, P1, P2, P3) = (P1 - P0) . ((P2 - P0) x (P3 - P0)) / 6`. The figure draws
//! the four sub-tetrahedra (X joined to each face), each face tinted with the colour of the
//! vertex opposite it, and its weight beside it.
//!
//! With a pixel, the point comes from the pixel's ray: the ray enters the tetrahedron at P on
//! a face (the opposite corner's weight 0, the other three the face triangle's perspective
//! weights `a b c`) and leaves through another; X is halfway between, inside, with four
//! positive weights. The weights are affine along the ray, so where it enters and leaves
//! follows from the weights at two of its points ([`segment_inside`]).

use glam::DVec3;

use super::draw::{Colour, RAY_COLOUR, Shape, ShapeKind};
use super::svg::{LABEL_SIZE, document, drawing_rect, rasterize_svg};
use super::{Orbit, SpaceScene};
use crate::figure::FigureError;
use crate::i18n::Lang;
use crate::probe::format::fmt_number;

/// The signed volume `V(P0, P1, P2, P3) = (P1 - P0) . ((P2 - P0) x (P3 - P0)) / 6`.
pub fn signed_volume(p: [DVec3; 4]) -> f64 {
    (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) / 6.0
}

/// The volume weights of `x` in tetrahedron `t`: `λ_i = V(t with t_i replaced by x) / V(t)`.
/// `None` for a flat tetrahedron.
pub fn volume_weights(t: [DVec3; 4], x: DVec3) -> Option<[f64; 4]> {
    let whole = signed_volume(t);
    if whole.abs() <= f64::EPSILON * (t[1] - t[0]).length().powi(3) || !whole.is_finite() {
        return None;
    }
    Some(std::array::from_fn(|i| {
        let mut sub = t;
        sub[i] = x;
        signed_volume(sub) / whole
    }))
}

/// The point the figure weighs without a pixel (or when the pixel's ray misses the
/// tetrahedron): `0.4 A + 0.3 B + 0.2 C + 0.1 D`, inside, with four different weights.
pub const POINT_WEIGHTS: [f64; 4] = [0.4, 0.3, 0.2, 0.1];

/// A ray that only grazes the tetrahedron (an edge or a corner) is treated as a miss: the
/// part inside must be at least this share of the segment tested, so that X, halfway, is
/// clearly inside.
const MIN_INSIDE_SHARE: f64 = 1e-9;

/// The part of the segment from `from` to `to` inside tetrahedron `t`, as the parameters
/// `(s_in, s_out)`, `0 <= s_in < s_out <= 1`, of the points `from + s (to - from)` where it
/// enters and leaves. The volume weights are affine along the segment,
/// `λ(s) = λ(from) + s (λ(to) - λ(from))`, and each `λ_i(s) >= 0` bounds `s` on one side.
/// `None` when the segment misses (or only touches) the tetrahedron, or it is flat.
///
/// The unit tetrahedron (weights `1 - x - y - z, x, y, z`) and the segment from
/// (0.1, 0.1, -1) to (0.1, 0.1, 1), where `z = -1 + 2s`: inside while `z >= 0` and
/// `1 - 0.2 - z >= 0`, so `s` runs from 0.5 to 0.9.
/// ```
/// use barylab::figure::space::segment_inside;
/// use glam::DVec3;
/// let t = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
/// let (s_in, s_out) =
///     segment_inside(t, DVec3::new(0.1, 0.1, -1.0), DVec3::new(0.1, 0.1, 1.0)).unwrap();
/// assert!((s_in - 0.5).abs() < 1e-12 && (s_out - 0.9).abs() < 1e-12);
/// assert_eq!(segment_inside(t, DVec3::new(2.0, 2.0, -1.0), DVec3::new(2.0, 2.0, 1.0)), None);
/// ```
pub fn segment_inside(t: [DVec3; 4], from: DVec3, to: DVec3) -> Option<(f64, f64)> {
    let start = volume_weights(t, from)?;
    let end = volume_weights(t, to)?;
    let (mut s_in, mut s_out) = (0.0_f64, 1.0_f64);
    for (l0, l1) in start.into_iter().zip(end) {
        let d = l1 - l0;
        if d > 0.0 {
            s_in = s_in.max(-l0 / d);
        } else if d < 0.0 {
            s_out = s_out.min(-l0 / d);
        } else if l0 < 0.0 {
            return None;
        }
    }
    (s_out - s_in > MIN_INSIDE_SHARE).then_some((s_in, s_out))
}

/// Where a pixel's ray runs through the tetrahedron.
#[derive(Clone, Debug, PartialEq)]
pub struct RayThrough {
    /// The pixel, `[x, y]`.
    pub pixel: [u32; 2],
    /// Where the ray enters: on a face, so the opposite corner's weight is 0.
    pub entry: DVec3,
    /// The entry point's volume weights.
    pub entry_weights: [f64; 4],
    /// Where the ray leaves.
    pub exit: DVec3,
}

impl RayThrough {
    /// The ray of `space`'s pixel through the tetrahedron `corners`, if it crosses it.
    fn of(space: &SpaceScene, corners: [DVec3; 4]) -> Option<Self> {
        let ray = space.ray.as_ref()?;
        let (s_in, s_out) = segment_inside(corners, ray.origin, ray.end)?;
        let at = |s: f64| ray.origin + s * (ray.end - ray.origin);
        let entry = at(s_in);
        let mut entry_weights = volume_weights(corners, entry)?;
        // The weight that bounded the entry is 0 there (not a rounding residue of 1e-16).
        let face = (0..4)
            .min_by(|&i, &j| entry_weights[i].total_cmp(&entry_weights[j]))
            .unwrap_or(0);
        entry_weights[face] = 0.0;
        Some(Self {
            pixel: ray.pixel,
            entry,
            entry_weights,
            exit: at(s_out),
        })
    }

    /// The corner whose weight is 0 where the ray enters (the face it enters through is the
    /// other three).
    pub fn entry_face_opposite(&self) -> usize {
        (0..4).find(|&i| self.entry_weights[i] == 0.0).unwrap_or(0)
    }
}

/// Whether `space` is a tetrahedron: four vertices and the four triangles of its faces.
pub fn is_tetrahedron(space: &SpaceScene) -> bool {
    let mut faces: Vec<[usize; 3]> = space
        .triangles
        .iter()
        .map(|t| {
            let mut c = t.corners;
            c.sort_unstable();
            c
        })
        .collect();
    faces.sort_unstable();
    faces.dedup();
    space.vertices.len() == 4 && faces == [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
}

/// The corners' colours: A red, B green, C blue, D yellow (the scene's own).
const CORNER_COLOURS: [[u8; 3]; 4] = [[220, 40, 40], [30, 160, 60], [40, 80, 220], [220, 170, 0]];

/// The tetrahedron figure.
#[derive(Clone, Debug)]
pub struct TetraFigure<'a> {
    space: &'a SpaceScene,
    orbit: Orbit,
    lang: Lang,
    corners: [DVec3; 4],
    names: [String; 4],
    point: DVec3,
    weights: [f64; 4],
    ray: Option<RayThrough>,
}

impl<'a> TetraFigure<'a> {
    /// The figure of the first four vertices of `space`: the point X halfway along the part of
    /// the pixel's ray inside it (when `space` has a ray that crosses it), else the point with
    /// [`POINT_WEIGHTS`]; an error when the scene has fewer than four vertices or they are flat.
    pub fn new(space: &'a SpaceScene, orbit: Orbit, lang: Lang) -> Result<Self, String> {
        let not_tetra = || lang.tr("space.tetra.not_tetra");
        let v = space.vertices.get(..4).ok_or_else(not_tetra)?;
        let corners: [DVec3; 4] = std::array::from_fn(|i| v[i].point);
        let names = std::array::from_fn(|i| v[i].name.clone());
        let ray = RayThrough::of(space, corners);
        let point = match &ray {
            Some(r) => (r.entry + r.exit) / 2.0,
            None => (0..4).map(|i| corners[i] * POINT_WEIGHTS[i]).sum(),
        };
        let weights = volume_weights(corners, point).ok_or_else(not_tetra)?;
        Ok(Self {
            space,
            orbit,
            lang,
            corners,
            names,
            point,
            weights,
            ray,
        })
    }

    /// The volume weights of the point, `[λ_A, λ_B, λ_C, λ_D]`.
    pub fn weights(&self) -> [f64; 4] {
        self.weights
    }

    /// The point X weighed.
    pub fn point(&self) -> DVec3 {
        self.point
    }

    /// The pixel's ray through the tetrahedron, when it crosses it.
    pub fn ray(&self) -> Option<&RayThrough> {
        self.ray.as_ref()
    }

    /// The drawing fitted into `rect` (`[x0, y0, x1, y1]`), labels `label_size` points, in
    /// painter's order.
    /// `measure`: a label's size as the renderer draws it
    /// ([`draw::shapes`](super::draw::shapes)).
    pub fn shapes(
        &self,
        rect: [f32; 4],
        label_size: f32,
        measure: super::draw::Measure<'_>,
    ) -> Vec<Shape> {
        let mut pts = self.corners.to_vec();
        pts.push(self.point);
        let pr = super::Projector::new(self.orbit, &pts, rect);
        let p2 = |p: DVec3| pr.project(p);
        let ink = Colour([30, 30, 30, 255]);
        let text = |at: [f32; 2], s: String, colour: Colour| Shape {
            kind: ShapeKind::Text {
                at,
                text: s,
                size: label_size,
                colour,
                anchor: super::Anchor2::Start,
            },
            depth: 0.0,
        };
        let mut back = Vec::new();
        let (mut labels, mut weight_labels) = (Vec::new(), Vec::new());
        for (i, [r, g, b]) in CORNER_COLOURS.into_iter().enumerate() {
            let face: Vec<DVec3> = (0..4)
                .filter(|&j| j != i)
                .map(|j| self.corners[j])
                .collect();
            let projected: Vec<([f32; 2], f64)> = face.iter().map(|p| p2(*p)).collect();
            back.push(Shape {
                kind: ShapeKind::Polygon {
                    points: projected.iter().map(|p| p.0).collect(),
                    fill: Colour([r, g, b, 55]),
                    stroke: Some((ink, 1.5)),
                },
                depth: projected.iter().map(|p| p.1).sum::<f64>() / 3.0,
            });
        }
        back.sort_by(|a, b| b.depth.total_cmp(&a.depth));
        let x = p2(self.point).0;
        if let Some(r) = &self.ray {
            // The ray inside the tetrahedron, with a stub before it enters.
            let (entry, exit) = (p2(r.entry).0, p2(r.exit).0);
            let before = p2(r.entry - 0.35 * (r.exit - r.entry)).0;
            for (from, to, dashed) in [(before, entry, true), (entry, exit, false)] {
                back.push(Shape {
                    kind: ShapeKind::Line {
                        from,
                        to,
                        colour: RAY_COLOUR,
                        width: 2.0,
                        dashed,
                    },
                    depth: 0.0,
                });
            }
        }
        for (i, c) in self.corners.iter().enumerate() {
            let [r, g, b] = CORNER_COLOURS[i];
            let colour = Colour([r, g, b, 255]);
            let (at, _) = p2(*c);
            back.push(Shape {
                kind: ShapeKind::Line {
                    from: x,
                    to: at,
                    colour: ink,
                    width: 1.2,
                    dashed: true,
                },
                depth: 0.0,
            });
            back.push(Shape {
                kind: ShapeKind::Dot {
                    centre: at,
                    radius: 5.0,
                    fill: colour,
                    stroke: Some((ink, 1.0)),
                },
                depth: 0.0,
            });
            labels.push(text(
                [at[0] + 8.0, at[1] - 8.0],
                self.names[i].clone(),
                colour,
            ));
            // The weight at the centre of the sub-tetrahedron opposite this corner.
            let centre = (self.point
                + (0..4)
                    .filter(|&j| j != i)
                    .map(|j| self.corners[j])
                    .sum::<DVec3>())
                / 4.0;
            let (at, _) = p2(centre);
            weight_labels.push(text(
                at,
                format!("λ_{} = {}", self.names[i], fmt_number(self.weights[i])),
                colour,
            ));
        }
        back.push(Shape {
            kind: ShapeKind::Dot {
                centre: x,
                radius: 6.0,
                fill: super::draw::P_COLOUR,
                stroke: Some((ink, 1.0)),
            },
            depth: 0.0,
        });
        labels.push(text(
            [x[0] + 9.0, x[1] + 18.0],
            "X".to_string(),
            super::draw::P_COLOUR,
        ));
        if let Some(r) = &self.ray {
            let at = p2(r.entry).0;
            back.push(Shape {
                kind: ShapeKind::Dot {
                    centre: at,
                    radius: 5.0,
                    fill: RAY_COLOUR,
                    stroke: Some((ink, 1.0)),
                },
                depth: 0.0,
            });
            labels.push(text(
                [at[0] - 22.0, at[1] - 6.0],
                "P".to_string(),
                RAY_COLOUR,
            ));
        }
        // The names and marks first, then the weights, spread so that none covers another.
        labels.extend(weight_labels);
        super::labels::spread_labels(&mut labels, rect, measure);
        back.extend(labels);
        back
    }

    /// The numbers beside the drawing, each with its colour: the point, its four weights and
    /// their sum; with a ray, where it enters (one weight 0: the face's triangle weights).
    pub fn panel_lines(&self) -> Vec<(String, Colour)> {
        let ink = Colour([30, 30, 30, 255]);
        let lang = self.lang;
        let mut panel = Vec::new();
        match &self.ray {
            Some(r) => {
                let [x, y] = r.pixel;
                let (x, y) = (x.to_string(), y.to_string());
                let opposite = r.entry_face_opposite();
                let face = (0..4)
                    .filter(|&j| j != opposite)
                    .map(|j| self.names[j].as_str())
                    .collect::<Vec<_>>()
                    .join(" ");
                let entry = (0..4)
                    .map(|i| fmt_number(r.entry_weights[i]))
                    .collect::<Vec<_>>()
                    .join(", ");
                panel.push((
                    lang.tr_with("space.tetra.ray", &[("x", &x), ("y", &y)]),
                    RAY_COLOUR,
                ));
                panel.push((
                    lang.tr_with(
                        "space.tetra.entry",
                        &[
                            ("face", &face),
                            ("name", &self.names[opposite]),
                            ("w", &entry),
                        ],
                    ),
                    RAY_COLOUR,
                ));
                panel.push((lang.tr("space.tetra.halfway"), super::draw::P_COLOUR));
            }
            None => panel.push((lang.tr("space.tetra.point"), super::draw::P_COLOUR)),
        }
        let face = |i: usize| -> String {
            (0..4)
                .filter(|&j| j != i)
                .map(|j| self.names[j].as_str())
                .collect()
        };
        for (i, [r, g, b]) in CORNER_COLOURS.into_iter().enumerate() {
            panel.push((
                lang.tr_with(
                    "space.tetra.weight",
                    &[
                        ("name", &self.names[i]),
                        ("v", &fmt_number(self.weights[i])),
                        ("face", &face(i)),
                        ("all", &self.names.concat()),
                    ],
                ),
                Colour([r, g, b, 255]),
            ));
        }
        let sum: f64 = self.weights.iter().sum();
        panel.push((
            lang.tr_with("space.tetra.sum", &[("sum", &fmt_number(sum))]),
            ink,
        ));
        if matches!(self.space.lens, super::Lens::ClipW { .. }) {
            panel.push((lang.tr("space.clip_scene"), ink));
        }
        panel
    }

    /// The figure as an SVG document.
    pub fn to_svg(&self) -> String {
        document(
            &self.lang.tr("space.tetra.title"),
            &self.shapes(drawing_rect(), LABEL_SIZE, &super::draw::svg_measure),
            &self.panel_lines(),
            self.lang,
        )
    }

    /// The figure as PNG file bytes, `scale` pixels per point.
    pub fn to_png(&self, scale: f32) -> Result<Vec<u8>, FigureError> {
        crate::figure::png::encode(&rasterize_svg(&self.to_svg(), self.lang, scale)?)
    }
}
