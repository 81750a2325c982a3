//! The real `barylab` binary: renders, AOV files, and one-line errors for bad input.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use barylab::raster::{NO_TRIANGLE, render};
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

/// Runs a command that must fail; returns its one-line error.
fn fails(args: &[&str]) -> String {
    let out = barylab(args);
    assert!(!out.status.success(), "{args:?} succeeded");
    let err = String::from_utf8_lossy(&out.stderr).trim_end().to_string();
    assert!(!err.is_empty(), "{args:?}: no error message");
    assert_eq!(
        err.lines().count(),
        1,
        "{args:?}: error is not one line:\n{err}"
    );
    err
}

#[test]
fn render_writes_the_same_pixels_as_the_library() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let o = barylab(&["render", &scene("default.json"), "-o", s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = image::open(&out).expect("png").to_rgba8();
    assert_eq!(img.dimensions(), (800, 600));
    let sc = Scene::default_scene();
    let tex = sc.load_texture(Path::new(".")).expect("texture");
    let r = render(&sc.to_mesh(), &tex, &sc.settings()).expect("render");
    assert_eq!(img, r.frame.to_image().expect("image"));
}

#[test]
fn render_options_override_the_scene() {
    let dir = tempfile::tempdir().expect("tempdir");
    let persp = dir.path().join("p.png");
    let affine = dir.path().join("a.png");
    let base = [
        "render",
        &scene("default.json"),
        "--size",
        "200x150",
        "--filter",
        "nearest",
    ];
    let run = |extra: &[&str], out: &PathBuf| {
        let mut args: Vec<&str> = base.to_vec();
        args.extend_from_slice(extra);
        args.extend_from_slice(&["-o", s(out)]);
        let o = barylab(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        image::open(out).expect("png").to_rgba8()
    };
    let p = run(&["--mode", "perspective"], &persp);
    let a = run(&["--mode", "affine"], &affine);
    assert_eq!(p.dimensions(), (200, 150));
    // The modes differ on a quad leaning away from the camera.
    let differing = p.pixels().zip(a.pixels()).filter(|(x, y)| x != y).count();
    assert!(differing > 500, "only {differing} pixels differ");
}

#[test]
fn aov_files_hold_the_buffers_with_nan_where_uncovered() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let aov = dir.path().join("aov");
    let o = barylab(&[
        "render",
        &scene("clip-two-triangles.json"),
        "-o",
        s(&out),
        "--aov",
        s(&aov),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sc = Scene::load(Path::new(&scene("clip-two-triangles.json"))).expect("scene");
    let tex = sc.load_texture(Path::new(".")).expect("texture");
    let f = render(&sc.to_mesh(), &tex, &sc.settings())
        .expect("render")
        .frame;

    type Px = Vec<Vec<[f32; 4]>>;
    let read = |name: &str| -> Px {
        let img = exr::prelude::read_first_rgba_layer_from_file(
            aov.join(name),
            |res, _| vec![vec![[0f32; 4]; res.width()]; res.height()],
            |px: &mut Px, pos, (r, g, b, a): (f32, f32, f32, f32)| {
                px[pos.y()][pos.x()] = [r, g, b, a]
            },
        )
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        img.layer_data.channel_data.pixels
    };
    let uv = read("uv.exr");
    let ws = read("weights_screen.exr");
    let wp = read("weights_perspective.exr");
    let depth = read("depth.exr");
    let inv_w = read("inv_w.exr");
    let (mut covered, mut uncovered) = (0, 0);
    for y in 0..f.height as usize {
        for x in 0..f.width as usize {
            let i = y * f.width as usize + x;
            if f.triangle[i] == NO_TRIANGLE {
                uncovered += 1;
                for file in [&uv, &ws, &wp, &depth, &inv_w] {
                    let p = file[y][x];
                    assert!(p[0].is_nan() && p[1].is_nan() && p[2].is_nan() && p[3] == 0.0);
                }
            } else {
                covered += 1;
                assert_eq!(&uv[y][x][..2], &f.uv_perspective[i][..]);
                assert_eq!(uv[y][x][3], 1.0);
                assert_eq!(&ws[y][x][..3], &f.weights_screen[i][..]);
                assert_eq!(&wp[y][x][..3], &f.weights_perspective[i][..]);
                assert_eq!(depth[y][x][0], f.depth[i]);
                assert_eq!(inv_w[y][x][0], f.inv_w[i]);
            }
        }
    }
    assert!(covered > 1000 && uncovered > 100, "{covered} / {uncovered}");
}

#[test]
fn help_lists_commands_and_examples() {
    let o = barylab(&["render", "--help"]);
    let text = String::from_utf8_lossy(&o.stdout);
    for needle in ["--mode", "--size", "--filter", "--aov", "Examples:"] {
        assert!(text.contains(needle), "help lacks {needle}:\n{text}");
    }
}

#[test]
fn bad_input_gives_one_line_errors() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("out.png");
    let out = s(&out);

    let e = fails(&["render", &scene("default.json")]);
    assert!(e.contains("--output"), "{e}");

    let e = fails(&["render", "no/such/scene.json", "-o", out]);
    assert!(e.contains("no/such/scene.json"), "{e}");

    let broken = dir.path().join("broken.json");
    std::fs::write(&broken, "{\n  \"width\": 4,\n  \"height\": 4,\n  \"vertices\": [ {\"clip\": [0,0,0]} ],\n  \"triangles\": []\n}").expect("write");
    let e = fails(&["render", s(&broken), "-o", out]);
    assert!(
        e.contains("broken.json:4:") && e.contains("vertices[0].clip"),
        "{e}"
    );

    let e = fails(&[
        "render",
        &scene("default.json"),
        "--size",
        "12by5",
        "-o",
        out,
    ]);
    assert!(e.contains("12by5"), "{e}");
    let e = fails(&["render", &scene("default.json"), "--size", "0x5", "-o", out]);
    assert!(e.contains("0x5"), "{e}");
    let e = fails(&[
        "render",
        &scene("default.json"),
        "--mode",
        "sideways",
        "-o",
        out,
    ]);
    assert!(e.contains("sideways"), "{e}");

    // The output's folder is a file: cannot be written.
    let file = dir.path().join("plain-file");
    std::fs::write(&file, b"x").expect("write");
    let target = file.join("out.png");
    let e = fails(&["render", &scene("default.json"), "-o", s(&target)]);
    assert!(
        e.contains("cannot write") && e.contains("plain-file"),
        "{e}"
    );

    let e = fails(&[
        "render",
        &scene("default.json"),
        "-o",
        s(&dir.path().join("out.jpg")),
    ]);
    assert!(e.contains("out.jpg") && e.contains(".png"), "{e}");

    let e = fails(&[
        "render",
        &scene("default.json"),
        "-o",
        out,
        "--aov",
        s(&target),
    ]);
    assert!(e.contains("AOV folder"), "{e}");

    let missing_tex = dir.path().join("tex.json");
    let text = std::fs::read_to_string(scene("front.json"))
        .expect("front")
        .replace("\"uv-grid\"", "\"nothere.png\"");
    std::fs::write(&missing_tex, text).expect("write");
    let e = fails(&["render", s(&missing_tex), "-o", out]);
    assert!(e.contains("nothere.png"), "{e}");
}

#[test]
fn render_options_for_rasterizer_and_threads_and_bench_json() {
    let dir = tempfile::tempdir().expect("tempdir");
    let a = dir.path().join("edge.png");
    let b = dir.path().join("scan.png");
    let run = |extra: &[&str], out: &Path| {
        let mut args = vec!["render", "assets/scenes/front.json", "--size", "120x90"];
        args.extend_from_slice(extra);
        let o = Command::new(env!("CARGO_BIN_EXE_barylab"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(&args)
            .arg("-o")
            .arg(out)
            .output()
            .expect("run");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    };
    run(&["--rasterizer", "edge", "--threads", "1"], &a);
    run(&["--rasterizer", "scanline", "--threads", "2"], &b);
    let (ia, ib) = (image::open(&a).expect("a"), image::open(&b).expect("b"));
    let differing = ia
        .to_rgba8()
        .pixels()
        .zip(ib.to_rgba8().pixels())
        .filter(|(x, y)| x != y)
        .count();
    assert!(
        differing <= 20,
        "{differing} pixels differ between rasterizers"
    );
    let e = fails(&[
        "render",
        &scene("front.json"),
        "-o",
        s(&a),
        "--threads",
        "0",
    ]);
    assert!(e.contains("--threads"), "{e}");

    let o = Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args([
            "bench",
            &scene("front.json"),
            "--size",
            "64x48",
            "--frames",
            "1",
            "--json",
        ])
        .output()
        .expect("bench");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let records: Vec<serde_json::Value> =
        serde_json::from_slice(&o.stdout).expect("bench --json prints JSON");
    assert!(records.len() >= 8, "{} records", records.len());
    for r in &records {
        for key in [
            "rasterizer",
            "filter",
            "mode",
            "threads",
            "width",
            "height",
            "median_ms",
            "mpix_per_s",
        ] {
            assert!(r.get(key).is_some(), "record lacks {key}: {r}");
        }
        assert_eq!(r["width"], 64);
        assert!(r["median_ms"].as_f64().is_some_and(|ms| ms > 0.0));
    }
    let names: std::collections::BTreeSet<_> = records
        .iter()
        .map(|r| r["rasterizer"].as_str().unwrap_or("").to_string())
        .collect();
    assert_eq!(names.into_iter().collect::<Vec<_>>(), ["edge", "scanline"]);
}

/// `bench --view` times what each compare mode draws, and says so in every record; a mesh
/// scene with `subdivide` benchmarks as the dense mesh it makes.
#[test]
fn bench_views_and_dense_meshes() {
    let bench_scene = format!(
        "{}/assets/bench/bench-mesh-5k.json",
        env!("CARGO_MANIFEST_DIR")
    );
    for view in ["single", "side", "wipe", "difference"] {
        let o = Command::new(env!("CARGO_BIN_EXE_barylab"))
            .args([
                "bench",
                &bench_scene,
                "--size",
                "96x54",
                "--frames",
                "1",
                "--view",
                view,
                "--json",
            ])
            .output()
            .expect("bench");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let records: Vec<serde_json::Value> = serde_json::from_slice(&o.stdout).expect("JSON");
        assert!(!records.is_empty());
        assert!(records.iter().all(|r| r["view"] == view), "{records:?}");
    }
    let o = Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(["bench", &bench_scene, "--view", "sideways"])
        .output()
        .expect("bench");
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("sideways"));
}
