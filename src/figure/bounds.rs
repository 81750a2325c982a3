//! Overlay geometry cut to a box around the image before it is drawn: a vertex near w = 0
//! projects to coordinates like 1e16 (or to infinity), which the SVG rasterizer cannot draw.
//! What shows on the image is unchanged: polygons and lines are clipped exactly (in f64), and
//! marks far off the image, or at non-finite positions, are left out.

use glam::DVec2;

use super::overlay::{Overlay, Shape};

/// Canvas pixels kept on each side of the image, in image sizes (the larger side): far more
/// than any stroke or label reaches into the image from outside, small enough for the
/// rasterizer's fixed-point arithmetic at every pixel size and scale.
pub const MARGIN_IN_IMAGE_SIZES: f64 = 2.0;

/// `overlay` with its geometry cut to the box around a `canvas`-sized image (see the module).
pub fn bounded(overlay: &Overlay, canvas: [u32; 2]) -> Overlay {
    let side = f64::from(canvas[0].max(canvas[1]).max(1));
    let margin = MARGIN_IN_IMAGE_SIZES * side;
    let lo = DVec2::splat(-margin);
    let hi = DVec2::new(f64::from(canvas[0]), f64::from(canvas[1])) + margin;
    let inside = |p: DVec2| p.is_finite() && p.cmpge(lo).all() && p.cmple(hi).all();
    let mut shapes = Vec::with_capacity(overlay.shapes.len());
    for shape in &overlay.shapes {
        match shape {
            Shape::Polygon { points, .. } if !points.iter().all(|p| inside(*p)) => {
                if !points.iter().all(|p| p.is_finite()) {
                    continue;
                }
                let cut = clip_polygon(points, lo, hi);
                if cut.len() >= 3 {
                    let mut s = shape.clone();
                    if let Shape::Polygon { points, .. } = &mut s {
                        *points = cut;
                    }
                    shapes.push(s);
                }
            }
            Shape::Line { points, .. } if !points.iter().all(|p| inside(*p)) => {
                for piece in clip_polyline(points, lo, hi) {
                    let mut s = shape.clone();
                    if let Shape::Line { points, .. } = &mut s {
                        *points = piece;
                    }
                    shapes.push(s);
                }
            }
            Shape::Rect { min, max, .. } => {
                if min.is_finite() && max.is_finite() {
                    let mut s = shape.clone();
                    if let Shape::Rect { min, max, .. } = &mut s {
                        (*min, *max) = (min.clamp(lo, hi), max.clamp(lo, hi));
                    }
                    shapes.push(s);
                }
            }
            Shape::Circle { centre: at, .. }
            | Shape::Text { at, .. }
            | Shape::HandleLabel { at, .. }
            | Shape::LabelPair { at, .. }
            | Shape::ColorBar { at, .. }
                if !inside(*at) => {}
            _ => shapes.push(shape.clone()),
        }
    }
    Overlay { shapes }
}

/// The polygon cut to the box `[lo, hi]` (Sutherland-Hodgman, one box side at a time).
/// The points must be finite.
pub fn clip_polygon(points: &[DVec2], lo: DVec2, hi: DVec2) -> Vec<DVec2> {
    // Each side as (axis, bound, keep the side where the coordinate is >= bound?).
    let sides = [
        (0, lo.x, true),
        (0, hi.x, false),
        (1, lo.y, true),
        (1, hi.y, false),
    ];
    let mut poly = points.to_vec();
    for (axis, bound, above) in sides {
        let keep = |p: DVec2| {
            if above {
                p[axis] >= bound
            } else {
                p[axis] <= bound
            }
        };
        let mut out = Vec::with_capacity(poly.len() + 2);
        for (i, &a) in poly.iter().enumerate() {
            let b = poly[(i + 1) % poly.len()];
            if keep(a) {
                out.push(a);
            }
            if keep(a) != keep(b) {
                out.push(on_side(a, b, axis, bound));
            }
        }
        poly = out;
        if poly.is_empty() {
            break;
        }
    }
    poly
}

/// Where segment a-b crosses the line `p[axis] = bound` (which it must cross). Measured from
/// the end nearer the line: from a point at 1e20 the crossing would lose every digit.
fn on_side(a: DVec2, b: DVec2, axis: usize, bound: f64) -> DVec2 {
    let (p, q) = if (a[axis] - bound).abs() <= (b[axis] - bound).abs() {
        (a, b)
    } else {
        (b, a)
    };
    let s = (bound - p[axis]) / (q[axis] - p[axis]);
    let mut r = p + (q - p) * s;
    r[axis] = bound;
    r
}

/// The open polyline cut to the box `[lo, hi]`: the pieces inside, each at least two points
/// (Liang-Barsky on each segment). Segments with a non-finite end are left out.
pub fn clip_polyline(points: &[DVec2], lo: DVec2, hi: DVec2) -> Vec<Vec<DVec2>> {
    let mut pieces: Vec<Vec<DVec2>> = Vec::new();
    let mut current: Vec<DVec2> = Vec::new();
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        match clip_segment(a, b, lo, hi) {
            Some((p, q)) => {
                if current.last() != Some(&p) {
                    if current.len() >= 2 {
                        pieces.push(std::mem::take(&mut current));
                    }
                    current = vec![p];
                }
                current.push(q);
                if q != b {
                    pieces.push(std::mem::take(&mut current));
                }
            }
            None => {
                if current.len() >= 2 {
                    pieces.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() >= 2 {
        pieces.push(current);
    }
    pieces
}

/// The part of segment a-b inside the box, if any (Liang-Barsky; the cut ends are found with
/// [`on_side`]).
fn clip_segment(a: DVec2, b: DVec2, lo: DVec2, hi: DVec2) -> Option<(DVec2, DVec2)> {
    if !(a.is_finite() && b.is_finite()) {
        return None;
    }
    let d = b - a;
    // Entering and leaving parameters, with the side (axis, bound) that set them.
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let (mut enter, mut leave) = (None, None);
    for (p, q, side) in [
        (-d.x, a.x - lo.x, (0, lo.x)),
        (d.x, hi.x - a.x, (0, hi.x)),
        (-d.y, a.y - lo.y, (1, lo.y)),
        (d.y, hi.y - a.y, (1, hi.y)),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 && r > t0 {
                (t0, enter) = (r, Some(side));
            } else if p > 0.0 && r < t1 {
                (t1, leave) = (r, Some(side));
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |side: Option<(usize, f64)>, end: DVec2| match side {
        Some((axis, bound)) => on_side(a, b, axis, bound),
        None => end,
    };
    Some((at(enter, a), at(leave, b)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_far_triangle_is_cut_to_the_box_and_keeps_its_edge_through_the_image() {
        let (lo, hi) = (DVec2::splat(-10.0), DVec2::splat(20.0));
        let far = DVec2::new(5.0, -3.6e16);
        let cut = clip_polygon(&[DVec2::new(0.0, 5.0), DVec2::new(10.0, 5.0), far], lo, hi);
        assert_eq!(cut.len(), 4, "{cut:?}");
        assert!(cut.iter().all(|p| p.cmpge(lo).all() && p.cmple(hi).all()));
        // The edges keep their direction: the cut points lie on the original edges.
        assert!(
            cut.iter()
                .any(|p| p.y == -10.0 && (p.x - 5.0 / 3.6e16 * 15.0).abs() < 1e-6)
        );
    }

    #[test]
    fn a_line_leaving_the_box_is_cut_into_pieces_inside() {
        let (lo, hi) = (DVec2::ZERO, DVec2::splat(10.0));
        let pts = [
            DVec2::new(1.0, 1.0),
            DVec2::new(1.0, 1e20),
            DVec2::new(5.0, 5.0),
            DVec2::new(6.0, 6.0),
            DVec2::new(f64::NAN, 0.0),
        ];
        let pieces = clip_polyline(&pts, lo, hi);
        assert_eq!(pieces.len(), 2, "{pieces:?}");
        assert_eq!(pieces[0], [DVec2::new(1.0, 1.0), DVec2::new(1.0, 10.0)]);
        let second = &pieces[1];
        assert_eq!(second.len(), 3, "{second:?}");
        assert!(
            second[0].y == 10.0 && (second[0].x - 5.0).abs() < 1e-9,
            "{second:?}"
        );
        assert_eq!(second[1..], [DVec2::new(5.0, 5.0), DVec2::new(6.0, 6.0)]);
    }
}
