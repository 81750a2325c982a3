//! The scanline rasterizer covers exactly the pixels the edge-function rasterizer covers and
//! interpolates the same values (to floating-point rounding).

mod common;

use barylab::raster::interpolate::fragment;
use barylab::raster::project::{SUBPIXEL, Viewport};
use barylab::raster::render::{ClipMesh, prepare_triangle};
use barylab::raster::scanline::rasterize_rows;
use barylab::raster::setup::sample_point;
use common::at_window;
use proptest::prelude::*;

const W: u32 = 48;
const H: u32 = 40;

fn grid(max: u32) -> impl Strategy<Value = f64> {
    (-4 * SUBPIXEL..(i64::from(max) + 4) * SUBPIXEL).prop_map(|k| k as f64 / SUBPIXEL as f64)
}

/// Window positions on pixel centres or half-pixels hit the fill rule's ties often.
fn tie_heavy(max: u32) -> impl Strategy<Value = f64> {
    prop_oneof![grid(max), (0..2 * max).prop_map(|k| f64::from(k) / 2.0)]
}

fn check(mesh: &ClipMesh) -> Result<(), TestCaseError> {
    let vp = Viewport {
        width: W,
        height: H,
    };
    for t in 0..mesh.triangles.len() as u32 {
        for setup in &prepare_triangle(mesh, t, vp).setups {
            let mut by_scanline = Vec::new();
            rasterize_rows(setup, 0..H, |x, y, f| by_scanline.push((x, y, *f)));
            let mut by_edges = Vec::new();
            for y in 0..H {
                for x in 0..W {
                    let e = setup.edge_values(sample_point(x, y));
                    if setup.covers(&e) {
                        by_edges.push((x, y, fragment(setup, x, y).expect("fragment")));
                    }
                }
            }
            let cov =
                |v: &Vec<(u32, u32, _)>| v.iter().map(|(x, y, _)| (*x, *y)).collect::<Vec<_>>();
            prop_assert_eq!(cov(&by_scanline), cov(&by_edges));
            for ((x, y, s), (_, _, e)) in by_scanline.iter().zip(&by_edges) {
                for k in 0..3 {
                    prop_assert!(
                        (s.screen[k] - e.screen[k]).abs() < 1e-9,
                        "({}, {}) screen",
                        x,
                        y
                    );
                    prop_assert!(
                        (s.perspective[k] - e.perspective[k]).abs() < 1e-9,
                        "({}, {}) persp",
                        x,
                        y
                    );
                }
                prop_assert!((s.depth - e.depth).abs() < 1e-9);
                prop_assert!((s.inv_w - e.inv_w).abs() < 1e-9 * e.inv_w.abs().max(1.0));
                for k in 0..s.correct.0.len() {
                    prop_assert!(
                        (s.correct.0[k] - e.correct.0[k]).abs() < 1e-5,
                        "({}, {}) slot {}",
                        x,
                        y,
                        k
                    );
                    prop_assert!((s.affine.0[k] - e.affine.0[k]).abs() < 1e-5);
                }
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn scanline_equals_edge_functions(
        pts in proptest::collection::vec((tie_heavy(W), tie_heavy(H), 0.2f64..30.0), 4),
    ) {
        let mesh = ClipMesh {
            vertices: pts.iter().map(|&(x, y, w)| at_window(x, y, w, W, H)).collect(),
            triangles: vec![[0, 1, 2], [0, 2, 3], [2, 1, 0]],
        };
        check(&mesh)?;
    }
}

#[test]
fn scanline_equals_edge_functions_on_every_sample_scene() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"));
    for entry in std::fs::read_dir(dir).expect("scenes") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        let mut scene = barylab::scene::Scene::load(&path).expect("scene");
        scene.set_size(W, H);
        check(&scene.to_mesh()).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
