//! Every value exact: barylab's per-pixel buffers (the AOVs) against an independent f64
//! evaluation of the exact answer on random clip-space triangles, with slivers, tiny
//! triangles, vertices behind the camera and triangles cut by the near and far planes.
//!
//! The exact answer at a pixel centre uses nothing of the pipeline (no clipping, no
//! projection, no snapping): the point `X = b_0 q_0 + b_1 q_1 + b_2 q_2` of the source
//! triangle seen at NDC `s` has `(X_x, X_y, X_w)` proportional to `(s_x, s_y, 1)`, so by
//! Cramer's rule `b_i` is proportional to the determinant with column `i` of
//! `[q_0 q_1 q_2]` (rows x, y, w) replaced by `(s_x, s_y, 1)`; the weights sum to 1. Then
//! `W = sum b_i w_i`, `Z = sum b_i z_i`, window depth `(Z / W + 1) / 2`, 1/w = `1 / W`;
//! `noperspective` (screen-space) weights `r_i = b_i w_i / W`, which is the source triangle's
//! screen-linear function even where a vertex is behind the camera.

mod common;

use barylab::raster::NO_TRIANGLE;
use barylab::raster::render::{ClipMesh, MeshVertex, render};
use barylab::raster::texture::Texture;
use common::settings;
use glam::{DVec3, DVec4, Vec2, Vec3};
use proptest::array::uniform3;
use proptest::prelude::*;

const W: u32 = 48;
const H: u32 = 36;

/// The target: f32 output precision.
const TOLERANCE: f64 = 1e-6;

/// Vertices closer than this to w = 0 (in clip w) are not generated: near w = 0 the
/// clipper's noperspective fallback (the cut's screen fraction) is used instead of the
/// source triangle's screen-linear function, which is what the exact answer here is.
const MIN_ABS_W: f64 = 0.05;

fn det3(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    a.dot(b.cross(c))
}

/// The exact values at window position `(px, py)` of the triangle `q` with attributes `uv`.
struct Exact {
    perspective: [f64; 3],
    screen: [f64; 3],
    depth: f64,
    inv_w: f64,
    uv_perspective: [f64; 2],
    uv_affine: [f64; 2],
}

fn exact(q: &[DVec4; 3], uv: &[Vec2; 3], px: f64, py: f64) -> Option<Exact> {
    let s = DVec3::new(
        2.0 * px / f64::from(W) - 1.0,
        1.0 - 2.0 * py / f64::from(H),
        1.0,
    );
    let c = q.map(|v| DVec3::new(v.x, v.y, v.w));
    let d = [
        det3(s, c[1], c[2]),
        det3(c[0], s, c[2]),
        det3(c[0], c[1], s),
    ];
    let sum = d[0] + d[1] + d[2];
    if sum == 0.0 {
        return None;
    }
    let b = d.map(|x| x / sum);
    let w = b[0] * q[0].w + b[1] * q[1].w + b[2] * q[2].w;
    let z = b[0] * q[0].z + b[1] * q[1].z + b[2] * q[2].z;
    let r = [0, 1, 2].map(|i| b[i] * q[i].w / w);
    let mix =
        |wt: &[f64; 3]| [0, 1].map(|k| (0..3).map(|i| wt[i] * f64::from(uv[i][k])).sum::<f64>());
    Some(Exact {
        perspective: b,
        screen: r,
        depth: (z / w + 1.0) / 2.0,
        inv_w: 1.0 / w,
        uv_perspective: mix(&b),
        uv_affine: mix(&r),
    })
}

/// |a - b| within the tolerance, relative for values beyond 1.
fn near(ours: f32, exact: f64) -> bool {
    (f64::from(ours) - exact).abs() <= TOLERANCE * exact.abs().max(1.0)
}

fn check(q: [DVec4; 3], uv: [Vec2; 3]) -> Result<usize, TestCaseError> {
    let mesh = ClipMesh {
        vertices: (0..3)
            .map(|i| MeshVertex {
                clip: q[i],
                uv: uv[i],
                color: Vec3::ONE,
                normal: Vec3::ZERO,
            })
            .collect(),
        triangles: vec![[0, 1, 2]],
    };
    let tex = Texture::from_texels(1, 1, vec![[255; 4]]).expect("texture");
    let r = render(&mesh, &tex, &settings(W, H)).expect("render");
    let f = &r.frame;
    let mut checked = 0;
    for y in 0..H {
        for x in 0..W {
            let i = (y * W + x) as usize;
            if f.triangle[i] == NO_TRIANGLE {
                continue;
            }
            let Some(e) = exact(&q, &uv, f64::from(x) + 0.5, f64::from(y) + 0.5) else {
                continue;
            };
            let at = format!("pixel ({x}, {y}) of {q:?}");
            for k in 0..3 {
                prop_assert!(
                    near(f.weights_perspective[i][k], e.perspective[k]),
                    "perspective weight {k}: {} vs exact {}, {at}",
                    f.weights_perspective[i][k],
                    e.perspective[k]
                );
                prop_assert!(
                    near(f.weights_screen[i][k], e.screen[k]),
                    "screen weight {k}: {} vs exact {}, {at}",
                    f.weights_screen[i][k],
                    e.screen[k]
                );
            }
            for k in 0..2 {
                prop_assert!(
                    near(f.uv_perspective[i][k], e.uv_perspective[k]),
                    "uv perspective {k}: {} vs exact {}, {at}",
                    f.uv_perspective[i][k],
                    e.uv_perspective[k]
                );
                prop_assert!(
                    near(f.uv_affine[i][k], e.uv_affine[k]),
                    "uv affine {k}: {} vs exact {}, {at}",
                    f.uv_affine[i][k],
                    e.uv_affine[k]
                );
            }
            prop_assert!(
                near(f.depth[i], e.depth),
                "depth {} vs exact {}, {at}",
                f.depth[i],
                e.depth
            );
            prop_assert!(
                near(f.inv_w[i], e.inv_w),
                "1/w {} vs exact {}, {at}",
                f.inv_w[i],
                e.inv_w
            );
            checked += 1;
        }
    }
    Ok(checked)
}

/// A clip-space vertex seen at window (x, y) (any real position, not on the 1/256 grid) with
/// clip w = `w` (negative: behind the camera) and NDC depth `zn` (beyond +-1: cut by the
/// near or far plane).
fn vertex(x: f64, y: f64, w: f64, zn: f64) -> DVec4 {
    let ndc = DVec3::new(
        2.0 * x / f64::from(W) - 1.0,
        1.0 - 2.0 * y / f64::from(H),
        zn,
    );
    DVec4::new(ndc.x * w, ndc.y * w, ndc.z * w.abs(), w)
}

fn w_value() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => MIN_ABS_W..20.0,
        1 => -5.0..-MIN_ABS_W,
    ]
}

fn any_vertex() -> impl Strategy<Value = DVec4> {
    (-20.0..68.0f64, -20.0..56.0f64, w_value(), -1.6..1.6f64)
        .prop_map(|(x, y, w, zn)| vertex(x, y, w, zn))
}

fn uv() -> impl Strategy<Value = Vec2> {
    (-2.0..3.0f32, -2.0..3.0f32).prop_map(|(u, v)| Vec2::new(u, v))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]

    /// Large triangles, some with a vertex behind the camera or beyond the near/far planes.
    #[test]
    fn random_triangles_are_exact(a in any_vertex(), b in any_vertex(), c in any_vertex(),
                                  uv in [uv(), uv(), uv()]) {
        check([a, b, c], uv)?;
    }

    /// Tiny triangles (a few pixels) anywhere, at any depth.
    #[test]
    fn tiny_triangles_are_exact(
        cx in 0.0..48.0f64, cy in 0.0..36.0f64,
        d in uniform3((-2.5..2.5f64, -2.5..2.5f64)),
        w in uniform3(MIN_ABS_W..20.0f64), zn in uniform3(-0.99..0.99f64),
        uv in [uv(), uv(), uv()]
    ) {
        let q = [0, 1, 2].map(|i| vertex(cx + d[i].0, cy + d[i].1, w[i], zn[i]));
        check(q, uv)?;
    }

    /// Slivers: long and a fraction of a pixel thin, at any angle.
    #[test]
    fn slivers_are_exact(
        x0 in -10.0..58.0f64, y0 in -10.0..46.0f64, angle in 0.0..std::f64::consts::TAU,
        len in 10.0..80.0f64, t in 0.05..0.95f64, width in 0.01..0.8f64,
        w in uniform3(MIN_ABS_W..20.0f64), zn in uniform3(-0.99..0.99f64),
        uv in [uv(), uv(), uv()]
    ) {
        let dir = glam::DVec2::from_angle(angle);
        let p0 = glam::DVec2::new(x0, y0);
        let p1 = p0 + dir * len;
        let p2 = p0 + dir * (len * t) + dir.perp() * width;
        let p = [p0, p1, p2];
        let q = [0, 1, 2].map(|i| vertex(p[i].x, p[i].y, w[i], zn[i]));
        check(q, uv)?;
    }
}

/// A sliver the snapping changes: its unsnapped vertices lie a fraction of a sub-pixel off
/// the 1/256 grid, so snapped and unsnapped weights differ; the values must follow the
/// unsnapped triangle (the exact answer), as llvmpipe's do.
#[test]
fn values_follow_the_unsnapped_positions() {
    let off = 0.4 / 256.0;
    let q = [
        vertex(2.0 + off, 3.0 - off, 1.0, 0.0),
        vertex(45.0 - off, 9.0 + off, 4.0, 0.5),
        vertex(3.0 + off, 30.0 + off, 2.0, -0.5),
    ];
    let uv = [
        Vec2::new(0.0, 0.0),
        Vec2::new(1.0, 0.0),
        Vec2::new(0.0, 1.0),
    ];
    let checked = check(q, uv).expect("exact");
    assert!(checked > 300, "only {checked} pixels covered");
}
