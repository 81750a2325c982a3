//! The classroom: fixed image sizes (a pin stays on its pixel through any layout change), the
//! canvas's share of a projector's window, presentation mode, undo and redo. Driven through
//! egui_kittest like tests/app.rs.

mod common;

use std::process::Command as Process;

use barylab::app::command::AppCommand;
use barylab::app::command::ExportCommand;
use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::Compare;
use barylab::probe::format::fmt_digits;
use barylab::scene::Scene;
use egui::Pos2;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec2;

fn harness(size: egui::Vec2) -> Harness<'static, BaryApp> {
    common::app::harness(size, AppOptions::default())
}

/// Lets a new window size or text size settle (the zoom lays the window out again).
fn settle(h: &mut Harness<'_, BaryApp>) {
    for _ in 0..4 {
        h.step();
    }
    h.run();
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

/// Moves the pointer off the canvas (onto the status line's left end).
fn away(h: &mut Harness<'_, BaryApp>) {
    let screen = h.ctx.content_rect();
    h.hover_at(Pos2::new(screen.left() + 2.0, screen.bottom() - 2.0));
    h.run();
}

/// The pinned pixel's screen weights, corrected weights and W_P, as the inspector has them.
fn pin_numbers(h: &Harness<'_, BaryApp>) -> ([u32; 2], Vec<f64>) {
    let r = h.state().pin_report().expect("pin report");
    let d = r.trace.detail.as_ref().expect("covered");
    let p = d.perspective.expect("1/w");
    let mut n = d.screen.rasterizer.to_vec();
    n.extend(p.correction.weights);
    n.push(p.correction.w_p);
    (r.pixel, n)
}

fn canvas_share(h: &Harness<'_, BaryApp>) -> f32 {
    let area = h.state().canvas().area.expect("laid out");
    let screen = h.ctx.content_rect();
    area.area() / screen.area()
}

#[test]
fn a_pin_stays_on_its_pixel_through_resizes_panels_comparisons_and_text_size() {
    let mut h = harness(egui::vec2(1500.0, 950.0));
    assert_eq!(
        h.state().canvas().output.as_ref().expect("rendered").size,
        [800, 600]
    );
    let p = [300, 420];
    let pos = pixel_centre(&h, p);
    click(&mut h, pos);
    away(&mut h);
    assert_eq!(h.state().state().view.pinned, Some(p));
    let reference = pin_numbers(&h);
    let changes: Vec<Vec<AppCommand>> = vec![
        vec![],
        vec![StateCommand::SetShowControls(false).into()],
        vec![StateCommand::SetShowInspector(false).into()],
        vec![StateCommand::SetCompare(Compare::SideBySide).into()],
        vec![StateCommand::SetCompare(Compare::Wipe).into()],
        vec![StateCommand::SetUiScale(1.6).into()],
        vec![
            StateCommand::SetShowControls(true).into(),
            StateCommand::SetShowInspector(true).into(),
            StateCommand::SetCompare(Compare::Single).into(),
            StateCommand::SetUiScale(1.0).into(),
        ],
    ];
    for size in [[1024.0, 768.0], [1280.0, 800.0], [1920.0, 1080.0]] {
        h.set_size(egui::vec2(size[0], size[1]));
        for c in &changes {
            for c in c {
                h.state_mut().push(c.clone());
            }
            settle(&mut h);
            let out = h.state().canvas().output.as_ref().expect("rendered");
            assert_eq!(
                out.size,
                [800, 600],
                "the image follows the layout at {size:?}"
            );
            assert_eq!(h.state().state().view.pinned, Some(p));
            assert_eq!(pin_numbers(&h), reference, "{size:?} after {c:?}");
        }
    }
}

#[test]
fn image_sizes_for_teaching_are_drawn_with_square_whole_pixels() {
    let mut h = harness(egui::vec2(1024.0, 768.0));
    for size in [[32, 24], [160, 120], [320, 240], [1280, 720]] {
        h.state_mut().push(StateCommand::SetImageSize(Some(size)));
        settle(&mut h);
        let out = h.state().canvas().output.as_ref().expect("rendered");
        assert_eq!(out.size, size);
        let view = h.state().canvas().views[0];
        let px = view.transform.scale * h.ctx.pixels_per_point();
        if px >= barylab::app::panels::canvas_layout::WHOLE_PIXELS_FROM {
            assert_eq!(px, px.round(), "{size:?}: {px} screen pixels per pixel");
        }
        assert!(view.rect.width() <= h.state().canvas().area.expect("laid out").width() + 0.5);
    }
    // 32x24 on a projector: every pixel is a big square, grid and sample points shown.
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([32, 24])));
    settle(&mut h);
    assert!(h.state().canvas().pixel_size >= 10);
    // "Fit window" follows the canvas again.
    h.state_mut().push(StateCommand::SetImageSize(None));
    settle(&mut h);
    let out = h.state().canvas().output.as_ref().expect("rendered");
    assert!(out.size[0] > 300, "{:?}", out.size);
}

#[test]
fn the_canvas_keeps_half_the_window_on_projectors_at_any_text_size() {
    for size in [[1024.0, 768.0], [1280.0, 800.0]] {
        let mut h = harness(egui::vec2(size[0], size[1]));
        for scale in [1.0, 1.3, 1.5, 2.0] {
            h.state_mut().push(StateCommand::SetUiScale(scale));
            settle(&mut h);
            let share = canvas_share(&h);
            assert!(
                share >= 0.5,
                "{size:?} at text size {scale}: canvas {share} {:?} of {:?}",
                h.state().canvas().area,
                h.ctx.content_rect()
            );
        }
    }
}

#[test]
fn presentation_mode_shows_the_pins_numbers_large_and_pages_through_presets() {
    let mut h = harness(egui::vec2(1024.0, 768.0));
    let p = [400, 420];
    h.key_press(egui::Key::F5);
    settle(&mut h);
    assert!(h.state().presenting());
    // No panels: the canvas has the window above the card.
    assert!(canvas_share(&h) > 0.6, "{}", canvas_share(&h));
    assert!(h.query_by_label("Present").is_none(), "top bar hidden");
    let pos = pixel_centre(&h, p);
    click(&mut h, pos);
    away(&mut h);
    let r = h.state().pin_report().expect("pinned");
    let c = r
        .trace
        .detail
        .as_ref()
        .and_then(|d| d.perspective)
        .expect("1/w");
    // The card's numbers are the trace's (on one line, or two on a narrow card).
    for line in [
        format!("1/W_P = {}", fmt_digits(c.correction.inv_w_p, 4)),
        format!("W_P = {}", fmt_digits(c.correction.w_p, 4)),
    ] {
        assert!(
            h.query_by_label_contains(&line).is_some(),
            "no {line:?} on the card"
        );
    }
    // The card names the pixel's depth, the trace's window depth.
    let depth = r
        .trace
        .detail
        .as_ref()
        .and_then(|d| d.depth)
        .expect("depth");
    let line = format!("depth z/w = {}", fmt_digits(depth.depth, 4));
    assert!(h.query_by_label(&line).is_some(), "no {line:?} on the card");
    // Page Down loads the first preset, Page Up steps back around to the last one; the pin
    // stays, and the card names the preset.
    h.key_press(egui::Key::PageDown);
    h.run();
    let front = barylab::app::document::presets::Preset::FrontFacing;
    let mut expected = front.scene();
    expected.set_size(800, 600);
    assert_eq!(h.state().state().scene, expected);
    assert_eq!(h.state().state().view.pinned, Some(p));
    assert!(
        h.query_by_label("Front-facing").is_some(),
        "the card names the preset"
    );
    h.key_press(egui::Key::PageUp);
    h.run();
    let last = barylab::app::document::presets::Preset::ALL
        [barylab::app::document::presets::Preset::ALL.len() - 1];
    let mut expected = last.scene();
    expected.set_size(800, 600);
    assert_eq!(h.state().state().scene, expected);
    // Esc leaves.
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(!h.state().presenting());
    assert!(h.query_by_label("Present").is_some());
}

#[test]
fn undo_restores_the_exact_corners_after_a_drag_and_redo_brings_them_back() {
    let mut h = harness(egui::vec2(1500.0, 950.0));
    let start_scene = h.state().state().scene.clone();
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let a = barylab::figure::vertices_on_screen(&start_scene, out.viewport())[0]
        .window
        .expect("A on screen");
    let start = h.state().canvas().views[0].transform.to_screen(a);
    h.hover_at(start);
    h.run();
    h.drag_at(start);
    h.run();
    for k in 1..=5 {
        h.hover_at(start + egui::vec2(12.0, -8.0) * k as f32);
        h.run();
    }
    h.drop_at(start + egui::vec2(60.0, -40.0));
    h.run();
    let dragged = h.state().state().scene.clone();
    assert_ne!(dragged, start_scene);
    // A preset on top: two steps.
    h.state_mut().push(StateCommand::Preset(
        barylab::app::document::presets::Preset::GrazingWall,
    ));
    h.run();
    let preset = h.state().state().scene.clone();
    assert_eq!(h.state().history().undo_steps(), 2);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(h.state().state().scene, dragged);
    // The whole drag is one step.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(h.state().state().scene, start_scene);
    assert!(!h.state().history().can_undo());
    h.key_press_modifiers(
        egui::Modifiers::COMMAND | egui::Modifiers::SHIFT,
        egui::Key::Z,
    );
    h.run();
    assert_eq!(h.state().state().scene, dragged);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Y);
    h.run();
    assert_eq!(h.state().state().scene, preset);
    assert!(!h.state().history().can_redo());
}

#[test]
fn the_exported_derivation_is_what_barylab_probe_prints_for_the_exported_scene() {
    let mut h = harness(egui::vec2(1024.0, 768.0));
    // A layout change after pinning: the exported numbers are still the pinned pixel's.
    let p = [333, 444];
    let pos = pixel_centre(&h, p);
    click(&mut h, pos);
    away(&mut h);
    h.state_mut()
        .push(StateCommand::SetCompare(Compare::SideBySide));
    h.set_size(egui::vec2(1280.0, 800.0));
    settle(&mut h);
    let dir = tempfile::tempdir().expect("tempdir");
    let folder = dir.path().join("out");
    for c in [
        ExportCommand::SetFolder(folder.clone()),
        ExportCommand::Export,
    ] {
        h.state_mut().push_export(c);
    }
    h.run();
    let outcome = h.state().export_panel().outcome.clone().expect("outcome");
    assert!(!outcome.error, "{:?}", outcome.lines);
    let md = std::fs::read_to_string(folder.join("figure-001.md")).expect("md");
    let json = folder.join("figure-001.json");
    let scene = Scene::load(&json).expect("exported scene");
    assert_eq!(scene.size(), (800, 600));
    let run = Process::new(env!("CARGO_BIN_EXE_barylab"))
        .arg("probe")
        .arg(&json)
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
    assert_eq!(String::from_utf8_lossy(&run.stdout), md);
}

#[test]
fn save_scene_writes_the_json_that_render_and_probe_read() {
    use barylab::app::command::FileCommand;
    let mut h = harness(egui::vec2(1280.0, 800.0));
    h.state_mut().push(StateCommand::Preset(
        barylab::app::document::presets::Preset::GrazingWall,
    ));
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([320, 240])));
    h.run();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("lesson.json");
    h.state_mut().push(FileCommand::SaveTo(path.clone()));
    h.run();
    assert!(
        h.state()
            .message()
            .is_some_and(|m| m.contains("lesson.json"))
    );
    let saved = Scene::load(&path).expect("saved scene loads");
    assert_eq!(saved, h.state().state().scene);
    assert_eq!(saved.size(), (320, 240));
    // File > Save writes the same file again, with the newest edit, and nothing else.
    h.state_mut().push(StateCommand::SetFov(40.0));
    h.state_mut().push(StateCommand::Preset(
        barylab::app::document::presets::Preset::FrontFacing,
    ));
    h.state_mut().push(FileCommand::Save);
    h.run();
    assert_eq!(Scene::load(&path).expect("saved"), h.state().state().scene);
    assert_eq!(std::fs::read_dir(dir.path()).expect("list").count(), 1);
    let run = Process::new(env!("CARGO_BIN_EXE_barylab"))
        .arg("probe")
        .arg(&path)
        .args(["--pixel", "160,120"])
        .output()
        .expect("run barylab probe");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}

#[test]
fn a_red_message_goes_when_its_cause_does() {
    let mut h = harness(egui::vec2(1280.0, 800.0));
    let bad = StateCommand::SetCorner {
        index: 0,
        position: glam::DVec3::new(f64::NAN, 0.0, 0.0),
        uv: glam::Vec2::ZERO,
        color: glam::Vec3::ONE,
    };
    h.state_mut().push(bad.clone());
    h.run();
    assert!(h.state().message().is_some(), "the failed edit is reported");
    // The next edit that works replaces the cause.
    h.state_mut()
        .push(StateCommand::SetTilt(barylab::scene::Tilt {
            pitch_deg: 10.0,
            yaw_deg: 0.0,
        }));
    h.run();
    assert_eq!(h.state().message(), None);
    // A preset starts afresh too.
    h.state_mut().push(bad);
    h.run();
    assert!(h.state().message().is_some());
    h.state_mut().push(StateCommand::Preset(
        barylab::app::document::presets::Preset::Floor,
    ));
    h.run();
    assert_eq!(h.state().message(), None);
}

#[test]
fn escape_closes_an_open_menu_before_it_unpins() {
    let mut h = harness(egui::vec2(1500.0, 950.0));
    let p = [300, 420];
    let pos = pixel_centre(&h, p);
    click(&mut h, pos);
    away(&mut h);
    h.get_by_label("File").click();
    h.run();
    assert!(
        h.query_by_label("Save scene as…").is_some(),
        "the menu is open"
    );
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(
        h.query_by_label("Save scene as…").is_none(),
        "Escape closed the menu"
    );
    assert_eq!(
        h.state().state().view.pinned,
        Some(p),
        "and left the pin alone"
    );
    h.key_press(egui::Key::Escape);
    h.run();
    assert_eq!(h.state().state().view.pinned, None);
}

/// Presenting a lesson at a projector's size: the strip under the picture names the step,
/// and the card does not repeat it in its small line (it was cut short there, too small for a
/// room), in both languages; outside a lesson the card still names the preset (above).
#[test]
fn presenting_a_lesson_names_the_step_once_in_the_strip() {
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        let lesson = barylab::lesson::Lesson::builtin().expect("the built-in lesson");
        let total = lesson.steps.len();
        let title = lesson.steps[2].title.get(lang).to_string();
        let mut h = common::app::harness(
            egui::vec2(1024.0, 768.0),
            AppOptions {
                lesson: Some((lesson, 2)),
                present: true,
                lang: Some(lang),
                ..AppOptions::default()
            },
        );
        settle(&mut h);
        assert!(h.state().presenting());
        let step = lang.tr_with("lesson.step_of", &[("n", &3), ("total", &total)]);
        assert_eq!(
            h.query_all_by_label_contains(&step).count(),
            1,
            "{lang:?}: {step:?} once, in the strip"
        );
        assert!(
            h.query_by_label(&title).is_some(),
            "{lang:?}: the strip names the title {title:?}"
        );
    }
}

/// The difference heatmap's colour bar at a lecture projector (1024x768, text size 1.5),
/// with the Lessons panel under a shrunk canvas (built-in lesson step 10) and presenting:
/// the bar, down to its 0 tick, lies on the shown image's height. (Sized for the image's
/// pixels, it ran past the bottom of the shrunk image and its 0 was cut off.)
#[test]
fn the_colour_bar_fits_the_shown_image_at_a_lecture_projector() {
    for present in [false, true] {
        let h = common::app::lecture_with("builtin", 10, barylab::i18n::Lang::En, present);
        let area = h.state().canvas().area.expect("laid out");
        let ticks: Vec<egui::Rect> = h
            .output()
            .shapes
            .iter()
            .filter_map(|c| match &c.shape {
                egui::Shape::Text(s) if s.galley.job.text == "0" => {
                    Some(s.galley.rect.translate(s.pos.to_vec2()))
                }
                _ => None,
            })
            .collect();
        assert_eq!(ticks.len(), 1, "present {present}: one 0 tick, {ticks:?}");
        assert!(
            area.contains_rect(ticks[0]),
            "present {present}: the 0 tick {:?} outside the canvas {area:?}",
            ticks[0]
        );
    }
}

/// At a lecture projector (1024x768, text size 1.5) with the Lessons panel under the canvas,
/// on every step of the three built-in lessons in both languages, the lesson's first row
/// (Previous, the step, Next) lies whole inside the Lessons panel, and the canvas and the
/// panel beside it end above it. (On texture step 9 the plot's chosen name wrapped to three
/// lines, the plot overflowed the panel, and the canvas covered Previous and Next.)
#[test]
fn every_step_keeps_previous_and_next_in_sight_beside_the_lessons_panel() {
    for lesson in ["builtin", "texture", "samples"] {
        let count = barylab::lesson::Lesson::open(std::path::Path::new(lesson))
            .expect("lesson")
            .steps
            .len();
        for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
            for step in 1..=count {
                let h = common::app::lecture_with(lesson, step, lang, false);
                let what = format!("{lesson} step {step} {lang:?}");
                let panel = h.state().lesson_panel_rect().expect("the Lessons panel");
                for key in ["lesson.previous", "lesson.next"] {
                    let b = h
                        .query_by_label(&lang.tr(key))
                        .unwrap_or_else(|| panic!("{what}: {key}"))
                        .rect();
                    assert!(
                        panel.expand(0.5).contains_rect(b),
                        "{what}: {key} at {b:?} outside the Lessons panel {panel:?}"
                    );
                }
                let canvas = h.state().canvas().area.expect("laid out");
                assert!(
                    canvas.bottom() <= panel.top() + 0.5,
                    "{what}: the canvas {canvas:?} reaches over the Lessons panel {panel:?}"
                );
                if let Some(space) = h.state().space_panel_rect() {
                    assert!(
                        space.bottom() <= panel.top() + 0.5,
                        "{what}: the 3D view {space:?}"
                    );
                }
            }
        }
    }
}

/// At a lecture projector (1024x768, text size 1.5) without presenting, the plot beside a
/// step's text keeps a height a room can read its curve in (50 points inside its axes), inside
/// the Lessons panel, on every step with a plot (built-in steps 11 and 15, texture step 9), in
/// English and Chinese. (Under "Plot:", the plot's name and two legend rows, it had 48 points,
/// the axes included.)
#[test]
fn a_steps_plot_beside_its_text_keeps_a_readable_height() {
    let mut seen = 0;
    for lesson in ["builtin", "texture"] {
        let steps = barylab::lesson::Lesson::open(std::path::Path::new(lesson))
            .expect("lesson")
            .steps;
        for (i, step) in steps.iter().enumerate() {
            if step.plot.is_none() {
                continue;
            }
            for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
                let h = common::app::lecture_with(lesson, i + 1, lang, false);
                let what = format!("{lesson} step {} {lang:?}", i + 1);
                let panel = h.state().lesson_panel_rect().expect("the Lessons panel");
                let plot = BaryApp::plot_rect(&h.ctx).unwrap_or_else(|| panic!("{what}: no plot"));
                assert!(
                    plot.height() >= 50.0,
                    "{what}: the plot is {} points high",
                    plot.height()
                );
                assert!(
                    panel.expand(0.5).contains_rect(plot),
                    "{what}: the plot {plot:?} outside the Lessons panel {panel:?}"
                );
                seen += 1;
            }
        }
    }
    assert_eq!(seen, 6, "three steps with a plot, in two languages");
}

/// On a 1024x768 projector with text size 1.5, built-in step 15 shows the 3D view beside a
/// canvas shortened by the step's plot: its drawing takes most of the panel's height (the
/// numbers, which had two cut lines under it, go into its tooltip). It had 97 of the panel's
/// 213 points.
#[test]
fn a_short_3d_view_gives_its_height_to_the_drawing() {
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        let h = common::app::lecture_with("builtin", 15, lang, false);
        let panel = h.state().space_panel_rect().expect("the 3D view's panel");
        let drawing = h.state().space_drawing_rect().expect("the drawing");
        assert!(
            panel.expand(0.5).contains_rect(drawing),
            "{lang:?}: {drawing:?} in {panel:?}"
        );
        assert!(
            drawing.height() >= 0.6 * panel.height(),
            "{lang:?}: the drawing is {} of the panel's {} points",
            drawing.height(),
            panel.height()
        );
    }
}

/// On a 1024x768 projector with text size 1.5 (not presenting), the samples lesson draws its
/// 120x120 picture at 2x: a room cannot see which samples each triangle covers. Beside the
/// canvas the pinned pixel is enlarged with its samples, at least 150 points square, clear of
/// the picture and the Lessons panel; a single-sample step (the last) has no such column.
#[test]
fn the_samples_lesson_enlarges_the_pinned_pixels_samples_beside_the_canvas() {
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        for step in 2..=5 {
            let h = common::app::lecture_with("samples", step, lang, false);
            let what = format!("samples step {step} {lang:?}");
            let column = h
                .state()
                .magnifier_rect()
                .unwrap_or_else(|| panic!("{what}: no magnifier"));
            assert!(
                column.width() >= 150.0 && column.height() >= 150.0,
                "{what}: the magnifier is {column:?}"
            );
            let canvas = h.state().canvas();
            assert!(!canvas.views.is_empty());
            for v in &canvas.views {
                assert!(
                    !column.intersects(v.rect),
                    "{what}: the magnifier {column:?} over the picture {:?}",
                    v.rect
                );
            }
            let panel = h.state().lesson_panel_rect().expect("the Lessons panel");
            assert!(
                column.bottom() <= panel.top() + 0.5,
                "{what}: {column:?} over the Lessons panel {panel:?}"
            );
        }
        let h = common::app::lecture_with("samples", 6, lang, false);
        assert_eq!(h.state().magnifier_rect(), None, "one sample per pixel");
    }
}
