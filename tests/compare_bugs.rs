//! Named bugs: for every bug of `barylab::compare::bugs`, an image made with that bug (here,
//! independently where it can be: flipped, transposed, recoloured, composited triangle by
//! triangle; otherwise barylab's render with a setting changed) is written as PNG, read back
//! and compared with barylab's render of the scene, and the comparison names that bug and no
//! other. The test scene (`tests/data/grade/bugs.json`, 64x64) has a perspective quad whose
//! diagonal and top, bottom, left and right edges pass exactly through pixel centres, and
//! three overlapping triangles drawn middle, front, back.

mod bugs_common;

use std::path::Path;
use std::process::Command;

use barylab::compare::bugs::Bug;
use barylab::compare::hypotheses::shifted;
use barylab::compare::{self, CoverageBy, Reference};
use barylab::i18n::Lang;
use barylab::raster::sample::{SampleCount, SamplePattern, SampleSettings, ShadingRate};
use barylab::raster::setup::TieRule;
use barylab::raster::{ClipMesh, Interpolation, RenderSettings, Texture, render};
use bugs_common::{black_edges, load, painted, save_png, scene_path};

/// barylab's render of `mesh` with `settings`, as pixels.
fn pixels(mesh: &ClipMesh, texture: &Texture, settings: &RenderSettings) -> Vec<[u8; 4]> {
    render(mesh, texture, settings)
        .expect("render")
        .frame
        .color
        .clone()
}

/// Writes `pixels` as a PNG, reads it back through the comparison's reader and compares it
/// with barylab's render of scene `name`.
fn compared(name: &str, pixels: &[[u8; 4]], dir: &Path) -> compare::Comparison {
    let (scene, texture, settings) = load(name);
    let file = dir.join("image.png");
    save_png(pixels, settings.width, &file);
    let image = compare::read_image(&file, Lang::En, |_, _| Ok(())).expect("read back");
    let mesh = scene.to_mesh();
    let reference = Reference {
        scene: &scene,
        mesh: &mesh,
        texture: &texture,
        settings,
    };
    compare::compare(&image, &reference, CoverageBy::Background([0, 0, 0]), 2).expect("compared")
}

/// The bugs named for `pixels` against scene `name` (which they must differ from).
fn named(name: &str, pixels: Vec<[u8; 4]>, dir: &Path) -> Vec<Bug> {
    let c = compared(name, &pixels, dir);
    assert!(!c.agrees(), "the buggy image equals barylab's");
    c.bugs
}

fn right(name: &str) -> Vec<[u8; 4]> {
    let (scene, texture, settings) = load(name);
    pixels(&scene.to_mesh(), &texture, &settings)
}

fn with_settings(change: impl Fn(&mut RenderSettings)) -> Vec<[u8; 4]> {
    let (scene, texture, mut settings) = load("bugs.json");
    change(&mut settings);
    pixels(&scene.to_mesh(), &texture, &settings)
}

fn check(bug: Bug, name: &str, image: Vec<[u8; 4]>) {
    let dir = tempfile::tempdir().expect("tempdir");
    assert_eq!(named(name, image, dir.path()), vec![bug], "{}", bug.code());
}

const N: usize = 64;

#[test]
fn barylabs_own_render_names_no_bug() {
    let dir = tempfile::tempdir().expect("tempdir");
    let c = compared("bugs.json", &right("bugs.json"), dir.path());
    assert!(c.agrees());
    assert!(c.bugs.is_empty() && c.regions.is_empty());
}

#[test]
fn y_flipped() {
    let ours = right("bugs.json");
    let flipped = (0..N * N)
        .map(|k| ours[(N - 1 - k / N) * N + k % N])
        .collect();
    check(Bug::YFlipped, "bugs.json", flipped);
}

#[test]
fn x_and_y_swapped() {
    let ours = right("bugs.json");
    let swapped = (0..N * N).map(|k| ours[(k % N) * N + k / N]).collect();
    check(Bug::XySwapped, "bugs.json", swapped);
}

#[test]
fn half_pixel_offset() {
    let (scene, texture, settings) = load("bugs.json");
    // Sampled at (x, y) instead of (x + 0.5, y + 0.5): the geometry moved by half a pixel.
    let moved = shifted(&scene.to_mesh(), settings.width, settings.height, 0.5, 0.5);
    check(
        Bug::HalfPixel,
        "bugs.json",
        pixels(&moved, &texture, &settings),
    );
}

#[test]
fn top_left_tie_rule() {
    check(
        Bug::TieRule,
        "bugs.json",
        with_settings(|s| s.tie_rule = TieRule::TopLeft),
    );
}

#[test]
fn no_fill_rule_shared_edges_missed_or_drawn_twice() {
    for rule in [TieRule::NoEdges, TieRule::AllEdges] {
        check(
            Bug::NoFillRule,
            "bugs.json",
            with_settings(|s| s.tie_rule = rule),
        );
    }
}

#[test]
fn affine_instead_of_perspective_correct() {
    check(
        Bug::Affine,
        "bugs.json",
        with_settings(|s| s.mode = Interpolation::Affine),
    );
}

#[test]
fn depth_test_reversed_or_missing() {
    let (scene, texture, settings) = load("bugs.json");
    let mut mesh = scene.to_mesh();
    for v in &mut mesh.vertices {
        v.clip.z = -v.clip.z;
    }
    check(
        Bug::DepthTest,
        "bugs.json",
        pixels(&mesh, &texture, &settings),
    );
    check(Bug::DepthTest, "bugs.json", painted("bugs.json", true));
}

#[test]
fn wrong_triangle_order_without_depth_test() {
    check(Bug::TriangleOrder, "bugs.json", painted("bugs.json", false));
}

#[test]
fn bgr_channels() {
    let bgr = right("bugs.json")
        .into_iter()
        .map(|c| [c[2], c[1], c[0], c[3]])
        .collect();
    check(Bug::Bgr, "bugs.json", bgr);
}

#[test]
fn gamma_applied() {
    let g = |v: u8| ((v as f32 / 255.0).powf(1.0 / 2.2) * 255.0).round() as u8;
    let bright = right("bugs.json")
        .into_iter()
        .map(|c| [g(c[0]), g(c[1]), g(c[2]), c[3]])
        .collect();
    check(Bug::Gamma, "bugs.json", bright);
}

#[test]
fn supersampled_where_one_sample_is_asked() {
    let ssaa = with_settings(|s| {
        s.samples = SampleSettings {
            count: SampleCount::Four,
            pattern: SamplePattern::Grid,
            rate: ShadingRate::Ssaa,
            ..SampleSettings::default()
        }
    });
    check(Bug::AntiAliasing, "bugs.json", ssaa);
}

#[test]
fn one_sample_where_supersampling_is_asked() {
    // The single-sample render against the supersampled scene.
    check(Bug::AntiAliasing, "bugs-ssaa.json", right("bugs.json"));
}

#[test]
fn black_edges_under_supersampling() {
    let (out, changed) = black_edges("bugs-ssaa.json");
    assert!(changed > 10, "{changed}");
    check(Bug::BlackEdges, "bugs-ssaa.json", out);
}

#[test]
fn the_command_names_the_bug_with_its_fix_and_lists_regions() {
    let dir = tempfile::tempdir().expect("tempdir");
    let ours = right("bugs.json");
    let flipped: Vec<u8> = (0..N * N)
        .flat_map(|k| ours[(N - 1 - k / N) * N + k % N])
        .collect();
    let file = dir.path().join("flipped.png");
    image::RgbaImage::from_raw(N as u32, N as u32, flipped)
        .expect("buffer")
        .save(&file)
        .expect("png");
    let scene = scene_path("bugs.json");
    let run = |extra: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_barylab"))
            .arg("compare")
            .arg(&scene)
            .arg(&file)
            .args(extra)
            .output()
            .expect("run barylab");
        assert_eq!(out.status.code(), Some(1));
        String::from_utf8_lossy(&out.stdout).to_string()
    };
    let text = run(&[]);
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[0].starts_with("verdict: looks like y flipped"),
        "{text}"
    );
    assert!(
        lines[1].chars().all(|c| c == '=') && !lines[1].is_empty(),
        "{text}"
    );
    assert!(
        lines[2].starts_with("named bug [y_flipped] Y flipped:"),
        "{text}"
    );
    assert!(lines[2].contains("Fix: "), "{text}");
    assert!(
        text.contains("regions of connected differing pixels"),
        "{text}"
    );
    assert!(text.contains("  region 1: "), "{text}");
    assert!(text.contains("    for example ("), "{text}");
    let zh = run(&["--lang", "zh"]);
    assert!(zh.contains("已识别的错误 [y_flipped] y 方向翻转"), "{zh}");
    assert!(zh.contains("区域 1："), "{zh}");
    let json: serde_json::Value = serde_json::from_str(&run(&["--json"])).expect("json");
    assert_eq!(json["bugs"], serde_json::json!(["y_flipped"]), "{json}");
    let regions = json["regions"].as_array().expect("regions");
    assert!(!regions.is_empty());
    let total: u64 = regions
        .iter()
        .map(|r| r["pixels"].as_u64().expect("n"))
        .sum();
    assert!(
        total
            <= json["only_theirs"].as_u64().expect("n")
                + json["only_ours"].as_u64().expect("n")
                + json["color_differing"].as_u64().expect("n")
    );
    let r = &regions[0];
    let b = r["bbox"].as_array().expect("bbox");
    assert_eq!(b.len(), 4);
    assert!(
        r["reason"].as_str().is_some_and(|s| s.contains("flipped")),
        "{r}"
    );
    assert!(!r["samples"].as_array().expect("samples").is_empty());
    assert!(json["region_count"].as_u64().expect("count") >= regions.len() as u64);
}
