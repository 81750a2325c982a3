//! The figures' labels: drawn as glyph outlines whose boxes are as wide as the font says
//! (measured here independently, with ttf-parser on the font file), whose glyphs stay inside
//! their boxes when resvg draws them, and the wipe line's two labels, which never overlap
//! and never leave their view, in figures and on the app's canvas.

mod common;

use std::path::Path;

use barylab::app::AppOptions;
use barylab::app::document::state::StateCommand as AppCommand;
use barylab::figure::text::{LABEL_INSET, LABEL_PAD, pair_fit, place_pair};
use barylab::figure::{Background, Compare, Figure, FigureOptions, svg};
use barylab::raster::Texture;
use barylab::scene::Scene;
use proptest::prelude::*;
use resvg::{tiny_skia, usvg};

fn scene(size: [u32; 2]) -> (Scene, Texture) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut scene = Scene::load(&root.join("assets/scenes/default.json")).expect("scene");
    scene.set_size(size[0], size[1]);
    let texture = scene
        .load_texture(&root.join("assets/scenes"))
        .expect("texture");
    (scene, texture)
}

/// One label of an SVG figure, read back from the document.
#[derive(Debug)]
struct Label {
    text: String,
    size: f32,
    /// x, y, width, height in points.
    r#box: [f32; 4],
    has_box: bool,
    /// The `<g fill=...>` with the glyphs' `<use>` elements.
    glyphs: String,
}

fn attr<'a>(element: &'a str, name: &str) -> &'a str {
    let key = format!(r#" {name}=""#);
    let start = element.find(&key).expect(name) + key.len();
    let rest = &element[start..];
    &rest[..rest.find('"').expect("closing quote")]
}

fn unescape(t: &str) -> String {
    t.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

fn labels(doc: &str) -> Vec<Label> {
    doc.split(r#"<g class="label""#)
        .skip(1)
        .map(|part| {
            let head = &part[..part.find('>').expect("tag end")];
            let element = format!(" {head}");
            let b: Vec<f32> = attr(&element, "data-box")
                .split(' ')
                .map(|v| v.parse().expect("number"))
                .collect();
            let body = &part[..part.find("</g>\n</g>").map_or(0, |e| e + 4)];
            let glyphs = body.find("<g fill").map_or(String::new(), |s| {
                let end = body[s..].find("</g>").expect("glyph group end") + s + 4;
                body[s..end].to_string()
            });
            Label {
                text: unescape(attr(&element, "aria-label")),
                size: attr(&element, "font-size").parse().expect("size"),
                r#box: [b[0], b[1], b[2], b[3]],
                has_box: body.contains("<rect"),
                glyphs,
            }
        })
        .collect()
}

/// The advance width of `text` at `size` points in the overlay font, measured with
/// ttf-parser: horizontal advances plus the kerning table's pairs, over the units per em.
fn advance(text: &str, size: f32) -> f32 {
    let face = ttf_parser::Face::parse(epaint_default_fonts::UBUNTU_LIGHT, 0).expect("font");
    let mut units = 0.0f32;
    let mut previous: Option<ttf_parser::GlyphId> = None;
    for c in text.chars() {
        let g = face.glyph_index(c).unwrap_or(ttf_parser::GlyphId(0));
        if let (Some(p), Some(kern)) = (previous, face.tables().kern) {
            let k = kern
                .subtables
                .into_iter()
                .filter(|st| st.horizontal && !st.variable)
                .find_map(|st| st.glyphs_kerning(p, g));
            units += f32::from(k.unwrap_or(0));
        }
        units += f32::from(face.glyph_hor_advance(g).unwrap_or(0));
        previous = Some(g);
    }
    units * size / f32::from(face.units_per_em())
}

/// Figures with every kind of label: handles, mode titles, the wipe pair, the difference
/// view's title and colour bar, the caption; at overlay scales 1 and 1.5.
fn figures() -> Vec<Figure> {
    figures_in(barylab::i18n::Lang::En)
}

/// [`figures`] with the labels in `lang` (English when Chinese was asked for and no CJK
/// font is installed).
fn figures_in(lang: barylab::i18n::Lang) -> Vec<Figure> {
    let mut out = Vec::new();
    for (size, compare, k) in [
        ([400, 300], Compare::Single, 1.0),
        ([200, 150], Compare::SideBySide, 1.5),
        ([320, 240], Compare::Wipe, 1.0),
        ([320, 240], Compare::Difference, 1.5),
    ] {
        let (scene, texture) = scene(size);
        let options = FigureOptions {
            compare,
            pinned: Some([size[0] / 2, size[1] * 2 / 3]),
            overlay_scale: k,
            caption: true,
            background: Background::White,
            ..FigureOptions::default()
        };
        out.push(Figure::compose_in(&scene, &texture, &options, lang).expect("figure"));
    }
    out
}

#[test]
fn every_label_box_is_as_wide_as_its_text_in_the_font() {
    let mut seen = 0;
    for fig in figures() {
        let doc = svg::to_svg(&fig).expect("svg");
        let found = labels(&doc);
        assert!(found.len() > 5, "{found:?}");
        for l in found {
            let pad = if l.has_box {
                2.0 * LABEL_PAD[0] * fig.overlay_scale
            } else {
                0.0
            };
            let expected = advance(&l.text, l.size) + pad;
            assert!(
                (l.r#box[2] - expected).abs() < 0.01,
                "{:?}: box {} wide, the font says {expected}",
                l.text,
                l.r#box[2]
            );
            seen += 1;
        }
    }
    assert!(seen > 40);
}

#[test]
fn resvg_draws_every_labels_glyphs_inside_its_box() {
    // Chinese labels take their glyphs from the system's CJK font, when there is one.
    let mut all = figures();
    all.extend(figures_in(barylab::i18n::Lang::Zh));
    for fig in all {
        let doc = svg::to_svg(&fig).expect("svg");
        let header = &doc[..doc.find('\n').expect("first line") + 1];
        let defs = &doc[doc.find("<defs>").expect("defs")..doc.find("</defs>").expect("defs")];
        let s = fig.scale as f32;
        let [w, h] = fig.pixel_dimensions();
        for l in labels(&doc) {
            if l.text.trim().is_empty() {
                continue;
            }
            // The label's glyphs alone, nothing clipping them.
            let one = format!("{header}{defs}</defs>\n{}</svg>\n", l.glyphs);
            let tree = usvg::Tree::from_str(&one, &usvg::Options::default()).expect("parses");
            let mut pixmap = tiny_skia::Pixmap::new(w, h).expect("pixmap");
            resvg::render(
                &tree,
                tiny_skia::Transform::identity(),
                &mut pixmap.as_mut(),
            );
            let [x, y, bw, bh] = l.r#box;
            // In PNG pixels, with one pixel for anti-aliasing.
            let (x0, y0) = ((x * s).floor() - 1.0, (y * s).floor() - 1.0);
            let (x1, y1) = (((x + bw) * s).ceil() + 1.0, ((y + bh) * s).ceil() + 1.0);
            let mut ink = 0;
            for (i, p) in pixmap.pixels().iter().enumerate() {
                if p.alpha() == 0 {
                    continue;
                }
                ink += 1;
                let (px, py) = ((i as u32 % w) as f32, (i as u32 / w) as f32);
                assert!(
                    px >= x0 && px < x1 && py >= y0 && py < y1,
                    "{:?}: ink at ({px}, {py}) outside its box {:?} (scale {s})",
                    l.text,
                    l.r#box
                );
            }
            assert!(ink > 0, "{:?} draws nothing", l.text);
        }
    }
}

#[test]
fn the_wipe_labels_never_overlap_nor_leave_their_view_in_figures() {
    let affine = barylab::figure::overlay::mode_label(barylab::raster::Interpolation::Affine);
    let perspective =
        barylab::figure::overlay::mode_label(barylab::raster::Interpolation::Perspective);
    for (size, pixel_size, k) in [
        ([400, 300], 1, 1.0),
        ([320, 240], 1, 1.5),
        ([80, 50], 8, 1.0),
        ([160, 120], 1, 2.0),
        ([32, 24], 1, 1.0),
    ] {
        let (scene, texture) = scene(size);
        for wipe in [0.0, 0.001, 0.02, 0.1, 0.3, 0.5, 0.7, 0.9, 0.98, 0.999, 1.0] {
            let options = FigureOptions {
                compare: Compare::Wipe,
                wipe,
                pixel_size,
                overlay_scale: k,
                ..FigureOptions::default()
            };
            let fig = Figure::compose(&scene, &texture, &options).expect("figure");
            let doc = svg::to_svg(&fig).expect("svg");
            let found = labels(&doc);
            let find = |t: &str| {
                found
                    .iter()
                    .find(|l| l.text == t)
                    .map(|l| l.r#box)
                    .unwrap_or_else(|| panic!("{t} not in {found:?}"))
            };
            let (l, r) = (find(affine), find(perspective));
            let clip = fig.views[0].clip;
            let what = format!("{size:?} x{pixel_size} k {k} wipe {wipe}: {l:?} {r:?} in {clip:?}");
            assert!(l[0] + l[2] <= r[0] + 0.01, "overlap: {what}");
            for b in [l, r] {
                assert!(
                    b[0] >= clip[0] + LABEL_INSET - 0.01
                        && b[0] + b[2] <= clip[2] - LABEL_INSET + 0.01
                        && b[1] >= clip[1] - 0.01
                        && b[1] + b[3] <= clip[3] + 0.01,
                    "outside: {what}"
                );
            }
        }
    }
}

proptest! {
    /// The pair placement the app's canvas and the figures share: shrunk by `pair_fit`, the
    /// labels never overlap and stay inside the clip, wherever the line is.
    #[test]
    fn a_fitted_pair_never_overlaps_nor_leaves_the_clip(
        x in -50.0f32..650.0,
        left in 10.0f32..400.0,
        right in 10.0f32..400.0,
        width in 120.0f32..600.0,
        gap in 0.0f32..40.0,
    ) {
        let clip = [0.0, -44.0, width, 300.0];
        let pad = 6.0;
        let f = pair_fit([left, right], pad, gap, clip);
        let sizes = [[left * f + 2.0 * pad, 30.0], [right * f + 2.0 * pad, 30.0]];
        let ([l, r], fits) = place_pair([x, -6.0], gap, sizes, clip);
        prop_assert!(fits);
        prop_assert!(l[2] + gap <= r[0] + 1e-3);
        prop_assert!(l[0] >= clip[0] + LABEL_INSET - 1e-3);
        prop_assert!(r[2] <= clip[2] - LABEL_INSET + 1e-3);
        prop_assert!(l[1] >= clip[1] && r[3] <= clip[3]);
    }
}

/// The app's canvas: the wipe labels as egui paints them, at 1024x768 with text size 1.5,
/// never overlap and stay on the canvas wherever the line is.
#[test]
fn the_wipe_labels_never_overlap_nor_leave_the_canvas_in_the_app() {
    let mut h = common::app::harness(egui::vec2(1024.0, 768.0), AppOptions::default());
    for c in [
        AppCommand::SetCompare(Compare::Wipe),
        AppCommand::SetUiScale(1.5),
    ] {
        h.state_mut().push(c);
    }
    for _ in 0..4 {
        h.step();
    }
    h.run();
    let affine = barylab::figure::overlay::mode_label(barylab::raster::Interpolation::Affine);
    let perspective =
        barylab::figure::overlay::mode_label(barylab::raster::Interpolation::Perspective);
    for wipe in [0.0, 0.01, 0.05, 0.25, 0.5, 0.75, 0.95, 0.99, 1.0] {
        h.state_mut().push(AppCommand::SetWipe(wipe));
        h.run();
        let area = h.state().canvas().area.expect("laid out");
        let find = |t: &str| {
            h.output()
                .shapes
                .iter()
                .find_map(|c| match &c.shape {
                    egui::Shape::Text(s) if s.galley.job.text == t => {
                        Some(s.galley.rect.translate(s.pos.to_vec2()))
                    }
                    _ => None,
                })
                .unwrap_or_else(|| panic!("{t} not painted at wipe {wipe}"))
        };
        let (l, r) = (find(affine), find(perspective));
        assert!(l.right() <= r.left(), "wipe {wipe}: {l:?} overlaps {r:?}");
        for b in [l, r] {
            assert!(
                area.expand(0.5).contains_rect(b),
                "wipe {wipe}: {b:?} leaves the canvas {area:?}"
            );
        }
    }
}
