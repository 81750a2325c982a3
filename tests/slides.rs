//! `barylab lesson --slides`: the built-in lesson as one self-contained HTML deck in both
//! languages (a slide per step, the figures inline and equal to `--step N --figure`'s, no
//! network, the keys a clicker sends), the Beamer PDF where pandoc and LaTeX's beamer class
//! are installed (else its message), and a screenshot of a slide in headless Chromium where
//! one is installed.

mod common;

use std::path::Path;
use std::process::{Command, Output};

use barylab::lesson::Lesson;
use base64::Engine;

fn barylab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .expect("run barylab")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

/// The `src` of every `<img>`, in order.
fn image_sources(html: &str) -> Vec<&str> {
    html.split("<img ")
        .skip(1)
        .filter_map(|tag| {
            let start = tag.find("src=\"")? + 5;
            let end = tag[start..].find('"')? + start;
            Some(&tag[start..end])
        })
        .collect()
}

/// Writes the built-in deck in `lang`; its HTML.
fn deck(dir: &Path, lang: &str) -> String {
    let out = dir.join(format!("deck-{lang}.html"));
    let run = barylab(&["lesson", "builtin", "--slides", s(&out), "--lang", lang]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    std::fs::read_to_string(&out).expect("the deck")
}

#[test]
fn the_builtin_lesson_is_one_offline_html_deck_in_both_languages() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let steps = lesson.steps.len();
    let dir = tempfile::tempdir().expect("tempdir");
    for (lang, try_this, code) in [("en", "Try this:", "en"), ("zh", "试一试：", "zh-CN")] {
        let html = deck(dir.path(), lang);
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(html.contains(&format!("<html lang=\"{code}\">")));
        // A title slide and one slide per step, each with its "try this".
        assert_eq!(html.matches("<section class=\"slide").count(), steps + 1);
        assert_eq!(html.matches(try_this).count(), steps, "{lang}");
        for (i, step) in lesson.steps.iter().enumerate() {
            let title = barylab::lesson::text::plain(step.title.get(if lang == "en" {
                barylab::i18n::Lang::En
            } else {
                barylab::i18n::Lang::Zh
            }));
            let escaped = barylab::figure::svg::escape(&title);
            assert!(
                html.contains(&format!("{}. {escaped}</h2>", i + 1)),
                "{title}"
            );
        }
        // Nothing from the network: no URL, no external style or script.
        assert!(!html.contains("http://") && !html.contains("https://"));
        assert!(!html.contains("<link") && !html.contains("<script src"));
        let sources = image_sources(&html);
        assert!(sources.len() >= steps, "a figure per step");
        assert!(sources.iter().all(|src| {
            src.starts_with("data:image/png;base64,") || src.starts_with("data:image/gif;base64,")
        }));
        // The keys a keyboard and a presentation clicker send.
        for key in [
            "'ArrowRight'",
            "'ArrowLeft'",
            "'PageDown'",
            "'PageUp'",
            "' '",
        ] {
            assert!(html.contains(key), "{key}");
        }
    }
}

#[test]
fn a_slide_shows_the_same_figure_as_the_step_figure_command() {
    let dir = tempfile::tempdir().expect("tempdir");
    let html = deck(dir.path(), "en");
    // Step 2's slide and its first image.
    let slide = html
        .split("<section class=\"slide\" id=\"step-2\">")
        .nth(1)
        .expect("step 2's slide");
    let src = image_sources(slide)[0];
    let png = base64::engine::general_purpose::STANDARD
        .decode(&src["data:image/png;base64,".len()..])
        .expect("base64");
    let inline = image::load_from_memory(&png).expect("a PNG").to_rgba8();
    let fig = dir.path().join("step2.png");
    let run = barylab(&["lesson", "builtin", "--step", "2", "--figure", s(&fig)]);
    assert!(run.status.success());
    let still = image::open(&fig).expect("figure").to_rgba8();
    assert!(inline == still, "the slide's figure is the step's figure");
}

/// The frames of an inline GIF or (A)PNG image.
fn inline_frames(src: &str) -> Vec<image::RgbaImage> {
    use image::AnimationDecoder;
    let (kind, data) = src
        .strip_prefix("data:image/")
        .and_then(|s| s.split_once(";base64,"))
        .expect("a base64 data: URI");
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(data)
        .expect("base64");
    let cursor = std::io::Cursor::new(bytes);
    let frames = match kind {
        "gif" => image::codecs::gif::GifDecoder::new(cursor)
            .expect("a GIF")
            .into_frames()
            .collect_frames(),
        _ => {
            let png = image::codecs::png::PngDecoder::new(cursor).expect("a PNG");
            if !png.is_apng().expect("PNG header") {
                return vec![
                    image::DynamicImage::from_decoder(png)
                        .expect("PNG")
                        .to_rgba8(),
                ];
            }
            png.apng().expect("APNG").into_frames().collect_frames()
        }
    }
    .expect("the frames decode");
    frames.into_iter().map(|f| f.into_buffer()).collect()
}

#[test]
fn steps_with_an_animation_show_it_on_their_slide() {
    let lesson = Lesson::builtin().expect("built-in lesson");
    let animated: Vec<(usize, u32)> = lesson
        .steps
        .iter()
        .enumerate()
        .filter_map(|(i, s)| s.animation.map(|a| (i + 1, a.frames)))
        .collect();
    assert!(
        animated.len() >= 3,
        "the built-in lesson animates a few steps"
    );
    let dir = tempfile::tempdir().expect("tempdir");
    let html = deck(dir.path(), "en");
    println!("the deck: {} bytes", html.len());
    for n in 1..=lesson.steps.len() {
        let slide = html
            .split(&format!("<section class=\"slide\" id=\"step-{n}\">"))
            .nth(1)
            .and_then(|s| s.split("</section>").next())
            .expect("the step's slide");
        let frames = inline_frames(image_sources(slide)[0]);
        match animated.iter().find(|(k, _)| *k == n) {
            Some(&(_, count)) => {
                assert_eq!(frames.len(), count as usize, "step {n}'s frames");
                let size = frames[0].dimensions();
                assert!(frames.iter().all(|f| f.dimensions() == size), "step {n}");
                assert!(
                    frames.windows(2).all(|p| p[0] != p[1]),
                    "step {n}: every frame changes"
                );
            }
            None => assert_eq!(frames.len(), 1, "step {n} is a still"),
        }
    }
}

#[test]
fn a_bad_animation_field_names_the_file_and_the_step() {
    let text = |animation: &str| {
        format!(
            r#"{{"title": {{"en": "t", "zh": "t"}}, "steps": [{{
              "title": {{"en": "a", "zh": "a"}}, "text": {{"en": "b", "zh": "b"}},
              "try": {{"en": "c", "zh": "c"}}, "scene": "builtin:default",
              "animation": {animation} }}]}}"#
        )
    };
    let dir = Path::new(".");
    let ok =
        barylab::lesson::parse_str(&text(r#"{"sweep": "clip", "vertex": "b"}"#), "ok.json", dir)
            .expect("a good animation");
    let a = ok.steps[0].animation.expect("parsed");
    assert_eq!(
        (a.sweep, a.frames, a.vertex),
        (barylab::animate::Sweep::Clip, 10, 1)
    );
    for (field, expected) in [
        (r#"{"sweep": "spin"}"#, "`spin` is not a sweep"),
        (r#"{"sweep": "depth", "frames": 500}"#, "`frames` 500"),
        (
            r#"{"sweep": "depth", "vertex": "Q7"}"#,
            "`Q7` is not a corner",
        ),
        (r#"{"sweep": "depth", "format": "mp4"}"#, "gif or apng"),
        (r#"{"sweep": "depth", "fps": 3}"#, "unknown field `fps`"),
    ] {
        let err =
            barylab::lesson::parse_str(&text(field), "bad.json", dir).expect_err("a bad animation");
        let m = err.to_string();
        assert!(
            m.contains("bad.json") && m.contains("steps[0].animation") && m.contains(expected),
            "{m}"
        );
    }
}

#[test]
fn bad_slide_outputs_and_the_pdf_deck() {
    let dir = tempfile::tempdir().expect("tempdir");
    let txt = dir.path().join("deck.txt");
    let run = barylab(&["lesson", "builtin", "--slides", s(&txt)]);
    assert!(!run.status.success());
    let msg = String::from_utf8_lossy(&run.stderr);
    assert!(msg.contains("deck.txt") && msg.contains(".html"), "{msg}");
    // The PDF: made where pandoc, pdflatex and beamer are installed; else a message naming
    // what is missing, and no file.
    let pdf = dir.path().join("deck.pdf");
    let run = barylab(&["lesson", "builtin", "--slides", s(&pdf)]);
    let beamer = Command::new("kpsewhich")
        .arg("beamer.cls")
        .output()
        .is_ok_and(|o| o.status.success() && !o.stdout.is_empty());
    let pandoc = Command::new("pandoc").arg("--version").output().is_ok();
    if beamer && pandoc {
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let bytes = std::fs::read(&pdf).expect("the PDF");
        assert!(bytes.starts_with(b"%PDF"));
    } else {
        assert!(!run.status.success());
        let msg = String::from_utf8_lossy(&run.stderr);
        assert!(msg.contains("deck.pdf"), "{msg}");
        assert!(msg.contains("pandoc") || msg.contains("beamer"), "{msg}");
        assert!(!pdf.exists());
        println!("SKIPPED the Beamer PDF: pandoc or LaTeX's beamer class is not installed");
    }
}

#[test]
fn headless_chromium_shows_a_slide_where_installed() {
    let Some(browser) = common::browser::chromium() else {
        return;
    };
    let dir = tempfile::tempdir().expect("tempdir");
    deck(dir.path(), "en");
    let shot = dir.path().join("slide.png");
    let url = format!("file://{}#3", s(&dir.path().join("deck-en.html")));
    common::browser::screenshot(browser, &url, [1280, 720], &shot).expect("run the browser");
    let img = image::open(&shot).expect("the screenshot").to_rgba8();
    assert_eq!(img.dimensions(), (1280, 720));
    // The slide's dark background and its white figure are both on the screen.
    assert!(img.pixels().any(|p| p[0] > 240 && p[1] > 240 && p[2] > 240));
    assert!(img.pixels().any(|p| p[0] < 40 && p[1] < 40 && p[2] < 50));
}
