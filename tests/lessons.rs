//! Lessons: the format (strict, errors with file, line and field), the built-in lesson, the
//! `barylab lesson` command (list, figure, handout) and the app's Lessons panel.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use barylab::i18n::Lang;
use barylab::lesson::{InspectorSection, Lesson, LessonError, LessonPlot, text};
use barylab::raster::NO_TRIANGLE;

fn barylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab")
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).to_string()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).to_string()
}

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

#[test]
fn the_builtin_lesson_has_at_least_12_steps_in_both_languages() {
    let lesson = Lesson::builtin().expect("the built-in lesson loads");
    assert!(lesson.steps.len() >= 12, "{} steps", lesson.steps.len());
    for (i, step) in lesson.steps.iter().enumerate() {
        for lang in Lang::ALL {
            for t in [&step.title, &step.text, &step.try_this] {
                assert!(!t.get(lang).trim().is_empty(), "step {}: empty text", i + 1);
            }
        }
        // Chinese texts are Chinese, not English copies.
        assert!(
            step.text
                .zh
                .chars()
                .any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
            "step {}: the zh text has no Chinese",
            i + 1
        );
        assert_ne!(step.text.en, step.text.zh);
        // A one-line summary for presentation mode's strip.
        let summary = step.summary.as_ref().expect("a summary");
        assert!(
            summary.en.len() < 100 && !summary.en.contains('\n'),
            "step {}",
            i + 1
        );
    }
    // The file in assets/ is the one compiled in.
    let from_file = barylab::lesson::load(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/lessons/interpolation.json"),
    )
    .expect("the lesson file loads");
    assert_eq!(from_file.steps, lesson.steps);
}

#[test]
fn every_step_of_the_builtin_lesson_renders_and_pins_a_real_pixel() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let mut plots = Vec::new();
    for i in 0..lesson.steps.len() {
        let state = lesson.state(i).expect("a state per step");
        let texture = state.scene.load_texture(Path::new("")).expect("texture");
        let out =
            barylab::raster::render(&state.scene.to_mesh(), &texture, &state.scene.settings())
                .expect("renders");
        let (w, h) = state.scene.size();
        let covered = out
            .frame
            .triangle
            .iter()
            .filter(|t| **t != NO_TRIANGLE)
            .count();
        assert!(
            covered > (w * h / 20) as usize,
            "step {}: {covered} pixels covered",
            i + 1
        );
        if let Some([x, y]) = state.pin {
            assert!(x < w && y < h, "step {}", i + 1);
            let trace =
                barylab::probe::probe(&state.scene, &texture, &state.scene.settings(), (x, y))
                    .expect("probe");
            assert!(
                trace.detail.is_some(),
                "step {}: the pin has no triangle",
                i + 1
            );
        }
        plots.extend(state.plot);
    }
    assert!(plots.contains(&LessonPlot::WRow) && plots.contains(&LessonPlot::DepthRow));
}

/// The numbers the texts quote are the probe's (4 significant digits, as the inspector).
#[test]
fn numbers_quoted_in_the_builtin_lesson_are_the_probes() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let probe_step = |n: usize| {
        let state = lesson.state(n - 1).expect("state");
        let texture = state.scene.load_texture(Path::new("")).expect("texture");
        let [x, y] = state.pin.expect("pinned");
        barylab::probe::probe(&state.scene, &texture, &state.scene.settings(), (x, y))
            .expect("probe")
    };
    let fmt = barylab::probe::format::fmt_number;
    let quotes = |n: usize, v: f64| {
        let t = fmt(v).replace('-', "−");
        let step = &lesson.steps[n - 1];
        assert!(
            step.text.en.contains(&t),
            "step {n} (en) does not quote {t}"
        );
        assert!(
            step.text.zh.contains(&t),
            "step {n} (zh) does not quote {t}"
        );
    };
    // Step 1: the screen weights of the middle pixel.
    let t1 = probe_step(1);
    let d = t1.detail.as_ref().expect("covered");
    for w in d.screen.rasterizer {
        quotes(1, w);
    }
    // Step 2: below edge AB, t is negative.
    let t2 = probe_step(2);
    let d = t2.detail.as_ref().expect("detail");
    assert!(d.screen.rasterizer[2] < 0.0);
    quotes(2, d.screen.rasterizer[2]);
    // Step 2: beyond corner A, two weights are negative and A's is above 1.
    let state = lesson.state(1).expect("state");
    let texture = state.scene.load_texture(Path::new("")).expect("texture");
    let corner = barylab::probe::probe(&state.scene, &texture, &state.scene.settings(), (20, 215))
        .expect("probe");
    let w = corner.detail.as_ref().expect("detail").screen.rasterizer;
    assert!(w[0] > 1.0 && w[1] < 0.0 && w[2] < 0.0, "{w:?}");
    for v in w {
        quotes(2, v);
    }
    // Step 11: W_P and a, b, c.
    let t11 = probe_step(11);
    let p = t11
        .detail
        .as_ref()
        .and_then(|d| d.perspective)
        .expect("perspective-correct");
    quotes(11, 1.0 / p.renderer_inv_w);
    for w in p.renderer_weights {
        quotes(11, w);
    }
    // Step 12 (w = 1 everywhere): the "corrected" uv is the affine one of step 9.
    let t9 = probe_step(9);
    let t12 = probe_step(12);
    let attribute = |t: &barylab::probe::PixelTrace| {
        t.detail
            .as_ref()
            .and_then(|d| d.attribute.clone())
            .expect("uv")
    };
    // Step 16: the near-plane cut on edge AB (z + w changes sign), K1's weights, and the
    // pinned pixel in the fan triangle K1 C K2 that the text names.
    let t16 = probe_step(16);
    let d = t16.detail.as_ref().expect("detail");
    let [a, b] = [0, 1].map(|i| d.vertices[i].clip);
    let (za, zb) = (a[2] + a[3], b[2] + b[3]);
    assert!(
        za < 0.0 && zb > 0.0,
        "A is behind the near plane, B in front"
    );
    let k = za / (za - zb);
    for v in [a[3], za, -za, zb, k, 1.0 - k] {
        quotes(16, v);
    }
    let c = d.clipping.as_ref().expect("the triangle is clipped");
    let fan: Vec<&str> = c
        .fan_triangle
        .iter()
        .map(|&i| c.polygon[i].name.as_str())
        .collect();
    assert_eq!(fan, ["K1", "C", "K2"]);
    assert!((f64::from(c.polygon[0].source_weights[1]) - k).abs() < 1e-6);
    // The picture frames the cut: K1 and K2 lie inside the image, on one row (the floor meets
    // the near plane along a line parallel to the image rows: the camera does not roll).
    let mark = barylab::figure::clip_mark(&t16).expect("a clip mark");
    let names: Vec<&str> = mark.corners.iter().map(|k| k.0.as_str()).collect();
    assert_eq!(names, ["K1", "B", "C", "K2"]);
    let [w, h] = t16.image_size.map(f64::from);
    for (name, p, made) in &mark.corners {
        assert!(
            p.x > 0.0 && p.x < w && p.y > 0.0 && p.y < h,
            "{name} at {p}"
        );
        assert_eq!(*made, name.starts_with('K'));
    }
    assert!((mark.corners[0].1.y - mark.corners[3].1.y).abs() < 1e-9);
    // Step 17: the pinned pixel on the tetrahedron's face A B D (c = 0), its three weights.
    let t17 = probe_step(17);
    let d = t17.detail.as_ref().expect("covered");
    let names: Vec<&str> = d.vertices.iter().map(|v| v.name.as_str()).collect();
    assert_eq!(names, ["A", "B", "D"]);
    let p = d.perspective.expect("perspective-correct");
    for w in p.renderer_weights {
        quotes(17, w);
    }
    let uv9 = attribute(&t9).uv_affine;
    let uv12 = attribute(&t12).uv_perspective;
    assert_eq!(fmt(f64::from(uv9[0])), fmt(f64::from(uv12[0])));
    quotes(12, f64::from(uv12[0]));
}

#[test]
fn the_example_in_the_docs_is_the_test_file_and_loads() {
    let docs =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/lessons.md"))
            .expect("docs/lessons.md");
    let block = docs
        .split("```json\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .expect("a JSON example");
    let file = std::fs::read_to_string(data("example-lesson.json")).expect("example");
    let a: serde_json::Value = serde_json::from_str(block).expect("docs JSON");
    let b: serde_json::Value = serde_json::from_str(&file).expect("file JSON");
    assert_eq!(
        a, b,
        "docs/lessons.md and tests/data/example-lesson.json differ"
    );
    let lesson = barylab::lesson::load(&data("example-lesson.json")).expect("the example loads");
    assert_eq!(lesson.steps.len(), 3);
    let st = lesson.state(1).expect("step 2");
    assert_eq!(st.scene.size(), (400, 300));
    assert_eq!(st.compare, barylab::figure::Compare::SideBySide);
    assert_eq!(st.plot, Some(LessonPlot::UvRow));
    let st0 = lesson.state(0).expect("step 1");
    assert_eq!(st0.inspector, vec![InspectorSection::ScreenWeights]);
    assert_eq!(
        st0.scene.settings().shading,
        barylab::raster::Shading::Barycentric
    );
    assert!(!lesson.state(2).expect("step 3").overlays.handles);
    let Some(text::Block::Formula(lines)) = text::blocks(&lesson.steps[1].text.en).pop() else {
        panic!("the second step ends with a formula block")
    };
    assert_eq!(lines, ["uv = r·uv_A + s·uv_B + t·uv_C"]);
}

/// Writes the example lesson with `edit` applied, in tests/data's folder (its scene paths are
/// relative), and returns the error of loading it.
fn error_of(name: &str, edit: impl FnOnce(&mut serde_json::Value)) -> (LessonError, String) {
    let text = std::fs::read_to_string(data("example-lesson.json")).expect("example");
    let mut v: serde_json::Value = serde_json::from_str(&text).expect("json");
    edit(&mut v);
    let dir = tempfile::tempdir_in(data("")).expect("tempdir");
    let sub = dir.path().join("x");
    std::fs::create_dir(&sub).expect("mkdir");
    let path = sub.join(name);
    std::fs::write(&path, serde_json::to_string_pretty(&v).expect("json")).expect("write");
    let err = barylab::lesson::load(&path).expect_err("a bad lesson");
    let out = barylab(&["lesson", s(&path), "--list"]);
    assert!(!out.status.success());
    (err, stderr(&out))
}

#[test]
fn a_bad_lesson_file_is_named_with_its_line_and_field() {
    // The scene paths of the copy are two folders deeper.
    let fix = |v: &mut serde_json::Value| {
        v["steps"][1]["scene"] = "../../../../assets/scenes/default.json".into();
    };
    let (err, message) = error_of("no-zh.json", |v| {
        fix(v);
        v["steps"][1]["title"]
            .as_object_mut()
            .expect("title")
            .remove("zh");
    });
    let LessonError::Parse {
        line,
        field,
        message: m,
        ..
    } = &err
    else {
        panic!("{err}")
    };
    assert!(
        *line > 1 && field.contains("steps[1].title") && m.contains("zh"),
        "{err}"
    );
    assert!(
        message.contains("no-zh.json:") && message.contains(&format!(":{line}:")),
        "{message}"
    );
    assert!(
        message.contains("steps[1].title") && message.contains("missing field `zh`"),
        "{message}"
    );
    assert_eq!(message.trim().lines().count(), 1, "{message}");

    let (err, _) = error_of("typo.json", |v| {
        fix(v);
        v["steps"][0]["colour"] = true.into();
    });
    assert!(
        err.to_string().contains("steps[0].colour") && err.to_string().contains("unknown field"),
        "{err}"
    );

    let (err, _) = error_of("pin.json", |v| {
        fix(v);
        v["steps"][2]["pin"] = serde_json::json!([64, 0]);
    });
    assert!(
        err.to_string().contains("steps[2]") && err.to_string().contains("outside the 64x48"),
        "{err}"
    );

    let (err, _) = error_of("scene.json", |v| {
        fix(v);
        v["steps"][2]["scene"]["vertices"][0]["clip"] = serde_json::json!([1, 2]);
    });
    let m = err.to_string();
    assert!(
        m.contains("steps[2].scene") && m.contains("vertices[0].clip"),
        "{m}"
    );

    let (err, _) = error_of("missing.json", |v| {
        v["steps"][1]["scene"] = "nope.json".into()
    });
    assert!(
        err.to_string().contains("steps[1].scene") && err.to_string().contains("nope.json"),
        "{err}"
    );

    let (err, _) = error_of("builtin.json", |v| {
        v["steps"][1]["scene"] = "builtin:nope".into()
    });
    assert!(
        err.to_string().contains("rgb-triangle"),
        "lists the built-in scenes: {err}"
    );
}

#[test]
fn list_prints_one_line_per_step() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let out = barylab(&["lesson", "builtin", "--list"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), lesson.steps.len() + 1, "{text}");
    assert_eq!(lines[0], lesson.title.en);
    assert_eq!(lines[1], format!(" 1. {}", lesson.steps[0].title.en));
    let zh = stdout(&barylab(&["lesson", "builtin", "--list", "--lang", "zh"]));
    assert!(zh.contains(&lesson.steps[0].title.zh), "{zh}");
    let bad = barylab(&["lesson", "builtin", "--step", "99"]);
    assert!(
        !bad.status.success() && stderr(&bad).contains("steps 1 to"),
        "{}",
        stderr(&bad)
    );
}

/// A step's figure is `barylab figure`'s for the same scene and options, byte for byte.
#[test]
fn a_steps_figure_is_barylab_figures_for_the_same_state() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let dir = tempfile::tempdir().expect("tempdir");
    for n in [1, 9, 16] {
        let state = lesson.state(n - 1).expect("state");
        let scene = dir.path().join(format!("scene-{n}.json"));
        std::fs::write(&scene, state.scene.to_json()).expect("write scene");
        let a = dir.path().join(format!("lesson-{n}.png"));
        let b = dir.path().join(format!("figure-{n}.png"));
        let out = barylab(&[
            "lesson",
            "builtin",
            "--step",
            &n.to_string(),
            "--figure",
            s(&a),
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        let mut args = vec!["figure".to_string(), s(&scene).to_string()];
        args.extend(state.figure_options().cli_args());
        args.extend(["-o".to_string(), s(&b).to_string()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = barylab(&args);
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        let (fa, fb) = (std::fs::read(&a).expect("a"), std::fs::read(&b).expect("b"));
        assert!(fa == fb, "step {n}: the figures differ ({args:?})");
    }
    let svg = dir.path().join("s.svg");
    let out = barylab(&["lesson", "builtin", "--step", "11", "--figure", s(&svg)]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        std::fs::read_to_string(&svg)
            .expect("svg")
            .starts_with("<svg")
    );
}

#[test]
fn the_handout_has_every_step_its_figures_and_never_overwrites() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let dir = tempfile::tempdir().expect("tempdir");
    for (lang, code) in [(Lang::En, "en"), (Lang::Zh, "zh")] {
        let out_dir = dir.path().join(code);
        let out = barylab(&[
            "lesson",
            "builtin",
            "--handout",
            s(&out_dir),
            "--lang",
            code,
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
        let md = std::fs::read_to_string(out_dir.join("handout.md")).expect("handout.md");
        assert!(md.starts_with("---\ntitle:"), "pandoc metadata first");
        for (i, step) in lesson.steps.iter().enumerate() {
            let n = i + 1;
            let heading = format!("## {n}. ");
            assert!(md.contains(&heading), "no heading for step {n}");
            let first_words: String = text::plain(step.title.get(lang)).chars().take(6).collect();
            assert!(md.contains(&first_words), "step {n}'s title");
            let png = step_images(&md, n).into_iter().next().expect("a figure");
            let bytes = std::fs::read(out_dir.join(&png)).expect("figure exists");
            assert!(bytes.starts_with(b"\x89PNG"), "{png} is a PNG");
        }
        // The pinned pixel's derivation, in the handout's language.
        let derivation = if lang == Lang::En {
            "step by step"
        } else {
            "逐步推导"
        };
        assert!(md.matches(derivation).count() >= 12, "derivations");
        assert!(md.contains("$"), "math for pandoc");
        // pandoc reads it (math, figures, code blocks) without a complaint. Where pandoc is
        // missing the check is skipped, except under CI=true (.ci/run installs it).
        let pandoc = Command::new("pandoc")
            .current_dir(&out_dir)
            .args(["handout.md", "-s", "--mathml", "-o", "handout.html"])
            .output();
        if pandoc.is_err() {
            assert!(
                std::env::var("CI").as_deref() != Ok("true"),
                "pandoc is not installed but CI=true: install the pandoc package"
            );
            println!("SKIPPED the pandoc check: pandoc is not installed");
        }
        if let Ok(out) = pandoc {
            assert!(
                out.status.success() && out.stderr.is_empty(),
                "{}",
                stderr(&out)
            );
            let html = std::fs::read_to_string(out_dir.join("handout.html")).expect("html");
            assert_eq!(html.matches("<img").count(), md.matches("![").count());
            std::fs::remove_file(out_dir.join("handout.html")).expect("remove");
        }
        // Never over an existing file: a second run fails and leaves the files as they were.
        let before = std::fs::read(out_dir.join("handout.md")).expect("md");
        let again = barylab(&[
            "lesson",
            "builtin",
            "--handout",
            s(&out_dir),
            "--lang",
            code,
        ]);
        assert!(!again.status.success() && stderr(&again).contains("already exists"));
        assert_eq!(
            std::fs::read(out_dir.join("handout.md")).expect("md"),
            before
        );
    }
}

/// The images step `n`'s section of a handout links to, in order.
fn step_images(md: &str, n: usize) -> Vec<String> {
    let start = md.find(&format!("\n## {n}. ")).expect("the step's heading");
    let section = &md[start + 1..];
    let end = section[1..].find("\n## ").map_or(section.len(), |e| e + 1);
    section[..end]
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split_once(')').map(|(name, _)| name.to_string()))
        .filter(|name| name.ends_with(".png"))
        .collect()
}

/// Every step's figure file is its own picture: steps that draw different pictures link
/// different files, steps that draw the same picture link one file, and no two files of the
/// handout are the same (each step's figure drawn again here, independently of the handout).
#[test]
fn handout_figures_are_distinct_and_shared_only_when_identical() {
    use barylab::lesson::handout::{handout, step_figure};
    let lesson = Lesson::builtin().expect("built-in lesson");
    let files = handout(&lesson, Lang::En).expect("handout");
    let md = String::from_utf8(files[0].bytes.clone()).expect("UTF-8");
    for (i, a) in files.iter().enumerate() {
        for b in &files[i + 1..] {
            assert!(a.bytes != b.bytes, "{} and {} are the same", a.name, b.name);
        }
    }
    let file = |name: &str| files.iter().find(|f| f.name == name).expect("linked file");
    let mut pictures: Vec<(Vec<u8>, String)> = Vec::new();
    for n in 1..=lesson.steps.len() {
        let linked = step_images(&md, n).into_iter().next().expect("a figure");
        let figure = step_figure(&lesson, n, Lang::En, |_| {}).expect("figure");
        let bytes = barylab::figure::png::to_png(&figure).expect("png");
        assert!(file(&linked).bytes == bytes, "step {n} links {linked}");
        match pictures.iter().find(|(b, _)| *b == bytes) {
            Some((_, earlier)) => assert_eq!(&linked, earlier, "step {n} repeats a picture"),
            None => {
                assert_eq!(linked, format!("step-{n:02}.png"));
                pictures.push((bytes, linked));
            }
        }
    }
    // And the quiz sheet with its answer key (the built-in lesson has quiz steps).
    let quiz = ["quiz.md", "quiz-key.md"]
        .iter()
        .filter(|n| files.iter().any(|f| f.name == **n))
        .count();
    assert_eq!(quiz, 2);
    assert_eq!(
        files.len(),
        1 + pictures.len() + md.matches("-plot.png)").count() + quiz
    );
}

/// A step with a row plot has it in the handout: the app's lines along the pinned row (the
/// same as a full render's row), drawn as a PNG; the w and the depth plots differ.
#[test]
fn handout_row_plots_are_the_apps() {
    use barylab::lesson::handout::{PLOT_SCALE, handout, plot_name, step_state, texture_of};
    use barylab::lesson::plot::{row_lines, row_plot};
    let lesson = Lesson::builtin().expect("built-in lesson");
    let files = handout(&lesson, Lang::Zh).expect("handout");
    let md = String::from_utf8(files[0].bytes.clone()).expect("UTF-8");
    let mut plots = Vec::new();
    for n in 1..=lesson.steps.len() {
        let state = step_state(&lesson, n).expect("state");
        let linked = step_images(&md, n);
        let Some(plot) = state.plot else {
            assert_eq!(linked.len(), 1, "step {n} has no plot");
            continue;
        };
        assert_eq!(linked, [format!("step-{n:02}.png"), plot_name(n)]);
        let texture = texture_of(&state, n).expect("texture");
        let pin = state.pin.expect("pinned");
        let drawn = row_plot(&state.scene, &texture, pin, plot, Lang::Zh).expect("plot");
        let full =
            barylab::raster::render(&state.scene.to_mesh(), &texture, &state.scene.settings())
                .expect("render");
        let lines = row_lines(&full.frame, pin[1], plot);
        assert_eq!(drawn.lines.len(), lines.len());
        for ((_, a), (_, b)) in drawn.lines.iter().zip(&lines) {
            assert!(a.len() > 100, "step {n}: {} points", a.len());
            assert_eq!(a, b, "step {n}: the plot is not the row's values");
        }
        assert_eq!(drawn.marker, Some(f64::from(pin[0])));
        let bytes = &files
            .iter()
            .find(|f| f.name == plot_name(n))
            .expect("plot file")
            .bytes;
        let image = image::load_from_memory(bytes).expect("a PNG");
        let size = barylab::figure::plot::PLOT_SIZE.map(|v| (v * PLOT_SCALE) as u32);
        assert_eq!((image.width(), image.height()), (size[0], size[1]));
        plots.push((plot, bytes.clone()));
    }
    assert_eq!(
        plots.iter().map(|(p, _)| *p).collect::<Vec<_>>(),
        [LessonPlot::WRow, LessonPlot::DepthRow]
    );
    assert!(plots[0].1 != plots[1].1);
}

/// The derivation's subsections of each step are numbered 1, 2, ... (the probe numbers them
/// in its full derivation, of which a step shows some).
#[test]
fn handout_headings_are_numbered_from_one() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let files = barylab::lesson::handout::handout(&lesson, Lang::En).expect("handout");
    let md = String::from_utf8(files[0].bytes.clone()).expect("UTF-8");
    let mut steps = 0;
    for (k, part) in md.split("\n## ").skip(1).enumerate() {
        assert!(part.starts_with(&format!("{}. ", k + 1)), "step {}", k + 1);
        steps += 1;
        let numbers: Vec<String> = part
            .lines()
            .filter_map(|l| l.strip_prefix("#### "))
            .map(|h| h.split_once(". ").expect("numbered").0.to_string())
            .collect();
        let expected: Vec<String> = (1..=numbers.len()).map(|i| i.to_string()).collect();
        assert_eq!(numbers, expected, "step {}", k + 1);
    }
    assert_eq!(steps, lesson.steps.len());
}

mod app {
    use barylab::app::command::LessonCommand;
    use barylab::app::document::presets::Preset;
    use barylab::app::document::state::StateCommand;
    use barylab::app::{AppOptions, BaryApp};
    use barylab::figure::Compare;
    use barylab::lesson::Lesson;
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;

    fn harness() -> Harness<'static, BaryApp> {
        super::common::app::harness(egui::vec2(1280.0, 800.0), AppOptions::default())
    }

    /// The step's scene, view and pin are what the lesson says.
    fn assert_at_step(h: &Harness<'_, BaryApp>, lesson: &Lesson, n: usize) {
        let want = lesson.state(n).expect("step");
        let app = h.state();
        assert_eq!(app.lesson_step(), Some(n));
        let s = app.state();
        assert_eq!(s.scene, want.scene, "step {}'s scene", n + 1);
        assert_eq!(s.view.pinned, want.pin);
        assert_eq!(s.view.compare, want.compare);
        assert_eq!(s.view.plot, want.plot);
        assert_eq!(s.view.rasterizer, want.rasterizer);
    }

    #[test]
    fn a_lesson_steps_with_next_and_page_down_and_leaving_restores_the_users_scene() {
        let lesson = Lesson::builtin().expect("built-in lesson");
        let mut h = harness();
        // The user's own work: a preset (one undo step), the side-by-side view and a pin.
        h.state_mut()
            .push(StateCommand::Preset(Preset::GrazingWall));
        h.run();
        h.state_mut()
            .push(StateCommand::SetCompare(Compare::SideBySide));
        h.state_mut().push(StateCommand::Pin(Some([5, 6])));
        h.run();
        let mine = h.state().state().clone();
        let undo_steps = h.state().history().undo_steps();
        assert_eq!(undo_steps, 1);

        h.state_mut().push(LessonCommand::OpenBuiltin);
        h.run();
        assert_at_step(&h, &lesson, 0);
        // The panel shows the step's text and its "try this".
        let title = format!("1. {}", lesson.steps[0].title.en);
        assert!(
            h.query_all_by_label(&title).count() >= 2,
            "the list and the heading"
        );
        // Next (the button) goes to step 2 and sets its state; Page Down to step 3.
        h.get_by_label("Next »").click();
        h.run();
        assert_at_step(&h, &lesson, 1);
        h.key_press(egui::Key::PageDown);
        h.run();
        assert_at_step(&h, &lesson, 2);
        h.key_press(egui::Key::PageUp);
        h.run();
        assert_at_step(&h, &lesson, 1);
        // Step changes are not edits: nothing to undo.
        assert!(!h.state().history().can_undo());
        // The user changes the step; "reset this step" puts it back.
        h.state_mut().push(StateCommand::SetMode(
            barylab::raster::Interpolation::Affine,
        ));
        h.state_mut().push(StateCommand::Pin(Some([1, 1])));
        h.run();
        h.get_by_label("Reset this step").click();
        h.run();
        assert_at_step(&h, &lesson, 1);
        // A step far on, then leave: the user's scene, view, pin and undo history are back.
        h.state_mut().push(LessonCommand::Go(15));
        h.run();
        assert_at_step(&h, &lesson, 15);
        h.get_by_label("Leave the lesson").click();
        h.run();
        assert_eq!(h.state().lesson_step(), None);
        assert_eq!(h.state().state(), &mine);
        assert_eq!(h.state().history().undo_steps(), undo_steps);
    }

    #[test]
    fn the_arrow_keys_step_only_while_no_pixel_is_pinned() {
        let lesson = Lesson::builtin().expect("built-in lesson");
        let mut h = harness();
        h.state_mut().push(LessonCommand::OpenBuiltin);
        h.run();
        // Step 1 pins a pixel: the arrows move the pin.
        h.key_press(egui::Key::ArrowRight);
        h.run();
        assert_eq!(h.state().lesson_step(), Some(0));
        assert_eq!(h.state().state().view.pinned, Some([161, 140]));
        // Unpinned (Esc), the arrows step through the lesson.
        h.key_press(egui::Key::Escape);
        h.run();
        h.key_press(egui::Key::ArrowRight);
        h.run();
        assert_at_step(&h, &lesson, 1);
        // Step 2 pins its own pixel: unpin again to step back.
        h.key_press(egui::Key::Escape);
        h.run();
        h.key_press(egui::Key::ArrowLeft);
        h.run();
        assert_at_step(&h, &lesson, 0);
        // A bad lesson file leaves everything as it was and says why.
        let before = h.state().state().clone();
        h.state_mut()
            .push(LessonCommand::OpenFile("/nonexistent/lesson.json".into()));
        h.run();
        assert_eq!(h.state().state(), &before);
        let banner = h.state().banner().expect("a banner").join(" ");
        assert!(banner.contains("lesson.json"), "{banner}");
    }

    #[test]
    fn hovering_the_steps_plot_marks_that_column_of_the_pinned_row() {
        let mut h = harness();
        h.state_mut().push(LessonCommand::OpenBuiltin);
        h.run();
        h.state_mut().push(LessonCommand::Go(10));
        h.run();
        let pin = h.state().state().view.pinned.expect("step 11 pins a pixel");
        assert!(h.state().state().view.plot.is_some());
        // The legend sits in the plot's top-left corner: below it is the plot.
        let legend = h.get_by_label("w (scaled to 0…1)").rect();
        h.hover_at(egui::pos2(legend.center().x, legend.bottom() + 30.0));
        h.run();
        let hovered = h
            .state()
            .canvas()
            .hover
            .expect("a hovered pixel from the plot");
        assert_eq!(hovered[1], pin[1], "on the pinned row");
        assert_eq!(h.state().hover_report().map(|r| r.pixel), Some(hovered));
    }

    #[test]
    fn the_row_plot_opens_from_the_menu_outside_a_lesson() {
        let mut h = harness();
        h.state_mut().push(StateCommand::Pin(Some([400, 420])));
        h.run();
        h.get_by_label("Lessons").click();
        h.run();
        h.get_by_label("Plot along the pinned row").click();
        h.run();
        assert_eq!(
            h.state().state().view.plot,
            Some(barylab::lesson::LessonPlot::UvRow)
        );
        let _ = h.get_by_label("Along the pinned pixel's row");
    }
}

/// Whatever the bytes, reading a lesson returns a lesson or an error naming the file; it never
/// panics. A built-in lesson cut short anywhere is an error with its line.
mod robust {
    use barylab::lesson::{LessonError, parse_str};
    use proptest::prelude::*;
    use std::path::Path;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

        #[test]
        fn arbitrary_text_never_panics(text in "\\PC{0,400}") {
            if let Err(e) = parse_str(&text, "x.json", Path::new(".")) {
                prop_assert!(e.to_string().starts_with("x.json"), "{}", e);
            }
        }

        #[test]
        fn a_cut_lesson_is_an_error_with_a_line(cut in 1usize..20_000) {
            let full = barylab::lesson::builtin::LESSON;
            let mut end = cut.min(full.len() - 2);
            while !full.is_char_boundary(end) {
                end -= 1;
            }
            let err = parse_str(&full[..end], "cut.json", Path::new("."))
                .expect_err("a cut lesson does not parse");
            let is_parse = matches!(err, LessonError::Parse { line, .. } if line >= 1);
            prop_assert!(is_parse, "{}", err);
        }
    }
}
