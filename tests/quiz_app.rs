//! The app's quiz mode (issue 34, item 5): on a quiz step in presentation mode at 1024x768,
//! text size 1.5, the pinned pixel's numbers are hidden; the class's prediction is typed;
//! Reveal shows the answer, the difference and the diagnosis. Driven through egui_kittest.

mod common;

use barylab::app::AppOptions;
use barylab::app::command::QuizCommand;
use barylab::i18n::Lang;
use barylab::lesson::Lesson;
use egui_kittest::kittest::Queryable;

const SIZE: egui::Vec2 = egui::vec2(1024.0, 768.0);

/// The built-in lesson's step 6 (index 5): the quiz asks r, s, t at (120, 180).
fn presenting_step_6(lang: Lang) -> egui_kittest::Harness<'static, barylab::app::BaryApp> {
    common::app::harness(
        SIZE,
        AppOptions {
            lesson: Some((Lesson::builtin().expect("the built-in lesson"), 5)),
            present: true,
            text_size: Some(1.5),
            lang: Some(lang),
            ..AppOptions::default()
        },
    )
}

/// The pinned pixel's r, s, t, from its trace (what the inspector would show).
fn rst(h: &egui_kittest::Harness<'_, barylab::app::BaryApp>) -> [f64; 3] {
    let report = h.state().pin_report().expect("the pinned pixel is probed");
    assert_eq!(report.pixel, [120, 180]);
    report
        .trace
        .detail
        .as_ref()
        .expect("a triangle")
        .screen
        .rasterizer
}

fn shown(h: &egui_kittest::Harness<'_, barylab::app::BaryApp>, text: &str) -> bool {
    h.query_all_by_label_contains(text).next().is_some()
}

#[test]
fn a_quiz_step_hides_the_numbers_until_reveal_and_diagnoses_a_swap() {
    let mut h = presenting_step_6(Lang::En);
    assert!(h.state().presenting());
    assert!(shown(&h, "Predict at pixel (120, 180)"));
    let [r, s, t] = rst(&h);
    // Hidden: no 4-digit r, s or t anywhere (the card would show them).
    for v in [r, s, t] {
        assert!(
            !shown(&h, &format!("{v:.4}")),
            "{v:.4} is shown before Reveal"
        );
    }
    assert!(h.query_by_label("Reveal").is_some());

    // The class swaps r and s: typed into the three fields.
    assert_eq!(
        h.get_all_by_role(egui::accesskit::Role::TextInput).count(),
        3,
        "a field per number"
    );
    for (i, v) in [s, r, t].into_iter().enumerate() {
        let field = h
            .get_all_by_role(egui::accesskit::Role::TextInput)
            .nth(i)
            .expect("the field");
        field.focus();
        field.type_text(&format!("{v:.3}"));
        h.run();
    }
    h.get_by_label("Reveal").click();
    h.run();
    assert!(shown(&h, &format!("{r:.4}")), "the answer after Reveal");
    assert!(shown(&h, "Not right."));
    assert!(shown(&h, "Diagnosis: weights from the wrong vertex order."));
    assert!(shown(
        &h,
        &format!("{:+.4}", (s * 1000.0).round() / 1000.0 - r)
    ));

    // Next step still works (Page Down): the quiz of step 6 ends with it.
    h.state_mut()
        .push(barylab::app::command::LessonCommand::Next);
    h.run();
    assert_eq!(h.state().lesson_step(), Some(6));
    assert!(!shown(&h, "Predict at pixel"));
}

#[test]
fn a_correct_answer_is_accepted_in_chinese() {
    let mut h = presenting_step_6(Lang::Zh);
    assert!(shown(&h, "预测像素 (120, 180) 的数值"));
    let [r, s, t] = rst(&h);
    for (part_index, v) in [r, s, t].into_iter().enumerate() {
        h.state_mut().push(QuizCommand::Edit {
            part: 0,
            index: part_index,
            text: format!("{v:.2}"),
        });
    }
    h.run();
    h.get_by_label("揭晓").click();
    h.run();
    assert!(shown(&h, "正确"), "the verdict in Chinese");
    assert!(!shown(&h, "诊断"));
}

#[test]
fn q_quizzes_any_pinned_pixel_and_the_inspector_hides_it() {
    let mut h = common::app::harness(
        egui::vec2(1400.0, 900.0),
        AppOptions {
            pin: Some([400, 420]),
            lang: Some(Lang::En),
            ..AppOptions::default()
        },
    );
    assert!(h.state().pin_report().is_some());
    assert!(!shown(&h, "hidden for the quiz"));
    h.key_press(egui::Key::Q);
    h.run();
    assert!(shown(&h, "Predict at pixel (400, 420)"));
    assert!(shown(&h, "are hidden for the quiz"), "the inspector's note");
    // Every quantity is asked: 3 + 3 + 1 + 2 fields.
    assert_eq!(
        h.get_all_by_role(egui::accesskit::Role::TextInput).count(),
        9
    );
    // Reveal with nothing typed: the answers, and the inspector's derivation comes back.
    h.get_by_label("Reveal").click();
    h.run();
    assert!(shown(&h, "No prediction typed."));
    assert!(!shown(&h, "are hidden for the quiz"));
    // Q again ends it.
    h.get_by_label("Hide the answer").click();
    h.run();
    h.key_press(egui::Key::Q);
    h.run();
    assert!(!shown(&h, "Predict at pixel"));
}

/// The quiz column's rect, as egui laid it out last.
fn quiz_column(h: &egui_kittest::Harness<'_, barylab::app::BaryApp>) -> egui::Rect {
    h.state().quiz_rect().expect("the quiz column is shown")
}

/// Outside presentation mode the quiz is a column beside the canvas: it covers neither the
/// picture nor the corners' labels, nor the Lessons panel under the canvas, and its Reveal
/// button is in sight without scrolling: at 1920x1080 with text size 1 (built-in step 11) and
/// at a 1024x768 projector with text size 1.5 (steps 6, 11 and 13). As a window over the
/// canvas, at 1024x768 it had no room beside the picture and covered it; on step 11 the
/// window, kept above the Lessons panel, had to be scrolled to reach Reveal.
#[test]
fn the_quiz_keeps_clear_of_the_picture_and_the_lessons_panel() {
    for lang in [Lang::En, Lang::Zh] {
        let mut wide = common::app::harness(
            egui::vec2(1920.0, 1080.0),
            AppOptions {
                lesson: Some((Lesson::builtin().expect("the built-in lesson"), 10)),
                text_size: Some(1.0),
                lang: Some(lang),
                ..AppOptions::default()
            },
        );
        for _ in 0..4 {
            wide.step();
        }
        wide.run();
        let lecture =
            [6, 11, 13].map(|step| common::app::lecture_with("builtin", step, lang, false));
        for (what, h) in std::iter::once(("1920x1080, step 11", &wide)).chain(
            ["step 6", "step 11", "step 13"]
                .into_iter()
                .zip(lecture.iter()),
        ) {
            let column = quiz_column(h);
            let canvas = h.state().canvas();
            assert!(!canvas.views.is_empty());
            for v in &canvas.views {
                assert!(
                    !column.intersects(v.rect),
                    "{lang:?}, {what}: the quiz {column:?} lies over the picture {:?}",
                    v.rect
                );
            }
            // Nor over any corner's label.
            let mut labels = 0;
            for c in &h.output().shapes {
                if let egui::Shape::Text(t) = &c.shape
                    && t.galley.job.text.contains("w = ")
                {
                    let label = t.galley.rect.translate(t.pos.to_vec2());
                    assert!(
                        !column.intersects(label),
                        "{lang:?}, {what}: the quiz {column:?} lies over {:?} at {label:?}",
                        t.galley.job.text
                    );
                    labels += 1;
                }
            }
            assert!(
                labels >= 3,
                "{lang:?}, {what}: the corners' labels, {labels} found"
            );
            if let Some(panel) = h.state().lesson_panel_rect() {
                assert!(
                    column.bottom() <= panel.top() + 0.5,
                    "{lang:?}, {what}: the quiz {column:?} reaches over the Lessons panel {panel:?}"
                );
            }
            let reveal = h.get_by_label(&lang.tr("quiz.reveal")).rect();
            assert!(
                column.contains_rect(reveal),
                "{lang:?}, {what}: Reveal {reveal:?} is out of sight of the quiz {column:?}"
            );
        }
    }
}

/// With a side panel open at 1024x768, text size 1.5, the canvas has no room for the quiz's
/// column: the quiz becomes a window in the canvas, and the canvas keeps its width (the
/// column had left it 140 points with the inspector open). Closing the panel docks it again.
#[test]
fn with_a_side_panel_open_the_quiz_is_a_window_and_the_canvas_keeps_its_width() {
    use barylab::app::document::state::StateCommand;
    let mut h = common::app::lecture_with("builtin", 11, Lang::En, false);
    let docked = quiz_column(&h);
    let canvas = h.state().canvas().area.expect("laid out");
    assert!(
        docked.left() >= canvas.right() - 0.5,
        "a column right of the canvas"
    );
    h.state_mut().push(StateCommand::SetShowInspector(true));
    for _ in 0..4 {
        h.step();
    }
    h.run();
    let canvas = h.state().canvas().area.expect("laid out");
    assert!(
        canvas.width() >= 300.0,
        "the canvas keeps {} points",
        canvas.width()
    );
    let window = quiz_column(&h);
    assert!(
        canvas.expand(0.5).contains_rect(window),
        "the quiz window {window:?} in the canvas {canvas:?}"
    );
    h.state_mut().push(StateCommand::SetShowInspector(false));
    for _ in 0..4 {
        h.step();
    }
    h.run();
    let again = quiz_column(&h);
    let canvas = h.state().canvas().area.expect("laid out");
    assert!(
        again.left() >= canvas.right() - 0.5 && again.top() <= docked.top() + 0.5,
        "docked again right of the canvas {canvas:?}: {again:?}"
    );
}
