//! Formats and messages for bad input (issue 18): TGA by its extension, truncated images,
//! byte order marks, readable numbers, escaped and shortened file names, options named.

mod bad_input;

use bad_input::{data, fails, s, scene, succeeds};

#[test]
fn tga_is_decoded_by_its_extension_and_truncated_images_are_errors() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    let out = d("out.png");
    let picture = image::RgbaImage::from_fn(64, 64, |x, y| {
        image::Rgba([(x * 4) as u8, (y * 4) as u8, 200, 255])
    });
    picture.save(d("red.tga")).expect("tga");
    succeeds(&["render", s(&d("red.tga")), "-o", s(&out)]);
    let shown = image::open(&out).expect("png").to_rgba8();
    assert!(
        shown.pixels().any(|p| p.0[2] == 200),
        "the TGA's blue is drawn"
    );

    for (name, format) in [
        ("photo.jpg", image::ImageFormat::Jpeg),
        ("photo.png", image::ImageFormat::Png),
    ] {
        let rgb = image::DynamicImage::ImageRgba8(picture.clone()).to_rgb8();
        rgb.save_with_format(d(name), format).expect("save");
        succeeds(&["render", s(&d(name)), "-o", s(&out)]);
        let bytes = std::fs::read(d(name)).expect("read");
        let cut = d(&format!("cut-{name}"));
        std::fs::write(&cut, &bytes[..bytes.len() * 2 / 3]).expect("write");
        let e = fails(&["render", s(&cut), "-o", s(&out)]);
        assert!(e.contains("cut-photo") && e.contains("truncated"), "{e}");
    }
    // A decoder's own message is one line too.
    let e = fails(&["render", &data("broken_image.png"), "-o", s(&out)]);
    assert!(e.contains("cannot decode texture"), "{e}");
}

#[test]
fn byte_order_marks_are_accepted_in_json_and_obj() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let json = dir.path().join("bom.json");
    let text = std::fs::read_to_string(scene("front.json")).expect("front");
    std::fs::write(&json, format!("\u{feff}{text}")).expect("write");
    succeeds(&["render", s(&json), "-o", s(&out)]);
    let obj = dir.path().join("bom.obj");
    std::fs::write(&obj, "\u{feff}v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("write");
    succeeds(&["render", s(&obj), "-o", s(&out)]);
}

#[test]
fn scene_messages_say_what_is_wrong_in_words() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).expect("write");
        p
    };
    let e = fails(&["render", s(&write("null.json", "null")), "-o", s(&out)]);
    assert!(
        e.contains("null.json: is not a scene: a scene is a JSON object")
            && e.ends_with("this file holds null\n"),
        "{e}"
    );
    assert!(!e.contains("struct") && !e.contains("Probe"), "{e}");
    let camera_null = std::fs::read_to_string(scene("default.json"))
        .expect("default")
        .replacen("\"camera\": {", "\"camera\": null, \"x\": {", 1);
    let e = fails(&["render", s(&write("cam.json", &camera_null)), "-o", s(&out)]);
    assert!(!e.contains("struct"), "{e}");

    let four = r#"{"width":4,"height":4,"vertices":[{"clip":[0,0,0,1]}],"triangles":[[0,0,0,0]]}"#;
    let e = fails(&["render", s(&write("four.json", four)), "-o", s(&out)]);
    assert!(
        e.contains("triangles[0]") && e.contains("exactly 3 vertex indices"),
        "{e}"
    );
    assert!(!e.contains("trailing characters"), "{e}");

    let far = std::fs::read_to_string(scene("default.json"))
        .expect("default")
        .replace("\"far\": 100.0", "\"far\": 1e308");
    assert!(far.contains("1e308"));
    let e = fails(&["render", s(&write("far.json", &far)), "-o", s(&out)]);
    assert!(
        e.contains("far.json") && e.contains("far plane is 1e308"),
        "{e}"
    );
    assert!(e.len() < 200, "{e}");
}

#[test]
fn options_are_named_and_checked_once() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    for (option, value, pixel) in [
        ("--pixel", "900,9", "(900, 9)"),
        ("--hover", "9,900", "(9, 900)"),
    ] {
        let e = fails(&[
            "figure",
            &scene("default.json"),
            option,
            value,
            "-o",
            s(&out),
        ]);
        assert_eq!(e.matches("outside").count(), 1, "{e}");
        assert!(
            e.contains(&format!(
                "default.json: {option} {value}: pixel {pixel} is outside the 800x600 image"
            )),
            "{e}"
        );
    }
    let e = fails(&["probe", &scene("default.json"), "--pixel", "800,0"]);
    assert!(
        e.contains("--pixel 800,0: pixel (800, 0) is outside") && e.matches("outside").count() == 1,
        "{e}"
    );
    let e = fails(&[
        "render",
        &scene("default.json"),
        "--size",
        "-5x10",
        "-o",
        s(&out),
    ]);
    assert!(e.contains("`-5x10` is not a size like 800x600"), "{e}");
    assert!(!out.exists());
    // The app's screenshot path is checked before a window opens.
    let e = fails(&["--fresh", "--screenshot", s(&dir.path().join("shot.jpg"))]);
    assert!(
        e.contains("shot.jpg") && e.contains("must be a .png file"),
        "{e}"
    );
}

#[test]
fn file_names_in_messages_are_escaped_and_shortened() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let odd = dir.path().join("a\u{1b}[31mred\nname.json");
    std::fs::write(&odd, "{").expect("write");
    let e = fails(&["render", s(&odd), "-o", s(&out)]);
    assert!(
        !e.contains('\u{1b}') && e.contains("a\\u{1b}[31mred\\nname.json"),
        "{e}"
    );
    let long = format!("{}/{}.json", dir.path().display(), "x".repeat(100_000));
    let e = fails(&["render", &long, "-o", s(&out)]);
    assert!(
        e.len() < 600 && e.contains('…') && e.contains("xx.json"),
        "{} bytes",
        e.len()
    );
}

#[test]
fn a_model_without_uvs_gets_a_note_that_matches_its_shading() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let notes = succeeds(&["render", &data("no_uv.obj"), "-o", s(&out)]);
    assert!(
        notes.contains("no texture coordinates") && notes.contains("lit by a headlight"),
        "{notes}"
    );
    let notes = succeeds(&[
        "render",
        &data("no_uv.obj"),
        "--shading",
        "texture",
        "-o",
        s(&out),
    ]);
    assert!(
        notes.contains("no texture coordinates") && notes.contains("one colour"),
        "{notes}"
    );
    assert!(!notes.contains("vertex colour"), "{notes}");
    let notes = succeeds(&[
        "render",
        &data("no_uv.obj"),
        "--shading",
        "depth",
        "-o",
        s(&out),
    ]);
    assert!(
        notes.contains("no texture coordinates") && !notes.contains("colour"),
        "{notes}"
    );
}
