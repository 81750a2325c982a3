//! The magnifier: a pixel and its neighbours enlarged, for the back rows of a lecture hall.
//! Plain shapes in canvas coordinates, drawn over the image enlarged so that
//! `2 * radius + 1` pixels fill the magnifier: the pixel grid, every pixel's sample point
//! (its centre, where the rasterizer tests coverage and interpolates), the marked pixel's
//! outline and sample, and the edges of the triangle its weights refer to. With several
//! samples per pixel, every sample point of every pixel shown ([`SampleMark`]): filled in its
//! triangle's colour when covered, hollow when not.

use glam::DVec2;

use super::shape::{Overlay, Shape, Stroke};
use super::style::{PIN, Rgba, SAMPLE_DOT, SHADOW};
use super::{TriangleMark, centre_of};

/// Pixels shown on each side of the marked one: 7 x 7 pixels in all, enough to see the
/// neighbours on both sides of an edge and large enough to read from the back of a room.
pub const MAGNIFIER_RADIUS: u32 = 3;

/// With several samples a pixel, 5 x 5 pixels: each pixel's cell is then large enough that
/// its four sample marks (and the neighbours' across a pixel border, 0.35 pixel apart in the
/// GL's standard pattern) keep apart at a projector's 1024 x 768; at 7 x 7 they touched.
pub const MAGNIFIER_RADIUS_SAMPLES: u32 = 2;

/// Pixels shown on each side of the marked one: [`MAGNIFIER_RADIUS`] for one sample a pixel,
/// [`MAGNIFIER_RADIUS_SAMPLES`] when `multisampled`.
///
/// ```
/// use barylab::figure::overlay::magnifier_radius;
/// assert_eq!((magnifier_radius(false), magnifier_radius(true)), (3, 2));
/// ```
pub fn magnifier_radius(multisampled: bool) -> u32 {
    if multisampled {
        MAGNIFIER_RADIUS_SAMPLES
    } else {
        MAGNIFIER_RADIUS
    }
}

/// Grid lines between the enlarged pixels: dark with a light edge, visible on any colour.
const GRID_LINES: [Stroke; 2] = [
    Stroke::new(2.0, [0, 0, 0, 150]),
    Stroke::new(1.0, [255, 255, 255, 70]),
];

/// One sample of a pixel in the magnifier: where it lies and which triangle kept it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleMark {
    /// Window position in pixels (y down, pixel corners at integers).
    pub position: DVec2,
    /// The source triangle whose fragment the sample kept; `None` when none covers it.
    pub triangle: Option<u32>,
}

/// Colours of the sample marks by triangle (source triangle index modulo the list): light,
/// saturated and apart from each other, each drawn with a dark outline.
const TRIANGLE_COLORS: [Rgba; 8] = [
    [255, 200, 40, 255],
    [80, 200, 255, 255],
    [120, 230, 100, 255],
    [255, 110, 200, 255],
    [190, 150, 255, 255],
    [255, 140, 70, 255],
    [60, 230, 200, 255],
    [240, 240, 120, 255],
];

/// The colour of triangle `t`'s sample marks.
///
/// ```
/// use barylab::figure::overlay::sample_color;
/// assert_eq!(sample_color(0), sample_color(8));
/// assert_ne!(sample_color(0), sample_color(1));
/// ```
pub fn sample_color(t: u32) -> Rgba {
    TRIANGLE_COLORS[t as usize % TRIANGLE_COLORS.len()]
}

/// Radius in points of a sample mark.
pub const SAMPLE_MARK_RADIUS: f32 = 5.0;

/// The canvas rectangle the magnifier around `pixel` shows: `2 * radius + 1` pixels on a side
/// centred on it (it may reach past the image's edges; nothing is drawn there).
///
/// ```
/// use barylab::figure::overlay::magnified_rect;
/// let (min, max) = magnified_rect([10, 0], 3);
/// assert_eq!((min.x, min.y, max.x, max.y), (7.0, -3.0, 14.0, 4.0));
/// ```
pub fn magnified_rect(pixel: [u32; 2], radius: u32) -> (DVec2, DVec2) {
    let r = f64::from(radius);
    let c = centre_of(pixel);
    let half = r + 0.5;
    (c - DVec2::splat(half), c + DVec2::splat(half))
}

/// The magnifier's shapes around `pixel` of a `size[0] x size[1]` image: the grid lines and
/// sample points of the pixels within `radius` that lie in the image, the triangle's edges
/// (unsnapped window positions, as the overlay draws them), and the marked pixel's outline
/// and sample point in the pin's colour; then `samples` (every sample of the pixels shown,
/// when there are several per pixel): filled in their triangle's [`sample_color`] when
/// covered, hollow when not, drawn last so that none is hidden.
pub fn magnifier(
    pixel: [u32; 2],
    triangle: Option<&TriangleMark>,
    size: [u32; 2],
    radius: u32,
    samples: &[SampleMark],
) -> Overlay {
    let mut shapes = Vec::new();
    let (lo, hi) = magnified_rect(pixel, radius);
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    // The part of the enlarged square that lies in the image, in whole pixels.
    let x0 = lo.x.max(0.0);
    let y0 = lo.y.max(0.0);
    let x1 = hi.x.min(w);
    let y1 = hi.y.min(h);
    if x0 < x1 && y0 < y1 {
        for stroke in GRID_LINES {
            let mut x = x0;
            while x <= x1 {
                shapes.push(Shape::Line {
                    points: vec![DVec2::new(x, y0), DVec2::new(x, y1)],
                    stroke,
                    dashed: false,
                });
                x += 1.0;
            }
            let mut y = y0;
            while y <= y1 {
                shapes.push(Shape::Line {
                    points: vec![DVec2::new(x0, y), DVec2::new(x1, y)],
                    stroke,
                    dashed: false,
                });
                y += 1.0;
            }
        }
    }
    if let Some(t) = triangle {
        let mut points = t.vertices.to_vec();
        points.push(t.vertices[0]);
        for (width, color) in [(5.0, SHADOW), (2.5, [255, 255, 255, 235])] {
            shapes.push(Shape::Line {
                points: points.clone(),
                stroke: Stroke::new(width, color),
                dashed: false,
            });
        }
    }
    let mut y = y0;
    while y < y1 {
        let mut x = x0;
        while x < x1 {
            let c = DVec2::new(x + 0.5, y + 0.5);
            shapes.push(Shape::Circle {
                centre: c,
                radius: 3.0,
                fill: SAMPLE_DOT,
                stroke: Some(Stroke::new(1.0, SHADOW)),
            });
            x += 1.0;
        }
        y += 1.0;
    }
    let (px, py) = (f64::from(pixel[0]), f64::from(pixel[1]));
    for (width, color) in [(6.0, SHADOW), (3.0, PIN)] {
        shapes.push(Shape::Rect {
            min: DVec2::new(px, py),
            max: DVec2::new(px + 1.0, py + 1.0),
            fill: [0, 0, 0, 0],
            stroke: Some(Stroke::new(width, color)),
        });
    }
    shapes.push(Shape::Circle {
        centre: centre_of(pixel),
        radius: if samples.is_empty() { 6.0 } else { 3.5 },
        fill: PIN,
        stroke: Some(Stroke::new(2.0, SHADOW)),
    });
    let inside = |p: DVec2| p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
    for s in samples.iter().filter(|s| inside(s.position)) {
        shapes.push(match s.triangle {
            Some(t) => Shape::Circle {
                centre: s.position,
                radius: SAMPLE_MARK_RADIUS,
                fill: sample_color(t),
                stroke: Some(Stroke::new(1.5, SHADOW)),
            },
            None => Shape::Circle {
                centre: s.position,
                radius: SAMPLE_MARK_RADIUS,
                fill: [0, 0, 0, 0],
                stroke: Some(Stroke::new(2.0, [235, 235, 235, 230])),
            },
        });
    }
    Overlay { shapes }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circles(o: &Overlay) -> Vec<DVec2> {
        o.shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Circle { centre, .. } => Some(*centre),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn every_pixel_in_the_square_has_its_sample_point_and_the_marked_one_is_last() {
        let o = magnifier([5, 5], None, [20, 20], 3, &[]);
        let c = circles(&o);
        // 49 sample points and the marked pixel's own.
        assert_eq!(c.len(), 50);
        assert_eq!(c[0], DVec2::new(2.5, 2.5));
        assert_eq!(c[48], DVec2::new(8.5, 8.5));
        assert_eq!(c[49], DVec2::new(5.5, 5.5));
    }

    #[test]
    fn at_the_image_corner_only_pixels_of_the_image_are_drawn() {
        let o = magnifier([0, 0], None, [20, 20], 3, &[]);
        let c = circles(&o);
        // 4 x 4 pixels of the 7 x 7 square lie in the image, and the marked one again.
        assert_eq!(c.len(), 17);
        assert!(
            c.iter()
                .all(|p| p.x > 0.0 && p.y > 0.0 && p.x < 4.0 && p.y < 4.0)
        );
        // Grid lines from 0 to 4 (5 each way), twice (dark and light).
        let lines = o
            .shapes
            .iter()
            .filter(|s| matches!(s, Shape::Line { .. }))
            .count();
        assert_eq!(lines, 2 * (5 + 5));
    }

    #[test]
    fn the_triangle_edges_are_a_closed_line_through_its_corners() {
        let t = TriangleMark {
            vertices: [
                DVec2::new(1.0, 1.0),
                DVec2::new(9.0, 2.0),
                DVec2::new(4.0, 8.0),
            ],
            mesh_indices: [Some(0), Some(1), Some(2)],
            weights: [0.2, 0.3, 0.5],
        };
        let o = magnifier([4, 4], Some(&t), [10, 10], 3, &[]);
        let edges: Vec<&Vec<DVec2>> = o
            .shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Line { points, .. } if points.len() == 4 => Some(points),
                _ => None,
            })
            .collect();
        assert_eq!(edges.len(), 2);
        assert_eq!(edges[0].first(), edges[0].last());
        assert_eq!(edges[0][1], DVec2::new(9.0, 2.0));
    }

    #[test]
    fn every_sample_is_drawn_filled_by_its_triangle_or_hollow() {
        // Pixel (5, 5) with four samples: two covered by triangle 2, two by none; one more
        // sample outside the square (pixel 12) is not drawn.
        let at = |x: f64, y: f64, t: Option<u32>| SampleMark {
            position: DVec2::new(x, y),
            triangle: t,
        };
        let samples = [
            at(5.375, 5.875, Some(2)),
            at(5.875, 5.625, Some(2)),
            at(5.125, 5.375, None),
            at(5.625, 5.125, None),
            at(12.5, 5.5, Some(1)),
        ];
        let o = magnifier([5, 5], None, [20, 20], 3, &samples);
        let marks: Vec<(DVec2, Rgba, bool)> = o
            .shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Circle {
                    centre,
                    radius,
                    fill,
                    stroke,
                } if *radius == SAMPLE_MARK_RADIUS => Some((*centre, *fill, stroke.is_some())),
                _ => None,
            })
            .collect();
        assert_eq!(marks.len(), 4, "{marks:?}");
        assert_eq!(marks[0], (DVec2::new(5.375, 5.875), sample_color(2), true));
        assert_eq!(marks[1].1, sample_color(2));
        // Hollow: no fill, an outline.
        assert_eq!(marks[2], (DVec2::new(5.125, 5.375), [0, 0, 0, 0], true));
        assert_eq!(marks[3].1, [0, 0, 0, 0]);
        // Drawn after everything else.
        let last = o.shapes.len() - 4;
        assert!(
            matches!(o.shapes[last], Shape::Circle { radius, .. } if radius == SAMPLE_MARK_RADIUS)
        );
    }
}
