//! The app's Export panel driven through egui_kittest, and its files checked against
//! `barylab figure` run on the exported scene.

mod common;

use std::path::Path;
use std::process::Command;

use barylab::app::command::ExportCommand;
use barylab::app::document::state::StateCommand as AppCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::Compare;
use egui::Pos2;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec2;

const SIZE: egui::Vec2 = egui::vec2(1500.0, 950.0);

fn harness() -> Harness<'static, BaryApp> {
    common::app::harness(SIZE, AppOptions::default())
}

fn pixel_centre(h: &Harness<'_, BaryApp>, p: [u32; 2]) -> Pos2 {
    let view = h.state().canvas().views[0];
    view.transform
        .to_screen(DVec2::new(f64::from(p[0]) + 0.5, f64::from(p[1]) + 0.5))
}

fn click(h: &mut Harness<'_, BaryApp>, pos: Pos2) {
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
}

/// Pins the pixel at a third of the canvas's width and two thirds of its height (on the quad).
fn pin(h: &mut Harness<'_, BaryApp>) -> [u32; 2] {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let p = [out.size[0] / 3, out.size[1] * 2 / 3];
    let pos = pixel_centre(h, p);
    click(h, pos);
    assert_eq!(h.state().state().view.pinned, Some(p));
    // Move the pointer off the canvas so nothing is hovered.
    h.hover_at(Pos2::new(2.0, SIZE.y - 2.0));
    h.run();
    p
}

#[test]
fn ctrl_s_exports_what_barylab_figure_draws_from_the_exported_scene() {
    let mut h = harness();
    // Not the default view: a wipe off centre, magnified pixels.
    for c in [
        AppCommand::SetCompare(Compare::Wipe),
        AppCommand::SetWipe(0.3),
        AppCommand::SetImageSize(None),
        AppCommand::SetPixelSize(4),
        // Text size 1.5: overlays 1.5 times larger on screen, and so in the figure.
        AppCommand::SetUiScale(1.5),
        // Room for the canvas at that size.
        AppCommand::SetShowControls(false),
        AppCommand::SetShowInspector(false),
    ] {
        h.state_mut().push(c);
    }
    // The new zoom lays the window out again over the next frames.
    for _ in 0..4 {
        h.step();
    }
    h.run();
    assert_eq!(h.state().canvas().views[0].transform.scale, 4.0 / 1.5);
    let p = pin(&mut h);
    let dir = tempfile::tempdir().expect("tempdir");
    let folder = dir.path().join("figures");
    // Ctrl+S opens the panel; its Export button writes the files.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::S);
    h.run();
    assert!(h.state().export_panel().open);
    h.state_mut()
        .push_export(ExportCommand::SetFolder(folder.clone()));
    h.run();
    h.get_by_label("Export").click();
    h.run();
    let outcome = h.state().export_panel().outcome.clone().expect("outcome");
    assert!(!outcome.error, "{:?}", outcome.lines);
    for ext in ["png", "svg", "md", "tex", "json"] {
        assert!(folder.join(format!("figure-001.{ext}")).is_file(), "{ext}");
    }
    // Ctrl+S again with the panel open: a second set, the first untouched.
    let first = std::fs::read(folder.join("figure-001.png")).expect("png");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::S);
    h.run();
    assert!(folder.join("figure-002.png").is_file());
    assert_eq!(
        std::fs::read(folder.join("figure-001.png")).expect("png"),
        first
    );

    // The PNG is twice (the default scale) the canvas as shown (4 points per pixel) plus
    // margins and title strip.
    let size = h.state().canvas().output.as_ref().expect("rendered").size;
    let png = image::open(folder.join("figure-001.png")).expect("png");
    // (4 screen pixels per rendered pixel; margins and title strip at text size 1.5.)
    let [m, _, strip] = barylab::figure::layout_points(1.5);
    assert_eq!(
        (png.width(), png.height()),
        (2 * (4 * size[0] + 2 * m), 2 * (4 * size[1] + 2 * m + strip))
    );

    // The panel shows the `barylab figure` command for this figure; run on the exported
    // scene it writes the same files.
    let command = outcome
        .lines
        .iter()
        .find(|l| l.starts_with("barylab figure "))
        .expect("command shown")
        .clone();
    for part in [
        format!("--pixel {},{}", p[0], p[1]),
        "--compare wipe --wipe 0.3".to_string(),
        "--pixel-size 4".to_string(),
        "--overlay-scale 1.5".to_string(),
    ] {
        assert!(command.contains(&part), "{command}");
    }
    let args: Vec<&str> = command.split_whitespace().skip(1).collect();
    let o = args.iter().position(|a| *a == "-o").expect("-o");
    for ext in ["png", "svg"] {
        let out = dir.path().join(format!("cli.{ext}"));
        let run = Command::new(env!("CARGO_BIN_EXE_barylab"))
            .args(&args[..o])
            .arg("-o")
            .arg(&out)
            .output()
            .expect("run barylab");
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert!(
            std::fs::read(&out).expect("cli")
                == std::fs::read(folder.join(format!("figure-001.{ext}"))).expect("app"),
            "{ext} differs"
        );
    }
    // The derivation is the pinned pixel's.
    let md = std::fs::read_to_string(folder.join("figure-001.md")).expect("md");
    assert!(md.starts_with(&format!("# barylab probe: pixel ({}, {})", p[0], p[1])));
}

#[test]
fn export_into_an_impossible_folder_shows_the_error_and_keeps_the_scene() {
    let mut h = harness();
    pin(&mut h);
    let dir = tempfile::tempdir().expect("tempdir");
    let file = dir.path().join("file.txt");
    std::fs::write(&file, "x").expect("write");
    let folder = file.join("sub");
    let before = h.state().state().clone();
    h.state_mut().push_export(ExportCommand::Open);
    h.state_mut()
        .push_export(ExportCommand::SetFolder(folder.clone()));
    h.run();
    h.get_by_label("Export").click();
    h.run();
    let outcome = h.state().export_panel().outcome.clone().expect("outcome");
    assert!(outcome.error);
    let shown = folder.display().to_string();
    assert!(outcome.lines[0].contains(&shown), "{:?}", outcome.lines);
    // In the panel and on the status line.
    assert!(h.query_all_by_label_contains(&shown).count() >= 1);
    assert!(h.state().message().is_some_and(|m| m.contains(&shown)));
    assert!(*h.state().state() == before, "the scene changed");
    assert!(!Path::new(&folder).exists());
    assert_eq!(std::fs::read_dir(dir.path()).expect("list").count(), 1);
}

#[test]
fn export_without_a_folder_asks_for_one() {
    let mut h = harness();
    h.state_mut().push_export(ExportCommand::Open);
    h.run();
    h.get_by_label("Export").click();
    h.run();
    let outcome = h.state().export_panel().outcome.clone().expect("outcome");
    assert!(outcome.error);
    assert_eq!(outcome.lines, ["choose a folder first"]);
}

#[test]
fn copy_figure_reports_what_happened_and_never_panics() {
    // Headless there is usually no clipboard: then the panel says so in one line.
    let mut h = harness();
    pin(&mut h);
    h.state_mut().push_export(ExportCommand::Open);
    h.run();
    h.get_by_label("Copy figure").click();
    h.run();
    let outcome = h.state().export_panel().outcome.clone().expect("outcome");
    assert_eq!(outcome.lines.len(), 1);
    if outcome.error {
        assert!(
            outcome.lines[0].starts_with("cannot copy to the clipboard: "),
            "{:?}",
            outcome.lines
        );
    } else {
        assert_eq!(outcome.lines[0], "figure copied to the clipboard");
    }
    let before = h.state().state().clone();
    h.run();
    assert!(*h.state().state() == before);
}
