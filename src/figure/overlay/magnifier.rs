//! The magnifier: a pixel and its neighbours enlarged, for the back rows of a lecture hall.
//! Plain shapes in canvas coordinates, drawn over the image enlarged so that
//! `2 * radius + 1` pixels fill the magnifier: the pixel grid, every pixel's sample point
//! (its centre, where the rasterizer tests coverage and interpolates), the marked pixel's
//! outline and sample, and the edges of the triangle its weights refer to.

use glam::DVec2;

use super::shape::{Overlay, Shape, Stroke};
use super::style::{PIN, SAMPLE_DOT, SHADOW};
use super::{TriangleMark, centre_of};

/// Pixels shown on each side of the marked one: 7 x 7 pixels in all, enough to see the
/// neighbours on both sides of an edge and large enough to read from the back of a room.
pub const MAGNIFIER_RADIUS: u32 = 3;

/// Grid lines between the enlarged pixels: dark with a light edge, visible on any colour.
const GRID_LINES: [Stroke; 2] = [
    Stroke::new(2.0, [0, 0, 0, 150]),
    Stroke::new(1.0, [255, 255, 255, 70]),
];

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
/// and sample point in the pin's colour, drawn last.
pub fn magnifier(
    pixel: [u32; 2],
    triangle: Option<&TriangleMark>,
    size: [u32; 2],
    radius: u32,
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
        radius: 6.0,
        fill: PIN,
        stroke: Some(Stroke::new(2.0, SHADOW)),
    });
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
        let o = magnifier([5, 5], None, [20, 20], 3);
        let c = circles(&o);
        // 49 sample points and the marked pixel's own.
        assert_eq!(c.len(), 50);
        assert_eq!(c[0], DVec2::new(2.5, 2.5));
        assert_eq!(c[48], DVec2::new(8.5, 8.5));
        assert_eq!(c[49], DVec2::new(5.5, 5.5));
    }

    #[test]
    fn at_the_image_corner_only_pixels_of_the_image_are_drawn() {
        let o = magnifier([0, 0], None, [20, 20], 3);
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
        let o = magnifier([4, 4], Some(&t), [10, 10], 3);
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
}
