//! Helpers of the named-bug tests (`compare_bugs.rs`, `grade.rs`): the test scenes and
//! images made with a bug independently of the library's own bug renders (the black edges
//! with the per-sample buffers view's writer, which `compare` does not use).
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use barylab::figure::sample_buffers::{black_edge_samples, resolved};
use barylab::raster::render::render_samples;
use barylab::raster::{ClipMesh, NO_TRIANGLE, RenderSettings, Texture, render};
use barylab::scene::Scene;

pub fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/grade")
        .join(name)
}

pub fn load(name: &str) -> (Scene, Texture, RenderSettings) {
    let path = scene_path(name);
    let scene = Scene::load(&path).expect("scene");
    let texture = scene
        .load_texture(path.parent().expect("folder"))
        .expect("texture");
    let settings = scene.settings();
    (scene, texture, settings)
}

/// The scene's triangles composited one at a time without a depth test: the last drawn on
/// top (`last_on_top`) or the first.
pub fn painted(name: &str, last_on_top: bool) -> Vec<[u8; 4]> {
    let (scene, texture, settings) = load(name);
    let mesh = scene.to_mesh();
    let mut out = vec![settings.background; (settings.width * settings.height) as usize];
    let mut order: Vec<usize> = (0..mesh.triangles.len()).collect();
    if !last_on_top {
        order.reverse();
    }
    for t in order {
        let one = ClipMesh {
            vertices: mesh.vertices.clone(),
            triangles: vec![mesh.triangles[t]],
        };
        let r = render(&one, &texture, &settings).expect("render");
        for (k, &tri) in r.frame.triangle.iter().enumerate() {
            if tri != NO_TRIANGLE {
                out[k] = r.frame.color[k];
            }
        }
    }
    out
}

/// GAMES101 A2's black edges on a supersampled scene, written the way the bug makes them:
/// where a pixel's samples hold two triangles, only the triangle of the most samples keeps
/// its samples (depth per pixel), the others stay background, then the samples are averaged.
/// Also returns how many pixels the bug changed.
pub fn black_edges(name: &str) -> (Vec<[u8; 4]>, usize) {
    let (scene, texture, settings) = load(name);
    black_edges_of(&scene, &texture, &settings)
}

/// [`black_edges`] of a loaded scene with its (multisampled) settings: the library's
/// [`black_edge_samples`] (what the app's black-edge toggle shows), resolved.
pub fn black_edges_of(
    scene: &Scene,
    texture: &Texture,
    settings: &RenderSettings,
) -> (Vec<[u8; 4]>, usize) {
    let (_, samples) = render_samples(&scene.to_mesh(), texture, settings).expect("render");
    let (bugged, changed) = black_edge_samples(&samples, settings.background);
    (resolved(&bugged), changed)
}

/// Saves RGBA pixels as a PNG `width` pixels wide.
pub fn save_png(pixels: &[[u8; 4]], width: u32, file: &Path) {
    let raw: Vec<u8> = pixels.iter().flatten().copied().collect();
    let height = (pixels.len() as u32) / width;
    image::RgbaImage::from_raw(width, height, raw)
        .expect("image buffer")
        .save(file)
        .expect("png written");
}
