//! Scene files: the samples load and draw, and bad files give messages naming the file,
//! the position and the field.

use std::path::Path;

use barylab::raster::{NO_TRIANGLE, render};
use barylab::scene::{Scene, SceneError};

fn scenes_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/scenes"))
}

fn err(text: &str) -> String {
    Scene::from_json(text, "bad.json")
        .expect_err("scene should be rejected")
        .to_string()
}

#[test]
fn default_json_is_the_built_in_default_scene() {
    let file = Scene::load(&scenes_dir().join("default.json")).expect("default.json");
    assert_eq!(file, Scene::default_scene());
}

#[test]
fn every_sample_scene_loads_draws_and_round_trips() {
    let mut n = 0;
    for entry in std::fs::read_dir(scenes_dir()).expect("scenes dir") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("json") {
            continue;
        }
        n += 1;
        let scene = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        // Named as a file in the scenes folder, so that a model path resolves as it did.
        let name = scenes_dir().join("round-trip.json");
        let again =
            Scene::from_json(&scene.to_json(), name.to_str().expect("utf-8")).expect("round trip");
        assert_eq!(scene, again, "{}", path.display());
        let tex = scene.load_texture(scenes_dir()).expect("texture");
        let r = render(&scene.to_mesh(), &tex, &scene.settings()).expect("render");
        let covered = r
            .frame
            .triangle
            .iter()
            .filter(|&&t| t != NO_TRIANGLE)
            .count();
        assert!(
            covered > 100,
            "{} covers only {covered} pixels",
            path.display()
        );
        assert!(r.frame.depth.iter().all(|d| d.is_finite()));
    }
    assert!(n >= 6, "only {n} sample scenes");
}

#[test]
fn unknown_field_is_an_error_naming_file_position_and_field() {
    let text = r#"{
  "width": 10, "height": 10,
  "vertices": [{"clip": [0, 0, 0, 1], "uv": [0, 0], "colour": [1, 0, 0]}],
  "triangles": []
}"#;
    let e = err(text);
    assert!(e.starts_with("bad.json:3:"), "{e}");
    assert!(e.contains("vertices[0]"), "{e}");
    assert!(e.contains("unknown field `colour`"), "{e}");
}

#[test]
fn wrong_type_names_the_field() {
    let text = r#"{"width": 10, "height": 10, "quad": [
        {"position": [0, 0, "x"], "uv": [0, 0]},
        {"position": [1, 0, 0], "uv": [1, 0]},
        {"position": [1, 1, 0], "uv": [1, 1]},
        {"position": [0, 1, 0], "uv": [0, 1]}]}"#;
    let e = err(text);
    assert!(e.starts_with("bad.json:2:"), "{e}");
    assert!(e.contains("quad[0].position"), "{e}");
}

#[test]
fn syntax_error_gives_line_and_column() {
    let e = err("{\n  \"width\": 10,\n  \"height\": ,\n}");
    assert!(e.starts_with("bad.json:3:13:"), "{e}");
}

#[test]
fn structural_problems_are_explained() {
    assert!(err(r#"{"width": 4, "height": 4}"#).contains("has none of `quad`"));
    let e = err(
        r#"{"width": 4, "height": 4, "vertices": [{"clip": [0,0,0,1]}], "triangles": [[0, 0, 3]]}"#,
    );
    assert!(
        e.contains("triangles[0]") && e.contains("vertex 3") && e.contains("only 1"),
        "{e}"
    );
    let e = err(r#"{"width": 0, "height": 4, "vertices": [], "triangles": []}"#);
    assert!(e.contains("image size 0x4"), "{e}");
    let quad = r#"[{"position":[0,0,0],"uv":[0,0]},{"position":[1,0,0],"uv":[0,0]},
                   {"position":[1,1,0],"uv":[0,0]},{"position":[0,1,0],"uv":[0,0]}]"#;
    let e = err(&format!(
        r#"{{"width": 4, "height": 4, "quad": {quad}, "camera": {{"eye": [0,0,1], "target": [0,0,1],
           "projection": {{"kind": "perspective", "fov_y_deg": 60, "near": 0.1, "far": 10}}}}}}"#
    ));
    assert!(e.contains("camera") && e.contains("same point"), "{e}");
    let e = err(&format!(
        r#"{{"width": 4, "height": 4, "quad": {quad}, "camera": {{"eye": [0,0,1], "target": [0,0,0],
           "projection": {{"kind": "perspective", "fov_y_deg": 60, "near": 0, "far": 10}}}}}}"#
    ));
    assert!(e.contains("near plane 0"), "{e}");
}

#[test]
fn texture_problems_name_the_texture_file() {
    let dir = tempfile::tempdir().expect("tempdir");
    let scene_path = dir.path().join("s.json");
    let text = std::fs::read_to_string(scenes_dir().join("front.json"))
        .expect("front.json")
        .replace("\"uv-grid\"", "\"pics/missing.png\"");
    std::fs::write(&scene_path, &text).expect("write");
    let scene = Scene::load(&scene_path).expect("scene itself is fine");
    let e = scene.load_texture(dir.path()).expect_err("missing texture");
    assert!(matches!(e, SceneError::Texture(_)));
    assert!(e.to_string().contains("pics/missing.png"), "{e}");

    std::fs::create_dir_all(dir.path().join("pics")).expect("mkdir");
    std::fs::write(dir.path().join("pics/missing.png"), b"not a png at all").expect("write");
    let e = scene.load_texture(dir.path()).expect_err("garbage texture");
    let msg = e.to_string();
    assert!(
        msg.contains("cannot decode") && msg.contains("missing.png"),
        "{msg}"
    );
}

#[test]
fn texture_file_is_loaded_relative_to_the_scene_and_flipped_so_v0_is_the_bottom() {
    let dir = tempfile::tempdir().expect("tempdir");
    // A 1x2 image: top pixel blue, bottom pixel red.
    let mut img = image::RgbaImage::new(1, 2);
    img.put_pixel(0, 0, image::Rgba([0, 0, 255, 255]));
    img.put_pixel(0, 1, image::Rgba([255, 0, 0, 255]));
    img.save(dir.path().join("tex.png")).expect("save");
    let text = std::fs::read_to_string(scenes_dir().join("front.json"))
        .expect("front.json")
        .replace("\"uv-grid\"", "\"tex.png\"");
    let scene = Scene::from_json(&text, "s.json").expect("scene");
    let tex = scene.load_texture(dir.path()).expect("texture");
    assert_eq!(tex.texel(0, 0), [255, 0, 0, 255]);
    assert_eq!(tex.texel(0, 1), [0, 0, 255, 255]);
}

#[test]
fn triangle_indices_match_the_mesh_without_building_it() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scenes: Vec<Scene> = std::fs::read_dir(dir.join("assets/scenes"))
        .expect("scenes")
        .map(|e| Scene::load(&e.expect("entry").path()).expect("scene"))
        .collect();
    scenes.push(
        barylab::scene::open_input(&dir.join("assets/models/torus.obj"))
            .expect("torus")
            .0,
    );
    for s in scenes {
        let mesh = s.to_mesh();
        for i in 0..=mesh.triangles.len() {
            assert_eq!(s.triangle(i), mesh.triangles.get(i).copied());
        }
    }
}
