//! Property tests of the rasterizer against independent computations.

mod common;

use barylab::raster::camera::{Camera, Projection};
use barylab::raster::clip::{ClipVertex, MIN_CLIP_W, clip_triangle};
use barylab::raster::project::{SUBPIXEL, Viewport};
use barylab::raster::render::{ClipMesh, MeshVertex};
use barylab::raster::varying::Varyings;
use barylab::raster::{Interpolation, NO_TRIANGLE, Shading, Texture};
use common::*;
use glam::{DVec3, DVec4, Vec2, Vec3};
use proptest::prelude::*;

const W: u32 = 64;
const H: u32 = 48;

fn tri_mesh(v: [MeshVertex; 3]) -> ClipMesh {
    ClipMesh {
        vertices: v.to_vec(),
        triangles: vec![[0, 1, 2]],
    }
}

/// A window position on the 1/256 sub-pixel grid, inside a margin around the viewport.
fn grid_coord(max: u32) -> impl Strategy<Value = f64> {
    let lo = -8 * SUBPIXEL;
    let hi = (i64::from(max) + 8) * SUBPIXEL;
    (lo..hi).prop_map(|k| k as f64 / SUBPIXEL as f64)
}

fn window_vertex() -> impl Strategy<Value = (f64, f64, f64)> {
    (grid_coord(W), grid_coord(H), 0.5f64..20.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Weights sum to 1 at every covered pixel, both kinds.
    #[test]
    fn weights_sum_to_one(a in window_vertex(), b in window_vertex(), c in window_vertex()) {
        let mesh = tri_mesh([a, b, c].map(|(x, y, w)| at_window(x, y, w, W, H)));
        let r = draw(&mesh, W, H);
        for i in 0..r.frame.triangle.len() {
            if r.frame.triangle[i] == NO_TRIANGLE { continue; }
            let s: f32 = r.frame.weights_screen[i].iter().sum();
            let p: f32 = r.frame.weights_perspective[i].iter().sum();
            prop_assert!((s - 1.0).abs() < 1e-5, "screen sum {}", s);
            prop_assert!((p - 1.0).abs() < 1e-5, "perspective sum {}", p);
        }
    }

    /// With equal w at all vertices, perspective-correct equals affine.
    #[test]
    fn affine_equals_perspective_when_w_is_equal(
        a in window_vertex(), b in window_vertex(), c in window_vertex(), w in 0.1f64..50.0
    ) {
        let mesh = tri_mesh([a, b, c].map(|(x, y, _)| at_window(x, y, w, W, H)));
        let r = draw(&mesh, W, H);
        for i in 0..r.frame.triangle.len() {
            if r.frame.triangle[i] == NO_TRIANGLE { continue; }
            for k in 0..3 {
                let d = (r.frame.weights_screen[i][k] - r.frame.weights_perspective[i][k]).abs();
                prop_assert!(d < 1e-5, "weight {} differs by {}", k, d);
            }
            for k in 0..2 {
                let d = (r.frame.uv_affine[i][k] - r.frame.uv_perspective[i][k]).abs();
                prop_assert!(d < 1e-5);
            }
        }
    }

    /// Perspective-correct weights at a pixel centre equal the barycentric coordinates of the
    /// 3D point where the eye ray through that centre meets the triangle's plane, computed
    /// independently in f64 in view space.
    #[test]
    fn perspective_weights_match_ray_plane_intersection(
        a in window_vertex(), b in window_vertex(), c in window_vertex(), fov in 30.0f64..100.0
    ) {
        let cam = Camera {
            eye: DVec3::ZERO, target: DVec3::NEG_Z, up: DVec3::Y,
            projection: Projection::Perspective { fov_y_deg: fov, near: 0.1, far: 100.0 },
        };
        let aspect = f64::from(W) / f64::from(H);
        let clip_from_view = cam.clip_from_view(aspect);
        let ty = (fov.to_radians() / 2.0).tan();
        let tx = ty * aspect;
        // View-space point seen at window (x, y) at distance w (= -z_view).
        let view_at = |x: f64, y: f64, w: f64| {
            let ndc_x = 2.0 * x / f64::from(W) - 1.0;
            let ndc_y = 1.0 - 2.0 * y / f64::from(H);
            DVec3::new(ndc_x * tx * w, ndc_y * ty * w, -w)
        };
        let views = [a, b, c].map(|(x, y, w)| view_at(x, y, w));
        let mesh = tri_mesh(views.map(|v| MeshVertex {
            clip: clip_from_view * v.extend(1.0),
            uv: Vec2::ZERO,
            color: Vec3::ONE,
            normal: Vec3::ZERO,
        }));
        let r = draw(&mesh, W, H);
        let n = (views[1] - views[0]).cross(views[2] - views[0]);
        for y in 0..H {
            for x in 0..W {
                let i = r.frame.index(x, y);
                if r.frame.triangle[i] == NO_TRIANGLE { continue; }
                let dir = view_at(f64::from(x) + 0.5, f64::from(y) + 0.5, 1.0);
                let t = n.dot(views[0]) / n.dot(dir);
                let p = dir * t;
                let nn = n.dot(n);
                let expect = [
                    n.dot((views[1] - p).cross(views[2] - p)) / nn,
                    n.dot((views[2] - p).cross(views[0] - p)) / nn,
                    n.dot((views[0] - p).cross(views[1] - p)) / nn,
                ];
                for (k, (&got, want)) in r.frame.weights_perspective[i].iter().zip(expect).enumerate() {
                    let got = f64::from(got);
                    prop_assert!((got - want).abs() < 2e-4,
                        "pixel ({}, {}) weight {}: rasterizer {} vs ray-plane {}", x, y, k, got, want);
                }
            }
        }
    }

    /// Every pixel of a convex quad is covered exactly once by its two triangles; no pixel
    /// of the shared diagonal is covered twice or missed.
    #[test]
    fn quad_diagonal_covered_exactly_once(
        cx in 10.0f64..54.0, cy in 10.0f64..38.0, r0 in 4.0f64..30.0,
        angles in proptest::collection::vec(0.0f64..std::f64::consts::TAU, 4),
        ws in proptest::collection::vec(0.5f64..10.0, 4),
    ) {
        let mut angles = angles;
        angles.sort_by(f64::total_cmp);
        let pts: Vec<(f64, f64)> = angles
            .iter()
            .map(|t| {
                let x = ((cx + r0 * t.cos()) * 256.0).round() / 256.0;
                let y = ((cy + r0 * t.sin()) * 256.0).round() / 256.0;
                (x, y)
            })
            .collect();
        let mesh = ClipMesh {
            vertices: pts.iter().zip(&ws).map(|(&(x, y), &w)| at_window(x, y, w, W, H)).collect(),
            triangles: vec![[0, 1, 2], [0, 2, 3]],
        };
        let counts = coverage_counts(&mesh, W, H);
        prop_assert!(counts.iter().all(|&c| c <= 1));
        // Pixels whose centre is strictly inside the quad (by an f64 test with margin) are
        // covered once: no holes along the diagonal.
        let inside = |px: f64, py: f64| {
            (0..4).all(|k| {
                let (ax, ay) = pts[k];
                let (bx, by) = pts[(k + 1) % 4];
                // Sorted angles in image coordinates (y down) wind clockwise on screen: cross > 0.
                (bx - ax) * (py - ay) - (by - ay) * (px - ax) > 1e-6
            })
        };
        for y in 0..H {
            for x in 0..W {
                if inside(f64::from(x) + 0.5, f64::from(y) + 0.5) {
                    prop_assert_eq!(counts[(y * W + x) as usize], 1, "hole at ({}, {})", x, y);
                }
            }
        }
    }

    /// Clipping keeps every output vertex inside the frustum (-w <= z <= w, w > 0) and the
    /// guard band, with attributes interpolated inside their input range.
    #[test]
    fn clipped_output_is_inside_the_frustum(
        coords in proptest::collection::vec(-10.0f64..10.0, 12)
    ) {
        let tri: [ClipVertex; 3] = std::array::from_fn(|k| ClipVertex::new(
            DVec4::new(coords[4 * k], coords[4 * k + 1], coords[4 * k + 2], coords[4 * k + 3]),
            Varyings::new(
                [(k == 0) as u8 as f32, (k == 1) as u8 as f32, (k == 2) as u8 as f32],
                Vec2::new(k as f32, 0.0),
                Vec3::ZERO,
            ),
        ));
        let g = Viewport { width: W, height: H }.guard_band_ndc();
        let poly = clip_triangle(&tri, g);
        for v in poly.vertices() {
            let c = v.clip;
            let tol = 1e-9 * (1.0 + c.abs().max_element());
            prop_assert!(c.w >= MIN_CLIP_W - tol, "w = {}", c.w);
            prop_assert!(c.z >= -c.w - tol && c.z <= c.w + tol, "z {} outside +-w {}", c.z, c.w);
            prop_assert!(c.x.abs() <= g * c.w + tol && c.y.abs() <= g * c.w + tol);
            let b = v.varyings.bary();
            prop_assert!((b.iter().sum::<f32>() - 1.0).abs() < 1e-5);
            prop_assert!(b.iter().all(|&x| (-1e-6..=1.0 + 1e-6).contains(&x)));
        }
    }

    /// `noperspective` attributes stay linear on screen through clipping (OpenGL 13.7.1): at
    /// every vertex of the clipped polygon they equal the 2D barycentric interpolation of the
    /// original vertices' values over the original triangle's projected corners (x/w, y/w,
    /// with the vertex behind the camera projected through its negative w, as GL does),
    /// computed here independently in f64.
    #[test]
    fn noperspective_attributes_stay_linear_on_screen_through_clipping(
        coords in proptest::collection::vec(-4.0f64..4.0, 9),
        w in proptest::collection::vec(0.3f64..4.0, 3),
        behind in 0usize..3,
        z_behind in 0.1f64..2.0,
    ) {
        let mut clip: [DVec4; 3] = std::array::from_fn(|k| {
            DVec4::new(coords[3 * k] * w[k], coords[3 * k + 1] * w[k], coords[3 * k + 2].clamp(-0.9, 0.9) * w[k], w[k])
        });
        // One vertex behind the camera: negative w, in front of the near plane's other side.
        clip[behind].w = -clip[behind].w;
        clip[behind].z = -z_behind;
        let uv = [Vec2::new(0.0, 0.0), Vec2::new(8.0, 1.0), Vec2::new(2.0, 5.0)];
        let tri: [ClipVertex; 3] = std::array::from_fn(|k| {
            ClipVertex::new(clip[k], Varyings::new([0.0; 3], uv[k], Vec3::ZERO))
        });
        let ndc = clip.map(|c| glam::DVec2::new(c.x / c.w, c.y / c.w));
        let area = |a: glam::DVec2, b: glam::DVec2, c: glam::DVec2| (b - a).perp_dot(c - a);
        let total = area(ndc[0], ndc[1], ndc[2]);
        prop_assume!(total.abs() > 1e-3);
        let g = Viewport { width: W, height: H }.guard_band_ndc();
        let poly = clip_triangle(&tri, g);
        for v in poly.vertices() {
            let p = glam::DVec2::new(v.clip.x / v.clip.w, v.clip.y / v.clip.w);
            let l = [
                area(p, ndc[1], ndc[2]) / total,
                area(ndc[0], p, ndc[2]) / total,
                area(ndc[0], ndc[1], p) / total,
            ];
            let expected: glam::DVec2 = (0..3).map(|k| uv[k].as_dvec2() * l[k]).sum();
            let got = v.noperspective.uv().as_dvec2();
            let scale = 1.0 + l.iter().map(|x| x.abs()).sum::<f64>() * 8.0;
            prop_assert!(
                (got - expected).length() <= 1e-4 * scale,
                "noperspective uv {:?}, screen-linear {:?} at ndc {:?}", got, expected, p
            );
        }
    }

    /// No NaN or infinity in any buffer, whatever the vertices: behind the camera, w = 0,
    /// negative w, degenerate, huge, or not finite at all.
    #[test]
    fn no_nan_in_any_buffer(
        coords in proptest::collection::vec(
            prop_oneof![
                4 => -5.0f64..5.0,
                1 => Just(0.0),
                1 => Just(1e30),
                1 => Just(-1e30),
                1 => Just(f64::NAN),
                1 => Just(f64::INFINITY),
            ],
            16,
        ),
        mode in prop_oneof![Just(Interpolation::Affine), Just(Interpolation::Perspective)],
        shading in prop_oneof![Just(Shading::Texture), Just(Shading::Depth), Just(Shading::Barycentric)],
    ) {
        let mesh = ClipMesh {
            vertices: (0..4).map(|k| MeshVertex {
                clip: DVec4::new(coords[4 * k], coords[4 * k + 1], coords[4 * k + 2], coords[4 * k + 3]),
                uv: Vec2::new(k as f32, 1.0),
                color: Vec3::ONE,
                normal: Vec3::ZERO,
            }).collect(),
            triangles: vec![[0, 1, 2], [0, 2, 3], [1, 1, 2]],
        };
        let mut s = settings(W, H);
        s.mode = mode;
        s.shading = shading;
        s.wireframe = true;
        let tex = Texture::builtin(barylab::raster::BuiltinTexture::Checker);
        let r = barylab::raster::render(&mesh, &tex, &s).expect("render");
        let f = &r.frame;
        prop_assert!(f.depth.iter().all(|x| x.is_finite()));
        prop_assert!(f.inv_w.iter().all(|x| x.is_finite()));
        prop_assert!(f.weights_screen.iter().flatten().all(|x| x.is_finite()));
        prop_assert!(f.weights_perspective.iter().flatten().all(|x| x.is_finite()));
        prop_assert!(f.uv_affine.iter().flatten().all(|x| x.is_finite()));
        prop_assert!(f.uv_perspective.iter().flatten().all(|x| x.is_finite()));
    }
}

/// A vertex dragged behind the camera: the visible part is drawn, with the same pixels as
/// the same quad cut at the near plane by hand (no flipped or exploded triangle).
#[test]
fn vertex_behind_camera_draws_the_visible_part_only() {
    let cam = Camera {
        eye: DVec3::ZERO,
        target: DVec3::NEG_Z,
        up: DVec3::Y,
        projection: Projection::Perspective {
            fov_y_deg: 90.0,
            near: 0.5,
            far: 50.0,
        },
    };
    let m = cam.clip_from_view(1.0);
    // Triangle on the plane y = -1: A behind the eye (z = +2), B and C in front.
    let pts = [
        DVec3::new(0.0, -1.0, 2.0),
        DVec3::new(2.0, -1.0, -4.0),
        DVec3::new(-2.0, -1.0, -4.0),
    ];
    let mesh = tri_mesh(pts.map(|p| MeshVertex {
        clip: m * p.extend(1.0),
        uv: Vec2::ZERO,
        color: Vec3::ONE,
        normal: Vec3::ZERO,
    }));
    let r = draw(&mesh, W, W);
    // Independent check: a pixel is covered iff its eye ray hits the triangle in front of the
    // near plane. Plane y = -1: ray (x_ndc t, y_ndc t, -t) meets it at t = 1 / -y_ndc.
    let mut mismatches = 0;
    for y in 0..W {
        for x in 0..W {
            let ndc_x = 2.0 * (f64::from(x) + 0.5) / f64::from(W) - 1.0;
            let ndc_y = 1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(W);
            let hit = if ndc_y < 0.0 {
                let t = -1.0 / ndc_y;
                let p = DVec3::new(ndc_x * t, -1.0, -t);
                let inside = |a: DVec3, b: DVec3| {
                    // In the plane y = -1, viewed from above: 2D cross in (x, z).
                    (b.x - a.x) * (p.z - a.z) - (b.z - a.z) * (p.x - a.x)
                };
                let s = [
                    inside(pts[0], pts[1]),
                    inside(pts[1], pts[2]),
                    inside(pts[2], pts[0]),
                ];
                (s.iter().all(|&v| v > 1e-9) || s.iter().all(|&v| v < -1e-9)) && t >= 0.5
            } else {
                false
            };
            if hit != r.frame.covered(x, y) {
                mismatches += 1;
            }
        }
    }
    // Only samples within float noise of an edge may differ.
    assert!(
        mismatches <= 2,
        "{mismatches} pixels differ from the ray test"
    );
    assert!(
        r.frame
            .triangle
            .iter()
            .filter(|&&t| t != NO_TRIANGLE)
            .count()
            > 300
    );
}
