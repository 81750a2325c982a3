//! The app's 3D view: on with `--space-view`, its numbers are the pinned pixel's (P's
//! weights the inspector's a b c), they follow a dragged corner, and the Controls toggle
//! turns it off. Driven through egui_kittest like tests/app.rs.

mod common;

use barylab::app::AppOptions;
use barylab::app::document::state::StateCommand;
use barylab::probe::format::fmt_number;
use barylab::raster::project::Viewport;
use egui_kittest::kittest::Queryable;
use glam::DVec2;

const SIZE: egui::Vec2 = egui::vec2(1600.0, 1000.0);

/// The 3D view's line of P's weights for the pinned pixel's trace.
fn abc_line(h: &egui_kittest::Harness<'_, barylab::app::BaryApp>) -> String {
    let report = h.state().pin_report().expect("the pinned pixel is probed");
    let detail = report.trace.detail.as_ref().expect("a triangle");
    let abc = detail
        .perspective
        .as_ref()
        .expect("1/w > 0")
        .correction
        .weights;
    let [a, b, c] = abc.map(fmt_number);
    format!("P: a, b, c = {a}, {b}, {c}")
}

#[test]
fn the_3d_view_shows_the_pinned_pixels_weights_and_follows_a_drag() {
    let mut h = common::app::harness(
        SIZE,
        AppOptions {
            space_view: true,
            pin: Some([400, 420]),
            ..AppOptions::default()
        },
    );
    assert!(h.state().state().view.space);
    let before = abc_line(&h);
    assert!(
        h.query_by_label(&before).is_some(),
        "the 3D view shows {before}"
    );
    assert!(h.query_by_label("The pixel's ray in 3D").is_some());

    // Drag corner C (index 2) elsewhere on screen: P's weights change, and the view shows
    // the new ones.
    let size = h.state().canvas().output.as_ref().expect("rendered").size;
    h.state_mut().push(StateCommand::MoveVertex {
        index: 2,
        to: DVec2::new(600.0, 150.0),
        viewport: Viewport {
            width: size[0],
            height: size[1],
        },
    });
    h.run();
    let after = abc_line(&h);
    assert_ne!(before, after);
    assert!(
        h.query_by_label(&after).is_some(),
        "the 3D view shows {after}"
    );
    assert!(h.query_by_label(&before).is_none());

    h.state_mut().push(StateCommand::SetSpaceView(false));
    h.run();
    assert!(h.query_by_label(&after).is_none());
    assert!(h.query_by_label("The pixel's ray in 3D").is_none());
}

/// Presentation mode shows the 3D view beside the picture on a wide window (16:10 here), with
/// the pinned pixel's weights, and leaves a 4:3 projector's width to the picture.
#[test]
fn presenting_shows_the_3d_view_on_wide_windows_only() {
    for (size, shown) in [
        (egui::vec2(1600.0, 1000.0), true),
        (egui::vec2(1024.0, 768.0), false),
    ] {
        let mut h = common::app::harness(
            size,
            AppOptions {
                space_view: true,
                present: true,
                pin: Some([400, 420]),
                ..AppOptions::default()
            },
        );
        h.run();
        let line = abc_line(&h);
        assert_eq!(
            h.query_by_label("The pixel's ray in 3D").is_some(),
            shown,
            "at {size:?}"
        );
        assert_eq!(h.query_by_label(&line).is_some(), shown, "at {size:?}");
    }
}

/// On a 4:3 projector, V puts the 3D view (with the pinned pixel's weights) in the picture's
/// place; any change of the scene brings the picture back.
#[test]
fn v_shows_the_3d_view_in_the_pictures_place_on_a_projector() {
    let mut h = common::app::harness(
        egui::vec2(1024.0, 768.0),
        AppOptions {
            space_view: true,
            present: true,
            pin: Some([400, 420]),
            ..AppOptions::default()
        },
    );
    h.run();
    let line = abc_line(&h);
    assert!(h.query_by_label("The pixel's ray in 3D").is_none());
    assert!(
        h.query_by_label("V: the 3D view").is_some(),
        "the card offers V"
    );
    h.key_press(egui::Key::V);
    h.run();
    assert!(h.query_by_label("The pixel's ray in 3D").is_some());
    assert!(
        h.query_by_label(&line).is_some(),
        "the 3D view shows {line}"
    );
    assert!(h.query_by_label("V: back to the picture").is_some());
    h.state_mut().push(StateCommand::SetShowGrid(true));
    h.run();
    assert!(h.query_by_label("The pixel's ray in 3D").is_none());
}

/// The lesson's tetrahedron step: the 3D view draws the volume weights of the point where the
/// pinned pixel's ray runs through the tetrahedron, its entry weights the card's a b c.
#[test]
fn the_tetrahedron_step_weighs_the_pinned_pixels_point() {
    let lesson = barylab::lesson::Lesson::builtin().expect("built-in lesson");
    let last = lesson.steps.len() - 1;
    let mut h = common::app::harness(
        SIZE,
        AppOptions {
            lesson: Some((lesson, last)),
            ..AppOptions::default()
        },
    );
    h.run();
    assert!(h.state().state().view.space, "the step opens the 3D view");
    assert!(
        h.query_by_label("Volume weights of a point in a tetrahedron")
            .is_some()
    );
    let report = h.state().pin_report().expect("the step pins a pixel");
    let detail = report.trace.detail.as_ref().expect("a triangle");
    let [a, b, c] = detail
        .perspective
        .as_ref()
        .expect("1/w > 0")
        .correction
        .weights
        .map(fmt_number);
    let entry = format!(
        "P, where it enters through face A B D: λ = ({a}, {b}, 0, {c}); λ_C = 0 and the other three are that triangle's weights a b c"
    );
    assert!(h.query_by_label(&entry).is_some(), "the view shows {entry}");
}

/// In a lesson at a lecture projector (1024x768 at text size 1.5, not presenting), the 3D
/// view's panel ends where the Lessons panel begins in every step that opens it: its numbers
/// scroll under the drawing. (Its content overflowed the panel, which then reached down over
/// the lesson's buttons, its edge drawn across "Reset this step".)
#[test]
fn the_3d_view_stays_above_the_lesson_panel_at_a_lecture_projector() {
    let lesson = barylab::lesson::Lesson::builtin().expect("built-in lesson");
    let steps: Vec<usize> = (0..lesson.steps.len())
        .filter(|&i| lesson.steps[i].space_view)
        .collect();
    assert!(steps.len() >= 3, "steps with the 3D view: {steps:?}");
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        for &step in &steps {
            let mut h = common::app::harness(
                egui::vec2(1024.0, 768.0),
                AppOptions {
                    lesson: Some((lesson.clone(), step)),
                    lang: Some(lang),
                    ..AppOptions::default()
                },
            );
            h.state_mut().push(StateCommand::SetUiScale(1.5));
            for _ in 0..4 {
                h.step();
            }
            h.run();
            assert!(
                h.state().state().view.space,
                "step {} opens the 3D view",
                step + 1
            );
            let space = h.state().space_panel_rect().expect("the 3D view's panel");
            let lessons = h.state().lesson_panel_rect().expect("the Lessons panel");
            assert!(
                space.bottom() <= lessons.top() + 0.5,
                "{lang:?} step {}: the 3D view reaches {} over the lesson panel at {}",
                step + 1,
                space.bottom(),
                lessons.top()
            );
        }
    }
}

/// On a 1024x768 projector with text size 1.5 (not presenting), the 3D view beside the canvas
/// is a drawing a room cannot read (built-in step 16: a few hundred points, labels 12 points
/// high, one over another). Its Enlarge button puts it in the picture's place, its numbers in
/// a column beside it, above the Lessons panel; V goes back to the picture and again to the 3D
/// view, and a change of the scene brings the picture back.
#[test]
fn on_a_projector_the_3d_view_enlarges_into_the_pictures_place_and_back() {
    use barylab::i18n::Lang;
    for lang in [Lang::En, Lang::Zh] {
        let mut h = common::app::lecture_with("builtin", 16, lang, false);
        assert!(h.state().state().view.space, "step 16 shows the 3D view");
        let small = h.state().space_drawing_rect().expect("the drawing");
        let canvas = h.state().canvas().area.expect("the canvas");
        let lessons = h.state().lesson_panel_rect().expect("the Lessons panel");
        h.get_by_label(&lang.tr("space.enlarge")).click();
        h.run();
        let big = h.state().space_drawing_rect().expect("the drawing");
        // The height is the room above the Lessons panel either way; the width grows.
        assert!(
            big.area() >= 1.4 * small.area() && big.height() >= small.height(),
            "{lang:?}: enlarged {big:?}, beside the canvas {small:?}"
        );
        assert!(
            big.intersects(canvas) && big.left() <= canvas.left() + 20.0,
            "{lang:?}: {big:?} is not in the picture's place {canvas:?}"
        );
        assert!(
            big.bottom() <= lessons.top() + 0.5,
            "{lang:?}: {big:?} over the Lessons panel {lessons:?}"
        );
        assert!(h.query_by_label(&lang.tr("space.shrink")).is_some());
        if lang == Lang::En {
            let numbers = h.get_by_label(&abc_line(&h)).rect();
            assert!(
                numbers.left() >= big.right() && numbers.bottom() <= lessons.top() + 0.5,
                "P's weights {numbers:?} beside the drawing {big:?}"
            );
        }
        h.key_press(egui::Key::V);
        h.run();
        let back = h.state().space_drawing_rect().expect("the drawing");
        assert!(
            (back.width() - small.width()).abs() < 1.0,
            "{lang:?}: V brings the picture back: {back:?}, was {small:?}"
        );
        assert!(h.query_by_label(&lang.tr("space.enlarge")).is_some());
        h.key_press(egui::Key::V);
        h.run();
        let again = h.state().space_drawing_rect().expect("the drawing");
        assert!(
            again.area() >= 1.4 * small.area(),
            "{lang:?}: V enlarges it"
        );
        h.state_mut().push(StateCommand::SetShowGrid(true));
        h.run();
        let after = h.state().space_drawing_rect().expect("the drawing");
        assert!(
            (after.width() - small.width()).abs() < 1.0,
            "{lang:?}: a change of the scene brings the picture back: {after:?}"
        );
        // A quiz (Q, on the pinned pixel) is on the picture: it comes back for it, and stays
        // after the quiz.
        h.key_press(egui::Key::V);
        h.run();
        assert!(h.query_by_label(&lang.tr("space.shrink")).is_some());
        h.key_press(egui::Key::Q);
        h.run();
        assert!(h.state().quiz_rect().is_some(), "{lang:?}: Q starts a quiz");
        h.key_press(egui::Key::Q);
        h.run();
        assert!(h.state().quiz_rect().is_none(), "{lang:?}: Q ends it");
        let after_quiz = h.state().space_drawing_rect().expect("the drawing");
        assert!(
            (after_quiz.width() - small.width()).abs() < 1.0,
            "{lang:?}: after a quiz the picture stays: {after_quiz:?}"
        );
    }
}

/// V pressed while the pointer is on the canvas (the natural way at a lecture), in
/// presentation mode and not: the 3D view in the picture's place traces the pinned pixel, not
/// the pixel the pointer was on before the canvas went away (which nothing hovers any more).
#[test]
fn the_enlarged_3d_view_traces_the_pinned_pixel_not_the_last_hovered_one() {
    for present in [false, true] {
        let mut h = common::app::lecture_with("builtin", 16, barylab::i18n::Lang::En, present);
        let pinned = h.state().state().view.pinned.expect("step 16 pins a pixel");
        let view = h.state().canvas().views[0];
        let other = [pinned[0] + 40, pinned[1].saturating_sub(40)];
        let at = view.transform.to_screen(DVec2::new(
            f64::from(other[0]) + 0.5,
            f64::from(other[1]) + 0.5,
        ));
        h.hover_at(at);
        h.run();
        assert_eq!(
            h.state().canvas().hover,
            Some(other),
            "the pointer is on {other:?}"
        );
        h.key_press(egui::Key::V);
        h.run();
        let back = if present {
            "V: back to the picture"
        } else {
            "Back to the picture"
        };
        assert!(
            h.query_by_label(back).is_some(),
            "present {present}: V enlarges"
        );
        assert_eq!(
            h.state().canvas().hover,
            None,
            "present {present}: nothing is hovered"
        );
        let line = abc_line(&h);
        assert!(
            h.query_by_label(&line).is_some(),
            "present {present}: the view shows the pinned pixel's {line}"
        );
    }
}
