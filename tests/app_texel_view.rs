//! The app's texture views: the texture lesson's steps open the texture-space and
//! level-of-detail views, which show the probe's numbers for the pinned pixel (computed here
//! with the library's probe, not read from the app); presentation mode at 1024x768 keeps the
//! view beside the picture; the card shows the level of detail; the Controls choice turns the
//! view off. Driven through egui_kittest like tests/app_space.rs.

mod common;

use std::path::Path;

use barylab::app::AppOptions;
use barylab::app::document::state::StateCommand;
use barylab::figure::TexelView;
use barylab::lesson::Lesson;
use barylab::probe::PixelTrace;
use barylab::probe::format::{fmt_digits, fmt_number};
use egui_kittest::kittest::Queryable;

const WIDE: egui::Vec2 = egui::vec2(1600.0, 1000.0);
const PROJECTOR: egui::Vec2 = egui::vec2(1024.0, 768.0);

/// The texture lesson at step `n` (1-based), in a window of `size`.
fn at_step(
    n: usize,
    size: egui::Vec2,
    present: bool,
) -> egui_kittest::Harness<'static, barylab::app::BaryApp> {
    let lesson = Lesson::open(Path::new("texture")).expect("the texture lesson");
    let mut h = common::app::harness(
        size,
        AppOptions {
            lesson: Some((lesson, n - 1)),
            present,
            ..AppOptions::default()
        },
    );
    h.run();
    h
}

/// The library's probe of step `n`'s pinned pixel, as the step sets the scene.
fn probe_step(n: usize) -> PixelTrace {
    let lesson = Lesson::open(Path::new("texture")).expect("the texture lesson");
    let state = lesson.state(n - 1).expect("state");
    let texture = state.scene.load_texture(Path::new("")).expect("texture");
    let [x, y] = state.pin.expect("pinned");
    barylab::probe::probe(&state.scene, &texture, &state.scene.settings(), (x, y)).expect("probe")
}

fn n(x: f32) -> String {
    fmt_number(f64::from(x))
}

/// The view's line of the levels `c` reads (and their weights), in `lang`.
fn levels_line(lang: barylab::i18n::Lang, c: &barylab::probe::LevelChoice) -> String {
    match c.next {
        Some((e, f)) => lang.tr_with(
            "texel_view.two_levels",
            &[
                ("d", &c.level),
                ("e", &e),
                ("wd", &n(1.0 - f)),
                ("we", &n(f)),
            ],
        ),
        None => lang.tr_with("texel_view.one_level", &[("d", &c.level)]),
    }
}

/// The view's colour line for colour `c`, in `lang`.
fn colour_line(lang: barylab::i18n::Lang, c: [u8; 4]) -> String {
    lang.tr_with(
        "texel_view.color",
        &[(
            "color",
            &format!("rgba({}, {}, {}, {})", c[0], c[1], c[2], c[3]),
        )],
    )
}

fn shows(h: &egui_kittest::Harness<'_, barylab::app::BaryApp>, line: &str) -> bool {
    h.query_by_label(line).is_some()
}

#[test]
fn the_trilinear_step_shows_the_footprint_levels_and_taps_of_the_pinned_pixel() {
    let h = at_step(8, WIDE, false);
    assert_eq!(h.state().state().view.texel, TexelView::Texture);
    assert!(shows(&h, "The pixel's lookup in texture space"));
    let t = probe_step(8);
    let l = common::lod_of(&t);
    let footprint = format!(
        "P_x = {}, P_y = {} texels; ρ = {}; λ = log2 ρ = {}",
        n(l.px),
        n(l.py),
        n(l.rho),
        n(l.trilinear.lambda)
    );
    assert!(shows(&h, &footprint), "the view shows {footprint}");
    let (e, f) = l.trilinear.next.expect("two levels");
    let levels = format!(
        "levels {} and {e}, weights {} and {}",
        l.trilinear.level,
        n(1.0 - f),
        n(f)
    );
    assert!(shows(&h, &levels), "the view shows {levels}");
    assert_eq!(l.taps.len(), 8, "two levels of four texels");
    for tap in &l.taps {
        let c = tap.texel;
        let line = format!(
            "level {}, texel ({}, {}) × {}: rgba({}, {}, {}, {})",
            tap.level,
            tap.i,
            tap.j,
            n(tap.weight),
            c[0],
            c[1],
            c[2],
            c[3]
        );
        assert!(shows(&h, &line), "the view shows {line}");
    }
    let c = t.color;
    let colour = format!("colour: rgba({}, {}, {}, {})", c[0], c[1], c[2], c[3]);
    assert!(shows(&h, &colour), "the view shows {colour}");
}

#[test]
fn the_mipmap_step_shows_every_pixels_level_and_the_pinned_pixels_lambda() {
    let h = at_step(7, WIDE, false);
    assert_eq!(h.state().state().view.texel, TexelView::Lod);
    assert!(shows(&h, "Each pixel's mipmap level"));
    let t = probe_step(7);
    let lambda = common::lod_of(&t).trilinear.lambda;
    let [x, y] = t.pixel;
    let line = format!(
        "pixel ({x}, {y}): λ = {}, level {}",
        n(lambda),
        lambda.floor()
    );
    assert!(shows(&h, &line), "the view shows {line}");
    // The far-checker floor runs from magnification at the bottom to level 8 at the horizon.
    // Each entry is its swatch (a square in the level's colour) and its name, one text.
    for entry in ["magnified (λ ≤ 0)", "level 0", "level 2", "level 8"] {
        let entry = format!("\u{25A0} {entry}");
        assert!(shows(&h, &entry), "the legend has {entry}");
    }
}

#[test]
fn on_a_projector_the_anisotropic_step_keeps_the_view_beside_the_picture() {
    let mut h = at_step(11, PROJECTOR, true);
    assert!(h.state().presenting());
    let t = probe_step(11);
    let a = common::lod_of(&t)
        .anisotropic
        .as_ref()
        .expect("anisotropic");
    let line = format!(
        "anisotropic: N = {} probes (at most {}); λ' = log2(P_max / N) = {}",
        a.n,
        a.max,
        n(a.levels.lambda)
    );
    assert!(shows(&h, &line), "the view shows {line}");
    assert_eq!(a.n, 13);
    // Presenting, the probes are a row of colour swatches after this line.
    assert!(shows(&h, "probes:"), "the view shows the probes");
    // The picture is still drawn, left of the view.
    let view = h
        .query_by_label("The pixel's lookup in texture space")
        .expect("the view")
        .rect();
    let canvas = h.state().canvas().area.expect("the canvas is laid out");
    assert!(canvas.max.x <= view.min.x, "{canvas:?} left of {view:?}");
    assert!(canvas.width() >= 0.5 * PROJECTOR.x, "{canvas:?}");

    h.state_mut()
        .push(StateCommand::SetTexelView(TexelView::Off));
    h.run();
    assert!(!shows(&h, &line));
}

#[test]
fn the_card_shows_the_level_of_detail_with_trilinear_filtering() {
    // Step 10 (trilinear, no texture view) on a wide screen: the card beside the picture.
    let h = at_step(10, WIDE, true);
    assert_eq!(h.state().state().view.texel, TexelView::Off);
    let t = probe_step(10);
    let l = common::lod_of(&t);
    let (e, _) = l.trilinear.next.expect("two levels");
    let d = |x: f32| fmt_digits(f64::from(x), 4);
    let line = format!(
        "ρ = {}  λ = {}  mip {}+{e}",
        d(l.rho),
        d(l.trilinear.lambda),
        l.trilinear.level
    );
    assert!(shows(&h, &line), "the card shows {line}");
}

#[test]
fn on_a_projector_the_level_of_detail_step_keeps_its_legend_in_the_window() {
    let h = at_step(7, PROJECTOR, true);
    let view = h
        .query_by_label("Each pixel's mipmap level")
        .expect("the view")
        .rect();
    let canvas = h.state().canvas().area.expect("the canvas is laid out");
    assert!(canvas.max.x <= view.min.x, "{canvas:?} left of {view:?}");
    for entry in ["\u{25A0} level 0", "\u{25A0} level 8"] {
        let r = h.query_by_label(entry).expect("a legend entry").rect();
        assert!(
            r.min.x >= view.min.x && r.max.x <= PROJECTOR.x && r.max.y <= PROJECTOR.y,
            "{entry} at {r:?}, the view at {view:?}"
        );
    }
}

/// The anisotropic step at a lecture projector (1024x768, text size 1.5, presentation
/// mode), in both languages: the texture view fits its panel without scrolling: its last line
/// (the colour) ends above the lesson bar, and the pictures between the numbers over them
/// (the levels' line) and under them (the probes' swatches) get at least 80 points.
#[test]
fn on_a_projector_at_text_size_1_5_the_anisotropic_view_fits_its_panel() {
    let t = probe_step(11);
    let l = common::lod_of(&t);
    let a = l.anisotropic.as_ref().expect("anisotropic");
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        let h = common::app::lecture("texture", 11, lang);
        let rect = |text: &str| {
            h.query_by_label(text)
                .unwrap_or_else(|| panic!("{lang:?}: {text} shown"))
                .rect()
        };
        let colour = colour_line(lang, t.color);
        let levels = levels_line(lang, &a.levels);
        let probes = lang.tr("texel_view.probes_compact");
        let bar = rect(&lang.tr("lesson.next"));
        let (last, over, under) = (rect(&colour), rect(&levels), rect(&probes));
        // The window is 1024x768 pixels, 683x512 points at text size 1.5.
        let window = h.ctx.content_rect();
        assert!(
            window.height() < 520.0,
            "{lang:?}: text size 1.5, {window:?}"
        );
        assert!(
            last.max.y <= bar.min.y,
            "{lang:?}: {colour} at {last:?}, the bar at {bar:?}, levels at {over:?}, probes at {under:?}"
        );
        assert!(
            last.max.y <= window.max.y,
            "{lang:?}: {last:?} in {window:?}"
        );
        assert!(
            under.min.y - over.max.y >= 80.0,
            "{lang:?}: the pictures' room from {over:?} to {under:?}"
        );
    }
}

/// The steps that show the texture view with several taps (bilinear; the footprint, the
/// level of detail, trilinear, the affine pitfall) at a lecture projector, in both languages:
/// the view fits its panel without scrolling (the colour line ends above the lesson bar), the
/// pictures get at least 120 points under the numbers over them, and the taps' lines, which
/// do not fit, are not drawn as lines (their weights are printed in the pictures).
#[test]
fn on_a_projector_at_text_size_1_5_the_bilinear_and_trilinear_views_fit_their_panel() {
    for step in [2, 6, 8, 12] {
        let t = probe_step(step);
        let a = t
            .detail
            .as_ref()
            .and_then(|d| d.attribute.as_ref())
            .expect("a texture lookup");
        for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
            let h = common::app::lecture("texture", step, lang);
            let rect = |text: &str| {
                h.query_by_label(text)
                    .unwrap_or_else(|| panic!("step {step} {lang:?}: {text} shown"))
                    .rect()
            };
            let rgba = |c: [u8; 4]| format!("rgba({}, {}, {}, {})", c[0], c[1], c[2], c[3]);
            let colour = colour_line(lang, t.color);
            // The last line over the pictures: the levels (trilinear), else the uv.
            let over_line = match a.lod.as_ref().map(|l| &l.trilinear) {
                Some(c) => levels_line(lang, c),
                None => lang.tr_with(
                    "texel_view.uv",
                    &[
                        ("x", &t.pixel[0]),
                        ("y", &t.pixel[1]),
                        ("u", &n(a.uv_perspective[0])),
                        ("v", &n(a.uv_perspective[1])),
                    ],
                ),
            };
            let bar = rect(&lang.tr("lesson.next"));
            let (last, over) = (rect(&colour), rect(&over_line));
            let window = h.ctx.content_rect();
            assert!(
                last.max.y <= bar.min.y && last.max.y <= window.max.y,
                "step {step} {lang:?}: {colour} at {last:?}, the bar at {bar:?}"
            );
            assert!(
                last.min.y - over.max.y >= 120.0,
                "step {step} {lang:?}: the pictures' room from {over:?} to {last:?}"
            );
            let taps = a.lod.as_ref().map_or(&a.taps_perspective, |l| &l.taps);
            assert!(taps.len() >= 4, "step {step}: several taps");
            let tap = &taps[0];
            let tap_line = lang.tr_with(
                "texel_view.tap",
                &[
                    ("level", &tap.level),
                    ("i", &tap.i),
                    ("j", &tap.j),
                    ("w", &n(tap.weight)),
                    ("color", &rgba(tap.texel)),
                ],
            );
            assert!(
                !shows(&h, &tap_line),
                "step {step} {lang:?}: the tap line {tap_line} is drawn"
            );
        }
    }
}

/// The step that plots lambda down a column (step 9) at a lecture projector, in both
/// languages: both legend entries over the plot show whole, left of the level-of-detail view
/// beside them (the second entry ran past the plot's right edge and was cut), in one row.
#[test]
fn on_a_projector_the_lambda_plots_legend_shows_whole() {
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        let h = common::app::lecture("texture", 9, lang);
        let view = h
            .query_by_label(&lang.tr("texel_view.lod_title"))
            .unwrap_or_else(|| panic!("{lang:?}: the level-of-detail view"))
            .rect();
        let mut rows = Vec::new();
        for key in ["lesson.plot_lambda_line", "lesson.plot_level_line"] {
            let name = lang.tr(key);
            let r = h
                .query_by_label(&name)
                .unwrap_or_else(|| panic!("{lang:?}: the legend entry {name}"))
                .rect();
            assert!(
                r.max.x <= view.min.x,
                "{lang:?}: {name} at {r:?} runs into the view at {view:?}"
            );
            rows.push(r.center().y);
        }
        // One row: a second one would squash the short plot under it.
        assert!(
            (rows[0] - rows[1]).abs() < 2.0,
            "{lang:?}: the legend takes two rows ({rows:?})"
        );
    }
}

/// The steps whose texture view shows three pictures (level 0 with the footprint and the two
/// levels read: the footprint, trilinear, the affine pitfall) at a lecture projector, in both
/// languages: the pictures use the room the numbers leave them (between the levels' line over
/// them and the colour line under them, across the panel) rather than two small rows with a
/// hole, without overlapping or leaving that room.
#[test]
fn on_a_projector_at_text_size_1_5_the_three_level_pictures_use_the_room() {
    for step in [6, 8, 12] {
        let t = probe_step(step);
        let l = t
            .detail
            .as_ref()
            .and_then(|d| d.attribute.as_ref())
            .and_then(|a| a.lod.as_ref())
            .expect("a level of detail");
        assert!(l.trilinear.next.is_some(), "step {step}: two levels");
        for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
            let h = common::app::lecture("texture", step, lang);
            let rect = |text: &str| {
                h.query_by_label(text)
                    .unwrap_or_else(|| panic!("step {step} {lang:?}: {text} shown"))
                    .rect()
            };
            let colour = colour_line(lang, t.color);
            let levels = levels_line(lang, &l.trilinear);
            let view = rect(&lang.tr("texel_view.texture_title"));
            let (over, under) = (rect(&levels), rect(&colour));
            let window = h.ctx.content_rect();
            let room = egui::Rect::from_min_max(
                egui::pos2(view.min.x, over.max.y),
                egui::pos2(window.max.x, under.min.y),
            );
            let pictures: Vec<egui::Rect> = h
                .query_all_by_role(egui::accesskit::Role::Image)
                .map(|p| p.rect())
                .filter(|r| r.min.x >= view.min.x - 1.0)
                .collect();
            assert_eq!(pictures.len(), 3, "step {step} {lang:?}: {pictures:?}");
            for (i, p) in pictures.iter().enumerate() {
                assert!(
                    room.expand(0.5).contains_rect(*p),
                    "step {step} {lang:?}: picture {i} at {p:?} outside {room:?}"
                );
                for q in &pictures[i + 1..] {
                    assert!(
                        !p.shrink(0.5).intersects(*q),
                        "step {step} {lang:?}: {p:?} overlaps {q:?}"
                    );
                }
            }
            let used: f32 = pictures.iter().map(|p| p.area()).sum();
            assert!(
                used >= 0.7 * room.area(),
                "step {step} {lang:?}: the pictures {pictures:?} fill {:.0}% of {room:?}",
                100.0 * used / room.area()
            );
        }
    }
}

/// The level-of-detail view's legend at step 9 (the lambda plot) at a lecture projector, in
/// both languages: every entry (its swatch and level) lies inside the panel, clear of its
/// edges by the panel's margin.
#[test]
fn on_a_projector_at_text_size_1_5_the_lod_legend_keeps_inside_its_panel() {
    for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
        let h = common::app::lecture("texture", 9, lang);
        let view = h
            .query_by_label(&lang.tr("texel_view.lod_title"))
            .unwrap_or_else(|| panic!("{lang:?}: the level-of-detail view"))
            .rect();
        let window = h.ctx.content_rect();
        let entries: Vec<egui::Rect> = h
            .query_all_by_label_contains("\u{25A0} ")
            .map(|n| n.rect())
            .collect();
        assert!(entries.len() >= 2, "{lang:?}: {entries:?}");
        for r in entries {
            assert!(
                r.min.x >= view.min.x - 0.5 && r.max.x <= window.max.x - 8.0,
                "{lang:?}: a legend entry at {r:?}, the view at {view:?} in {window:?}"
            );
        }
    }
}

/// Beside the Lessons panel at a lecture projector (1024x768, text size 1.5, not presenting),
/// the texture view shows its first picture (level 0 with the footprint) under the pixel's
/// line, at least 80 points of it above the Lessons panel, in every step with the view and
/// both languages: the derivatives' and levels' lines come after the pictures. (They came
/// first and filled the short panel; the pictures were out of sight.)
#[test]
fn beside_the_lessons_panel_the_texture_view_shows_its_picture_first() {
    let lesson = Lesson::open(Path::new("texture")).expect("the texture lesson");
    let steps: Vec<usize> = (1..=lesson.steps.len())
        .filter(|&n| {
            lesson.state(n - 1).expect("state").texture_view == barylab::figure::TexelView::Texture
        })
        .collect();
    assert!(steps.len() >= 3, "steps with the texture view: {steps:?}");
    for step in steps {
        for lang in [barylab::i18n::Lang::En, barylab::i18n::Lang::Zh] {
            let h = common::app::lecture_with("texture", step, lang, false);
            let view = h
                .query_by_label(&lang.tr("texel_view.texture_title"))
                .unwrap_or_else(|| panic!("step {step} {lang:?}: the texture view"))
                .rect();
            let lessons = h.state().lesson_panel_rect().expect("the Lessons panel");
            let first = h
                .query_all_by_role(egui::accesskit::Role::Image)
                .map(|p| p.rect())
                .filter(|r| r.min.x >= view.min.x - 1.0)
                .min_by(|a, b| a.min.y.total_cmp(&b.min.y))
                .unwrap_or_else(|| panic!("step {step} {lang:?}: a picture"));
            assert!(
                first.min.y + 80.0 <= lessons.min.y,
                "step {step} {lang:?}: the picture starts at {} and the Lessons panel at {}",
                first.min.y,
                lessons.min.y
            );
        }
    }
}
