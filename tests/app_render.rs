//! The canvas's long renders (issue 30): a render that takes longer than a frame goes on on a
//! thread of its own while the previous picture stays, under a progress bar with Cancel;
//! Cancel keeps the previous picture and its numbers, and says how to make the render lighter.

mod common;

use std::time::{Duration, Instant};

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const SIZE: egui::Vec2 = egui::vec2(1500.0, 950.0);

/// The shown picture's size and generation.
fn shown(h: &Harness<'static, BaryApp>) -> ([u32; 2], u64) {
    let out = h.state().canvas().output.as_ref().expect("a picture");
    (out.size, out.generation)
}

/// Asserts that the first view is laid out for a picture of `size`: its screen rectangle is
/// `size` pixels at its scale (so the pixel under the pointer is the shown picture's).
fn laid_out_for(h: &Harness<'static, BaryApp>, size: [u32; 2]) {
    let v = h.state().canvas().views.first().expect("a view");
    let s = v.transform.scale;
    assert!(
        (v.rect.width() - size[0] as f32 * s).abs() < 0.01
            && (v.rect.height() - size[1] as f32 * s).abs() < 0.01,
        "{:?} at {s} points a pixel is not {size:?}",
        v.rect
    );
}

/// Runs frames (a few milliseconds apart) until the picture shown is `size`, at most a
/// minute.
fn until_drawn(h: &mut Harness<'static, BaryApp>, size: [u32; 2]) {
    let start = Instant::now();
    while shown(h).0 != size {
        assert!(start.elapsed() < Duration::from_secs(60), "still drawing");
        std::thread::sleep(Duration::from_millis(20));
        h.step();
    }
    assert_eq!(h.state().canvas().underway(), None);
}

/// Runs frames until the render of `size` is under way on its own thread (it took longer
/// than a frame), at most 20 frames.
fn until_underway(h: &mut Harness<'static, BaryApp>, size: [u32; 2]) {
    for _ in 0..20 {
        h.step();
        if let Some(u) = h.state().canvas().underway() {
            assert_eq!(u.size, size);
            return;
        }
    }
    panic!("the {size:?} render was not under way");
}

#[test]
fn a_long_render_shows_progress_and_can_be_cancelled() {
    let mut h = common::app::harness(SIZE, AppOptions::default());
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([320, 240])));
    h.run();
    let (before, generation) = shown(&h);
    assert_eq!(before, [320, 240]);
    let pin = [100, 80];
    h.state_mut().push(StateCommand::Pin(Some(pin)));
    h.run();
    let report = format!("{:?}", h.state().pin_report().expect("pinned"));
    // 8192x8192 default scene: 67 million pixels of two triangles, seconds of work.
    let big = [8192, 8192];
    h.state_mut().push(StateCommand::SetImageSize(Some(big)));
    until_underway(&mut h, big);
    // (A new area is laid out unseen in its first frame.)
    h.step();
    // The previous picture stays, with its numbers, under the progress bar.
    assert_eq!(shown(&h), (before, generation));
    laid_out_for(&h, before);
    h.get_by_label_contains("Drawing the 8192×8192 picture");
    h.get_by_label("Cancel").click();
    h.step();
    h.step();
    h.step();
    assert_eq!(h.state().canvas().underway(), None);
    assert_eq!(shown(&h), (before, generation), "the previous picture");
    assert_eq!(h.state().canvas().cancelled, Some(big));
    h.get_by_label_contains("The 8192×8192 picture was cancelled");
    h.get_by_label_contains("choose a smaller image size");
    // Nothing starts the same render again by itself. A pixel pinned now is the shown
    // picture's (the size change unpinned the old one).
    h.state_mut().push(StateCommand::Pin(Some(pin)));
    h.run();
    assert_eq!(h.state().canvas().underway(), None);
    assert_eq!(shown(&h), (before, generation));
    assert_eq!(
        format!("{:?}", h.state().pin_report().expect("pinned")),
        report,
        "the pinned pixel's numbers are the shown picture's"
    );
    // A lighter size is drawn at once, and the note goes.
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([160, 120])));
    h.run();
    assert_eq!(shown(&h).0, [160, 120]);
    laid_out_for(&h, [160, 120]);
    assert_eq!(shown(&h).1, generation + 1);
    assert_eq!(h.state().canvas().cancelled, None);
    assert!(h.query_by_label_contains("was cancelled").is_none());
}

#[test]
fn a_long_render_left_alone_is_shown_when_done() {
    let mut h = common::app::harness(SIZE, AppOptions::default());
    let (_, generation) = shown(&h);
    let big = [3000, 3000];
    h.state_mut().push(StateCommand::SetImageSize(Some(big)));
    until_drawn(&mut h, big);
    assert_eq!(shown(&h), (big, generation + 1));
    let out = h.state().canvas().output.as_ref().expect("a picture");
    let render = out.renders.first().expect("a render");
    assert_eq!(render.1.frame.color.len(), 3000 * 3000);
    assert!(h.query_by_label_contains("Drawing the").is_none());
}
