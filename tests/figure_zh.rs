//! `barylab figure --lang zh`: Chinese labels drawn with a system CJK font, never boxes. Under
//! CI (CI=true) a missing CJK font fails; elsewhere the tests say so and pass.

use std::path::Path;

use barylab::figure::{Background, Compare, Figure, FigureOptions, png};
use barylab::i18n::{Lang, cjk_font};
use barylab::raster::Texture;
use barylab::scene::Scene;
use resvg::{tiny_skia, usvg};

/// Whether the CJK font is there; without it, fails under CI and skips elsewhere.
fn have_cjk_font() -> bool {
    if cjk_font().is_some() {
        return true;
    }
    assert!(
        std::env::var("CI").as_deref() != Ok("true"),
        "no CJK font found: CI needs fonts-noto-cjk"
    );
    eprintln!("no CJK font installed: Chinese label checks skipped");
    false
}

fn scene() -> (Scene, Texture) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/scenes");
    let mut scene = Scene::load(&dir.join("default.json")).expect("scene");
    scene.set_size(200, 150);
    let texture = scene.load_texture(&dir).expect("texture");
    (scene, texture)
}

/// `text` drawn at 32 px by the figures' PNG path (resvg, the overlay font first).
fn draw(text: &str, lang: Lang) -> Vec<u8> {
    let svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="240" height="48"><text x="4" y="36" font-size="32" font-family="{}">{text}</text></svg>"#,
        barylab::figure::svg::font_families(lang)
    );
    let tree = usvg::Tree::from_str(&svg, &png::svg_options_in(lang)).expect("SVG");
    let mut pixmap = tiny_skia::Pixmap::new(240, 48).expect("pixmap");
    resvg::render(
        &tree,
        tiny_skia::Transform::identity(),
        &mut pixmap.as_mut(),
    );
    pixmap.data().to_vec()
}

fn ink(pixels: &[u8]) -> usize {
    pixels.chunks(4).filter(|p| p[3] > 0).count()
}

/// Two different Chinese words of the same length draw differently and with ink: missing
/// glyphs would be the same boxes (or nothing) for both.
#[test]
fn chinese_labels_have_real_glyphs() {
    if !have_cjk_font() {
        return;
    }
    let (a, b) = (draw("仿射插值", Lang::Zh), draw("透视校正", Lang::Zh));
    assert!(
        ink(&a) > 200 && ink(&b) > 200,
        "no ink: {} {}",
        ink(&a),
        ink(&b)
    );
    assert_ne!(a, b, "two Chinese words drew the same pixels: boxes?");
    // The overlay font alone has no Chinese glyphs: the same words come out the same there
    // (boxes or nothing), which is what the check above rules out.
    assert_eq!(draw("仿射插值", Lang::En), draw("透视校正", Lang::En));
}

#[test]
fn a_chinese_figure_differs_from_the_english_one_only_in_its_labels() {
    if !have_cjk_font() {
        return;
    }
    let (scene, texture) = scene();
    let options = FigureOptions {
        compare: Compare::SideBySide,
        pinned: Some([100, 110]),
        background: Background::White,
        ..FigureOptions::default()
    };
    let en = Figure::compose(&scene, &texture, &options).expect("figure");
    let zh = Figure::compose_in(&scene, &texture, &options, Lang::Zh).expect("figure");
    assert_eq!((en.lang, zh.lang), (Lang::En, Lang::Zh));
    assert_eq!(en.size, zh.size);
    let (pe, pz) = (
        png::rasterize(&en).expect("png"),
        png::rasterize(&zh).expect("png"),
    );
    assert_ne!(pe, pz, "the Chinese figure looks like the English one");
    // The images themselves (below the title strip) are the same.
    let view = &zh.views[0];
    let y = view.origin[1] + 40;
    for x in view.origin[0] + 40..view.origin[0] + 60 {
        assert_eq!(pe.get_pixel(x, y), pz.get_pixel(x, y));
    }
    let svg = barylab::figure::svg::to_svg(&zh).expect("svg");
    assert!(svg.contains("透视校正插值") && svg.contains("仿射插值"));
    // Drawn as outlines: the CJK font's glyphs are in the file, no viewer needs the font.
    assert!(svg.contains(r#"<path id="g1-"#), "no CJK glyph outlines");
}

#[test]
fn the_cli_draws_chinese_labels() {
    if !have_cjk_font() {
        return;
    }
    let dir = tempfile::tempdir().expect("temp dir");
    let out_path = dir.path().join("zh.svg");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_barylab"))
        .args(["figure", "assets/scenes/default.json", "--size", "200x150"])
        .args(["--lang", "zh", "-o"])
        .arg(&out_path)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(&out_path).expect("svg");
    assert!(svg.contains("透视校正插值"), "{svg}");
}

/// The floor brackets of the lesson's texel formula, which egui's Ubuntu Light lacks, come from
/// the bundled symbols font in both of the figures' text paths: the labels' glyph outlines and
/// resvg's text (the PNG figures), in both languages.
#[test]
fn floor_brackets_have_real_glyphs_in_the_figures() {
    use barylab::figure::text::{GlyphFont, glyph_outline, glyphs};
    let g = glyphs("⌊u·W⌋", 20.0);
    assert_eq!(g.len(), 5);
    for k in [0, 4] {
        assert_eq!(g[k].font, GlyphFont::Symbols, "glyph {k}: {:?}", g[k]);
        assert_ne!(g[k].id, 0);
        assert!(!glyph_outline(g[k].font, g[k].id).is_empty());
    }
    assert_eq!(g[1].font, GlyphFont::Overlay);
    // The two brackets are different shapes, not the same box.
    assert_ne!(
        glyph_outline(g[0].font, g[0].id),
        glyph_outline(g[4].font, g[4].id)
    );
    for lang in [Lang::En, Lang::Zh] {
        let (a, b) = (draw("⌊⌊⌊⌊", lang), draw("⌋⌋⌋⌋", lang));
        assert!(ink(&a) > 100 && ink(&b) > 100, "no ink in {lang:?}");
        assert_ne!(a, b, "⌊ and ⌋ drew the same pixels in {lang:?}: boxes?");
    }
}
