//! The probe's worked example checks by hand: every line of arithmetic it prints gives its
//! printed result from its printed operands, at the precision shown; the clipped triangle's
//! λ lines and the nearest filter's wrap step are reproducible from the numbers on the page.

use std::path::{Path, PathBuf};

use barylab::i18n::Lang;
use barylab::probe::format::{self, Format};
use barylab::probe::probe;
use barylab::raster::{Filter, Interpolation, Wrap};
use barylab::scene::Scene;

fn scene(name: &str) -> (Scene, PathBuf) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    (Scene::load(&dir.join(name)).expect(name), dir)
}

/// A tiny calculator for the text format's arithmetic: numbers (with `e` exponents), `+`,
/// `-`, `·`, `×`, `/`, parentheses and unary minus. `None` for anything else (symbols,
/// tuples, words).
struct Calc<'a> {
    s: &'a [char],
    i: usize,
}

impl Calc<'_> {
    fn eval(text: &str) -> Option<f64> {
        let chars: Vec<char> = text.chars().filter(|c| !c.is_whitespace()).collect();
        if chars.is_empty() {
            return None;
        }
        let mut c = Calc { s: &chars, i: 0 };
        let v = c.sum()?;
        (c.i == chars.len()).then_some(v)
    }

    fn peek(&self) -> Option<char> {
        self.s.get(self.i).copied()
    }

    fn sum(&mut self) -> Option<f64> {
        let mut v = self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.i += 1;
            let r = self.product()?;
            v = if op == '+' { v + r } else { v - r };
        }
        Some(v)
    }

    fn product(&mut self) -> Option<f64> {
        let mut v = self.unary()?;
        while let Some(op @ ('·' | '×' | '/')) = self.peek() {
            self.i += 1;
            let r = self.unary()?;
            v = if op == '/' { v / r } else { v * r };
        }
        Some(v)
    }

    fn unary(&mut self) -> Option<f64> {
        match self.peek()? {
            '-' => {
                self.i += 1;
                Some(-self.unary()?)
            }
            '(' => {
                self.i += 1;
                let v = self.sum()?;
                (self.peek()? == ')').then(|| self.i += 1)?;
                Some(v)
            }
            _ => self.number(),
        }
    }

    fn number(&mut self) -> Option<f64> {
        let start = self.i;
        while let Some(c) = self.peek() {
            let exp_sign = matches!(c, '-' | '+') && self.i > start && self.s[self.i - 1] == 'e';
            if c.is_ascii_digit() || c == '.' || c == 'e' || exp_sign {
                self.i += 1;
            } else {
                break;
            }
        }
        self.s[start..self.i]
            .iter()
            .collect::<String>()
            .parse()
            .ok()
    }
}

/// The formula chains of a text derivation: a line and its continuation lines (those that
/// start with `=`), split at ` = `, with any note in parentheses after four spaces dropped.
fn chains(text: &str) -> Vec<Vec<String>> {
    let mut out: Vec<String> = Vec::new();
    for line in text.lines() {
        let t = line.trim();
        let t = t.split("    (").next().unwrap_or(t);
        match (t.strip_prefix("= "), out.last_mut()) {
            (Some(rest), Some(prev)) => {
                prev.push_str(" = ");
                prev.push_str(rest);
            }
            _ => out.push(t.to_string()),
        }
    }
    out.iter()
        .flat_map(|l| l.split(",   "))
        .map(|f| f.split(" = ").map(str::to_string).collect())
        .collect()
}

/// Checks every chain whose last two parts are arithmetic and a number: the arithmetic of
/// the printed operands must give the printed result within 0.6 units of its fourth
/// significant digit. Returns how many were checked.
fn check_arithmetic(text: &str, what: &str) -> usize {
    let mut checked = 0;
    for chain in chains(text) {
        let n = chain.len();
        if n < 3 {
            continue;
        }
        let (expr, result) = (&chain[n - 2], &chain[n - 1]);
        // Only lines that compute: the operand side has an operator.
        if !expr.contains(['·', '/', '+', '×']) && !expr.trim_start_matches('-').contains('-') {
            continue;
        }
        let (Some(v), Some(shown)) = (Calc::eval(expr), Calc::eval(result)) else {
            continue;
        };
        if shown == 0.0 || !v.is_finite() {
            continue;
        }
        let unit = 10f64.powi(shown.abs().log10().floor() as i32 - 3);
        assert!(
            (v - shown).abs() <= 0.6 * unit,
            "{what}: `{expr} = {result}` does not check: the operands give {v}"
        );
        checked += 1;
    }
    checked
}

/// The numeric tokens of a text derivation, in order (the numbers, not the words around them;
/// a token is a digit run with its decimal point and exponent). "2D" and "3D" are words (the
/// Chinese text says 二维, 三维), not numbers.
fn numbers(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let chars: Vec<char> = text.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        let exponent = (c == 'e' || c == '-')
            && cur
                .chars()
                .last()
                .is_some_and(|p| p.is_ascii_digit() || p == 'e')
            && chars
                .get(i + 1)
                .is_some_and(|n| n.is_ascii_digit() || *n == '-');
        if c.is_ascii_digit() || (c == '.' && !cur.is_empty()) || (!cur.is_empty() && exponent) {
            cur.push(c);
        } else if !cur.is_empty() {
            let word = c == 'D' && cur.len() == 1;
            let token = std::mem::take(&mut cur);
            if !word {
                out.push(token);
            }
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// The formula lines of a text derivation (indented four spaces; prose has two).
fn formulas(text: &str) -> String {
    text.lines()
        .filter(|l| l.starts_with("    "))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn every_printed_computation_checks_by_hand() {
    let cases = [
        ("default.json", (400, 420)),
        ("default.json", (190, 200)),
        ("corner-behind.json", (300, 200)),
        ("corner-behind.json", (20, 470)),
        ("vertex-colors.json", (240, 200)),
        ("clip-two-triangles.json", (30, 20)),
        ("far-checker.json", (200, 100)),
        ("orthographic.json", (200, 150)),
    ];
    let mut total = 0;
    for (name, (x, y)) in cases {
        let (scene, dir) = scene(name);
        let texture = scene.load_texture(&dir).expect("texture");
        for mode in [Interpolation::Affine, Interpolation::Perspective] {
            let mut settings = scene.settings();
            settings.mode = mode;
            let (x, y) = (x.min(settings.width - 1), y.min(settings.height - 1));
            let t = probe(&scene, &texture, &settings, (x, y)).expect("probe");
            let text = format::write(&t, Format::Text);
            total += check_arithmetic(&text, &format!("{name} ({x}, {y}) {mode:?}"));
            // The Chinese derivation: the same arithmetic, the same numbers in the same order.
            let zh = format::write_in(&t, Format::Text, Lang::Zh);
            let checked = check_arithmetic(&zh, &format!("zh: {name} ({x}, {y}) {mode:?}"));
            assert_eq!(checked, check_arithmetic(&text, "en"), "{name} ({x}, {y})");
            assert_eq!(
                numbers(&formulas(&zh)),
                numbers(&formulas(&text)),
                "{name} ({x}, {y}) {mode:?}"
            );
        }
    }
    assert!(
        total > 300,
        "only {total} computations found: is the parser broken?"
    );
}

/// The calculator and the check reject what they must: the old output `W_P = 1/10.4 =
/// 0.09611` (an operand rounded to the result's digits) does not check.
#[test]
fn a_line_with_short_operands_fails_the_check() {
    assert_eq!(Calc::eval("0.25·1.72973/1"), Some(0.25 * 1.72973));
    assert_eq!(Calc::eval("-68461.1 / (-340696)"), Some(68461.1 / 340696.0));
    assert_eq!(Calc::eval("1.25e-9"), Some(1.25e-9));
    assert_eq!(Calc::eval("(1, 2)"), None);
    let good = "    W_P = 1/10.4047 = 0.09611\n";
    assert_eq!(check_arithmetic(good, "good"), 1);
    let bad = "    W_P = 1/10.4 = 0.09611\n";
    let r = std::panic::catch_unwind(|| check_arithmetic(bad, "bad"));
    assert!(r.is_err(), "1/10.4 = 0.09611 passed the check");
}

/// A clipped triangle's λ lines: with the weights and every vertex's λ on the page, a
/// student reproduces the printed λ of the pixel, both ways.
#[test]
fn clipped_lambda_lines_are_reproducible() {
    let (scene, dir) = scene("corner-behind.json");
    let texture = scene.load_texture(&dir).expect("texture");
    let t = probe(&scene, &texture, &scene.settings(), (300, 200)).expect("probe");
    let d = t.detail.as_ref().expect("detail");
    assert!(d.clipping.is_some());
    let rv = &d.raster.vertices;
    let sw = d.source_weights.expect("source weights");
    let p = d.perspective.expect("perspective");
    for i in 0..3 {
        let affine: f64 = (0..3)
            .map(|k| d.screen.rasterizer[k] * f64::from(rv[k].source_weights_affine[i]))
            .sum();
        let smooth: f64 = (0..3)
            .map(|k| p.renderer_weights[k] * f64::from(rv[k].source_weights[i]))
            .sum();
        assert!(
            (affine - f64::from(sw.screen[i])).abs() < 1e-6,
            "affine λ {i}"
        );
        assert!(
            (smooth - f64::from(sw.perspective[i])).abs() < 1e-6,
            "smooth λ {i}"
        );
    }
    // A clip-made vertex's noperspective λ differs from its smooth λ, and the page says so.
    assert!(
        rv.iter()
            .any(|v| v.source_weights_affine != v.source_weights)
    );
    let text = format::write(&t, Format::Text);
    assert!(text.contains("lambda(K1) = (-7.25, 8.25, 0)"), "{text}");
    assert!(text.contains("lambda(K1) = (0.725, 0.275, 0)"), "{text}");
    assert!(
        text.contains("(λ_A, λ_C, λ_D) = 0.0981922·(-7.25, 8.25, 0)"),
        "{text}"
    );
}

/// Nearest filtering with a repeating wrap shows the wrap step: `floor(u W)` before it, the
/// wrapped texel after it, and the two agree by `mod`. (A quad whose uv runs from 0 to 3.)
#[test]
fn nearest_wrap_step_is_shown() {
    let json = r#"{
      "width": 32, "height": 32,
      "vertices": [
        { "clip": [-1.0, -1.0, 0.0, 1.0], "uv": [0.0, 0.0] },
        { "clip": [2.0, -2.0, 0.0, 2.0], "uv": [3.0, 0.0] },
        { "clip": [2.0, 2.0, 0.0, 2.0], "uv": [3.0, 3.0] },
        { "clip": [-1.0, 1.0, 0.0, 1.0], "uv": [0.0, 3.0] }
      ],
      "triangles": [[0, 1, 2], [0, 2, 3]],
      "texture": "uv-grid",
      "filter": "nearest",
      "wrap": "repeat"
    }"#;
    let scene = Scene::from_json(json, "wrap.json").expect("scene");
    let texture = scene.load_texture(Path::new(".")).expect("texture");
    let settings = scene.settings();
    assert_eq!(
        (settings.filter, settings.wrap),
        (Filter::Nearest, Wrap::Repeat)
    );
    let (tw, th) = (i64::from(texture.width()), i64::from(texture.height()));
    let mut shown = 0;
    for (x, y) in [(30, 2), (28, 28), (16, 16), (2, 2)] {
        let t = probe(&scene, &texture, &settings, (x, y)).expect("probe");
        let a = t
            .detail
            .as_ref()
            .and_then(|d| d.attribute.as_ref())
            .expect("attribute");
        let text = format::write(&t, Format::Text);
        for tap in a.taps_affine.iter().chain(&a.taps_perspective) {
            let [i, j] = tap
                .unwrapped
                .expect("nearest taps carry the unwrapped texel");
            assert_eq!(i.rem_euclid(tw), i64::from(tap.i));
            assert_eq!(j.rem_euclid(th), i64::from(tap.j));
            if [i, j] != [i64::from(tap.i), i64::from(tap.j)] {
                // The text breaks the line before each arrow.
                let unwrapped = format!("= ({i}, {j})");
                let line = format!("→ repeat, i mod {tw}, j mod {th}: ({}, {})", tap.i, tap.j);
                assert!(
                    text.contains(&unwrapped),
                    "missing `{unwrapped}` in\n{text}"
                );
                assert!(text.contains(&line), "missing `{line}` in\n{text}");
                shown += 1;
            }
        }
    }
    assert!(shown > 0, "no pixel needed the wrap step: pick others");
}
