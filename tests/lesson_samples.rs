//! The samples lesson (assets/lessons/samples.json): both languages in every step, the
//! numbers its texts quote are the probe's (the samples a triangle covers, the resolve, the
//! black-edge colour from the resolve formula, where the centroid evaluates, the flat colour),
//! and `barylab lesson` lists it, prints a step and draws a step's figure.

use std::path::{Path, PathBuf};
use std::process::Command;

use barylab::i18n::Lang;
use barylab::lesson::Lesson;
use barylab::probe::PixelTrace;
use barylab::raster::sample::resolve;

fn lesson_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/lessons/samples.json")
}

fn open() -> Lesson {
    barylab::lesson::load(&lesson_path()).expect("the samples lesson loads")
}

/// The pinned pixel of step `n` (from 1), probed in the state the step sets.
fn probe_step(lesson: &Lesson, n: usize) -> PixelTrace {
    let state = lesson.state(n - 1).expect("state");
    let dir = state.scene_dir.clone().unwrap_or_default();
    let texture = state.scene.load_texture(&dir).expect("texture");
    let [x, y] = state.pin.expect("pinned");
    barylab::probe::probe(&state.scene, &texture, &state.scene.settings(), (x, y)).expect("probe")
}

/// Both languages of step `n` quote `text`.
fn quotes(lesson: &Lesson, n: usize, text: &str) {
    let step = &lesson.steps[n - 1];
    for lang in Lang::ALL {
        assert!(
            step.text.get(lang).contains(text),
            "step {n} ({lang:?}) does not quote {text}"
        );
    }
}

#[test]
fn every_step_has_both_languages() {
    let lesson = open();
    assert!(
        (5..=8).contains(&lesson.steps.len()),
        "{}",
        lesson.steps.len()
    );
    for (i, step) in lesson.steps.iter().enumerate() {
        for lang in Lang::ALL {
            for t in [&step.title, &step.text, &step.try_this] {
                assert!(!t.get(lang).trim().is_empty(), "step {}", i + 1);
            }
        }
        assert!(
            step.text
                .zh
                .chars()
                .any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
            "step {}: the zh text has no Chinese",
            i + 1
        );
        assert!(step.summary.is_some(), "step {}: a summary", i + 1);
    }
}

#[test]
fn the_numbers_quoted_are_the_probes() {
    let lesson = open();
    // Step 1: one sample, the centre inside the green (front) triangle 0.
    let t1 = probe_step(&lesson, 1);
    assert!(t1.samples.is_empty());
    assert_eq!(t1.written_by, Some(0));
    // Step 2: the 2x2 grid; triangle 0 covers samples 0, 2, 3, sample 1 keeps triangle 1.
    let t2 = probe_step(&lesson, 2);
    let owners: Vec<Option<u32>> = t2.samples.iter().map(|s| s.triangle).collect();
    assert_eq!(owners, [Some(0), Some(1), Some(0), Some(0)]);
    assert_eq!(t2.samples[1].position, [83.75, 42.25]);
    quotes(&lesson, 2, "(83.75, 42.25)");
    // Step 3: the two colours (GAMES101's main.cpp: cols 217, 238, 185 and 185, 217, 238;
    // the front one is step 1's pixel) and their resolve.
    let [g, b] = [[217, 238, 185, 255], [185, 217, 238, 255]];
    assert_eq!(t1.color, g);
    for c in [g, b] {
        quotes(&lesson, 3, &format!("({}, {}, {})", c[0], c[1], c[2]));
    }
    let resolved = resolve(&[g, b, g, g]);
    assert_eq!(
        resolved, t2.color,
        "the resolve of the samples is the pixel"
    );
    quotes(
        &lesson,
        3,
        &format!("({}, {}, {})", resolved[0], resolved[1], resolved[2]),
    );
    // Step 4: the black-edge colour, sample 1 left at the black background.
    let black = [0, 0, 0, 255];
    let bug = resolve(&[g, black, g, g]);
    quotes(&lesson, 4, &format!("({}, {}, {})", bug[0], bug[1], bug[2]));
    // Step 5: MSAA with centroid; triangle 1 covers only sample 0, the centre is outside.
    let t5 = probe_step(&lesson, 5);
    let shading = t5.sample_shading.as_ref().expect("samples");
    let blue = shading
        .triangles
        .iter()
        .find(|t| t.triangle == 1)
        .expect("triangle 1 covers a sample");
    assert_eq!(blue.covered, [0]);
    assert!(!blue.centre_inside);
    assert_eq!(blue.centroid_sample, Some(0));
    // ... and the picture shows it: sample 0 is blue's, the other three the background's.
    let owners: Vec<_> = t5.samples.iter().map(|s| s.triangle).collect();
    assert_eq!(owners, [Some(1), None, None, None]);
    let [x, y] = blue.evaluated_at.expect("shaded once");
    quotes(&lesson, 5, &format!("({x}, {y})"));
    // Step 6: flat, the last vertex's colour everywhere.
    let t6 = probe_step(&lesson, 6);
    let c = t6.color;
    assert_eq!(c, [0, 0, 255, 255]);
    quotes(&lesson, 6, &format!("({}, {}, {})", c[0], c[1], c[2]));
}

#[test]
fn barylab_lesson_lists_prints_and_draws_it() {
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_barylab"))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .args(["lesson", "assets/lessons/samples.json"])
            .args(args)
            .output()
            .expect("run barylab")
    };
    let list = run(&["--list"]);
    assert!(list.status.success());
    let text = String::from_utf8_lossy(&list.stdout);
    assert!(text.contains(" 4. The black-edge bug"), "{text}");
    let step = run(&["--step", "4", "--lang", "zh"]);
    assert!(String::from_utf8_lossy(&step.stdout).contains("黑边"));
    let dir = tempfile_dir();
    let out = dir.join("step2.png");
    let fig = run(&["--step", "2", "--figure", out.to_str().expect("utf-8")]);
    assert!(
        fig.status.success(),
        "{}",
        String::from_utf8_lossy(&fig.stderr)
    );
    let png = std::fs::read(&out).expect("the figure is written");
    assert!(png.starts_with(b"\x89PNG"));
    std::fs::remove_dir_all(&dir).expect("clean up");
}

fn tempfile_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("barylab-lesson-samples-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    dir
}

/// The per-sample buffers of step `n`'s state (its scene at the step's size), with the bug
/// when the step's view has it.
fn step_samples(lesson: &Lesson, n: usize) -> barylab::raster::multisample::SampleBuffer {
    let state = lesson.state(n - 1).expect("state");
    let dir = state.scene_dir.clone().unwrap_or_default();
    let texture = state.scene.load_texture(&dir).expect("texture");
    barylab::figure::sample_buffers::samples_of(
        &state.scene,
        &texture,
        &state.scene.settings(),
        state.samples_view.black_edges,
    )
    .expect("samples")
}

#[test]
fn the_steps_select_the_views_their_texts_describe() {
    use barylab::figure::sample_buffers::{SampleBufferKind, image};
    let lesson = open();
    let [g, b] = [[217, 238, 185, 255], [185, 217, 238, 255]];
    // Step 2 shows sample 1's colour: blue at the pinned pixel, whose resolve is mostly green.
    let v2 = lesson.state(1).expect("state").samples_view;
    assert_eq!(
        (v2.kind, v2.index, v2.black_edges),
        (SampleBufferKind::Color, 1, false)
    );
    let s2 = step_samples(&lesson, 2);
    let at = |px: &[[u8; 4]], x: usize, y: usize| px[y * 120 + x];
    assert_eq!(at(&image(&s2, v2.kind, 1), 83, 42), b);
    assert_eq!(at(&image(&s2, v2.kind, 0), 83, 42), g);
    // Step 4 draws the bug: the pinned pixel resolves to the colour its text quotes.
    let v4 = lesson.state(3).expect("state").samples_view;
    assert!(v4.black_edges && v4.kind == SampleBufferKind::Resolve);
    let bug = at(&image(&step_samples(&lesson, 4), v4.kind, 0), 83, 42);
    assert_eq!(bug, resolve(&[g, [0, 0, 0, 255], g, g]));
    quotes(&lesson, 4, &format!("({}, {}, {})", bug[0], bug[1], bug[2]));
    // The other steps show the usual image.
    for n in [1, 3, 5, 6] {
        assert!(
            !lesson.state(n - 1).expect("state").samples_view.is_on(),
            "step {n}"
        );
    }
}

#[test]
fn it_is_a_builtin_lesson_that_opens_from_any_folder() {
    let builtin = barylab::lesson::builtin::lesson("samples").expect("registered");
    assert_eq!(
        builtin.text,
        std::fs::read_to_string(lesson_path()).expect("read")
    );
    let dir = std::env::temp_dir().join(format!(
        "barylab-lesson-samples-builtin-{}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let out = dir.join("step4.png");
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_barylab"))
            .current_dir(&dir)
            .args(["lesson", "samples"])
            .args(args)
            .output()
            .expect("run barylab")
    };
    for n in 1..=6 {
        let step = run(&["--step", &n.to_string()]);
        assert!(
            step.status.success(),
            "step {n}: {}",
            String::from_utf8_lossy(&step.stderr)
        );
    }
    let fig = run(&["--step", "4", "--figure", out.to_str().expect("utf-8")]);
    assert!(
        fig.status.success(),
        "{}",
        String::from_utf8_lossy(&fig.stderr)
    );
    std::fs::remove_dir_all(&dir).expect("clean up");
}
