//! The quiz (issue 34, item 5): answers from the probe, verdicts within the tolerance, and
//! each known mistake diagnosed from a wrong answer computed here by hand; quiz steps in
//! lessons.

use barylab::i18n::Lang;
use barylab::lesson::{Lesson, LessonError, parse_str};
use barylab::probe::quiz::{self, Expected, Mistake, Quantity, TOLERANCE};
use barylab::probe::{PixelTrace, probe};
use barylab::raster::{BuiltinTexture, Texture};
use barylab::scene::Scene;

/// One triangle in clip space on an 8x8 image: window A = (0, 8), B = (8, 8), C = (0, 0)
/// (y down), w = 1, 2, 4, uv A = (0, 0), B = (1, 0), C = (0, 1).
const SCENE: &str = r#"{
  "width": 8, "height": 8,
  "vertices": [
    { "clip": [-1.0, -1.0, 0.0, 1.0], "uv": [0.0, 0.0], "color": [1.0, 0.0, 0.0] },
    { "clip": [2.0, -2.0, 0.0, 2.0], "uv": [1.0, 0.0], "color": [0.0, 1.0, 0.0] },
    { "clip": [-4.0, 4.0, 0.0, 4.0], "uv": [0.0, 1.0], "color": [0.0, 0.0, 1.0] }
  ],
  "triangles": [[0, 1, 2]],
  "texture": "uv-grid"
}"#;

const W: [f64; 3] = [1.0, 2.0, 4.0];
const WINDOW: [[f64; 2]; 3] = [[0.0, 8.0], [8.0, 8.0], [0.0, 0.0]];

fn trace(x: u32, y: u32) -> PixelTrace {
    let scene = Scene::from_json(SCENE, "quiz test scene").expect("the test scene reads");
    let texture = Texture::builtin(BuiltinTexture::UvGrid);
    probe(&scene, &texture, &scene.settings(), (x, y)).expect("the pixel probes")
}

/// Screen weights of `p` by sub-triangle areas, written out here (not the probe's function).
fn by_hand(p: [f64; 2]) -> [f64; 3] {
    let area = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    };
    let [a, b, c] = WINDOW;
    let whole = area(a, b, c);
    [
        area(p, b, c) / whole,
        area(a, p, c) / whole,
        area(a, b, p) / whole,
    ]
}

/// `1/W_P` and a, b, c from screen weights, written out here.
fn correct(l: [f64; 3], w: [f64; 3]) -> (f64, [f64; 3]) {
    let inv = l[0] / w[0] + l[1] / w[1] + l[2] / w[2];
    (inv, [0, 1, 2].map(|i| l[i] / w[i] / inv))
}

fn expected(ask: Quantity) -> Expected {
    let mut key = quiz::key(&trace(4, 6), &[ask]).expect("the pixel has a key");
    key.pop().expect("one quantity asked")
}

#[test]
fn the_answers_are_the_hand_computed_numbers() {
    let rst = by_hand([4.5, 6.5]);
    assert_eq!(rst, [0.25, 0.5625, 0.1875]);
    let (inv, abc) = correct(rst, W);
    let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
    let key = quiz::key(&trace(4, 6), &Quantity::ALL).expect("a key");
    assert_eq!(key.len(), 4);
    assert!(close(&key[0].values, &rst), "{:?}", key[0].values);
    assert!(close(&key[1].values, &abc), "{:?}", key[1].values);
    assert!(close(&key[2].values, &[inv]), "{:?}", key[2].values);
    assert!((inv - 37.0 / 64.0).abs() < 1e-15);
    // uv = a uv_A + b uv_B + c uv_C = (b, c).
    assert!(
        close(&key[3].values, &[abc[1], abc[2]]),
        "{:?}",
        key[3].values
    );
}

#[test]
fn correct_answers_are_accepted_when_rounded_to_two_decimals() {
    let rst = by_hand([4.5, 6.5]);
    let rounded = rst.map(|v| (v * 100.0).round() / 100.0);
    let v = expected(Quantity::ScreenWeights).check(&rounded);
    assert!(v.correct, "{v:?}");
    assert_eq!(v.diagnosis, None);
    let (inv, _) = correct(rst, W);
    assert!(
        expected(Quantity::InvW)
            .check(&[(inv * 100.0).round() / 100.0])
            .correct
    );
    // Fractions typed by the class read exactly.
    let typed: Vec<f64> = ["1/4", "9/16", "0.1875"]
        .iter()
        .map(|t| quiz::parse_number(t).expect("a number"))
        .collect();
    assert!(expected(Quantity::ScreenWeights).check(&typed).correct);
}

#[test]
fn a_near_miss_is_wrong_with_its_differences_and_no_diagnosis() {
    let v = expected(Quantity::ScreenWeights).check(&[0.25, 0.58, 0.17]);
    assert!(!v.correct);
    assert_eq!(v.diagnosis, None);
    let want = [0.0, 0.58 - 0.5625, 0.17 - 0.1875];
    assert_eq!(v.differences.len(), 3);
    for (d, w) in v.differences.iter().zip(want) {
        assert!((d - w).abs() < 1e-9, "{:?}", v.differences);
    }
    // Just outside the tolerance is wrong, just inside right.
    let e = expected(Quantity::InvW);
    let inv = 37.0 / 64.0;
    assert!(e.check(&[inv + 0.9 * TOLERANCE]).correct);
    assert!(!e.check(&[inv + 1.5 * TOLERANCE]).correct);
    // Too few numbers: wrong, not a panic.
    assert!(!expected(Quantity::Uv).check(&[0.5]).correct);
}

#[test]
fn screen_weights_given_as_perspective_weights_are_diagnosed() {
    let rst = by_hand([4.5, 6.5]);
    let v = expected(Quantity::Weights).check(&rst);
    assert!(!v.correct);
    assert_eq!(v.diagnosis, Some(Mistake::ScreenForPerspective));
    // And the other way round.
    let (_, abc) = correct(rst, W);
    let v = expected(Quantity::ScreenWeights).check(&abc);
    assert_eq!(v.diagnosis, Some(Mistake::ScreenForPerspective));
}

#[test]
fn w_equal_to_one_is_diagnosed_for_inv_w_and_uv() {
    let rst = by_hand([4.5, 6.5]);
    let (inv_one, _) = correct(rst, [1.0; 3]);
    assert_eq!(inv_one, 1.0);
    let v = expected(Quantity::InvW).check(&[inv_one]);
    assert_eq!(v.diagnosis, Some(Mistake::WOne));
    // Affine uv = r uv_A + s uv_B + t uv_C = (s, t).
    let v = expected(Quantity::Uv).check(&[rst[1], rst[2]]);
    assert!(!v.correct);
    assert_eq!(v.diagnosis, Some(Mistake::WOne));
}

#[test]
fn weights_in_the_wrong_vertex_order_are_diagnosed() {
    let rst = by_hand([4.5, 6.5]);
    let v = expected(Quantity::ScreenWeights).check(&[rst[1], rst[0], rst[2]]);
    assert_eq!(v.diagnosis, Some(Mistake::VertexOrder));
    let (_, abc) = correct(rst, W);
    let v = expected(Quantity::Weights).check(&[abc[2], abc[0], abc[1]]);
    assert_eq!(v.diagnosis, Some(Mistake::VertexOrder));
    // 1/W_P with r and s paired with the other vertex's w.
    let (inv, _) = correct([rst[1], rst[0], rst[2]], W);
    let v = expected(Quantity::InvW).check(&[inv]);
    assert_eq!(v.diagnosis, Some(Mistake::VertexOrder));
    // uv from a, b, c given to the wrong vertices: a to C, c to A: (b, a).
    let v = expected(Quantity::Uv).check(&[abc[1], abc[0]]);
    assert_eq!(v.diagnosis, Some(Mistake::VertexOrder));
}

#[test]
fn a_forgotten_half_pixel_offset_is_diagnosed() {
    let corner = by_hand([4.0, 6.0]);
    let v = expected(Quantity::ScreenWeights).check(&corner);
    assert!(!v.correct);
    assert_eq!(v.diagnosis, Some(Mistake::HalfPixel));
    let (inv, abc) = correct(corner, W);
    assert_eq!(
        expected(Quantity::Weights).check(&abc).diagnosis,
        Some(Mistake::HalfPixel)
    );
    assert_eq!(
        expected(Quantity::InvW).check(&[inv]).diagnosis,
        Some(Mistake::HalfPixel)
    );
    assert_eq!(
        expected(Quantity::Uv).check(&[abc[1], abc[2]]).diagnosis,
        Some(Mistake::HalfPixel)
    );
}

#[test]
fn every_mistake_is_named_and_explained_in_both_languages() {
    for m in [
        Mistake::ScreenForPerspective,
        Mistake::WOne,
        Mistake::VertexOrder,
        Mistake::HalfPixel,
    ] {
        for lang in Lang::ALL {
            let (name, text) = (m.name(lang), m.explain(lang));
            assert!(
                !name.starts_with("quiz.") && !text.starts_with("quiz."),
                "{name}"
            );
            assert!(text.len() > 40, "{text}");
        }
        assert!(
            m.explain(Lang::Zh)
                .chars()
                .any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
        );
    }
    assert!(Mistake::HalfPixel.explain(Lang::Zh).contains("像素中心"));
    assert!(
        Mistake::ScreenForPerspective
            .name(Lang::Zh)
            .contains("透视校正")
    );
}

fn lesson_with(quiz: &str, pin: &str) -> Result<Lesson, LessonError> {
    let text = format!(
        r#"{{"title": {{"en": "T", "zh": "题"}}, "steps": [
  {{"title": {{"en": "A", "zh": "甲"}}, "text": {{"en": "x", "zh": "文"}},
    "try": {{"en": "y", "zh": "试"}}, "scene": "builtin:rgb-triangle"{pin},
    "quiz": {quiz}}}
]}}"#
    );
    parse_str(&text, "quiz.json", std::path::Path::new("."))
}

#[test]
fn a_quiz_step_reads_and_pins_its_pixel() {
    let l = lesson_with(r#"{"pixel": [10, 20], "ask": ["weights", "uv"]}"#, "")
        .expect("the quiz step reads");
    let state = l.state(0).expect("step 1");
    assert_eq!(state.pin, Some([10, 20]));
    let q = state.quiz.expect("a quiz");
    assert_eq!(q.pixel, [10, 20]);
    assert_eq!(q.ask, vec![Quantity::Weights, Quantity::Uv]);
    // Without its own pixel the quiz asks about the pin.
    let l = lesson_with(r#"{"ask": ["inv_w"]}"#, r#", "pin": [3, 4]"#).expect("reads");
    assert_eq!(
        l.state(0).and_then(|s| s.quiz).map(|q| q.pixel),
        Some([3, 4])
    );
}

#[test]
fn bad_quiz_steps_name_the_file_and_the_step() {
    for (quiz, pin, says) in [
        (r#"{"ask": []}"#, "", "is empty"),
        (r#"{"ask": ["uv", "uv"]}"#, "", "twice"),
        (r#"{"ask": ["rst"]}"#, "", "rst"),
        (r#"{"ask": ["uv"]}"#, "", "needs a pixel"),
        (r#"{"ask": ["uv"], "pixel": [5000, 1]}"#, "", "outside"),
        (r#"{"ask": ["uv"], "pixle": [1, 1]}"#, "", "pixle"),
    ] {
        let e = lesson_with(quiz, pin).expect_err(quiz).to_string();
        assert!(e.starts_with("quiz.json:"), "{e}");
        assert!(e.contains("steps[0]"), "{e}");
        assert!(e.contains(says), "{quiz}: {e}");
    }
}

#[test]
fn the_builtin_lesson_keeps_17_steps_and_its_quiz_pixels_have_answers() {
    let lesson = Lesson::builtin().expect("the built-in lesson");
    assert_eq!(lesson.steps.len(), 17);
    let mut asked = Vec::new();
    for i in 0..lesson.steps.len() {
        let state = lesson.state(i).expect("a step");
        let Some(q) = state.quiz else { continue };
        let texture = Texture::builtin(BuiltinTexture::UvGrid);
        let t = probe(
            &state.scene,
            &texture,
            &state.scene.settings(),
            q.pixel.into(),
        )
        .expect("probes");
        assert!(
            t.written_by.is_some(),
            "step {}: the quiz pixel is covered",
            i + 1
        );
        let key = quiz::key(&t, &q.ask).expect("a key");
        assert_eq!(key.len(), q.ask.len());
        asked.extend(q.ask);
    }
    for q in Quantity::ALL {
        assert!(asked.contains(&q), "the built-in lesson asks {q:?}");
    }
}

#[test]
fn the_handout_has_a_quiz_sheet_and_an_answer_key_in_both_languages() {
    use barylab::lesson::handout;
    let lesson = Lesson::builtin().expect("the built-in lesson");
    // The numbers of step 6's quiz pixel, from the probe.
    let state = lesson.state(5).expect("step 6");
    let texture = handout::texture_of(&state, 6).expect("a texture");
    let t = probe(&state.scene, &texture, &state.scene.settings(), (120, 180)).expect("probes");
    let rst = t.detail.as_ref().expect("a triangle").screen.rasterizer;
    for (lang, says) in [(Lang::En, "predict"), (Lang::Zh, "预测")] {
        let files = handout::handout(&lesson, lang).expect("the handout");
        let file = |name: &str| {
            let f = files
                .iter()
                .find(|f| f.name == name)
                .unwrap_or_else(|| panic!("{name} is written"));
            String::from_utf8(f.bytes.clone()).expect("UTF-8")
        };
        let sheet = file("quiz.md");
        let key = file("quiz-key.md");
        // Three questions, each with a figure that is among the files, and blank lines.
        assert_eq!(sheet.matches("\n## ").count(), 3, "{sheet}");
        assert!(sheet.contains(says), "{sheet}");
        assert!(sheet.contains("(120, 180)") && sheet.contains("(400, 420)"));
        for line in sheet.lines().filter(|l| l.starts_with("![")) {
            let name = line
                .rsplit_once('(')
                .and_then(|(_, n)| n.strip_suffix(')'))
                .expect("a figure link");
            assert!(files.iter().any(|f| f.name == name), "{name} is written");
        }
        assert_eq!(sheet.matches("r = \\_").count(), 1);
        assert_eq!(sheet.matches("1/W_P = \\_").count(), 1);
        // The sheet gives no answer; the key does, with the derivation and the mistakes.
        let r = format!("{:.4}", rst[0]);
        assert!(!sheet.contains(&r), "{sheet}");
        assert!(
            key.contains(&format!("r = {r}, s = {:.4}, t = {:.4}", rst[1], rst[2])),
            "{key}"
        );
        assert!(key.contains(&Mistake::VertexOrder.name(lang)), "{key}");
        assert!(key.contains(&Mistake::WOne.name(lang)), "{key}");
        assert!(key.contains("#### 1."), "the derivation's sections: {key}");
    }
}

#[test]
fn barylab_lesson_handout_writes_the_quiz_files() {
    let dir = tempfile::tempdir().expect("a temp dir");
    let out = dir.path().join("handout");
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(["lesson", "builtin", "--handout"])
        .arg(&out)
        .output()
        .expect("run barylab");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    for name in ["handout.md", "quiz.md", "quiz-key.md", "step-06.png"] {
        assert!(out.join(name).is_file(), "{name}");
    }
}
