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
