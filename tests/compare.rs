//! `barylab compare` on images made by hand: barylab's own render agrees; renders made the
//! wrong way (affine, y flipped, rotated, sampled at integer coordinates) are named as such,
//! with a reason per pixel; bad input is one line naming the file.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod common;

use barylab::compare::hypotheses::shifted;
use barylab::raster::{Interpolation, RenderSettings, render};
use barylab::scene::Scene;

fn barylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab")
}

fn scene(name: &str) -> String {
    format!("{}/assets/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

/// barylab's render of a scene file with `change` applied to the settings and `mesh_change`
/// to the mesh, saved as PNG.
fn make_image(
    name: &str,
    dir: &Path,
    file: &str,
    change: impl Fn(&mut RenderSettings),
    mesh_change: impl Fn(barylab::raster::ClipMesh, &RenderSettings) -> barylab::raster::ClipMesh,
) -> PathBuf {
    let path = scene(name);
    let scene = Scene::load(Path::new(&path)).expect("scene");
    let texture = scene
        .load_texture(Path::new(&path).parent().expect("folder"))
        .expect("texture");
    let mut settings = scene.settings();
    change(&mut settings);
    let mesh = mesh_change(scene.to_mesh(), &settings);
    let out = render(&mesh, &texture, &settings).expect("render");
    let file = dir.join(file);
    out.frame
        .to_image()
        .expect("image")
        .save(&file)
        .expect("save");
    file
}

fn as_is(m: barylab::raster::ClipMesh, _: &RenderSettings) -> barylab::raster::ClipMesh {
    m
}

fn compare(args: &[&str]) -> (Option<i32>, String, String) {
    let mut all = vec!["compare"];
    all.extend(args);
    let out = barylab(&all);
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

#[test]
fn barylabs_own_render_agrees() {
    let dir = tempfile::tempdir().expect("tempdir");
    for name in [
        "default.json",
        "vertex-colors.json",
        "clip-two-triangles.json",
    ] {
        let right = make_image(name, dir.path(), "right.png", |_| {}, as_is);
        let (code, out, err) = compare(&[&scene(name), s(&right)]);
        assert_eq!(code, Some(0), "{name}: {out}{err}");
        assert!(out.contains("verdict: the images agree"), "{out}");
        assert!(out.contains("coverage: 0 pixels differ"), "{out}");
    }
}

#[test]
fn affine_interpolation_is_named_with_the_uv_difference_in_texels() {
    let dir = tempfile::tempdir().expect("tempdir");
    let wrong = make_image(
        "default.json",
        dir.path(),
        "affine.png",
        |s| s.mode = Interpolation::Affine,
        as_is,
    );
    let diff = dir.path().join("diff.png");
    let (code, out, err) = compare(&[&scene("default.json"), s(&wrong), "-o", s(&diff)]);
    assert_eq!(code, Some(1), "{out}{err}");
    assert!(out.contains("verdict: looks like affine"), "{out}");
    assert!(
        out.contains("texels between perspective-correct and affine"),
        "{out}"
    );
    assert!(err.contains("differs from barylab's render"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    // The difference image: the scene's size, red to yellow where colours differ.
    let d = image::open(&diff).expect("diff.png").to_rgba8();
    assert_eq!(d.dimensions(), (800, 600));
    assert!(d.pixels().any(|p| p.0[0] == 255 && p.0[2] == 0));
    // The texels named are the heatmap's and the inspector's measure: the length of the uv
    // offset in texels, from barylab's own render of the scene.
    let (_, json, _) = compare(&[&scene("default.json"), s(&wrong), "--json"]);
    let json: serde_json::Value = serde_json::from_str(&json).expect("json");
    let first = &json["first"][0];
    assert_eq!(first["why"]["kind"], "other_mode", "{first}");
    let texels = first["why"]["texels"].as_f64().expect("texels") as f32;
    let [x, y] = [0, 1].map(|i| first["pixel"][i].as_u64().expect("pixel") as u32);
    let path = scene("default.json");
    let sc = Scene::load(Path::new(&path)).expect("scene");
    let tex = sc
        .load_texture(Path::new(&path).parent().expect("folder"))
        .expect("texture");
    let out = render(&sc.to_mesh(), &tex, &sc.settings()).expect("render");
    let k = (y * out.frame.width + x) as usize;
    let expected = barylab::figure::heatmap::texel_difference(
        out.frame.uv_affine[k],
        out.frame.uv_perspective[k],
        (tex.width(), tex.height()),
    );
    // (Up to the JSON's rounding of an f32.)
    assert!(
        (texels - expected).abs() < 1e-5,
        "at ({x}, {y}): {texels} against {expected}"
    );
}

#[test]
fn flipped_and_rotated_images_are_named() {
    let dir = tempfile::tempdir().expect("tempdir");
    let right = make_image("vertex-colors.json", dir.path(), "right.png", |_| {}, as_is);
    let img = image::open(&right).expect("png");
    let flipped = dir.path().join("flipped.png");
    img.flipv().save(&flipped).expect("save");
    let rotated = dir.path().join("rotated.png");
    img.rotate180().save(&rotated).expect("save");
    let (code, out, _) = compare(&[&scene("vertex-colors.json"), s(&flipped)]);
    assert_eq!(code, Some(1));
    assert!(out.contains("verdict: looks like y flipped"), "{out}");
    assert!(
        out.contains("agrees with barylab's image flipped upside down"),
        "{out}"
    );
    let (code, out, _) = compare(&[&scene("vertex-colors.json"), s(&rotated), "--json"]);
    assert_eq!(code, Some(1));
    let json: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(
        json["looks_like"]
            .as_str()
            .is_some_and(|l| l.contains("rotated by 180 degrees")),
        "{json}"
    );
    assert_eq!(json["hypotheses"][0]["kind"], "rotated180");
    assert_eq!(json["hypotheses"][0]["differing"], 0);
}

#[test]
fn samples_at_integer_coordinates_are_named() {
    let dir = tempfile::tempdir().expect("tempdir");
    // Sampling at (x, y) is the geometry moved by half a pixel right and down.
    let wrong = make_image(
        "clip-two-triangles.json",
        dir.path(),
        "integer.png",
        |_| {},
        |m, s| shifted(&m, s.width, s.height, 0.5, 0.5),
    );
    let (code, out, _) = compare(&[&scene("clip-two-triangles.json"), s(&wrong)]);
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("verdict: looks like pixel centres at integer coordinates"),
        "{out}"
    );
}

#[test]
fn a_few_pixels_off_get_reasons_from_the_probe() {
    let dir = tempfile::tempdir().expect("tempdir");
    let right = make_image("vertex-colors.json", dir.path(), "right.png", |_| {}, as_is);
    let mut img = image::open(&right).expect("png").to_rgba8();
    // One covered pixel recoloured, one uncovered pixel painted: nothing whole-image fits.
    img.put_pixel(240, 180, image::Rgba([0, 0, 0, 255]));
    img.put_pixel(2, 2, image::Rgba([255, 255, 255, 255]));
    let edited = dir.path().join("edited.png");
    img.save(&edited).expect("save");
    let (code, out, _) = compare(&[&scene("vertex-colors.json"), s(&edited), "--json"]);
    assert_eq!(code, Some(1), "{out}");
    let json: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert!(json["looks_like"].is_null(), "{json}");
    assert_eq!(json["only_theirs"], 1, "{json}");
    assert_eq!(json["color_differing"], 1, "{json}");
    let first = json["first"].as_array().expect("first");
    assert_eq!(first.len(), 2);
    assert_eq!(first[0]["pixel"], serde_json::json!([2, 2]));
    assert_eq!(first[0]["difference"], "only_theirs");
    assert!(
        first[0]["reason"]
            .as_str()
            .is_some_and(|r| r.contains("outside edge") || r.contains("no triangle comes near")),
        "{json}"
    );
    assert_eq!(first[1]["difference"], "color");
    assert!(
        first[1]["reason"]
            .as_str()
            .is_some_and(|r| r.contains("colour differs by")),
        "{json}"
    );
}

#[test]
fn bad_images_are_one_line_naming_the_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let one_line = |args: &[&str], needle: &str| {
        let (code, out, err) = compare(args);
        assert_eq!(code, Some(1), "{args:?}: {out}{err}");
        assert!(out.is_empty(), "{out}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(needle), "{args:?}: {err}");
        err
    };
    let missing = dir.path().join("missing.png");
    one_line(&[&scene("default.json"), s(&missing)], "missing.png");
    let text = dir.path().join("notes.png");
    std::fs::write(&text, "not an image").expect("write");
    one_line(&[&scene("default.json"), s(&text)], "notes.png");
    let small = dir.path().join("small.png");
    image::RgbaImage::new(64, 48).save(&small).expect("save");
    let err = one_line(&[&scene("default.json"), s(&small)], "small.png");
    assert!(err.contains("64x48") && err.contains("800x600"), "{err}");
    // The same image at its size compares (and differs: it is all transparent).
    let (code, _, _) = compare(&[&scene("default.json"), s(&small), "--size", "64x48"]);
    assert_eq!(code, Some(1));
    // The difference image is never written over an input.
    let right = make_image("default.json", dir.path(), "right.png", |_| {}, as_is);
    let before = std::fs::read(&right).expect("read");
    one_line(
        &[&scene("default.json"), s(&right), "-o", s(&right)],
        "it is an input",
    );
    assert_eq!(std::fs::read(&right).expect("read"), before);
    // A usage error (exit 2), one line.
    let (code, _, err) = compare(&[&scene("default.json"), s(&right), "--background", "purple"]);
    assert_eq!(code, Some(2));
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("`purple` is not a colour"), "{err}");
}

#[test]
fn coverage_by_alpha_when_the_image_is_transparent() {
    let dir = tempfile::tempdir().expect("tempdir");
    let clear = make_image(
        "clip-two-triangles.json",
        dir.path(),
        "clear.png",
        |s| s.background = [0, 0, 0, 0],
        as_is,
    );
    let (code, out, err) = compare(&[&scene("clip-two-triangles.json"), s(&clear)]);
    assert_eq!(code, Some(0), "{out}{err}");
    assert!(out.contains("covered: alpha of at least 128"), "{out}");
    assert!(out.contains("verdict: the images agree"), "{out}");
}

/// GAMES101 Assignment 2: barylab's render agrees; the course's usual mistakes are named.
#[test]
fn games101_assignment_2_mistakes_are_named() {
    let dir = tempfile::tempdir().expect("tempdir");
    let a2 = scene("games101-a2.json");
    let run = |image: &Path| compare(&[&a2, s(image), "--background", "black"]);
    let right = make_image("games101-a2.json", dir.path(), "right.png", |_| {}, as_is);
    let (code, out, err) = run(&right);
    assert_eq!(code, Some(0), "{out}{err}");
    // The depth test reversed (z sign): the far triangle drawn over the near one.
    let reversed = make_image(
        "games101-a2.json",
        dir.path(),
        "reversed.png",
        |_| {},
        |mut m, _| {
            for v in &mut m.vertices {
                v.clip.z = -v.clip.z;
            }
            m
        },
    );
    let (code, out, _) = run(&reversed);
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.starts_with("verdict: looks like a reversed depth test"),
        "{out}"
    );
    assert!(out.contains("named bug [depth_test]"), "{out}");
    // The projection's w with the wrong sign: the picture turned by 180 degrees.
    let img = image::open(&right).expect("png");
    let rotated = dir.path().join("rotated.png");
    img.rotate180().save(&rotated).expect("save");
    let (_, out, _) = run(&rotated);
    assert!(
        out.contains("verdict: looks rotated by 180 degrees"),
        "{out}"
    );
    // insideTriangle(int x, int y, ...) truncating x + 0.5: samples at integer coordinates,
    // in the framework's y-up rows.
    let integer = make_image(
        "games101-a2.json",
        dir.path(),
        "integer.png",
        |_| {},
        |m, s| shifted(&m, s.width, s.height, 0.5, -0.5),
    );
    let (_, out, _) = run(&integer);
    assert!(
        out.contains("verdict: looks like pixel centres at integer coordinates"),
        "{out}"
    );
}

/// The English fragments of the `compare` catalogue section (between placeholders, with two
/// or more English words besides names), which a Chinese report must not contain.
fn english_fragments() -> Vec<String> {
    let path = format!("{}/locales/en.yml", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("catalogue");
    let value: serde_yaml::Value = serde_yaml::from_str(&text).expect("YAML");
    fn strings(v: &serde_yaml::Value, out: &mut Vec<String>) {
        match v {
            serde_yaml::Value::Mapping(m) => m.values().for_each(|v| strings(v, out)),
            serde_yaml::Value::String(s) => out.push(s.clone()),
            _ => {}
        }
    }
    let mut all = Vec::new();
    strings(&value["compare"], &mut all);
    assert!(all.len() > 50, "the compare section: {}", all.len());
    let names = [
        "barylab", "OpenGL", "Mesa", "llvmpipe", "MSAA", "Vulkan", "GPU",
    ];
    let mut out = Vec::new();
    for s in all {
        let mut rest = s.as_str();
        loop {
            let (piece, next) = match rest.find("%{") {
                Some(i) => (&rest[..i], rest[i..].find('}').map(|j| &rest[i + j + 1..])),
                None => (rest, None),
            };
            let words = piece
                .split(|c: char| !c.is_ascii_alphabetic())
                .filter(|w| w.len() >= 3 && !names.contains(w))
                .count();
            if words >= 2 {
                out.push(piece.trim().to_string());
            }
            match next {
                Some(n) => rest = n,
                None => break,
            }
        }
    }
    out
}

#[test]
fn the_report_and_the_reasons_are_chinese_with_lang_zh() {
    let dir = tempfile::tempdir().expect("tempdir");
    let affine = make_image(
        "default.json",
        dir.path(),
        "affine.png",
        |s| s.mode = Interpolation::Affine,
        as_is,
    );
    let right = make_image("vertex-colors.json", dir.path(), "right.png", |_| {}, as_is);
    let flipped = dir.path().join("flipped.png");
    image::open(&right)
        .expect("png")
        .flipv()
        .save(&flipped)
        .expect("save");
    let english = english_fragments();
    for (name, image, words) in [
        ("default.json", &affine, ["结论：看起来像仿射插值", "纹素"]),
        (
            "vertex-colors.json",
            &flipped,
            ["结论：看起来 y 方向被翻转了", "上下翻转后的 barylab 图像"],
        ),
    ] {
        let (code, out, err) = compare(&[&scene(name), s(image), "--lang", "zh"]);
        assert_eq!(code, Some(1), "{out}{err}");
        for w in words {
            assert!(out.contains(w), "{w}: {out}");
        }
        assert!(out.contains("个由相连的不同像素组成的区域"), "{out}");
        for e in &english {
            assert!(!out.contains(e.as_str()), "English {e:?} in: {out}");
            assert!(!err.contains(e.as_str()), "English {e:?} in: {err}");
        }
        assert!(err.contains("个不同"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        // The same in English names the English words, and JSON stays English.
        let (_, en, _) = compare(&[&scene(name), s(image), "--lang", "en"]);
        assert!(en.contains("verdict: looks"), "{en}");
        let (_, json, _) = compare(&[&scene(name), s(image), "--lang", "zh", "--json"]);
        let json: serde_json::Value = serde_json::from_str(&json).expect("json");
        assert!(
            json["looks_like"]
                .as_str()
                .is_some_and(|l| l.starts_with("looks")),
            "{json}"
        );
        let first = &json["first"][0];
        assert!(first["why"]["kind"].is_string(), "{json}");
        assert!(
            first["reason"].as_str().is_some_and(|r| r.is_ascii()),
            "{json}"
        );
    }
    assert_eq!(
        compare(&[&scene("default.json"), s(&affine), "--json"]).1,
        compare(&[&scene("default.json"), s(&affine), "--json", "--lang", "zh"]).1,
        "JSON is the same in every language"
    );
}

/// What a comparison reads of barylab's render (colour, coverage by triangle, both uvs) is the
/// same from the fast path's render (`render_for_comparison`) as from the full render, with
/// both rasterizers, so the comparison does not depend on which one made it.
#[test]
fn the_comparison_render_equals_the_full_render_where_a_comparison_reads_it() {
    use barylab::compare::render_for_comparison;
    let names = [
        "default.json",
        "bench-1080p.json",
        "corner-behind.json",
        "vertex-colors.json",
    ];
    let variants = common::scene_variants(&names, (320, 240));
    for (what, mesh, tex, s) in &variants {
        let full = render(mesh, tex, s).expect("full render").frame;
        let fast = render_for_comparison(mesh, tex, s)
            .expect("fast render")
            .frame;
        assert_eq!(fast.color, full.color, "{what}: colour");
        assert_eq!(fast.triangle, full.triangle, "{what}: triangle");
        assert_eq!(fast.uv_affine, full.uv_affine, "{what}: affine uv");
        assert_eq!(
            fast.uv_perspective, full.uv_perspective,
            "{what}: perspective uv"
        );
    }
    assert_eq!(variants.len(), 16);
}
