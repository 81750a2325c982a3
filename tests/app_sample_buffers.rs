//! The per-sample buffers view in the app: the control's buttons set the view, the canvas's
//! image then comes from the core's samples (the coverage count, sample 1's colour), and the
//! black-edge toggle clears the pinned pixel's blue sample, as `figure::sample_buffers` does.

mod common;

use barylab::app::document::state::StateCommand;
use barylab::app::{AppOptions, BaryApp};
use barylab::figure::sample_buffers::{SampleBufferKind, SampleView, coverage_colour};
use barylab::raster::Interpolation;
use egui::Color32;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

fn open() -> Harness<'static, BaryApp> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/scenes/games101-a2-ssaa.json");
    let opened = barylab::scene::open_input(&path).expect("the scene opens");
    let mut h = common::app::harness(
        egui::vec2(1500.0, 2400.0),
        AppOptions {
            scene: Some(opened),
            ..AppOptions::default()
        },
    );
    h.state_mut()
        .push(StateCommand::SetImageSize(Some([120, 120])));
    h.run();
    h
}

/// Pixel (x, y) of the image the canvas takes from the samples under `view`.
fn shown(h: &Harness<'static, BaryApp>, view: SampleView, x: usize, y: usize) -> Color32 {
    let image = h
        .state()
        .canvas()
        .samples
        .image(Interpolation::Perspective, view)
        .expect("the samples are made while the view is on");
    assert_eq!(image.size, [120, 120]);
    image.pixels[y * 120 + x]
}

fn rgba(c: [u8; 4]) -> Color32 {
    Color32::from_rgba_unmultiplied(c[0], c[1], c[2], c[3])
}

#[test]
fn the_control_shows_each_buffer_and_the_black_edge_bug() {
    let mut h = open();
    assert_eq!(h.state().canvas().samples_shown, 0, "the usual image");
    h.get_by_label("coverage count").click();
    h.run();
    let view = h.state().state().view.samples_view;
    assert_eq!(view.kind, SampleBufferKind::Coverage);
    assert_eq!(h.state().canvas().samples_shown, 1);
    assert_eq!(shown(&h, view, 83, 42), rgba(coverage_colour(4, 4)));
    assert_eq!(shown(&h, view, 2, 2), rgba(coverage_colour(0, 4)));

    h.get_by_label("sample colour").click();
    h.run();
    let view = SampleView {
        index: 1,
        ..h.state().state().view.samples_view
    };
    h.state_mut().push(StateCommand::SetSamplesView(view));
    h.run();
    let view = h.state().state().view.samples_view;
    assert_eq!((view.kind, view.index), (SampleBufferKind::Color, 1));
    let blue = rgba([185, 217, 238, 255]);
    assert_eq!(shown(&h, view, 83, 42), blue);

    // The bug: the blue triangle's sample 1 of that pixel keeps the background.
    h.get_by_label("Black-edge bug (GAMES101 A2)").click();
    h.run();
    let view = h.state().state().view.samples_view;
    assert!(view.black_edges);
    assert_eq!(shown(&h, view, 83, 42), Color32::BLACK);
    // And the resolve with it: (163, 179, 139), darker than both triangles.
    h.get_by_label("resolve").click();
    h.run();
    let view = h.state().state().view.samples_view;
    assert_eq!(h.state().canvas().samples_shown, 1);
    assert_eq!(shown(&h, view, 83, 42), rgba([163, 179, 139, 255]));

    h.get_by_label("Black-edge bug (GAMES101 A2)").click();
    h.run();
    assert!(!h.state().state().view.samples_view.is_on());
    assert_eq!(h.state().canvas().samples_shown, 0, "the usual image again");
}

/// The closed three-point white lines the canvas paints (the triangles' outlines: stroke
/// `[255, 255, 255, 230]`, see `figure::overlay::is_triangle_outline`).
fn outlines(h: &Harness<'static, BaryApp>) -> usize {
    fn count(shape: &egui::Shape) -> usize {
        let white = Color32::from_rgba_unmultiplied(255, 255, 255, 230);
        match shape {
            egui::Shape::Vec(v) => v.iter().map(count).sum(),
            egui::Shape::Path(p) => usize::from(
                p.closed
                    && p.points.len() == 3
                    && p.stroke.color == egui::epaint::ColorMode::Solid(white),
            ),
            _ => 0,
        }
    }
    h.output().shapes.iter().map(|c| count(&c.shape)).sum()
}

/// The black-edge bug's dark line runs along the green triangle's edge: the canvas's white
/// outline of the pinned pixel's triangle would lie right over it, so a sample buffer view
/// draws no outline.
#[test]
fn a_sample_buffer_view_leaves_the_edge_pixels_uncovered() {
    let mut h = open();
    h.state_mut().push(StateCommand::Pin(Some([83, 42])));
    h.run();
    assert_eq!(
        outlines(&h),
        1,
        "the usual image outlines the pinned pixel's triangle"
    );
    h.get_by_label("Black-edge bug (GAMES101 A2)").click();
    h.run();
    assert!(h.state().state().view.samples_view.black_edges);
    assert_eq!(outlines(&h), 0, "the dark line stays visible");
    h.get_by_label("Black-edge bug (GAMES101 A2)").click();
    h.run();
    assert_eq!(outlines(&h), 1, "the outline comes back");
}
