//! Exact-pixel golden tests of the fill rule: shapes whose edges pass exactly through pixel
//! centres. Samples on left and bottom edges are covered, on top and right edges not.

mod common;

use barylab::raster::render::ClipMesh;
use barylab::raster::setup::Facing;
use common::*;

const W: u32 = 16;
const H: u32 = 16;

fn quad(points: [(f64, f64); 4], w: [f64; 4]) -> ClipMesh {
    ClipMesh {
        vertices: points
            .iter()
            .zip(w)
            .map(|(&(x, y), w)| at_window(x, y, w, W, H))
            .collect(),
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    }
}

#[test]
fn square_on_pixel_centres_covers_left_and_bottom_edges_only() {
    // Corners on the centres of pixels (2,2), (6,2), (6,6), (2,6).
    let mesh = quad([(2.5, 2.5), (6.5, 2.5), (6.5, 6.5), (2.5, 6.5)], [1.0; 4]);
    let expected = art("
        ................
        ................
        ................
        ..####..........
        ..####..........
        ..####..........
        ..####..........
        ................
        ................
        ................
        ................
        ................
        ................
        ................
        ................
        ................");
    assert_eq!(coverage_art(&draw(&mesh, W, H)), expected);
    // The diagonal (2.5,2.5)-(6.5,6.5) passes through 4 of these centres: each exactly once.
    assert!(coverage_counts(&mesh, W, H).iter().all(|&c| c <= 1));
}

#[test]
fn square_rule_is_the_same_for_both_windings_and_any_w() {
    let ccw = quad(
        [(2.5, 2.5), (6.5, 2.5), (6.5, 6.5), (2.5, 6.5)],
        [1.0, 2.0, 4.0, 3.0],
    );
    let cw = quad(
        [(2.5, 2.5), (2.5, 6.5), (6.5, 6.5), (6.5, 2.5)],
        [1.0, 3.0, 4.0, 2.0],
    );
    let a = draw(&ccw, W, H);
    let b = draw(&cw, W, H);
    assert_eq!(coverage_art(&a), coverage_art(&b));
    // A->B->C going right then down is clockwise on screen: the back face in OpenGL.
    assert_eq!(a.triangles[0].facing(), Some(Facing::Back));
    assert_eq!(b.triangles[0].facing(), Some(Facing::Front));
}

#[test]
fn diamond_on_pixel_centres() {
    // Vertices on pixel centres, every edge at 45 degrees through centres.
    let top = (8.5, 5.5);
    let right = (11.5, 8.5);
    let bottom = (8.5, 11.5);
    let left = (5.5, 8.5);
    // Split along the horizontal diagonal: upper triangle owns it (bottom edge, inclusive).
    let mesh = ClipMesh {
        vertices: [left, top, right, bottom]
            .iter()
            .map(|&(x, y)| at_window(x, y, 1.0, W, H))
            .collect(),
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    };
    let expected = art("
        ................
        ................
        ................
        ................
        ................
        ................
        .......##.......
        ......####......
        .....######.....
        ......####......
        .......##.......
        ................
        ................
        ................
        ................
        ................");
    let r = draw(&mesh, W, H);
    assert_eq!(coverage_art(&r), expected);
    // 18 pixels = the diamond's area, each covered once.
    let counts = coverage_counts(&mesh, W, H);
    assert_eq!(counts.iter().sum::<u32>(), 18);
    assert!(counts.iter().all(|&c| c <= 1));
    // The horizontal diagonal's row (y = 8.5) belongs to the upper triangle.
    for x in 5..=10 {
        assert_eq!(r.frame.triangle[r.frame.index(x, 8)], 0, "pixel ({x}, 8)");
    }
}

#[test]
fn thin_sliver_and_zero_area_triangles() {
    // A zero-area triangle (collinear) draws nothing and creates no NaN.
    let mesh = ClipMesh {
        vertices: [(1.0, 1.0), (5.0, 5.0), (9.0, 9.0)]
            .iter()
            .map(|&(x, y)| at_window(x, y, 1.0, W, H))
            .collect(),
        triangles: vec![[0, 1, 2]],
    };
    let r = draw(&mesh, W, H);
    assert!(
        r.frame
            .triangle
            .iter()
            .all(|&t| t == barylab::raster::NO_TRIANGLE)
    );
    assert_eq!(
        r.triangles[0].status,
        barylab::raster::render::TriangleStatus::Empty
    );
    // A triangle narrower than a pixel that contains no centre covers nothing.
    let mesh = ClipMesh {
        vertices: [(3.1, 1.0), (3.4, 1.0), (3.2, 9.0)]
            .iter()
            .map(|&(x, y)| at_window(x, y, 1.0, W, H))
            .collect(),
        triangles: vec![[0, 1, 2]],
    };
    assert!(
        draw(&mesh, W, H)
            .frame
            .triangle
            .iter()
            .all(|&t| t == barylab::raster::NO_TRIANGLE)
    );
}

#[test]
fn vertical_edge_through_centres_splits_pixels_exactly() {
    // Two rectangles side by side sharing the vertical edge x = 4.5: its centres go to the
    // right-hand rectangle (for which it is a left edge).
    let left = quad([(1.5, 1.5), (4.5, 1.5), (4.5, 4.5), (1.5, 4.5)], [1.0; 4]);
    let right = quad([(4.5, 1.5), (7.5, 1.5), (7.5, 4.5), (4.5, 4.5)], [1.0; 4]);
    let mut mesh = left.clone();
    let base = mesh.vertices.len() as u32;
    mesh.vertices.extend(right.vertices);
    mesh.triangles
        .extend(right.triangles.iter().map(|t| t.map(|i| i + base)));
    let r = draw(&mesh, W, H);
    for y in 2..=4 {
        assert_eq!(
            r.frame.triangle[r.frame.index(4, y)] / 2,
            1,
            "pixel (4, {y})"
        );
        assert_eq!(
            r.frame.triangle[r.frame.index(1, y)] / 2,
            0,
            "pixel (1, {y})"
        );
        assert!(!r.frame.covered(7, y));
    }
    assert!(coverage_counts(&mesh, W, H).iter().all(|&c| c <= 1));
}
