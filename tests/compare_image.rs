//! File > Compare with image… in the app, driven through egui_kittest: barylab's own render
//! agrees; a few changed pixels and an affine render are found, with reasons; a wrong size
//! says so and offers the image's size; clicking a mismatched pixel pins it with its reason.
//! The comparison runs in a background thread: the frame that starts it returns at once, the
//! last result stays shown meanwhile, and a later frame shows the new one ([`settle`]).

mod common;

use std::path::{Path, PathBuf};

use barylab::app::command::AppCommand;
use barylab::app::command::FileCommand;
use barylab::app::document::state::StateCommand as AppCmd;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::Compare;
use barylab::i18n::Lang;
use barylab::raster::Interpolation;
use barylab::raster::render::Rasterizer;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec2;

const SIZE: egui::Vec2 = egui::vec2(1280.0, 800.0);
const IMAGE: [u32; 2] = [160, 120];

fn harness() -> Harness<'static, BaryApp> {
    let mut h = common::app::harness(SIZE, AppOptions::default());
    h.state_mut().push(AppCmd::SetImageSize(Some(IMAGE)));
    h.run();
    h
}

/// The canvas's current render, as the app shows it.
fn canvas_colors(h: &Harness<'_, BaryApp>) -> Vec<[u8; 4]> {
    let out = h.state().canvas().output.as_ref().expect("rendered");
    assert_eq!(out.size, IMAGE);
    let mode = h.state().state().options().mode;
    out.render(mode).expect("a render").frame.color.clone()
}

fn write_png(path: &Path, size: [u32; 2], pixels: &[[u8; 4]]) {
    let img = image::RgbaImage::from_fn(size[0], size[1], |x, y| {
        image::Rgba(pixels[(y * size[0] + x) as usize])
    });
    img.save(path).expect("png written");
}

fn compare(h: &mut Harness<'_, BaryApp>, path: PathBuf) {
    h.state_mut().push(FileCommand::CompareImage(path));
    settle(h);
}

/// Whether a comparison is going on in the background.
fn comparing(h: &Harness<'_, BaryApp>) -> bool {
    h.state()
        .compare_image()
        .is_some_and(|ic| ic.is_comparing())
}

/// Runs frames until the background comparison's result is shown (a bounded number of
/// frames, a short sleep between them).
fn settle(h: &mut Harness<'_, BaryApp>) {
    const FRAMES: usize = 3000;
    for _ in 0..FRAMES {
        h.run();
        if !comparing(h) {
            // Once more: the strip shows what the last frame took.
            h.run();
            return;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    panic!("no comparison result after {FRAMES} frames");
}

fn summary(h: &Harness<'_, BaryApp>) -> String {
    let ic = h.state().compare_image().expect("comparing");
    let c = ic.comparison.as_ref().expect("compared");
    barylab::app::panels::compare_image::summary(c, barylab::i18n::Lang::En)
}

#[test]
fn barylabs_own_render_agrees_and_a_changed_one_differs() {
    let mut h = harness();
    let dir = tempfile::tempdir().expect("tempdir");
    let ours = canvas_colors(&h);
    let same = dir.path().join("same.png");
    write_png(&same, IMAGE, &ours);
    compare(&mut h, same);
    assert!(h.state().compare_image().is_some());
    let s = summary(&h);
    assert!(s.starts_with("No difference"), "{s}");
    h.get_by_label(&s);
    // The canvas shows the comparison in every mode; the strip's Close leaves it.
    for label in ["Side by side", "Wipe", "Difference", "Single"] {
        h.get_by_label(label).click();
        h.run();
        assert!(h.state().canvas().error.is_none(), "{label}");
    }

    // A few pixels changed: found, with the largest difference.
    let mut changed = ours.clone();
    let covered: Vec<usize> = (0..ours.len()).filter(|&k| ours[k] != ours[0]).collect();
    assert!(covered.len() > 100);
    for k in [
        covered[10],
        covered[covered.len() / 2],
        covered[covered.len() - 10],
    ] {
        changed[k] = [changed[k][0] ^ 0x40, changed[k][1], changed[k][2], 255];
    }
    let path = dir.path().join("changed.png");
    write_png(&path, IMAGE, &changed);
    compare(&mut h, path);
    let c = h
        .state()
        .compare_image()
        .and_then(|ic| ic.comparison.clone())
        .expect("compared");
    assert!(!c.agrees());
    assert!(
        c.differing() >= 1 && c.differing() <= 3,
        "{}",
        c.differing()
    );
    let s = summary(&h);
    assert!(s.contains("largest colour difference 64 levels"), "{s}");

    // "First mismatch" pins the first changed pixel, with its reason in the strip.
    h.get_by_label("First mismatch").click();
    h.run();
    h.run();
    let first = c.first[0].pixel;
    assert_eq!(h.state().state().view.pinned, Some(first));
    let pinned = format!("Pinned ({}, {}):", first[0], first[1]);
    assert!(h.query_by_label_contains(&pinned).is_some(), "{pinned}");

    h.get_by_label("Close comparison").click();
    h.run();
    assert!(h.state().compare_image().is_none());
}

/// Screen position (points) of the centre of rendered pixel `p` in view 0.
fn pixel_centre(h: &Harness<'_, BaryApp>, p: [u32; 2]) -> egui::Pos2 {
    let view = h.state().canvas().views[0];
    view.transform
        .to_screen(DVec2::new(f64::from(p[0]) + 0.5, f64::from(p[1]) + 0.5))
}

/// The app's affine render saved as a PNG (as a student's affine rasterizer would draw it),
/// with the app back in perspective-correct mode: the folder (it lives as long as this value),
/// the file and its pixels.
fn affine_image(h: &mut Harness<'_, BaryApp>) -> (tempfile::TempDir, PathBuf, Vec<[u8; 4]>) {
    h.state_mut().push(AppCmd::SetMode(Interpolation::Affine));
    h.run();
    let affine = canvas_colors(h);
    h.state_mut()
        .push(AppCmd::SetMode(Interpolation::Perspective));
    h.run();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("affine.png");
    write_png(&path, IMAGE, &affine);
    (dir, path, affine)
}

#[test]
fn an_affine_render_is_explained_and_clicking_a_mismatch_pins_it() {
    let mut h = harness();
    let (_dir, path, affine) = affine_image(&mut h);
    compare(&mut h, path);
    let c = h
        .state()
        .compare_image()
        .and_then(|ic| ic.comparison.clone())
        .expect("compared");
    assert!(c.color_differing > 0);
    let looks = c.looks_like.expect("a verdict").text(Lang::En);
    assert!(looks.contains("affine"), "{looks}");
    assert!(
        h.query_by_label_contains("looks like affine").is_some(),
        "the verdict is in the strip"
    );

    // Click a mismatched pixel in the canvas: it is pinned, with its reason.
    // The differing pixel nearest the image's centre (away from the vertex handles).
    let ours = canvas_colors(&h);
    let w = IMAGE[0] as usize;
    let k = (0..ours.len())
        .filter(|&k| (0..3).any(|i| ours[k][i].abs_diff(affine[k][i]) > 2))
        .min_by_key(|&k| {
            (k % w).abs_diff(w / 2).pow(2) + (k / w).abs_diff(IMAGE[1] as usize / 2).pow(2)
        })
        .expect("a colour difference");
    let p = [(k % w) as u32, (k / w) as u32];
    h.run();
    let pos = pixel_centre(&h, p);
    assert!(h.state().canvas().views[0].rect.contains(pos), "{pos:?}");
    h.hover_at(pos);
    h.run();
    assert_eq!(h.state().canvas().hover, Some(p), "hovered");
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
    }
    h.run();
    assert_eq!(h.state().state().view.pinned, Some(p));
    let reason = h
        .state()
        .compare_image()
        .and_then(|ic| ic.pin_reason.clone())
        .and_then(|(_, r)| r)
        .expect("a reason for the pinned pixel")
        .expect("the probe found it");
    let en = reason.text(Lang::En);
    assert!(en.contains("affine"), "{en}");

    // In Chinese, the verdict and the pinned pixel's reason are Chinese, with no English
    // catalogue text left in them.
    let zh = reason.text(Lang::Zh);
    assert!(zh.contains("仿射插值") && zh.contains("纹素"), "{zh}");
    for english in ["affine", "texels", "looks like", "perspective-correct"] {
        assert!(!zh.contains(english), "{zh}");
    }
    let looks_zh = c.looks_like.expect("a verdict").text(Lang::Zh);
    assert!(looks_zh.contains("看起来像仿射插值"), "{looks_zh}");
    assert!(!looks_zh.contains("looks like"), "{looks_zh}");
    if barylab::i18n::cjk_font().is_none() {
        // Without a Chinese font the app stays English (tests/app_lang.rs).
        return;
    }
    h.state_mut().push(AppCommand::SetLang(Lang::Zh));
    h.run();
    assert_eq!(h.state().lang(), Lang::Zh);
    assert!(
        h.query_by_label(&looks_zh).is_some(),
        "the Chinese verdict is in the strip"
    );
    assert!(
        h.query_by_label_contains(&format!("已钉住 ({}, {})：{zh}", p[0], p[1]))
            .is_some(),
        "the Chinese reason is in the strip"
    );
    assert!(h.query_by_label_contains("looks like affine").is_none());
}

#[test]
fn a_wrong_size_says_so_and_offers_the_images_size() {
    let mut h = harness();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("small.png");
    write_png(&path, [32, 24], &vec![[0, 0, 0, 255]; 32 * 24]);
    compare(&mut h, path);
    let ic = h.state().compare_image().expect("loaded");
    assert_eq!(ic.size_mismatch, Some(IMAGE));
    assert!(ic.comparison.is_none());
    h.get_by_label_contains("small.png is 32×24, but the canvas image is 160×120");
    h.get_by_label("Set the image size to 32×24").click();
    settle(&mut h);
    assert_eq!(h.state().state().scene.size(), (32, 24));
    let ic = h.state().compare_image().expect("still comparing");
    assert_eq!(ic.size_mismatch, None);
    assert!(ic.comparison.is_some());

    // Not an image, and a folder: a message naming the file, no panic.
    let bad = dir.path().join("notes.png");
    std::fs::write(&bad, b"not a png").expect("written");
    compare(&mut h, bad);
    let m = h.state().message().expect("a message").to_string();
    assert!(m.contains("notes.png"), "{m}");
    compare(&mut h, dir.path().to_path_buf());
    let m = h.state().message().expect("a message").to_string();
    assert!(m.contains("not a regular file"), "{m}");
}

#[test]
fn a_chosen_background_colour_decides_coverage() {
    let mut h = harness();
    let dir = tempfile::tempdir().expect("tempdir");
    // An opaque image on a white background, where barylab's background is dark: against
    // the scene's background everything is covered; against white, the coverage is read.
    let ours = canvas_colors(&h);
    let bg = ours[0];
    let white: Vec<[u8; 4]> = ours
        .iter()
        .map(|&p| if p == bg { [255, 255, 255, 255] } else { p })
        .collect();
    let path = dir.path().join("white.png");
    write_png(&path, IMAGE, &white);
    compare(&mut h, path);
    let c = h
        .state()
        .compare_image()
        .and_then(|ic| ic.comparison.clone())
        .expect("compared");
    assert!(c.only_theirs > 0, "{}", summary(&h));
    h.state_mut()
        .push(FileCommand::SetCompareBackground([255, 255, 255]));
    settle(&mut h);
    let s = summary(&h);
    assert!(s.starts_with("No difference"), "{s}");
}

/// The comparison is made again only when what is compared changes: another compare view
/// renders the canvas anew but compares nothing; another mode compares again. At 1920x1080,
/// where one comparison takes a noticeable time (printed).
#[test]
fn a_new_render_of_the_same_scene_does_not_compare_again() {
    const BIG: [u32; 2] = [1920, 1080];
    let mut h = harness();
    h.state_mut().push(AppCmd::SetImageSize(Some(BIG)));
    h.state_mut().push(AppCmd::SetMode(Interpolation::Affine));
    h.run();
    let colors = |h: &Harness<'_, BaryApp>| {
        let out = h.state().canvas().output.as_ref().expect("rendered");
        assert_eq!(out.size, BIG);
        let mode = h.state().state().options().mode;
        out.render(mode).expect("a render").frame.color.clone()
    };
    let affine = colors(&h);
    h.state_mut()
        .push(AppCmd::SetMode(Interpolation::Perspective));
    h.run();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("affine-1080p.png");
    write_png(&path, BIG, &affine);
    let start = std::time::Instant::now();
    compare(&mut h, path);
    let first = start.elapsed();
    let ic = h.state().compare_image().expect("comparing");
    assert!(ic.comparison.as_ref().is_some_and(|c| !c.agrees()));
    let made = ic.comparisons();
    let generation = |h: &Harness<'_, BaryApp>| {
        h.state()
            .canvas()
            .output
            .as_ref()
            .map(|o| o.generation)
            .expect("rendered")
    };
    let settled = |h: &Harness<'_, BaryApp>| {
        let ic = h.state().compare_image().expect("comparing");
        ic.settled(
            h.state().canvas().output.as_ref(),
            Interpolation::Perspective,
        )
    };
    // Another rasterizer renders anew (the same pixels): nothing is compared again.
    for r in [Rasterizer::Scanline, Rasterizer::EdgeFunction] {
        let before = generation(&h);
        let start = std::time::Instant::now();
        h.state_mut().push(AppCmd::SetRasterizer(r));
        h.run();
        eprintln!("{r:?} at 1920x1080: {:?}", start.elapsed());
        assert_ne!(generation(&h), before, "{r:?} renders anew");
        let ic = h.state().compare_image().expect("comparing");
        assert_eq!(ic.comparisons(), made, "{r:?} compares nothing again");
        assert!(settled(&h));
    }
    for view in [Compare::SideBySide, Compare::Difference, Compare::Single] {
        h.state_mut().push(AppCmd::SetCompare(view));
        h.run();
        let ic = h.state().compare_image().expect("comparing");
        assert_eq!(ic.comparisons(), made, "{view:?} compares nothing again");
        assert!(settled(&h));
    }
    // A change while a button is held (a drag) is compared when it is released.
    let corner = egui::pos2(SIZE.x - 4.0, SIZE.y - 4.0);
    let button = |h: &mut Harness<'_, BaryApp>, pressed| {
        h.event(egui::Event::PointerButton {
            pos: corner,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
    };
    h.hover_at(corner);
    button(&mut h, true);
    h.state_mut()
        .push(AppCmd::SetTieRule(barylab::raster::setup::TieRule::TopLeft));
    h.run();
    let ic = h.state().compare_image().expect("comparing");
    assert!(
        ic.deferred && ic.comparison.is_none(),
        "not compared during the drag"
    );
    assert_eq!(ic.comparisons(), made);
    button(&mut h, false);
    settle(&mut h);
    let ic = h.state().compare_image().expect("comparing");
    assert!(
        !ic.deferred && ic.comparison.is_some(),
        "compared after the drag"
    );
    assert_eq!(ic.comparisons(), made + 1);
    let made = made + 1;
    h.state_mut().push(AppCmd::SetMode(Interpolation::Affine));
    settle(&mut h);
    let ic = h.state().compare_image().expect("comparing");
    assert_eq!(ic.comparisons(), made + 1, "another mode compares again");
    assert!(ic.comparison.as_ref().is_some_and(|c| c.agrees()));
    eprintln!("first comparison at 1920x1080 (with its frames): {first:?}");
}

/// The comparison runs in the background: the frame that starts it returns without its
/// result ("Comparing…" in the strip), a later frame shows it. While a new comparison runs
/// the last result stays shown and a mismatch pinned on it gets its reason; a comparison
/// overtaken by another (the mode changed again) is dropped.
#[test]
fn the_comparison_runs_in_the_background_and_the_last_result_stays_shown() {
    let mut h = harness();
    let (_dir, path, _) = affine_image(&mut h);

    // Frame 1 opens the image; frame 2 starts the comparison and returns without it.
    h.state_mut().push(FileCommand::CompareImage(path));
    h.step();
    h.step();
    let ic = h.state().compare_image().expect("opened");
    assert!(ic.is_comparing(), "started in the background");
    assert!(ic.comparison.is_none() && ic.view.result.is_none());
    assert_eq!(ic.comparisons(), 1);
    let out = h.state().canvas().output.as_ref();
    assert!(!ic.settled(out, Interpolation::Perspective));
    h.step();
    assert!(
        h.query_by_label_contains("Comparing…").is_some(),
        "the strip says a comparison is going on"
    );
    settle(&mut h);
    let ic = h.state().compare_image().expect("opened");
    assert!(!ic.is_comparing(), "done");
    let out = h.state().canvas().output.as_ref();
    assert!(ic.settled(out, Interpolation::Perspective));
    let c = ic.comparison.clone().expect("the result is shown");
    assert!(ic.view.result.is_some());
    assert!(c.color_differing > 0, "{}", summary(&h));
    assert!(h.query_by_label_contains("Comparing…").is_none());
    h.get_by_label(&summary(&h));

    // Another mode: the frame that starts the new comparison still shows the last result,
    // and a mismatch pinned in it is explained from it.
    let p = c.first[0].pixel;
    h.state_mut().push(AppCmd::SetMode(Interpolation::Affine));
    h.state_mut().push(AppCmd::Pin(Some(p)));
    h.step();
    h.step();
    let ic = h.state().compare_image().expect("opened");
    assert!(ic.is_comparing(), "the new comparison is going on");
    assert_eq!(ic.comparisons(), 2);
    assert!(
        ic.comparison.as_ref().is_some_and(|c| !c.agrees()) && ic.view.result.is_some(),
        "the last result stays shown"
    );
    let reason = ic
        .pin_reason
        .clone()
        .filter(|(at, _)| *at == p)
        .and_then(|(_, r)| r)
        .expect("the pinned mismatch has a reason")
        .expect("the probe found it");
    assert!(reason.text(Lang::En).contains("affine"), "{reason:?}");
    settle(&mut h);
    let ic = h.state().compare_image().expect("opened");
    assert!(!ic.is_comparing());
    assert!(ic.comparison.as_ref().is_some_and(|c| c.agrees()));
    assert_eq!(
        ic.pin_reason.clone().map(|(at, r)| (at, r.is_none())),
        Some((p, true))
    );

    // Two changes in a row: the first comparison is dropped, the shown one is the last's.
    h.state_mut()
        .push(AppCmd::SetMode(Interpolation::Perspective));
    h.step();
    h.step();
    h.state_mut().push(AppCmd::SetMode(Interpolation::Affine));
    h.step();
    h.step();
    assert_eq!(h.state().compare_image().expect("opened").comparisons(), 4);
    settle(&mut h);
    let ic = h.state().compare_image().expect("opened");
    let out = h.state().canvas().output.as_ref();
    assert!(ic.settled(out, Interpolation::Affine));
    assert!(
        ic.comparison.as_ref().is_some_and(|c| c.agrees()),
        "the affine comparison is shown, not the overtaken perspective one"
    );
}
