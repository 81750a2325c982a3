//! OBJ models and image files given in place of a scene: the shipped models draw, and every
//! kind of bad file gives a clear message naming the file (tests/data holds real files).

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::model::ModelMesh;
use barylab::raster::{NO_TRIANGLE, Shading, render};
use barylab::scene::{ModelScene, Scene};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn model_err(name: &str) -> String {
    ModelMesh::load(&data(name)).expect_err(name).to_string()
}

fn run(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn shipped_models_load_and_draw_with_a_framing_camera() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/models");
    for name in ["cube.obj", "sphere.obj", "torus.obj"] {
        let scene = ModelScene::for_model(&dir.join(name), 320, 240).expect(name);
        assert!(scene.mesh.has_uv, "{name} has uvs");
        let scene = Scene::Model(scene);
        let tex = scene.load_texture(&dir).expect("texture");
        let r = render(&scene.to_mesh(), &tex, &scene.settings()).expect("render");
        let f = &r.frame;
        let covered = f.triangle.iter().filter(|&&t| t != NO_TRIANGLE).count();
        assert!(covered > 320 * 240 / 10, "{name}: {covered} pixels");
        // Framed: nothing touches the image border.
        for x in 0..f.width {
            assert!(
                !f.covered(x, 0) && !f.covered(x, f.height - 1),
                "{name} touches top/bottom"
            );
        }
        for y in 0..f.height {
            assert!(
                !f.covered(0, y) && !f.covered(f.width - 1, y),
                "{name} touches a side"
            );
        }
    }
}

#[test]
fn cube_faces_are_drawn_with_the_mtl_colour_when_shaded_by_colour() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/models");
    let mut s = ModelScene::for_model(&dir.join("cube.obj"), 200, 150).expect("cube");
    s.shading = Some(Shading::VertexColor);
    let scene = Scene::Model(s);
    let tex = scene.load_texture(&dir).expect("texture");
    let r = render(&scene.to_mesh(), &tex, &scene.settings()).expect("render");
    let i = r.frame.index(100, 75);
    // cube.mtl: Kd 1.0 0.85 0.6.
    assert_eq!(r.frame.color[i], [255, 217, 153, 255]);
}

#[test]
fn mtl_texture_is_loaded_relative_to_the_obj() {
    let mut m = ModelScene::for_model(&data("textured.obj"), 64, 64).expect("model");
    m.filter = barylab::raster::Filter::Nearest;
    let scene = Scene::Model(m);
    let tex = scene
        .load_texture(Path::new(""))
        .expect("texture from textured.mtl");
    // rgbw.png: bottom row red, green (v = 0); top row white, blue.
    assert_eq!(tex.texel(0, 0), [255, 0, 0, 255]);
    assert_eq!(tex.texel(1, 1), [0, 0, 255, 255]);
    // The quad faces the camera and is textured: the four colours all appear.
    let r = render(&scene.to_mesh(), &tex, &scene.settings()).expect("render");
    for c in [
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [255, 255, 255, 255],
        [0, 0, 255, 255],
    ] {
        assert!(r.frame.color.contains(&c), "colour {c:?} missing");
    }
}

#[test]
fn bad_model_files_are_explained() {
    let e = model_err("empty.obj");
    assert!(
        e.contains("empty.obj") && e.contains("empty (0 bytes)"),
        "{e}"
    );
    let e = model_err("garbage.obj");
    assert!(
        e.contains("garbage.obj") && e.contains("not a readable text OBJ"),
        "{e}"
    );
    let e = model_err("out_of_range.obj");
    assert!(
        e.contains("out_of_range.obj") && e.contains("vertex index beyond"),
        "{e}"
    );
    let e = model_err("nan.obj");
    assert!(
        e.contains("nan.obj") && e.contains("vertex 2") && e.contains("not a finite"),
        "{e}"
    );
    let e = model_err("huge.obj");
    assert!(
        e.contains("huge.obj") && e.contains("vertex 2") && e.contains("larger"),
        "{e}"
    );
    let e = model_err("does-not-exist.obj");
    assert!(
        e.contains("does-not-exist.obj") && e.contains("cannot read"),
        "{e}"
    );
}

#[test]
fn recoverable_problems_become_notes() {
    let m = ModelMesh::load(&data("no_uv.obj")).expect("no_uv loads");
    assert!(!m.has_uv);
    assert!(
        m.notes.iter().any(|n| n.contains("no texture coordinates")),
        "{:?}",
        m.notes
    );
    let s = Scene::Model(ModelScene::for_model(&data("no_uv.obj"), 32, 32).expect("scene"));
    assert_eq!(s.settings().shading, Shading::Lambert);

    let m = ModelMesh::load(&data("missing_mtl.obj")).expect("missing mtl still loads");
    assert!(
        m.notes.iter().any(|n| n.contains("material library")),
        "{:?}",
        m.notes
    );
    assert!(m.has_uv);

    // A truncated last face still gives the faces before it, and says what is missing.
    let m = ModelMesh::load(&data("truncated.obj")).expect("truncated");
    assert_eq!(m.triangles.len(), 2);
}

#[test]
fn missing_or_broken_textures_name_the_file() {
    for (obj, needle) in [
        ("missing_texture.obj", "nothere.png"),
        ("broken_texture.obj", "broken_image.png"),
    ] {
        let scene = Scene::Model(ModelScene::for_model(&data(obj), 32, 32).expect(obj));
        let e = scene
            .load_texture(Path::new(""))
            .expect_err(obj)
            .to_string();
        assert!(e.contains(needle), "{obj}: {e}");
    }
}

#[test]
fn cli_takes_models_and_images_in_place_of_a_scene() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("o.png");
    let out_s = out.to_str().expect("utf-8");

    let obj = data("textured.obj");
    let (ok, stdout, stderr) = run(&[
        "render",
        obj.to_str().expect("utf-8"),
        "--size",
        "80x60",
        "-o",
        out_s,
    ]);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("2 of 2 triangles"), "{stdout}");
    assert_eq!(
        image::open(&out).expect("png").to_rgba8().dimensions(),
        (80, 60)
    );

    let img = data("rgbw.png");
    let (ok, _, stderr) = run(&[
        "render",
        img.to_str().expect("utf-8"),
        "--size",
        "80x60",
        "--filter",
        "nearest",
        "-o",
        out_s,
    ]);
    assert!(ok, "{stderr}");
    let pic = image::open(&out).expect("png").to_rgba8();
    assert!(
        pic.pixels().any(|p| p.0 == [255, 0, 0, 255]),
        "the photo's red is drawn"
    );

    let (ok, _, stderr) = run(&[
        "render",
        data("no_uv.obj").to_str().expect("utf-8"),
        "-o",
        out_s,
    ]);
    assert!(ok, "{stderr}");
    assert!(
        stderr.contains("note:") && stderr.contains("no texture coordinates"),
        "{stderr}"
    );

    for (file, needle) in [
        ("empty.png", "empty.png"),
        ("broken_image.png", "broken_image.png"),
        ("garbage.obj", "garbage.obj"),
    ] {
        let (ok, _, stderr) = run(&["render", data(file).to_str().expect("utf-8"), "-o", out_s]);
        assert!(!ok, "{file} should fail");
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
        assert!(stderr.contains(needle), "{stderr}");
    }
    let (ok, _, stderr) = run(&["render", "notes.txt", "-o", out_s]);
    assert!(!ok && stderr.contains("unknown kind of file"), "{stderr}");
}

#[test]
fn huge_images_are_downscaled_with_a_note() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("big.png");
    image::RgbaImage::from_pixel(5000, 10, image::Rgba([9, 99, 199, 255]))
        .save(&path)
        .expect("save");
    let (tex, note) = barylab::raster::Texture::load_noted(&path).expect("load");
    assert_eq!((tex.width(), tex.height()), (4096, 8));
    let note = note.expect("a note");
    assert!(
        note.contains("5000x10") && note.contains("4096x8"),
        "{note}"
    );
    assert_eq!(tex.texel(100, 3), [9, 99, 199, 255]);
}
