//! The two rasterizers, and any number of threads, produce the same framebuffer: identical
//! coverage, values equal up to floating-point rounding.

mod common;

use barylab::raster::render::{ClipMesh, Rasterizer, RenderSettings, render};
use barylab::raster::{BuiltinTexture, Filter, Framebuffer, Interpolation, Texture};
use barylab::scene::Scene;
use common::at_window;
use proptest::prelude::*;

fn draw(mesh: &ClipMesh, tex: &Texture, s: &RenderSettings, threads: usize) -> Framebuffer {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool")
        .install(|| render(mesh, tex, s).expect("render").frame)
}

/// Same coverage and triangle everywhere; float buffers within `tol`; colours may differ only
/// where rounding moved a value across a texel or 8-bit boundary (at most 0.2% of pixels, by
/// at most a few levels unless nearest filtering switched texels).
fn assert_equal(a: &Framebuffer, b: &Framebuffer, what: &str) {
    assert_eq!(a.triangle, b.triangle, "{what}: coverage differs");
    let close = |x: f32, y: f32| (x - y).abs() <= 1e-5 * (1.0 + x.abs());
    for i in 0..a.triangle.len() {
        assert!(close(a.depth[i], b.depth[i]), "{what}: depth at {i}");
        assert!(close(a.inv_w[i], b.inv_w[i]), "{what}: 1/w at {i}");
        for k in 0..3 {
            assert!(
                close(a.weights_screen[i][k], b.weights_screen[i][k]),
                "{what}: screen weight at {i}"
            );
            assert!(
                close(a.weights_perspective[i][k], b.weights_perspective[i][k]),
                "{what}: weight at {i}"
            );
        }
        for k in 0..2 {
            assert!(
                close(a.uv_affine[i][k], b.uv_affine[i][k]),
                "{what}: uv at {i}"
            );
            assert!(
                close(a.uv_perspective[i][k], b.uv_perspective[i][k]),
                "{what}: uv at {i}"
            );
        }
    }
    let differing = a.color.iter().zip(&b.color).filter(|(x, y)| x != y).count();
    assert!(
        differing * 500 <= a.color.len(),
        "{what}: {differing} of {} colours differ",
        a.color.len()
    );
}

#[test]
fn rasterizers_and_thread_counts_agree_on_every_sample_scene() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"));
    let mut n = 0;
    for entry in std::fs::read_dir(dir).expect("scenes") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        let mut scene = Scene::load(&path).expect("scene");
        let (w, h) = scene.size();
        if w * h > 640 * 480 {
            scene.set_size(w / 4, h / 4);
        }
        let tex = scene.load_texture(dir).expect("texture");
        let mesh = scene.to_mesh();
        for mode in [Interpolation::Affine, Interpolation::Perspective] {
            let edge = RenderSettings {
                mode,
                ..scene.settings()
            };
            let scan = RenderSettings {
                rasterizer: Rasterizer::Scanline,
                ..edge
            };
            let reference = draw(&mesh, &tex, &edge, 1);
            let name = path.display();
            // More threads: bit for bit the same.
            assert!(
                draw(&mesh, &tex, &edge, 3) == reference,
                "{name}: threads changed the output"
            );
            assert!(
                draw(&mesh, &tex, &scan, 2) == draw(&mesh, &tex, &scan, 1),
                "{name}: scanline threads"
            );
            assert_equal(
                &reference,
                &draw(&mesh, &tex, &scan, 2),
                &format!("{name} {mode:?}"),
            );
        }
        n += 1;
    }
    assert!(n >= 8);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn rasterizers_agree_on_random_meshes(
        pts in proptest::collection::vec((-10.0f64..74.0, -10.0f64..58.0, 0.3f64..12.0), 6),
        persp in any::<bool>(),
        bilinear in any::<bool>(),
    ) {
        let mesh = ClipMesh {
            vertices: pts.iter().map(|&(x, y, w)| at_window(x, y, w, 64, 48)).collect(),
            triangles: vec![[0, 1, 2], [3, 4, 5], [0, 2, 4], [5, 3, 1]],
        };
        let tex = Texture::builtin(BuiltinTexture::Checker);
        let edge = RenderSettings {
            width: 64,
            height: 48,
            mode: if persp { Interpolation::Perspective } else { Interpolation::Affine },
            filter: if bilinear { Filter::Bilinear } else { Filter::Nearest },
            ..RenderSettings::default()
        };
        let scan = RenderSettings { rasterizer: Rasterizer::Scanline, ..edge };
        let a = draw(&mesh, &tex, &edge, 1);
        let b = draw(&mesh, &tex, &scan, 2);
        prop_assert_eq!(&a.triangle, &b.triangle);
        for i in 0..a.triangle.len() {
            for k in 0..3 {
                prop_assert!((a.weights_perspective[i][k] - b.weights_perspective[i][k]).abs() < 1e-5);
            }
        }
    }
}

/// `render_row` (the row plot's render) holds row `y` of the full render, every buffer, bit for
/// bit, with both rasterizers and modes, on scenes with clipped and overlapping triangles.
#[test]
fn render_row_equals_the_full_renders_row() {
    use barylab::raster::render_row;
    let names = [
        "default.json",
        "corner-behind.json",
        "clip-two-triangles.json",
        "vertex-colors.json",
    ];
    let mut rows = 0;
    for (what, mesh, tex, s) in common::scene_variants(&names, (200, 150)) {
        let full = render(&mesh, &tex, &s).expect("render").frame;
        let (w, h) = (s.width, s.height);
        for y in [0, h / 3, h / 2, h - 1] {
            let row = render_row(&mesh, &tex, &s, y).expect("row");
            let r = y as usize * w as usize..(y as usize + 1) * w as usize;
            let what = format!("{what} row {y}");
            assert_eq!((row.width, row.height), (w, 1), "{what}");
            assert_eq!(row.color, full.color[r.clone()], "{what}: colour");
            assert_eq!(row.depth, full.depth[r.clone()], "{what}: depth");
            assert_eq!(row.triangle, full.triangle[r.clone()], "{what}: triangle");
            assert_eq!(
                row.uv_affine,
                full.uv_affine[r.clone()],
                "{what}: affine uv"
            );
            assert_eq!(
                row.uv_perspective,
                full.uv_perspective[r.clone()],
                "{what}: uv"
            );
            assert_eq!(row.inv_w, full.inv_w[r.clone()], "{what}: 1/w");
            assert_eq!(
                row.weights_screen,
                full.weights_screen[r.clone()],
                "{what}: weights"
            );
            assert_eq!(row.facing, full.facing[r], "{what}: facing");
            rows += 1;
        }
    }
    assert_eq!(rows, 64);
}
