//! Tetrahedron (volume) coordinates: a point X inside a tetrahedron ABCD is
//! `X = λ_A A + λ_B B + λ_C C + λ_D D` with `λ_A + λ_B + λ_C + λ_D = 1`, each weight the ratio
//! of a sub-tetrahedron's signed volume to the whole one's: `λ_A = V(X, B, C, D) / V(A, B, C,
//! D)`, ..., `V(P0, P1, P2, P3) = (P1 - P0) . ((P2 - P0) x (P3 - P0)) / 6`. The figure draws
//! the four sub-tetrahedra (X joined to each face), each face tinted with the colour of the
//! vertex opposite it, and its weight beside it.

use glam::DVec3;

use super::draw::{Colour, Shape, ShapeKind};
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

/// The point the figure weighs: `0.4 A + 0.3 B + 0.2 C + 0.1 D`, inside, with four different
/// weights.
pub const POINT_WEIGHTS: [f64; 4] = [0.4, 0.3, 0.2, 0.1];

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
}

impl<'a> TetraFigure<'a> {
    /// The figure of the first four vertices of `space` and the point with
    /// [`POINT_WEIGHTS`]; an error when the scene has fewer than four vertices or they are flat.
    pub fn new(space: &'a SpaceScene, orbit: Orbit, lang: Lang) -> Result<Self, String> {
        let not_tetra = || lang.tr("space.tetra.not_tetra");
        let v = space.vertices.get(..4).ok_or_else(not_tetra)?;
        let corners: [DVec3; 4] = std::array::from_fn(|i| v[i].point);
        let names = std::array::from_fn(|i| v[i].name.clone());
        let point = (0..4).map(|i| corners[i] * POINT_WEIGHTS[i]).sum();
        let weights = volume_weights(corners, point).ok_or_else(not_tetra)?;
        Ok(Self {
            space,
            orbit,
            lang,
            corners,
            names,
            point,
            weights,
        })
    }

    /// The volume weights of the point, `[λ_A, λ_B, λ_C, λ_D]`.
    pub fn weights(&self) -> [f64; 4] {
        self.weights
    }

    fn shapes(&self) -> Vec<Shape> {
        let mut pts = self.corners.to_vec();
        pts.push(self.point);
        let pr = super::Projector::new(self.orbit, &pts, drawing_rect());
        let p2 = |p: DVec3| pr.project(p);
        let ink = Colour([30, 30, 30, 255]);
        let text = |at: [f32; 2], s: String, colour: Colour| Shape {
            kind: ShapeKind::Text {
                at,
                text: s,
                size: LABEL_SIZE,
                colour,
                anchor: super::Anchor2::Start,
            },
            depth: 0.0,
        };
        let mut back = Vec::new();
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
            back.push(text(
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
            back.push(text(
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
        back.push(text(
            [x[0] + 9.0, x[1] + 18.0],
            "X".to_string(),
            super::draw::P_COLOUR,
        ));
        back
    }

    /// The figure as an SVG document.
    pub fn to_svg(&self) -> String {
        let ink = Colour([30, 30, 30, 255]);
        let mut panel = vec![(self.lang.tr("space.tetra.point"), super::draw::P_COLOUR)];
        let face = |i: usize| -> String {
            (0..4)
                .filter(|&j| j != i)
                .map(|j| self.names[j].as_str())
                .collect()
        };
        for (i, [r, g, b]) in CORNER_COLOURS.into_iter().enumerate() {
            panel.push((
                self.lang.tr_with(
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
            self.lang
                .tr_with("space.tetra.sum", &[("sum", &fmt_number(sum))]),
            ink,
        ));
        if matches!(self.space.lens, super::Lens::ClipW { .. }) {
            panel.push((self.lang.tr("space.clip_scene"), ink));
        }
        document(
            &self.lang.tr("space.tetra.title"),
            &self.shapes(),
            &panel,
            self.lang,
        )
    }

    /// The figure as PNG file bytes, `scale` pixels per point.
    pub fn to_png(&self, scale: f32) -> Result<Vec<u8>, FigureError> {
        crate::figure::png::encode(&rasterize_svg(&self.to_svg(), self.lang, scale)?)
    }
}
