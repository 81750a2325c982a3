//! The figure caption for print, and the issue's "done when": a pinned pixel's numbers are
//! identical in the app, in its exported derivation and caption, and from `barylab probe` on
//! the exported scene; the app's figure with a caption is byte for byte what `barylab figure
//! --caption` makes from the exported scene.

mod common;

use std::path::Path;
use std::process::Command as Process;

use barylab::app::command::ExportCommand;
use barylab::app::document::state::StateCommand as AppCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::{Background, Compare, Figure, FigureOptions, caption, svg};
use barylab::i18n::Lang;
use barylab::probe::format::fmt_number;
use barylab::scene::Scene;
use egui::Pos2;
use egui_kittest::Harness;
use glam::DVec2;

fn harness(size: egui::Vec2) -> Harness<'static, BaryApp> {
    common::app::harness(size, AppOptions::default())
}

fn click(h: &mut Harness<'_, BaryApp>, p: [u32; 2]) {
    let view = h.state().canvas().views[0];
    let pos = view
        .transform
        .to_screen(DVec2::new(f64::from(p[0]) + 0.5, f64::from(p[1]) + 0.5));
    h.hover_at(pos);
    h.run();
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
    }
    h.run();
    // Off the canvas: only the pin is marked.
    let screen = h.ctx.content_rect();
    h.hover_at(Pos2::new(screen.left() + 2.0, screen.bottom() - 2.0));
    h.run();
}

/// The caption's lines as the SVG names them (each line is a label whose aria-label is its
/// text), from the first caption line on.
fn caption_text(doc: &str, first_line_starts: &str) -> String {
    let texts: Vec<&str> = doc
        .split(r#"<g class="label" aria-label=""#)
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .collect();
    let start = texts
        .iter()
        .position(|t| t.starts_with(first_line_starts))
        .expect("caption in the SVG");
    texts[start..].join(" ")
}

fn probe_markdown(scene: &Path, p: [u32; 2]) -> String {
    let run = Process::new(env!("CARGO_BIN_EXE_barylab"))
        .arg("probe")
        .arg(scene)
        .args([
            "--pixel",
            &format!("{},{}", p[0], p[1]),
            "--format",
            "markdown",
        ])
        .output()
        .expect("run barylab probe");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    String::from_utf8_lossy(&run.stdout).into_owned()
}

#[test]
fn a_pinned_pixels_numbers_are_the_same_in_the_app_the_export_and_barylab_probe() {
    for size in [egui::vec2(1024.0, 768.0), egui::vec2(1280.0, 800.0)] {
        let mut h = harness(size);
        h.state_mut()
            .push(AppCommand::SetCompare(Compare::SideBySide));
        h.run();
        let p = [333, 444];
        click(&mut h, p);
        // The app's numbers: the inspector's trace of the pin.
        let report = h.state().pin_report().expect("pinned");
        assert_eq!(report.pixel, p);
        let d = report.trace.detail.clone().expect("covered");
        let corr = d.perspective.expect("1/w").correction;
        let uv = d.attribute.clone().expect("uv");
        let mut app_numbers: Vec<f64> = d.screen.rasterizer.to_vec();
        app_numbers.extend(corr.weights);
        app_numbers.push(corr.w_p);
        app_numbers.extend(uv.uv_affine.map(f64::from));
        app_numbers.extend(uv.uv_perspective.map(f64::from));

        let dir = tempfile::tempdir().expect("tempdir");
        let folder = dir.path().join("out");
        for c in [
            ExportCommand::SetFolder(folder.clone()),
            ExportCommand::SetCaption(true),
            ExportCommand::Export,
        ] {
            h.state_mut().push_export(c);
        }
        h.run();
        let outcome = h.state().export_panel().outcome.clone().expect("outcome");
        assert!(!outcome.error, "{:?}", outcome.lines);

        // The probe on the exported scene (loaded from its file, its texture found from
        // there): the same f64s and f32s, bit for bit.
        let json = folder.join("figure-001.json");
        let scene = Scene::load(&json).expect("exported scene");
        let texture = scene.load_texture(&folder).expect("texture");
        let t = barylab::probe::probe(&scene, &texture, &scene.settings(), (p[0], p[1]))
            .expect("probe");
        let pd = t.detail.expect("covered");
        let pc = pd.perspective.expect("1/w").correction;
        let pa = pd.attribute.expect("uv");
        let mut probed: Vec<f64> = pd.screen.rasterizer.to_vec();
        probed.extend(pc.weights);
        probed.push(pc.w_p);
        probed.extend(pa.uv_affine.map(f64::from));
        probed.extend(pa.uv_perspective.map(f64::from));
        assert_eq!(probed, app_numbers, "at {size:?}");
        // `barylab probe` prints the exported derivation, character for character.
        let md = std::fs::read_to_string(folder.join("figure-001.md")).expect("md");
        assert_eq!(probe_markdown(&json, p), md);

        // The derivation and the caption print them, as the derivation writes numbers.
        let doc = std::fs::read_to_string(folder.join("figure-001.svg")).expect("svg");
        let cap = caption_text(&doc, "Pixel (333, 444)");
        for x in &app_numbers {
            let shown = fmt_number(*x);
            assert!(md.contains(&shown), "{shown} not in the derivation");
            assert!(cap.contains(&shown), "{shown} not in the caption: {cap}");
        }
        let rst: Vec<String> = d.screen.rasterizer.iter().map(|x| fmt_number(*x)).collect();
        assert!(
            cap.contains(&format!("r, s, t = {}", rst.join(", "))),
            "{cap}"
        );
        assert!(
            cap.contains(&format!("W_P = {}", fmt_number(corr.w_p))),
            "{cap}"
        );

        // The command the panel shows, run on the exported scene: the same PNG and SVG.
        let command = outcome
            .lines
            .iter()
            .find(|l| l.starts_with("barylab figure "))
            .expect("command shown")
            .clone();
        assert!(command.contains("--caption"), "{command}");
        let args: Vec<&str> = command.split_whitespace().skip(1).collect();
        let o = args.iter().position(|a| *a == "-o").expect("-o");
        for ext in ["png", "svg"] {
            let out = dir.path().join(format!("cli.{ext}"));
            let run = Process::new(env!("CARGO_BIN_EXE_barylab"))
                .args(&args[..o])
                .arg("-o")
                .arg(&out)
                .output()
                .expect("run barylab figure");
            assert!(
                run.status.success(),
                "{}",
                String::from_utf8_lossy(&run.stderr)
            );
            assert!(
                std::fs::read(&out).expect("cli")
                    == std::fs::read(folder.join(format!("figure-001.{ext}"))).expect("app"),
                "{ext} differs at {size:?}"
            );
        }
    }
}

fn default_scene(size: [u32; 2]) -> (Scene, barylab::raster::Texture) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scene = Scene::load(&root.join("assets/scenes/default.json")).expect("scene");
    scene.set_size(size[0], size[1]);
    let texture = scene
        .load_texture(&root.join("assets/scenes"))
        .expect("texture");
    (scene, texture)
}

#[test]
fn the_caption_adds_lines_below_the_views_and_fits_the_figures_width() {
    for size in [[400, 300], [120, 90]] {
        let (scene, texture) = default_scene(size);
        let plain = FigureOptions {
            pinned: Some([size[0] / 2, size[1] * 2 / 3]),
            background: Background::White,
            ..FigureOptions::default()
        };
        let with = FigureOptions {
            caption: true,
            ..plain.clone()
        };
        let a = Figure::compose(&scene, &texture, &plain).expect("figure");
        let b = Figure::compose(&scene, &texture, &with).expect("figure");
        assert!(a.caption.is_none());
        let c = b.caption.as_ref().expect("caption");
        // Same width, taller by the caption and a margin; the views where they were.
        let [m, _, _] = barylab::figure::layout_points(1.0);
        assert_eq!(b.size[0], a.size[0]);
        assert_eq!(b.size[1], a.size[1] + c.height().ceil() as u32 + m);
        assert_eq!(c.origin[1], a.size[1] as f32);
        assert_eq!(a.views[0].origin, b.views[0].origin);
        // Every line inside the figure's margins.
        for i in 0..c.lines.len() {
            let r = c.line_box(i);
            assert!(
                r[0] >= m as f32 && r[2] <= (b.size[0] - m) as f32 + 0.01,
                "{r:?}"
            );
        }
        // The caption is drawn: the image part of the PNG is unchanged, the bottom differs.
        let (pa, pb) = (
            barylab::figure::png::rasterize(&a).expect("png"),
            barylab::figure::png::rasterize(&b).expect("png"),
        );
        let v = &a.views[0];
        for y in v.origin[1]..v.origin[1] + size[1] {
            for x in v.origin[0]..v.origin[0] + size[0] {
                assert_eq!(pa.get_pixel(x, y), pb.get_pixel(x, y));
            }
        }
        let dark = (a.size[1]..b.size[1])
            .flat_map(|y| (0..b.size[0]).map(move |x| (x, y)))
            .filter(|&(x, y)| pb.get_pixel(x, y).0[0] < 128)
            .count();
        assert!(dark > 100, "caption ink: {dark}");
    }
}

#[test]
fn the_caption_is_in_chinese_with_the_standard_terms() {
    let (scene, texture) = default_scene([200, 150]);
    let prober = barylab::probe::Prober::new(&scene, &texture, &scene.settings()).expect("probe");
    let trace = prober.pixel(100, 100).expect("trace");
    let zh: Vec<String> = caption::groups(&trace, [200, 150], Lang::Zh)
        .concat()
        .into_iter()
        .collect();
    let all = zh.join(" ");
    for term in ["重心坐标", "透视校正插值", "仿射插值", "W_P"] {
        assert!(all.contains(term), "{term} not in {all}");
    }
    let en = caption::groups(&trace, [200, 150], Lang::En)
        .concat()
        .join(" ");
    assert!(
        en.starts_with("Pixel (100, 100) of the 200x150 image"),
        "{en}"
    );
    // The numbers are the same in both languages.
    let d = trace.detail.as_ref().expect("covered");
    for x in d.screen.rasterizer {
        assert!(all.contains(&fmt_number(x)) && en.contains(&fmt_number(x)));
    }
    // And the SVG of a Chinese figure names the caption lines in Chinese (when a CJK font is
    // there to draw them; otherwise the figure falls back to English).
    let options = FigureOptions {
        pinned: Some([100, 100]),
        caption: true,
        ..FigureOptions::default()
    };
    let fig = Figure::compose_in(&scene, &texture, &options, Lang::Zh).expect("figure");
    let doc = svg::to_svg(&fig).expect("svg");
    let expect = if fig.lang == Lang::Zh {
        "像素 (100, 100)"
    } else {
        "Pixel (100, 100)"
    };
    assert!(doc.contains(expect));
}
