//! Samples per pixel: coverage at every sample against a hand-written edge test, the
//! resolve, MSAA and supersampling, centre / centroid / sample locations (with the exact
//! perspective value there), `flat` and the provoking vertex, and one sample drawn through the
//! sample path giving the single-sample render pixel for pixel.

mod common;

use barylab::raster::render::{ClipMesh, RenderSettings, render, render_samples};
use barylab::raster::sample::{
    Location, ProvokingVertex, SampleCount, SamplePattern, SampleSettings, ShadingRate,
};
use barylab::raster::{NO_TRIANGLE, Shading, Texture};
use common::*;
use glam::Vec3;

const W: u32 = 12;
const H: u32 = 10;

fn white() -> Texture {
    Texture::from_texels(1, 1, vec![[255; 4]]).expect("1x1 texture")
}

fn mesh(points: &[(f64, f64, f64)], triangles: Vec<[u32; 3]>) -> ClipMesh {
    ClipMesh {
        vertices: points
            .iter()
            .map(|&(x, y, w)| at_window(x, y, w, W, H))
            .collect(),
        triangles,
    }
}

fn with(samples: SampleSettings) -> RenderSettings {
    RenderSettings {
        samples,
        ..settings(W, H)
    }
}

fn count(count: SampleCount, pattern: SamplePattern) -> SampleSettings {
    SampleSettings {
        count,
        pattern,
        ..SampleSettings::default()
    }
}

/// The sample positions in a pixel, written out by hand (pixels, image rows, y down).
fn hand_positions(c: SampleCount, p: SamplePattern) -> Vec<(f64, f64)> {
    match (c, p) {
        // llvmpipe's GL_SAMPLE_POSITION (y up) flipped: y' = 1 - y.
        (SampleCount::Four, SamplePattern::Standard) => {
            vec![
                (0.375, 0.875),
                (0.875, 0.625),
                (0.125, 0.375),
                (0.625, 0.125),
            ]
        }
        (SampleCount::Four, SamplePattern::Grid) => {
            vec![(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)]
        }
        (SampleCount::Eight, _) => [
            (9, 5),
            (7, 11),
            (13, 9),
            (5, 3),
            (3, 13),
            (1, 7),
            (11, 15),
            (15, 1),
        ]
        .iter()
        .map(|&(x, y)| (f64::from(x) / 16.0, 1.0 - f64::from(y) / 16.0))
        .collect(),
        _ => vec![(0.5, 0.5)],
    }
}

/// Whether a point is covered by the triangle (window positions, y down) under llvmpipe's
/// rule, written independently: orient the corners clockwise on screen, then a point is
/// inside when every cross product `d x (p - s)` is positive, or zero on an edge going up
/// the image (a left edge) or going left along a row (a bottom edge).
fn inside(t: [(f64, f64); 3], p: (f64, f64)) -> bool {
    let area = (t[1].0 - t[0].0) * (t[2].1 - t[0].1) - (t[1].1 - t[0].1) * (t[2].0 - t[0].0);
    let t = if area > 0.0 { t } else { [t[0], t[2], t[1]] };
    (0..3).all(|i| {
        let (s, e) = (t[i], t[(i + 1) % 3]);
        let d = (e.0 - s.0, e.1 - s.1);
        let v = d.0 * (p.1 - s.1) - d.1 * (p.0 - s.0);
        v > 0.0 || (v == 0.0 && (d.1 < 0.0 || (d.1 == 0.0 && d.0 < 0.0)))
    })
}

/// Corners on sixteenths of a pixel, so some sample positions lie exactly on edges.
const POINTS: [(f64, f64, f64); 5] = [
    (1.0, 1.0, 1.0),
    (9.0, 1.5, 1.0),
    (7.375, 8.875, 1.0),
    (0.5, 7.0, 1.0),
    (11.0, 9.0, 1.0),
];
const TRIANGLES: [[u32; 3]; 3] = [[0, 1, 2], [0, 2, 3], [1, 4, 2]];

#[test]
fn every_sample_is_covered_as_a_hand_written_edge_test_says_and_shared_edges_once() {
    let m = mesh(&POINTS, TRIANGLES.to_vec());
    let corner = |i: u32| (POINTS[i as usize].0, POINTS[i as usize].1);
    for (c, p) in [
        (SampleCount::Four, SamplePattern::Standard),
        (SampleCount::Four, SamplePattern::Grid),
        (SampleCount::Eight, SamplePattern::Standard),
    ] {
        let (_, samples) = render_samples(&m, &white(), &with(count(c, p))).expect("render");
        let pos = hand_positions(c, p);
        assert_eq!(samples.offsets.len(), pos.len());
        for y in 0..H {
            for x in 0..W {
                for (k, &(ox, oy)) in pos.iter().enumerate() {
                    let at = (f64::from(x) + ox, f64::from(y) + oy);
                    let covering: Vec<u32> = (0..TRIANGLES.len() as u32)
                        .filter(|&t| inside(TRIANGLES[t as usize].map(corner), at))
                        .collect();
                    assert!(
                        covering.len() <= 1,
                        "{c:?} {p:?} ({x}, {y}) #{k}: {covering:?}"
                    );
                    let want = covering.first().copied().unwrap_or(NO_TRIANGLE);
                    assert_eq!(
                        samples.pixel(x, y)[k].triangle,
                        want,
                        "{c:?} {p:?} pixel ({x}, {y}) sample {k} at {at:?}"
                    );
                }
            }
        }
    }
}

/// A triangle too thin to hold a pixel centre (rows 3.55 to 3.95 and a sliver between
/// columns' centres) covers the samples a hand-written edge test says under 4 and 16
/// samples (4 standard, 4 grid, 8), in a multisampled render and in its colour-and-depth fast
/// path; with one sample it draws nothing, as before.
#[test]
fn a_triangle_between_pixel_centres_covers_its_samples() {
    let thin = [
        [(1.0, 3.5625, 1.0), (10.0, 3.625, 1.0), (5.0, 3.9375, 1.0)],
        [(6.5625, 1.0, 1.0), (6.9375, 2.0, 1.0), (6.625, 9.0, 1.0)],
    ];
    for pts in thin {
        let m = mesh(&pts, vec![[0, 1, 2]]);
        let corners = pts.map(|(x, y, _)| (x, y));
        let one = render(&m, &white(), &with(SampleSettings::default())).expect("render");
        assert!(one.frame.triangle.iter().all(|&t| t == NO_TRIANGLE));
        for (c, p) in [
            (SampleCount::Four, SamplePattern::Standard),
            (SampleCount::Four, SamplePattern::Grid),
            (SampleCount::Eight, SamplePattern::Standard),
        ] {
            let (full, samples) = render_samples(&m, &white(), &with(count(c, p))).expect("render");
            let pos = hand_positions(c, p);
            let mut covered = 0;
            for y in 0..H {
                for x in 0..W {
                    for (k, &(ox, oy)) in pos.iter().enumerate() {
                        let at = (f64::from(x) + ox, f64::from(y) + oy);
                        let want = if inside(corners, at) { 0 } else { NO_TRIANGLE };
                        covered += usize::from(want == 0);
                        assert_eq!(
                            samples.pixel(x, y)[k].triangle,
                            want,
                            "{c:?} {p:?} pixel ({x}, {y}) sample {k} at {at:?}"
                        );
                    }
                }
            }
            assert!(covered >= 8, "{c:?} {p:?}: {covered} samples covered");
            let mut fast = barylab::raster::Framebuffer::empty();
            barylab::raster::render_into(
                &mut fast,
                &m,
                &white(),
                &with(count(c, p)),
                barylab::raster::Buffers::ColorDepth,
            )
            .expect("render");
            assert_eq!(fast.color, full.frame.color, "{c:?} {p:?}");
        }
    }
}

/// A sample exactly on the shared diagonal of a quad belongs to exactly one of its halves,
/// and every sample strictly inside the quad to one: no gaps, no double coverage.
#[test]
fn a_shared_diagonal_through_samples_is_covered_once() {
    // Diagonal (2, 2)-(8, 8): through every grid sample (x + 0.25, y + 0.25) on it.
    let pts = [
        (2.0, 2.0, 1.0),
        (8.0, 2.0, 1.0),
        (8.0, 8.0, 1.0),
        (2.0, 8.0, 1.0),
    ];
    let m = mesh(&pts, vec![[0, 1, 2], [0, 2, 3]]);
    let (_, s) = render_samples(
        &m,
        &white(),
        &with(count(SampleCount::Four, SamplePattern::Grid)),
    )
    .expect("render");
    let mut on_diagonal = 0;
    for y in 2..8 {
        for x in 2..8 {
            for (k, v) in s.pixel(x, y).iter().enumerate() {
                assert_ne!(v.triangle, NO_TRIANGLE, "({x}, {y}) sample {k}: a gap");
                let (ox, oy) = hand_positions(SampleCount::Four, SamplePattern::Grid)[k];
                if f64::from(x) + ox == f64::from(y) + oy {
                    on_diagonal += 1;
                    // Under llvmpipe's rule the diagonal is a left edge of A B C (its
                    // interior, up and right, lies to the right of the edge going up).
                    assert_eq!(v.triangle, 0, "({x}, {y}) sample {k}");
                }
            }
        }
    }
    assert_eq!(on_diagonal, 12);
}

#[test]
fn the_resolve_is_the_average_of_the_samples() {
    // A white triangle whose left edge is x = 3.5: pixel column 3 has the grid samples at
    // x = 3.75 inside and 3.25 outside, so two of four: (2 * 255 + 2 * 0 + 2) / 4 = 128.
    let m = mesh(
        &[(3.5, 0.0, 1.0), (12.0, 0.0, 1.0), (3.5, 10.0, 1.0)],
        vec![[0, 1, 2]],
    );
    let s = RenderSettings {
        shading: Shading::VertexColor,
        background: [0, 0, 0, 255],
        ..with(count(SampleCount::Four, SamplePattern::Grid))
    };
    let r = render(&m, &white(), &s).expect("render");
    assert_eq!(r.frame.color[r.frame.index(3, 2)], [128, 128, 128, 255]);
    assert_eq!(r.frame.color[r.frame.index(4, 2)], [255, 255, 255, 255]);
    assert_eq!(r.frame.color[r.frame.index(2, 2)], [0, 0, 0, 255]);
}

/// The hand-worked pixel: an edge at x = 0.55 in pixel (4, 3) leaves standard samples 1
/// (x 0.875) and 3 (x 0.625) inside, 0 (0.375) and 2 (0.125) and the centre outside.
#[test]
fn centroid_takes_the_lowest_covered_sample_and_the_centre_extrapolates() {
    let m = mesh(
        &[(4.55, -20.0, 1.0), (30.0, 3.5, 1.0), (4.55, 30.0, 1.0)],
        vec![[0, 1, 2]],
    );
    let uv_at = |x: f64, y: f64| [(x / f64::from(W)) as f32, (y / f64::from(H)) as f32];
    let close = |a: [f32; 2], b: [f32; 2]| (a[0] - b[0]).abs() < 1e-6 && (a[1] - b[1]).abs() < 1e-6;
    let four = count(SampleCount::Four, SamplePattern::Standard);
    for (location, want) in [
        // Centroid: sample 1 at (4.875, 3.625) for both covered samples.
        (
            Location::Centroid,
            [None, Some((4.875, 3.625)), None, Some((4.875, 3.625))],
        ),
        // Centre: (4.5, 3.5), outside the triangle: the plane's value there, extrapolated.
        (
            Location::Center,
            [None, Some((4.5, 3.5)), None, Some((4.5, 3.5))],
        ),
        // Sample: each sample's own position.
        (
            Location::Sample,
            [None, Some((4.875, 3.625)), None, Some((4.625, 3.125))],
        ),
    ] {
        let s = with(SampleSettings { location, ..four });
        let (_, samples) = render_samples(&m, &white(), &s).expect("render");
        for (k, (v, w)) in samples.pixel(4, 3).iter().zip(want).enumerate() {
            match w {
                None => assert_eq!(v.triangle, NO_TRIANGLE, "{location:?} sample {k}"),
                Some((x, y)) => {
                    assert_eq!(v.triangle, 0, "{location:?} sample {k}");
                    assert!(close(v.uv, uv_at(x, y)), "{location:?} #{k}: {:?}", v.uv);
                }
            }
        }
    }
}

/// With the corners at different w, `smooth` at the centroid is the exact perspective value
/// at the sample: `p_i = (l_i / w_i) / sum_k (l_k / w_k)`, `uv = sum p_i uv_i`, with the screen
/// weights `l` of the sample position worked out here.
#[test]
fn smooth_at_the_centroid_is_the_exact_perspective_value_there() {
    let pts = [(4.55, -20.0, 1.0), (30.0, 3.5, 4.0), (4.55, 30.0, 2.0)];
    let m = mesh(&pts, vec![[0, 1, 2]]);
    let s = with(SampleSettings {
        location: Location::Centroid,
        ..count(SampleCount::Four, SamplePattern::Standard)
    });
    let (_, samples) = render_samples(&m, &white(), &s).expect("render");
    let (px, py) = (4.875, 3.625);
    let cross = |a: (f64, f64, f64), b: (f64, f64, f64), p: (f64, f64)| {
        (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0)
    };
    let area = cross(pts[0], pts[1], (pts[2].0, pts[2].1));
    let l = [
        cross(pts[1], pts[2], (px, py)) / area,
        cross(pts[2], pts[0], (px, py)) / area,
        cross(pts[0], pts[1], (px, py)) / area,
    ];
    let q: Vec<f64> = (0..3).map(|i| l[i] / pts[i].2).collect();
    let sum: f64 = q.iter().sum();
    let uv = |i: usize| [pts[i].0 / f64::from(W), pts[i].1 / f64::from(H)];
    let want = [0, 1].map(|c| (0..3).map(|i| q[i] / sum * uv(i)[c]).sum::<f64>());
    for k in [1, 3] {
        let got = samples.pixel(4, 3)[k].uv;
        for c in 0..2 {
            assert!(
                (f64::from(got[c]) - want[c]).abs() < 5e-6,
                "{got:?} vs {want:?}"
            );
        }
    }
}

#[test]
fn msaa_shades_once_per_pixel_and_supersampling_every_sample() {
    let m = mesh(&POINTS, TRIANGLES.to_vec());
    let four = count(SampleCount::Four, SamplePattern::Standard);
    let one = render(&m, &white(), &settings(W, H)).expect("render");
    let (msaa, ms) = render_samples(&m, &white(), &with(four)).expect("render");
    let ssaa_settings = with(SampleSettings {
        rate: ShadingRate::Ssaa,
        ..four
    });
    let (_, ss) = render_samples(&m, &white(), &ssaa_settings).expect("render");
    // Pixel (4, 4) lies inside triangle 0 with all four samples.
    let inner = ms.pixel(4, 4);
    assert!(inner.iter().all(|v| v.triangle == 0));
    // MSAA at the centre: one colour, the single-sample pixel's.
    let centre = one.frame.color[one.frame.index(4, 4)];
    assert!(inner.iter().all(|v| v.color == centre), "{inner:?}");
    assert_eq!(msaa.frame.color[msaa.frame.index(4, 4)], centre);
    // Supersampling: the barycentric colour differs from sample to sample.
    let colors: Vec<[u8; 4]> = ss.pixel(4, 4).iter().map(|v| v.color).collect();
    assert!(colors.windows(2).any(|w| w[0] != w[1]), "{colors:?}");
}

#[test]
fn flat_takes_the_provoking_vertex_exactly() {
    let mut m = mesh(
        &[(1.0, 1.0, 1.0), (11.0, 2.0, 2.0), (5.0, 9.0, 3.0)],
        vec![[0, 1, 2]],
    );
    m.vertices[0].color = Vec3::new(1.0, 0.0, 0.0);
    m.vertices[1].color = Vec3::new(0.0, 1.0, 0.0);
    m.vertices[2].color = Vec3::new(0.2, 0.4, 1.0);
    for (c, provoking, want) in [
        (SampleCount::One, ProvokingVertex::Last, [51, 102, 255, 255]),
        (
            SampleCount::Four,
            ProvokingVertex::Last,
            [51, 102, 255, 255],
        ),
        (SampleCount::Four, ProvokingVertex::First, [255, 0, 0, 255]),
    ] {
        let s = RenderSettings {
            shading: Shading::VertexColor,
            ..with(SampleSettings {
                count: c,
                flat: true,
                provoking,
                ..SampleSettings::default()
            })
        };
        let r = render(&m, &white(), &s).expect("render");
        let (_, samples) = render_samples(&m, &white(), &s).expect("render");
        let mut drawn = 0;
        for v in samples.samples.iter().filter(|v| v.triangle == 0) {
            assert_eq!(v.color, want, "{c:?} {provoking:?}");
            drawn += 1;
        }
        assert!(drawn > 20);
        assert_eq!(r.frame.color[r.frame.index(5, 4)], want);
    }
}

/// One sample at the centre through the sample path is the single-sample render, pixel for
/// pixel and buffer for buffer.
#[test]
fn one_sample_through_the_sample_path_is_the_usual_render() {
    let m = mesh(&POINTS, TRIANGLES.to_vec());
    for shading in [Shading::Barycentric, Shading::Texture, Shading::Depth] {
        let s = RenderSettings {
            shading,
            wireframe: shading == Shading::Texture,
            ..settings(W, H)
        };
        let tex = Texture::builtin(barylab::raster::BuiltinTexture::UvGrid);
        let usual = render(&m, &tex, &s).expect("render");
        let (sampled, samples) = render_samples(&m, &tex, &s).expect("render");
        assert!(sampled.frame == usual.frame, "{shading:?}");
        assert_eq!(samples.offsets.len(), 1);
    }
}

#[test]
fn the_grid_pattern_has_no_eight_samples() {
    let m = mesh(&POINTS, TRIANGLES.to_vec());
    let err = render(
        &m,
        &white(),
        &with(count(SampleCount::Eight, SamplePattern::Grid)),
    )
    .expect_err("grid of 8");
    assert!(err.to_string().contains("grid"), "{err}");
}

/// Depth is tested per sample, at each sample's own position, even when MSAA shades once:
/// triangle 0's window depth grows as x / 12 across the image, triangle 1 (drawn after) is
/// flat at 4.6 / 12. In pixel 4 the samples at x = 4.875 and 4.625 (1 and 3) see triangle 1
/// nearer, those at 4.375 and 4.125 (0 and 2) triangle 0; at the centre (4.5) triangle 0 is.
/// (Pixel (4, 1) lies in the quad half A B C, triangle 0.)
#[test]
fn depth_is_tested_at_every_sample() {
    let mut m = mesh(
        &[
            (0.0, 0.0, 1.0),
            (12.0, 0.0, 1.0),
            (12.0, 10.0, 1.0),
            (0.0, 10.0, 1.0),
            (0.0, 0.0, 1.0),
            (12.0, 0.0, 1.0),
            (12.0, 10.0, 1.0),
        ],
        vec![[0, 1, 2], [0, 2, 3], [4, 5, 6]],
    );
    for (i, v) in m.vertices.iter_mut().enumerate() {
        // Window depth d = (z_ndc + 1) / 2 with w = 1.
        let d = if i < 4 {
            v.clip.x * 0.5 + 0.5
        } else {
            4.6 / 12.0
        };
        v.clip.z = 2.0 * d - 1.0;
    }
    let s = with(count(SampleCount::Four, SamplePattern::Standard));
    let (_, samples) = render_samples(&m, &white(), &s).expect("render");
    let owners: Vec<u32> = samples.pixel(4, 1).iter().map(|v| v.triangle).collect();
    assert_eq!(owners, [0, 2, 0, 2]);
}
