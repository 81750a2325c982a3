//! The 2x2 quad of the texture derivatives on the canvas and in exported figures: outlined
//! around the pinned pixel with the four pixels' uvs (the probe's), a helper pixel marked as
//! extrapolated, and nothing of it without a level-of-detail derivation.

mod common;

use std::path::Path;

use barylab::figure::overlay::Shape;
use barylab::figure::{Figure, FigureOptions};
use barylab::probe::PixelTrace;
use barylab::probe::format::fmt_number;
use barylab::raster::Filter;
use barylab::scene::Scene;
use glam::DVec2;

fn far_checker(filter: Filter) -> Scene {
    let mut scene = Scene::load(Path::new("assets/scenes/far-checker.json")).expect("scene");
    let options = barylab::edit::SceneOptions {
        filter,
        ..barylab::edit::options(&scene)
    };
    barylab::edit::set_options(&mut scene, options);
    scene
}

/// The figure's overlay texts and rectangles with the pixel `pin` pinned.
fn marks(scene: &Scene, pin: [u32; 2]) -> (Vec<String>, Vec<(DVec2, DVec2)>, PixelTrace) {
    let texture = scene.load_texture(Path::new("")).expect("texture");
    let options = FigureOptions {
        pinned: Some(pin),
        ..FigureOptions::default()
    };
    let fig = Figure::compose(scene, &texture, &options).expect("figure");
    let mut texts = Vec::new();
    let mut rects = Vec::new();
    for s in &fig.views[0].overlay.shapes {
        match s {
            Shape::Text { text, .. } => texts.push(text.clone()),
            Shape::Rect { min, max, .. } => rects.push((*min, *max)),
            _ => {}
        }
    }
    (texts, rects, fig.pinned.expect("the pinned pixel's trace"))
}

#[test]
fn the_pinned_pixels_quad_is_outlined_with_the_probes_uvs() {
    let scene = far_checker(Filter::Trilinear);
    let (texts, rects, trace) = marks(&scene, [240, 160]);
    let l = common::lod_of(&trace);
    let o = l.quad[0].pixel;
    assert_eq!(o, [240, 160]);
    let origin = DVec2::new(f64::from(o[0]), f64::from(o[1]));
    assert!(
        rects.contains(&(origin, origin + DVec2::splat(2.0))),
        "the quad's outline in {rects:?}"
    );
    for (k, q) in l.quad.iter().enumerate() {
        assert!(q.inside, "pixel {:?} of the quad is inside", q.pixel);
        let uv = q.uv.expect("a uv");
        let label = format!(
            "uv_{}{} = ({}, {})",
            k % 2,
            k / 2,
            fmt_number(f64::from(uv[0])),
            fmt_number(f64::from(uv[1]))
        );
        assert!(texts.contains(&label), "{label} in {texts:?}");
    }
    // The lesson quotes uv_00 = (10, 2.314) and uv_10 = (10.01, 2.314) for this pixel.
    assert!(texts.contains(&"uv_00 = (10, 2.314)".to_string()));
    assert!(texts.contains(&"uv_10 = (10.01, 2.314)".to_string()));
}

#[test]
fn a_quad_neighbour_outside_the_triangle_is_named_a_helper() {
    let scene = far_checker(Filter::Trilinear);
    let texture = scene.load_texture(Path::new("")).expect("texture");
    let settings = scene.settings();
    // Up the middle column to the floor's last row: its quad reaches above the horizon.
    let pin = (100..320)
        .map(|y| [240, y])
        .find(|&[x, y]| {
            let t = barylab::probe::probe(&scene, &texture, &settings, (x, y)).expect("probe");
            t.written_by.is_some()
                && t.detail
                    .as_ref()
                    .and_then(|d| d.attribute.as_ref())
                    .and_then(|a| a.lod.as_ref())
                    .is_some_and(|l| l.quad.iter().any(|q| !q.inside))
        })
        .expect("a pixel of the floor whose quad has a helper");
    let (texts, _, trace) = marks(&scene, pin);
    let l = common::lod_of(&trace);
    let helpers: Vec<String> = l
        .quad
        .iter()
        .enumerate()
        .filter(|(_, q)| !q.inside)
        .map(|(k, q)| {
            let uv = q.uv.expect("extrapolated uv");
            format!(
                "uv_{}{} = ({}, {}): helper, extrapolated",
                k % 2,
                k / 2,
                fmt_number(f64::from(uv[0])),
                fmt_number(f64::from(uv[1]))
            )
        })
        .collect();
    assert!(!helpers.is_empty());
    for h in &helpers {
        assert!(texts.contains(h), "{h} in {texts:?}");
    }
}

#[test]
fn without_a_level_of_detail_there_is_no_quad() {
    let scene = far_checker(Filter::Bilinear);
    let (texts, _, _) = marks(&scene, [240, 160]);
    assert!(
        !texts.iter().any(|t| t.starts_with("uv_")),
        "no quad labels in {texts:?}"
    );
}

/// The four labels sit as the quad's pixels do, in two rows on one side of the quad (above
/// it in the image's lower half, below it in the upper half): `uv_0j` left of the quad's
/// centre, `uv_1j` right of it, row 0 over row 1.
#[test]
fn the_quad_labels_sit_in_two_rows_on_the_roomier_side() {
    let scene = far_checker(Filter::Trilinear);
    let texture = scene.load_texture(Path::new("")).expect("texture");
    for (pin, up) in [([240, 290], true), ([240, 160], true), ([240, 140], false)] {
        let options = FigureOptions {
            pinned: Some(pin),
            ..FigureOptions::default()
        };
        let fig = Figure::compose(&scene, &texture, &options).expect("figure");
        let mut offsets = [None; 4];
        for s in &fig.views[0].overlay.shapes {
            if let Shape::Text {
                text, at, offset, ..
            } = s
                && let Some(ij) = text.strip_prefix("uv_")
            {
                let k =
                    usize::from(ij.as_bytes()[0] - b'0') + 2 * usize::from(ij.as_bytes()[1] - b'0');
                let centre = DVec2::new(f64::from(pin[0] & !1) + 1.0, f64::from(pin[1] & !1));
                assert_eq!(at.x, centre.x, "{text}: centred on the quad");
                offsets[k] = Some(*offset);
            }
        }
        let o = offsets.map(|o| o.expect("four quad labels"));
        for k in 0..4 {
            assert_eq!(o[k][0] < 0.0, k % 2 == 0, "{pin:?} uv {k}: {o:?}");
            assert_eq!(o[k][1] < 0.0, up, "{pin:?} uv {k}: {o:?}");
        }
        // Row 0 over row 1, the two labels of a row level.
        assert!(o[0][1] < o[2][1] && o[1][1] < o[3][1], "{pin:?}: {o:?}");
        assert_eq!((o[0][1], o[2][1]), (o[1][1], o[3][1]));
    }
}
