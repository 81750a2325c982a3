//! Recording a drag in the app and exporting it (File > Export animation…), driven through
//! egui_kittest: R starts recording, a corner is dragged over a few frames, ■ Stop ends it,
//! the trim keeps part of it, Export writes a GIF in the background; the GIF decoded has one
//! frame per kept state, and frames change exactly where the recorded scene changed.

mod common;

use std::time::{Duration, Instant};

use barylab::app::command::{AnimationCommand, ExportCommand, FileCommand};
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::vertices_on_screen;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use image::AnimationDecoder;

const SIZE: egui::Vec2 = egui::vec2(1280.0, 800.0);

/// Corner A's position on the screen.
fn corner_a(h: &Harness<'_, BaryApp>) -> egui::Pos2 {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    let a = vertices_on_screen(&h.state().state().scene, out.viewport())[0]
        .window
        .expect("A on screen");
    h.state().canvas().views[0].transform.to_screen(a)
}

/// Steps the app until the export going on has finished (it runs on its own thread).
fn wait_for_export(h: &mut Harness<'_, BaryApp>) {
    let start = Instant::now();
    while h.state().animation_panel().exporting() {
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "the export ends"
        );
        std::thread::sleep(Duration::from_millis(50));
        h.step();
    }
    h.run();
}

fn gif_frames(path: &std::path::Path) -> Vec<image::RgbaImage> {
    let file = std::io::BufReader::new(std::fs::File::open(path).expect("the GIF"));
    image::codecs::gif::GifDecoder::new(file)
        .expect("a GIF")
        .into_frames()
        .collect_frames()
        .expect("its frames")
        .into_iter()
        .map(|f| f.into_buffer())
        .collect()
}

#[test]
fn a_recorded_drag_exports_as_a_gif_with_a_frame_per_kept_state() {
    let dir = tempfile::tempdir().expect("tempdir");
    let mut h = common::app::harness(SIZE, AppOptions::default());
    h.state_mut()
        .push_export(ExportCommand::SetFolder(dir.path().to_path_buf()));
    h.state_mut().push_export(ExportCommand::SetScale(1));
    h.state_mut().push(FileCommand::ExportAnimation);
    h.run();
    assert!(h.query_by_label("Export animation").is_some(), "the window");

    // R starts recording (and shows the recording in the window).
    h.key_press(egui::Key::R);
    h.run();
    assert!(h.state().animation_panel().recorder.recording());
    assert!(h.query_by_label("■ Stop").is_some());

    // Two still frames, then corner A dragged in four moves, then two still frames.
    h.step();
    let start = corner_a(&h);
    let before = h.state().state().scene.clone();
    h.hover_at(start);
    h.step();
    h.drag_at(start);
    h.step();
    let delta = egui::vec2(48.0, -32.0);
    for k in 1..=4 {
        h.hover_at(start + delta * (k as f32 / 4.0));
        h.step();
    }
    h.drop_at(start + delta);
    h.step();
    h.step();
    assert_ne!(h.state().state().scene, before, "the drag moved A");
    h.get_by_label("■ Stop").click();
    h.run();
    let panel = h.state().animation_panel();
    assert!(!panel.recorder.recording());
    let n = panel.recorder.len();
    // egui_kittest advances egui's clock by 1/4 s a frame: 6 or 7 ticks of 1/25 s each.
    assert!(n >= 6 * 9, "{n} frames recorded");
    assert!(
        h.query_by_label(&format!("{n} frames, {:.1} s", n as f64 / 25.0))
            .is_some(),
        "the window says what was recorded"
    );

    // Keep all but the first and the last frame, and export.
    h.state_mut().push(AnimationCommand::SetTrim(1, n - 2));
    h.run();
    let kept = h.state().animation_panel().recorder.trimmed();
    assert_eq!(kept.len(), n - 2);
    h.get_by_label("Export").click();
    h.run();
    wait_for_export(&mut h);
    let outcome = h
        .state()
        .animation_panel()
        .outcome
        .clone()
        .expect("an outcome");
    assert!(!outcome.error, "{:?}", outcome.lines);
    let path = dir.path().join("animation-001.gif");
    assert!(
        outcome.summary.contains("animation-001.gif"),
        "{}",
        outcome.summary
    );
    assert!(outcome.summary.contains(&format!("{} frames", n - 2)));
    assert_eq!(h.state().message(), Some(outcome.summary.as_str()));

    let frames = gif_frames(&path);
    assert_eq!(frames.len(), kept.len(), "a frame per kept state");
    let size = frames[0].dimensions();
    assert!(frames.iter().all(|f| f.dimensions() == size));
    let mut changes = 0;
    for k in 0..kept.len() - 1 {
        let same_state = kept[k] == kept[k + 1];
        assert_eq!(
            frames[k] == frames[k + 1],
            same_state,
            "frames {k} and {}: the state {}",
            k + 1,
            if same_state {
                "did not change"
            } else {
                "changed"
            }
        );
        changes += usize::from(!same_state);
    }
    assert!(changes >= 3, "the drag shows in {changes} changes");
    assert_ne!(frames[0], frames[frames.len() - 1]);

    // A second export never overwrites the first.
    h.get_by_label("Export").click();
    h.run();
    wait_for_export(&mut h);
    assert!(dir.path().join("animation-002.gif").exists());
}
