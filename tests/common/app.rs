//! The app under egui_kittest, for the GUI tests: one way to build the harness.

use barylab::app::{AppOptions, BaryApp};
use egui_kittest::Harness;

/// Frames the harness runs at most to let the app settle after an event.
pub const MAX_STEPS: u64 = 30;

/// The app with `options`, in a window of `size` points, after its first frames.
pub fn harness(size: egui::Vec2, options: AppOptions) -> Harness<'static, BaryApp> {
    harness_of(BaryApp::new(None, options), size)
}

/// `app` in a window of `size` points, after its first frames.
pub fn harness_of(app: BaryApp, size: egui::Vec2) -> Harness<'static, BaryApp> {
    let mut h = Harness::builder()
        .with_size(size)
        .with_max_steps(MAX_STEPS)
        .build_ui_state(|ui, app: &mut BaryApp| app.show(ui), app);
    h.run();
    h
}

/// The app presenting step `step` (from 1) of the lesson `lesson` (a built-in name or a
/// file) in `lang` at a lecture projector: a 1024x768 window at text size 1.5.
pub fn lecture(lesson: &str, step: usize, lang: barylab::i18n::Lang) -> Harness<'static, BaryApp> {
    lecture_with(lesson, step, lang, true)
}

/// [`lecture`], presenting or not (the Lessons panel under the canvas).
pub fn lecture_with(
    lesson: &str,
    step: usize,
    lang: barylab::i18n::Lang,
    present: bool,
) -> Harness<'static, BaryApp> {
    let lesson = barylab::lesson::Lesson::open(std::path::Path::new(lesson)).expect("the lesson");
    let mut h = harness(
        egui::vec2(1024.0, 768.0),
        AppOptions {
            lesson: Some((lesson, step - 1)),
            present,
            lang: Some(lang),
            ..AppOptions::default()
        },
    );
    h.state_mut()
        .push(barylab::app::document::state::StateCommand::SetUiScale(1.5));
    for _ in 0..4 {
        h.step();
    }
    h.run();
    h
}
