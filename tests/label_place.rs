//! Labels that belong to one thing, where they are drawn: on the app's canvas at a lecture
//! projector (1024x768, text size 1.5, presentation mode; the texts and handles as egui
//! paints them) and in the lessons' SVG figures (the label boxes the document records). The
//! 2x2 quad's four uv labels form one block laid out as the pixels are (`uv_00 uv_10` over
//! `uv_01 uv_11`), clear of each other, of the handles and their labels and of the quad,
//! near the quad or tied to it by a leader line; every vertex handle's label lies nearer
//! its own handle than any other handle, on every step of both built-in lessons.

mod common;

use std::path::Path;

use barylab::figure::label_place::{LEADER_FROM, box_distance, point_distance};
use barylab::i18n::Lang;
use barylab::lesson::Lesson;

type Box2 = [f32; 4];

/// What a view draws, in points.
#[derive(Debug, Default)]
struct Drawn {
    /// Each handle's name, centre and radius.
    handles: Vec<(char, [f32; 2], f32)>,
    /// Each boxed label's text and box (the text's box on the canvas, the label's box with
    /// its padding in a figure).
    labels: Vec<(String, Box2)>,
    /// The quad's yellow outline.
    quad: Option<Box2>,
    /// Yellow line segments (the leader).
    leaders: Vec<[[f32; 2]; 2]>,
}

/// The quad's colour (outline, labels, leader).
const QUAD: [u8; 3] = [255, 220, 60];

fn overlap(a: Box2, b: Box2) -> bool {
    a[0] < b[2] - 0.01 && b[0] < a[2] - 0.01 && a[1] < b[3] - 0.01 && b[1] < a[3] - 0.01
}

fn centre(b: Box2) -> [f32; 2] {
    [(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0]
}

/// The app at step `n` (from 1) of `lesson`, presenting at a projector, text size 1.5.
fn app(lesson: &str, n: usize, lang: Lang) -> Drawn {
    app_with(lesson, n, lang, true)
}

/// [`app`], presenting or with the Lessons panel under the canvas.
fn app_with(lesson: &str, n: usize, lang: Lang, present: bool) -> Drawn {
    let h = common::app::lecture_with(lesson, n, lang, present);
    let mut d = Drawn::default();
    let mut letters = Vec::new();
    let mut circles = Vec::new();
    for c in &h.output().shapes {
        match &c.shape {
            egui::Shape::Text(s) => {
                let r = s.galley.rect.translate(s.pos.to_vec2());
                let b = [r.min.x, r.min.y, r.max.x, r.max.y];
                let t = s.galley.job.text.clone();
                let mut chars = t.chars();
                match (chars.next(), chars.next()) {
                    (Some(l), None) if l.is_ascii_uppercase() => letters.push((l, centre(b))),
                    _ => d.labels.push((t, b)),
                }
            }
            egui::Shape::Circle(s) if s.radius >= 8.0 => {
                circles.push(([s.center.x, s.center.y], s.radius));
            }
            egui::Shape::Rect(s) if s.stroke.color.to_array()[..3] == QUAD => {
                let r = s.rect;
                d.quad = Some([r.min.x, r.min.y, r.max.x, r.max.y]);
            }
            egui::Shape::LineSegment { points, stroke } if stroke.color.to_array()[..3] == QUAD => {
                d.leaders.push(points.map(|p| [p.x, p.y]));
            }
            _ => {}
        }
    }
    d.handles = handles(&letters, &circles);
    d
}

/// The handles: each letter drawn at the centre of a circle (within a point).
fn handles(
    letters: &[(char, [f32; 2])],
    circles: &[([f32; 2], f32)],
) -> Vec<(char, [f32; 2], f32)> {
    letters
        .iter()
        .filter_map(|&(l, p)| {
            circles
                .iter()
                .find(|(c, _)| (c[0] - p[0]).abs() < 1.5 && (c[1] - p[1]).abs() < 1.5)
                .map(|&(c, r)| (l, c, r))
        })
        .collect()
}

fn attr(element: &str, name: &str) -> Option<f32> {
    let key = format!(r#" {name}=""#);
    let start = element.find(&key)? + key.len();
    let rest = &element[start..];
    rest[..rest.find('"')?].parse().ok()
}

fn attr_str<'a>(element: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(r#" {name}=""#);
    let start = element.find(&key)? + key.len();
    let rest = &element[start..];
    Some(&rest[..rest.find('"')?])
}

/// Step `n`'s figure of `lesson` as SVG, read back.
fn figure(lesson: &str, n: usize, lang: Lang) -> Drawn {
    let l = Lesson::open(Path::new(lesson)).expect("the lesson");
    let fig = barylab::lesson::handout::step_figure(&l, n, lang, |_| {}).expect("figure");
    let doc = barylab::figure::svg::to_svg(&fig).expect("svg");
    let quad_hex = format!("#{:02x}{:02x}{:02x}", QUAD[0], QUAD[1], QUAD[2]);
    let mut d = Drawn::default();
    let mut letters = Vec::new();
    let mut circles = Vec::new();
    for line in doc.lines() {
        if line.starts_with(r#"<g class="label""#) {
            let b: Vec<f32> = attr_str(line, "data-box")
                .expect("box")
                .split(' ')
                .map(|v| v.parse().expect("number"))
                .collect();
            let b = [b[0], b[1], b[0] + b[2], b[1] + b[3]];
            let text = attr_str(line, "aria-label").expect("text").to_string();
            let mut chars = text.chars();
            match (chars.next(), chars.next()) {
                (Some(l), None) if l.is_ascii_uppercase() => letters.push((l, centre(b))),
                _ => d.labels.push((text, b)),
            }
        } else if line.starts_with("<circle") {
            let (x, y, r) = (attr(line, "cx"), attr(line, "cy"), attr(line, "r"));
            if let (Some(x), Some(y), Some(r)) = (x, y, r)
                && r >= 8.0
            {
                circles.push(([x, y], r));
            }
        } else if line.starts_with("<rect") && attr_str(line, "stroke") == Some(&quad_hex) {
            let [x, y, w, h] = ["x", "y", "width", "height"].map(|a| attr(line, a).expect(a));
            d.quad = Some([x, y, x + w, y + h]);
        } else if line.starts_with("<polyline") && attr_str(line, "stroke") == Some(&quad_hex) {
            let p: Vec<f32> = attr_str(line, "points")
                .expect("points")
                .split([' ', ','])
                .map(|v| v.parse().expect("number"))
                .collect();
            d.leaders.push([[p[0], p[1]], [p[2], p[3]]]);
        }
    }
    d.handles = handles(&letters, &circles);
    d
}

/// The uv labels' boxes, in the order `uv_00 uv_10 uv_01 uv_11`.
fn quad_labels(d: &Drawn) -> [Box2; 4] {
    ["uv_00", "uv_10", "uv_01", "uv_11"].map(|name| {
        let found: Vec<Box2> = d
            .labels
            .iter()
            .filter(|(t, _)| t.starts_with(name))
            .map(|(_, b)| *b)
            .collect();
        assert_eq!(found.len(), 1, "{name} once in {:?}", d.labels);
        found[0]
    })
}

/// The block's checks on what `d` draws (`what` names it in messages).
fn check_block(d: &Drawn, what: &str) {
    let [b00, b10, b01, b11] = quad_labels(d);
    // Two rows of two, as the pixels: left column x, right column x + 1, upper row y.
    assert!(
        b00[2] <= b10[0] && b01[2] <= b11[0],
        "{what}: columns {d:?}"
    );
    assert!(b00[3] <= b01[1] && b10[3] <= b11[1], "{what}: rows {d:?}");
    assert!(
        (b00[1] - b10[1]).abs() < 0.5 && (b01[1] - b11[1]).abs() < 0.5,
        "{what}: rows level {d:?}"
    );
    // The left column flush right, the right column flush left: one block.
    assert!(
        (b00[2] - b01[2]).abs() < 0.5 && (b10[0] - b11[0]).abs() < 0.5,
        "{what}: {d:?}"
    );
    assert!(
        b10[0] - b00[2] < 20.0 && b01[1] - b00[3] < 20.0,
        "{what}: one block {d:?}"
    );
    let uv = [b00, b10, b01, b11];
    for (i, a) in uv.iter().enumerate() {
        for b in &uv[i + 1..] {
            assert!(!overlap(*a, *b), "{what}: {a:?} over {b:?}");
        }
        for (name, c, r) in &d.handles {
            let o = [c[0] - r, c[1] - r, c[0] + r, c[1] + r];
            assert!(!overlap(*a, o), "{what}: {a:?} over handle {name}");
        }
        for (t, b) in d.labels.iter().filter(|(t, _)| t.contains("w = ")) {
            assert!(!overlap(*a, *b), "{what}: {a:?} over {t}");
        }
    }
    let quad = d.quad.expect("the quad's outline");
    let block = [
        b00[0].min(b01[0]),
        b00[1],
        b10[2].max(b11[2]),
        b01[3].max(b11[3]),
    ];
    let gap = box_distance(block, quad);
    assert!(
        gap > 0.0,
        "{what}: the block {block:?} covers the quad {quad:?}"
    );
    if gap > LEADER_FROM {
        // Far: a leader from the block's edge to the quad's.
        let [a, b] = *d
            .leaders
            .first()
            .unwrap_or_else(|| panic!("{what}: a leader, {d:?}"));
        // (The block of the texts, the labels' boxes reach their padding further; the
        // outline's box, the leader ends at its shadow's edge.)
        assert!(
            point_distance(block, a) < 8.0,
            "{what}: leader starts at the block {a:?}"
        );
        assert!(
            point_distance(quad, b) < 9.0,
            "{what}: leader ends at the quad {b:?}"
        );
    } else {
        assert!(d.leaders.is_empty(), "{what}: no leader when near");
    }
}

/// Every handle label nearer its own handle (named by its first letter) than any other, and
/// every handle has its label.
fn check_handle_labels(d: &Drawn, what: &str) {
    let labels: Vec<&(String, Box2)> = d
        .labels
        .iter()
        .filter(|(t, _)| t.contains("  w = "))
        .collect();
    assert!(!labels.is_empty() || d.handles.is_empty(), "{what}: {d:?}");
    // (Two views side by side each have their A, B, ...: a label's own handle is the nearest
    // of its name.)
    for (t, b) in labels {
        let name = t.chars().next().expect("a name");
        let mine = d
            .handles
            .iter()
            .filter(|h| h.0 == name)
            .map(|h| point_distance(*b, h.1))
            .fold(f32::INFINITY, f32::min);
        assert!(mine.is_finite(), "{what}: {t} has a handle");
        for (other, c, _) in d.handles.iter().filter(|h| h.0 != name) {
            let theirs = point_distance(*b, *c);
            assert!(
                mine < theirs,
                "{what}: {t} at {b:?} is {mine} from {name}, {theirs} from {other}"
            );
        }
    }
}

#[test]
fn the_quad_labels_are_one_block_as_the_pixels_on_the_canvas_and_in_figures() {
    for step in [3, 7, 9, 11] {
        for lang in [Lang::En, Lang::Zh] {
            check_block(
                &app("texture", step, lang),
                &format!("app, step {step} {lang:?}"),
            );
        }
        check_block(
            &figure("texture", step, Lang::En),
            &format!("figure, step {step}"),
        );
    }
}

#[test]
fn every_handle_label_is_nearer_its_own_handle_than_any_other() {
    let texture = Lesson::open(Path::new("texture"))
        .expect("lesson")
        .steps
        .len();
    let builtin = Lesson::open(Path::new("builtin"))
        .expect("lesson")
        .steps
        .len();
    for (lesson, count) in [("texture", texture), ("builtin", builtin)] {
        for step in 1..=count {
            let d = app(lesson, step, Lang::En);
            assert!(d.handles.len() >= 3, "{lesson} {step}: the handles {d:?}");
            check_handle_labels(&d, &format!("app, {lesson} step {step}"));
            check_handle_labels(
                &figure(lesson, step, Lang::En),
                &format!("figure, {lesson} step {step}"),
            );
        }
    }
}

/// With the Lessons panel under the canvas at a lecture projector (1024x768, text size 1.5:
/// the pictures are small, two side by side smaller still), no handle label covers another
/// on any step of either built-in lesson, in either language: a label that finds no free
/// place at full size takes a smaller one, and so does the quad's block of uv labels. (On
/// the built-in lesson's step 12, D's label lay over C's; on texture step 9 the uv block lay
/// over D's and C's.)
#[test]
fn handle_labels_never_cover_each_other_beside_the_lessons_panel() {
    for lesson in ["builtin", "texture"] {
        let count = Lesson::open(Path::new(lesson)).expect("lesson").steps.len();
        for lang in [Lang::En, Lang::Zh] {
            for step in 1..=count {
                let d = app_with(lesson, step, lang, false);
                let labels: Vec<&(String, Box2)> = d
                    .labels
                    .iter()
                    .filter(|(t, _)| t.contains("w = "))
                    .collect();
                for (i, (t, a)) in labels.iter().enumerate() {
                    for (u, b) in &labels[i + 1..] {
                        assert!(
                            !overlap(*a, *b),
                            "{lesson} step {step} {lang:?}: {t} at {a:?} covers {u} at {b:?}"
                        );
                    }
                }
                // Nor does the quad's block of uv labels (which takes a smaller size too).
                for (u, b) in d.labels.iter().filter(|(t, _)| t.starts_with("uv_")) {
                    for (t, a) in &labels {
                        assert!(
                            !overlap(*a, *b),
                            "{lesson} step {step} {lang:?}: {u} at {b:?} covers {t} at {a:?}"
                        );
                    }
                }
            }
        }
    }
}
