//! A file named on the command line that cannot be opened: the app starts on the default
//! scene and shows why in the window (issue 30: it used to exit before opening a window, so a
//! teacher who started it from a file manager saw nothing).

mod common;

use barylab::app::AppOptions;
use barylab::scene::Scene;

#[test]
fn a_start_up_error_is_shown_over_the_default_scene() {
    let e = "/tmp/x.json: is not a scene: a scene is a JSON object ({ ... }), this file holds \
             a JSON array ([ ... ])";
    let h = common::app::harness(
        egui::vec2(1200.0, 800.0),
        AppOptions {
            startup_error: Some(e.to_string()),
            ..AppOptions::default()
        },
    );
    assert_eq!(h.state().message(), Some(e));
    assert_eq!(h.state().state().scene, Scene::default_scene());
    assert!(
        h.state().canvas().output.is_some(),
        "the default scene is drawn"
    );
}
