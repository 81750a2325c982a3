//! Figures for lecture notes: the library's composition, SVG and PNG, the export's files and
//! names, and `barylab figure`.

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::figure::export::{self, ExportRequest, ExportSelection};
use barylab::figure::{Background, Compare, Figure, FigureOptions, png, svg};
use barylab::probe::format::fmt_number;
use barylab::raster::{self, Texture};
use barylab::scene::Scene;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The default scene at 200x150 and its texture.
fn small_default() -> (Scene, Texture) {
    let mut scene = Scene::load(&root().join("assets/scenes/default.json")).expect("scene");
    scene.set_size(200, 150);
    let texture = scene
        .load_texture(&root().join("assets/scenes"))
        .expect("texture");
    (scene, texture)
}

fn pinned(pixel: [u32; 2], scale: u32) -> FigureOptions {
    FigureOptions {
        pinned: Some(pixel),
        scale,
        background: Background::White,
        ..FigureOptions::default()
    }
}

/// The scene's render settings on a white figure: the image's background is white too.
fn on_white(scene: &Scene) -> raster::RenderSettings {
    raster::RenderSettings {
        background: [255, 255, 255, 255],
        ..scene.settings()
    }
}

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .current_dir(root())
        .args(args)
        .output()
        .expect("run barylab")
}

#[test]
fn png_size_follows_the_scale_and_the_raster_is_a_real_re_render() {
    let (scene, texture) = small_default();
    for scale in [1, 2, 4] {
        let fig = Figure::compose(&scene, &texture, &pinned([100, 100], scale)).expect("figure");
        // One view: the image plus a margin all round and the title strip above.
        let m = barylab::figure::FIGURE_MARGIN;
        let strip = barylab::figure::overlay::TITLE_STRIP as u32;
        assert_eq!(fig.size, [200 + 2 * m, 150 + 2 * m + strip]);
        assert_eq!(
            fig.pixel_dimensions(),
            [fig.size[0] * scale, fig.size[1] * scale]
        );
        let image = png::rasterize(&fig).expect("png");
        assert_eq!(
            image.dimensions(),
            (fig.size[0] * scale, fig.size[1] * scale)
        );
        // The view's raster is the scene rendered at scale x the size, not an upscale.
        let mut hi = scene.clone();
        hi.set_size(200 * scale, 150 * scale);
        let direct = raster::render(&hi.to_mesh(), &texture, &on_white(&hi)).expect("render");
        assert!(
            fig.views[0].raster == direct.frame.to_image().expect("image"),
            "scale {scale}"
        );
        // The PNG holds that raster where no overlay covers it: the top-left image corner
        // (the default quad lies lower down; no label reaches there), white for print.
        let o = fig.views[0].origin.map(|v| v * scale);
        assert_eq!(image.get_pixel(o[0], o[1]).0, [255, 255, 255, 255]);
        for (x, y) in [(0, 0), (3 * scale, 2 * scale)] {
            assert_eq!(
                image.get_pixel(o[0] + x, o[1] + y),
                direct.frame.to_image().expect("image").get_pixel(x, y),
                "scale {scale}"
            );
        }
    }
}

#[test]
fn a_magnified_figure_keeps_the_scenes_pixels() {
    let (mut scene, texture) = small_default();
    scene.set_size(40, 30);
    let options = FigureOptions {
        pixel_size: 8,
        scale: 2,
        ..pinned([20, 20], 2)
    };
    let fig = Figure::compose(&scene, &texture, &options).expect("figure");
    let direct = raster::render(&scene.to_mesh(), &texture, &on_white(&scene)).expect("render");
    let r = &fig.views[0].raster;
    assert_eq!(r.dimensions(), (40 * 16, 30 * 16));
    for (x, y) in [(0, 0), (13, 7), (20, 20), (39, 29)] {
        for (dx, dy) in [(0, 0), (15, 15), (7, 3)] {
            assert_eq!(
                r.get_pixel(16 * x + dx, 16 * y + dy).0,
                direct.frame.color[(y * 40 + x) as usize]
            );
        }
    }
}

#[test]
fn the_svg_parses_and_holds_the_labels_as_outlines_named_by_their_text() {
    let (scene, texture) = small_default();
    let options = FigureOptions {
        compare: Compare::SideBySide,
        ..pinned([100, 100], 2)
    };
    let fig = Figure::compose(&scene, &texture, &options).expect("figure");
    let doc = svg::to_svg(&fig).expect("svg");
    let tree = barylab::figure::png::svg_options();
    let tree = resvg::usvg::Tree::from_str(&doc, &tree).expect("usvg parses the SVG");
    let [w, h] = fig.pixel_dimensions();
    assert_eq!(tree.size().width(), w as f32);
    assert_eq!(tree.size().height(), h as f32);
    // Every label is drawn as glyph outlines (no <text> a viewer could set in another
    // font), its text kept in the group's aria-label.
    fn has_text(g: &resvg::usvg::Group) -> bool {
        g.children().iter().any(|node| match node {
            resvg::usvg::Node::Group(g) => has_text(g),
            resvg::usvg::Node::Text(_) => true,
            _ => false,
        })
    }
    assert!(!has_text(tree.root()));
    assert!(!doc.contains("<text"));
    let found: Vec<String> = doc
        .split(r#"<g class="label" aria-label=""#)
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .map(str::to_string)
        .collect();
    // The vertex labels with their w, computed independently from the scene's clip w.
    let mesh = scene.to_mesh();
    let w_a = barylab::figure::overlay::format_w(mesh.vertices[0].clip.w);
    // (Each view of this small figure is too narrow for its mode's whole title: the short
    // forms, see `a_narrow_side_by_side_figure_titles_its_views_with_the_short_forms`.)
    for label in [
        "AFFINE".to_string(),
        "PERSPECTIVE".to_string(),
        format!("A  w = {w_a}"),
    ] {
        // Two views: each label twice (the mode titles once each).
        assert!(found.contains(&label), "{label:?} not in {found:?}");
    }
    assert_eq!(
        found.iter().filter(|t| t.starts_with("A  w = ")).count(),
        2,
        "{found:?}"
    );
    // The raster is embedded in each view.
    assert_eq!(doc.matches("data:image/png;base64,").count(), 2);
}

#[test]
fn export_writes_fresh_names_and_the_derivation_has_the_pixels_numbers() {
    let (scene, texture) = small_default();
    let fig = Figure::compose(&scene, &texture, &pinned([100, 100], 1)).expect("figure");
    let dir = tempfile::tempdir().expect("tempdir");
    let request = ExportRequest {
        folder: dir.path(),
        stem: "figure",
        figure: &fig,
        scene: &scene,
        scene_dir: Some(&root().join("assets/scenes")),
        selection: ExportSelection::default(),
    };
    let first = export::export(&request).expect("export");
    let names = |files: &[PathBuf]| -> Vec<String> {
        files
            .iter()
            .map(|f| f.file_name().expect("name").to_string_lossy().into_owned())
            .collect()
    };
    assert_eq!(
        names(&first),
        [
            "figure-001.png",
            "figure-001.svg",
            "figure-001.md",
            "figure-001.tex",
            "figure-001.json"
        ]
    );
    let png_before = std::fs::read(&first[0]).expect("png");
    let second = export::export(&request).expect("export again");
    assert_eq!(names(&second)[0], "figure-002.png");
    assert_eq!(
        std::fs::read(&first[0]).expect("png"),
        png_before,
        "overwritten"
    );
    // A name taken by any of the kinds is skipped.
    std::fs::write(dir.path().join("figure-003.tex"), "mine").expect("write");
    let third = export::export(&request).expect("export a third time");
    assert_eq!(names(&third)[0], "figure-004.png");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("figure-003.tex")).expect("read"),
        "mine"
    );

    // The derivation's numbers are the probe's.
    let trace =
        barylab::probe::probe(&scene, &texture, &scene.settings(), (100, 100)).expect("probe");
    let detail = trace.detail.as_ref().expect("covered");
    let p = detail.perspective.as_ref().expect("perspective");
    let md = std::fs::read_to_string(&first[2]).expect("md");
    let tex = std::fs::read_to_string(&first[3]).expect("tex");
    for doc in [&md, &tex] {
        assert!(doc.contains("100"), "pixel missing");
        assert!(doc.contains(&fmt_number(p.correction.w_p)), "W_P missing");
        for w in detail.screen.rasterizer {
            assert!(doc.contains(&fmt_number(w)), "screen weight {w} missing");
        }
    }
    assert!(md.starts_with("# barylab probe: pixel (100, 100)"));
    assert!(tex.contains("\\"), "not LaTeX");
}

#[test]
fn export_into_an_impossible_folder_names_it_and_writes_nothing() {
    let (scene, texture) = small_default();
    let fig = Figure::compose(&scene, &texture, &pinned([100, 100], 1)).expect("figure");
    let dir = tempfile::tempdir().expect("tempdir");
    // A folder under a regular file cannot be made, not even by root.
    let file = dir.path().join("file.txt");
    std::fs::write(&file, "x").expect("write");
    let folder = file.join("sub");
    let err = export::export(&ExportRequest {
        folder: &folder,
        stem: "figure",
        figure: &fig,
        scene: &scene,
        scene_dir: None,
        selection: ExportSelection::default(),
    })
    .expect_err("must fail");
    let message = err.to_string();
    assert!(message.contains(&folder.display().to_string()), "{message}");
    assert!(!message.contains('\n'), "{message}");
    assert_eq!(std::fs::read_dir(dir.path()).expect("list").count(), 1);
}

#[test]
fn the_exported_scene_loads_back_from_elsewhere_and_renders_identically() {
    // A scene whose texture is an image next to it, named relatively.
    let src = tempfile::tempdir().expect("tempdir");
    let mut img = image::RgbaImage::new(4, 4);
    for (i, p) in img.pixels_mut().enumerate() {
        p.0 = [(i * 16) as u8, 255 - (i * 16) as u8, 90, 255];
    }
    img.save(src.path().join("tex.png")).expect("texture");
    let mut json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root().join("assets/scenes/default.json")).expect("read"),
    )
    .expect("json");
    json["texture"] = "tex.png".into();
    json["filter"] = "nearest".into();
    let scene_path = src.path().join("scene.json");
    std::fs::write(&scene_path, json.to_string()).expect("write");
    let (mut scene, dir) = barylab::scene::open_input(&scene_path).expect("open");
    scene.set_size(160, 120);
    let texture = scene.load_texture(&dir).expect("texture");

    let saved = export::scene_json(&scene, Some(&dir));
    let elsewhere = tempfile::tempdir().expect("tempdir");
    let copy = elsewhere.path().join("copy.json");
    std::fs::write(&copy, &saved).expect("write");
    let back = Scene::load(&copy).expect("loads back");
    assert_eq!(back.size(), (160, 120));
    let back_texture = back.load_texture(elsewhere.path()).expect("texture found");
    let a = raster::render(&scene.to_mesh(), &texture, &scene.settings()).expect("render");
    let b = raster::render(&back.to_mesh(), &back_texture, &back.settings()).expect("render");
    assert!(a.frame.color == b.frame.color);
}

#[test]
fn cli_figure_equals_the_library_export_and_reports_bad_output_in_one_line() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = dir.path().join("side.png");
    let run = barylab(&[
        "figure",
        "assets/scenes/default.json",
        "--size",
        "200x150",
        "--pixel",
        "100,100",
        "--compare",
        "side",
        "--scale",
        "2",
        "--background",
        "white",
        "-o",
        out.to_str().expect("utf-8"),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let (scene, texture) = small_default();
    let options = FigureOptions {
        compare: Compare::SideBySide,
        ..pinned([100, 100], 2)
    };
    let fig = Figure::compose(&scene, &texture, &options).expect("figure");
    assert!(std::fs::read(&out).expect("cli png") == png::to_png(&fig).expect("png"));

    for (output, expect) in [
        ("fig.gif", "must be a .png or .svg file"),
        ("file.txt/fig.png", "cannot write"),
    ] {
        std::fs::write(dir.path().join("file.txt"), "x").expect("write");
        let target = dir.path().join(output);
        let run = barylab(&[
            "figure",
            "assets/scenes/default.json",
            "-o",
            target.to_str().expect("utf-8"),
        ]);
        assert!(!run.status.success());
        let err = String::from_utf8_lossy(&run.stderr);
        assert!(err.contains(expect), "{err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
    // A pixel outside the image is a clear error.
    let run = barylab(&[
        "figure",
        "assets/scenes/default.json",
        "--size",
        "200x150",
        "--pixel",
        "200,10",
        "-o",
        dir.path().join("x.svg").to_str().expect("utf-8"),
    ]);
    assert!(!run.status.success());
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(err.contains("outside the 200x150 image"), "{err}");
}

#[test]
fn the_overlay_scale_enlarges_labels_and_margins_not_the_image() {
    // Wide enough for the mode title at twice the size (a label wider than its view would
    // shrink to fit it).
    let (mut scene, texture) = small_default();
    scene.set_size(600, 450);
    let one = Figure::compose(&scene, &texture, &pinned([300, 300], 1)).expect("figure");
    let options = FigureOptions {
        overlay_scale: 2.0,
        ..pinned([300, 300], 1)
    };
    let two = Figure::compose(&scene, &texture, &options).expect("figure");
    let [m, _, strip] = barylab::figure::layout_points(2.0);
    assert_eq!(two.size, [600 + 2 * m, 450 + 2 * m + strip]);
    assert!(one.views[0].raster == two.views[0].raster);
    let font_sizes = |f: &Figure| -> Vec<f32> {
        let doc = svg::to_svg(f).expect("svg");
        doc.split("font-size=\"")
            .skip(1)
            .filter_map(|rest| rest.split('"').next()?.parse().ok())
            .collect()
    };
    let (a, b) = (font_sizes(&one), font_sizes(&two));
    assert!(!a.is_empty());
    assert_eq!(b, a.iter().map(|v| 2.0 * v).collect::<Vec<_>>());
    // Out of range: a clear error.
    let bad = FigureOptions {
        overlay_scale: 9.0,
        ..pinned([100, 100], 1)
    };
    let err = Figure::compose(&scene, &texture, &bad).expect_err("out of range");
    assert_eq!(err.to_string(), "overlay scale 9 is outside 0.5..=5");
}

/// A side-by-side figure too narrow for the whole mode titles titles its views with their
/// short forms, as the app does: shrunk to fit, "AFFINE (screen-space)" was much smaller
/// than "PERSPECTIVE-CORRECT" beside it.
#[test]
fn a_narrow_side_by_side_figure_titles_its_views_with_the_short_forms() {
    let titles = |size: [u32; 2], scale: u32| {
        let (mut scene, texture) = small_default();
        scene.set_size(size[0], size[1]);
        let options = FigureOptions {
            compare: Compare::SideBySide,
            ..pinned([size[0] / 2, size[1] / 2], scale)
        };
        let fig = Figure::compose(&scene, &texture, &options).expect("figure");
        let doc = svg::to_svg(&fig).expect("svg");
        let found: Vec<String> = doc
            .split(r#"<g class="label" aria-label=""#)
            .skip(1)
            .filter_map(|rest| rest.split('"').next())
            .filter(|t| t.starts_with("AFFINE") || t.starts_with("PERSPECTIVE"))
            .map(str::to_string)
            .collect();
        found
    };
    assert_eq!(titles([120, 90], 1), ["AFFINE", "PERSPECTIVE"]);
    // Wide enough: the whole titles.
    assert_eq!(
        titles([400, 300], 1),
        ["AFFINE (screen-space)", "PERSPECTIVE-CORRECT"]
    );
}
