//! `barylab grade` on a generated class: 300 submissions (correct images, every named bug,
//! broken files: not an image, truncated, the wrong size, a FIFO, a student folder with a
//! missing image) against the two test scenes. Every injected bug is named in the CSV and
//! the HTML report; broken files are rows with their reason; the outputs are never written
//! over an input. The time is printed (never asserted).

mod bugs_common;
mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use barylab::compare::bugs::Bug;
use barylab::compare::hypotheses::Candidates;
use barylab::compare::{Reference, render_for_comparison};
use bugs_common::{black_edges, save_png, scene_path};

const STUDENTS: usize = 300;

/// barylab's render of the scene file at `path` (colours) and its bug renders.
fn candidates(path: &Path) -> (Vec<[u8; 4]>, Candidates) {
    let scene = barylab::scene::Scene::load(path).expect("scene");
    let texture = scene
        .load_texture(path.parent().expect("folder"))
        .expect("texture");
    let settings = scene.settings();
    let mesh = scene.to_mesh();
    let render = render_for_comparison(&mesh, &texture, &settings).expect("render");
    let reference = Reference {
        scene: &scene,
        mesh: &mesh,
        texture: &texture,
        settings,
    };
    let c = Candidates::new(&reference, &render.frame).expect("candidates");
    (render.frame.color.clone(), c)
}

/// barylab's image of a test scene with `bug`, from the library's bug renders (`None`:
/// barylab's own image).
fn image_with(name: &str, bug: Option<Bug>) -> Vec<[u8; 4]> {
    if bug == Some(Bug::BlackEdges) {
        return black_edges(name).0;
    }
    let (ours, c) = candidates(&scene_path(name));
    match bug {
        None => ours,
        Some(b) => b
            .image(&c)
            .unwrap_or_else(|| panic!("{} has no image for {name}", b.code()))
            .color
            .clone(),
    }
}

/// A CSV line split into fields (quoted fields with doubled quotes).
fn fields(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut cur)),
            (c, _) => cur.push(c),
        }
    }
    out.push(cur);
    out
}

/// What each submission should give: (student, scene) -> (verdict, bug code or "").
type Expected = BTreeMap<(String, String), (&'static str, &'static str)>;

/// Writes the class into `dir`; returns what each submission should give.
fn write_class(dir: &Path) -> Expected {
    let single: Vec<Option<Bug>> = std::iter::once(None)
        .chain(
            Bug::ALL
                .into_iter()
                .filter(|b| *b != Bug::BlackEdges)
                .map(Some),
        )
        .collect();
    let images: Vec<(Option<Bug>, Vec<[u8; 4]>)> = single
        .iter()
        .map(|&b| (b, image_with("bugs.json", b)))
        .collect();
    let black = image_with("bugs-ssaa.json", Some(Bug::BlackEdges));
    let ssaa_right = image_with("bugs-ssaa.json", None);
    let mut expected = Expected::new();
    let mut add = |student: String, scene: &str, verdict, bug| {
        expected.insert((student, scene.to_string()), (verdict, bug));
    };
    for i in 0..STUDENTS {
        let student = format!("s{i:03}");
        match i % 20 {
            // Correct images and every bug on the single-sample scene.
            k @ 0..=12 => {
                let (bug, pixels) = &images[k % images.len()];
                save_png(pixels, 64, &dir.join(format!("{student}-bugs.png")));
                match bug {
                    Some(b) => add(student, "bugs", "fail", b.code()),
                    None => add(student, "bugs", "pass", ""),
                }
            }
            13 => {
                save_png(&black, 64, &dir.join(format!("{student}_bugs-ssaa.png")));
                add(student, "bugs-ssaa", "fail", "black_edges");
            }
            14 => {
                // One sample where the scene asks for supersampling.
                save_png(
                    &images[0].1,
                    64,
                    &dir.join(format!("{student}-bugs-ssaa.png")),
                );
                add(student, "bugs-ssaa", "fail", "anti_aliasing");
            }
            15 => {
                // A folder with both images, the second one y flipped.
                let folder = dir.join(&student);
                std::fs::create_dir(&folder).expect("folder");
                save_png(&images[0].1, 64, &folder.join("bugs.png"));
                let flipped: Vec<[u8; 4]> = (0..64 * 64)
                    .map(|k| ssaa_right[(63 - k / 64) * 64 + k % 64])
                    .collect();
                save_png(&flipped, 64, &folder.join("BUGS-SSAA.png"));
                add(student.clone(), "bugs", "pass", "");
                add(student, "bugs-ssaa", "fail", "y_flipped");
            }
            16 => {
                std::fs::write(dir.join(format!("{student}-bugs.png")), "not a picture")
                    .expect("write");
                add(student, "bugs", "bad", "");
            }
            17 => {
                let file = dir.join(format!("{student}-bugs.png"));
                save_png(&images[0].1, 64, &file);
                let bytes = std::fs::read(&file).expect("read");
                std::fs::write(&file, &bytes[..bytes.len() / 2]).expect("truncate");
                add(student, "bugs", "bad", "");
            }
            18 => {
                save_png(
                    &images[0].1[..32 * 32],
                    32,
                    &dir.join(format!("{student}-bugs.png")),
                );
                add(student, "bugs", "bad", "");
            }
            _ => {
                // A folder with no image for the second scene.
                let folder = dir.join(&student);
                std::fs::create_dir(&folder).expect("folder");
                save_png(&ssaa_right, 64, &folder.join("bugs-ssaa.png"));
                add(student.clone(), "bugs", "bad", "");
                add(student, "bugs-ssaa", "pass", "");
            }
        }
    }
    expected
}

fn barylab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(args)
        .output()
        .expect("run barylab")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

#[test]
fn a_class_of_300_submissions_is_graded_with_every_bug_named() {
    let dir = tempfile::tempdir().expect("tempdir");
    let subs = dir.path().join("homework");
    std::fs::create_dir(&subs).expect("folder");
    let mut expected = write_class(&subs);
    // A FIFO is a row with its reason, never a hang.
    #[cfg(unix)]
    {
        let fifo = subs.join("zz-fifo-bugs.png");
        let c = std::ffi::CString::new(s(&fifo)).expect("path");
        // SAFETY: mkfifo reads the NUL-terminated path only.
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0);
        expected.insert(("zz-fifo".into(), "bugs".into()), ("bad", ""));
    }
    // A name that must be escaped in the report.
    save_png(
        &image_with("bugs.json", None),
        64,
        &subs.join("<i>x&y\"-bugs.png"),
    );
    expected.insert(("<i>x&y\"".into(), "bugs".into()), ("pass", ""));
    let report = dir.path().join("report.html");
    let csv = dir.path().join("grades.csv");
    let (a, b) = (scene_path("bugs.json"), scene_path("bugs-ssaa.json"));
    let start = Instant::now();
    let out = barylab(&[
        "grade",
        s(&a),
        s(&b),
        "--submissions",
        s(&subs),
        "--report",
        s(&report),
        "--csv",
        s(&csv),
    ]);
    let took = start.elapsed();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    println!(
        "graded {} submissions in {took:.2?}: {stdout}",
        expected.len()
    );
    assert!(
        stdout.contains(&format!("{} submissions", expected.len())),
        "{stdout}"
    );

    let text = std::fs::read_to_string(&csv).expect("csv");
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("student,scene,verdict,bugs,pixels_differing,regions,file,problem")
    );
    let mut seen = BTreeMap::new();
    for line in lines {
        let f = fields(line);
        assert_eq!(f.len(), 8, "{line}");
        seen.insert((f[0].clone(), f[1].clone()), f);
    }
    assert_eq!(seen.len(), expected.len());
    let mut named = BTreeMap::<&str, usize>::new();
    for (key, (verdict, bug)) in &expected {
        let f = seen
            .get(key)
            .unwrap_or_else(|| panic!("no row for {key:?}"));
        assert_eq!(f[2], *verdict, "{key:?}: {f:?}");
        let codes: Vec<&str> = f[3].split(';').filter(|c| !c.is_empty()).collect();
        if bug.is_empty() {
            assert!(codes.is_empty(), "{key:?}: {f:?}");
        } else {
            assert_eq!(codes, vec![*bug], "{key:?}: {f:?}");
            *named.entry(bug).or_default() += 1;
        }
        match *verdict {
            "pass" => assert_eq!(f[4], "0", "{f:?}"),
            "fail" => assert!(f[4].parse::<usize>().expect("count") > 0, "{f:?}"),
            _ => assert!(!f[7].is_empty(), "a bad row names its problem: {f:?}"),
        }
    }
    for b in Bug::ALL {
        assert!(named.contains_key(b.code()), "{} never injected", b.code());
    }
    // The reasons of the broken files.
    let problem = |student: &str| seen[&(student.to_string(), "bugs".to_string())][7].clone();
    assert!(problem("s016").contains("not a PNG"), "{}", problem("s016"));
    assert!(problem("s018").contains("32x32"), "{}", problem("s018"));
    assert!(problem("s019").contains("no image"), "{}", problem("s019"));
    assert!(
        problem("zz-fifo").contains("FIFO"),
        "{}",
        problem("zz-fifo")
    );
    assert!(!problem("s017").is_empty());

    let html = std::fs::read_to_string(&report).expect("report");
    assert!(html.starts_with("<!DOCTYPE html>"));
    assert!(html.contains("<style>") && !html.contains("<link") && !html.contains("src=\"http"));
    assert!(html.contains("data:image/png;base64,"));
    for b in Bug::ALL {
        assert!(
            html.contains(&format!("<code>{}</code>", b.code())),
            "{}",
            b.code()
        );
        assert!(
            html.contains(&b.title(barylab::i18n::Lang::En)),
            "{}",
            b.code()
        );
    }
    let students = expected
        .keys()
        .map(|k| &k.0)
        .collect::<std::collections::BTreeSet<_>>();
    assert_eq!(html.matches("<section id=\"s").count(), students.len());
    assert!(html.contains("&lt;i&gt;x&amp;y&quot;") && !html.contains("<i>x&y"));
    // A few region lines with reasons in the students' sections.
    assert!(html.contains("region 1: "), "no regions in the report");

    // The report as a browser draws it: the page and the difference thumbnails (many colours).
    if let Some(browser) = common::browser::chromium() {
        let shot = dir.path().join("report.png");
        let url = format!("file://{}", s(&report));
        common::browser::screenshot(browser, &url, [1280, 900], &shot).expect("the browser");
        let img = image::open(&shot).expect("the screenshot").to_rgba8();
        assert_eq!(img.dimensions(), (1280, 900));
        let colours: std::collections::BTreeSet<[u8; 3]> =
            img.pixels().map(|p| [p[0], p[1], p[2]]).collect();
        assert!(colours.len() > 200, "only {} colours drawn", colours.len());
    }
}

#[test]
fn outputs_never_replace_an_input_and_the_report_is_chinese_with_lang_zh() {
    let dir = tempfile::tempdir().expect("tempdir");
    let subs = dir.path().join("homework");
    std::fs::create_dir(&subs).expect("folder");
    let right = image_with("bugs.json", None);
    let flipped: Vec<[u8; 4]> = (0..64 * 64)
        .map(|k| right[(63 - k / 64) * 64 + k % 64])
        .collect();
    save_png(&right, 64, &subs.join("alice.png"));
    save_png(&flipped, 64, &subs.join("bob.png"));
    let scene = scene_path("bugs.json");
    let alice = subs.join("alice.png");
    let before = std::fs::read(&alice).expect("read");
    // Over a submission: refused, the file unchanged.
    let out = barylab(&[
        "grade",
        s(&scene),
        "--submissions",
        s(&subs),
        "--report",
        s(&dir.path().join("r.html")),
        "--csv",
        s(&alice.with_extension("csv")),
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("submissions folder"), "{err}");
    assert_eq!(std::fs::read(&alice).expect("read"), before);
    // In Chinese.
    let report = dir.path().join("report.html");
    let out = barylab(&[
        "grade",
        s(&scene),
        "--submissions",
        s(&subs),
        "--report",
        s(&report),
        "--lang",
        "zh",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let html = std::fs::read_to_string(&report).expect("report");
    for w in [
        "全班报告",
        "通过",
        "不通过",
        "y 方向翻转",
        "改法",
        "区域 1：",
    ] {
        assert!(html.contains(w), "{w}");
    }
    assert!(html.contains("lang=\"zh-CN\""));
}

/// `cargo test --release --test grade -- --ignored --nocapture`: 300 submissions of
/// GAMES101 A2 at 700x700 (a third correct, a third y flipped, a third with the depth test
/// reversed), timed.
#[test]
#[ignore]
fn three_hundred_at_700x700_timed() {
    let dir = tempfile::tempdir().expect("tempdir");
    let subs = dir.path().join("homework");
    std::fs::create_dir(&subs).expect("folder");
    let scene: PathBuf = [env!("CARGO_MANIFEST_DIR"), "assets/scenes/games101-a2.json"]
        .iter()
        .collect();
    let path = scene.to_str().expect("utf-8");
    let (ours, c) = candidates(&scene);
    let images = [
        ours,
        Bug::YFlipped.image(&c).expect("flipped").color.clone(),
        Bug::DepthTest.image(&c).expect("depth").color.clone(),
    ];
    for i in 0..STUDENTS {
        save_png(&images[i % 3], 700, &subs.join(format!("s{i:03}.png")));
    }
    let start = Instant::now();
    let out = barylab(&[
        "grade",
        path,
        "--submissions",
        s(&subs),
        "--report",
        s(&dir.path().join("r.html")),
        "--csv",
        s(&dir.path().join("g.csv")),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    println!(
        "300 submissions of 700x700 in {:.2?}: {}",
        start.elapsed(),
        String::from_utf8_lossy(&out.stdout)
    );
}
