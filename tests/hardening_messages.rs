//! Hardening, round 2 (issue 30): each message names the file and the real problem in plain
//! words.

mod bad_input;

use std::path::Path;

use bad_input::{bin, fails, s, scene, stderr, succeeds};

/// The default scene with `field` set to the JSON `value`, written to `dir/name`.
fn scene_with(dir: &Path, name: &str, field: &str, value: serde_json::Value) -> String {
    let text = std::fs::read_to_string(scene("default.json")).expect("default scene");
    let mut v: serde_json::Value = serde_json::from_str(&text).expect("json");
    v[field] = value;
    let path = dir.join(name);
    std::fs::write(&path, v.to_string()).expect("write scene");
    s(&path).to_string()
}

#[test]
fn scene_files_that_are_not_scenes_say_what_they_hold() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("o.png");
    for (text, held) in [
        ("[1, 2]", "a JSON array ([ ... ])"),
        ("  \"scene\"", "a JSON string"),
        ("42", "a number"),
        ("", "nothing (it is empty)"),
    ] {
        let p = dir.path().join("x.json");
        std::fs::write(&p, text).expect("write");
        let e = fails(&["render", s(&p), "-o", s(&out)]);
        assert_eq!(
            e,
            format!(
                "error: {}: is not a scene: a scene is a JSON object ({{ ... }}), this file \
                 holds {held}\n",
                s(&p)
            )
        );
    }
    let sc = scene_with(dir.path(), "e.json", "texture", "".into());
    assert_eq!(
        fails(&["render", &sc, "-o", s(&out)]),
        format!(
            "error: {sc}: field `texture` is empty: name an image file (relative to the scene \
             file) or a built-in texture (uv-grid, checker, rgbw-2x2, noise)\n"
        )
    );
}

#[test]
fn an_output_named_only_by_its_extension_is_explained() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join(".png");
    assert_eq!(
        fails(&["render", &scene("default.json"), "-o", s(&out)]),
        format!(
            "error: cannot write {}: the file name is only the extension .png: give it a name, \
             e.g. out.png\n",
            s(&out)
        )
    );
}

#[test]
fn a_closed_standard_output_is_an_error() {
    let bin_path = env!("CARGO_BIN_EXE_barylab");
    let run = |redirect: &str| {
        std::process::Command::new("sh")
            .arg("-c")
            .arg(format!("exec \"$0\" probe \"$1\" --pixel 1,1 {redirect}"))
            .arg(bin_path)
            .arg(scene("default.json"))
            .output()
            .expect("sh")
    };
    let o = run(">&-");
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        stderr(&o),
        "error: standard output is closed (the command was run with >&-): nothing could be \
         printed; send it to a file, or to /dev/null to discard it\n"
    );
    // Sent to /dev/null on purpose: not an error.
    let o = run(">/dev/null");
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_bad_material_library_line_is_named_with_its_file_and_number() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    std::fs::write(d("bad.mtl"), "newmtl a\nKd 1 0 0\n\nKd x y\nNs 10\n").expect("write");
    std::fs::write(
        d("m.obj"),
        "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n",
    )
    .expect("write");
    let notes = succeeds(&["render", s(&d("m.obj")), "-o", s(&d("o.png"))]);
    assert!(
        notes.contains(&format!(
            "note: the material library (mtllib) of {} could not be loaded ({} line 4: `Kd x y` \
             cannot be read); drawing without materials\n",
            s(&d("m.obj")),
            s(&d("bad.mtl"))
        )),
        "{notes}"
    );
}

#[test]
fn a_lesson_step_error_is_said_once() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    std::fs::write(d("notes.png"), "not a picture\n").expect("write");
    scene_with(dir.path(), "s.json", "texture", "notes.png".into());
    bad_input::write_one_step_lesson(&d("l.json"), "s.json");
    let e = fails(&[
        "lesson",
        s(&d("l.json")),
        "--step",
        "1",
        "--figure",
        s(&d("f.png")),
    ]);
    assert_eq!(
        e,
        format!(
            "error: {}: step 1: cannot decode texture {}: it is not an image: its content is \
             text, not PNG, JPEG, BMP, TGA or WebP data\n",
            s(&d("l.json")),
            s(&d("notes.png"))
        )
    );
}

#[test]
fn no_display_is_said_without_a_source_path() {
    let o = bin()
        .args(["--fresh"])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .output()
        .expect("run");
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(!e.contains(".rs:"), "{e}");
    assert!(
        e.contains("no display to open a window on: run barylab in a desktop session"),
        "{e}"
    );
}

#[test]
fn absurd_work_is_refused_with_the_estimate() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    // One large triangle a million times over: hours of drawing.
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    obj.push_str(&"f 1 2 3\n".repeat(1_000_000));
    std::fs::write(d("many.obj"), obj).expect("write");
    let out = bin()
        .args(["render", s(&d("many.obj")), "-o", s(&d("o.png"))])
        .output()
        .expect("run");
    let e = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{e}");
    assert!(
        e.contains(&format!(
            "error: {}: drawing its 1000000 triangles at 800x600 covers about ",
            s(&d("many.obj"))
        )) && e.contains("more than the 1e10 barylab draws in one command"),
        "{e}"
    );
    assert!(!d("o.png").exists());
    // A thousand copies are drawn.
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    obj.push_str(&"f 1 2 3\n".repeat(1000));
    std::fs::write(d("few.obj"), obj).expect("write");
    succeeds(&["render", s(&d("few.obj")), "-o", s(&d("o.png"))]);
}
