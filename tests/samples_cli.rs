//! Samples in scene files, on the command line and in the probe: the six fields and
//! options, their errors, `render --samples`, and `probe --format json`'s samples.

use std::process::{Command, Output};

use barylab::raster::render::{render, render_samples};
use barylab::raster::sample::{
    Location, ProvokingVertex, SampleCount, SamplePattern, SampleSettings, ShadingRate,
};
use barylab::raster::{NO_TRIANGLE, Texture};
use barylab::scene::Scene;

const CLIP: &str = r#"{
  "width": 24, "height": 18,
  "vertices": [
    { "clip": [-0.9, -0.9, 0.0, 1.0], "uv": [0.0, 0.0] },
    { "clip": [0.9, -0.7, 0.0, 1.0], "uv": [1.0, 0.0] },
    { "clip": [1.6, 2.2, 0.0, 2.5], "uv": [1.0, 1.0] },
    { "clip": [-2.1, 2.4, 0.0, 3.0], "uv": [0.0, 1.0] }
  ],
  "triangles": [[0, 1, 2], [0, 2, 3]],
  "texture": "checker",
  "filter": "nearest"
  FIELDS
}"#;

fn scene_text(fields: &str) -> String {
    CLIP.replace("  FIELDS", fields)
}

fn barylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab")
}

fn write_scene(dir: &std::path::Path, fields: &str) -> String {
    let path = dir.join("s.json");
    std::fs::write(&path, scene_text(fields)).expect("write scene");
    path.to_str().expect("utf-8").to_string()
}

#[test]
fn the_six_fields_are_read_written_and_default_to_one_centre_sample() {
    let text = scene_text(
        r#", "samples": 4, "sample_pattern": "grid", "shading_rate": "ssaa",
        "location": "centroid", "flat": true, "provoking_vertex": "first""#,
    );
    let scene = Scene::from_json(&text, "s.json").expect("scene");
    let want = SampleSettings {
        count: SampleCount::Four,
        pattern: SamplePattern::Grid,
        rate: ShadingRate::Ssaa,
        location: Location::Centroid,
        flat: true,
        provoking: ProvokingVertex::First,
    };
    assert_eq!(scene.settings().samples, want);
    let again = Scene::from_json(&scene.to_json(), "s.json").expect("round trip");
    assert_eq!(again.settings().samples, want);
    assert!(scene.to_json().contains("\"samples\": 4"));
    let plain = Scene::from_json(&scene_text(""), "s.json").expect("scene");
    assert_eq!(plain.settings().samples, SampleSettings::default());
    assert!(!plain.to_json().contains("samples"), "{}", plain.to_json());
}

#[test]
fn bad_values_name_the_file_and_the_field() {
    for (fields, words) in [
        (r#", "samples": 3"#, ["samples", "1, 4, 8 or 16"]),
        (r#", "location": "middle""#, ["location", "centroid"]),
        (r#", "shading_rate": "fast""#, ["shading_rate", "ssaa"]),
        (
            r#", "samples": 8, "sample_pattern": "grid""#,
            ["sample_pattern", "grid"],
        ),
        (r#", "flat": "yes""#, ["flat", "boolean"]),
    ] {
        let err = Scene::from_json(&scene_text(fields), "bad.json")
            .expect_err(fields)
            .to_string();
        assert!(err.starts_with("bad.json"), "{fields}: {err}");
        for w in words {
            assert!(err.contains(w), "{fields}: `{err}` lacks `{w}`");
        }
    }
}

#[test]
fn render_with_samples_writes_the_resolved_image() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = write_scene(dir.path(), "");
    let out = dir.path().join("4x.png");
    let o = barylab(&[
        "render",
        &scene,
        "-o",
        out.to_str().expect("utf-8"),
        "--samples",
        "4",
        "--location",
        "centroid",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let png = image::open(&out).expect("png").to_rgba8();
    let mut s = Scene::load(std::path::Path::new(&scene)).expect("scene");
    let samples = SampleSettings {
        count: SampleCount::Four,
        location: Location::Centroid,
        ..SampleSettings::default()
    };
    s.set_samples(samples);
    let tex = s.load_texture(dir.path()).expect("texture");
    let r = render(&s.to_mesh(), &tex, &s.settings()).expect("render");
    assert!(
        png == r.frame.to_image().expect("image"),
        "the PNG is not the library's resolve"
    );
    // And it is anti-aliased: some pixel is neither background nor the single-sample one.
    s.set_samples(SampleSettings::default());
    let one = render(&s.to_mesh(), &tex, &s.settings()).expect("render");
    assert!(one.frame.color != r.frame.color);
}

#[test]
fn bad_options_fail_on_one_line() {
    let dir = tempfile::tempdir().expect("temp dir");
    let scene = write_scene(dir.path(), "");
    let out = dir.path().join("x.png");
    let out = out.to_str().expect("utf-8");
    for (args, word) in [
        (vec!["--samples", "3"], "1, 4, 8 or 16"),
        (vec!["--samples", "8", "--sample-pattern", "grid"], "grid"),
        (vec!["--provoking-vertex", "middle"], "first"),
    ] {
        let mut all = vec!["render", scene.as_str(), "-o", out];
        all.extend(&args);
        let o = barylab(&all);
        assert!(!o.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(word), "{args:?}: {err}");
    }
    assert!(!std::path::Path::new(out).exists());
}

/// A pixel the first triangle covers only partly: the probe's samples are the render's, and
/// the centroid lands on the lowest covered sample.
#[test]
fn the_probe_lists_every_sample_and_where_the_centroid_landed() {
    let dir = tempfile::tempdir().expect("temp dir");
    let fields = r#", "samples": 4, "location": "centroid""#;
    let scene_path = write_scene(dir.path(), fields);
    let scene = Scene::load(std::path::Path::new(&scene_path)).expect("scene");
    let tex: Texture = scene.load_texture(dir.path()).expect("texture");
    let (r, samples) = render_samples(&scene.to_mesh(), &tex, &scene.settings()).expect("render");
    let (x, y) = (0..18u32)
        .flat_map(|y| (0..24u32).map(move |x| (x, y)))
        .find(|&(x, y)| {
            let p = samples.pixel(x, y);
            p[0].triangle == NO_TRIANGLE && p.iter().any(|s| s.triangle == 0)
        })
        .expect("a pixel partly covered by triangle 0, sample 0 not");
    let o = barylab(&[
        "probe",
        &scene_path,
        "--pixel",
        &format!("{x},{y}"),
        "--format",
        "json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let list = json["samples"].as_array().expect("samples");
    assert_eq!(list.len(), 4);
    let first = samples.pixel(x, y).iter().position(|s| s.triangle == 0);
    for (k, (j, s)) in list.iter().zip(samples.pixel(x, y)).enumerate() {
        assert_eq!(j["index"], k);
        let covered = s.triangle != NO_TRIANGLE;
        assert_eq!(j["covered"], covered);
        if covered {
            assert_eq!(j["triangle"], s.triangle);
            let uv = [0, 1].map(|c| j["uv"][c].as_f64().map(|v| v as f32));
            assert_eq!(uv, [Some(s.uv[0]), Some(s.uv[1])]);
            assert_eq!(j["depth"].as_f64().map(|v| v as f32), Some(s.depth));
        } else {
            assert!(j["triangle"].is_null() && j["uv"].is_null() && j["depth"].is_null());
        }
    }
    let t0 = &json["sample_shading"]["triangles"][0];
    assert_eq!(t0["triangle"], 0);
    assert_eq!(t0["centroid_sample"].as_u64(), first.map(|k| k as u64));
    let k = first.expect("covered");
    assert_eq!(t0["evaluated_at"], list[k]["position"]);
    let color = r.frame.color[r.frame.index(x, y)];
    assert_eq!(json["color"], serde_json::json!(color));
    // The text names the centroid's choice, in Chinese too.
    let zh = barylab(&[
        "probe",
        &scene_path,
        "--pixel",
        &format!("{x},{y}"),
        "--lang",
        "zh",
    ]);
    let text = String::from_utf8_lossy(&zh.stdout);
    assert!(text.contains("采样点") && text.contains("质心"), "{text}");
}

/// The LaTeX probe has the samples section the text and Markdown probes have (the same
/// document): each sample's coverage and the resolve, escaped for LaTeX.
#[test]
fn the_latex_probe_lists_the_samples() {
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/scenes/games101-a2-ssaa.json");
    let out = barylab(&[
        "probe",
        scene.to_str().expect("utf-8"),
        "--size",
        "120x120",
        "--pixel",
        "83,42",
        "--format",
        "latex",
    ]);
    assert!(out.status.success());
    let tex = String::from_utf8_lossy(&out.stdout);
    assert!(tex.contains(". The samples}"), "{tex}");
    assert!(
        tex.contains("sample 1 at (83.75, 42.25): covered by triangle 1"),
        "{tex}"
    );
    assert!(tex.contains("Triangle 0 covers samples 0, 2, 3"), "{tex}");
    assert!(
        tex.contains("rgba(209, 233, 198, 255) = \\#d1e9c6"),
        "{tex}"
    );
}
