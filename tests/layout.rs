//! Layout on a projector: at 1024x768 and larger text sizes nothing the class needs is cut
//! off. The status line keeps its mode, canvas and frame time whole (it drops the less
//! important parts instead of eliding them), and the inspector's numbers stay inside its
//! panel. Driven through egui_kittest like tests/app.rs.

mod common;

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::i18n::{Lang, cjk_font};
use barylab::probe::format::fmt_number;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};

fn harness(size: [f32; 2], options: AppOptions) -> Harness<'static, BaryApp> {
    common::app::harness(egui::vec2(size[0], size[1]), options)
}

/// Lets a new window size or text size settle (the zoom lays the window out again).
fn settle(h: &mut Harness<'_, BaryApp>) {
    for _ in 0..4 {
        h.step();
    }
    h.run();
}

/// The languages to check: Chinese only with a font that has its glyphs.
fn langs() -> Vec<Lang> {
    if cjk_font().is_some() {
        vec![Lang::En, Lang::Zh]
    } else {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "no CJK font found: CI needs fonts-noto-cjk"
        );
        vec![Lang::En]
    }
}

/// Points `text` takes on one line in the body font.
fn text_width(h: &Harness<'_, BaryApp>, text: &str) -> f32 {
    let font = egui::TextStyle::Body.resolve(&h.ctx.global_style());
    h.ctx.fonts_mut(|f| {
        f.layout_no_wrap(text.to_string(), font, egui::Color32::WHITE)
            .size()
            .x
    })
}

/// Asserts the label containing `part` is shown whole (not elided) inside the window.
fn whole(h: &Harness<'_, BaryApp>, part: &str, what: &str) {
    let screen = h.ctx.content_rect();
    let node = h
        .query_all_by_label_contains(part)
        .last()
        .unwrap_or_else(|| panic!("{what}: no label with {part:?}"));
    let ak = node.accesskit_node();
    let label = ak.label().or_else(|| ak.value()).unwrap_or_default();
    let rect = node.rect();
    let need = text_width(h, &label);
    assert!(
        rect.width() + 0.5 >= need && rect.right() <= screen.right() + 0.5,
        "{what}: {label:?} is cut: {rect:?} for {need} points in {screen:?}"
    );
}

#[test]
fn the_status_line_keeps_mode_canvas_and_frame_time_whole_on_a_projector() {
    for lang in langs() {
        let options = AppOptions {
            lang: Some(lang),
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        let frame = lang_word(lang, "frame");
        for scale in [1.0, 1.5, 2.0] {
            h.state_mut().push(StateCommand::SetUiScale(scale));
            for compare in [
                barylab::figure::Compare::Single,
                barylab::figure::Compare::SideBySide,
            ] {
                h.state_mut().push(StateCommand::SetCompare(compare));
                settle(&mut h);
                let what = format!("{lang:?} at text size {scale}, {compare:?}");
                whole(&h, &frame, &what);
                whole(&h, "800×600", &what);
            }
        }
    }
}

/// The first word of the status line's `key` entry, from the catalogue.
fn lang_word(lang: Lang, key: &str) -> String {
    barylab::i18n::tr(lang, &format!("app.status.{key}"))
        .split_whitespace()
        .next()
        .unwrap_or_default()
        .to_string()
}

/// The inspector's per-vertex numbers of the pinned pixel, as it prints them.
fn pin_numbers(h: &Harness<'_, BaryApp>) -> Vec<String> {
    let r = h.state().pin_report().expect("pin report");
    let d = r.trace.detail.as_ref().expect("covered");
    let p = d.perspective.expect("1/w");
    let mut n: Vec<f64> = d.screen.rasterizer.to_vec();
    n.extend(p.correction.weights);
    n.extend(d.raster.vertices.iter().map(|v| v.inv_w));
    n.into_iter().map(fmt_number).collect()
}

/// Points: the right edge of what the inspector panel shows (inside its frame's margin and
/// beside its scroll bar; the panel is at the window's right edge).
fn inspector_right(h: &Harness<'_, BaryApp>) -> f32 {
    let scroll = h.ctx.global_style().spacing.scroll;
    h.ctx.content_rect().right() - 8.0 - scroll.allocated_width()
}

#[test]
fn the_inspectors_numbers_are_never_cut_at_its_edge() {
    for lang in langs() {
        for (size, scales) in [
            ([1280.0, 800.0], [1.0, 1.25, 1.5]),
            ([1280.0, 800.0], [1.3, 1.4, 1.1]),
            ([1024.0, 768.0], [1.0, 1.0, 1.0]),
            ([1920.0, 1080.0], [1.0, 1.5, 2.0]),
        ] {
            let options = AppOptions {
                lang: Some(lang),
                pin: Some([400, 420]),
                ..AppOptions::default()
            };
            let mut h = harness(size, options);
            for scale in scales {
                h.state_mut().push(StateCommand::SetUiScale(scale));
                settle(&mut h);
                // Hover another pixel, so the pinned-and-hovered table shows too.
                let view = h.state().canvas().views[0];
                let pos = view.transform.to_screen(glam::DVec2::new(300.5, 450.5));
                h.hover_at(pos);
                settle(&mut h);
                let right = inspector_right(&h);
                let what = format!("{lang:?} {size:?} at text size {scale}");
                for n in pin_numbers(&h) {
                    let nodes: Vec<egui::Rect> = h
                        .query_all_by_label_contains(&n)
                        .map(|node| node.rect())
                        .collect();
                    assert!(!nodes.is_empty(), "{what}: {n} not shown");
                    for r in nodes {
                        assert!(
                            r.right() <= right + 0.5,
                            "{what}: {n} is cut: {r:?}, the panel shows up to {right}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_lesson_leaves_the_canvas_most_of_the_window_on_a_wide_screen() {
    let lesson = barylab::lesson::Lesson::builtin().expect("built-in lesson");
    let steps = lesson.steps.len();
    for lang in langs() {
        let options = AppOptions {
            lang: Some(lang),
            lesson: Some((lesson.clone(), 2)),
            ..AppOptions::default()
        };
        let mut h = harness([1920.0, 1080.0], options);
        h.state_mut().push(StateCommand::SetUiScale(1.5));
        settle(&mut h);
        for step in [2, 0, steps - 1] {
            h.state_mut().enter_lesson(lesson.clone(), step);
            settle(&mut h);
            let window = h.ctx.content_rect();
            let canvas = h.state().canvas().area.expect("the canvas is shown");
            // Over half the window (the top bar and the status line take their share); it
            // was 0.42 when the panel kept the points it had at text size 1.
            assert!(
                canvas.height() >= 0.5 * window.height(),
                "{lang:?} step {}: the canvas is {canvas:?} in {window:?}",
                step + 1
            );
        }
    }
}

#[test]
fn the_presentation_cards_keys_have_a_readable_line_of_their_own() {
    for lang in langs() {
        let options = AppOptions {
            lang: Some(lang),
            present: true,
            pin: Some([400, 420]),
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        settle(&mut h);
        let hint = barylab::i18n::tr(lang, "app.present.leave");
        let node = h
            .query_all_by_label_contains("F5")
            .last()
            .unwrap_or_else(|| panic!("{lang:?}: no line of keys"));
        let rect = node.rect();
        // Its own line (it was squeezed beside the title), not much smaller than the body text
        // (the label is taller than its text size; the card's numbers are larger), inside the
        // window.
        let body = egui::TextStyle::Body.resolve(&h.ctx.global_style()).size;
        assert!(
            rect.height() >= 0.8 * body,
            "{lang:?}: {hint:?} is {rect:?} for body text of {body} points"
        );
        let window = h.ctx.content_rect();
        assert!(
            window.contains_rect(rect),
            "{lang:?}: {rect:?} in {window:?}"
        );
        // Below every other line of the card, overlapping none.
        let wp = h
            .query_all_by_label_contains("W_P =")
            .map(|n| n.rect())
            .collect::<Vec<_>>();
        assert!(!wp.is_empty(), "{lang:?}: the card shows no W_P");
        for r in wp {
            assert!(
                r.bottom() <= rect.top() + 0.5,
                "{lang:?}: {r:?} over {rect:?}"
            );
        }
    }
}

/// The image's share of the window (both in points) in presentation mode.
fn image_share(h: &Harness<'_, BaryApp>) -> f32 {
    let window = h.ctx.content_rect();
    let views = &h.state().canvas().views;
    views.iter().map(|v| v.rect.area()).sum::<f32>() / window.area()
}

/// The screen positions of the handles the canvas drew, in every view.
fn handles_on_screen(h: &Harness<'_, BaryApp>) -> Vec<egui::Pos2> {
    let canvas = h.state().canvas();
    let Some(output) = &canvas.output else {
        return Vec::new();
    };
    let vertices = barylab::figure::vertices_on_screen(&output.scene, output.viewport());
    let per_pixel = |v: &barylab::app::panels::canvas::View| v.rect.width() / output.size[0] as f32;
    let image = glam::DVec2::new(f64::from(output.size[0]), f64::from(output.size[1]));
    let mut out = Vec::new();
    for v in &canvas.views {
        for &k in &canvas.handles {
            if let Some(p) = vertices
                .get(k)
                .and_then(|x| x.window)
                .map(|w| barylab::figure::overlay::handle_position(w, image))
            {
                out.push(v.rect.min + per_pixel(v) * egui::vec2(p.x as f32, p.y as f32));
            }
        }
    }
    out
}

/// The least share of the window the picture keeps when it makes room for the card (and the
/// row plot, and the difference view's colour bar) beside or under it: a fifth (at 1024x768,
/// text size 1.5, a single picture keeps about a third).
const BESIDE_LEAST: f32 = 0.2;

/// The card over the picture (if it is over it) hides no handle, and the picture keeps half
/// the window when the card is over it, [`BESIDE_LEAST`] when it makes room for the card.
fn check_card(h: &Harness<'_, BaryApp>, what: &str) {
    let share = image_share(h);
    let over = &h.state().canvas().avoid;
    for card in over {
        for p in handles_on_screen(h) {
            assert!(
                !card.contains(p),
                "{what}: the card {card:?} hides the handle at {p:?}"
            );
        }
    }
    let least = if over.is_empty() { BESIDE_LEAST } else { 0.5 };
    assert!(
        share >= least,
        "{what}: the picture has {share} of the window"
    );
}

#[test]
fn presenting_on_a_projector_gives_the_picture_half_the_window_and_hides_no_handle() {
    let lesson = barylab::lesson::Lesson::builtin().expect("built-in lesson");
    for scale in [1.0, 1.5] {
        // The default scene with nothing pinned: the small card over the picture, which has
        // half the window at least.
        let options = AppOptions {
            present: true,
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        h.state_mut().push(StateCommand::SetUiScale(scale));
        settle(&mut h);
        let share = image_share(&h);
        assert!(share >= 0.5, "text size {scale}, nothing pinned: {share}");
        assert!(
            !h.state().canvas().avoid.is_empty(),
            "the small card lies over the picture"
        );
        // A pixel pinned: the full card over the picture where a corner hides no handle,
        // else beside it.
        let options = AppOptions {
            present: true,
            pin: Some([400, 420]),
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        h.state_mut().push(StateCommand::SetUiScale(scale));
        settle(&mut h);
        check_card(&h, &format!("text size {scale}, pinned"));
        // Every step of the lesson.
        let options = AppOptions {
            present: true,
            lesson: Some((lesson.clone(), 0)),
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        h.state_mut().push(StateCommand::SetUiScale(scale));
        settle(&mut h);
        for n in 0..lesson.steps.len() {
            h.state_mut().enter_lesson(lesson.clone(), n);
            settle(&mut h);
            check_card(&h, &format!("text size {scale}, step {}", n + 1));
        }
    }
}

/// Presenting with nothing pinned, the pointer on a pixel fills the card, which then lies in
/// a corner of the picture; on the default scene at 1024x768, text size 1.5, every corner holds
/// a handle. Pointing at any handle (to drag it), the card is not over it: it moves out from
/// under the pointer. (It stayed in the top-right corner over C.)
#[test]
fn presenting_the_hovered_pixels_card_keeps_out_from_under_the_pointer() {
    let options = AppOptions {
        present: true,
        ..AppOptions::default()
    };
    let mut h = harness([1024.0, 768.0], options);
    h.state_mut().push(StateCommand::SetUiScale(1.5));
    settle(&mut h);
    let handles = handles_on_screen(&h);
    assert_eq!(handles.len(), 4, "the quad's four handles");
    for p in handles {
        h.event(egui::Event::PointerMoved(p));
        settle(&mut h);
        assert!(
            h.state().hover_report().is_some(),
            "a pixel is hovered at {p:?}"
        );
        let cards = &h.state().canvas().avoid;
        assert!(!cards.is_empty(), "the card lies over the picture");
        for card in cards {
            assert!(
                !card.contains(p),
                "the card {card:?} lies over the handle under the pointer at {p:?}"
            );
        }
    }
}

#[test]
fn the_c_key_hides_the_card_and_gives_the_pinned_picture_half_the_window() {
    for scale in [1.0, 1.5] {
        let options = AppOptions {
            present: true,
            pin: Some([400, 420]),
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        h.state_mut().push(StateCommand::SetUiScale(scale));
        settle(&mut h);
        let with_card = image_share(&h);
        h.key_press(egui::Key::C);
        settle(&mut h);
        assert!(!h.state().state().view.show_card, "C hides the card");
        let alone = image_share(&h);
        assert!(
            alone >= 0.5 && alone > with_card,
            "text size {scale}: the picture alone has {alone} of the window (with the card {with_card})"
        );
        assert!(
            h.state().canvas().avoid.is_empty(),
            "no card over the picture"
        );
        assert_eq!(
            h.state().state().view.pinned,
            Some([400, 420]),
            "the pin stays"
        );
        h.key_press(egui::Key::C);
        settle(&mut h);
        assert!(h.state().state().view.show_card, "C again shows the card");
        assert!(
            (image_share(&h) - with_card).abs() < 1e-3,
            "the same layout as before"
        );
    }
}

#[test]
fn on_a_projector_at_text_size_one_and_a_half_every_panel_opens_and_the_lesson_steps() {
    let lesson = barylab::lesson::Lesson::builtin().expect("built-in lesson");
    for scale in [1.5, 2.0] {
        let options = AppOptions {
            lesson: Some((lesson.clone(), 10)),
            ..AppOptions::default()
        };
        let mut h = harness([1024.0, 768.0], options);
        h.state_mut().push(StateCommand::SetUiScale(scale));
        // The step's quiz ended (its column beside the canvas is tests/quiz_app.rs's).
        h.state_mut()
            .push(barylab::app::command::QuizCommand::Toggle);
        settle(&mut h);
        let window = h.ctx.content_rect();
        let canvas = h.state().canvas().area.expect("the canvas is shown");
        // Previous and Next are whole, inside the window, below the canvas.
        for label in ["« Previous", "Next »"] {
            let r = h.get_by_label(label).rect();
            assert!(
                window.contains_rect(r),
                "{scale}: {label} {r:?} in {window:?}"
            );
            assert!(
                r.top() >= canvas.bottom() - 0.5,
                "{scale}: {label} {r:?} under {canvas:?}"
            );
        }
        // Each side panel opens when asked for: the canvas gives way (before, both panels were
        // strips beside it).
        let before = canvas.width();
        for show in [
            StateCommand::SetShowInspector(true),
            StateCommand::SetShowControls(true),
        ] {
            h.state_mut().push(show.clone());
            settle(&mut h);
            let now = h
                .state()
                .canvas()
                .area
                .expect("the canvas is shown")
                .width();
            assert!(
                now <= before - 200.0,
                "{scale}: after {show:?} the canvas is {now} points wide (was {before})"
            );
        }
    }
}

#[test]
fn presenting_magnifies_the_pinned_pixel_where_a_corner_is_free_and_m_hides_it() {
    // A wide screen: the magnifier sits in the card's column.
    let options = AppOptions {
        present: true,
        pin: Some([400, 420]),
        ..AppOptions::default()
    };
    let mut h = harness([1920.0, 1080.0], options);
    settle(&mut h);
    assert!(
        h.query_by_label_contains("Pixel 400, 420 enlarged")
            .is_some(),
        "the magnifier names the pinned pixel"
    );
    h.key_press(egui::Key::M);
    settle(&mut h);
    assert!(!h.state().state().view.show_magnifier);
    assert!(h.query_by_label_contains("enlarged").is_none());
    // Nothing pinned: no magnifier.
    let options = AppOptions {
        present: true,
        ..AppOptions::default()
    };
    let mut h = harness([1920.0, 1080.0], options);
    settle(&mut h);
    assert!(h.query_by_label_contains("enlarged").is_none());
}

#[test]
fn s_steps_along_the_scanline_span_only_with_the_scanline_rasterizer() {
    let lesson = barylab::lesson::Lesson::builtin().expect("built-in lesson");
    let options = AppOptions {
        present: true,
        lesson: Some((lesson.clone(), 0)),
        ..AppOptions::default()
    };
    let mut h = harness([1024.0, 768.0], options);
    settle(&mut h);
    // Step 1 uses edge functions: S does nothing.
    h.key_press(egui::Key::S);
    settle(&mut h);
    assert!(!h.state().canvas().span_play);
    // Step 6 uses the scanline rasterizer: S starts the stepping, S again stops it.
    let six = lesson
        .steps
        .iter()
        .position(|s| s.rasterizer == barylab::raster::render::Rasterizer::Scanline)
        .expect("a scanline step");
    h.state_mut().enter_lesson(lesson.clone(), six);
    settle(&mut h);
    h.key_press(egui::Key::S);
    h.step();
    assert!(h.state().canvas().span_play);
    h.key_press(egui::Key::S);
    h.step();
    assert!(!h.state().canvas().span_play);
}

/// The font size of the painted text starting with `start` (the canvas's title) and the
/// largest size of the corners' labels ("w = ").
fn title_and_label_sizes(h: &Harness<'_, BaryApp>, start: &str) -> (Option<(String, f32)>, f32) {
    let mut title = None;
    let mut label: f32 = 0.0;
    for c in &h.output().shapes {
        if let egui::Shape::Text(t) = &c.shape {
            let size = t.galley.job.sections[0].format.font_id.size;
            if t.galley.job.text.starts_with(start) {
                title = Some((t.galley.job.text.clone(), size));
            } else if t.galley.job.text.contains("w = ") {
                label = label.max(size);
            }
        }
    }
    (title, label)
}

/// At a 1024x768 projector with text size 1.5, a canvas title too long for its view is a
/// shorter form at full size (as large as the corners' labels), not the whole sentence
/// shrunk to about 13 pixels: the built-in step 6 beside the quiz ("SCREEN SPACE (w = 1.00)"
/// for "SCREEN SPACE (every w = 1.00: both modes agree)") and the samples lesson's black-edge
/// step beside the enlarged pixel ("Resolve (black-edge bug)" for "Resolve: the average of 4
/// samples (black-edge bug)").
#[test]
fn a_long_canvas_title_is_a_shorter_form_at_full_size() {
    for lang in langs() {
        let bug = lang.tr_with("figure.samples.with_bug", &[("view", &"")]);
        let cases = [
            (
                "builtin",
                6,
                lang.tr("figure.flat_shortest"),
                lang.tr_with("figure.flat", &[("w", &"1.00")]),
            ),
            (
                "samples",
                4,
                lang.tr("figure.samples.short.resolve"),
                barylab::figure::sample_buffers::title(
                    barylab::figure::sample_buffers::SampleBufferKind::Resolve,
                    0,
                    4,
                    true,
                    lang,
                ),
            ),
        ];
        for (lesson, step, start, whole) in cases {
            let h = common::app::lecture_with(lesson, step, lang, false);
            let (title, label) = title_and_label_sizes(&h, &start);
            let (text, size) =
                title.unwrap_or_else(|| panic!("{lang:?}, {lesson} {step}: no title {start:?}…"));
            assert!(
                label > 0.0,
                "{lang:?}, {lesson} {step}: the corners' labels"
            );
            assert!(
                size >= label - 0.01,
                "{lang:?}, {lesson} {step}: the title {text:?} at {size} points, the labels at {label}"
            );
            assert_ne!(
                text, whole,
                "{lang:?}, {lesson} {step}: the whole title does not fit"
            );
            if lesson != "builtin" {
                assert!(
                    text.contains(bug.trim()),
                    "{lang:?}: {text:?} names the bug"
                );
            }
        }
    }
}
