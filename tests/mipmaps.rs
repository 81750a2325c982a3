//! Level of detail from 2x2-quad uv differences, and what trilinear filtering does far away.

use barylab::raster::interpolate::quad_lod;
use barylab::raster::project::Viewport;
use barylab::raster::render::{ClipMesh, MeshVertex, prepare_triangle};
use barylab::raster::{Filter, Interpolation, render};
use barylab::scene::Scene;
use glam::{DVec4, Vec2, Vec3};

#[test]
fn lod_of_a_screen_aligned_quad_is_log2_of_texels_per_pixel() {
    // A 64x64-pixel square filling the viewport with uv 0..1: on a 256-texel texture one pixel
    // steps 4 texels, so lambda = log2(4) = 2 at every pixel, for both modes.
    let v = |x: f64, y: f64, u: f32, t: f32| MeshVertex {
        clip: DVec4::new(x, y, 0.0, 1.0),
        uv: Vec2::new(u, t),
        color: Vec3::ONE,
        normal: Vec3::ZERO,
    };
    let mesh = ClipMesh {
        vertices: vec![
            v(-1.0, -1.0, 0.0, 0.0),
            v(1.0, -1.0, 1.0, 0.0),
            v(1.0, 1.0, 1.0, 1.0),
        ],
        triangles: vec![[0, 1, 2]],
    };
    let vp = Viewport {
        width: 64,
        height: 64,
    };
    let tri = prepare_triangle(&mesh, 0, vp);
    let setup = &tri.setups[0];
    for mode in [Interpolation::Affine, Interpolation::Perspective] {
        for (x, y) in [(40, 40), (63, 10), (33, 32)] {
            let l = quad_lod(setup, x, y, mode, 256, 256);
            assert!((l - 2.0).abs() < 1e-4, "({x}, {y}): {l}");
        }
    }
}

#[test]
fn trilinear_removes_the_moire_of_a_far_checkerboard() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/assets/scenes/far-checker.json"
    );
    let scene = Scene::load(std::path::Path::new(path)).expect("scene");
    let tex = scene
        .load_texture(std::path::Path::new("."))
        .expect("texture");
    let mesh = scene.to_mesh();
    // Spread of the grey levels in a band of rows just below the horizon.
    let spread = |filter| {
        let mut s = scene.settings();
        s.filter = filter;
        let f = render(&mesh, &tex, &s).expect("render").frame;
        let first = (0..f.height)
            .find(|&y| f.covered(f.width / 2, y))
            .expect("horizon");
        let vals: Vec<f64> = (first + 2..first + 8)
            .flat_map(|y| (0..f.width).map(move |x| (x, y)))
            .filter(|&(x, y)| f.covered(x, y))
            .map(|(x, y)| f64::from(f.color[f.index(x, y)][0]))
            .collect();
        let mean = vals.iter().sum::<f64>() / vals.len() as f64;
        (vals.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / vals.len() as f64).sqrt()
    };
    let nearest = spread(Filter::Nearest);
    let trilinear = spread(Filter::Trilinear);
    assert!(nearest > 60.0, "nearest should alias: spread {nearest}");
    assert!(
        trilinear < nearest / 4.0,
        "trilinear spread {trilinear} vs nearest {nearest}"
    );
}
