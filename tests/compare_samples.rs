//! `barylab compare` against a multisampled reference (`--samples 4 --sample-pattern grid`):
//! GAMES101 A2's black edges (written here the way the bug makes them), a single-sample image
//! (no anti-aliasing), differences only on edges, and barylab's own multisampled render.

mod bugs_common;

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::raster::sample::{SampleCount, SamplePattern, SampleSettings};
use barylab::raster::{NO_TRIANGLE, RenderSettings, render};
use barylab::scene::Scene;

const SCENE: &str = "games101-a2.json";
const GRID4: [&str; 4] = ["--samples", "4", "--sample-pattern", "grid"];

fn scene_path() -> String {
    format!("{}/assets/scenes/{SCENE}", env!("CARGO_MANIFEST_DIR"))
}

/// The scene, its texture and its settings with 4 grid samples (`samples = 4`) or one.
fn load(samples: SampleCount) -> (Scene, barylab::raster::Texture, RenderSettings) {
    let path = scene_path();
    let scene = Scene::load(Path::new(&path)).expect("scene");
    let texture = scene
        .load_texture(Path::new(&path).parent().expect("folder"))
        .expect("texture");
    let mut settings = scene.settings();
    settings.samples = SampleSettings {
        count: samples,
        pattern: SamplePattern::Grid,
        ..SampleSettings::default()
    };
    (scene, texture, settings)
}

fn save(pixels: Vec<[u8; 4]>, w: u32, h: u32, file: &Path) -> PathBuf {
    let raw: Vec<u8> = pixels.into_iter().flatten().collect();
    image::RgbaImage::from_raw(w, h, raw)
        .expect("image buffer")
        .save(file)
        .expect("save");
    file.to_path_buf()
}

/// The 2x2-supersampled render with GAMES101 A2's bug: where a pixel's samples hold two
/// triangles, only the triangle of the most samples keeps its samples (depth kept per pixel
/// rejects the other's), the rest stay background, then the four are averaged. Also returns
/// how many pixels the bug changed.
fn black_edge_image(file: &Path) -> (PathBuf, usize) {
    let (scene, texture, settings) = load(SampleCount::Four);
    let (pixels, changed) = bugs_common::black_edges_of(&scene, &texture, &settings);
    (save(pixels, settings.width, settings.height, file), changed)
}

fn compare_json(image: &Path, extra: &[&str]) -> (Option<i32>, serde_json::Value) {
    let scene = scene_path();
    let mut args = vec!["compare", &scene, image.to_str().expect("utf-8")];
    args.extend(extra);
    args.push("--json");
    let out = Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(&args)
        .output()
        .expect("run barylab");
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let json = serde_json::from_str(&text).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {text}\n{}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code(), json)
}

#[test]
fn the_black_edge_bug_is_named() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (file, changed) = black_edge_image(&dir.path().join("black.png"));
    assert!(changed > 20, "the bug changed only {changed} pixels");
    let (code, json) = compare_json(&file, &GRID4);
    assert_eq!(code, Some(1), "{json}");
    assert_eq!(json["looks_like_kind"], "black_edges", "{json}");
    assert!(
        json["looks_like"]
            .as_str()
            .is_some_and(|l| l.contains("black edges")),
        "{json}"
    );
    let h = &json["hypotheses"][0];
    assert_eq!(
        (&h["kind"], &h["differing"]),
        (&"black_edges".into(), &0.into())
    );
    // The Chinese report names it too.
    let out = Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args([
            "compare",
            "--lang",
            "zh",
            &scene_path(),
            file.to_str().expect("utf-8"),
        ])
        .args(GRID4)
        .output()
        .expect("run barylab");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("黑边"), "{text}");
}

#[test]
fn a_single_sample_image_has_no_anti_aliasing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (scene, texture, settings) = load(SampleCount::One);
    let r = render(&scene.to_mesh(), &texture, &settings).expect("render");
    let file = save(
        r.frame.color.clone(),
        r.frame.width,
        r.frame.height,
        &dir.path().join("single.png"),
    );
    let (code, json) = compare_json(&file, &GRID4);
    assert_eq!(code, Some(1), "{json}");
    assert_eq!(json["looks_like_kind"], "no_anti_aliasing", "{json}");
    assert!(
        json["looks_like"]
            .as_str()
            .is_some_and(|l| l.contains("no anti-aliasing")),
        "{json}"
    );
    // Against a single-sample reference the same image agrees.
    let (code, json) = compare_json(&file, &[]);
    assert_eq!(code, Some(0), "{json}");
}

#[test]
fn edge_only_differences_and_an_exact_image() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (scene, texture, settings) = load(SampleCount::Four);
    let r = render(&scene.to_mesh(), &texture, &settings).expect("render");
    let (w, h) = (r.frame.width, r.frame.height);
    let exact = save(r.frame.color.clone(), w, h, &dir.path().join("exact.png"));
    let (code, json) = compare_json(&exact, &GRID4);
    assert_eq!(code, Some(0), "{json}");
    assert!(json["looks_like"].is_null(), "{json}");
    // Edge pixels (resolved colour not the single-sample one) brightened to white: neither
    // black edges nor the single-sample image, but every difference is on an edge.
    let (scene1, texture1, settings1) = load(SampleCount::One);
    let one = render(&scene1.to_mesh(), &texture1, &settings1).expect("render");
    let mut pixels = r.frame.color.clone();
    let mut changed = 0;
    for (k, p) in pixels.iter_mut().enumerate() {
        if *p != one.frame.color[k] && r.frame.triangle[k] != NO_TRIANGLE {
            *p = [255, 255, 255, 255];
            changed += 1;
        }
    }
    assert!(changed > 20, "only {changed} edge pixels");
    let file = save(pixels, w, h, &dir.path().join("edges.png"));
    let (code, json) = compare_json(&file, &GRID4);
    assert_eq!(code, Some(1), "{json}");
    assert_eq!(json["looks_like_kind"], "edges_only", "{json}");
    assert!(
        json["looks_like"]
            .as_str()
            .is_some_and(|l| l.contains("anti-aliased edges differ; the interior agrees")),
        "{json}"
    );
}
