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
            Shape::QuadLabels(q) => {
                texts.extend(q.texts.iter().flatten().map(|(t, _)| t.clone()));
            }
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

/// The four labels are one block, in the order of the quad's pixels (`uv_ij` for pixel
/// `(x0 + i, y0 + j)` at index `i + 2 j`), for the quad `(x0, y0)..(x0 + 2, y0 + 2)`,
/// preferably above the quad in the image's lower half and below it in the upper half, and
/// placed after the handles (so it keeps clear of them and their labels).
#[test]
fn the_quad_labels_are_one_block_in_the_pixels_order_after_the_handles() {
    let scene = far_checker(Filter::Trilinear);
    let texture = scene.load_texture(Path::new("")).expect("texture");
    for (pin, up) in [([240, 290], true), ([240, 160], true), ([240, 140], false)] {
        let options = FigureOptions {
            pinned: Some(pin),
            ..FigureOptions::default()
        };
        let fig = Figure::compose(&scene, &texture, &options).expect("figure");
        let shapes = &fig.views[0].overlay.shapes;
        let at = shapes
            .iter()
            .position(|s| matches!(s, Shape::QuadLabels(_)))
            .expect("the quad's labels");
        let last_handle = shapes
            .iter()
            .rposition(|s| matches!(s, Shape::HandleLabel { .. }))
            .expect("handle labels");
        assert!(
            at > last_handle,
            "{pin:?}: the block is placed after the handles"
        );
        let Shape::QuadLabels(q) = &shapes[at] else {
            unreachable!()
        };
        let (min, max, texts, above) = (&q.min, &q.max, &q.texts, &q.above);
        let o = DVec2::new(f64::from(pin[0] & !1), f64::from(pin[1] & !1));
        assert_eq!((*min, *max), (o, o + DVec2::splat(2.0)));
        assert_eq!(*above, up, "{pin:?}");
        for (k, t) in texts.iter().enumerate() {
            let (t, _) = t.as_ref().expect("four labels");
            assert!(
                t.starts_with(&format!("uv_{}{} = (", k % 2, k / 2)),
                "{k}: {t}"
            );
        }
    }
}
