//! Bad input, full disks and huge requests (issue 18): the real binary never panics, never
//! hangs on a FIFO or a device, refuses requests past the memory budget, and never leaves a
//! half-written or overwritten file.

mod bad_input;

use std::path::PathBuf;

use bad_input::{
    bin, data, fails, fails_with, mkfifo, s, scene, stderr, succeeds, temporary_files, tool,
};

const TRIANGLE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";

#[test]
fn enormous_overlay_geometry_is_cut_before_drawing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let p = dir.path().join("p.json");
    std::fs::write(
        &p,
        r#"{"width":7,"height":2,"vertices":[{"clip":[-1,1,0,0]},{"clip":[0,0,0,3.5e38]},{"clip":[0,3.4e38,0,0]}],"triangles":[[0,1,2]]}"#,
    )
    .expect("write");
    for out in ["p.png", "p.svg"] {
        let out = dir.path().join(out);
        for extra in [
            &["--pixel", "0,0"][..],
            &["--hover", "3,1", "--compare", "side"],
        ] {
            let mut args = vec!["figure", s(&p), "-o", s(&out)];
            args.extend_from_slice(extra);
            succeeds(&args);
        }
    }
    // No coordinate in the SVG is beyond the box around the image.
    let svg = std::fs::read_to_string(dir.path().join("p.svg")).expect("svg");
    let longest = svg
        .split(|c: char| !(c.is_ascii_digit() || c == '.'))
        .map(str::len)
        .max()
        .unwrap_or(0);
    assert!(
        longest < 12,
        "a number with {longest} characters in the SVG"
    );
    assert!(image::open(dir.path().join("p.png")).is_ok());
}

#[test]
fn a_closed_standard_output_ends_quietly_with_a_non_zero_code() {
    let (reader, writer) = std::io::pipe().expect("pipe");
    drop(reader);
    let out = bin()
        .args(["probe", &scene("default.json"), "--pixel", "400,420"])
        .stdout(writer)
        .output()
        .expect("run");
    assert_eq!(out.status.code(), Some(141), "{}", stderr(&out));
    assert_eq!(stderr(&out), "");
}

#[test]
fn a_full_standard_output_is_a_one_line_error() {
    for args in [
        &["probe", &scene("default.json"), "--pixel", "400,420"][..],
        &[
            "bench",
            &scene("front.json"),
            "--size",
            "8x8",
            "--frames",
            "1",
        ],
        &["--help"],
    ] {
        let full = std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full");
        let e = fails_with(bin().stdout(full), args);
        assert!(e.contains("cannot write to standard output"), "{e}");
    }
}

#[test]
fn requests_past_the_memory_budget_are_refused_with_need_and_limit() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let default = scene("default.json");
    // (options after the scene, parts of the message)
    let cases: [(&[&str], &[&str]); 3] = [
        (
            &["render", "--size", "16384x16384"],
            &[
                "16384x16384",
                "15.3 GiB",
                "4.0 GiB",
                "BARYLAB_MEMORY_LIMIT",
                "--memory-limit",
            ],
        ),
        (
            &["figure", "--size", "16000x16000"],
            &["16000x16000", "needs about"],
        ),
        // The scene fits, its figure at 4 PNG pixels per point (rendered again at
        // 16000x16000) does not.
        (
            &["figure", "--size", "4000x4000", "--scale", "4"],
            &["figure needs about", "4.0 GiB"],
        ),
    ];
    for (options, needles) in cases {
        let mut args = vec![options[0], &default, "-o", s(&out)];
        args.extend_from_slice(&options[1..]);
        let e = fails(&args);
        assert!(needles.iter().all(|n| e.contains(n)), "{e}");
    }
    let e = fails(&[
        "render",
        &scene("default.json"),
        "-o",
        s(&out),
        "--memory-limit",
        "1M",
    ]);
    assert!(
        e.contains("800x600") && e.contains("1.0 MiB (--memory-limit)"),
        "{e}"
    );
    let e = fails_with(
        bin().env("BARYLAB_MEMORY_LIMIT", "lots"),
        &["render", &scene("default.json"), "-o", s(&out)],
    );
    assert!(
        e.contains("BARYLAB_MEMORY_LIMIT=lots is not a memory size"),
        "{e}"
    );
    assert!(!out.exists());

    // A model and a scene with many triangles (the budget scaled down with them).
    let obj = dir.path().join("many.obj");
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    text.push_str(&"f 1 2 3\n".repeat(200_000));
    std::fs::write(&obj, text).expect("write");
    let e = fails(&["render", s(&obj), "-o", s(&out), "--memory-limit", "4M"]);
    assert!(
        e.contains("model") && e.contains("many.obj") && e.contains("needs about"),
        "{e}"
    );
    let e = fails(&["probe", s(&obj), "--pixel", "1,1", "--memory-limit", "64M"]);
    assert!(e.contains("render of 200000 triangles needs about"), "{e}");
    let json = dir.path().join("many.json");
    let tris = vec!["[0,1,2]"; 200_000].join(",");
    std::fs::write(
        &json,
        format!(
            r#"{{"width":8,"height":8,"vertices":[{{"clip":[0,0,0,1]}},{{"clip":[1,0,0,1]}},{{"clip":[0,1,0,1]}}],"triangles":[{tris}]}}"#
        ),
    )
    .expect("write");
    let e = fails(&["render", s(&json), "-o", s(&out), "--memory-limit", "64M"]);
    assert!(e.contains("render of 200000 triangles needs about"), "{e}");
    assert!(!out.exists());
}

#[test]
fn only_regular_files_are_read_and_the_error_names_what_was_given() {
    if !tool("mkfifo") {
        return;
    }
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    let out = d("out.png");
    for name in ["fifo.json", "fifo.obj", "fifo.png", "fifo.mtl"] {
        mkfifo(&d(name));
    }
    std::os::unix::fs::symlink("/dev/zero", d("zero.obj")).expect("link");
    std::os::unix::fs::symlink("/dev/zero", d("zero.jpg")).expect("link");
    std::fs::create_dir(d("folder.json")).expect("dir");
    let cases = [
        ("fifo.json", "cannot read scene", "a FIFO"),
        ("fifo.obj", "cannot read model", "a FIFO"),
        ("fifo.png", "cannot read texture", "a FIFO"),
        ("zero.obj", "cannot read model", "a character device"),
        ("zero.jpg", "cannot read texture", "a character device"),
        ("folder.json", "cannot read scene", "a folder"),
    ];
    for (name, what, kind) in cases {
        let e = fails(&["render", s(&d(name)), "-o", s(&out)]);
        assert!(
            e.contains(what) && e.contains(name) && e.contains(kind),
            "{e}"
        );
        assert!(!e.contains("empty (0 bytes)"), "{e}");
    }
    // A scene whose texture is a FIFO.
    let tex = d("tex.json");
    let text = std::fs::read_to_string(scene("front.json")).expect("front");
    std::fs::write(&tex, text.replace("\"uv-grid\"", "\"fifo.png\"")).expect("write");
    let e = fails(&["render", s(&tex), "-o", s(&out)]);
    assert!(e.contains("fifo.png") && e.contains("a FIFO"), "{e}");
    // mtllib a FIFO or /dev/zero: a note, and the model draws without materials.
    for mtl in ["fifo.mtl", "/dev/zero"] {
        let obj = d("m.obj");
        std::fs::write(&obj, format!("mtllib {mtl}\n{TRIANGLE_OBJ}")).expect("write");
        let notes = succeeds(&["render", s(&obj), "-o", s(&out)]);
        assert!(
            notes.contains("material library") && notes.contains("not a regular file"),
            "{notes}"
        );
    }
    // map_Kd a FIFO: an error naming it.
    std::fs::write(d("t.mtl"), "newmtl x\nmap_Kd fifo.png\n").expect("write");
    let obj = d("t.obj");
    std::fs::write(&obj, format!("mtllib t.mtl\nusemtl x\n{TRIANGLE_OBJ}")).expect("write");
    let e = fails(&["render", s(&obj), "-o", s(&out)]);
    assert!(e.contains("fifo.png") && e.contains("a FIFO"), "{e}");

    // Past the size cap (a sparse file: nothing is written to disk).
    let big = d("big.json");
    std::fs::File::create(&big)
        .and_then(|f| f.set_len(barylab::files::MAX_SCENE_BYTES + 1))
        .expect("sparse file");
    let e = fails(&["render", s(&big), "-o", s(&out)]);
    assert!(
        e.contains("big.json") && e.contains("more than the 256.0 MiB allowed"),
        "{e}"
    );
}

#[test]
fn outputs_are_checked_before_rendering_and_failures_leave_files_as_they_were() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    let out = d("out.png");
    std::fs::write(&out, b"the good old picture").expect("write");
    let plain = d("plain-file");
    std::fs::write(&plain, b"x").expect("write");

    // The extension is checked before a render that would not even fit.
    let e = fails(&[
        "render",
        &scene("default.json"),
        "--size",
        "16384x16384",
        "-o",
        s(&d("o.jpg")),
        "--memory-limit",
        "1M",
    ]);
    assert!(
        e.contains("o.jpg") && e.contains("must be a .png file"),
        "{e}"
    );
    let e = fails(&["figure", &scene("default.json"), "-o", s(&d("o.pdf"))]);
    assert!(e.contains("must be a .png or .svg file"), "{e}");
    // An invalid --aov folder fails before out.png is written.
    let e = fails(&[
        "render",
        &scene("default.json"),
        "-o",
        s(&out),
        "--aov",
        s(&plain),
    ]);
    assert!(e.contains("AOV folder") && e.contains("plain-file"), "{e}");
    let e = fails(&[
        "render",
        &scene("default.json"),
        "-o",
        s(&d("nowhere/out.png")),
    ]);
    assert!(e.contains("folder") && e.contains("does not exist"), "{e}");
    let e = fails(&["render", &scene("default.json"), "-o", s(&d("dir.png/"))]);
    assert!(e.contains("dir.png") && e.contains("names a folder"), "{e}");
    // A read-only file is not replaced.
    let locked = d("locked.png");
    std::fs::write(&locked, b"keep").expect("write");
    let mut perms = std::fs::metadata(&locked).expect("meta").permissions();
    perms.set_readonly(true);
    std::fs::set_permissions(&locked, perms).expect("chmod");
    let e = fails(&["render", &scene("default.json"), "-o", s(&locked)]);
    assert!(e.contains("locked.png") && e.contains("read-only"), "{e}");
    assert_eq!(std::fs::read(&locked).expect("read"), b"keep");
    assert_eq!(std::fs::read(&out).expect("out"), b"the good old picture");

    // An AOV set is all or nothing: one file cannot be written, so none is, and neither is
    // the image; the files of an earlier run stay as they were.
    let aov = d("aov");
    std::fs::create_dir(&aov).expect("dir");
    std::fs::write(aov.join("uv.exr"), b"earlier run").expect("write");
    std::fs::create_dir(aov.join("depth.exr")).expect("dir");
    let e = fails(&[
        "render",
        &scene("clip-two-triangles.json"),
        "-o",
        s(&out),
        "--aov",
        s(&aov),
    ]);
    assert!(e.contains("depth.exr") && e.contains("a folder"), "{e}");
    assert_eq!(
        std::fs::read(aov.join("uv.exr")).expect("uv"),
        b"earlier run"
    );
    assert!(!aov.join("inv_w.exr").exists() && !aov.join("weights_screen.exr").exists());
    assert_eq!(std::fs::read(&out).expect("out"), b"the good old picture");
    assert_eq!(temporary_files(&aov), Vec::<PathBuf>::new());
    assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());

    // When it works, every file is replaced and no temporary file is left.
    std::fs::remove_dir(aov.join("depth.exr")).expect("rm");
    succeeds(&[
        "render",
        &scene("clip-two-triangles.json"),
        "-o",
        s(&out),
        "--aov",
        s(&aov),
    ]);
    assert!(image::open(&out).is_ok());
    for f in barylab::aov::AOV_FILES {
        assert!(
            std::fs::read(aov.join(f))
                .expect("aov")
                .starts_with(&[0x76, 0x2f, 0x31, 0x01]),
            "{f} is not EXR"
        );
    }
    assert_eq!(temporary_files(&aov), Vec::<PathBuf>::new());
    assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());
}

#[test]
fn an_output_that_is_a_link_is_written_where_it_points_and_stays_a_link() {
    let dir = tempfile::tempdir().expect("tempdir");
    let real = dir.path().join("real.png");
    let link = dir.path().join("link.png");
    std::fs::write(&real, b"old").expect("write");
    std::os::unix::fs::symlink(&real, &link).expect("link");
    succeeds(&[
        "render",
        &scene("front.json"),
        "--size",
        "32x24",
        "-o",
        s(&link),
    ]);
    assert!(
        std::fs::symlink_metadata(&link)
            .expect("link")
            .file_type()
            .is_symlink()
    );
    let img = image::open(&real).expect("a PNG where the link points");
    assert_eq!((img.width(), img.height()), (32, 24));
    assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());
}

#[test]
fn an_output_that_is_an_input_is_refused() {
    let dir = tempfile::tempdir().expect("tempdir");
    let d = |n: &str| dir.path().join(n);
    std::fs::copy(data("rgbw.png"), d("in.png")).expect("copy");
    let before = std::fs::read(d("in.png")).expect("read");
    let e = fails(&["render", s(&d("in.png")), "-o", s(&d("in.png"))]);
    assert!(e.contains("in.png") && e.contains("is an input"), "{e}");
    // The same file by another name.
    std::os::unix::fs::symlink(d("in.png"), d("link.png")).expect("link");
    let e = fails(&["figure", s(&d("in.png")), "-o", s(&d("link.png"))]);
    assert!(e.contains("is an input"), "{e}");
    // A scene whose texture is the output.
    let text = std::fs::read_to_string(scene("front.json")).expect("front");
    std::fs::write(d("s.json"), text.replace("\"uv-grid\"", "\"in.png\"")).expect("write");
    let e = fails(&["render", s(&d("s.json")), "-o", s(&d("in.png"))]);
    assert!(e.contains("is an input"), "{e}");
    assert_eq!(std::fs::read(d("in.png")).expect("read"), before);
    // A model's texture.
    std::fs::copy(data("textured.obj"), d("m.obj")).expect("copy");
    std::fs::copy(data("textured.mtl"), d("textured.mtl")).expect("copy");
    let mtl = std::fs::read_to_string(d("textured.mtl")).expect("mtl");
    let texture = mtl
        .lines()
        .find_map(|l| l.strip_prefix("map_Kd "))
        .expect("map_Kd")
        .trim()
        .to_string();
    std::fs::copy(
        format!("{}/tests/data/{texture}", env!("CARGO_MANIFEST_DIR")),
        d(&texture),
    )
    .expect("copy");
    let e = fails(&["render", s(&d("m.obj")), "-o", s(&d(&texture))]);
    assert!(e.contains("is an input"), "{e}");
}

#[test]
fn a_failed_atomic_write_leaves_the_old_file_and_no_temporary() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("notes.md");
    std::fs::write(&path, "old").expect("write");
    let r = barylab::files::write_atomic(&path, |w| {
        use std::io::Write;
        w.write_all(b"half of the new")?;
        Err(std::io::Error::new(
            std::io::ErrorKind::StorageFull,
            "disk full",
        ))
    });
    let e = r.expect_err("fails").to_string();
    assert!(e.contains("notes.md") && e.contains("disk full"), "{e}");
    assert_eq!(std::fs::read_to_string(&path).expect("read"), "old");
    assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());
    barylab::files::write_bytes(&path, b"new").expect("write");
    assert_eq!(std::fs::read_to_string(&path).expect("read"), "new");
    // write_new never overwrites.
    let e = barylab::files::write_new(&path, b"newer")
        .expect_err("exists")
        .to_string();
    assert!(e.contains("notes.md"), "{e}");
    assert_eq!(std::fs::read_to_string(&path).expect("read"), "new");
    assert_eq!(temporary_files(dir.path()), Vec::<PathBuf>::new());
}
